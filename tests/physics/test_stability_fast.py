"""The fast exact stability of wheel orbits (stability.wheel_stability:
Householder complement, eigenvalues from the invariants of the reduced 4x4
Jacobian) against the method as first written (tests/physics/
stability_reference.py: complete QR, np.linalg.eigvals), on random orbits
and on orbits next to stability boundaries (beyond the paper;
docs/stability.md sec. 1).
"""

import numpy as np
import pytest
from stability_reference import wheel_stability_ref

from deathsphere.physics import stability as st
from deathsphere.physics.stability import stability_boundary_alphas

G = 9.80665


def _compare(th, al, a, r, k, outside):
    new = st.wheel_stability(th, al, a, r, k, G, outside)
    ref = wheel_stability_ref(th, al, a, r, k, G, outside)
    np.testing.assert_array_equal(new["verdict"], ref["verdict"])
    live = np.isfinite(ref["growth_rate"])
    np.testing.assert_array_equal(np.isfinite(new["growth_rate"]), live)
    np.testing.assert_array_equal(new["omega"][live], ref["omega"][live])
    np.testing.assert_array_equal(new["rate_scale"][live], ref["rate_scale"][live])
    # frequencies to 1e-9 of the eigenvalue's size (relative, on stable orbits)
    size = ref["freq_fast"][live] + ref["growth_rate"][live]
    for key in ("freq_slow", "freq_fast"):
        d = np.abs(new[key][live] - ref[key][live])
        assert np.all(d <= 1e-9 * size), (key, np.max(d / size))
    # stable orbits: 1e-9 relative; or 1e-10 of the rate scale for a slow
    # frequency that vanishes at a boundary (e4 -> 0), where neither method
    # is better conditioned than eps S^2 / f (~1e-9 f at f ~ 3e-4 S); or the
    # reference's own error where it shows one: the exact spectrum of a
    # stable orbit is imaginary, and on a few orbits whose reduced Jacobian is
    # badly conditioned (|K| ~ 1e3 x the frequencies) eigvals leaves real
    # parts up to ~2e-8 of the rate scale
    stable = ref["verdict"] == st.Verdict.STABLE
    for key in ("freq_slow", "freq_fast"):
        d = np.abs(new[key][stable] - ref[key][stable])
        tol = np.maximum(np.maximum(1e-9 * ref[key], 1e-10 * ref["rate_scale"]), ref["growth_rate"])
        assert np.all(d <= tol[stable]), key
    # growth rates: unstable orbits to 1e-9 of the eigenvalue's size; stable
    # ones get 0 exactly (the reference's round-off real parts, up to 2e-8
    # of the rate scale, are below STABLE_TOL: the verdicts agree above)
    unstable = ref["verdict"] == st.Verdict.UNSTABLE
    d = np.abs(new["growth_rate"][unstable] - ref["growth_rate"][unstable])
    assert np.all(d <= 1e-9 * (ref["freq_fast"] + ref["growth_rate"])[unstable])
    assert np.all(new["growth_rate"][stable] == 0.0)
    return new, ref


@pytest.mark.parametrize("outside", [False, True])
def test_random_orbits_agree_with_the_reference(outside):
    rng = np.random.default_rng(11 + outside)
    n = 6000
    th = np.radians(rng.uniform(0.5, 179.5, n))
    al = np.radians(rng.uniform(0.0, 360.0, n) if outside else rng.uniform(-10.0, 100.0, n))
    a_r = rng.choice([0.01, 0.1, 0.3, 0.6], n)
    k = rng.choice([0.25, 0.5, 1.0], n)
    new, ref = _compare(th, al, a_r, 1.0, k, outside)
    assert np.sum(ref["verdict"] == st.Verdict.STABLE) > 500
    assert np.sum(ref["verdict"] == st.Verdict.UNSTABLE) > 100


@pytest.mark.parametrize("a_r,k", [(0.1, 0.5), (0.3, 0.25), (0.6, 0.5)])
def test_orbits_next_to_stability_boundaries_agree_with_the_reference(a_r, k):
    """Orbits 1e-7 .. 1e-3 rad in alpha from a boundary (where the growth
    rate rises like the square root of the distance) keep their verdicts."""
    th = np.radians(np.linspace(10.0, 170.0, 17))
    b = stability_boundary_alphas(th, a_r, 1.0, k, G)
    tt, bb = np.broadcast_to(th[:, None], b.shape), b
    ok = np.isfinite(bb)
    assert ok.sum() >= 5
    d = np.array([-1e-3, -1e-5, -1e-7, 1e-7, 1e-5, 1e-3])
    TH = np.repeat(tt[ok], d.size)
    AL = (bb[ok][:, None] + d[None, :]).reshape(-1)
    new, ref = _compare(TH, AL, a_r, 1.0, k, False)
    assert np.sum(ref["verdict"] == st.Verdict.STABLE) > 5
    assert np.sum(ref["verdict"] == st.Verdict.UNSTABLE) > 5


def test_reduced_jacobian_spans_the_same_quotient():
    """The new complement basis differs from the QR one by an orthogonal
    change of basis: the same spectrum, the basis orthonormal (scaled) and
    orthogonal to the removed directions' span."""
    th, al = np.radians([60.0, 90.0, 40.0]), np.radians([25.0, 80.0, 12.0])
    L = st.wheel_reduced_jacobian(th, al, 0.3, 3.0, 0.5, G)
    ev_inv = st.wheel_stability(th, al, 0.3, 3.0, 0.5, G)["eigenvalues"]
    for i in range(3):
        ev = np.linalg.eigvals(L["K"][i])
        dist = np.abs(ev[:, None] - ev_inv[i][None, :])
        assert np.all(dist.min(axis=0) <= 1e-9 * np.max(np.abs(ev)))
        assert np.all(dist.min(axis=1) <= 1e-9 * np.max(np.abs(ev)))
        B = L["basis"][i] / np.r_[[0.3] * 3, [1.0] * 3, [st.wheel_stability(th[i], al[i], 0.3, 3.0, 0.5, G)
                                                          ["rate_scale"]] * 3][:, None]
        np.testing.assert_allclose(B.T @ B, np.eye(4), atol=1e-13)


@pytest.mark.parametrize("solver, second", [
    (st.wheel_stability, lambda rng, n: np.deg2rad(rng.uniform(1, 80, n))),
    (st.sphere_stability, lambda rng, n: rng.uniform(-20, 20, n)),
])
def test_an_orbits_stability_does_not_depend_on_its_batch(solver, second):
    """Bit for bit the same whether an orbit is analysed alone or beside
    others (a sweep's output must not change with --chunk-size): the sums
    over components run in a fixed order (vectors.contract), where einsum's
    order changed with the number of orbits."""
    rng = np.random.default_rng(3)
    n = 40
    th, sec = np.deg2rad(rng.uniform(20, 160, n)), second(rng, n)
    whole = solver(th, sec, 0.3, 3.0, 0.5, G)
    assert np.isfinite(whole["freq_fast"]).sum() > n // 2
    for size in (1, 2, 3, 7):
        for start in range(0, n, size):
            part = solver(th[start:start + size], sec[start:start + size], 0.3, 3.0, 0.5, G)
            for key in ("growth_rate", "freq_slow", "freq_fast", "verdict", "eigenvalues"):
                np.testing.assert_array_equal(part[key], whole[key][start:start + size], err_msg=f"{key} {size}")
