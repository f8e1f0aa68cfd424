"""Result tables of ``limits`` on a surface other than the globe: the
feasible tilts on a lane, and the lowest and highest lanes (beyond the
paper; method in docs/limits.md sec. 8, physics in
:mod:`deathsphere.physics.lane_region`)."""

from __future__ import annotations

import math

import numpy as np

from deathsphere.physics import lane_region
from deathsphere.physics.status import REASON_TEXT, STATUS_LABELS, Reason, Status
from deathsphere.records.paper_bodies import WHEEL
from deathsphere.requests.decode import paper_body_codes
from deathsphere.results.limits import NOT_A_WHEEL, _degrees, _limit, _speed, interval_rows
from deathsphere.table import Table

#: The request fields of ``limits --surface`` (an --input file's columns).
LANE_LIMITS_FIELDS = ("body", "side", "height", "a", "k", "g", "mu", "max_g")

#: What ends the range of lanes, in words (no commas: awk -F, safe).
BOUND_NOTES = {
    "floor": "the floor: the lowest lane of the ground",
    "top": "the ground's highest lane (the wall's top or a cone's apex or a profile's last sample)",
    "limits": "where the last feasible tilt closes (fit or floor or contact or friction or load)",
    "none": "no highest lane within mu and max_g: every lane scanned is feasible and the ground has no "
            "highest lane (a drum's or a cone's: give wall_height)",
}
#: Added where the range reaches the floor but no tilt is feasible on it.
APPROACHED_NOTE = " (approached: feasible on every lane just above it but not on it)"
#: Added where the wall is upright at both ends of the range.
UPRIGHT_NOTE = ("; on an upright wall mu_required = g r'/v^2 and the load do not depend on the lane's height: "
                "friction and load set no highest lane and only the wall's top does")


def _lane_geometry(ground, height):
    from deathsphere.physics.revolution import lane

    where = lane(ground, np.asarray(height, dtype=float))
    return where["z"] - ground.lowest, where["rho"], np.rad2deg(where["wall_angle"])


def intervals_on(ground, height: np.ndarray, a, k, g, outside, mu, max_g) -> Table:
    """The open intervals of alpha with a feasible orbit on each lane, with
    the speed range over each; a lane without any gives one row with
    ``intervals`` = 0."""
    iv = lane_region.allowed_alpha_on(ground, height, a, k, g, outside, mu, max_g)
    row, j, count, present, lo, hi, vmin, vmax = interval_rows(iv)
    lift, rho, beta = _lane_geometry(ground, np.asarray(height, dtype=float).reshape(-1)[row])
    off = np.asarray(height, dtype=float).reshape(-1)[row]
    on_wall = (off >= 0) & (off <= getattr(ground, "highest_lane", math.inf))
    n = row.size
    return Table({
        "height_m": np.where(on_wall, lift, np.nan), "intervals": count[row],
        "interval": np.where(present, j + 1, 0),
        "alpha_min_deg": _degrees(lo), "alpha_max_deg": _degrees(hi),
        "v_min_m_s": _speed(vmin), "v_max_m_s": np.where(np.isinf(vmax), np.nan, _speed(vmax)),
        "a_m": np.full(n, a), "k": np.full(n, k),
        "mu_available": np.full(n, _limit(mu)), "max_g": np.full(n, _limit(max_g)),
        "surface": np.full(n, ground.name, dtype=object),
        "rho_contact_m": np.where(on_wall, rho, np.nan), "wall_angle_deg": np.where(on_wall, beta, np.nan),
    })


def lanes_on(ground, a, k, g, outside, mu, max_g) -> Table:
    """The lowest and the highest lane with a feasible tilt, one row each
    (``lane``), with what ends the range there (``bound``) and the first
    allowed interval of alpha on that lane and its speed range."""
    found = lane_region.lane_range(ground, a, k, g, outside, mu, max_g)
    heights = np.array([found.lowest, found.highest])
    finite = np.isfinite(heights)
    iv = lane_region.allowed_alpha_on(ground, np.where(finite, heights, 0.0), a, k, g, outside, mu, max_g)
    lift, rho, beta = _lane_geometry(ground, np.where(finite, heights, 0.0))
    first = [iv.intervals(i)[0] if finite[i] and iv.count[i] else (math.nan,) * 4 for i in range(2)]
    bounds = [found.lowest_bound, found.highest_bound]
    upright = found.found and bool(np.all(np.abs(np.rad2deg(ground.wall_angle(
        np.array([found.lowest, min(found.highest, found.scan_top)]))) - 90.0) < 1e-12))
    notes = []
    for bound in bounds:
        if not found.found:
            notes.append("no feasible tilt on any lane within mu and max_g")
        else:
            approached = bound == "floor" and not iv.count[bounds.index(bound)]
            notes.append(BOUND_NOTES[bound] + (APPROACHED_NOTE if approached else "")
                         + (UPRIGHT_NOTE if upright and bound in ("top", "none") else ""))
    keep = finite & found.found
    return Table({
        "lane": np.array(["lowest", "highest"], dtype=object),
        "found": np.array([found.found] * 2),
        "height_m": np.where(keep, lift, np.nan),
        "rho_contact_m": np.where(keep, rho, np.nan), "wall_angle_deg": np.where(keep, beta, np.nan),
        "bound": np.array(bounds, dtype=object),
        "alpha_min_deg": _degrees(np.array([f[0] for f in first])),
        "alpha_max_deg": _degrees(np.array([f[1] for f in first])),
        "v_min_m_s": _speed(np.array([f[2] for f in first])),
        "v_max_m_s": np.array([_limit(f[3]) for f in first]),
        "a_m": np.full(2, a), "k": np.full(2, k), "mu_available": np.full(2, _limit(mu)),
        "max_g": np.full(2, _limit(max_g)), "surface": np.full(2, ground.name, dtype=object),
        "note": np.array(notes, dtype=object),
    })


def lane_limits_rows(req: dict, ground, lanes: bool) -> Table:
    """The limits of every request of ``req`` (flat arrays of
    :data:`LANE_LIMITS_FIELDS`, ``input_row`` and ``invalid`` reasons) on
    ``ground``, in request order: with ``lanes`` the lowest and highest
    lane of each (two rows), else the intervals of alpha on each request's
    lane (a row per interval, one for a lane without any).  Requests are
    grouped by setup, one vectorised search per distinct setup; a request
    that is invalid, or not a wheel's, is one row with the reason."""
    from deathsphere.model import validate_requests

    n = len(req["input_row"])
    reason = req["invalid"].copy()
    probe = dict(req, ground=ground)
    probe["alpha"] = np.zeros(n)       # a tilt, so that the wheel's combination rules pass
    probe["theta"] = np.full(n, np.nan)
    for name in ("omega3", "omega", "speed", "com_speed"):
        probe[name] = np.full(n, np.nan)
    if lanes:
        probe["height"] = np.zeros(n)
    body = paper_body_codes(req["body"])
    reason = np.where((reason == "") & (body >= 0) & (body != WHEEL.code), NOT_A_WHEEL, reason)
    reason = np.where(reason == "", validate_requests(probe), reason)
    k_all = probe["k"]
    # a file's lane off the wall is its row, no_fit with the orbit's reason (typed ones are refused before)
    off_wall = np.zeros(n, dtype=bool)
    if not lanes:
        h = np.asarray(req["height"], dtype=float)
        off_wall = (reason == "") & ((h < 0) | (h > getattr(ground, "highest_lane", math.inf)))
        reason = np.where(off_wall, REASON_TEXT[Reason.LANE_OFF_WALL], reason)
    ok = reason == ""
    keys = np.column_stack([req["a"], k_all, req["g"], req["mu"], req["max_g"],
                            (req["side"] == "outside").astype(float)])
    parts, order = [], []
    rows = np.flatnonzero(ok)
    if rows.size:
        unique, inverse = np.unique(keys[rows], axis=0, return_inverse=True)
        for u, (a, k, g, mu, max_g, outside) in enumerate(unique):
            sub = rows[inverse.reshape(-1) == u]
            if lanes:
                one = lanes_on(ground, a, k, g, bool(outside), mu, max_g)
                parts.append(Table({name: np.tile(col, sub.size) for name, col in one.columns.items()}))
                order.append(np.repeat(sub, 2))
            else:
                table = intervals_on(ground, req["height"][sub], a, k, g, bool(outside), mu, max_g)
                firsts = np.asarray(table.columns["interval"]) <= 1
                parts.append(table)
                order.append(sub[np.cumsum(firsts) - 1])
    template = parts[0] if parts else (lanes_on(ground, 0.3, 0.5, 9.80665, False, math.inf, math.inf) if lanes
                                       else intervals_on(ground, np.zeros(1), 0.3, 0.5, 9.80665, False, math.inf,
                                                         math.inf))
    bad = np.flatnonzero(~ok)
    echoed = {"a_m": "a", "k": "k"} if lanes else {"a_m": "a", "k": "k", "height_m": "height"}
    columns = {}
    for name in template.names:
        arrays = [np.asarray(t.columns[name]) for t in parts]
        if bad.size:
            kind = np.asarray(template.columns[name]).dtype
            if name in echoed:
                filler = np.asarray(k_all if name == "k" else req[echoed[name]], dtype=float)[bad]
            elif name == "surface":
                filler = np.full(bad.size, ground.name, dtype=object)
            elif kind.kind == "f":
                filler = np.full(bad.size, np.nan)
            else:
                arrays = [x.astype(object) for x in arrays]
                filler = np.full(bad.size, None, dtype=object)
            arrays.append(filler)
        columns[name] = np.concatenate(arrays) if arrays else np.zeros(0)
    source = np.concatenate([o.astype(np.int64) for o in order] + [bad]) if (order or bad.size) \
        else np.zeros(0, dtype=np.int64)
    pick = np.argsort(source, kind="stable")
    columns = {name: col[pick] for name, col in columns.items()}
    src = source[pick]
    columns["input_row"] = np.asarray(req["input_row"], dtype=np.int64)[src]
    columns["body"] = req["body"][src].astype(object)
    columns["side"] = req["side"][src].astype(object)
    columns["status"] = np.where(reason[src] == "", "ok", np.where(off_wall[src], STATUS_LABELS[Status.NO_FIT],
                                                                  "invalid")).astype(object)
    columns["reason"] = reason[src].astype(object)
    return Table(columns)
