"""The paper's bodies as records: a word names one only through the
decoder, and a record's attributes are the paper's."""

import numpy as np
import pytest

from deathsphere.model import Setup
from deathsphere.params import ParameterError
from deathsphere.records.paper_bodies import BALL, PAPER_BODIES, PARTICLE, WHEEL, Ball
from deathsphere.requests.decode import decode_paper_body, decode_paper_lane, paper_body_codes, paper_body_named


def test_a_word_decodes_to_its_record_case_aside():
    assert decode_paper_body("Sphere") is BALL and decode_paper_body(" wheel ") is WHEEL
    assert decode_paper_body(PARTICLE) is PARTICLE          # a record passes through
    assert paper_body_named("Sphere") is None               # a table's word is read exactly


def test_a_word_naming_no_body_is_refused_naming_the_key_as_typed():
    with pytest.raises(ParameterError, match=r"^shape must be one of wheel \| sphere \(got 'particle'\)$"):
        decode_paper_body("particle", key="shape", allowed=(WHEEL, BALL))
    with pytest.raises(ParameterError, match=r"body must be one of wheel \| sphere \| particle \(got 3\)"):
        decode_paper_body(3)


def test_a_column_of_words_decodes_to_codes_in_the_records_order():
    codes = paper_body_codes(np.array(["sphere", "wheel", "disc", "particle", ""], dtype=object))
    assert codes.tolist() == [BALL.code, WHEEL.code, -1, PARTICLE.code, -1]
    assert [PAPER_BODIES[c] for c in codes[[0, 1, 3]]] == [BALL, WHEEL, PARTICLE]
    assert paper_body_codes(np.full(4, "wheel", dtype=object)).tolist() == [0] * 4   # one word: decided once


def test_the_records_default_inertia_is_the_papers():
    # Table 1's wheel has its mass on the rim (I11 = 2 k m a^2 = m a^2: k = 1/2); a solid ball
    # has I = 2/5 m a^2 (sec. 4); a point particle no rotational inertia
    assert (WHEEL.default_k, BALL.default_k, PARTICLE.default_k) == (0.5, 0.4, 0.0)
    assert Setup(body="sphere").k == 0.4 and isinstance(Setup(body="sphere").body, Ball)
    assert (WHEEL.rolls, BALL.rolls, PARTICLE.rolls) == (True, True, False)
    # eq. 29 fixes a wheel's orbit at theta by one of its tilt, contact speed, centre speed, rate; eq. 55 a
    # ball's by its spin or rate
    assert (WHEEL.held_by, BALL.held_by, PARTICLE.held_by) == (("alpha", "speed", "com_speed", "omega"),
                                                               ("omega3", "omega"), ())


def test_a_setup_refuses_a_word_naming_no_body():
    with pytest.raises(ValueError, match=r"body must be one of wheel \| sphere \| particle \(got 'disc'\)"):
        Setup(body="disc")


def _lane(body, **given):
    return decode_paper_lane({"theta": 60.0, **given}, body, lambda key, raw: float(raw))


def test_which_key_holds_a_lane_is_the_bodys():
    from deathsphere.requests.records import ComSpeed, ContactSpeed, Horizontal, Rate, Spin, Theta, Tilt, Vertical

    assert _lane(WHEEL, alpha=10) == Horizontal(at=Theta(60.0), by=Tilt(10.0))
    assert _lane(WHEEL, speed=7, branch=3) == Horizontal(at=Theta(60.0), by=ContactSpeed(7.0, 3))  # checked once solved
    assert _lane(WHEEL, com_speed=7, branch=3) == Horizontal(at=Theta(60.0), by=ComSpeed(7.0, 3))
    assert _lane(BALL, omega3=40, branch=1) == Horizontal(at=Theta(60.0), by=Spin(40.0, 1))
    assert _lane(BALL, omega=-2) == Horizontal(at=Theta(60.0), by=Rate(-2.0, 0))
    assert _lane(WHEEL, vertical=True, v_top=6) == Vertical(v_top=6.0, theta=60.0)


@pytest.mark.parametrize("body, given, words", [
    (WHEEL, {}, "a wheel's steady orbit needs alpha"),
    (WHEEL, {"alpha": 10, "speed": 7}, "one of them alone"),
    (WHEEL, {"omega3": 40}, "no omega3"),
    (BALL, {"alpha": 10}, "a sphere's steady orbit needs exactly one of omega3 and omega"),
    (BALL, {"omega3": 40, "omega": 2}, "exactly one of omega3 and omega"),
    (BALL, {"omega3": 40, "branch": 2}, "branch must be 0"),
    (BALL, {"vertical": True, "v_top": 6}, "vertical=True simulates a wheel"),
    (WHEEL, {"alpha": 10, "v_top": 6}, "v_top is for vertical orbits"),
])
def test_a_lane_its_body_cannot_hold_is_refused(body, given, words):
    with pytest.raises(ParameterError, match=words):
        _lane(body, **given)
