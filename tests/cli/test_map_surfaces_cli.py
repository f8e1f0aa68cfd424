"""map on the other surfaces (docs/limits.md sec. 8): the boundary data
checked against orbit --surface at sampled cells, the figure written, and
the globe's options that do not apply refused in one line naming them."""

import csv
import io

import numpy as np
import pytest

import deathsphere

CONE = dict(surface="cone", diameter=6.0, wall_angle=80.0, wall_height=8.0)


def _ok(alpha_deg, height, mu, max_g, shape=CONE):
    t = deathsphere.orbit(alpha=np.asarray(alpha_deg, dtype=float), height=height, mu=mu, max_g=max_g,
                          stability=False, **shape)
    return np.asarray(t["status"]) == "ok"


@pytest.mark.parametrize("shape, mu, max_g", [(CONE, 1.0, 4.0),
                                             (dict(surface="cylinder", diameter=9.7536, wall_height=6.0), 0.8,
                                              float("inf"))])
def test_the_data_matches_orbit_at_sampled_cells(shape, mu, max_g):
    heights = [0.5, 2.0, 5.0]
    t = deathsphere.region(height=heights, mu=mu, max_g=max_g, **shape)
    rng = np.random.default_rng(7)
    for h in heights:
        rows = np.asarray(t["height_m"]) == h
        alpha = np.sort(np.asarray(t["alpha_deg"])[rows])
        above = np.asarray(t["feasible_above"])[rows][np.argsort(np.asarray(t["alpha_deg"])[rows])]
        below = np.asarray(t["feasible_below"])[rows][np.argsort(np.asarray(t["alpha_deg"])[rows])]
        # each side of a boundary point as the data says
        assert np.array_equal(_ok(alpha + 1e-5, h, mu, max_g, shape), above)
        assert np.array_equal(_ok(alpha - 1e-5, h, mu, max_g, shape), below)
        # random cells between boundary points: feasible exactly as the point below them says
        cells = rng.uniform(-179.9, 179.9, 400)
        index = np.searchsorted(alpha, cells) - 1
        want = np.where(index >= 0, above[np.maximum(index, 0)], False)
        assert np.array_equal(_ok(cells, h, mu, max_g, shape), want)
        assert want.any()


def test_the_csv_and_the_figure_through_the_command_line(run, tmp_path):
    res = run("map", "--surface", "cylinder", "--diameter", "32ft", "--wall-height", "6", "--height", "0:6:3",
              "--mu", "1", "--max-g", "4", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    got = list(csv.DictReader(io.StringIO(res.stdout)))
    assert {r["height_m"] for r in got} == {"0.0", "3.0", "6.0"}
    opens = [r for r in got if r["feasible_above"] == "True" and r["feasible_below"] == "False"]
    assert {r["curve"] for r in opens} == {"max_g"} and len(opens) == 3
    pytest.importorskip("matplotlib")
    out = tmp_path / "drum.png"
    res = run("map", "--surface", "cone", "--diameter", "6", "--wall-angle", "80", "--wall-height", "8",
              "--height", "0:8:1", "--mu", "1", "--output", str(out))
    assert res.exit_code == 0, res.stderr
    assert out.stat().st_size > 1000


@pytest.mark.parametrize("args, option", [
    (("--step", "1"), "--step"),
    (("--height", "-2"), "--height"),
    (("--turn-radius", "2"), "--turn-radius"),
])
def test_bad_input_is_one_line_naming_the_option(run, args, option):
    res = run("map", "--surface", "cylinder", "--diameter", "32ft", *args)
    assert res.exit_code == 2
    assert option in res.stderr.lower() or option in res.stderr
    assert len(res.stderr.strip().splitlines()) == 1 and "Traceback" not in res.stderr


def test_a_terminal_shows_the_allowed_intervals_of_a_few_lanes(run):
    res = run("map", "--surface", "plane", "--turn-radius", "1:5:1", "--mu", "1", "--format", "table")
    assert res.exit_code == 0, res.stderr
    assert "turn radius" in res.stdout and "90.00" in res.stdout
