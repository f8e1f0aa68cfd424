"""The depth of an overlap (docs/show.md, "The depth of an overlap"): a
graze reads a small negative clearance, two riders in one place a large
one, against constructions computed here point by point."""

import math

import numpy as np
import pytest

import deathsphere
from deathsphere.act.envelope import overlap_clearance

R = 16 * 0.3048 / 2
WIDTH = 0.6


def _brute_clearance(p0, p1, q0, q1, radii, n=1201):
    """The clearance the long way, for one configuration: both axes as n
    points, their least distance d over all point pairs, and the overlap
    across (radii less each point's distance to the other axis's points)
    summed along each axis by the midpoint rule."""
    s = (np.arange(n) + 0.5) / n
    a = p0[:, None] + np.outer(p1 - p0, s)
    b = q0[:, None] + np.outer(q1 - q0, s)
    dist = np.linalg.norm(a[:, :, None] - b[:, None, :], axis=0)                  # (n, n)
    d = dist.min()
    if d >= radii:
        return d - radii
    along = [np.linalg.norm(p1 - p0) * np.maximum(0, radii - dist.min(axis=1)).mean(),
             np.linalg.norm(q1 - q0) * np.maximum(0, radii - dist.min(axis=0)).mean()]
    return d - radii - 0.5 * sum(along) / radii


@pytest.mark.parametrize("case", ["crossing", "tip", "coincident", "side_by_side", "apart"])
def test_the_clearance_of_two_capsules_against_the_long_way(case):
    L, radii = 1.6, 0.6
    z = np.zeros(3)
    p0, p1 = np.array([-L / 2, 0, 0]), np.array([L / 2, 0, 0])
    q0, q1 = {"crossing": (np.array([0, -L / 2, 0]), np.array([0, L / 2, 0])),
              "tip": (np.array([L / 2, 0, 0]), np.array([L / 2, L, 0])),
              "coincident": (p0, p1),
              "side_by_side": (p0 + [0, 0.5, 0], p1 + [0, 0.5, 0]),
              "apart": (p0 + [0, 0.7, 0], p1 + [0, 0.7, 0])}[case]
    got = float(overlap_clearance(p0, p1, q0, q1, radii))
    # closed forms: the overlap across is radii - |x| either side of a crossing, radii - d along side by side
    closed = {"crossing": -radii - radii, "tip": -radii - radii / 2, "coincident": -radii - L,
              "side_by_side": 0.5 - radii - L * (radii - 0.5) / radii, "apart": 0.7 - radii}[case]
    assert got == pytest.approx(closed, abs=1e-3)
    assert got == pytest.approx(_brute_clearance(p0, p1, q0 + z, q1 + z, radii), abs=2e-3)


def _looper(name, azimuth, phase):
    return {"name": name, "lane": "vertical", "azimuth": azimuth, "v_top": "6.5m/s", "phase": phase,
            "width": f"{WIDTH}m"}


def _act(*riders):
    return deathsphere.show({"globe": {"radius": R, "mu": 0.9, "max_g": 8, "min_clearance": "0.15m"},
                             "rider": list(riders)})


def test_a_head_on_reads_the_riders_length_deeper_than_their_width():
    # two loopers in crossing planes, both at the top at t = 0: the two envelopes are one
    act = _act(_looper("A", 0, 0), _looper("B", 90, 0))
    at = act.positions([0.0])
    length = float(np.linalg.norm(at["A"]["head"][:, 0] - at["A"]["contact"][:, 0]))
    assert np.allclose(at["A"]["head"], at["B"]["head"]) and np.allclose(at["A"]["contact"], at["B"]["contact"])
    row = act.pairs[0]
    assert row["verdict"] == "collision"
    assert row["min_clearance_m"] == pytest.approx(-WIDTH - length, abs=2e-3)
    assert row["t_s"] == pytest.approx(0.0, abs=1e-3)


def test_a_graze_reads_a_little_below_zero():
    # two loopers one behind the other in one plane, straddling the top at t = 0 (where they are slowest,
    # so closest): their heads are WIDTH - 0.02 apart then, their axes meet nowhere
    lane = _act(_looper("A", 0, 0)).lanes[0]
    head = lane.points["head"]
    half = math.degrees(math.asin((WIDTH - 0.02) / (2 * head)))
    act = _act(_looper("A", 0, 360 - half), _looper("B", 0, half))
    at = act.positions([0.0])
    a, b = at["A"], at["B"]
    assert np.linalg.norm(a["head"][:, 0] - b["head"][:, 0]) == pytest.approx(WIDTH - 0.02, abs=1e-9)
    expect = _brute_clearance(a["contact"][:, 0], a["head"][:, 0], b["contact"][:, 0], b["head"][:, 0], WIDTH)
    row = act.pairs[0]
    assert -0.03 < expect < -0.02
    assert row["verdict"] == "collision"
    assert row["min_clearance_m"] == pytest.approx(expect, abs=1e-3)
