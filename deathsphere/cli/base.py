"""The ``deathsphere`` command line: the group, the shared options and
helpers, and the entry point.  Each command lives in a module of its own
(:mod:`deathsphere.cli.orbit`, ...); none computes physics: they parse,
call the model and render.  Usage errors become one line on stderr with
exit status 2 (:class:`DeathsphereGroup`); results go to stdout, diagnostics
to stderr.
"""

from __future__ import annotations

import errno
import importlib.util
import math
import os
import sys
from contextlib import contextmanager

import click
import numpy as np
from rich.console import Console

from deathsphere import __version__
from deathsphere.constants import (
    BODIES,
    SIDES,
    STANDARD_GRAVITY,
    TABLE1_SPHERE_RADIUS,
    TABLE1_WHEEL_RADIUS,
)
from deathsphere.exitcodes import ExitCode
from deathsphere.grid import Axis, RangeError, Segment, parse_segment
from deathsphere.model import Setup, Table
from deathsphere.params import PARAMS, ParameterError, check, first_problem
from deathsphere.render.fit_table import MAX_TERMINAL_ROWS
from deathsphere.render.formats import FORMATS, write_csv, write_json, write_ndjson
from deathsphere.render.orbit_views import write_rich_table

CONTEXT = {"help_option_names": ["-h", "--help"], "max_content_width": 100}


def stdout_console() -> Console:
    # rich honours NO_COLOR and TERM=dumb itself
    return Console(highlight=False)


def stderr_console() -> Console:
    return Console(stderr=True, highlight=False)


# ---------------------------------------------------------------------------
# shared options


def output_options(formats=FORMATS):
    def decorator(f):
        return click.option(
            "--format", "fmt", type=click.Choice(formats, case_sensitive=False), default=None,
            help="Output format [default: table on a terminal, csv when piped].")(f)
    return decorator


def body_options(f):
    options = [
        click.option("--body", type=click.Choice(BODIES, case_sensitive=False), default="wheel",
                     show_default=True, help="Rolling body."),
        click.option("--side", type=click.Choice(SIDES, case_sensitive=False), default="inside",
                     show_default=True, help="Body inside or outside the fixed sphere."),
        click.option("-a", "--wheel-radius", "a", type=Quantity("a"), default=TABLE1_WHEEL_RADIUS,
                     show_default=True, metavar="M", help="Body radius a [m]."),
        click.option("-r", "--sphere-radius", "r", type=Quantity("r"), default=TABLE1_SPHERE_RADIUS,
                     show_default=True, metavar="M", help="Fixed sphere radius r [m]."),
        click.option("-k", "--inertia", "k", type=Quantity("k"), default=None, metavar="K",
                     help="Inertia factor k: I11 = 2 k m a^2 for a wheel, I = k m a^2 for a sphere "
                          "[default: 0.5 wheel, 0.4 sphere]."),
        click.option("-g", "--gravity", "g", type=Quantity("g"), default=STANDARD_GRAVITY, show_default=True,
                     metavar="M_S2", help="Gravitational acceleration [m/s^2]."),
        click.option("--mu", type=Quantity("mu"), default=math.inf, metavar="MU",
                     help="Friction coefficient available; orbits needing more have status 'slips' "
                          "[default: unlimited]."),
    ]
    for option in reversed(options):
        f = option(f)
    return f


def make_setup(body, side, a, r, k, g, mu) -> Setup:
    """A :class:`Setup` from options already checked one by one; what is
    left to refuse here is a combination (e.g. r <= a inside)."""
    try:
        return Setup(body=body.lower(), side=side.lower(), a=a, r=r, k=k, g=g, mu=mu)
    except ValueError as exc:
        raise click.UsageError(str(exc)) from None


class Quantity(click.ParamType):
    """One number, checked against its domain in :mod:`deathsphere.params`
    at parse time: a bad value is a usage error (exit 2) before any work."""

    def __init__(self, name: str):
        self.param_name = name
        self.name = PARAMS[name].unit or "number"

    def convert(self, value, param, ctx):
        if isinstance(value, float):
            return value
        try:
            number = float(str(value).strip())
        except ValueError:
            self.fail(f"{self.param_name}: {value!r} is not a number", param, ctx)
        try:
            return check(self.param_name, number)
        except ParameterError as exc:
            self.fail(str(exc), param, ctx)


class Values(click.ParamType):
    """One value or ``start:stop:step`` range of a repeatable option, as a
    lazy :class:`~deathsphere.grid.Segment` whose every value is in the
    domain (a range is monotone: its ends decide)."""

    name = "values"

    def __init__(self, name: str):
        self.param_name = name

    def convert(self, value, param, ctx):
        if isinstance(value, Segment):
            return value
        try:
            seg = parse_segment(str(value), self.param_name)
        except RangeError as exc:
            self.fail(str(exc).split(": ", 1)[-1], param, ctx)
        reason = first_problem(self.param_name, [seg.first, seg.last])
        if not reason and PARAMS[self.param_name].nonzero and Axis([seg]).contains_zero():
            reason = f"{self.param_name} must not be 0 ({PARAMS[self.param_name].allowed()})"
        if reason:
            self.fail(reason, param, ctx)
        return seg


def axis(segments, default=None) -> Axis:
    """The axis of a repeatable :class:`Values` option (``default`` if not given)."""
    if segments:
        return Axis(list(segments))
    return Axis.of([math.nan if default is None else default])


class OutputPath(click.ParamType):
    """A file to write, checked before any work: a known extension, an
    existing writable directory, not a directory itself, and the optional
    package the format needs installed."""

    name = "file"

    def __init__(self, extensions: dict[str, str | None]):
        #: extension -> the module it needs (None: nothing beyond the core)
        self.extensions = extensions

    def convert(self, value, param, ctx):
        path = os.fspath(value)
        if os.path.isdir(path) or path.endswith(os.sep):
            self.fail(f"{path!r} is a directory, not a file name", param, ctx)
        ext = os.path.splitext(path)[1].lower().lstrip(".")
        if ext not in self.extensions:
            names = ["." + e for e in self.extensions]
            self.fail(f"{path!r}: the file name must end in {', '.join(names[:-1])} or {names[-1]}", param, ctx)
        folder = os.path.dirname(os.path.abspath(path))
        if not os.path.isdir(folder):
            self.fail(f"{path!r}: the directory {os.path.dirname(path) or '.'!r} does not exist", param, ctx)
        if not os.access(folder, os.W_OK) or (os.path.exists(path) and not os.access(path, os.W_OK)):
            self.fail(f"{path!r}: no permission to write there", param, ctx)
        module = self.extensions[ext]
        if module is not None and importlib.util.find_spec(module) is None:
            raise click.UsageError(f"writing .{ext} needs {module}: pip install 'deathsphere[plot]'")
        return path


def input_option(fields: str):
    return click.option(
        "--input", "input_path", default=None, metavar="FILE|-",
        help=f"CSV of requests, one per line; its header names the options ({fields}); '-' reads stdin. "
             "Every line after the header gives one row (input_row = its line number after the header); "
             "a bad line is an invalid row with its reason.")


def open_requests(path: str, fields: dict, defaults: dict, ignore=(), aliases=None):
    """A :class:`~deathsphere.inputs.RequestReader` over ``--input``; an
    unreadable input (missing, not CSV text, bad header) is a usage error."""
    from deathsphere.inputs import ALIASES, InputError, RequestReader, open_input

    try:
        stream = open_input(path)
        return RequestReader(stream, fields, defaults, source="stdin" if path == "-" else path,
                             aliases=ALIASES if aliases is None else aliases, ignore=ignore)
    except InputError as exc:
        raise click.UsageError(str(exc)) from None


class _Progress:
    """What a command reports progress to: ``advance(n)`` or ``update(done, total)``.
    Without a bar (not a terminal) both do nothing."""

    def __init__(self, bar=None, task=None):
        self.bar, self.task = bar, task

    def advance(self, n: int = 1, description: str | None = None) -> None:
        if self.bar is not None:
            self.bar.update(self.task, advance=n, **({"description": description} if description else {}))

    def update(self, done: int, total: int) -> None:
        if self.bar is not None:
            self.bar.update(self.task, completed=done, total=total)


@contextmanager
def progress(label: str, total: int, streaming: bool = False):
    """A rich progress bar on stderr when stderr is a terminal (nothing
    otherwise, so pipes and logs stay clean); yields a :class:`_Progress`.

    ``streaming``: results go to stdout while the bar runs; if stdout is the
    same terminal the rows themselves show the progress, and a bar would
    mix with them (a CSV header landing on the bar's line), so none is drawn."""
    if not _isatty(sys.stderr) or (streaming and _isatty(sys.stdout)):
        yield _Progress()
        return
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
    )

    with Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
                  console=stderr_console(), transient=True, redirect_stdout=False, redirect_stderr=False) as bar:
        yield _Progress(bar, bar.add_task(label, total=total))


def _isatty(stream) -> bool:
    try:
        return stream is not None and stream.isatty()
    except (ValueError, OSError):  # closed
        return False


def choose_format(fmt: str | None) -> str:
    """The output format: as given, else a table on a terminal and CSV when piped."""
    if fmt:
        return fmt.lower()
    return "table" if _isatty(sys.stdout) else "csv"


def concat(tables: list[Table]) -> Table:
    if len(tables) == 1:
        return tables[0]
    return Table({n: np.concatenate([t[n] for t in tables]) for n in tables[0].names})


class Tally:
    """Rows written and rows invalid, counted as the chunks stream past."""

    def __init__(self):
        self.rows = self.invalid = 0

    def count(self, tables):
        for table in tables:
            self.rows += len(table)
            if "status" in table:
                self.invalid += int(np.count_nonzero(table["status"] == "invalid"))
            yield table


def run_batches(batches, evaluate, fmt: str, *, label: str, total: int | None = None,
                title: str | None = None, view=None, keep=None, output: str | None = None) -> Tally:
    """Evaluate request batches one by one and write each result as it
    comes (CSV/JSON/NDJSON stream with flat memory; the terminal table keeps
    the first rows and counts the rest), with a progress bar on a terminal.

    ``batches`` yields ``(n_requests, request)``; ``keep`` filters rows of
    each result (``--only``); ``output`` is a file to write instead of
    stdout (see :func:`emit`).  Returns the :class:`Tally`.
    """
    tally = Tally()
    # rows going to a file leave the terminal to the progress bar
    streaming = fmt != "table" and output is None

    def results(bar):
        for n, req in batches:
            table = evaluate(req)
            if keep is not None:
                table = keep(table)
            yield table
            bar.advance(n)

    with progress(label, total, streaming=streaming) as bar:
        emit(tally.count(results(bar)), fmt, title, view, output=output)
    return tally


def finish(tally: Tally) -> None:
    """Exit status 1, with a note on stderr, when some rows were invalid."""
    if tally.invalid:
        stderr_console().print(f"deathsphere: {tally.invalid} input row(s) invalid; see their reason column",
                               style="yellow")
        sys.exit(ExitCode.INVALID_ROWS)


def emit(chunks, fmt: str, title: str | None = None, view=None, output: str | None = None) -> int:
    """Write tables in the chosen format to stdout (or to the file
    ``output``, already checked by :class:`OutputPath`); returns the row count.

    The terminal view draws at most :data:`MAX_TERMINAL_ROWS` rows (it
    still consumes every chunk, so the count and the exit status are those
    of the whole result) and says how many it left out.  ``parquet`` needs
    ``output`` (a binary file with its own row groups, never a terminal)."""
    if fmt == "parquet":
        from deathsphere.render.compiled import write_parquet

        return write_parquet(chunks, output)
    writer = {"csv": write_csv, "json": write_json, "ndjson": write_ndjson}.get(fmt)
    if writer is not None and output is not None:
        with open(output, "w", encoding="utf-8", newline="") as out:
            return writer(chunks, out)
    if writer is not None:
        return writer(chunks, sys.stdout)
    head, total = [], 0
    for table in chunks:
        if total < MAX_TERMINAL_ROWS:
            head.append(table)
        total += len(table)
    if not head:
        return 0
    table = concat(head)
    if len(table) > MAX_TERMINAL_ROWS:
        table = Table({n: c[:MAX_TERMINAL_ROWS] for n, c in table.columns.items()})
    if view is not None:
        stdout_console().print(view(table, total_rows=total))
        return total
    write_rich_table(table, stdout_console(), title, total_rows=total)
    return total


class _OutputFailed(Exception):
    """An OSError met while writing the results (not an input problem)."""


class DeathsphereGroup(click.Group):
    """A click group whose ``main`` is the one place where failures become
    exit statuses (docs/contract.md, "Exit status"): a usage error is one
    line on stderr and status 2; a failed write of the results (stdout
    closed, disk full) one line and status 3; a reader that stops reading
    (``| head``) a quiet status 0; Ctrl-C status 130.  (Done here rather
    than in a wrapper so that click's CliRunner sees it.)"""

    def invoke(self, ctx):
        try:
            rv = super().invoke(ctx)
            sys.stdout.flush()  # a full disk shows at the flush: report it here, not at exit
            return rv
        except OSError as exc:
            # click swallows EPIPE itself (exit 1) if this reaches it; input
            # problems are turned into usage errors where the input is read,
            # so an OSError here comes from writing
            raise _OutputFailed(exc) from None

    def main(self, args=None, prog_name=None, complete_var=None, standalone_mode=True, **extra):
        args = sys.argv[1:] if args is None else list(args)
        if sys.stdout is None:  # started with stdout closed (`>&-`)
            click.echo("deathsphere: error: cannot write the results: standard output is closed", err=True)
            sys.exit(ExitCode.OUTPUT)
        if not args:  # bare `deathsphere`: the help as a page, not as an error line
            with self.make_context(prog_name or "deathsphere", ["--help"], resilient_parsing=True) as ctx:
                click.echo(self.get_help(ctx))
            sys.exit(ExitCode.OK)
        try:
            code = super().main(args=args, prog_name=prog_name or "deathsphere",
                                complete_var=complete_var, standalone_mode=False, **extra)
        except click.exceptions.UsageError as exc:
            command = exc.ctx.command_path if exc.ctx is not None else "deathsphere"
            fail(f"{one_line(exc.format_message())} (see '{command} --help')")
        except ParameterError as exc:  # the API's validation, reached through a command
            fail(f"{one_line(str(exc))} (see 'deathsphere {_command_name(args)} --help')")
        except click.exceptions.ClickException as exc:
            fail(one_line(exc.format_message()))
        except (click.exceptions.Abort, KeyboardInterrupt):
            click.echo("deathsphere: interrupted", err=True)
            sys.exit(ExitCode.INTERRUPTED)
        except _OutputFailed as failed:
            exc = failed.args[0]
            _silence_stdout()
            if exc.errno == errno.EPIPE or isinstance(exc, BrokenPipeError):
                sys.exit(ExitCode.OK)  # the reader went away (`| head`): not an error
            click.echo(f"deathsphere: error: cannot write the results: {exc.strerror or exc}", err=True)
            sys.exit(ExitCode.OUTPUT)
        sys.exit(code or 0)


def _command_name(args) -> str:
    return next((a for a in args if not a.startswith("-")), "")


def _silence_stdout() -> None:
    """Point stdout at /dev/null so that Python's flush at exit does not
    fail a second time (and print a traceback) on the dead stream."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        pass


def one_line(message: str) -> str:
    return " ".join(message.split())


def fail(message: str):
    click.echo(f"deathsphere: error: {message}", err=True)
    sys.exit(ExitCode.USAGE)


# ---------------------------------------------------------------------------
# commands


@click.group(cls=DeathsphereGroup, context_settings=CONTEXT)
@click.version_option(__version__, "-V", "--version", prog_name="deathsphere")
def cli():
    """Orbits of a wheel or sphere rolling without slipping on a fixed sphere:
    the motorcycle "globe of death" as physics, after K. T. McDonald,
    "Circular Orbits Inside the Sphere of Death" (1993).

    \b
    Examples:
      deathsphere orbit --theta 60 --alpha 10          one orbit, every quantity
      deathsphere orbit --theta 30:90:15 --alpha 10 --format csv
      deathsphere vertical --theta 90 --v-top 6         a vertical loop
      deathsphere orbit --body sphere --theta 60 --omega3 80
      deathsphere sweep --theta 5:175:1 --alpha 1:89:1 --only ok
      deathsphere map                                   the allowed region (paper's figure)
      deathsphere limits --mu 1 --max-g 5               the highest orbit a rider can hold
      deathsphere table1                                the paper's Table 1, checked
      deathsphere verify                                every claim of the paper, checked
      deathsphere simulate --theta 60 --alpha 10        integrate the exact equations
    """


# ---------------------------------------------------------------------------
# entry point


def main(argv=None) -> None:
    """Console-script entry point (see :class:`DeathsphereGroup` for exit codes)."""
    cli.main(args=argv)
