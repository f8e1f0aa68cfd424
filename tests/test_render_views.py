"""Terminal views at a given console width: identifying columns always
shown, numbers never cut, left-out columns named, long tables capped."""

import io
import re

import numpy as np
import pytest
from rich.console import Console

from deathsphere.model import Setup, Table, evaluate, make_requests
from deathsphere.render import orbit_views
from deathsphere.render.orbit_views import (
    generic_table,
    many_orbits_table,
    one_orbit_table,
    vertical_view,
    write_rich_table,
)
from deathsphere.render.paper_views import stability_view, table1_view
from deathsphere.render.terminal_table import MAX_TERMINAL_ROWS, format_number

WIDTHS = (60, 80, 120)


def show(renderable, width: int) -> str:
    console = Console(width=width, record=True, force_terminal=True, file=io.StringIO())
    console.print(renderable)
    return console.export_text()


def table_blocks(text: str) -> list[list[str]]:
    """The data lines of each table: from under the header rule to the
    first blank line."""
    blocks, current = [], None
    for line in text.splitlines():
        if "━━━" in line:
            current = []
            blocks.append(current)
        elif current is not None:
            if not line.strip():
                current = None
            else:
                current.append(line)
    return blocks


def header_text(text: str) -> str:
    """Everything above the first header rule (title and headers)."""
    return text.split("━━━", 1)[0]


def left_out(text: str) -> list[str]:
    """The column keys named by the left-out line (empty if none)."""
    flat = " ".join(text.split())
    m = re.search(r"left out at \d+ columns: (.*?) \(--format csv or a wider terminal shows them\)", flat)
    return m.group(1).split(", ") if m else []


def assert_fits(text: str, width: int):
    assert all(len(line) <= width for line in text.splitlines())
    for block in table_blocks(text):
        for line in block:
            assert "…" not in line, line


@pytest.fixture(scope="module")
def wheels() -> Table:
    theta, alpha = np.meshgrid([30.0, 45.0, 60.0, 75.0, 90.0], [5.0, 10.0, 60.0], indexing="ij")
    n = theta.size
    return evaluate(make_requests(n, input_row=np.arange(1, n + 1), body="wheel", theta=theta.ravel(),
                                  alpha=alpha.ravel(), mu=1.0))


@pytest.fixture(scope="module")
def spheres() -> Table:
    return evaluate(make_requests(2, input_row=np.array([1, 2]), body="sphere", theta=60.0,
                                  omega3=np.array([40.0, 400.0])))


@pytest.mark.parametrize("width", WIDTHS)
def test_many_wheels_keep_identifying_columns_and_whole_numbers(wheels, width):
    text = show(many_orbits_table(wheels, title="wheels"), width)
    assert_fits(text, width)
    heads = header_text(text)
    for head in ("#", "θ°", "α°", "status"):
        assert head in heads
    rows = table_blocks(text)[0]
    assert len(rows) == len(wheels)
    dropped = left_out(text)
    for i, line in enumerate(rows):
        cells = line.split()
        assert cells[:4] == [str(wheels["input_row"][i]), format_number(wheels["theta_deg"][i].item()),
                             format_number(wheels["alpha_deg"][i].item()), wheels["status"][i]]
        if "omega_rad_s" not in dropped:
            assert format_number(wheels["omega_rad_s"][i].item()) in cells
    # shown columns keep their units; the left-out ones are named, in priority order
    expected = orbit_views.SUMMARY_DROP_ORDER["wheel"][:len(dropped)]
    assert tuple(dropped) == expected
    if "omega_rad_s" not in dropped:
        assert "rad/s" in heads
    if width <= 60:
        assert "stability" in dropped and "csv" in text
    if width >= 120:
        assert dropped == [] and "stability" in heads


@pytest.mark.parametrize("width", WIDTHS)
def test_many_spheres_show_the_least_spin(spheres, width):
    text = show(many_orbits_table(spheres), width)
    assert_fits(text, width)
    heads = header_text(text)
    for head in ("#", "θ°", "br", "status"):
        assert head in heads
    least = format_number(spheres["omega3_min_real_rad_s"][0].item())
    flat = " ".join(text.split())
    assert f"needs |ω₃| ≥ {least} rad/s for an orbit" in flat and "θ = 60°" in flat
    dropped = left_out(text)
    assert tuple(dropped) == orbit_views.SUMMARY_DROP_ORDER["sphere"][:len(dropped)]
    if "omega3_min_real_rad_s" not in dropped:
        assert "|ω₃| min" in heads and all(least in line for line in table_blocks(text)[0])


def test_one_sphere_without_an_orbit_says_which_spin_would_do():
    table = evaluate(make_requests(1, body="sphere", theta=60.0, omega3=40.0))
    assert table["status"][0] == "no_orbit"
    flat = " ".join(show(one_orbit_table(table), 80).split())
    real = format_number(table["omega3_min_real_rad_s"][0].item())
    contact = format_number(table["omega3_min_contact_rad_s"][0].item())
    assert f"needs |ω₃| ≥ {real} rad/s for an orbit" in flat and f"≥ {contact} rad/s for contact" in flat
    assert "least |ω₃| for a real orbit" in flat


@pytest.mark.parametrize("width", (60, 80))
def test_one_orbit_leaves_out_only_the_source(width):
    text = show(one_orbit_table(Setup().orbit(60.0, 10.0)), width)
    assert_fits(text, width)
    assert "v_cm = |r'|Ω centre speed" in text and "nutation, slow (turning frame)" in text
    assert left_out(text) == ([] if width >= 80 else ["source"])


def _row_value(text: str, label: str, unit: str) -> float:
    """The value of the one table line that starts with ``label`` and has ``unit`` after the value."""
    hits = [m for m in (re.match(rf"\s*{re.escape(label)}\s+(\S+)\s+{re.escape(unit)}(\s|$)", line)
                        for line in text.splitlines()) if m]
    assert len(hits) == 1, (label, unit, text)
    return float(hits[0].group(1))


@pytest.mark.parametrize("width", (60, 80))
@pytest.mark.parametrize("body, request_", [
    ("wheel", dict(theta=60.0, alpha=10.0)),
    ("sphere", dict(theta=60.0, omega=-25.0)),
])
def test_one_orbit_shows_km_h_and_rpm_beside_si(width, body, request_):
    table = evaluate(make_requests(1, body=body, **request_))
    assert table["status"][0] == "ok"
    text = show(one_orbit_table(table), width)
    assert_fits(text, width)
    speed_label = "v_cm = |r'|Ω centre speed"
    spin_label = "ω₁ = r'Ω/a wheel spin" if body == "wheel" else "rolling rate v_cm/a"
    m_s, rad_s = _row_value(text, speed_label, "m/s"), _row_value(text, spin_label, "rad/s")
    km_h, rpm = _row_value(text, "the same in km/h", "km/h"), _row_value(text, "the same in rpm", "rpm")
    # by hand from the figures shown (5 significant digits each) ...
    assert km_h == pytest.approx(m_s * 3.6, rel=2e-4)
    assert rpm == pytest.approx(rad_s * 60.0 / (2.0 * np.pi), rel=2e-4)
    # ... and from the unrounded result, to the digits shown
    assert format_number(table["v_cm_m_s"][0].item() * 3.6, 5) == f"{km_h:.5g}"
    assert format_number(table["spin_rad_s"][0].item() * 30.0 / np.pi, 5) == f"{rpm:.5g}"
    # each right under its SI row
    lines = [line.strip() for line in text.splitlines()]
    at = next(i for i, line in enumerate(lines) if line.startswith(speed_label))
    assert lines[at + 1].startswith("the same in km/h")
    at = next(i for i, line in enumerate(lines) if line.startswith(spin_label))
    assert lines[at + 1].startswith("the same in rpm")


def test_wheel_at_60_10_in_km_h_and_rpm():
    """deathsphere orbit --theta 60 --alpha 10: 7.8767 m/s is 28.356 km/h,
    26.256 rad/s is 250.72 rpm."""
    text = show(one_orbit_table(Setup().orbit(60.0, 10.0)), 80)
    assert left_out(text) == []
    assert _row_value(text, "the same in km/h", "km/h") == 28.356
    assert _row_value(text, "the same in rpm", "rpm") == 250.72


def test_a_particle_has_km_h_and_no_rpm():
    text = show(one_orbit_table(evaluate(make_requests(1, body="particle", theta=120.0))), 100)
    assert "the same in km/h" in text and "rpm" not in text


@pytest.mark.parametrize("width", (60, 80))
@pytest.mark.parametrize("theta, alpha", [(90.0, 45.0), (170.0, 30.0)])
def test_stability_labels_stay_on_one_line(width, theta, alpha):
    import deathsphere

    text = show(stability_view(deathsphere.stability(theta, alpha)), width)
    assert_fits(text, width)
    lines = text.splitlines()
    for label in ("growth rate (max Re of the eigenvalues)", "slow nutation frequency", "slow nutation, rad/s",
                  "fast nutation, rad/s", "verdict"):
        assert any(label in line for line in lines), label
    for case in ("equator", "small wheel", "near pole"):
        assert any(re.search(rf"^\s+{case}: (applies|not here)\s*$", line) for line in lines), case
    assert "printed" in text and "exact" in text
    if width >= 80:
        # nothing important goes at 80 columns
        assert {"corrected", "deviation"} <= set(text.split()) and left_out(text) in ([], ["equation"])
    assert "verdicts:" in text


def test_row_cap_line_and_legend_of_the_rows_shown():
    n = 16_000
    theta = np.linspace(5.0, 175.0, n)
    table = evaluate(make_requests(n, input_row=np.arange(1, n + 1), body="wheel", theta=theta,
                                   alpha=np.full(n, 30.0)), stability=False)
    console = Console(width=100, record=True, force_terminal=True, file=io.StringIO())
    assert write_rich_table(table, console, "many") == n
    text = console.export_text()
    assert f"showing the first {MAX_TERMINAL_ROWS} of {n} rows; use --format csv" in text
    rows = table_blocks(text)[0]
    assert len(rows) == MAX_TERMINAL_ROWS
    shown = set(table["status"][:MAX_TERMINAL_ROWS].tolist()) - {"ok"}
    assert shown
    for status in shown:
        assert any(line.startswith(f"{status}: ") for line in text.splitlines())
    for status in set(table["status"].tolist()) - shown - {"ok"}:
        assert not any(line.startswith(f"{status}: ") for line in text.splitlines())


def test_caller_gives_the_total_of_a_streamed_result():
    table = evaluate(make_requests(3, input_row=np.array([1, 2, 3]), body="wheel", theta=60.0,
                                   alpha=np.array([5.0, 10.0, 15.0])), stability=False)
    text = show_write(table, total_rows=5000)
    assert "showing the first 3 of 5000 rows" in text
    one = Table({name: col[:1] for name, col in table.columns.items()})
    assert "showing the first 1 of 40 rows" in show_write(one, total_rows=40)
    assert "showing" not in show_write(one)


def show_write(table, **kw) -> str:
    console = Console(width=100, record=True, force_terminal=True, file=io.StringIO())
    write_rich_table(table, console, "t", **kw)
    return console.export_text()


def test_only_the_rows_shown_are_formatted(monkeypatch):
    n = 5_000
    table = evaluate(make_requests(n, body="wheel", theta=np.linspace(5.0, 175.0, n), alpha=np.full(n, 20.0)),
                     stability=False)
    calls = []
    real = orbit_views.format_number
    monkeypatch.setattr(orbit_views, "format_number", lambda *a, **k: calls.append(1) or real(*a, **k))
    show(many_orbits_table(table), 120)
    columns = len(orbit_views.SUMMARY_COLUMNS["wheel"])
    assert 0 < len(calls) <= 2 * columns * MAX_TERMINAL_ROWS


@pytest.mark.parametrize("width", WIDTHS)
def test_vertical_orbits_fit(width):
    from deathsphere.results.vertical import evaluate_vertical, vertical_requests

    n = 6
    req = vertical_requests(n, theta=np.full(n, 60.0), v_top=np.linspace(3.0, 8.0, n),
                            side="inside", a=0.3, r=3.0, k=0.5, g=9.80665, mu=np.inf)
    table = evaluate_vertical(req, stability=False)
    text = show(vertical_view(table), width)
    assert_fits(text, width)
    heads = header_text(text)
    for head in ("#", "θ°", "v top", "status"):
        assert head in heads
    dropped = left_out(text)
    assert tuple(dropped) == orbit_views.VERTICAL_DROP_ORDER[:len(dropped)]
    assert (width <= 60) == bool(dropped)
    for i, line in enumerate(table_blocks(text)[0]):
        assert line.split()[:3] == [str(table["input_row"][i]), "60", format_number(table["v_cm_m_s"][i].item())]


@pytest.mark.parametrize("width", WIDTHS)
def test_generic_table_keeps_keys_units_and_names_what_it_leaves_out(width):
    from deathsphere.results.vertical import vertical_points, vertical_requests

    req = vertical_requests(1, theta=np.array([60.0]), v_top=np.array([6.0]), side="inside",
                            a=0.3, r=3.0, k=0.5, g=9.80665, mu=np.inf)
    table = vertical_points(req, 6)
    text = show(generic_table(table, "points"), width)
    assert_fits(text, width)
    heads = header_text(text)
    assert "phi" in heads and "deg" in heads
    dropped = left_out(text)
    shown = [n for n in table.names if n not in dropped and n not in ("input_row", "theta_deg", "status", "reason")]
    assert "phi_deg" in shown
    # left out from the right, in table order
    assert dropped == [n for n in reversed(table.names) if n in dropped]
    if width >= 120:
        assert dropped == [] and "m/s²" in heads
    else:
        assert "mu_required" in dropped
    # inputs equal in every row go to a line under the table (strings too), in words with their units
    assert "theta = 60 deg" in text and "status = ok" in text and "theta_deg" not in text.split("left out")[0]


@pytest.mark.parametrize("width", (60, 80))
def test_limits_table_fits(width):
    from deathsphere.results.limits import intervals_table

    table = intervals_table(Setup(), np.arange(30.0, 61.0, 10.0), np.inf)
    text = show(generic_table(table, "limits"), width)
    assert_fits(text, width)
    assert "theta" in header_text(text) and "m/s" in header_text(text)


@pytest.mark.parametrize("width", WIDTHS)
def test_table1_leaves_out_the_acceleration_block_whole(width):
    from deathsphere.results.table1 import PRINTED
    from deathsphere.results.table1 import table1_comparison as table1

    text = show(table1_view(table1(), PRINTED), width)
    assert_fits(text, width)
    assert "θ°" in text and "α°" in text and "μ eq.35" in text
    assert left_out(text) in ([], ["g's", "acc g", "acc m/s²"])
    assert (left_out(text) == []) == (width >= 80)


COLOUR = re.compile(r"\x1b\[([0-9;]*)m")


def colour_codes(text: str) -> list[str]:
    found = []
    for params in COLOUR.findall(text):
        codes = [int(p) for p in params.split(";") if p]
        found += [c for c in codes if 30 <= c <= 49 or 90 <= c <= 107]
    return found


@pytest.mark.parametrize("no_color", ["1", None])
def test_no_color_is_respected(monkeypatch, wheels, no_color):
    if no_color:
        monkeypatch.setenv("NO_COLOR", no_color)
    else:
        monkeypatch.delenv("NO_COLOR", raising=False)
    out = io.StringIO()
    console = Console(width=80, force_terminal=True, color_system="standard", file=out)
    console.print(many_orbits_table(wheels, "wheels"))
    text = out.getvalue()
    assert "\x1b[" in text  # a terminal all the same (bold headers)
    assert bool(colour_codes(text)) == (no_color is None)
    assert "rad/s" in text and "m/s" in text
