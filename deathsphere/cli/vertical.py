"""``deathsphere vertical``: vertical orbits of a wheel."""

from __future__ import annotations

import math

import click
import numpy as np

from deathsphere.cli.base import (
    Quantity,
    Values,
    axis,
    choose_format,
    cli,
    finish,
    input_option,
    make_setup,
    open_requests,
    output_options,
    run_batches,
)
from deathsphere.cli.orbit import _total, input_batches
from deathsphere.grid import grid_chunks
from deathsphere.constants import (
    SIDES,
    STANDARD_GRAVITY,
    TABLE1_SPHERE_RADIUS,
    TABLE1_WHEEL_RADIUS,
)

#: Rows of the point-by-point output computed at once (requests x points).
POINT_ROWS = 65536


@cli.command("vertical", short_help="Vertical orbit of a wheel: contact, forces, friction, worst point, lap time.")
@click.option("--theta", multiple=True, type=Values("theta"), metavar="DEG",
              help="Cone angle of the orbit about the horizontal axis, 0..180 (90 = a vertical great circle).")
@click.option("--v-top", "v_top", multiple=True, type=Values("v_top"), metavar="M_S",
              help="Speed of the wheel's centre at the top, >= 0.")
@click.option("--phidot-top", "phidot_top", multiple=True, type=Values("phidot_top"), metavar="RAD_S",
              help="Orbital rate at the top, >= 0.")
@click.option("--side", type=click.Choice(SIDES, case_sensitive=False), default="inside", show_default=True,
              help="Wheel inside or outside the sphere (outside it leaves the surface, eq. 82).")
@click.option("-a", "--wheel-radius", "a", type=Quantity("a"), default=TABLE1_WHEEL_RADIUS, show_default=True,
              metavar="M")
@click.option("-r", "--sphere-radius", "r", type=Quantity("r"), default=TABLE1_SPHERE_RADIUS, show_default=True,
              metavar="M")
@click.option("-k", "--inertia", "k", type=Quantity("k"), default=0.5, show_default=True, metavar="K",
              help="Inertia factor, I11 = 2 k m a^2.")
@click.option("-g", "--gravity", "g", type=Quantity("g"), default=STANDARD_GRAVITY, show_default=True,
              metavar="M_S2")
@click.option("--mu", type=Quantity("mu"), default=math.inf, metavar="MU",
              help="Friction available [default: unlimited].")
@click.option("--points", type=Quantity("points"), default=None, metavar="N",
              help="Print the orbit point by point at N azimuths phi from the top (0) to 360 deg (2..1e6).")
@input_option("theta, v_top or phidot_top, side, a, r, k, g, mu")
@click.option("--stability/--no-stability", "with_stability", default=True, show_default=True,
              help="Exact stability by Floquet analysis over one lap (docs/stability.md).")
@output_options()
def vertical_command(theta, v_top, phidot_top, side, a, r, k, g, mu, points, input_path, with_stability, fmt):
    """Vertical orbit of a wheel: contact all round (eq. 28a), forces and friction (eqs. 27-28b).

    Reports the least top speed for contact, the normal force and friction
    needed round the orbit, the worst point (where mu peaks) and the lap time
    (an elliptic integral).  Outside the sphere no vertical orbit closes: the
    row gives where the wheel leaves the surface (from rest: eq. 82).
    Rates and speeds are at the top; forces and mu_required at the worst point.

    \b
    Examples:
      deathsphere vertical --theta 90 --v-top 6
      deathsphere vertical --theta 60 --v-top 4:8:1 --mu 1.5
      deathsphere vertical --theta 90 --v-top 6 --points 13 --format csv
      deathsphere vertical --side outside --theta 90 --v-top 0
    """
    from deathsphere.render.orbit_views import vertical_view
    from deathsphere.results.vertical import COLUMNS, VERTICAL_FIELDS, evaluate_vertical, vertical_points, vertical_requests

    setup = make_setup("wheel", side, a, r, k, g, mu)
    fmt = choose_format(fmt)
    defaults = dict(side=setup.side, a=setup.a, r=setup.r, k=setup.k, g=setup.g, mu=setup.mu)
    points = None if points is None else int(points)
    chunk = 256 if points is None else max(1, POINT_ROWS // points)
    if input_path is not None:
        if theta or v_top or phidot_top:
            raise click.UsageError("with --input, give theta and v_top/phidot_top as CSV columns")
        echo = ("side", "theta_deg", "a_m", "r_m", "k", "g_m_s2", "mu_available", "v_cm_m_s")
        aliases = {"theta_deg": "theta", "a_m": "a", "r_m": "r", "g_m_s2": "g", "mu_available": "mu",
                   "v_cm_m_s": "v_top"}
        reader = open_requests(input_path, VERTICAL_FIELDS, defaults, aliases=aliases,
                               ignore=[c for c in COLUMNS if c not in echo])

        batches, total = input_batches(reader, chunk, vertical_requests), None
    else:
        if not theta:
            raise click.UsageError("give --theta DEG (or --input FILE)")
        if bool(v_top) == bool(phidot_top):
            raise click.UsageError("give exactly one of --v-top M_S and --phidot-top RAD_S")
        key = "v_top" if v_top else "phidot_top"
        axes = {"theta": axis(theta), key: axis(v_top or phidot_top)}
        total = _total(axes)

        def batches():
            for first, grid in grid_chunks(axes, chunk):
                n = len(grid["theta"])
                yield n, vertical_requests(n, input_row=np.arange(first + 1, first + n + 1), **grid, **defaults)

        batches = batches()
    if points:
        def point_batches():
            # an orbit of more than POINT_ROWS points is written slice by slice
            for n, req in batches:
                for start in range(0, points, POINT_ROWS):
                    yield (n if start + POINT_ROWS >= points else 0), (req, start)

        tally = run_batches(point_batches(), lambda job: vertical_points(job[0], points, job[1], job[1] + POINT_ROWS),
                            fmt, label="vertical orbits", total=total,
                            title="Vertical orbit point by point (eqs. 27, 28, 28b; phi from the top)")
    else:
        tally = run_batches(batches, lambda req: evaluate_vertical(req, stability=with_stability), fmt,
                            label="vertical orbits", total=total, view=vertical_view)
    finish(tally)
