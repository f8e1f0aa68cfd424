"""``limits`` on a surface other than the globe: the feasible tilts on a
lane of a drum, a cone, flat ground or a profile, and the lowest and
highest lanes (beyond the paper; docs/limits.md sec. 8)."""

from __future__ import annotations

import math
from functools import partial

import numpy as np

from deathsphere.api.arguments import (
    CHUNK,
    R,
    broadcast_flat,
    checked_array,
    checked_axis,
    checked_choice,
    checked_scalar,
    grid_shape,
    is_given,
    one_default,
    raise_if_all_invalid,
    refuse_large_grid,
)
from deathsphere.api.streams import Chunks, input_requests, request_reader
from deathsphere.constants import SIDES
from deathsphere.params import ParameterError
from deathsphere.records.paper_bodies import Wheel
from deathsphere.requests.arena import arena, lane_key, refuse_above_top
from deathsphere.requests.decode import decode_paper_body

#: Lanes :func:`limits_on` evaluates at once (each a root search).
MAX_LANES = 100_000


def ground_of(surface, r, diameter, wall_angle, wall_height, profile, theta=None, height=None, turn_radius=None):
    """The arena of ``limits`` and ``map`` off the globe, and the name of
    its lane keyword (``height``, or ``turn_radius`` on flat ground); a
    lane given by the other keyword, or by theta, is refused naming it."""
    ground = arena(surface, None if r is R else r, diameter, wall_angle, wall_height, profile)
    word = lane_key(ground)
    if is_given(theta):
        raise ParameterError(f"theta is the sphere's polar angle: on the {ground.name} give the lane's {word}",
                             "theta")
    if word == "turn_radius" and is_given(height):
        raise ParameterError("on flat ground the lane is its turn_radius, not a height", "height")
    if word == "height" and is_given(turn_radius):
        raise ParameterError(f"turn_radius is the lane on flat ground (surface plane); on the {ground.name} give "
                             "height", "turn_radius")
    return ground, word


def _arena(typed: dict):
    """``ground_of`` from the keywords as given."""
    return ground_of(typed.get("surface"), typed.get("r", R), typed.get("diameter"), typed.get("wall_angle"),
                     typed.get("wall_height"), typed.get("profile"), typed.get("theta"), typed.get("height"),
                     typed.get("turn_radius"))


def _lanes(word, value):
    """The lanes as values: numbers, or ``start:stop:step`` text as an axis."""
    if isinstance(value, str) or (isinstance(value, (list, tuple)) and any(isinstance(v, str) for v in value)):
        axis = checked_axis(word, value)
        _too_many(word, [len(axis)])
        return axis.values()
    return value


def _too_many(word, counts):
    return refuse_large_grid(counts, command="limits", limit=MAX_LANES, param=word,
                             instead="each is a root search; split the range of lanes into several runs")


def limits_on(typed: dict):
    """:func:`deathsphere.limits` on a drum, a cone, flat ground or a
    profile (docs/limits.md sec. 8, docs/surfaces.md S1-S5); ``typed``: the
    keywords of :func:`deathsphere.limits` as given (``surface`` and its
    shape, ``height`` or ``turn_radius``, ``theta``, ``body``, ``side``,
    ``a``, ``r``, ``diameter``, ``k``, ``g``, ``mu``, ``max_g``).

    With a lane (``height``; on flat ground ``turn_radius``): one row per
    interval of alpha with a feasible orbit on it (the fit S4, the floor
    S5, Omega^2 > 0 of S2 = eq. (29), contact and friction S3 within
    ``mu``, the load within ``max_g``), with the speed range over each;
    a lane without any gives one row with ``intervals`` = 0.  Without a
    lane: two rows, the lowest and the highest lane with a feasible tilt
    (``lane``, ``bound``, ``note``; on an upright wall friction and load
    set no highest lane: only the wall's top does).  Then ``input_row``,
    ``body``, ``side``, ``status``, ``reason``.
    """
    from deathsphere.model import make_requests
    from deathsphere.results.lane_limits import NOT_A_WHEEL, lane_limits_rows

    body = decode_paper_body(typed.get("body", "wheel"))
    side = checked_choice("side", typed.get("side", "inside"), SIDES)
    if not isinstance(body, Wheel):
        raise ParameterError(NOT_A_WHEEL, "body")
    ground, word = _arena(typed)
    lane = typed.get(word)
    given = {name: typed.get(name) for name in ("a", "k", "g", "mu", "max_g")}
    if is_given(lane):
        given["height"] = _lanes(word, lane)
    checked = {name: checked_array(word if name == "height" else name, v) for name, v in given.items()
               if v is not None}
    _too_many(word, grid_shape(checked))
    if word == "height" and "height" in checked and np.size(checked["height"]):
        refuse_above_top(ground, float(np.max(checked["height"])))
    shape, flat = broadcast_flat(checked)
    req = make_requests(math.prod(shape), body=body, side=side, ground=ground, **flat)
    return raise_if_all_invalid(lane_limits_rows(req, ground, lanes=not is_given(lane)))


def limits_on_input(source, typed: dict, chunk_size: int = CHUNK) -> Chunks:
    """The limits on a lane of each request in a CSV file, on one arena:
    ``deathsphere limits --surface ... --input FILE``; ``typed`` the
    keywords of :func:`deathsphere.limits_input` as given.  The file's
    header names ``height`` (the lane; on flat ground the turn radius;
    ``height_m`` read too) and optionally ``body``, ``side``, ``a``, ``k``,
    ``g``, ``mu``, ``max_g``; an option given applies to every row.  A bad
    line, or a body other than a wheel, is one ``invalid`` row with the
    reason."""
    from deathsphere.inputs import ALIASES
    from deathsphere.model import REQUEST_FIELDS, make_requests
    from deathsphere.results.lane_limits import LANE_LIMITS_FIELDS, lane_limits_rows

    ground, word = _arena(typed)
    overrides = {}
    if typed.get("body") is not None:
        overrides["body"] = decode_paper_body(typed["body"]).word
    if typed.get("side") is not None:
        overrides["side"] = checked_choice("side", typed["side"], SIDES)
    for name, value in (("height", typed.get(word)),) + tuple((key, typed.get(key)) for key in
                                                              ("a", "k", "g", "mu", "max_g")):
        value = one_default(word if name == "height" else name, value)
        if value is not None:
            overrides[name] = value
    fields = {name: REQUEST_FIELDS[name] for name in LANE_LIMITS_FIELDS}
    reader = request_reader(source, fields, overrides, {**ALIASES, "height_m": "height", "turn_radius": "height"},
                            ())
    chunk_size = int(checked_scalar("chunk_size", chunk_size))
    make = partial(make_requests, typed=reader.typed, ground=ground)
    return Chunks((n, lane_limits_rows(req, ground, lanes=False)) for n, req in input_requests(reader, chunk_size,
                                                                                              make))
