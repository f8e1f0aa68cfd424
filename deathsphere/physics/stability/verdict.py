"""Stability verdicts: the codes and the tolerances that decide them (beyond
the paper; docs/stability.md sec. 1).

An orbit is called stable when its growth rate is at most STABLE_TOL of its
rate scale, unstable when at least UNSTABLE_TOL, unknown between.
"""

from __future__ import annotations

from enum import IntEnum

import numpy as np

__all__ = ["Verdict", "VERDICT_LABELS", "STABLE_TOL", "UNSTABLE_TOL", "verdict_from_growth", "STABILITY_KINDS",
           "stability_kind"]


class Verdict(IntEnum):
    """Stability verdict codes (column ``stability`` of the CLI); beyond the
    paper, tolerances in docs/stability.md sec. 1."""

    STABLE = 0
    UNSTABLE = 1
    UNKNOWN = 2

    @property
    def label(self) -> str:
        return self.name.lower()


VERDICT_LABELS = np.array([v.label for v in Verdict], dtype=object)

#: growth rate / rate scale at or below which an orbit is called stable.
#: The spectrum of an exact stable orbit is purely imaginary (the flow is
#: reversible); round-off gives real parts ~1e-15 of the rate scale for simple
#: eigenvalues and up to ~1e-8 where two frequencies collide (a defective
#: double eigenvalue: error ~ sqrt(eps)).  Measured worst case over 224 895
#: orbits of the survey grids: 3.8e-10 (docs/stability.md).
STABLE_TOL = 1e-7
#: growth rate / rate scale at or above which an orbit is called unstable
#: (measured smallest on the same grids: 3.8e-4).  Between the two the verdict
#: is "unknown": the growth rate rises like the square root of the distance to
#: a stability boundary, so such an orbit lies within ~1e-10 (relative) of one.
UNSTABLE_TOL = 1e-5


def verdict_from_growth(growth, scale):
    """Verdict codes (int8 :class:`Verdict`) from growth rates [1/s] and rate
    scales [1/s]: stable where growth/scale <= STABLE_TOL, unstable where
    >= UNSTABLE_TOL, unknown between and where either is NaN.

    Beyond the paper: the verdict's tolerances, docs/stability.md sec. 1.
    """
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = growth / scale
    verdict = np.full(growth.shape, Verdict.UNKNOWN, dtype=np.int8)
    verdict[np.nan_to_num(rel, nan=np.inf) <= STABLE_TOL] = Verdict.STABLE
    verdict[np.nan_to_num(rel, nan=-np.inf) >= UNSTABLE_TOL] = Verdict.UNSTABLE
    return verdict


#: The words of :func:`stability_kind`, column ``stability_kind``: what a
#: disturbance does, where "stable" alone (no mode grows) does not say.
STABILITY_KINDS = ("damped", "neutral", "growing", "unknown")


def stability_kind(growth, scale):
    """What a small disturbance does, from growth rates [1/s] (the largest
    real part of the linearised spectrum) and rate scales [1/s], with the
    verdict's tolerances: ``damped`` where growth/scale < -STABLE_TOL (every
    mode decays), ``neutral`` where |growth/scale| <= STABLE_TOL (the
    largest real part zero to the tolerance: a disturbance persists, as on
    the paper's stable orbits, whose spectrum is imaginary), ``growing``
    where >= UNSTABLE_TOL (unstable), ``unknown`` between (as the verdict's),
    '' where the growth rate is NaN (not analysed).  A zero scale with a
    zero growth rate is neutral.  An object array of those words.

    Beyond the paper: docs/stability.md sec. 1 (the tolerances).
    """
    growth = np.asarray(growth, dtype=float)
    scale = np.broadcast_to(np.asarray(scale, dtype=float), growth.shape)
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = np.where(scale > 0, growth / np.where(scale > 0, scale, 1.0), np.where(growth == 0, 0.0, np.nan))
    out = np.full(growth.shape, "unknown", dtype=object)
    with np.errstate(invalid="ignore"):
        out[rel < -STABLE_TOL] = "damped"
        out[np.abs(rel) <= STABLE_TOL] = "neutral"
        out[rel >= UNSTABLE_TOL] = "growing"
    out[np.isnan(growth)] = ""
    return out
