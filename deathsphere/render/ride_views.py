"""Terminal views of ``deathsphere ride`` and ``deathsphere machines``: what
a show crew reads off a screen.  One orbit (or loop) is a
quantity/value/unit table like ``orbit``'s
(:func:`~deathsphere.render.orbit_views.quantity_table`); several rows put
the safety columns first (status, speed in km/h, lean, load, friction
needed, head clearance) and leave out the rest where the console is too
narrow; the rider's table says why the speeds that fail fail.  Each view
is its column specs (:mod:`~deathsphere.render.view_builder`); a quantity
typed in another unit shows in it beside SI."""

from __future__ import annotations

import numpy as np

from rich.markup import escape

from deathsphere.render.display_units import AS_TYPED, KM_H, DisplayUnits
from deathsphere.render.orbit_views import quantity_table
from deathsphere.render.terminal_table import (
    MAX_TERMINAL_ROWS,
    STABILITY_STYLE,
    FitTable,
    echo_number,
    first_rows,
    format_number,
    is_undefined,
    row_record,
    status_legend,
    status_text,
)
from deathsphere.render.view_builder import Column, ColumnSpec, build_table, globe_text, quantity_rows
from deathsphere.table import Table


def _limit(value) -> str:
    return "∞" if is_undefined(value) else format_number(value)


def _span(lo, hi, digits: int = 3) -> str:
    if is_undefined(lo):
        return "—"
    a, b = format_number(lo, digits), format_number(hi, digits)
    return a if a == b else f"{a}–{b}"


def _spans(digits: int = 3):
    """A range's cell: its ends (a tuple) as ``a–b``."""
    return lambda ends: _span(*ends, digits)


def _stability_cell(v) -> str:
    return STABILITY_STYLE.get(v, escape(str(v)))


def _any(column: str):
    """A spec's ``when``: shown only if some row has a value in ``column``."""
    return lambda head: any(head.columns[column].tolist())


#: A rider's speed, the contact's (his speedometer's; --speed): km/h (or the
#: unit typed) where the safety columns are; the centre of mass's (--com-speed) beside it.
SPEED = dict(kind="speed", params=("speed",), crew=KM_H)
COM_SPEED = dict(kind="speed", params=("com_speed",), crew=KM_H)
LENGTH = dict(kind="length")

def _by_radius(heights, radii) -> bool:
    """Lanes named by their distance from the axis, not their height: every
    height 0 and the contact off the axis (flat ground's turn radius; a
    floor's lane on a wall shows its radius too)."""
    heights, radii = np.asarray(heights, dtype=float), np.asarray(radii, dtype=float)
    return bool(heights.size) and bool(np.all(heights == 0) and np.all(radii > 1e-6))


def _turn_radius_shown(head) -> bool:
    if "rho_contact_m" not in head.columns:
        return False
    return _by_radius(head.columns["height_m"], head.columns["rho_contact_m"])


#: The one-orbit view, the crew's first: (spec) per row, source in ``source``.
ORBIT_FIELDS = (
    ColumnSpec("v_contact_m_s", "speed of the contact (speedometer)", "m/s", source="Ω r sin θ", show="display",
               **SPEED),
    ColumnSpec("v_cm_m_s", "speed of the centre of mass", "m/s", source="eq. M8", show="display", **COM_SPEED),
    ColumnSpec("lean_deg", "lean from the vertical, 90° − α", "deg"),
    ColumnSpec("load_g", "load on the rider |F|/(m g)", "g", source="eq. M11"),
    ColumnSpec("mu_required", "μ required", source="eq. M9"),
    ColumnSpec("head_clearance_m", "head clearance", "m", source="eq. M2", **LENGTH),
    ColumnSpec("height_m", "contact height above the floor", "m", kind="length", params=("height",)),
    ColumnSpec("rho_contact_m", "turn radius of the contact", "m", kind="length", params=("turn_radius",),
               when=lambda get: _by_radius([get["height_m"]], [get["rho_contact_m"]])),
    ColumnSpec("com_orbit_radius_m", "radius of the CoM's lap", "m", source="eq. M3", **LENGTH),
    ColumnSpec("omega_rad_s", "Ω lap rate", "rad/s", source="eq. M8", kind="rate"),
    ColumnSpec("period_s", "lap time 2π/Ω", "s"),
    ColumnSpec("wheel_spin_rad_s", "wheel spin (relative to frame)", "rad/s", source="eq. M4", kind="rate"),
    ColumnSpec("normal_per_mass_m_s2", "normal force / m", "m/s²", source="eq. M9"),
    ColumnSpec("friction_per_mass_m_s2", "friction / m (+ down the wall)", "m/s²", source="eq. M9"),
    *(ColumnSpec(key, label, unit, source="sec. 5", when=lambda get, key=key: not is_undefined(get[key]))
      for key, label, unit in (("growth_rate_1_s", "growth rate (max Re λ)", "1/s"),
                               ("freq_slow_rad_s", "nutation, slow", "rad/s"),
                               ("freq_fast_rad_s", "nutation, fast", "rad/s"))),
)
OK_REASON = "fits, Ω² > 0, keeps contact, enough friction, load within the limit"

#: The several-orbit view: the row's identity, then the safety columns,
#: then the rest.  Left out first on a narrow console: everything after
#: the safety columns, from the right; θ goes before them (the height says
#: where the lap is).
MANY_COLUMNS = (
    ColumnSpec("input_row", "#", format=str),
    ColumnSpec("height_m", "height", "m", kind="length", params=("height",)),
    ColumnSpec("rho_contact_m", "turn\nradius", "m", kind="length", params=("turn_radius",),
               when=_turn_radius_shown),
    ColumnSpec("theta_deg", "θ", "°", drop=6, kind="angle", params=("theta",)),
    ColumnSpec("status", "status", format=status_text, justify="left"),
    ColumnSpec("v_contact_km_h", "speed", "m/s", value=lambda get: get["v_contact_m_s"], show="display", **SPEED),
    # the centre of mass's beside it, left out after alpha and theta (the speedometer's is the rider's)
    ColumnSpec("v_cm_km_h", "CoM\nspeed", "m/s", value=lambda get: get["v_cm_m_s"], show="display", drop=6.5,
               **COM_SPEED),
    ColumnSpec("lean_deg", "lean", "°"),
    ColumnSpec("load_g", "load", "g"),
    ColumnSpec("mu_required", "μ\nneeded"),
    ColumnSpec("head_clearance_m", "head\nclear", "m", **LENGTH),
    ColumnSpec("alpha_deg", "α", "°", drop=5, kind="angle", params=("alpha",)),
    ColumnSpec("v_contact_m_s", "speed", "m/s", drop=4, show="echo", **SPEED),

    ColumnSpec("period_s", "lap", "s", drop=3),
    ColumnSpec("stability", "stability", format=_stability_cell, drop=2, when=_any("stability")),
    ColumnSpec("growth_rate_1_s", "growth", "1/s", drop=1, when=_any("stability")),
)

#: Why a speed fails in the rider's table: count column -> words.
WHY = (("slips", "slips"), ("over_g", "over g"), ("head_hits", "head"), ("no_contact", "no contact"),
       ("no_orbit", "no lap"))


def _setup_line(get: dict, mu: bool = True, units: DisplayUnits = AS_TYPED) -> str:
    friction = f"μ available {_limit(get['mu_available'])}, " if mu else ""
    return (f"{globe_text(get, units, number=echo_number)}, g = {format_number(get['g_m_s2'], 6)} m/s², "
            f"{friction}max load {_limit(get['max_g'])} g")


def _mu_varies(table: Table) -> bool:
    """Several values of μ among the rows (``--mu 0.8:1:0.1``): a column, not a line under the table."""
    return len({_limit(v) for v in table.columns["mu_available"].tolist()}) > 1


def _with_mu_column(after: str):
    """An ``extra`` of :func:`build_table`: where μ varies, its column after ``after``."""
    def extra(columns: list, head: Table) -> list:
        if not _mu_varies(head):
            return columns
        at = next(i for i, c in enumerate(columns) if c.key == after) + 1
        return [*columns[:at], Column("mu_available", "μ", [_limit(v) for v in head.columns["mu_available"].tolist()]),
                *columns[at:]]
    return extra


def _stability_rows(get: dict) -> dict:
    # the long method text is the CSV's; on screen a pointer to it
    if get.get("stability"):
        return {"stability": get["stability"], "stability_method": "sec. 5, steer locked"}
    return {"stability": ""}


def one_orbit_view(table: Table, units: DisplayUnits = AS_TYPED) -> FitTable:
    """Every quantity of one orbit, one per line, with its unit and equation."""
    get = row_record(table)
    rows = quantity_rows(get, ORBIT_FIELDS, units)
    where = f"θ = {echo_number(get['theta_deg'])}°, α = {echo_number(get['alpha_deg'])}°"
    if get.get("surface") not in (None, "sphere"):
        # a drum's or a cone's lane has no theta: the wall's angle says where
        where = (f"on the {get['surface']}, wall at {echo_number(get['wall_angle_deg'])}°, "
                 f"α = {echo_number(get['alpha_deg'])}°")
    title = f"{get['machine']}, {where}\n{_setup_line(get, units=units)}"
    return quantity_table(title, {**get, **_stability_rows(get)}, rows, OK_REASON)


def _machine_line(head: Table, units: DisplayUnits) -> str:
    first = row_record(head)
    return f"{first['machine']}: {_setup_line(first, not _mu_varies(head), units)}"


def many_orbits_view(table: Table, title: str | None = None, total_rows: int | None = None,
                     units: DisplayUnits = AS_TYPED) -> FitTable:
    """One line per orbit (the first MAX_TERMINAL_ROWS), safety columns first."""
    head = first_rows(table, MAX_TERMINAL_ROWS)
    return build_table(table, MANY_COLUMNS, units=units, title=title, total_rows=total_rows,
                       setup=_machine_line(head, units), notes=status_legend(head), extra=_with_mu_column("theta_deg"))


def _why(get: dict) -> str:
    parts = [f"{get[col]} {words}" for col, words in WHY if get.get(col)]
    return ", ".join(parts) if parts else "—"


def _varies(column: str):
    """A limit shown as a column only where it varies (else in the line under the table)."""
    return lambda head: len({_limit(v) for v in head.columns[column].tolist()}) > 1


#: The rider's table on screen; the rest of its numbers are the CSV's.
SUMMARY_VIEW = (
    ColumnSpec("height_m", "height", "m", kind="length", params=("height",)),
    ColumnSpec("rho_contact_m", "turn\nradius", "m", kind="length", params=("turn_radius",),
               when=_turn_radius_shown),
    ColumnSpec("theta_deg", "θ", "°", drop=1, kind="angle", params=("theta",)),
    ColumnSpec("mu_available", "μ", format=_limit, when=_varies("mu_available")),
    ColumnSpec("max_g", "max", "g", format=_limit, when=_varies("max_g")),
    ColumnSpec("ok", "ok", value=lambda get: f"{get[_tried(get) + '_ok']}/{get[_tried(get) + '_tried']}"),
    # the speedometer's range (the contact's); the centre of mass's is the CSV's v_min_km_h, v_max_km_h
    ColumnSpec("speed", "speed", "m/s", value=lambda get: (get["v_contact_min_m_s"], get["v_contact_max_m_s"]),
               format=_spans(), show="display", **SPEED),
    ColumnSpec("lean", "lean", "°", value=lambda get: (get["lean_min_deg"], get["lean_max_deg"]), format=_spans(),
               drop=2),
    # two digits on screen: the column must leave room for why (the CSV has them all)
    ColumnSpec("load", "load", "g", value=lambda get: (get["load_min_g"], get["load_max_g"]), format=_spans(2)),
    ColumnSpec("mu_max", "μ\nneeded", digits=2),
    ColumnSpec("head", "head\nclear", "m", value=lambda get: get["head_clearance_min_m"], digits=2, **LENGTH),
    ColumnSpec("why", "why the others fail", value=_why, justify="left"),
)


def _tried(get) -> str:
    """What the rider's table counts: speeds tried, or tilts (``--alpha``)."""
    return "tilts" if "tilts_tried" in get else "speeds"


class _WhyWraps(FitTable):
    """A FitTable whose ``why`` column wraps (at word breaks) rather than
    push the numbers off a narrow console: the numbers never wrap."""

    def build(self, columns):
        out = super().build(columns)
        for col, spec in zip(out.columns, columns):
            if spec.key == "why":
                col.no_wrap, col.overflow, col.min_width = False, "fold", 10
        return out


def _fixed_limits(head: Table) -> str:
    """The limits that are the same in every row, for the line under the table."""
    words = {"mu_available": "μ available", "max_g": "max load (g)"}
    return ", ".join(f"{words[k]} {_limit(head.columns[k][0])}" for k in words
                     if len(head) and not _varies(k)(head))


def summary_view(table: Table, title: str | None = None, total_rows: int | None = None,
                 units: DisplayUnits = AS_TYPED) -> FitTable:
    """The rider's table: per contact point, the speeds (or tilts) that
    are ok of those tried, over them the speed, lean and load ranges, the
    most friction needed and the least head clearance, and why the others
    fail; the limits (μ available, max load) as a column where they vary,
    else in a line under the table."""
    tried = _tried(table)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    note = (f"{_fixed_limits(head)}; ok: {tried} feasible of those tried; ranges over the ok ones, μ needed the "
            f"most of them, head clear the least; no lap: no tilt gives the speed or the wheel does not fit")
    return build_table(table, SUMMARY_VIEW, units=units, title=title, total_rows=total_rows, setup=note,
                       cls=_WhyWraps)


#: The one-loop view; the speeds also in the user's unit (km/h when none was typed).
LOOP_SPEED = dict(kind="speed", params=("v_top",), crew=KM_H)
LOOP_FIELDS = (
    ColumnSpec("v_top_m_s", "speed at the top", "m/s", **LOOP_SPEED),
    ColumnSpec("v_top_min_m_s", "least top speed for contact", "m/s", source="eq. M22", **LOOP_SPEED),
    ColumnSpec("v_bottom_m_s", "speed at the bottom", "m/s", source="eq. M23", **LOOP_SPEED),
    ColumnSpec("load_bottom_g", "load at the bottom (the most)", "g", source="eq. M23"),
    ColumnSpec("load_top_g", "load at the top", "g"),
    ColumnSpec("mu_required", "μ required (most round loop)", source="eq. M24"),
    ColumnSpec("phi_worst_deg", "where μ peaks, φ from the top", "deg", source="eq. M24"),
    ColumnSpec("head_clearance_m", "head clearance", "m", **LENGTH),
    ColumnSpec("com_loop_radius_m", "radius of the CoM's loop", "m", **LENGTH),
    ColumnSpec("omega_top_rad_s", "rate at the top", "rad/s", kind="rate"),
    ColumnSpec("omega_bottom_rad_s", "rate at the bottom", "rad/s", kind="rate"),
)
LOOP_SPEEDS = ("v_top_m_s", "v_top_min_m_s", "v_bottom_m_s")
LOOP_OK = "keeps contact all round, enough friction, load within the limit"

#: Several loops: a line each; the head clearance is a safety column and stays longest.
LOOP_COLUMNS = (
    ColumnSpec("input_row", "#", format=str),
    ColumnSpec("theta_deg", "θ", "°", kind="angle", params=("theta",)),
    ColumnSpec("v_top_m_s", "v top", "m/s", **LOOP_SPEED),
    ColumnSpec("status", "status", format=status_text, justify="left"),
    ColumnSpec("load_bottom_g", "load\nbottom", "g"),
    ColumnSpec("mu_required", "μ\nneeded"),
    ColumnSpec("v_top_min_m_s", "v top\nmin", "m/s", drop=2, **LOOP_SPEED),
    ColumnSpec("head_clearance_m", "head\nclear", "m", drop=3, **LENGTH),
    ColumnSpec("v_bottom_m_s", "v\nbottom", "m/s", drop=1, **LOOP_SPEED),
)


#: The one-loop view inside a closed profile (docs/machine.md eqs. M25-M30): the load is largest
#: where the curve bends most, not always at the bottom; the lap time.
LOOP_ON_FIELDS = (
    ColumnSpec("v_top_m_s", "speed at the top", "m/s", **LOOP_SPEED),
    ColumnSpec("v_top_min_m_s", "least top speed for contact", "m/s", source="eq. M29", **LOOP_SPEED),
    ColumnSpec("v_bottom_m_s", "speed at the bottom", "m/s", source="eq. M26", **LOOP_SPEED),
    ColumnSpec("load_max_g", "load, the most round the loop", "g", source="eq. M30"),
    ColumnSpec("phi_load_max_deg", "where the load peaks, φ from the top", "deg", source="eq. M30"),
    ColumnSpec("load_bottom_g", "load at the bottom", "g", source="eq. M28"),
    ColumnSpec("load_top_g", "load at the top", "g", source="eq. M28"),
    ColumnSpec("mu_required", "μ required (most round loop)", source="eq. M30"),
    ColumnSpec("phi_worst_deg", "where μ peaks, φ from the top", "deg", source="eq. M30"),
    ColumnSpec("period_s", "lap time", "s", source="eq. M30"),
    ColumnSpec("head_clearance_m", "head clearance (the least round the loop)", "m", source="eq. M30", **LENGTH),
    ColumnSpec("com_loop_radius_m", "radius of the CoM's path at the top", "m", **LENGTH),
    ColumnSpec("omega_top_rad_s", "rate at the top", "rad/s", kind="rate"),
    ColumnSpec("omega_bottom_rad_s", "rate at the bottom", "rad/s", kind="rate"),
)
#: Several loops inside a profile: the largest load round the loop in place of the bottom's.
LOOP_ON_COLUMNS = tuple(ColumnSpec("load_max_g", "load\nmost", "g") if spec.key == "load_bottom_g" else spec
                        for spec in LOOP_COLUMNS)


def _loop_on_line(get: dict, mu: bool = True) -> str:
    """The arena and the limits of a loop inside a profile (no sphere's radius names it)."""
    friction = f"μ available {_limit(get['mu_available'])}, " if mu else ""
    return (f"inside the {get['surface']} ({format_number(get['height_m'], 6)} m high), "
            f"g = {format_number(get['g_m_s2'], 6)} m/s², {friction}max load {_limit(get['max_g'])} g")


def _loop_title(get: dict, units: DisplayUnits) -> str:
    return (f"vertical loop of {get['machine']}, θ = {echo_number(get['theta_deg'])}°\n"
            f"{_setup_line(get, units=units)}")


def loop_view(table: Table, total_rows: int | None = None, title: str | None = None,
              units: DisplayUnits = AS_TYPED) -> FitTable:
    """Vertical loops of a machine: one loop a quantity per line, several a
    line each; the speeds in the unit typed beside m/s (km/h when none was)."""
    inside = "surface" in table.columns           # a profile's loop (docs/machine.md eqs. M25-M30)
    if len(table) == 1 and not (total_rows or 0) > 1:
        get = row_record(table)
        specs = LOOP_ON_FIELDS if inside else LOOP_FIELDS
        fields = [spec for spec in specs if spec.key in LOOP_SPEEDS or not is_undefined(get[spec.key])]
        rows = quantity_rows(get, fields, units)
        heading = (f"vertical loop of {get['machine']}, θ = {echo_number(get['theta_deg'])}°\n{_loop_on_line(get)}"
                   if inside else _loop_title(get, units))
        return quantity_table(heading, {**get, "stability": ""}, rows, LOOP_OK)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    setup = (f"{row_record(head)['machine']}: {_loop_on_line(row_record(head), not _mu_varies(head))}" if inside
             else _machine_line(head, units))
    return build_table(table, LOOP_ON_COLUMNS if inside else LOOP_COLUMNS, units=units, title=title,
                       total_rows=total_rows, setup=setup, notes=status_legend(head),
                       extra=_with_mu_column("theta_deg"))


def ride_view(table: Table, total_rows: int | None = None, title: str | None = None,
              units: DisplayUnits = AS_TYPED) -> FitTable:
    """``ride``'s terminal view: one orbit, several, or the rider's table."""
    if "speeds_tried" in table or "tilts_tried" in table:
        return summary_view(table, title, total_rows, units)
    if len(table) == 1 and not (total_rows or 0) > 1:
        return one_orbit_view(table, units)
    return many_orbits_view(table, title, total_rows, units)


#: ``machines`` on screen; the sources go under it.  Left out first: the
#: inertias from the spin's, then the tyre.
MACHINE_COLUMNS = (
    ColumnSpec("name", "name", justify="left"),
    ColumnSpec("kind", "kind", justify="left"),
    ColumnSpec("mass_kg", "mass", "kg", kind="mass"),
    *(ColumnSpec(key, header, "m", kind="length", drop=drop) for key, header, drop in (
        ("com_height_m", "h", None), ("wheel_radius_m", "a", None), ("tyre_radius_m", "t", 5),
        ("head_height_m", "head", None))),
    *(ColumnSpec(key, header, "kg m²", drop=drop) for key, header, drop in (
        ("roll_inertia_kg_m2", "I roll", 4), ("pitch_inertia_kg_m2", "I pitch", 3),
        ("yaw_inertia_kg_m2", "I yaw", 2), ("spin_inertia_kg_m2", "J spin", 1))),
)


def machines_view(table: Table, total_rows: int | None = None, title: str | None = None,
                  units: DisplayUnits = AS_TYPED) -> FitTable:
    """The presets: a line of numbers each, and where each comes from under the table."""
    sources = [f"[dim]{escape(n)} ({escape(k)}): {escape(s)}[/dim]" for n, k, s in
               zip(table.columns["name"].tolist(), table.columns["kind"].tolist(), table.columns["source"].tolist())]
    return build_table(table, MACHINE_COLUMNS, units=units, title=title, total_rows=total_rows, notes=sources)
