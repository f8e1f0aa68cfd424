"""The viewer's event statuses are the simulation's: every body's run
(the paper's, a machine's, the two-wheeler's) ends in one RunStatus
vocabulary, and the viewer, which reads tables only, writes its part out."""

from deathsphere.simulation.status import ENDED_EARLY, ENDED_EARLY_LABELS, STATUSES, RunStatus
from deathsphere.viewer.scene import EVENT_STATUSES


def test_viewer_event_statuses_are_the_simulations():
    assert EVENT_STATUSES == ENDED_EARLY_LABELS
    assert set(EVENT_STATUSES) <= set(STATUSES)
    assert ENDED_EARLY_LABELS == tuple(RunStatus(s).label for s in ENDED_EARLY)
