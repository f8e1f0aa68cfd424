"""``map --stability`` off the globe (docs/limits.md sec. 8): the stability
boundary on each lane and the stable parts of the allowed intervals agree
with ``orbit --surface``'s stability of the same orbits, on a cone, a
bowl's profile and outside a cone leaning in."""

import csv
import io
import math
from pathlib import Path

import numpy as np
import pytest

import deathsphere

ROOT = Path(__file__).resolve().parents[1]
BOWL = str(ROOT / "examples" / "bowl.csv")
CASES = {
    "cone": dict(surface="cone", diameter=6, wall_angle=80, wall_height=3),
    "bowl": dict(surface="profile", profile=BOWL),
    "outside": dict(surface="cone", diameter=6, wall_angle=100, wall_height=3, side="outside"),
}
A = 0.3


def _verdicts(case, height, alpha):
    """orbit --surface's status and stability of the orbits at lane ``height`` [m] and tilts ``alpha`` [deg]."""
    rows = deathsphere.orbit(a=A, height=float(height), alpha=[float(x) for x in alpha], **CASES[case])
    return list(zip(np.ravel(rows["status"]), np.ravel(rows["stability"])))


@pytest.mark.parametrize("case", ["cone", "bowl", "outside"])
def test_the_stable_parts_are_orbit_surfaces_stable_orbits(case):
    heights = [0.6, 1.5, 2.4]
    curves = deathsphere.region_curves(a=A, stability=True, height=heights, **CASES[case])
    lo, hi = curves.stable
    seen = set()
    # a grid of tilts across each lane's allowed intervals, off their ends and the stability boundary
    for i, h in enumerate(heights):
        ends = [(curves.lo_deg[i, j], curves.hi_deg[i, j]) for j in range(int(curves.count[i]))]
        alpha = np.concatenate([np.linspace(a + 0.3, b - 0.3, 7) for a, b in ends])
        in_stable = np.zeros(alpha.size, dtype=bool)
        for j in range(lo.shape[1]):
            in_stable |= (alpha > lo[i, j]) & (alpha < hi[i, j])
        for al, inside, (status, stability) in zip(alpha, in_stable, _verdicts(case, h, alpha)):
            assert status == "ok", (h, al)
            assert stability == ("stable" if inside else "unstable"), (h, al)
            seen.add(stability)
    assert seen == {"stable", "unstable"}              # the grid crosses the boundary


@pytest.mark.parametrize("case", ["cone", "bowl"])
def test_either_side_of_each_stability_row_orbit_surface_disagrees(case):
    table = deathsphere.region(a=A, stability=True, height="0.5:2.5:1", **CASES[case])
    rows = [i for i in range(len(table)) if table["curve"][i] == "stability"]
    assert rows and all(table["equation"][i] == "stability boundary (exact linearisation)" for i in rows)
    for i in rows:
        h, al = table["height_m"][i], table["alpha_deg"][i]
        assert table["feasible_below"][i] and table["feasible_above"][i]
        (_, below), (_, above) = _verdicts(case, h, [al - 1e-5, al + 1e-5])
        assert {below, above} == {"stable", "unstable"}, (h, al)


def test_the_command_line_gives_the_stability_rows_and_the_stable_tilts(run):
    res = run("map", "--surface", "cone", "--diameter", "6", "--wall-angle", "80", "--wall-height", "3", "-a", "0.3",
              "--height", "1.5", "--stability", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    (row,) = [r for r in csv.DictReader(io.StringIO(res.stdout)) if r["curve"] == "stability"]
    alpha = float(row["alpha_deg"])
    # orbit --surface on the command line, either side of it
    res = run("orbit", "--surface", "cone", "--diameter", "6", "--wall-angle", "80", "--wall-height", "3", "-a", "0.3",
              "--height", "1.5", "--alpha", f"{alpha - 0.01}", "--alpha", f"{alpha + 0.01}", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    assert [r["stability"] for r in csv.DictReader(io.StringIO(res.stdout))] == ["stable", "unstable"]
    res = run("map", "--surface", "cone", "--diameter", "6", "--wall-angle", "80", "--wall-height", "3", "-a", "0.3",
              "--height", "0:3:0.5", "--stability", "--format", "table")
    assert res.exit_code == 0, res.stderr
    assert "stable alpha" in res.stdout and f"0.00 .. {alpha:.2f}" in res.stdout
    assert not math.isnan(alpha)


def test_the_figure_draws_the_boundary_and_a_bad_flag_is_refused(tmp_path):
    pytest.importorskip("matplotlib")
    from deathsphere.errors import ParameterError
    from deathsphere.render.lane_map_figure import plot_lane_map

    curves = deathsphere.region_curves(a=A, stability=True, height="0.5:2.5:0.5", **CASES["cone"])
    fig = plot_lane_map(curves, output=str(tmp_path / "cone.png"))
    labels = [text.get_text() for text in fig.axes[0].get_legend().get_texts()] if fig.axes[0].get_legend() else \
        [text.get_text() for text in fig.legends[0].get_texts()]
    assert "stability boundary (exact linearisation)" in labels and (tmp_path / "cone.png").stat().st_size > 1000
    with pytest.raises(ParameterError, match="stability must be True or False"):
        deathsphere.region(a=A, stability="yes", height=1.5, **CASES["cone"])
