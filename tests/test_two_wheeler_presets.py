"""The motorcycle presets of the two-wheeler (docs/two-wheeler.md sec.
1.1-1.3): from their 26 parameters, an independent sum over the four bodies
gives back the published totals of Cossalter's sport tourer (Table 7.2)
and stunt125's; keeping a wheel's mass in its frame leaves the benchmark's
equations unchanged; the estimates do not reach the linearised equations;
both weave and capsize as a motorcycle does."""

import math
from dataclasses import replace

import numpy as np
import pytest

import deathsphere
from deathsphere.records import two_wheeler_presets
from deathsphere.api.machines import PRESETS
from deathsphere.records.two_wheeler_presets import COSSALTER_TABLE_7_2 as TABLE
from deathsphere.api.two_wheelers import TWO_WHEELERS, TwoWheeler
from deathsphere.physics.two_wheeler import linear
from deathsphere.physics.two_wheeler.parameters import benchmark_bicycle


def _tensor(ixx, iyy, izz, ixz=0.0):
    return np.array([[ixx, 0.0, ixz], [0.0, iyy, 0.0], [ixz, 0.0, izz]])


def _bodies(p):
    """(mass, centre (x, 0, z), tensor about it) of R, B, H, F in the reference configuration."""
    return [(p.mR, np.array([0.0, 0.0, -p.rR]), _tensor(p.IRxx, p.IRyy, p.IRxx)),
            (p.mB, np.array([p.xB, 0.0, p.zB]), _tensor(p.IBxx, p.IByy, p.IBzz, p.IBxz)),
            (p.mH, np.array([p.xH, 0.0, p.zH]), _tensor(p.IHxx, p.IHyy, p.IHzz, p.IHxz)),
            (p.mF, np.array([p.w, 0.0, -p.rF]), _tensor(p.IFxx, p.IFyy, p.IFxx))]


def _locked_totals(p):
    """The whole with its wheels locked: mass, mass centre, inertia tensor about it (a forward sum)."""
    bodies = _bodies(p)
    mass = sum(m for m, _, _ in bodies)
    centre = sum(m * r for m, r, _ in bodies) / mass
    tensor = sum(i + m * ((r - centre) @ (r - centre) * np.eye(3) - np.outer(r - centre, r - centre))
                 for m, r, i in bodies)
    return mass, centre, tensor


def test_the_sport_tourer_gives_back_table_7_2():
    t = TWO_WHEELERS["sport-tourer"]
    mass, centre, tensor = _locked_totals(t)
    assert mass == pytest.approx(TABLE["mass"], rel=1e-12)
    assert centre[0] == pytest.approx(TABLE["b"], rel=1e-12) and -centre[2] == pytest.approx(TABLE["h"], rel=1e-12)
    assert (tensor[0, 0], tensor[2, 2], tensor[0, 2]) == pytest.approx((TABLE["Ixx"], TABLE["Izz"], TABLE["Ixz"]),
                                                                     rel=1e-12, abs=1e-12)
    caster = math.radians(TABLE["caster_deg"])
    assert (t.w, t.lam, t.c * math.cos(caster)) == pytest.approx((TABLE["wheelbase"], caster, TABLE["normal_trail"]))
    assert (t.rR, t.rF, t.IRyy, t.IFyy) == (TABLE["rear_radius"], TABLE["front_radius"], TABLE["rear_spin_inertia"],
                                            TABLE["front_spin_inertia"])
    # the front assembly: its mass centre e_f ahead of the steer axis at height h_f, its moment about the axis
    s, ahead = np.array([math.sin(t.lam), 0.0, math.cos(t.lam)]), np.array([math.cos(t.lam), 0.0, -math.sin(t.lam)])
    offset = np.array([t.xH - (t.w + t.c), 0.0, t.zH])
    assert t.mH == TABLE["front_mass"] and -t.zH == pytest.approx(TABLE["h_f"])
    assert offset @ ahead == pytest.approx(TABLE["e_f"], rel=1e-12)
    about_axis = s @ _tensor(t.IHxx, t.IHyy, t.IHzz, t.IHxz) @ s + t.mH * (offset @ ahead) ** 2
    assert about_axis == pytest.approx(TABLE["front_steer_inertia"], rel=1e-12)


def test_stunt125_steer_has_stunt125s_totals():
    one, t = PRESETS["stunt125"], TWO_WHEELERS["stunt125-steer"]
    mass, centre, tensor = _locked_totals(t)
    assert mass == pytest.approx(one.mass, rel=1e-12) and -centre[2] == pytest.approx(one.h, rel=1e-12)
    assert tensor == pytest.approx(np.diag(one.inertia), rel=1e-12, abs=1e-12)
    assert t.IRyy + t.IFyy == pytest.approx(one.spin_inertia, rel=1e-12) and -t.head[1] == one.head


def _lumped(p):
    """Table 1 with each wheel's mass and diametral moment moved into the frame carrying its axle."""
    def merge(m, r, i, wheel_mass, wheel_centre, wheel_axial):
        total = m + wheel_mass
        centre = (m * r + wheel_mass * wheel_centre) / total
        shifted = [(m, r, i), (wheel_mass, wheel_centre, wheel_axial)]
        return total, centre, sum(j + k * ((c - centre) @ (c - centre) * np.eye(3) - np.outer(c - centre, c - centre))
                                  for k, c, j in shifted)

    (m_r, c_r, _), (m_b, c_b, i_b), (m_h, c_h, i_h), (m_f, c_f, _) = _bodies(p)
    m_b, c_b, i_b = merge(m_b, c_b, i_b, m_r, c_r, _tensor(p.IRxx, 0.0, p.IRxx))
    m_h, c_h, i_h = merge(m_h, c_h, i_h, m_f, c_f, _tensor(p.IFxx, 0.0, p.IFxx))
    return replace(p, mR=0.0, IRxx=0.0, mF=0.0, IFxx=0.0, mB=m_b, xB=c_b[0], zB=c_b[2], IBxx=i_b[0, 0],
                   IByy=i_b[1, 1], IBzz=i_b[2, 2], IBxz=i_b[0, 2], mH=m_h, xH=c_h[0], zH=c_h[2], IHxx=i_h[0, 0],
                   IHyy=i_h[1, 1], IHzz=i_h[2, 2], IHxz=i_h[0, 2])


def test_a_wheels_mass_kept_in_its_frame_changes_nothing():
    """sec. 1.1: the benchmark bicycle with mR = mF = IRxx = IFxx = 0 has its matrices."""
    table1 = linear.benchmark_matrices(benchmark_bicycle())
    lumped = linear.benchmark_matrices(_lumped(benchmark_bicycle()))
    for name in ("M", "C1", "K0", "K2"):
        assert getattr(lumped, name) == pytest.approx(getattr(table1, name), rel=1e-12, abs=1e-12)


def test_the_estimates_do_not_reach_the_linearised_equations(monkeypatch):
    before = linear.benchmark_matrices(TwoWheeler(**two_wheeler_presets.sport_tourer()).parameters())
    monkeypatch.setattr(two_wheeler_presets, "FRONT_GYRATION", 0.2)
    monkeypatch.setattr(two_wheeler_presets, "LATERAL_SPREAD", 0.05)
    changed = TwoWheeler(**two_wheeler_presets.sport_tourer())
    assert changed.IHxx != TWO_WHEELERS["sport-tourer"].IHxx and changed.IByy != TWO_WHEELERS["sport-tourer"].IByy
    after = linear.benchmark_matrices(changed.parameters())
    for name in ("M", "C1", "K0", "K2"):
        assert getattr(after, name) == pytest.approx(getattr(before, name), rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("name", ["sport-tourer", "stunt125-steer"])
def test_weave_stable_at_speed_capsize_mildly_unstable(name):
    summary = deathsphere.ride(machine=name, flat=True, speed="0:60:1", summary=True)[0]
    weave, capsize = summary["weave_speed_m_s"], summary["capsize_speed_m_s"]
    assert 3 < weave < capsize < 20            # a motorcycle's window lies above a bicycle's 4.3-6.0 m/s
    rows = deathsphere.ride(machine=name, flat=True, speed=[weave - 1, (weave + capsize) / 2, capsize + 1, 60.0])
    assert list(rows["stability"]) == ["unstable", "stable", "unstable", "unstable"]
    below = rows[0]
    assert below["eig_1_re"] > 0 and below["eig_1_im"] != 0        # the weave, oscillating and growing
    for row in rows[2:]:
        # the capsize alone grows, slowly and without oscillating; the weave is damped
        assert 0 < row["growth_rate_1_s"] < 0.2 and row["eig_1_im"] == 0
        assert all(row[f"eig_{i}_re"] < 0 for i in (2, 3, 4))
