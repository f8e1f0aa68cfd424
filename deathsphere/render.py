"""Writers for result tables: rich table, CSV, JSON and NDJSON.

Every writer takes an iterable of :class:`~deathsphere.model.Table` chunks so
that sweeps stream with flat memory; the header (CSV) or the opening bracket
(JSON) is written once.  Undefined values (NaN) are empty in CSV and null in
JSON; floats are written in Python's shortest round-trip form.
"""

from __future__ import annotations

import json
import math
from typing import IO, Iterable

import numpy as np
from rich import box
from rich.console import Console, Group
from rich.table import Table as RichTable

from deathsphere.model import TEXT_COLUMNS, Table
from deathsphere.table1 import decimals

FORMATS = ("table", "csv", "json", "ndjson")


def _csv_field(text: str) -> str:
    if any(c in text for c in ',"\n\r'):
        return '"' + text.replace('"', '""') + '"'
    return text


def _float_text(x: float) -> str:
    return "" if x != x else repr(x)


def _column_strings(name: str, values: np.ndarray) -> list[str]:
    """Text of one column.  Values that repeat (inputs, statuses, reasons)
    are formatted once each: a chunk of a grid holds few distinct inputs, and
    float formatting is what CSV output spends its time on."""
    n = len(values)
    if n == 0:
        return []
    if name in TEXT_COLUMNS or values.dtype == object:
        # few distinct texts per column: quote each once (None -> empty)
        cache: dict = {}
        text = []
        for v in values.tolist():
            t = cache.get(v)
            if t is None:
                t = cache[v] = "" if v is None else _csv_field(str(v))
            text.append(t)
        return text
    if values.dtype.kind in "iub":
        return list(map(str, values.tolist()))
    if (values[0] == values).all() or np.isnan(values).all():
        return [_float_text(float(values[0]))] * n
    if name in REPEATING_COLUMNS:
        unique, inverse = np.unique(values, return_inverse=True)
        text = list(map(_float_text, unique.tolist()))
        return [text[i] for i in inverse.tolist()]
    text = list(map(repr, values.tolist()))
    for i in np.flatnonzero(np.isnan(values)).tolist():
        text[i] = ""
    return text


#: Input columns: in a grid chunk they take few distinct values.
REPEATING_COLUMNS = frozenset({"theta_deg", "alpha_deg", "a_m", "r_m", "k", "g_m_s2", "mu_available"})


def csv_text(table: Table, header: bool) -> str:
    """One chunk as CSV text (with the header line first if asked)."""
    columns = [_column_strings(n, table[n]) for n in table.names]
    lines = [",".join(row) for row in zip(*columns)]
    if header:
        lines.insert(0, ",".join(table.names))
    return "\n".join(lines) + "\n" if lines else ""


def write_csv(chunks: Iterable[Table], out: IO[str]) -> int:
    rows = 0
    for i, table in enumerate(chunks):
        out.write(csv_text(table, header=i == 0))
        rows += len(table)
    return rows


def _json_value(v):
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def json_records(table: Table) -> list[str]:
    cols = [(n, table[n].tolist()) for n in table.names]
    return [json.dumps({n: _json_value(v[i]) for n, v in cols}) for i in range(len(table))]


def write_ndjson(chunks: Iterable[Table], out: IO[str]) -> int:
    rows = 0
    for table in chunks:
        lines = json_records(table)
        if lines:
            out.write("\n".join(lines) + "\n")
        rows += len(lines)
    return rows


def write_json(chunks: Iterable[Table], out: IO[str]) -> int:
    """A JSON array of row objects, streamed chunk by chunk."""
    rows = 0
    out.write("[")
    for table in chunks:
        for line in json_records(table):
            out.write(("\n  " if rows == 0 else ",\n  ") + line)
            rows += 1
    out.write("\n]\n" if rows else "]\n")
    return rows


def format_number(value, digits: int = 4) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "—"
    if isinstance(value, (int, np.integer)):
        return str(value)
    if isinstance(value, float) and math.isinf(value):
        return "∞" if value > 0 else "-∞"
    return f"{value:.{digits}g}"


STATUS_STYLE = {"ok": "green", "slips": "yellow", "invalid": "red"}


def status_text(status: str) -> str:
    style = STATUS_STYLE.get(status, "magenta")
    return f"[{style}]{status}[/{style}]"


#: (column, label, unit, source) for the one-orbit view.
ORBIT_FIELDS = (
    ("r_prime_m", "r' centre to axis", "m", "eq. 8b"),
    ("omega_rad_s", "Ω orbital rate", "rad/s", "eq. 29"),
    ("period_s", "period 2π/Ω", "s", ""),
    ("v_cm_m_s", "v_cm = |r'|Ω centre speed", "m/s", ""),
    ("spin_rad_s", "ω₁ = r'Ω/a wheel spin", "rad/s", "eq. 13"),
    ("omega3_rad_s", "ω₃ = -Ω sin α", "rad/s", "eq. 13"),
    ("branch", "branch of eq. 55 (0 slow, 1 fast)", "", "eq. 55"),
    ("omega3_min_real_rad_s", "least |ω₃| for a real orbit", "rad/s", "eq. 56"),
    ("omega3_min_contact_rad_s", "least |ω₃| for contact", "rad/s", "eq. 58/59"),
    ("accel_m_s2", "centre acceleration", "m/s²", "eq. 32"),
    ("accel_g", "centre acceleration", "g", "eq. 36"),
    ("normal_per_mass_m_s2", "normal force / m", "m/s²", "eq. 32"),
    ("friction_per_mass_m_s2", "friction / m (+ down)", "m/s²", "eq. 32"),
    ("mu_required", "μ required", "", "eq. 35"),
    ("growth_rate_1_s", "growth rate (max Re λ)", "1/s", "exact"),
    ("freq_slow_rad_s", "nutation, slow (turning frame)", "rad/s", "exact"),
    ("freq_fast_rad_s", "nutation, fast (turning frame)", "rad/s", "exact"),
)

OK_REASON = "fits, Ω² > 0, keeps contact, enough friction"

STABILITY_STYLE = {"stable": "[green]stable[/green]", "unstable": "[red]unstable[/red]",
                   "unknown": "[magenta]unknown[/magenta]"}

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


def _record(table: Table, row: int = 0) -> dict:
    """One row as plain Python values."""
    return {n: (v.item() if hasattr(v, "item") else v) for n, v in ((n, table[n][row]) for n in table.names)}


def _setup_line(get: dict) -> str:
    return (f"a = {format_number(get['a_m'])} m, r = {format_number(get['r_m'])} m, "
            f"k = {format_number(get['k'])}, g = {format_number(get['g_m_s2'], 6)} m/s²")


def quantity_table(title: str, get: dict, rows, ok_text: str) -> RichTable:
    """The one-result view: ``rows`` of (label, value, unit, source), then
    the stability (if computed) and the status, the reason as caption."""
    out = RichTable(title=title, box=box.SIMPLE_HEAVY, title_justify="left")
    for head in ("quantity", "value", "unit", "source"):
        out.add_column(head, justify="right" if head == "value" else "left", style="dim" if head == "source" else None)
    for label, value, unit, source in rows:
        out.add_row(label, value, unit, source)
    if get.get("stability"):
        out.add_row("stability", STABILITY_STYLE.get(get["stability"], get["stability"]), "", get["stability_method"])
    out.add_row("status", status_text(get["status"]), "", "")
    out.caption = f"{get['status']}: {get['reason'] or ok_text}"
    out.caption_justify = "left"
    return out


def one_orbit_table(table: Table, row: int = 0) -> RichTable:
    """A two-column view of every quantity of one orbit (undefined ones as —)."""
    get = _record(table, row)
    angles = f"θ = {format_number(get['theta_deg'])}°"
    if not _isnan(get["alpha_deg"]):
        angles += f", α = {format_number(get['alpha_deg'])}°"
    rows = []
    for col, label, unit, source in ORBIT_FIELDS:
        override = BODY_LABELS.get((get["body"], col), (label, source))
        if col in get and override is not None:
            rows.append((override[0], format_number(get[col], 5), unit, override[1]))
    mu = get.get("mu_available")
    rows.append(("μ available", "∞" if _isnan(mu) else format_number(mu), "", "--mu"))
    return quantity_table(f"{get['body']} {get['side']}, {angles}\n{_setup_line(get)}", get, rows, OK_REASON)


def _isnan(v) -> bool:
    return v is None or (isinstance(v, float) and math.isnan(v))


#: Headers of the many-orbit terminal view, and the columns shown per body
#: (each set fits 80 terminal columns).
SUMMARY_HEADERS = {
    "input_row": "#", "theta_deg": "θ°", "alpha_deg": "α°", "branch": "br", "omega3_rad_s": "ω₃\nrad/s",
    "status": "status", "omega_rad_s": "Ω\nrad/s", "v_cm_m_s": "v_cm\nm/s", "spin_rad_s": "ω₁\nrad/s",
    "accel_g": "accel\ng", "mu_required": "μ\nrequired", "stability": "stability",
}
SUMMARY_COLUMNS = {
    "wheel": ("input_row", "theta_deg", "alpha_deg", "status", "omega_rad_s", "v_cm_m_s",
              "accel_g", "mu_required", "stability"),
    "sphere": ("input_row", "theta_deg", "branch", "omega3_rad_s", "status", "omega_rad_s", "v_cm_m_s",
               "mu_required", "stability"),
    "particle": ("input_row", "theta_deg", "status", "omega_rad_s", "v_cm_m_s", "accel_g"),
    "mixed": ("input_row", "theta_deg", "alpha_deg", "branch", "status", "omega_rad_s", "v_cm_m_s",
              "mu_required", "stability"),
}


def many_orbits_table(table: Table, title: str | None = None) -> Group:
    """One summary row per orbit, then each distinct reason once."""
    out = RichTable(title=title, box=box.SIMPLE_HEAVY, title_justify="left")
    bodies = set(table["body"].tolist())
    columns = SUMMARY_COLUMNS[bodies.pop() if len(bodies) == 1 else "mixed"]
    fields = [(c, SUMMARY_HEADERS[c]) for c in columns]
    for col, head in fields:
        out.add_column(head, justify="left" if col in TEXT_COLUMNS else "right", no_wrap=True)
    cols = {c: table[c].tolist() for c, _ in fields}
    for i in range(len(table)):
        cells = []
        for col, _ in fields:
            v = cols[col][i]
            if col == "status":
                cells.append(status_text(v))
            elif col == "stability":
                cells.append(STABILITY_STYLE.get(v, v))
            elif col in TEXT_COLUMNS:
                cells.append(str(v))
            else:
                cells.append(format_number(v))
        out.add_row(*cells)
    reasons = dict.fromkeys(zip(table["status"].tolist(), table["reason"].tolist()))
    legend = [f"{status_text(st)}: {why}" for st, why in reasons if why]
    return Group(out, *legend)


def generic_table(table: Table, title: str | None = None) -> RichTable:
    """Any table: one column per field (for results that are not orbits)."""
    out = RichTable(title=title, box=box.SIMPLE_HEAVY, title_justify="left")
    if len(table) == 1:
        out.add_column("quantity")
        out.add_column("value", justify="right")
        for name, v in _record(table).items():
            out.add_row(name, str(v) if isinstance(v, (str, bool)) else format_number(v, 6))
        return out
    # columns equal in every row (the inputs) go to the caption
    same = [n for n in table.names if len(set(map(str, table[n].tolist()))) == 1]
    names = [n for n in table.names if n not in same]
    out.caption = ", ".join(f"{n} = {format_number(table[n][0].item())}" for n in same)
    out.caption_justify = "left"
    for name in names:
        out.add_column(name.replace("_", " "), justify="left" if table[name].dtype == object else "right")
    cols = [table[n].tolist() for n in names]
    for i in range(len(table)):
        out.add_row(*[str(c[i]) if isinstance(c[i], (str, bool)) else format_number(c[i]) for c in cols])
    return out


def write_rich_table(table: Table, console: Console, title: str | None = None) -> int:
    """Terminal view: every quantity for one orbit, a summary row per orbit
    for many; any other table column by column."""
    if "body" not in table or "status" not in table:
        console.print(generic_table(table, title))
    elif len(table) == 1:
        console.print(one_orbit_table(table))
    else:
        console.print(many_orbits_table(table, title))
    return len(table)


def table1_view(table: Table, printed) -> Group:
    """Table 1 printed vs computed (✓ where the printed value is reproduced
    at its printed precision), then the notes."""
    out = RichTable(title="McDonald (1993) Table 1: wheel a = 0.3 m, k = 1/2, sphere r = 3.0 m",
                    box=box.SIMPLE_HEAVY, title_justify="left")
    for head in ("θ°", "α°", "μ", "μ eq.35", "v_cm", "eq.29", "g's", "acc g", "acc m/s²"):
        out.add_column(head, justify="right", no_wrap=True)
    tick = {True: "[green]✓[/green]", False: "[red]✗[/red]"}
    notes = []
    for i, row in enumerate(printed):
        out.add_row(
            row[0], row[1], row[2],
            f"{table['mu_computed'][i]:.{decimals(row[2]) + 1}f}{tick[bool(table['mu_agrees'][i])]}",
            row[3],
            f"{table['v_cm_computed_m_s'][i]:.{decimals(row[3]) + 1}f}{tick[bool(table['v_cm_agrees'][i])]}",
            row[4],
            f"{table['accel_g_computed'][i]:.2f}{tick[bool(table['gs_column_is_g'][i])]}",
            f"{table['accel_m_s2_computed'][i]:.1f}{tick[bool(table['gs_column_is_m_s2'][i])]}",
        )
        if not table["mu_agrees"][i]:
            notes.append(f"θ={row[0]}° α={row[1]}°: μ printed {row[2]}, eq. 35 gives "
                         f"{table['mu_computed'][i]:.4f} (erratum T1-mu)")
    if table["gs_column_is_m_s2"].all() and not table["gs_column_is_g"].any():
        notes.append("\"No. of g's\" is the centre acceleration in m/s², not in g, in every row (erratum T1-g)")
    lines = ["Printed: μ, v_cm (m/s), \"No. of g's\"; computed with one more digit; "
             "✓ = reproduced at the printed precision.", *notes, "Evidence: docs/errata.md"]
    return Group(out, *lines)


#: (column, label, unit, source) for the vertical-orbit view.
VERTICAL_FIELDS = (
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


def vertical_view(table: Table):
    """One vertical orbit: a quantity per line; several: one line each."""
    if len(table) == 1:
        get = _record(table)
        rows = [(label, format_number(get[col], 5), unit, source)
                for col, label, unit, source in VERTICAL_FIELDS if not _isnan(get[col])]
        title = f"vertical orbit, wheel {get['side']}, θ = {format_number(get['theta_deg'])}°\n{_setup_line(get)}"
        return quantity_table(title, get, rows, "keeps contact all round with enough friction")
    out = RichTable(title="Vertical orbits (eqs. 27-28b)", box=box.SIMPLE_HEAVY, title_justify="left")
    cols = (("input_row", "#"), ("theta_deg", "θ°"), ("v_cm_m_s", "v top\nm/s"), ("status", "status"),
            ("v_top_min_m_s", "v min\nm/s"), ("period_s", "lap\ns"), ("phi_worst_deg", "worst\nφ°"),
            ("mu_required", "μ\nrequired"), ("phi_leave_deg", "leaves\nφ°"))
    for col, head in cols:
        out.add_column(head, justify="left" if col == "status" else "right", no_wrap=True)
    for i in range(len(table)):
        out.add_row(*[status_text(table[c][i]) if c == "status" else format_number(table[c][i].item())
                      for c, _ in cols])
    reasons = dict.fromkeys(zip(table["status"].tolist(), table["reason"].tolist()))
    return Group(out, *[f"{status_text(st)}: {why}" for st, why in reasons if why])


VERDICT_MARK = {"confirmed": "[green]✓ confirmed[/green]", "corrected": "[yellow]~ corrected[/yellow]",
                "refuted": "[red]✗ refuted[/red]"}


def checklist_view(table: Table, counts: dict) -> Group:
    """``deathsphere verify``: one block per claim, then the counts."""
    from rich.markup import escape

    parts = []
    for row in table.records():
        parts.append(f"{VERDICT_MARK[row['verdict']]}  [bold]{escape(row['id'])}[/bold]  "
                     f"(sec. {escape(row['section'])}, {escape(row['equation'])}) {escape(row['claim'])}")
        parts.append(f"    [dim]{escape(row['evidence'])}[/dim]")
    parts.append("")
    parts.append(", ".join(f"{n} {v}" for v, n in counts.items()) + f" ({len(table)} claims)")
    return Group(*parts)


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
    ("n_steps", "steps", ""),
    ("wall_time_s", "wall time", "s"),
)


def simulation_view(summary: Table):
    """The summary of one simulated body (the first row if several)."""
    get = _record(summary)
    what = (f"{get['body']} {get['side']}, {get['orbit']} orbit, θ = {format_number(get['theta_deg'])}°"
            + (f", α = {format_number(get['alpha_deg'])}°" if not _isnan(get.get("alpha_deg")) else "")
            + (f", kick {format_number(get['perturb_rad'])} rad" if get.get("perturb_rad") else ""))
    out = RichTable(title=f"simulation: {what}\nsolve_ivp {get['method']}, rtol {get['rtol']:g}, "
                          f"atol {get['atol']:g}, {get['frame']} frame",
                    box=box.SIMPLE_HEAVY, title_justify="left")
    for head in ("quantity", "value", "unit"):
        out.add_column(head, justify="right" if head == "value" else "left")
    for col, label, unit in SIMULATION_FIELDS:
        if col in get and not _isnan(get[col]):
            out.add_row(label, format_number(get[col], 4), unit)
    status = get["status"]
    style = {"completed": "green", "contact_lost": "red", "slips": "yellow"}.get(status, "magenta")
    out.add_row("status", f"[{style}]{status}[/{style}]", "")
    out.caption = f"{status}: {get['reason']}" if get.get("reason") else None
    out.caption_justify = "left"
    return out


def _cell(v, digits=4):
    if v is None:
        return "—"
    if isinstance(v, str):
        return STABILITY_STYLE.get(v, v)
    return format_number(v, digits)


def stability_view(table: Table, setup) -> Group:
    """``deathsphere stability``: the exact block, then the paper's results."""
    get = table.records()
    head = (f"stability of a wheel {setup.side}, θ = {format_number(get[0]['theta_deg'])}°, "
            f"α = {format_number(get[0]['alpha_deg'])}° (a = {format_number(setup.a)} m, "
            f"r = {format_number(setup.r)} m, k = {format_number(setup.k)})")
    exact = RichTable(title=head + "\nexact: the equations of motion linearised about the orbit",
                      box=box.SIMPLE_HEAVY, title_justify="left")
    for col in ("quantity", "value", "units"):
        exact.add_column(col, justify="right" if col == "value" else "left")
    for row in get:
        if row["source"] == "exact":
            exact.add_row(row["quantity"], _cell(row["exact"], 5), row["units"])
    paper = RichTable(title="the paper's results (printed, corrected, exact; deviation = printed vs exact)",
                      box=box.SIMPLE_HEAVY, title_justify="left")
    for col in ("result", "eq.", "applies", "printed", "corrected", "exact", "deviation"):
        paper.add_column(col, justify="left" if col in ("result", "eq.") else "right")
    notes = []
    for row in get:
        if row["source"] == "exact":
            continue
        verdict = row["quantity"].startswith("verdict")
        dev = row["deviation"]
        dev_text = "—" if dev is None else (("differs" if dev else "agrees") if verdict else f"{100 * dev:+.1f} %")
        validity = row["validity"]
        symbol = "a/r'" if row["source"].endswith("small wheel") else "r'/a"
        applies = ("yes" if row["applies"] else "no") + (f" ({symbol} {validity:.3g})" if validity is not None else "")
        paper.add_row(f"{row['source'][7:]}: {row['quantity']}", row["equation"], applies,
                      _cell(row["paper"]), _cell(row["corrected"]), _cell(row["exact"]), dev_text)
        if row["note"] not in notes:
            notes.append(row["note"])
    return Group(exact, paper, *[f"[dim]{n}[/dim]" for n in notes], "[dim]errata E1-E9: docs/stability.md, "
                                                                        "docs/errata.md[/dim]")
