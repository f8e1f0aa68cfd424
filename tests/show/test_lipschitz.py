"""The show's one branch and bound (deathsphere.act.lipschitz): no dip of a
Lipschitz function is missed, whatever the first samples miss."""

import math

import numpy as np

from deathsphere.act.lipschitz import SPLIT, refine_intervals
from deathsphere.act.pairs import refine
from deathsphere.act.timing import first_below


def _narrow_dip(x):
    """|slope| <= 41: a baseline of 1 with a 0.5 deep notch 0.02 wide at 0.7321."""
    return 1.0 + 0.05 * np.sin(3 * x) - np.maximum(0.0, 0.5 - 40.0 * np.abs(x - 0.7321))


def test_the_least_value_between_coarse_samples_is_found():
    x = np.linspace(0.0, 2.0, 11)                # 0.2 apart: the notch falls between samples
    c = _narrow_dip(x)
    assert c.min() > 0.9                         # the samples alone do not see it
    best, where = refine(_narrow_dip, x, c, 41.0, tol=1e-6)
    dense = np.linspace(0.0, 2.0, 2_000_001)
    assert abs(best - _narrow_dip(dense).min()) < 2e-6 and abs(where - 0.7321) < 1e-4


def test_the_first_time_below_a_level_is_found():
    hit = first_below(_narrow_dip, 0.0, 2.0, 41.0, level=0.8, tol=1e-9, first_step=2.0)
    # the notch reaches 0.8 where 40 |x - 0.7321| = 0.5 - (1.05ish - 0.8): just left of its centre
    dense = np.linspace(0.0, 2.0, 4_000_001)
    expected = dense[np.argmax(_narrow_dip(dense) < 0.8)]
    assert abs(hit - expected) < 1e-5
    assert math.isinf(first_below(_narrow_dip, 0.0, 2.0, 41.0, level=0.4, tol=1e-9))


def test_each_round_splits_the_kept_intervals():
    """Samples 0.5 apart on [0, 1]; keep what starts left of 0.25: the first
    round splits [0, 0.5] into SPLIT, the second the SPLIT/2 pieces left of 0.25."""
    x = np.linspace(0.0, 1.0, 3)
    rounds = []
    for inner, ci in refine_intervals(lambda t: np.zeros_like(t), x, np.zeros(3), 0.5, 1.0,
                                      lambda left, bound: (left < 0.25) & (bound < -1e-3)):
        rounds.append(inner)
        if len(rounds) == 2:
            break
    assert rounds[0].shape == (1, SPLIT - 1) and np.allclose(rounds[0][0], 0.5 / SPLIT * np.arange(1, SPLIT))
    assert rounds[1].shape == (SPLIT // 2, SPLIT - 1)
    # nothing kept: no round at all
    assert list(refine_intervals(np.sin, x, np.zeros(3), 0.5, 1.0, lambda left, bound: bound > 0)) == []
