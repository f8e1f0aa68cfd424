"""``deathsphere docs``: the shipped documentation, by topic
(:mod:`deathsphere.topics`)."""

from __future__ import annotations

import contextlib
import os
import sys

import click

from deathsphere.cli.base import _isatty, cli, stdout_console


@cli.command("docs")
@click.argument("topic", required=False, metavar="[TOPIC]")
@click.option("--no-pager", is_flag=True, default=False,
              help="Print a long topic on the terminal at once instead of through the pager.")
def docs_command(topic, no_pager):
    """The documentation the help texts cite, shipped with the package.

    Without TOPIC, list the topics and their titles.  With one, show that
    document: rendered on a terminal (through $PAGER, else 'less -R', when
    it is longer than the screen, as git does), the Markdown as it is when
    piped (so it can be saved).  A help text's citation docs/NAME.md can be
    given as it is printed: NAME, NAME.md and docs/NAME.md all work.

    \b
    Examples:
      deathsphere docs                      the topics
      deathsphere docs errata               where the paper is wrong
      deathsphere docs docs/contract.md     as a help text cites it
      deathsphere docs stability > s.md     the Markdown, to a file
      deathsphere docs machine --no-pager   all at once, no pager
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

        console = stdout_console()
        with console.capture() as captured:
            console.print(Markdown(text))
        rendered = captured.get()
        if no_pager or rendered.count("\n") < console.height or not page(rendered):
            sys.stdout.write(rendered)
    else:
        click.echo(text, nl=not text.endswith("\n"))


def page(rendered: str) -> bool:
    """Show ``rendered`` (text with its colour codes) through the pager, as
    git does: ``$PAGER`` (an empty one: none), else ``less -R`` (colours
    kept); less's ``LESS`` defaults to FRX as git's (quit on a screen's worth,
    colours, no screen clearing) when unset.  False when there is no pager
    to run (the caller prints instead); the pager quitting early is no error."""
    import shlex
    import subprocess

    command = shlex.split(os.environ.get("PAGER", "less -R"))
    try:
        out = sys.stdout.fileno()  # the pager writes where we would (a test's stream has no descriptor)
    except (AttributeError, ValueError, OSError):
        return False
    if not command:
        return False
    sys.stdout.flush()
    try:
        pager = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=out, env={"LESS": "FRX", **os.environ})
    except OSError:  # not installed, not executable
        return False
    try:
        pager.stdin.write(rendered.encode("utf-8"))
        pager.stdin.close()
    except BrokenPipeError:  # the reader quit before the end (q in less)
        with contextlib.suppress(OSError):
            pager.stdin.close()
    while True:
        try:
            pager.wait()
            return True
        except KeyboardInterrupt:  # Ctrl-C belongs to the pager (less uses it), as under git
            continue


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
