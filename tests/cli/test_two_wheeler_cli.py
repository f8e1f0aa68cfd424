"""``deathsphere ride --flat`` and ``--steer`` for a two-wheeler: the
benchmark's eigenvalues and weave and capsize speeds (the published
numbers held by tests/physics/test_two_wheeler.py), one-line refusals with
exit status 2, and terminal views no wider than the terminal."""

import csv
import functools
import importlib.util
import io
import re
from pathlib import Path

import pytest
from rich.cells import cell_len


@functools.cache
def _published():
    # the published figures' module, loaded when a test first asks (not at collection)
    path = Path(__file__).resolve().parents[1] / "physics" / "test_two_wheeler.py"
    spec = importlib.util.spec_from_file_location("published_benchmark_cli", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


BIKE = ("ride", "--machine", "benchmark-bicycle")
#: The benchmark's published numbers hold at its g = 9.81 (Table 1), which the run is given.
FLAT = (*BIKE, "--flat", "--speed", "0:10:0.1", "-g", "9.81")
TURNS = (*BIKE, "--steer", "free", "--diameter", "16ft", "--height", "1:2:0.5", "--speed", "5:10:5")
HANDS_FREE = (*BIKE, "--steer-torque", "0", "--diameter", "16ft", "--height", "1")


def _rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_flat_straight_running_prints_table_2_at_its_speeds(run):
    res = run(*FLAT, "--format", "csv")
    assert res.exit_code == 0, res.output
    rows = _rows(res.stdout)
    assert len(rows) == 101 and list(rows[0])[:7] == ["input_row", "machine", "steer", "speed_m_s", "g_m_s2",
                                                       "stability", "growth_rate_1_s"]
    by_speed = {float(r["speed_m_s"]): r for r in rows}
    for v in (0.0, 4.0, 5.0, 10.0):
        got = [complex(float(by_speed[v][f"eig_{i}_re"]), float(by_speed[v][f"eig_{i}_im"])) for i in range(1, 5)]
        expected = sorted(_published().TABLE2[v], key=lambda z: (-z.real, -z.imag))
        assert max(abs(a - b) for a, b in zip(got, expected)) < 1e-12
    stable = [float(r["speed_m_s"]) for r in rows if r["stability"] == "stable"]
    assert min(stable) > _published().WEAVE and max(stable) < _published().CAPSIZE


def test_the_summary_has_the_weave_and_capsize_speeds(run):
    res = run(*FLAT, "--summary", "--format", "csv")
    (row,) = _rows(res.stdout)
    assert abs(float(row["weave_speed_m_s"]) - _published().WEAVE) < 1e-10
    assert abs(float(row["capsize_speed_m_s"]) - _published().CAPSIZE) < 1e-10


def test_hands_free_turns_on_the_globe(run):
    res = run(*HANDS_FREE, "--format", "csv")
    rows = _rows(res.stdout)
    assert res.exit_code == 0 and len(rows) >= 2
    for col in ("steer_deg", "steer_torque_n_m", "pitch_deg", "normal_rear_per_mass_m_s2",
                "normal_front_per_mass_m_s2", "mu_required_rear", "mu_required_front", "stability",
                "growth_rate_1_s", "eig_6_re", "eig_6_im"):
        assert col in rows[0]
    assert all(float(r["steer_torque_n_m"]) == 0.0 and r["input_row"] == "1" for r in rows)


@pytest.mark.parametrize("args, words", [
    (("ride", "--machine", "stunt125", "--flat", "--speed", "5"), "is a single-contact machine"),
    (("ride", "--steer", "free", "--theta", "90", "--speed", "5"), "is a single-contact machine"),
    ((*BIKE, "--flat", "--speed", "5", "--theta", "90"), "flat ground has no lane"),
    ((*BIKE, "--flat", "--speed", "-1"), "Invalid value for '--speed'"),
    ((*BIKE, "--steer", "free", "--theta", "90"), "give speed"),
    ((*BIKE, "--steer", "sideways", "--theta", "90", "--speed", "5"), "steer must be one of free | locked or torque=T"),
    ((*BIKE, "--flat", "--speed", "5", "--steer-torque", "1"), "steer_torque is for the globe"),
    ((*BIKE, "--steer-torque", "0", "--theta", "90", "--summary"), "give speed, not steer_torque"),
    ((*BIKE, "--steer", "free", "--theta", "90", "--speed", "5", "--summary", "--no-stability"),
     "needs the stability"),
    ((*BIKE, "--steer", "free", "--theta", "90", "--speed", "5", "--mu", "0.5:0.7:0.1"), "takes one mu per call"),
    ((*BIKE, "--steer", "free", "--theta", "90", "--speed", "5", "--max-g", "0"), "Invalid value for '--max-g'"),
    ((*BIKE, "--flat", "--speed", "5", "--mu", "0.8"), "mu and max_g are for the globe"),
    ((*BIKE, "--flat", "--speed", "5", "--mass", "90"), "does not take mass"),
])
def test_bad_combinations_exit_2_with_one_line(run, args, words):
    res = run(*args)
    assert res.exit_code == 2 and res.stdout == ""
    assert words in res.stderr and len(res.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("width", [80, 100])
@pytest.mark.parametrize("args", [(*BIKE, "--flat", "--speed", "0:10:1"), (*FLAT, "--summary"), TURNS,
                                  HANDS_FREE], ids=["flat", "summary", "turns", "hands-free"])
def test_the_terminal_views_fit(run, args, width):
    res = run(*args, "--format", "table", env={"COLUMNS": str(width), "NO_COLOR": "1"})
    assert res.exit_code == 0, res.output
    text = re.sub(r"\x1b\[[0-9;]*m", "", res.stdout)
    assert max(cell_len(line) for line in text.splitlines()) <= width
    assert "benchmark-bicycle" in text and "Traceback" not in text
