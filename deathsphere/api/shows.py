"""The show: several riders sharing one globe (``deathsphere show``;
docs/show.md): lanes, clearance, timing, drift, and where a rider who loses
speed falls.  Beyond the paper; the machine's physics is ``ride``'s
(docs/machine.md)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from deathsphere.errors import ParameterError
from deathsphere.act.lanes import Lane, build_lanes
from deathsphere.act.plan import EXAMPLE_PLAN, Plan, read_plan
from deathsphere.table import Table

__all__ = ["show", "ShowResult", "EXAMPLE_PLAN", "RIDER_COLUMNS", "PAIR_COLUMNS", "FALL_COLUMNS",
           "FALLS_SUMMARY_COLUMNS"]

#: The columns of ``riders``, in order.  ``theta_deg`` and ``phi0_deg``
#: are the contact's at t = 0 (a horizontal lane's theta throughout; a
#: vertical lane's from its phase and azimuth as typed); a
#: vertical lane has no alpha, leans 0 (upright in its loop's plane), its
#: v_cm the centre of mass's speed at the top and its load_g the bottom's,
#: and fills ``v_top_m_s`` .. ``load_bottom_g``; the speed band is of the
#: contact's speed (horizontal, however the plan holds the lane) or of v_top
#: (vertical), empty where the planned speed is not feasible or an edge lies
#: beyond 1/16..16 times it.
RIDER_COLUMNS = ("name", "lane", "theta_deg", "phi0_deg", "alpha_deg", "lean_deg", "v_cm_m_s", "v_cm_km_h",
                 "v_contact_m_s", "period_s", "load_g", "mu_required", "head_clearance_m", "status", "reason",
                 "speed_low_m_s", "speed_high_m_s", "margin_low_pct", "margin_high_pct", "v_top_m_s",
                 "v_top_min_m_s", "v_bottom_m_s", "load_bottom_g", "machine", "width_m", "phase_deg", "phase_from",
                 "window_lo_deg", "window_hi_deg", "safe_phases_deg", "in_the_way")
#: What the appended columns of ``riders`` say of a rider's phase:
#: ``phase_deg`` the phase ridden [deg] (a horizontal lane's azimuth at t =
#: 0, a vertical lane's psi from the top), ``phase_from`` 'plan' or 'auto'
#: (chosen by phase='auto'); for a phase chosen, ``window_lo_deg`` ..
#: ``window_hi_deg`` the run of safe phases holding it (lo > hi: across
#: 360), ``safe_phases_deg`` every run as text ('170-186 290-300'; 'none'),
#: and ``in_the_way`` when there is none the riders still closer than
#: min_clearance at the phase taken, ';' between names.
#: The columns of ``pairs``, in order; ``basis`` says how the least
#: clearance was found ('act': over the act's times; 'geometric': two
#: horizontal lanes of different rates sweep every relative phase, so both
#: riders in one meridian plane).
PAIR_COLUMNS = ("rider_a", "rider_b", "min_clearance_m", "t_s", "theta_a_deg", "phi_a_deg", "theta_b_deg",
                "phi_b_deg", "verdict", "drift_time_s", "basis", "height_a_m", "height_b_m", "closest_height_m",
                "closest_phi_deg")
#: ``height_a_m`` and ``height_b_m`` are the contacts' heights above the
#: floor at t_s, ``closest_height_m`` and ``closest_phi_deg`` those of the
#: point of closest approach (midway between the closest points of the two
#: envelopes' axes).
#: The columns of ``fall``, in order: a looper who swings reaches
#: ``swing_height_m`` (his contact's height above the floor at the swing's
#: highest point) and ``crosses_lane`` says whether the victim's lane meets
#: the arc he swings on (a horizontal lane no higher, every loop).
FALL_COLUMNS = ("rider", "t_fail_s", "speed_fraction", "outcome", "t_contact_lost_s", "theta_lost_deg",
                "phi_lost_deg", "t_land_s", "theta_land_deg", "phi_land_deg", "fall_time_s", "impact_speed_m_s",
                "victim", "min_clearance_m", "t_min_s", "hit", "swing_height_m", "crosses_lane", "height_lost_m",
                "height_land_m")
#: ``height_lost_m`` and ``height_land_m``: the heights above the floor of
#: the contact where it is lost and of the landing point (empty where he
#: does not fall).
#: The columns of the summary of ``falls``.
FALLS_SUMMARY_COLUMNS = ("rider", "victim", "falls", "hits", "hit_fraction", "impact_speed_max_m_s")
PHASES = ("plan", "auto")


@dataclass
class ShowResult:
    """An act planned: ``riders`` and ``pairs`` tables, the act's
    ``duration_s``, whether the riders' periods are ``commensurate``, each
    vertical rider's ``phase_windows`` (name -> list of (from, to) [deg] of
    safe phases; filled with phase='auto') and, for one with none, the
    riders ``in_the_way`` (name -> [names]), the checked ``plan`` and the
    ``lanes``."""

    plan: Plan
    lanes: list[Lane]
    riders: Table
    pairs: Table
    duration_s: float
    commensurate: bool
    phase_windows: dict = field(default_factory=dict)
    in_the_way: dict = field(default_factory=dict)

    @property
    def infeasible(self) -> dict:
        """{name: status} of the riders whose lane is not ok (the act cannot
        be ridden as planned)."""
        return {str(n): str(st) for n, st in zip(self.riders["name"], self.riders["status"]) if st != "ok"}

    def positions(self, t) -> dict:
        """Each rider's 'contact', 'head' and 'com' points (3, n) [m, the
        globe's frame] at the times t (n,) [s], by name (a two-wheeler's
        'contact' its rear contact, and the other ends of its envelope's
        segments: 'front_contact', 'rear_back', 'front_front', 'rear_top',
        'front_top'); ParameterError for
        a time that is not a finite number."""
        try:
            t = np.asarray(t, dtype=float).reshape(-1)
        except (TypeError, ValueError):
            raise ParameterError(f"t must be times in seconds (got {t!r})", "t") from None
        if not np.isfinite(t).all():
            bad = t[~np.isfinite(t)][0]
            raise ParameterError(f"t must be finite times in seconds (got {float(bad)!r})", "t")
        return {lane.name: {k: v for k, v in lane.kinematics(t).items()
                            if k in ("contact", "head", "com") or any(k in pair for pair in lane.segments)}
                for lane in self.lanes}

    def fall(self, rider: str, t: float, speed_fraction: float = 0.5) -> Table:
        """At time t [s] the rider's speed drops to ``speed_fraction`` (0 = a
        dead stop .. 1) of his speed at that instant, along his direction of
        travel: where he loses contact, where and when he lands, and for
        every other rider the least clearance [m] (to 1 mm) between the
        falling rider (a sphere of radius width/2 about his centre of mass)
        and that rider's envelope during the flight (docs/show.md).  Columns
        :data:`FALL_COLUMNS`, one row per other rider (one row with an empty
        victim when he is alone)."""
        from deathsphere.act.falls import refine_victim, simulate_falls

        names = [lane.name for lane in self.lanes]
        if rider not in names:
            raise ParameterError(f"rider must be one of {', '.join(names)} (got {rider!r})", "rider")
        # a time beyond the act is not in it (and an enormous one rounds the flight away)
        t = _number("t", t, 0.0, self.duration_s, " s (the act's times)")
        speed_fraction = _number("speed_fraction", speed_fraction, 0.0, 1.0)
        k = names.index(rider)
        res = _typed_heights(simulate_falls(self.lanes, self.plan.globe, [k], [t], [speed_fraction]),
                             self.plan, np.array([k]))
        base = _fall_base(res, 0, self.lanes[k].name, t, speed_fraction)
        rows = []
        for j, victim in enumerate(self.lanes):
            if j == k:
                continue
            c, when = float(res["clearance"][0, j]), float(res["t_min"][0, j])
            if math.isfinite(res["fall_time"][0]):
                c, when = refine_victim(self.lanes[k], victim, res["x0"][:, 0], res["v0"][:, 0],
                                        float(res["t_lost"][0]), float(res["fall_time"][0]), self.plan.globe.g)
            rows.append({**base, "victim": victim.name, "min_clearance_m": c, "t_min_s": when,
                         "hit": bool(c < 0), "crosses_lane": _crosses(victim, base["swing_height_m"])})
        if not rows:
            rows.append({**base, "victim": "", "min_clearance_m": math.nan, "t_min_s": math.nan, "hit": False,
                         "crosses_lane": False})
        return _rows_table(rows, FALL_COLUMNS)

    def fall_path(self, rider: str, t: float, speed_fraction: float = 0.5, points: int = 64) -> dict | None:
        """The flight of the fall :meth:`fall` reports, as points: ``t``
        (points,) [s] from contact lost to the landing and ``com`` (3,
        points) [m] his centre of mass there (the parabola from where and
        how he leaves the wall); None where he does not fly (he rides on or
        swings).  What the 3-D view draws on a drum or a cone, where the
        landing's height and azimuth do not fix the point (on the floor its
        distance from the axis is free)."""
        from deathsphere.act.falls import flight_point, simulate_falls

        names = [lane.name for lane in self.lanes]
        if rider not in names:
            raise ParameterError(f"rider must be one of {', '.join(names)} (got {rider!r})", "rider")
        t = _number("t", t, 0.0, self.duration_s, " s (the act's times)")
        speed_fraction = _number("speed_fraction", speed_fraction, 0.0, 1.0)
        res = simulate_falls(self.lanes, self.plan.globe, [names.index(rider)], [t], [speed_fraction])
        flight = float(res["fall_time"][0])
        if not math.isfinite(flight):
            return None
        s = np.linspace(0.0, flight, max(2, int(points)))
        return {"t": float(res["t_lost"][0]) + s, "com": flight_point(res["x0"], res["v0"], s, self.plan.globe.g)}

    def falls(self, n: int, seed: int = 0, scheduler=None, progress=None) -> tuple[Table, Table]:
        """Monte Carlo of ``n`` falls: a random rider (any: a single-contact
        machine or a two-wheeler, docs/show.md sec. 13), a random time in the
        act, a random speed fraction in [0, 1), drawn from ``seed``;
        evaluated vectorised, in chunks, on a dask.distributed cluster with
        ``scheduler`` (an address or a Client; the same rows in the same
        order as here).  Returns (outcomes, summary): outcomes one row per
        fall with :data:`FALL_COLUMNS`, its victim the rider he comes
        closest to (sampled at FLIGHT_SAMPLES instants of the flight);
        summary :data:`FALLS_SUMMARY_COLUMNS`: per falling rider and victim
        (an empty victim: any), how many falls, how many hit, the fraction,
        and the worst landing speed; the last row (both empty) all falls.
        ``progress(done, n)``, if given, is told the falls done, chunk by chunk."""
        from deathsphere.parallel import ordered_map
        from deathsphere.act.falls import fall_chunk

        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 1 <= n <= MAX_FALLS:
            raise ParameterError(f"n must be a whole number of falls 1..{MAX_FALLS} (got {n!r})", "n")
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
            raise ParameterError(f"seed must be a whole number >= 0 (got {seed!r})", "seed")
        rng = np.random.default_rng(int(seed))
        rider = rng.integers(0, len(self.lanes), int(n))
        t = rng.uniform(0.0, self.duration_s, int(n))
        fraction = rng.uniform(0.0, 1.0, int(n))
        client, own = (None, False)
        if scheduler is not None:
            from deathsphere.cluster import connect

            client, own = connect(scheduler)
        items = ((self.lanes, self.plan.globe, rider[s:s + FALLS_CHUNK], t[s:s + FALLS_CHUNK],
                  fraction[s:s + FALLS_CHUNK]) for s in range(0, int(n), FALLS_CHUNK))
        parts = []
        for part in ordered_map(fall_chunk, items, jobs=1, client=client, close=own):
            parts.append(part)
            if progress is not None:
                progress(min(int(n), FALLS_CHUNK * len(parts)), int(n))
        # (n,) and (3, n) arrays join along the falls, (n, riders) ones along their rows
        res = {key: np.concatenate([p[key] for p in parts], axis=0 if key in ("clearance", "t_min") else -1)
               for key in parts[0]}
        res = _typed_heights(res, self.plan, rider)
        return _outcomes_table(self, res, rider, t, fraction), _summary_table(self, res, rider)


#: The most falls one Monte Carlo draws, and how many are evaluated at once.
MAX_FALLS = 10_000_000
FALLS_CHUNK = 4096


def _typed_heights(res: dict, plan: Plan, rider) -> dict:
    """The falls' ``height_lost`` of riders on horizontal lanes as their
    heights were typed (contact is lost on the lane)."""
    typed = np.array(lane_heights(plan))[np.asarray(rider)]
    lost = np.isfinite(res["height_lost"]) & np.isfinite(typed)
    res["height_lost"] = np.where(lost, typed, res["height_lost"])
    return res


def _duration(value) -> float:
    """The act's duration [s] as the API takes a number: a number, a numpy
    scalar or text ("60"); ParameterError naming ``duration`` otherwise."""
    from deathsphere import units

    raw = value.item() if isinstance(value, np.generic) else value
    if isinstance(raw, str):
        try:
            raw = units.parse_value(raw, "none", "duration")
        except ParameterError:
            pass
    if isinstance(raw, bool) or not isinstance(raw, (int, float)) or not 0 < raw < math.inf:
        raise ParameterError(f"duration must be a number of seconds > 0 (got {value!r})", "duration")
    return float(raw)


def _number(name: str, value, lo: float, hi: float, what: str = "") -> float:
    """value as a float, or ParameterError naming ``name`` and the range (``what`` follows it)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) or not (
            lo <= value <= hi):
        raise ParameterError(f"{name} must be a number in [{lo:g}, {hi:g}]{what} (got {value!r})", name)
    return float(value)


def _fall_base(res: dict, i: int, name: str, t: float, fraction: float) -> dict:
    """The columns of a fall before the victim's, for fall i of ``res``."""
    from deathsphere.act.falls import outcome_names

    return {"rider": name, "t_fail_s": t, "speed_fraction": fraction,
            "outcome": str(outcome_names(res["outcome"][i:i + 1])[0]),
            **{col: float(res[key][i]) for col, key in (
                ("t_contact_lost_s", "t_lost"), ("theta_lost_deg", "theta_lost"), ("phi_lost_deg", "phi_lost"),
                ("t_land_s", "t_land"), ("theta_land_deg", "theta_land"), ("phi_land_deg", "phi_land"),
                ("fall_time_s", "fall_time"), ("impact_speed_m_s", "impact_speed"),
                ("swing_height_m", "swing_height"), ("height_lost_m", "height_lost"),
                ("height_land_m", "height_land"))}}


def _crosses(victim: Lane, swing_height: float) -> bool:
    """Whether a swing up to ``swing_height`` [m] (NaN: no swing) meets the
    victim's lane: the arc through the floor reaches every height up to it on
    both sides of the loop, where every horizontal lane no higher and every
    loop (through the floor) pass."""
    if not math.isfinite(swing_height):
        return False
    if victim.kind == "vertical":
        return True
    return victim.orbit["height"] <= swing_height


_TEXT = {"name", "lane", "status", "reason", "machine", "rider_a", "rider_b", "verdict", "basis", "rider", "outcome",
         "victim", "phase_from", "safe_phases_deg", "in_the_way"}


def _rows_table(rows: list[dict], columns) -> Table:
    def kind(c):
        return object if c in _TEXT else bool if c in ("hit", "crosses_lane") else float
    return Table({c: np.array([r[c] for r in rows], dtype=kind(c)) for c in columns})


def _outcomes_table(result: ShowResult, res: dict, rider, t, fraction) -> Table:
    """One row per fall of the Monte Carlo, its victim the closest rider."""
    from deathsphere.act.falls import outcome_names

    names = np.array([lane.name for lane in result.lanes], dtype=object)
    clear = res["clearance"]
    flying = np.isfinite(clear).any(axis=1)
    closest = np.argmin(np.where(np.isfinite(clear), clear, np.inf), axis=1)
    rows = np.arange(rider.size)
    least = np.where(flying, clear[rows, closest], np.nan)
    cols = {"rider": names[rider], "t_fail_s": t, "speed_fraction": fraction, "outcome": outcome_names(res["outcome"]),
            "t_contact_lost_s": res["t_lost"], "theta_lost_deg": res["theta_lost"], "phi_lost_deg": res["phi_lost"],
            "t_land_s": res["t_land"], "theta_land_deg": res["theta_land"], "phi_land_deg": res["phi_land"],
            "fall_time_s": res["fall_time"], "impact_speed_m_s": res["impact_speed"],
            "victim": np.where(flying, names[closest], ""), "min_clearance_m": least,
            "t_min_s": np.where(flying, res["t_min"][rows, closest], np.nan), "hit": flying & (least < 0),
            "swing_height_m": res["swing_height"], "height_lost_m": res["height_lost"],
            "height_land_m": res["height_land"],
            "crosses_lane": _crosses_any(result.lanes, rider, res["swing_height"])}
    return Table({c: np.asarray(cols[c], dtype=object if c in _TEXT else None) for c in FALL_COLUMNS})


def _crosses_any(lanes, rider, swing_height) -> np.ndarray:
    """Per fall of the Monte Carlo: his swing meets another rider's lane (:func:`_crosses`)."""
    swings = np.isfinite(swing_height)
    reach = np.where(swings, swing_height, -np.inf)
    out = np.zeros(rider.size, dtype=bool)
    for k, lane in enumerate(lanes):
        low = -np.inf if lane.kind == "vertical" else lane.orbit["height"]
        out |= swings & (rider != k) & (low <= reach)
    return out


def _summary_table(result: ShowResult, res: dict, rider) -> Table:
    """Per falling rider and victim: falls, hits, their fraction, the worst
    landing speed (the falls of that rider that fly)."""
    names = [lane.name for lane in result.lanes]
    hits = np.where(np.isfinite(res["clearance"]), res["clearance"], np.inf) < 0      # (n, riders)
    speed = res["impact_speed"]
    rows = []

    def add(who, victim, sel, hit):
        count, n_hit = int(sel.sum()), int((hit & sel).sum())
        worst = speed[sel & np.isfinite(speed)]
        rows.append({"rider": who, "victim": victim, "falls": count, "hits": n_hit,
                     "hit_fraction": n_hit / count if count else math.nan,
                     "impact_speed_max_m_s": float(worst.max()) if worst.size else math.nan})

    anyone = hits.any(axis=1)
    for k, name in enumerate(names):
        mine = rider == k
        add(name, "", mine, anyone)
        for j, victim in enumerate(names):
            if j != k:
                add(name, victim, mine, hits[:, j])
    everyone = np.ones(rider.size, dtype=bool)
    for j, victim in enumerate(names):
        add("", victim, everyone, hits[:, j])
    add("", "", everyone, anyone)
    return Table({c: np.array([r[c] for r in rows], dtype=object if c in ("rider", "victim") else
                              np.int64 if c in ("falls", "hits") else float) for c in FALLS_SUMMARY_COLUMNS})


def _decimal(x: float):
    """x as the decimal its shortest text reads (282.3, not 282.29999...)."""
    from decimal import Decimal

    return Decimal(repr(float(x)))


def loop_start_angles(phase_deg: float, azimuth_deg: float) -> tuple[float, float]:
    """(theta, phi) [deg] of a vertical lane's contact at t = 0, from its
    phase psi (from the top) and its plane's azimuth, in decimal arithmetic
    on the values as typed, so that they echo them: psi 178 is theta 178
    (not 177.99999999999986 through the contact's coordinates), 282.3 is
    theta 77.7 on the far side (phi = azimuth + 180).  At the top or the
    bottom, where phi is not defined, phi is the loop's azimuth."""
    psi = _decimal(phase_deg) % 360              # a Decimal's remainder keeps the dividend's sign
    psi = psi + 360 if psi < 0 else psi
    azimuth = _decimal(azimuth_deg)
    if psi <= 180:
        theta, phi = psi, azimuth
    else:
        theta, phi = 360 - psi, azimuth + 180
    phi = phi % 360
    return float(theta), float(phi + 360 if phi < 0 else phi)


def horizontal_start_angles(rider, lane: Lane, ground) -> tuple[float, float]:
    """(theta, phi) [deg] of a horizontal lane's contact at t = 0, echoing
    the plan: theta as typed (a lane given by its height: from the
    contact's coordinates; NaN on a drum or a cone), phi the phase as typed
    in 0..360 in decimal arithmetic (phi = phase +- Omega t: 120 is 120,
    not 119.99999999999999 through the contact's coordinates)."""
    from deathsphere import requests
    from deathsphere.act.pairs import contact_angles

    theta, _ = contact_angles(lane, 0.0, ground)
    if isinstance(getattr(rider.request.lane, "at", None), requests.Theta) and not math.isnan(theta):
        theta = float(rider.theta_deg)
    phi = _decimal(rider.phase_deg) % 360          # a Decimal's remainder keeps the dividend's sign
    return theta, float(phi + 360 if phi < 0 else phi)


def _rider_row(lane: Lane, rider, band, ground) -> dict:
    """The riders table's row of one lane (its orbit as ``ride`` reports it,
    the speed band)."""
    orbit, nan = lane.orbit, math.nan
    if lane.kind == "vertical":
        theta0, phi0 = loop_start_angles(rider.phase_deg, rider.azimuth_deg)
    else:
        theta0, phi0 = horizontal_start_angles(rider, lane, ground)
    out = {"name": lane.name, "lane": lane.kind, "theta_deg": theta0, "phi0_deg": phi0, "machine": lane.machine.name,
           "width_m": lane.width_m, "status": lane.status, "reason": lane.reason,
           "mu_required": orbit["mu_required"], "head_clearance_m": orbit["head_clearance"],
           # a lap time as planned (the lane's, solved, agrees to ROOT_MATCH_RTOL)
           "period_s": rider.period if math.isfinite(getattr(rider, "period", math.nan)) else lane.period_s}
    if lane.kind == "horizontal":
        # a speed as planned (ride echoes a speed asked for); the band is of the contact's
        planned = rider.speed if math.isfinite(rider.speed) else orbit["v_contact"]
        v_cm = rider.com_speed if math.isfinite(rider.com_speed) else orbit["v_cm"]
        out.update(alpha_deg=orbit["alpha_deg"], lean_deg=90.0 - orbit["alpha_deg"], v_cm_m_s=v_cm,
                   v_contact_m_s=planned, load_g=orbit["load_g"], v_top_m_s=nan, v_top_min_m_s=nan,
                   v_bottom_m_s=nan, load_bottom_g=nan)
    else:
        planned = rider.v_top
        r_g = orbit["r_g"]
        out.update(alpha_deg=nan, lean_deg=0.0, v_cm_m_s=planned, v_contact_m_s=planned * ground.radius / r_g,
                   load_g=orbit["load_bottom"], v_top_m_s=planned, v_top_min_m_s=orbit["v_top_min"],
                   v_bottom_m_s=orbit["v_bottom"], load_bottom_g=orbit["load_bottom"])
    out["v_cm_km_h"] = round(out["v_cm_m_s"] * 3.6, 9)
    low, high = band
    out.update(speed_low_m_s=low, speed_high_m_s=high, margin_low_pct=100.0 * (planned - low) / planned,
               margin_high_pct=100.0 * (high - planned) / planned)
    return out


def _window_holding(phase: float, windows) -> tuple[float, float]:
    """The run of safe phases (lo, hi) [deg] holding ``phase`` (lo > hi:
    across 360), NaN when none does."""
    for lo, hi in windows:
        if (lo <= phase <= hi) if lo <= hi else (phase >= lo or phase <= hi):
            return float(lo), float(hi)
    return math.nan, math.nan


def _phase_columns(rider, windows: dict, in_the_way: dict) -> dict:
    """The riders table's phase columns of one rider (:data:`RIDER_COLUMNS`)."""
    name, phase = rider.name, rider.phase_deg
    if name not in windows:
        return {"phase_deg": phase, "phase_from": "plan", "window_lo_deg": math.nan, "window_hi_deg": math.nan,
                "safe_phases_deg": "", "in_the_way": ""}
    runs = windows[name]
    lo, hi = _window_holding(phase, runs)
    return {"phase_deg": phase, "phase_from": "auto", "window_lo_deg": lo, "window_hi_deg": hi,
            "safe_phases_deg": " ".join(f"{a:.6g}-{b:.6g}" for a, b in runs) or "none",
            "in_the_way": ";".join(in_the_way.get(name, []))}


def riders_table(plan: Plan, lanes: list[Lane], windows: dict | None = None, in_the_way: dict | None = None) -> Table:
    """The ``riders`` table (columns :data:`RIDER_COLUMNS`), one row per
    rider in the plan's order; ``windows`` and ``in_the_way`` those of
    phase='auto' (by name) for the riders whose phase it chose."""
    from deathsphere.act.margins import speed_bands

    planned = [(r.speed if math.isfinite(r.speed) else lane.orbit["v_contact"]) if r.lane == "horizontal"
               else r.v_top for r, lane in zip(plan.riders, lanes)]
    bands = speed_bands(lanes, plan.globe, planned)
    ground = plan.globe.ground
    rows = [{**_rider_row(lane, rider, band, ground), **_phase_columns(rider, windows or {}, in_the_way or {})}
            for lane, rider, band in zip(lanes, plan.riders, bands)]
    return _rows_table(rows, RIDER_COLUMNS)


def lane_heights(plan: Plan) -> list[float]:
    """Each rider's contact height above the floor [m] on a horizontal lane,
    as typed when the plan gives it (else from his theta); NaN on a
    vertical lane (his height changes)."""
    from deathsphere import requests

    out = []
    for rider in plan.riders:
        at = getattr(rider.request.lane, "at", None)
        if rider.lane != "horizontal":
            out.append(math.nan)
        elif isinstance(at, requests.Height):
            out.append(float(at.height))
        else:
            out.append(float(plan.globe.ground.height(math.radians(rider.theta_deg))))
    return out


def pairs_table(lanes: list[Lane], duration: float, min_clearance: float, drift: bool = True, *,
                ground, heights=None, done=None) -> Table:
    """The ``pairs`` table (columns :data:`PAIR_COLUMNS`): every pair (a before
    b in the plan), its least clearance over the act, when and where, the
    verdict and the drift time (NaN: never), the heights where it happens;
    ``ground`` the globe (its contact angles), ``heights`` the horizontal
    lanes' heights as typed (:func:`lane_heights`; NaN: from the contact);
    ``done(n)``, if given, is told of n more pairs found (a progress bar)."""
    done = done or (lambda n: None)
    from deathsphere.act.pairs import act_pairs, contact_angles, least_clearance, least_clearances, clearance_verdict, where_closest
    from deathsphere.act.timing import drift_time

    over_time = act_pairs(lanes)
    found = dict(zip(over_time, ((c, t, "act") for c, t in least_clearances(lanes, over_time, duration))))
    done(len(over_time))
    rows = []
    for i, a in enumerate(lanes):
        for j in range(i + 1, len(lanes)):
            b = lanes[j]
            c, t, basis = found[(i, j)] if (i, j) in found else least_clearance(a, b, duration)
            (ta, pa), (tb, pb) = contact_angles(a, t, ground), contact_angles(b, t, ground)
            v = clearance_verdict(c, min_clearance)
            dt = drift_time(a, b, min_clearance) if drift and v == "clear" else math.nan
            where = where_closest(a, b, t, ground)
            for key, k in (("height_a", i), ("height_b", j)):
                if heights is not None and math.isfinite(heights[k]):
                    where[key] = heights[k]           # a horizontal lane's contact stays at its height, as typed
            rows.append({"rider_a": a.name, "rider_b": b.name, "min_clearance_m": c, "t_s": t, "theta_a_deg": ta,
                         "phi_a_deg": pa, "theta_b_deg": tb, "phi_b_deg": pb, "verdict": v,
                         "drift_time_s": dt if math.isfinite(dt) else math.nan, "basis": basis,
                         "height_a_m": where["height_a"], "height_b_m": where["height_b"],
                         "closest_height_m": where["height"], "closest_phi_deg": where["phi"]})
            if (i, j) not in found:
                done(1)
    return _rows_table(rows, PAIR_COLUMNS)


def show(plan, *, duration=None, phase: str = "plan", progress=None) -> ShowResult:
    """Plan an act (docs/show.md): ``plan`` a path to a TOML file or a dict
    ({"globe": {...}, "rider": [...]}; {"arena": {...}, ...} on a drum or a
    cone, sec. 11); ``duration`` [s] the act's length
    when the riders' periods are not commensurate (over the plan's
    ``duration``; the common period is used whenever they are); ``phase``
    'plan' (the plan's phases) or 'auto' (each vertical rider's phase, in
    plan order, maximising his least clearance; ``phase_windows`` then holds
    the safe phases).  A bad plan raises ParameterError, one line naming the
    rider and the key (its ``param`` None: a plan's key is not an argument
    here), before any work.  ``progress(done, total)``, if given, is told
    the steps done (the riders, each vertical rider timed, each pair).

    >>> import deathsphere
    >>> act = deathsphere.show({"globe": {"diameter": "16ft", "mu": 0.9}, "rider": [
    ...     {"name": "Ana", "lane": "horizontal", "height": "2m", "speed": "32km/h"}]})
    >>> act.riders["status"].tolist(), len(act.pairs)
    (['ok'], 0)
    """
    from deathsphere.act.pairs import act_duration
    from deathsphere.act.timing import auto_phases

    if phase not in PHASES:
        raise ParameterError(f"phase must be plan or auto (got {phase!r})", "phase")
    if duration is not None:
        duration = _duration(duration)
    try:
        plan = read_plan(plan)
        lanes = build_lanes(plan)
    except ParameterError as exc:
        # a plan's key (its message names it: "rider 'Ben': phase: ..."), not this function's argument of one name
        raise ParameterError(str(exc), None) from None
    try:
        span, commensurate = act_duration(lanes, plan.globe.duration if duration is None else duration)
    except ValueError as exc:
        raise ParameterError(str(exc), "duration") from None
    n = len(lanes)
    steps = [0, 1 + n * (n - 1) // 2 + (sum(lane.kind == "vertical" for lane in lanes) if phase == "auto" else 0)]

    def step(k: int = 1) -> None:
        steps[0] += k
        if progress is not None:
            progress(steps[0], steps[1])

    windows, in_the_way = {}, {}
    if phase == "auto":
        phases, windows, in_the_way = auto_phases(lanes, span, plan.globe.min_clearance, timed=step)
        plan = plan.with_phases(phases)
        lanes = build_lanes(plan)
    riders = riders_table(plan, lanes, windows, in_the_way)
    step()
    pairs = pairs_table(lanes, span, plan.globe.min_clearance, ground=plan.globe.ground, heights=lane_heights(plan),
                        done=step)
    return ShowResult(plan=plan, lanes=lanes, riders=riders, pairs=pairs, duration_s=span,
                      commensurate=commensurate, phase_windows=windows, in_the_way=in_the_way)
