"""Writers for result tables: rich table, CSV, JSON and NDJSON.

Every writer takes an iterable of :class:`~deathsphere.model.Table` chunks so
that sweeps stream with flat memory; the header (CSV) or the opening bracket
(JSON) is written once.  Undefined values (NaN) are empty in CSV and null in
JSON; floats are written in Python's shortest round-trip form.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import IO, Iterable

import numpy as np
from rich import box
from rich.console import Console, ConsoleOptions, Group
from rich.markup import escape
from rich.measure import Measurement
from rich.table import Table as RichTable
from rich.text import Text

from deathsphere.model import TEXT_COLUMNS, Table
from deathsphere.results.table1 import decimals

FORMATS = ("table", "csv", "json", "ndjson")


def _csv_field(text: str) -> str:
    if any(c in text for c in ',"\n\r'):
        return '"' + text.replace('"', '""') + '"'
    return text


def _float_text(x: float) -> str:
    return "" if x != x else repr(x)


def _column_strings(name: str, values: np.ndarray) -> list[str]:
    """Text of one column.  Values that repeat (inputs, statuses, reasons)
    are formatted once each: a chunk of a grid holds few distinct inputs, and
    float formatting is what CSV output spends its time on."""
    n = len(values)
    if n == 0:
        return []
    if name in TEXT_COLUMNS or values.dtype == object:
        # few distinct texts per column: quote each once (None -> empty)
        cache: dict = {}
        text = []
        for v in values.tolist():
            t = cache.get(v)
            if t is None:
                t = cache[v] = "" if v is None else _csv_field(str(v))
            text.append(t)
        return text
    if values.dtype.kind in "iub":
        return list(map(str, values.tolist()))
    values = values.astype(np.float64, copy=False)
    # values compared by their bits: -0.0 == 0.0, yet repr tells them apart
    bits = values.view(np.int64)
    if (bits[0] == bits).all() or np.isnan(values).all():
        return [_float_text(float(values[0]))] * n
    if name in REPEATING_COLUMNS:
        unique, inverse = np.unique(bits, return_inverse=True)
        text = list(map(_float_text, unique.view(np.float64).tolist()))
        return [text[i] for i in inverse.tolist()]
    text = list(map(repr, values.tolist()))
    for i in np.flatnonzero(np.isnan(values)).tolist():
        text[i] = ""
    return text


#: Input columns: in a grid chunk they take few distinct values.
REPEATING_COLUMNS = frozenset({"theta_deg", "alpha_deg", "a_m", "r_m", "k", "g_m_s2", "mu_available"})


def csv_text(table: Table, header: bool) -> str:
    """One chunk as CSV text (with the header line first if asked)."""
    columns = [_column_strings(n, table[n]) for n in table.names]
    lines = [",".join(row) for row in zip(*columns)]
    if header:
        lines.insert(0, ",".join(table.names))
    return "\n".join(lines) + "\n" if lines else ""


#: Which CSV writer formats a chunk: None picks per chunk (below), True
#: the compiled one (:mod:`deathsphere.fastwriters`, the ``fast`` extra)
#: for every chunk, False the pure-Python one.  The bytes are the same
#: (tests/test_writers.py compares them), so chunks may mix.
COMPILED_CSV: bool | None = None

#: With COMPILED_CSV None the compiled writer takes over once an output is
#: this long, and only for chunks of COMPILED_MIN_CHUNK rows or more:
#: importing polars costs ~0.2 s, which a short output (`orbit`, a small
#: sweep) would pay in latency, and polars' per-call cost (~1 ms) is more
#: than the pure-Python writer spends on a few hundred rows.
COMPILED_AFTER_ROWS = 20_000
COMPILED_MIN_CHUNK = 1024


def write_csv(chunks: Iterable[Table], out: IO[str], compiled: bool | None = None) -> int:
    """Stream tables as CSV: the header once, then every chunk's rows.
    ``compiled`` None takes :data:`COMPILED_CSV`."""
    mode = COMPILED_CSV if compiled is None else compiled
    fast = None
    rows = 0
    for i, table in enumerate(chunks):
        text = csv_text
        if mode or (mode is None and rows >= COMPILED_AFTER_ROWS and len(table) >= COMPILED_MIN_CHUNK):
            if fast is None:
                from deathsphere import fastwriters

                fast = fastwriters.csv_text if fastwriters.csv_available() else False
            text = fast or csv_text
        out.write(text(table, header=i == 0))
        rows += len(table)
    return rows


def _json_value(v):
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def json_records(table: Table) -> list[str]:
    cols = [(n, table[n].tolist()) for n in table.names]
    return [json.dumps({n: _json_value(v[i]) for n, v in cols}) for i in range(len(table))]


def write_ndjson(chunks: Iterable[Table], out: IO[str]) -> int:
    rows = 0
    for table in chunks:
        lines = json_records(table)
        if lines:
            out.write("\n".join(lines) + "\n")
        rows += len(lines)
    return rows


def write_json(chunks: Iterable[Table], out: IO[str]) -> int:
    """A JSON array of row objects, streamed chunk by chunk."""
    rows = 0
    out.write("[")
    for table in chunks:
        for line in json_records(table):
            out.write(("\n  " if rows == 0 else ",\n  ") + line)
            rows += 1
    out.write("\n]\n" if rows else "]\n")
    return rows


def format_number(value, digits: int = 4) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "—"
    if isinstance(value, (int, np.integer)):
        return str(value)
    if isinstance(value, float) and math.isinf(value):
        return "∞" if value > 0 else "-∞"
    return f"{value:.{digits}g}"


STATUS_STYLE = {"ok": "green", "slips": "yellow", "invalid": "red"}


def status_text(status: str) -> str:
    style = STATUS_STYLE.get(status, "magenta")
    return f"[{style}]{status}[/{style}]"


# ---------------------------------------------------------------------------
# tables that fit the console

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
    return (f"[dim]left out at {width} columns: {', '.join(keys)} "
            f"(--format csv or a wider terminal shows them)[/dim]")


def row_cap_line(shown: int, total: int) -> str:
    return f"… showing the first {shown} of {total} rows; use --format csv for all of them"


def _head(table: Table, n: int) -> Table:
    return table if len(table) <= n else Table({name: col[:n] for name, col in table.columns.items()})


def _total(table: Table, total_rows: int | None) -> int:
    return len(table) if total_rows is None else max(int(total_rows), len(table))


def _legend(table: Table) -> list[str]:
    """Each distinct (status, reason) once, in order of appearance."""
    reasons = dict.fromkeys(zip(table["status"].tolist(), table["reason"].tolist()))
    return [f"{status_text(st)}: {escape(str(why))}" for st, why in reasons if why]


#: (column, label, unit, source) for the one-orbit view.
ORBIT_FIELDS = (
    ("r_prime_m", "r' centre to axis", "m", "eq. 8b"),
    ("omega_rad_s", "Ω orbital rate", "rad/s", "eq. 29"),
    ("period_s", "period 2π/Ω", "s", ""),
    ("v_cm_m_s", "v_cm = |r'|Ω centre speed", "m/s", ""),
    ("spin_rad_s", "ω₁ = r'Ω/a wheel spin", "rad/s", "eq. 13"),
    ("omega3_rad_s", "ω₃ = -Ω sin α", "rad/s", "eq. 13"),
    ("branch", "branch of eq. 55 (0 slow, 1 fast)", "", "eq. 55"),
    ("omega3_min_real_rad_s", "least |ω₃| for a real orbit", "rad/s", "eq. 56"),
    ("omega3_min_contact_rad_s", "least |ω₃| for contact", "rad/s", "eq. 58/59"),
    ("accel_m_s2", "centre acceleration", "m/s²", "eq. 32"),
    ("accel_g", "centre acceleration", "g", "eq. 36"),
    ("normal_per_mass_m_s2", "normal force / m", "m/s²", "eq. 32"),
    ("friction_per_mass_m_s2", "friction / m (+ down)", "m/s²", "eq. 32"),
    ("mu_required", "μ required", "", "eq. 35"),
    ("growth_rate_1_s", "growth rate (max Re λ)", "1/s", "exact"),
    ("freq_slow_rad_s", "nutation, slow (turning frame)", "rad/s", "exact"),
    ("freq_fast_rad_s", "nutation, fast (turning frame)", "rad/s", "exact"),
)

OK_REASON = "fits, Ω² > 0, keeps contact, enough friction"

STABILITY_STYLE = {"stable": "[green]stable[/green]", "unstable": "[red]unstable[/red]",
                   "unknown": "[magenta]unknown[/magenta]"}

#: Labels that differ by body: (body, column) -> (label, source); None hides the row.
BODY_LABELS = {
    ("sphere", "r_prime_m"): ("r' centre to axis, (r ∓ a) sin θ", "eq. 42"),
    ("sphere", "accel_m_s2"): ("centre acceleration", ""),
    ("sphere", "spin_rad_s"): ("rolling rate v_cm/a", ""),
    ("sphere", "omega3_rad_s"): ("ω₃ spin about contact normal", "eq. 55"),
    ("sphere", "omega_rad_s"): ("Ω orbital rate (signed)", "eq. 55"),
    ("sphere", "accel_g"): ("centre acceleration", ""),
    ("sphere", "normal_per_mass_m_s2"): ("normal force / m", "eq. 57"),
    ("sphere", "friction_per_mass_m_s2"): ("friction / m (+ down)", "eq. 57"),
    ("particle", "omega_rad_s"): ("Ω orbital rate", "Ω² = -g/(r cos θ)"),
    ("particle", "r_prime_m"): ("r' = r sin θ", ""),
    ("particle", "accel_m_s2"): ("centre acceleration", ""),
    ("particle", "normal_per_mass_m_s2"): ("normal force / m", ""),
    ("particle", "friction_per_mass_m_s2"): None,
    ("particle", "spin_rad_s"): None,
    ("particle", "omega3_rad_s"): None,
    ("particle", "accel_g"): ("centre acceleration", ""),
    ("particle", "mu_required"): None,
    ("wheel", "branch"): None,
    ("wheel", "omega3_min_real_rad_s"): None,
    ("wheel", "omega3_min_contact_rad_s"): None,
    ("particle", "omega3_min_real_rad_s"): None,
    ("particle", "omega3_min_contact_rad_s"): None,
    ("particle", "branch"): None,
}


def _record(table: Table, row: int = 0) -> dict:
    """One row as plain Python values."""
    return {n: (v.item() if hasattr(v, "item") else v) for n, v in ((n, table[n][row]) for n in table.names)}


def _setup_line(get: dict) -> str:
    return (f"a = {format_number(get['a_m'])} m, r = {format_number(get['r_m'])} m, "
            f"k = {format_number(get['k'])}, g = {format_number(get['g_m_s2'], 6)} m/s²")


def quantity_table(title: str, get: dict, rows, ok_text: str, notes=()) -> FitTable:
    """The one-result view: ``rows`` of (label, value, unit, source), then
    the stability (if computed) and the status; the reason under it.  On a
    narrow console the source column goes first."""
    rows = list(rows)
    if get.get("stability"):
        rows.append(("stability", STABILITY_STYLE.get(get["stability"], get["stability"]), "",
                     get["stability_method"]))
    rows.append(("status", status_text(get["status"]), "", ""))
    labels, values, units, sources = (list(c) for c in zip(*rows))
    columns = [Column("quantity", "quantity", labels, "left"), Column("value", "value", values),
               Column("unit", "unit", units, "left"), Column("source", "source", sources, "left", "dim")]
    reason = f"[dim italic]{get['status']}: {escape(get['reason'] or ok_text)}[/dim italic]"
    return FitTable(columns, drop_order=("source",), title=title, footer=[reason, *notes])


def spin_needed_line(get: dict) -> str:
    """Sphere: the least |ω₃| for an orbit and for contact, as a sentence."""
    real, contact = get["omega3_min_real_rad_s"], get["omega3_min_contact_rad_s"]
    where = f"θ = {format_number(get['theta_deg'])}°"
    contact_text = ("no spin keeps contact" if _isnan(contact)
                    else f"≥ {format_number(contact)} rad/s for contact (eqs. 58/59)")
    return f"needs |ω₃| ≥ {format_number(real)} rad/s for an orbit (eq. 56), {contact_text} at {where}"


def spin_too_low(get: dict) -> bool:
    """A rolling sphere with no orbit (or no contact) because |ω₃| is below
    the least that gives one; not, say, the missing second branch on the
    equator, or the slow branch of a spin that is fast enough."""
    if get.get("body") != "sphere" or "omega3_min_real_rad_s" not in get or _isnan(get.get("omega3_rad_s")):
        return False
    spin = abs(get["omega3_rad_s"])
    if get["status"] == "no_orbit":
        return spin < get["omega3_min_real_rad_s"]
    if get["status"] == "no_contact":
        least = get["omega3_min_contact_rad_s"]
        return _isnan(least) or spin < least
    return False


def one_orbit_table(table: Table, row: int = 0) -> FitTable:
    """A two-column view of every quantity of one orbit (undefined ones as —)."""
    get = _record(table, row)
    angles = f"θ = {format_number(get['theta_deg'])}°"
    if not _isnan(get["alpha_deg"]):
        angles += f", α = {format_number(get['alpha_deg'])}°"
    rows = []
    for col, label, unit, source in ORBIT_FIELDS:
        override = BODY_LABELS.get((get["body"], col), (label, source))
        if col in get and override is not None:
            rows.append((override[0], format_number(get[col], 5), unit, override[1]))
    mu = get.get("mu_available")
    rows.append(("μ available", "∞" if _isnan(mu) else format_number(mu), "", "--mu"))
    notes = []
    if spin_too_low(get):
        notes.append(spin_needed_line(get))
    return quantity_table(f"{get['body']} {get['side']}, {angles}\n{_setup_line(get)}", get, rows, OK_REASON,
                          notes)


def _isnan(v) -> bool:
    return v is None or (isinstance(v, float) and math.isnan(v))


#: Headers of the many-orbit terminal view (units on the last line).
SUMMARY_HEADERS = {
    "input_row": "#", "theta_deg": "θ°", "alpha_deg": "α°", "branch": "br", "omega3_rad_s": "ω₃\nrad/s",
    "status": "status", "omega_rad_s": "Ω\nrad/s", "v_cm_m_s": "v_cm\nm/s", "spin_rad_s": "ω₁\nrad/s",
    "accel_g": "accel\ng", "mu_required": "μ\nrequired", "stability": "stability",
    "omega3_min_real_rad_s": "|ω₃| min\norbit\nrad/s", "omega3_min_contact_rad_s": "|ω₃| min\ncontact\nrad/s",
}
#: Columns of the many-orbit view per body, in display order.  The ones not
#: in SUMMARY_DROP_ORDER identify the row (#, θ, α or branch, status) and are
#: always shown.
SUMMARY_COLUMNS = {
    "wheel": ("input_row", "theta_deg", "alpha_deg", "status", "omega_rad_s", "v_cm_m_s",
              "accel_g", "mu_required", "stability"),
    "sphere": ("input_row", "theta_deg", "branch", "omega3_rad_s", "status", "omega_rad_s", "v_cm_m_s",
               "omega3_min_real_rad_s", "omega3_min_contact_rad_s", "mu_required", "stability"),
    "particle": ("input_row", "theta_deg", "status", "omega_rad_s", "v_cm_m_s", "accel_g"),
    "mixed": ("input_row", "theta_deg", "alpha_deg", "branch", "status", "omega_rad_s", "v_cm_m_s",
              "mu_required", "stability"),
}
#: What a narrow console leaves out first, per body.  Stability and μ are
#: verdicts on an orbit that exists, so they go before the orbit itself
#: (Ω, v_cm).  For a sphere the least spins go first: they depend on θ
#: alone, not on the row, and for the rows that need them (no orbit, no
#: contact) a line under the table gives them anyway; its own ω₃ is an
#: input and goes last.
SUMMARY_DROP_ORDER = {
    "wheel": ("stability", "mu_required", "accel_g", "v_cm_m_s", "omega_rad_s"),
    "sphere": ("omega3_min_contact_rad_s", "omega3_min_real_rad_s", "stability", "mu_required", "v_cm_m_s",
               "omega_rad_s", "omega3_rad_s"),
    "particle": ("accel_g", "v_cm_m_s", "omega_rad_s"),
    "mixed": ("stability", "mu_required", "v_cm_m_s", "omega_rad_s"),
}
#: Lines of "needs |ω₃| ≥ ..." under a many-sphere table; the columns carry the rest.
MAX_SPIN_LINES = 3


def _summary_cells(col: str, values: list) -> list[str]:
    if col == "status":
        return [status_text(v) for v in values]
    if col == "stability":
        return [STABILITY_STYLE.get(v, v) for v in values]
    if col in TEXT_COLUMNS:
        return [escape(str(v)) for v in values]
    return [format_number(v) for v in values]


def _spin_lines(table: Table) -> list[str]:
    """For the spheres shown whose spin is too low for an orbit or for
    contact: the least spin that would do, once per setup and θ."""
    if "omega3_min_real_rad_s" not in table:
        return []
    rows = [i for i, (b, s) in enumerate(zip(table["body"].tolist(), table["status"].tolist()))
            if b == "sphere" and s != "ok"]
    setup_cols = ("a_m", "r_m", "k", "g_m_s2", "side")
    first = {}
    for i in rows:
        get = _record(table, i)
        if spin_too_low(get):
            first.setdefault(tuple(get[c] for c in ("theta_deg", *setup_cols)), i)
    several_setups = len({key[1:] for key in first}) > 1
    lines = []
    for key, i in list(first.items())[:MAX_SPIN_LINES]:
        get = _record(table, i)
        line = spin_needed_line(get)
        if several_setups:
            line += f" ({get['side']}, {_setup_line(get)})"
        lines.append(line)
    if len(first) > MAX_SPIN_LINES:
        lines.append(f"… and at {len(first) - MAX_SPIN_LINES} more θ: see the |ω₃| min columns "
                     f"(omega3_min_real_rad_s, omega3_min_contact_rad_s)")
    return lines


def many_orbits_table(table: Table, title: str | None = None, total_rows: int | None = None) -> FitTable:
    """One summary row per orbit (the first MAX_TERMINAL_ROWS of
    ``total_rows``), then each distinct reason once."""
    total = _total(table, total_rows)
    head = _head(table, MAX_TERMINAL_ROWS)
    bodies = set(head["body"].tolist())
    kind = bodies.pop() if len(bodies) == 1 else "mixed"
    columns = [Column(col, SUMMARY_HEADERS[col], _summary_cells(col, head[col].tolist()),
                      "left" if col in TEXT_COLUMNS else "right")
               for col in SUMMARY_COLUMNS[kind] if col in head]
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    return FitTable(columns, SUMMARY_DROP_ORDER[kind], title=title, footer=footer,
                    notes=[*_legend(head), *_spin_lines(head)])


#: Column-name endings that are units, longest first.
UNIT_SUFFIXES = (("_m_s2", "m/s²"), ("_rad_s", "rad/s"), ("_m_s", "m/s"), ("_1_s", "1/s"), ("_deg", "deg"),
                 ("_s", "s"), ("_m", "m"), ("_g", "g"))
#: Columns of any table that say which row it is: never left out.
GENERIC_KEYS = frozenset({"input_row", "curve", "theta_deg", "phi_deg", "interval", "status", "found"})


def column_header(name: str) -> str:
    """``v_min_m_s`` -> ``v min`` over ``m/s``: the unit stays in the header."""
    for suffix, unit in UNIT_SUFFIXES:
        if name.endswith(suffix) and len(name) > len(suffix):
            return f"{_words(name[:-len(suffix)])}\n{unit}"
    return _words(name)


def _words(stem: str) -> str:
    # v_cm is a symbol, not two words; "per mass" is the "/ m" of the orbit views
    return stem.replace("v_cm", "\0").replace("_per_mass", " / m").replace("_", " ").replace("\0", "v_cm")


def _plain_cell(v, digits: int = 4) -> str:
    if isinstance(v, (str, bool, np.bool_)):
        return escape(str(v))
    return format_number(v, digits)


def generic_table(table: Table, title: str | None = None, total_rows: int | None = None) -> FitTable:
    """Any table: one column per field (for results that are not orbits).

    Columns equal in every row (the inputs) go to a line under it, and a
    status's reason to a legend.  On a narrow console the columns are left
    out from the right (these tables put their inputs first), keeping the
    first column and any of GENERIC_KEYS."""
    if len(table) == 1 and not (total_rows or 0) > 1:
        names = [(n, v) for n, v in _record(table).items()]
        return FitTable([Column("quantity", "quantity", [n for n, _ in names], "left"),
                         Column("value", "value", [_plain_cell(v, 6) for _, v in names])], title=title)
    total = _total(table, total_rows)
    head = _head(table, MAX_TERMINAL_ROWS)
    same = [n for n in table.names if _constant(table[n])]
    legend = _legend(head) if "status" in table and "reason" in table else []
    hidden = set(same) | ({"reason"} if legend or "status" in table else set())
    names = [n for n in table.names if n not in hidden]
    columns = [Column(n, column_header(n), [_plain_cell(v) for v in head[n].tolist()],
                      "left" if head[n].dtype == object else "right") for n in names]
    keys = {names[0], *GENERIC_KEYS} if names else set()
    drop_order = [n for n in reversed(names) if n not in keys]
    first = _record(head) if same else {}
    constants = ", ".join(f"{n} = {_plain_cell(first[n])}" for n in same if first[n] != "")
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    notes = [f"[dim]{constants}[/dim]"] if constants else []
    return FitTable(columns, drop_order, title=title, footer=footer, notes=[*notes, *legend])


def _constant(values: np.ndarray) -> bool:
    if len(values) == 0:
        return False
    if values.dtype.kind == "f":
        return bool((values == values[0]).all() or np.isnan(values).all())
    if values.dtype.kind in "iub":
        return bool((values == values[0]).all())
    first = str(values[0])
    return all(str(v) == first for v in values.tolist())


def write_rich_table(table: Table, console: Console, title: str | None = None,
                     total_rows: int | None = None) -> int:
    """Terminal view: every quantity for one orbit, a summary row per orbit
    for many; any other table column by column.  At most MAX_TERMINAL_ROWS
    rows are formatted and printed, with a line saying how many there are
    (``total_rows`` when the caller hands over only the first rows of a
    longer result).  Returns the number of rows given."""
    total = _total(table, total_rows)
    if "body" not in table or "status" not in table:
        console.print(generic_table(table, title, total))
    elif len(table) == 1 and total == 1:
        console.print(one_orbit_table(table))
    else:
        console.print(many_orbits_table(table, title, total))
    return len(table)


#: The acceleration trio of Table 1 ("No. of g's" printed beside both
#: readings of it) goes first, as a block: one of the three alone says
#: nothing; then the speed pair; μ, the paper's headline, stays longest.
TABLE1_DROP_ORDER = (("g's", "acc g", "acc m/s²"), ("v_cm", "eq.29"))


def table1_view(table: Table, printed) -> FitTable:
    """Table 1 printed vs computed (✓ where the printed value is reproduced
    at its printed precision), then the notes."""
    tick = {True: "[green]✓[/green]", False: "[red]✗[/red]"}
    rows = []
    notes = []
    for i, row in enumerate(printed):
        rows.append((
            row[0], row[1], row[2],
            f"{table['mu_computed'][i]:.{decimals(row[2]) + 1}f}{tick[bool(table['mu_agrees'][i])]}",
            row[3],
            f"{table['v_cm_computed_m_s'][i]:.{decimals(row[3]) + 1}f}{tick[bool(table['v_cm_agrees'][i])]}",
            row[4],
            f"{table['accel_g_computed'][i]:.2f}{tick[bool(table['gs_column_is_g'][i])]}",
            f"{table['accel_m_s2_computed'][i]:.1f}{tick[bool(table['gs_column_is_m_s2'][i])]}",
        ))
        if not table["mu_agrees"][i]:
            notes.append(f"θ={row[0]}° α={row[1]}°: μ printed {row[2]}, eq. 35 gives "
                         f"{table['mu_computed'][i]:.4f} (erratum T1-mu)")
    if table["gs_column_is_m_s2"].all() and not table["gs_column_is_g"].any():
        notes.append("\"No. of g's\" is the centre acceleration in m/s², not in g, in every row (erratum T1-g)")
    heads = ("θ°", "α°", "μ", "μ eq.35", "v_cm", "eq.29", "g's", "acc g", "acc m/s²")
    columns = [Column(h, h, [r[j] for r in rows]) for j, h in enumerate(heads)]
    lines = ["Printed: μ, v_cm (m/s), \"No. of g's\"; computed with one more digit; "
             "✓ = reproduced at the printed precision.", *notes, "Evidence: docs/errata.md"]
    return FitTable(columns, TABLE1_DROP_ORDER,
                    title="McDonald (1993) Table 1: wheel a = 0.3 m, k = 1/2, sphere r = 3.0 m", notes=lines)


#: (column, label, unit, source) for the vertical-orbit view.
VERTICAL_FIELDS = (
    ("r_prime_m", "r' radius of the centre's circle", "m", "eq. 8b"),
    ("v_cm_m_s", "speed at the top", "m/s", ""),
    ("v_top_min_m_s", "least top speed for contact", "m/s", "eq. 28a"),
    ("omega_rad_s", "rate at the top", "rad/s", ""),
    ("v_bottom_m_s", "speed at the bottom", "m/s", "eq. 27"),
    ("period_s", "lap time", "s", "eq. 27"),
    ("accel_g", "largest acceleration (bottom)", "g", ""),
    ("normal_top_per_mass_m_s2", "normal force / m at the top", "m/s²", "eq. 28"),
    ("normal_bottom_per_mass_m_s2", "normal force / m at the bottom", "m/s²", "eq. 28"),
    ("mu_top", "μ at top and bottom, |cot θ|", "", "eq. 28b"),
    ("phi_worst_deg", "worst point φ (μ peaks)", "deg", ""),
    ("mu_required", "μ required (at the worst point)", "", "eq. 28b"),
    ("phi_slip_deg", "first slip at φ (with --mu)", "deg", ""),
    ("phi_leave_deg", "leaves the surface at φ", "deg", "eq. 82"),
    ("growth_rate_1_s", "growth rate of a perturbation", "1/s", "floquet"),
)

#: Columns of the many-vertical-orbit view: (column, header).
VERTICAL_COLUMNS = (("input_row", "#"), ("theta_deg", "θ°"), ("v_cm_m_s", "v top\nm/s"), ("status", "status"),
                    ("v_top_min_m_s", "v min\nm/s"), ("period_s", "lap\ns"), ("phi_worst_deg", "worst\nφ°"),
                    ("mu_required", "μ\nrequired"), ("phi_leave_deg", "leaves\nφ°"))
#: Left out first on a narrow console: where μ peaks and the lap time
#: describe an orbit that works; where it leaves the wall, the μ it needs
#: and the least top speed say whether it works at all.
VERTICAL_DROP_ORDER = ("phi_worst_deg", "period_s", "phi_leave_deg", "mu_required", "v_top_min_m_s")


def vertical_view(table: Table, total_rows: int | None = None):
    """One vertical orbit: a quantity per line; several: one line each
    (the first MAX_TERMINAL_ROWS of them)."""
    if len(table) == 1 and not (total_rows or 0) > 1:
        get = _record(table)
        rows = [(label, format_number(get[col], 5), unit, source)
                for col, label, unit, source in VERTICAL_FIELDS if not _isnan(get[col])]
        title = f"vertical orbit, wheel {get['side']}, θ = {format_number(get['theta_deg'])}°\n{_setup_line(get)}"
        return quantity_table(title, get, rows, "keeps contact all round with enough friction")
    total = _total(table, total_rows)
    head = _head(table, MAX_TERMINAL_ROWS)
    columns = [Column(col, header, _summary_cells(col, head[col].tolist()), "left" if col == "status" else "right")
               for col, header in VERTICAL_COLUMNS]
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    return FitTable(columns, VERTICAL_DROP_ORDER, title="Vertical orbits (eqs. 27-28b)", footer=footer,
                    notes=_legend(head))


VERDICT_MARK = {"confirmed": "[green]✓ confirmed[/green]", "corrected": "[yellow]~ corrected[/yellow]",
                "refuted": "[red]✗ refuted[/red]"}


def checklist_view(table: Table, counts: dict) -> Group:
    """``deathsphere verify``: one block per claim, then the counts."""
    parts = []
    for row in table.records():
        parts.append(f"{VERDICT_MARK[row['verdict']]}  [bold]{escape(row['id'])}[/bold]  "
                     f"(sec. {escape(row['section'])}, {escape(row['equation'])}) {escape(row['claim'])}")
        parts.append(f"    [dim]{escape(row['evidence'])}[/dim]")
    parts.append("")
    parts.append(", ".join(f"{n} {v}" for v, n in counts.items()) + f" ({len(table)} claims)")
    return Group(*parts)


#: (column, label, unit) of the simulation summary view.
SIMULATION_FIELDS = (
    ("periods_simulated", "periods simulated", ""),
    ("event_time_s", "event at t", "s"),
    ("event_phi_deg", "event at phi", "deg"),
    ("max_theta_drift_deg", "max drift of theta", "deg"),
    ("max_alpha_drift_deg", "max drift of alpha", "deg"),
    ("min_normal_per_mass_m_s2", "least normal force / m", "m/s²"),
    ("max_mu_required", "most friction needed μ", ""),
    ("max_abs_energy_drift", "max |energy drift| (relative)", ""),
    ("max_constraint_residual", "max constraint residual", ""),
    ("n_steps", "steps", ""),
    ("wall_time_s", "wall time", "s"),
)


def simulation_view(summary: Table):
    """The summary of one simulated body (the first row if several)."""
    get = _record(summary)
    what = (f"{get['body']} {get['side']}, {get['orbit']} orbit, θ = {format_number(get['theta_deg'])}°"
            + (f", α = {format_number(get['alpha_deg'])}°" if not _isnan(get.get("alpha_deg")) else "")
            + (f", kick {format_number(get['perturb_rad'])} rad" if get.get("perturb_rad") else ""))
    out = RichTable(title=f"simulation: {what}\nsolve_ivp {get['method']}, rtol {get['rtol']:g}, "
                          f"atol {get['atol']:g}, {get['frame']} frame",
                    box=box.SIMPLE_HEAVY, title_justify="left")
    for head in ("quantity", "value", "unit"):
        out.add_column(head, justify="right" if head == "value" else "left", no_wrap=True)
    for col, label, unit in SIMULATION_FIELDS:
        if col in get and not _isnan(get[col]):
            out.add_row(label, format_number(get[col], 4), unit)
    status = get["status"]
    style = {"completed": "green", "contact_lost": "red", "slips": "yellow"}.get(status, "magenta")
    out.add_row("status", f"[{style}]{status}[/{style}]", "")
    out.caption = f"{status}: {get['reason']}" if get.get("reason") else None
    out.caption_justify = "left"
    return out


def _cell(v, digits=4):
    if v is None:
        return "—"
    if isinstance(v, str):
        return STABILITY_STYLE.get(v, v)
    return format_number(v, digits)


#: Left out first when the paper's results do not fit: the equation
#: numbers (also in docs/stability.md), then the deviation (printed vs
#: exact can be read off), then the corrected value.  The result, printed
#: and exact values always stay.
STABILITY_DROP_ORDER = ("equation", "deviation", "corrected")


def _paper_label(quantity: str, units: str) -> tuple[str, str]:
    """A one-line label and the condition it drops: "verdict (w^2 > 0)" ->
    ("verdict", "w^2 > 0"); a frequency carries its unit."""
    label, _, condition = quantity.partition(" (")
    label = label.replace(" frequency", "")
    if units:
        label += f", {units}"
    return label, condition.rstrip(")")


def stability_view(table: Table, setup) -> Group:
    """``deathsphere stability``: the exact block, then the paper's results
    grouped by case (equator, small wheel, near the poles), whether each
    applies here, and the notes.  Labels stay on one line; the conditions
    of the verdicts and the premises' parameters go to lines under it."""
    from deathsphere.physics.stability import SMALL_WHEEL_VALIDITY

    get = table.records()
    head = (f"[italic]stability of a wheel {setup.side}, θ = {format_number(get[0]['theta_deg'])}°, "
            f"α = {format_number(get[0]['alpha_deg'])}° (a = {format_number(setup.a)} m, "
            f"r = {format_number(setup.r)} m, k = {format_number(setup.k)})[/italic]")
    exact_rows = [row for row in get if row["source"] == "exact"]
    exact = FitTable([Column("quantity", "quantity", [escape(r["quantity"]) for r in exact_rows], "left"),
                      Column("value", "value", [_cell(r["exact"], 5) for r in exact_rows]),
                      Column("units", "units", [r["units"] for r in exact_rows], "left")],
                     title="exact: the equations of motion linearised about the orbit")
    cells = {key: [] for key in ("result", "equation", "paper", "corrected", "exact", "deviation")}
    notes, conditions, premises = [], [], []
    group = None
    for row in get:
        if row["source"] == "exact":
            continue
        case = row["source"].removeprefix("paper: ")
        if (case, row["applies"]) != group:
            group = (case, row["applies"])
            where = "[green]applies[/green]" if row["applies"] else "not here"
            for key, column in cells.items():
                column.append(f"[bold]{escape(case)}[/bold]: {where}" if key == "result" else "")
            if row["validity"] is not None:
                symbol, limit = (("a/r'", SMALL_WHEEL_VALIDITY) if case.endswith("small wheel") else ("r'/a", 1))
                premises.append(f"{case} {symbol} = {row['validity']:.3g} (applies up to {limit:g})")
        label, condition = _paper_label(row["quantity"], row["units"])
        if condition:
            conditions.append(f"{case} {condition}")
        verdict = row["quantity"].startswith("verdict")
        dev = row["deviation"]
        cells["result"].append(f"  {escape(label)}")
        cells["equation"].append(escape(row["equation"]))
        cells["paper"].append(_cell(row["paper"]))
        cells["corrected"].append(_cell(row["corrected"]))
        cells["exact"].append(_cell(row["exact"]))
        cells["deviation"].append("—" if dev is None else
                                  (("differs" if dev else "agrees") if verdict else f"{100 * dev:+.1f} %"))
        if row["note"] not in notes:
            notes.append(row["note"])
    headers = {"result": "result", "equation": "eq.", "paper": "printed", "corrected": "corrected",
               "exact": "exact", "deviation": "deviation"}
    columns = [Column(key, headers[key], column, "left" if key in ("result", "equation") else "right")
               for key, column in cells.items()]
    lines = []
    if conditions:
        lines.append("[dim]verdicts: " + "; ".join(escape(c) for c in conditions) + "[/dim]")
    if premises:
        lines.append("[dim]here: " + ", ".join(escape(p) for p in premises) + "[/dim]")
    lines += [f"[dim]{escape(n)}[/dim]" for n in notes]
    lines.append("[dim]errata E1-E9: docs/stability.md, docs/errata.md[/dim]")
    orbit = next((r for r in exact_rows if r["quantity"] == "orbit status"), None)
    if orbit is not None and orbit["exact"] not in ("ok", "slips"):
        # nothing to linearise about: say why instead of an empty table
        why = exact_rows[-1]["note"]
        return Group(head, exact, f"[yellow]{escape(why)}[/yellow]")
    paper = FitTable(columns, STABILITY_DROP_ORDER,
                     title="the paper's results (printed, corrected, exact; deviation = printed vs exact)",
                     notes=lines)
    return Group(head, exact, "", paper)
