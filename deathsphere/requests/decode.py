"""The one decoder: request records from a mapping of keys as typed (a show
plan's ``[globe]`` and ``[[rider]]`` tables, the command line's options, the
API's keywords).  Which lane, which of theta and height, which of the
tilt, the two speeds and the lap time, radius or diameter: decided here,
once, as the records' structure.

``read(key, raw)`` reads one value the way its caller's values come: one
number with a unit for a plan (:func:`.values.table_reader`), an array for
the API's broadcast grids; it refuses a value outside the registry's
bounds itself, naming the key."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from deathsphere.errors import ParameterError
from deathsphere.params import choice, shown_number
from deathsphere.physics.ground import Sphere
from deathsphere.records.paper_bodies import PAPER_BODIES, Ball, PaperBodyKind, Wheel
from deathsphere.requests.keys import Keys
from deathsphere.requests.records import (ComSpeed, ContactSpeed, Height, Horizontal, Period, Rate, RiderRequest,
                                          Run, SameLap, Spin, Theta, Tilt, Vertical)

#: The ways a lane may be held, by kind.
LANES = ("horizontal", "vertical")
#: How a rider's horizontal lane is held (ride, a show's plan): each key as typed and its record (one of them).
LANE_HOLDS = {"alpha": Tilt, "speed": ContactSpeed, "com_speed": ComSpeed, "period": Period,
              "same_lap_as": SameLap}
#: The keys that belong to one kind of lane only.
LANE_KEYS = {"horizontal": ("theta", "height", *LANE_HOLDS, "direction"), "vertical": ("v_top", "azimuth")}


def _one_of(given: Mapping, keys: Keys, first: str, second: str, what: str):
    """The one of ``first``/``second`` given, as (key, raw); refused when
    both or neither are (both: named by the second, as typed)."""
    has = [k for k in (first, second) if given.get(k) is not None]
    if len(has) != 1:
        keys.fail(second if has else first, f"give exactly one of {first} and {second}{what}", missing=not has)
    return has[0], given[has[0]]


def _exactly_one(given: Mapping, keys: Keys, names, what: str):
    """The one of ``names`` given, as (key, raw); refused when several
    (named by the second given, as typed) or none are."""
    has = [k for k in names if given.get(k) is not None]
    if len(has) != 1:
        listed = ", ".join(names[:-1]) + f" and {names[-1]}"
        keys.fail(has[1] if has else names[0], f"give exactly one of {listed}{what}", missing=not has)
    return has[0], given[has[0]]


def decode_ground(given: Mapping, keys: Keys, read) -> Sphere:
    """The globe from its ``diameter`` or radius (``radius`` in a plan, ``r``
    as an option or keyword)."""
    radius = "radius" if "radius" in given else "r"
    key, raw = _one_of(given, keys, "diameter", radius, "")
    value = read(key, raw)
    return Sphere(value / 2.0 if key == "diameter" else value)


def decode_run(given: Mapping, keys: Keys, read, defaults: Mapping) -> Run:
    """The run: the ground, gravity and the limits (``defaults`` where a key
    was not given: a plan's or the API's)."""
    def value(key):
        raw = given.get(key)
        return read(key, defaults[key] if raw is None else raw)

    return Run(ground=decode_ground(given, keys, read), g=value("g"), mu=value("mu"), max_g=value("max_g"))


def _within(height, ground: Sphere, keys: Keys, key: str):
    """A height inside the globe (on a drum or a cone: no higher than its
    wall's top), else refused (naming the lowest offender)."""
    if not isinstance(ground, Sphere):
        h, top = np.asarray(height, dtype=float), float(ground.highest_lane)
        if np.any(h > top):
            keys.fail(key, f"height (contact height) is above the wall's top: it must be at most the "
                           f"{ground.name}'s wall height {top:g} m (got {shown_number(float(np.max(h)))})")
        return height
    h, top = np.asarray(height, dtype=float), 2.0 * np.asarray(ground.radius, dtype=float)
    try:
        out = h > top
    except ValueError:      # not broadcast together: refused as such where the grid is built
        return height
    if np.any(out):
        i = np.unravel_index(int(np.argmax(out)), out.shape) if out.ndim else ()
        t = top if top.ndim == 0 else np.broadcast_to(top, out.shape)[i]
        keys.fail(key, f"height (contact height) is outside the globe: it must be at most the globe's diameter "
                       f"{float(t):g} m (got {shown_number(float(h[i]))})")
    return height


def decode_lane(given: Mapping, keys: Keys, read, ground: Sphere, cone: bool = False,
                plan: bool = False) -> Horizontal | Vertical:
    """The lane a rider's keys describe: ``lane`` (``"horizontal"``, the
    default, or ``"vertical"``) and the keys of that kind only; ``cone``: a
    vertical lane takes ``theta``, its cone angle (``ride --vertical``; a
    show's loopers ride great circles).  A horizontal lane is held by
    exactly one of :data:`LANE_HOLDS`; ``plan``: a show's plan, whose riders ride
    a speed or a lap (no tilt) and may take another rider's lap
    (``same_lap_as``)."""
    kind = given.get("lane", "horizontal")
    if kind not in LANES:
        keys.fail("lane", f"must be horizontal or vertical (got {kind!r})")
    other = LANE_KEYS["vertical" if kind == "horizontal" else "horizontal"]
    wrong = [k for k in other if given.get(k) is not None and not (cone and k == "theta")]
    if wrong:
        keys.refuse(wrong[0], f"is not a key of a {kind} lane")
    if kind == "vertical":
        if given.get("v_top") is None:
            keys.fail("v_top", "a vertical lane needs v_top (the centre of mass's speed at the top)", missing=True)
        extra = {k: read(k, given[k]) for k in ("azimuth", "theta") if given.get(k) is not None}
        if cone and given.get("theta") is None:
            keys.fail("theta", "a vertical loop needs theta (its cone angle; 90: a great circle)", missing=True)
        return Vertical(v_top=read("v_top", given["v_top"]), **extra)
    key, raw = _one_of(given, keys, "theta", "height", " (the contact's height above the floor)")
    at = Theta(read(key, raw)) if key == "theta" else Height(_within(read(key, raw), ground, keys, key))
    holds = tuple(k for k in LANE_HOLDS if k != ("alpha" if plan else "same_lap_as"))
    key, raw = _exactly_one(given, keys, holds, " (speed: the contact's along the ground; com_speed: the centre "
                                                "of mass's; period: the lap time)")
    if key == "same_lap_as":
        if not isinstance(raw, str) or not raw:
            keys.fail(key, f"must be the name of another rider of the plan (got {raw!r})")
        return Horizontal(at=at, by=SameLap(raw))
    return Horizontal(at=at, by=LANE_HOLDS[key](read(key, raw)))


#: A rider's direction, as typed, seen from above.
DIRECTIONS = {"ccw": 1, "cw": -1}


def decode_rider(given: Mapping, keys: Keys, read, body, ground: Sphere, cone: bool = False,
                 plan: bool = False) -> RiderRequest:
    """One rider on ``ground``: its body (a machine record), its lane, its
    direction (``ccw`` or ``cw``), phase and name (``plan``: as
    :func:`decode_lane`)."""
    direction = given.get("direction", "ccw")
    if direction not in DIRECTIONS:
        keys.fail("direction", f"must be ccw or cw, seen from above (got {direction!r})")
    phase = given.get("phase")
    return RiderRequest(body=body, lane=decode_lane(given, keys, read, ground, cone, plan),
                        direction=DIRECTIONS[direction],
                        phase=0.0 if phase is None else read("phase", phase), name=str(given.get("name") or ""))


# ---------------------------------------------------------------------------
# the paper's bodies: the one place a word names one

#: The paper's bodies by the word that names them (``--body``, the API's
#: ``body=``, an input CSV's ``body`` column, a result table's read back).
PAPER_BODY_WORDS = {body.word: body for body in PAPER_BODIES}


def decode_paper_body(raw, key: str = "body", allowed=PAPER_BODIES) -> PaperBodyKind:
    """The paper's body ``raw`` names (case aside, as the command line
    takes it) or ``raw`` itself if a body's record, one of ``allowed``;
    anything else refused naming ``key``."""
    words = tuple(body.word for body in allowed)
    if isinstance(raw, PaperBodyKind) and raw in allowed:
        return raw
    if not isinstance(raw, str):
        raise ParameterError(f"{key} must be one of {' | '.join(words)} (got {raw!r})", key)
    return PAPER_BODY_WORDS[choice(key, raw, words)]


def paper_body_named(word) -> PaperBodyKind | None:
    """The paper's body ``word`` names exactly (None: it names none)."""
    return PAPER_BODY_WORDS.get(word) if isinstance(word, str) else None


def text_codes(values: np.ndarray, vocabulary: tuple) -> np.ndarray:
    """The index of each text value in ``vocabulary`` (int8; -1 for none of
    them).  A request batch compares its text columns once, here, and
    integers from then on: comparing an object array costs a Python call
    per element, and a sweep's batch holds one body and one side in every
    row (one comparison decides it)."""
    codes = np.full(values.size, -1, dtype=np.int8)
    if values.size == 0:
        return codes
    first = values[0]
    if isinstance(first, str) and np.all(values == first):
        codes[:] = vocabulary.index(first) if first in vocabulary else -1
        return codes
    for j, word in enumerate(vocabulary):
        codes[values == word] = j
    return codes


def paper_body_codes(words: np.ndarray) -> np.ndarray:
    """Each row's body code (its index in :data:`PAPER_BODIES`; -1: a word
    that names none), from a column of words as typed or printed."""
    return text_codes(np.asarray(words, dtype=object).reshape(-1), tuple(PAPER_BODY_WORDS))


# ---------------------------------------------------------------------------
# a machine file: its keys as typed, each value within the registry's bounds

def decode_machine_file(path, base=None):
    """A single-contact machine from its file (``--machine-file``, a show
    plan's ``machine_file``; docs/machine.md sec. 7): a small TOML file
    (``key = value`` lines) or a CSV file (a header naming the keys, one row
    of values), keys ``name``, ``source``, ``base`` and those of
    :data:`~deathsphere.records.machine_files.FILE_KEYS`.  Each value is read
    as a plan's are (a number, or text with a unit suffix: ``"16in"``),
    within the registry's bounds of the parameter it sets; a key not given
    keeps ``base``'s value (a preset; default the default machine).  A
    refusal names the file and the key as typed (``machine file bike.toml:
    wheel_radius: ...``), reported under ``machine_file``."""
    from dataclasses import replace

    from deathsphere.params import PARAMS
    from deathsphere.records.machine import UNECHOABLE
    from deathsphere.records.machine_files import FILE_KEYS, file_source, machine_file_data
    from deathsphere.records.machine_presets import DEFAULT_MACHINE, as_machine
    from deathsphere.requests.values import typed_value

    data, p = machine_file_data(path)
    keys = Keys(where=f"machine file {p.name}", param="machine_file")
    unknown = sorted(set(data) - set(FILE_KEYS) - {"name", "source", "base"})
    if unknown:
        keys.fail(None, f"unknown key {unknown[0]!r} (known: name, source, base, {', '.join(FILE_KEYS)})")
    values = {param: typed_value(keys, key, data[key], PARAMS[param].kind, param)
              for key, param in FILE_KEYS.items() if key in data}
    try:
        start = as_machine(str(data.get("base", DEFAULT_MACHINE if base is None else base)))
    except ParameterError as exc:
        keys.fail("base", str(exc))
    try:
        machine = start.with_overrides(**values)    # the record's own rules: how its values go together
    except ParameterError as exc:
        keys.fail(None, str(exc))
    if "name" not in data and any(c in p.stem for c in UNECHOABLE):
        keys.fail(None, f"its name (the file's name: {p.stem!r}) holds a comma or a line break, which the CSV "
                        "output cannot echo; give a name key")
    try:
        return replace(machine, name=str(data.get("name", p.stem)), source=str(data.get("source", file_source(p.name))))
    except ParameterError as exc:
        keys.fail("name" if "name" in data else "source", str(exc))


def read_machine_file(path, base=None):
    """A machine file's machine: a two-wheeler when it is a two-wheeler's
    (:func:`~deathsphere.records.two_wheeler_files.is_two_wheeler_file`,
    read by :func:`~deathsphere.records.two_wheeler_files.two_wheeler_file`),
    else the single-contact machine of :func:`decode_machine_file`;
    ``base`` the preset whose values the keys not given keep."""
    from deathsphere.records.machine_presets import DEFAULT_MACHINE
    from deathsphere.records.two_wheeler_files import is_two_wheeler_file, two_wheeler_file

    if is_two_wheeler_file(path):
        return two_wheeler_file(path, base=DEFAULT_MACHINE if base is None else base)
    return decode_machine_file(path, base=base)


# ---------------------------------------------------------------------------
# a paper body's lane in a run (``simulate``): which keys hold it, decided once

#: The rule that one of a paper body's keys holds its steady horizontal
#: orbit (the record's ``held_by``), in words.
HELD_BY = {
    Wheel: "a wheel's steady orbit needs alpha (deg), or its speed (the contact's), com_speed (the centre's) or "
           "rate: one of them alone (no omega3)",
    Ball: "a sphere's steady orbit needs exactly one of omega3 and omega (no alpha, speed or com_speed)",
}
#: How a horizontal lane is held, by the key that holds it.
HOLDS = {"alpha": Tilt, "speed": ContactSpeed, "com_speed": ComSpeed, "omega": Rate, "omega3": Spin}
#: The keys of a lane of ``simulate``'s: a horizontal lane's holders and a loop's top speed.
RUN_LANE_KEYS = (*HOLDS, "v_top")


def decode_paper_lane(given: Mapping, body: PaperBodyKind, read, keys: Keys = Keys(),
                      at: Height | None = None) -> Horizontal | Vertical:
    """The lane a paper body's run starts on, from ``simulate``'s keys as
    typed: with ``vertical`` a wheel's loop at its top speed ``v_top`` and
    cone angle ``theta``; else the horizontal orbit at ``theta`` (or ``at``,
    a lane by its height on another ground) held by one of the body's keys
    alone (its record's ``held_by``), on the root ``branch`` where several
    orbits share it (0 first; the tilt's in increasing alpha, or eq. 55's
    slow and fast root)."""
    theta = read("theta", given["theta"]) if at is None else None
    typed = {key: read(key, given[key]) for key in RUN_LANE_KEYS if given.get(key) is not None}
    branch = given.get("branch", 0)
    if given.get("vertical"):
        if not isinstance(body, Wheel) or set(typed) != {"v_top"}:
            keys.fail(None, "vertical=True simulates a wheel: give theta and v_top (no alpha, speed, com_speed, "
                            "omega or omega3)")
        _paper_branch(branch, keys)
        return Vertical(v_top=typed["v_top"], theta=theta)
    if "v_top" in typed:
        keys.fail(None, "v_top is for vertical orbits (vertical=True)")
    if len(typed) != 1 or next(iter(typed)) not in body.held_by:
        keys.fail(None, HELD_BY[type(body)])
    (key, value), = typed.items()
    where = Theta(theta) if at is None else at
    if key == "alpha":
        _paper_branch(branch, keys)
        return Horizontal(at=where, by=Tilt(value))
    if isinstance(body, Ball):
        _paper_branch(branch, keys)
    # a wheel's contact speed, centre speed or rate: its tilt, the root ``branch``, is found when the run is prepared
    return Horizontal(at=where, by=HOLDS[key](value, branch))


def _paper_branch(branch, keys: Keys) -> None:
    """A branch where at most two orbits share a lane (eq. 55's roots)."""
    if isinstance(branch, bool) or branch not in (0, 1):
        keys.fail(None, f"branch must be 0 (slow root of eq. 55) or 1 (fast root) (got {branch!r})")


# ---------------------------------------------------------------------------
# a request table's rows (``--input``): a refusal names the column as typed

def as_typed(key: str, reason: str, typed: Mapping) -> str:
    """``reason`` (a refusal of the registry's ``key``, in its words) naming
    the column as its header typed it when that is another name (an alias:
    ``theta_deg: theta (polar angle) must be ...``); ``typed``: field -> the
    header's name (those the header names alike need no more); no reason
    ('') stays none."""
    name = typed.get(key, key)
    return reason if name == key or not reason else f"{name}: {reason}"
