"""The allowed (lane, alpha) region of a wheel on a surface other than the
globe, for ``map --surface``: the boundaries as data and the region as a
figure's curves (beyond the paper; docs/limits.md sec. 8; physics in
:mod:`deathsphere.physics.lane_region`).  Plain data; the figure is drawn by
:mod:`deathsphere.render.lane_map_figure`."""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import partial

import numpy as np

from deathsphere.physics import lane_region
from deathsphere.physics.revolution import lane
from deathsphere.results.limits import _degrees
from deathsphere.table import Table

#: Lanes of a map when none are given.
DEFAULT_LANES = 361
#: With no top, a map spans this many of the ground's length scale
#: (its radius; on flat ground the wheel's radius).
NO_TOP_SPAN = {True: 4.0, False: 20.0}

#: Boundary name -> its equation, in words (docs/surfaces.md, the paper's on the globe).
EQUATIONS = {
    "S4": "fit (S4; eq. 0 on the globe)",
    "S5": "floor (S5)",
    "S2": "Omega^2 = 0 or pole (S2 = eq. 29)",
    "S3": "contact (S3; eq. 33 on the globe)",
    "mu": "friction limit mu_required = mu (S3 and eq. 35)",
    "max_g": "load limit load_g = max_g (eqs. 32 and 36)",
    "stability": "stability boundary (exact linearisation)",
}
#: How far either side of a boundary point its two sides are tested [rad].
SIDE_STEP = 1e-7


def default_lanes(ground, a) -> np.ndarray:
    """The lanes [m] of a map when none are given: DEFAULT_LANES from the
    floor to the ground's highest lane or, with no top, over NO_TOP_SPAN
    of its length scale (first lane just off the floor, where a bowl's
    bottom is the axis)."""
    top = float(getattr(ground, "highest_lane", math.inf))
    if not math.isfinite(top):
        radius = getattr(ground, "radius", None)
        scale = float(radius) if radius else float(a)
        top = NO_TOP_SPAN[bool(radius)] * scale
    return np.linspace(0.0, top, DEFAULT_LANES)


def _x_of(ground, heights):
    """The map's abscissa: the lane's height above the floor and the
    contact's distance from the axis (flat ground's lane), the wall angle."""
    where = lane(ground, heights)
    return where["z"] - ground.lowest, where["rho"], np.rad2deg(where["wall_angle"])


def _boundaries(ground, heights, a, k, g, outside, mu, max_g, stability: bool, run=None) -> dict:
    """Each boundary's alphas (n, m) [rad] on the lanes, by name; with
    ``stability`` also ``stability``, where feasible orbits change from
    stable to unstable (the exact linearisation on that ground, bisected
    to 1e-10 rad between samples 0.25 deg apart, as on the globe), its
    batches of lanes run by ``run`` (a :class:`StabilityRun`; None: here)."""
    curves = lane_region.lane_boundaries(ground, heights, a, k, outside, mu, max_g)
    if stability:
        curves["stability"] = (run or StabilityRun()).crossings(ground, heights, a, k, g, outside, mu, max_g)
    return curves


@dataclass
class StabilityRun:
    """Where the stability boundary's batches of lanes run: ``jobs`` local
    processes, or a dask cluster (``cluster`` = ``(client, own)`` from
    :func:`deathsphere.cluster.connect`), through the house's one runner
    (:func:`deathsphere.parallel.ordered_map`, results in input order, so
    the values are those of one process); ``progress(n)`` is told as each
    batch of n lanes is done."""

    jobs: int = 1
    cluster: tuple | None = None
    progress: object = None

    def crossings(self, ground, heights, a, k, g, outside, mu, max_g) -> np.ndarray:
        from deathsphere.parallel import ordered_map
        from deathsphere.physics.stability.lane_margin import joined_crossings, lane_batches

        batches = lane_batches(heights)
        work = partial(_stability_batch, ground=ground, a=a, k=k, g=g, outside=outside, mu=mu, max_g=max_g)
        client, own = self.cluster if self.cluster is not None else (None, False)
        parts = []
        for batch, part in zip(batches, ordered_map(work, batches, self.jobs, client=client, close=own)):
            parts.append(part)
            if self.progress is not None:
                self.progress(batch.size)
        return joined_crossings(parts, heights.size)


def _stability_batch(heights, ground, a, k, g, outside, mu, max_g) -> np.ndarray:
    """The stability boundary on one batch of lanes (one unit of parallel work)."""
    from deathsphere.physics.stability.lane_margin import stability_crossings_on

    return stability_crossings_on(ground, heights, a, k, g, outside, mu, max_g)


def lane_boundary_table(ground, heights, a, k, g, outside, mu, max_g, stability: bool = False,
                        run: StabilityRun | None = None) -> Table:
    """Every boundary point of the allowed region at each lane, one row each:
    ``curve`` (S4, S5, S2, S3, mu, max_g; with ``stability`` also
    ``stability``), ``equation``, ``height_m``,
    ``alpha_deg``, and whether the orbit is feasible just below and just
    above it in alpha (``feasible_below``, ``feasible_above``: status ok of
    ``orbit --surface`` within mu, and the load within max_g, SIDE_STEP rad
    away), then the setup and the lane's ``rho_contact_m``, ``wall_angle_deg``;
    ``run``: where the stability boundary runs (:class:`StabilityRun`)."""
    heights = np.asarray(heights, dtype=float).reshape(-1)
    curves = _boundaries(ground, heights, a, k, g, outside, mu, max_g, stability, run)
    names, eqs, rows, alphas = [], [], [], []
    for name, alpha in curves.items():
        i, j = np.nonzero(np.isfinite(alpha))
        names.append(np.full(i.size, name, dtype=object))
        eqs.append(np.full(i.size, EQUATIONS[name], dtype=object))
        rows.append(i)
        alphas.append(alpha[i, j])
    row, alpha = np.concatenate(rows), np.concatenate(alphas)
    order = np.lexsort((alpha, row))              # lane by lane, alpha up
    row, alpha = row[order], alpha[order]
    lane_h = heights[row]
    below = lane_region.feasible_on(ground, lane_h, alpha - SIDE_STEP, a, k, g, outside, mu, max_g)
    above = lane_region.feasible_on(ground, lane_h, alpha + SIDE_STEP, a, k, g, outside, mu, max_g)
    lift, rho, beta = _x_of(ground, lane_h)
    n = row.size
    return Table({
        "curve": np.concatenate(names)[order], "equation": np.concatenate(eqs)[order],
        "height_m": lift, "alpha_deg": np.rad2deg(alpha),
        "feasible_below": below.astype(bool), "feasible_above": above.astype(bool),
        "a_m": np.full(n, float(a)), "k": np.full(n, float(k)),
        "mu_available": np.full(n, math.nan if math.isinf(mu) else float(mu)),
        "max_g": np.full(n, math.nan if math.isinf(max_g) else float(max_g)),
        "surface": np.full(n, ground.name, dtype=object), "rho_contact_m": rho, "wall_angle_deg": beta,
    })


@dataclass
class LaneCurves:
    """The allowed region for a figure: per lane ``x_m`` (the height above
    the floor, or on flat ground the turn radius: ``x_label`` says which),
    the allowed intervals ``lo_deg``, ``hi_deg`` (n, m) and ``count`` (n,);
    ``points``: curve name -> (x_m, alpha_deg) of its boundary points;
    the setup for the title; ``stable`` (with stability) the stable parts
    of the allowed intervals."""

    ground_name: str
    x_label: str
    x_m: np.ndarray
    lo_deg: np.ndarray
    hi_deg: np.ndarray
    count: np.ndarray
    points: dict
    a: float
    k: float
    outside: bool
    mu: float
    max_g: float
    #: with stability: the allowed intervals' stable parts per lane, (lo_deg, hi_deg) (n, m) NaN-padded
    stable: tuple | None = None


def lane_curves(ground, heights, a, k, g, outside, mu, max_g, stability: bool = False,
                run: StabilityRun | None = None) -> LaneCurves:
    """The allowed intervals and the boundary points at ``heights`` [m]
    (with ``stability`` the stability boundary's too, run by ``run`` as for
    :func:`lane_boundary_table`, and each allowed interval's stable parts)."""
    heights = np.asarray(heights, dtype=float).reshape(-1)
    iv = lane_region.allowed_alpha_on(ground, heights, a, k, g, outside, mu, max_g)
    lift, rho, _ = _x_of(ground, heights)
    on_flat = not hasattr(ground, "highest_lane")
    x = rho if on_flat else lift
    curves = _boundaries(ground, heights, a, k, g, outside, mu, max_g, stability, run)
    points = {}
    for name, alpha in curves.items():
        i, j = np.nonzero(np.isfinite(alpha))
        points[name] = (x[i], np.rad2deg(alpha[i, j]))
    stable = stable_parts(ground, heights, iv, curves["stability"], a, k, g, outside) if stability else None
    return LaneCurves(ground_name=ground.name,
                      x_label="turn radius of the contact [m]" if on_flat else "height of the lane [m]",
                      x_m=x, lo_deg=_degrees(iv.lo), hi_deg=_degrees(iv.hi), count=iv.count, points=points,
                      a=float(a), k=float(k), outside=bool(outside), mu=float(mu), max_g=float(max_g),
                      stable=stable)


def stable_parts(ground, heights, iv, crossings, a, k, g, outside):
    """Per lane, the parts of its allowed intervals where the orbit is
    stable: (lo_deg, hi_deg) arrays (n, m), NaN-padded.  Each allowed
    interval is cut at the stability boundary's alphas inside it and each
    piece's stability is its midpoint's sign of the margin (one batched
    call over every piece of every lane)."""
    from deathsphere.physics.stability.lane_margin import stability_margin_on

    n = heights.size
    cuts = np.sort(np.concatenate((np.where(np.isfinite(iv.lo), iv.lo, np.nan),
                                   np.where(np.isfinite(iv.hi), iv.hi, np.nan), crossings), axis=1), axis=1)
    left, right = cuts[:, :-1], cuts[:, 1:]
    mid = 0.5 * (left + right)
    inside = np.zeros(mid.shape, dtype=bool)
    for j in range(iv.lo.shape[1]):                          # the few intervals of a lane, not its orbits
        inside |= (mid > iv.lo[:, j:j + 1]) & (mid < iv.hi[:, j:j + 1])
    inside &= np.isfinite(mid)
    stable = np.zeros(mid.shape, dtype=bool)
    rows = np.broadcast_to(heights[:, None], mid.shape)
    stable[inside] = stability_margin_on(ground, rows[inside], mid[inside], a, k, g, outside) > 0
    lo, hi = np.full(mid.shape, np.nan), np.full(mid.shape, np.nan)
    lo[stable], hi[stable] = left[stable], right[stable]
    # the stable pieces of a lane, first ones first (the NaNs last)
    order = np.argsort(np.where(stable, left, np.inf), axis=1, kind="stable")
    lo, hi = np.take_along_axis(lo, order, axis=1), np.take_along_axis(hi, order, axis=1)
    keep = max(int(np.max(np.sum(stable, axis=1), initial=0)), 1)
    return _degrees(lo[:, :keep]).reshape(n, keep), _degrees(hi[:, :keep]).reshape(n, keep)
