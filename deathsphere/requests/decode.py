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

from deathsphere.params import shown_number
from deathsphere.physics.ground import Sphere
from deathsphere.requests.keys import Keys
from deathsphere.requests.records import (ComSpeed, ContactSpeed, Height, Horizontal, Period, RiderRequest, Run,
                                          SameLap, Theta, Tilt, Vertical)

#: The ways a lane may be held, by kind.
LANES = ("horizontal", "vertical")
#: How a horizontal lane is held: each key as typed and its record (one of them).
HOLDS = {"alpha": Tilt, "speed": ContactSpeed, "com_speed": ComSpeed, "period": Period, "same_lap_as": SameLap}
#: The keys that belong to one kind of lane only.
LANE_KEYS = {"horizontal": ("theta", "height", *HOLDS, "direction"), "vertical": ("v_top", "azimuth")}


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
    """A height inside the globe, else refused (naming the lowest offender)."""
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
    exactly one of :data:`HOLDS`; ``plan``: a show's plan, whose riders ride
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
    holds = tuple(k for k in HOLDS if k != ("alpha" if plan else "same_lap_as"))
    key, raw = _exactly_one(given, keys, holds, " (speed: the contact's along the ground; com_speed: the centre "
                                                "of mass's; period: the lap time)")
    if key == "same_lap_as":
        if not isinstance(raw, str) or not raw:
            keys.fail(key, f"must be the name of another rider of the plan (got {raw!r})")
        return Horizontal(at=at, by=SameLap(raw))
    return Horizontal(at=at, by=HOLDS[key](read(key, raw)))


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
