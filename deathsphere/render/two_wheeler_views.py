"""Terminal views of ``deathsphere ride`` for a two-wheeler: straight running
on flat ground (eigenvalues against speed), its summary (weave and capsize
speeds), the steady turns on the globe and their rider's table.  Eigenvalues show as complex
numbers, one cell each; the columns that do not fit a narrow console are
left out from the right and named under the table."""

from __future__ import annotations

from rich.markup import escape

from deathsphere.render.ride_views import _WhyWraps, _limit, _span
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

#: Columns of the turns on the globe, in order: the row's identity and the
#: rider's numbers, then the rest (left out first, from the right).
TURN_VIEW = (("input_row", "#"), ("height_m", "height\nm"), ("status", "status"), ("v_rear_m_s", "v rear\nm/s"),
             ("lean_surface_deg", "lean°\nwall"), ("steer_deg", "steer°"), ("steer_torque_n_m", "T_δ\nN m"),
             ("stability", "stability"), ("growth_rate_1_s", "growth\n1/s"), ("load_g", "load\ng"),
             ("mu_required_rear", "μ\nrear"), ("mu_required_front", "μ\nfront"),
             ("head_clearance_m", "head\nclear\nm"), ("theta_deg", "θ°"))
TURN_DROP = ("theta_deg", "head_clearance_m", "mu_required_front", "mu_required_rear", "load_g")


def _cells(col: str, values: list) -> list[str]:
    styled = {"status": status_text, "stability": lambda v: STABILITY_STYLE.get(v, escape(str(v))), "input_row": str}
    return [styled.get(col, format_number)(v) for v in values]


def _eigenvalue(re, im) -> str:
    if re != re:  # NaN: no eigenvalue
        return "—"
    if im == 0:
        return format_number(re, 3)
    return f"{format_number(re, 3)}{'+' if im > 0 else '-'}{format_number(abs(im), 3)}i"


def _eigen_columns(head: Table) -> list[Column]:
    k = sum(1 for c in head.columns if c.endswith("_re") and c.startswith("eig_"))
    return [Column(f"eig_{i}", f"λ{i}\n1/s", [_eigenvalue(re, im) for re, im in
                                             zip(head.columns[f"eig_{i}_re"].tolist(),
                                                 head.columns[f"eig_{i}_im"].tolist())])
            for i in range(1, k + 1)]


def straight_view(table: Table, total_rows: int | None = None, title: str | None = None) -> FitTable:
    """Upright straight running: speed, verdict, growth rate, every eigenvalue."""
    if "weave_speed_m_s" in table:
        columns = [Column(c, h, [escape(str(v)) if c == "machine" else format_number(v, 15)
                                 for v in table.columns[c].tolist()], "left" if c == "machine" else "right")
                   for c, h in (("machine", "machine"), ("weave_speed_m_s", "weave speed\nm/s"),
                                ("capsize_speed_m_s", "capsize speed\nm/s"), ("speeds_tried", "speeds\ntried"),
                                ("speeds_stable", "speeds\nstable"))]
        return FitTable(columns, ("speeds_stable", "speeds_tried"), title=title)
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    columns = [Column(c, h, _cells(c, head.columns[c].tolist())) for c, h in
               (("speed_m_s", "speed\nm/s"), ("stability", "stability"), ("growth_rate_1_s", "growth\n1/s"))]
    eig = _eigen_columns(head)
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    first = row_record(head)
    note = f"[dim]{escape(str(first['machine']))}, steer {first['steer']}, g = {format_number(first['g_m_s2'])} m/s²[/dim]"
    return FitTable(columns + eig, tuple(c.key for c in reversed(eig)), title=title, footer=footer, notes=[note])


def turns_view(table: Table, total_rows: int | None = None, title: str | None = None) -> FitTable:
    """Steady turns on the globe: one line per turn, the rider's numbers
    first; the rider's table (``--summary``) one line per lane."""
    if "speeds_tried" in table:
        return turn_summary_view(table, total_rows, title)
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    columns = [Column(c, h, _cells(c, head.columns[c].tolist()), "left" if c == "status" else "right")
               for c, h in TURN_VIEW]
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    first = row_record(head)
    note = (f"[dim]{escape(str(first['machine']))}: r = {format_number(first['r_m'])} m, steer {first['steer']}"
            f"{_limits_text(first)}; lean from the wall's normal at the rear contact, + to the rider's right (the "
            "floor's side)[/dim]")
    return FitTable(columns, TURN_DROP + ("growth_rate_1_s",), title=title, footer=footer,
                    notes=[note, *status_legend(head)])


def _limits_text(get: dict) -> str:
    """The limits given, for the line under a table (none: nothing)."""
    words = (("mu_available", "μ available {}"), ("max_g", "max load {} g"))
    return "".join(f", {text.format(format_number(get[c]))}" for c, text in words if not is_undefined(get[c]))


#: Columns of the rider's table on the globe: (key, header); the rest of
#: its numbers are the CSV's.
TURN_SUMMARY_VIEW = (("height_m", "height\nm"), ("theta_deg", "θ°"), ("ok", "ok"), ("speed", "v rear\nm/s"),
                     ("lean", "lean°"), ("load", "load\ng"), ("mu_max", "μ\nneeded"), ("head", "head\nclear\nm"),
                     ("torque", "T_δ\nN m"), ("stable", "stable\nm/s"), ("hands", "hands-\nfree\nm/s"),
                     ("why", "why the others fail"))
TURN_SUMMARY_DROP = ("theta_deg", "lean", "torque", "head")
#: Why a speed fails on the globe: count column -> words (ride's, less the head).
TURN_WHY = (("slips", "slips"), ("over_g", "over g"), ("no_contact", "no contact"), ("no_orbit", "no turn"))


def _hands_free_cell(speeds: str, stable: str) -> str:
    """The hands-free speeds to 0.1 m/s, a stable one marked ✓."""
    calm = set(stable.split())
    cells = [f"{float(v):.1f}" + ("✓" if v in calm else "") for v in speeds.split()]
    return " ".join(cells) if cells else "—"


def turn_summary_view(table: Table, total_rows: int | None = None, title: str | None = None) -> FitTable:
    """The rider's table on the globe: per lane, the rear speeds ok of
    those tried, over them the speed, lean, load and steer torque ranges,
    the most friction needed and the least head clearance, the stable
    speeds, the lane's hands-free speeds and why the others fail."""
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    cells = {key: [] for key, _ in TURN_SUMMARY_VIEW}
    for i in range(len(head)):
        get = row_record(head, i)
        cells["height_m"].append(format_number(get["height_m"]))
        cells["theta_deg"].append(format_number(get["theta_deg"]))
        cells["ok"].append(f"{get['speeds_ok']}/{get['speeds_tried']}")
        cells["speed"].append(_span(get["v_rear_min_m_s"], get["v_rear_max_m_s"]))
        cells["lean"].append(_span(get["lean_min_deg"], get["lean_max_deg"]))
        cells["load"].append(_span(get["load_min_g"], get["load_max_g"], 2))
        cells["mu_max"].append(format_number(get["mu_max"], 2))
        cells["head"].append(format_number(get["head_clearance_min_m"], 2))
        cells["torque"].append(_span(get["steer_torque_min_n_m"], get["steer_torque_max_n_m"], 2))
        cells["stable"].append(_span(get["stable_v_min_m_s"], get["stable_v_max_m_s"]))
        cells["hands"].append(_hands_free_cell(get["hands_free_v_rear_m_s"], get["hands_free_stable_v_rear_m_s"]))
        parts = [f"{get[col]} {words}" for col, words in TURN_WHY if get[col]]
        cells["why"].append(", ".join(parts) if parts else "—")
    columns = [Column(key, header, cells[key], "left" if key == "why" else "right")
               for key, header in TURN_SUMMARY_VIEW]
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    first = row_record(head)
    limits = f"μ available {_limit(first['mu_available'])}, max load {_limit(first['max_g'])} g"
    notes = [f"[dim]{limits}, steer {first['steer']}; ok: rear speeds feasible of those tried; ranges over the ok "
             "ones, μ needed the most of them, head clear the least; stable: the ok speeds stable with the steer "
             "so held; hands-free: the lane's turns with no steer torque, at any speed (✓ stable)[/dim]"]
    return _WhyWraps(columns, TURN_SUMMARY_DROP, title=title, footer=footer, notes=notes)
