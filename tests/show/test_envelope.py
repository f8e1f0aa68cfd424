"""Segment distances against brute force over many points of each segment."""

import numpy as np

from deathsphere.act.envelope import point_segment_distance, segment_distance


def _brute(p0, p1, q0, q1, n=401):
    s = np.linspace(0, 1, n)
    a = p0[:, None] + s * (p1 - p0)[:, None]
    b = q0[:, None] + s * (q1 - q0)[:, None]
    return np.sqrt(((a[:, :, None] - b[:, None, :]) ** 2).sum(axis=0)).min()


def test_segment_distance_against_brute_force():
    rng = np.random.default_rng(4)
    p0, p1, q0, q1 = (rng.normal(size=(3, 20)) for _ in range(4))
    q1[:, 0] = q0[:, 0] + 2 * (p1[:, 0] - p0[:, 0])        # parallel segments
    q1[:, 1] = q0[:, 1]                                      # a point
    d, s, t = segment_distance(p0, p1, q0, q1)
    for i in range(20):
        brute = _brute(p0[:, i], p1[:, i], q0[:, i], q1[:, i])
        assert brute - 5e-3 <= d[i] <= brute + 1e-12
    assert np.all((s >= 0) & (s <= 1) & (t >= 0) & (t <= 1))


def test_crossing_segments_touch_and_points_project():
    d, _, _ = segment_distance(np.array([-1.0, 0, 0]), np.array([1.0, 0, 0]), np.array([0, -1.0, 0.5]),
                               np.array([0, 1.0, 0.5]))
    assert d == 0.5
    x = np.array([[0.5, 3.0], [2.0, 0.0], [0.0, 0.0]])
    assert np.allclose(point_segment_distance(x, np.zeros(3)[:, None], np.array([1.0, 0, 0])[:, None]), [2.0, 2.0])
