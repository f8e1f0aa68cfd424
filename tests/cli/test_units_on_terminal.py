"""Units out as they went in, on a terminal (docs/units.md): a value typed
in ft or km/h comes back in ft or km/h beside SI in every command's
terminal view, as a person sees it through a pseudo-terminal 80 and 100
columns wide; ``--units si`` shows SI alone, ``--units imperial`` ft and
mph; and the CSV is the same bytes whatever ``--units`` says."""

import re

import pytest
from rich.cells import cell_len
from test_terminal_views import ANSI, run_in_pty, run_on_terminal

WIDTHS = (80, 100)
ACT = """
[globe]
diameter = 4.88
min_clearance = 0.15

[[rider]]
name = "Ana"
lane = "horizontal"
height = 1.5
speed = 8.0
"""


def screen(args, columns: int) -> str:
    """What a terminal ``columns`` wide shows of ``deathsphere ARGS``: the
    in-process terminal, which test_terminal_views proves shows what a
    pseudo-terminal shows (and :func:`test_the_in_process_screen_is_the_pseudo_terminals`
    for the units' views), without a fresh interpreter per view."""
    with pytest.MonkeyPatch.context() as monkeypatch:
        shown = run_on_terminal(args, columns, monkeypatch)
    assert shown.traceback is None, shown.traceback
    text = ANSI.sub("", shown.stdout + shown.stderr)
    assert max(cell_len(line) for line in text.splitlines()) <= columns, text
    return text


@pytest.mark.parametrize("args, columns", [
    (("ride", "--diameter", "16ft", "--height", "5ft", "--speed", "40km/h"), 80),
    (("ride", "--machine", "stunt125-steer", "--steer", "free", "--diameter", "16ft", "--height", "3:6:1ft",
      "--speed", "30km/h", "--units", "imperial"), 100),
])
def test_the_in_process_screen_is_the_pseudo_terminals(args, columns):
    """The units' views as :func:`screen` shows them are, line for line, what
    a pseudo-terminal of the same size shows."""
    real = [line.rstrip() for line in ANSI.sub("", run_in_pty(args, columns)).splitlines() if line.strip()]
    assert real == [line.rstrip() for line in screen(args, columns).splitlines() if line.strip()]


def assert_rows(text: str, *patterns: str):
    """Each ``patterns`` a row of the view (label, value and unit, regex)."""
    missing = [p for p in patterns if not re.search(p, text)]
    assert not missing, (missing, text)


def rows_with(text: str, words: str) -> list[str]:
    return [line for line in text.splitlines() if words in line]


def header(text: str) -> str:
    """The lines above the table's rule: the title and the headers."""
    return text.split("━━━", 1)[0]


def cell_pairs(text: str, first: str, second: str) -> bool:
    """Whether a header line has ``first`` and, further right, ``second``."""
    return any(first in line and second in line[line.index(first) + len(first):] for line in header(text).splitlines())


@pytest.mark.parametrize("columns", WIDTHS)
def test_ride_heights_and_globe_in_ft_speeds_in_km_h(columns):
    text = screen(("ride", "--diameter", "16ft", "--height", "0:8:2ft", "--speed", "40km/h"), columns)
    # a height column in m, and beside it the same heights in ft, as typed: 0, 2, 4, 6, 8
    assert cell_pairs(text, "m", "ft")
    for i, ft in enumerate(("0", "2", "4", "6", "8"), start=1):
        row = next(line.split() for line in text.splitlines() if line.split()[:1] == [str(i)])
        assert row[2] == ft, row
    assert "km/h" in header(text) and all(" 40 " in line for line in rows_with(text, " ok "))
    assert "r = 2.4384 m (diameter 16 ft)" in " ".join(text.split())


@pytest.mark.parametrize("columns", WIDTHS)
def test_one_ride_orbit_in_the_units_typed(columns):
    text = screen(("ride", "--theta", "90", "--speed", "40km/h", "--diameter", "16ft"), columns)
    assert_rows(text, r"speed of the contact \(speedometer\)\s+40\s+km/h", r"the same in m/s\s+11\.111\s+m/s",
                r"contact height above the floor\s+2\.4384\s+m", r"the same in ft\s+8\s+ft")


@pytest.mark.parametrize("columns", WIDTHS)
def test_the_riders_table_in_ft(columns):
    text = screen(("ride", "--diameter", "16ft", "--height", "2:8:2ft", "--speed", "10:30:10km/h", "--summary"),
                  columns)
    assert cell_pairs(text, "m", "ft") and "km/h" in header(text)
    heights = [line.split()[:2] for line in text.splitlines() if re.match(r"\s+\d", line)]
    assert ["0.6096", "2"] in heights and ["2.438", "8"] in heights


@pytest.mark.parametrize("columns", WIDTHS)
def test_two_wheeler_turns_in_the_units_typed(columns):
    text = screen(("ride", "--machine", "benchmark-bicycle", "--steer", "free", "--diameter", "16ft", "--height",
                   "4ft", "--speed", "18km/h"), columns)
    row = next(line.split() for line in text.splitlines() if line.split()[:1] == ["1"])
    # #, height m, height ft, status, v rear m/s, v rear km/h
    assert row[1:3] == ["1.219", "4"] and row[4:6] == ["5", "18"], row
    assert "r = 2.4384 m (diameter 16 ft)" in " ".join(text.split())


@pytest.mark.parametrize("columns", WIDTHS)
def test_orbit_in_the_units_typed(columns):
    one = screen(("orbit", "--theta", "90", "--com-speed", "40km/h", "--diameter", "16ft"), columns)
    assert_rows(one, r"v_cm = \|r'\|Ω centre speed\s+11\.111\s+m/s", r"the same in km/h\s+40\s+km/h",
                r"r = 2\.4384 m \(diameter 16 ft\)")
    many = screen(("orbit", "--theta", "60", "--com-speed", "5:35:10km/h"), columns)
    assert cell_pairs(many, "m/s", "km/h")
    assert [line.split()[6] for line in many.splitlines() if re.match(r"\s+[1-4]\s", line)] == ["5", "15", "25", "35"]


@pytest.mark.parametrize("columns", WIDTHS)
def test_vertical_in_the_units_typed(columns):
    text = screen(("vertical", "--theta", "90", "--v-top", "18km/h"), columns)
    assert re.search(r"speed at the top\s+5\s+m/s", text) and re.search(r"the same in km/h\s+18\s+km/h", text)


@pytest.mark.parametrize("columns", WIDTHS)
def test_simulate_summary_in_the_units_typed(columns):
    text = screen(("simulate", "--theta", "90", "--com-speed", "40km/h", "--diameter", "16ft", "--periods", "1"),
                  columns)
    flat = " ".join(text.split())
    assert "v_cm = 11.11 m/s (40 km/h)" in flat and "r = 2.4384 m (diameter 16 ft)" in flat


@pytest.mark.parametrize("columns", WIDTHS)
def test_units_si_shows_si_alone(columns):
    text = screen(("ride", "--diameter", "16ft", "--height", "0:8:2ft", "--speed", "40km/h", "--units", "si"),
                  columns)
    assert not re.search(r"\bft\b", text) and "km/h" not in text and "speed" in header(text)
    assert "r = 2.4384 m," in " ".join(text.split())
    one = screen(("orbit", "--theta", "60", "--alpha", "10", "--units", "si"), columns)
    assert "the same in" not in one and "rpm" not in one


@pytest.mark.parametrize("columns", WIDTHS)
def test_units_imperial_shows_ft_and_mph(columns):
    text = screen(("ride", "--diameter", "4.8768", "--height", "0.6096", "--height", "2.4384", "--speed", "40km/h",
                   "--units", "imperial"), columns)
    assert cell_pairs(text, "m", "ft") and "mph" in header(text) and "km/h" not in text
    heights = [line.split()[1:3] for line in text.splitlines() if re.match(r"\s+[12]\s", line)]
    assert heights == [["0.6096", "2"], ["2.438", "8"]]
    one = screen(("orbit", "--theta", "90", "--com-speed", "40km/h", "--units", "imperial"), columns)
    assert re.search(r"the same in mph\s+24\.855\s+mph", one) and "km/h" not in one


@pytest.mark.parametrize("columns", WIDTHS)
def test_show_speeds_follow_units(columns, tmp_path):
    plan = tmp_path / "act.toml"
    plan.write_text(ACT, encoding="utf-8")
    crew = screen(("show", str(plan), "--table", "riders"), columns)
    assert "km/h" in crew and "28.8 (8.00)" in crew
    imperial = screen(("show", str(plan), "--table", "riders", "--units", "imperial"), columns)
    assert "mph" in imperial and "17.9 (8.00)" in imperial and "km/h" not in imperial
    si = screen(("show", str(plan), "--table", "riders", "--units", "si"), columns)
    assert "km/h" not in si and "mph" not in si and re.search(r"\s8\.00\s", si)


#: A plan typed in feet and mph (the crew's rule too), and the same plan in SI.
FEET_ACT = """
[globe]
diameter = "16ft"
min_clearance = "0.5ft"

[[rider]]
name = "Ana"
lane = "horizontal"
height = "4ft"
speed = "25mph"

[[rider]]
name = "Ben"
lane = "horizontal"
height = "6ft"
same_lap_as = "Ana"
phase = 180
"""
#: 16 ft = 4.8768 m, 0.5 ft = 0.1524 m, 4 ft = 1.2192 m, 6 ft = 1.8288 m, 25 mph = 25 x 0.44704 m/s.
SI_ACT = (FEET_ACT.replace('"16ft"', "4.8768").replace('"0.5ft"', "0.1524").replace('"4ft"', "1.2192")
          .replace('"6ft"', "1.8288").replace('"25mph"', "11.176"))


def _pair_cells(text: str) -> list[str]:
    return next(line.split() for line in text.splitlines() if "Ana – Ben" in line)


@pytest.mark.parametrize("columns", WIDTHS)
def test_show_plan_values_come_back_in_the_units_typed(columns, tmp_path):
    plan = tmp_path / "act.toml"
    plan.write_text(FEET_ACT, encoding="utf-8")
    text = screen(("show", str(plan), "--fail", "Ana@0.3:0"), columns)
    riders, pairs = text.split("Pairs over the act", 1)
    pairs, falls = pairs.split("Ana at t = 0.3 s", 1)
    # the rule typed as 0.5 ft: 0.1524 m, and 0.5 ft beside it
    assert "conflict: closer than 0.152 m (0.5 ft)" in " ".join(pairs.split())
    # the speed typed in mph: 25 mph is 11.176 m/s
    assert "mph" in header(riders) and "km/h" not in riders and "25.0 (11.18)" in riders
    # every length was typed in ft: the least clearance in m, then the same in ft (m / 0.3048)
    assert cell_pairs(pairs, "m", "ft") and cell_pairs(falls, "m", "ft")
    for cells, at in ((_pair_cells(pairs), 4), (next(line.split() for line in falls.splitlines()
                                                      if line.split()[:2] == ["Ana", "Ben"]), 3)):
        metres, feet = float(cells[at]), float(cells[at + 1])
        assert abs(feet - metres / 0.3048) < 0.0006 + 0.0005 / 0.3048, cells
    # the heights as typed beside m where the console has room; at 80 columns both go, named in words
    rows = {line.split()[0]: line.split() for line in riders.splitlines() if line.split()[:1] in (["Ana"], ["Ben"])}
    if columns >= 100:
        assert cell_pairs(riders, "height", "height") and rows["Ana"][3:5] == ["1.219", "4"]
        assert rows["Ben"][3:5] == ["1.829", "6"], rows
    else:
        assert re.search(r"left out at 80 columns:[^(]*\bheight, height in ft\b", " ".join(riders.split()))


@pytest.mark.parametrize("columns", WIDTHS)
def test_show_plan_in_si_adds_no_other_unit(columns, tmp_path):
    plan = tmp_path / "act.toml"
    plan.write_text(SI_ACT, encoding="utf-8")
    text = screen(("show", str(plan)), columns)
    assert not re.search(r"\bft\b", text) and "mph" not in text and "km/h" in text
    assert "conflict: closer than 0.152 m;" in " ".join(text.split())
    typed = tmp_path / "feet.toml"
    typed.write_text(FEET_ACT, encoding="utf-8")
    si = screen(("show", str(typed), "--units", "si"), columns)
    assert not re.search(r"\bft\b", si) and "mph" not in si and "km/h" not in si


@pytest.mark.parametrize("table", ["riders", "pairs"])
def test_show_csv_is_si_whatever_the_plan_typed(run, tmp_path, table):
    feet, si = tmp_path / "feet.toml", tmp_path / "si.toml"
    feet.write_text(FEET_ACT, encoding="utf-8")
    si.write_text(SI_ACT, encoding="utf-8")
    typed = run("show", str(feet), "--table", table, "--format", "csv")
    assert typed.exit_code == 0, typed.output
    assert typed.stdout_bytes == run("show", str(si), "--table", table, "--format", "csv").stdout_bytes


@pytest.mark.parametrize("args", [
    ("ride", "--diameter", "16ft", "--height", "0:8:2ft", "--speed", "40km/h"),
    ("ride", "--diameter", "16ft", "--height", "0:2.4:0.8m", "--speed", "10:30:10km/h", "--summary"),
    ("orbit", "--theta", "90", "--speed", "40km/h", "--diameter", "16ft"),
    ("vertical", "--theta", "90", "--v-top", "18km/h"),
    ("limits", "--theta", "60", "--diameter", "16ft", "--mu", "1"),
], ids=["ride", "summary", "orbit", "vertical", "limits"])
def test_csv_is_the_same_whatever_units_says(run, args):
    plain = run(*args, "--format", "csv")
    assert plain.exit_code == 0, plain.output
    for system in ("as-typed", "si", "metric", "imperial"):
        assert run(*args, "--format", "csv", "--units", system).stdout_bytes == plain.stdout_bytes


@pytest.mark.parametrize("columns", WIDTHS)
def test_show_monte_carlo_falls_headers_and_outcomes_in_words(columns, tmp_path):
    plan = tmp_path / "act.toml"
    plan.write_text(FEET_ACT, encoding="utf-8")
    text = screen(("show", str(plan), "--monte-carlo", "8", "--seed", "1", "--table", "falls"), columns)
    # the least clearance's unit once, under its words (m, and ft beside it: every length typed in ft)
    assert "clear m" not in header(text) and cell_pairs(text, "m", "ft"), text
    assert "rides_on" not in text and "rides on" in text


@pytest.mark.parametrize("columns", WIDTHS)
def test_a_fall_on_the_wall_says_its_heights_in_the_plans_ft(columns):
    from pathlib import Path

    wall = Path(__file__).resolve().parents[2] / "examples" / "wall_of_death.toml"
    text = screen(("show", str(wall), "--fail", "Ben@1.2:0.5", "--table", "falls"), columns)
    # Ben rides 6 ft up the wall (1.8288 m), where he leaves it; the heights were typed in ft
    assert "leaves the wall at t = 1.2 s (1.83 m (6.00 ft) up," in " ".join(text.split()), text
