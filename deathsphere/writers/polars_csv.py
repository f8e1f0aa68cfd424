"""The CSV writer compiled in polars (the optional ``fast`` extra:
``pip install 'deathsphere[fast]'``).

The CSV they write is byte for byte the pure-Python writer's
(:func:`deathsphere.table.cells.csv_text`); only the speed differs.  How that
is kept exact:

* **Floats.**  polars writes the shortest digit string that round-trips,
  as Python's ``repr`` does, and in the same form (``60.0``,
  ``1.5e+20``, ``1e+16``, ``123456789012345.0``, ``-0.0``, ``5e-324``) for
  every value except those in 1e-10 <= |x| < 1e-4, where it writes
  ``1e-9`` and ``0.000025`` for repr's ``1e-09`` and ``2.5e-05``.  Those
  values (rare in results) are formatted by ``repr`` itself and spliced in.
  Because a future polars could format differently, :func:`csv_available`
  first checks polars against ``repr`` on :data:`PROBES` (every form and
  boundary) and declines if any differs; the writer then falls back to
  the pure-Python one.
* **NaN** becomes null, written as an empty cell.
* **Text** is quoted here with the contract's rule (only a cell holding a
  comma, quote, CR or LF; quotes doubled), and polars is told never to
  quote, so its own quoting rules (it quotes an empty string) never apply.
* **The header** is the column names joined by commas, as in the
  pure-Python writer.

Nothing here is imported until a compiled writer is asked for: polars and
pyarrow take a noticeable time to import.
"""

from __future__ import annotations

import importlib.util
import math
import os
import re
import threading

import numpy as np

from deathsphere.table.cells import column_strings, float_text, one_float_text, one_text

#: polars writes |x| in this range differently from repr (exponent
#: 'e-9' for 'e-09'; positional below 1e-4 where repr switches to an exponent).
_REPR_LOW, _REPR_HIGH = 1e-10, 1e-4

#: Values whose polars text must equal repr, checked once before polars is
#: trusted: each form repr uses and each of its boundaries, both signs.
PROBES = (
    0.0, -0.0, 1.0, 60.0, 0.1, 0.3, 2.3026338854496538, 1.0 / 3.0, 100.0, 0.0001, 0.00012345678901234567,
    0.00030000000000000003, 123456789012345.0, 999999999999999.9, 1e15, 1234567890123456.0,
    9999999999999998.0, 1e16, 1.2345678901234568e+16, 1.5e20, 1e21, 1e22, 1e100, 1.7976931348623157e308,
    1e-10 * 0.999, 9.999e-11, 1e-11, 1.5e-100, 5e-324, 2.2250738585072014e-308, 2.225073858507201e-308,
    math.pi * 1e5, 4.35, 0.5, 2.5, 1e23, 9007199254740993.0, 12345.678,
)


def _module(name: str) -> bool:
    return importlib.util.find_spec(name) is not None


_csv_ok: bool | None = None
#: The check runs once even when a warm-up thread and the writer ask at once.
_csv_lock = threading.Lock()


def csv_available() -> bool:
    """polars is installed and formats floats as repr does (checked once)."""
    global _csv_ok
    with _csv_lock:
        if _csv_ok is None:
            _csv_ok = _module("polars") and _polars_matches_repr()
        return _csv_ok


def _polars_matches_repr() -> bool:
    import polars as pl

    probes = [s * x for x in PROBES for s in (1.0, -1.0)]
    probes = [x for x in probes if not (_REPR_LOW <= abs(x) < _REPR_HIGH)]
    try:
        text = pl.DataFrame({"x": probes}).write_csv(include_header=False, quote_style="never")
    except Exception:  # an incompatible polars: the pure-Python writer is always right
        return False
    return text.split("\n")[:-1] == [repr(x) for x in probes]


def _needs_quote(text: str) -> bool:
    return "," in text or '"' in text or "\r" in text or "\n" in text


def _quote(pl, s, distinct):
    """The contract's CSV quoting on a polars String series (nulls stay null).
    ``distinct`` are its values: a result's text columns hold a handful of
    statuses and reasons, so the rule is decided on those, not per row."""
    bad = [x for x in distinct if isinstance(x, str) and _needs_quote(x)]
    if not bad:
        return s
    return s.replace({x: '"' + x.replace('"', '""') + '"' for x in bad})


def _repeated(pl, name: str, text, n: int):
    """A String series of ``n`` times ``text`` (None: null), built in polars
    from one value (``pl.repeat`` costs 10x as much)."""
    return pl.Series(name, [text], dtype=pl.String).new_from_index(0, n)


def _series(pl, name: str, values: np.ndarray):
    """One column as a polars series that writes the pure-Python writer's text."""
    kind = values.dtype.kind
    if kind == "f":
        values = values.astype(np.float64, copy=False)
        if len(values) > 1 and one_float_text(values):
            return _repeated(pl, name, float_text(float(values[0])) or None, len(values))
        s = pl.Series(name, values, nan_to_null=True)
        size = np.abs(values)
        odd = np.flatnonzero((size >= _REPR_LOW) & (size < _REPR_HIGH))
        if len(odd):
            s = s.cast(pl.String).scatter(odd, [repr(x) for x in values[odd].tolist()])
        return s
    if kind in "iu":
        return pl.Series(name, values)
    if kind == "O" and len(values) and one_text(values):
        return _quote(pl, _repeated(pl, name, values[0], len(values)), (values[0],))
    if kind == "O" or kind in "US":
        items = values.tolist()
        try:
            s = pl.Series(name, items, strict=True)
        except Exception:
            s = None
        if s is not None and s.dtype in (pl.String, pl.Null):  # Null: every cell None, written empty
            return _quote(pl, s, set(items))
        if s is not None and s.dtype == pl.Int64:
            return s
    # anything else (bools, mixed objects): the pure-Python text, already quoted
    return pl.Series(name, column_strings(name, values), dtype=pl.String)


def polars_csv_text(table, header: bool, sink=None) -> str:
    """One chunk as CSV text, equal to :func:`deathsphere.table.cells.csv_text`.
    Given ``sink``, a binary file, the text is written there as UTF-8 and
    '' returned: a chunk's text never exists as a Python string (polars
    would build it as bytes, decode it, and the text file encode it back:
    three copies of ~5 MB per chunk of 16,384 rows)."""
    import polars as pl

    names = table.names
    head = ",".join(names) + "\n" if header and names else ""
    if sink is not None:
        sink.write(head.encode())
        head = ""
    if len(table) == 0:
        return head
    frame = pl.DataFrame([_series(pl, n, table.columns[n]) for n in names])
    options = dict(include_header=False, quote_style="never", null_value="", line_terminator="\n")
    if sink is None:
        return head + frame.write_csv(**options)
    try:
        frame.write_csv(sink, **options)
    except OSError as exc:
        # polars names the OS's error only in words ("Broken pipe (os error
        # 32)"); the command line tells a reader gone (EPIPE) by its errno
        code = re.search(r"os error (\d+)", str(exc)) if exc.errno is None else None
        if code is None:
            raise
        raise OSError(int(code.group(1)), os.strerror(int(code.group(1)))) from None
    return ""
