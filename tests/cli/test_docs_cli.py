"""``deathsphere docs``: the shipped documentation by topic."""

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
