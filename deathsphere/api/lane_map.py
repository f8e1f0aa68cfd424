"""``map`` on a surface other than the globe: the allowed (lane, alpha)
region of a wheel on a drum, a cone, flat ground or a profile, as data and
as a figure's curves (beyond the paper; docs/limits.md sec. 8)."""

from __future__ import annotations

import numpy as np

from deathsphere.api.arguments import INF, A, G, checked_axis, checked_choice, checked_scalar, is_given
from deathsphere.api.lane_limits import MAX_LANES, _arena, _too_many
from deathsphere.constants import SIDES
from deathsphere.params import ParameterError
from deathsphere.requests.arena import refuse_above_top


def _setup(typed: dict):
    """The ground, the lanes [m], the setup's scalars and the side from the
    keywords of :func:`deathsphere.region` as given (``typed``; its
    ``stability`` is read by the callers)."""
    from deathsphere.params import first_problem
    from deathsphere.results.lane_map import default_lanes

    if typed.get("step") is not None:
        raise ParameterError("step is the globe's theta step: on another surface give the lanes as "
                             "height start:stop:step (turn_radius on flat ground)", "step")
    ground, word = _arena(dict(typed, theta=None))
    side = checked_choice("side", typed.get("side", "inside"), SIDES)
    defaults = {"a": A, "k": 0.5, "g": G, "mu": INF, "max_g": INF}
    values = {}
    for name, default in defaults.items():
        value = typed.get(name)
        values[name] = checked_scalar(name, default if value is None else value)
        problem = first_problem(name, [values[name]])
        if problem:
            raise ParameterError(problem, name)
    lane = typed.get(word)
    if is_given(lane):
        axis = checked_axis(word, list(lane) if isinstance(lane, (list, tuple)) else lane)
        _too_many(word, [len(axis)])
        heights = np.asarray(axis.values(), dtype=float)
        problem = first_problem("height", heights)
        if problem:
            raise ParameterError(problem.replace("height", word, 1), word)
        if word == "height" and heights.size:
            refuse_above_top(ground, float(np.max(heights)))
    else:
        heights = default_lanes(ground, values["a"])
    return ground, heights, values, side == "outside"


def region_on(typed: dict):
    """The allowed (lane, alpha) region of a wheel off the globe as data:
    ``deathsphere map --surface ... --format csv``; ``typed`` the keywords
    of :func:`deathsphere.region` as given.  One row per boundary point on
    each lane (``height`` [m] values or ``start:stop:step`` text, on flat
    ground ``turn_radius``; default: 361 lanes from the floor to the top):
    ``curve`` (S4 fit, S5 floor, S2 Omega^2 = 0 or pole, S3 contact, mu,
    max_g; with ``stability`` also ``stability``, where the exact
    linearisation's verdict changes), ``equation``, ``height_m``,
    ``alpha_deg`` and whether the orbit
    just below and just above it in alpha is feasible (``feasible_below``,
    ``feasible_above``), then the setup and the lane."""
    from deathsphere.results.lane_map import lane_boundary_table

    ground, heights, v, outside = _setup(typed)
    stability = _stability(typed)
    return lane_boundary_table(ground, heights, v["a"], v["k"], v["g"], outside, v["mu"], v["max_g"],
                               stability=stability, run=_run(typed, stability, heights.size))


def _stability(typed: dict) -> bool:
    from deathsphere.api.arguments import checked_flag

    value = typed.get("stability")
    return checked_flag("stability", False if value is None else value)


def _run(typed: dict, stability: bool, lanes: int):
    """Where the stability boundary's batches of lanes run, from ``typed``'s
    ``jobs``, ``scheduler`` and ``progress`` (``progress(done, total)`` in
    lanes), as the globe's map: a scheduler is connected now (a missing
    extra or an unreachable one fails before any work), only with stability."""
    from deathsphere.api.streams import cluster_of
    from deathsphere.results.lane_map import StabilityRun

    jobs = int(checked_scalar("jobs", 1 if typed.get("jobs") is None else typed["jobs"]))
    cluster = cluster_of(typed.get("scheduler"), jobs) if stability else None
    report, tick = typed.get("progress"), None
    if report is not None:
        done = [0]

        def tick(n):
            done[0] += n
            report(done[0], lanes)
    return StabilityRun(jobs=jobs, cluster=cluster, progress=tick)


def region_curves_on(typed: dict):
    """The allowed region off the globe as a figure's curves
    (:class:`deathsphere.results.lane_map.LaneCurves`): what ``deathsphere
    map --surface ... --output FILE`` draws; ``typed`` as for :func:`region_on`."""
    from deathsphere.results.lane_map import lane_curves

    ground, heights, v, outside = _setup(typed)
    stability = _stability(typed)
    return lane_curves(ground, heights, v["a"], v["k"], v["g"], outside, v["mu"], v["max_g"],
                       stability=stability, run=_run(typed, stability, heights.size))


__all__ = ["region_on", "region_curves_on", "MAX_LANES"]
