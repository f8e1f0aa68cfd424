"""One value of a table typed by hand (a show's plan): a number, or text
with a unit suffix as on the command line ("16ft", "32km/h"), within the
registry's bounds; refused in one line naming the key as typed."""

from __future__ import annotations

import math

from deathsphere import params, units
from deathsphere.errors import ParameterError
from deathsphere.requests.keys import Keys


def typed_value(keys: Keys, key: str, raw, kind: str, param: str | None = None, lo=None, lo_open=False) -> float:
    """``raw`` as a float in the API's unit of ``kind``; within the bounds of
    the registry's ``param``, or at least (above, ``lo_open``) ``lo``."""
    if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
        keys.fail(key, f"must be a number or text with a unit (got {raw!r})")
    try:
        value = units.parse_value(raw, kind, key) if isinstance(raw, str) else float(raw)
    except ParameterError as exc:
        keys.fail(key, str(exc))
    if param is not None:
        reason = params.problems(param, [value])[0]
        if reason:
            keys.fail(key, reason)
    if not math.isfinite(value) and not (param in ("mu", "max_g") and value == math.inf):
        keys.fail(key, f"must be a finite number (got {raw!r})")
    if lo is not None and (value < lo or (lo_open and value == lo)):
        keys.fail(key, f"must be {'above' if lo_open else 'at least'} {lo:g} (got {raw!r})")
    return value


#: Keys typed in a table that are not the registry's: their kind (no bounds).
ANGLES = {"phase": "angle", "azimuth": "angle"}


def table_reader(keys: Keys):
    """A reader for :mod:`deathsphere.requests.decode`: ``read(key, raw)``,
    one value of the registry's parameter named as the key (``radius`` is
    the registry's ``r``; a phase or an azimuth is any angle)."""
    def read(key: str, raw):
        if key in ANGLES:
            return typed_value(keys, key, raw, ANGLES[key])
        param = "r" if key == "radius" else key
        return typed_value(keys, key, raw, params.PARAMS[param].kind, param)

    return read
