"""``deathsphere map`` and ``deathsphere limits``: the allowed region and
the rider's limits (:func:`deathsphere.api.region`, :func:`~deathsphere.api.region_cells`,
:func:`~deathsphere.api.region_curves`, :func:`~deathsphere.api.limits`)."""

from __future__ import annotations

import click

from deathsphere import api
from deathsphere.cli.base import (
    OutputPath,
    body_options,
    choose_format,
    cli,
    emit,
    fail,
    given,
    jobs_option,
    number_option,
    one_line,
    output_options,
    progress,
    stability_option,
    stderr_console,
    stdout_console,
    values_option,
)

#: Figure formats of the map (matplotlib, the plot extra).
FIGURES = {"png": "matplotlib", "svg": "matplotlib", "pdf": "matplotlib"}


@cli.command("map")
@body_options(bodies=("wheel",), radii_only=True)
@number_option("mu", "MU", "Also draw the friction limit mu_required = MU.", None, "none")
@number_option("max_g", "G", "Also draw the g-load limit accel_g = G.", ("--max-g",), "none")
@click.option("--output", type=OutputPath(FIGURES), default=None, metavar="FILE",
              help="Write the figure to FILE (.png, .svg or .pdf); needs pip install 'deathsphere[plot]'.")
@number_option("step", "DEG", "theta step of the boundary data (--format csv/json), 0.001..10.", None, "0.5")
@stability_option(default=False, help=(
    "Also show the exact linear stability of each orbit (beyond the paper, docs/stability.md): stable and "
    "unstable parts of the allowed region and the boundary between them.  Wheel only: a rolling sphere "
    "has no tilt alpha (and all its horizontal orbits are stable)."))
@jobs_option("computing the stability boundary (--format csv/json)")
@output_options()
def map_command(side, a, r, k, mu, max_g, output, step, stability, jobs, fmt):
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
      deathsphere map -a 0.9 -r 3 --stability --output map.png
    """
    options = given(side=side, a=a, r=r, k=k, mu=mu, max_g=max_g)
    if output is not None:
        from deathsphere.render.figures import PlotExtraMissing, import_matplotlib
        from deathsphere.render.map_figure import plot_map

        try:
            import_matplotlib()  # before the work: a missing extra is one line, at once
            plot_map(api.region_curves(stability=stability, **options), output=output)
        except PlotExtraMissing as exc:
            fail(one_line(str(exc)))
        stderr_console().print(f"deathsphere: wrote {output}")
        return
    fmt = choose_format(fmt)
    if fmt == "table":
        from deathsphere.render.charplot import char_map, columns_for_width, to_rich

        width = max(40, min(stdout_console().width, 100))
        cells = api.region_cells(stability=stability, columns=columns_for_width(width), **options)
        stdout_console().print(to_rich(char_map(cells)), end="")
        return
    with progress("boundaries", None) as bar:
        table = api.region(stability=stability, progress=bar.update, **given(step=step, jobs=jobs), **options)
    emit([table], fmt)


@cli.command("limits")
@values_option("theta", "DEG", "Polar angle(s) of the orbit; without it: the highest orbit possible.")
@number_option("max_g", "G", "Largest centre acceleration the rider takes, in g.", ("--max-g",), "unlimited")
@body_options(bodies=("wheel",))
@output_options()
def limits_command(theta, max_g, side, a, r, k, g, mu, fmt):
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
    table = api.limits(**given(theta=theta, max_g=max_g, side=side, a=a, r=r, k=k, g=g, mu=mu))
    title = ("Feasible tilts (fit, Omega^2 > 0, contact, mu, g-load)" if theta else
             "The highest orbit possible (smallest theta with a feasible tilt)")
    emit([table], choose_format(fmt), title=title)
