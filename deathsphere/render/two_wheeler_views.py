"""Terminal views of ``deathsphere ride`` for a two-wheeler: straight running
on flat ground (eigenvalues against speed), its summary (weave and capsize
speeds), the steady turns on the globe and their rider's table.  Eigenvalues show as complex
numbers, one cell each; the columns that do not fit a narrow console are
left out from the right and named under the table.  Each view is its
column specs (:mod:`~deathsphere.render.view_builder`)."""

from __future__ import annotations

from rich.markup import escape

from deathsphere.render.display_units import AS_TYPED, DisplayUnits
from deathsphere.render.ride_views import _limit, _span, _spans, _stability_cell, _turn_radius_shown
from deathsphere.render.terminal_table import (
    MAX_TERMINAL_ROWS,
    FitTable,
    echo_number,
    first_rows,
    format_number,
    is_undefined,
    row_record,
    status_legend,
    status_text,
)
from deathsphere.render.view_builder import ColumnSpec, build_table, globe_text
from deathsphere.table import Table

#: The rear contact's speed: typed as --speed.
REAR_SPEED = dict(kind="speed", params=("speed",))
HEIGHT = ColumnSpec("height_m", "height", "m", kind="length", params=("height",))
#: flat ground's lane: the rear contact's distance from the turn's centre (shown where every height is 0)
TURN_RADIUS = ColumnSpec("rho_contact_m", "turn\nradius", "m", kind="length", params=("turn_radius",),
                         when=_turn_radius_shown)

#: The turns on the globe, in order: the row's identity and the rider's
#: numbers, then the rest (left out first, from the right); the steer
#: torque and the verdict go last, where the units typed take the room.
TURN_VIEW = (
    ColumnSpec("input_row", "#", format=str),
    HEIGHT,
    TURN_RADIUS,
    ColumnSpec("status", "status", format=status_text, justify="left"),
    ColumnSpec("v_rear_m_s", "v rear", "m/s", **REAR_SPEED),
    ColumnSpec("lean_surface_deg", "lean°\nwall"),
    ColumnSpec("steer_deg", "steer", "°"),
    ColumnSpec("steer_torque_n_m", "T_δ", "N m", drop=7),
    ColumnSpec("stability", "stability", format=_stability_cell, drop=8),
    ColumnSpec("growth_rate_1_s", "growth", "1/s", drop=6),
    ColumnSpec("load_g", "load", "g", drop=5),
    ColumnSpec("mu_required_rear", "μ\nrear", drop=4),
    ColumnSpec("mu_required_front", "μ\nfront", drop=3),
    ColumnSpec("head_clearance_m", "head\nclear", "m", drop=2, kind="length"),
    ColumnSpec("theta_deg", "θ", "°", drop=1, kind="angle", params=("theta",)),
)


def _eigenvalue(re, im) -> str:
    if re != re:  # NaN: no eigenvalue
        return "—"
    if im == 0:
        return format_number(re, 3)
    return f"{format_number(re, 3)}{'+' if im > 0 else '-'}{format_number(abs(im), 3)}i"


def _eigen_specs(head: Table) -> list[ColumnSpec]:
    """A column per eigenvalue, as many as the table has; left out from the last."""
    k = sum(1 for c in head.columns if c.endswith("_re") and c.startswith("eig_"))
    return [ColumnSpec(f"eig_{i}", f"λ{i}", "1/s", drop=k - i,
                       value=lambda get, i=i: (get[f"eig_{i}_re"], get[f"eig_{i}_im"]),
                       format=lambda pair: _eigenvalue(*pair)) for i in range(1, k + 1)]


#: The weave and capsize speeds to every digit: they are the benchmark's
#: (Meijaard et al. 2007 give 15).
WEAVE_VIEW = (
    ColumnSpec("machine", "machine", justify="left"),
    ColumnSpec("weave_speed_m_s", "weave speed", "m/s", digits=15, **REAR_SPEED),
    ColumnSpec("capsize_speed_m_s", "capsize speed", "m/s", digits=15, **REAR_SPEED),
    ColumnSpec("speeds_tried", "speeds\ntried", drop=2),
    ColumnSpec("speeds_stable", "speeds\nstable", drop=1),
)
STRAIGHT_VIEW = (
    ColumnSpec("speed_m_s", "speed", "m/s", **REAR_SPEED),
    ColumnSpec("stability", "stability", format=_stability_cell),
    ColumnSpec("growth_rate_1_s", "growth", "1/s"),
)


def straight_view(table: Table, total_rows: int | None = None, title: str | None = None,
                  units: DisplayUnits = AS_TYPED) -> FitTable:
    """Upright straight running: speed, verdict, growth rate, every eigenvalue."""
    if "weave_speed_m_s" in table:
        return build_table(table, WEAVE_VIEW, units=units, title=title, total_rows=total_rows)
    first = row_record(table)
    setup = f"{escape(str(first['machine']))}, steer {first['steer']}, g = {format_number(first['g_m_s2'])} m/s²"
    specs = (*STRAIGHT_VIEW, *_eigen_specs(first_rows(table, MAX_TERMINAL_ROWS)))
    return build_table(table, specs, units=units, title=title, total_rows=total_rows, setup=setup)


def turns_view(table: Table, total_rows: int | None = None, title: str | None = None,
               units: DisplayUnits = AS_TYPED) -> FitTable:
    """Steady turns on the globe: one line per turn, the rider's numbers
    first; the rider's table (``--summary``) one line per lane."""
    if "speeds_tried" in table:
        return turn_summary_view(table, total_rows, title, units)
    first = row_record(table)
    if first.get("surface") == "plane":
        # flat ground: no radius to name, and the ground's normal is the vertical
        setup = (f"{escape(str(first['machine']))}: flat ground, steer {first['steer']}{_limits_text(first)}; lean "
                 "from the vertical, into the turn")
    else:
        setup = (f"{escape(str(first['machine']))}: {globe_text(first, units, number=echo_number)}, steer "
                 f"{first['steer']}{_limits_text(first)}; lean from the wall's normal at the rear contact, + to the "
                 "rider's right (the floor's side)")
    return build_table(table, TURN_VIEW, units=units, title=title, total_rows=total_rows, setup=setup,
                       notes=status_legend(first_rows(table, MAX_TERMINAL_ROWS)))


def _limits_text(get: dict) -> str:
    """The limits given, for the line under a table (none: nothing)."""
    words = (("mu_available", "μ available {}"), ("max_g", "max load {} g"))
    return "".join(f", {text.format(format_number(get[c]))}" for c, text in words if not is_undefined(get[c]))


def _hands_free_cell(speeds: str, stable: str) -> str:
    """The hands-free speeds to 0.1 m/s, a stable one marked ✓."""
    calm = set(stable.split())
    cells = [f"{float(v):.1f}" + ("✓" if v in calm else "") for v in speeds.split()]
    return " ".join(cells) if cells else "—"


#: Why a speed fails on the globe: count column -> its letter in the cell
#: and the words of the legend under the table (ride's causes, less the
#: head's).  Letters keep the cell to one short line, whatever fails, so the
#: rider's numbers keep their room on an 80-column console.
TURN_WHY = (("slips", "s", "slips"), ("over_g", "g", "over max g"), ("no_contact", "c", "no contact (a wheel lifts)"),
            ("no_orbit", "n", "no turn"))
#: The legend of the why cell's letters.
TURN_WHY_LEGEND = "why the others fail: " + ", ".join(f"{letter} {words}" for _, letter, words in TURN_WHY)


def _turn_why(get: dict) -> str:
    parts = [f"{get[col]}{letter}" for col, letter, _ in TURN_WHY if get[col]]
    return " ".join(parts) if parts else "—"


def _ends(lo: str, hi: str):
    return lambda get: (get[lo], get[hi])


def _stable_cell(get: dict) -> str:
    """The stable band within the limits; else, in brackets, the band stable
    only beyond them (slips or over g: not the rider's)."""
    if not is_undefined(get["stable_v_min_m_s"]) or is_undefined(get["stable_beyond_v_min_m_s"]):
        return _span(get["stable_v_min_m_s"], get["stable_v_max_m_s"])
    return f"({_span(get['stable_beyond_v_min_m_s'], get['stable_beyond_v_max_m_s'])})"


#: ln 2: a disturbance growing at rate s doubles in ln 2 / s.
_LN2 = 0.6931471805599453


def _doubling_cell(get: dict) -> str:
    """How soon a disturbance doubles on the lane's ok turns, the
    fastest-growing one's (the least time the rider has): ln 2 / its growth
    rate; ∞ where none grows."""
    fast = get["growth_max_1_s"]
    if is_undefined(fast):
        return "—"
    return format_number(_LN2 / fast, 2) if fast > 0 else "∞"


#: The rider's table on the globe; the rest of its numbers are the CSV's.
#: What the rider asks stays longest on a narrow console (lean, steer
#: torque, head clearance, the speeds that work and the hands-free ones,
#: how soon a disturbance doubles); θ, μ needed, load and the stable band
#: go first; "why" stays, on one line.
TURN_SUMMARY_VIEW = (
    HEIGHT,
    TURN_RADIUS,
    ColumnSpec("theta_deg", "θ", "°", drop=1, kind="angle", params=("theta",)),
    ColumnSpec("ok", "ok", value=lambda get: f"{get['speeds_ok']}/{get['speeds_tried']}", drop=5),
    # the speeds that work in the unit typed alone (SI where none was): the rider's room goes to the rest
    ColumnSpec("speed", "v rear", "m/s", value=_ends("v_rear_min_m_s", "v_rear_max_m_s"), format=_spans(),
               show="display", **REAR_SPEED),
    ColumnSpec("lean", "lean°\nvert.", value=_ends("lean_vertical_min_deg", "lean_vertical_max_deg"),
               format=_spans(2), drop=10),
    ColumnSpec("load", "load", "g", value=_ends("load_min_g", "load_max_g"), format=_spans(2), drop=3),
    ColumnSpec("mu_max", "μ\nneeded", digits=2, drop=2),
    ColumnSpec("head", "head\nclear", "m", value=lambda get: get["head_clearance_min_m"], digits=2, drop=8,
               kind="length"),
    ColumnSpec("torque", "T_δ", "N m", value=_ends("steer_torque_min_n_m", "steer_torque_max_n_m"),
               format=_spans(2), drop=6),
    ColumnSpec("stable", "stable", "m/s", value=_stable_cell, format=str, drop=4),
    # the hands-free speeds are a list in one cell: m/s only
    ColumnSpec("hands", "hands-\nfree", "m/s", format=str, drop=9,
               value=lambda get: _hands_free_cell(get["hands_free_v_rear_m_s"], get["hands_free_stable_v_rear_m_s"])),
    ColumnSpec("doubles", "to 2×", "s", value=_doubling_cell, format=str, drop=7),
    ColumnSpec("why", "why the\nothers\nfail", value=_turn_why, justify="left"),
)


def turn_summary_view(table: Table, total_rows: int | None = None, title: str | None = None,
                      units: DisplayUnits = AS_TYPED) -> FitTable:
    """The rider's table on the globe: per lane, the rear speeds ok of
    those tried, over them the speed, lean, load and steer torque ranges,
    the most friction needed and the least head clearance, the stable
    speeds, the lane's hands-free speeds and why the others fail."""
    first = row_record(table)
    limits = f"μ available {_limit(first['mu_available'])}, max load {_limit(first['max_g'])} g"
    note = (f"{limits}, steer {first['steer']}; ok: rear speeds feasible of those tried; ranges over the ok "
            "ones, lean from the vertical, μ needed the most of them, head clear the least; stable: the ok speeds "
            "stable with the steer so held, (in brackets) stable only beyond the limits; hands-free: the lane's "
            "turns with no steer torque, at any speed (✓ stable); to 2×: how soon a disturbance doubles on the "
            f"fastest-growing ok turn, ln 2 / growth rate (∞: none grows); {TURN_WHY_LEGEND} (the speeds so "
            "failing, counted)")
    return build_table(table, TURN_SUMMARY_VIEW, units=units, title=title, total_rows=total_rows, setup=note)
