"""The text of a ``reason`` cell (docs/contract.md, "Output columns").

The contract promises that a reason is one line with no comma, so that CSV
output splits with ``awk -F,``.  Two functions keep that promise for every
reason, whoever wrote it:

* :func:`echo` shows a user's text (a cell of an ``--input`` file, a body
  name) inside a reason: as a Python literal (``repr``: quotes, control
  characters and backslashes escaped), cut after :data:`ECHO_CHARS`
  characters, with each comma written ``\\x2c``.  Since ``repr`` already
  writes a backslash as ``\\\\``, ``\\x2c`` in an echo can only stand for a
  comma: the user's text can be recovered exactly (up to the cut).
* :func:`reason_column` is the gate every ``reason`` column passes on its
  way into a :class:`~deathsphere.table.Table`: a comma still left (a text
  from outside the package, such as an integrator's message) becomes ``;``
  and a line break a space.  The package's own reason texts are written
  without commas (a test collects them all), so for them the gate changes
  nothing.

This module imports only numpy: every layer may use it.
"""

from __future__ import annotations

import numpy as np

#: Characters of a user's text shown in a reason before it is cut ("...").
ECHO_CHARS = 40

#: How a comma of a user's text is written inside a reason.
ECHO_COMMA = "\\x2c"

_UNSAFE = (",", "\n", "\r")


def echo(text, limit: int = ECHO_CHARS) -> str:
    """``text`` (a user's input) as it appears inside a reason: a quoted
    Python literal, at most ``limit`` characters of it, commas as ``\\x2c``.

    >>> echo("6,0")
    "'6\\\\x2c0'"
    >>> print(echo("bi,ke"))
    'bi\\x2cke'
    """
    text = str(text)
    shown = repr(text if len(text) <= limit else text[:limit] + "...")
    return shown.replace(",", ECHO_COMMA)


def reason_text(text: str) -> str:
    """One reason as a ``reason`` cell holds it: one line, no comma."""
    if not any(c in text for c in _UNSAFE):
        return text
    return text.replace("\r\n", " ").replace("\r", " ").replace("\n", " ").replace(",", ";")


def reason_column(values):
    """A ``reason`` column with every cell passed through :func:`reason_text`.

    A column holds few distinct texts (the fixed reasons, repeated), so each
    distinct text is looked at once; when none needs a change the column is
    returned as it is (no copy)."""
    values = np.asarray(values)
    if values.size == 0 or values.dtype.kind not in "OU":
        return values
    distinct = set(values.reshape(-1).tolist())
    bad = {t: reason_text(t) for t in distinct if isinstance(t, str) and any(c in t for c in _UNSAFE)}
    if not bad:
        return values
    out = values.astype(object)
    flat = out.reshape(-1)
    flat[:] = [bad.get(t, t) if isinstance(t, str) else t for t in flat.tolist()]
    return out
