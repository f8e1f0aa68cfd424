"""A terminal view labels its quantities in words with their units, never
a CSV column's snake_case name (``alpha min ... deg``, not
``alpha_min_deg``), and its titles wrap at the terminal's width; seen
through a pseudo-terminal 80 and 100 columns wide (and 60 for the
wrapping)."""

import re

import pytest
from test_units_on_terminal import WIDTHS, assert_rows, screen

#: A CSV column's name: words joined by underscores.
SNAKE = re.compile(r"\b[a-z0-9]+_[a-z0-9_]+\b")


@pytest.mark.parametrize("columns", WIDTHS)
def test_limits_one_result_in_words_with_units(columns):
    text = screen(("limits", "--theta", "60", "--mu", "1"), columns)
    assert not SNAKE.findall(text), SNAKE.findall(text)
    assert_rows(text, r"theta\s+60\s+deg", r"alpha max\s+7\.\d+\s+deg", r"v min\s+\d+\.\d+\s+m/s",
                r"mu available\s+1\s")


@pytest.mark.parametrize("columns", WIDTHS)
def test_two_wheeler_summary_in_words_with_units(columns):
    text = screen(("simulate", "--machine", "stunt125-steer", "--steer", "free", "--diameter", "16ft", "--height",
                   "2", "--speed", "9", "--periods", "0.05"), columns)
    assert not SNAKE.findall(text), SNAKE.findall(text)
    assert_rows(text, r"v rear\s+9\s+m/s", r"k lean\s+0\s+N·m/rad", r"k rate\s+0\s+N·m·s/rad",
                r"steer torque\s+[\d.]+\s+N·m *\n", r"steer mode\s+free")
    # a torque is not a length: the globe typed in ft shows lengths in ft, not N·m
    lines = text.splitlines()
    torque = next(i for i, line in enumerate(lines) if "steer torque" in line)
    assert "the same in" not in lines[torque + 1]


def test_simulate_title_wraps_at_the_terminal_not_the_table():
    text = screen(("simulate", "--theta", "60", "--alpha", "10", "--periods", "0.2"), 60)
    rule = next(line for line in text.splitlines() if "━━━" in line)
    first = text.splitlines()[0].rstrip()
    # the table is narrower than the terminal: its title uses the terminal's width
    assert len(rule.strip()) < 56 and len(first) > len(rule.strip()), text
    assert "simulation: wheel inside, horizontal orbit, θ = 60°, α = 10°" in first


@pytest.mark.parametrize("columns", WIDTHS)
def test_a_tables_common_values_in_words_with_units(columns):
    text = screen(("limits", "--mu", "1", "--max-g", "5", "--theta", "30:150:30"), columns)
    flat = " ".join(text.split())
    assert "a = 0.3 m, r = 3 m, inertia factor k = 0.5, mu available = 1, max load = 5 g" in flat, text
    assert not SNAKE.findall(text.split("━━━", 1)[1].split("left out", 1)[0]), text


@pytest.mark.parametrize("columns", WIDTHS)
def test_a_negative_zero_reads_zero(columns):
    # on a great circle the friction along the loop is -0.0 at the top: it reads 0
    text = screen(("vertical", "--theta", "90", "--v-top", "6", "--points", "5"), columns)
    assert not re.search(r"(?<![\w.])-0(?![\w.])", text), text
    assert "friction meridional / m = 0 m/s²" in " ".join(text.split())


@pytest.mark.parametrize("columns", WIDTHS)
@pytest.mark.parametrize("args, title", [
    (("orbit", "--theta", "123.456", "--alpha", "10.25", "-r", "2.4384"),
     "wheel inside, θ = 123.456°, α = 10.25° a = 0.3 m, r = 2.4384 m, k = 0.5"),
    (("simulate", "--theta", "123.456", "--alpha", "10.25", "--periods", "0.1"), "θ = 123.456°, α = 10.25°"),
    (("stability", "--theta", "123.456", "--alpha", "10.25", "-r", "2.4384"),
     "θ = 123.456°, α = 10.25° (a = 0.3 m, r = 2.4384 m, k = 0.5)"),
    (("ride", "--theta", "123.456", "--speed", "8.125", "--diameter", "16ft"),
     "stunt125, θ = 123.456°"),
], ids=["orbit", "simulate", "stability", "ride"])
def test_a_title_echoes_the_inputs_as_typed(columns, args, title):
    # not 123.5 and 2.438: an input is shown to the digits it was typed with
    flat = " ".join(screen(args, columns).split())
    assert title in flat, flat


@pytest.mark.parametrize("columns", WIDTHS)
def test_simulate_on_the_drum_titles_its_height_as_typed(columns):
    text = screen(("simulate", "--surface", "cylinder", "--diameter", "32ft", "--height", "3ft", "--alpha", "20",
                   "--periods", "0.1"), columns)
    # 3 ft is 0.9144 m exactly; the drum's 32 ft diameter is its 4.8768 m radius
    flat = " ".join(text.split())
    assert "on the cylinder, height 0.9144 m (3 ft), α = 20°" in flat and "r = 4.8768 m (diameter 32 ft)" in flat
