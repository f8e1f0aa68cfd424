"""The pieces every terminal view is built of: :class:`FitTable` (a rich
table that leaves out whole columns rather than cut a number), number and
status text, and the row cap :data:`MAX_TERMINAL_ROWS`."""

from __future__ import annotations

import math
from dataclasses import dataclass
from decimal import Decimal

import numpy as np
from rich import box
from rich.console import Console, ConsoleOptions
from rich.markup import escape
from rich.measure import Measurement
from rich.table import Table as RichTable
from rich.text import Text

from deathsphere.table import Table


def format_number(value, digits: int = 4) -> str:
    """A number for the terminal: ``digits`` significant digits, — for
    undefined, ∞ for infinite, integers whole."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "—"
    if isinstance(value, (int, np.integer)):
        return str(value)
    if isinstance(value, float) and math.isinf(value):
        return "∞" if value > 0 else "-∞"
    if value == 0:      # a negative zero (a force's sign at rest) reads 0, not -0
        return "0"
    return f"{value:.{digits}g}"


#: The most significant digits an input is echoed with as written.
ECHO_DIGITS = 7


def echo_number(value, digits: int = 4) -> str:
    """A value a title echoes (an input such as θ): as written when its
    shortest text has at most :data:`ECHO_DIGITS` significant digits
    (``--theta 123.456`` reads 123.456, not 123.5), else ``digits`` of them
    as :func:`format_number` gives (a value the command computed, such as
    the tilt of a speed, or a unit's conversion: 2.0944rad is 120.0003)."""
    if isinstance(value, (float, np.floating)) and math.isfinite(value) and value != 0:
        text = repr(float(value))
        if len(Decimal(text).normalize().as_tuple().digits) <= ECHO_DIGITS:
            return text[:-2] if text.endswith(".0") else text
    return format_number(value, digits)


STATUS_STYLE = {"ok": "green", "slips": "yellow", "invalid": "red"}


def status_text(status: str) -> str:
    """A status in its colour (rich markup)."""
    style = STATUS_STYLE.get(status, "magenta")
    return f"[{style}]{status}[/{style}]"


#: A stability verdict in its colour (rich markup).
STABILITY_STYLE = {"stable": "[green]stable[/green]", "unstable": "[red]unstable[/red]",
                   "unknown": "[magenta]unknown[/magenta]"}


#: Rows a terminal view shows.  A screen holds some 50 lines; nobody reads
#: more than a few screens of numbers, and 200 rows still render in well
#: under a second (rich spends ~2.4 ms a row), where 16,000 took half a
#: minute.  Anything longer is data for a file or a pipe: --format csv.
MAX_TERMINAL_ROWS = 200


@dataclass
class Column:
    """One column of a :class:`FitTable`: ``key`` names it in the line that
    lists left-out columns (the CSV column name where there is one)."""

    key: str
    header: str
    cells: list
    justify: str = "right"
    style: str | None = None


class FitTable:
    """A table that fits the console it is printed on.

    Cells never wrap and are never cut: when the natural width of every
    column is more than the console has, whole columns are left out, group
    by group in ``drop_order`` (least important first), and a line under
    the table names them.  Columns in no group always stay: they identify
    the row.  The width is decided at render time by measuring the built
    table, so one renderable serves any console.

    ``title`` goes above the table and ``footer`` right under it, ``notes``
    after the left-out line; all three wrap at the console width rather
    than the table's.
    """

    def __init__(self, columns, drop_order=(), title: str | None = None, footer=(), notes=()):
        self.columns = list(columns)
        keys = {c.key for c in self.columns}
        groups = (tuple(k for k in ((g,) if isinstance(g, str) else g) if k in keys) for g in drop_order)
        self.drop_order = [g for g in groups if g]
        self.title = title
        self.footer = list(footer)
        self.notes = list(notes)

    def build(self, columns) -> RichTable:
        out = RichTable(box=box.SIMPLE_HEAVY)
        for c in columns:
            # fold, not ellipsis: only a console narrower than the
            # identifying columns can need it, and a folded number is still whole
            out.add_column(c.header, justify=c.justify, style=c.style, no_wrap=True, overflow="fold")
        for row in zip(*(c.cells for c in columns)):
            out.add_row(*row)
        return out

    def fit(self, console: Console, options: ConsoleOptions) -> tuple[RichTable, list[str]]:
        """The table to print within ``options.max_width`` and the keys left out of it."""
        width = options.max_width
        # measured without a limit: the natural width, every cell on one line
        wide = options.update(width=max(width, 100_000))
        shown, left_out = list(self.columns), []
        table = self.build(shown)
        for group in self.drop_order:
            if Measurement.get(console, wide, table).maximum <= width:
                break
            left_out += group
            shown = [c for c in shown if c.key not in group]
            table = self.build(shown)
        return table, left_out

    def __rich_console__(self, console: Console, options: ConsoleOptions):
        table, left_out = self.fit(console, options)
        if self.title:
            yield Text(self.title, style="table.title")
        yield table
        yield from self.footer
        if left_out:
            yield left_out_line(left_out, options.max_width)
        yield from self.notes


def left_out_line(keys, width: int) -> str:
    """The line under a table naming the columns a narrow console left out
    (a column's twin in another unit as ``height_m in ft``)."""
    named = ", ".join(key.replace(":", " in ", 1) for key in keys)
    return (f"[dim]left out at {width} columns: {named} "
            f"(--format csv or a wider terminal shows them)[/dim]")


def row_cap_line(shown: int, total: int) -> str:
    """The line under a table that shows only its first rows."""
    return f"… showing the first {shown} of {total} rows; use --format csv for all of them"


def first_rows(table: Table, n: int) -> Table:
    """The first ``n`` rows (the table itself when it is not longer)."""
    return table if len(table) <= n else Table({name: col[:n] for name, col in table.columns.items()})


def row_total(table: Table, total_rows: int | None) -> int:
    """Rows of the whole result: ``total_rows`` when a caller hands over
    only the first rows of a longer one."""
    return len(table) if total_rows is None else max(int(total_rows), len(table))


def status_legend(table: Table) -> list[str]:
    """Each distinct (status, reason) once, in order of appearance."""
    reasons = dict.fromkeys(zip(table.columns["status"].tolist(), table.columns["reason"].tolist()))
    return [f"{status_text(st)}: {escape(str(why))}" for st, why in reasons if why]


def row_record(table: Table, row: int = 0) -> dict:
    """One row as a dict of plain Python values."""
    return {n: (v.item() if hasattr(v, "item") else v) for n, v in ((n, table.columns[n][row]) for n in table.names)}


def is_undefined(v) -> bool:
    """None or NaN: a value a view shows as —."""
    return v is None or (isinstance(v, float) and math.isnan(v))
