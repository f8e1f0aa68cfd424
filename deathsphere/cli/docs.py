"""``deathsphere docs``: the shipped documentation, by topic
(:mod:`deathsphere.topics`)."""

from __future__ import annotations

import sys

import click

from deathsphere.cli.base import _isatty, cli, stdout_console


@cli.command("docs")
@click.argument("topic", required=False, metavar="[TOPIC]")
def docs_command(topic):
    """The documentation the help texts cite, shipped with the package.

    Without TOPIC, list the topics and their titles.  With one, show that
    document: rendered on a terminal, the Markdown as it is when piped (so
    it can be saved or paged).  A help text's citation docs/NAME.md can be
    given as it is printed: NAME, NAME.md and docs/NAME.md all work.

    \b
    Examples:
      deathsphere docs                      the topics
      deathsphere docs errata               where the paper is wrong
      deathsphere docs docs/contract.md     as a help text cites it
      deathsphere docs stability > s.md     the Markdown, to a file
    """
    from deathsphere.topics import UnknownTopic, doc_text, docs_topics

    if topic is None:
        topics = docs_topics()
        if _isatty(sys.stdout):
            stdout_console().print(topics_view(topics))
            return
        width = max(map(len, topics))
        for name, title in topics.items():
            click.echo(f"{name:<{width}}  {title}")
        return
    try:
        text = doc_text(topic)
    except UnknownTopic as exc:
        raise click.BadParameter(str(exc), param_hint="'TOPIC'") from None
    if _isatty(sys.stdout):
        from rich.markdown import Markdown

        stdout_console().print(Markdown(text))
    else:
        click.echo(text, nl=not text.endswith("\n"))


def topics_view(topics: dict):
    """The topics on a terminal: a title longer than the line wraps under
    itself, so that the names stay one column to read down."""
    from rich.table import Table
    from rich.text import Text

    grid = Table.grid(padding=(0, 2))
    grid.add_column(no_wrap=True)
    grid.add_column(overflow="fold")
    for name, title in topics.items():
        grid.add_row(Text(name), Text(title))  # titles are text, not markup
    return grid
