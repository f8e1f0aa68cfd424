"""The time series of a run: what is sampled at each output time and how
the rows are assembled (beyond the paper; docs/simulation.md, "Outputs").

:func:`sample_quantities` turns states of the equations of motion (those
of the run's body model, :mod:`deathsphere.simulation.bodies`) into the
series' quantities (contact point angles, tilt, speed, contact force,
energy drift, constraint residual; a machine's extras);
:func:`series_rows` keeps the output rows of them and :func:`rows_table`
sorts row blocks into one time-major :class:`Table`.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from deathsphere.physics import dynamics as dyn
from deathsphere.simulation.bodies import model_of, take
from deathsphere.simulation.starts import Starts
from deathsphere.table import Table

__all__ = ["SERIES_COLUMNS", "series_columns", "sample_quantities", "series_rows", "rows_table", "concat_tables",
           "wrap_angle"]

#: Time-series columns, one row per body and sample time (docs/simulation.md).
#: ``friction_magnitude_per_mass_m_s2`` is the size of the tangential contact
#: force / m (>= 0), not the signed F_theta/m of ``deathsphere orbit``.
SERIES_COLUMNS = (
    "input_row", "t_s", "phi_deg", "theta_deg", "alpha_deg", "speed_m_s",
    "normal_per_mass_m_s2", "friction_magnitude_per_mass_m_s2", "mu_required",
    "energy_drift", "constraint_residual",
)



def series_columns(model) -> tuple:
    """The time series' columns for a body model: :data:`SERIES_COLUMNS`,
    then the model's own (a machine: ``v_cm_m_s``, ``head_clearance_m``)."""
    return SERIES_COLUMNS + tuple(model.series_extras)


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
    (magnitude), ``mu``, ``drift``, ``resid`` and the body model's extra
    columns under their names (``model.series_extras``); with ``with_state`` also
    ``state`` (9, m, nb), the states in lab components.
    """
    s = starts
    model = model_of(s.params)
    p = take(s.params, idx)
    R = s.frame[idx]                                             # (nb, 3, 3)
    pvec = model.contact_point(y, p)                            # (3, m, nb)
    pl = np.einsum("bji,jmb->imb", R, pvec)                    # orbit-frame components
    zp = np.moveaxis(R[:, :, 2], 0, 1)[:, None, :]             # z' (3, 1, nb)
    theta = model.polar_angle(pl)
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
    al = model.tilt_angle(y, p, pvec, zp)
    alpha0 = s.alpha[idx]
    alpha = alpha0 + wrap_angle(al - alpha0)
    speed = model.centre_speed(y, pvec)
    f = model.contact_force(y, p)
    drift = (model.energy(y, p) - e0[idx]) / e_scale[idx]
    resid = model.residual(y, p)
    q = {
        "theta": theta, "phi": phi, "alpha": alpha, "speed": speed,
        "normal": f["normal"], "friction": f["friction_magnitude"], "mu": f["mu_required"],
        "drift": drift, "resid": resid,
    }
    q.update(model.extras(y, p))
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


def series_rows(input_row, t, q, keep, extras=()) -> dict:
    """Long-format rows (time-major) of the samples ``q`` of bodies labelled
    ``input_row`` (nb,) at times t (m,), where keep (m, nb); ``extras`` the
    body model's own columns, which ``q`` holds under their names."""
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
        **{name: q[name][keep] for name in extras},
    }


def rows_table(parts: list[dict], columns: Sequence[str] = SERIES_COLUMNS) -> Table:
    """One time-major Table of ``columns`` from row blocks (sorted by time,
    then input_row)."""
    if not parts:
        return Table({name: np.zeros(0, dtype=np.int64 if name == "input_row" else float)
                      for name in columns})
    cols = {name: np.concatenate([p[name] for p in parts]) for name in columns}
    order = np.lexsort((cols["input_row"], cols["t_s"]))
    return Table({name: v[order] for name, v in cols.items()})


def concat_tables(tables: Sequence[Table]) -> Table:
    """Concatenate Tables with the same columns (e.g. the chunks of a run)."""
    tables = [t for t in tables if t is not None]
    if not tables:
        return rows_table([])
    names = tables[0].names
    return Table({name: np.concatenate([t.columns[name] for t in tables]) for name in names})
