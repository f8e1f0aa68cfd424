"""A particle sliding freely on a horizontal circle of a fixed sphere."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from deathsphere.physics.particle import omega_squared, particle_orbit
from deathsphere.physics.status import Reason, Status

G = 9.80665
R = 3.0


@settings(max_examples=60, deadline=None)
@given(theta=st.floats(np.radians(90.5), np.radians(179.5)))
def test_inside_below_equator_force_balance(theta):
    """Newton with vectors: m a = N + m g, N along the radius, pointing to the centre."""
    out = particle_orbit(theta, R, G)
    assert out["status"] == Status.OK
    om2 = float(out["omega2"])
    n_out = np.array([np.sin(theta), 0.0, np.cos(theta)])
    accel = -R * np.sin(theta) * om2 * np.array([1.0, 0.0, 0.0])
    force = accel + G * np.array([0.0, 0.0, 1.0])              # N/m = a + g z
    # the force is purely normal (no friction) and presses inwards with the reported size
    assert np.linalg.norm(np.cross(force, n_out)) == pytest.approx(0.0, abs=1e-12 * (1 + om2 * R))
    assert -(force @ n_out) == pytest.approx(float(out["normal"]), rel=1e-12)
    assert float(out["normal"]) > 0
    assert float(out["accel"]) == pytest.approx(R * abs(np.sin(theta)) * om2)
    assert float(out["period"]) == pytest.approx(2 * np.pi / np.sqrt(om2))
    assert float(out["v_cm"]) == pytest.approx(R * np.sin(theta) * np.sqrt(om2))
    assert float(out["mu_required"]) == 0.0 and float(out["friction"]) == 0.0


@settings(max_examples=60, deadline=None)
@given(theta=st.floats(np.radians(0.5), np.radians(179.5)), outside=st.booleans())
def test_no_orbit_at_or_above_equator_and_none_outside(theta, outside):
    out = particle_orbit(theta, R, G, outside=outside)
    if np.cos(theta) >= -1e-12:
        assert out["status"] == Status.NO_ORBIT
        assert out["reason"] == Reason.PARTICLE_ABOVE_EQUATOR
        assert np.isnan(out["omega"])
    elif outside:
        # Omega^2 > 0 but the sphere would have to pull the particle in
        assert out["status"] == Status.NO_CONTACT
        assert out["reason"] == Reason.PARTICLE_OUTSIDE_BELOW_EQUATOR
        assert float(out["normal"]) < 0
    else:
        assert out["status"] == Status.OK


def test_omega_squared_formula_and_equator():
    theta = np.radians([120.0, 150.0, 90.0, 60.0])
    om2 = omega_squared(theta, R, G)
    assert om2[:2] == pytest.approx(-G / (R * np.cos(theta[:2])))
    assert np.isnan(om2[2]) and om2[3] < 0


def test_poles_and_no_warnings():
    out = particle_orbit(np.array([0.0, np.pi, np.pi / 2, 1e-300]), R, G, mu=np.array([0.0]))
    assert out["reason"].tolist() == [Reason.POLE, Reason.POLE, Reason.PARTICLE_ABOVE_EQUATOR, Reason.POLE]
    for outside in (False, True):
        particle_orbit(np.linspace(0, np.pi, 181), R, G, outside=outside, mu=0.0)


def test_never_slips():
    out = particle_orbit(np.radians(135.0), R, G, mu=0.0)
    assert out["status"] == Status.OK
