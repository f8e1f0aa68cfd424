"""The least clearance of every pair of riders over the act (beyond the
paper; docs/show.md, "Clearance"), with no minimum missed between samples."""

from __future__ import annotations


def least_clearance(lane_a, lane_b, duration, *, clock_a=1.0):
    """The least clearance [m] of two lanes' envelopes over [0, duration],
    when it happens [s], and the basis ('act' or 'geometric').  Not yet
    implemented."""
    raise NotImplementedError("deathsphere.show.pairs.least_clearance is being written")


def pairs_table(lanes, duration, min_clearance):
    """The ``pairs`` table (columns :data:`deathsphere.api.show.PAIR_COLUMNS`).
    Not yet implemented."""
    raise NotImplementedError("deathsphere.show.pairs.pairs_table is being written")
