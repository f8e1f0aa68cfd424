"""Several ``--fail`` options: every fall is counted in the tables and
drawn in the 3-D view on its rider's track; two falls of one rider are
refused in the view in one line (a track draws one fall), never dropped."""

import json

import numpy as np
import pytest

from deathsphere.api.shows import EXAMPLE_PLAN, show
from deathsphere.table import Table
from deathsphere.viewer.show_scene import act_scene


@pytest.fixture(scope="module")
def act(tmp_path_factory):
    path = tmp_path_factory.mktemp("act") / "act.toml"
    path.write_text(EXAMPLE_PLAN, encoding="utf-8")
    return show(str(path))


def test_every_fall_is_drawn_on_its_riders_track(act):
    falls = Table.concat([act.fall("Cal", 0.3, 0.0), act.fall("Ben", 0.2, 0.5), act.fall("Eve", 1.0, 0.3)])
    scene = act_scene(act, falls)
    by_name = {track.name: track for track in scene.tracks}
    for rider, t in (("Cal", 0.3), ("Ben", 0.2), ("Eve", 1.0)):
        assert by_name[rider].event_time == t
        assert by_name[rider].status == str(falls["outcome"][list(falls["rider"]).index(rider)])
    # the two that fall have their paths, each landing where its row says
    for rider in ("Cal", "Ben"):
        row = list(falls["rider"]).index(rider)
        assert falls["outcome"][row] == "falls"
        t_path, path = by_name[rider].paths["fall"]
        assert t_path[-1] == pytest.approx(falls["t_land_s"][row])
        theta = np.degrees(np.arccos(path[2, -1] / np.linalg.norm(path[:, -1])))
        assert theta == pytest.approx(falls["theta_land_deg"][row], abs=1e-6)
    assert "fall" not in by_name["Ana"].paths and by_name["Ana"].event_time is None
    assert sum(1 for note in scene.notes if "drops to" in note["text"]) == 3
    assert {m["label"] for m in scene.moments} >= {"Cal's fall", "Ben's fall"}


def test_two_falls_of_one_rider_are_refused_by_the_scene(act):
    falls = Table.concat([act.fall("Ben", 0.2, 0.5), act.fall("Ben", 1.2, 0.3)])
    with pytest.raises(ValueError, match="one fall per rider: Ben falls at t = 0.2 s and at t = 1.2 s"):
        act_scene(act, falls)


def test_the_command_draws_every_fall_and_counts_them(run, tmp_path):
    plan = tmp_path / "act.toml"
    plan.write_text(EXAMPLE_PLAN, encoding="utf-8")
    rows = json.loads(run("show", str(plan), "--fail", "Cal@0.3:0", "--fail", "Ben@0.2:0.5", "--format",
                          "json").stdout)
    assert [(r["rider"], r["t_fail_s"]) for r in rows] == [("Cal", 0.3)] * 4 + [("Ben", 0.2)] * 4
    res = run("show", str(plan), "--fail", "Ben@0.2:0.5", "--fail", "Ben@1.2:0.3", "--output",
              str(tmp_path / "act.html"))
    assert res.exit_code == 2
    assert res.stderr.count("\n") == 1 and "Traceback" not in res.stderr
    assert "draws one fall per rider: --fail Ben@0.2:0.5 and --fail Ben@1.2:0.3 are both Ben's" in res.stderr
    assert not (tmp_path / "act.html").exists()
