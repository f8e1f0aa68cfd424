"""``deathsphere table1`` and ``deathsphere verify``: the paper, checked."""

from __future__ import annotations

import click

from deathsphere import api
from deathsphere.cli.base import (
    choose_format,
    cli,
    emit,
    given,
    progress,
    stdout_console,
)
from deathsphere.cli.options import jobs_option, output_options


@cli.command("table1")
@output_options()
def table1_command(fmt):
    """The paper's Table 1: printed mu, v_cm and "No. of g's" beside the computed values.

    Wheel a = 0.3 m, k = 1/2 in a sphere r = 3.0 m, standard gravity.  The
    note column names every disagreement; docs/errata.md explains them.

    \b
    Example:
      deathsphere table1
      deathsphere table1 --format csv
    """
    table = api.table1()
    fmt = choose_format(fmt)
    if fmt == "table":
        from deathsphere.render.paper_views import table1_view

        stdout_console().print(table1_view(table, api.table1_printed()))
    else:
        emit([table], fmt)


@cli.command("verify")
@click.option("--claim", "claims", multiple=True, metavar="ID", help="Check only this claim (repeatable).")
@jobs_option()
@output_options()
def verify_command(claims, jobs, fmt):
    """Check every quantitative claim of the paper: a checklist with the evidence.

    Each claim (Table 1, the inequalities and limits of each section, the
    figure, ...) is recomputed from this package's physics and marked
    confirmed, corrected (right in substance, wrong in a sign, a factor, a
    label or a digit: see docs/errata.md) or refuted, with numbers.

    \b
    Examples:
      deathsphere verify
      deathsphere verify --claim T1-g --claim E28
      deathsphere verify --format csv
    """
    fmt = choose_format(fmt)
    with progress("checking claims", api.n_claims(claims)) as bar:
        table = api.verify(claims, progress=lambda claim: bar.advance(1, description=claim.id),
                           **given(jobs=jobs))
    if fmt == "table":
        from deathsphere.render.paper_views import checklist_view

        stdout_console().print(checklist_view(table, api.verify_counts(table)))
    else:
        emit([table], fmt)
