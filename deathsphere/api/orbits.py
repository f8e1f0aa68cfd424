"""Horizontal orbits: ``orbit``, ``sweep`` and ``orbit --input`` (McDonald 1993
eqs. (0), (8b), (13), (29)-(36), (55)-(59), (81), (83))."""

from __future__ import annotations

import math
from functools import partial

import numpy as np

from deathsphere.api.arguments import (
    CHUNK,
    INF,
    A,
    G,
    R,
    axis_max,
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
    radii_of,
    raise_if_all_invalid,
    refuse_radius_with_diameter,
    sphere_radius,
)
from deathsphere.api.streams import (
    Chunks,
    evaluate_filtered,
    cluster_of,
    evaluated,
    grid_requests,
    input_requests,
    request_reader,
)
from deathsphere.constants import (
    SIDES,
)
from deathsphere.model import (
    COLUMNS,
    REQUEST_FIELDS,
    evaluate,
    make_requests,
    validate_requests,
)
from deathsphere.params import ParameterError
from deathsphere.records.paper_bodies import Ball, Wheel
from deathsphere.requests.decode import decode_paper_body
from deathsphere.requests.arena import SURFACES  # noqa: F401  (the arenas orbit and sweep take, by name)
from deathsphere.table import Table

#: Peak memory one call of :func:`orbit` or :func:`~deathsphere.api.vertical`
#: may take: a larger broadcast is refused before any array is built, with
#: a pointer to the streamed form (:func:`sweep`, ``vertical_sweep``), whose
#: memory stays flat.
CALL_BYTES = 2 * 1024 ** 3
#: Peak bytes per row of :func:`orbit`, measured with tracemalloc over 2e5
#: rows: ~1.1 kB with the stability columns (~0.7 kB without).
ORBIT_ROW_BYTES = 1100
#: Rows one :func:`orbit` call evaluates at most: CALL_BYTES / ORBIT_ROW_BYTES.
MAX_ORBIT_ROWS = CALL_BYTES // ORBIT_ROW_BYTES
#: Grid points per chunk of :func:`sweep` and rows per chunk of
#: :func:`orbit_input` at most: a larger ``chunk_size`` is clamped to this
#: (the rows are the same; the stability columns may differ in the last
#: digit with the chunk size, docs/contract.md).  A chunk, with its CSV
#: text, peaks at ~2 kB per row (tracemalloc, with or without stability), so
#: this keeps one chunk under ~256 MiB; each of ``jobs`` processes holds one.
MAX_CHUNK_ROWS = 131072


def refuse_oversized(arrays: dict, row_bytes: int, call: str, instead: str, per_request: int = 1) -> None:
    """ParameterError when the broadcast of ``arrays`` would need more than
    :data:`CALL_BYTES` at ``row_bytes`` per row (``per_request`` rows per
    element), checked from the shapes alone, before anything is allocated.
    Shapes that do not broadcast are left to the caller's own message."""
    try:
        shape = np.broadcast_shapes(*(v.shape for v in arrays.values()))
    except ValueError:
        return
    rows = math.prod(shape) * per_request
    limit = CALL_BYTES // row_bytes
    if rows > limit:
        raise ParameterError(
            f"{call} evaluates at most {limit} rows at once ({CALL_BYTES // 1024 ** 3} GiB at ~{row_bytes} bytes "
            f"each); these arguments give {rows} (shape {shape}): use {instead}, which streams them chunk by chunk "
            f"in flat memory")


def orbit(theta=None, alpha=None, *, body: str = "wheel", side: str = "inside", a=A, r=R, k=None, g=G,
          mu=INF, omega3=None, omega=None, speed=None, com_speed=None, max_g=INF, diameter=None, only=None,
          stability: bool = True, surface="sphere", height=None, wall_angle=None, wall_height=None,
          profile=None, turn_radius=None) -> Table:
    """Steady horizontal orbits: ``deathsphere orbit``.

    McDonald (1993): the fit, eq. (0) (outside: eq. 81); r', eq. (8b); the
    spins, eq. (13); the rate Omega and the forces, eqs. (29)-(36) (outside
    the contact condition is eq. 83); a rolling sphere, eqs. (55)-(59).
    Stability (``stability=True``) is beyond the paper: docs/stability.md.
    All numeric arguments broadcast against each other like numpy arrays.

    Parameters
    ----------
    theta : float or array_like
        Polar angle of the contact point from the upward vertical [deg], 0..180.
    alpha : float or array_like, optional
        Wheel: tilt of the wheel below the orbit plane [deg], any angle
        (reduced to (-180, 180]; 205 = -155).  A wheel needs exactly one of
        ``alpha``, ``speed``, ``com_speed`` and ``omega``; a sphere and a
        particle take none.
    body : {"wheel", "sphere", "particle"}
    side : {"inside", "outside"}
    a, r : float or array_like
        Body radius and sphere radius [m] (inside: r > a).
    k : float or array_like, optional
        Inertia factor (wheel: I11 = 2 k m a^2, default 0.5; sphere:
        I = k m a^2, default 0.4).
    g : float or array_like
        Gravity [m/s^2].
    mu : float or array_like
        Friction coefficient available (``inf``: no limit); orbits needing
        more have status ``slips``.
    omega3 : float or array_like, optional
        Sphere: spin about the contact normal [rad/s]; eq. (55) gives up to
        two orbit rates, one row each (``branch`` 0 slow, 1 fast).
    omega : float or array_like, optional
        Orbital rate Omega [rad/s].  Sphere: signed about the upward
        vertical (omega3 follows from eq. 55).  Wheel: > 0; eq. (29) is
        solved for every tilt alpha giving it, one row each.
    speed : float or array_like, optional
        Wheel: the contact's speed along the ground (a speedometer's) [m/s].
        The contact runs round the parallel of radius rho_P = r sin(theta),
        so it fixes the rate Omega = speed / rho_P; every tilt alpha giving
        that rate, one row each (as ``omega``).  With the contact on the
        axis (theta 0 or 180) no rate gives it: status ``no_orbit``, reason
        contact_on_axis.  Echoed in ``v_contact_m_s``.
    com_speed : float or array_like, optional
        Wheel: the centre's speed v_cm [m/s]; every tilt alpha giving it, one
        row each.  Echoed in ``v_cm_m_s``.
    stability : bool
        Fill the stability columns (exact linearisation); False is faster.
        On surfaces other than the sphere they stay empty (docs/surfaces.md).
    surface : {"sphere", "cylinder", "cone", "plane", "profile"} or a ground record
        The arena (docs/surfaces.md): the globe (default; ``r`` or
        ``diameter``), the wall of death's drum (``diameter``, optional
        ``wall_height``), the well of death's cone or a banked track
        (``diameter`` at the floor, ``wall_angle``, optional
        ``wall_height``), flat ground, or a meridian's samples
        (``profile``: a CSV file or a Profile); or a record, e.g.
        ``Cylinder(4.8768, 6.0)``.
    height : float or array_like, optional
        The lane's height above the surface's lowest point [m]: on the
        sphere instead of ``theta``; on a drum, a cone or a profile the lane.
    wall_angle : float
        The cone's wall angle from the horizontal [deg], strictly between 0
        and 180 (90: a drum).
    wall_height : float
        The drum's or the cone's wall height [m]: no lane above it.
    profile : str, path or Profile
        The meridian's samples (a CSV file with columns rho_m,z_m).
    turn_radius : float or array_like, optional
        On flat ground (``surface="plane"``): the contact's distance from
        the turn's centre [m], the lane.

    Returns
    -------
    Table
        The columns of ``deathsphere orbit --format csv`` (docs/contract.md),
        one row per element of the broadcast, in row-major order, and
        ``table.shape`` the broadcast shape (``table.grid("v_cm_m_s")``
        gives a column in that shape).  Where one request can have several
        answers -- a sphere given ``omega3`` (two roots of eq. 55) or a
        wheel given ``speed``, ``com_speed`` or ``omega`` (one row per tilt) -- the rows
        cannot keep a rectangular shape: the table is flat (``shape ==
        (len(table),)``) and ``input_row`` is 1 + the request's flat index
        in the broadcast, shared by its rows.

    Raises
    ------
    ParameterError
        A value outside its parameter's allowed set, wherever it is in an
        array (the command line refuses such an option as a whole), e.g.
        ``theta (polar angle) must be 0..180 deg (got 200)``; arguments that
        broadcast to more than :data:`MAX_ORBIT_ROWS` (1952257) rows, about
        2 GiB (use :func:`sweep`); or a call none
        of whose requests can be computed (one request that breaks a
        combination rule, such as r <= a inside or a wheel given no tilt).
        When only some elements of the broadcast break a combination rule
        (r <= a for some of the a and r given), those rows come back with
        status ``invalid`` and the reason, and the rest are computed, as in
        a ``sweep`` or an ``--input`` batch.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.orbit(60, 10)
    >>> t.shape, str(t["status"]), round(float(t["v_cm_m_s"]), 2)
    ((), 'ok', 7.88)
    >>> t = deathsphere.orbit([[30], [60], [90]], [5, 10], stability=False)
    >>> t.shape
    (3, 2)
    >>> t.grid("status")
    array([['ok', 'ok'],
           ['ok', 'ok'],
           ['ok', 'ok']], dtype=object)
    >>> s = deathsphere.orbit(60, body="sphere", omega3=80, stability=False)
    >>> s["branch"].tolist(), s["input_row"].tolist()
    ([0, 1], [1, 1])
    >>> deathsphere.orbit(200, 10)
    Traceback (most recent call last):
    ...
    deathsphere.ParameterError: theta (polar angle) must be 0..180 deg (got 200)
    """
    body, side = decode_paper_body(body), checked_choice("side", side, SIDES)
    stability, keep = checked_flag("stability", stability), checked_statuses(only)
    ground, r, diameter, height = _arena_of(surface, r, diameter, wall_angle, wall_height, profile, height,
                                            turn_radius, theta)
    r = sphere_radius(r, diameter)
    given = {"theta": theta, "alpha": alpha, "a": a, "r": r, "k": k, "g": g, "mu": mu, "max_g": max_g,
             "omega3": omega3, "omega": omega, "speed": speed, "com_speed": com_speed, "height": height}
    checked = {name: checked_array(name, v) for name, v in given.items() if v is not None}
    refuse_oversized(checked, ORBIT_ROW_BYTES, "deathsphere.orbit()", "deathsphere.sweep()")
    shape, flat = broadcast_flat(checked)
    n = math.prod(shape)
    table = raise_if_all_invalid(evaluate(make_requests(n, body=body, side=side, ground=ground, **flat),
                                          stability=stability))
    # a wheel solved for its tilt, a ball given its spin: a row per root
    several = (isinstance(body, Wheel) and alpha is None) or (isinstance(body, Ball) and omega3 is not None)
    if keep is not None:
        return table[np.isin(table["status"], keep)]
    return table if several else Table(table.columns, shape=shape)


def _arena_of(surface, r, diameter, wall_angle, wall_height, profile, height, turn_radius, theta, axis=False):
    """The arena of orbit, sweep and orbit --input (docs/surfaces.md):
    ``(ground, r, diameter, lane height)``, the ground None for the globe
    (whose radius or diameter, possibly an axis, goes on as before).  On
    flat ground the lane is ``turn_radius``; elsewhere ``height`` (``axis``:
    sweep's axis text, checked as an axis by the caller)."""
    from deathsphere.requests.arena import arena, is_globe, lane_key, refuse_above_top

    if is_globe(surface):
        if turn_radius is not None:
            raise ParameterError("turn_radius is the lane on flat ground (surface plane); on the sphere give theta "
                                 "or height", "turn_radius")
        if wall_angle is not None or wall_height is not None or profile is not None:
            name = "wall_angle" if wall_angle is not None else "wall_height" if wall_height is not None else "profile"
            raise ParameterError(f"{name} is not a shape of the sphere (it takes r, diameter); choose the surface "
                                 "(cylinder, cone, profile)", name)
        if surface is not None and not isinstance(surface, str):
            if (r is not R and r is not None) or diameter is not None:
                raise ParameterError("the Sphere record given has its radius; give it or r, not both", "r")
            r = surface.radius
        return None, r, diameter, height
    ground = arena(surface, None if r is R else r, diameter, wall_angle, wall_height, profile)
    if turn_radius is not None and lane_key(ground) != "turn_radius":
        raise ParameterError(f"turn_radius is the lane on flat ground (surface plane); on the {ground.name} give "
                             "height", "turn_radius")
    if is_given(theta):
        raise ParameterError(f"theta is the sphere's polar angle: on the {ground.name} give the lane's "
                             f"{lane_key(ground)}", "theta")
    if lane_key(ground) == "turn_radius":
        if height is not None:
            raise ParameterError("on flat ground the lane is its turn_radius, not a height", "height")
        if turn_radius is None:
            raise ParameterError("on flat ground give the lane's turn_radius", "turn_radius", missing=True)
        height = turn_radius if axis else checked_array("turn_radius", turn_radius)
    elif not is_given(height):
        raise ParameterError(f"on the {ground.name} give the lane's height (its height above the lowest point)",
                             "height", missing=True)
    else:
        # a lane typed above the wall is bad input, as in ride (a file's rows say no_fit instead)
        refuse_above_top(ground, axis_max(checked_axis("height", height)))
    return ground, R, None, height


def sweep(theta=None, alpha=None, *, a=A, r=R, k=None, body: str = "wheel", side: str = "inside", g=G, mu=INF,
          omega3=None, omega=None, speed=None, com_speed=None, max_g=INF, diameter=None, only=None,
          chunk_size: int = CHUNK,
          stability: bool = True, jobs: int = 1, scheduler=None, surface="sphere", height=None, wall_angle=None,
          wall_height=None, profile=None, turn_radius=None) -> Chunks:
    """Every combination of the axes, chunk by chunk: ``deathsphere sweep``
    (and ``deathsphere orbit`` given several values).

    The physics of :func:`orbit` (McDonald 1993 eqs. (0), (8b), (13),
    (29)-(36), (55)-(59), (81), (83)) over a cartesian grid that is never
    held in memory.

    Parameters
    ----------
    theta, alpha, a, r, k, omega3, omega, speed, com_speed : float, array_like or str
        The axes (units as in :func:`orbit`): a value, a list or array of
        values, or the command line's text, one value or a range
        ``"start:stop:step"`` (stop included when on the grid, e.g.
        ``"5:175:1"``), or a list mixing both (the values of a repeated
        option, in order).  Grid order is a, r, k, theta, then speed,
        com_speed, alpha, omega3 or omega fastest.  ``speed`` is the
        contact's, ``com_speed`` the centre's, as for :func:`orbit`.
    body, side, g, mu : as for :func:`orbit` (one value each).
    surface, wall_angle, wall_height, profile : the arena, as for :func:`orbit` (one value each).
    height, turn_radius : the lane on the arena, an axis like theta (after theta in grid order).
    only : str or list of str, optional
        Keep only rows with these statuses (``"ok"``, ``"no_fit"``, ...).
    chunk_size : int
        Grid points evaluated per chunk (memory stays flat); at most
        :data:`MAX_CHUNK_ROWS` (131072, ~256 MiB per chunk): a larger value
        is clamped to it, which changes nothing in the output.
    stability : bool
        Fill the stability columns.
    jobs : int
        Processes evaluating chunks (1..256); the chunks come back in grid
        order, the same tables as with one.
    scheduler : str or distributed.Client, optional
        Evaluate the chunks on a dask.distributed cluster: the scheduler's
        address (``"tcp://host:8786"``) or a Client (the ``distributed``
        extra).  The chunks come back in grid order, the same tables as a
        local run; at most two chunks per worker are in flight.  Not with
        ``jobs`` > 1.

    Returns
    -------
    Chunks
        An iterator of tables, one per chunk of ``chunk_size`` grid points,
        in grid order (with ``only``, a chunk may be empty); ``input_row``
        numbers the grid points from 1.  Together they are ``deathsphere
        sweep --format csv``.  A combination that is not allowed (r <= a
        inside) is an ``invalid`` row with the reason.

    Raises
    ------
    ParameterError
        At the call (before any chunk): a value outside its set, a bad
        range, or inputs the body does not take.

    Examples
    --------
    >>> import deathsphere
    >>> chunks = deathsphere.sweep("30:90:30", [5, 10], chunk_size=4, stability=False)
    >>> chunks.total, [len(c) for c in chunks]
    (6, [4, 2])
    >>> ok = deathsphere.sweep(60, [10, 30, 60], only="ok", stability=False)
    >>> [row["alpha_deg"] for chunk in ok for row in chunk]
    [10.0, 30.0]
    """
    body, side = decode_paper_body(body), checked_choice("side", side, SIDES)
    g, mu, max_g = checked_scalar("g", g), checked_scalar("mu", mu), checked_scalar("max_g", max_g)
    chunk_size, jobs = int(checked_scalar("chunk_size", chunk_size)), int(checked_scalar("jobs", jobs))
    chunk_size = min(chunk_size, MAX_CHUNK_ROWS)
    stability, keep = checked_flag("stability", stability), checked_statuses(only)
    ground, r, diameter, height = _arena_of(surface, r, diameter, wall_angle, wall_height, profile, height,
                                            turn_radius, theta, axis=True)
    refuse_radius_with_diameter(r, diameter)
    if diameter is not None:
        r = None
    if not is_given(theta) and ground is None and not is_given(height):
        raise ParameterError("theta is required: one or more values or start:stop:step ranges", "theta",
                             missing=True)
    r_axis = checked_axis("r", r, R) if diameter is None else radii_of(checked_axis("diameter", diameter))
    lane = "turn_radius" if ground is not None and not hasattr(ground, "highest_lane") else "height"
    axes = {"a": checked_axis("a", a, A), "r": r_axis, "k": checked_axis("k", k), "theta": checked_axis("theta", theta),
            "height": checked_axis(lane, height), "speed": checked_axis("speed", speed),
            "com_speed": checked_axis("com_speed", com_speed), "alpha": checked_axis("alpha", alpha), "omega3": checked_axis("omega3", omega3),
            "omega": checked_axis("omega", omega)}
    total = checked_grid_size(axes)
    if len(axes["a"]) == 1 and len(axes["r"]) == 1 and ground is None:
        # one body in one sphere: a combination that cannot be is bad input,
        # not a grid of invalid rows
        one = np.zeros(1, dtype=np.int64)
        checked_setup(body, side, axes["a"].take(one)[0], axes["r"].take(one)[0], None, g, mu)
    # which inputs the body takes is the same for every grid point: ask the
    # model's validator about the first one (with a and r that always fit,
    # so that only a per-point combination such as r <= a gives invalid rows)
    first = {name: axes[name].take(np.zeros(1, dtype=np.int64))
             for name in ("theta", "alpha", "k", "omega3", "omega", "speed", "com_speed", "height")}
    if ground is None:  # a lane by its height is checked per point against each globe's diameter
        first["height"] = np.where(np.isnan(first["height"]), np.nan, 0.0)
    reason = validate_requests(make_requests(1, body=body, side=side, a=1.0, r=2.0, g=g, mu=mu, ground=ground,
                                             **first))[0]
    if reason:
        raise ParameterError(reason)
    fixed = dict(body=body, side=side, g=g, mu=mu, max_g=max_g, ground=ground)
    work = partial(evaluate_filtered, stability=stability, keep=keep)
    cluster = cluster_of(scheduler, jobs)
    return Chunks(evaluated(grid_requests(axes, chunk_size, make_requests, fixed), work, jobs, cluster), total)


def orbit_input(source, *, theta=None, alpha=None, omega3=None, omega=None, speed=None, com_speed=None, body=None,
                side=None,
                a=None, r=None, diameter=None, k=None, g=None, mu=None, max_g=None, only=None,
                stability: bool = True, chunk_size: int = CHUNK, jobs: int = 1, scheduler=None,
                surface="sphere", height=None, wall_angle=None, wall_height=None, profile=None,
                turn_radius=None) -> Chunks:
    """Horizontal orbits of the requests in a CSV file: ``deathsphere orbit --input FILE``.

    The physics of :func:`orbit`, one request per line, streamed: a file of
    any length runs in the memory of one chunk.

    Parameters
    ----------
    source : str or path
        The CSV file, or ``"-"`` for standard input.  Its header names the
        inputs (``theta``, ``alpha``, ``omega3``, ``omega``, ``speed`` (the
        contact's), ``com_speed`` (the centre's), ``body``, ``side``, ``a``, ``r``, ``k``, ``g``, ``mu``); an output
        CSV of ``orbit`` is read too (``theta_deg``, ``alpha_deg``, ...
        echo their inputs; its other columns are ignored).
    theta, alpha, omega3, omega, speed, com_speed, body, side, a, r, diameter, k, g, mu, max_g
        One value each, applied to every row: over the file's column where
        it has one (a result CSV fed back with a new ``mu``), else as the
        column.  Not given (None): the file's value, or the parameter's
        default where the file has no column or a cell is empty.
    surface, wall_angle, wall_height, profile : the arena of every row, as for
        :func:`orbit`; a row's lane is then its ``height`` (a ``height`` or
        ``height_m`` column, or ``height``/``turn_radius`` here).
    only, stability, chunk_size, jobs, scheduler : as for :func:`sweep`.

    Returns
    -------
    Chunks
        The tables of ``deathsphere orbit --input FILE --format csv``: every
        non-blank line after the header gives one request, ``input_row``
        its position, in order; a line that cannot be read is an
        ``invalid`` row with its reason (docs/contract.md, "Input files").

    Raises
    ------
    ParameterError
        A default outside its set, or a file that cannot be read as a whole
        (missing, empty, not CSV text, an unknown column).

    Examples
    --------
    >>> import os, tempfile, deathsphere
    >>> path = os.path.join(tempfile.mkdtemp(), "requests.csv")
    >>> _ = open(path, "w").write("theta,alpha\\n60,10\\n60,oops\\n")
    >>> table = deathsphere.orbit_input(path, stability=False).table()
    >>> table["status"].tolist(), table["input_row"].tolist()
    (['ok', 'invalid'], [1, 2])
    """
    chunk_size, jobs = int(checked_scalar("chunk_size", chunk_size)), int(checked_scalar("jobs", jobs))
    chunk_size = min(chunk_size, MAX_CHUNK_ROWS)
    stability, keep = checked_flag("stability", stability), checked_statuses(only)
    overrides = {}
    if body is not None:
        overrides["body"] = decode_paper_body(body).word
    if side is not None:
        overrides["side"] = checked_choice("side", side, SIDES)
    from deathsphere.requests.arena import is_globe

    lane = None if turn_radius is None else one_default("turn_radius", turn_radius)
    if is_globe(surface):
        ground = _arena_of(surface, R if r is None else r, diameter, wall_angle, wall_height, profile, None,
                           turn_radius, None)[0]
    else:
        # the file's rows hold the lanes: the arena is checked here with a stand-in lane
        ground = _arena_of(surface, R if r is None else r, diameter, wall_angle, wall_height, profile, 0.0,
                           None, None)[0]
        r = diameter = None
    height = lane if lane is not None else height
    r = sphere_radius(r, diameter)
    for name, value in (("theta", theta), ("alpha", alpha), ("omega3", omega3), ("omega", omega),
                        ("speed", speed), ("com_speed", com_speed), ("a", a), ("r", r), ("k", k), ("g", g), ("mu", mu), ("max_g", max_g),
                        ("height", height)):
        value = one_default(name, value)
        if value is not None:
            overrides[name] = value
    from deathsphere.inputs import ALIASES

    # a result CSV fed back carries its lanes' heights (on the globe they agree with theta), and its tilt
    # alpha_deg holds each row: its v_cm_m_s (a centre speed, com_speed in a file without alpha_deg) is read
    # and ignored
    reader = request_reader(source, REQUEST_FIELDS, overrides, {**ALIASES, "height_m": "height"}, COLUMNS,
                            ignore_when={"v_cm_m_s": "alpha_deg"})
    work = partial(evaluate_filtered, stability=stability, keep=keep)
    cluster = cluster_of(scheduler, jobs)
    # a row's refusal names its column as the file's header typed it
    make = partial(make_requests, typed=reader.typed, ground=ground)
    return Chunks(evaluated(input_requests(reader, chunk_size, make), work, jobs, cluster))
