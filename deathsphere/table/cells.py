"""The text of a table's cells: CSV and JSON, one chunk at a time.

The contract's rules for cells live here once (docs/contract.md): floats in
Python's shortest round-trip form (``repr``), undefined values (NaN, and
empty text: :func:`is_undefined_text`) as an empty CSV cell and a null
everywhere else (JSON, Parquet, row dicts, the dataframe exports), text
quoted only when it holds a comma, a quote, CR or LF, and the type each
column has outside numpy (:func:`column_kind`).  Nothing here imports from
the rest of the package, so the :class:`~deathsphere.table.Table` and every
writer can use it.
"""

from __future__ import annotations

import json
import math

import numpy as np


def one_float_text(values: np.ndarray) -> bool:
    """Whether every float of a column writes the same text: the same bits
    (not ==: -0.0 == 0.0, yet repr tells them apart), or all NaN.  A grid's
    chunk holds several such columns (its a, r, k, g, empty limits), which
    the writers build from one value."""
    bits = values.view(np.int64)
    # the first and last values differ in most columns: only the others are compared in full
    return bool((bits[0] == bits[-1] and (bits[0] == bits).all())
                or (values[0] != values[0] and np.isnan(values).all()))


def one_text(values: np.ndarray) -> bool:
    """Whether an object column holds one text (or None) in every row (a
    grid's body and side, blank stability columns), which the writers build
    from one value instead of converting each row's string."""
    first = values[0]
    return (first is None or isinstance(first, str)) and bool(np.all(values == first))


def is_text(values: np.ndarray) -> bool:
    """Whether a column holds text (or None): object, str or bytes arrays.
    An object column of ints (``branch``) counts as text here too: its cells
    are written with ``str`` either way."""
    return values.dtype.kind in "OUS"


def is_undefined_text(v) -> bool:
    """Whether a text cell is undefined: None, or empty text.  Results mark
    text that does not apply (a reason when there is nothing wrong, the
    stability of an orbit not analysed) with "", which CSV cannot tell from
    None anyway; every other output reads both as null through this rule."""
    return v is None or (isinstance(v, str) and v == "")


def cell_value(v):
    """A cell as a plain Python value, undefined as None (NaN, None, "")."""
    if isinstance(v, np.generic):
        v = v.item()
    if isinstance(v, float):
        return None if math.isnan(v) else v
    return None if is_undefined_text(v) else v


def undefined_text_mask(values: np.ndarray) -> np.ndarray:
    """:func:`is_undefined_text` of every cell of a text column, at numpy's speed."""
    if values.dtype.kind in "US":
        return values == values.dtype.type()
    distinct = set(values.tolist()) if values.size else set()
    # a result's text column holds a handful of distinct values: compare
    # row by row only for those present (an object comparison per row is
    # slow, and most columns hold no empty text or no None at all)
    mask = np.zeros(values.shape, dtype=bool)
    if "" in distinct:
        mask |= values == ""
    if None in distinct:
        mask |= np.equal(values, None)
    return mask


def text_cells(values: np.ndarray) -> list:
    """A text column as str or None (undefined text), as the exports hold it;
    a non-str value is written as CSV writes it (``str``)."""
    return [None if is_undefined_text(v) else v if isinstance(v, str) else str(v) for v in values.tolist()]


#: Object columns that hold whole numbers or None (a sphere's ``branch``).
#: Known by name so that a chunk in which every value is None (no row has a
#: branch) keeps the integer type of the others, in a Parquet file's schema
#: as in a concatenation.
INTEGER_OBJECT_COLUMNS = frozenset({"branch"})


def column_kind(name: str, values: np.ndarray) -> str:
    """The type of a column outside numpy: "float", "int", "bool" or "text".

    numpy dtypes say it for every column but object ones, which hold text
    and None, or (``branch``, the stability comparison's columns) numbers,
    flags or None; those are typed by what they hold, None aside: only
    bools "bool", only ints "int", numbers with a float "float", anything
    else (text, a mixture, nothing at all) "text", written as in CSV."""
    kind = values.dtype.kind
    if kind == "f":
        return "float"
    if kind in "iu":
        return "int"
    if kind == "b":
        return "bool"
    if kind in "US":
        return "text"
    if kind != "O":
        raise TypeError(f"column {name!r}: no cell type for {values.dtype}")
    if name in INTEGER_OBJECT_COLUMNS:
        return "int"
    kinds = {type(v) for v in values.tolist() if v is not None}
    if not kinds:
        return "text"
    if kinds <= {bool, np.bool_}:
        return "bool"
    if any(issubclass(k, (bool, np.bool_)) for k in kinds):
        return "text"
    if all(issubclass(k, (int, np.integer)) for k in kinds):
        return "int"
    if all(issubclass(k, (int, float, np.integer, np.floating)) for k in kinds):
        return "float"
    return "text"


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
                t = cache[v] = "" if is_undefined_text(v) else csv_field(str(v))
            text.append(t)
        return text
    if values.dtype.kind in "iub":
        return list(map(str, values.tolist()))
    values = values.astype(np.float64, copy=False)
    if one_float_text(values):
        return [float_text(float(values[0]))] * n
    bits = values.view(np.int64)
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
    columns = [column_strings(n, table.columns[n]) for n in table.names]
    lines = [",".join(row) for row in zip(*columns)]
    if header:
        lines.insert(0, ",".join(table.names))
    return "\n".join(lines) + "\n" if lines else ""


def python_values(values: np.ndarray, finite: bool = False) -> list:
    """A column as plain Python values, undefined as None (:func:`cell_value`
    for every cell; ``finite`` makes infinities None too, for JSON).  Column
    by column, touching only the cells that change: JSON output spends its
    time here."""
    out = values.tolist()
    kind = values.dtype.kind
    if kind == "f":
        blank = ~np.isfinite(values) if finite else np.isnan(values)
    elif kind in "OUS":
        blank = undefined_text_mask(values)
        if kind == "O":
            blank |= np.array([isinstance(v, float) and (v != v or (finite and not math.isfinite(v)))
                               for v in out], dtype=bool) if len(out) else blank
    else:
        return out
    for i in np.flatnonzero(blank).tolist():
        out[i] = None
    return out


def json_records(table) -> list[str]:
    """One JSON object per row (NaN, infinities and empty text as null)."""
    cols = [(n, python_values(table.columns[n], finite=True)) for n in table.names]
    return [json.dumps({n: v[i] for n, v in cols}) for i in range(len(table))]


def decimals(printed: str) -> int:
    """Number of decimals a printed value carries ("0.96" -> 2, "48" -> 0)."""
    return len(printed.split(".")[1]) if "." in printed else 0
