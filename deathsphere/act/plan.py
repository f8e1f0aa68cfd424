"""The plan of a show (docs/show.md): a globe (or an ``[arena]``: the wall
of death's drum, the well of death's cone, sec. 11; a profile, sec. 12) and its riders, read
from a TOML file or a dict and checked once, before any work.  Every fault is one
line naming the rider (or the globe) and the key; every dimensional value
takes the command line's unit suffixes ("16ft", "32km/h")."""

from __future__ import annotations

import math
import pathlib
from dataclasses import dataclass, field, replace

import numpy as np

from deathsphere import requests
from deathsphere.constants import STANDARD_GRAVITY as G
from deathsphere.errors import ParameterError
from deathsphere.records.machine import Machine
from deathsphere.records.machine_files import FILE_KEYS
from deathsphere.records.machine_presets import PRESETS, as_machine
from deathsphere.records.two_wheeler import TwoWheeler
from deathsphere.records.two_wheeler_presets import TWO_WHEELERS
from deathsphere.requests import decode
from deathsphere.requests.arena import arena, is_globe
from deathsphere.requests.keys import Keys
from deathsphere.requests.records import Run
from deathsphere.requests.values import typed_value, table_reader

#: The keys of the ``[globe]`` table.
GLOBE_KEYS = ("diameter", "radius", "mu", "max_g", "min_clearance", "g", "duration")
#: The keys of the ``[arena]`` table: the wall of death's drum, the well
#: of death's cone or a profile's surface of revolution (requests/arena.py
#: builds the ground), and the run's keys as in ``[globe]``.
ARENA_KEYS = ("surface", "diameter", "radius", "wall_angle", "wall_height", "profile", "mu", "max_g",
              "min_clearance", "g", "duration")
#: The surfaces a show's ``[arena]`` takes (flat ground has no wall to ride).
ARENA_SURFACES = ("sphere", "cylinder", "cone", "profile")
#: The keys of a ``[[rider]]`` table (``width`` overrides the machine's).
RIDER_KEYS = ("name", "machine", "lane", "height", "theta", "speed", "com_speed", "period", "same_lap_as",
              "direction", "phase", "azimuth", "v_top", "width")
#: How a show's horizontal lane may be held (one of them): the contact's speed
#: (a speedometer's), the centre of mass's, the lap time, another rider's lap.
HOLDS = ("speed", "com_speed", "period", "same_lap_as")
#: Characters a rider's name may not hold (the tables' and --fail's separators).
NOT_IN_NAMES = ",@\n\r"
#: The crew's rule when the plan gives none [m] (the spacing quoted for an
#: eight-rider act is 10-15 cm).
DEFAULT_MIN_CLEARANCE = 0.15
#: A contact closer than this to the axis [m] is on it (a profile's
#: spline meets the axis to about this, not to the bit).
ON_AXIS_M = 1e-6
#: The globe's keys a plan may leave out.
GLOBE_DEFAULTS = {"g": G, "mu": math.inf, "max_g": math.inf}


@dataclass(frozen=True)
class Globe:
    """The globe: the run the riders share (its ground, gravity g [m/s^2],
    the friction available mu, the largest load max_g [g], the act's
    duration [s] when the plan gives one, None: not given) and the crew's
    least clearance [m]."""

    run: Run
    min_clearance: float = DEFAULT_MIN_CLEARANCE

    @property
    def ground(self):
        """The ground the riders roll on: the globe (a Sphere), or an
        ``[arena]``'s drum or cone."""
        return self.run.ground

    @property
    def is_globe(self) -> bool:
        """True on the globe (the sphere): vertical loops are its physics only (a fall's flight lands on any arena)."""
        return is_globe(self.run.ground)

    r = property(lambda self: self.run.r, doc="The globe's radius [m].")
    g = property(lambda self: self.run.g, doc="Gravity [m/s^2].")
    mu = property(lambda self: self.run.mu, doc="The friction available.")
    max_g = property(lambda self: self.run.max_g, doc="The largest load allowed [g].")
    duration = property(lambda self: self.run.duration, doc="The act's length [s] (None: not given).")


@dataclass(frozen=True)
class Rider:
    """One rider of the plan, checked: its request (body, lane, direction,
    phase, name) on the globe ``ground``, read as the act reads a rider:
    lane 'horizontal' (theta_deg of the contact, held by one of the
    contact's speed [m/s] ``speed``, the centre of mass's ``com_speed``, the
    lap time ``period`` [s] or another rider's lap ``same_lap_as`` (NaN or
    None where not given), direction +1 ccw / -1 cw seen from above,
    phase_deg the contact's azimuth at t = 0) or 'vertical' (azimuth_deg of the loop's
    plane, v_top [m/s] the centre of mass's speed at the top, phase_deg the
    angle psi from the top at t = 0)."""

    request: requests.RiderRequest
    ground: object
    #: the plan's ``width`` [m] of a two-wheeler (whose record has none; a machine's is its record's)
    width_m: float | None = None

    name = property(lambda self: self.request.name)
    machine = property(lambda self: self.request.body)
    lane = property(lambda self: self.request.lane.kind)
    phase_deg = property(lambda self: self.request.phase)
    direction = property(lambda self: self.request.direction)

    @property
    def width(self) -> float:
        return self.machine.width if self.width_m is None else self.width_m

    @property
    def theta_deg(self) -> float:
        at = getattr(self.request.lane, "at", None)
        if isinstance(at, requests.Height):
            if not is_globe(self.ground):          # theta is the globe's: a wall's lane is its height
                return math.nan
            return math.degrees(float(self.ground.theta(at.height)))
        return at.theta if at is not None else math.nan

    @property
    def height(self) -> float:
        """The contact's height above the floor [m] as planned (NaN: given by theta, or a vertical lane)."""
        at = getattr(self.request.lane, "at", None)
        return float(at.height) if isinstance(at, requests.Height) else math.nan

    @property
    def contact_height(self) -> float:
        """The contact's height above the floor [m] on a horizontal lane: as
        typed, else from theta on the globe (r (1 + cos theta)); NaN on a
        vertical lane (his height changes round the loop)."""
        if self.lane != "horizontal":
            return math.nan
        at = self.request.lane.at
        if isinstance(at, requests.Height):
            return float(at.height)
        return float(self.ground.height(math.radians(at.theta)))

    @property
    def speed(self) -> float:
        """The contact's speed along the ground [m/s] as planned (NaN: not given)."""
        by = getattr(self.request.lane, "by", None)
        return by.speed if isinstance(by, requests.ContactSpeed) else math.nan

    @property
    def com_speed(self) -> float:
        """The centre of mass's speed [m/s] as planned (NaN: not given)."""
        by = getattr(self.request.lane, "by", None)
        return by.speed if isinstance(by, requests.ComSpeed) else math.nan

    @property
    def period(self) -> float:
        """The lap time [s] as planned (NaN: not given)."""
        by = getattr(self.request.lane, "by", None)
        return by.period if isinstance(by, requests.Period) else math.nan

    @property
    def same_lap_as(self) -> str | None:
        """The rider whose lap this one rides (None: its own)."""
        by = getattr(self.request.lane, "by", None)
        return by.name if isinstance(by, requests.SameLap) else None

    @property
    def azimuth_deg(self) -> float:
        return getattr(self.request.lane, "azimuth", math.nan)

    @property
    def v_top(self) -> float:
        return getattr(self.request.lane, "v_top", math.nan)


#: The plan's dimensional keys whose values a terminal view shows back in
#: the unit typed, by the registry's name (a plan's ``radius`` is ``r``),
#: and their kind; the registry has no ``min_clearance``: a length.
TYPED_KEYS = {"diameter": "length", "radius": "length", "wall_height": "length", "min_clearance": "length",
              "height": "length", "width": "length", "speed": "speed", "com_speed": "speed", "v_top": "speed"}


def typed_values(plan: dict) -> dict:
    """``{name: (kind, values as typed)}`` of :data:`TYPED_KEYS` over the
    plan's tables, in the plan's order (a number is in the API's unit, a
    text carries its unit: ``"0.5ft"``); only the keys the plan gives."""
    tables = [plan.get("globe"), plan.get("arena")]
    riders = plan.get("rider", [])
    tables += [riders] if isinstance(riders, dict) else list(riders) if isinstance(riders, list) else []
    out: dict = {}
    for table in tables:
        if not isinstance(table, dict):
            continue
        for key, kind in TYPED_KEYS.items():
            if table.get(key) is not None:
                name = "r" if key == "radius" else key
                out[name] = (kind, out.get(name, (kind, ()))[1] + (table[key],))
    return out


@dataclass(frozen=True)
class Plan:
    """A checked plan: the globe and its riders, in the plan's order;
    ``typed``: its dimensional values as typed (:func:`typed_values`), so
    that a terminal view shows them back in their units."""

    globe: Globe
    riders: tuple[Rider, ...]
    typed: dict = field(default_factory=dict)

    def names(self) -> list[str]:
        return [r.name for r in self.riders]

    def with_phases(self, phases: dict) -> Plan:
        """The plan with some riders' phases [deg] replaced, by name."""
        return replace(self, riders=tuple(
            replace(r, request=replace(r.request, phase=float(phases.get(r.name, r.phase_deg))))
            for r in self.riders))


def _fail(where: str, key: str | None, what: str):
    Keys(where).fail(key, what)


def _unknown(where: str, table: dict, known) -> None:
    extra = [k for k in table if k not in known]
    if extra:
        _fail(where, extra[0], f"unknown key (known: {', '.join(known)})")


def _globe(raw) -> Globe:
    keys = Keys("globe")
    if not isinstance(raw, dict):
        keys.fail(None, "the plan needs a [globe] table (diameter or radius, mu, max_g, min_clearance)")
    _unknown(keys.where, raw, GLOBE_KEYS)
    run = decode.decode_run(raw, keys, table_reader(keys), GLOBE_DEFAULTS)
    clear = typed_value(keys, "min_clearance", raw.get("min_clearance", DEFAULT_MIN_CLEARANCE), "length", lo=0.0)
    if "duration" in raw:
        run = replace(run, duration=typed_value(keys, "duration", raw["duration"], "none", lo=0.0, lo_open=True))
    return Globe(run=run, min_clearance=clear)


def _profile(keys: Keys, raw, base_dir: pathlib.Path | None):
    """An ``[arena]``'s ``profile``: a Profile as it is (a dict plan from the
    API), or a CSV file's path, relative to the plan file's directory when
    the plan is a file (as a machine file's), else to the working directory."""
    from deathsphere.physics.ground import Profile

    if isinstance(raw, Profile):
        return raw
    if not isinstance(raw, (str, pathlib.Path)):
        keys.fail("profile", f"must be a profile CSV file's path (rho_m,z_m rows) or a Profile (got {raw!r})")
    path = pathlib.Path(raw)
    return base_dir / path if base_dir is not None and not path.is_absolute() else path


def _arena(raw, base_dir: pathlib.Path | None = None) -> Globe:
    """An ``[arena]`` table: the ground from its ``surface`` and shape
    through :func:`deathsphere.requests.arena.arena` (a refusal names the
    plan's key: ``arena: wall_angle: ...``; a profile file's path is read
    from ``base_dir``, the plan file's directory), the run's keys as
    ``[globe]``'s."""
    keys = Keys("arena")
    if not isinstance(raw, dict):
        keys.fail(None, "must be a table (surface, diameter, wall_height; a cone's wall_angle; a profile's profile)")
    _unknown(keys.where, raw, ARENA_KEYS)
    surface = raw.get("surface")
    if surface is None:
        keys.fail("surface", f"the arena needs its surface ({' | '.join(ARENA_SURFACES)})")
    if isinstance(surface, str) and surface.strip().lower() == "profile" and "profile" not in raw:
        keys.fail("profile", "a profile arena needs its meridian: profile = \"FILE.csv\" (rho_m,z_m rows, the "
                             "path relative to the plan's directory)")
    if not isinstance(surface, str) or surface.strip().lower() not in ARENA_SURFACES:
        keys.fail("surface", f"must be one of {' | '.join(ARENA_SURFACES)} (got {surface!r}): a show's riders "
                             "ride up a wall")
    typed = {"radius": "r"}
    shape = {typed.get(k, k): raw[k] for k in ("diameter", "radius", "wall_angle", "wall_height") if k in raw}
    if "profile" in raw:
        shape["profile"] = _profile(keys, raw["profile"], base_dir)
    try:
        ground = arena(surface, **shape)
    except ParameterError as exc:
        key = {"r": "radius"}.get(exc.param, exc.param)
        keys.fail(key if key in raw or key in ARENA_KEYS else None, str(exc))
    read = table_reader(keys)

    def value(key):
        return read(key, GLOBE_DEFAULTS[key] if raw.get(key) is None else raw[key])

    run = Run(ground=ground, g=value("g"), mu=value("mu"), max_g=value("max_g"))
    clear = typed_value(keys, "min_clearance", raw.get("min_clearance", DEFAULT_MIN_CLEARANCE), "length", lo=0.0)
    if "duration" in raw:
        run = replace(run, duration=typed_value(keys, "duration", raw["duration"], "none", lo=0.0, lo_open=True))
    return Globe(run=run, min_clearance=clear)


def _on_a_wall(keys: Keys, raw: dict, ground) -> None:
    """A rider on a drum or a cone: a horizontal lane by its height (theta
    and a vertical loop are the globe's), no higher than the wall's top."""
    if raw.get("lane") == "vertical":
        roof = "a show's loops ride the globe's great circles" if _closed_on_top(ground) else \
            "a loop over the top needs a roof"
        keys.fail("lane", f"a vertical loop is the globe's: not on a {ground.name} ({roof}; ride horizontal lanes "
                          "by their height)")
    if "theta" in raw:
        keys.fail("theta", f"a lane on a {ground.name} is given by its height above the floor (theta is the "
                           "globe's polar angle)")


def _closed_on_top(ground) -> bool:
    """True for a wall whose meridian ends on the axis at its top (a
    profile's dome): it has a roof, though a show's loops are the globe's."""
    top = float(ground.highest_lane)
    return math.isfinite(top) and not float(ground.contact(top)[0]) > ON_AXIS_M


def _machine(where: str, raw, base_dir: pathlib.Path | None) -> Machine:
    """A preset's name, a machine file (TOML or CSV, relative to the plan)
    or the machine's parameters inline (the keys of a machine file)."""
    if isinstance(raw, dict):
        known = ("name", "source", "base", *FILE_KEYS)
        _unknown(where, raw, known)
        try:
            start = as_machine(str(raw.get("base", "stunt125")))
            m = start.with_overrides(**{FILE_KEYS[k]: v for k, v in raw.items() if k in FILE_KEYS})
            return replace(m, name=str(raw.get("name", m.name)), source=str(raw.get("source", "the plan")))
        except ParameterError as exc:
            _fail(where, f"machine.{exc.param or 'base'}", str(exc))
    if not isinstance(raw, str):
        _fail(where, "machine", f"must be a preset's name, a machine file or a table of parameters (got {raw!r})")
    if raw.strip().lower() in PRESETS:
        return PRESETS[raw.strip().lower()]
    if raw.strip().lower() in TWO_WHEELERS:
        return TWO_WHEELERS[raw.strip().lower()]
    path = pathlib.Path(raw)
    if base_dir is not None and not path.is_absolute():
        path = base_dir / path
    if path.suffix.lower() in (".toml", ".csv", ".txt") and path.is_file():
        try:      # ride's --machine-file reader: a two-wheeler's file or a single-contact machine's
            return decode.read_machine_file(path)
        except ParameterError as exc:
            _fail(where, "machine", str(exc))
    _fail(where, "machine", f"unknown machine {raw!r} (a preset: {' | '.join(PRESETS)}; a two-wheeler: "
                            f"{' | '.join(TWO_WHEELERS)}; or a .toml/.csv machine file or a two-wheeler's .txt; or "
                            "an inline table)")


def _rider(i: int, raw, globe: Globe, base_dir) -> Rider:
    if not isinstance(raw, dict):
        _fail(f"rider {i + 1}", None, f"must be a table (got {raw!r})")
    name = raw.get("name")
    # the names a plan takes are those --fail NAME@T can name: no '@', no space at either end
    if not isinstance(name, str) or not name.strip() or name != name.strip() or any(c in name for c in NOT_IN_NAMES):
        _fail(f"rider {i + 1}", "name", "must be a non-empty text without a comma, '@', line break or space at "
                                        f"either end (got {name!r})")
    keys = Keys(f"rider {name!r}")
    _unknown(keys.where, raw, RIDER_KEYS)
    if raw.get("lane") not in decode.LANES:     # a plan names its lane (no default)
        keys.fail("lane", f"must be horizontal or vertical (got {raw.get('lane')!r})")
    machine = _machine(keys.where, raw.get("machine", "stunt125"), base_dir)
    if isinstance(machine, TwoWheeler):
        return _two_wheeler_rider(keys, raw, machine, globe)
    if "width" in raw:
        machine = replace(machine, width=typed_value(keys, "width", raw["width"], "length", "width"))
    if machine.width is None:
        keys.fail("width", f"machine {machine.name!r} has no width: give width (handlebar or shoulders)")
    if raw["lane"] == "horizontal" and not any(k in raw for k in HOLDS):   # a show's rider rides a speed, not a tilt
        keys.fail("speed", "a horizontal lane needs speed (the contact's along the ground, what a speedometer "
                           "reads), com_speed (the centre of mass's), period (the lap time) or same_lap_as (a "
                           "rider's name)")
    if not globe.is_globe:
        _on_a_wall(keys, raw, globe.ground)
    rider = decode.decode_rider(raw, keys, table_reader(keys), machine, globe.ground, plan=True)
    if not globe.is_globe:
        _off_the_axis(keys, rider, globe.ground)
    return Rider(request=rider, ground=globe.ground)


def _two_wheeler_rider(keys: Keys, raw: dict, machine: TwoWheeler, globe: Globe) -> Rider:
    """A two-wheeler rider (docs/show.md, "Two-wheeler riders"): a
    horizontal lane held by its rear contact's speed, ``ride``'s steady
    turn there; its width from the plan (the record has none)."""
    if raw.get("lane") == "vertical":
        keys.fail("lane", f"a two-wheeler ({machine.name!r}) rides horizontal lanes only in a show (its vertical "
                          "loop is not analysed: ride it on a single-contact machine)")
    held = next((k for k in ("com_speed", "period", "same_lap_as") if k in raw), None)
    if held is not None:
        keys.fail(held, f"a two-wheeler's lane is held by speed (its rear contact's, as ride's --speed); {held} is "
                        "a single-contact machine's hold in a show")
    if "width" not in raw:
        keys.fail("width", f"two-wheeler {machine.name!r} has no width: give width (handlebar or shoulders)")
    width = typed_value(keys, "width", raw["width"], "length", "width")
    if "speed" not in raw:
        keys.fail("speed", "a two-wheeler's horizontal lane needs speed (its rear contact's along the ground)")
    if not globe.is_globe:
        _on_a_wall(keys, raw, globe.ground)
    rider = decode.decode_rider(raw, keys, table_reader(keys), machine, globe.ground, plan=True)
    if not globe.is_globe:
        _off_the_axis(keys, rider, globe.ground)
    return Rider(request=rider, ground=globe.ground, width_m=width)


def _off_the_axis(keys: Keys, rider, ground) -> None:
    """A lane by its height on a wall whose meridian meets the axis there (a
    profile closed at the bottom or the top): the contact would not go
    round, so no speed or lap holds it; refused naming ``height``."""
    at = getattr(rider.lane, "at", None)
    if isinstance(at, requests.Height) and not float(ground.contact(float(at.height))[0]) > ON_AXIS_M:
        keys.fail("height", f"the {ground.name}'s meridian meets its axis at this height (the contact would not "
                            "go round): a lane is a height where the wall is away from the axis")


def _plain(raw):
    """A plan dict with numpy scalars as the Python numbers they hold (the
    API takes a numpy number wherever it takes a number)."""
    if isinstance(raw, dict):
        return {k: _plain(v) for k, v in raw.items()}
    if isinstance(raw, (list, tuple)):
        return [_plain(v) for v in raw]
    if isinstance(raw, np.generic):
        return raw.item()
    return raw


def read_plan(plan) -> Plan:
    """A checked :class:`Plan` from a path to a TOML file (str or
    pathlib.Path) or a dict of the same tables ({"globe": {...}, "rider":
    [{...}, ...]}, or {"arena": {...}, ...}: a drum, a cone or a profile,
    whose riders ride horizontal lanes by their height; a profile file's
    path is relative to the plan file's directory).  Raises ParameterError, one line naming the rider (or
    the globe) and the key: an unknown key, an unknown machine, a rider
    outside the globe, duplicate names, no riders, a value outside its
    range or of the wrong unit.  (A vertical lane that is not feasible at
    all is refused when the lanes are built: :func:`deathsphere.act.lanes.build_lanes`.)"""
    import tomllib

    base_dir = None
    if isinstance(plan, (str, pathlib.Path)):
        path = pathlib.Path(plan)
        try:
            text = path.read_text(encoding="utf-8-sig")
        except (OSError, UnicodeDecodeError) as exc:
            raise ParameterError(f"plan: cannot read {str(plan)!r}: {getattr(exc, 'strerror', None) or exc}",
                                 "plan") from None
        try:
            plan = tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            raise ParameterError(f"plan: {path.name} is not TOML ({exc})", "plan") from None
        base_dir = path.parent
    plan = _plain(plan)
    if not isinstance(plan, dict):
        raise ParameterError(f"plan must be a path to a TOML file or a dict (got {type(plan).__name__})", "plan")
    _unknown("plan", plan, ("globe", "arena", "rider"))
    if "globe" in plan and "arena" in plan:
        _fail("plan", "arena", "give [globe] (the globe of death) or [arena] (a drum or a cone), not both")
    globe = _arena(plan["arena"], base_dir) if "arena" in plan else _globe(plan.get("globe"))
    raw = plan.get("rider", [])
    if isinstance(raw, dict):
        raw = [raw]
    if not isinstance(raw, list) or not raw:
        _fail("plan", "rider", "no riders: give at least one [[rider]] table")
    riders = tuple(_rider(i, r, globe, base_dir) for i, r in enumerate(raw))
    seen = set()
    for rider in riders:
        if rider.name in seen:
            _fail(f"rider {rider.name!r}", "name", "is given twice (names must differ)")
        seen.add(rider.name)
    _check_laps(riders)
    return Plan(globe=globe, riders=riders, typed=typed_values(plan))


def _check_laps(riders) -> None:
    """Every ``same_lap_as`` names another rider of the plan, and following
    them from any rider ends at a rider whose lap is his own (no circle)."""
    named = {r.name: r.same_lap_as for r in riders}
    for rider in riders:
        seen, name = [rider.name], rider.same_lap_as
        while name is not None:
            if name not in named:
                _fail(f"rider {rider.name!r}", "same_lap_as", f"names no rider of the plan (got {name!r}; riders: "
                                                               f"{', '.join(named)})")
            if name in seen:
                _fail(f"rider {rider.name!r}", "same_lap_as", "the riders' same_lap_as go round in a circle ("
                                                               + " -> ".join([*seen, name]) + "): one of them "
                                                               "needs a lap of its own (speed, com_speed or period)")
            seen.append(name)
            name = named[name]


#: A commented plan to start from (``deathsphere show --example``): a
#: 16-foot globe, three horizontal lanes and two loopers timed through them.
EXAMPLE_PLAN = '''\
# A show's plan for `deathsphere show PLAN.toml` (docs/show.md).
# Every dimensional value takes a unit: "16ft", "2.0m", "32km/h".
# The globe is centred at the origin, z up; angles in degrees.

[globe]
diameter = "16ft"          # or radius
mu = 0.9                   # tyre on steel mesh
max_g = 8                  # a loop's bottom is at least 6 g even for a point mass
min_clearance = "0.15m"    # the crew's rule: closer than this is a conflict
# duration = 60            # seconds; the act's length when the riders' periods are not commensurate
                           # (here every lap takes 1.274 s: the act is one lap)

# A horizontal lane: the contact at height above the floor (or theta from the
# top), phi = phase + Omega t (ccw) or phase - Omega t (cw), ride's steady orbit,
# held by one of: speed (the contact's along the ground, what the speedometer
# reads), com_speed (the centre of mass's), period (the lap time) or
# same_lap_as (another rider's lap).
[[rider]]
name = "Ana"
machine = "stunt125"       # a preset, a machine file, or an inline table of its parameters
width = "0.6m"             # handlebar or shoulders, the wider (here narrowed bars; else the machine's)
lane = "horizontal"
height = "1.4m"            # of the contact above the globe's floor (or theta)
speed = "39.18km/h"        # the contact's, as for ride: a lap in the loopers' 1.274 s
direction = "ccw"          # seen from above
phase = 0                  # deg: azimuth of the contact at t = 0

[[rider]]
name = "Cal"
machine = "stunt125"
width = "0.6m"
lane = "horizontal"
height = "2.0m"
period = "1.274s"          # the lap time
direction = "ccw"
phase = 40

[[rider]]
name = "Dee"
machine = "stunt125"
width = "0.6m"
lane = "horizontal"
height = "2.7m"
same_lap_as = "Ben"        # a looper's lap, whatever it is
direction = "ccw"
phase = 0

# A vertical lane: a great circle in the plane of the vertical and the
# direction azimuth; psi from the top, psi(0) = phase; ride --vertical's loop.
[[rider]]
name = "Ben"
machine = "stunt125"
width = "0.6m"
lane = "vertical"
azimuth = 90               # deg: the loop's plane holds the vertical and this direction
v_top = "6.5m/s"           # the centre of mass's speed at the top
phase = 178                # deg along the loop, from the top, at t = 0 (--phase auto's choice)

[[rider]]
name = "Eve"
machine = "stunt125"
width = "0.6m"
lane = "vertical"
azimuth = 0
v_top = "6.5m/s"
phase = 282
'''
