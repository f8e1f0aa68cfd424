"""One way to build a terminal view: columns declared once as
:class:`ColumnSpec` and turned into a :class:`FitTable` by
:func:`build_table` (a line per row) or into quantity/value/unit rows by
:func:`quantity_rows` (one result, a quantity per line).

A spec says which CSV column it shows, its header words and SI unit, its
digits (or a formatter), when a narrow console leaves it out and its
style; with a ``kind`` it is a physical quantity, and the
:class:`~deathsphere.render.display_units.DisplayUnits` the command line
hands over decide whether the same figure shows again beside it in the
unit typed (``height m`` then ``height ft``).  The builder writes the
titles, the setup line, the left-out line and the row cap, so every view
says them the same way.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from rich.markup import escape

from deathsphere.render.display_units import AS_TYPED, DisplayUnit, DisplayUnits
from deathsphere.render.terminal_table import (
    MAX_TERMINAL_ROWS,
    Column,
    FitTable,
    first_rows,
    format_number,
    is_undefined,
    row_cap_line,
    row_record,
    row_total,
)
from deathsphere.table import Table

#: The drop priority of a column that goes only when nothing else is left
#: to go (less its place: of several such, the rightmost goes first).
LAST = 1e9
#: Headers whose unit is a sign glued to the words (θ°), not a line under them.
GLUED_UNITS = ("°",)


@dataclass(frozen=True)
class ColumnSpec:
    """One column of a view (or one row of a one-result view).

    ``key``: the CSV column it shows (or a name of the view's own, with
    ``value`` reading the row); ``header``: its words (a label in a
    one-result view); ``unit``: the SI unit the column holds; ``digits``:
    significant digits, or ``format`` (value -> text) instead; ``drop``:
    when a narrow console leaves it out, lowest first (columns of one
    number go together; None: it identifies the row and always stays);
    ``kind`` and ``params``: the physical kind and the options the value
    was typed as, for the unit shown beside SI; ``crew``: the unit shown
    beside SI when nothing was asked for (km/h for a rider's speed);
    ``show``: ``both`` (SI, and the other unit beside it), ``display``
    (the other unit alone, or SI when there is none) or ``echo`` (SI only
    where another unit is shown elsewhere: ride's speed in m/s after the
    km/h); ``when``: a test of the rows shown, False leaves it out;
    ``source``: the equation, for a one-result view."""

    key: str
    header: str
    unit: str = ""
    digits: int = 4
    format: Callable | None = None
    drop: float | None = None
    justify: str = "right"
    style: str | None = None
    kind: str | None = None
    params: tuple = ()
    crew: DisplayUnit | None = None
    show: str = "both"
    value: Callable | None = None
    when: Callable | None = None
    source: str = ""

    def heading(self, unit: str | None = None) -> str:
        unit = self.unit if unit is None else unit
        if not unit:
            return self.header
        return f"{self.header}{unit}" if unit in GLUED_UNITS else f"{self.header}\n{unit}"

    def display_unit(self, units: DisplayUnits) -> DisplayUnit | None:
        """The unit shown beside (or, ``display``, instead of) SI; None: SI alone."""
        if self.kind is None:
            return None
        unit = units.unit(self.kind, self.params, self.crew)
        return None if unit is None or unit.name == self.unit else unit

    def raw(self, get: dict):
        return self.value(get) if self.value is not None else get.get(self.key)

    def text(self, value, number=format_number, digits: int | None = None) -> str:
        if self.format is not None:
            return self.format(value)
        if isinstance(value, str):
            return escape(value)
        return number(value, self.digits if digits is None else digits)


def converted(value, unit: DisplayUnit | None):
    """``value`` (or each value of a tuple: a range's ends) in ``unit``;
    undefined values stay undefined."""
    if unit is None:
        return value
    if isinstance(value, tuple):
        return tuple(converted(v, unit) for v in value)
    return value if is_undefined(value) else unit.of(value)


def _keep(spec: ColumnSpec, head: Table, shown: DisplayUnit | None) -> bool:
    if spec.when is not None and not spec.when(head):
        return False
    if spec.value is None and spec.key not in head:
        return False
    return not (spec.show == "echo" and shown is None)


def columns_of(head: Table, specs, units: DisplayUnits = AS_TYPED, number=format_number):
    """The :class:`Column` list and drop order of ``specs`` over the rows
    of ``head``: each spec's column, and right after it the same figures
    in the unit :meth:`ColumnSpec.display_unit` gives (left out with it;
    beside a column that always stays, it stays too if the quantity was
    typed in that unit, else it is the last to go)."""
    records = [row_record(head, i) for i in range(len(head))]
    columns, drops = [], []
    for spec in specs:
        other = spec.display_unit(units)
        if not _keep(spec, head, other):
            continue
        values = [spec.raw(get) for get in records]
        parts = []
        if spec.show == "display" and other is not None:
            parts.append((f"{spec.key}:{other.name}", other))
        else:
            parts.append((spec.key, None))
            if spec.show == "both" and other is not None:
                parts.append((f"{spec.key}:{other.name}", other))
        for key, unit in parts:
            cells = [spec.text(converted(v, unit), number) for v in values]
            columns.append(Column(key, spec.heading(unit.name if unit else None), cells, spec.justify, spec.style))
            drop = spec.drop
            if drop is None and unit is not None and spec.show == "both" and not units.was_typed(spec.params):
                drop = LAST - len(columns)
            if drop is not None:
                drops.append((drop, key))
    order = []
    for priority in sorted({p for p, _ in drops}):
        order.append(tuple(k for p, k in drops if p == priority))
    return columns, order


def build_table(table: Table, specs, *, units: DisplayUnits = AS_TYPED, title: str | None = None,
                setup: str | None = None, notes=(), total_rows: int | None = None, number=format_number,
                cls=FitTable, extra=None) -> FitTable:
    """A line per row (the first :data:`MAX_TERMINAL_ROWS` of
    ``total_rows``): ``specs``' columns, the row cap line under the table
    when rows were left out, then the ``setup`` line (dim) and ``notes``.
    ``number``: the view's number format (the one of ``terminal_table``
    unless the view has its own); ``extra``: (columns, head) -> columns,
    a view's last word on its columns (a column that varies by row)."""
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    columns, drop_order = columns_of(head, specs, units, number)
    if extra is not None:
        columns = extra(columns, head)
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    lines = ([f"[dim]{setup}[/dim]"] if setup else []) + list(notes)
    return cls(columns, drop_order, title=title, footer=footer, notes=lines)


def quantity_rows(get: dict, specs, units: DisplayUnits = AS_TYPED, number=format_number, digits: int = 5):
    """(label, value, unit, source) rows of one result: a spec per row,
    and under it ``  the same in ft`` where another unit is shown
    (``display``: that unit's row first, SI under it)."""
    rows = []
    for spec in specs:
        other = spec.display_unit(units)
        if spec.when is not None and not spec.when(get):
            continue
        if spec.value is None and spec.key not in get:
            continue
        value = spec.raw(get)
        si = (spec.header, spec.text(value, number, digits), spec.unit, spec.source)
        if other is None:
            if spec.show != "echo":
                rows.append(si)
            continue
        same = (spec.text(converted(value, other), number, digits), other.name)
        if spec.show == "display":
            rows.append((spec.header, *same, spec.source))
            rows.append((f"  the same in {spec.unit}", si[1], spec.unit, _inverse(other.how)))
        else:
            rows.append(si)
            rows.append((f"  the same in {other.name}", *same, other.how))
    return rows


def _inverse(how: str) -> str:
    """``× 3.6`` read back: ``÷ 3.6``."""
    if how.startswith("× "):
        return "÷ " + how[2:]
    if how.startswith("÷ "):
        return "× " + how[2:]
    return how


def quantity_text(value, si_unit: str, unit: DisplayUnit | None, digits: int = 4, number=format_number) -> str:
    """A quantity for a setup line: ``2.438 m``, with the other unit in
    brackets where one is shown (``2.438 m (8 ft)``)."""
    text = f"{number(value, digits)} {si_unit}".rstrip()
    if unit is None or is_undefined(value):
        return text
    return f"{text} ({number(unit.of(value), digits)} {unit.name})"


def globe_text(get: dict, units: DisplayUnits, number=format_number) -> str:
    """The globe's radius for a setup line, ``r = 2.438 m``; given by its
    diameter in another unit, that beside it (``r = 2.438 m (diameter
    16 ft)``), or the radius in the unit shown for lengths."""
    r = get["r_m"]
    across = units.typed.get("diameter")
    if across is not None and not is_undefined(r):
        return f"r = {number(r)} m (diameter {number(across.of(2 * r))} {across.name})"
    return f"r = {quantity_text(r, 'm', _other(units.unit('length', ('r',)), 'm'), number=number)}"


def _other(unit: DisplayUnit | None, si: str) -> DisplayUnit | None:
    return None if unit is None or unit.name == si else unit
