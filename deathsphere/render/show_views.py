"""Terminal views of ``deathsphere show``: what the crew and the safety
officer read off a screen before an act (docs/show.md).

The riders: each lane's status, its speed in km/h beside m/s, lean, load,
friction needed, head clearance and the speed margin.  The pairs: the
least clearance, when, the verdict (a conflict or a collision in red) and
the drift time.  A fall: where the rider leaves the wall and lands, and
whom he falls into (a hit in red).  Every view fits the console by
leaving out whole columns, never by cutting a number (:class:`FitTable`).
"""

from __future__ import annotations

import math

from rich.markup import escape

from deathsphere.render.terminal_table import (
    MAX_TERMINAL_ROWS,
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

#: km/h per m/s (exact by definition).
KM_H = 3.6

#: A pair's verdict in its colour: a conflict (closer than the plan's
#: min_clearance) and a collision (the envelopes overlap) in red.
VERDICT_STYLE = {"clear": "green", "conflict": "red", "collision": "bold red"}
#: A fall's outcome in its colour.
OUTCOME_STYLE = {"rides_on": "green", "swings": "yellow", "falls": "red"}


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


def speed_cell(m_s) -> str:
    """A speed in km/h with m/s beside it: ``32.0 (8.89)``."""
    if is_undefined(m_s):
        return "—"
    return f"{float(m_s) * KM_H:.1f} ({float(m_s):.2f})"


def _column(table: Table, name: str):
    return table.columns[name].tolist() if name in table else [None] * len(table)


def _margin(lo, hi) -> str:
    """The speed band as percentages of the planned speed: ``−12/+8``."""
    if is_undefined(lo) and is_undefined(hi):
        return "—"
    low = "—" if is_undefined(lo) else f"{-abs(float(lo)):.0f}"
    high = "∞" if is_undefined(hi) or math.isinf(float(hi)) else f"+{abs(float(hi)):.0f}"
    return f"{low}/{high}"


#: Left out first on a narrow console (whole columns, least needed first).
RIDERS_DROP_ORDER = ("v_contact", "period_s", "alpha_deg", "theta_deg", "v_bottom", "mu_required")


def riders_view(table: Table, total_rows: int | None = None, result=None) -> FitTable:
    """One line per rider: the lane, its status, the planned speed (km/h and
    m/s), lean, load, friction needed, head clearance and the margin of
    speed in which the lane stays feasible; a looper's top and bottom."""
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    vertical = [lane == "vertical" for lane in _column(head, "lane")]
    v_top = _column(head, "v_top_m_s")
    speed = [v_top[i] if vertical[i] else v for i, v in enumerate(_column(head, "v_cm_m_s"))]
    columns = [
        Column("name", "rider", [escape(str(v)) for v in _column(head, "name")], "left"),
        Column("lane", "lane", [("vert." if v else "horiz.") for v in vertical], "left"),
        Column("status", "status", [status_text(str(v)) for v in _column(head, "status")], "left"),
        Column("speed", "speed km/h\n(m/s)", [speed_cell(v) for v in speed]),
        Column("margin", "margin\n%", [_margin(lo, hi) for lo, hi in zip(_column(head, "margin_low_pct"),
                                                                         _column(head, "margin_high_pct"))]),
        Column("lean_deg", "lean°", [format_number(v, 3) for v in _column(head, "lean_deg")]),
        Column("load_g", "load\ng", [format_number(v, 3) for v in _column(head, "load_g")]),
        Column("head_clearance_m", "head\nclear\nm", [_fixed(v, 2) for v in _column(head, "head_clearance_m")]),
        Column("mu_required", "μ\nneeded", [format_number(v, 2) for v in _column(head, "mu_required")]),
        Column("theta_deg", "θ°", [format_number(v, 3) for v in _column(head, "theta_deg")]),
        Column("alpha_deg", "α°", [format_number(v, 3) for v in _column(head, "alpha_deg")]),
        Column("period_s", "lap\ns", [format_number(v, 3) for v in _column(head, "period_s")]),
    ]
    if any(vertical):
        bottom = _column(head, "v_bottom_m_s")
        columns.append(Column("v_bottom", "bottom km/h\n(m/s)",
                              [speed_cell(b) if vert else "" for b, vert in zip(bottom, vertical)]))
    columns.append(Column("v_contact", "contact\nm/s", [format_number(v, 3) for v in _column(head, "v_contact_m_s")]))
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    notes = ["[dim]speed: a horizontal rider's centre of mass, a looper's at the top; margin: the band of "
             "speeds, in % of the planned one, in which the lane stays feasible[/dim]"]
    looper = [row_record(head, i) for i in range(len(head)) if vertical[i]]
    for get in looper:
        least = get.get("v_top_min_m_s")
        if not is_undefined(least):
            notes.append(f"[dim]{escape(str(get['name']))}: least top speed {speed_cell(least)} km/h (m/s); "
                         f"bottom load {format_number(get.get('load_bottom_g'), 3)} g[/dim]")
    notes += [line for line in status_legend(head) if not line.startswith(status_text("ok"))]
    return FitTable(columns, RIDERS_DROP_ORDER, title=_title("Riders", result), footer=footer, notes=notes)


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


#: Left out first on a narrow console.
PAIRS_DROP_ORDER = ("where_b", "where_a")


def pairs_view(table: Table, total_rows: int | None = None, result=None) -> FitTable:
    """One line per pair: the least clearance over the act, when, where
    each rider's contact was, the verdict (conflict and collision in red)
    and the drift time."""
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    verdicts = [str(v) for v in _column(head, "verdict")]
    clearance = [_fixed(v, 3) for v in _column(head, "min_clearance_m")]
    clearance = [c if v == "clear" else f"[{VERDICT_STYLE.get(v, 'red')}]{c}[/]" for c, v in zip(clearance, verdicts)]
    columns = [
        Column("pair", "pair", [f"{escape(str(a))} – {escape(str(b))}"
                                for a, b in zip(_column(head, "rider_a"), _column(head, "rider_b"))], "left"),
        Column("verdict", "verdict", [_styled(v, VERDICT_STYLE) for v in verdicts], "left"),
        Column("min_clearance_m", "least\nclear\nm", clearance),
        Column("t_s", "at t\ns", [format_number(v, 4) for v in _column(head, "t_s")]),
        Column("drift_time_s", "drift\ntime s", [_drift(v) if verdict == "clear" else "—"
                                                 for v, verdict in zip(_column(head, "drift_time_s"), verdicts)]),
        Column("where_a", "A θ°/φ°", [_where(t, p) for t, p in zip(_column(head, "theta_a_deg"),
                                                                   _column(head, "phi_a_deg"))]),
        Column("where_b", "B θ°/φ°", [_where(t, p) for t, p in zip(_column(head, "theta_b_deg"),
                                                                   _column(head, "phi_b_deg"))]),
    ]
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    notes = [f"[dim]{_rule(result)}least clear: the envelopes' distance (negative: they overlap); drift time: "
             "how long the pair stays clear with one rider 1 % fast or slow (the worse)[/dim]"]
    notes += _pair_notes(head, result)
    return FitTable(columns, PAIRS_DROP_ORDER, title=_title("Pairs", result), footer=footer, notes=notes)


def _rule(result) -> str:
    plan = getattr(result, "plan", None)
    globe = getattr(plan, "globe", None)
    value = getattr(globe, "min_clearance", None) if globe is not None else None
    if value is None:
        return ""
    return f"conflict: closer than {format_number(float(value), 3)} m; "


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
    windows = getattr(result, "phase_windows", None) or {}
    for name, window in dict(windows).items():
        notes.append(f"[dim]{escape(str(name))}: safe phases {escape(_window_text(window))}[/dim]")
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


def _fall_line(get: dict) -> str:
    """One fall in words (plain text: it is the view's title): who, when,
    the outcome, where he leaves the wall and lands, how long and how hard."""
    who = (f"{get['rider']} at t = {format_number(get['t_fail_s'], 4)} s drops to "
           f"{100 * float(get['speed_fraction']):.0f} % of the speed: {str(get['outcome']).replace('_', ' ')}")
    if get["outcome"] == "swings" and not is_undefined(get.get("swing_height_m")):
        return f"{who} on the wall, up to {get['swing_height_m']:.2f} m above the floor"
    if get["outcome"] != "falls":
        return who
    return (f"{who}; leaves the wall at t = {format_number(get['t_contact_lost_s'], 4)} s "
            f"(θ {_angle(get['theta_lost_deg'])}°, φ {_angle(get['phi_lost_deg'], wrap=True)}°), "
            f"lands at t = {format_number(get['t_land_s'], 4)} s (θ {_angle(get['theta_land_deg'])}°, "
            f"φ {_angle(get['phi_land_deg'], wrap=True)}°) after {format_number(get['fall_time_s'], 3)} s at "
            f"{speed_cell(get['impact_speed_m_s'])} km/h (m/s)")


def _hit_cell(value, clearance=None, crosses=None) -> str:
    """HIT in red, clear in green; a swing that crosses the rider's lane
    in yellow; — when there was no flight to check."""
    if clearance is not None and is_undefined(clearance):
        return "[yellow]crosses his lane[/yellow]" if _true(crosses) else "—"
    return "[bold red]HIT[/bold red]" if _true(value) else "[green]clear[/green]"


def _true(value) -> bool:
    return value is not None and not is_undefined(value) and bool(value) and str(value).lower() not in ("false", "0")


#: More falls than this are a list (a Monte Carlo's), one line each.
FALLS_AS_BLOCKS = 4


def falls_view(table: Table, total_rows: int | None = None, result=None) -> FitTable:
    """Each fall in words, then per other rider the least clearance
    between the falling rider and him (a hit in red); a Monte Carlo's many
    falls a line per row instead."""
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    firsts: dict = {}
    for i, key in enumerate(zip(_column(head, "rider"), _column(head, "t_fail_s"), _column(head, "speed_fraction"))):
        firsts.setdefault(key, i)
    if len(firsts) > FALLS_AS_BLOCKS:
        return _falls_list(head, total)
    lines = [_fall_line(row_record(head, i)) for i in firsts.values()]
    columns = [
        Column("rider", "rider", [escape(str(v)) for v in _column(head, "rider")], "left"),
        Column("victim", "other rider", [escape(str(v)) if v else "(alone)" for v in _column(head, "victim")],
               "left"),
        Column("hit", "", [_hit_cell(v, c, x) for v, c, x in zip(_column(head, "hit"), _column(head, "min_clearance_m"),
                                                              _column(head, "crosses_lane"))], "left"),
        Column("min_clearance_m", "least\nclear\nm", [_fixed(v, 3) for v in _column(head, "min_clearance_m")]),
        Column("t_min_s", "at t\ns", [format_number(v, 4) for v in _column(head, "t_min_s")]),
    ]
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    notes = ["[dim]least clear: between the falling rider (a ball of half his width about his centre of "
             "mass) and the other's envelope, during the fall; below zero he falls into him[/dim]"]
    return FitTable(columns, (), title="\n".join(lines), footer=footer, notes=notes)


def _falls_list(head: Table, total: int) -> FitTable:
    columns = [
        Column("rider", "rider", [escape(str(v)) for v in _column(head, "rider")], "left"),
        Column("t_fail_s", "fails\nat t s", [format_number(v, 4) for v in _column(head, "t_fail_s")]),
        Column("speed_fraction", "speed\nleft", [format_number(v, 2) for v in _column(head, "speed_fraction")]),
        Column("outcome", "outcome", [_styled(str(v), OUTCOME_STYLE) for v in _column(head, "outcome")], "left"),
        Column("victim", "other", [escape(str(v)) for v in _column(head, "victim")], "left"),
        Column("hit", "", [_hit_cell(v, c) for v, c in zip(_column(head, "hit"), _column(head, "min_clearance_m"))],
               "left"),
        Column("min_clearance_m", "least\nclear m", [_fixed(v, 3) for v in _column(head, "min_clearance_m")]),
        Column("impact_speed_m_s", "impact km/h\n(m/s)", [speed_cell(v) for v in _column(head, "impact_speed_m_s")]),
        Column("fall_time_s", "fall\ns", [format_number(v, 3) for v in _column(head, "fall_time_s")]),
    ]
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    return FitTable(columns, ("fall_time_s", "t_fail_s"), title="Falls", footer=footer)


#: The Monte Carlo summary's columns on screen: (column, header).
SUMMARY_HEADERS = {"rider": "falling\nrider", "victim": "other\nrider", "falls": "falls", "hits": "hits",
                   "hit_fraction": "hit\n%", "impact_speed_max_m_s": "worst impact\nkm/h (m/s)"}


def _summary_cells(name: str, values: list, blank: str) -> list[str]:
    if name in ("rider", "victim"):
        return [escape(str(v)) if v else blank for v in values]
    if name == "hit_fraction":
        return [_fixed(100 * float(v), 1) if not is_undefined(v) else "—" for v in values]
    if name == "impact_speed_max_m_s":
        return [speed_cell(v) for v in values]
    return [escape(str(v)) if isinstance(v, str) else format_number(v, 4) for v in values]


def falls_summary_view(table: Table, total_rows: int | None = None, result=None) -> FitTable:
    """The Monte Carlo's summary: per falling rider (and over all of
    them), how many falls, how many hit another rider (per other rider,
    and anyone), and the worst landing speed."""
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    columns = []
    for name in head.names:
        values = _column(head, name)
        blank = "(any)" if name == "rider" else "(anyone)"
        columns.append(Column(name, SUMMARY_HEADERS.get(name, name), _summary_cells(name, values, blank),
                              "left" if name in ("rider", "victim") else "right"))
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    notes = ["[dim]random riders at random times of the act, each dropping to a random fraction of his speed "
             "in [0, 1); a hit: the falling rider's ball meets another's envelope in flight[/dim]"]
    drop = tuple(reversed([c.key for c in columns[2:]]))
    return FitTable(columns, drop, title="The odds: random falls in the act", footer=footer, notes=notes)
