"""The allowed region and the rider's limits: ``map`` and ``limits``."""

from __future__ import annotations

import math
from functools import partial

from deathsphere.api.arguments import (
    CHUNK,
    INF,
    A,
    G,
    R,
    broadcast_flat,
    checked_array,
    checked_axis,
    checked_choice,
    checked_scalar,
    checked_setup,
    grid_shape,
    is_given,
    one_default,
    raise_if_all_invalid,
    refuse_large_grid,
    sphere_radius,
)
from deathsphere.api.streams import Chunks, cluster_of, input_requests, request_reader
from deathsphere.constants import (
    SIDES,
)
from deathsphere.params import ParameterError
from deathsphere.records.paper_bodies import WHEEL, Wheel
from deathsphere.requests.decode import decode_paper_body
from deathsphere.table import Table

#: theta values :func:`limits` evaluates at once (each a root search).
MAX_LIMIT_THETAS = 100_000


def _ratio(a, r, side, g=G, diameter=None) -> tuple[float, float]:
    """The body radius over the sphere radius (all the map depends on), to
    15 significant digits so that ``-a 0.3 -r 3`` is the 0.1 a user reads
    (0.3 / 3.0 is 0.09999999999999999 in float64), and the inertia factor."""
    side = checked_choice("side", side, SIDES)
    # g is checked but changes nothing: the region's angles and the load
    # in g do not depend on it (it scales every speed by sqrt(g))
    setup = checked_setup(WHEEL, side, a, sphere_radius(r, diameter), None, g, INF)
    return float(f"{setup.a / setup.r:.15g}"), side


def region(a=A, r=R, *, k=0.5, side: str = "inside", mu=INF, max_g=INF, g=G, diameter=None, step=None,
           stability: bool = False,
           jobs: int = 1, progress=None, scheduler=None, **arena) -> Table:
    """The allowed (theta, alpha) region of a wheel as data: ``deathsphere map --format csv``.

    Its boundaries are the paper's: eq. (0) (the wheel fits; outside eq. 81),
    eq. (29) (Omega^2 > 0) and eq. (33) (contact; outside eq. 83); the
    friction and load limits and the stability boundary are beyond the
    paper (docs/limits.md, docs/stability.md).  The region depends on the
    radii only through a/r (the paper's figure: 0.1).

    Parameters
    ----------
    a, r : float
        Wheel and sphere radius [m] (inside: r > a); or ``diameter``, the sphere's.
    g : float
        Gravity [m/s^2]: checked, but the region does not depend on it.
    k : float
        Inertia factor.
    side : {"inside", "outside"}
    mu : float
        Also the friction limit mu_required = mu (``inf``: none).
    max_g : float
        Also the load limit load_g = max_g [g] (``inf``: none; docs/limits.md).
    step : float
        theta step of the data [deg], 0.001..10 (default 0.5).
    **arena : surface, wall_angle, wall_height, profile, height, turn_radius
        Off the globe (docs/limits.md sec. 8): the region in (lane, alpha)
        on that arena, :func:`deathsphere.api.lane_map.region_on` (the
        lanes ``height``, or ``turn_radius`` on flat ground, in place of
        theta; ``stability`` adds the curve ``stability`` along each lane,
        its batches of 16 lanes on ``jobs`` processes or ``scheduler``'s
        cluster, ``progress`` told in lanes).
    stability : bool
        Also the curve ``stability`` (slow: exact linearisation).
    jobs : int
        Processes computing the stability boundary (same values as with one).
    scheduler : str or distributed.Client, optional
        Compute the stability boundary on a dask.distributed cluster (its
        scheduler's address or a Client; the ``distributed`` extra): the
        same values as a local run.  Not with ``jobs`` > 1.
    progress : callable, optional
        ``progress(done, total)`` as blocks of thetas (off the globe: of
        lanes) of the stability boundary are done (the slow part).

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
    from deathsphere.results.limits import boundary_table, theta_grid

    if _off_globe(arena):
        from deathsphere.api.lane_map import region_on

        return region_on(dict(arena, a=a, r=r, diameter=diameter, k=k, g=g, side=side, mu=mu, max_g=max_g,
                              stability=stability, step=step, jobs=jobs, scheduler=scheduler, progress=progress))
    step = 0.5 if step is None else step
    a_over_r, side = _ratio(a, r, side, g, diameter)
    values = {name: checked_scalar(name, v) for name, v in (("k", k), ("mu", mu), ("max_g", max_g), ("step", step),
                                                      ("jobs", jobs))}
    cluster = cluster_of(scheduler, int(values["jobs"])) if stability else None
    tick = None
    if progress is not None:
        total, done = theta_grid(values["step"]).size, [0]

        def tick(n):
            done[0] += n
            progress(done[0], total)
    return boundary_table(a_over_r, values["k"], side == "outside", values["mu"], values["max_g"], values["step"],
                          stability=bool(stability), progress=tick, jobs=int(values["jobs"]),
                          cluster=cluster)


def region_cells(a=A, r=R, *, k=0.5, side: str = "inside", mu=INF, max_g=INF, g=G, diameter=None,
                 stability: bool = False,
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

    a_over_r, side = _ratio(a, r, side, g, diameter)
    values = {name: checked_scalar(name, v) for name, v in (("k", k), ("mu", mu), ("max_g", max_g))}
    try:
        return cell_map(a_over_r, 1.0, values["k"], outside=side == "outside", mu=values["mu"],
                        max_g=values["max_g"], stability=bool(stability), resolution=(int(columns), rows))
    except ValueError as exc:
        raise ParameterError(str(exc)) from None


def region_curves(a=A, r=R, *, k=0.5, side: str = "inside", mu=INF, max_g=INF, g=G, diameter=None,
                  stability: bool = False, jobs: int = 1, scheduler=None, progress=None, **arena):
    """The allowed region as curves: what ``deathsphere map --output FILE``
    draws (:mod:`deathsphere.render.map_figure`; the paper's figure).

    Returns
    -------
    deathsphere.results.region_map.CurveMap
        The allowed alpha intervals, the boundary polylines and, with
        ``stability``, the stability margin on a 0.25 deg grid and its
        zero contour (beyond the paper).  Needs contourpy (the plot extra).
        Off the globe (``surface`` ... in ``arena``, as for :func:`region`):
        a :class:`deathsphere.results.lane_map.LaneCurves`, its stability
        boundary on ``jobs`` processes or ``scheduler``'s cluster with
        ``progress`` as for :func:`region` (the same curves as with one).
        On the globe the curves are drawn on grids of their own in one
        process: ``jobs`` other than 1 or a ``scheduler`` is refused there,
        and ``progress`` is not told.
    """
    from deathsphere.results.region_map import curve_map

    if _off_globe(arena):
        from deathsphere.api.lane_map import region_curves_on

        return region_curves_on(dict(arena, a=a, r=r, diameter=diameter, k=k, g=g, side=side, mu=mu, max_g=max_g,
                                     stability=stability, jobs=jobs, scheduler=scheduler, progress=progress))
    if scheduler is not None or int(checked_scalar("jobs", jobs)) != 1:
        raise ParameterError("on the sphere the figure's curves are drawn on grids of their own in one process: "
                             "jobs and scheduler are the boundary data's (region) or another surface's",
                             "scheduler" if scheduler is not None else "jobs")
    a_over_r, side = _ratio(a, r, side, g, diameter)
    values = {name: checked_scalar(name, v) for name, v in (("k", k), ("mu", mu), ("max_g", max_g))}
    return curve_map(a_over_r, 1.0, values["k"], outside=side == "outside", mu=values["mu"],
                     max_g=values["max_g"], stability=bool(stability))


def limits(theta=None, *, body: str = "wheel", side: str = "inside", a=A, r=R, k=None, g=G, mu=INF, max_g=INF,
           diameter=None, surface=None, height=None, turn_radius=None, wall_angle=None, wall_height=None,
           profile=None) -> Table:
    """The feasible tilts at theta, or the highest orbit: ``deathsphere limits``.

    Beyond the paper (method: docs/limits.md), from its conditions eqs. (0),
    (29), (33) (outside (81), (83)), the friction needed (eq. 35) and the
    load on the rider (load_g = sqrt(1 + accel_g^2), eqs. 32 and 36).

    Parameters
    ----------
    theta : float, array_like or str, optional
        Polar angle(s) of the orbit [deg]: values or ``"start:stop:step"``
        text as for :func:`sweep`, at most 100000.  Without it: the highest
        orbit possible (the smallest theta with a feasible tilt).
    body : {"wheel"}
        Only a wheel has a tilt to choose; another body is refused.
    side, a, r, k, g, mu, diameter : as for :func:`orbit`.
    surface, wall_angle, wall_height, profile : the arena, as for :func:`orbit`
        (docs/surfaces.md); off the globe the lane is ``height`` (on flat
        ground ``turn_radius``) in place of theta, and without one the
        answer is the lowest and the highest lane
        (:func:`deathsphere.api.lane_limits.limits_on`, docs/limits.md sec. 8).
    height, turn_radius : float, array_like or str, optional
        The lanes off the globe [m] (values or ``start:stop:step`` text).
    max_g : float or array_like
        Largest centre acceleration the rider takes [g] (``inf``: no limit).
        The numeric arguments broadcast against each other (a text range of
        theta is one axis of values); each element is one request.

    Returns
    -------
    Table
        With ``theta``: one row per interval of alpha with a feasible orbit
        (``alpha_min_deg``, ``alpha_max_deg``, the speed range
        ``v_min_m_s``..``v_max_m_s``), a theta without any giving one row
        with ``intervals`` = 0 (flat: a theta may have several intervals).
        Without: one row per setup (``found``, ``theta_deg``, ``alpha_deg``,
        ``v_cm_m_s``, ``note``).  Then ``input_row`` (the request's flat
        index + 1), ``body``, ``side``, ``status`` and ``reason``.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.limits(60, mu=1.2)
    >>> int(t["intervals"][0]), round(float(t["alpha_max_deg"][0]), 3)
    (1, 10.104)
    >>> t = deathsphere.limits([60, 90], mu=[[1.2], [2.0]])
    >>> t["input_row"].tolist(), t["mu_available"].tolist()
    ([1, 2, 3, 4], [1.2, 1.2, 2.0, 2.0])
    """
    from deathsphere.model import make_requests
    from deathsphere.requests.arena import names_a_wall
    from deathsphere.results.limits import limits_rows

    if names_a_wall(surface, wall_angle, wall_height, profile):
        from deathsphere.api.lane_limits import limits_on

        return limits_on(dict(surface=surface, height=height, turn_radius=turn_radius, theta=theta,
                              wall_angle=wall_angle, wall_height=wall_height, profile=profile, body=body, side=side,
                              a=a, r=r, diameter=diameter, k=k, g=g, mu=mu, max_g=max_g))
    _globe_lane(height, turn_radius)
    body, side = decode_paper_body(body), checked_choice("side", side, SIDES)
    if not isinstance(body, Wheel):
        from deathsphere.results.limits import NOT_A_WHEEL

        raise ParameterError(NOT_A_WHEEL, "body")
    r = sphere_radius(r, diameter)
    given = {"a": a, "r": r, "k": k, "g": g, "mu": mu, "max_g": max_g}
    if is_given(theta):
        thetas = theta
        if isinstance(theta, str) or (isinstance(theta, (list, tuple)) and any(isinstance(v, str) for v in theta)):
            thetas = checked_axis("theta", theta).values() if len(checked_axis("theta", theta)) <= MAX_LIMIT_THETAS \
                else _too_many([len(checked_axis("theta", theta))])
        given["theta"] = thetas
    checked = {name: checked_array(name, v) for name, v in given.items() if v is not None}
    _too_many(grid_shape(checked))
    shape, flat = broadcast_flat(checked)
    n = math.prod(shape)
    req = make_requests(n, body=body, side=side, **flat)
    table = limits_rows(req, highest=not is_given(theta))
    return raise_if_all_invalid(table)


#: The keywords of an arena other than the globe (``region``, ``region_curves``).
ARENA_KEYS = ("surface", "wall_angle", "wall_height", "profile", "height", "turn_radius")


def _off_globe(arena: dict) -> bool:
    """True when ``arena`` (keywords of :data:`ARENA_KEYS`) names a surface
    other than the globe; an unknown keyword is refused naming it, a lane
    on the globe too (the globe's map runs over theta)."""
    from deathsphere.requests.arena import names_a_wall

    for key in arena:
        if key not in ARENA_KEYS:
            raise TypeError(f"unexpected keyword argument {key!r}")
    if names_a_wall(arena.get("surface"), arena.get("wall_angle"), arena.get("wall_height"), arena.get("profile")):
        return True
    _globe_lane(arena.get("height"), arena.get("turn_radius"))
    return False


def _globe_lane(height, turn_radius):
    """On the globe ``limits`` and ``map`` name a lane by theta: a height or a turn
    radius is refused, naming it."""
    for name, value in (("height", height), ("turn_radius", turn_radius)):
        if is_given(value):
            raise ParameterError(f"{name}: on the sphere the lane is theta (a height or a turn radius is a lane "
                                 "on another surface: choose it with surface)", name)


def _too_many(counts):
    """Refuse, from the counts alone, more thetas than one call searches."""
    return refuse_large_grid(counts, command="limits", limit=MAX_LIMIT_THETAS, param="theta",
                             instead="each is a root search; split the theta range into several runs")


def limits_input(source, *, theta=None, body=None, side=None, a=None, r=None, k=None, g=None, mu=None, max_g=None,
                 diameter=None, chunk_size: int = CHUNK, surface=None, height=None, turn_radius=None,
                 wall_angle=None, wall_height=None, profile=None) -> Chunks:
    """The limits of the requests in a CSV file: ``deathsphere limits --input
    FILE``.  Its header names ``theta`` (required in every row) and
    optionally ``body``, ``side``, ``a``, ``r``, ``k``, ``g``, ``mu``,
    ``max_g``; an option given applies to every row (as for
    :func:`deathsphere.orbit_input`).  Each request gives its intervals,
    numbered by ``input_row``; a bad line, or a body other than a wheel, is
    one ``invalid`` row with the reason.  Off the globe (``surface`` ...)
    the rows' lanes are ``height``: :func:`deathsphere.api.lane_limits.limits_on_input`."""
    from deathsphere.inputs import ALIASES
    from deathsphere.model import REQUEST_FIELDS, make_requests
    from deathsphere.requests.arena import names_a_wall
    from deathsphere.results.limits import LIMITS_FIELDS, limits_rows

    if names_a_wall(surface, wall_angle, wall_height, profile):
        from deathsphere.api.lane_limits import limits_on_input

        return limits_on_input(source, dict(surface=surface, wall_angle=wall_angle, wall_height=wall_height,
                                            profile=profile, height=height, turn_radius=turn_radius, theta=theta,
                                            body=body, side=side, a=a, r=R if r is None else r, diameter=diameter,
                                            k=k, g=g, mu=mu, max_g=max_g), chunk_size=chunk_size)
    _globe_lane(height, turn_radius)

    overrides = {}
    if body is not None:
        overrides["body"] = decode_paper_body(body).word
    if side is not None:
        overrides["side"] = checked_choice("side", side, SIDES)
    for name, value in (("theta", theta), ("a", a), ("r", sphere_radius(r, diameter)), ("k", k), ("g", g),
                        ("mu", mu), ("max_g", max_g)):
        value = one_default(name, value)
        if value is not None:
            overrides[name] = value
    fields = {name: REQUEST_FIELDS[name] for name in LIMITS_FIELDS}
    reader = request_reader(source, fields, overrides, ALIASES, ())
    chunk_size = int(checked_scalar("chunk_size", chunk_size))

    def work(req):
        return limits_rows(req, highest=False)
    make = partial(make_requests, typed=reader.typed)     # a row's refusal names its column as typed
    return Chunks((n, work(req)) for n, req in input_requests(reader, chunk_size, make))
