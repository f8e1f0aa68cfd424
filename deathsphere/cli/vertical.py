"""``deathsphere vertical``: vertical orbits of a wheel."""

from __future__ import annotations

import math
import sys

import click

from deathsphere.cli.base import (
    ORBIT_MAX_ROWS,
    choose_format,
    cli,
    emit,
    evaluate_in_chunks,
    make_setup,
    output_options,
    parse_angles,
    parse_rates,
    stderr_console,
    stdout_console,
)
from deathsphere.constants import (
    SIDES,
    STANDARD_GRAVITY,
    TABLE1_SPHERE_RADIUS,
    TABLE1_WHEEL_RADIUS,
)
from deathsphere.exitcodes import ExitCode
from deathsphere.grid import grid_chunks, grid_size
from deathsphere.inputs import InputError, read_table


@cli.command("vertical", short_help="Vertical orbit of a wheel: contact, forces, friction, worst point, lap time.")
@click.option("--theta", multiple=True, metavar="DEG",
              help="Cone angle of the orbit about the horizontal axis, 0..180 (90 = a vertical great circle).")
@click.option("--v-top", "v_top", multiple=True, metavar="M_S", help="Speed of the wheel's centre at the top.")
@click.option("--phidot-top", "phidot_top", multiple=True, metavar="RAD_S", help="Orbital rate at the top.")
@click.option("--side", type=click.Choice(SIDES, case_sensitive=False), default="inside", show_default=True,
              help="Wheel inside or outside the sphere (outside it leaves the surface, eq. 82).")
@click.option("-a", "--wheel-radius", "a", type=float, default=TABLE1_WHEEL_RADIUS, show_default=True, metavar="M")
@click.option("-r", "--sphere-radius", "r", type=float, default=TABLE1_SPHERE_RADIUS, show_default=True,
              metavar="M")
@click.option("-k", "--inertia", "k", type=float, default=0.5, show_default=True, metavar="K",
              help="Inertia factor, I11 = 2 k m a^2.")
@click.option("-g", "--gravity", "g", type=float, default=STANDARD_GRAVITY, show_default=True, metavar="M_S2")
@click.option("--mu", type=float, default=math.inf, metavar="MU", help="Friction available [default: unlimited].")
@click.option("--points", type=click.IntRange(2, 1_000_000), default=None, metavar="N",
              help="Print the orbit point by point at N azimuths phi from the top (0) to 360 deg.")
@click.option("--input", "input_file", type=click.File("r"), default=None, metavar="FILE|-",
              help="CSV of requests (theta, v_top or phidot_top, side, a, r, k, g, mu); '-' reads stdin.")
@click.option("--stability/--no-stability", "with_stability", default=True, show_default=True,
              help="Exact stability by Floquet analysis over one lap (docs/stability.md).")
@output_options()
def vertical_command(theta, v_top, phidot_top, side, a, r, k, g, mu, points, input_file, with_stability, fmt):
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
    from deathsphere.vertical import (
        VERTICAL_FIELDS,
        evaluate_vertical,
        vertical_points,
        vertical_requests,
    )

    setup = make_setup("wheel", side, a, r, k, g, mu)
    fmt = choose_format(fmt)
    defaults = dict(side=setup.side, a=setup.a, r=setup.r, k=setup.k, g=setup.g, mu=setup.mu)
    if input_file is not None:
        if theta or v_top or phidot_top:
            raise click.UsageError("with --input, give theta and v_top/phidot_top as CSV columns")
        try:
            n, values, invalid = read_table(input_file, defaults, getattr(input_file, "name", "input"),
                                            VERTICAL_FIELDS)
        except InputError as exc:
            raise click.UsageError(str(exc)) from None
        req = vertical_requests(n, invalid=invalid, **values)
    else:
        if not theta:
            raise click.UsageError("give --theta DEG (or --input FILE)")
        if bool(v_top) == bool(phidot_top):
            raise click.UsageError("give exactly one of --v-top M_S and --phidot-top RAD_S")
        speeds = parse_rates(v_top, "v-top") if v_top else parse_rates(phidot_top, "phidot-top")
        if v_top and (speeds < 0).any():
            raise click.BadParameter("the top speed must be >= 0 m/s", param_hint="'--v-top'")
        axes = {"theta": parse_angles(theta, "theta", ORBIT_MAX_ROWS), "speed": speeds}
        if grid_size(axes) > ORBIT_MAX_ROWS:
            raise click.UsageError(f"{grid_size(axes)} orbits is more than `vertical` holds at once")
        _, grid = next(grid_chunks(axes, grid_size(axes)))
        key = "v_top" if v_top else "phidot_top"
        req = vertical_requests(len(grid["theta"]), theta=grid["theta"], **{key: grid["speed"]}, **defaults)
    if points:
        table = vertical_points(req, points)
        emit([table], fmt, title="Vertical orbit point by point (eqs. 27, 28, 28b; phi from the top)")
    else:
        # the Floquet analysis integrates a lap per orbit: chunks of 32 keep the bar moving
        table = evaluate_in_chunks(req, lambda sub: evaluate_vertical(sub, stability=with_stability),
                                   "vertical orbits", 32)
        if fmt == "table":
            from deathsphere.render import vertical_view

            stdout_console().print(vertical_view(table))
        else:
            emit([table], fmt)
    if (table["status"] == "invalid").any():
        stderr_console().print("deathsphere: some input rows are invalid; see their reason column", style="yellow")
        sys.exit(ExitCode.INVALID_ROWS)
