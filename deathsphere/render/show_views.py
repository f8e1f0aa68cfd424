"""Terminal views of ``deathsphere show``: what the crew and the safety
officer read off a screen before an act (docs/show.md).

The riders: each lane's status, its speed in km/h beside m/s, lean, load,
friction needed, head clearance and the speed margin.  The pairs: the
least clearance, when, the verdict (a conflict or a collision in red) and
the drift time.  A fall: where the rider leaves the wall and lands, and
whom he falls into (a hit in red).  Every view fits the console by
leaving out whole columns, never by cutting a number (:class:`FitTable`),
and is its column specs (:mod:`~deathsphere.render.view_builder`).  The
speeds show in km/h beside m/s, and a quantity the plan typed in a unit
of its own (``height = "6ft"``, ``min_clearance = "0.5ft"``, ``speed =
"30mph"``) in that unit beside SI, as an option typed with a unit is in
the other commands' views (or in the unit ``--units`` asks for; the
record of them is the command line's, from the plan's values as typed).
"""

from __future__ import annotations

import math

from rich.markup import escape

from deathsphere.render.display_units import AS_TYPED, KM_H, DisplayUnit, DisplayUnits
from deathsphere.render.terminal_table import (
    MAX_TERMINAL_ROWS,
    FitTable,
    first_rows,
    format_number,
    is_undefined,
    row_record,
    status_legend,
    status_text,
)
from deathsphere.render.view_builder import ColumnSpec, build_table
from deathsphere.table import Table

#: A pair's verdict in its colour: a conflict (closer than the plan's
#: min_clearance) and a collision (the envelopes overlap) in red.
VERDICT_STYLE = {"clear": "green", "conflict": "red", "collision": "bold red"}
#: A fall's outcome in its colour.
OUTCOME_STYLE = {"rides_on": "green", "swings": "yellow", "falls": "red"}


def _outcome(value) -> str:
    """A fall's outcome in its colour, in words (``rides on``, the CSV's ``rides_on``)."""
    text = str(value)
    style = OUTCOME_STYLE.get(text, "magenta")
    return f"[{style}]{escape(text.replace('_', ' '))}[/{style}]"


def _styled(value: str, styles: dict) -> str:
    style = styles.get(value, "magenta")
    return f"[{style}]{escape(value)}[/{style}]"


def _fixed(value, decimals: int) -> str:
    """A number with a fixed count of decimals (clearances in mm steps:
    0.153 m), — for undefined, ∞ for infinite."""
    if is_undefined(value):
        return "—"
    value = float(value)
    if math.isinf(value):
        return "∞" if value > 0 else "-∞"
    return f"{value:.{decimals}f}"


def speed_cell(m_s, unit: DisplayUnit | None = KM_H) -> str:
    """A speed in km/h (or ``unit``) with m/s beside it: ``32.0 (8.89)``;
    m/s alone when ``unit`` is None."""
    if isinstance(m_s, str):  # a horizontal rider's empty bottom speed
        return m_s
    if is_undefined(m_s):
        return "—"
    if unit is None:
        return f"{float(m_s):.2f}"
    return f"{unit.of(m_s):.1f} ({float(m_s):.2f})"


#: The plan's keys a rider's speed cell shows: a horizontal rider's
#: contact (or centre of mass's) speed, a looper's speed at the top.
SPEED_KEYS = ("speed", "com_speed", "v_top")
#: The plan's key a clearance is checked against: a least clearance is
#: shown in the unit the crew's rule was typed in.
RULE_KEYS = ("min_clearance",)


def _speed_unit(units: DisplayUnits) -> DisplayUnit | None:
    unit = units.unit("speed", SPEED_KEYS, KM_H)
    return None if unit is None or unit.name == "m/s" else unit


def _speed_words(unit: DisplayUnit | None) -> str:
    """How a speed cell reads, for a header or a sentence: ``km/h (m/s)``."""
    return "m/s" if unit is None else f"{unit.name} (m/s)"


def _speed_spec(key: str, words: str, units: DisplayUnits, **more) -> ColumnSpec:
    """A speed column: the crew's unit with m/s in brackets (one cell, so
    that a narrow console keeps both)."""
    unit = _speed_unit(units)
    header = f"{words} {unit.name}\n(m/s)" if unit is not None else f"{words}\nm/s"
    return ColumnSpec(key, header, format=lambda v: speed_cell(v, unit), **more)


def _column(table: Table, name: str):
    return table.columns[name].tolist() if name in table else [None] * len(table)


def _margin(lo, hi) -> str:
    """The speed band as percentages of the planned speed: ``−12/+8``."""
    if is_undefined(lo) and is_undefined(hi):
        return "—"
    low = "—" if is_undefined(lo) else f"{-abs(float(lo)):.0f}"
    high = "∞" if is_undefined(hi) or math.isinf(float(hi)) else f"+{abs(float(hi)):.0f}"
    return f"{low}/{high}"


def _lane_speed(get: dict):
    """A horizontal rider's speedometer (his contact's speed), a looper's
    centre of mass's at the top."""
    return get.get("v_top_m_s") if get.get("lane") == "vertical" else get.get("v_contact_m_s")


def _clearance_spec(key: str, header: str, decimals: int, **more) -> ColumnSpec:
    """A clearance in mm steps (0.153 m), in ft too where lengths are asked for in ft."""
    return ColumnSpec(key, header, "m", format=lambda v: _fixed(v, decimals), kind="length", **more)


def _heights(result) -> dict:
    """Each rider's contact height above the floor [m] as planned, by name
    (a horizontal lane's: the plan's, or from its theta on the globe)."""
    plan = getattr(result, "plan", None)
    return {rider.name: rider.contact_height for rider in getattr(plan, "riders", ())}


def _height_spec(result) -> ColumnSpec:
    """The lane's height above the floor, in the unit the plan typed the
    heights in beside m (the two go together on a narrow console, after
    the friction needed: at 80 columns the riders' own figures fill the
    line); — for a looper (his height changes round the loop)."""
    heights = _heights(result)
    return ColumnSpec("height", "height", "m", digits=4, kind="length", params=("height",), drop=7,
                      when=lambda head: bool(heights),
                      value=lambda get: heights.get(get.get("name"), math.nan))


def _digits(key: str, header: str, unit: str = "", digits: int = 3, **more) -> ColumnSpec:
    return ColumnSpec(key, header, unit, digits=digits, value=lambda get: get.get(key), **more)


def riders_view(table: Table, total_rows: int | None = None, result=None,
                units: DisplayUnits = AS_TYPED) -> FitTable:
    """One line per rider: the lane, its status, the planned speed (km/h and
    m/s), lean, load, friction needed, head clearance and the margin of
    speed in which the lane stays feasible; a looper's top and bottom."""
    head = first_rows(table, MAX_TERMINAL_ROWS)
    vertical = [lane == "vertical" for lane in _column(head, "lane")]
    unit = _speed_unit(units)
    specs = [
        ColumnSpec("name", "rider", justify="left", value=lambda get: str(get.get("name"))),
        ColumnSpec("lane", "lane", justify="left", value=lambda get: "vert." if get.get("lane") == "vertical"
                   else "horiz."),
        ColumnSpec("status", "status", justify="left", format=lambda v: status_text(str(v)),
                   value=lambda get: get.get("status")),
        _height_spec(result),
        _speed_spec("speed", "speed", units, value=_lane_speed),
        ColumnSpec("margin", "margin\n%", format=lambda ends: _margin(*ends),
                   value=lambda get: (get.get("margin_low_pct"), get.get("margin_high_pct"))),
        _digits("lean_deg", "lean°"),
        _digits("load_g", "load", "g"),
        _clearance_spec("head_clearance_m", "head\nclear", 2, value=lambda get: get.get("head_clearance_m")),
        _digits("mu_required", "μ\nneeded", digits=2, drop=6),
        # to a tenth of a degree, as the pairs' θ/φ (three digits read 115.2 as 115 but 82.8 as 82.8)
        ColumnSpec("theta_deg", "θ°", format=_angle, drop=4, value=lambda get: get.get("theta_deg")),
        _digits("alpha_deg", "α°", drop=3),
        _digits("period_s", "lap", "s", drop=2),
        _speed_spec("v_bottom", "bottom", units, drop=5, when=lambda head: any(vertical),
                    value=lambda get: get.get("v_bottom_m_s") if get.get("lane") == "vertical" else ""),
        _digits("v_cm_m_s", "CoM", "m/s", drop=1),
    ]
    notes = ["[dim]speed: a horizontal rider's contact (his speedometer), a looper's centre of mass at the top "
             "(CoM: a horizontal rider's centre of mass); margin: the band of "
             "speeds, in % of the planned one, in which the lane stays feasible[/dim]"]
    looper = [row_record(head, i) for i in range(len(head)) if vertical[i]]
    for get in looper:
        least = get.get("v_top_min_m_s")
        if not is_undefined(least):
            notes.append(f"[dim]{escape(str(get['name']))}: least top speed {speed_cell(least, unit)} "
                         f"{_speed_words(unit)}; bottom load {format_number(get.get('load_bottom_g'), 3)} g[/dim]")
    notes += [line for line in status_legend(head) if not line.startswith(status_text("ok"))]
    notes += _infeasible_verdict(result)
    return build_table(table, specs, units=units, title=_title("Riders", result), total_rows=total_rows,
                       notes=notes)


def _infeasible_verdict(result) -> list[str]:
    """The verdict line of a plan with a lane that is not ok (none else)."""
    bad = getattr(result, "infeasible", None) or {}
    if not bad:
        return []
    who = ", ".join(f"{name} ({status})" for name, status in bad.items())
    return [f"[bold red]not feasible as planned: {escape(who)}[/bold red]"]


def _title(what: str, result) -> str:
    if result is None:
        return what
    duration = getattr(result, "duration_s", None)
    if duration is None or is_undefined(duration):
        return what
    kind = "the common period" if getattr(result, "commensurate", False) else "the planned duration"
    return f"{what} over the act: {format_number(float(duration), 4)} s ({kind})"


def _drift(value) -> str:
    """How long a pair stays clear with a rider 1 % off: never closer is ∞."""
    if is_undefined(value) or (isinstance(value, float) and math.isinf(value)) or value == "":
        return "never"
    return format_number(float(value), 3)


def _angle(value, wrap: bool = False) -> str:
    """An angle to a tenth of a degree (an azimuth of 359.96° reads 0.0)."""
    if is_undefined(value):
        return "—"
    value = round(float(value), 1)
    return f"{value % 360.0 if wrap else value:.1f}"


def _where(theta, phi) -> str:
    return f"{_angle(theta)}/{_angle(phi, wrap=True)}"


def _pair_clearance(pair) -> str:
    """A least clearance (and its pair's verdict), in the verdict's colour where it is not clear."""
    clearance, verdict = pair
    text = _fixed(clearance, 3)
    return text if verdict == "clear" else f"[{VERDICT_STYLE.get(verdict, 'red')}]{text}[/]"


#: The pairs on screen; where each rider was goes first on a narrow console.
PAIRS_VIEW = (
    ColumnSpec("pair", "pair", justify="left", format=str,
               value=lambda get: f"{escape(str(get.get('rider_a')))} – {escape(str(get.get('rider_b')))}"),
    ColumnSpec("verdict", "verdict", justify="left", format=lambda v: _styled(str(v), VERDICT_STYLE),
               value=lambda get: get.get("verdict")),
    ColumnSpec("min_clearance_m", "least\nclear", "m", format=_pair_clearance, kind="length", params=RULE_KEYS,
               value=lambda get: (get.get("min_clearance_m"), str(get.get("verdict")))),
    ColumnSpec("t_s", "at t", "s", value=lambda get: get.get("t_s")),
    ColumnSpec("drift_time_s", "drift\ntime s", format=str,
               value=lambda get: _drift(get.get("drift_time_s")) if str(get.get("verdict")) == "clear" else "—"),
    ColumnSpec("where_a", "A θ°/φ°", format=str, drop=2,
               value=lambda get: _where(get.get("theta_a_deg"), get.get("phi_a_deg"))),
    ColumnSpec("where_b", "B θ°/φ°", format=str, drop=1,
               value=lambda get: _where(get.get("theta_b_deg"), get.get("phi_b_deg"))),
)


def pairs_view(table: Table, total_rows: int | None = None, result=None,
               units: DisplayUnits = AS_TYPED) -> FitTable:
    """One line per pair: the least clearance over the act, when, where
    each rider's contact was, the verdict (conflict and collision in red)
    and the drift time."""
    head = first_rows(table, MAX_TERMINAL_ROWS)
    notes = [f"[dim]{_rule(result, units)}least clear: the envelopes' distance (negative: minus the overlap's depth); drift time: "
             "how long the pair stays clear with one rider 1 % fast or slow (the worse)[/dim]"]
    notes += _pair_notes(head, result)
    return build_table(table, PAIRS_VIEW, units=units, title=_title("Pairs", result), total_rows=total_rows,
                       notes=notes)


def _rule(result, units: DisplayUnits = AS_TYPED) -> str:
    """The plan's rule, in the unit it was typed in beside m: ``conflict:
    closer than 0.152 m (0.5 ft); ``."""
    plan = getattr(result, "plan", None)
    globe = getattr(plan, "globe", None)
    value = getattr(globe, "min_clearance", None) if globe is not None else None
    if value is None:
        return ""
    return f"conflict: closer than {_length_text(float(value), units.unit('length', RULE_KEYS), 3)}; "


def _length_text(value: float, unit: DisplayUnit | None, digits: int) -> str:
    """A length in m, and in ``unit`` in brackets where it is another: ``0.152 m (0.5 ft)``."""
    text = f"{format_number(value, digits)} m"
    if unit is None or unit.name == "m" or is_undefined(value):
        return text
    return f"{text} ({format_number(unit.of(value), digits)} {unit.name})"


def _pair_notes(head: Table, result) -> list[str]:
    """Which pairs' least clearance is geometric (horizontal lanes of
    different periods meet at every relative phase) and the vertical
    riders' safe windows of phase."""
    notes = []
    geometric = [f"{a} – {b}" for a, b, basis in zip(_column(head, "rider_a"), _column(head, "rider_b"),
                                                       _column(head, "basis")) if basis == "geometric"]
    if geometric:
        notes.append(f"[dim]{escape(', '.join(geometric))}: horizontal lanes of different periods pass at every "
                     "relative phase; their least clearance is the geometric one (both riders in one meridian "
                     "plane), whatever the phases[/dim]")
    bad = getattr(result, "infeasible", None) or {}
    marked = [f"{a} – {b}" for a, b in zip(_column(head, "rider_a"), _column(head, "rider_b"))
              if a in bad or b in bad]
    if marked:
        notes.append(f"[bold red]{escape(', '.join(marked))}: a lane that is not feasible "
                     f"({escape(', '.join(bad))}); its clearances are of the lane as planned[/bold red]")
    windows = getattr(result, "phase_windows", None) or {}
    in_the_way = getattr(result, "in_the_way", None) or {}
    for name, window in dict(windows).items():
        blocking = in_the_way.get(name) or []
        way = f" (in the way at the best phase: {', '.join(map(str, blocking))})" if not window and blocking else ""
        notes.append(f"[dim]{escape(str(name))}: safe phases {escape(_window_text(window) + way)}[/dim]")
    return notes


def _window_text(window) -> str:
    """A window of safe phases as text: intervals in degrees, or as given."""
    try:
        spans = [(float(lo), float(hi)) for lo, hi in window]
    except (TypeError, ValueError):
        return str(window)
    if not spans:
        return "none: every phase brings a pair closer than the rule"
    return ", ".join(f"{lo:.0f}°–{hi:.0f}°" for lo, hi in spans)


def _fall_line(get: dict, unit: DisplayUnit | None = KM_H, height: DisplayUnit | None = None) -> str:
    """One fall in words (plain text: it is the view's title): who, when,
    the outcome, where he leaves the wall and lands, how long and how hard."""
    who = (f"{get['rider']} at t = {format_number(get['t_fail_s'], 4)} s drops to "
           f"{100 * float(get['speed_fraction']):.0f} % of the speed: {str(get['outcome']).replace('_', ' ')}")
    if get["outcome"] == "swings" and not is_undefined(get.get("swing_height_m")):
        return f"{who} on the wall, up to {_height_text(float(get['swing_height_m']), height)} above the floor"
    if get["outcome"] != "falls":
        return who
    return (f"{who}; leaves the wall at t = {format_number(get['t_contact_lost_s'], 4)} s "
            f"({_place(get, 'lost', height)}), lands at t = {format_number(get['t_land_s'], 4)} s "
            f"({_place(get, 'land', height)}) "
            f"after {format_number(get['fall_time_s'], 3)} s at {speed_cell(get['impact_speed_m_s'], unit)} "
            f"{_speed_words(unit)}")


def _height_text(metres: float, unit: DisplayUnit | None) -> str:
    """A height to the cm, in ``unit`` too where it is another: ``0.91 m (3.00 ft)``."""
    beside = "" if unit is None or unit.name == "m" else f" ({unit.of(metres):.2f} {unit.name})"
    return f"{metres:.2f} m{beside}"


def _place(get: dict, end: str, height: DisplayUnit | None = None) -> str:
    """Where a fall leaves the wall or lands: θ and φ in the globe; on a
    drum or a cone, where θ is not defined, the height above the floor (in
    the unit the plan typed the heights in beside m) and φ."""
    phi = f"φ {_angle(get[f'phi_{end}_deg'], wrap=True)}°"
    if is_undefined(get[f"theta_{end}_deg"]) and not is_undefined(get.get(f"height_{end}_m")):
        return f"{_height_text(float(get[f'height_{end}_m']), height)} up, {phi}"
    return f"θ {_angle(get[f'theta_{end}_deg'])}°, {phi}"


def _hit_cell(value, clearance=None, crosses=None, rule: float = 0.0) -> str:
    """HIT in red, conflict (closer than the plan's ``rule`` [m]) in
    yellow, clear in green; a swing that crosses the rider's lane in
    yellow; — when there was no flight to check."""
    if clearance is not None and is_undefined(clearance):
        return "[yellow]crosses his lane[/yellow]" if _true(crosses) else "—"
    if _true(value):
        return "[bold red]HIT[/bold red]"
    if clearance is not None and float(clearance) < rule:
        return "[yellow]conflict[/yellow]"
    return "[green]clear[/green]"


def _min_clearance(result) -> float:
    """The plan's min_clearance [m] (0 without a plan: only a hit is not clear)."""
    globe = getattr(getattr(result, "plan", None), "globe", None)
    return float(getattr(globe, "min_clearance", 0.0) or 0.0)


def _true(value) -> bool:
    return value is not None and not is_undefined(value) and bool(value) and str(value).lower() not in ("false", "0")


#: More falls than this are a list (a Monte Carlo's), one line each.
FALLS_AS_BLOCKS = 4


def _text(key: str, header: str, blank: str = "", **more) -> ColumnSpec:
    return ColumnSpec(key, header, justify="left", value=lambda get: str(get.get(key) or blank), **more)


def _clearance(decimals: int, header: str) -> ColumnSpec:
    return ColumnSpec("min_clearance_m", header, "m", format=lambda v: _fixed(v, decimals), kind="length",
                      params=RULE_KEYS,
                      value=lambda get: get.get("min_clearance_m"))


def _fall_view(rule: float) -> tuple:
    """A few falls: per other rider the least clearance (a hit in red, a
    conflict under the plan's ``rule`` [m] in yellow)."""
    return (
        _text("rider", "rider"),
        _text("victim", "other rider", "(alone)"),
        ColumnSpec("hit", "", justify="left", format=str,
                   value=lambda get: _hit_cell(get.get("hit"), get.get("min_clearance_m"), get.get("crosses_lane"),
                                               rule)),
        _clearance(3, "least\nclear"),
        ColumnSpec("t_min_s", "at t", "s", value=lambda get: get.get("t_min_s")),
    )


def falls_view(table: Table, total_rows: int | None = None, result=None,
               units: DisplayUnits = AS_TYPED) -> FitTable:
    """Each fall in words, then per other rider the least clearance
    between the falling rider and him (a hit in red); a Monte Carlo's many
    falls a line per row instead."""
    head = first_rows(table, MAX_TERMINAL_ROWS)
    firsts: dict = {}
    for i, key in enumerate(zip(_column(head, "rider"), _column(head, "t_fail_s"), _column(head, "speed_fraction"))):
        firsts.setdefault(key, i)
    if len(firsts) > FALLS_AS_BLOCKS:
        return _falls_list(table, total_rows, units, _min_clearance(result))
    unit = _speed_unit(units)
    height = units.unit("length", ("height",))
    lines = [_fall_line(row_record(head, i), unit, height) for i in firsts.values()]
    notes = ["[dim]least clear: between the falling rider (a ball of half his width about his centre of "
             "mass) and the other's envelope, during the fall; below zero he falls into him[/dim]"]
    return build_table(table, _fall_view(_min_clearance(result)), units=units, title="\n".join(lines), total_rows=total_rows, notes=notes)


def _falls_list(table: Table, total_rows, units: DisplayUnits, rule: float = 0.0) -> FitTable:
    specs = (
        _text("rider", "rider"),
        ColumnSpec("t_fail_s", "fails\nat t s", drop=2, value=lambda get: get.get("t_fail_s")),
        ColumnSpec("speed_fraction", "speed\nleft", digits=2, value=lambda get: get.get("speed_fraction")),
        ColumnSpec("outcome", "outcome", justify="left", format=_outcome, value=lambda get: get.get("outcome")),
        _text("victim", "other"),
        ColumnSpec("hit", "", justify="left", format=str,
                   value=lambda get: _hit_cell(get.get("hit"), get.get("min_clearance_m"), rule=rule)),
        _clearance(3, "least\nclear"),
        _speed_spec("impact_speed_m_s", "impact", units, value=lambda get: get.get("impact_speed_m_s")),
        ColumnSpec("fall_time_s", "fall", "s", digits=3, drop=1, value=lambda get: get.get("fall_time_s")),
    )
    return build_table(table, specs, units=units, title="Falls", total_rows=total_rows)


#: The Monte Carlo summary's columns on screen: (column, header).
SUMMARY_HEADERS = {"rider": "falling\nrider", "victim": "other\nrider", "falls": "falls", "hits": "hits",
                   "hit_fraction": "hit\n%", "impact_speed_max_m_s": "worst impact\nkm/h (m/s)"}


def _summary_cells(name: str, values: list, blank: str, unit: DisplayUnit | None = KM_H) -> list[str]:
    if name in ("rider", "victim"):
        return [escape(str(v)) if v else blank for v in values]
    if name == "hit_fraction":
        return [_fixed(100 * float(v), 1) if not is_undefined(v) else "—" for v in values]
    if name == "impact_speed_max_m_s":
        return [speed_cell(v, unit) for v in values]
    return [escape(str(v)) if isinstance(v, str) else format_number(v, 4) for v in values]


def falls_summary_view(table: Table, total_rows: int | None = None, result=None,
                       units: DisplayUnits = AS_TYPED) -> FitTable:
    """The Monte Carlo's summary: per falling rider (and over all of
    them), how many falls, how many hit another rider (per other rider,
    and anyone), and the worst landing speed."""
    unit = _speed_unit(units)
    headers = {**SUMMARY_HEADERS, "impact_speed_max_m_s": f"worst impact\n{_speed_words(unit)}"}
    specs = [ColumnSpec(name, headers.get(name, name), drop=None if k < 2 else -k,
                        justify="left" if name in ("rider", "victim") else "right",
                        format=lambda v, name=name: _summary_cells(name, [v], _blank(name), unit)[0],
                        value=lambda get, name=name: get.get(name))
             for k, name in enumerate(table.names)]
    notes = ["[dim]random riders at random times of the act, each dropping to a random fraction of his speed "
             "in [0, 1); a hit: the falling rider's ball meets another's envelope in flight[/dim]"]
    return build_table(table, specs, units=units, title="The odds: random falls in the act", total_rows=total_rows,
                       notes=notes)


def _blank(name: str) -> str:
    return "(any)" if name == "rider" else "(anyone)"
