"""The documentation shipped inside the package, by topic.

The help texts and outputs cite ``docs/<name>.md``; those files are package
data (``deathsphere/docs/``), so an installed copy can show them offline
(``deathsphere docs NAME``).  A topic is named by its file's stem; the
forms ``errata``, ``errata.md`` and ``docs/errata.md`` all name the same
one, so a citation can be pasted as it is printed::

    >>> from deathsphere.topics import doc_text, docs_topics
    >>> docs_topics()["errata"].split(":")[0]
    'Errata'
    >>> doc_text("docs/errata.md") == doc_text("errata")
    True
"""

from __future__ import annotations

import re
from importlib import resources

__all__ = ["UnknownTopic", "doc_text", "docs_topics", "topic_name"]

#: The package folder holding the Markdown files (and the figures they embed).
DOCS = "docs"


class UnknownTopic(LookupError):
    """No shipped document has this name; the message lists those that do."""


def _folder():
    return resources.files("deathsphere").joinpath(DOCS)


def _title(text: str) -> str:
    """The first Markdown heading without its ``#`` marks, code ticks and emphasis."""
    for line in text.splitlines():
        if line.startswith("#"):
            return re.sub(r"[`*]", "", line.lstrip("#")).strip()
    return ""


def docs_topics() -> dict[str, str]:
    """Every shipped topic and its title, in alphabetical order of name.

    Returns
    -------
    dict of str to str
        ``{name: title}``: the file's stem (``errata`` for ``docs/errata.md``)
        and its first heading.
    """
    names = sorted(entry.name[:-3] for entry in _folder().iterdir() if entry.name.endswith(".md"))
    return {name: _title(_folder().joinpath(f"{name}.md").read_text(encoding="utf-8")) for name in names}


def topic_name(topic: str) -> str:
    """The topic a name stands for: ``errata``, ``errata.md`` or ``docs/errata.md``.

    Parameters
    ----------
    topic : str
        A topic as the user typed it or as a help text cites it.

    Returns
    -------
    str
        The name of a shipped topic.

    Raises
    ------
    UnknownTopic
        When no shipped document has that name; the message names those that do.
    """
    name = re.sub(r"\.md$", "", re.sub(r"^(?:\./)?(?:deathsphere/)?docs/", "", topic.strip()))
    known = docs_topics()
    if name not in known:
        raise UnknownTopic(f"unknown topic {topic!r}; the topics are: {', '.join(known)}")
    return name


def doc_text(topic: str) -> str:
    """The Markdown text of one topic.

    Parameters
    ----------
    topic : str
        ``errata``, ``errata.md`` or ``docs/errata.md`` (see :func:`topic_name`).

    Returns
    -------
    str
        The document as shipped, Markdown.

    Raises
    ------
    UnknownTopic
        When no shipped document has that name.
    """
    return _folder().joinpath(f"{topic_name(topic)}.md").read_text(encoding="utf-8")
