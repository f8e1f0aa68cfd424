"""``map`` on a surface other than the globe: the allowed (lane, alpha)
region of a wheel on a drum, a cone, flat ground or a profile, as data and
as a figure's curves (beyond the paper; docs/limits.md sec. 8)."""

from __future__ import annotations

import numpy as np

from deathsphere.api.arguments import INF, A, G, R, checked_axis, checked_choice, checked_scalar, is_given
from deathsphere.api.lane_limits import MAX_LANES, _too_many, ground_of
from deathsphere.constants import SIDES
from deathsphere.params import ParameterError


def _setup(surface, r, diameter, wall_angle, wall_height, profile, height, turn_radius, a, k, g, side, mu, max_g,
           stability, step):
    from deathsphere.params import first_problem
    from deathsphere.results.lane_map import default_lanes

    if stability:
        raise ParameterError("the stability map is the globe's: off the globe map draws the allowed region "
                             "only (orbit --surface gives each orbit's stability)", "stability")
    if step is not None:
        raise ParameterError("step is the globe's theta step: on another surface give the lanes as "
                             "height start:stop:step (turn_radius on flat ground)", "step")
    ground, word = ground_of(surface, r, diameter, wall_angle, wall_height, profile, None, height, turn_radius)
    side = checked_choice("side", side, SIDES)
    values = {name: checked_scalar(name, v) for name, v in (("a", a), ("k", 0.5 if k is None else k), ("g", g),
                                                          ("mu", mu), ("max_g", max_g))}
    for name, value in values.items():
        problem = first_problem(name, [value])
        if problem:
            raise ParameterError(problem, name)
    lane = turn_radius if word == "turn_radius" else height
    if is_given(lane):
        axis = checked_axis(word, list(lane) if isinstance(lane, (list, tuple)) else lane)
        _too_many(word, [len(axis)])
        heights = np.asarray(axis.values(), dtype=float)
        problem = first_problem("height", heights)
        if problem:
            raise ParameterError(problem.replace("height", word, 1), word)
    else:
        heights = default_lanes(ground, values["a"])
    return ground, heights, values, side == "outside"


def region_on(*, surface, height=None, turn_radius=None, wall_angle=None, wall_height=None, profile=None, a=A,
              r=R, diameter=None, k=None, g=G, side="inside", mu=INF, max_g=INF, stability=False, step=None):
    """The allowed (lane, alpha) region of a wheel off the globe as data:
    ``deathsphere map --surface ... --format csv``.  One row per boundary
    point on each lane (``height`` [m] values or ``start:stop:step`` text,
    on flat ground ``turn_radius``; default: 361 lanes from the floor to the
    top): ``curve`` (S4 fit, S5 floor, S2 Omega^2 = 0 or pole, S3 contact,
    mu, max_g), ``equation``, ``height_m``, ``alpha_deg`` and whether the
    orbit just below and just above it in alpha is feasible
    (``feasible_below``, ``feasible_above``), then the setup and the lane."""
    from deathsphere.results.lane_map import lane_boundary_table

    ground, heights, v, outside = _setup(surface, r, diameter, wall_angle, wall_height, profile, height,
                                         turn_radius, a, k, g, side, mu, max_g, stability, step)
    return lane_boundary_table(ground, heights, v["a"], v["k"], v["g"], outside, v["mu"], v["max_g"])


def region_curves_on(*, surface, height=None, turn_radius=None, wall_angle=None, wall_height=None, profile=None,
                     a=A, r=R, diameter=None, k=None, g=G, side="inside", mu=INF, max_g=INF, stability=False,
                     step=None):
    """The allowed region off the globe as a figure's curves
    (:class:`deathsphere.results.lane_map.LaneCurves`): what ``deathsphere
    map --surface ... --output FILE`` draws."""
    from deathsphere.results.lane_map import lane_curves

    ground, heights, v, outside = _setup(surface, r, diameter, wall_angle, wall_height, profile, height,
                                         turn_radius, a, k, g, side, mu, max_g, stability, step)
    return lane_curves(ground, heights, v["a"], v["k"], v["g"], outside, v["mu"], v["max_g"])


__all__ = ["region_on", "region_curves_on", "MAX_LANES"]
