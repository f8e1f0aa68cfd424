"""The show on a profile, two more independent checks (docs/show.md sec.
12): the 16-foot globe sampled as a profile gives the globe act's riders
(its own closed forms) to the sampling's accuracy, and a same-lap pair's
drift time in the bowl of examples/bowl_of_death.toml against a brute force
over relative azimuths on the bowl's closed-form meridian."""

import math
from pathlib import Path

import numpy as np
import pytest

import deathsphere
from deathsphere.physics.ground import Profile

ROOT = Path(__file__).resolve().parents[2]
#: examples/bowl.csv: the floor's edge at RHO0, a quarter circle of radius RF up to a vertical wall
RHO0, RF = 3.0, 2.0


def _rider(name, height, **hold):
    return {"name": name, "machine": "stunt125", "width": "0.6m", "lane": "horizontal", "height": height, **hold}


def test_a_profile_sampled_from_the_globe_gives_the_globes_riders_to_the_samplings_accuracy():
    """The 16-foot globe's meridian sampled every degree of theta from the
    bottom to 150 deg: the riders' numbers (the globe's closed forms, eqs.
    M1-M12, against the general surface of revolution's) agree to 1e-6
    relative (measured: 4.7e-7 at 1 deg, 5.4e-6 at 2 deg, 7.8e-8 at 0.5
    deg: the spline's error), the pairs' least clearance to 1e-8 m
    (measured 4.4e-9 m)."""
    r = 8 * 0.3048
    riders = [_rider("Ana", "1.4m", speed="39.18km/h", phase=0), _rider("Cal", "2.0m", period="1.274s", phase=40),
              _rider("Dee", "2.7m", same_lap_as="Cal", phase=0)]
    theta = np.radians(np.arange(0.0, 150.5, 1.0))
    profile = Profile(r * np.sin(theta), r * (1 - np.cos(theta)))
    globe = deathsphere.show({"globe": {"diameter": "16ft", "mu": 0.9, "max_g": 8}, "rider": riders})
    sampled = deathsphere.show({"arena": {"surface": "profile", "profile": profile, "mu": 0.9, "max_g": 8},
                                "rider": riders})
    assert list(sampled.riders["status"]) == list(globe.riders["status"]) == ["ok"] * 3
    for column in ("alpha_deg", "v_cm_m_s", "period_s", "load_g", "mu_required", "head_clearance_m",
                   "speed_low_m_s", "speed_high_m_s"):
        assert np.allclose(sampled.riders[column], globe.riders[column], rtol=1e-6, atol=0), column
    assert np.allclose(sampled.pairs["min_clearance_m"], globe.pairs["min_clearance_m"], rtol=0, atol=1e-8)


def _axis(lane, t):
    """A lane's envelope axis from its height and tilt alone on the bowl's
    closed form: P on the quarter circle (cos beta = 1 - z/RF, rho = RHO0 +
    RF sin beta), Q = P + t n (n = -sin beta rho-hat + cos beta z-hat), the
    head H = Q + (head - t) u, u = -cos alpha rho-hat + sin alpha z-hat
    (docs/machine.md eq. MS1)."""
    m = lane.machine
    beta = math.acos(1.0 - lane.height / RF) if lane.height < RF else 0.5 * math.pi
    rho = RHO0 + RF * math.sin(beta)
    phi = lane.phase + lane.rate * t
    rho_hat, z_hat = np.stack((np.cos(phi), np.sin(phi), 0 * phi)), np.array([0, 0, 1.0])[:, None]
    p = rho * rho_hat + lane.height * z_hat
    q = p + m.tyre_radius * (-math.sin(beta) * rho_hat + math.cos(beta) * z_hat)
    u = -math.cos(lane.alpha) * rho_hat + math.sin(lane.alpha) * z_hat
    return p, q + (m.head_height - m.tyre_radius) * u


def _clearances(a, b, t_a, t_b):
    """The clearance of a at t_a and b at t_b: 401 points along a's axis,
    each one's distance to b's axis by projection, less the half-widths."""
    s = np.linspace(0.0, 1.0, 401)
    out = []
    for ta, tb in zip(np.array_split(t_a, max(1, t_a.size // 500)), np.array_split(t_b, max(1, t_a.size // 500))):
        (p0, p1), (q0, q1) = _axis(a, ta), _axis(b, tb)
        x = p0[:, :, None] + (p1 - p0)[:, :, None] * s
        d = (q1 - q0)[:, :, None]
        u = np.clip(np.sum((x - q0[:, :, None]) * d, axis=0) / np.sum(d * d, axis=0), 0, 1)
        gap = x - q0[:, :, None] - u * d
        out.append(np.sqrt(np.sum(gap * gap, axis=0)).min(axis=1))
    return np.concatenate(out) - 0.5 * (a.width_m + b.width_m)


def test_a_same_lap_pairs_drift_in_the_bowl_against_a_brute_force_over_relative_azimuths():
    """Ben on Ana's lap 40 deg ahead, half a metre further up the bank: with
    Ana's clock 1 % fast or slow the two drift apart in azimuth at 1 % of
    her rate, and the drift time is the first relative azimuth either way at
    which they come closer than the crew's 0.15 m, over that rate (docs/show.md
    sec. 5)."""
    plan = {"arena": {"surface": "profile", "profile": str(ROOT / "examples" / "bowl.csv"), "mu": 0.8,
                      "max_g": 6, "min_clearance": "0.15m"},
            "rider": [_rider("Ana", "0.5m", speed="30km/h", phase=0), _rider("Ben", "1.0m", same_lap_as="Ana",
                                                                             phase=40)]}
    act = deathsphere.show(plan)
    a, b = act.lanes
    assert act.pairs["basis"][0] == "act" and act.pairs["verdict"][0] == "clear"
    x = np.linspace(0.0, 2 * math.pi, 8001)
    soonest = math.inf
    for sense in (1.0, -1.0):
        # a's angle moved by sense x against b's at t = 0: a at the time sense x / rate
        c = _clearances(a, b, sense * x / a.rate, np.zeros_like(x))
        below = np.flatnonzero(c < 0.15)
        if below.size:
            soonest = min(soonest, x[below[0]] / (0.01 * abs(a.rate)))
    assert math.isfinite(soonest)
    step = (x[1] - x[0]) / (0.01 * abs(a.rate))      # the brute force's resolution in time
    assert act.pairs["drift_time_s"][0] == pytest.approx(soonest, abs=2 * step)
