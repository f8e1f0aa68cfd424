"""The Python API gives what the command line prints: every function against
its command's ``--format csv`` output (run in-process), the Table's
protocols, and the one exception type with the command line's message."""

import csv
import io
import math
import sys

import numpy as np
import pytest
from click.testing import CliRunner

import deathsphere
from deathsphere import ParameterError, Setup, Table
from deathsphere.cli import cli
from deathsphere.model import COLUMNS
from deathsphere.writers.stream import write_csv


def cli_csv(*args, code=0):
    """stdout of ``deathsphere ARGS --format csv``, checking the exit status."""
    result = CliRunner().invoke(cli, [*args, "--format", "csv"], catch_exceptions=False)
    assert result.exit_code == code, result.stderr
    return result.stdout


def cli_error(*args):
    """The message of a usage error, as the API should raise it: the line
    after ``deathsphere: error:`` without click's ``Invalid value for
    '--x':`` and the ``(see '... --help')`` hint."""
    result = CliRunner().invoke(cli, list(args), catch_exceptions=False)
    assert result.exit_code == 2, result.stdout
    line = result.stderr.strip()
    assert line.count("\n") == 0 and line.startswith("deathsphere: error: ")
    line = line.removeprefix("deathsphere: error: ")
    if line.startswith("Invalid value for "):
        line = line.split(": ", 1)[1]
    return line.rsplit(" (see '", 1)[0]


def assert_same_csv(api_text, cli_text):
    """Cell for cell (a readable failure), then byte for byte."""
    api_rows, cli_rows = (list(csv.reader(io.StringIO(t))) for t in (api_text, cli_text))
    assert api_rows[0] == cli_rows[0]
    assert len(api_rows) == len(cli_rows)
    for i, (a, c) in enumerate(zip(api_rows[1:], cli_rows[1:]), start=1):
        assert dict(zip(api_rows[0], a)) == dict(zip(cli_rows[0], c)), f"row {i}"
    assert api_text == cli_text


def joined_csv(tables):
    out = io.StringIO()
    write_csv(tables, out)
    return out.getvalue()


# ---------------------------------------------------------------------------
# orbit: every body and side equals the command line


ORBIT_CASES = [
    # (api call, CLI arguments)
    (lambda: deathsphere.orbit([[30], [60], [90]], [5, 10, 25]),
     ["orbit", "--theta", "30:90:30", "--alpha", "5", "--alpha", "10", "--alpha", "25"]),
    (lambda: deathsphere.orbit([[30], [150]], [80, 60, 205], side="outside", mu=2),
     ["orbit", "--side", "outside", "--theta", "30", "--theta", "150", "--alpha", "80", "--alpha", "60",
      "--alpha", "205", "--mu", "2"]),
    (lambda: deathsphere.orbit([[45], [60]], 10, a=0.1, r=2.5, k=0.3, g=9.81, mu=1.2),
     ["orbit", "--theta", "45", "--theta", "60", "--alpha", "10", "-a", "0.1", "-r", "2.5", "-k", "0.3",
      "-g", "9.81", "--mu", "1.2"]),
    (lambda: deathsphere.orbit(60, speed=[7, 9]),
     ["orbit", "--theta", "60", "--speed", "7", "--speed", "9"]),
    (lambda: deathsphere.orbit([60, 90], omega=4),
     ["orbit", "--theta", "60", "--theta", "90", "--omega", "4"]),
    (lambda: deathsphere.orbit([[60], [120]], body="sphere", omega3=[40, 80]),
     ["orbit", "--body", "sphere", "--theta", "60", "--theta", "120", "--omega3", "40", "--omega3", "80"]),
    (lambda: deathsphere.orbit([[30], [150]], body="sphere", side="outside", omega3=200),
     ["orbit", "--body", "sphere", "--side", "outside", "--theta", "30", "--theta", "150", "--omega3", "200"]),
    (lambda: deathsphere.orbit([[60], [120]], body="sphere", omega=[5, -5]),
     ["orbit", "--body", "sphere", "--theta", "60", "--theta", "120", "--omega", "5", "--omega", "-5"]),
    (lambda: deathsphere.orbit([[60], [120]], body="sphere", side="outside", omega=[5, -5], k=0.7),
     ["orbit", "--body", "sphere", "--side", "outside", "--theta", "60", "--theta", "120", "--omega", "5",
      "--omega", "-5", "-k", "0.7"]),
    (lambda: deathsphere.orbit(np.arange(100, 171, 10), body="particle"),
     ["orbit", "--body", "particle", "--theta", "100:170:10"]),
    (lambda: deathsphere.orbit([30, 100], body="particle", side="outside", mu=0.5),
     ["orbit", "--body", "particle", "--side", "outside", "--theta", "30", "--theta", "100", "--mu", "0.5"]),
    (lambda: deathsphere.orbit([[60], [90]], [10, 80], stability=False),
     ["orbit", "--theta", "60", "--theta", "90", "--alpha", "10", "--alpha", "80", "--no-stability"]),
]


@pytest.mark.parametrize("call, args", ORBIT_CASES, ids=[" ".join(a[1:4]) + f" #{i}" for i, (_, a) in
                                                        enumerate(ORBIT_CASES)])
def test_orbit_equals_the_command_line(call, args):
    table = call()
    assert table.names == list(COLUMNS)
    assert_same_csv(table.to_csv(), cli_csv(*args))


def test_broadcast_shape_is_kept():
    theta = np.linspace(30, 150, 5)[:, None]
    table = deathsphere.orbit(theta, [10.0, 25.0], stability=False)
    assert table.shape == (5, 2) and len(table) == 10
    assert table.grid("theta_deg").tolist() == np.broadcast_to(theta, (5, 2)).tolist()
    assert table.grid("alpha_deg")[:, 1].tolist() == [25.0] * 5
    one = deathsphere.orbit(theta[3, 0], 25.0, stability=False)
    assert table.grid("v_cm_m_s")[3, 1] == one["v_cm_m_s"]
    assert one.shape == () and len(one) == 1
    assert deathsphere.orbit(np.full((2, 3, 4), 60.0), 10, stability=False).shape == (2, 3, 4)


def test_several_answers_give_a_flat_table_numbered_by_flat_index():
    spun = deathsphere.orbit([[60], [120]], body="sphere", omega3=[40, 80], stability=False)
    assert spun.shape == (len(spun),) == (8,)
    assert spun["input_row"].tolist() == [1, 1, 2, 2, 3, 3, 4, 4]
    assert spun["branch"].tolist() == [0, 1] * 4
    solved = deathsphere.orbit([60, 90], speed=7, stability=False)
    assert solved.shape == (len(solved),) and set(solved["input_row"].tolist()) == {1, 2}


def test_an_element_breaking_a_combination_is_an_invalid_row_like_a_sweep():
    table = deathsphere.orbit(60, 10, a=[0.3, 4.0], stability=False)
    assert table["status"].tolist()[0] == "ok" and table["status"][1] == "invalid"
    cli = list(csv.DictReader(io.StringIO(
        cli_csv("sweep", "--theta", "60", "--alpha", "10", "-a", "0.3", "-a", "4", "--no-stability", code=1))))
    assert table["reason"][1] == cli[1]["reason"]


def test_a_call_with_no_computable_row_raises():
    with pytest.raises(ParameterError, match=r"r \(sphere radius\) must be > a"):
        deathsphere.orbit([60, 90], 10, a=[4.0, 5.0])
    with pytest.raises(ParameterError, match="a wheel needs exactly one of alpha"):
        deathsphere.orbit(60)
    with pytest.raises(ParameterError, match="a particle takes only theta"):
        deathsphere.orbit(120, 10, body="particle")
    with pytest.raises(ParameterError, match="broadcast"):
        deathsphere.orbit([60, 70, 80], [10, 20])


# ---------------------------------------------------------------------------
# the other commands


@pytest.mark.parametrize("call, args", [
    (lambda: deathsphere.vertical([[60], [90]], [4, 6]),
     ["vertical", "--theta", "60", "--theta", "90", "--v-top", "4", "--v-top", "6"]),
    (lambda: deathsphere.vertical(90, phidot_top=[1, 2], mu=1.5, k=0.4),
     ["vertical", "--theta", "90", "--phidot-top", "1", "--phidot-top", "2", "--mu", "1.5", "-k", "0.4"]),
    (lambda: deathsphere.vertical(90, [0, 3], side="outside"),
     ["vertical", "--side", "outside", "--theta", "90", "--v-top", "0", "--v-top", "3"]),
    (lambda: deathsphere.vertical([60, 90], 6, points=13),
     ["vertical", "--theta", "60", "--theta", "90", "--v-top", "6", "--points", "13"]),
])
def test_vertical_equals_the_command_line(call, args):
    assert_same_csv(call().to_csv(), cli_csv(*args))


def test_vertical_shapes():
    assert deathsphere.vertical([[60], [90]], [4, 6, 8], stability=False).shape == (2, 3)
    points = deathsphere.vertical([60, 90], 6, points=13)
    assert points.shape == (2, 13)
    assert points.grid("theta_deg")[1].tolist() == [90.0] * 13


@pytest.mark.parametrize("call, args", [
    (lambda: deathsphere.limits([60, 90], mu=1.2), ["limits", "--theta", "60", "--theta", "90", "--mu", "1.2"]),
    (lambda: deathsphere.limits(np.array([30.0, 60.0]), side="outside", a=0.5),
     ["limits", "--side", "outside", "-a", "0.5", "--theta", "30", "--theta", "60"]),
    (lambda: deathsphere.limits(mu=1, max_g=5), ["limits", "--mu", "1", "--max-g", "5"]),
    (lambda: deathsphere.region(step=5), ["map", "--step", "5"]),
    (lambda: deathsphere.region(0.9, side="outside", mu=1, max_g=4, k=0.4, step=2.5),
     ["map", "-a", "0.9", "--side", "outside", "--mu", "1", "--max-g", "4", "-k", "0.4", "--step", "2.5"]),
    (lambda: deathsphere.stability(90, 45), ["stability", "--theta", "90", "--alpha", "45"]),
    (lambda: deathsphere.stability(60, 10, a=0.03, mu=2), ["stability", "--theta", "60", "--alpha", "10",
                                                          "-a", "0.03", "--mu", "2"]),
    (lambda: deathsphere.stability(30, 80, side="outside"),
     ["stability", "--side", "outside", "--theta", "30", "--alpha", "80"]),
    (lambda: deathsphere.table1(), ["table1"]),
    (lambda: deathsphere.verify(["T1-v", "E28"]), ["verify", "--claim", "T1-v", "--claim", "E28"]),
])
def test_table_commands_equal_the_command_line(call, args):
    assert_same_csv(call().to_csv(), cli_csv(*args))


def test_region_with_the_stability_curve():
    table = deathsphere.region(0.9, step=10, stability=True)
    assert "stability" in set(table["curve"])
    assert_same_csv(table.to_csv(), cli_csv("map", "-a", "0.9", "--step", "10", "--stability"))


def test_sweep_chunks_come_in_order_and_join_to_the_command_line():
    chunks = deathsphere.sweep("30:90:15", [5, 15, 25], a=[0.3, 0.6], chunk_size=4)
    assert not isinstance(chunks, Table)
    tables = list(chunks)
    assert [len(t) for t in tables] == [4, 4, 4, 4, 4, 4, 4, 2]
    assert np.concatenate([t["input_row"] for t in tables]).tolist() == list(range(1, 31))
    assert_same_csv(joined_csv(tables), cli_csv("sweep", "--theta", "30:90:15", "--alpha", "5", "--alpha", "15",
                                                 "--alpha", "25", "-a", "0.3", "-a", "0.6", "--chunk-size", "4"))


def test_sweep_of_a_sphere_with_invalid_combinations_and_only():
    tables = list(deathsphere.sweep([60, 120], body="sphere", omega3="40:80:40", r=[3.0, 0.2],
                                    only=["ok", "invalid"], stability=False))
    cli = cli_csv("sweep", "--body", "sphere", "--theta", "60", "--theta", "120", "--omega3", "40:80:40",
                  "-r", "3", "-r", "0.2", "--only", "ok", "--only", "invalid", "--no-stability", code=1)
    assert_same_csv(joined_csv(tables), cli)
    assert "invalid" in set(np.concatenate([t["status"] for t in tables]))


def test_sweep_refuses_bad_input_at_the_call_not_at_the_first_chunk():
    with pytest.raises(ParameterError) as err:
        deathsphere.sweep("5:200:5", 10)
    assert str(err.value) == cli_error("sweep", "--theta", "5:200:5", "--alpha", "10")
    with pytest.raises(ParameterError, match="a sphere needs exactly one of omega3"):
        deathsphere.sweep(60, body="sphere")
    with pytest.raises(ParameterError, match="only must be one of"):
        deathsphere.sweep(60, 10, only="fine")


def test_simulate_equals_the_command_line():
    args = ["simulate", "--theta", "60", "--alpha", "10", "--perturb", "0.01", "--periods", "0.5",
            "--points-per-period", "10"]
    series, summary = deathsphere.simulate(60, 10, perturb=0.01, periods=0.5, points_per_period=10)
    assert_same_csv(series.to_csv(), cli_csv(*args))
    cli = next(csv.DictReader(io.StringIO(cli_csv(*args, "--summary-only"))))
    api = next(csv.DictReader(io.StringIO(summary.to_csv())))
    assert api.pop("wall_time_s") and cli.pop("wall_time_s")  # the one column that is not reproducible
    assert api == cli


def test_simulate_a_sphere_and_a_vertical_orbit():
    args = ["simulate", "--body", "sphere", "--theta", "60", "--omega3", "80", "--branch", "1",
            "--periods", "0.3", "--points-per-period", "10"]
    series, _ = deathsphere.simulate(60, body="sphere", omega3=80, branch=1, periods=0.3, points_per_period=10)
    assert_same_csv(series.to_csv(), cli_csv(*args))
    series, summary = deathsphere.simulate(90, vertical=True, v_top=6, periods=0.2, points_per_period=10)
    assert_same_csv(series.to_csv(), cli_csv("simulate", "--vertical", "--theta", "90", "--v-top", "6",
                                             "--periods", "0.2", "--points-per-period", "10"))
    assert summary["orbit"][0] == "vertical"


# ---------------------------------------------------------------------------
# bad input: one exception type, the command line's message


@pytest.mark.parametrize("call, args", [
    (lambda: deathsphere.orbit(200, 10), ["orbit", "--theta", "200", "--alpha", "10"]),
    (lambda: deathsphere.orbit([60, 200], 10), ["orbit", "--theta", "60", "--theta", "200", "--alpha", "10"]),
    (lambda: deathsphere.orbit(60, 2e6), ["orbit", "--theta", "60", "--alpha", "2e6"]),
    (lambda: deathsphere.orbit(60, 10, a=0), ["orbit", "--theta", "60", "--alpha", "10", "-a", "0"]),
    (lambda: deathsphere.orbit(60, 10, r=[3, -1]), ["orbit", "--theta", "60", "--alpha", "10", "-r", "-1"]),
    (lambda: deathsphere.orbit(60, 10, k=2000), ["orbit", "--theta", "60", "--alpha", "10", "-k", "2000"]),
    (lambda: deathsphere.orbit(60, 10, g=0), ["orbit", "--theta", "60", "--alpha", "10", "-g", "0"]),
    (lambda: deathsphere.orbit(60, 10, mu=-1), ["orbit", "--theta", "60", "--alpha", "10", "--mu", "-1"]),
    (lambda: deathsphere.orbit(60, 10, a=4), ["orbit", "--theta", "60", "--alpha", "10", "-a", "4"]),
    (lambda: deathsphere.orbit(60, body="sphere", omega=0), ["orbit", "--body", "sphere", "--theta", "60",
                                                            "--omega", "0"]),
    (lambda: deathsphere.orbit(60, speed=0), ["orbit", "--theta", "60", "--speed", "0"]),
    (lambda: deathsphere.orbit(60, body="sphere", omega3=2e9), ["orbit", "--body", "sphere", "--theta", "60",
                                                               "--omega3", "2e9"]),
    (lambda: deathsphere.vertical(90, -1), ["vertical", "--theta", "90", "--v-top", "-1"]),
    (lambda: deathsphere.vertical(90, 6, points=1), ["vertical", "--theta", "90", "--v-top", "6", "--points", "1"]),
    (lambda: deathsphere.region(step=20), ["map", "--step", "20", "--format", "csv"]),
    (lambda: deathsphere.region(k=-1), ["map", "-k", "-1", "--format", "csv"]),
    (lambda: deathsphere.limits(mu=1, max_g=0), ["limits", "--mu", "1", "--max-g", "0"]),
    (lambda: deathsphere.limits(60, r=0.1), ["limits", "--theta", "60", "-r", "0.1"]),
    (lambda: deathsphere.stability(90, 45, k=-0.5), ["stability", "--theta", "90", "--alpha", "45", "-k", "-0.5"]),
    (lambda: deathsphere.simulate(60, 10, periods=0), ["simulate", "--theta", "60", "--alpha", "10",
                                                       "--periods", "0"]),
    (lambda: deathsphere.simulate(60, 10, perturb=90), ["simulate", "--theta", "60", "--alpha", "10",
                                                        "--perturb", "90"]),
    (lambda: deathsphere.simulate(60, 10, rtol=1), ["simulate", "--theta", "60", "--alpha", "10", "--rtol", "1"]),
    (lambda: deathsphere.region(a=3.3), ["map", "-a", "3.3", "--format", "csv"]),
    (lambda: deathsphere.sweep(60, 10, a=4), ["sweep", "--theta", "60", "--alpha", "10", "-a", "4"]),
    (lambda: deathsphere.limits("1:2:0"), ["limits", "--theta", "1:2:0"]),
    (lambda: deathsphere.simulate(60, 10, points_per_period=1.5),
     ["simulate", "--theta", "60", "--alpha", "10", "--points-per-period", "1.5"]),
    (lambda: deathsphere.simulate(60, 10, k=0), ["simulate", "--theta", "60", "--alpha", "10", "-k", "0"]),
    (lambda: deathsphere.verify("nope"), ["verify", "--claim", "nope"]),
])
def test_bad_input_raises_the_command_lines_message(call, args):
    with pytest.raises(ParameterError) as err:
        call()
    message = str(err.value)
    assert "\n" not in message
    expected = cli_error(*args)
    # the command line names its options (--k); the API its parameters (k)
    assert message == expected.replace("-k > 0", "k > 0")


def test_parameter_error_is_a_value_error_and_choices_say_what_is_allowed():
    assert issubclass(ParameterError, ValueError)
    with pytest.raises(ParameterError, match=r"body must be one of wheel \| sphere \| particle \(got 'bike'\)"):
        deathsphere.orbit(60, 10, body="bike")
    with pytest.raises(ParameterError, match="side must be one of"):
        deathsphere.vertical(90, 6, side="above")
    with pytest.raises(ParameterError, match=r"theta \(polar angle\) must be a finite number"):
        deathsphere.orbit([60, math.nan], 10)
    with pytest.raises(ParameterError, match="theta must be a number"):
        deathsphere.orbit("sixty", 10)
    with pytest.raises(ParameterError, match="r \\(sphere radius\\) must be > a = 3.3 m"):
        deathsphere.region(3.3)
    with pytest.raises(ParameterError, match="method must be one of"):
        deathsphere.simulate(60, 10, method="euler", periods=0.1)
    with pytest.raises(ParameterError, match="a wheel's steady orbit needs alpha"):
        deathsphere.simulate(60, periods=0.1)


# ---------------------------------------------------------------------------
# Table


@pytest.fixture
def table():
    return deathsphere.orbit([[60], [90]], [10, 80], stability=False)


def test_table_rows(table):
    rows = list(table)
    assert len(rows) == len(table) == 4
    assert all(isinstance(r, dict) and list(r) == list(COLUMNS) for r in rows)
    assert rows[0]["v_cm_m_s"] == table["v_cm_m_s"][0] and isinstance(rows[0]["v_cm_m_s"], float)
    assert table[0] == rows[0] and table[-1] == rows[-1] and table[np.int64(2)] == rows[2]
    with pytest.raises(IndexError):
        table[4]
    assert isinstance(table["status"], np.ndarray)
    with pytest.raises(KeyError):
        table["no_such_column"]


def test_to_dicts_turns_nan_into_none(table):
    dicts = table.to_dicts()
    assert dicts == list(table) == table.records()
    assert dicts[0]["mu_available"] is None and dicts[0]["stability"] is None  # --no-stability: undefined
    blank = [i for i, s in enumerate(table["status"]) if s in ("no_fit", "no_orbit")]
    assert blank and dicts[blank[0]]["mu_required"] is None
    assert math.isnan(table["mu_required"][blank[0]])


def test_row_selection_gives_flat_tables(table):
    part = table[1:3]
    assert isinstance(part, Table) and len(part) == 2 and part.shape == (2,)
    ok = table[table["status"] == "ok"]
    assert set(ok["status"]) == {"ok"}


def test_to_csv_writes_the_command_lines_bytes(table, tmp_path):
    cli = cli_csv("orbit", "--theta", "60", "--theta", "90", "--alpha", "10", "--alpha", "80", "--no-stability")
    assert table.to_csv() == cli
    path = tmp_path / "out.csv"
    assert table.to_csv(path) is None
    assert path.read_bytes() == cli.encode()
    buf = io.StringIO()
    table.to_csv(buf)
    assert buf.getvalue() == cli


def test_repr_shows_the_columns_and_the_first_rows(table):
    text = repr(table)
    from deathsphere.model import COLUMNS

    assert text.startswith(f"Table: 4 rows x {len(COLUMNS)} columns, shape (2, 2)")
    assert "v_cm_m_s" in text and "reason" in text and f"{table['v_cm_m_s'][0]:.6g}" in text
    narrow = Table({"x": np.arange(8.0), "s": np.array(list("abcdefgh"), dtype=object)})
    lines = repr(narrow).splitlines()
    assert lines[1].split() == ["x", "s"] and lines[2].split() == ["0", "a"]
    assert lines[-1] == "... (3 more rows)"
    html = table._repr_html_()
    assert html.count("<tr>") == 5 and "<th>v_cm_m_s</th>" in html


def test_to_pandas_hands_every_column_in_order(table):
    import pandas as pd  # the test extra installs it (pyproject.toml)
    frame = table.to_pandas()
    assert isinstance(frame, pd.DataFrame) and list(frame.columns) == list(COLUMNS) and len(frame) == 4
    assert frame["v_cm_m_s"].tolist() == pytest.approx(table["v_cm_m_s"].tolist(), nan_ok=True)
    assert frame["v_cm_m_s"].dtype == np.float64 and frame["input_row"].dtype == np.int64


def test_to_pandas_without_pandas_says_how_to_install_it(table, monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)   # import pandas -> ImportError
    with pytest.raises(ImportError, match=r"^Table\.to_pandas\(\) needs pandas: pip install 'deathsphere\[dataframes\]'$"):
        table.to_pandas()


# ---------------------------------------------------------------------------
# the older entry points, and the names shared with modules


def test_setup_orbit_keeps_the_shape_and_takes_every_body():
    grid = Setup().orbit(np.arange(30, 91, 15.0)[:, None], np.array([5.0, 10.0])[None, :])
    assert grid.shape == (5, 2)
    particle = Setup(body="particle").orbit([120.0, 150.0])
    assert particle["status"].tolist() == ["ok", "ok"]
    sphere = Setup(body="sphere").orbit(60, omega3=80)
    assert sphere["branch"].tolist() == [0, 1]
    assert sphere.to_csv() == deathsphere.orbit(60, body="sphere", omega3=80).to_csv()


def test_command_names_are_the_api_functions():
    """deathsphere.vertical etc. are the functions; the code behind them lives
    in deathsphere.results, so no name means two things."""
    from deathsphere.results import verify

    assert verify.CLAIMS and callable(verify.run)
    for name in ("vertical", "limits", "table1", "verify"):
        assert getattr(deathsphere, name) is getattr(deathsphere.api, name)
    assert deathsphere.verify("T1-v")["verdict"].tolist() == ["confirmed"]


def test_everything_is_exported():
    for name in ("orbit", "vertical", "sweep", "region", "limits", "stability", "simulate", "table1", "verify",
                 "Table", "ParameterError", "Setup", "__version__"):
        assert name in deathsphere.__all__ and getattr(deathsphere, name) is not None


def test_the_readme_python_example_runs(tmp_path, monkeypatch):
    import re
    from pathlib import Path

    readme = (Path(__file__).resolve().parents[1] / "README.md").read_text()
    (block,) = re.findall(r"## Python API\n.*?```python\n(.*?)```", readme, flags=re.S)
    monkeypatch.chdir(tmp_path)      # it writes orbits.csv
    exec(compile(block, "README.md", "exec"), {})
    assert (tmp_path / "orbits.csv").read_text().startswith("input_row,body,side,")


# ---------------------------------------------------------------------------
# the streamed forms the command line calls


def test_input_files_stream_the_command_lines_rows(tmp_path):
    path = tmp_path / "requests.csv"
    path.write_text("theta,alpha,mu\n60,10,\n\n90,x,1\n120,80,0.5\n")
    chunks = deathsphere.orbit_input(str(path), mu=2)
    assert chunks.total is None
    table = chunks.table()
    assert chunks.done == 3 and table["input_row"].tolist() == [1, 3, 4]
    assert table["status"][1] == "invalid" and table["mu_available"][0] == 2.0
    assert_same_csv(table.to_csv(), cli_csv("orbit", "--input", str(path), "--mu", "2", code=1))
    loops = tmp_path / "loops.csv"
    loops.write_text("theta,v_top\n90,6\n60,-1\n")
    table = deathsphere.vertical_input(str(loops), stability=False).table()
    assert_same_csv(table.to_csv(), cli_csv("vertical", "--input", str(loops), "--no-stability", code=1))


def test_grids_are_the_command_lines_and_know_their_size():
    chunks = deathsphere.vertical_sweep("60:90:30", [6, 7], stability=False)
    assert chunks.total == 4
    assert_same_csv(chunks.table().to_csv(),
                    cli_csv("vertical", "--theta", "60:90:30", "--v-top", "6", "--v-top", "7", "--no-stability"))
    points = deathsphere.vertical_sweep(90, 6, points=5).table()
    assert_same_csv(points.to_csv(), cli_csv("vertical", "--theta", "90", "--v-top", "6", "--points", "5"))
    speeds = deathsphere.sweep(["60", "70:80:10"], speed=["7", 9], stability=False).table()
    assert_same_csv(speeds.to_csv(), cli_csv("orbit", "--theta", "60", "--theta", "70:80:10", "--speed", "7",
                                             "--speed", "9", "--no-stability"))


def test_more_processes_give_the_same_tables():
    one = deathsphere.sweep("10:170:20", "5:85:20", chunk_size=7).table()
    two = deathsphere.sweep("10:170:20", "5:85:20", chunk_size=7, jobs=2).table()
    assert one.to_csv() == two.to_csv() and len(one) == 45
    assert (deathsphere.region(step=10, stability=True, jobs=2).to_csv()
            == deathsphere.region(step=10, stability=True).to_csv())


def test_the_chunk_size_does_not_change_a_byte():
    """A row's numbers, stability included, do not depend on the rows
    evaluated beside it."""
    whole = deathsphere.sweep("10:170:20", "5:85:20").table()
    assert whole["stability"].tolist().count("stable") > 5
    for size in (1, 2, 7):
        assert deathsphere.sweep("10:170:20", "5:85:20", chunk_size=size).table().to_csv() == whole.to_csv()


def test_inputs_are_echoed_as_given():
    # a quantity the request fixes is printed as typed, not as recomputed
    solved = deathsphere.orbit(60, com_speed=7, stability=False)
    assert len(solved) >= 1 and set(solved["v_cm_m_s"].tolist()) == {7.0}
    solved = deathsphere.orbit(60, speed=7, stability=False)
    assert len(solved) >= 1 and set(solved["v_contact_m_s"].tolist()) == {7.0}
    assert set(deathsphere.orbit(60, omega=4, stability=False)["omega_rad_s"].tolist()) == {4.0}
    assert float(deathsphere.vertical(90, 6, stability=False)["v_cm_m_s"]) == 6.0
    _, summary = deathsphere.simulate(60, 10, perturb=0.5, periods=0.05, points_per_period=10)
    assert (summary["theta_deg"][0], summary["alpha_deg"][0], summary["perturb_deg"][0]) == (60.0, 10.0, 0.5)
    assert float(deathsphere.region(step=10)["a_over_r"][0]) == 0.1


def test_the_map_draws_the_apis_cells():
    from deathsphere.render.charplot import char_map, columns_for_width

    cells = deathsphere.region_cells(a=0.9, columns=columns_for_width(80))
    assert (cells.a, cells.r) == (0.3, 1.0)   # a/r = 0.9 / 3 as the user reads it
    drawn = CliRunner().invoke(cli, ["map", "-a", "0.9", "--format", "table"], env={"COLUMNS": "80"}).stdout
    assert [line.rstrip() for line in str(char_map(cells)).splitlines()] == [
        line.rstrip() for line in drawn.splitlines()]
