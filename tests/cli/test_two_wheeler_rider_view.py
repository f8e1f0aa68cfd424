"""The two-wheeler's rider's table on a terminal (``ride --steer ...
--summary``), as a person sees it through a pseudo-terminal 80 and 100
columns wide: what the rider asked stays (lean, steer torque, head
clearance, the speeds that work, the hands-free speeds, how soon a
disturbance doubles), other columns go first, and "why the others fail"
takes one line per lane (docs/two-wheeler.md sec. 10)."""

import functools

import pytest
from rich.cells import cell_len
from test_terminal_views import ANSI, run_in_pty

RIDER = ("ride", "--machine", "sport-tourer", "--steer", "locked", "--diameter", "16ft", "--height", "1:2:0.5",
         "--speed", "40:65:3km/h", "--summary", "--max-g", "5", "--mu", "1")
#: The header words of what the rider asked, each column's own.
ASKED = ("lean°", "T_δ", "clear", "v rear", "free", "to 2×")


@functools.cache
def _screen(columns: int) -> tuple[str, ...]:
    """The screen at a width, drawn once for the tests that read it (a
    fresh interpreter on a pseudo-terminal: some 1.5 s)."""
    text = ANSI.sub("", run_in_pty(RIDER, columns))
    assert "Traceback" not in text, text
    lines = tuple(text.splitlines())
    assert max(cell_len(line) for line in lines) <= columns, text
    return lines


@pytest.mark.parametrize("columns", (80, 100))
def test_the_riders_table_keeps_what_the_rider_asked(columns):
    lines = _screen(columns)
    # the header: the lines above the table's rule (a progress bar may come
    # first on a slow machine: its lines are not the table's)
    rule = next(i for i, line in enumerate(lines) if line.strip() and set(line.strip()) == {"━"})
    header = " ".join(lines[max(0, rule - 6):rule])
    for words in ASKED:
        assert words in header, (words, "\n".join(lines))
    left_out = next(i for i, line in enumerate(lines) if line.startswith("left out at"))
    gone = " ".join(lines[left_out:left_out + 2])
    # the others go first: θ, the friction and load ranges
    assert "theta_deg" in gone and "mu_max" in gone and "load" in gone


@pytest.mark.parametrize("columns", (80, 100))
def test_why_the_others_fail_takes_one_line_per_lane(columns):
    lines = _screen(columns)
    rows = [line for line in lines if line.split()[:1] in (["1"], ["1.5"], ["2"])]
    # one line per lane, each ending in its reasons whole
    assert [row.split()[0] for row in rows] == ["1", "1.5", "2"]
    assert all(row.rstrip().endswith("g") and "over" not in row for row in rows), "\n".join(lines)


def test_a_band_stable_only_beyond_the_limits_is_in_brackets():
    lines = _screen(100)
    lane = next(line for line in lines if line.split()[:1] == ["1"])
    assert "(13.6–16.1)" in lane, "\n".join(lines)
