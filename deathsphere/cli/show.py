"""``deathsphere show``: an act of several riders sharing one globe
(:func:`deathsphere.api.shows.show`, docs/show.md).

The command parses, calls the API and renders; the plan is validated by
the API, once, before any work (a bad plan is one line naming the rider
and the key, exit status 2)."""

from __future__ import annotations

import re
import sys

import click
from deathsphere.errors import ParameterError
from deathsphere.exitcodes import ExitCode
from deathsphere.cli.base import (
    OutputPath,
    choose_format,
    cli,
    emit,
    fail,
    one_line,
    progress,
    stderr_console,
    stdout_console,
)
from deathsphere.cli.options import output_options, plan_display_units, single, units_option

#: The tables the command writes (``--table``): the riders' lanes, every
#: pair over the act, the falls (of --fail or --monte-carlo) and the
#: Monte Carlo's summary.
TABLES = ("riders", "pairs", "falls", "summary")
#: --output extensions: the act's 3-D view, or the chosen table as a file.
VIEWS = ("html", "gif", "mp4")
OUTPUTS = {"html": None, "gif": "matplotlib", "mp4": "matplotlib", "csv": None, "json": None, "ndjson": None,
           "parquet": "pyarrow"}
FORMATS = ("table", "csv", "json", "ndjson", "parquet")

#: NAME@T[:FRACTION]: a rider's name (anything without '@'), the time in
#: seconds (a trailing s allowed), the fraction of his speed left.
FAIL_SYNTAX = re.compile(r"^(?P<name>[^@]+)@(?P<t>[^:@]+?)(?:s)?(?::(?P<fraction>[^:@]+))?$")


def parse_fail(value: str) -> tuple[str, float, float | None]:
    """``(rider, t [s], speed fraction or None)`` of a ``--fail`` value;
    ValueError with the syntax when it is not ``NAME@T[:FRACTION]``.
    Whether the rider exists and the numbers are in range is the API's
    to say."""
    m = FAIL_SYNTAX.match(value.strip())
    if m is None:
        raise ValueError(f"{value!r} is not NAME@T[:FRACTION] (e.g. Ana@3.5:0.4: Ana at t = 3.5 s drops to "
                         "40 % of her speed)")
    try:
        t = float(m["t"])
        fraction = None if m["fraction"] is None else float(m["fraction"])
    except ValueError:
        raise ValueError(f"{value!r}: T and FRACTION are numbers (NAME@T[:FRACTION], e.g. Ana@3.5:0.4)") from None
    return m["name"].strip(), t, fraction


def _fail_option(ctx, param, values):
    out = []
    for value in values:
        try:
            out.append((*parse_fail(value), value))
        except ValueError as exc:
            raise click.BadParameter(str(exc), ctx=ctx, param=param) from None
    return tuple(out)


def _table_format(fmt: str | None, output: str | None) -> str:
    """The format of the table written: as given, else the --output file's
    extension, else a table on a terminal and CSV when piped."""
    ext = output.rsplit(".", 1)[-1].lower() if output else None
    if ext in VIEWS:
        ext = None
    if fmt is not None and ext is not None and fmt.lower() != ext:
        raise click.UsageError(f"--format {fmt} does not match the --output file {output!r} (.{ext})")
    if (fmt or "").lower() == "parquet" and ext is None:
        raise click.UsageError("--format parquet writes a file: give --output FILE.parquet")
    if ext is not None:
        return ext
    return choose_format(fmt)


def _preflight_view(output: str) -> None:
    """Before any work: a .gif or .mp4 needs its plot extra and encoder."""
    from deathsphere.viewer import ViewerUnavailable, check_view_output

    try:
        check_view_output(output)
    except ViewerUnavailable as exc:
        fail(one_line(str(exc)))


def _check_choices(plan, example, table, fails, monte_carlo, seed, scheduler, output, others=()):
    """The options that do not go together, refused before the plan is read
    (``others``: whether each remaining option was given)."""
    if example:
        if plan is not None or table or fails or monte_carlo is not None or output is not None or seed is not None \
                or scheduler is not None or any(others):
            raise click.UsageError("--example prints the example plan and takes nothing else")
        return
    if plan is None:
        raise click.UsageError("give a plan (deathsphere show PLAN.toml), or --example to print one to start from")
    if fails and monte_carlo is not None:
        raise click.UsageError("give --fail or --monte-carlo, not both")
    if monte_carlo is None and (seed is not None or scheduler is not None):
        raise click.UsageError("--seed and --scheduler go with --monte-carlo N")
    if table == "falls" and not fails and monte_carlo is None:
        raise click.UsageError("--table falls needs --fail NAME@T[:FRACTION] or --monte-carlo N")
    if table == "summary" and monte_carlo is None:
        raise click.UsageError("--table summary is the Monte Carlo's: give --monte-carlo N")
    ext = output.rsplit(".", 1)[-1].lower() if output else None
    if ext in VIEWS and table:
        raise click.UsageError(f"--output {output} draws the act; --table chooses a table to write, not both")
    if ext in VIEWS and monte_carlo is not None:
        raise click.UsageError(f"--output {output} draws the act (with --fail, the fall); not with --monte-carlo")
    if ext in VIEWS:
        # a rider's track draws one fall: two of one rider are refused, not one of them dropped
        first = {}
        for name, _, _, typed in fails:
            if name in first:
                raise click.UsageError(f"--output {output} draws one fall per rider: --fail {first[name]} and "
                                       f"--fail {typed} are both {name}'s (draw them one at a time, or write "
                                       "the falls table)")
            first[name] = typed


def _view(name: str, **kwargs):
    """A terminal view of render.show_views, imported only when a table is drawn."""
    def view(table, total_rows=None):
        from deathsphere.render import show_views

        return getattr(show_views, name)(table, total_rows=total_rows, **kwargs)
    return view


VIEW_OF = {"riders": "riders_view", "pairs": "pairs_view", "falls": "falls_view", "summary": "falls_summary_view"}


def _falls(result, fails, monte_carlo, seed, scheduler):
    """The falls table (and the Monte Carlo's summary, else None)."""
    from deathsphere.table import Table

    if monte_carlo is not None:
        with progress("falls", monte_carlo) as bar:
            return result.falls(monte_carlo, **({"seed": seed} if seed is not None else {}),
                                **({"scheduler": scheduler} if scheduler is not None else {}), progress=bar.update)
    tables = []
    for name, t, f, typed in fails:
        try:
            tables.append(result.fall(name, t, **({"speed_fraction": f} if f is not None else {})))
        except ParameterError as exc:     # named as typed: the API's 't' is the T of --fail NAME@T
            raise click.BadParameter(f"{typed!r}: {exc}", param_hint="'--fail'") from None
    return Table.concat(tables), None


@cli.command("show", short_help="An act of several riders in one globe: lanes, clearance, timing, falls.")
@click.argument("plan", required=False, metavar="PLAN.toml")
@click.option("--example", is_flag=True, default=False,
              help="Print a commented example plan to start from (deathsphere show --example > act.toml).")
@single("--table", "table", type=click.Choice(TABLES, case_sensitive=False), default=None,
        help="The table to write: riders (each lane, checked), pairs (every pair's least clearance over the "
             "act), falls (of --fail or --monte-carlo), summary (the Monte Carlo's) [default: on a terminal "
             "riders and pairs (and the falls); piped, falls with --fail or --monte-carlo, else riders].")
@single("--duration", type=click.FloatRange(0, None, min_open=True), default=None, metavar="SECONDS",
        help="The act's length [s] when the riders' periods are not commensurate; when they are, the act "
             "is their common period and a duration is not used [default: the plan's duration].")
@single("--phase", type=click.Choice(("plan", "auto"), case_sensitive=False), default=None,
        help="auto: each vertical rider's phase, in plan order, that maximises the least clearance (the "
             "safe window is reported) [default: plan, the phases as written].")
@click.option("--fail", "fails", multiple=True, metavar="NAME@T[:FRACTION]", callback=_fail_option,
              help="At time T [s] the rider NAME drops to FRACTION of his speed (0 a dead stop) [default "
                   "fraction: 0.5]: where he loses the wall, where he lands and whom he falls into.  "
                   "Repeatable.")
@single("--monte-carlo", "monte_carlo", type=click.IntRange(1, None), default=None, metavar="N",
        help="N falls of random riders at random times with random speed fractions in [0, 1): the outcomes "
             "and a summary (who hits whom, the worst landing speeds).")
@single("--seed", type=int, default=None, help="Seed of --monte-carlo's draws (the same seed, the same rows).")
# the show's own: it has no --jobs to be kept apart from
@single("--scheduler", default=None, metavar="ADDRESS",
        help="With --monte-carlo: evaluate the falls on the dask.distributed cluster whose scheduler is at "
             "ADDRESS (tcp://host:8786; the distributed extra); the rows are those of a local run.  A scheduler "
             "that does not answer within 5 s is a usage error (importing distributed adds a few seconds before "
             "that).")
@single("--output", type=OutputPath(OUTPUTS), default=None, metavar="FILE",
        help="Draw the act in 3-D: .html (interactive, self-contained), .gif or .mp4 (plot extra; .mp4 "
             "ffmpeg), every rider's envelope moving with the clock, the least-clearance pair marked, with "
             "--fail each fall's path (one fall per rider).  Or write the table to "
             ".csv/.json/.ndjson/.parquet.  Nothing is printed on stdout then.")
@output_options(FORMATS)
@units_option()
def show_command(plan, example, table, duration, phase, fails, monte_carlo, seed, scheduler, output, fmt, units):
    """An act: several riders sharing one globe (docs/show.md).

    PLAN.toml names the globe and every rider's lane (horizontal: height,
    speed, direction, phase; vertical: the loop's azimuth, speed at the
    top, phase).  The riders table checks each lane and its speed margin;
    the pairs table gives every pair's least clearance over the act, when
    and where, the verdict against the plan's min_clearance and the drift
    time (how long a 1 % speed error leaves the pair clear).  --fail
    drops a rider's speed and follows his fall; --monte-carlo draws many
    falls.

    \b
    Examples:
      deathsphere show --example > act.toml
      deathsphere show act.toml
      deathsphere show act.toml --phase auto --table pairs
      deathsphere show act.toml --fail Ben@1.2:0.3
      deathsphere show act.toml --monte-carlo 2000 --seed 1
      deathsphere show act.toml --table pairs --format csv
      deathsphere show act.toml --fail Ben@1.2:0.3 --output act.html
    """
    table = table.lower() if table else None
    _check_choices(plan, example, table, fails, monte_carlo, seed, scheduler, output,
                   [v is not None for v in (duration, phase, fmt, units)])
    if example:
        from deathsphere.api.shows import EXAMPLE_PLAN

        click.echo(EXAMPLE_PLAN, nl=not EXAMPLE_PLAN.endswith("\n"))
        return
    drawn = output is not None and output.rsplit(".", 1)[-1].lower() in VIEWS
    fmt_out = None if drawn else _table_format(fmt, output)
    if drawn:
        if fmt is not None:
            raise click.UsageError(f"--output {output} draws the act: --format does not apply")
        _preflight_view(output)
    from deathsphere.api.shows import show

    options = {k: v for k, v in (("duration", duration), ("phase", phase and phase.lower())) if v is not None}
    try:
        # the pairs (and --phase auto) can take seconds: a bar on a terminal
        with progress("act", None) as bar:
            result = show(plan, **options, progress=bar.update)
    except ParameterError as exc:
        if exc.param in options:        # an option typed: named as click names its own refusals
            raise click.BadParameter(str(exc), param_hint=f"'--{exc.param}'") from None
        # the plan's (its message names the key): never an option that was not typed
        raise click.UsageError(str(exc)) from None
    falls, summary = (None, None)
    if fails or monte_carlo is not None:
        falls, summary = _falls(result, fails, monte_carlo, seed, scheduler)
    if drawn:
        from deathsphere.viewer import write_scene
        from deathsphere.viewer.show_scene import act_scene

        with progress("frames", None) as bar:
            size = write_scene(output, act_scene(result, falls if fails else None), progress=bar.update)
        stderr_console().print(f"deathsphere: wrote {output} ({size / 1e6:.2f} MB)", soft_wrap=True)
        return
    tables = {"riders": result.riders, "pairs": result.pairs, "falls": falls, "summary": summary}
    # the plan's values as typed: a key typed with a unit comes back in it, as an option does
    shown_units = plan_display_units(units, result.plan.typed)
    if fmt_out == "table" and table is None:
        console = stdout_console()
        shown = ["riders", "pairs"] + (["falls"] if fails else []) + (["summary"] if summary is not None else [])
        for k, name in enumerate(shown):
            rendered = emit_view(tables[name], name, result, shown_units)
            if rendered is not None:
                if k:
                    console.print()
                console.print(rendered)
        _finish(result)
        return
    if table is None:
        table = "falls" if falls is not None else "riders"
    emit([tables[table]], fmt_out, view=_view(VIEW_OF[table], result=result, units=shown_units), output=output)
    if output is not None:
        stderr_console().print(f"deathsphere: wrote {output}", soft_wrap=True)
    _finish(result)


def _finish(result) -> None:
    """Exit status 1, with one line on stderr, when a lane is not feasible
    (as a command with invalid rows: the tables are still written)."""
    if result.infeasible:
        who = ", ".join(f"{name} ({status})" for name, status in result.infeasible.items())
        stderr_console().print(f"deathsphere: not feasible as planned: {who}; see the riders' status",
                               style="yellow", soft_wrap=True, markup=False)
        sys.exit(ExitCode.INVALID_ROWS)


def emit_view(table, name: str, result, units=None):
    """The terminal view of one of the act's tables (None for no rows)."""
    from deathsphere.cli.base import terminal_view

    shown = terminal_view([table], view=_view(VIEW_OF[name], result=result,
                                              **({"units": units} if units is not None else {})))
    return None if shown is None else shown[0]
