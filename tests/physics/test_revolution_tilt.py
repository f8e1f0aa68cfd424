"""The wheel given its rate or speed on any ground (deathsphere.physics.revolution_tilt,
docs/surfaces.md S2): every root put back into eq. S2 written out here, every
sign change of S2 in the fit window of S4 (written out here) found, the
globe through the general path the globe's own solve, and a status with a
reason for every request without a root."""

import warnings

import numpy as np
import pytest

from deathsphere.physics import region
from deathsphere.physics.ground import Cone, Cylinder, Plane, Profile, Sphere
from deathsphere.physics.revolution_tilt import wheel_tilts
from deathsphere.physics.status import Reason, Status

G = 9.81
A, K = 0.3, 0.5
DRUM = Cylinder(4.8768, 6.0)
WELL = Cone(3.0, np.radians(80.0), 8.0)
BOARDS = Cone(10.0, np.radians(40.0), 6.0)
C_BOWL = 0.08                                  # the bowl z = c rho^2, sampled
_RHO = np.linspace(0.0, 12.0, 121)
BOWL = Profile(_RHO, C_BOWL * _RHO ** 2)


def _s2_rate_squared(rho, alpha):
    """Eq. S2 (eq. 29 with r' = rho - a cos(alpha)), written out."""
    rp = rho - A * np.cos(alpha)
    return G / np.tan(alpha) / ((2 * K + 1) * rp + K * A * np.cos(alpha))


def _lane(ground, height):
    rho, _ = ground.contact(np.asarray(height, dtype=float))
    n_rho, n_z = ground.normal(np.asarray(height, dtype=float))
    beta = np.arctan2(-np.asarray(n_rho, dtype=float), np.asarray(n_z, dtype=float))
    return float(rho), float(beta)


def _sign_changes(rho, beta, omega, outside):
    """Zeros of g cos(alpha) - Omega^2 sin(alpha) D on a fine scan of the tilts
    where the rim fits, a sin(beta)/rho < sin(alpha + beta) inside (S4,
    Meusnier), sin(alpha + beta) < 0 outside."""
    alpha = np.linspace(-np.pi - beta, np.pi - beta, 400_001)
    fits = np.sin(alpha + beta) < 0 if outside else A * np.sin(beta) / rho < np.sin(alpha + beta)
    d = (2 * K + 1) * (rho - A * np.cos(alpha)) + K * A * np.cos(alpha)
    f = G * np.cos(alpha) - omega ** 2 * np.sin(alpha) * d
    change = (np.sign(f[1:]) != np.sign(f[:-1])) & fits[1:] & fits[:-1]
    return alpha[1:][change]


CASES = [(DRUM, [0.5, 2.0, 5.0]), (WELL, [0.0, 3.0, 7.0]), (BOARDS, [1.0, 4.0]), (BOWL, [0.5, 3.0, 9.0]),
         (Plane(), [2.0, 10.0, 40.0])]


@pytest.mark.parametrize("ground, heights", CASES, ids=["drum", "well80", "boards40", "bowl", "plane"])
@pytest.mark.parametrize("omega", [0.6, 1.7, 3.0, 7.5])
@pytest.mark.parametrize("outside", [False, True], ids=["inside", "outside"])
def test_every_root_is_s2s_and_every_sign_change_is_a_root(ground, heights, omega, outside):
    res = wheel_tilts(ground, np.array(heights), A, K, G, omega=omega, outside=outside)
    for i, height in enumerate(heights):
        rho, beta = _lane(ground, height)
        roots = res["alpha"][i][np.isfinite(res["alpha"][i])]
        assert res["count"][i] == roots.size
        np.testing.assert_allclose(_s2_rate_squared(rho, roots), omega ** 2, rtol=1e-10)
        scanned = _sign_changes(rho, beta, omega, outside)
        assert roots.size == scanned.size, (height, roots, scanned)
        # the scan runs over one period from -pi - beta, the solve's window from pi - beta outside
        np.testing.assert_allclose(np.sort(np.mod(roots + beta + np.pi, 2 * np.pi)),
                                   np.sort(np.mod(scanned + beta + np.pi, 2 * np.pi)), atol=2e-5)
        if roots.size == 0:
            assert res["unsolved_status"][i] == Status.NO_ORBIT
            assert res["unsolved_reason"][i] == Reason.SURFACE_NO_ALPHA


def test_a_contact_speed_is_the_rate_round_the_lane_and_a_centre_speed_is_v_cm():
    heights = np.array([0.0, 3.0, 7.0])
    rho = np.array([_lane(WELL, h)[0] for h in heights])
    by_speed = wheel_tilts(WELL, heights, A, K, G, speed=11.0)
    by_rate = wheel_tilts(WELL, heights, A, K, G, omega=11.0 / rho)
    np.testing.assert_array_equal(by_speed["alpha"], by_rate["alpha"])
    by_period = wheel_tilts(WELL, heights, A, K, G, period=2 * np.pi * rho / 11.0)
    np.testing.assert_allclose(by_period["alpha"], by_rate["alpha"], rtol=1e-13)
    centre = wheel_tilts(WELL, heights, A, K, G, com_speed=9.0)
    for i in range(heights.size):
        roots = centre["alpha"][i][np.isfinite(centre["alpha"][i])]
        assert roots.size >= 1
        rp = rho[i] - A * np.cos(roots)
        np.testing.assert_allclose(np.abs(rp) * np.sqrt(_s2_rate_squared(rho[i], roots)), 9.0, rtol=1e-10)


@pytest.mark.parametrize("outside", [False, True])
def test_the_globe_through_the_general_path_is_the_globes_solve(outside):
    r = 3.0
    globe = Sphere(r)
    theta = np.radians(np.linspace(4.3, 175.3, 58))
    height = globe.height(theta)
    for target in ({"omega": 2.2}, {"omega": 6.0}, {"com_speed": 3.5}, {"speed": 4.0}):
        general = wheel_tilts(globe, height, A, K, G, outside=outside, mu=1.1, **target)
        if "speed" in target:   # the globe's contact speed: the rate round its parallel r sin(theta)
            reference = region.solve_alpha(theta, A, r, K, G, omega=target["speed"] / (r * np.sin(theta)),
                                           outside=outside, mu=1.1)
        else:
            key = "speed" if "com_speed" in target else "omega"
            reference = region.solve_alpha(theta, A, r, K, G, outside=outside, mu=1.1, **{key: list(target.values())[0]})
        np.testing.assert_array_equal(general["count"], reference["count"])
        m = int(np.max(reference["count"]))
        assert m >= 1
        got, want = general["alpha"][:, :m], reference["alpha"][:, :m]
        np.testing.assert_array_equal(np.isnan(got), np.isnan(want))
        fin = np.isfinite(want)
        assert np.max(np.abs(got[fin] - want[fin])) <= 1e-12
        np.testing.assert_array_equal(general["status"][:, :m][fin], reference["status"][:, :m][fin])


def test_requests_without_a_root_say_why_and_warn_nothing():
    needle = Cone(1.0, np.radians(100.0), 5.6)      # leaning in, nearly to its apex
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        off = wheel_tilts(DRUM, [7.0, -1.0, np.nan], A, K, G, omega=3.0)
        axis = wheel_tilts(BOWL, 0.0, A, K, G, speed=5.0)
        narrow = wheel_tilts(needle, 5.6, A, K, G, omega=3.0)
        slow = wheel_tilts(DRUM, 2.0, A, K, G, omega=0.05)
        bad = wheel_tilts(DRUM, 2.0, A, K, G, omega=[0.0, -1.0, np.inf, np.nan])
    assert np.all(off["count"] == 0) and np.all(off["unsolved_reason"] == Reason.LANE_OFF_WALL)
    assert np.all(off["unsolved_status"] == Status.NO_FIT) and np.all(np.isnan(off["lane"]["rho_contact"]))
    assert axis["count"] == 0 and axis["unsolved_reason"] == Reason.LANE_ON_AXIS
    # the contact 0.0125 m from the axis: the wall bends more than the rim at every tilt
    assert narrow["count"] == 0 and narrow["unsolved_reason"] == Reason.NO_TILT_FITS_LANE
    assert narrow["unsolved_status"] == Status.NO_FIT
    assert slow["count"] == 0 and slow["unsolved_reason"] == Reason.SURFACE_NO_ALPHA
    assert slow["lane"]["rho_contact"] == pytest.approx(DRUM.radius)
    assert np.all(bad["count"] == 0) and np.all(bad["unsolved_status"] == Status.NO_ORBIT)


def test_exactly_one_target():
    with pytest.raises(ValueError, match="exactly one"):
        wheel_tilts(DRUM, 2.0, A, K, G, omega=3.0, speed=4.0)
