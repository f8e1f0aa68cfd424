"""The docs travel with the package: every ``docs/<name>.md`` that a help
text, an output or a docstring of the package cites is a shipped topic that
``deathsphere docs`` shows, and a wheel carries the files."""

import importlib
import importlib.util
import re
import subprocess
import sys
from pathlib import Path

import pytest

from deathsphere.topics import UnknownTopic, doc_text, docs_topics, topic_name

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "deathsphere"
DOCS = PACKAGE / "docs"
#: A citation as the sources write it: docs/errata.md, docs/stability.md.
CITED = re.compile(r"\bdocs/([a-z0-9_-]+\.md)")


def citations() -> dict[str, list[str]]:
    """Each cited file -> the source files citing it (the docs themselves
    excluded: they are what is cited)."""
    found: dict[str, list[str]] = {}
    for path in sorted(PACKAGE.rglob("*")):
        if path.is_dir() or DOCS in path.parents or path.suffix not in {".py", ".html"}:
            continue
        for name in CITED.findall(path.read_text(encoding="utf-8")):
            found.setdefault(name, []).append(str(path.relative_to(ROOT)))
    return found


def test_the_sources_cite_the_docs():
    cited = citations()
    assert sum(map(len, cited.values())) >= 50       # the scan did find the help texts
    assert {"contract.md", "errata.md", "stability.md"} <= set(cited)


@pytest.mark.parametrize("name", sorted(citations()))
def test_every_cited_doc_is_a_shipped_topic(run, name):
    assert (DOCS / name).is_file(), (name, citations()[name])
    assert topic_name(f"docs/{name}") == name[:-3]
    res = run("docs", f"docs/{name}")
    assert res.exit_code == 0 and res.stdout == doc_text(name), res.stderr


def test_every_shipped_markdown_file_is_a_topic_with_a_title():
    topics = docs_topics()
    assert sorted(topics) == sorted(p.stem for p in DOCS.glob("*.md"))
    assert all(topics.values()), topics


def test_the_figures_the_docs_embed_are_shipped():
    for doc in DOCS.glob("*.md"):
        for target in re.findall(r"!\[[^\]]*\]\(([^)\s]+)\)", doc.read_text(encoding="utf-8")):
            assert (DOCS / target).is_file(), (doc.name, target)


def test_an_unknown_topic_names_the_known_ones():
    with pytest.raises(UnknownTopic, match="errata"):
        topic_name("docs/nothing.md")


@pytest.mark.skipif(importlib.util.find_spec("setuptools") is None,
                    reason="collecting the package data needs setuptools, the build backend, installed")
def test_the_build_carries_the_docs(tmp_path):
    """setuptools' build_py, as a wheel build runs it, copies every doc and
    figure (a wheel holds what build_py lays out; building one offline would
    need the wheel package too)."""
    build = "import sys; from setuptools import setup; sys.argv[1:] = ['-q', 'build_py', '--build-lib', sys.argv[1]]; setup()"
    subprocess.run([sys.executable, "-c", build, str(tmp_path)], cwd=ROOT, check=True, capture_output=True,
                   timeout=120)
    shipped = {p.name for p in (tmp_path / "deathsphere" / "docs").iterdir()}
    assert shipped == {p.name for p in DOCS.iterdir() if p.suffix in {".md", ".png"}}


#: What a physics docstring cites: the paper's equation numbers (eq. 29,
#: eqs. 56, (208), the machine's M9), the benchmark's, or work beyond the
#: paper ("beyond the paper", or the docs/ page that derives it).
CITES = re.compile(r"beyond\s+the\s+paper|\beqs?\.\s*\(?[A-Z]?\d|\(\d+[a-z]?\)|\bM\d+|Meijaard|docs/[a-z0-9_-]+\.md",
                   re.IGNORECASE)


def test_every_public_physics_function_cites_its_equations():
    """The physics core's public functions (each module's ``__all__``) say
    which equations they implement, or that they go beyond the paper."""
    import inspect
    import pkgutil

    import deathsphere.physics as physics

    uncited, seen = [], 0
    for info in pkgutil.walk_packages(physics.__path__, "deathsphere.physics."):
        module = importlib.import_module(info.name)
        for name in getattr(module, "__all__", ()):
            obj = getattr(module, name, None)
            if inspect.isfunction(obj) and obj.__module__ == module.__name__:
                seen += 1
                if not CITES.search(obj.__doc__ or ""):
                    uncited.append(f"{info.name}.{name}")
    assert seen >= 100 and not uncited, uncited
