"""Whether a lane holds a two-wheeler at a speed (physics.two_wheeler.holds,
docs/show.md sec. 13): a speed with no turn sought holds nowhere, without a
warning, and the turn that holds is a turn at that speed, ok within mu."""

import math
import warnings

import numpy as np

from deathsphere.physics.ground import Cylinder
from deathsphere.physics.two_wheeler import steady
from deathsphere.physics.two_wheeler.holds import turn_holds
from deathsphere.records.two_wheeler_presets import TWO_WHEELERS

G = 9.80665
DRUM = Cylinder(16 * 0.3048, 12 * 0.3048)
HEIGHT = 6 * 0.3048
BIKE = TWO_WHEELERS["stunt125-steer"]


def test_no_speed_holds_where_no_turn_is_sought_and_no_warning_leaks():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = turn_holds(HEIGHT, [0.0, -1.0, math.nan, math.inf, 12.5], BIKE.parameters(), DRUM, G, BIKE.head, 0.8)
    assert out["holds"].tolist() == [False, False, False, False, True]
    assert np.isnan(out["lean"][:4]).all() and np.isfinite(out["lean"][4])


def test_the_turn_that_holds_is_a_turn_at_that_speed_within_mu():
    speeds = np.array([6.0, 12.5, 15.0])
    out = turn_holds(HEIGHT, speeds, BIKE.parameters(), DRUM, G, BIKE.head, 0.8)
    assert out["holds"].tolist() == [False, True, True]
    # the steer of the lean that holds, from the kinematic condition, and that turn's state
    lean = out["lean"][1:]
    steer = steady.solve_steer(np.full(2, HEIGHT), lean, BIKE.parameters(), DRUM)
    state = steady.turn_state(np.full(2, HEIGHT), lean, steer, BIKE.parameters(), DRUM, G, BIKE.head)
    assert np.allclose(state["v_rear"], speeds[1:], rtol=1e-9)
    assert (np.fmax(state["mu_required_rear"], state["mu_required_front"]) <= 0.8).all()
    assert (state["head_clearance"] > 0).all() and (state["contact"] == 1).all()
    # friction is what fails the slow one: with more of it the lane holds there too
    assert turn_holds(HEIGHT, 6.0, BIKE.parameters(), DRUM, G, BIKE.head, 3.0)["holds"].tolist() == [True]
