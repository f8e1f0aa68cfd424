"""The ``deathsphere`` command line: the group, the shared options and
helpers, and the entry point.

Each command lives in a module of its own (:mod:`deathsphere.cli.orbit`,
...) and only parses its options, calls the function of the same name in
:mod:`deathsphere.api` with them as typed (the API checks every value and
supplies every default: one place) and renders what comes back.  A
:class:`~deathsphere.params.ParameterError` from the API becomes click's
usage error naming the option (:class:`Command`); usage errors are one line
on stderr with exit status 2 (:class:`DeathsphereGroup`); results go to
stdout, diagnostics to stderr.  rich is imported only to draw (a terminal
table, a progress bar, a note on stderr), so a piped command never pays for it.
"""

from __future__ import annotations

import errno
import math
import importlib.util
import os
import sys
import threading
import time
from contextlib import contextmanager
from functools import partial

import click

from deathsphere import __version__
from deathsphere.exitcodes import ExitCode
from deathsphere.memory import reuse_freed_memory
from deathsphere.threads import leave_a_core_to_the_evaluation
from deathsphere.params import ParameterError
from deathsphere.writers.stream import write_csv, write_json, write_ndjson

CONTEXT = {"help_option_names": ["-h", "--help"], "max_content_width": 80}


def stdout_console():
    from rich.console import Console

    # rich honours NO_COLOR and TERM=dumb itself
    return Console(highlight=False)


def stderr_console():
    from rich.console import Console

    return Console(stderr=True, highlight=False)


def given(**options) -> dict:
    """The options the user gave (None and an empty repeated option are
    left out, so that the API's own defaults apply)."""
    return {name: value for name, value in options.items() if value is not None and value != ()}


class Command(click.Command):
    """A command whose API errors are usage errors naming their option: a
    :class:`ParameterError` about ``theta`` reads ``Invalid value for
    '--theta': ...``, as if click had refused the value itself."""

    def invoke(self, ctx):
        try:
            return super().invoke(ctx)
        except ParameterError as exc:
            option = next((p for p in self.params if exc.param is not None and p.name == exc.param), None)
            if option is not None and exc.missing:
                raise click.MissingParameter(ctx=ctx, param=option) from None
            if option is not None:
                raise click.BadParameter(str(exc), ctx=ctx, param=option) from None
            raise click.UsageError(str(exc), ctx=ctx) from None


# ---------------------------------------------------------------------------
# shared options: deathsphere.cli.options (from the parameter registry)


#: The optional package an output needs -> the extra that installs it.
EXTRAS = {"matplotlib": "plot", "pyarrow": "fast"}


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
            extra = EXTRAS.get(module, "plot")
            raise click.UsageError(f"writing .{ext} needs {module}: pip install 'deathsphere[{extra}]'")
        return path


#: Work that ends sooner draws no progress bar: a bar that flashes up for a
#: fraction of a second only leaves a flicker (or, mixed with output, residue).
#: The environment variable DEATHSPHERE_PROGRESS_DELAY (seconds) sets it for
#: a run: 0 shows the bar of any work at once (the tests of the bar use it,
#: so that they need not run seconds of work to see one).
PROGRESS_DELAY_S = 1.0


def _progress_delay() -> float:
    text = os.environ.get("DEATHSPHERE_PROGRESS_DELAY", "")
    try:
        delay = float(text)
    except ValueError:
        return PROGRESS_DELAY_S
    return delay if math.isfinite(delay) and delay >= 0 else PROGRESS_DELAY_S


class _Progress:
    """What a command reports progress to: ``advance(n)`` or ``update(done, total)``.
    Without a bar (not a terminal) both do nothing.  The bar is drawn only
    once the work has run :data:`PROGRESS_DELAY_S`."""

    def __init__(self, bar=None, task=None, delay: float = PROGRESS_DELAY_S):
        self.bar, self.task, self.delay = bar, task, delay
        self.started = False
        self._since = time.monotonic()
        self._lock = threading.Lock()

    def _show(self) -> None:
        # also called from the timer of progress() (work that reports nothing)
        with self._lock:
            if not self.started and time.monotonic() - self._since >= self.delay:
                self.bar.start()
                self.started = True

    def _stop(self) -> None:
        with self._lock:
            if self.started:
                self.bar.stop()
            self.started = True  # a timer firing late draws nothing

    def advance(self, n: int = 1, description: str | None = None) -> None:
        if self.bar is not None:
            self.bar.update(self.task, advance=n, **({"description": description} if description else {}))
            self._show()

    def update(self, done: int, total: int) -> None:
        if self.bar is not None:
            self.bar.update(self.task, completed=done, total=total)
            self._show()


@contextmanager
def progress(label: str, total: int, streaming: bool = False):
    """A rich progress bar on stderr when stderr is a terminal (nothing
    otherwise, so pipes and logs stay clean), drawn only for work that runs
    longer than :data:`PROGRESS_DELAY_S` and removed when it ends; yields a
    :class:`_Progress`.

    ``streaming``: results go to stdout while the bar runs; if stdout is the
    same terminal the rows themselves show the progress, and a bar would
    mix with them (a CSV header landing on the bar's line), so none is drawn.

    Work that reports nothing (``total`` None and no call) still shows its
    bar once it has run :data:`PROGRESS_DELAY_S`: a pulse and the time
    elapsed, so that a long wait is never a silent one."""
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

    bar = Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
                   console=stderr_console(), transient=True, redirect_stdout=False, redirect_stderr=False)
    delay = _progress_delay()
    state = _Progress(bar, bar.add_task(label, total=total), delay)
    timer = threading.Timer(delay, state._show)
    timer.daemon = True
    timer.start()
    try:
        yield state
    finally:
        timer.cancel()
        state._stop()


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


class Tally:
    """Rows written and rows invalid, counted as the chunks stream past."""

    def __init__(self):
        self.rows = self.invalid = 0

    def count(self, tables):
        for table in tables:
            self.rows += len(table)
            if "status" in table:
                self.invalid += int((table["status"] == "invalid").sum())
            yield table


def stream(chunks, fmt: str, *, label: str, title: str | None = None, view=None,
           output: str | None = None, units=None) -> Tally:
    """Write the tables of an :class:`~deathsphere.api.Chunks` as they come
    (CSV/JSON/NDJSON with flat memory; the terminal table keeps the first
    rows and counts the rest), with a progress bar on a terminal that
    follows ``chunks.done`` of ``chunks.total``.  ``output`` is a file to
    write instead of stdout (see :func:`emit`); ``units``: the display
    units of the terminal view (:func:`terminal_view`).  Returns the :class:`Tally`."""
    tally = Tally()
    # rows going to a file leave the terminal to the progress bar
    streaming = fmt != "table" and output is None

    def tables(bar):
        for table in chunks:
            yield table
            bar.update(chunks.done, chunks.total)

    with progress(label, chunks.total, streaming=streaming) as bar:
        if fmt == "table":
            # read everything while the bar runs; draw once it is gone, so
            # that no trace of it is left in the table
            shown = terminal_view(tally.count(tables(bar)), title, view, units)
        else:
            emit(tally.count(tables(bar)), fmt, title, view, output=output, expected=chunks.total)
    if fmt == "table" and shown is not None:
        stdout_console().print(shown[0])
    return tally


#: Rows per piece when a table computed whole is written piece by piece
#: (:func:`pieces`): a progress bar's step, a few tenths of a second of CSV.
PIECE_ROWS = 50_000


def pieces(table, rows: int = PIECE_ROWS):
    """A table computed whole as :class:`~deathsphere.api.streams.Chunks`
    of consecutive rows, for :func:`stream` to write with its progress bar
    (writing a million rows takes longer than computing them).  A table of
    one piece is handed on as it is (a grid keeps its shape for the view)."""
    from deathsphere.api.streams import Chunks

    n = len(table)
    if n <= rows:
        return Chunks(iter([(n, table)]), total=n)
    return Chunks(((min(rows, n - start), table[start:start + rows]) for start in range(0, n, rows)), total=n)


def say_written(output: str, rows: int | None = None, size: int | None = None) -> None:
    """The one line on stderr naming a file a command wrote: with its row
    count (a table) or its size (a page, a figure), when known."""
    what = f" ({rows} row{'s' if rows != 1 else ''})" if rows is not None else \
        f" ({size / 1e6:.2f} MB)" if size is not None else ""
    stderr_console().print(f"deathsphere: wrote {output}{what}", soft_wrap=True, markup=False, highlight=False)


def collect(chunks, label: str):
    """Every table of an :class:`~deathsphere.api.Chunks` joined into one
    (a result needed whole, e.g. to summarise it), with the progress bar
    of :func:`stream` while they are evaluated."""
    from deathsphere.table import Table

    tables = []
    with progress(label, chunks.total) as bar:
        for table in chunks:
            tables.append(table)
            bar.update(chunks.done, chunks.total)
    return Table.concat(tables)


def finish(tally: Tally) -> None:
    """Exit status 1, with a note on stderr, when some rows were invalid."""
    if tally.invalid:
        stderr_console().print(f"deathsphere: {tally.invalid} input row(s) invalid; see their reason column",
                               style="yellow")
        sys.exit(ExitCode.INVALID_ROWS)


def emit(chunks, fmt: str, title: str | None = None, view=None, output: str | None = None,
         expected: int | None = None, units=None) -> int:
    """Write tables in the chosen format to stdout (or to the file
    ``output``, already checked by :class:`OutputPath`); returns the row count.

    The terminal view draws at most :data:`MAX_TERMINAL_ROWS` rows (it
    still consumes every chunk, so the count and the exit status are those
    of the whole result) and says how many it left out.  ``parquet`` needs
    ``output`` (a binary file with its own row groups, never a terminal).
    ``expected``: the rows to come when known (a sweep's grid), which lets
    a long CSV take the compiled writer from its first chunk."""
    if fmt == "parquet":
        from deathsphere.writers.parquet import write_parquet

        return write_parquet(chunks, output)
    writer = {"csv": write_csv, "json": write_json, "ndjson": write_ndjson}.get(fmt)
    if writer is write_csv:
        writer = partial(write_csv, expected=expected)
    if writer is not None and output is not None:
        from deathsphere.writers.atomic import atomic_file

        with atomic_file(output, "w", encoding="utf-8", newline="") as out:
            return writer(chunks, out)
    if writer is not None:
        return writer(chunks, sys.stdout)
    shown = terminal_view(chunks, title, view, units)
    if shown is None:
        return 0
    stdout_console().print(shown[0])
    return shown[1]


def terminal_view(chunks, title: str | None = None, view=None, units=None):
    """``(renderable, rows read)``: the terminal view of the tables in
    ``chunks`` (every chunk is read, so the count and the exit status are
    those of the whole result; at most :data:`MAX_TERMINAL_ROWS` rows are
    drawn), or None for no rows.  ``units``: the
    :class:`~deathsphere.render.display_units.DisplayUnits` of the default
    view (a ``view`` of a command's own carries its own)."""
    from deathsphere.render.orbit_views import rich_table
    from deathsphere.render.terminal_table import MAX_TERMINAL_ROWS
    from deathsphere.table import Table

    head, total = [], 0
    for table in chunks:
        if total < MAX_TERMINAL_ROWS:
            head.append(table)
        total += len(table)
    if not head:
        return None
    table = Table.concat(head)
    if len(table) > MAX_TERMINAL_ROWS:
        table = table[:MAX_TERMINAL_ROWS]
    if view is not None:
        shown = view(table, total_rows=total)
    else:
        shown = rich_table(table, title, total_rows=total, **({"units": units} if units is not None else {}))
    return shown, total


class _OutputFailed(Exception):
    """An OSError met while writing the results (not an input problem)."""


class _Interrupted(Exception):
    """Ctrl-C in a command, carried past click (which would print an empty
    line before its Abort) to :meth:`DeathsphereGroup.main`."""


class DeathsphereGroup(click.Group):
    """A click group whose ``main`` is the one place where failures become
    exit statuses (docs/contract.md, "Exit status"): a usage error is one
    line on stderr and status 2; a failed write of the results (stdout
    closed, disk full) one line and status 3; a reader that stops reading
    (``| head``) a quiet status 0; Ctrl-C status 130 and SIGTERM 143, one
    line each.  A file output left unwritten by any of these (it is written
    under a temporary name, :mod:`deathsphere.writers.atomic`) is named on
    the same line.  (Done here rather than in a wrapper so that click's
    CliRunner sees it.)"""

    command_class = Command

    def invoke(self, ctx):
        try:
            rv = super().invoke(ctx)
            sys.stdout.flush()  # a full disk shows at the flush: report it here, not at exit
            return rv
        except KeyboardInterrupt:
            raise _Interrupted() from None
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
        _unwritten()  # only this command's files are named (an API caller's earlier ones are not)
        try:
            with _stops_as_exceptions():
                code = super().main(args=args, prog_name=prog_name or "deathsphere",
                                    complete_var=complete_var, standalone_mode=False, **extra)
        except click.exceptions.UsageError as exc:
            command = exc.ctx.command_path if exc.ctx is not None else "deathsphere"
            fail(f"{one_line(exc.format_message())} (see '{command} --help'){_unwritten()}")
        except ParameterError as exc:  # the API's validation, reached through a command
            fail(f"{one_line(str(exc))} (see 'deathsphere {_command_name(args)} --help'){_unwritten()}")
        except click.exceptions.ClickException as exc:
            fail(one_line(exc.format_message()) + _unwritten())
        except (click.exceptions.Abort, KeyboardInterrupt, _Interrupted):
            # on a terminal the line goes below the echoed ^C
            start = "\n" if _isatty(sys.stderr) else ""
            click.echo(f"{start}deathsphere: interrupted{_unwritten()}", err=True)
            sys.exit(ExitCode.INTERRUPTED)
        except Terminated:
            click.echo(f"deathsphere: terminated{_unwritten()}", err=True)
            sys.exit(ExitCode.TERMINATED)
        except _OutputFailed as failed:
            exc = failed.args[0]
            _silence_stdout()
            if exc.errno == errno.EPIPE or isinstance(exc, BrokenPipeError):
                sys.exit(ExitCode.OK)  # the reader went away (`| head`): not an error
            click.echo(f"deathsphere: error: cannot write the results: {exc.strerror or exc}{_unwritten()}",
                       err=True)
            sys.exit(ExitCode.OUTPUT)
        sys.exit(code or 0)


class Terminated(BaseException):
    """SIGTERM, raised where the program is, as Ctrl-C raises
    KeyboardInterrupt: every ``finally`` and the file writers' clean-up run
    (the default action would end the process on the spot, leaving a
    partial file).  A BaseException, so that no ``except Exception`` takes it."""


#: Stops that arrived inside the import machinery, to raise once out of it.
_DEFERRED: list[type[BaseException]] = []


def _stop_handler(stop: type[BaseException]):
    """A signal handler raising ``stop`` where the program is, except inside
    importlib's own code (a module lock's clean-up, run at any moment): an
    exception raised there is swallowed ("Exception ignored in ...") and
    can leave the module locks held, so that a thread importing at the
    same time (Parquet's warm-up) and the command waiting for it hang.
    There the stop is deferred and retried 10 ms later (SIGALRM)."""
    def handler(signum, frame):
        _raise_or_defer(stop, frame)
    return handler


def _raise_or_defer(stop, frame):
    import signal

    if frame is not None and frame.f_code.co_filename.startswith("<frozen importlib"):
        _DEFERRED.append(stop)
        signal.setitimer(signal.ITIMER_REAL, 0.01)
        return
    raise stop()


def _retry_deferred(signum, frame):
    if _DEFERRED:
        stop = _DEFERRED[0]
        _DEFERRED.clear()
        _raise_or_defer(stop, frame)


@contextmanager
def _stops_as_exceptions():
    """While a command runs, Ctrl-C raises KeyboardInterrupt and SIGTERM
    :class:`Terminated` (never inside the import machinery: see
    :func:`_stop_handler`).  Only the main thread can set a handler: under
    a test runner's thread nothing changes."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    handlers = {signal.SIGINT: _stop_handler(KeyboardInterrupt), signal.SIGTERM: _stop_handler(Terminated),
                signal.SIGALRM: _retry_deferred}
    previous = {sig: signal.signal(sig, handler) for sig, handler in handlers.items()}
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        _DEFERRED.clear()
        for sig, handler in previous.items():
            signal.signal(sig, signal.SIG_DFL if handler is None else handler)


def _unwritten() -> str:
    """'' or, after a failed or stopped write, the note that names the
    file(s) left unwritten (nothing is under their name)."""
    # a command that wrote no file never imported the writer: nothing to say, nothing to import
    atomic = sys.modules.get("deathsphere.writers.atomic")
    names = atomic.not_written() if atomic is not None else []
    return f"; not written: {', '.join(names)}" if names else ""


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
      deathsphere orbit --theta 60 --alpha 10     one orbit, every quantity
      deathsphere orbit --theta 30:90:15 --alpha 10 --format csv
      deathsphere vertical --theta 90 --v-top 6   a vertical loop
      deathsphere orbit --body sphere --theta 60 --omega3 80
      deathsphere sweep --theta 5:175:1 --alpha 1:89:1 --only ok
      deathsphere map                             the allowed region
      deathsphere limits --mu 1 --max-g 5         the highest orbit possible
      deathsphere table1                          the paper's Table 1
      deathsphere verify                          the paper's claims
      deathsphere simulate --theta 60 --alpha 10  the exact equations
    """


# ---------------------------------------------------------------------------
# entry point


def main(argv=None) -> None:
    """Console-script entry point (see :class:`DeathsphereGroup` for exit codes)."""
    reuse_freed_memory()
    leave_a_core_to_the_evaluation()
    cli.main(args=argv)
