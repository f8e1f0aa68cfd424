"""A two-wheeler from a file, and its text (beyond the paper;
docs/two-wheeler.md sec. 1.4): the BicycleParameters library's benchmark
format (``<Name>Benchmark.txt``: ``name = value`` or ``name =
value+/-uncertainty`` lines, the benchmark's 26 names) and the project's
machine file (TOML ``key = value`` lines or a CSV header and row, read as
:func:`~deathsphere.requests.decode.decode_machine_file` reads them) whose keys are
the benchmark's names.  A bad file is refused in one line.

Gravity is the run's, not the two-wheeler's: a BicycleParameters file's
``g`` (the format has one) is read and left out of the record, and the
project's file has no ``g`` key.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

from deathsphere.records.machine import UNECHOABLE
from deathsphere.records.machine_files import machine_file_data, machine_file_text
from deathsphere.records.two_wheeler import DEFAULT_HEAD, TwoWheeler
from deathsphere.records.two_wheeler_presets import TWO_WHEELERS, as_two_wheeler
from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.params import PARAMS, ParameterError
from deathsphere.physics.two_wheeler.parameters import FIELD_NAMES, PARAMETER_NAMES

__all__ = ["two_wheeler_file", "is_two_wheeler_file", "two_wheeler_text", "FILE_STYLES"]

#: The texts :func:`two_wheeler_text` writes.
FILE_STYLES = ("toml", "bicycleparameters")
#: The project's keys beside the benchmark's 25 (Table 1's but g; the head point in m, z down).
OWN_KEYS = ("name", "source", "base", "head_x", "head_z")
#: What a value given as text with a unit is (docs/units.md; the registry's
#: kind); the rest are plain numbers in SI (moments of inertia in kg m^2).
_KINDS = {**{k: PARAMS[k].kind for k in FIELD_NAMES if PARAMS[k].kind != "none"},
          **dict.fromkeys(("head_x", "head_z"), "length")}
#: Keys some BicycleParameters files add that restate the Whipple model's
#: symmetry: read when they agree with it, refused when they do not.
_RESTATED = {"yB": "0", "yH": "0", "IRzz": "IRxx", "IFzz": "IFxx"}
#: A value as the uncertainties package writes it: 1.02, 1.02+/-0.01, (1.00+/-0.01)e-05.
_DIGITS = r"[+-]?(?:\d+\.?\d*|\.\d+)"
_NUMBER = rf"{_DIGITS}(?:[eE][+-]?\d+)?"
_UFLOAT = re.compile(rf"(?P<plain>{_NUMBER})(?:\s*(?:\+/-|±)\s*{_NUMBER})?"
                     rf"|\(\s*(?P<scaled>{_DIGITS})\s*(?:\+/-|±)\s*{_DIGITS}\s*\)[eE](?P<exponent>[+-]?\d+)")


def _refuse(name: str, what: str):
    raise ParameterError(f"machine file {name}: {what}", "machine_file")


def _nominal(text: str, where: str, file: str) -> float:
    """The nominal value of ``value`` or ``value+/-uncertainty``; several,
    comma-separated, are averaged (as BicycleParameters' reader does)."""
    values = []
    for part in text.split(","):
        match = _UFLOAT.fullmatch(part.strip())
        if match is None:
            _refuse(file, f"{where}: {part.strip()!r} is not a number or number+/-uncertainty")
        plain = match.group("plain")
        values.append(float(plain if plain is not None else f"{match.group('scaled')}e{match.group('exponent')}"))
    return sum(values) / len(values)


def _bicycle_parameters_values(text: str, file: str) -> dict:
    """The 26 numbers of a BicycleParameters benchmark file: ``#`` starts a
    comment, blank lines are skipped, every other line is ``name = value``."""
    values = {}
    for number, line in enumerate(text.splitlines(), 1):
        content = line.split("#", 1)[0]
        if not content.strip():
            continue
        key, equals, value = content.partition("=")
        key = key.strip()
        if not equals or "=" in value or not key:
            _refuse(file, f"line {number} is not 'name = value' (got {line.strip()!r})")
        if key in values:
            _refuse(file, f"{key} is given twice (line {number}): which one is meant?")
        values[key] = _nominal(value, f"line {number} ({key})", file)
    for key, same in _RESTATED.items():
        if key in values:
            expected = 0.0 if same == "0" else values.get(same, values[key])
            if not math.isclose(values.pop(key), expected, rel_tol=1e-9, abs_tol=1e-12):
                _refuse(file, f"{key} must be {same} in the Whipple model (a plane of symmetry and axisymmetric "
                              "wheels)")
    unknown = sorted(set(values) - set(PARAMETER_NAMES))
    if unknown:
        _refuse(file, f"{unknown[0]!r} is not one of the benchmark's 26 parameters (a BicycleParameters file of "
                      "another model?); known: " + ", ".join(PARAMETER_NAMES))
    return values


def _value(key: str, value, file: str) -> float:
    """One value of the project's file: a number in SI (``lam`` in rad), or
    text: a number in SI or one with a unit (``"27deg"``, ``"1.25m"``)."""
    from deathsphere import units

    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        _refuse(file, f"{key} must be a number (got {value!r})")
    if not isinstance(value, str):
        return float(value)
    try:
        number, unit = units.split_unit(value)
        if unit is None:
            return float(number)
    except ValueError as exc:
        _refuse(file, f"{key}: {exc}")
    kind = _KINDS.get(key)
    if kind is None:
        _refuse(file, f"{key} is a plain number in SI (kg m^2): no unit (got {value!r})")
    try:
        si = units.to_api_unit(float(number), unit, kind, key)
    except ValueError as exc:
        _refuse(file, f"{key}: {exc}")
    return math.radians(si) if kind == "angle" else si


def _name(data: dict, stem: str, file: str) -> str:
    if "name" not in data and any(c in stem for c in UNECHOABLE):
        _refuse(file, f"its name (the file's name: {stem!r}) holds a comma or a line break, which the CSV output "
                      "cannot echo; give a name key")
    return str(data.get("name", stem))


def _built(values: dict, head, name: str, source: str, file: str) -> TwoWheeler:
    try:
        return TwoWheeler(**values, head=head, name=name, source=source)
    except ParameterError as exc:
        _refuse(file, str(exc))


def is_two_wheeler_file(path) -> bool:
    """True for a BicycleParameters benchmark file (``.txt``) or a machine
    file whose keys include one of the benchmark's names."""
    if Path(path).suffix.lower() == ".txt":
        return True
    data, _ = machine_file_data(path)
    return any(k in PARAMETER_NAMES for k in data)


def two_wheeler_file(path, base=None) -> TwoWheeler:
    """A :class:`TwoWheeler` from a file (docs/two-wheeler.md sec. 1.4):
    a BicycleParameters benchmark file (``.txt``; the nominal values, the
    uncertainties dropped; its name from the file's, ``<Name>Benchmark.txt``)
    or a TOML or CSV machine file with the benchmark's names as keys (SI,
    ``lam`` in rad, or text with a unit), and ``name``, ``source``,
    ``head_x``, ``head_z`` (the head point, m, z down) and ``base``: a
    two-wheeler preset whose values the keys not given keep (``base`` the
    argument when the file has none; without either every one of the 25 is
    needed)."""
    from deathsphere.table.reasons import reason_text

    if Path(path).suffix.lower() == ".txt":
        text, p = machine_file_text(path)
        values = _bicycle_parameters_values(text, p.name)
        missing = [k for k in PARAMETER_NAMES if k not in values]
        if missing:
            _refuse(p.name, f"{', '.join(missing[:5])}{' ...' if len(missing) > 5 else ''} missing: a "
                            "BicycleParameters benchmark file gives all 26 of the benchmark's parameters")
        stem = p.stem[: -len("Benchmark")] if p.stem.endswith("Benchmark") and p.stem != "Benchmark" else p.stem
        del values["g"]                                 # the run's, not the two-wheeler's
        return _built(values, DEFAULT_HEAD, _name({}, stem, p.name),
                      reason_text(f"BicycleParameters file {p.name}; head point assumed"), p.name)
    data, p = machine_file_data(path)
    if "g" in data:
        _refuse(p.name, "g is the run's gravity, not the two-wheeler's: give it to the run (-g/--gravity, g=) "
                        "instead of the file")
    unknown = sorted(set(data) - set(FIELD_NAMES) - set(OWN_KEYS))
    if unknown:
        _refuse(p.name, f"unknown key {unknown[0]!r} (known: {', '.join(OWN_KEYS)} and the benchmark's "
                        f"{', '.join(FIELD_NAMES)})")
    base = data.get("base", base if isinstance(base, str) and base.strip().lower() in TWO_WHEELERS else None)
    if base is not None and (not isinstance(base, str) or base.strip().lower() not in TWO_WHEELERS):
        _refuse(p.name, f"base must be a two-wheeler preset ({' | '.join(TWO_WHEELERS)}; got {base!r})")
    start = TWO_WHEELERS[base.strip().lower()] if base is not None else None
    missing = [k for k in FIELD_NAMES if k not in data]
    if missing and start is None:
        _refuse(p.name, f"{', '.join(missing[:5])}{' ...' if len(missing) > 5 else ''} missing: give all 25 of the "
                        "benchmark's parameters but g, or base = a two-wheeler preset whose values the others keep")
    values = {k: _value(k, data[k], p.name) if k in data else getattr(start, k) for k in FIELD_NAMES}
    head = start.head if start is not None else DEFAULT_HEAD
    head = tuple(_value(k, data[k], p.name) if k in data else h for k, h in zip(("head_x", "head_z"), head))
    return _built(values, head, _name(data, p.stem, p.name), str(data.get("source", reason_text(f"file {p.name}"))),
                  p.name)


def two_wheeler_text(machine, style: str = "toml") -> str:
    """A two-wheeler (a :class:`TwoWheeler` or a preset's name) as the text
    of a file that :func:`two_wheeler_file` reads back exactly: ``toml``,
    the project's (name, source, head, then the 25 in Table 1's order, no g), or
    ``bicycleparameters``, the library's benchmark format (the 26 sorted by
    name, as its writer sorts them; no uncertainties, no head; its ``g``,
    which the format needs, standard gravity, the run's by default)."""
    t = as_two_wheeler(machine)
    if style not in FILE_STYLES:
        raise ParameterError(f"style must be one of {' | '.join(FILE_STYLES)} (got {style!r})", "style")
    values = t.benchmark_values()
    if style == "bicycleparameters":
        values = values | {"g": STANDARD_GRAVITY}
        return "".join(f"{k} = {values[k]!r}\n" for k in sorted(values))
    head = {"head_x": t.head[0], "head_z": t.head[1]}
    return (f"name = {json.dumps(t.name, ensure_ascii=False)}\nsource = {json.dumps(t.source, ensure_ascii=False)}\n"
            + "".join(f"{k} = {v!r}\n" for k, v in (head | values).items()))
