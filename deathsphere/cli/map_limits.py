"""``deathsphere map`` and ``deathsphere limits``: the allowed region and
the rider's limits (:func:`deathsphere.api.region`, :func:`~deathsphere.api.region_cells`,
:func:`~deathsphere.api.region_curves`, :func:`~deathsphere.api.limits`)."""

from __future__ import annotations

import click

from deathsphere import api
from deathsphere.cli.base import (
    OutputPath,
    choose_format,
    cli,
    emit,
    fail,
    finish,
    given,
    one_line,
    progress,
    say_written,
    stdout_console,
    stream,
)
from deathsphere.cli.options import (
    body_option,
    display_units,
    input_option,
    jobs_option,
    output_options,
    param_option,
    scheduler_option,
    setup_options,
    single,
    stability_option,
    surface_options,
    units_option,
)

#: Figure formats of the map (matplotlib, the plot extra).
FIGURES = {"png": "matplotlib", "svg": "matplotlib", "pdf": "matplotlib"}


@cli.command("map")
@setup_options()
@surface_options()
@param_option("max_g")
@single("--output", type=OutputPath(FIGURES), default=None, metavar="FILE",
        help="Write the figure to FILE (.png, .svg or .pdf); needs pip install 'deathsphere[plot]'.")
@param_option("step")
@stability_option(default=False, help=(
    "Also show the exact linear stability of each orbit (beyond the paper, docs/stability.md): stable and "
    "unstable parts of the allowed region and the boundary between them.  Wheel only: a rolling sphere "
    "has no tilt alpha (and all its horizontal orbits are stable)."))
@jobs_option()
@scheduler_option()
@output_options()
def map_command(side, a, r, diameter, k, g, mu, surface, wall_angle, wall_height, profile, height, turn_radius,
                max_g, output, step, stability, jobs, scheduler, fmt):
    """The allowed (theta, alpha) region of horizontal wheel orbits: the paper's figure.

    Bounded by eq. (0) (the wheel fits), eq. (29) (Omega^2 > 0) and eq. (33)
    (contact); outside the sphere by eqs. (81), (29), (83).  With --mu or
    --max-g the friction and load limits are drawn too.  On a terminal a
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
      deathsphere map --surface cone --diameter 6 --wall-angle 80 \\
          --wall-height 8 --mu 1 --output cone.png
      deathsphere map --surface cylinder --diameter 32ft --wall-height 12ft \\
          --mu 0.8 --max-g 3

    On a drum, a cone, flat ground or a profile (--surface) the map is the
    allowed (height, alpha) region (on flat ground (turn radius, alpha)):
    --height start:stop:step gives the lanes [default: 361 from the floor to
    the wall's top]; --format csv/json the boundary points with whether the
    orbit is feasible just below and above each; on a terminal a character
    plot over (height, alpha) and the allowed intervals of a few lanes.
    --stability there adds the curve 'stability' (the exact linearisation
    on that ground, bisected as on the globe) and on a terminal each lane's
    stable tilts; --jobs N or --scheduler ADDR compute its batches of lanes
    on N processes or a dask cluster (the same output as one), whatever the
    output.  No --step there (docs/limits.md sec. 8); on the globe only
    --format csv/json takes --step, --jobs and --scheduler.
    """
    options = given(side=side, a=a, r=r, diameter=diameter, k=k, g=g, mu=mu, max_g=max_g)
    arena = given(surface=surface, wall_angle=wall_angle, wall_height=wall_height, profile=profile, height=height,
                  turn_radius=turn_radius)
    from deathsphere.api.ride_surfaces import names_a_wall

    if names_a_wall(surface, wall_angle, wall_height, profile):
        # the lanes come back in the unit they were typed in (--wall-height 12ft: ft)
        lane_unit = display_units(None, click.get_current_context().params).unit("length", ("height", "turn_radius"))
        _map_on(arena, options, output, fmt, given(step=step, jobs=jobs, scheduler=scheduler), stability,
                lane_unit)
        return
    if height or turn_radius:
        api.region(**given(height=height, turn_radius=turn_radius))   # refused: the globe's lane is theta
    if output is not None or choose_format(fmt) == "table":
        # the figure and the terminal plot draw exact curves on grids of their own: a
        # step or processes given for the data would be silently ignored there
        _refuse_unused("only the boundary data (--format csv or json) takes it; the figure and the "
                       "terminal plot are drawn on grids of their own",
                       step=step, jobs=jobs, scheduler=scheduler)
    if output is not None:
        from deathsphere.render.figures import PlotExtraMissing, import_matplotlib
        from deathsphere.render.map_figure import plot_map

        try:
            import_matplotlib()  # before the work: a missing extra is one line, at once
            # the curves report no progress (a few seconds with --stability): the bar shows the time taken
            with progress("map", None):
                curves = api.region_curves(stability=stability, **options)
            plot_map(curves, output=output)
        except PlotExtraMissing as exc:
            fail(one_line(str(exc)))
        say_written(output)
        return
    fmt = choose_format(fmt)
    if fmt == "table":
        from deathsphere.render.charplot import char_map, columns_for_width, to_rich

        width = max(40, min(stdout_console().width, 100))
        cells = api.region_cells(stability=stability, columns=columns_for_width(width), **options)
        stdout_console().print(to_rich(char_map(cells)), end="")
        return
    with progress("boundaries", None) as bar:
        table = api.region(stability=stability, progress=bar.update,
                           **given(step=step, jobs=jobs, scheduler=scheduler), **options)
    emit([table], fmt)


def _refuse_unused(why, **typed):
    """A usage error for the first of ``typed`` given where it has no effect."""
    for name, value in typed.items():
        if value is not None:
            raise click.BadParameter(why, param_hint=f"'--{name}'")


def _map_on(arena, options, output, fmt, typed, stability, lane_unit):
    """``map`` off the globe: the figure, the data, or on a terminal the
    chart and the allowed intervals of a few lanes (the lanes beside metres
    in ``lane_unit``, a DisplayUnit or None); ``typed``: --step, --jobs and
    --scheduler as given.  A bar on stderr counts the stability boundary's lanes."""
    if output is not None:
        from deathsphere.render.figures import PlotExtraMissing, import_matplotlib
        from deathsphere.render.lane_map_figure import plot_lane_map

        try:
            import_matplotlib()
            with progress("map", None) as bar:
                curves = api.region_curves(stability=stability, progress=bar.update, **typed, **arena, **options)
            plot_lane_map(curves, output=output)
        except PlotExtraMissing as exc:
            fail(one_line(str(exc)))
        say_written(output)
        return
    fmt = choose_format(fmt)
    if fmt == "table":
        from deathsphere.render.charplot import to_rich
        from deathsphere.render.lane_charplot import drawable, lane_char_map
        from deathsphere.render.lane_map_text import lane_map_text

        with progress("map", None) as bar:
            curves = api.region_curves(stability=stability, progress=bar.update, **typed, **arena, **options)
        if drawable(curves):
            # the chart of the whole wall, then the intervals of a few lanes in numbers
            width = max(40, min(stdout_console().width, 100))
            stdout_console().print(to_rich(lane_char_map(curves, width, lane_unit)), end="")
        stdout_console().print(lane_map_text(curves, unit=lane_unit))
        return
    with progress("boundaries", None) as bar:
        table = api.region(stability=stability, progress=bar.update, **typed, **arena, **options)
    emit([table], fmt)


@cli.command("limits")
@param_option("theta", multiple=True, help="Polar angle(s) of the orbit; without it: the highest orbit possible.")
@param_option("max_g")
@body_option()
@setup_options()
@surface_options()
@input_option("theta, body, side, a, r, k, g, mu, max_g; off the globe height in place of theta")
@output_options()
@units_option()
def limits_command(theta, max_g, body, side, a, r, diameter, k, g, mu, surface, wall_angle, wall_height, profile,
                   height, turn_radius, input, fmt, units):
    """Which tilts alpha give a feasible orbit at theta, and at what speeds (beyond the paper).

    With --theta: the interval(s) of alpha where the wheel fits, Omega^2 > 0
    and it keeps contact, within --mu and --max-g, with the speed range over
    each.  Without --theta: the highest orbit possible (smallest theta) with
    its alpha and speed.  A wheel's tilt is what is chosen: another body is
    refused (in an --input file, its row is invalid with the reason).
    Method: docs/limits.md.

    On a drum, a cone, flat ground or a profile (--surface, docs/surfaces.md)
    the lane is --height (on flat ground --turn-radius) in place of
    --theta; without one: the lowest and the highest lane the friction and
    the load allow (on an upright wall friction and load set no highest
    lane: only the wall's top does).  Method: docs/limits.md sec. 8.

    \b
    Examples:
      deathsphere limits --theta 60 --mu 1.2
      deathsphere limits --mu 1 --max-g 5
      deathsphere limits --theta 30:90:10 --diameter 16ft --mu 1 --max-g 4
      deathsphere limits --surface cylinder --diameter 32ft --height 2m \\
          --mu 1 --max-g 4
      deathsphere limits --surface cone --diameter 6 --wall-angle 80 \\
          --wall-height 8 --mu 1 --max-g 4
    """
    options = given(max_g=max_g, body=body, side=side, a=a, r=r, diameter=diameter, k=k, g=g, mu=mu,
                    surface=surface, wall_angle=wall_angle, wall_height=wall_height, profile=profile)
    lanes = given(height=height, turn_radius=turn_radius)
    fmt = choose_format(fmt)
    shown = display_units(units, click.get_current_context().params)
    if input is not None:
        finish(stream(api.limits_input(input, **given(theta=theta), **lanes, **options), fmt, label="limits",
                      title="Feasible tilts (fit, Omega^2 > 0, contact, mu, load)", units=shown))
        return
    table = api.limits(**given(theta=theta), **lanes, **options)
    title = ("Feasible tilts (fit, Omega^2 > 0, contact, mu, load)" if theta or lanes else
             "The lowest and the highest lane possible" if "lane" in table.names else
             "The highest orbit possible (smallest theta with a feasible tilt)")
    emit([table], fmt, title=title, units=shown)
