"""The arena of a run (deathsphere.requests.arena): one ground record from
the keywords that name a surface and its shape, or a record as given."""

import math

import numpy as np
import pytest

import deathsphere
from deathsphere.errors import ParameterError
from deathsphere.physics.ground import Cone, Cylinder, Plane, Profile, Sphere
from deathsphere.requests.arena import arena, lane_key


def test_each_surface_from_its_keywords():
    assert arena() == Sphere(3.0)
    assert arena("sphere", diameter="16ft") == Sphere(16 * 0.3048 / 2)
    assert arena("cylinder", diameter="32ft", wall_height=6) == Cylinder(32 * 0.3048 / 2, 6.0)
    cone = arena("Cone", diameter=6, wall_angle=80)
    assert cone.radius == 3.0 and math.isclose(cone.wall_angle_rad, math.radians(80)) and cone.wall_height == math.inf
    assert arena("plane") == Plane()
    drum = Cylinder(2.0)
    assert arena(drum) is drum
    profile = Profile([2.0, 2.0, 2.0, 2.0], [0.0, 1.0, 2.0, 3.0])
    assert arena("profile", profile=profile) is profile
    assert lane_key(Plane()) == "turn_radius" and lane_key(drum) == "height"


@pytest.mark.parametrize("kwargs, param", [
    (dict(surface="drum"), "surface"),
    (dict(surface=3.0), "surface"),
    (dict(surface="cone", diameter=6), "wall_angle"),
    (dict(surface="cone", wall_angle=80), "diameter"),
    (dict(surface="cone", diameter=6, wall_angle=0), "wall_angle"),
    (dict(surface="cone", diameter=6, wall_angle=180), "wall_angle"),
    (dict(surface="cylinder", diameter=6, wall_angle=90), "wall_angle"),
    (dict(surface="cylinder", diameter=6, wall_height=-1), "wall_height"),
    (dict(surface="plane", diameter=6), "diameter"),
    (dict(surface="profile"), "profile"),
    (dict(surface="sphere", r=3, diameter=6), "diameter"),
    (dict(surface=Cylinder(2.0), diameter=6), "diameter"),
])
def test_bad_arenas_name_the_keyword(kwargs, param):
    with pytest.raises(ParameterError) as err:
        arena(**kwargs)
    assert err.value.param == param and "\n" not in str(err.value)


def test_a_record_and_its_keywords_give_one_table():
    by_record = deathsphere.orbit(surface=Cylinder(4.8768, 6.0), height=[1.0, 5.0], alpha=[10, 89.9],
                                  stability=False)
    by_words = deathsphere.orbit(surface="cylinder", diameter=9.7536, wall_height=6, height=[1.0, 5.0],
                                 alpha=[10, 89.9], stability=False)
    for name in ("v_cm_m_s", "mu_required", "rho_contact_m"):
        assert np.array_equal(by_record[name], by_words[name], equal_nan=True)
    assert by_record["status"].tolist() == by_words["status"].tolist() == ["ok", "no_fit"]
    # a lane over the wall's top is refused alike, naming height
    for surface in (dict(surface=Cylinder(4.8768, 6.0)), dict(surface="cylinder", diameter=9.7536, wall_height=6)):
        with pytest.raises(ParameterError) as err:
            deathsphere.orbit(height=[1.0, 7.0], alpha=10, stability=False, **surface)
        assert err.value.param == "height" and "at most 6 m" in str(err.value)
    globe = deathsphere.orbit(60, 10, surface=Sphere(2.0), stability=False)
    assert float(globe["v_cm_m_s"]) == float(deathsphere.orbit(60, 10, r=2.0, stability=False)["v_cm_m_s"])


def test_the_ball_and_the_particle_off_the_globe():
    ball = deathsphere.orbit(surface="cylinder", diameter=9, height=2, body="sphere", omega3=60, stability=False)
    assert ball["branch"].tolist() == [0, 1] and ball["status"].tolist() == ["ok", "no_orbit"]
    # on an upright wall a ball holds by its spin: k a omega3 Omega + g = 0 (docs/surfaces.md S6)
    omega = float(ball["omega_rad_s"][0])
    assert math.isclose(0.4 * 0.3 * 60 * omega + 9.80665, 0.0, abs_tol=1e-12)
    particle = deathsphere.orbit(surface="cone", diameter=6, wall_angle=60, height=1, body="particle",
                                 stability=False)
    rho = 3.0 + 1.0 / math.tan(math.radians(60))
    assert math.isclose(float(particle["omega_rad_s"]) ** 2, 9.80665 * math.tan(math.radians(60)) / rho,
                        rel_tol=1e-13)
