"""Branch and bound on a Lipschitz bound: the one search under the show's
least clearances and drift times (beyond the paper; docs/show.md,
"Clearance").

A function f changing no faster than L, sampled at c_i and c_j a step w
apart, is at least (c_i + c_j)/2 - L w/2 between them.  An interval whose
bound the caller still cares about is split into :data:`SPLIT` and sampled
again, until none is left: no dip of f is missed.  What "cares about"
means is the caller's: below the least sample so far (the least value,
:func:`deathsphere.act.pairs.refine`), or below a level before the first
time found under it (:func:`deathsphere.act.timing.first_below`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import numpy as np

__all__ = ["SPLIT", "refine_intervals"]

#: Each interval kept is split into this many.
SPLIT = 8


def refine_intervals(f: Callable, x, c, width: float, lipschitz: float,
                     keep: Callable) -> Iterator[tuple[np.ndarray, np.ndarray]]:
    """Refine the intervals between the evenly spaced samples ``x`` (``width``
    apart) with values ``c`` of a vectorised ``f`` changing at most at
    ``lipschitz``.  Each round keeps the intervals where ``keep(left,
    bound)`` is true (``left`` their left ends, ``bound`` the least f can
    reach on them), splits those into :data:`SPLIT` and yields the new
    interior points and f there, (k, SPLIT - 1) each; it ends when no
    interval is kept.  ``keep`` is called afresh each round, so a caller
    may tighten what it keeps from what the rounds yield."""
    left, cl, cr = x[:-1], c[:-1], c[1:]
    while left.size:
        kept = keep(left, 0.5 * (cl + cr) - 0.5 * lipschitz * width)
        if not kept.any():
            return
        left, cl, cr = left[kept], cl[kept], cr[kept]
        width /= SPLIT
        inner = left[:, None] + width * np.arange(1, SPLIT)
        ci = f(inner.reshape(-1)).reshape(inner.shape)
        yield inner, ci
        values = np.concatenate((cl[:, None], ci, cr[:, None]), axis=1)
        left = (left[:, None] + width * np.arange(SPLIT)).reshape(-1)
        cl, cr = values[:, :-1].reshape(-1), values[:, 1:].reshape(-1)
