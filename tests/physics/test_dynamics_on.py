"""The equations of motion on any ground (physics/dynamics_on.py) and their
exact linear stability (physics/stability/on_ground.py): the sphere's closed
forms reproduced by the general path, steady orbits as fixed points on the
drum and the cones, energy and contact held along the integrator, and the
golfer's dilemma (a ball in a vertical drum bobs at Omega sqrt(k/(k+1)),
derived in docs/dynamics.md eq. G9 independently of the code)."""

import numpy as np
import pytest

from deathsphere.physics import dynamics as dyn
from deathsphere.physics import dynamics_on as don
from deathsphere.physics.ground import Cone, Cylinder, Profile, Sphere
from deathsphere.physics.stability import sphere_stability, wheel_stability
from deathsphere.physics.stability.on_ground import ball_stability_on, wheel_stability_on

R, A, G = 3.0, 0.3, 9.81
GROUNDS = [Cylinder(5.0), Cone(5.0, np.radians(80)), Cone(5.0, np.radians(100))]


def _random_states(ball, n=60, seed=1):
    rng = np.random.default_rng(seed)
    k = rng.uniform(0.3, 1.0, n)
    X, _ = dyn.wheel_orbit_state(rng.uniform(0.5, 2.6, n), rng.uniform(0.2, 1.3, n), A, R, k, G)
    return X + rng.normal(0.0, 0.05, X.shape), k, rng


@pytest.mark.parametrize("outside", [False, True], ids=["inside", "outside"])
@pytest.mark.parametrize("ball", [False, True])
def test_general_path_on_the_sphere_is_the_closed_form(ball, outside):
    X, k, rng = _random_states(ball)
    closed = dyn.body_params(A, R, k, G, outside=outside, sphere=ball)
    general = don.ground_body(Sphere(R), A, k, G, sphere=ball, outside=outside)
    f0 = dyn.rhs(X, closed, 0.7)
    assert np.max(np.abs(don.rhs_on(X, general, 0.7) - f0)) <= 1e-12 * np.max(np.abs(f0))
    V = rng.normal(size=(9, 4, X.shape[1]))
    j0 = dyn.jvp(X, V, closed, 0.7)
    assert np.max(np.abs(don.jvp_on(X, V, general, 0.7) - j0)) <= 1e-12 * np.max(np.abs(j0))
    e0 = dyn.energy(X, closed)
    assert np.max(np.abs(don.energy_on(X, general) - e0)) <= 1e-12 * np.max(np.abs(e0))
    F0, F1 = dyn.contact_force(X, closed), don.contact_force_on(X, general)
    scale = np.max(np.abs(F0["force"]))
    assert np.max(np.abs(F1["force"] - F0["force"])) <= 1e-12 * scale
    assert np.max(np.abs(F1["normal"] - F0["normal"])) <= 1e-12 * scale


@pytest.mark.parametrize("ground", GROUNDS, ids=["drum", "cone80", "cone100"])
def test_steady_orbits_are_fixed_points_on_any_ground(ground):
    X, om = don.wheel_orbit_state_on(ground, 2.0, np.radians(20), A, 0.5, G)
    p = don.ground_body(ground, A, 0.5, G)
    scale = np.max(np.abs(X[6:9])) * om
    assert np.max(np.abs(don.rhs_on(X, p, om))) < 1e-13 * scale
    # the same state with Omega off by 1e-6 is not one (eq. 29 is tested)
    X2, _ = don.wheel_state_at(*ground.contact(2.0), np.radians(20), A, 0.5, G)
    assert np.max(np.abs(don.rhs_on(X2, p, om * (1 + 1e-6)))) > 1e-8 * scale
    assert abs(don.gap_on(X, p)) < 1e-12
    Xb, _ = don.ball_orbit_state_on(ground, 2.0, 4.0, A, 0.4, G)
    pb = don.ground_body(ground, A, 0.4, G, sphere=True)
    rates = don.rhs_on(Xb, pb, 4.0)
    # the ball's marker rows turn with the ball; centre and spin stand still
    assert np.max(np.abs(rates[[0, 1, 2, 6, 7, 8]])) < 1e-13 * np.max(np.abs(Xb[6:9])) * 4.0
    assert abs(don.gap_on(Xb, pb)) < 1e-12


def test_stability_on_the_sphere_is_todays():
    S = Sphere(5.0)
    th, al = np.array([1.2, 1.6, 2.0, 1.0]), np.array([0.6, 0.9, 1.2, 0.4])
    k = np.array([0.5, 1.0, 0.5, 0.3])
    ref = wheel_stability(th, al, A, 5.0, k, G)
    got = wheel_stability_on(S, S.height(th), al, A, k, G)
    diff = np.sort_complex(got["eigenvalues"]) - np.sort_complex(ref["eigenvalues"])
    assert np.max(np.abs(diff)) < 1e-10 * np.max(ref["rate_scale"])
    assert np.array_equal(got["verdict"], ref["verdict"])
    om = np.array([3.0, 4.0, 5.0, 6.0])
    ref = sphere_stability(th, om, A, 5.0, k, G)
    got = ball_stability_on(S, S.height(th), om, A, k, G)
    diff = np.sort_complex(got["eigenvalues"]) - np.sort_complex(ref["eigenvalues"])
    assert np.max(np.abs(diff)) < 1e-10 * np.max(ref["rate_scale"])


@pytest.mark.parametrize("k", [0.4, 2.0 / 3.0])
def test_golfers_dilemma_linearisation(k):
    om = np.array([3.0, 6.0, 11.0])
    out = ball_stability_on(Cylinder(5.0), 2.0, om, A, k, G)
    # eq. G9: the bobbing frequency Omega sqrt(k/(k+1)), independent of a and the drum
    assert np.allclose(out["freq_fast"], om * np.sqrt(k / (k + 1)), rtol=1e-10, atol=0)
    assert np.all(np.abs(out["eigenvalues"].real) < 1e-10 * out["rate_scale"][:, None])


# ---------------------------------------------------------------- the outside

HILL = Cone(6.0, np.radians(120))         # a cone leaning in, ridden on its outside: a conical hill
_DOME_THETA = np.radians(np.linspace(80.0, 20.0, 241))
DOME = Profile(5.0 * np.sin(_DOME_THETA), 5.0 * np.cos(_DOME_THETA))    # a globe's cap, sampled


def test_stability_outside_the_sphere_through_the_general_path_is_the_globes():
    S = Sphere(5.0)
    th = np.array([0.6, 1.0, 1.4, 1.2, 0.9])
    al = th + np.array([0.5, 1.0, 1.5, 2.5, 0.3])       # in eq. (81)'s window theta < alpha < theta + pi
    k = np.array([0.5, 1.0, 0.5, 0.3, 0.5])
    ref = wheel_stability(th, al, A, 5.0, k, G, outside=True)
    got = wheel_stability_on(S, S.height(th), al, A, k, G, outside=True)
    live = np.isfinite(ref["growth_rate"])
    assert live.sum() >= 3 and set(ref["verdict"][live]) >= {0, 1}      # stable and unstable among them
    np.testing.assert_array_equal(got["verdict"], ref["verdict"])
    diff = np.sort_complex(got["eigenvalues"][live]) - np.sort_complex(ref["eigenvalues"][live])
    assert np.max(np.abs(diff)) < 1e-12 * np.max(ref["rate_scale"][live])
    om = np.array([3.0, 4.0, 5.0, 6.0, 2.0])
    ref = sphere_stability(th, om, A, 5.0, k, G, outside=True)
    got = ball_stability_on(S, S.height(th), om, A, k, G, outside=True)
    live = np.isfinite(ref["growth_rate"])
    assert live.sum() >= 3
    diff = np.sort_complex(got["eigenvalues"][live]) - np.sort_complex(ref["eigenvalues"][live])
    assert np.max(np.abs(diff)) < 1e-12 * np.max(ref["rate_scale"][live])


def _finite_difference_spectrum(p, X0, om, step=1e-6):
    """Eigenvalues of the 9 x 9 Jacobian of the flow in the frame turning at
    Omega (:func:`dynamics_on.ode_on`), by central differences of the
    state: no dual numbers, no constraint reduction, no integration."""
    f = don.ode_on(p, om)
    J = np.empty((9, 9))
    for j in range(9):
        d = np.zeros(9)
        d[j] = step * max(1.0, abs(X0[j]))
        J[:, j] = (f(0.0, X0 + d) - f(0.0, X0 - d)) / (2 * d[j])
    return np.linalg.eigvals(J)


def _contained(reduced, full, tol):
    """Every reduced eigenvalue is one of the full Jacobian's."""
    return all(np.min(np.abs(full - ev)) < tol for ev in reduced)


@pytest.mark.parametrize("ground, height", [(HILL, 2.0), (DOME, 1.5)], ids=["hill120", "dome"])
def test_stability_outside_agrees_with_finite_differences_of_the_flow(ground, height):
    from deathsphere.physics.revolution import ball_orbit_from_rate, wheel_orbit

    tilts = np.radians([65.0, 75.0, 85.0]) if ground is HILL else np.radians([65.0, 80.0, 230.0])
    checked = 0
    for alpha in tilts:
        if wheel_orbit(ground, height, alpha, A, 0.5, G, outside=True)["status"] != 0:
            continue
        X0, om = don.wheel_orbit_state_on(ground, height, alpha, A, 0.5, G)
        p = don.ground_body(ground, A, 0.5, G, outside=True)
        assert np.max(np.abs(don.rhs_on(X0, p, om))) < 1e-12 * np.max(np.abs(X0[6:9])) * om   # a fixed point
        st = wheel_stability_on(ground, height, alpha, A, 0.5, G, outside=True)
        full = _finite_difference_spectrum(p, X0, float(om))
        assert _contained(st["eigenvalues"].ravel(), full, 1e-6 * float(st["rate_scale"]))
        checked += 1
    assert checked >= 2
    om = 1.0
    assert ball_orbit_from_rate(ground, height, om, A, 0.4, G, outside=True)["status"] == 0
    X0, _ = don.ball_orbit_state_on(ground, height, om, A, 0.4, G, outside=True)
    p = don.ground_body(ground, A, 0.4, G, sphere=True, outside=True)
    st = ball_stability_on(ground, height, om, A, 0.4, G, outside=True)
    # the full Jacobian also turns the ball's marker rows: its pair is extra
    assert _contained(st["eigenvalues"].ravel(), _finite_difference_spectrum(p, X0, om), 1e-6 * float(st["rate_scale"]))


def test_the_dome_sampled_outside_is_the_globes_outside():
    """A globe's cap sampled at 241 points: its outside's stability through
    the profile is the globe's closed-form outside to the sampling's error."""
    S = Sphere(5.0)
    th = np.radians([40.0, 55.0, 70.0])
    al = th + np.radians([30.0, 60.0, 150.0])
    ref = wheel_stability(th, al, A, 5.0, 0.5, G, outside=True)
    got = wheel_stability_on(DOME, 5.0 * np.cos(th) - DOME.lowest, al, A, 0.5, G, outside=True)
    live = np.isfinite(ref["growth_rate"])
    assert live.sum() >= 2
    diff = np.sort_complex(got["eigenvalues"][live]) - np.sort_complex(ref["eigenvalues"][live])
    assert np.max(np.abs(diff)) < 1e-5 * np.max(ref["rate_scale"][live])


def test_the_outside_of_an_upright_drum_has_no_orbit_with_contact():
    """Outside an upright wall the push points away from the axis, and the
    centre's circle needs a force towards it (S3: N/m = -r' Omega^2 < 0):
    no tilt of the outside's window rides, so there is no stability to find."""
    from deathsphere.physics.revolution import wheel_orbit

    drum = Cylinder(5.0)
    alpha = np.radians(np.linspace(90.5, 179.5, 179))
    res = wheel_orbit(drum, 2.0, alpha, A, 0.5, G, outside=True)
    assert not np.any(res["status"] == 0)
