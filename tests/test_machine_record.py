"""The machine's record (deathsphere.records): fields named as the
parameter registry names them, the body only (no gravity, no globe), the
short keywords of docs/machine.md still accepted, and the API's names
unchanged."""

import dataclasses

import pytest

import deathsphere
from deathsphere import params
from deathsphere.api import machines as api_machines
from deathsphere.records import machine_presets
from deathsphere.records.machine import ALIASES, FIELD_PARAMS, Machine
from deathsphere.requests import decode


def test_the_records_fields_are_the_registrys_names():
    fields = {f.name for f in dataclasses.fields(Machine)}
    assert fields == {"mass", "com_height", "wheel_radius", "tyre_radius", "inertia", "spin_inertia", "head_height",
                      "width", "name", "source"}
    assert all(p in params.PARAMS for p in FIELD_PARAMS.values())
    # the body only: gravity and the globe belong to the run
    assert not fields & {"g", "r", "radius", "gravity", "ground"}


def test_the_short_keywords_make_the_same_machine():
    old = Machine(mass=172, h=0.78, a=0.3, t=0.045, inertia=(25, 40, 20), spin_inertia=0.8, head=1.68)
    new = Machine(mass=172, com_height=0.78, wheel_radius=0.3, tyre_radius=0.045, inertia=(25, 40, 20),
                  spin_inertia=0.8, head_height=1.68)
    assert old == new
    assert (old.h, old.head) == (0.78, 1.68)
    assert set(ALIASES.values()) <= set(FIELD_PARAMS)


def test_a_field_and_its_short_name_both_given_is_refused():
    with pytest.raises(deathsphere.ParameterError, match="com_height or its short name h") as err:
        Machine(mass=100, h=0.8, com_height=0.8, a=0.3)
    assert err.value.param == "com_height"


def test_overrides_take_the_registrys_names_and_the_fields():
    m = machine_presets.stunt125()
    assert m.with_overrides(a=0.32).wheel_radius == m.with_overrides(wheel_radius=0.32).wheel_radius == 0.32
    assert m.with_overrides(com_height="70cm").com_height == pytest.approx(0.7)


def test_the_api_names_are_the_records():
    assert deathsphere.Machine is Machine is api_machines.Machine
    assert api_machines.PRESETS is machine_presets.PRESETS
    assert api_machines.machine_file is decode.decode_machine_file
    for name in ("stunt125", "DEFAULT_MACHINE", "echoable_text", "machine_file_data", "machine_file_text",
                 "UNECHOABLE", "FILE_KEYS", "as_machine", "paper_wheel", "benchmark_bicycle_rigid"):
        assert hasattr(api_machines, name), name
    assert len(deathsphere.api.machines_table()) >= len(machine_presets.PRESETS)
