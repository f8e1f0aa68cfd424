"""The plan: TOML or dict, every fault one line naming the rider and the key."""

import copy
import math

import pytest

import deathsphere
from deathsphere.act.plan import EXAMPLE_PLAN, read_plan

BASE = {"globe": {"diameter": "16ft", "mu": 0.9, "max_g": 8, "min_clearance": "15cm"},
        "rider": [{"name": "Ana", "machine": "stunt125", "lane": "horizontal", "height": "2.0m", "com_speed": "32km/h",
                   "direction": "ccw", "phase": 0},
                  {"name": "Ben", "machine": "stunt125", "lane": "vertical", "azimuth": 90, "v_top": "6.5m/s",
                   "phase": 180}]}


def _with(change):
    plan = copy.deepcopy(BASE)
    change(plan)
    return plan


def test_units_are_read_as_on_the_command_line():
    plan = read_plan(BASE)
    assert plan.globe.r == pytest.approx(16 * 0.3048 / 2)
    assert plan.globe.min_clearance == pytest.approx(0.15)
    ana, ben = plan.riders
    assert ana.com_speed == pytest.approx(32 / 3.6) and math.isnan(ana.speed)
    # height 2.0 m of the contact above the floor: cos(theta) = h / r - 1
    assert ana.theta_deg == pytest.approx(math.degrees(math.acos(2.0 / (16 * 0.3048 / 2) - 1)), rel=1e-12)
    assert ben.v_top == 6.5 and ben.azimuth_deg == 90 and ben.phase_deg == 180


def test_a_toml_file_and_a_dict_are_the_same_plan(tmp_path):
    import tomllib

    path = tmp_path / "act.toml"
    path.write_text(EXAMPLE_PLAN, encoding="utf-8")
    assert read_plan(path) == read_plan(tomllib.loads(EXAMPLE_PLAN))
    assert len(read_plan(path).riders) == 5


@pytest.mark.parametrize("change, words", [
    (lambda p: p["rider"][0].update(colour="red"), ("rider 'Ana'", "colour", "unknown key")),
    (lambda p: p["rider"][1].update(machine="harley"), ("rider 'Ben'", "machine", "unknown machine")),
    (lambda p: p["rider"][0].update(height="5m"), ("rider 'Ana'", "height", "outside the globe")),
    (lambda p: p["rider"][1].update(v_top="1m/s"), ("rider 'Ben'", "v_top", "not feasible")),
    (lambda p: p["rider"][1].update(name="Ana"), ("rider 'Ana'", "name", "twice")),
    (lambda p: p.update(rider=[]), ("plan", "rider", "no riders")),
    (lambda p: p["globe"].update(diameter="16kg"), ("globe", "diameter")),
    (lambda p: p["rider"][0].update(speed="32km/h", v_top="6m/s"), ("rider 'Ana'", "v_top", "horizontal")),
    (lambda p: p["rider"][0].update(direction="up"), ("rider 'Ana'", "direction", "ccw or cw")),
])
def test_a_bad_plan_is_one_line_naming_the_rider_and_the_key(change, words):
    with pytest.raises(deathsphere.ParameterError) as err:
        deathsphere.show(_with(change))
    message = str(err.value)
    assert "\n" not in message
    for word in words:
        assert word in message


def test_a_machine_inline_and_its_width():
    plan = read_plan(_with(lambda p: p["rider"][0].update(machine={"base": "stunt125", "mass": "150kg"},
                                                          width="0.6m")))
    assert plan.riders[0].machine.mass == 150 and plan.riders[0].width == 0.6


def test_a_machine_without_width_is_refused(tmp_path):
    (tmp_path / "m.toml").write_text('name = "mine"\nmass = 150\n', encoding="utf-8")
    machine = deathsphere.Machine(mass=150, h=0.8, a=0.3, inertia=(20, 30, 15), head=1.6)
    assert machine.width is None
    plan = _with(lambda p: p["rider"][0].update(machine={"base": "paper-wheel"}))
    assert read_plan(plan).riders[0].width == 0.0   # the paper's wheel is thin


def test_the_act_duration_and_the_results_arguments_are_checked_in_one_line():
    incommensurate = _with(lambda p: p["rider"][0].update(com_speed="31km/h"))
    with pytest.raises(deathsphere.ParameterError, match="duration"):
        deathsphere.show(incommensurate)
    act = deathsphere.show(_with(lambda p: (p["rider"][0].update(com_speed="31km/h"), p["globe"].update(duration=4))))
    assert act.duration_s == 4 and not act.commensurate
    assert deathsphere.show(incommensurate, duration=2.5).duration_s == 2.5
    for call, name in ((lambda: act.fall("Zed", 0.1), "rider"), (lambda: act.fall("Ana", -1.0), "t"),
                       (lambda: act.fall("Ana", 0.1, 1.5), "speed_fraction"), (lambda: act.falls(0), "n"),
                       (lambda: act.falls(5, seed=-2), "seed"), (lambda: deathsphere.show(BASE, phase="best"), "phase"),
                       (lambda: deathsphere.show(BASE, duration=-1), "duration")):
        with pytest.raises(deathsphere.ParameterError) as err:
            call()
        assert err.value.param == name and "\n" not in str(err.value)
