"""Every body model keeps the one protocol (simulation.body.Body): the
paper's bodies, the machines and the two-wheeler; their events are Event
records ending a body with a RunStatus, and one solve_ivp call serves them
all (beyond the paper; docs/simulation.md, "Bodies", "Events")."""

import pathlib

import numpy as np

import deathsphere
from deathsphere.model import Setup
from deathsphere.simulation import horizontal_starts
from deathsphere.physics.ground import Cylinder, Plane
from deathsphere.records.paper_bodies import WHEEL
from deathsphere.simulation.bodies import MACHINE, ON_GROUND, PAPER
from deathsphere.simulation.ground_starts import ground_starts
from deathsphere.simulation.body import Body
from deathsphere.simulation.event import Event
from deathsphere.simulation.status import RunStatus
from deathsphere.simulation.two_wheeler import TWO_WHEELER


def test_every_model_keeps_the_protocol():
    for model in (PAPER, MACHINE, ON_GROUND, TWO_WHEELER):
        assert isinstance(model, Body), model.name
        assert len(model.state_names) == len(model.state_units)


def test_the_events_are_event_records_with_run_statuses():
    starts = horizontal_starts(Setup(), 60.0, 10.0)
    events = PAPER.terminal_events(starts.params, np.array([10.0]))   # ample friction: neither event is past
    assert [e.status for e in events] == [RunStatus.CONTACT_LOST, RunStatus.SLIPS]
    for e in events:
        assert isinstance(e, Event) and e.terminal and e.direction == -1 and e.reason == e.status.reason
        assert e(0.0, starts.state.reshape(-1)) > 0


def test_a_wall_adds_its_floor_and_top_and_flat_ground_neither():
    on_drum = ground_starts(Cylinder(5.0, 3.0), WHEEL, 2.0, {"alpha_deg": 20.0}, a=0.3, k=0.5, g=9.81)
    events = ON_GROUND.terminal_events(on_drum.params, np.array([10.0]))
    assert [e.status for e in events] == [RunStatus.CONTACT_LOST, RunStatus.SLIPS, RunStatus.HITS_FLOOR,
                                          RunStatus.OVER_THE_TOP]
    y = on_drum.state.reshape(-1)
    # on the steady orbit 2 m up a 3 m wall: the contact 1 m below the top; the centre a sin(alpha)
    # above the contact (eq. 11: e3 = cos(alpha) r - sin(alpha) z) and the rim's lowest point
    # a sqrt(1 - e1_z^2) = a sin(alpha) below the centre, so 2 m above the floor
    assert abs(events[3](0.0, y) - 1.0) < 1e-12
    assert abs(events[2](0.0, y) - 2.0) < 1e-12
    flat = ground_starts(Plane(), WHEEL, 5.0, {"alpha_deg": 45.0}, a=0.3, k=0.5, g=9.81)
    assert len(ON_GROUND.terminal_events(flat.params, np.array([10.0]))) == 2


def test_one_solve_ivp_call_in_the_package():
    root = pathlib.Path(deathsphere.__file__).parent
    calls = [p.relative_to(root).as_posix() for p in root.rglob("*.py")
             for line in p.read_text(encoding="utf-8").splitlines() if "solve_ivp(" in line.split("#")[0]
             and not line.lstrip().startswith(("#", "``"))]
    assert calls == ["simulation/integrator.py"]
