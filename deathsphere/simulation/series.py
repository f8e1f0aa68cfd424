"""The time series of a run: what is sampled at each output time and how
the rows are assembled (beyond the paper; docs/simulation.md, "Outputs").

:func:`sample_quantities` turns states of the equations of motion of
:mod:`deathsphere.physics.dynamics` into the series' quantities (contact
point angles, tilt, speed, contact force, energy drift, constraint
residual); :func:`series_rows` keeps the output rows of them and
:func:`rows_table` sorts row blocks into one time-major :class:`Table`.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from deathsphere.physics import dynamics as dyn
from deathsphere.simulation.starts import Starts
from deathsphere.table import Table

__all__ = ["SERIES_COLUMNS", "sample_quantities", "series_rows", "rows_table", "concat_tables", "wrap_angle"]

#: Time-series columns, one row per body and sample time (docs/simulation.md).
#: ``friction_magnitude_per_mass_m_s2`` is the size of the tangential contact
#: force / m (>= 0), not the signed F_theta/m of ``deathsphere orbit``.
SERIES_COLUMNS = (
    "input_row", "t_s", "phi_deg", "theta_deg", "alpha_deg", "speed_m_s",
    "normal_per_mass_m_s2", "friction_magnitude_per_mass_m_s2", "mu_required",
    "energy_drift", "constraint_residual",
)


def wrap_angle(x):
    """x [rad] wrapped into [-pi, pi)."""
    return (x + np.pi) % (2 * np.pi) - np.pi


def sample_quantities(starts: Starts, idx, y, t, frame_rate, phi_carry, e0, e_scale, with_state=False) -> dict:
    """Time-series quantities of the bodies ``idx`` of ``starts`` at states
    y (9, m, nb) and times t (m,), in SI units and radians.

    ``frame_rate`` [rad/s], ``phi_carry`` [rad], ``e0`` and ``e_scale`` are
    per-body arrays of the whole run: the rate of the frame integrated in,
    the azimuth's unwrap carry (advanced here, in place), the start energy
    and the energy scale of the drift.  Returns a dict of (m, nb) arrays
    ``theta``, ``phi``, ``alpha``, ``speed``, ``normal``, ``friction``
    (magnitude), ``mu``, ``drift``, ``resid``; with ``with_state`` also
    ``state`` (9, m, nb), the states in lab components.
    """
    s = starts
    p = dyn.BodyParams(*(x[idx] for x in s.params))
    R = s.frame[idx]                                             # (nb, 3, 3)
    pvec = dyn.contact_point(y, p)                              # (3, m, nb)
    c, e1, w = y[dyn.C], y[dyn.E1], y[dyn.W]
    pl = np.einsum("bji,jmb->imb", R, pvec)                    # orbit-frame components
    zp = np.moveaxis(R[:, :, 2], 0, 1)[:, None, :]             # z' (3, 1, nb)
    theta = np.arctan2(np.hypot(pl[0], pl[1]), pl[2])
    # azimuth about z': unwrapped sample by sample from the carry; in the
    # turning frame the frame's own rotation Omega t is added afterwards
    raw = np.arctan2(pl[1], pl[0])
    prev = phi_carry[idx]
    phi_f = np.empty_like(raw)
    for i in range(raw.shape[0]):
        prev = prev + wrap_angle(raw[i] - prev)
        phi_f[i] = prev
    phi_carry[idx] = prev
    phi = phi_f + frame_rate[idx][None, :] * t[:, None]
    # tilt (eq. 11): z' = -cos(alpha) e1 - sin(alpha) e3; for a sphere the
    # equivalent alpha of sec. 4 (axis 3 along the radius)
    e3 = (pvec - c) / p.a
    e1h = e1 / np.sqrt(np.sum(e1 * e1, axis=0))
    z3 = np.sum(zp * e3, axis=0)
    z1 = np.sum(zp * e1h, axis=0)
    cos_sphere = np.where(p.outside, -1.0, 1.0) * np.sqrt(np.maximum(1.0 - z3 * z3, 0.0))
    al = np.arctan2(-z3, np.where(p.sphere, cos_sphere, -z1))
    alpha0 = s.alpha[idx]
    alpha = alpha0 + wrap_angle(al - alpha0)
    speed = np.sqrt(np.sum(np.cross(pvec - c, w, axis=0) ** 2, axis=0))   # |a e3 x w|, eq. (6)
    f = dyn.contact_force(y, p)
    drift = (dyn.energy(y, p) - e0[idx]) / e_scale[idx]
    res = dyn.constraint_residuals(y, p)
    resid = np.maximum(np.where(p.sphere, 0.0, np.abs(res["axis"])), np.abs(res["contact"]) / p.r)
    q = {
        "theta": theta, "phi": phi, "alpha": alpha, "speed": speed,
        "normal": f["normal"], "friction": f["friction_magnitude"], "mu": f["mu_required"],
        "drift": drift, "resid": resid,
    }
    if with_state:
        q["state"] = lab_states(y, frame_rate[idx][None, :] * t[:, None])
    return q


def lab_states(y, angle):
    """States y (9, m, nb) of a frame at ``angle`` (m, nb) [rad] from the lab
    about +z (the turning frame: Omega t) in lab components."""
    cos, sin = np.cos(angle), np.sin(angle)
    lab = np.array(y, dtype=float, copy=True)
    for rows in (dyn.C, dyn.E1, dyn.W):
        x, yy = y[rows][0], y[rows][1]
        lab[rows.start], lab[rows.start + 1] = cos * x - sin * yy, sin * x + cos * yy
    return lab


def series_rows(input_row, t, q, keep) -> dict:
    """Long-format rows (time-major) of the samples ``q`` of bodies labelled
    ``input_row`` (nb,) at times t (m,), where keep (m, nb)."""
    return {
        "input_row": np.broadcast_to(input_row[None, :], keep.shape)[keep].astype(np.int64),
        "t_s": np.broadcast_to(t[:, None], keep.shape)[keep],
        "phi_deg": np.rad2deg(q["phi"][keep]),
        "theta_deg": np.rad2deg(q["theta"][keep]),
        "alpha_deg": np.rad2deg(q["alpha"][keep]),
        "speed_m_s": q["speed"][keep],
        "normal_per_mass_m_s2": q["normal"][keep],
        "friction_magnitude_per_mass_m_s2": q["friction"][keep],
        "mu_required": q["mu"][keep],
        "energy_drift": q["drift"][keep],
        "constraint_residual": q["resid"][keep],
    }


def rows_table(parts: list[dict]) -> Table:
    """One time-major Table from row blocks (sorted by time, then input_row)."""
    if not parts:
        return Table({name: np.zeros(0, dtype=np.int64 if name == "input_row" else float)
                      for name in SERIES_COLUMNS})
    cols = {name: np.concatenate([p[name] for p in parts]) for name in SERIES_COLUMNS}
    order = np.lexsort((cols["input_row"], cols["t_s"]))
    return Table({name: v[order] for name, v in cols.items()})


def concat_tables(tables: Sequence[Table]) -> Table:
    """Concatenate Tables with the same columns (e.g. the chunks of a run)."""
    tables = [t for t in tables if t is not None]
    if not tables:
        return rows_table([])
    names = tables[0].names
    return Table({name: np.concatenate([t.columns[name] for t in tables]) for name in names})
