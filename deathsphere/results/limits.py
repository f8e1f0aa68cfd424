"""Result tables for the allowed region and the rider's limits (beyond the
paper; methods in docs/limits.md, physics in :mod:`deathsphere.physics.region`)."""

from __future__ import annotations

import math
from functools import partial

import numpy as np

from deathsphere.constants import BOUNDARY_LABELS
from deathsphere.model import Setup, Table
from deathsphere.parallel import ordered_map
from deathsphere.physics import region
from deathsphere.records.paper_bodies import WHEEL
from deathsphere.requests.decode import paper_body_codes

#: Boundary name -> the equation it comes from (inside, outside).
EQUATIONS = {
    **BOUNDARY_LABELS,
    "stability": ("stability boundary (exact linearisation)", "stability boundary (exact linearisation)"),
}


def _limit(x: float) -> float:
    return math.nan if math.isinf(x) else x


def _degrees(alpha_rad):
    """Degrees, rounded at 1e-10 deg: the roots are accurate to ~1e-12 rad,
    and an end at alpha = 0 should not print as 1.3e-13 (nor -0)."""
    return np.round(np.rad2deg(alpha_rad), 10) + 0.0


def _speed(v):
    """At an end where Omega^2 -> 0 (alpha -> 90 deg) the speed goes to 0 as
    sqrt(cot alpha), so a 1e-12 rad root error leaves ~1e-7 m/s: speeds
    below 1e-6 m/s are that round-off, and are the limit 0."""
    return np.where(np.abs(v) < 1e-6, 0.0, v)


def theta_grid(step_deg: float) -> np.ndarray:
    """The theta grid [deg] of the boundary data: multiples of ``step_deg``
    strictly inside (0, 180), where every boundary is defined; each the
    float nearest the decimal multiple of the step as written (``--step
    0.1``: 0.3, not the 0.30000000000000004 of 3 x 0.1), as a range's values
    are (grid.py: rounded to the step's decimals)."""
    theta = np.arange(1.0, math.ceil(180.0 / step_deg - 0.5)) * step_deg
    text = repr(float(step_deg))
    if "e" not in text and "." in text:
        theta = np.round(theta, len(text.split(".")[1]))
    return theta[theta < 180.0 - 0.5 * step_deg]


#: theta values per call of the stability boundary (a progress tick each).
_STABILITY_CHUNK = 64


def _stability_part(theta_deg: np.ndarray, a_over_r: float, k: float, outside: bool, mu: float,
                    max_g: float) -> np.ndarray:
    """The stability boundary at a block of thetas (one unit of parallel work)."""
    from deathsphere.physics.stability import (
        stability_boundary_alphas,  # only map --stability needs it
    )

    return stability_boundary_alphas(np.deg2rad(theta_deg), a_over_r, 1.0, k, outside=outside, mu=mu,
                                     max_g=max_g)


def boundary_table(a_over_r: float, k: float, outside: bool, mu: float, max_g: float, step_deg: float,
                   stability: bool = False, progress=None, jobs: int = 1, cluster=None) -> Table:
    """Every boundary curve alpha(theta) of the allowed region, one row per
    point (curve, equation, theta_deg, alpha_deg), theta on a grid of
    ``step_deg`` over (0, 180) deg, each alpha root-found to 1e-9 rad or better.

    With ``stability`` also the curve ``stability``: where feasible orbits
    change from stable to unstable (:func:`stability_boundary_alphas`,
    bisected to 1e-10 rad between samples 0.25 deg apart in alpha; beyond
    the paper), in blocks of thetas on ``jobs`` processes (the same values
    as with one; or on a dask cluster, ``cluster`` being ``(client, own)``
    from :func:`deathsphere.cluster.connect`).  ``progress(n)`` is told as each n theta values are done
    (the stability boundary is the slow part: ~100x the others)."""
    theta = theta_grid(step_deg)
    curves = region.boundary_alphas(np.deg2rad(theta), a_over_r, 1.0, k, outside=outside, mu=mu, max_g=max_g)
    if stability:
        blocks = [theta[start:start + _STABILITY_CHUNK] for start in range(0, theta.size, _STABILITY_CHUNK)]
        work = partial(_stability_part, a_over_r=a_over_r, k=k, outside=outside, mu=mu, max_g=max_g)
        parts = []
        client, own = cluster if cluster is not None else (None, False)
        for block, part in zip(blocks, ordered_map(work, blocks, jobs, client=client, close=own)):
            parts.append(part)
            if progress is not None:
                progress(block.size)
        width = max(p.shape[1] for p in parts)
        curves["stability"] = np.concatenate(
            [np.pad(p, ((0, 0), (0, width - p.shape[1])), constant_values=np.nan) for p in parts])
    names, eqs, thetas, alphas = [], [], [], []
    for name, alpha in curves.items():
        i, j = np.nonzero(np.isfinite(alpha))
        names.append(np.full(i.size, name, dtype=object))
        eqs.append(np.full(i.size, EQUATIONS[name][int(outside)], dtype=object))
        thetas.append(theta[i])
        alphas.append(np.rad2deg(alpha[i, j]))
    return Table({"curve": np.concatenate(names), "equation": np.concatenate(eqs),
                  "theta_deg": np.concatenate(thetas), "alpha_deg": np.concatenate(alphas),
                  "a_over_r": np.full(sum(map(len, names)), a_over_r), "k": np.full(sum(map(len, names)), k)})


def interval_rows(iv):
    """The rows of an intervals table from NaN-padded intervals per lane
    (:class:`~deathsphere.physics.region.AlphaIntervals` or its lanes' kin):
    one row per interval, one for a lane with none.  Returns (row, j,
    count, present, lo, hi, speed_min, speed_max): each row's lane and
    interval index, the lane's count, whether the row is an interval, and
    its ends and speed range (NaN where it is none)."""
    count = np.asarray(iv.count).reshape(-1)

    def slots_of(field):
        # one NaN slot when no lane has any interval (the arrays are then (n, 0))
        x = np.asarray(getattr(iv, field)).reshape(count.size, -1)
        return x if x.shape[1] else np.full((count.size, 1), np.nan)

    slots = np.maximum(count, 1)
    row = np.repeat(np.arange(count.size), slots)
    j = np.concatenate([np.arange(s) for s in slots]) if row.size else np.empty(0, int)
    present = j < count[row]
    lo, hi, vmin, vmax = (np.where(present, slots_of(f)[row, np.minimum(j, slots_of(f).shape[1] - 1)], np.nan)
                          for f in ("lo", "hi", "speed_min", "speed_max"))
    return row, j, count, present, lo, hi, vmin, vmax


def intervals_table(setup: Setup, theta_deg: np.ndarray, max_g: float) -> Table:
    """The open intervals of alpha with a feasible orbit at each theta, with
    the speed range over each; a theta without any gives one row with
    ``intervals`` = 0."""
    iv = region.allowed_alpha(np.deg2rad(theta_deg), setup.a, setup.r, setup.k, setup.g,
                              setup.side == "outside", setup.mu, max_g)
    row, j, count, present, lo, hi, vmin, vmax = interval_rows(iv)
    n = row.size
    return Table({
        "theta_deg": theta_deg[row], "intervals": count[row],
        "interval": np.where(present, j + 1, 0),
        "alpha_min_deg": _degrees(lo), "alpha_max_deg": _degrees(hi),
        "v_min_m_s": _speed(vmin), "v_max_m_s": np.where(np.isinf(vmax), np.nan, _speed(vmax)),
        "a_m": np.full(n, setup.a), "r_m": np.full(n, setup.r), "k": np.full(n, setup.k),
        "mu_available": np.full(n, _limit(setup.mu)), "max_g": np.full(n, _limit(max_g)),
    })


def highest_orbit_table(setup: Setup, max_g: float) -> Table:
    """The highest orbit possible (smallest theta) within mu and max_g.

    ``v_cm_m_s`` is the limit of the least speed as theta -> theta*; empty
    when that limit is unbounded (e.g. friction alone: alpha -> 0)."""
    h = region.highest_orbit(setup.a, setup.r, setup.k, setup.g, setup.side == "outside", setup.mu, max_g)
    row = {
        "found": h.found, "theta_deg": math.degrees(h.theta), "alpha_deg": math.degrees(h.alpha),
        "alpha_min_deg": math.degrees(h.alpha_lo), "alpha_max_deg": math.degrees(h.alpha_hi),
        "v_cm_m_s": _limit(h.speed), "a_m": setup.a, "r_m": setup.r, "k": setup.k,
        "mu_available": _limit(setup.mu), "max_g": _limit(max_g), "note": _highest_note(h),
    }
    return Table({name: np.array([value], dtype=object if name == "note" else None) for name, value in row.items()})


def _highest_note(h) -> str:
    """What the highest-orbit row means, in words (no commas: awk -F, safe)."""
    if not h.found:
        return "no feasible orbit at any theta within mu and max_g"
    if not math.isfinite(h.speed):
        return ("a bound approached but not reached: the least speed grows without limit as theta "
                "approaches theta_deg (v_cm_m_s empty)")
    return "v_cm_m_s is the least speed in the limit theta -> theta_deg"


#: The request fields of ``limits`` (an --input file's columns).
LIMITS_FIELDS = ("body", "side", "theta", "a", "r", "k", "g", "mu", "max_g")
#: Appended to the interval columns when the rows answer several requests.
REQUEST_COLUMNS = ("input_row", "body", "side", "status", "reason")
#: Why a request that is not a wheel's gets no limits.
NOT_A_WHEEL = ("limits analyses the tilt alpha of a wheel: a sphere's tilt is fixed by theta and a particle "
               "has none (use orbit)")


def limits_rows(req: dict, highest: bool) -> Table:
    """The limits of every request of ``req`` (flat arrays of
    :data:`LIMITS_FIELDS`, ``input_row`` and ``invalid`` reasons, as the
    model's requests), in request order: with ``highest``, the highest orbit
    of each; else the intervals of alpha at each request's theta (several
    rows for one request with several intervals).  Requests are grouped by
    their setup, one vectorised root search per distinct setup; a request
    that is invalid, or not a wheel's, is one row with the reason."""
    from deathsphere.model import validate_requests

    n = len(req["input_row"])
    reason = req["invalid"].copy()
    probe = dict(req)
    probe["alpha"] = np.zeros(n)  # a tilt, so that the wheel's combination rules pass
    for name in ("omega3", "omega", "speed"):
        probe[name] = np.full(n, np.nan)
    if highest:
        probe["theta"] = np.full(n, 90.0)
    body = paper_body_codes(req["body"])
    # a known body that is not a wheel: the reason is that limits are a wheel's
    reason = np.where((reason == "") & (body >= 0) & (body != WHEEL.code), NOT_A_WHEEL, reason)
    reason = np.where(reason == "", validate_requests(probe), reason)
    req = {**req, "k": probe["k"]}  # the validator fills k by body
    ok = reason == ""
    keys = np.column_stack([req[name] for name in ("a", "r", "k", "g", "mu", "max_g")]
                           + [(req["side"] == "outside").astype(float)])
    parts, order = [], []
    rows = np.flatnonzero(ok)
    if rows.size:
        unique, inverse = np.unique(keys[rows], axis=0, return_inverse=True)
        for u, (a, r, k, g, mu, max_g, outside) in enumerate(unique):
            sub = rows[inverse.reshape(-1) == u]
            setup = Setup(side="outside" if outside else "inside", a=a, r=r, k=k, g=g, mu=mu)
            if highest:
                one = highest_orbit_table(setup, max_g)
                table = Table({name: np.repeat(col, sub.size) for name, col in one.columns.items()})
                source = sub
            else:
                table = intervals_table(setup, req["theta"][sub], max_g)
                source = sub[_request_of(table, req["theta"][sub])]
            parts.append(table)
            order.append(source)
    order = [o.astype(np.int64) for o in order]
    bad = np.flatnonzero(~ok)
    template = parts[0] if parts else (highest_orbit_table(Setup(), math.inf) if highest
                                       else intervals_table(Setup(), np.zeros(1), math.inf))
    echoed = {"theta_deg": "theta", "a_m": "a", "r_m": "r", "k": "k"}
    columns = {}
    for name in template.names:
        arrays = [np.asarray(t.columns[name]) for t in parts]
        if bad.size:
            # a request without limits: its inputs echoed, every result empty
            kind = np.asarray(template.columns[name]).dtype
            if name in echoed and not highest or name in ("a_m", "r_m", "k"):
                filler = req[echoed[name]][bad].astype(float)
            elif kind.kind == "f":
                filler = np.full(bad.size, np.nan)
            else:
                arrays = [x.astype(object) for x in arrays]
                filler = np.full(bad.size, None, dtype=object)
            arrays.append(filler)
        columns[name] = np.concatenate(arrays) if arrays else np.zeros(0)
    source = np.concatenate(order + [bad]) if (order or bad.size) else np.zeros(0, dtype=np.int64)
    pick = np.argsort(source, kind="stable")
    columns = {name: col[pick] for name, col in columns.items()}
    src = source[pick]
    columns["input_row"] = np.asarray(req["input_row"], dtype=np.int64)[src]
    columns["body"] = req["body"][src].astype(object)
    columns["side"] = req["side"][src].astype(object)
    columns["status"] = np.where(reason[src] == "", "ok", "invalid").astype(object)
    columns["reason"] = reason[src].astype(object)
    return Table(columns)


def _request_of(table: Table, thetas: np.ndarray) -> np.ndarray:
    """Which of ``thetas`` (the requests of one setup, in order) each row of
    :func:`intervals_table` answers: its rows come theta by theta, one per
    interval (one for a theta without any)."""
    firsts = np.flatnonzero(np.asarray(table.columns["interval"]) <= 1)
    request = np.zeros(len(table), dtype=np.int64)
    request[firsts[1:]] = 1
    return np.cumsum(request)
