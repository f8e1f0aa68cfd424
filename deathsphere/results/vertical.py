"""Vertical orbits of a wheel as result tables (sec. 2.2.1; sec. 3, eq. 82).

A request is a vertical circle (cone angle ``theta`` about a horizontal
axis, 90 deg = great circle) and the wheel's speed at the top (``v_top`` of
its centre, or the rate ``phidot_top``).  :func:`evaluate_vertical` gives one
summary row per request; :func:`vertical_points` the orbit point by point.

The summary shares the orbit contract's columns where the meaning carries
over (rates and speeds are taken at the top, accelerations at the bottom where
they peak, forces and mu at the worst point, where mu peaks), then adds its
own.  Physics: :mod:`deathsphere.physics.vertical_orbit`.
"""

from __future__ import annotations

import math

import numpy as np

from deathsphere import params
from deathsphere.model import COLUMNS as ORBIT_COLUMNS
from deathsphere.model import (
    NOT_ANALYSED_K0,
    REQUEST_FIELDS,
    Table,
    echo_given,
    finite_or_blank,
    make_requests,
    validate_requests,
)
from deathsphere.physics import vertical_orbit
from deathsphere.physics.stability import methods
from deathsphere.physics.status import REASON_TEXT, STATUS_LABELS, Status
from deathsphere.records.paper_bodies import WHEEL
from deathsphere.requests.decode import as_typed

#: Request fields of a vertical orbit (CSV header names for --input).
VERTICAL_FIELDS = {
    "side": REQUEST_FIELDS["side"],
    "theta": (None, "deg", "cone angle of the orbit about the horizontal axis, 0..180 (90: great circle)"),
    "v_top": (None, "m/s", "speed of the wheel's centre at the top"),
    "phidot_top": (None, "rad/s", "orbital rate at the top"),
    **{name: REQUEST_FIELDS[name] for name in ("a", "r", "g", "mu")},
    # a vertical orbit is a wheel's: its inertia factor defaults to the wheel's
    "k": (WHEEL.default_k, *REQUEST_FIELDS["k"][1:]),
}

#: Summary columns: the orbit contract's first 22 (without omega3/branch),
#: then the vertical-orbit columns.
#: The friction there is a magnitude (its along-track and meridional parts
#: are the ``--points`` columns), not the orbit's signed F_theta/m: hence its
#: own name.
COLUMNS = tuple("friction_magnitude_per_mass_m_s2" if c == "friction_per_mass_m_s2" else c
                for c in ORBIT_COLUMNS[: ORBIT_COLUMNS.index("mu_available") + 1]) + (
    "v_top_min_m_s", "omega_top_min_rad_s", "v_bottom_m_s", "phi_worst_deg", "mu_top",
    "normal_top_per_mass_m_s2", "normal_bottom_per_mass_m_s2", "phi_leave_deg", "phi_slip_deg",
    "stability", "stability_method", "growth_rate_1_s",
)

FLOQUET_METHOD = methods.FLOQUET


#: Point-by-point columns (``--points N``).
POINT_COLUMNS = (
    "input_row", "theta_deg", "phi_deg", "status", "reason", "omega_rad_s", "v_cm_m_s", "accel_m_s2",
    "normal_per_mass_m_s2", "friction_along_per_mass_m_s2", "friction_meridional_per_mass_m_s2",
    "mu_required",
)

SUMMARY_KEYS = {
    "r_prime": "r_prime_m", "omega": "omega_rad_s", "period": "period_s", "v_cm": "v_cm_m_s",
    "spin": "spin_rad_s", "accel": "accel_m_s2", "accel_g": "accel_g", "normal": "normal_per_mass_m_s2",
    "friction": "friction_magnitude_per_mass_m_s2", "mu_required": "mu_required", "v_min": "v_top_min_m_s",
    "omega_min": "omega_top_min_rad_s", "v_bottom": "v_bottom_m_s", "mu_top": "mu_top",
    "normal_top": "normal_top_per_mass_m_s2", "normal_bottom": "normal_bottom_per_mass_m_s2",
}
ANGLE_KEYS = {"phi_worst": "phi_worst_deg", "phi_leave": "phi_leave_deg", "phi_slip": "phi_slip_deg"}


def vertical_requests(n: int, invalid=None, input_row=None, v_top=None, phidot_top=None, **fields) -> dict:
    """A vertical-orbit request batch: an orbit request of a wheel in the
    orbit plane (alpha = 0 inside, 180 deg outside) plus the top speed/rate."""
    side = np.broadcast_to(np.asarray(fields.pop("side", "inside"), dtype=object), (n,))
    req = make_requests(n, invalid=invalid, input_row=input_row, body=WHEEL, side=side,
                        alpha=np.where(side == "outside", 180.0, 0.0), **fields)
    for name, value in (("v_top", v_top), ("phidot_top", phidot_top)):
        req[name] = np.broadcast_to(np.asarray(math.nan if value is None else value, dtype=float), (n,)).copy()
    return req


def validate_vertical(req) -> np.ndarray:
    """Each vertical request's reason to be invalid ('' if valid): the orbit
    request's checks, then exactly one of v_top and phidot_top, in bounds."""
    reason = validate_requests(req)
    v, w = req["v_top"], req["phidot_top"]
    both_or_none = np.isnan(v) == np.isnan(w)
    for i in np.flatnonzero((reason == "") & both_or_none):
        reason[i] = "give exactly one of v_top (m/s) and phidot_top (rad/s)"
    typed = req.get("typed", {})
    for name, given in (("v_top", ~np.isnan(v)), ("phidot_top", ~np.isnan(w))):
        rows = np.flatnonzero((reason == "") & given)
        reason[rows] = [as_typed(name, words, typed) for words in params.problems(name, req[name][rows])]
    return reason


def _top_rate(req, rows):
    theta = np.deg2rad(req["theta"][rows])
    outside = req["side"][rows] == "outside"
    from_speed = vertical_orbit.top_rate_from_speed(req["v_top"][rows], theta, req["a"][rows], req["r"][rows], outside)
    with np.errstate(invalid="ignore"):
        return theta, outside, np.where(np.isnan(req["v_top"][rows]), np.abs(req["phidot_top"][rows]), from_speed)


def summary_arrays(reason_words, evaluate) -> tuple:
    """(out, status, reason) of a loop's summary rows: every request's
    :data:`SUMMARY_KEYS` and :data:`ANGLE_KEYS` columns (angles in degrees),
    filled where ``reason_words`` is empty from ``evaluate(rows)`` (the
    physics, on the globe or round a profile's loop), an invalid row keeping
    its reason."""
    n = len(reason_words)
    rows = np.flatnonzero(reason_words == "")
    out = {col: np.full(n, np.nan) for col in list(SUMMARY_KEYS.values()) + list(ANGLE_KEYS.values())}
    status = np.full(n, Status.INVALID, dtype=np.int8)
    reason = reason_words.astype(object)
    if rows.size:
        res = evaluate(rows)
        for key, col in SUMMARY_KEYS.items():
            out[col][rows] = res[key]
        for key, col in ANGLE_KEYS.items():
            out[col][rows] = np.rad2deg(res[key])
        status[rows] = res["status"]
        reason[rows] = REASON_TEXT[res["reason"]]
    return out, status, reason


def evaluate_vertical(req: dict, stability: bool = True) -> Table:
    """One summary row per request, in input order (invalid rows kept, with reasons).

    With ``stability``, orbits that keep contact (status ok or slips; inside:
    outside no vertical orbit closes) get their exact stability from the
    Floquet multipliers of the linearised equations of motion over one lap
    (beyond the paper, docs/stability.md sec. 2); ``growth_rate_1_s`` is
    log(max |multiplier|) / lap time."""
    n = len(req["theta"])

    def evaluate(rows):
        theta, outside, rate = _top_rate(req, rows)
        return vertical_orbit.vertical_orbit(theta, rate, req["a"][rows], req["r"][rows], req["k"][rows],
                                             req["g"][rows], outside, req["mu"][rows])

    out, status, reason = summary_arrays(validate_vertical(req), evaluate)
    verdict = np.full(n, "", dtype=object)
    method = np.full(n, "", dtype=object)
    growth = np.full(n, np.nan)
    live = np.flatnonzero(np.isin(status, (Status.OK, Status.SLIPS)) & (req["side"] == "inside"))
    if stability:
        # k = 0 (no rotational inertia) makes the equations of motion singular
        singular = live[req["k"][live] == 0]
        verdict[singular] = "unknown"
        method[singular] = NOT_ANALYSED_K0
        live = live[req["k"][live] > 0]
    if stability and live.size:
        from deathsphere.physics.stability import VERDICT_LABELS, vertical_floquet

        floquet = vertical_floquet(np.deg2rad(req["theta"][live]), out["omega_rad_s"][live], req["a"][live],
                                   req["r"][live], req["k"][live], req["g"][live])
        verdict[live] = VERDICT_LABELS[floquet["verdict"]]
        method[live] = FLOQUET_METHOD
        growth[live] = floquet["growth_rate"]
    columns = {
        "stability": verdict, "stability_method": method, "growth_rate_1_s": growth,
        "input_row": req["input_row"].astype(np.int64), "body": req["body"], "side": req["side"],
        "theta_deg": req["theta"], "alpha_deg": req["alpha"], "a_m": req["a"], "r_m": req["r"],
        "k": req["k"], "g_m_s2": req["g"], "status": STATUS_LABELS[status], "reason": reason,
        "mu_available": np.where(np.isinf(req["mu"]), np.nan, req["mu"]),
        **out,
    }
    finite_or_blank(columns)
    # the top speed or rate given is printed as given (v / r' * r' may differ
    # in the last bit; a wheel that does not fit computes none)
    echo_given(columns, {"v_cm_m_s": req["v_top"], "omega_rad_s": req["phidot_top"]})
    return Table({name: columns[name] for name in COLUMNS})


def phi_degrees(points: int) -> np.ndarray:
    """The azimuths of :func:`~deathsphere.physics.vertical_orbit.phi_grid`
    in degrees as the table writes them: k x 360 / (points - 1), each the
    float nearest that fraction (``--points 13``: 0, 30, ..., 120, not the
    119.99999999999999 of the radians' grid turned back into degrees); the
    radians the physics is evaluated at are within a rounding of them."""
    k = np.arange(int(points), dtype=float)
    return k * 360.0 / (int(points) - 1) if points > 1 else k


def vertical_points(req: dict, points: int, start: int = 0, stop: int | None = None) -> Table:
    """The orbit point by point: ``points`` azimuths phi from the top (0 deg)
    round to 360 deg for every valid request (rows grouped by request, in
    input order); an invalid request gives one row with its reason.

    ``start:stop`` picks a slice of the azimuths, so that a long orbit can be
    written piece by piece in bounded memory; an invalid request's row comes
    with the slice that starts at 0."""
    def evaluate(rows, phi):
        theta, outside, rate = _top_rate(req, rows)
        return vertical_orbit.vertical_profile(phi[None, :], theta[:, None], rate[:, None], req["a"][rows, None],
                                               req["r"][rows, None], req["k"][rows, None], req["g"][rows, None],
                                               outside[:, None], req["mu"][rows, None])

    columns, order = point_columns(req, validate_vertical(req), vertical_orbit.phi_grid(points), points, start,
                                   stop, evaluate, ("v_cm_m_s", "omega_rad_s"))
    return Table({name: columns[name][order] for name in POINT_COLUMNS})


#: The physics' keys of a loop's points and the columns they fill.
POINT_KEYS = (("omega", "omega_rad_s"), ("v_cm", "v_cm_m_s"), ("accel", "accel_m_s2"),
              ("normal", "normal_per_mass_m_s2"), ("along", "friction_along_per_mass_m_s2"),
              ("meridional", "friction_meridional_per_mass_m_s2"), ("mu_required", "mu_required"))


def point_columns(req: dict, reason_words, phi_all, points: int, start: int, stop, evaluate, echoed) -> tuple:
    """(columns, row order) of a loop's points table: ``points`` angles phi
    (``phi_all`` [rad], sliced ``start:stop``) for every valid request
    (``reason_words`` empty), rows grouped by request, an invalid request's
    one row with the slice that starts at 0; ``evaluate(rows, phi)`` the
    physics (on the globe or round a profile's loop), its dict of
    :data:`POINT_KEYS`, ``status`` and ``reason`` of shape (rows, phi); at the
    top (phi = 0 and 360 deg) the ``echoed`` columns given print as given."""
    rows = np.flatnonzero(reason_words == "")
    phi = phi_all[start:stop]
    bad = np.flatnonzero(reason_words != "") if start == 0 else np.empty(0, dtype=np.int64)
    source = np.concatenate([np.repeat(rows, phi.size), bad])
    m = rows.size * phi.size
    cols = {c: np.full(source.size, np.nan) for c in POINT_COLUMNS[5:]}
    status = np.full(source.size, Status.INVALID, dtype=np.int8)
    reason = np.empty(source.size, dtype=object)
    reason[m:] = reason_words[source[m:]]
    phi_col = np.full(source.size, np.nan)
    if rows.size:
        res = evaluate(rows, phi)
        for key, col in POINT_KEYS:
            cols[col][:m] = np.asarray(res[key]).reshape(-1)
        status[:m] = np.asarray(res["status"]).reshape(-1)
        reason[:m] = REASON_TEXT[np.asarray(res["reason"]).reshape(-1)]
        phi_col[:m] = np.tile(phi_degrees(points)[start:stop], rows.size)
    order = np.argsort(source, kind="stable")
    columns = {
        "input_row": req["input_row"][source].astype(np.int64), "theta_deg": req["theta"][source],
        "phi_deg": phi_col, "status": STATUS_LABELS[status], "reason": reason, **cols,
    }
    given = {"v_cm_m_s": "v_top", "omega_rad_s": "phidot_top"}
    top = (phi_col == 0.0) | (phi_col == 360.0)
    echo_given(columns, {col: np.where(top, req[given[col]][source], np.nan) for col in echoed})
    return columns, order
