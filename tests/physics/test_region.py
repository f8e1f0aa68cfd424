"""The allowed (theta, alpha) region, its boundaries, the highest orbit and
solve_alpha (deathsphere.physics.region), checked against the orbit
quantities of deathsphere.physics.wheel evaluated point by point and against
brute-force scans -- never against region.py's own polynomials."""

import math

import numpy as np
import pytest

from deathsphere.physics import region, wheel
from deathsphere.physics.geometry import r_prime
from deathsphere.physics.status import Status

G = 9.80665
A, R, K = 0.3, 3.0, 0.5            # Table 1's wheel and sphere (a/r = 0.1)
deg = np.deg2rad

# (a, r, k, outside, mu, max_g)
CONFIGS = [
    (0.3, 3.0, 0.5, False, np.inf, np.inf),
    (0.3, 3.0, 0.5, False, 1.0, 5.0),
    (0.9, 3.0, 0.25, False, 0.7, 3.0),
    (0.05, 3.0, 1.0, False, 2.0, np.inf),
    (0.3, 3.0, 0.5, True, np.inf, np.inf),
    (1.5, 3.0, 0.5, True, 0.8, 2.0),
]
IDS = ["table1", "table1-mu1-g5", "big-wheel", "small-wheel", "outside", "outside-big-limits"]

THETA = deg(np.linspace(0.5, 179.5, 120))
EPS = 1e-9


def _physical(theta, alpha, a, r, k, outside):
    """Quantities at (theta, alpha) straight from wheel.py / geometry.py."""
    om2 = wheel.omega_squared(theta, alpha, a, r, k, G)
    rp = r_prime(theta, alpha, a, r)
    f_r, f_theta = wheel.contact_force_spherical(theta, rp, om2, G)
    normal = f_r if outside else -f_r
    fit = np.sin(alpha - theta) if outside else np.sin(theta - alpha) - a / r
    with np.errstate(divide="ignore", invalid="ignore"):
        mu_req = np.abs(f_theta) / normal
    return {"fit": fit, "om2": om2, "normal": normal, "mu": mu_req,
            "g": np.abs(wheel.centre_accel_g(theta, alpha, a, r, k)),   # keeps the sign of r'
            # what the rider feels: |F|/(m g) with F/m = g z-hat - r' Omega^2 r'-hat (eq. 32)
            "load": np.hypot(1.0, wheel.centre_accel_g(theta, alpha, a, r, k))}


def _load(orb):
    """The load |F| / (m g) of horizontal_orbit's rows, from the centre's
    acceleration in g (eq. 36) and gravity, orthogonal to it (eq. 32)."""
    return np.hypot(1.0, orb["accel_g"])


def _brackets_sign_change(theta, roots, fun, tol=EPS):
    """fun(theta, alpha) changes sign between alpha -+ tol at every root."""
    th = np.broadcast_to(theta[:, None], roots.shape)
    ok = np.isfinite(roots)
    left = fun(th[ok], roots[ok] - tol)
    right = fun(th[ok], roots[ok] + tol)
    return left, right


@pytest.mark.parametrize("a, r, k, outside, mu, max_g", CONFIGS, ids=IDS)
def test_boundaries_satisfy_their_equations(a, r, k, outside, mu, max_g):
    b = region.boundary_alphas(THETA, a, r, k, outside=outside, mu=mu, max_g=max_g)
    assert set(b) >= {"eq0", "eq29", "eq33"}
    phys = lambda key: (lambda t, al: _physical(t, al, a, r, k, outside)[key])  # noqa: E731

    left, right = _brackets_sign_change(THETA, b["eq0"], phys("fit"))
    assert left.size >= THETA.size and np.all(left * right < 0)

    # eq. (29): Omega^2 changes sign (through zero or through a pole)
    left, right = _brackets_sign_change(THETA, b["eq29"], phys("om2"))
    assert left.size >= 2 * THETA.size and np.all(left * right < 0)

    # eq. (33)/(83): the normal force changes sign where Omega^2 is finite
    left, right = _brackets_sign_change(THETA, b["eq33"], phys("normal"))
    assert left.size >= THETA.size and np.all(left * right < 0)

    if np.isfinite(mu):
        m = lambda t, al: phys("mu")(t, al) - mu  # noqa: E731
        left, right = _brackets_sign_change(THETA, b["mu"], m)
        assert left.size > 10 and np.all(left * right < 0)
    if np.isfinite(max_g):
        gl = lambda t, al: phys("load")(t, al) - max_g  # noqa: E731
        left, right = _brackets_sign_change(THETA, b["max_g"], gl)
        assert left.size > 10 and np.all(left * right < 0)


@pytest.mark.parametrize("outside", [False, True])
def test_boundaries_none_missed_against_dense_scan(outside):
    """Every sign change of the physical functions on a 20 000-point alpha
    scan lies within one scan step of a reported boundary root."""
    a, r, k, mu, max_g = 0.3, 3.0, 0.5, 1.0, 5.0
    theta = deg(np.array([3.0, 10.0, 33.0, 60.0, 89.0, 120.0, 150.0, 176.0, 178.5]))
    b = region.boundary_alphas(theta, a, r, k, outside=outside, mu=mu, max_g=max_g)
    lo, hi = region.alpha_window(theta, outside)
    al = lo[:, None] + (hi - lo)[:, None] * np.linspace(1e-6, 1 - 1e-6, 20001)[None, :]
    step = (hi - lo)[0] / 20000
    ph = _physical(theta[:, None], al, a, r, k, outside)
    real = np.isfinite(ph["om2"]) & (ph["om2"] > 0)
    checks = {
        "eq0": ph["fit"],
        "eq33": np.where(real, ph["normal"], np.nan),
        "mu": np.where(real & (ph["normal"] > 0), ph["mu"] - mu, np.nan),
        "max_g": np.where(real & (ph["normal"] > 0), ph["load"] - max_g, np.nan),
    }
    for name, val in checks.items():
        for i in range(theta.size):
            v = val[i]
            change = np.nonzero(np.isfinite(v[:-1]) & np.isfinite(v[1:]) & (v[:-1] * v[1:] < 0))[0]
            roots = b[name][i][np.isfinite(b[name][i])]
            for j in change:
                mid = 0.5 * (al[i, j] + al[i, j + 1])
                assert roots.size and np.min(np.abs(roots - mid)) <= step, (name, i, j)


def _intervals_match_feasibility(a, r, k, outside, mu, max_g, theta, n_alpha):
    iv = region.allowed_alpha(theta, a, r, k, G, outside=outside, mu=mu, max_g=max_g)
    lo, hi = region.fit_interval(theta, a, r, outside)
    al = lo[:, None] + (hi - lo)[:, None] * np.linspace(0, 1, n_alpha)[None, :]
    orb = wheel.horizontal_orbit(theta[:, None], al, a, r, k, G, outside, mu)
    ok = orb["status"] == Status.OK
    if np.isfinite(max_g):
        ok &= _load(orb) <= max_g
    inside = iv.contains(al)
    # points within EPS of an interval end are ambiguous (the end is a boundary)
    ends = np.concatenate([iv.lo, iv.hi], axis=-1)
    with np.errstate(invalid="ignore"):
        near = np.any(np.abs(al[..., None] - ends[:, None, :]) < 1e-7, axis=-1)
    near |= np.abs(al - lo[:, None]) < 1e-7
    near |= np.abs(al - hi[:, None]) < 1e-7
    assert np.array_equal(inside[~near], ok[~near])
    return iv, ok


@pytest.mark.parametrize("a, r, k, outside, mu, max_g", CONFIGS, ids=IDS)
def test_intervals_contain_exactly_the_feasible_points(a, r, k, outside, mu, max_g):
    iv, ok = _intervals_match_feasibility(a, r, k, outside, mu, max_g, THETA, 3001)
    assert ok.any()                      # the comparison is not vacuous
    assert np.all(np.diff(iv.lo, axis=-1)[np.isfinite(np.diff(iv.lo, axis=-1))] > 0)
    assert np.all((iv.hi > iv.lo)[np.isfinite(iv.lo)])


def test_intervals_near_the_poles_and_folds():
    """The thin feasible slivers near theta = 180 deg (eqs. 29 and 33 almost
    coincide there) and near the fit corner at theta = asin(a/r)."""
    theta = deg(np.concatenate([np.linspace(5.6, 7.0, 30), np.linspace(174.0, 179.99, 60)]))
    iv, ok = _intervals_match_feasibility(A, R, K, False, np.inf, np.inf, theta, 20001)
    assert ok.any()


def test_paper_inside_orbits_need_0_lt_alpha_lt_90():
    """Sec. 2.2.2: 'steady horizontal orbits are possible only for
    0 < alpha < pi/2' -- whatever a/r and k."""
    for a, k in [(0.3, 0.5), (2.0, 0.25), (2.9, 1.0), (0.01, 0.0)]:
        iv = region.allowed_alpha(THETA, a, 3.0, k, G)
        f = np.isfinite(iv.lo)
        assert f.any()
        assert np.all(iv.lo[f] >= -1e-12) and np.all(iv.hi[f] <= np.pi / 2 + 1e-12)


TABLE1 = [  # theta, alpha (deg), v_cm (m/s) -- McDonald (1993) Table 1
    (15, 5, 4.8), (30, 5, 8.0), (45, 10, 7.0), (60, 10, 7.9), (60, 25, 4.9),
    (75, 15, 6.8), (75, 30, 4.7), (90, 25, 5.3), (90, 45, 3.7), (135, 60, 2.3),
]


def test_table1_orbits_are_inside_the_region_and_speed_range():
    th = deg(np.array([t[0] for t in TABLE1], dtype=float))
    al = deg(np.array([t[1] for t in TABLE1], dtype=float))
    iv = region.allowed_alpha(th, A, R, K, G)
    assert np.all(iv.contains(al))
    v = wheel.horizontal_orbit(th, al, A, R, K, G)["v_cm"]
    j = np.argmax((al[:, None] > iv.lo) & (al[:, None] < iv.hi), axis=1)
    rows = np.arange(th.size)
    assert np.all(iv.speed_min[rows, j] <= v) and np.all(v <= iv.speed_max[rows, j])


@pytest.mark.parametrize("a, r, k, outside, mu, max_g", CONFIGS[:4], ids=IDS[:4])
def test_speed_range_against_dense_sampling(a, r, k, outside, mu, max_g):
    theta = deg(np.array([8.0, 20.0, 45.0, 70.0, 100.0, 150.0, 177.0]))
    iv = region.allowed_alpha(theta, a, r, k, G, outside=outside, mu=mu, max_g=max_g)
    for i in range(theta.size):
        for lo, hi, vmin, vmax in iv.intervals(i):
            ends = (hi - lo) * np.logspace(-9, -2, 36)
            al = np.concatenate([lo + ends, np.linspace(lo, hi, 20001)[1:-1], hi - ends])
            v = wheel.horizontal_orbit(theta[i], al, a, r, k, G, outside)["v_cm"]
            assert np.all(np.isfinite(v))
            assert vmin <= v.min() * (1 + 1e-9) and v.max() <= vmax * (1 + 1e-9)
            assert v.min() <= vmin * 1.01 + 1e-3          # the bound is the infimum
            if np.isfinite(vmax):
                assert v.max() >= vmax * 0.99
            else:
                assert v.max() > 50 * v.min() or v.max() > 100.0


def test_scalar_theta_and_list_of_intervals():
    iv = region.allowed_alpha(deg(60.0), A, R, K, G)
    assert iv.lo.shape == (1,) and iv.count.shape == ()
    (lo, hi, vmin, vmax), = iv.intervals()
    assert lo == pytest.approx(0.0, abs=1e-12)
    assert hi == pytest.approx(deg(40.2173), abs=1e-5)      # contact, eq. (33)
    assert vmax == np.inf and 3.0 < vmin < 4.0


# --------------------------------------------------------------------------
# solve_alpha


def _speed_poly(theta, alpha, a, r, k, v):
    """g r'^2 cos(alpha) - v^2 (denominator of eq. 29): zero where v_cm = v."""
    rp = r_prime(theta, alpha, a, r)
    return G * rp ** 2 * np.cos(alpha) - v ** 2 * wheel.omega_squared_denominator(theta, alpha, a, r, k)


@pytest.mark.parametrize("outside", [False, True])
def test_solve_alpha_finds_every_speed_root(outside):
    rng = np.random.default_rng(5)
    a, r, k = 0.3, 3.0, 0.5
    theta = deg(rng.uniform(1.0, 179.0, 40))
    speed = rng.uniform(0.05, 12.0, 40)
    sol = region.solve_alpha(theta, a, r, k, G, speed=speed, outside=outside, alpha_range=(-np.pi, np.pi))
    assert sol["alpha"].shape[:1] == (40,)
    total = 0
    al = np.linspace(-np.pi, np.pi, 400001)
    for i in range(theta.size):
        f = _speed_poly(theta[i], al, a, r, k, speed[i])
        n_changes = int(np.sum(f[:-1] * f[1:] < 0))
        roots = sol["alpha"][i][np.isfinite(sol["alpha"][i])]
        assert roots.size == n_changes == sol["count"][i]
        total += roots.size
        real = np.isfinite(sol["omega2"][i][: roots.size])
        assert np.allclose(sol["v_cm"][i][: roots.size][real], speed[i], rtol=1e-9)
    assert total > 40


def test_solve_alpha_default_range_is_the_fit_interval_and_statuses():
    th = deg(np.array([15.0, 30.0, 60.0, 90.0, 135.0]))
    sol = region.solve_alpha(th, A, R, K, G, speed=4.8)
    lo, hi = region.fit_interval(th, A, R)
    f = np.isfinite(sol["alpha"])
    assert np.all((sol["alpha"] > lo[:, None])[f]) and np.all((sol["alpha"] < hi[:, None])[f])
    assert np.all(sol["status"][~f] == Status.INVALID)
    ok = sol["status"] == Status.OK
    # Table 1: theta = 15 deg, v = 4.8 m/s at alpha = 5 deg
    assert np.rad2deg(sol["alpha"][0][ok[0]]) == pytest.approx([5.0], abs=0.05)
    # each root's status is what horizontal_orbit says there
    orb = wheel.horizontal_orbit(th[:, None], np.where(f, sol["alpha"], 0.0), A, R, K, G)
    assert np.array_equal(orb["status"][f], sol["status"][f])
    # with a friction limit the same roots may slip
    slip = region.solve_alpha(th, A, R, K, G, speed=4.8, mu=1.0)
    assert np.any(slip["status"] == Status.SLIPS)


def test_solve_alpha_by_rotation_rate():
    rng = np.random.default_rng(7)
    theta = deg(rng.uniform(1.0, 179.0, 30))
    omega = rng.uniform(0.2, 8.0, 30)
    sol = region.solve_alpha(theta, A, R, K, G, omega=omega, alpha_range=(-np.pi, np.pi))
    al = np.linspace(-np.pi, np.pi, 200001)
    for i in range(theta.size):
        f = G * np.cos(al) - omega[i] ** 2 * wheel.omega_squared_denominator(theta[i], al, A, R, K)
        roots = sol["alpha"][i][np.isfinite(sol["alpha"][i])]
        assert roots.size == int(np.sum(f[:-1] * f[1:] < 0))
        assert np.allclose(sol["omega"][i][: roots.size], omega[i], rtol=1e-9)


def test_solve_alpha_rejects_bad_requests():
    with pytest.raises(ValueError, match="exactly one"):
        region.solve_alpha(1.0, A, R, K, G)
    with pytest.raises(ValueError, match="exactly one"):
        region.solve_alpha(1.0, A, R, K, G, speed=1.0, omega=1.0)
    with pytest.raises(ValueError, match="> 0"):
        region.solve_alpha(1.0, A, R, K, G, speed=0.0)
    with pytest.raises(ValueError, match="r > a"):
        region.allowed_alpha(1.0, 3.0, 3.0, K, G)
    with pytest.raises(ValueError, match="mu"):
        region.allowed_alpha(1.0, A, R, K, G, mu=-1.0)


# --------------------------------------------------------------------------
# the highest orbit


def _brute_force_highest(a, r, k, mu, max_g, near, outside=False):
    """Smallest theta of a feasible point, by brute force: a coarse grid
    (0.5 deg x 0.1 deg, every alpha) below ``near`` - 5 deg, and a fine one
    (0.05 deg x 0.01 deg, 0 < alpha < 90 deg) from there to ``near`` + 0.5 deg."""
    def first(th, al):
        orb = wheel.horizontal_orbit(th[:, None], al[None, :], a, r, k, G, outside, mu)
        ok = (orb["status"] == Status.OK) & (_load(orb) <= max_g)
        rows = np.nonzero(ok.any(axis=1))[0]
        return th[rows[0]] if rows.size else np.inf
    start = np.rad2deg(near) - 5.0
    coarse = first(deg(np.arange(0.25, start, 0.5)), deg(np.arange(-180.0, 180.0, 0.1)))
    fine = first(deg(np.arange(start, start + 5.5, 0.05)), deg(np.arange(0.005, 90.0, 0.01)))
    return min(coarse, fine)


@pytest.mark.parametrize("mu, max_g", [(1.0, 5.0), (2.0, 10.0), (np.inf, 3.0)])
def test_highest_orbit_closed_form_and_brute_force(mu, max_g):
    """docs/limits.md: with a load limit L and friction mu the highest orbit
    is theta* = pi/2 + atan(1/G) - atan(mu), where r' Omega^2 = G g and the
    load sqrt(1 + G^2) = L (the contact force leans in from the horizontal
    by psi, tan psi = 1/G, and its size is m g / sin psi)."""
    h = region.highest_orbit(A, R, K, G, mu=mu, max_g=max_g)
    assert h.found
    accel = math.sqrt(max_g ** 2 - 1)
    expected = np.pi / 2 + math.atan(1 / accel) - math.atan(mu)
    assert h.theta == pytest.approx(expected, abs=1e-9)
    if mu != 2.0:
        brute = _brute_force_highest(A, R, K, mu, max_g, h.theta)
        assert h.theta - 1e-9 <= brute <= h.theta + deg(0.5)
    # the limiting orbit runs at the load limit, on the friction limit
    orb = wheel.horizontal_orbit(h.theta_bracket[1], h.alpha, A, R, K, G)
    assert _load(orb) == pytest.approx(max_g, rel=1e-6) and orb["load_g"] == pytest.approx(max_g, rel=1e-6)
    if np.isfinite(mu):
        assert orb["mu_required"] == pytest.approx(mu, rel=1e-6)
    assert h.speed == pytest.approx(np.sqrt(accel * G * abs(orb["r_prime"])), rel=1e-6)
    assert h.speed == pytest.approx(orb["v_cm"], rel=1e-6)


def test_highest_orbit_friction_only_needs_infinite_speed():
    h = region.highest_orbit(A, R, K, G, mu=1.0)
    assert h.theta == pytest.approx(np.pi / 4, abs=1e-9)      # mu >= cot(theta) as alpha -> 0
    assert h.alpha == pytest.approx(0.0, abs=1e-8) and h.speed == np.inf
    brute = _brute_force_highest(A, R, K, 1.0, np.inf, h.theta)
    assert h.theta <= brute <= h.theta + deg(0.5)


def test_highest_orbit_unlimited_is_the_fit_corner():
    h = region.highest_orbit(A, R, K, G)
    assert h.theta == pytest.approx(math.asin(A / R), abs=1e-9)
    assert h.alpha == pytest.approx(0.0, abs=1e-8)


def test_highest_orbit_outside_is_the_top_and_none_when_impossible():
    h = region.highest_orbit(A, R, K, G, outside=True)
    assert h.found and h.theta < 1e-9
    assert h.alpha == pytest.approx(np.pi / 2, abs=1e-6)        # a wheel standing on the top
    none = region.highest_orbit(A, R, K, G, mu=0.0)
    assert not none.found and math.isnan(none.theta)
