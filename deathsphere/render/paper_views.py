"""Terminal views of the paper's checks: Table 1 printed vs computed, the
checklist of claims (``deathsphere verify``) and the stability results
(``deathsphere stability``)."""

from __future__ import annotations

from rich.console import Group
from rich.markup import escape

from deathsphere.model import LIVE_STATUSES
from deathsphere.render.terminal_table import (
    STABILITY_STYLE,
    Column,
    FitTable,
    echo_number,
    format_number,
)
from deathsphere.table import Table
from deathsphere.table.cells import decimals

#: The acceleration trio of Table 1 ("No. of g's" printed beside both
#: readings of it) goes first, as a block: one of the three alone says
#: nothing; then the speed pair; μ, the paper's headline, stays longest.
TABLE1_DROP_ORDER = (("g's", "acc g", "acc m/s²"), ("v_cm", "eq.29"))


def table1_view(table: Table, printed) -> FitTable:
    """Table 1 printed vs computed (✓ where the printed value is reproduced
    at its printed precision), then the notes."""
    tick = {True: "[green]✓[/green]", False: "[red]✗[/red]"}
    rows = []
    notes = []
    for i, row in enumerate(printed):
        rows.append((
            row[0], row[1], row[2],
            f"{table['mu_computed'][i]:.{decimals(row[2]) + 1}f}{tick[bool(table['mu_agrees'][i])]}",
            row[3],
            f"{table['v_cm_computed_m_s'][i]:.{decimals(row[3]) + 1}f}{tick[bool(table['v_cm_agrees'][i])]}",
            row[4],
            f"{table['accel_g_computed'][i]:.2f}{tick[bool(table['gs_column_is_g'][i])]}",
            f"{table['accel_m_s2_computed'][i]:.1f}{tick[bool(table['gs_column_is_m_s2'][i])]}",
        ))
        if not table["mu_agrees"][i]:
            notes.append(f"θ={row[0]}° α={row[1]}°: μ printed {row[2]}, eq. 35 gives "
                         f"{table['mu_computed'][i]:.4f} (erratum T1-mu)")
    if table["gs_column_is_m_s2"].all() and not table["gs_column_is_g"].any():
        notes.append("\"No. of g's\" is the centre acceleration in m/s², not in g, in every row (erratum T1-g)")
    heads = ("θ°", "α°", "μ", "μ eq.35", "v_cm", "eq.29", "g's", "acc g", "acc m/s²")
    columns = [Column(h, h, [r[j] for r in rows]) for j, h in enumerate(heads)]
    lines = ["Printed: μ, v_cm (m/s), \"No. of g's\"; computed with one more digit; "
             "✓ = reproduced at the printed precision.", *notes, "Evidence: docs/errata.md"]
    return FitTable(columns, TABLE1_DROP_ORDER,
                    title="McDonald (1993) Table 1: wheel a = 0.3 m, k = 1/2, sphere r = 3.0 m", notes=lines)


VERDICT_MARK = {"confirmed": "[green]✓ confirmed[/green]", "corrected": "[yellow]~ corrected[/yellow]",
                "refuted": "[red]✗ refuted[/red]"}


def checklist_view(table: Table, counts: dict) -> Group:
    """``deathsphere verify``: one block per claim, then the counts."""
    parts = []
    for row in table.records():
        parts.append(f"{VERDICT_MARK[row['verdict']]}  [bold]{escape(row['id'])}[/bold]  "
                     f"(sec. {escape(row['section'])}, {escape(row['equation'])}) {escape(row['claim'])}")
        parts.append(f"    [dim]{escape(row['evidence'])}[/dim]")
    parts.append("")
    parts.append(", ".join(f"{n} {v}" for v, n in counts.items()) + f" ({len(table)} claims)")
    return Group(*parts)


def _cell(v, digits=4):
    if v is None:
        return "—"
    if isinstance(v, str):
        return STABILITY_STYLE.get(v, v)
    return format_number(v, digits)


#: Left out first when the paper's results do not fit: the equation
#: numbers (also in docs/stability.md), then the deviation (printed vs
#: exact can be read off), then the corrected value.  The result, printed
#: and exact values always stay.
STABILITY_DROP_ORDER = ("equation", "deviation", "corrected")


def _paper_label(quantity: str, units: str) -> tuple[str, str]:
    """A one-line label and the condition it drops: "verdict (w^2 > 0)" ->
    ("verdict", "w^2 > 0"); a frequency carries its unit."""
    label, _, condition = quantity.partition(" (")
    label = label.replace(" frequency", "")
    if units:
        label += f", {units}"
    return label, condition.rstrip(")")


def stability_view(table: Table) -> Group:
    """``deathsphere stability``: the exact block, then the paper's results
    grouped by case (equator, small wheel, near the poles), whether each
    applies here, and the notes.  Labels stay on one line; the conditions
    of the verdicts and the premises' parameters go to lines under it."""
    get = table.records()
    theta = get[0]["theta_deg"]
    # off the globe an orbit has a lane's height, not a polar angle
    where = (f"θ = {echo_number(theta)}°" if theta is not None and theta == theta else
             f"on the {get[0].get('surface')}, height {echo_number(get[0].get('height_m'))} m")
    head = (f"[italic]stability of a wheel {get[0]['side']}, {where}, "
            f"α = {echo_number(get[0]['alpha_deg'])}° (a = {echo_number(get[0]['a_m'])} m, "
            f"r = {echo_number(get[0]['r_m'])} m, k = {echo_number(get[0]['k'])})[/italic]")
    exact_rows = [row for row in get if row["source"] == "exact"]
    exact = FitTable([Column("quantity", "quantity", [escape(r["quantity"]) for r in exact_rows], "left"),
                      Column("value", "value", [_cell(r["exact"], 5) for r in exact_rows]),
                      Column("units", "units", [r["units"] for r in exact_rows], "left")],
                     title="exact: the equations of motion linearised about the orbit")
    cells = {key: [] for key in ("result", "equation", "paper", "corrected", "exact", "deviation")}
    notes, conditions, premises = [], [], []
    group = None
    for row in get:
        if row["source"] == "exact":
            continue
        case = row["source"].removeprefix("paper: ")
        if (case, row["applies"]) != group:
            group = (case, row["applies"])
            where = "[green]applies[/green]" if row["applies"] else "not here"
            for key, column in cells.items():
                column.append(f"[bold]{escape(case)}[/bold]: {where}" if key == "result" else "")
            if row["validity"] is not None:
                symbol, limit = ("a/r'" if case.endswith("small wheel") else "r'/a"), row["validity_limit"]
                premises.append(f"{case} {symbol} = {row['validity']:.3g} (applies up to {limit:g})")
        label, condition = _paper_label(row["quantity"], row["units"])
        if condition:
            conditions.append(f"{case} {condition}")
        verdict = row["quantity"].startswith("verdict")
        dev = row["deviation"]
        cells["result"].append(f"  {escape(label)}")
        cells["equation"].append(escape(row["equation"]))
        cells["paper"].append(_cell(row["paper"]))
        cells["corrected"].append(_cell(row["corrected"]))
        cells["exact"].append(_cell(row["exact"]))
        cells["deviation"].append("—" if dev is None else
                                  (("differs" if dev else "agrees") if verdict else f"{100 * dev:+.1f} %"))
        if row["note"] not in notes:
            notes.append(row["note"])
    headers = {"result": "result", "equation": "eq.", "paper": "printed", "corrected": "corrected",
               "exact": "exact", "deviation": "deviation"}
    columns = [Column(key, headers[key], column, "left" if key in ("result", "equation") else "right")
               for key, column in cells.items()]
    lines = []
    if conditions:
        lines.append("[dim]verdicts: " + "; ".join(escape(c) for c in conditions) + "[/dim]")
    if premises:
        lines.append("[dim]here: " + ", ".join(escape(p) for p in premises) + "[/dim]")
    lines += [f"[dim]{escape(n)}[/dim]" for n in notes]
    lines.append("[dim]errata E1-E9: docs/stability.md, docs/errata.md[/dim]")
    orbit = next((r for r in exact_rows if r["quantity"] == "orbit status"), None)
    if orbit is not None and orbit["exact"] not in LIVE_STATUSES:
        # nothing to linearise about: say why instead of an empty table
        why = exact_rows[-1]["note"]
        return Group(head, exact, f"[yellow]{escape(why)}[/yellow]")
    if not any(row["source"] != "exact" for row in get) and "off the globe" in exact_rows[-1]["note"]:
        # the paper's results are the globe's: off it the exact rows are the answer
        return Group(head, exact, "[dim]off the globe only the exact rows apply (the paper's results are the "
                                  "sphere's)[/dim]")
    paper = FitTable(columns, STABILITY_DROP_ORDER,
                     title="the paper's results (printed, corrected, exact; deviation = printed vs exact)",
                     notes=lines)
    return Group(head, exact, "", paper)
