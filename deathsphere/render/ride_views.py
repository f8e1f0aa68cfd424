"""Terminal views of ``deathsphere ride`` and ``deathsphere machines``: what
a show crew reads off a screen.  One orbit (or loop) is a
quantity/value/unit table like ``orbit``'s
(:func:`~deathsphere.render.orbit_views.quantity_table`); several rows put
the safety columns first (status, speed in km/h, lean, load, friction
needed, head clearance) and leave out the rest where the console is too
narrow; the rider's table says why the speeds that fail fail."""

from __future__ import annotations

from rich.markup import escape

from deathsphere.render.orbit_views import quantity_table
from deathsphere.render.terminal_table import (
    MAX_TERMINAL_ROWS,
    STABILITY_STYLE,
    Column,
    FitTable,
    first_rows,
    format_number,
    is_undefined,
    row_cap_line,
    row_record,
    row_total,
    status_legend,
    status_text,
)
from deathsphere.table import Table

#: km/h per m/s (exact by definition: the view never needs pint).
KM_H = 3.6

#: (column, label, unit, source) of the one-orbit view, the crew's first.
ORBIT_FIELDS = (
    ("v_cm_km_h", "speed of the centre of mass", "km/h", "eq. M8"),
    ("v_cm_m_s", "  the same in m/s", "m/s", "÷ 3.6"),
    ("lean_deg", "lean from the vertical, 90° − α", "deg", ""),
    ("load_g", "load on the rider |F|/(m g)", "g", "eq. M11"),
    ("mu_required", "μ required", "", "eq. M9"),
    ("head_clearance_m", "head clearance", "m", "eq. M2"),
    ("height_m", "contact height above the floor", "m", ""),
    ("com_orbit_radius_m", "radius of the CoM's lap", "m", "eq. M3"),
    ("omega_rad_s", "Ω lap rate", "rad/s", "eq. M8"),
    ("period_s", "lap time 2π/Ω", "s", ""),
    ("v_contact_m_s", "speed of the contact point", "m/s", ""),
    ("wheel_spin_rad_s", "wheel spin (relative to frame)", "rad/s", "eq. M4"),
    ("normal_per_mass_m_s2", "normal force / m", "m/s²", "eq. M9"),
    ("friction_per_mass_m_s2", "friction / m (+ down the wall)", "m/s²", "eq. M9"),
    ("growth_rate_1_s", "growth rate (max Re λ)", "1/s", "sec. 5"),
    ("freq_slow_rad_s", "nutation, slow", "rad/s", "sec. 5"),
    ("freq_fast_rad_s", "nutation, fast", "rad/s", "sec. 5"),
)
OK_REASON = "fits, Ω² > 0, keeps contact, enough friction, load within the limit"

#: Columns of the several-orbit view, in order, with their headers: the
#: row's identity, then the safety columns, then the rest.
MANY_COLUMNS = (
    ("input_row", "#"), ("height_m", "height\nm"), ("theta_deg", "θ°"), ("status", "status"),
    ("v_cm_km_h", "speed\nkm/h"), ("lean_deg", "lean°"), ("load_g", "load\ng"), ("mu_required", "μ\nneeded"),
    ("head_clearance_m", "head\nclear\nm"), ("alpha_deg", "α°"), ("v_cm_m_s", "speed\nm/s"),
    ("period_s", "lap\ns"), ("stability", "stability"), ("growth_rate_1_s", "growth\n1/s"),
)
#: Left out first on a narrow console: everything after the safety columns,
#: from the right; θ goes before them (the height says where the lap is).
MANY_DROP_ORDER = ("growth_rate_1_s", "stability", "period_s", "v_cm_m_s", "alpha_deg", "theta_deg")

#: Why a speed fails in the rider's table: count column -> words.
WHY = (("slips", "slips"), ("over_g", "over g"), ("head_hits", "head"), ("no_contact", "no contact"),
       ("no_orbit", "no lap"))


def _limit(value) -> str:
    return "∞" if is_undefined(value) else format_number(value)


def _setup_line(get: dict, mu: bool = True) -> str:
    friction = f"μ available {_limit(get['mu_available'])}, " if mu else ""
    return (f"r = {format_number(get['r_m'])} m, g = {format_number(get['g_m_s2'], 6)} m/s², "
            f"{friction}max load {_limit(get['max_g'])} g")


def _mu_varies(table: Table) -> bool:
    """Several values of μ among the rows (``--mu 0.8:1:0.1``): a column, not a line under the table."""
    return len({_limit(v) for v in table.columns["mu_available"].tolist()}) > 1


def _with_mu_column(columns: list, head: Table, after: str) -> list:
    at = next(i for i, c in enumerate(columns) if c.key == after) + 1
    return [*columns[:at], Column("mu_available", "μ", [_limit(v) for v in head.columns["mu_available"].tolist()]),
            *columns[at:]]


def _stability_rows(get: dict) -> dict:
    # the long method text is the CSV's; on screen a pointer to it
    if get.get("stability"):
        return {"stability": get["stability"], "stability_method": "sec. 5, no steering"}
    return {"stability": ""}


def one_orbit_view(table: Table) -> FitTable:
    """Every quantity of one orbit, one per line, with its unit and equation."""
    get = row_record(table)
    rows = [(label, format_number(get[col], 5), unit, source) for col, label, unit, source in ORBIT_FIELDS
            if not (col.startswith(("growth", "freq")) and is_undefined(get[col]))]
    where = f"θ = {format_number(get['theta_deg'])}°, α = {format_number(get['alpha_deg'])}°"
    title = f"{get['machine']}, {where}\n{_setup_line(get)}"
    return quantity_table(title, {**get, **_stability_rows(get)}, rows, OK_REASON)


def _cells(col: str, values: list) -> list[str]:
    if col == "status":
        return [status_text(v) for v in values]
    if col == "stability":
        return [STABILITY_STYLE.get(v, escape(str(v))) for v in values]
    if col == "input_row":
        return [str(v) for v in values]
    return [format_number(v) for v in values]


def many_orbits_view(table: Table, title: str | None = None, total_rows: int | None = None) -> FitTable:
    """One line per orbit (the first MAX_TERMINAL_ROWS), safety columns first."""
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    columns = [Column(col, header, _cells(col, head.columns[col].tolist()), "left" if col == "status" else "right")
               for col, header in MANY_COLUMNS
               if not (col == "stability" and not any(head.columns[col].tolist()))
               and not (col == "growth_rate_1_s" and not any(head.columns["stability"].tolist()))]
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    first, several = row_record(head), _mu_varies(head)
    if several:
        columns = _with_mu_column(columns, head, "theta_deg")
    return FitTable(columns, MANY_DROP_ORDER, title=title, footer=footer,
                    notes=[f"[dim]{first['machine']}: {_setup_line(first, not several)}[/dim]", *status_legend(head)])


def _span(lo, hi, digits: int = 3) -> str:
    if is_undefined(lo):
        return "—"
    a, b = format_number(lo, digits), format_number(hi, digits)
    return a if a == b else f"{a}–{b}"


def _why(get: dict) -> str:
    parts = [f"{get[col]} {words}" for col, words in WHY if get.get(col)]
    return ", ".join(parts) if parts else "—"


#: Columns of the rider's table on screen: (key, header).
SUMMARY_VIEW = (("height_m", "height\nm"), ("theta_deg", "θ°"), ("mu_available", "μ"), ("max_g", "max\ng"),
                ("ok", "ok"), ("speed", "speed\nkm/h"), ("lean", "lean°"), ("load", "load\ng"),
                ("mu_max", "μ\nneeded"), ("head", "head\nclear\nm"), ("why", "why the others fail"))
SUMMARY_DROP_ORDER = ("theta_deg", "lean")


class _WhyWraps(FitTable):
    """A FitTable whose ``why`` column wraps (at word breaks) rather than
    push the numbers off a narrow console: the numbers never wrap."""

    def build(self, columns):
        out = super().build(columns)
        for col, spec in zip(out.columns, columns):
            if spec.key == "why":
                col.no_wrap, col.overflow, col.min_width = False, "fold", 10
        return out


def summary_view(table: Table, title: str | None = None, total_rows: int | None = None) -> FitTable:
    """The rider's table: per contact point, the speeds (or tilts) that
    are ok of those tried, over them the speed, lean and load ranges, the
    most friction needed and the least head clearance, and why the others
    fail; the limits (μ available, max load) as a column where they vary,
    else in a line under the table."""
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    tried = "tilts" if "tilts_tried" in head else "speeds"
    cells = {key: [] for key, _ in SUMMARY_VIEW}
    for i in range(len(head)):
        get = row_record(head, i)
        cells["height_m"].append(format_number(get["height_m"]))
        cells["theta_deg"].append(format_number(get["theta_deg"]))
        cells["mu_available"].append(_limit(get["mu_available"]))
        cells["max_g"].append(_limit(get["max_g"]))
        cells["ok"].append(f"{get[f'{tried}_ok']}/{get[f'{tried}_tried']}")
        cells["speed"].append(_span(get["v_min_km_h"], get["v_max_km_h"]))
        cells["lean"].append(_span(get["lean_min_deg"], get["lean_max_deg"]))
        # two digits on screen: the column must leave room for why (the CSV has them all)
        cells["load"].append(_span(get["load_min_g"], get["load_max_g"], 2))
        cells["mu_max"].append(format_number(get["mu_max"], 2))
        cells["head"].append(format_number(get["head_clearance_min_m"], 2))
        cells["why"].append(_why(get))
    constant = [k for k in ("mu_available", "max_g") if len(set(cells[k])) <= 1]
    columns = [Column(key, header, cells[key], "left" if key == "why" else "right")
               for key, header in SUMMARY_VIEW if key not in constant]
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    limits = {"mu_available": "μ available", "max_g": "max load (g)"}
    fixed = ", ".join(f"{limits[k]} {cells[k][0]}" for k in constant if cells[k])
    notes = [f"[dim]{fixed}; ok: {tried} feasible of those tried; ranges over the ok ones, μ needed the "
             f"most of them, head clear the least; no lap: no tilt gives the speed or the wheel does not fit[/dim]"]
    return _WhyWraps(columns, SUMMARY_DROP_ORDER, title=title, footer=footer, notes=notes)


#: (column, label, unit, source) of the one-loop view; speeds also in the user's unit.
LOOP_FIELDS = (
    ("v_top_m_s", "speed at the top", "m/s", ""),
    ("v_top_min_m_s", "least top speed for contact", "m/s", "eq. M22"),
    ("v_bottom_m_s", "speed at the bottom", "m/s", "eq. M23"),
    ("load_bottom_g", "load at the bottom (the most)", "g", "eq. M23"),
    ("load_top_g", "load at the top", "g", ""),
    ("mu_required", "μ required (most round loop)", "", "eq. M24"),
    ("phi_worst_deg", "where μ peaks, φ from the top", "deg", "eq. M24"),
    ("head_clearance_m", "head clearance", "m", ""),
    ("com_loop_radius_m", "radius of the CoM's loop", "m", ""),
    ("omega_top_rad_s", "rate at the top", "rad/s", ""),
    ("omega_bottom_rad_s", "rate at the bottom", "rad/s", ""),
)
LOOP_SPEEDS = ("v_top_m_s", "v_top_min_m_s", "v_bottom_m_s")
LOOP_OK = "keeps contact all round, enough friction, load within the limit"


def _loop_title(get: dict) -> str:
    return f"vertical loop of {get['machine']}, θ = {format_number(get['theta_deg'])}°\n{_setup_line(get)}"


def loop_view(table: Table, total_rows: int | None = None, speed_unit: tuple[str, float] | None = None,
              title: str | None = None) -> FitTable:
    """Vertical loops of a machine: one loop a quantity per line, several a
    line each; ``speed_unit`` (name, per m/s) the unit the speeds were typed
    in, shown beside m/s (km/h when none was typed)."""
    unit, scale = speed_unit if speed_unit and speed_unit[0] != "m/s" else ("km/h", KM_H)
    if len(table) == 1 and not (total_rows or 0) > 1:
        get = row_record(table)
        rows = []
        for col, label, u, source in LOOP_FIELDS:
            if is_undefined(get[col]) and col not in LOOP_SPEEDS:
                continue
            rows.append((label, format_number(get[col], 5), u, source))
            if col in LOOP_SPEEDS:
                value = get[col] if is_undefined(get[col]) else get[col] * scale
                rows.append((f"  the same in {unit}", format_number(value, 5), unit, ""))
        return quantity_table(_loop_title(get), {**get, "stability": ""}, rows, LOOP_OK)
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    columns = [Column("input_row", "#", _cells("input_row", head.columns["input_row"].tolist())),
               Column("theta_deg", "θ°", _cells("theta_deg", head.columns["theta_deg"].tolist()))]
    for col, header in (("v_top_m_s", "v top"), ("status", "status"), ("load_bottom_g", "load\nbottom\ng"),
                        ("mu_required", "μ\nneeded"), ("v_top_min_m_s", "v top\nmin"),
                        ("head_clearance_m", "head\nclear\nm"), ("v_bottom_m_s", "v\nbottom")):
        values = head.columns[col].tolist()
        if col in LOOP_SPEEDS:
            columns.append(Column(col, f"{header}\nm/s", _cells(col, values)))
            columns.append(Column(f"{col}:{unit}", f"{header}\n{unit}",
                                  _cells(col, [v if is_undefined(v) else v * scale for v in values])))
        else:
            columns.append(Column(col, header, _cells(col, values), "left" if col == "status" else "right"))
    # the head clearance is a safety column: it stays longest
    drop = (("v_bottom_m_s", f"v_bottom_m_s:{unit}"), ("v_top_min_m_s", f"v_top_min_m_s:{unit}"), "head_clearance_m")
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    first, several = row_record(head), _mu_varies(head)
    if several:
        columns = _with_mu_column(columns, head, "theta_deg")
    return FitTable(columns, drop, title=title, footer=footer,
                    notes=[f"[dim]{first['machine']}: {_setup_line(first, not several)}[/dim]", *status_legend(head)])


def ride_view(table: Table, total_rows: int | None = None, title: str | None = None) -> FitTable:
    """``ride``'s terminal view: one orbit, several, or the rider's table."""
    if "speeds_tried" in table or "tilts_tried" in table:
        return summary_view(table, title, total_rows)
    if len(table) == 1 and not (total_rows or 0) > 1:
        return one_orbit_view(table)
    return many_orbits_view(table, title, total_rows)


#: Columns of ``machines`` on screen: (column, header); the sources go under it.
MACHINE_COLUMNS = (("name", "name"), ("kind", "kind"), ("mass_kg", "mass\nkg"), ("com_height_m", "h\nm"),
                   ("wheel_radius_m", "a\nm"), ("tyre_radius_m", "t\nm"), ("head_height_m", "head\nm"),
                   ("roll_inertia_kg_m2", "I roll\nkg m²"), ("pitch_inertia_kg_m2", "I pitch\nkg m²"),
                   ("yaw_inertia_kg_m2", "I yaw\nkg m²"), ("spin_inertia_kg_m2", "J spin\nkg m²"))


def machines_view(table: Table, total_rows: int | None = None, title: str | None = None) -> FitTable:
    """The presets: a line of numbers each, and where each comes from under the table."""
    text = ("name", "kind")
    columns = [Column(col, header, [escape(str(v)) if col in text else format_number(v)
                                    for v in table.columns[col].tolist()], "left" if col in text else "right")
               for col, header in MACHINE_COLUMNS]
    sources = [f"[dim]{escape(n)} ({escape(k)}): {escape(s)}[/dim]" for n, k, s in
               zip(table.columns["name"].tolist(), table.columns["kind"].tolist(), table.columns["source"].tolist())]
    drop = ("spin_inertia_kg_m2", "yaw_inertia_kg_m2", "pitch_inertia_kg_m2", "roll_inertia_kg_m2", "tyre_radius_m")
    return FitTable(columns, drop, title=title, notes=sources)
