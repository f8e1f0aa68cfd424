"""A plan's refusals name the plan's key, in the plan's words, and never
an option that was not typed; the act's length asks for the key to add
and gives the laps in seconds."""

import re

import pytest

import deathsphere

PLAN = """
[globe]
diameter = "16ft"
mu = 0.9
max_g = 8
{globe}

[[rider]]
name = "A"
lane = "horizontal"
height = "2m"
speed = "30km/h"

[[rider]]
name = "V"
lane = "vertical"
azimuth = 0
v_top = "{v_top}"
{looper}
"""


def _plan(tmp_path, globe="", v_top="6.1m/s", looper=""):
    path = tmp_path / "act.toml"
    path.write_text(PLAN.format(globe=globe, v_top=v_top, looper=looper), encoding="utf-8")
    return str(path)


def _one_line(res):
    assert res.exit_code == 2 and "Traceback" not in res.stderr
    (line,) = res.stderr.splitlines()
    return line


def test_laps_not_commensurate_ask_for_the_plans_duration_in_seconds(run, tmp_path):
    plan = _plan(tmp_path)
    act = deathsphere.show(plan, duration=5)
    laps = {lane.name: lane.period_s for lane in act.lanes}
    line = _one_line(run("show", plan))
    assert "duration = 60 in the plan's [globe]" in line
    assert f"A {laps['A']:.4g} s" in line and f"V {laps['V']:.4g} s" in line
    assert "--duration" not in line and not re.search(r"\d+/\d+", line)        # no option, no fractions of seconds
    assert run("show", plan, "--duration", "5").exit_code == 0


@pytest.mark.parametrize("options", [(), ("--phase", "auto"), ("--duration", "5")])
def test_a_plans_bad_phase_or_duration_names_the_plans_key_not_an_option(run, tmp_path, options):
    for globe, looper, key in (("duration = -3", "", "globe: duration:"), ("", 'phase = "abc"', "rider 'V': phase:")):
        line = _one_line(run("show", _plan(tmp_path, globe=globe, v_top="6.5m/s", looper=looper), *options))
        assert key in line
        assert "'--phase'" not in line and "'--duration'" not in line


def test_a_typed_option_is_named_and_a_plans_key_is_not_an_argument(run, tmp_path):
    line = _one_line(run("show", _plan(tmp_path, v_top="6.5m/s"), "--duration", "0"))
    assert "'--duration'" in line
    with pytest.raises(deathsphere.ParameterError) as err:
        deathsphere.show(_plan(tmp_path, v_top="6.5m/s", looper='phase = "abc"'))
    assert err.value.param is None and str(err.value).startswith("rider 'V': phase:")
