"""highest_orbit against the plain method it shortens: a scan of all 2048
thetas and one bisection step per feasibility test."""

import numpy as np
import pytest

from deathsphere.physics import region

A, R, K, G = 0.3, 3.0, 0.5, 9.80665


def plain_bracket(a, r, k, g, outside, mu, max_g, n_theta=2048, xtol=1e-11):
    def feasible(theta):
        return np.asarray(region.allowed_alpha(theta, a, r, k, g, outside, mu, max_g).count) > 0

    grid = (np.arange(n_theta) + 0.5) * (np.pi / n_theta)
    j = int(np.nonzero(feasible(grid))[0][0])
    lo, hi = (0.0 if j == 0 else float(grid[j - 1])), float(grid[j])
    while hi - lo > xtol:
        mid = 0.5 * (lo + hi)
        if feasible(mid):
            hi = mid
        else:
            lo = mid
    return lo, hi


@pytest.mark.parametrize("outside, mu, max_g", [(False, 1.0, 5.0), (False, np.inf, np.inf), (True, np.inf, np.inf)])
def test_same_bracket_as_a_full_scan_and_plain_bisection(outside, mu, max_g):
    h = region.highest_orbit(A, R, K, G, outside=outside, mu=mu, max_g=max_g)
    lo, hi = plain_bracket(A, R, K, G, outside, mu, max_g)
    assert h.theta_bracket == pytest.approx((lo, hi), abs=1e-13)
    assert h.theta == pytest.approx(0.5 * (lo + hi), abs=1e-13)
