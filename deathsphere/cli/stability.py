"""``deathsphere stability``: one orbit's exact stability beside the paper's results."""

from __future__ import annotations

import click

from deathsphere.cli.base import (
    Quantity,
    body_options,
    choose_format,
    cli,
    emit,
    make_setup,
    output_options,
    stdout_console,
)


@cli.command("stability")
@click.option("--theta", required=True, type=Quantity("theta"), metavar="DEG", help="Polar angle of the orbit, 0..180.")
@click.option("--alpha", required=True, type=Quantity("alpha"), metavar="DEG",
              help="Tilt of the wheel, any angle (205 = -155).")
@body_options
@output_options()
def stability_command(theta, alpha, body, side, a, r, k, g, mu, fmt):
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
    from deathsphere.results.stability_report import stability_report

    setup = make_setup(body, side, a, r, k, g, mu)
    if setup.body != "wheel":
        raise click.UsageError("stability compares a wheel's orbit with the paper; for a sphere see the "
                               "stability columns of `deathsphere orbit --body sphere`")
    table = stability_report(setup, theta, alpha)
    fmt = choose_format(fmt)
    if fmt == "table":
        from deathsphere.render.paper_views import stability_view

        stdout_console().print(stability_view(table, setup))
    else:
        emit([table], fmt)
