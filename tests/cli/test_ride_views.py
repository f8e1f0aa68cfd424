"""``ride`` and ``machines`` on a terminal, as a person sees them: no line
wider than the terminal at 80 and 100 columns, no name cut, the safety
columns first, the rider's table saying why speeds fail, the loop's speeds
in the unit typed."""

import re

import pytest
from rich.cells import cell_len

from deathsphere.api.rides import RIDE_COLUMNS

SUMMARY = ("ride", "--diameter", "16ft", "--height", "0:2.4:0.4m", "--com-speed", "10:35:5km/h", "--mu", "1",
           "--max-g", "5", "--summary")
ONE = ("ride", "--theta", "90", "--speed", "40km/h", "--diameter", "16ft")
MANY = ("ride", "--diameter", "16ft", "--height", "0.4", "--height", "2.4", "--com-speed", "10:35:5km/h", "--mu", "1",
        "--max-g", "5")
LOOP = ("ride", "--vertical", "--theta", "90", "--v-top", "30km/h", "--mu", "0.1", "--max-g", "2")
LOOPS = ("ride", "--vertical", "--theta", "60", "--theta", "90", "--v-top", "20:40:10mph", "--machine",
         "benchmark-bicycle-rigid")


def _screen(run, args, width):
    res = run(*args, "--format", "table", env={"COLUMNS": str(width), "NO_COLOR": "1"})
    assert res.exit_code == 0, res.output
    return re.sub(r"\x1b\[[0-9;]*m", "", res.stdout)


@pytest.mark.parametrize("width", [80, 100])
@pytest.mark.parametrize("args", [ONE, MANY, SUMMARY, LOOP, LOOPS, ("machines",)],
                         ids=["one", "many", "summary", "loop", "loops", "machines"])
def test_no_line_is_wider_than_the_terminal(run, args, width):
    text = _screen(run, args, width)
    assert max(cell_len(line) for line in text.splitlines()) <= width


def test_one_orbit_is_a_quantity_value_unit_table_with_whole_names(run):
    text = _screen(run, ONE, 80)
    assert "quantity" in text and "value" in text and "unit" in text and "source" in text
    for words in ("speed of the contact (speedometer)", "speed of the centre of mass", "lean from the vertical",
                  "μ required", "head clearance"):
        assert words in text
    # never a column name cut to ten characters (mu_availab, head_clear)
    assert not any(name[:10] in text.split() for name in RIDE_COLUMNS if len(name) > 10)
    # the speed typed (the contact's) comes back as typed, first
    line = next(ln for ln in text.splitlines() if "speed of the" in ln)
    assert "speed of the contact" in line and " 40 " in line and "km/h" in line


def test_several_orbits_show_the_safety_columns_first_at_80(run):
    text = _screen(run, MANY, 80)
    header = text.splitlines()[:6]
    # where each safety column's header sits across the line
    order = [next(ln.index(w) for ln in header if w in ln) for w in ("status", "km/h", "lean", "load", "needed",
                                                                     "clear")]
    first_row = next(ln for ln in text.splitlines() if ln.split()[:1] == ["1"])
    assert sorted(order) == order and "10" in first_row.split()
    assert "left out at 80 columns" in text         # the rest where it fits: not at 80
    assert "left out" not in _screen(run, MANY, 160)


def test_the_riders_table_says_why_speeds_fail(run):
    text = _screen(run, SUMMARY, 80)
    assert "why the others fail" in text
    assert re.search(r"\d slips", text) and re.search(r"\d over g", text) and re.search(r"\d no lap", text)
    assert "load" in text and "needed" in text and "clear" in text
    assert "μ available 1" in text and "max load (g) 5" in text


def test_a_loop_shows_its_bottom_load_and_speeds_in_the_unit_typed(run):
    one = _screen(run, LOOP, 80)
    assert "load at the bottom" in one and "7.7579" in one and "the same in km/h" in one
    assert re.search(r"the same in km/h\s+30\s", one)
    many = _screen(run, LOOPS, 80)
    assert "mph" in many and "m/s" in many
    assert re.search(r"\s20\s", next(ln for ln in many.splitlines() if ln.split()[:1] == ["1"]))


def test_several_values_of_mu_are_a_column_not_one_line(run):
    text = _screen(run, (*MANY[:-4], "--mu", "0.6", "--mu", "1"), 80)
    assert "μ available" not in text
    rows = [ln.split() for ln in text.splitlines() if ln.split()[:1] in (["1"], ["7"])]   # six speeds a mu
    # #, height, (θ where it fits), μ
    assert "0.6" in rows[0][2:4] and "1" in rows[1][2:4] and "0.6" not in rows[1][2:4]
    loops = _screen(run, (*LOOPS, "--mu", "0.5", "--mu", "0.7"), 80)
    assert "μ available" not in loops and "slips" in loops
