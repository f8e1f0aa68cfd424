"""Terminal views of orbits: every quantity of one orbit, a summary row
per orbit for many, the vertical orbits, and any other result table column
by column (:func:`write_rich_table` picks).  Each view is its column specs
(:mod:`~deathsphere.render.view_builder`); a quantity typed in another unit
shows in it beside SI."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from rich.console import Console
from rich.markup import escape

from deathsphere.model import Table
from deathsphere.params import PARAMS
from deathsphere.render.display_units import AS_TYPED, KM_H, RPM, DisplayUnits
from deathsphere.render.terminal_table import (
    MAX_TERMINAL_ROWS,
    STABILITY_STYLE,
    Column,
    FitTable,
    echo_number,
    first_rows,
    format_number,
    is_undefined,
    row_record,
    row_total,
    status_legend,
    status_text,
)
from deathsphere.render.view_builder import ColumnSpec, build_table, globe_text, quantity_rows, quantity_text

#: (column, label, unit, source) for the one-orbit view.
ORBIT_FIELDS = (
    ("r_prime_m", "r' centre to axis", "m", "eq. 8b"),
    ("omega_rad_s", "Ω orbital rate", "rad/s", "eq. 29"),
    ("period_s", "period 2π/Ω", "s", ""),
    ("v_cm_m_s", "v_cm = |r'|Ω centre speed", "m/s", ""),
    ("v_contact_m_s", "v_contact = |Ω|ρ contact speed", "m/s", ""),
    ("spin_rad_s", "ω₁ = r'Ω/a wheel spin", "rad/s", "eq. 13"),
    ("omega3_rad_s", "ω₃ = -Ω sin α", "rad/s", "eq. 13"),
    ("branch", "branch of eq. 55 (0 slow, 1 fast)", "", "eq. 55"),
    ("omega3_min_real_rad_s", "least |ω₃| for a real orbit", "rad/s", "eq. 56"),
    ("omega3_min_contact_rad_s", "least |ω₃| for contact", "rad/s", "eq. 58/59"),
    ("accel_m_s2", "centre acceleration", "m/s²", "eq. 32"),
    ("accel_g", "centre acceleration", "g", "eq. 36"),
    ("load_g", "load on the rider |a − g|/g", "g", "eq. 32"),
    ("normal_per_mass_m_s2", "normal force / m", "m/s²", "eq. 32"),
    ("friction_per_mass_m_s2", "friction / m (+ down)", "m/s²", "eq. 32"),
    ("mu_required", "μ required", "", "eq. 35"),
    ("growth_rate_1_s", "growth rate (max Re λ)", "1/s", "exact"),
    ("freq_slow_rad_s", "nutation, slow (turning frame)", "rad/s", "exact"),
    ("freq_fast_rad_s", "nutation, fast (turning frame)", "rad/s", "exact"),
)

OK_REASON = "fits, Ω² > 0, keeps contact, enough friction"

#: How a one-orbit row is shown beside SI: column -> (kind, the options it
#: is typed as, the crew's unit).  The centre speed and the wheel's spin
#: are repeated in km/h and rpm when nothing else was asked for (3.6 and
#: 60/2π are exact by definition: no pint).  A row of its own rather than
#: a cell beside the SI figure: "m/s (28.4 km/h)" widens the unit column
#: enough that an 80-column terminal would lose the source column.
FIELD_UNITS = {
    "r_prime_m": ("length", (), None),
    "omega_rad_s": ("rate", ("omega",), None),
    "v_cm_m_s": ("speed", ("com_speed",), KM_H),
    "v_contact_m_s": ("speed", ("speed",), None),
    "spin_rad_s": ("rate", (), RPM),
    "omega3_rad_s": ("rate", ("omega3",), None),
}


def _field_spec(col: str, label: str, unit: str, source: str) -> ColumnSpec:
    kind, params, crew = FIELD_UNITS.get(col, (None, (), None))
    return ColumnSpec(col, label, unit, source=source, kind=kind, params=params, crew=crew)


#: Labels that differ by body: (body, column) -> (label, source); None hides the row.
BODY_LABELS = {
    ("sphere", "r_prime_m"): ("r' centre to axis, (r ∓ a) sin θ", "eq. 42"),
    ("sphere", "accel_m_s2"): ("centre acceleration", ""),
    ("sphere", "spin_rad_s"): ("rolling rate v_cm/a", ""),
    ("sphere", "omega3_rad_s"): ("ω₃ spin about contact normal", "eq. 55"),
    ("sphere", "omega_rad_s"): ("Ω orbital rate (signed)", "eq. 55"),
    ("sphere", "accel_g"): ("centre acceleration", ""),
    ("sphere", "normal_per_mass_m_s2"): ("normal force / m", "eq. 57"),
    ("sphere", "friction_per_mass_m_s2"): ("friction / m (+ down)", "eq. 57"),
    ("particle", "omega_rad_s"): ("Ω orbital rate", "Ω² = -g/(r cos θ)"),
    ("particle", "r_prime_m"): ("r' = r sin θ", ""),
    ("particle", "accel_m_s2"): ("centre acceleration", ""),
    ("particle", "normal_per_mass_m_s2"): ("normal force / m", ""),
    ("particle", "friction_per_mass_m_s2"): None,
    ("particle", "spin_rad_s"): None,
    ("particle", "omega3_rad_s"): None,
    ("particle", "accel_g"): ("centre acceleration", ""),
    ("particle", "mu_required"): None,
    ("wheel", "branch"): None,
    ("wheel", "omega3_min_real_rad_s"): None,
    ("wheel", "omega3_min_contact_rad_s"): None,
    ("particle", "omega3_min_real_rad_s"): None,
    ("particle", "omega3_min_contact_rad_s"): None,
    ("particle", "branch"): None,
}


def _on_another_surface(get: dict) -> bool:
    """A row on a surface other than the globe (docs/surfaces.md)."""
    return get.get("surface") not in (None, "", "sphere")


def _arena_text(get: dict, units: DisplayUnits = AS_TYPED) -> str:
    """The arena of a row: the globe's radius, or the surface by name."""
    if not _on_another_surface(get):
        return globe_text(get, units, number=echo_number)
    if is_undefined(get.get("r_m")):
        return str(get["surface"])
    radius = quantity_text(get["r_m"], "m", units.unit("length", ("diameter",)), number=echo_number)
    return f"{get['surface']} of radius {radius}"


def _lane_text(get: dict, units: DisplayUnits = AS_TYPED) -> str:
    """Where the row's lane is: θ on the globe; elsewhere the contact's
    height, distance from the axis and the wall's angle."""
    if not _on_another_surface(get):
        return f"θ = {echo_number(get['theta_deg'])}°"
    height = quantity_text(get["height_m"], "m", units.unit("length", ("height",)), number=echo_number)
    return (f"h = {height}, ρ = {format_number(get['rho_contact_m'])} m, "
            f"β = {echo_number(get['wall_angle_deg'])}°")


def _setup_line(get: dict, units: DisplayUnits = AS_TYPED) -> str:
    a = quantity_text(get["a_m"], "m", units.unit("length", ("a",)), number=echo_number)
    return (f"a = {a}, {_arena_text(get, units)}, "
            f"k = {echo_number(get['k'])}, g = {format_number(get['g_m_s2'], 6)} m/s²")


def quantity_table(title: str, get: dict, rows, ok_text: str, notes=()) -> FitTable:
    """The one-result view: ``rows`` of (label, value, unit, source), then
    the stability (if computed) and the status; the reason under it.  On a
    narrow console the source column goes first."""
    rows = list(rows)
    if get.get("stability"):
        rows.append(("stability", STABILITY_STYLE.get(get["stability"], get["stability"]), "",
                     get["stability_method"]))
        if get.get("stability_kind"):
            # which kind of stable (or unstable): a disturbance that persists, dies or grows
            rows.append(("  a disturbance is", get["stability_kind"], "", "stability_kind"))
    rows.append(("status", status_text(get["status"]), "", ""))
    labels, values, units, sources = (list(c) for c in zip(*rows))
    columns = [Column("quantity", "quantity", labels, "left"), Column("value", "value", values),
               Column("unit", "unit", units, "left"), Column("source", "source", sources, "left", "dim")]
    reason = f"[dim italic]{get['status']}: {escape(get['reason'] or ok_text)}[/dim italic]"
    return FitTable(columns, drop_order=("source",), title=title, footer=[reason, *notes])


def spin_needed_line(get: dict) -> str:
    """Sphere: the least |ω₃| for an orbit and for contact, as a sentence."""
    real, contact = get["omega3_min_real_rad_s"], get["omega3_min_contact_rad_s"]
    where = f"θ = {echo_number(get['theta_deg'])}°"
    contact_text = ("no spin keeps contact" if is_undefined(contact)
                    else f"≥ {format_number(contact)} rad/s for contact (eqs. 58/59)")
    return f"needs |ω₃| ≥ {format_number(real)} rad/s for an orbit (eq. 56), {contact_text} at {where}"


def spin_too_low(get: dict) -> bool:
    """A rolling sphere with no orbit (or no contact) because |ω₃| is below
    the least that gives one; not, say, the missing second branch on the
    equator, or the slow branch of a spin that is fast enough."""
    if get.get("body") != "sphere" or "omega3_min_real_rad_s" not in get or is_undefined(get.get("omega3_rad_s")):
        return False
    spin = abs(get["omega3_rad_s"])
    if get["status"] == "no_orbit":
        return spin < get["omega3_min_real_rad_s"]
    if get["status"] == "no_contact":
        least = get["omega3_min_contact_rad_s"]
        return is_undefined(least) or spin < least
    return False


def one_orbit_table(table: Table, row: int = 0, units: DisplayUnits = AS_TYPED) -> FitTable:
    """A two-column view of every quantity of one orbit (undefined ones as —)."""
    get = row_record(table, row)
    angles = _lane_text(get, units)
    if not is_undefined(get["alpha_deg"]):
        angles += f", α = {echo_number(get['alpha_deg'])}°"
    specs = []
    for col, label, unit, source in ORBIT_FIELDS:
        override = BODY_LABELS.get((get["body"], col), (label, source))
        if override is not None:
            specs.append(_field_spec(col, override[0], unit, override[1]))
    rows = quantity_rows(get, specs, units)
    mu = get.get("mu_available")
    rows.append(("μ available", "∞" if is_undefined(mu) else format_number(mu), "", "--mu"))
    notes = []
    if spin_too_low(get):
        notes.append(spin_needed_line(get))
    return quantity_table(f"{get['body']} {get['side']}, {angles}\n{_setup_line(get, units)}", get, rows,
                          OK_REASON, notes)


def _styled(styles: dict):
    return lambda v: styles.get(v, escape(str(v)))


#: The many-orbit terminal view's columns (units on the headers' last line).
SUMMARY_SPECS = {spec.key: spec for spec in (
    ColumnSpec("input_row", "#"),
    ColumnSpec("theta_deg", "θ", "°", kind="angle", params=("theta",)),
    ColumnSpec("height_m", "h", "m", kind="length", params=("height",)),
    ColumnSpec("alpha_deg", "α", "°", kind="angle", params=("alpha",)),
    ColumnSpec("branch", "br"),
    ColumnSpec("omega3_rad_s", "ω₃", "rad/s", kind="rate", params=("omega3",)),
    ColumnSpec("status", "status", format=status_text, justify="left"),
    ColumnSpec("omega_rad_s", "Ω", "rad/s", kind="rate", params=("omega",)),
    ColumnSpec("v_cm_m_s", "v_cm", "m/s", kind="speed", params=("com_speed",)),
    ColumnSpec("v_contact_m_s", "v_contact", "m/s", kind="speed", params=("speed",)),
    ColumnSpec("spin_rad_s", "ω₁", "rad/s", kind="rate"),
    ColumnSpec("accel_g", "accel", "g"),
    ColumnSpec("load_g", "load", "g"),
    ColumnSpec("mu_required", "μ\nrequired"),
    ColumnSpec("stability", "stability", format=_styled(STABILITY_STYLE), justify="left"),
    ColumnSpec("omega3_min_real_rad_s", "|ω₃| min\norbit", "rad/s", kind="rate", params=("omega3",)),
    ColumnSpec("omega3_min_contact_rad_s", "|ω₃| min\ncontact", "rad/s", kind="rate", params=("omega3",)),
)}
#: Headers of the many-orbit terminal view (units on the last line).
SUMMARY_HEADERS = {key: spec.heading() for key, spec in SUMMARY_SPECS.items()}
#: Columns of the many-orbit view per body, in display order.  The ones not
#: in SUMMARY_DROP_ORDER identify the row (#, θ, α or branch, status) and are
#: always shown.
SUMMARY_COLUMNS = {
    "wheel": ("input_row", "theta_deg", "alpha_deg", "status", "omega_rad_s", "v_cm_m_s", "v_contact_m_s",
              "load_g", "mu_required", "stability"),
    "sphere": ("input_row", "theta_deg", "branch", "omega3_rad_s", "status", "omega_rad_s", "v_cm_m_s",
               "omega3_min_real_rad_s", "omega3_min_contact_rad_s", "mu_required", "stability"),
    "particle": ("input_row", "theta_deg", "status", "omega_rad_s", "v_cm_m_s", "load_g"),
    "mixed": ("input_row", "theta_deg", "alpha_deg", "branch", "status", "omega_rad_s", "v_cm_m_s",
              "mu_required", "stability"),
}
#: What a narrow console leaves out first, per body.  Stability and μ are
#: verdicts on an orbit that exists, so they go before the orbit itself
#: (Ω, v_cm).  For a sphere the least spins go first: they depend on θ
#: alone, not on the row, and for the rows that need them (no orbit, no
#: contact) a line under the table gives them anyway; its own ω₃ is an
#: input and goes last.
SUMMARY_DROP_ORDER = {
    "wheel": ("stability", "mu_required", "load_g", "v_contact_m_s", "v_cm_m_s", "omega_rad_s"),
    "sphere": ("omega3_min_contact_rad_s", "omega3_min_real_rad_s", "stability", "mu_required", "v_cm_m_s",
               "omega_rad_s", "omega3_rad_s"),
    "particle": ("load_g", "v_cm_m_s", "omega_rad_s"),
    "mixed": ("stability", "mu_required", "v_cm_m_s", "omega_rad_s"),
}
#: Lines of "needs |ω₃| ≥ ..." under a many-sphere table; the columns carry the rest.
MAX_SPIN_LINES = 3


def summary_specs(kind: str) -> list[ColumnSpec]:
    """The many-orbit view's specs for ``kind`` (a body, or mixed), each
    with its place in the body's drop order."""
    order = SUMMARY_DROP_ORDER[kind]
    return [replace(SUMMARY_SPECS[col], drop=order.index(col) if col in order else None)
            for col in SUMMARY_COLUMNS[kind]]


def _spin_lines(table: Table) -> list[str]:
    """For the spheres shown whose spin is too low for an orbit or for
    contact: the least spin that would do, once per setup and θ."""
    if "omega3_min_real_rad_s" not in table:
        return []
    rows = [i for i, (b, s) in enumerate(zip(table.columns["body"].tolist(), table.columns["status"].tolist()))
            if b == "sphere" and s != "ok"]
    setup_cols = ("a_m", "r_m", "k", "g_m_s2", "side")
    first = {}
    for i in rows:
        get = row_record(table, i)
        if spin_too_low(get):
            first.setdefault(tuple(get[c] for c in ("theta_deg", *setup_cols)), i)
    several_setups = len({key[1:] for key in first}) > 1
    lines = []
    for key, i in list(first.items())[:MAX_SPIN_LINES]:
        get = row_record(table, i)
        line = spin_needed_line(get)
        if several_setups:
            line += f" ({get['side']}, {_setup_line(get)})"
        lines.append(line)
    if len(first) > MAX_SPIN_LINES:
        lines.append(f"… and at {len(first) - MAX_SPIN_LINES} more θ: see the |ω₃| min columns "
                     f"(omega3_min_real_rad_s, omega3_min_contact_rad_s)")
    return lines


def many_orbits_table(table: Table, title: str | None = None, total_rows: int | None = None,
                      units: DisplayUnits = AS_TYPED) -> FitTable:
    """One summary row per orbit (the first MAX_TERMINAL_ROWS of
    ``total_rows``), then each distinct reason once."""
    head = first_rows(table, MAX_TERMINAL_ROWS)
    bodies = set(head.columns["body"].tolist())
    kind = bodies.pop() if len(bodies) == 1 else "mixed"
    specs = summary_specs(kind)
    if "surface" in head and any(s not in ("", "sphere") for s in head.columns["surface"].tolist()):
        # off the globe a lane is its height (theta is the sphere's)
        specs = [replace(SUMMARY_SPECS["height_m"], drop=spec.drop) if spec.key == "theta_deg" else spec
                 for spec in specs]
    # the number format looked up here, at the call: the view's own
    return build_table(table, specs, units=units, title=title, total_rows=total_rows,
                       notes=[*status_legend(head), *_spin_lines(head)], number=format_number)


#: Column-name endings that are units, longest first.
UNIT_SUFFIXES = (("_n_m_s_rad", "N·m·s/rad"), ("_n_m_rad", "N·m/rad"), ("_kg_m2", "kg·m²"), ("_n_m", "N·m"),
                 ("_m_s2", "m/s²"), ("_rad_s", "rad/s"), ("_deg_s", "deg/s"), ("_km_h", "km/h"), ("_m_s", "m/s"),
                 ("_1_s", "1/s"), ("_deg", "deg"), ("_pct", "%"), ("_kg", "kg"), ("_s", "s"), ("_m", "m"),
                 ("_g", "g"))
#: Columns of any table that say which row it is: never left out.
GENERIC_KEYS = frozenset({"input_row", "curve", "theta_deg", "phi_deg", "interval", "status", "found"})


#: Columns that hold an option as typed (theta_deg holds --theta).
TYPED_COLUMNS = {p.column: (name,) for name, p in PARAMS.items() if p.column}


#: Columns whose name does not read as words once its unit is off: the
#: words and the unit a view shows instead.
NAMED_COLUMNS = {"max_g": ("max load", "g"), "steer": ("steer mode", ""), "k": ("inertia factor k", "")}


def _split_name(name: str) -> tuple[str, str]:
    """``v_min_m_s`` -> (``v min``, ``m/s``): the words and the unit."""
    if name in NAMED_COLUMNS:
        return NAMED_COLUMNS[name]
    for suffix, unit in UNIT_SUFFIXES:
        if name.endswith(suffix) and len(name) > len(suffix):
            return _words(name[:-len(suffix)]), unit
    return _words(name), ""


#: The kind of the quantities in each SI unit a view shows in another unit.
UNIT_KINDS = {"m": "length", "m/s": "speed", "rad/s": "rate", "deg": "angle", "kg": "mass"}


def quantity_kind(name: str) -> str | None:
    """The kind of quantity a column holds, read off its name's unit (the
    whole unit: ``steer_torque_n_m`` is in N·m, not a length)."""
    return UNIT_KINDS.get(_split_name(name)[1])


def _words(stem: str) -> str:
    # v_cm is a symbol, not two words; "per mass" is the "/ m" of the orbit views
    return stem.replace("v_cm", "\0").replace("_per_mass", " / m").replace("_", " ").replace("\0", "v_cm")


def _plain_cell(v, digits: int = 4) -> str:
    if isinstance(v, (str, bool, np.bool_)):
        return escape(str(v))
    return format_number(v, digits)


def generic_spec(name: str, drop=None, justify: str = "right") -> ColumnSpec:
    """Any table's column as a spec: its header and kind read off its name."""
    words, unit = _split_name(name)
    return ColumnSpec(name, words, unit, drop=drop, justify=justify, format=None, kind=quantity_kind(name),
                      params=TYPED_COLUMNS.get(name, ()))


def generic_table(table: Table, title: str | None = None, total_rows: int | None = None,
                  units: DisplayUnits = AS_TYPED) -> FitTable:
    """Any table: one column per field (for results that are not orbits).

    Columns equal in every row (the inputs) go to a line under it, and a
    status's reason to a legend.  On a narrow console the columns are left
    out from the right (these tables put their inputs first), keeping the
    first column and any of GENERIC_KEYS.  A length, speed, rate or angle
    shows again in the unit :class:`DisplayUnits` gives, beside SI."""
    if len(table) == 1 and not (total_rows or 0) > 1:
        # one result: a quantity per line, its name in words and its unit apart (as one orbit's view)
        get = row_record(table)
        rows = quantity_rows(get, [generic_spec(n) for n in table.names], units, number=_plain_cell, digits=6)
        return FitTable([Column("quantity", "quantity", [r[0] for r in rows], "left"),
                         Column("value", "value", [r[1] for r in rows]),
                         Column("unit", "unit", [escape(r[2]) for r in rows], "left")], title=title)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    same = [n for n in table.names if _constant(table.columns[n])]
    legend = status_legend(head) if "status" in table and "reason" in table else []
    hidden = set(same) | ({"reason"} if legend or "status" in table else set())
    names = [n for n in table.names if n not in hidden]
    keys = {names[0], *GENERIC_KEYS} if names else set()
    drops = [n for n in reversed(names) if n not in keys]
    specs = [generic_spec(n, drops.index(n) if n in drops else None,
                          "left" if head.columns[n].dtype == object else "right") for n in names]
    first = row_record(head) if same else {}
    constants = ", ".join(_constant_text(n, first[n]) for n in same if first[n] != "")
    notes = [f"[dim]{constants}[/dim]"] if constants else []
    return build_table(table, specs, units=units, title=title, total_rows=total_rows, notes=[*notes, *legend],
                       number=_plain_cell)


def _constant_text(name: str, value) -> str:
    """A column equal in every row, for the line under the table: its name
    in words and its unit (``a = 0.3 m``, ``max load = 5 g``)."""
    words, unit = _split_name(name)
    text = _plain_cell(value)
    return f"{words} = {text} {escape(unit)}" if unit and text not in ("—", "") else f"{words} = {text}"


def _constant(values: np.ndarray) -> bool:
    if len(values) == 0:
        return False
    if values.dtype.kind == "f":
        return bool((values == values[0]).all() or np.isnan(values).all())
    if values.dtype.kind in "iub":
        return bool((values == values[0]).all())
    first = str(values[0])
    return all(str(v) == first for v in values.tolist())


#: The columns that make a table one of orbits, and every column the orbit
#: views read without asking: a table that lacks one (the limits, a
#: region's boundaries) is shown column by column, never half as an orbit.
ORBIT_VIEW_COLUMNS = frozenset({"input_row", "body", "side", "theta_deg", "alpha_deg", "a_m", "r_m", "k", "g_m_s2",
                                "status", "reason", "omega_rad_s"})


def rich_table(table: Table, title: str | None = None, total_rows: int | None = None,
               units: DisplayUnits = AS_TYPED):
    """Terminal view: every quantity for one orbit, a summary row per orbit
    for many (a table with every column of :data:`ORBIT_VIEW_COLUMNS`);
    any other table column by column.  At most MAX_TERMINAL_ROWS
    rows are formatted, with a line saying how many there are
    (``total_rows`` when the caller hands over only the first rows of a
    longer result)."""
    total = row_total(table, total_rows)
    if not ORBIT_VIEW_COLUMNS <= set(table.names):
        return generic_table(table, title, total, units)
    if len(table) == 1 and total == 1:
        return one_orbit_table(table, units=units)
    return many_orbits_table(table, title, total, units)


def write_rich_table(table: Table, console: Console, title: str | None = None,
                     total_rows: int | None = None, units: DisplayUnits = AS_TYPED) -> int:
    """:func:`rich_table` printed on ``console``; returns the number of rows given."""
    console.print(rich_table(table, title, total_rows, units))
    return len(table)


#: How a vertical orbit's quantities show beside SI: column -> (kind, options typed as).
VERTICAL_UNITS = {"r_prime_m": ("length", ()), "v_cm_m_s": ("speed", ("v_top",)),
                  "v_top_min_m_s": ("speed", ("v_top",)), "v_bottom_m_s": ("speed", ("v_top",)),
                  "omega_rad_s": ("rate", ("phidot_top",)), "theta_deg": ("angle", ("theta",))}


def _vertical_spec(col: str, header: str, unit: str = "", **more) -> ColumnSpec:
    kind, params = VERTICAL_UNITS.get(col, (None, ()))
    return ColumnSpec(col, header, unit, kind=kind, params=params, **more)


#: The vertical-orbit view, a row per quantity (undefined ones left out):
#: column, label, unit, source (the globe's equations).
_VERTICAL_QUANTITIES = (
    ("r_prime_m", "r' radius of the centre's circle", "m", "eq. 8b"),
    ("v_cm_m_s", "speed at the top", "m/s", ""),
    ("v_top_min_m_s", "least top speed for contact", "m/s", "eq. 28a"),
    ("omega_rad_s", "rate at the top", "rad/s", ""),
    ("v_bottom_m_s", "speed at the bottom", "m/s", "eq. 27"),
    ("period_s", "lap time", "s", "eq. 27"),
    ("accel_g", "largest acceleration (bottom)", "g", ""),
    ("normal_top_per_mass_m_s2", "normal force / m at the top", "m/s²", "eq. 28"),
    ("normal_bottom_per_mass_m_s2", "normal force / m at the bottom", "m/s²", "eq. 28"),
    ("mu_top", "μ at top and bottom, |cot θ|", "", "eq. 28b"),
    ("phi_worst_deg", "worst point φ (μ peaks)", "deg", ""),
    ("mu_required", "μ required (at the worst point)", "", "eq. 28b"),
    ("phi_slip_deg", "first slip at φ (with --mu)", "deg", ""),
    ("phi_leave_deg", "leaves the surface at φ", "deg", "eq. 82"),
    ("growth_rate_1_s", "growth rate of a perturbation", "1/s", "floquet"),
)
#: Inside a closed profile (docs/surfaces.md eqs. S9-S12): the labels and
#: sources that differ (None: the globe's), and the loop's height.
_ON_PROFILE = {
    "r_prime_m": ("r' centre path's radius at the top", "1/κ_C"), "v_top_min_m_s": (None, "eq. S10"),
    "omega_rad_s": ("rate at the top, v κ_C", None), "v_bottom_m_s": (None, "eq. S9"), "period_s": (None, "eq. S12"),
    "accel_g": ("largest acceleration", None), "normal_top_per_mass_m_s2": (None, "eq. S10"),
    "normal_bottom_per_mass_m_s2": (None, "eq. S10"), "mu_top": ("μ at top and bottom", "eq. S11"),
    "mu_required": (None, "eq. S11"),
}


def _vertical_fields(quantities):
    return tuple(_vertical_spec(col, label, unit, source=source, when=lambda get, col=col: not is_undefined(get[col]))
                 for col, label, unit, source in quantities)


VERTICAL_FIELDS = _vertical_fields(_VERTICAL_QUANTITIES)
VERTICAL_FIELDS_ON_PROFILE = _vertical_fields(
    [(col, _ON_PROFILE.get(col, (None, None))[0] or label, unit, _ON_PROFILE.get(col, (None, None))[1] or source)
     for col, label, unit, source in _VERTICAL_QUANTITIES if col not in ("phi_leave_deg", "growth_rate_1_s")]
    + [("height_m", "height of the loop", "m", "")])

#: Left out first on a narrow console: where μ peaks and the lap time
#: describe an orbit that works; where it leaves the wall, the μ it needs
#: and the least top speed say whether it works at all.
VERTICAL_DROP_ORDER = ("phi_worst_deg", "period_s", "phi_leave_deg", "mu_required", "v_top_min_m_s")
#: The many-vertical-orbit view's columns.
VERTICAL_COLUMNS = tuple(
    _vertical_spec(col, header, unit, drop=VERTICAL_DROP_ORDER.index(col) if col in VERTICAL_DROP_ORDER else None,
                   **more)
    for col, header, unit, more in (
        ("input_row", "#", "", {}), ("theta_deg", "θ", "°", {}), ("v_cm_m_s", "v top", "m/s", {}),
        ("status", "status", "", {"format": status_text, "justify": "left"}), ("v_top_min_m_s", "v min", "m/s", {}),
        ("period_s", "lap", "s", {}), ("phi_worst_deg", "worst\nφ", "°", {}), ("mu_required", "μ\nrequired", "", {}),
        ("phi_leave_deg", "leaves\nφ", "°", {})))


def vertical_view(table: Table, total_rows: int | None = None, units: DisplayUnits = AS_TYPED):
    """One vertical orbit: a quantity per line; several: one line each
    (the first MAX_TERMINAL_ROWS of them)."""
    if len(table) == 1 and not (total_rows or 0) > 1:
        get = row_record(table)
        on_profile = "surface" in table.columns
        rows = quantity_rows(get, VERTICAL_FIELDS_ON_PROFILE if on_profile else VERTICAL_FIELDS, units)
        title = (f"vertical orbit, wheel {get['side']}, θ = {echo_number(get['theta_deg'])}°"
                 f"{' inside the profile (eqs. S9-S12)' if on_profile else ''}\n{_setup_line(get, units)}")
        return quantity_table(title, get, rows, "keeps contact all round with enough friction")
    title = "Vertical orbits inside the profile (eqs. S9-S12)" if "surface" in table.columns else \
        "Vertical orbits (eqs. 27-28b)"
    return build_table(table, VERTICAL_COLUMNS, units=units, title=title,
                       total_rows=total_rows, notes=status_legend(first_rows(table, MAX_TERMINAL_ROWS)))
