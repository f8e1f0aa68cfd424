import csv
import io
import json
import sys

import numpy as np
import pytest


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_map_in_the_terminal_labels_the_three_curves(run):
    text = run("map", "--format", "table", env={"COLUMNS": "80"}).stdout
    lines = text.splitlines()
    assert max(len(line) for line in lines) <= 80
    for label in ("eq. (0)", "eq. (29)", "eq. (33)", "a/r = 0.1"):
        assert label in text


def test_map_boundaries_as_data(run):
    out = rows(run("map", "--format", "csv", "--step", "1").stdout)
    assert {r["curve"] for r in out} == {"eq0", "eq29", "eq33"}
    # eq. (0) as an equality: sin(theta - alpha) = a/r on its curve
    th = np.deg2rad([float(r["theta_deg"]) for r in out if r["curve"] == "eq0"])
    al = np.deg2rad([float(r["alpha_deg"]) for r in out if r["curve"] == "eq0"])
    assert np.allclose(np.abs(np.sin(th - al)), 0.1, atol=1e-9)


def test_map_with_limits_adds_their_curves(run):
    out = json.loads(run("map", "--format", "json", "--mu", "1", "--max-g", "5", "--step", "2").stdout)
    assert {"mu", "max_g"} <= {r["curve"] for r in out}


def test_map_writes_an_image(run, tmp_path):
    out = tmp_path / "map.png"
    res = run("map", "--output", str(out))
    assert res.exit_code == 0 and out.read_bytes()[:4] == b"\x89PNG"
    assert "wrote" in res.stderr


def test_map_without_the_plot_extra_says_which_extra(run, tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    res = run("map", "--output", str(tmp_path / "map.png"))
    assert res.exit_code == 2
    (line,) = res.stderr.strip().splitlines()
    assert "pip install 'deathsphere[plot]'" in line


@pytest.mark.parametrize("args, words", [
    (["-a", "0"], "--wheel-radius"), (["-a", "4.5"], "must be > a = 4.5 m"),
    (["--output", "map.jpg"], ".png, .svg or .pdf"), (["--max-g", "0"], "--max-g"), (["-k", "-1"], "k (inertia"),
])
def test_map_usage_errors(run, args, words):
    res = run("map", *args)
    assert res.exit_code == 2 and words in res.stderr


def test_highest_orbit_with_mu_and_g_limit(run):
    (row,) = json.loads(run("limits", "--mu", "1", "--max-g", "5", "--format", "json").stdout)
    # closed form (docs/limits.md): theta* = 90 deg + atan(1/G) - atan(mu),
    # G = sqrt(L^2 - 1) the centre's acceleration that a load L allows
    assert row["found"] is True
    assert row["theta_deg"] == pytest.approx(90 + np.degrees(np.arctan(1 / np.sqrt(24))) - 45, abs=1e-6)
    assert row["v_cm_m_s"] == pytest.approx(10.29, abs=0.01)


def test_alpha_intervals_at_theta(run):
    out = rows(run("limits", "--theta", "60", "--theta", "30", "--mu", "1.2", "--format", "csv").stdout)
    assert [r["intervals"] for r in out] == ["1", "0"]
    lo, hi = float(out[0]["alpha_min_deg"]), float(out[0]["alpha_max_deg"])
    # every alpha strictly inside is ok with mu 1.2; just outside the top end it slips
    ok = run("orbit", "--theta", "60", "--alpha", f"{lo + 0.01}:{hi - 0.01}:0.5", "--mu", "1.2", "--format", "csv")
    assert {r["status"] for r in rows(ok.stdout)} == {"ok"}
    beyond = rows(run("orbit", "--theta", "60", "--alpha", str(hi + 0.01), "--mu", "1.2", "--format", "csv").stdout)
    assert beyond[0]["status"] != "ok"


def test_body_is_offered_where_it_makes_sense_and_refused_with_the_reason(run):
    # the map and a vertical orbit are a wheel's: --body is not offered at all
    for command in ("map", "vertical"):
        res = run(command, "--body", "sphere", "--theta", "60")
        assert res.exit_code == 2 and "No such option '--body'" in res.stderr
    # limits takes --body (one vocabulary) and says why it answers only for a wheel
    res = run("limits", "--body", "sphere", "--theta", "60")
    assert res.exit_code == 2 and res.stderr.count("\n") == 1 and "tilt alpha of a wheel" in res.stderr
    # ... and in a file of requests, such a row is invalid with that reason while the others are answered
    res = run("limits", "--input", "-", "--format", "csv", input="theta,body\n60,wheel\n60,sphere\n")
    out = rows(res.stdout)
    assert res.exit_code == 1 and [r["status"] for r in out] == ["ok", "invalid"]
    assert "tilt alpha of a wheel" in out[1]["reason"] and out[0]["intervals"] == "1"


def test_map_stability_in_the_terminal(run):
    text = run("map", "-a", "0.9", "--stability", "--format", "table", env={"COLUMNS": "80"}).stdout
    lines = text.splitlines()
    assert max(len(line) for line in lines) <= 80
    assert "x allowed, unstable" in text and ". allowed, stable" in text
    grid = "".join(line.split("|", 1)[1] for line in lines if "|" in line)
    assert grid.count("x") > 50 and grid.count(".") > 50
    assert "x" not in "".join(line.split("|", 1)[1] for line in
                              run("map", "-a", "0.9", "--format", "table").stdout.splitlines() if "|" in line)


def test_map_stability_boundary_as_data(run):
    from deathsphere.physics.stability import Verdict, wheel_stability

    out = rows(run("map", "-a", "0.9", "--stability", "--format", "csv", "--step", "5").stdout)
    stab = [r for r in out if r["curve"] == "stability"]
    assert {"eq0", "eq29", "eq33", "stability"} == {r["curve"] for r in out}
    assert len(stab) > 30 and all("exact linearisation" in r["equation"] for r in stab)
    th = np.deg2rad([float(r["theta_deg"]) for r in stab])
    al = np.deg2rad([float(r["alpha_deg"]) for r in stab])
    # every point lies between a stable and an unstable orbit at its theta
    d = np.deg2rad(1e-4)
    below = wheel_stability(th, al - d, 0.3, 1.0, 0.5, 9.80665)["verdict"]
    above = wheel_stability(th, al + d, 0.3, 1.0, 0.5, 9.80665)["verdict"]
    assert set(zip(below.tolist(), above.tolist())) <= {(Verdict.STABLE, Verdict.UNSTABLE),
                                                         (Verdict.UNSTABLE, Verdict.STABLE)}
    # e.g. at theta = 45 deg the orbits go unstable above alpha = 16.84 deg (docs/stability.md 6.4)
    (at45,) = [float(r["alpha_deg"]) for r in stab if float(r["theta_deg"]) == 45.0]
    assert at45 == pytest.approx(16.84, abs=0.01)


@pytest.mark.parametrize("args, option", [
    (["--step", "15", "--output", "map.png"], "--step"),       # a step past the data's range, once accepted
    (["--step", "1", "--output", "map.png"], "--step"),
    (["--step", "1", "--format", "table"], "--step"),
    (["--jobs", "2", "--format", "table"], "--jobs"),
    (["--jobs", "2", "--output", "map.png"], "--jobs"),
    (["--surface", "cylinder", "--diameter", "10", "--step", "1", "--format", "csv"], "--step"),
])
def test_an_option_the_map_would_ignore_is_refused_by_name(args, option, run, tmp_path):
    # the globe's figure and terminal plot are drawn on grids of their own, and off the
    # globe the lanes are --height's: a step or processes given there would do nothing
    res = run("map", *[str(tmp_path / a) if a.endswith(".png") else a for a in args])
    assert res.exit_code == 2 and res.stdout == ""
    assert res.stderr.count("\n") == 1 and f"'{option}'" in res.stderr
    assert not (tmp_path / "map.png").exists()


def test_the_step_still_sets_the_globes_boundary_data(run):
    coarse, fine = (rows(run("map", "--format", "csv", "--step", s).stdout) for s in ("5", "1"))
    assert len(fine) > len(coarse) > 0


def test_off_the_globe_the_terminal_shows_the_lanes_in_the_unit_typed(run):
    feet = run("map", "--surface", "cylinder", "--diameter", "32ft", "--wall-height", "12ft", "--format", "table",
               env={"COLUMNS": "100"}).stdout
    assert "height of the lane [ft]" in feet and "height of the lane [m]" in feet
    assert any(cells[1:3] == ["3.658", "12"] for cells in
               ([c.strip() for c in line.split("│")] for line in feet.splitlines()))
    metres = run("map", "--surface", "cylinder", "--diameter", str(32 * 0.3048), "--wall-height", str(12 * 0.3048),
                 "--format", "table", env={"COLUMNS": "100"}).stdout
    assert "[ft]" not in metres and "height of the lane [m]" in metres
    # the data stay in metres whatever was typed
    csv_feet = run("map", "--surface", "cylinder", "--diameter", "32ft", "--wall-height", "12ft", "--format", "csv")
    csv_metres = run("map", "--surface", "cylinder", "--diameter", "9.7536", "--wall-height", "3.6576",
                     "--format", "csv")
    assert csv_feet.stdout == csv_metres.stdout
