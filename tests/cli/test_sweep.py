import csv
import io
import json
import subprocess
import sys

from deathsphere.model import COLUMNS


def test_sweep_streams_the_whole_grid_in_order(run):
    res = run("sweep", "--theta", "10:170:40", "--alpha", "5:25:10", "--chunk-size", "4")
    out = list(csv.DictReader(io.StringIO(res.stdout)))
    assert res.exit_code == 0 and len(out) == 5 * 3
    assert [int(r["input_row"]) for r in out] == list(range(1, 16))
    assert res.stdout.count("input_row") == 1  # one header across chunks


def test_sweep_only_filter_and_parameters(run):
    res = run("sweep", "--theta", "30:150:10", "--alpha", "5:45:5", "-a", "0.1", "-a", "0.3", "--only", "ok",
              "--format", "ndjson")
    out = [json.loads(line) for line in res.stdout.splitlines()]
    assert out and all(r["status"] == "ok" for r in out)
    assert {r["a_m"] for r in out} == {0.1, 0.3}
    assert list(out[0]) == list(COLUMNS)


def test_sweep_only_filter_that_keeps_nothing_still_has_a_header(run):
    res = run("sweep", "--theta", "0", "--alpha", "10", "--only", "ok")
    assert res.stdout.strip() == ",".join(COLUMNS)


def test_sweep_bad_parameter_is_a_usage_error(run):
    res = run("sweep", "--theta", "60", "--alpha", "10", "-a", "0.1", "-a", "-2")
    assert res.exit_code == 2 and "a (body radius)" in res.stderr


def test_sweep_into_head_ends_quietly():
    proc = subprocess.run(
        f"{sys.executable} -m deathsphere sweep --theta 0:180:0.05 --alpha 0:90:0.05 | head -3",
        shell=True, capture_output=True, text=True, timeout=60)
    assert len(proc.stdout.splitlines()) == 3
    assert "Traceback" not in proc.stderr and "Error" not in proc.stderr


def _with_stderr_on_a_terminal(*args, delay=None):
    """Run the command with stderr on a pseudo-terminal; (process, what the terminal saw).

    ``delay``: the progress bar's delay for this run (DEATHSPHERE_PROGRESS_DELAY;
    0 draws the bar of any work at once, so a test need not run seconds of it).

    The terminal is read while the command runs, as a terminal would: a
    pseudo-terminal holds a few kB, and a progress bar that redraws for
    longer than that (a slow, shared machine) would otherwise block on it."""
    import os
    import pty
    import threading

    leader, follower = pty.openpty()
    chunks = []

    def read():
        while True:
            try:
                data = os.read(leader, 65536)
            except OSError:
                return
            if not data:
                return
            chunks.append(data)

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    try:
        proc = subprocess.run([sys.executable, "-m", "deathsphere", *args], stdout=subprocess.PIPE, stderr=follower,
                              timeout=300,
                              env={**os.environ, "COLUMNS": "80",
                                   **({} if delay is None else {"DEATHSPHERE_PROGRESS_DELAY": str(delay)})})
        os.close(follower)
        reader.join(timeout=10)
    finally:
        os.close(leader)
    return proc, b"".join(chunks)


def test_progress_bar_on_a_terminal_never_swallows_stdout():
    """With stderr a terminal the progress bar of a sweep in several chunks
    shows there (drawn at once: no delay), and every CSV row still goes to
    stdout (rich's Live must not redirect stdout)."""
    # 65 k orbits: four chunks of the sweep
    proc, seen = _with_stderr_on_a_terminal("sweep", "--theta", "0:180:0.5", "--alpha", "0:90:0.5", delay=0)
    lines = proc.stdout.decode().splitlines()
    assert proc.returncode == 0 and len(lines) == 1 + 361 * 181
    assert b"input_row" not in seen and b"sweep" in seen  # the bar, not the data, on the terminal


def test_work_under_a_second_draws_no_bar():
    """A single orbit, or a small sweep, leaves the terminal alone: no bar
    flashes up (and none can leave residue in the output)."""
    for args in (["orbit", "--theta", "60", "--alpha", "10"], ["sweep", "--theta", "0:180:10", "--alpha", "10"]):
        proc, seen = _with_stderr_on_a_terminal(*args)
        assert proc.returncode == 0 and proc.stdout and seen == b"", args
