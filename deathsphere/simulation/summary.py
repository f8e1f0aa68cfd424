"""The summary of a run: one row per body (beyond the paper;
docs/simulation.md, "Outputs").

A :class:`Ledger` keeps the per-body bookkeeping while a run goes on:
final status and reason, the extremes of the sampled quantities (drifts of
theta and alpha, least normal force, most friction needed, largest energy
drift and constraint residual), the event's time and place, the time
reached, and the solver's counters; :meth:`Ledger.table` turns it into the
summary :class:`Table` (columns :data:`SUMMARY_COLUMNS`, then the body
model's own: a machine's name and least head clearance).
"""

from __future__ import annotations

import numpy as np

from deathsphere.simulation.bodies import model_of, take
from deathsphere.simulation.starts import Starts
from deathsphere.simulation.status import RunStatus, status_labels
from deathsphere.table import Table

__all__ = ["SUMMARY_COLUMNS", "Ledger"]

#: Summary columns, one row per body (docs/simulation.md).
SUMMARY_COLUMNS = (
    "input_row", "body", "side", "orbit", "theta_deg", "alpha_deg", "a_m", "r_m", "k", "g_m_s2",
    "omega_rad_s", "omega3_rad_s", "speed_m_s", "period_s", "perturb_deg", "perturb_theta_deg",
    "mu_available", "status", "reason", "event_time_s", "event_phi_deg", "event_theta_deg",
    "event_alpha_deg", "periods_simulated", "max_theta_drift_deg", "max_alpha_drift_deg",
    "min_normal_per_mass_m_s2", "max_mu_required", "max_abs_energy_drift",
    "max_constraint_residual", "method", "rtol", "atol", "frame", "n_steps", "n_fev", "wall_time_s",
)

#: per-body accumulators (NaN until a sample or an event sets them)
_ACCUMULATORS = ("theta_drift", "alpha_drift", "min_normal", "max_mu", "max_drift", "max_resid",
                 "event_t", "event_phi", "event_theta", "event_alpha", "t_done")


class Ledger:
    """Per-body bookkeeping of one run of the bodies ``starts``.

    ``status`` (int8 :class:`RunStatus` codes) and ``reason`` start as the
    starts' own; ``acc`` holds the accumulators (summary extremes, event
    data, ``t_done`` the time reached); ``phi_carry`` the azimuth's unwrap
    carry; ``e0``, ``e_scale`` the start energy and the scale of the
    energy drift (kinetic energy + g r, per unit mass); ``n_steps``,
    ``n_fev`` the solver's counters over all its calls.
    """

    def __init__(self, starts: Starts):
        s = starts
        n = len(s)
        self.starts = s
        self.status = s.status.copy()
        self.reason = s.reason.copy()
        self.acc = {name: np.full(n, np.nan) for name in _ACCUMULATORS}
        self.phi_carry = s.phi0.astype(float).copy()
        self.e0 = np.full(n, np.nan)
        self.e_scale = np.ones(n)
        self.model = model_of(s.params)
        for key, _, _ in self.model.extremes:
            self.acc[key] = np.full(n, np.nan)
        ok = s.pending
        if ok.any():
            p_ok = take(s.params, ok)
            e0 = self.model.energy(s.state[:, ok], p_ok)
            self.e0[ok] = e0
            self.e_scale[ok] = self.model.energy_scale(s.state[:, ok], p_ok, e0)
        self.n_steps = 0
        self.n_fev = 0

    def fold(self, idx, q, within):
        """Fold samples ``q`` of bodies ``idx`` into the summary extremes,
        only where ``within`` (m, nb) (a body's samples up to its end time)."""
        acc = self.acc
        th0, al0 = self.starts.theta[idx], self.starts.alpha[idx]
        reductions = (
            ("theta_drift", np.fmax, np.abs(q["theta"] - th0)),
            ("alpha_drift", np.fmax, np.abs(q["alpha"] - al0)),
            ("min_normal", np.fmin, q["normal"]),
            ("max_mu", np.fmax, q["mu"]),
            ("max_drift", np.fmax, np.abs(q["drift"])),
            ("max_resid", np.fmax, q["resid"]),
        ) + tuple((key, op, q[name]) for key, op, name in self.model.extremes)
        for key, op, v in reductions:
            acc[key][idx] = op(acc[key][idx], op.reduce(np.where(within, v, np.nan), axis=0))

    def finish(self, i, status: RunStatus, reason: str | None = None):
        """Body ``i`` ends with ``status`` (reason: the status's own words
        unless given)."""
        self.status[i], self.reason[i] = status, status.reason if reason is None else reason

    def record_event(self, i, j, status: RunStatus, t, q):
        """Body ``i`` (column j of the last sample of ``q``) stops at time t
        with ``status``: where it was is kept for the summary."""
        self.finish(i, status)
        acc = self.acc
        acc["event_t"][i] = t
        acc["event_phi"][i] = q["phi"][-1, j]
        acc["event_theta"][i] = q["theta"][-1, j]
        acc["event_alpha"][i] = q["alpha"][-1, j]
        acc["t_done"][i] = t

    def table(self, *, mu, method, rtol, atol, frame, wall) -> Table:
        """The summary (:data:`SUMMARY_COLUMNS`) of a run with the options
        given (``mu`` per body, inf: none) that took ``wall`` seconds."""
        s = self.starts
        acc = self.acc
        n = len(s)
        ok = s.pending
        nan = np.full(n, np.nan)
        period = s.period
        with np.errstate(invalid="ignore", divide="ignore"):
            done = np.where(ok, acc["t_done"] / np.where(ok, period, 1.0), nan)
        cols = {
            "input_row": s.input_row.astype(np.int64),
            "body": s.body, "side": s.side, "orbit": s.orbit,
            "theta_deg": s.theta_deg, "alpha_deg": s.alpha_deg,
            "a_m": s.params.a.astype(float), "r_m": s.params.r.astype(float),
            # a machine has inertias, not the paper's one factor k
            "k": np.asarray(getattr(s.params, "k", nan), dtype=float), "g_m_s2": s.params.g.astype(float),
            "omega_rad_s": s.rate, "omega3_rad_s": s.omega3, "speed_m_s": s.speed, "period_s": period,
            "perturb_deg": s.perturb_deg.astype(float), "perturb_theta_deg": s.perturb_theta_deg.astype(float),
            "mu_available": np.where(np.isinf(mu), np.nan, mu),
            "status": status_labels(self.status), "reason": self.reason.astype(object),
            "event_time_s": acc["event_t"],
            "event_phi_deg": np.rad2deg(acc["event_phi"]),
            "event_theta_deg": np.rad2deg(acc["event_theta"]),
            "event_alpha_deg": np.rad2deg(acc["event_alpha"]),
            "periods_simulated": done,
            "max_theta_drift_deg": np.rad2deg(acc["theta_drift"]),
            "max_alpha_drift_deg": np.rad2deg(acc["alpha_drift"]),
            "min_normal_per_mass_m_s2": acc["min_normal"],
            "max_mu_required": acc["max_mu"],
            "max_abs_energy_drift": acc["max_drift"],
            "max_constraint_residual": acc["max_resid"],
            "method": np.full(n, method, dtype=object),
            "rtol": np.full(n, rtol), "atol": np.full(n, atol),
            "frame": np.full(n, frame, dtype=object),
            "n_steps": np.full(n, self.n_steps, dtype=np.int64),
            "n_fev": np.full(n, self.n_fev, dtype=np.int64),
            "wall_time_s": np.full(n, wall),
        }
        fell = (self.status == RunStatus.CONTACT_LOST) | (self.status == RunStatus.SLIPS)
        if fell.any():
            idx = np.flatnonzero(fell)
            note = self.model.fall_note(take(s.params, idx), s.theta[idx], s.alpha[idx])
            cols["reason"][idx] = cols["reason"][idx] + note
        cols.update(self.model.summary_echo(s.params))
        cols.update({key: acc[key] for key, _, _ in self.model.extremes})
        return Table({name: cols[name] for name in SUMMARY_COLUMNS + tuple(self.model.summary_extras)})
