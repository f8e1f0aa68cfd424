"""Terminal views of ``deathsphere ride`` for a two-wheeler: straight running
on flat ground (eigenvalues against speed), its summary (weave and capsize
speeds) and the steady turns on the globe.  Eigenvalues show as complex
numbers, one cell each; the columns that do not fit a narrow console are
left out from the right and named under the table."""

from __future__ import annotations

from rich.markup import escape

from deathsphere.render.terminal_table import (
    MAX_TERMINAL_ROWS,
    STABILITY_STYLE,
    Column,
    FitTable,
    first_rows,
    format_number,
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
    """Steady turns on the globe: one line per turn, the rider's numbers first."""
    total = row_total(table, total_rows)
    head = first_rows(table, MAX_TERMINAL_ROWS)
    columns = [Column(c, h, _cells(c, head.columns[c].tolist()), "left" if c == "status" else "right")
               for c, h in TURN_VIEW]
    footer = [row_cap_line(len(head), total)] if total > len(head) else []
    first = row_record(head)
    note = (f"[dim]{escape(str(first['machine']))}: r = {format_number(first['r_m'])} m, steer {first['steer']}; "
            "lean from the wall's normal at the rear contact, + to the rider's right (the floor's side)[/dim]")
    return FitTable(columns, TURN_DROP + ("growth_rate_1_s",), title=title, footer=footer,
                    notes=[note, *status_legend(head)])
