"""``deathsphere docs``: the shipped documentation by topic."""

import pytest

from deathsphere.cli import docs
from deathsphere.topics import doc_text, docs_topics


def test_docs_lists_every_topic_with_its_title(run):
    res = run("docs")
    assert res.exit_code == 0
    lines = res.stdout.splitlines()
    assert len(lines) == len(docs_topics())
    for line, (name, title) in zip(lines, docs_topics().items()):
        assert line.split()[0] == name and line.endswith(title)


def test_a_topic_piped_is_its_markdown(run):
    for form in ("errata", "errata.md", "docs/errata.md"):
        res = run("docs", form)
        assert res.exit_code == 0 and res.stdout == doc_text("errata")


def test_a_topic_on_a_terminal_is_rendered(run, monkeypatch):
    monkeypatch.setattr(docs, "_isatty", lambda stream: True)
    res = run("docs", "errata", env={"COLUMNS": "100", "NO_COLOR": "1"})
    assert res.exit_code == 0
    assert "Errata" in res.stdout and "# Errata" not in res.stdout   # the heading is drawn, not marked up


def test_an_unknown_topic_is_one_line_and_status_2(run):
    res = run("docs", "nope")
    assert res.exit_code == 2 and res.stdout == ""
    assert len(res.stderr.strip().splitlines()) == 1
    assert "unknown topic 'nope'" in res.stderr and "errata" in res.stderr and "Traceback" not in res.stderr


def test_docs_help_fits_80_columns(run):
    res = run("docs", "--help", env={"COLUMNS": "80"})
    assert res.exit_code == 0 and "deathsphere docs errata" in res.stdout
    assert max(map(len, res.stdout.splitlines())) <= 80


def _paged_lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if line.startswith("paged:")]


def test_a_long_topic_on_a_terminal_goes_through_the_pager(monkeypatch):
    """On a terminal a topic longer than the screen is handed to $PAGER,
    rendered; --no-pager prints it at once."""
    from test_terminal_views import ANSI, run_in_pty

    monkeypatch.setenv("PAGER", "sed -e s/^/paged:/")  # a pager that marks what it was given
    for columns in (80, 100):
        seen = ANSI.sub("", run_in_pty(("docs", "errata"), columns))
        paged = _paged_lines(seen)
        assert len(paged) > 50 and any("Errata" in line for line in paged)  # the whole page, rendered
        assert "# Errata" not in seen
        unpaged = ANSI.sub("", run_in_pty(("docs", "errata", "--no-pager"), columns))
        assert _paged_lines(unpaged) == [] and "Errata" in unpaged


def test_no_pager_when_piped_or_when_there_is_none(run, monkeypatch):
    monkeypatch.setenv("PAGER", "sed -e s/^/paged:/")
    res = run("docs", "errata")
    assert res.stdout == doc_text("errata")  # piped: the Markdown, never paged
    monkeypatch.setattr(docs, "_isatty", lambda stream: True)
    monkeypatch.setenv("PAGER", "no-such-pager-anywhere")
    res = run("docs", "errata", env={"COLUMNS": "100", "NO_COLOR": "1"})
    assert res.exit_code == 0 and "Errata" in res.stdout  # printed instead


def test_a_topic_that_fits_the_screen_is_not_paged(run, monkeypatch):
    monkeypatch.setattr(docs, "_isatty", lambda stream: True)
    monkeypatch.setattr(docs, "page", lambda rendered: pytest.fail("paged a topic that fits"))
    res = run("docs", "index", env={"COLUMNS": "100", "LINES": "1000", "NO_COLOR": "1"})
    assert res.exit_code == 0 and res.stdout.count("\n") < 1000
