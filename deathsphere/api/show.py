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


def show(plan, *, duration=None, phase: str = "plan") -> ShowResult:
    """Plan an act (docs/show.md): ``plan`` a path to a TOML file or a dict
    ({"globe": {...}, "rider": [...]}); ``duration`` [s] the act's length
    when the riders' periods are not commensurate (over the plan's);
    ``phase`` 'plan' (the plan's phases) or 'auto' (each vertical rider's
    phase, in plan order, maximising the least clearance).  A bad plan
    raises ParameterError, one line naming the rider and the key, before
    any work.  Not yet implemented."""
    raise NotImplementedError("deathsphere.api.show.show is being written")
