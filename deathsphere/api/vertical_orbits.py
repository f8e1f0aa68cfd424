"""Vertical orbits of a wheel: ``vertical``, its sweep and its input file
(McDonald 1993 sec. 2.2.1)."""

from __future__ import annotations

import math
from functools import partial

import numpy as np

from deathsphere.api.arguments import (
    INF,
    A,
    G,
    R,
    broadcast_flat,
    checked_array,
    checked_axis,
    checked_choice,
    checked_flag,
    checked_grid_size,
    checked_scalar,
    checked_setup,
    checked_statuses,
    is_given,
    one_default,
    raise_if_all_invalid,
    sphere_radius,
)
from deathsphere.api.orbits import refuse_oversized
from deathsphere.api.streams import (
    Chunks,
    grid_requests,
    input_requests,
    request_reader,
)
from deathsphere.constants import (
    SIDES,
)
from deathsphere.params import ParameterError, shown_number
from deathsphere.records.paper_bodies import WHEEL
from deathsphere.table import Table

#: Output columns of ``vertical`` that echo an input, read back under that
#: input's name when a result CSV is fed to :func:`vertical_input` (every
#: other output column is ignored).  ``v_cm_m_s`` is the speed at the
#: azimuth ``phi_deg``: the top in the summary (which has no ``phi_deg``),
#: each point's own in the point-by-point output.
#: ``orbit``'s are :data:`deathsphere.inputs.ALIASES`.
VERTICAL_ECHO = {"theta_deg": "theta", "a_m": "a", "r_m": "r", "g_m_s2": "g", "mu_available": "mu",
                 "v_cm_m_s": "v_top", "phi_deg": "phi"}

#: The azimuth from the top at which a row's speed or rate is given: a
#: point of the point-by-point output read back (0, the top, otherwise).
PHI_FIELD = {"phi": (0.0, "deg", "azimuth from the top at which v_top or phidot_top is given")}

#: A speed at phi no top speed gives (eq. 27: the wheel gains speed on the way down).
SLOWER_THAN_FROM_REST = "the speed at phi is below that of a wheel starting from rest at the top (eq. 27)"


def requests_at_phi(n: int, invalid=None, input_row=None, phi=None, **fields) -> dict:
    """:func:`~deathsphere.results.vertical.vertical_requests` from rows that
    give the speed (``v_top``) or rate (``phidot_top``) at azimuth ``phi``
    [deg] from the top: taken back to the top by energy conservation,
    eq. (27), phidot_top^2 = phidot(phi)^2 - 4 g sin^2(phi/2) / ((2k+1) r').
    A point read back from ``vertical --points`` is a request for its orbit."""
    from deathsphere.physics.vertical_orbit import rate_squared, vertical_r_prime
    from deathsphere.results.vertical import vertical_requests

    req = vertical_requests(n, invalid=invalid, input_row=input_row, **fields)
    phi = np.broadcast_to(np.asarray(0.0 if phi is None else phi, dtype=float), (n,))
    rows = np.flatnonzero(np.nan_to_num(phi) != 0.0)
    if rows.size == 0:
        return req
    theta, outside = np.deg2rad(req["theta"][rows]), req["side"][rows] == "outside"
    a, r, k, g = (req[name][rows] for name in ("a", "r", "k", "g"))
    with np.errstate(all="ignore"):  # unchecked values: the evaluation gives their reasons
        gain = rate_squared(np.deg2rad(phi[rows]), theta, 0.0, a, r, k, g, outside)
        rp = vertical_r_prime(theta, a, r, outside)
        most = rate_squared(np.pi, theta, 0.0, a, r, k, g, outside)  # top to bottom
        gained = {"phidot_top": (gain, most), "v_top": (gain * rp ** 2, most * rp ** 2)}
        top = {name: req[name][rows] ** 2 - gained[name][0] for name in gained}
    for name, squared in top.items():
        given = np.isfinite(squared)
        # rounding in the output read back leaves a point a hair below the top's speed
        tolerance = 1e-9 * (req[name][rows] ** 2 + np.nan_to_num(gained[name][1]))
        req[name][rows] = np.where(given & (squared >= -tolerance), np.sqrt(np.maximum(squared, 0.0)), np.nan)
        slow = given & (squared < -tolerance) & (req["invalid"][rows] == "")
        req["invalid"][rows[slow]] = SLOWER_THAN_FROM_REST
    return req


#: Peak bytes per row of :func:`vertical`, measured with tracemalloc: a
#: summary row ~10 kB with stability (the Floquet integration over a lap),
#: ~0.9 kB without; a row of the point-by-point output ~0.3 kB.
VERTICAL_ROW_BYTES = {True: 10_200, False: 900}
POINT_ROW_BYTES = 300

#: Rows of the point-by-point output of a vertical orbit computed at once
#: (requests x points): a long orbit is written in slices of this many.
POINT_ROWS = 65536


def vertical(theta, v_top=None, *, phidot_top=None, side: str = "inside", a=A, r=R, k=0.5, g=G, mu=INF,
             diameter=None, points=None, only=None, stability: bool = True) -> Table:
    """Vertical orbits of a wheel: ``deathsphere vertical``.

    McDonald (1993) sec. 2.2.1: contact all the way round, eq. (28a); the
    forces and friction round the orbit, eqs. (26)-(28b); outside the sphere
    no vertical orbit closes and the row says where the wheel leaves the
    surface (from rest: eq. 82).  Stability (Floquet, over one lap) is
    beyond the paper: docs/stability.md.

    Parameters
    ----------
    theta : float or array_like
        Cone angle of the orbit about the horizontal axis [deg], 0..180
        (90: a vertical great circle).
    v_top : float or array_like, optional
        Speed of the wheel's centre at the top [m/s], >= 0.
    phidot_top : float or array_like, optional
        Orbital rate at the top [rad/s], >= 0 (give exactly one of
        ``v_top`` and ``phidot_top``).
    side : {"inside", "outside"}
    a, r, k, g, mu : float or array_like
        As for :func:`orbit` (k = 0.5 by default).
    points : int, optional
        Give the orbit point by point at ``points`` azimuths phi from the
        top (0) round to 360 deg (2..1e6) instead of one summary row.
    stability : bool
        Fill the stability columns of the summary.

    Returns
    -------
    Table
        The columns of ``deathsphere vertical --format csv``: one summary row
        per element of the broadcast (``shape`` the broadcast shape); with
        ``points``, ``points`` rows per request (``shape`` the broadcast
        shape + ``(points,)``; flat if some request is invalid, which gives
        one row).

    Raises
    ------
    ParameterError
        As for :func:`orbit`; also when the rows would need more than
        2 GiB (:data:`VERTICAL_ROW_BYTES`, :data:`POINT_ROW_BYTES` per row):
        use :func:`vertical_sweep`.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.vertical(90, 6, stability=False)
    >>> str(t["status"]), round(float(t["v_top_min_m_s"]), 3)
    ('ok', 5.146)
    >>> p = deathsphere.vertical(90, [6, 7], points=5)
    >>> p.shape, p.grid("phi_deg")[0].tolist()
    ((2, 5), [0.0, 90.0, 180.0, 270.0, 360.0])
    """
    from deathsphere.results.vertical import (
        evaluate_vertical,
        vertical_points,
        vertical_requests,
    )

    side = checked_choice("side", side, SIDES)
    stability, keep = checked_flag("stability", stability), checked_statuses(only)
    r = sphere_radius(r, diameter)
    given = {"theta": theta, "v_top": v_top, "phidot_top": phidot_top, "a": a, "r": r, "k": k, "g": g, "mu": mu}
    checked = {name: checked_array(name, v) for name, v in given.items() if v is not None}
    if points is not None:
        points = int(checked_scalar("points", points))
        refuse_oversized(checked, POINT_ROW_BYTES, "deathsphere.vertical(points=...)",
                         "deathsphere.vertical_sweep()", per_request=points)
    else:
        refuse_oversized(checked, VERTICAL_ROW_BYTES[bool(stability)], "deathsphere.vertical()",
                         "deathsphere.vertical_sweep()")
    shape, flat = broadcast_flat(checked)
    n = math.prod(shape)
    req = vertical_requests(n, side=side, **flat)
    if points is None:
        table = Table(raise_if_all_invalid(evaluate_vertical(req, stability=stability)).columns, shape=shape)
    else:
        table = raise_if_all_invalid(vertical_points(req, points))
        if len(table) == n * points:
            table = Table(table.columns, shape=shape + (points,))
    return table if keep is None else table[np.isin(table["status"], keep)]


def _vertical_setup(side, a, r, k, g, mu) -> dict:
    """The scalar options of a vertical orbit, checked (a wheel; r > a inside)."""
    setup = checked_setup(WHEEL, side, a, r, k, g, mu)
    return dict(side=setup.side, a=setup.a, r=setup.r, k=setup.k, g=setup.g, mu=setup.mu)


def _vertical_work(points: int | None, stability: bool, keep=None, loop=None):
    """What one batch of vertical requests becomes: summary rows, or the
    orbit point by point in slices of at most :data:`POINT_ROWS` rows
    (only the rows whose status is in ``keep``, if given); on the globe,
    or inside the closed profile's ``loop`` when given."""
    from deathsphere.results.vertical import evaluate_vertical, vertical_points

    def kept(table):
        return table if keep is None else table[np.isin(table["status"], keep)]

    if loop is None:
        summary = partial(evaluate_vertical, stability=stability)
        sliced_points = vertical_points
    else:
        from deathsphere.results.vertical_on import evaluate_vertical_on, vertical_points_on

        summary = partial(evaluate_vertical_on, loop=loop, stability=stability)
        sliced_points = partial(vertical_points_on, loop=loop)
    if points is None:
        return lambda batches: ((n, kept(summary(req))) for n, req in batches)

    def sliced(batches):
        for n, req in batches:
            for start in range(0, points, POINT_ROWS):
                last = start + POINT_ROWS >= points
                yield (n if last else 0), kept(sliced_points(req, points=points, start=start,
                                                             stop=start + POINT_ROWS))
    return sliced


def _loop_options(loop, points, side) -> None:
    """On a closed profile: the inside only, and ``points`` (angles phi from
    the top) only where phi names one point (a meridian that turns one way)."""
    if loop is None:
        return
    if side == "outside":
        from deathsphere.results.vertical_on import SIDE_INSIDE

        raise ParameterError(SIDE_INSIDE, "side")
    if points is not None and not loop.turns_one_way:
        raise ParameterError("points: the profile's meridian bends both ways, so an angle phi of the loop's tangent "
                             "names more than one point (the summary rows are computed)", "points")


def _theta_in_meridian(loop, axis) -> None:
    """On a closed profile every theta typed must be 90 deg (a loop in a meridian plane), refused in one line."""
    if loop is None:
        return
    for start in range(0, len(axis), 65536):              # in slices: a long range is never held at once
        values = axis.take(np.arange(start, min(start + 65536, len(axis))))
        if np.any(values != 90.0):
            from deathsphere.results.vertical_on import THETA_IN_MERIDIAN

            raise ParameterError(f"{THETA_IN_MERIDIAN} (got {shown_number(float(values[values != 90.0][0]))})",
                                 "theta")


def _vertical_chunk(points: int | None) -> int:
    return 256 if points is None else max(1, POINT_ROWS // points)


def vertical_sweep(theta=None, v_top=None, *, phidot_top=None, side: str = "inside", a=A, r=R, k=0.5, g=G, mu=INF,
                   diameter=None, points=None, only=None, stability: bool = True, surface=None, wall_angle=None,
                   wall_height=None, profile=None) -> Chunks:
    """Every combination of cone angles and top speeds, chunk by chunk:
    ``deathsphere vertical`` (the physics of :func:`vertical`).

    Parameters
    ----------
    theta, v_top, phidot_top : float, array_like or str
        Axes of the grid (theta outer), as for :func:`sweep`: values,
        arrays, ``"start:stop:step"`` text or a list mixing them.  Give
        exactly one of ``v_top`` [m/s] and ``phidot_top`` [rad/s].
    side, a, r, diameter, k, g, mu, points, only, stability : as for :func:`vertical` (one value each).
    surface, wall_angle, wall_height, profile : the arena, as for :func:`orbit`:
        a vertical loop needs a surface that closes over the top: the globe,
        or a profile closed at both ends (theta 90 only, inside; beyond the
        paper, docs/surfaces.md eqs. S9-S12: the globe's columns, then
        ``surface`` and ``height_m``; with ``stability`` the loop's Floquet
        stability on the profile, docs/stability.md sec. 2.1: 1-3 s for a
        few loops, about 6 s for 100); elsewhere it is refused, saying why
        (:mod:`deathsphere.api.vertical_arena`).

    Returns
    -------
    Chunks
        The tables of ``deathsphere vertical --format csv``; ``input_row``
        numbers the grid points from 1.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.vertical_sweep("60:90:30", [6, 7], stability=False).table()
    >>> t["theta_deg"].tolist(), t["v_cm_m_s"].tolist()
    ([60.0, 60.0, 90.0, 90.0], [6.0, 7.0, 6.0, 7.0])
    """
    from deathsphere.api.vertical_arena import loop_arena
    from deathsphere.results.vertical import vertical_requests

    loop = loop_arena(surface, None if r is R else r, diameter, wall_angle, wall_height, profile)
    if loop is None:
        fixed = _vertical_setup(side, a, sphere_radius(r, diameter), k, g, mu)
    else:
        from deathsphere.results.vertical_on import NO_SPHERE_R

        fixed = _vertical_setup(side, a, NO_SPHERE_R, k, g, mu)          # the loop's fit is its own status
    points = None if points is None else int(checked_scalar("points", points))
    _loop_options(loop, points, fixed["side"])
    stability, keep = checked_flag("stability", stability), checked_statuses(only)
    if not is_given(theta):
        raise ParameterError("theta is required: one or more values or start:stop:step ranges", "theta",
                             missing=True)
    if is_given(v_top) == is_given(phidot_top):
        raise ParameterError("give exactly one of v_top (m/s) and phidot_top (rad/s)",
                             "phidot_top" if is_given(v_top) else "v_top")
    key, value = ("v_top", v_top) if is_given(v_top) else ("phidot_top", phidot_top)
    axes = {"theta": checked_axis("theta", theta), key: checked_axis(key, value)}
    _theta_in_meridian(loop, axes["theta"])
    total = checked_grid_size(axes)
    batches = grid_requests(axes, _vertical_chunk(points), vertical_requests, fixed)
    return Chunks(_vertical_work(points, stability, keep, loop)(batches), total)


def vertical_input(source, *, theta=None, v_top=None, phidot_top=None, side=None, a=None, r=None, k=None,
                   g=None, mu=None, diameter=None, points=None, only=None, stability: bool = True, surface=None,
                   wall_angle=None, wall_height=None, profile=None) -> Chunks:
    """Vertical orbits of the requests in a CSV file: ``deathsphere vertical --input FILE``.

    As :func:`orbit_input`, for :func:`vertical`: the header names
    ``theta`` and ``v_top`` or ``phidot_top`` (and optionally ``side``,
    ``a``, ``r``, ``k``, ``g``, ``mu``); ``surface``, ``profile`` (and the
    shape keywords) as for :func:`vertical_sweep`: inside a closed profile
    every row is a loop in a meridian plane (a row with another theta is
    invalid, saying why); a keyword argument given applies
    to every row, over the file's column (one value each); one not given
    takes the file's value, else its default (k = 0.5).  A result CSV of
    ``vertical`` is read too: the summary (``v_cm_m_s`` is the top speed)
    and the point-by-point output of ``points`` (each point a request; its
    ``v_cm_m_s`` is the speed at phi and is ignored, so the top speed comes
    from ``v_top`` or ``phidot_top``).

    Examples
    --------
    >>> import os, tempfile, deathsphere
    >>> path = os.path.join(tempfile.mkdtemp(), "loops.csv")
    >>> _ = open(path, "w").write("theta,v_top\\n90,6\\n90,-1\\n")
    >>> t = deathsphere.vertical_input(path, stability=False).table()
    >>> t["status"].tolist()
    ['ok', 'invalid']
    """
    from deathsphere.api.vertical_arena import loop_arena
    from deathsphere.results.vertical import COLUMNS as VERTICAL_COLUMNS
    from deathsphere.results.vertical import POINT_COLUMNS, VERTICAL_FIELDS

    # off the globe: a closed profile's loop, or refused saying why
    loop = loop_arena(surface, r, diameter, wall_angle, wall_height, profile)

    points = None if points is None else int(checked_scalar("points", points))
    _loop_options(loop, points, side)
    stability, keep = checked_flag("stability", stability), checked_statuses(only)
    overrides = {} if side is None else {"side": checked_choice("side", side, SIDES)}
    # on a profile the sphere's radius is no request's (the arena refused r and diameter there)
    radius = sphere_radius(r, diameter) if loop is None else None
    for name, value in (("theta", theta), ("v_top", v_top), ("phidot_top", phidot_top), ("a", a),
                        ("r", radius), ("k", k), ("g", g), ("mu", mu)):
        value = one_default(name, value)
        if value is not None:
            overrides[name] = value
    if "v_top" in overrides or "phidot_top" in overrides:
        overrides["phi"] = 0.0  # an option's speed is the top's, whatever the file's phi
    # both outputs can be fed back: the summary and the orbit point by point
    outputs = list(dict.fromkeys(VERTICAL_COLUMNS + POINT_COLUMNS))
    if loop is not None:
        from deathsphere.results.vertical_on import ARENA_COLUMNS

        outputs += list(ARENA_COLUMNS)          # a profile's outputs read back, on a profile
    reader = request_reader(source, {**VERTICAL_FIELDS, **PHI_FIELD}, overrides, VERTICAL_ECHO, outputs)
    # a row's refusal names its column as the file's header typed it
    at_phi = partial(requests_at_phi, typed=reader.typed) if loop is None else partial(
        _requests_on, loop=loop, typed=reader.typed)
    batches = input_requests(reader, _vertical_chunk(points), at_phi)
    return Chunks(_vertical_work(points, stability, keep, loop)(batches))


def _requests_on(n: int, invalid=None, input_row=None, phi=None, *, loop, **fields) -> dict:
    """A closed profile's requests from an input file's rows: a speed given
    at an angle ``phi`` [deg] from the top (a point of ``vertical --points``
    read back) is taken back to the top by energy conservation, eq. S9
    (docs/surfaces.md); a rate given at phi is refused, as is phi on a
    meridian that bends both ways (phi names more than one point there)."""
    from deathsphere.physics.vertical_orbit_on import top_speed_on
    from deathsphere.results.vertical import vertical_requests

    req = vertical_requests(n, invalid=invalid, input_row=input_row, **fields)
    phi = np.broadcast_to(np.asarray(0.0 if phi is None else phi, dtype=float), (n,))
    rows = np.flatnonzero((np.nan_to_num(phi) != 0.0) & (req["invalid"] == ""))
    if rows.size == 0:
        return req
    by_rate = ~np.isnan(req["phidot_top"][rows])
    req["invalid"][rows[by_rate]] = "phi: on a profile a rate is given at the top (phi 0); give v_top at phi"
    if not loop.turns_one_way:
        req["invalid"][rows[~by_rate]] = ("phi: the profile's meridian bends both ways: phi names more than one "
                                          "point of the loop (give the speed at the top: phi 0)")
        return req
    rows = rows[~by_rate & ~np.isnan(req["v_top"][rows])]
    with np.errstate(all="ignore"):      # unchecked values: the evaluation gives their reasons
        top = top_speed_on(loop, np.deg2rad(phi[rows]), req["v_top"][rows], req["a"][rows], req["k"][rows],
                           req["g"][rows])
    slow = np.isnan(top) & np.isfinite(req["v_top"][rows]) & (req["v_top"][rows] >= 0)
    req["v_top"][rows] = np.where(slow, req["v_top"][rows], top)
    req["invalid"][rows[slow]] = ("the speed at phi is below that of a wheel starting from rest at the top "
                                  "(surfaces.md eq. S9) or the wheel does not fit the loop")
    return req
