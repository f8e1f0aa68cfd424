"""``ride`` streams as ``sweep`` does: --output FILE, --jobs, --scheduler and
a progress bar (deathsphere.api.ride_streams)."""

import csv
import io
import json

import numpy as np
import pytest

import deathsphere
from deathsphere.table import Table

GRID = ("--theta", "0:180:2", "--alpha", "-90:90:2", "--no-stability")


@pytest.mark.parametrize("ext", ["csv", "json", "ndjson"])
def test_ride_output_file_holds_what_stdout_would(run, tmp_path, ext):
    target = tmp_path / f"ride.{ext}"
    to_file = run("ride", *GRID, "--output", str(target))
    to_stdout = run("ride", *GRID, "--format", ext)
    assert to_file.exit_code == 0 and to_file.stdout == ""
    assert target.read_text(encoding="utf-8") == to_stdout.stdout
    assert [p.name for p in tmp_path.iterdir()] == [target.name]


def test_ride_parquet_has_the_rows_of_the_csv(run, tmp_path):
    pq = pytest.importorskip("pyarrow.parquet")
    target = tmp_path / "ride.parquet"
    assert run("ride", "--theta", "60:90:10", "--speed", "30:50:10km/h", "--output", str(target)).exit_code == 0
    rows = list(csv.DictReader(io.StringIO(run("ride", "--theta", "60:90:10", "--speed", "30:50:10km/h",
                                               "--format", "csv").stdout)))
    table = pq.read_table(target).to_pylist()
    assert [r["input_row"] for r in table] == [int(r["input_row"]) for r in rows]
    assert [r["alpha_deg"] for r in table] == [float(r["alpha_deg"]) for r in rows]


def test_parquet_needs_a_file(run):
    res = run("ride", "--theta", "60", "--alpha", "10", "--format", "parquet")
    assert res.exit_code == 2 and "--output" in res.stderr


def test_ride_jobs_give_the_same_bytes(run, tmp_path):
    # 181 x 181 points: two chunks of the stream, evaluated on two processes
    grid = ("--theta", "0:180:1", "--alpha", "-90:90:1", "--no-stability")
    one, two = tmp_path / "one.csv", tmp_path / "two.csv"
    assert run("ride", *grid, "--output", str(one)).exit_code == 0
    assert run("ride", *grid, "--jobs", "2", "--output", str(two)).exit_code == 0
    assert one.read_bytes() == two.read_bytes() and len(one.read_bytes().splitlines()) == 1 + 181 * 181


def test_jobs_and_scheduler_together_are_refused(run):
    res = run("ride", "--theta", "60", "--alpha", "10", "--jobs", "2", "--scheduler", "tcp://127.0.0.1:1")
    assert res.exit_code == 2 and "--scheduler" in res.stderr


@pytest.mark.parametrize("how", [{"alpha": np.arange(-30.0, 31.0, 7.5)}, {"speed": np.arange(5.0, 20.0, 2.5)}])
def test_ride_sweep_in_chunks_is_one_ride_call(how):
    theta = np.arange(40.0, 141.0, 20.0)
    name, values = next(iter(how.items()))
    whole = deathsphere.ride(theta[:, None], machine="stunt125", **{name: values[None, :]})
    for chunk_size in (1, 7, 1000):
        parts = Table.concat(list(deathsphere.ride_sweep(theta, machine="stunt125", chunk_size=chunk_size,
                                                         **{name: values})))
        assert parts.to_csv() == whole.to_csv()


def test_ride_sweep_checks_every_value_before_any_chunk():
    with pytest.raises(deathsphere.ParameterError, match="height"):
        deathsphere.ride_sweep(height=[1.0, 2.0, 9.0], alpha=10, machine="stunt125", r=3.0)


def test_ride_draws_a_progress_bar_on_a_terminal(run, monkeypatch, tmp_path):
    from rich.console import Console

    import deathsphere.cli.base as base

    screen = io.StringIO()
    monkeypatch.setattr(base, "_isatty", lambda stream: True)
    monkeypatch.setattr(base, "PROGRESS_DELAY_S", 0.0)
    monkeypatch.setattr(base, "stderr_console", lambda: Console(file=screen, force_terminal=True, width=80))
    target = tmp_path / "ride.json"
    res = run("ride", *GRID, "--output", str(target))
    assert res.exit_code == 0 and len(json.loads(target.read_text())) == 91 * 91
    assert "ride" in screen.getvalue() and "8281/8281" in screen.getvalue()
