"""``deathsphere map`` and ``deathsphere limits``: the allowed region and
the rider's limits."""

from __future__ import annotations

import math

import click

from deathsphere.cli.base import (
    OutputPath,
    Quantity,
    Values,
    axis,
    body_options,
    choose_format,
    cli,
    emit,
    fail,
    make_setup,
    one_line,
    output_options,
    progress,
    stderr_console,
    stdout_console,
)

#: Figure formats of the map (matplotlib, the plot extra).
FIGURES = {"png": "matplotlib", "svg": "matplotlib", "pdf": "matplotlib"}
#: theta values `limits --theta` evaluates at once (each a root search).
MAX_LIMIT_THETAS = 100_000
from deathsphere.constants import SIDES


@cli.command("map")
@click.option("--a-over-r", "a_over_r", type=Quantity("a_over_r"), default=0.1, show_default=True,
              help="Wheel radius over sphere radius (the paper's figure: 0.1).")
@click.option("-k", "--inertia", "k", type=Quantity("k"), default=0.5, show_default=True, metavar="K")
@click.option("--side", type=click.Choice(SIDES, case_sensitive=False), default="inside", show_default=True)
@click.option("--mu", type=Quantity("mu"), default=math.inf, metavar="MU",
              help="Also draw the friction limit mu_required = MU.")
@click.option("--max-g", "max_g", type=Quantity("max_g"), default=math.inf, metavar="G",
              help="Also draw the g-load limit accel_g = G.")
@click.option("--output", type=OutputPath(FIGURES), default=None, metavar="FILE",
              help="Write the figure to FILE (.png, .svg or .pdf); needs pip install 'deathsphere[plot]'.")
@click.option("--step", type=Quantity("step"), default=0.5, show_default=True, metavar="DEG",
              help="theta step of the boundary data (--format csv/json), 0.001..10.")
@click.option("--stability", is_flag=True,
              help="Also show the exact linear stability of each orbit (beyond the paper, docs/stability.md): "
                   "stable and unstable parts of the allowed region and the boundary between them.  "
                   "Wheel only: a rolling sphere has no tilt alpha (and all its horizontal orbits "
                   "are stable).")
@output_options()
def map_command(a_over_r, k, side, mu, max_g, output, step, stability, fmt):
    """The allowed (theta, alpha) region of horizontal wheel orbits: the paper's figure.

    Bounded by eq. (0) (the wheel fits), eq. (29) (Omega^2 > 0) and eq. (33)
    (contact); outside the sphere by eqs. (81), (29), (83).  With --mu or
    --max-g the friction and g-load limits are drawn too.  On a terminal a
    character plot; --format csv/json prints the boundary curves as data
    (root-found to 1e-9 rad); --output writes a figure.  With --stability
    the unstable orbits are marked (x on a terminal, red in a figure) and the
    stability boundary is drawn (exact linearisation, beyond the paper); with
    --format csv/json it is the curve 'stability' (bisected to 1e-10 rad
    between samples 0.25 deg apart in alpha).

    \b
    Examples:
      deathsphere map
      deathsphere map --mu 1 --max-g 5
      deathsphere map --format csv --step 1 | head
      deathsphere map --output map.png
      deathsphere map --a-over-r 0.3 --stability --output map.png
    """
    side = side.lower()
    if side == "inside" and not a_over_r < 1:
        raise click.BadParameter("must be < 1 inside the sphere", param_hint="'--a-over-r'")
    outside = side == "outside"
    if output is not None:
        from deathsphere.render.figures import PlotExtraMissing, import_matplotlib
        from deathsphere.render.map_figure import plot_map
        from deathsphere.results import region_map

        try:
            import_matplotlib()  # before the work: a missing extra is one line, at once
            plot_map(region_map.curve_map(a_over_r, 1.0, k, outside=outside, mu=mu, max_g=max_g,
                                          stability=stability), output=output)
        except PlotExtraMissing as exc:
            fail(one_line(str(exc)))
        stderr_console().print(f"deathsphere: wrote {output}")
        return
    fmt = choose_format(fmt)
    if fmt == "table":
        from deathsphere.render.charplot import char_map, columns_for_width, to_rich
        from deathsphere.results import region_map

        width = max(40, min(stdout_console().width, 100))
        cells = region_map.cell_map(a_over_r, 1.0, k, outside=outside, mu=mu, max_g=max_g, stability=stability,
                                    resolution=(columns_for_width(width), None))
        stdout_console().print(to_rich(char_map(cells)), end="")
        return
    from deathsphere.results.limits import boundary_table, boundary_thetas

    thetas = boundary_thetas(step)
    with progress("boundaries", thetas.size) as bar:
        table = boundary_table(a_over_r, k, outside, mu, max_g, step, stability=stability, progress=bar.advance)
    emit([table], fmt)


@cli.command("limits")
@click.option("--theta", multiple=True, type=Values("theta"), metavar="DEG",
              help="Polar angle(s) of the orbit; without it: the highest orbit possible.")
@click.option("--max-g", "max_g", type=Quantity("max_g"), default=math.inf, metavar="G",
              help="Largest centre acceleration the rider takes, in g [default: unlimited].")
@body_options
@output_options()
def limits_command(theta, max_g, body, side, a, r, k, g, mu, fmt):
    """Which tilts alpha give a feasible orbit at theta, and at what speeds (beyond the paper).

    With --theta: the interval(s) of alpha where the wheel fits, Omega^2 > 0
    and it keeps contact, within --mu and --max-g, with the speed range over
    each.  Without --theta: the highest orbit possible (smallest theta) with
    its alpha and speed.  Method: docs/limits.md.

    \b
    Examples:
      deathsphere limits --theta 60 --mu 1.2
      deathsphere limits --mu 1 --max-g 5
    """
    from deathsphere.results.limits import highest_orbit_table, intervals_table

    setup = make_setup(body, side, a, r, k, g, mu)
    if setup.body != "wheel":
        raise click.UsageError("limits are computed for a wheel (--body wheel)")
    fmt = choose_format(fmt)
    if theta:
        thetas = axis(theta)
        if len(thetas) > MAX_LIMIT_THETAS:
            raise click.BadParameter(f"{len(thetas)} values, more than {MAX_LIMIT_THETAS}", param_hint="'--theta'")
        table = intervals_table(setup, thetas.values(), max_g)
        title = "Feasible tilts (fit, Omega^2 > 0, contact, mu, g-load)"
    else:
        table = highest_orbit_table(setup, max_g)
        title = "The highest orbit possible (smallest theta with a feasible tilt)"
    emit([table], fmt, title=title)
