"""Terminal view of a simulation: the summary of one simulated body."""

from __future__ import annotations

from rich.markup import escape

from deathsphere.render.display_units import AS_TYPED, DisplayUnits
from deathsphere.render.terminal_table import Column, FitTable, echo_number, is_undefined, row_record
from deathsphere.render.view_builder import ColumnSpec, globe_text, quantity_rows, quantity_text
from deathsphere.table import Table

#: (column, label, unit) of the simulation summary view.
SIMULATION_FIELDS = (
    ("periods_simulated", "periods simulated", ""),
    ("event_time_s", "event at t", "s"),
    ("event_phi_deg", "event at phi", "deg"),
    ("max_theta_drift_deg", "max drift of theta", "deg"),
    ("max_alpha_drift_deg", "max drift of alpha", "deg"),
    ("min_normal_per_mass_m_s2", "least normal force / m", "m/s²"),
    ("max_mu_required", "most friction needed μ", ""),
    ("max_abs_energy_drift", "max |energy drift| (relative)", ""),
    ("max_constraint_residual", "max constraint residual", ""),
    ("min_head_clearance_m", "least head clearance", "m"),
    ("max_height_drift_m", "max drift of the height", "m"),
    ("max_rho_drift_m", "max drift of rho", "m"),
    ("n_steps", "steps", ""),
    ("wall_time_s", "wall time", "s"),
)


def _typed_line(get: dict, units: DisplayUnits) -> str:
    """The orbit's speed and the globe, where they show in another unit
    (typed so, or asked for): ``v_cm = 11.11 m/s (40 km/h), r = 2.438 m
    (diameter 16 ft)``; empty otherwise (the SI figures are the CSV's)."""
    parts = []
    speed = units.unit("speed", ("speed",))
    if speed is not None and not is_undefined(get.get("speed_m_s")):
        parts.append(f"v_cm = {quantity_text(get['speed_m_s'], 'm/s', speed)}")
    if (units.unit("length", ("r", "diameter")) is not None) and not is_undefined(get.get("r_m")):
        parts.append(globe_text(get, units, number=echo_number))
    return ", ".join(parts)


def simulation_view(summary: Table, units: DisplayUnits = AS_TYPED) -> FitTable:
    """The summary of one simulated body (the first row if several); the
    head clearance, the orbit's speed and the globe also in the unit
    ``units`` gives.  The title and the reason wrap at the console's
    width, not the table's."""
    get = row_record(summary)
    # off the globe the lane is its height (flat ground: its turn radius, r_m); inputs echoed as typed
    lane = (f"θ = {echo_number(get['theta_deg'])}°" if "surface" not in get
            else f"on the {get['surface']}, turn radius {echo_number(get['r_m'])} m" if get["surface"] == "plane"
            else f"on the {get['surface']}, height "
                 f"{quantity_text(get['height_m'], 'm', units.unit('length', ('height',)), number=echo_number)}")
    what = (f"{get['body']} {get['side']}, {get['orbit']} orbit, {lane}"
            + (f", α = {echo_number(get['alpha_deg'])}°" if not is_undefined(get.get("alpha_deg")) else "")
            + (f", kick {echo_number(get['perturb_deg'])} deg" if get.get("perturb_deg") else ""))
    typed = _typed_line(get, units)
    title = (f"simulation: {what}\n{typed + chr(10) if typed else ''}solve_ivp {get['method']}, "
             f"rtol {get['rtol']:g}, atol {get['atol']:g}, {get['frame']} frame")
    specs = [ColumnSpec(col, label, unit, kind="length" if unit == "m" else None) for col, label, unit in
             SIMULATION_FIELDS if col in get and not is_undefined(get[col])]
    rows = [(escape(label), value, unit) for label, value, unit, _ in quantity_rows(get, specs, units, digits=4)]
    status = get["status"]
    style = {"completed": "green", "contact_lost": "red", "slips": "yellow"}.get(status, "magenta")
    rows.append(("status", f"[{style}]{escape(status)}[/{style}]", ""))
    columns = [Column(head, head, [row[k] for row in rows], "right" if head == "value" else "left")
               for k, head in enumerate(("quantity", "value", "unit"))]
    notes = [escape(f"{status}: {get['reason']}")] if get.get("reason") else []
    return FitTable(columns, title=title, notes=notes)
