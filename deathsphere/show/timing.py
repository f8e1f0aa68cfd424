"""Timing the vertical riders through the horizontal lanes, and the drift
of a rider whose speedometer reads 1 % off (beyond the paper; docs/show.md)."""

from __future__ import annotations


def auto_phases(lanes, duration, min_clearance):
    """Each vertical rider's phase [deg], in plan order, maximising the least
    clearance, and the windows of safe phases.  Not yet implemented."""
    raise NotImplementedError("deathsphere.show.timing.auto_phases is being written")


def drift_time(lane_a, lane_b, min_clearance, error=0.01):
    """Time [s] until a clear pair first comes closer than min_clearance
    with rider A running ``error`` fast or slow, the worse (inf: never).
    Not yet implemented."""
    raise NotImplementedError("deathsphere.show.timing.drift_time is being written")
