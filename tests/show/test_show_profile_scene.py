"""The 3-D view's title of a show on a profile whose floor is a point: a
dome (tests/data/ellipsoid_dome.csv, 8 m across at its widest) is named by
its widest diameter, not its floor's."""

from pathlib import Path

import pytest

import deathsphere

DOME = Path(__file__).resolve().parents[1] / "data" / "ellipsoid_dome.csv"


def test_a_dome_acts_title_gives_its_widest_diameter():
    from deathsphere.viewer.show_scene import act_scene

    plan = {"arena": {"surface": "profile", "profile": str(DOME), "mu": 0.8, "max_g": 6},
            "rider": [{"name": "Ana", "machine": "stunt125", "width": "0.7m", "lane": "horizontal",
                       "height": "2.5m", "speed": "40km/h"}]}
    scene = act_scene(deathsphere.show(plan))
    assert max(scene.ground["rho"]) == pytest.approx(4.0, abs=1e-6)
    assert "on a profile 8.00 m across" in scene.title
