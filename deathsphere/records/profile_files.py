"""Profile files (``--profile FILE``): the meridian of a surface of
revolution as CSV samples, one point a row from the lowest upwards, under
a header naming the two columns with their unit, ``rho_m,z_m`` (or
``rho_ft,z_ft``, ``rho_cm,z_cm`` ...: any length unit of docs/units.md).
Read into a :class:`~deathsphere.physics.ground.Profile` in metres
(docs/surfaces.md, "Profiles")."""

from __future__ import annotations

import csv

import numpy as np

from deathsphere.errors import ParameterError
from deathsphere.physics.ground.profile import Profile, ProfileError

__all__ = ["profile_file"]


def _refuse(name: str, message: str):
    raise ParameterError(f"profile file {name}: {message}", "profile")


def _column_unit(name: str, header: str, quantity: str) -> str:
    key = header.strip()
    if not key.lower().startswith(quantity + "_") or len(key) == len(quantity) + 1:
        _refuse(name, f"the header must name the columns rho_UNIT,z_UNIT (e.g. rho_m,z_m; got {key!r})")
    return key[len(quantity) + 1:]


def profile_file(path) -> Profile:
    """The Profile in a CSV file; refuses in one line naming the file and,
    where it is one row's fault, the row (1 = the first row after the
    header): a file that cannot be read, is empty, not text, has another
    header, a row that is not two numbers, and every profile
    :class:`~deathsphere.physics.ground.Profile` refuses."""
    import pathlib

    from deathsphere import units

    p = pathlib.Path(path)
    try:
        raw = p.read_bytes()
    except OSError as exc:
        raise ParameterError(f"cannot read the profile file {str(path)!r}: {exc.strerror}", "profile") from None
    if b"\0" in raw:
        _refuse(p.name, "not a text file (it holds NUL bytes); a profile is CSV text: rho_m,z_m then a row per point")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        _refuse(p.name, f"not UTF-8 text (byte {exc.start}); save it as UTF-8 CSV")
    rows = [(i, r) for i, r in enumerate(csv.reader(text.splitlines())) if any(c.strip() for c in r)]
    if not rows:
        _refuse(p.name, "empty; a profile is a header rho_m,z_m and a row per point of the meridian")
    _, header = rows[0]
    if len(header) != 2:
        _refuse(p.name, f"the header must name two columns, rho_UNIT,z_UNIT (got {len(header)})")
    scales = []
    for column, quantity in zip(header, ("rho", "z")):
        unit = _column_unit(p.name, column, quantity)
        try:
            scales.append(units.factor(unit, "length", "profile"))
        except ParameterError as exc:
            _refuse(p.name, f"column {column.strip()!r}: {exc}")
    values = np.empty((len(rows) - 1, 2))
    for j, (_, row) in enumerate(rows[1:]):
        if len(row) != 2:
            _refuse(p.name, f"row {j + 1}: two values expected (rho, z), got {len(row)}")
        try:
            values[j] = [float(cell) for cell in row]
        except ValueError:
            _refuse(p.name, f"row {j + 1}: not two numbers ({','.join(c.strip() for c in row)!r})")
    try:
        return Profile(values[:, 0] * scales[0], values[:, 1] * scales[1])
    except ProfileError as exc:
        _refuse(p.name, str(exc).removeprefix("profile: "))
