"""The text of a table's cells: CSV and JSON, one chunk at a time.

The contract's rules for cells live here once (docs/contract.md): floats in
Python's shortest round-trip form (``repr``), undefined (NaN) as an empty
CSV cell and a JSON null, text quoted only when it holds a comma, a quote,
CR or LF.  Nothing here imports from the rest of the package, so the
:class:`~deathsphere.table.Table` and every writer can use it.
"""

from __future__ import annotations

import json
import math

import numpy as np


def is_text(values: np.ndarray) -> bool:
    """Whether a column holds text (or None): object, str or bytes arrays.
    An object column of ints (``branch``) counts as text here too: its cells
    are written with ``str`` either way."""
    return values.dtype.kind in "OUS"


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
    if is_text(values):
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


def csv_text(table, header: bool) -> str:
    """One chunk as CSV text (with the header line first if asked)."""
    columns = [column_strings(n, table[n]) for n in table.names]
    lines = [",".join(row) for row in zip(*columns)]
    if header:
        lines.insert(0, ",".join(table.names))
    return "\n".join(lines) + "\n" if lines else ""


def _json_value(v):
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def json_records(table) -> list[str]:
    """One JSON object per row (NaN and infinities as null)."""
    cols = [(n, table[n].tolist()) for n in table.names]
    return [json.dumps({n: _json_value(v[i]) for n, v in cols}) for i in range(len(table))]


def decimals(printed: str) -> int:
    """Number of decimals a printed value carries ("0.96" -> 2, "48" -> 0)."""
    return len(printed.split(".")[1]) if "." in printed else 0
