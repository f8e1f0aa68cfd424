"""``deathsphere stability``: one orbit's exact stability beside the paper's
results (:func:`deathsphere.api.stability`)."""

from __future__ import annotations

from deathsphere import api
from deathsphere.cli.base import (
    body_options,
    choose_format,
    cli,
    emit,
    given,
    number_option,
    output_options,
    stdout_console,
)


@cli.command("stability")
@number_option("theta", "DEG", "Polar angle of the orbit, 0..180.", required=True)
@number_option("alpha", "DEG", "Tilt of the wheel, any angle (205 = -155).", required=True)
@body_options(bodies=("wheel",))
@output_options()
def stability_command(theta, alpha, side, a, r, k, g, mu, fmt):
    """Exact stability of a wheel's horizontal orbit, and the paper's results beside it.

    The exact verdict, growth rate and the two nutation frequencies come from
    the equations of motion linearised about the orbit (docs/stability.md).
    Then each of the paper's results -- the equator (eqs. 133-138), small
    wheels (eq. 207), near the poles (eq. 208) -- as printed and as
    corrected, whether its premise holds here, and its deviation from the
    exact value.

    \b
    Examples:
      deathsphere stability --theta 90 --alpha 45
      deathsphere stability --theta 90 --alpha 80      (unstable: the equator claim fails)
      deathsphere stability --theta 60 --alpha 10 -a 0.03 --format csv
    """
    table = api.stability(**given(theta=theta, alpha=alpha, side=side, a=a, r=r, k=k, g=g, mu=mu))
    fmt = choose_format(fmt)
    if fmt == "table":
        from deathsphere.render.paper_views import stability_view

        stdout_console().print(stability_view(table))
    else:
        emit([table], fmt)
