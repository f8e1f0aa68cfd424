"""Reading orbit requests from a CSV whose header names the options.

Header names are the request fields (``theta, alpha, a, r, k, g, mu, body,
side``) or the output column names that carry them (``theta_deg, a_m,
g_m_s2, mu_available`` ...), so a result CSV's input columns can be fed back.
An unknown column is an error (exit 2): silently ignoring it would hide a typo
such as ``thetta``.  A bad *value* only spoils its own row, which comes out
with status ``invalid`` and the reason.
"""

from __future__ import annotations

import csv
import math
from typing import IO

import numpy as np

from deathsphere.model import REQUEST_FIELDS, make_requests

ALIASES = {
    "theta_deg": "theta", "alpha_deg": "alpha", "a_m": "a", "r_m": "r", "g_m_s2": "g",
    "mu_available": "mu",
}
TEXT_FIELDS = ("body", "side")


class InputError(ValueError):
    """The input as a whole cannot be read (empty, unknown column, ...)."""


def allowed_columns(fields=REQUEST_FIELDS) -> str:
    return ", ".join(list(fields) + [a for a, f in ALIASES.items() if f in fields])


def read_requests(stream: IO[str], defaults: dict, source: str = "input") -> dict:
    """Parse a request CSV into an orbit request batch (see :func:`make_requests`)."""
    n, values, invalid = read_table(stream, defaults, source)
    return make_requests(n, invalid=invalid, **values)


def read_table(stream: IO[str], defaults: dict, source: str = "input", fields=REQUEST_FIELDS):
    """Parse a CSV whose header names some of ``fields`` (name -> (default,
    unit, words)).  Returns ``(n, values, invalid)``: the number of records,
    one array per field (columns, else ``defaults``), and the reason each
    record is unreadable ('' if it is fine).

    ``defaults`` fill fields that have no column or an empty cell.  Blank
    lines are skipped; every other record is one request, numbered from 1.
    """
    reader = csv.reader(stream)
    header = None
    for header in reader:
        if any(cell.strip() for cell in header):
            break
    else:
        header = None
    if not header:
        raise InputError(f"{source} is empty: expected a header line naming the columns "
                         f"({allowed_columns(fields)})")
    names = [ALIASES.get(h.strip().lower(), h.strip().lower()) for h in header]
    unknown = [h for h, n in zip(header, names) if n not in fields]
    if unknown:
        raise InputError(f"{source}: unknown column {unknown[0]!r}; allowed: {allowed_columns(fields)}")
    dupes = sorted({n for n in names if names.count(n) > 1})
    if dupes:
        raise InputError(f"{source}: column {dupes[0]!r} appears more than once")

    rows = [row for row in reader if any(cell.strip() for cell in row)]
    n = len(rows)
    values = {name: [] for name in names}
    invalid = np.full(n, "", dtype=object)
    for i, row in enumerate(rows):
        if len(row) != len(names):
            invalid[i] = f"row has {len(row)} fields but the header has {len(names)}"
            row = (row + [""] * len(names))[: len(names)]
        for name, cell in zip(names, row):
            cell = cell.strip()
            if name in TEXT_FIELDS:
                values[name].append(cell.lower() if cell else defaults.get(name, fields[name][0]))
                continue
            if not cell:
                default = defaults.get(name, fields[name][0])
                values[name].append(math.nan if default is None else default)
                continue
            try:
                number = float(cell)
            except ValueError:
                number = math.nan
            if math.isnan(number) or (math.isinf(number) and name != "mu"):
                if not invalid[i]:
                    invalid[i] = f"{name}: {cell!r} is not a finite number"
                number = math.nan
            values[name].append(number)
    out = {k: v for k, v in defaults.items() if v is not None}
    out.update({name: np.array(v, dtype=object if name in TEXT_FIELDS else float)
                for name, v in values.items()})
    return n, out, invalid
