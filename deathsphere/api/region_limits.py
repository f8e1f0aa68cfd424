"""The allowed region and the rider's limits: ``map`` and ``limits``."""

from __future__ import annotations

from deathsphere.api.arguments import (
    INF,
    A,
    G,
    R,
    checked_axis,
    checked_choice,
    checked_scalar,
    checked_setup,
    is_given,
)
from deathsphere.constants import (
    SIDES,
)
from deathsphere.params import ParameterError
from deathsphere.table import Table

#: theta values :func:`limits` evaluates at once (each a root search).
MAX_LIMIT_THETAS = 100_000


def _ratio(a, r, side) -> tuple[float, float]:
    """The body radius over the sphere radius (all the map depends on), to
    15 significant digits so that ``-a 0.3 -r 3`` is the 0.1 a user reads
    (0.3 / 3.0 is 0.09999999999999999 in float64), and the inertia factor."""
    side = checked_choice("side", side, SIDES)
    setup = checked_setup("wheel", side, a, r, None, G, INF)
    return float(f"{setup.a / setup.r:.15g}"), side


def region(a=A, r=R, *, k=0.5, side: str = "inside", mu=INF, max_g=INF, step=0.5, stability: bool = False,
           jobs: int = 1, progress=None) -> Table:
    """The allowed (theta, alpha) region of a wheel as data: ``deathsphere map --format csv``.

    Its boundaries are the paper's: eq. (0) (the wheel fits; outside eq. 81),
    eq. (29) (Omega^2 > 0) and eq. (33) (contact; outside eq. 83); the
    friction and g-load limits and the stability boundary are beyond the
    paper (docs/limits.md, docs/stability.md).  The region depends on the
    radii only through a/r (the paper's figure: 0.1).

    Parameters
    ----------
    a, r : float
        Wheel and sphere radius [m] (inside: r > a).
    k : float
        Inertia factor.
    side : {"inside", "outside"}
    mu : float
        Also the friction limit mu_required = mu (``inf``: none).
    max_g : float
        Also the g-load limit accel_g = max_g [g] (``inf``: none).
    step : float
        theta step of the data [deg], 0.001..10.
    stability : bool
        Also the curve ``stability`` (slow: exact linearisation).
    jobs : int
        Processes computing the stability boundary (same values as with one).
    progress : callable, optional
        ``progress(done, total)`` as blocks of thetas of the stability
        boundary are done (the slow part).

    Returns
    -------
    Table
        One row per boundary point: ``curve``, ``equation``, ``theta_deg``,
        ``alpha_deg`` (root-found to 1e-9 rad), ``a_over_r``, ``k``.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.region(step=10)
    >>> sorted(set(t["curve"])), float(t["a_over_r"][0])
    (['eq0', 'eq29', 'eq33'], 0.1)
    """
    from deathsphere.results.limits import boundary_table, boundary_thetas

    a_over_r, side = _ratio(a, r, side)
    values = {name: checked_scalar(name, v) for name, v in (("k", k), ("mu", mu), ("max_g", max_g), ("step", step),
                                                      ("jobs", jobs))}
    tick = None
    if progress is not None:
        total, done = boundary_thetas(values["step"]).size, [0]

        def tick(n):
            done[0] += n
            progress(done[0], total)
    return boundary_table(a_over_r, values["k"], side == "outside", values["mu"], values["max_g"], values["step"],
                          stability=bool(stability), progress=tick, jobs=int(values["jobs"]))


def region_cells(a=A, r=R, *, k=0.5, side: str = "inside", mu=INF, max_g=INF, stability: bool = False,
                 columns: int = 72, rows=None):
    """The allowed region on a grid of cells: what ``deathsphere map`` draws
    on a terminal (:mod:`deathsphere.render.charplot`).

    The boundaries of :func:`region` sampled on ``columns`` theta cells and
    ``rows`` alpha cells (None: the map's default), each cell marked
    feasible or not and, with ``stability``, stable or not (beyond the paper).

    Returns
    -------
    deathsphere.results.region_map.CellMap

    Examples
    --------
    >>> import deathsphere
    >>> cells = deathsphere.region_cells(columns=36)
    >>> cells.feasible.shape[1], bool(cells.feasible.any())
    (36, True)
    """
    from deathsphere.results.region_map import cell_map

    a_over_r, side = _ratio(a, r, side)
    values = {name: checked_scalar(name, v) for name, v in (("k", k), ("mu", mu), ("max_g", max_g))}
    try:
        return cell_map(a_over_r, 1.0, values["k"], outside=side == "outside", mu=values["mu"],
                        max_g=values["max_g"], stability=bool(stability), resolution=(int(columns), rows))
    except ValueError as exc:
        raise ParameterError(str(exc)) from None


def region_curves(a=A, r=R, *, k=0.5, side: str = "inside", mu=INF, max_g=INF, stability: bool = False):
    """The allowed region as curves: what ``deathsphere map --output FILE``
    draws (:mod:`deathsphere.render.map_figure`; the paper's figure).

    Returns
    -------
    deathsphere.results.region_map.CurveMap
        The allowed alpha intervals, the boundary polylines and, with
        ``stability``, the stability margin on a 0.25 deg grid and its
        zero contour (beyond the paper).  Needs contourpy (the plot extra).
    """
    from deathsphere.results.region_map import curve_map

    a_over_r, side = _ratio(a, r, side)
    values = {name: checked_scalar(name, v) for name, v in (("k", k), ("mu", mu), ("max_g", max_g))}
    return curve_map(a_over_r, 1.0, values["k"], outside=side == "outside", mu=values["mu"],
                     max_g=values["max_g"], stability=bool(stability))


def limits(theta=None, *, a=A, r=R, k=None, g=G, mu=INF, max_g=INF, side: str = "inside") -> Table:
    """The feasible tilts at theta, or the highest orbit: ``deathsphere limits``.

    Beyond the paper (method: docs/limits.md), from its conditions eqs. (0),
    (29), (33) (outside (81), (83)), the friction needed (eq. 35) and the
    g-load (eq. 36).

    Parameters
    ----------
    theta : float, array_like or str, optional
        Polar angle(s) of the orbit [deg]: values or ``"start:stop:step"``
        text as for :func:`sweep`, at most 100000.  Without it: the highest
        orbit possible (the smallest theta with a feasible tilt).
    a, r, k, g, mu, side : as for :func:`orbit` (a wheel; one value each).
    max_g : float
        Largest centre acceleration the rider takes [g] (``inf``: no limit).

    Returns
    -------
    Table
        With ``theta``: one row per interval of alpha with a feasible orbit
        (``alpha_min_deg``, ``alpha_max_deg``, the speed range
        ``v_min_m_s``..``v_max_m_s``), a theta without any giving one row
        with ``intervals`` = 0 (flat: a theta may have several intervals).
        Without: one row (``found``, ``theta_deg``, ``alpha_deg``,
        ``v_cm_m_s``, ``note``).

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.limits(60, mu=1.2)
    >>> int(t["intervals"][0]), round(float(t["alpha_max_deg"][0]), 3)
    (1, 10.104)
    """
    from deathsphere.results.limits import highest_orbit_table, intervals_table

    setup = checked_setup("wheel", side, a, r, k, g, mu)
    max_g = checked_scalar("max_g", max_g)
    if not is_given(theta):
        return highest_orbit_table(setup, max_g)
    thetas = checked_axis("theta", theta)
    if len(thetas) > MAX_LIMIT_THETAS:
        raise ParameterError(f"theta: {len(thetas)} values, more than {MAX_LIMIT_THETAS} (each is a root search)",
                             "theta")
    return intervals_table(setup, thetas.values(), max_g)
