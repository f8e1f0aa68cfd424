"""Work that takes seconds shows a progress bar on stderr when it is a
terminal, and only there: stdout is byte for byte what a pipe gets.  A
table written to a file (--output) is named on stderr with its rows."""

import csv
import os
import subprocess
import sys

import pytest
from test_sweep import _with_stderr_on_a_terminal

# work of several chunks, its bar drawn at once (no delay: DEATHSPHERE_PROGRESS_DELAY=0)
LONG = {
    "ride --summary": ["ride", "--diameter", "16ft", "--height", "0:2.4:0.1", "--speed", "5:35:0.5km/h",
                       "--mu", "1", "--max-g", "5", "--summary"],
    "ride --vertical": ["ride", "--vertical", "--diameter", "16ft", "--theta", "0:180:1",
                        "--v-top", "20:40:0.5km/h", "--format", "ndjson"],
}


def _piped(*args):
    return subprocess.run([sys.executable, "-m", "deathsphere", *args], capture_output=True, timeout=300)


@pytest.mark.parametrize("name", LONG)
def test_long_ride_shows_its_bar_on_stderr_only(name):
    args = LONG[name]
    piped = _piped(*args)
    assert piped.returncode == 0 and piped.stderr == b""  # no bar into a pipe
    proc, seen = _with_stderr_on_a_terminal(*args, delay=0)
    assert proc.returncode == 0
    assert proc.stdout == piped.stdout  # the bar never reaches the data
    assert b"ride" in seen and b"\xe2\x94\x81" in seen  # the label and the bar's line, on the terminal


def test_map_figure_with_stability_shows_a_bar_while_the_curves_are_found(tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "map.png"
    proc, seen = _with_stderr_on_a_terminal("map", "--stability", "-a", "0.9", "-r", "3",
                                            "--output", str(out), delay=0)
    assert proc.returncode == 0 and proc.stdout == b"" and out.stat().st_size > 0
    assert b"map" in seen and b"0:00:0" in seen  # the label and the time elapsed
    assert f"deathsphere: wrote {out}".encode() in seen


@pytest.mark.parametrize("args", [
    ["sweep", "--theta", "10:170:40", "--alpha", "5:25:10"],
    ["ride", "--theta", "90", "--speed", "20:40:10km/h", "--diameter", "16ft"],
    ["ride", "--height", "1:2:0.5", "--speed", "20:40:10km/h", "--diameter", "16ft", "--summary"],
    ["ride", "--vertical", "--theta", "90", "--v-top", "20:40:5km/h", "--diameter", "16ft"],
    ["ride", "--machine", "benchmark-bicycle", "--flat", "--speed", "0:10:1"],
])
def test_a_table_written_to_a_file_is_named_with_its_rows(args, tmp_path, run):
    out = tmp_path / "out.csv"
    res = run(*args, "--output", str(out))
    assert res.exit_code == 0 and res.stdout == ""
    with open(out, newline="") as f:
        rows = len(list(csv.DictReader(f)))
    assert res.stderr == f"deathsphere: wrote {out} ({rows} rows)\n"


def test_one_row_is_a_row(tmp_path, run):
    out = tmp_path / "one.csv"
    res = run("sweep", "--theta", "60", "--alpha", "10", "--output", os.fspath(out))
    assert res.stderr == f"deathsphere: wrote {out} (1 row)\n"
