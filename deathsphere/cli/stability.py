"""``deathsphere stability``: orbits' exact stability beside the paper's
results (:func:`deathsphere.api.stability`, :func:`deathsphere.api.stability_input`)."""

from __future__ import annotations

import click

from deathsphere import api
from deathsphere.cli.orbit import one_hold
from deathsphere.cli.base import (
    choose_format,
    cli,
    emit,
    finish,
    given,
    stdout_console,
    stream,
)
from deathsphere.cli.options import (
    body_option,
    input_option,
    output_options,
    param_option,
    params_options,
    setup_options,
    surface_options,
)


@cli.command("stability")
@param_option("theta", multiple=True)
@params_options("alpha", "speed", "com_speed", "omega", "omega3",
                multiple=("alpha", "speed", "com_speed", "omega", "omega3"))
@body_option()
@setup_options()
@surface_options()
@input_option("theta, alpha, speed, com_speed, omega, omega3, body, side, a, r, k, g, mu; off the globe height")
@output_options()
def stability_command(theta, alpha, speed, com_speed, omega, omega3, body, side, a, r, diameter, k, g, mu, surface,
                      wall_angle, wall_height, profile, height, turn_radius, input, fmt):
    """Exact stability of horizontal orbits, and the paper's results beside it.

    The orbits are those orbit gives for the same options.  For each: the
    exact verdict, growth rate and the two nutation frequencies from the
    equations of motion linearised about the orbit (docs/stability.md);
    then, for a wheel, each of the paper's results -- the equator (eqs.
    133-138), small wheels (eq. 207), near the poles (eq. 208) -- as
    printed and as corrected, whether its premise holds here, and its
    deviation from the exact value.

    \b
    Examples:
      deathsphere stability --theta 90 --alpha 45
      deathsphere stability --theta 90 --alpha 80    (unstable, unlike the paper)
      deathsphere stability --theta 60 --alpha 10 -a 0.03 --format csv
      deathsphere stability --theta 90 --speed 40km/h --diameter 16ft
      deathsphere stability --theta 90 --com-speed 40km/h --diameter 16ft
      deathsphere stability --body sphere --theta 60 --omega3 80
      deathsphere stability --surface cylinder --diameter 32ft --height 2 \\
          --alpha 10

    On a drum, a cone, flat ground or a profile (--surface, the lane
    --height or --turn-radius) only the exact rows apply: the paper's
    results are the globe's, and the exact rows' note says so.
    """
    options = given(body=body, side=side, a=a, r=r, diameter=diameter, k=k, g=g, mu=mu, surface=surface,
                    wall_angle=wall_angle, wall_height=wall_height, profile=profile)
    one_hold(alpha, speed, com_speed, omega)
    orbit = given(theta=theta, height=height, turn_radius=turn_radius, alpha=alpha, speed=speed,
                  com_speed=com_speed, omega=omega, omega3=omega3)
    fmt = choose_format(fmt)
    if input is None and not (theta or height or turn_radius):
        raise click.UsageError("Missing option '--theta' (off the globe '--height' or '--turn-radius'; or give "
                               "--input FILE)")
    if input is not None:
        finish(stream(api.stability_input(input, **orbit, **options), fmt, label="stability",
                      title="Stability of each orbit", view=_views if fmt == "table" else None))
        return
    table = api.stability(**_grid(orbit), **options)
    if fmt == "table":
        stdout_console().print(_views(table))
    else:
        emit([table], fmt)


def _grid(orbit: dict) -> dict:
    """The command line's values (text, perhaps ranges or with units) as the
    API's arrays: the lane (theta; off the globe height or turn_radius) down, the orbit's other input across (every
    combination, as orbit evaluates them)."""
    from deathsphere.api.arguments import checked_axis, refuse_large_grid, value_counts
    from deathsphere.api.orbits import MAX_ORBIT_ROWS

    refuse_large_grid(value_counts(orbit), command="stability", limit=MAX_ORBIT_ROWS,
                      instead="use 'deathsphere sweep' (it streams the orbits, stability columns included) or "
                              "split the ranges into several runs")
    grid = {name: checked_axis(name, list(values)).values() for name, values in orbit.items()}
    lanes = ("theta", "height", "turn_radius")       # the lane down, as orbit evaluates them
    return {name: (values[:, None] if name in lanes else values[None, :]) for name, values in grid.items()}


def _views(table, total_rows=None):
    """One view per orbit of a report (rows grouped by input_row and branch)."""
    from rich.console import Group

    from deathsphere.render.paper_views import stability_view

    keys = list(zip(table["input_row"].tolist(), table["branch"].tolist()))
    starts = [i for i in range(len(keys)) if i == 0 or keys[i] != keys[i - 1]] + [len(keys)]
    return Group(*(stability_view(table[starts[j]:starts[j + 1]]) for j in range(len(starts) - 1)))
