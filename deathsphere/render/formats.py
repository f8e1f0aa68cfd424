"""File formats of result tables: CSV, JSON and NDJSON.

Every writer takes an iterable of :class:`~deathsphere.model.Table` chunks so
that sweeps stream with flat memory; the header (CSV) or the opening bracket
(JSON) is written once.  Undefined values (NaN) are empty in CSV and null in
JSON; floats are written in Python's shortest round-trip form.

Nothing here imports rich: a command writing CSV or JSON does not pay for
the terminal views (:mod:`deathsphere.render.orbit_views` and the others).
"""

from __future__ import annotations

import json
import math
from typing import IO, Iterable

import numpy as np

from deathsphere.model import TEXT_COLUMNS, Table

FORMATS = ("table", "csv", "json", "ndjson")


def csv_field(text: str) -> str:
    """A text cell as CSV: quoted (quotes doubled) only when it holds a
    comma, a quote, CR or LF."""
    if any(c in text for c in ',"\n\r'):
        return '"' + text.replace('"', '""') + '"'
    return text


def float_text(x: float) -> str:
    """A float as CSV: repr (the shortest round-trip form); NaN empty."""
    return "" if x != x else repr(x)


def column_strings(name: str, values: np.ndarray) -> list[str]:
    """The CSV text of one column, already quoted.  Values that repeat
    (inputs, statuses, reasons) are formatted once each: a chunk of a grid holds few distinct inputs, and
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
                t = cache[v] = "" if v is None else csv_field(str(v))
            text.append(t)
        return text
    if values.dtype.kind in "iub":
        return list(map(str, values.tolist()))
    values = values.astype(np.float64, copy=False)
    # values compared by their bits: -0.0 == 0.0, yet repr tells them apart
    bits = values.view(np.int64)
    if (bits[0] == bits).all() or np.isnan(values).all():
        return [float_text(float(values[0]))] * n
    if name in REPEATING_COLUMNS:
        unique, inverse = np.unique(bits, return_inverse=True)
        text = list(map(float_text, unique.view(np.float64).tolist()))
        return [text[i] for i in inverse.tolist()]
    text = list(map(repr, values.tolist()))
    for i in np.flatnonzero(np.isnan(values)).tolist():
        text[i] = ""
    return text


#: Input columns: in a grid chunk they take few distinct values.
REPEATING_COLUMNS = frozenset({"theta_deg", "alpha_deg", "a_m", "r_m", "k", "g_m_s2", "mu_available"})


def csv_text(table: Table, header: bool) -> str:
    """One chunk as CSV text (with the header line first if asked)."""
    columns = [column_strings(n, table[n]) for n in table.names]
    lines = [",".join(row) for row in zip(*columns)]
    if header:
        lines.insert(0, ",".join(table.names))
    return "\n".join(lines) + "\n" if lines else ""


#: Which CSV writer formats a chunk: None picks per chunk (below), True
#: the compiled one (:mod:`deathsphere.render.compiled`, the ``fast`` extra)
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
                from deathsphere.render import compiled

                fast = compiled.csv_text if compiled.csv_available() else False
            text = fast or csv_text
        out.write(text(table, header=i == 0))
        rows += len(table)
    return rows


def _json_value(v):
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def json_records(table: Table) -> list[str]:
    """One JSON object per row (NaN and infinities as null)."""
    cols = [(n, table[n].tolist()) for n in table.names]
    return [json.dumps({n: _json_value(v[i]) for n, v in cols}) for i in range(len(table))]


def write_ndjson(chunks: Iterable[Table], out: IO[str]) -> int:
    """Stream tables as NDJSON: one object per line."""
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
