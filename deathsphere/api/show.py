"""The show: several riders sharing one globe (``deathsphere show``;
docs/show.md): lanes, clearance, timing, drift, and where a rider who loses
speed falls.  Beyond the paper; the machine's physics is ``ride``'s
(docs/machine.md)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from deathsphere.errors import ParameterError
from deathsphere.show.lanes import Lane, build_lanes
from deathsphere.show.plan import EXAMPLE_PLAN, Plan, read_plan
from deathsphere.table import Table

__all__ = ["show", "ShowResult", "EXAMPLE_PLAN", "RIDER_COLUMNS", "PAIR_COLUMNS", "FALL_COLUMNS",
           "FALLS_SUMMARY_COLUMNS"]

#: The columns of ``riders``, in order (vertical lanes fill the last four).
RIDER_COLUMNS = ("name", "lane", "theta_deg", "phi0_deg", "alpha_deg", "lean_deg", "v_cm_m_s", "v_cm_km_h",
                 "v_contact_m_s", "period_s", "load_g", "mu_required", "head_clearance_m", "status", "reason",
                 "speed_low_m_s", "speed_high_m_s", "margin_low_pct", "margin_high_pct", "v_top_m_s",
                 "v_top_min_m_s", "v_bottom_m_s", "load_bottom_g", "machine", "width_m")
#: The columns of ``pairs``, in order; ``basis`` says how the least
#: clearance was found ('act': over the act's times; 'geometric': two
#: horizontal lanes of different rates sweep every relative phase, so both
#: riders in one meridian plane).
PAIR_COLUMNS = ("rider_a", "rider_b", "min_clearance_m", "t_s", "theta_a_deg", "phi_a_deg", "theta_b_deg",
                "phi_b_deg", "verdict", "drift_time_s", "basis")
#: The columns of ``fall``, in order.
FALL_COLUMNS = ("rider", "t_fail_s", "speed_fraction", "outcome", "t_contact_lost_s", "theta_lost_deg",
                "phi_lost_deg", "t_land_s", "theta_land_deg", "phi_land_deg", "fall_time_s", "impact_speed_m_s",
                "victim", "min_clearance_m", "t_min_s", "hit")
#: The columns of the summary of ``falls``.
FALLS_SUMMARY_COLUMNS = ("rider", "victim", "falls", "hits", "hit_fraction", "impact_speed_max_m_s")
PHASES = ("plan", "auto")


@dataclass
class ShowResult:
    """An act planned: ``riders`` and ``pairs`` tables, the act's
    ``duration_s``, whether the riders' periods are ``commensurate``, each
    vertical rider's ``phase_windows`` (name -> list of (from, to) [deg] of
    safe phases; filled with phase='auto'), the checked ``plan`` and the
    ``lanes``."""

    plan: Plan
    lanes: list[Lane]
    riders: Table
    pairs: Table
    duration_s: float
    commensurate: bool
    phase_windows: dict = field(default_factory=dict)

    def positions(self, t) -> dict:
        """Each rider's 'contact', 'head' and 'com' points (3, n) [m, the
        globe's frame] at the times t (n,) [s], by name."""
        t = np.asarray(t, dtype=float).reshape(-1)
        return {lane.name: {k: v for k, v in lane.kinematics(t).items() if k in ("contact", "head", "com")}
                for lane in self.lanes}

    def fall(self, rider: str, t: float, speed_fraction: float = 0.5) -> Table:
        """At time t the rider's speed drops to ``speed_fraction`` of his
        speed: columns :data:`FALL_COLUMNS`, one row per other rider.  Not
        yet implemented (needs deathsphere.physics.fall)."""
        raise NotImplementedError("ShowResult.fall waits for deathsphere.physics.fall")

    def falls(self, n: int, seed: int = 0, scheduler=None) -> tuple[Table, Table]:
        """Monte Carlo of n falls (random rider, time in the act, fraction in
        [0, 1)): (outcomes, summary).  Not yet implemented."""
        raise NotImplementedError("ShowResult.falls waits for deathsphere.physics.fall")


def _rider_row(lane: Lane, rider, globe) -> dict:
    """The riders table's row of one lane (ride's row, the speed band)."""
    from deathsphere.show.margins import speed_band
    from deathsphere.show.pairs import contact_angles

    row, nan = lane.row, math.nan
    theta0, phi0 = contact_angles(lane, 0.0)
    out = {"name": lane.name, "lane": lane.kind, "theta_deg": theta0, "phi0_deg": phi0, "machine": lane.machine.name,
           "width_m": lane.width_m, "status": row["status"], "reason": row["reason"],
           "mu_required": row["mu_required"], "head_clearance_m": row["head_clearance_m"], "period_s": lane.period_s}
    if lane.kind == "horizontal":
        planned = rider.speed
        out.update(alpha_deg=row["alpha_deg"], lean_deg=row["lean_deg"], v_cm_m_s=row["v_cm_m_s"],
                   v_contact_m_s=row["v_contact_m_s"], load_g=row["load_g"], v_top_m_s=nan, v_top_min_m_s=nan,
                   v_bottom_m_s=nan, load_bottom_g=nan)
    else:
        planned = rider.v_top
        r_g = row["com_loop_radius_m"]
        out.update(alpha_deg=nan, lean_deg=0.0, v_cm_m_s=planned, v_contact_m_s=planned * lane.r / r_g,
                   load_g=row["load_bottom_g"], v_top_m_s=planned, v_top_min_m_s=row["v_top_min_m_s"],
                   v_bottom_m_s=row["v_bottom_m_s"], load_bottom_g=row["load_bottom_g"])
    out["v_cm_km_h"] = round(out["v_cm_m_s"] * 3.6, 9)
    low, high = speed_band(lane, globe, planned)
    out.update(speed_low_m_s=low, speed_high_m_s=high, margin_low_pct=100.0 * (planned - low) / planned,
               margin_high_pct=100.0 * (high - planned) / planned)
    return out


def riders_table(plan: Plan, lanes: list[Lane]) -> Table:
    """The ``riders`` table (columns :data:`RIDER_COLUMNS`), one row per rider in the plan's order."""
    rows = [_rider_row(lane, rider, plan.globe) for lane, rider in zip(lanes, plan.riders)]
    text = {"name", "lane", "status", "reason", "machine"}
    return Table({c: np.array([r[c] for r in rows], dtype=object if c in text else float) for c in RIDER_COLUMNS})


def pairs_table(lanes: list[Lane], duration: float, min_clearance: float, drift: bool = True) -> Table:
    """The ``pairs`` table (columns :data:`PAIR_COLUMNS`): every pair (a before
    b in the plan), its least clearance over the act, when and where, the
    verdict and the drift time (NaN: never)."""
    from deathsphere.show.pairs import contact_angles, least_clearance, verdict
    from deathsphere.show.timing import drift_time

    rows = []
    for i, a in enumerate(lanes):
        for b in lanes[i + 1:]:
            c, t, basis = least_clearance(a, b, duration)
            (ta, pa), (tb, pb) = contact_angles(a, t), contact_angles(b, t)
            v = verdict(c, min_clearance)
            dt = drift_time(a, b, min_clearance) if drift and v == "clear" else math.nan
            rows.append({"rider_a": a.name, "rider_b": b.name, "min_clearance_m": c, "t_s": t, "theta_a_deg": ta,
                         "phi_a_deg": pa, "theta_b_deg": tb, "phi_b_deg": pb, "verdict": v,
                         "drift_time_s": dt if math.isfinite(dt) else math.nan, "basis": basis})
    text = {"rider_a", "rider_b", "verdict", "basis"}
    return Table({c: np.array([r[c] for r in rows], dtype=object if c in text else float) for c in PAIR_COLUMNS})


def show(plan, *, duration=None, phase: str = "plan") -> ShowResult:
    """Plan an act (docs/show.md): ``plan`` a path to a TOML file or a dict
    ({"globe": {...}, "rider": [...]}); ``duration`` [s] the act's length
    when the riders' periods are not commensurate (over the plan's
    ``duration``; the common period is used whenever they are); ``phase``
    'plan' (the plan's phases) or 'auto' (each vertical rider's phase, in
    plan order, maximising his least clearance; ``phase_windows`` then holds
    the safe phases).  A bad plan raises ParameterError, one line naming the
    rider and the key, before any work.

    >>> import deathsphere
    >>> act = deathsphere.show({"globe": {"diameter": "16ft", "mu": 0.9}, "rider": [
    ...     {"name": "Ana", "lane": "horizontal", "height": "2m", "speed": "32km/h"}]})
    >>> str(act.riders["status"][0]), act.pairs.columns["rider_a"].size
    ('ok', 0)
    """
    from deathsphere.show.pairs import act_duration
    from deathsphere.show.timing import auto_phases

    if phase not in PHASES:
        raise ParameterError(f"phase must be plan or auto (got {phase!r})", "phase")
    plan = read_plan(plan)
    if duration is not None:
        if isinstance(duration, bool) or not isinstance(duration, (int, float)) or not 0 < duration < math.inf:
            raise ParameterError(f"duration must be a number of seconds > 0 (got {duration!r})", "duration")
    lanes = build_lanes(plan)
    try:
        span, commensurate = act_duration(lanes, plan.globe.duration if duration is None else duration)
    except ValueError as exc:
        raise ParameterError(str(exc), "duration") from None
    if duration is not None:
        span = float(duration)
    windows = {}
    if phase == "auto":
        phases, windows = auto_phases(lanes, span, plan.globe.min_clearance)
        plan = plan.with_phases(phases)
        lanes = build_lanes(plan)
    riders = riders_table(plan, lanes)
    pairs = pairs_table(lanes, span, plan.globe.min_clearance)
    return ShowResult(plan=plan, lanes=lanes, riders=riders, pairs=pairs, duration_s=span,
                      commensurate=commensurate, phase_windows=windows)
