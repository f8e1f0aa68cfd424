"""``deathsphere show``: every option, the refusals (one line, exit status
2, before any work), the tables' columns in the documented order, the
example plan's round trip, and the terminal views at 80 and 100 columns."""

import csv
import io
import json
import re

import pytest
from rich.cells import cell_len

from deathsphere.api.shows import EXAMPLE_PLAN, FALL_COLUMNS, PAIR_COLUMNS, RIDER_COLUMNS
from deathsphere.cli.show import parse_fail

ANSI = re.compile(r"\x1b\[[0-9;]*m")

#: The columns the product's requirements name, in their order: the
#: tables start with them (columns are only appended after).
RIDERS_NAMED = ("name", "lane", "theta_deg", "phi0_deg", "alpha_deg", "lean_deg", "v_cm_m_s", "v_cm_km_h",
                "v_contact_m_s", "period_s", "load_g", "mu_required", "head_clearance_m", "status", "reason",
                "speed_low_m_s", "speed_high_m_s", "margin_low_pct", "margin_high_pct", "v_top_m_s",
                "v_top_min_m_s", "v_bottom_m_s", "load_bottom_g")
PAIRS_NAMED = ("rider_a", "rider_b", "min_clearance_m", "t_s", "theta_a_deg", "phi_a_deg", "theta_b_deg",
               "phi_b_deg", "verdict", "drift_time_s")
FALL_NAMED = ("rider", "t_fail_s", "speed_fraction", "outcome", "t_contact_lost_s", "theta_lost_deg",
              "phi_lost_deg", "t_land_s", "theta_land_deg", "phi_land_deg", "fall_time_s", "impact_speed_m_s",
              "victim", "min_clearance_m", "t_min_s", "hit")

#: Two riders a lane apart in height, both leaning: their envelopes meet.
CLOSE = """
[globe]
diameter = "16ft"
mu = 1.2
max_g = 8
min_clearance = "0.15m"
duration = 5

[[rider]]
name = "Low"
machine = "stunt125"
lane = "horizontal"
height = "1.6m"
speed = "30km/h"
direction = "ccw"
phase = 0

[[rider]]
name = "High"
machine = "stunt125"
lane = "horizontal"
height = "2.1m"
speed = "30km/h"
direction = "ccw"
phase = 0
"""


#: A small act (fast to plan): two riders on horizontal lanes, one looper.
SMALL = """
[globe]
diameter = "16ft"
mu = 0.9
max_g = 8
min_clearance = "0.15m"
duration = 4

[[rider]]
name = "Ana"
machine = "stunt125"
lane = "horizontal"
height = "2.4m"
speed = "32km/h"
direction = "ccw"
phase = 0

[[rider]]
name = "Cal"
machine = "stunt125"
lane = "horizontal"
height = "1.2m"
speed = "32km/h"
direction = "cw"
phase = 180

[[rider]]
name = "Ben"
machine = "stunt125"
lane = "vertical"
azimuth = 90
v_top = "6.5m/s"
phase = 180
"""
SMALL_NAMES = ["Ana", "Cal", "Ben"]


@pytest.fixture(scope="module")
def plan_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("show") / "act.toml"
    path.write_text(SMALL, encoding="utf-8")
    return str(path)


def _rows(text):
    return list(csv.reader(io.StringIO(text)))


def _refused(res, *words):
    """One line on stderr, exit status 2, nothing on stdout, the words in it."""
    assert res.exit_code == 2, (res.exit_code, res.stdout, res.stderr)
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1, res.stderr
    assert not res.stdout
    for word in words:
        assert word in lines[0], (word, lines[0])
    return lines[0]


# ---------------------------------------------------------------------------
# the example plan and the tables


def test_example_round_trips(run, tmp_path):
    res = run("show", "--example")
    assert res.exit_code == 0 and res.stdout.strip() == EXAMPLE_PLAN.strip()
    plan = tmp_path / "plan.toml"
    plan.write_text(res.stdout, encoding="utf-8")
    shown = run("show", str(plan))
    assert shown.exit_code == 0, shown.stderr
    rows = _rows(shown.stdout)
    names = re.findall(r'^name = "([^"]+)"', EXAMPLE_PLAN, flags=re.M)
    assert [row[0] for row in rows[1:]] == names


def test_riders_csv_has_the_named_columns_in_order(run, plan_file):
    res = run("show", plan_file, "--table", "riders", "--format", "csv")
    header = _rows(res.stdout)[0]
    assert tuple(header[:len(RIDERS_NAMED)]) == RIDERS_NAMED
    assert tuple(header) == RIDER_COLUMNS


def test_pairs_csv_has_the_named_columns_in_order(run, plan_file):
    res = run("show", plan_file, "--table", "pairs")
    rows = _rows(res.stdout)
    assert tuple(rows[0][:len(PAIRS_NAMED)]) == PAIRS_NAMED and tuple(rows[0]) == PAIR_COLUMNS
    n = len(SMALL_NAMES)
    assert len(rows) - 1 == n * (n - 1) // 2
    verdicts = {row[rows[0].index("verdict")] for row in rows[1:]}
    assert verdicts <= {"clear", "conflict", "collision"}


def test_fail_writes_one_row_per_other_rider(run, plan_file):
    res = run("show", plan_file, "--fail", "Ben@1.2:0.3")
    assert res.exit_code == 0, res.stderr
    rows = _rows(res.stdout)
    assert tuple(rows[0][:len(FALL_NAMED)]) == FALL_NAMED and tuple(rows[0]) == FALL_COLUMNS
    victims = [row[rows[0].index("victim")] for row in rows[1:]]
    assert sorted(victims) == ["Ana", "Cal"]
    assert {row[0] for row in rows[1:]} == {"Ben"}
    assert {float(row[rows[0].index("speed_fraction")]) for row in rows[1:]} == {0.3}


def test_fail_fraction_defaults_to_a_half(run, plan_file):
    res = run("show", plan_file, "--fail", "Ana@2", "--format", "json")
    assert res.exit_code == 0, res.stderr
    records = json.loads(res.stdout)
    assert records and {r["speed_fraction"] for r in records} == {0.5}
    assert {r["t_fail_s"] for r in records} == {2.0}


def test_two_fails_are_both_in_the_table(run, plan_file):
    res = run("show", plan_file, "--fail", "Ana@1:0", "--fail", "Cal@2:0", "--format", "ndjson")
    assert res.exit_code == 0, res.stderr
    riders = [json.loads(line)["rider"] for line in res.stdout.splitlines()]
    assert riders == ["Ana"] * 2 + ["Cal"] * 2


def test_monte_carlo_is_reproducible_by_seed(run, plan_file):
    one = run("show", plan_file, "--monte-carlo", "50", "--seed", "7")
    two = run("show", plan_file, "--monte-carlo", "50", "--seed", "7", "--table", "falls")
    other = run("show", plan_file, "--monte-carlo", "50", "--seed", "8")
    assert one.exit_code == 0, one.stderr
    assert one.stdout == two.stdout and one.stdout != other.stdout
    summary = run("show", plan_file, "--monte-carlo", "50", "--seed", "7", "--table", "summary")
    assert summary.exit_code == 0 and _rows(summary.stdout)[0][0] == "rider"


def test_phase_auto_reports_a_window_and_moves_no_horizontal_rider(run, plan_file):
    auto = run("show", plan_file, "--phase", "auto", "--format", "json")
    assert auto.exit_code == 0, auto.stderr
    phi0 = {r["name"]: r["phi0_deg"] for r in json.loads(auto.stdout)}
    assert (phi0["Ana"], phi0["Cal"]) == (0, 180)      # the plan's phases
    screen = _screen(run, ("show", plan_file, "--phase", "auto", "--table", "pairs"), 100)
    assert "Ben: safe phases" in ANSI.sub("", screen)


def test_duration_bounds_the_act(run, plan_file):
    res = run("show", plan_file, "--table", "pairs", "--duration", "1.5", "--format", "json")
    assert res.exit_code == 0, res.stderr
    timed = [r["t_s"] for r in json.loads(res.stdout) if r["basis"] == "act"]
    assert timed and all(0 <= t <= 1.5 for t in timed)
    screen = _screen(run, ("show", plan_file, "--table", "pairs", "--duration", "1.5"), 100)
    assert "over the act: 1.5 s" in screen


def test_parquet_and_csv_files(run, plan_file, tmp_path):
    pytest.importorskip("pyarrow")
    out = tmp_path / "pairs.parquet"
    res = run("show", plan_file, "--table", "pairs", "--output", str(out))
    assert res.exit_code == 0 and not res.stdout and out.stat().st_size > 0
    import pyarrow.parquet as pq

    assert tuple(pq.read_table(out).column_names) == PAIR_COLUMNS


def test_a_table_to_a_csv_file(run, plan_file, tmp_path):
    text = tmp_path / "riders.csv"
    assert run("show", plan_file, "--output", str(text)).exit_code == 0
    assert _rows(text.read_text())[0][:2] == ["name", "lane"]


def test_html_view_is_written(run, plan_file, tmp_path):
    out = tmp_path / "act.html"
    res = run("show", plan_file, "--fail", "Ben@1.2:0.3", "--output", str(out))
    assert res.exit_code == 0, res.stderr
    assert not res.stdout and "wrote" in res.stderr
    assert "deathsphere-scene/1" in out.read_text(encoding="utf-8")


# ---------------------------------------------------------------------------
# refusals: one line, status 2, before any work


@pytest.mark.parametrize("args, words", [
    ((), ["--example"]),
    (("PLAN", "--example"), ["--example"]),
    (("--example", "--format", "json"), ["--example"]),
    (("--example", "--duration", "3"), ["--example"]),
    (("--example", "--phase", "auto"), ["--example"]),
    (("--example", "--units", "si"), ["--example"]),
    (("--example", "--seed", "1"), ["--example"]),
    (("PLAN", "--fail", "Ana@1", "--monte-carlo", "10"), ["--fail", "--monte-carlo"]),
    (("PLAN", "--fail", "Ana"), ["NAME@T[:FRACTION]"]),
    (("PLAN", "--fail", "Ana@soon"), ["number"]),
    (("PLAN", "--table", "falls"), ["--fail"]),
    (("PLAN", "--table", "summary"), ["--monte-carlo"]),
    (("PLAN", "--seed", "3"), ["--monte-carlo"]),
    (("PLAN", "--scheduler", "tcp://127.0.0.1:8786"), ["--monte-carlo"]),
    (("PLAN", "--format", "parquet"), ["--output"]),
    (("PLAN", "--output", "act.html", "--table", "pairs"), ["--table"]),
    (("PLAN", "--output", "act.html", "--format", "csv"), ["--format"]),
    (("PLAN", "--output", "pairs.csv", "--format", "json"), ["--format"]),
    (("PLAN", "--output", "act.png"), [".html"]),
    (("PLAN", "--monte-carlo", "0"), ["--monte-carlo"]),
    (("PLAN", "--phase", "later"), ["--phase"]),
])
def test_usage_refused(run, plan_file, tmp_path, monkeypatch, args, words):
    monkeypatch.chdir(tmp_path)
    args = tuple(plan_file if a == "PLAN" else a for a in args)
    _refused(run("show", *args), *words)


BAD_PLANS = [
    ('name = "Ana"', 'name = "Ana"\ncolour = "red"', ["Ana", "colour"]),
    (r'machine = "stunt125"', 'machine = "unicycle"', ["Ana", "machine"]),
    (r'height = "[^"]+"', 'height = "6m"', ["Ana", "height"]),
    (r'v_top = "[^"]+"', 'v_top = "0.5m/s"', ["Ben", "v_top"]),
    ('name = "Cal"', 'name = "Ana"', ["Ana", "name"]),
]


@pytest.mark.parametrize("old, new, words", BAD_PLANS, ids=["key", "machine", "outside", "loop", "duplicate"])
def test_bad_plan_is_one_line_naming_rider_and_key(run, tmp_path, old, new, words):
    bad = re.sub(old, new, EXAMPLE_PLAN, count=1)
    assert bad != EXAMPLE_PLAN
    plan = tmp_path / "bad.toml"
    plan.write_text(bad, encoding="utf-8")
    _refused(run("show", str(plan)), *words)


def test_a_plan_without_riders_is_refused(run, tmp_path):
    plan = tmp_path / "empty.toml"
    plan.write_text(EXAMPLE_PLAN.split("[[rider]]")[0], encoding="utf-8")
    _refused(run("show", str(plan)), "rider")


def test_a_missing_plan_file_is_refused(run, tmp_path):
    _refused(run("show", str(tmp_path / "nowhere.toml")), "nowhere.toml")


def test_a_fall_of_an_unknown_rider_is_refused(run, plan_file):
    _refused(run("show", plan_file, "--fail", "Zed@1"), "Zed")


@pytest.mark.parametrize("value", ["Ana@inf", "Ana@1e300:0", "Ana@nan", "Ana@9999"])
def test_a_fall_outside_the_act_is_refused_naming_the_value_typed(run, plan_file, value):
    _refused(run("show", plan_file, "--fail", value), f"'--fail': '{value}'")


@pytest.mark.parametrize("text, expected", [
    ("Ana@3.5:0.4", ("Ana", 3.5, 0.4)), ("Ana@3.5", ("Ana", 3.5, None)), ("Ana@2s:0", ("Ana", 2.0, 0.0)),
    ("Mary Ann@0.25", ("Mary Ann", 0.25, None)),
])
def test_parse_fail(text, expected):
    assert parse_fail(text) == expected


@pytest.mark.parametrize("text", ["Ana", "@1", "Ana@", "Ana@1:", "Ana@x", "Ana@1:half", "A@1@2"])
def test_parse_fail_refuses(text):
    with pytest.raises(ValueError):
        parse_fail(text)


# ---------------------------------------------------------------------------
# the terminal views


def _screen(run, args, width, color=False):
    env = {"COLUMNS": str(width), **({"FORCE_COLOR": "1", "NO_COLOR": ""} if color else {"NO_COLOR": "1"})}
    res = run(*args, "--format", "table", env=env)
    assert res.exit_code == 0, res.stderr
    return res.stdout


@pytest.mark.parametrize("width", [80, 100])
@pytest.mark.parametrize("extra", [(), ("--fail", "Ben@1.2:0.3"), ("--monte-carlo", "40", "--seed", "1"),
                                   ("--monte-carlo", "40", "--seed", "1", "--table", "falls"), ("--table", "pairs")],
                         ids=["act", "fail", "odds", "falls", "pairs"])
def test_no_line_is_wider_than_the_terminal(run, plan_file, width, extra):
    text = ANSI.sub("", _screen(run, ("show", plan_file, *extra), width))
    assert max(cell_len(line) for line in text.splitlines()) <= width
    if not extra:
        assert "Riders" in text and "Pairs" in text


def test_speeds_in_km_h_beside_m_s(run, plan_file):
    text = ANSI.sub("", _screen(run, ("show", plan_file, "--table", "riders"), 100))
    # Ana's speedometer reads 32 km/h (her contact's speed, as planned): 8.89 m/s beside it
    line = next(line for line in text.splitlines() if line.strip().startswith("Ana"))
    assert "32.0 (8.89)" in line


def test_conflicts_are_red(run, tmp_path):
    plan = tmp_path / "close.toml"
    plan.write_text(CLOSE, encoding="utf-8")
    text = _screen(run, ("show", str(plan), "--table", "pairs"), 100, color=True)
    line = next(line for line in text.splitlines() if "Low" in line and "High" in line)
    verdict = re.search(r"(conflict|collision)", ANSI.sub("", line))
    assert verdict, line
    assert re.search(r"\x1b\[(1;)?31m" + verdict.group(1), line), repr(line)


def test_a_hit_is_red_on_the_line_of_the_rider_fallen_into(run, plan_file):
    """The view says HIT, in red, exactly for the riders the table marks hit."""
    data = json.loads(run("show", plan_file, "--fail", "Ana@0.5:0", "--format", "json").stdout)
    hit = {r["victim"]: r["hit"] for r in data}
    assert any(hit.values()) and not all(hit.values())      # the case shows both
    text = _screen(run, ("show", plan_file, "--fail", "Ana@0.5:0", "--table", "falls"), 100, color=True)
    for victim, was_hit in hit.items():
        line = next(line for line in text.splitlines() if re.search(rf"Ana\S*\s+\S*{victim}\b", ANSI.sub("", line)))
        assert bool(re.search(r"\x1b\[(1;)?31mHIT", line)) == was_hit, repr(line)


def test_help_names_only_options_the_command_has(run):
    res = run("show", "--help")
    assert res.exit_code == 0
    assert "--jobs" not in res.stdout and "--scheduler" in res.stdout


#: A horizontal lane at the top of the globe (no contact) and a looper.
AT_THE_TOP = """
[globe]
diameter = "16ft"
mu = 0.9
max_g = 8
duration = 60

[[rider]]
name = "Ana"
lane = "horizontal"
height = "16ft"
com_speed = "1m/s"

[[rider]]
name = "Ben"
lane = "vertical"
azimuth = 0
v_top = "6.5m/s"
"""


def test_an_infeasible_lane_is_a_verdict_marks_its_pairs_and_exits_1(run, tmp_path):
    plan = tmp_path / "top.toml"
    plan.write_text(AT_THE_TOP, encoding="utf-8")
    res = run("show", str(plan), "--format", "json")
    assert res.exit_code == 1
    assert [r["status"] for r in json.loads(res.stdout)] == ["no_contact", "ok"]
    assert res.stderr.strip() == "deathsphere: not feasible as planned: Ana (no_contact); see the riders' status"
    shown = run("show", str(plan), "--format", "table", env={"COLUMNS": "100", "NO_COLOR": "1"})
    assert shown.exit_code == 1
    screen = ANSI.sub("", shown.stdout)
    assert "not feasible as planned: Ana (no_contact)" in screen
    assert "Ana – Ben: a lane that is not feasible (Ana)" in screen


def test_a_fall_closer_than_the_plans_rule_is_a_conflict_not_clear(run, tmp_path):
    plan = tmp_path / "act.toml"
    plan.write_text(EXAMPLE_PLAN, encoding="utf-8")
    rows = json.loads(run("show", str(plan), "--fail", "Ana@0.5443:0", "--format", "json").stdout)
    (eve,) = [r for r in rows if r["victim"] == "Eve"]
    assert 0 < eve["min_clearance_m"] < 0.15
    screen = ANSI.sub("", _screen(run, ("show", str(plan), "--fail", "Ana@0.5443:0", "--table", "falls"), 100))
    (line,) = [ln for ln in screen.splitlines() if " Eve " in ln]
    assert "conflict" in line and "clear " not in line.replace("least clear", "")


def test_a_contact_speed_where_the_contact_does_not_move_is_a_one_line_refusal(run, tmp_path):
    plan = tmp_path / "top.toml"
    plan.write_text(AT_THE_TOP.replace('com_speed = "1m/s"', 'speed = "1m/s"'), encoding="utf-8")
    res = run("show", str(plan), "--format", "csv")
    assert res.exit_code == 2 and "Traceback" not in res.output
    assert "rider 'Ana': speed:" in res.stderr and "vertical axis" in res.stderr
