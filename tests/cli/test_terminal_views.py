"""Every view a person sees on a terminal works.

Each command's ``--help``, every example its help shows and every
``deathsphere ...`` line of the README run with stdout a terminal 80 and
100 columns wide, and fail on a traceback, on an exit status outside the
contract's 0/1, or on a line wider than the terminal.  The commands come
from the click group itself, so a new command is covered without a word
here; a command whose terminal view no example exercises fails
:func:`test_every_command_shows_its_terminal_view`.

The runs are in-process (a fresh interpreter per case would pay its
start-up some 300 times): stdout is a text stream that says it is a
terminal and ``COLUMNS`` gives its width, which is all the CLI and rich
consult.  Long work is run smaller (:func:`bounded`), an example that draws
a figure or an animation is parsed rather than drawn (:data:`DRAWN_FILES`),
and what a person supplies (a machine file, a scheduler) is provided
(:func:`provided`).  :func:`test_in_process_terminal_is_the_real_one` proves the
route by drawing a few of the same views through a real pseudo-terminal
(its window size set by TIOCSWINSZ, no ``COLUMNS``) and comparing the text.
"""

from __future__ import annotations

import fcntl
import io
import os
import re
import select
import shlex
import struct
import subprocess
import sys
import termios
import traceback
from dataclasses import dataclass
from pathlib import Path

import click
import pytest
from rich.cells import cell_len
from shipped_plans import copy_plan

from deathsphere.cli import cli

README = Path(__file__).resolve().parents[2] / "README.md"
WIDTHS = (80, 100)
#: The exit statuses a command may end with on an example (docs/contract.md):
#: 0, or 1 when some rows are invalid.
CONTRACT_STATUSES = (0, 1)
ANSI = re.compile(r"\x1b\[[0-?]*[ -/]*[@-~]|\x1b\][^\x07\x1b]*(?:\x07|\x1b\\)|\x1b[=>]")

#: Grid ranges longer than this are run on a coarser grid of the same span
#: (a sweep's example over 16,000 orbits proves nothing more than over 20).
MAX_RANGE_POINTS = 40
#: A simulation runs at most this many periods (or seconds, where it has no period) here: its view
#: is laid out the same over a quarter of a lap as over twenty.
MAX_PERIODS = 0.25
#: ... and off the globe (``--surface``) at most this many, where the general contact search makes a
#: step some ten times dearer (a quarter of a lap of the drum's example took 2.5 s, this 0.4 s); no
#: example there ends on an event (the globe's events end views within a quarter of a lap).
MAX_PERIODS_OFF_THE_GLOBE = 0.05


@dataclass(frozen=True)
class Case:
    """One command line as a person types it: where it was found, the
    arguments after ``deathsphere``, the text piped into it, and whether
    its stdout goes to a pipe or a file."""

    where: str
    line: str
    args: tuple
    stdin: str | None = None
    piped: bool = False

    @property
    def format(self) -> str | None:
        return self.args[self.args.index("--format") + 1].lower() if "--format" in self.args[:-1] else None

    @property
    def drawn(self) -> bool:
        """Its stdout is drawn to fit a terminal: a table, asked for or the
        default on a terminal (not piped, not to a file with --output)."""
        return self.format == "table" or (self.format is None and not self.piped and "--output" not in self.args)

    @property
    def view(self) -> bool:
        """A terminal's width reaches it: a drawing on the terminal itself."""
        return self.drawn and not self.piped

    def __str__(self):
        return f"{self.where}: {self.line}"


def parse_line(where: str, line: str) -> Case | None:
    """A shell line of an example as a :class:`Case` (None: not a deathsphere command)."""
    stdin = None
    m = re.match(r"printf '([^']*)' \| (.*)$", line)
    if m:
        stdin, line = m.group(1).encode().decode("unicode_escape"), m.group(2)
    if not re.match(r"deathsphere(\s|$)", line):
        return None
    command, piped = line, False
    for sep in (" | ", " > "):
        if sep in command:
            command, piped = command.split(sep)[0], True
    return Case(where, line, tuple(shlex.split(command)[1:]), stdin, piped)


def help_examples(path: tuple, command: click.Command) -> list[Case]:
    """The example lines of a command's help: the indented lines under
    "Example(s):" up to the next blank line, a trailing backslash joining a
    line to the next, a comment of two or more spaces cut off."""
    text = command.help or ""
    lines, out, inside, pending = text.splitlines(), [], False, ""
    for raw in lines:
        if re.match(r"\s*Examples?:\s*$", raw):
            inside = True
            continue
        if not inside:
            continue
        if not raw.strip() or raw.strip() == "\b":
            if pending or out:
                break
            continue
        joined = pending + raw.strip()
        if joined.endswith("\\"):
            pending = joined[:-1].rstrip() + " "
            continue
        pending = ""
        out.append(re.split(r"\s{2,}", joined)[0])
    where = " ".join(("deathsphere", *path, "--help"))
    return [c for c in (parse_line(where, line) for line in out) if c is not None]


def readme_lines() -> list[Case]:
    """Every ``deathsphere ...`` line of the README's code blocks (a comment after ``  #`` cut off)."""
    cases = []
    for block in re.findall(r"```[a-z]*\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S):
        for line in block.splitlines():
            case = parse_line("README.md", line.split("  #")[0].strip())
            if case is not None:
                cases.append(case)
    return cases


def commands() -> list[tuple[tuple, click.Command]]:
    """The group and each of its commands, by the words that name them."""
    return [((), cli), *(((name,), command) for name, command in sorted(cli.commands.items()))]


def all_cases() -> list[Case]:
    cases = []
    for path, command in commands():
        cases.append(Case(" ".join(("deathsphere", *path)), "--help", (*path, "--help")))
        cases += help_examples(path, command)
    cases += readme_lines()
    unique = {}
    for case in cases:
        unique.setdefault((case.args, case.stdin, case.piped), case)
    return list(unique.values())


def bounded(args: tuple) -> tuple:
    """The arguments with long grids coarsened and simulations shortened
    (a command that takes --periods runs at most :data:`MAX_PERIODS`, off
    the globe :data:`MAX_PERIODS_OFF_THE_GLOBE`): the same views over less
    work."""
    most = MAX_PERIODS_OFF_THE_GLOBE if "--surface" in args else MAX_PERIODS
    out = []
    for i, arg in enumerate(args):
        m = re.fullmatch(r"(-?[\d.]+):(-?[\d.]+):([\d.]+)", arg)
        if m:
            start, stop, step = map(float, m.groups())
            if step > 0 and (stop - start) / step > MAX_RANGE_POINTS:
                arg = f"{m.group(1)}:{m.group(2)}:{(stop - start) / 10:g}"
        if i > 0 and args[i - 1] in ("--periods", "--duration") and float(arg) > most:
            arg = str(most)
        out.append(arg)
    command = cli.commands.get(args[0]) if args else None
    takes_periods = command is not None and any(p.name == "periods" for p in command.params)
    # a two-wheeler's straight running on flat ground has no period: its length is --duration (s)
    timed = "--duration" in args or ("--flat" in args and "--turn-radius" not in args)
    if takes_periods and not {"--periods", "--duration", "--help"} & set(args):
        out += ["--duration" if timed else "--periods", str(most)]
    return tuple(out)


#: A machine file as a person writes one: a name and the keys that differ from the preset.
MACHINE_FILES = {".toml": 'name = "my bike"\nmass = 160\n', ".csv": "name,mass\nmy bike,160\n"}


def provided(args: tuple, folder: Path) -> tuple:
    """What an example leaves to the person, provided: the machine file it
    names is written in ``folder``, a profile shipped in examples/ copied
    there, and a show's plan (one shipped in
    examples/, else the one ``show --example`` prints); a dask scheduler's
    address is left out (the output is that of a local run, docs/contract.md)."""
    if args and args[0] == "show":
        from deathsphere.api.shows import EXAMPLE_PLAN

        for arg in args[1:]:
            if arg.endswith(".toml") and not (folder / arg).exists():
                copy_plan(README.parent / arg, folder / arg, EXAMPLE_PLAN)
    out, skip = [], False
    for i, arg in enumerate(args):
        if skip:
            skip = False
            continue
        if arg == "--scheduler":
            skip = True
            continue
        if i > 0 and args[i - 1] == "--profile" and (README.parent / arg).is_file() and not (folder / arg).exists():
            (folder / arg).parent.mkdir(parents=True, exist_ok=True)       # a profile shipped in examples/
            (folder / arg).write_bytes((README.parent / arg).read_bytes())
        if i > 0 and args[i - 1] == "--machine-file" and not (folder / arg).exists():
            (folder / arg).write_text(MACHINE_FILES[Path(arg).suffix.lower()], encoding="utf-8")
        out.append(arg)
    return tuple(out)


class TerminalText(io.TextIOWrapper):
    """A text stream that is a terminal, as far as ``isatty`` tells."""

    def isatty(self):
        return True


@dataclass
class Shown:
    status: object
    stdout: str
    stderr: str
    traceback: str | None = None


def run_on_terminal(args, columns: int, monkeypatch, stdin: str | None = None, terminal: bool = True) -> Shown:
    """Run ``deathsphere ARGS`` in-process as on a terminal ``columns``
    wide (stdout a terminal unless ``terminal`` is false: a pipe).  An
    exception that escapes the CLI is what Python would print as a
    traceback."""
    out_bytes, err = io.BytesIO(), io.StringIO()
    out = (TerminalText if terminal else io.TextIOWrapper)(out_bytes, encoding="utf-8", write_through=True)
    with monkeypatch.context() as m:
        for name in ("NO_COLOR", "FORCE_COLOR", "TTY_COMPATIBLE", "TTY_INTERACTIVE", "COLORTERM", "TERM_PROGRAM"):
            m.delenv(name, raising=False)
        m.setenv("COLUMNS", str(columns))
        m.setenv("LINES", "50")
        m.setenv("TERM", "xterm-256color")
        m.setattr(sys, "stdout", out)
        m.setattr(sys, "stderr", err)
        m.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO((stdin or "").encode()), encoding="utf-8"))
        status, trace = 0, None
        try:
            cli.main(args=list(args), prog_name="deathsphere")
        except SystemExit as exc:
            status = exc.code if exc.code is not None else 0
        except Exception:  # noqa: BLE001 - what would reach the person as a traceback
            status, trace = "traceback", traceback.format_exc()
        out.flush()
    return Shown(status, out_bytes.getvalue().decode("utf-8"), err.getvalue(), trace)


def visible_lines(text: str) -> list[str]:
    """The lines as a terminal shows them: escape codes removed, a carriage
    return starting the line over."""
    return [ANSI.sub("", line).rsplit("\r", 1)[-1].rstrip() for line in text.split("\n")]


def is_data(stdout: str) -> bool:
    """CSV, JSON or NDJSON asked for on a terminal: records, not a view to fit."""
    first = next((line for line in stdout.splitlines() if line.strip()), "")
    return first.startswith(("{", "[")) or re.fullmatch(r"[a-z_][a-z0-9_]*(,[a-z_][a-z0-9_]*)+", first) is not None


def problems(shown: Shown, columns: int, drawn: bool = True) -> list[str]:
    """What is wrong with what a person saw; ``drawn``: stdout is a view
    to fit the terminal (else records, or nothing a terminal shows)."""
    found = []
    if shown.traceback or "Traceback" in shown.stdout + shown.stderr:
        found.append("traceback:\n" + (shown.traceback or shown.stderr))
    if shown.status not in CONTRACT_STATUSES:
        found.append(f"exit status {shown.status}: {shown.stderr.strip()}")
    streams = [("stderr", shown.stderr)]
    if drawn and not is_data(shown.stdout):
        streams.append(("stdout", shown.stdout))
    for name, text in streams:
        for line in visible_lines(text):
            if cell_len(line) > columns:
                found.append(f"{name} line of {cell_len(line)} columns: {line!r}")
    return found


CASES = all_cases()


def _ids(case: Case) -> str:
    return case.line if case.line != "--help" else " ".join(("deathsphere", *case.args))


def table_variants(cases) -> list[Case]:
    """Each example that asks for records (--format csv, json, ndjson) once
    more with --format table, piped: a table is a view wherever it goes."""
    out = []
    for case in cases:
        if "--format" not in case.args[:-1] or case.view:
            continue
        if case.args[0] == "map" and "--step" in case.args:
            continue  # the data's theta step: the map's plot refuses it (tests/cli/test_map_limits.py)
        command = cli.commands[case.args[0]]
        fmt = next((p for p in command.params if p.name == "fmt"), None)
        if fmt is None or "table" not in getattr(fmt.type, "choices", ()):
            continue
        i = case.args.index("--format")
        args = (*case.args[:i + 1], "table", *case.args[i + 2:])
        out.append(Case(case.where, " ".join(("deathsphere", *args, "| less")), args, case.stdin, piped=True))
    return out


#: A view at each width; what no terminal width reaches (a pipe, a file,
#: records) once, at the narrower, where its notes on stderr must fit.
RUNS = [pytest.param(case, columns, id=f"{_ids(case)} @{columns}")
        for case in CASES + table_variants(CASES) for columns in (WIDTHS if case.view else WIDTHS[:1])]


#: Files whose drawing takes seconds to a minute (a figure's region, an
#: animation's frames): their examples are parsed as the command would
#: parse them, not run; the one line they show on a terminal ("wrote FILE")
#: is that of every --output, which the other examples run.
DRAWN_FILES = (".png", ".svg", ".pdf", ".gif", ".mp4")


def draws_a_file(args: tuple) -> bool:
    return "--output" in args[:-1] and args[args.index("--output") + 1].lower().endswith(DRAWN_FILES)


@pytest.mark.parametrize("case, columns", RUNS)
def test_terminal_view(case, columns, tmp_path, monkeypatch):
    """No traceback, an exit status of the contract, every line within the terminal."""
    monkeypatch.chdir(tmp_path)  # examples with --output write here
    args = provided(bounded(case.args), tmp_path)
    if draws_a_file(args):
        with cli.make_context("deathsphere", list(args), resilient_parsing=False) as ctx:
            command = cli.get_command(ctx, args[0])
            command.make_context(args[0], list(args[1:]), parent=ctx)
        return
    shown = run_on_terminal(args, columns, monkeypatch, case.stdin, terminal=not case.piped)
    found = problems(shown, columns, case.drawn)
    assert not found, f"{case} at {columns} columns:\n" + "\n".join(found)


def test_cases_are_found():
    """The collection itself: each command's examples, the README's lines,
    continued lines joined and comments cut off."""
    lines = {c.line for c in CASES}
    assert "deathsphere limits --mu 1 --max-g 5" in lines
    assert "deathsphere stability --theta 90 --alpha 80" in lines  # its "(unstable, ...)" cut off
    assert any(c.where == "README.md" for c in CASES)
    assert any(c.stdin for c in CASES)
    assert len([c for c in CASES if c.where.endswith("--help")]) > 2 * len(cli.commands)


def test_a_continued_example_is_one_line():
    @click.command()
    def sample():
        """Sample.

        \b
        Examples:
          deathsphere orbit --theta 60 \\
              --alpha 10        one orbit
          deathsphere map
        """

    assert [c.args for c in help_examples(("orbit",), sample)] == [("orbit", "--theta", "60", "--alpha", "10"),
                                                                   ("map",)]


def test_every_command_shows_its_terminal_view():
    """Each command has an example (its help's or the README's) whose stdout is the terminal."""
    shown = {c.args[0] for c in CASES if not c.piped and "--output" not in c.args and "--help" not in c.args}
    assert set(cli.commands) <= shown, sorted(set(cli.commands) - shown)


@pytest.mark.parametrize("args", [("limits", "--mu", "1", "--max-g", "5"), ("limits", "--theta", "60"),
                                  ("orbit", "--theta", "30:90:15", "--alpha", "10")])
def test_table_when_piped(args, monkeypatch):
    """--format table is a view whether or not stdout is a terminal."""
    shown = run_on_terminal((*args, "--format", "table"), 80, monkeypatch, terminal=False)
    assert not problems(shown, 80)
    assert shown.stdout.strip() and not is_data(shown.stdout)


# ---------------------------------------------------------------------------
# the real terminal, to prove the in-process one


def run_in_pty(args, columns: int) -> str:
    """``deathsphere ARGS`` in a fresh interpreter whose stdin, stdout and
    stderr are a pseudo-terminal ``columns`` wide; everything it showed."""
    master, slave = os.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 50, columns, 0, 0))
    env = {k: v for k, v in os.environ.items()
           if k not in ("COLUMNS", "LINES", "NO_COLOR", "FORCE_COLOR", "TTY_COMPATIBLE", "TTY_INTERACTIVE",
                        "COLORTERM", "TERM_PROGRAM")}
    env["TERM"] = "xterm-256color"
    proc = subprocess.Popen([sys.executable, "-m", "deathsphere", *args], stdin=slave, stdout=slave, stderr=slave,
                            env=env, close_fds=True)
    os.close(slave)
    chunks = []
    while True:
        ready, _, _ = select.select([master], [], [], 60)
        if not ready:
            break
        try:
            data = os.read(master, 65536)
        except OSError:  # the terminal closed: the command ended
            break
        if not data:
            break
        chunks.append(data)
    os.close(master)
    proc.wait(timeout=60)
    return b"".join(chunks).decode("utf-8").replace("\r\n", "\n")


@pytest.mark.parametrize("args, columns", [
    (("limits", "--mu", "1", "--max-g", "5"), 80),
    (("orbit", "--theta", "60", "--alpha", "5:40:5"), 80),
    (("docs",), 80),
    (("vertical", "--theta", "90", "--v-top", "6"), 100),
])
def test_in_process_terminal_is_the_real_one(args, columns, monkeypatch):
    """What the in-process terminal shows is, character for character,
    what a pseudo-terminal of the same size shows."""
    real = visible_lines(run_in_pty(args, columns))
    shown = run_on_terminal(args, columns, monkeypatch)
    assert shown.traceback is None
    assert [line for line in real if line] == [line for line in visible_lines(shown.stdout + shown.stderr) if line]
