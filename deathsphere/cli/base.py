"""The ``deathsphere`` command line: the group, the shared options and
helpers, and the entry point.  Each command lives in a module of its own
(:mod:`deathsphere.cli.orbit`, ...); none computes physics: they parse,
call the model and render.  Usage errors become one line on stderr with
exit status 2 (:class:`DeathsphereGroup`); results go to stdout, diagnostics
to stderr.
"""

from __future__ import annotations

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
from deathsphere.grid import RangeError, parse_many
from deathsphere.model import Setup, Table, angle_problem
from deathsphere.render import (
    FORMATS,
    write_csv,
    write_json,
    write_ndjson,
    write_rich_table,
)

CONTEXT = {"help_option_names": ["-h", "--help"], "max_content_width": 100}

#: Largest grid ``orbit`` evaluates in one go; bigger ones belong to ``sweep``.
ORBIT_MAX_ROWS = 1_000_000

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
        click.option("-a", "--wheel-radius", "a", type=float, default=TABLE1_WHEEL_RADIUS, show_default=True,
                     metavar="M", help="Body radius a [m]."),
        click.option("-r", "--sphere-radius", "r", type=float, default=TABLE1_SPHERE_RADIUS, show_default=True,
                     metavar="M", help="Fixed sphere radius r [m]."),
        click.option("-k", "--inertia", "k", type=float, default=None, metavar="K",
                     help="Inertia factor k: I11 = 2 k m a^2 for a wheel, I = k m a^2 for a sphere "
                          "[default: 0.5 wheel, 0.4 sphere]."),
        click.option("-g", "--gravity", "g", type=float, default=STANDARD_GRAVITY, show_default=True,
                     metavar="M_S2", help="Gravitational acceleration [m/s^2]."),
        click.option("--mu", type=float, default=math.inf, metavar="MU",
                     help="Friction coefficient available; orbits needing more have status 'slips' "
                          "[default: unlimited]."),
    ]
    for option in reversed(options):
        f = option(f)
    return f


def make_setup(body, side, a, r, k, g, mu) -> Setup:
    try:
        return Setup(body=body.lower(), side=side.lower(), a=a, r=r, k=k, g=g, mu=mu)
    except ValueError as exc:
        raise click.UsageError(str(exc)) from None


def parse_angles(texts, name: str, max_values: int | None = None):
    try:
        values = parse_many(texts, f"--{name}", max_values)
    except RangeError as exc:
        raise click.BadParameter(str(exc).split(": ", 1)[-1], param_hint=f"'--{name}'") from None
    for v in values:
        problem = angle_problem(name, float(v))
        if problem:
            raise click.BadParameter(problem, param_hint=f"'--{name}'")
    return values


def parse_rates(texts, name: str, max_values: int | None = None):
    try:
        return parse_many(texts, f"--{name}", max_values)
    except RangeError as exc:
        raise click.BadParameter(str(exc).split(": ", 1)[-1], param_hint=f"'--{name}'") from None

class _Progress:
    """What a command reports progress to: ``advance(n)`` or ``update(done, total)``."""

    def __init__(self, bar=None, task=None):
        self.bar, self.task = bar, task

    def advance(self, n: int = 1, description: str | None = None) -> None:
        if self.bar is not None:
            self.bar.update(self.task, advance=n, **({"description": description} if description else {}))

    def update(self, done: int, total: int) -> None:
        if self.bar is not None:
            self.bar.update(self.task, completed=done, total=total)


@contextmanager
def progress(label: str, total: int):
    """A rich progress bar on stderr when stderr is a terminal (nothing
    otherwise, so pipes and logs stay clean); yields a :class:`_Progress`."""
    if not sys.stderr.isatty():
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


def evaluate_in_chunks(req: dict, evaluate, label: str, chunk: int) -> Table:
    """``evaluate(sub_request)`` over consecutive slices of a request batch,
    with a progress bar on a terminal; the tables are joined in input order."""
    n = len(req["theta"])
    if n <= chunk:
        return evaluate(req)
    parts = []
    with progress(label, n) as bar:
        for start in range(0, n, chunk):
            parts.append(evaluate({key: value[start:start + chunk] for key, value in req.items()}))
            bar.advance(min(chunk, n - start))
    return Table({name: np.concatenate([t[name] for t in parts]) for name in parts[0].names})


def choose_format(fmt: str | None) -> str:
    if fmt:
        return fmt.lower()
    return "table" if sys.stdout.isatty() else "csv"


def emit(chunks, fmt: str, title: str | None = None) -> int:
    """Write tables in the chosen format to stdout; returns the row count."""
    out = sys.stdout
    if fmt == "csv":
        return write_csv(chunks, out)
    if fmt == "json":
        return write_json(chunks, out)
    if fmt == "ndjson":
        return write_ndjson(chunks, out)
    tables = list(chunks)
    table = tables[0] if len(tables) == 1 else Table({n: np.concatenate([t[n] for t in tables]) for n in tables[0].names})
    return write_rich_table(table, stdout_console(), title)


class DeathsphereGroup(click.Group):
    """A click group whose ``main`` turns every usage error into one line on
    stderr with exit status 2, and a closed pipe or Ctrl-C into a quiet stop.
    (Done here rather than in a wrapper so that click's CliRunner sees it.)"""

    def main(self, args=None, prog_name=None, complete_var=None, standalone_mode=True, **extra):
        try:
            code = super().main(args=args, prog_name=prog_name or "deathsphere",
                                complete_var=complete_var, standalone_mode=False, **extra)
        except click.exceptions.UsageError as exc:
            command = exc.ctx.command_path if exc.ctx is not None else "deathsphere"
            fail(f"{one_line(exc.format_message())} (see '{command} --help')")
        except click.exceptions.ClickException as exc:  # e.g. a missing --input file
            fail(one_line(exc.format_message()))
        except (click.exceptions.Abort, KeyboardInterrupt):
            click.echo("deathsphere: interrupted", err=True)
            sys.exit(130)
        except BrokenPipeError:
            # the reader went away (e.g. `| head`): stop quietly, and keep
            # Python from complaining when it flushes stdout at exit
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            sys.exit(ExitCode.OK)
        sys.exit(code or 0)


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
      deathsphere orbit --body sphere --theta 60 --omega3 40
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
