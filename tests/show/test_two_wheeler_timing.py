"""A show's two-wheeler rider in the timing: a pair's drift time and a
looper's phase search take his whole envelope (every segment), each
against brute force computed the long way."""

import math
from dataclasses import replace

import numpy as np
import pytest
from brute_segments import brute_distance

from deathsphere.act.lanes import build_lanes
from deathsphere.act.plan import read_plan
from deathsphere.act.timing import DRIFT_ERROR, drift_time, phase_clearances_each

R = 16 * 0.3048 / 2


def _plan(*riders):
    return {"globe": {"radius": R, "mu": 0.9, "max_g": 8}, "rider": list(riders)}


def _two_wheeler(**more):
    rider = {"name": "T", "machine": "stunt125-steer", "width": "0.5m", "lane": "horizontal", "height": "2.2m",
             "speed": "40km/h", **more}
    return {k: v for k, v in rider.items() if v is not None}


def test_the_drift_of_a_two_wheeler_and_a_machine_on_one_lap_against_brute_force_over_the_azimuth():
    # the machine rides the two-wheeler's lap 60 deg ahead of her rear contact, 0.5 m higher: they turn as one, and
    # her clock 1 % off slips her round at 1 % of her rate until some segment pair comes within 0.15 m
    t, m = build_lanes(read_plan(_plan(_two_wheeler(), {
        "name": "M", "lane": "horizontal", "height": "2.7m", "same_lap_as": "T", "phase": 60.0, "width": "0.5m"})))
    got = drift_time(t, m, 0.15)
    x = np.linspace(0.0, 2 * np.pi, 200001)
    pb = m.at_angle(np.full_like(x, m.phase))
    radii = 0.5 * (t.width_m + m.width_m)
    first = np.inf
    for sense in (1.0, -1.0):
        pa = t.at_angle(t.phase + sense * x)
        c = np.minimum.reduce([brute_distance(pa[a], pa[b], pb["contact"], pb["head"])
                               for a, b in t.segments]) - radii
        below = np.flatnonzero(c < 0.15)
        if below.size:
            first = min(first, x[below[0]])
    expect = first / (abs(t.rate) * DRIFT_ERROR)
    assert len(t.segments) > 1 and math.isfinite(expect)
    # to the azimuth grid's step and the search's 1 mm (its Lipschitz bound per radian: the lane's reach)
    step = (x[1] - x[0]) / (abs(t.rate) * DRIFT_ERROR)
    assert got == pytest.approx(expect, abs=2 * step + 1e-3 / (t.reach * abs(t.rate) * DRIFT_ERROR))


def test_a_loopers_phase_search_through_a_two_wheeler_takes_his_whole_envelope():
    from deathsphere.act.envelope import overlap_clearance
    from deathsphere.act.timing import PHASE_AXIS_POINTS

    plan = _plan(_two_wheeler(phase=-165.0),
                 {"name": "V", "lane": "vertical", "azimuth": 0, "v_top": "6.5m/s", "phase": 0, "width": "0.5m"})
    t, v = build_lanes(read_plan(plan))
    phases, least = phase_clearances_each(v, [t], v.period_s, steps=36)
    # each candidate phase's least over the same samples: the looper shifted to that phase, every segment of the
    # two-wheeler's envelope (a miss's distance the long way; an overlap's depth by the envelope's own measure)
    dt = v.period_s / 36
    times = np.arange(int(math.ceil(v.period_s / dt)) + 1) * dt
    radii = 0.5 * (t.width_m + v.width_m)
    ends = t.segment_ends(times)
    misses, wheels = 0, 0
    for k in range(36):
        q0, q1 = replace(v, phase=math.radians(phases[k])).ends(times)
        each = [overlap_clearance(p0, p1, q0, q1, radii, PHASE_AXIS_POINTS).min() for p0, p1 in ends]
        assert least[0, k] == pytest.approx(min(each), abs=1e-9)
        brute = min(float(np.min(brute_distance(p0, p1, q0, q1))) for p0, p1 in ends) - radii
        if brute > 0:
            assert least[0, k] == pytest.approx(brute, abs=1e-9)
            misses += 1
        wheels += min(each) < each[0] - 0.05           # a segment other than contact -> head comes closest
    assert misses >= 3 and wheels >= 3
