"""Vertical loops of a wheel inside a closed profile as result tables
(beyond the paper: docs/surfaces.md, "S9-S12. A vertical loop inside a
closed profile").

The same requests and columns as the globe's (:mod:`deathsphere.results.vertical`),
then the arena's: ``surface`` and ``height_m`` (the loop's top above its
bottom).  A request's loop runs in a meridian plane, so its ``theta`` must
be 90 deg and its ``side`` inside: another row is ``invalid``, saying so.
``r_m`` is empty (the sphere's radius is not the profile's).  The
stability columns are the globe's: the loop's Floquet multipliers over one
lap of the wheel's exact equations of motion on the profile
(``floquet``; docs/stability.md sec. 2.1), ``not-analysed-k0`` where k =
0.  Physics: :mod:`deathsphere.physics.vertical_orbit_on`,
:mod:`deathsphere.physics.stability.loop_floquet`.
"""

from __future__ import annotations

import numpy as np

from deathsphere import params
from deathsphere.model import NOT_ANALYSED_K0, Table, echo_given, finite_or_blank
from deathsphere.physics import vertical_orbit_on
from deathsphere.physics.stability import methods
from deathsphere.physics.status import STATUS_LABELS, Status
from deathsphere.requests.decode import as_typed
from deathsphere.results.vertical import (
    COLUMNS,
    POINT_COLUMNS,
    point_columns,
    summary_arrays,
    validate_vertical,
)

#: The arena's columns, appended to the globe's.
ARENA_COLUMNS = ("surface", "height_m")
SUMMARY_COLUMNS = COLUMNS + ARENA_COLUMNS
POINTS_COLUMNS = POINT_COLUMNS + ARENA_COLUMNS

#: Why a row's theta is refused on a profile.
THETA_IN_MERIDIAN = ("a vertical loop on a profile runs in a meridian plane through the axis: theta must be 90 deg "
                     "(a circle of another cone angle is not a plane curve on the profile)")
SIDE_INSIDE = "a vertical loop on a profile is computed inside only"
#: The sphere's radius a profile's request carries: the globe's checks of a
#: request ask r > a, which is not the loop's fit (a kappa_max < 1, its own
#: status), so a request on a profile is checked against a radius no wheel
#: reaches; ``r_m`` is written empty.
NO_SPHERE_R = params.PARAMS["r"].hi


def _validate_on(req) -> np.ndarray:
    """The globe's checks of every value but r (the sphere's radius, not the
    profile's: the loop's fit is its own status, a kappa_max < 1), then
    theta = 90 deg and the inside."""
    globe = dict(req)
    globe["r"] = np.full(req["r"].shape, NO_SPHERE_R)
    reason = validate_vertical(globe)
    req["k"] = globe["k"]
    typed = req.get("typed", {})
    with np.errstate(invalid="ignore"):
        theta_off = (reason == "") & (np.abs(req["theta"] - 90.0) > 0)
    reason[theta_off] = [as_typed("theta", f"{THETA_IN_MERIDIAN} (got {params.shown_number(float(t))})", typed)
                         for t in req["theta"][theta_off]]
    outside = (reason == "") & (req["side"] == "outside")
    reason[outside] = as_typed("side", SIDE_INSIDE, typed)
    return reason


def _top_speed(req, rows, loop):
    """The top speed of the centre per valid row: v_top as given, or the top
    rate phidot_top times the centre path's radius of curvature at the top."""
    v = req["v_top"][rows]
    rate = np.abs(req["phidot_top"][rows])
    stretch = 1.0 - req["a"][rows] * loop.kappa[-1]
    with np.errstate(divide="ignore", invalid="ignore"):
        radius = np.where(stretch > 0, stretch / loop.kappa[-1], np.nan)
    return np.where(np.isnan(v), rate * radius, v)


def _arena(columns: dict, n: int, loop) -> None:
    columns["surface"] = np.full(n, loop.ground.name, dtype=object)
    columns["height_m"] = np.full(n, loop.height)
    columns["r_m"] = np.full(n, np.nan)


def _stability(req, loop, status, stability: bool) -> tuple:
    """(stability, stability_method, growth_rate_1_s) per row, as the
    globe's (:func:`deathsphere.results.vertical.evaluate_vertical`): with
    ``stability``, a loop that keeps contact (ok or slips) gets its Floquet
    verdict and growth rate, k = 0 ``unknown``, ``not-analysed-k0``."""
    n = status.size
    verdict = np.full(n, "", dtype=object)
    method = np.full(n, "", dtype=object)
    growth = np.full(n, np.nan)
    live = np.flatnonzero(np.isin(status, (Status.OK, Status.SLIPS)))
    if not stability:
        return verdict, method, growth
    # k = 0 (no rotational inertia) makes the equations of motion singular
    singular = live[req["k"][live] == 0]
    verdict[singular] = "unknown"
    method[singular] = NOT_ANALYSED_K0
    live = live[req["k"][live] > 0]
    if live.size:
        from deathsphere.physics.stability import VERDICT_LABELS, loop_floquet_on

        floquet = loop_floquet_on(loop, _top_speed(req, live, loop), req["a"][live], req["k"][live], req["g"][live])
        verdict[live] = VERDICT_LABELS[floquet["verdict"]]
        method[live] = methods.FLOQUET
        growth[live] = floquet["growth_rate"]
    return verdict, method, growth


def evaluate_vertical_on(req: dict, loop, stability: bool = True) -> Table:
    """One summary row per request on ``loop``
    (:class:`~deathsphere.physics.vertical_orbit_on.Loop`), in input order
    (invalid rows kept, with reasons): :data:`SUMMARY_COLUMNS`; with
    ``stability`` the loop's Floquet stability (beyond the paper,
    docs/stability.md sec. 2.1)."""
    n = len(req["theta"])

    def evaluate(rows):
        return vertical_orbit_on.vertical_loop_on(loop, _top_speed(req, rows, loop), req["a"][rows], req["k"][rows],
                                                  req["g"][rows], req["mu"][rows])

    out, status, reason = summary_arrays(_validate_on(req), evaluate)
    verdict, method, growth = _stability(req, loop, status, stability)
    columns = {
        "stability": verdict,
        "stability_method": method,
        "growth_rate_1_s": growth,
        "input_row": req["input_row"].astype(np.int64), "body": req["body"], "side": req["side"],
        "theta_deg": req["theta"], "alpha_deg": req["alpha"], "a_m": req["a"],
        "k": req["k"], "g_m_s2": req["g"], "status": STATUS_LABELS[status], "reason": reason,
        "mu_available": np.where(np.isinf(req["mu"]), np.nan, req["mu"]),
        **out,
    }
    _arena(columns, n, loop)
    finite_or_blank(columns)
    echo_given(columns, {"v_cm_m_s": req["v_top"], "omega_rad_s": req["phidot_top"]})
    return Table({name: columns[name] for name in SUMMARY_COLUMNS})


def vertical_points_on(req: dict, loop, points: int, start: int = 0, stop: int | None = None) -> Table:
    """The loop point by point at ``points`` angles phi from the top (0) round
    to 360 deg (the turn of the loop's tangent: on a circle the centre's
    azimuth), as :func:`deathsphere.results.vertical.vertical_points`, with
    the arena's columns; ``start:stop`` a slice of the angles."""
    def evaluate(rows, phi):
        return vertical_orbit_on.loop_points_on(loop, phi, _top_speed(req, rows, loop), req["a"][rows],
                                                req["k"][rows], req["g"][rows], req["mu"][rows])

    columns, order = point_columns(req, _validate_on(req), np.linspace(0.0, 2 * np.pi, int(points)), points, start,
                                   stop, evaluate, ("v_cm_m_s",))
    n = order.size
    columns["surface"] = np.full(n, loop.ground.name, dtype=object)
    columns["height_m"] = np.full(n, loop.height)
    return Table({name: columns[name][order] for name in POINTS_COLUMNS})
