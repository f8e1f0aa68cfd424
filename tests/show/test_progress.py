"""The show's long work draws a progress bar on stderr on a terminal (the
pairs and --phase auto, the Monte Carlo, a GIF's frames), and stdout holds
the same bytes as without it."""

import io

import pytest

import deathsphere
from deathsphere.api.shows import EXAMPLE_PLAN


def _terminal(monkeypatch):
    """stderr a terminal, the bar drawn at once, into a string."""
    from rich.console import Console

    import deathsphere.cli.base as base

    out = io.StringIO()
    monkeypatch.setattr(base, "_isatty", lambda stream: True)
    monkeypatch.setattr(base, "PROGRESS_DELAY_S", 0.0)
    monkeypatch.setattr(base, "stderr_console", lambda: Console(file=out, force_terminal=True, width=100))
    return out


def test_the_api_reports_every_step(tmp_path):
    plan = tmp_path / "act.toml"
    plan.write_text(EXAMPLE_PLAN, encoding="utf-8")
    seen = []
    act = deathsphere.show(str(plan), phase="auto", progress=lambda done, total: seen.append((done, total)))
    # the riders, the two loopers timed, the ten pairs
    assert seen[-1] == (13, 13) and all(a[0] < b[0] for a, b in zip(seen, seen[1:]))
    falls = []
    act.falls(4097, seed=1, progress=lambda done, total: falls.append((done, total)))
    assert falls == [(4096, 4097), (4097, 4097)]          # chunk by chunk


def test_the_command_draws_its_bars_on_a_terminal_and_stdout_is_unchanged(run, tmp_path, monkeypatch):
    plan = tmp_path / "act.toml"
    plan.write_text(EXAMPLE_PLAN, encoding="utf-8")
    args = ("show", str(plan), "--monte-carlo", "20", "--seed", "1", "--format", "csv")
    piped = run(*args)
    screen = _terminal(monkeypatch)
    res = run(*args)
    assert res.exit_code == 0 and res.stdout == piped.stdout
    drawn = screen.getvalue()
    assert "act" in drawn and "11/11" in drawn and "falls" in drawn and "20/20" in drawn
