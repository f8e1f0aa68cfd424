"""``ride --vertical`` inside a profile that closes over the top: the
single-contact machine's vertical loop in a meridian plane (beyond the
paper; docs/machine.md sec. 10, "Inside a closed profile", eqs. M25-M30).

The globe's loop stays on :mod:`deathsphere.api.rides` (its table byte for
byte); this one gives the same columns (``r_m`` empty: no sphere's radius
names the arena), then the arena's, ``surface`` and ``height_m`` (the
loop's top above its bottom, as the paper's wheel's loop on a profile),
then what a loop of varying curvature adds: the lap time, the largest
load round the loop and where, and the stability columns (``unknown``,
``not-analysed-loop``: the machine's loop has no Floquet analysis; the
paper's wheel's loop inside a profile has, docs/stability.md sec. 2.1).  theta must be 90 deg (the loop runs through the axis) and the
machine rides inside.
"""

from __future__ import annotations

import math

import numpy as np

from deathsphere.api.arguments import broadcast_flat, checked_array, grid_shape, refuse_large_grid
from deathsphere.api.vertical_arena import loop_of
from deathsphere.params import ParameterError, shown_number
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.physics.machine_loop_on import machine_loop_on
from deathsphere.physics.stability import methods
from deathsphere.physics.status import REASON_TEXT, STATUS_LABELS, Status
from deathsphere.table import Table

__all__ = ["ride_loop_on", "ARENA_COLUMNS"]

#: Appended to the globe's loop columns (``deathsphere.api.rides.LOOP_COLUMNS``).
ARENA_COLUMNS = ("surface", "height_m", "period_s", "load_max_g", "phi_load_max_deg", "stability",
                 "stability_method")
#: Loops per call of the physics: each is a row of arrays against the loop's
#: grid of 1025 points, so a call's memory grows with it (512 loops: about
#: 140 MB at the peak; about 2,500 loops a second on one core,
#: benchmarks/bench_vertical_on.py).
LOOPS_PER_CALL = 512
#: The most loops one ``ride --vertical`` on a profile computes (about a
#: minute at the rate above); the globe's closed forms take far more.
MAX_LOOP_ON_ROWS = 100_000
#: What a lane of ``ride --vertical`` is not on a profile.
NOT_A_LOOP = ("height", "alpha", "speed", "com_speed", "period", "turn_radius")


def _refuse_other_lanes(typed: dict) -> None:
    for key in NOT_A_LOOP:
        if typed.get(key) is not None:
            raise ParameterError(f"a vertical loop takes theta (90 deg: it runs through the profile's axis) and v_top "
                                 f"(the centre of mass's speed at the top), not {key}", key)
    if typed.get("v_top") is None:
        raise ParameterError("give v_top (the centre of mass's speed at the top of the loop)", "v_top", missing=True)
    if typed.get("theta") is None:
        raise ParameterError("give theta 90 (a vertical loop on a profile runs in a meridian plane)", "theta",
                             missing=True)


def ride_loop_on(ground, typed: dict, m, options, rides) -> Table:
    """The machine's vertical loops inside ``ground`` (a profile closed at
    both ends; else refused naming ``vertical``): ``typed`` the keywords as
    given (theta, v_top, g, mu, max_g), ``m`` the machine record,
    ``options`` the ride's options (the statuses kept; the rider's table is
    refused), ``rides`` the module of the globe's loop columns (appended
    to) and the row limit."""
    # the ground first: on a drum or a cone the loop itself is what is refused (the option typed: vertical)
    loop = loop_of(ground, "vertical")
    _refuse_other_lanes(typed)
    if options.summary:
        raise ParameterError("the rider's table (summary) is for horizontal orbits, not a vertical loop", "summary")
    checked = {"theta": checked_array("theta", typed["theta"]), "v_top": checked_array("v_top", typed["v_top"]),
               **{k: checked_array(k, typed[k]) for k in ("g", "mu", "max_g")}}
    off = checked["theta"][np.abs(checked["theta"] - 90.0) > 0]
    if off.size:
        raise ParameterError("a vertical loop on a profile runs in a meridian plane through the axis: theta must "
                             f"be 90 deg (got {shown_number(float(off.reshape(-1)[0]))})", "theta")
    refuse_large_grid(grid_shape(checked), command="ride --vertical on a profile",
                      limit=min(MAX_LOOP_ON_ROWS, rides.MAX_RIDE_ROWS),
                      instead="give fewer top speeds (a loop on a profile is solved round its curve, about "
                              "2,000 a second)")
    shape, flat = broadcast_flat(checked)
    n = math.prod(shape)
    arrays = machine_arrays(m)
    # a few hundred loops a call: the memory stays flat (the arrays are loops x the loop's grid)
    pieces = [machine_loop_on(loop, *(flat[k][lo:lo + LOOPS_PER_CALL] for k in ("v_top", "g")), arrays,
                              *(flat[k][lo:lo + LOOPS_PER_CALL] for k in ("mu", "max_g")))
              for lo in range(0, n, LOOPS_PER_CALL)] or [machine_loop_on(loop, np.zeros(0), np.zeros(0), arrays)]
    res = {k: np.concatenate([np.asarray(p[k]).reshape(-1) for p in pieces]) for k in pieces[0]}
    # a loop that keeps contact all round (as ride's orbits: ok, slips, over_g) is one to analyse
    live = np.isin(res["status"], (Status.OK, Status.SLIPS, Status.OVER_G))
    cols = {"input_row": np.arange(n) + 1, "machine": np.full(n, m.name, dtype=object),
            "theta_deg": flat["theta"], "r_m": np.full(n, np.nan), "g_m_s2": flat["g"], "v_top_m_s": flat["v_top"],
            "status": STATUS_LABELS[res["status"]], "reason": REASON_TEXT[res["reason"]],
            # no top speed holds it (an overhang): empty, the reason says so
            "v_top_min_m_s": np.where(np.isinf(res["v_top_min"]), np.nan, res["v_top_min"]),
            "v_bottom_m_s": res["v_bottom"], "omega_top_rad_s": res["omega_top"],
            "omega_bottom_rad_s": res["omega_bottom"], "com_loop_radius_m": res["r_g"],
            "load_top_g": res["load_top"], "load_bottom_g": res["load_bottom"],
            "head_clearance_m": res["head_clearance"],
            "mu_available": np.where(np.isinf(flat["mu"]), np.nan, flat["mu"]),
            "max_g": np.where(np.isinf(flat["max_g"]), np.nan, flat["max_g"]),
            "mu_required": res["mu_required"], "phi_worst_deg": np.degrees(res["phi_worst"]),
            "surface": np.full(n, ground.name, dtype=object), "height_m": np.full(n, loop.height),
            "period_s": res["period"], "load_max_g": res["load_max"],
            "phi_load_max_deg": np.degrees(res["phi_load_max"]),
            "stability": np.where(live, "unknown", "").astype(object),
            "stability_method": np.where(live, methods.NOT_ANALYSED_LOOP_OFF_GLOBE, "").astype(object)}
    table = Table({c: cols[c] for c in (*rides.LOOP_COLUMNS, *ARENA_COLUMNS)}, shape=shape)
    return options.kept(table)
