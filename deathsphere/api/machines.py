"""The machine of ``deathsphere ride``: :class:`Machine` (a motorcycle and
rider as one single-contact gyrostat, docs/machine.md), its presets and
machine files.

A machine is validated once, at construction: a bad one raises
:class:`~deathsphere.ParameterError` with one line before any work.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from deathsphere import params
from deathsphere.constants import TABLE1_WHEEL_RADIUS
from deathsphere.params import ParameterError

#: Machine field -> registry parameter (its unit, bounds and option name).
FIELD_PARAMS = {"mass": "mass", "h": "com_height", "a": "a", "t": "tyre_radius", "spin_inertia": "spin_inertia",
                "head": "head_height", "width": "width"}
INERTIA_PARAMS = ("roll_inertia", "pitch_inertia", "yaw_inertia")
#: Relative slack of the rigid-body inequalities (round-off of published numbers).
INERTIA_RTOL = 1e-9


def _number(field: str, value) -> float:
    if isinstance(value, str):
        from deathsphere.api.arguments import number_from_text

        value = number_from_text(FIELD_PARAMS.get(field, field), value)
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ParameterError(f"machine {field} must be a number (got {value!r})", FIELD_PARAMS.get(field, field))
    return float(value)


#: Characters an echoed text may not hold: the CSV output promises that
#: ``awk -F,`` splits every row (docs/contract.md, "Output columns").
UNECHOABLE = (",", "\n", "\r")


def echoable_text(what: str, value) -> str:
    """``value`` if it is text that can be echoed in every output row (no
    comma, no line break); else ParameterError naming the character."""
    if not isinstance(value, str):
        raise ParameterError(f"{what} must be text (got {value!r})", "machine")
    bad = next((c for c in UNECHOABLE if c in value), None)
    if bad is not None:
        shown = "a comma" if bad == "," else "a line break"
        raise ParameterError(f"{what} {value!r} holds {shown}: every output row echoes it and CSV rows must split "
                             "at each comma (write ';' or a space instead)", "machine")
    return value


@dataclass(frozen=True, kw_only=True)
class Machine:
    """A machine: a rigid frame (motorcycle and rider, wheels locked) with
    axisymmetric wheels spinning about one axle direction, rolling without
    slipping at one contact point (docs/machine.md).

    mass [kg]; h [m] height of the centre of mass above the contact along
    the up-axis (upright on flat ground); a [m] wheel radius to the tyre's
    crown; t [m] the crown's radius (0: knife edge); inertia [kg m^2]
    (I_roll, I_pitch, I_yaw), principal moments of the whole machine with its
    wheels locked about its centre of mass; spin_inertia [kg m^2] the sum of
    the wheels' polar moments; head [m] the top of the rider's head above
    the contact along the up-axis (default h); width [m] handlebar or the
    rider's shoulders, whichever is wider: the diameter of the rider's
    envelope in a show (None: not known; a show refuses it); name and
    source describe it.

    >>> Machine(mass=0, h=0.8, a=0.3, inertia=(1, 1, 1), spin_inertia=0.5)
    Traceback (most recent call last):
    ...
    deathsphere.ParameterError: mass (machine mass) must be 1e-09..1e+09 kg (got 0)
    """

    mass: float
    h: float
    a: float
    t: float = 0.0
    inertia: tuple[float, float, float] = (0.0, 0.0, 0.0)
    spin_inertia: float = 0.0
    head: float | None = None
    width: float | None = None
    name: str = "custom"
    source: str = ""

    def __post_init__(self):
        set_ = object.__setattr__
        for field in ("name", "source"):
            set_(self, field, echoable_text(f"machine {field}", getattr(self, field)))
        for field, pname in FIELD_PARAMS.items():
            value = getattr(self, field)
            if field == "head" and value is None:
                value = self.h
            if field == "width" and value is None:
                continue
            value = _number(field, value)
            reason = params.problems(pname, [value])[0]
            if reason:
                raise ParameterError(reason, pname)
            set_(self, field, value)
        inertia = self.inertia
        if isinstance(inertia, (str, bytes)) or np.ndim(inertia) != 1 or len(inertia) != 3:
            raise ParameterError(f"machine inertia must be three numbers (I_roll, I_pitch, I_yaw) (got {inertia!r})",
                                 "roll_inertia")
        values = []
        for pname, value in zip(INERTIA_PARAMS, inertia):
            value = _number(pname, value)
            reason = params.problems(pname, [value])[0]
            if reason:
                raise ParameterError(reason, pname)
            values.append(value)
        set_(self, "inertia", tuple(values))
        if not self.t < self.a:
            raise ParameterError(f"tyre_radius t ({self.t:g} m) must be less than the wheel radius a ({self.a:g} m)",
                                 "tyre_radius")
        if not self.head >= self.h:
            raise ParameterError(f"head_height ({self.head:g} m) must be at least the centre-of-mass height h "
                                 f"({self.h:g} m)", "head_height")
        total = sum(values)
        for pname, value in zip(INERTIA_PARAMS, values):
            if value > total - value + INERTIA_RTOL * total:
                raise ParameterError(
                    f"{pname} ({value:g} kg m^2) exceeds the sum of the other two moments ({total - value:g}): no "
                    "rigid body has these principal moments (triangle inequality)", pname)
        if self.spin_inertia > values[1] * (1 + INERTIA_RTOL):
            raise ParameterError(
                f"spin_inertia ({self.spin_inertia:g} kg m^2) exceeds the pitch inertia ({values[1]:g}) of the whole "
                "machine, which contains the wheels' polar moments", "spin_inertia")

    @property
    def roll_inertia(self) -> float:
        return self.inertia[0]

    @property
    def pitch_inertia(self) -> float:
        return self.inertia[1]

    @property
    def yaw_inertia(self) -> float:
        return self.inertia[2]

    def with_overrides(self, **values) -> Machine:
        """A copy with some parameters replaced, by their registry names
        (``mass``, ``com_height``, ``a``, ``tyre_radius``, ``roll_inertia``,
        ... ``head_height``); None leaves a value as it is."""
        given = {k: v for k, v in values.items() if v is not None}
        if not given:
            return self
        by_param = {v: k for k, v in FIELD_PARAMS.items()}
        changes, inertia = {}, list(self.inertia)
        for key, value in given.items():
            if key in by_param:
                changes[by_param[key]] = value
            elif key in INERTIA_PARAMS:
                inertia[INERTIA_PARAMS.index(key)] = value
            else:
                raise ParameterError(f"unknown machine parameter {key!r}", key)
        return replace(self, **changes, inertia=tuple(inertia), name=f"{self.name} (modified)")

    def row(self) -> dict:
        """The machine as a row of ``deathsphere machines``."""
        return {"name": self.name, "mass_kg": self.mass, "com_height_m": self.h, "wheel_radius_m": self.a,
                "tyre_radius_m": self.t, "roll_inertia_kg_m2": self.inertia[0],
                "pitch_inertia_kg_m2": self.inertia[1], "yaw_inertia_kg_m2": self.inertia[2],
                "spin_inertia_kg_m2": self.spin_inertia, "head_height_m": self.head, "source": self.source,
                "width_m": math.nan if self.width is None else self.width}


def paper_wheel(a: float = TABLE1_WHEEL_RADIUS, k: float = 0.5, mass: float = 1.0) -> Machine:
    """McDonald's wheel as a machine: h = a, t = 0, inertia (k, 2k, k) m a^2,
    spin inertia 2 k m a^2, the head at the hub (docs/machine.md sec. 4)."""
    i = k * mass * a * a
    return Machine(mass=mass, h=a, a=a, t=0.0, inertia=(i, 2 * i, i), spin_inertia=2 * i, head=a, width=0.0,
                   name="paper-wheel", source="McDonald (1993) Table 1: a = 0.3 m k = 1/2 (mass 1 kg: any mass gives "
                   "the same orbits); width 0: the paper's thin wheel")


#: Meijaard, Papadopoulos, Ruina and Schwab (2007), Proc. R. Soc. A 463,
#: 1955-1982, Table 1 (the benchmark bicycle with rider).  Axes: x forward,
#: z down, origin at the rear contact; (mass kg, x m, z m, Ixx, Iyy, Izz, Ixz
#: kg m^2).  Wheels: Izz = Ixx.
BENCHMARK_BODIES = {
    "rear wheel R": (2.0, 0.0, -0.3, 0.0603, 0.12, 0.0603, 0.0),
    "rear frame and rider B": (85.0, 0.3, -0.9, 9.2, 11.0, 2.8, 2.4),
    "front fork and handlebar H": (4.0, 0.9, -0.7, 0.05892, 0.06, 0.00708, -0.00756),
    "front wheel F": (3.0, 1.02, -0.35, 0.1405, 0.28, 0.1405, 0.0),
}
#: The benchmark's wheel radii rR, rF [m] and polar moments IRyy, IFyy [kg m^2].
BENCHMARK_WHEELS = ((0.3, 0.12), (0.35, 0.28))
#: Estimate (not in the benchmark): top of a seated adult rider's head [m].
BENCHMARK_HEAD_ESTIMATE = 1.75
#: Estimate (not in the benchmark): a city bicycle's handlebar, wider than
#: an adult's shoulders (about 0.45 m) [m].
BENCHMARK_WIDTH_ESTIMATE = 0.60


def benchmark_totals():
    """Total mass [kg], centre of mass (x, height) [m] and the inertia
    (Ixx, Iyy, Izz, Ixz) [kg m^2] about it of the benchmark bicycle with
    rider, wheels locked (parallel-axis theorem over the four bodies)."""
    rows = np.array(list(BENCHMARK_BODIES.values()))
    m, x, z = rows[:, 0], rows[:, 1], rows[:, 2]
    mt = m.sum()
    xt, zt = (m * x).sum() / mt, (m * z).sum() / mt
    dx, dz = x - xt, z - zt
    ixx = (rows[:, 3] + m * dz * dz).sum()
    iyy = (rows[:, 4] + m * (dx * dx + dz * dz)).sum()
    izz = (rows[:, 5] + m * dx * dx).sum()
    ixz = (rows[:, 6] - m * dx * dz).sum()
    return float(mt), float(xt), float(-zt), (float(ixx), float(iyy), float(izz), float(ixz))


def benchmark_bicycle() -> Machine:
    """The benchmark bicycle with rider as one contact (docs/machine.md sec. 7):
    mass and centre of mass from its Table 1; the locked inertia's diagonal
    in its axes (its product Ixz neglected); one wheel of the mean radius
    a = (rR + rF)/2 with the spin inertia J = a (IRyy/rR + IFyy/rF), which
    keeps the wheels' spin angular momentum at a given speed exact."""
    mt, _, h, (ixx, iyy, izz, _) = benchmark_totals()
    (r_r, i_r), (r_f, i_f) = BENCHMARK_WHEELS
    a = 0.5 * (r_r + r_f)
    return Machine(mass=mt, h=h, a=a, t=0.0, inertia=(ixx, iyy, izz), spin_inertia=a * (i_r / r_r + i_f / r_f),
                   head=BENCHMARK_HEAD_ESTIMATE, width=BENCHMARK_WIDTH_ESTIMATE, name="benchmark-bicycle",
                   source="Meijaard Papadopoulos Ruina Schwab (2007) Table 1; head height and width estimates")


def stunt125() -> Machine:
    """A light 125 cc trail/stunt motorcycle with rider: every number an
    estimate (docs/machine.md sec. 7)."""
    return Machine(mass=165.0, h=0.80, a=0.30, t=0.045, inertia=(25.0, 40.0, 20.0), spin_inertia=0.8, head=1.65,
                   width=0.80, name="stunt125", source="estimates (docs/machine.md sec. 7): 90 kg bike + 75 kg rider; "
                   "tyres 70/100-19 and 90/100-16; handlebar 0.8 m")


#: The presets of ``--machine``, by name.
PRESETS = {m.name: m for m in (paper_wheel(), benchmark_bicycle(), stunt125())}
DEFAULT_MACHINE = "stunt125"


def as_machine(machine) -> Machine:
    """A :class:`Machine` from a Machine or a preset's name."""
    if isinstance(machine, Machine):
        return machine
    if isinstance(machine, str):
        key = machine.strip().lower()
        if key in PRESETS:
            return PRESETS[key]
        raise ParameterError(f"machine must be one of {' | '.join(PRESETS)} or a deathsphere.Machine "
                             f"(got {machine!r})", "machine")
    raise ParameterError(f"machine must be a deathsphere.Machine or a preset's name (got {machine!r})", "machine")


#: Keys of a machine file (TOML or CSV) -> registry parameter.
FILE_KEYS = {"mass": "mass", "com_height": "com_height", "wheel_radius": "a", "tyre_radius": "tyre_radius",
             "roll_inertia": "roll_inertia", "pitch_inertia": "pitch_inertia", "yaw_inertia": "yaw_inertia",
             "spin_inertia": "spin_inertia", "head_height": "head_height", "width": "width"}


def machine_file(path, base=DEFAULT_MACHINE) -> Machine:
    """A machine from a small TOML file (``key = value`` lines) or a CSV file
    (a header naming the keys, one row of values): keys ``name``, ``source``
    and those of :data:`FILE_KEYS` (numbers, or text with a unit suffix:
    ``"16in"``); a key not given keeps ``base``'s value (a preset)."""
    data, p = machine_file_data(path)
    unknown = sorted(set(data) - set(FILE_KEYS) - {"name", "source", "base"})
    if unknown:
        raise ParameterError(f"machine file {p.name}: unknown key {unknown[0]!r} (known: name, source, base, "
                             f"{', '.join(FILE_KEYS)})", "machine_file")
    start = as_machine(str(data.get("base", base)))
    values = {FILE_KEYS[k]: v for k, v in data.items() if k in FILE_KEYS}
    machine = start.with_overrides(**values)
    if "name" not in data and any(c in p.stem for c in UNECHOABLE):
        raise ParameterError(f"machine file {p.name}: its name (the file's name: {p.stem!r}) holds a comma or a line "
                             "break, which the CSV output cannot echo; give a name key", "machine_file")
    from deathsphere.table.reasons import reason_text

    # the file's name as the default source, written as a reason is (no comma, one line)
    return replace(machine, name=str(data.get("name", p.stem)),
                   source=str(data.get("source", reason_text(f"file {p.name}"))))


def machine_file_data(path) -> tuple[dict, "pathlib.Path"]:
    """The keys and values of a machine file, TOML (``.toml``: ``key =
    value`` lines) or CSV (a header naming the keys, one row of values),
    and its path; what is not such a file is refused in one line
    (:func:`machine_file`; the two-wheeler's files read them too)."""
    import csv
    import tomllib

    text, p = machine_file_text(path)
    if p.suffix.lower() == ".toml":
        try:
            return tomllib.loads(text), p
        except tomllib.TOMLDecodeError as exc:
            raise ParameterError(f"machine file {p.name}: not TOML ({exc})", "machine_file") from None
    rows = [r for r in csv.reader(text.splitlines()) if any(c.strip() for c in r)]
    if len(rows) != 2 or len(rows[0]) != len(rows[1]):
        raise ParameterError(f"machine file {p.name}: a CSV machine file is a header and one row of values",
                             "machine_file")
    keys = [k.strip() for k in rows[0]]
    twice = next((k for i, k in enumerate(keys) if k in keys[:i]), None)
    if twice is not None:
        raise ParameterError(f"machine file {p.name}: key {twice!r} is given twice (which one is meant?)",
                             "machine_file")
    return dict(zip(keys, (v.strip() for v in rows[1]))), p


def machine_file_text(path) -> tuple[str, "pathlib.Path"]:
    """A machine file's text and path; a file that cannot be read, or is
    not text, is refused in one line."""
    import pathlib

    p = pathlib.Path(path)
    try:
        raw = p.read_bytes()
    except OSError as exc:
        raise ParameterError(f"cannot read the machine file {str(path)!r}: {exc.strerror}", "machine_file") from None
    return _machine_text(raw, p.name), p


def _machine_text(raw: bytes, name: str) -> str:
    """A machine file's text: UTF-8, its byte-order mark dropped (a
    spreadsheet's export), or UTF-16 with a byte-order mark; anything else
    is refused in one line."""
    import codecs

    encoding = "utf-16" if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)) else "utf-8-sig"
    try:
        return raw.decode(encoding)
    except UnicodeDecodeError as exc:
        shown = encoding.upper().replace("-SIG", "")
        raise ParameterError(f"machine file {name}: not {shown} text (byte {exc.start}: "
                             f"{raw[exc.start:exc.start + 1]!r}); save it as UTF-8", "machine_file") from None
