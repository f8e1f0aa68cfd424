"""The Python API: one function per command of the command line.

Each function takes the command's options as parameters of the same names
and units (angles in degrees, everything else SI) and returns what the
command prints with ``--format csv``, as a :class:`~deathsphere.model.Table`
with the same columns and values (docs/api.md, docs/contract.md):

=====================  =======================================
command                function
=====================  =======================================
``deathsphere orbit``  :func:`orbit`
``vertical``           :func:`vertical`
``sweep``              :func:`sweep` (an iterator of chunks)
``map --format csv``   :func:`region`
``limits``             :func:`limits`
``stability``          :func:`stability`
``simulate``           :func:`simulate` (series and summary)
``table1``             :func:`table1`
``verify``             :func:`verify`
=====================  =======================================

Bad input raises :class:`~deathsphere.params.ParameterError` (a
``ValueError``) with the one-line reason the command line prints after
``Invalid value for '--option':``.  Arrays broadcast like numpy's; the rules
for an array with some bad elements are in :func:`orbit` ("Raises").
"""

from __future__ import annotations

import math
import os
from collections import deque
from collections.abc import Iterator
from functools import partial

import numpy as np

from deathsphere import params
from deathsphere.constants import (
    BODIES,
    SIDES,
    STANDARD_GRAVITY,
    TABLE1_SPHERE_RADIUS,
    TABLE1_WHEEL_RADIUS,
)
from deathsphere.grid import Axis, RangeError, Segment, grid_chunks, grid_size, parse_segment
from deathsphere.model import COLUMNS, REQUEST_FIELDS, Setup, Table, evaluate, make_requests, validate_requests
from deathsphere.params import ParameterError
from deathsphere.physics.status import STATUS_LABELS

__all__ = ["orbit", "sweep", "orbit_input", "vertical", "vertical_sweep", "vertical_input", "region",
           "region_cells", "region_curves", "limits", "stability", "simulate", "prepare_simulation", "table1",
           "verify", "Chunks", "ParameterError"]

G = STANDARD_GRAVITY
A = TABLE1_WHEEL_RADIUS
R = TABLE1_SPHERE_RADIUS
INF = math.inf

#: Orbits per chunk of :func:`sweep` (the command line's ``--chunk-size`` default).
CHUNK = 16384
#: Output columns of ``vertical`` that echo an input, read back under that
#: input's name when a result CSV is fed to :func:`vertical_input` (every
#: other output column is ignored; ``v_cm_m_s`` is the speed at the top).
#: ``orbit``'s are :data:`deathsphere.inputs.ALIASES`.
VERTICAL_ECHO = {"theta_deg": "theta", "a_m": "a", "r_m": "r", "g_m_s2": "g", "mu_available": "mu",
                 "v_cm_m_s": "v_top"}
#: Rows of the point-by-point output of a vertical orbit computed at once
#: (requests x points): a long orbit is written in slices of this many.
POINT_ROWS = 65536
#: solve_ivp's methods and the frames :func:`simulate` integrates in
#: (as in :mod:`deathsphere.simulation`, named here so that a call is
#: checked before scipy is imported).
METHODS = ("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA")
METHODS_LOWER = tuple(m.lower() for m in METHODS)
FRAMES = ("turning", "lab")
#: theta values :func:`limits` evaluates at once (each a root search).
MAX_LIMIT_THETAS = 100_000
#: Row statuses (``only=`` of :func:`sweep`).
STATUSES = tuple(str(s) for s in STATUS_LABELS)


# ---------------------------------------------------------------------------
# checking the arguments: every domain is in deathsphere.params, every
# combination rule in the model's validators; nothing is re-implemented here


def _values(name: str, value) -> np.ndarray:
    """``value`` (a number, list or array) as a float array whose every
    element is an allowed ``name``; else ParameterError with the reason."""
    if isinstance(value, str):
        raise ParameterError(f"{name} must be a number (got {value!r})", name)
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a number (got {value!r})", name) from None
    reason = params.first_problem(name, arr)
    if reason:
        raise ParameterError(reason, name)
    return arr


def _scalar(name: str, value) -> float:
    """One allowed value of ``name`` (a number, or its text as typed on the
    command line; an array of one element is not one value)."""
    if isinstance(value, (list, tuple)) and len(value) == 1:
        value = value[0]
    if np.ndim(value) != 0:
        raise ParameterError(f"{name} takes one value (got an array of shape {np.shape(value)})", name)
    return params.check(name, value)


def _optional(name: str, value) -> float | None:
    return None if value is None else _scalar(name, value)


def _choice(name: str, value, allowed) -> str:
    if not isinstance(value, str):
        raise ParameterError(f"{name} must be one of {' | '.join(allowed)} (got {value!r})", name)
    return params.choice(name, value, allowed)


def _broadcast(values: dict[str, np.ndarray]) -> tuple[tuple[int, ...], dict[str, np.ndarray]]:
    """The broadcast shape and every array flattened to it (row-major)."""
    try:
        shape = np.broadcast_shapes(*(v.shape for v in values.values()))
    except ValueError:
        shapes = ", ".join(f"{n} {v.shape}" for n, v in values.items() if v.ndim)
        raise ParameterError(f"the arguments cannot be broadcast together (shapes: {shapes})") from None
    return shape, {n: np.broadcast_to(v, shape).reshape(-1) for n, v in values.items()}


def _setup(body, side, a, r, k, g, mu) -> Setup:
    """A :class:`Setup` from one value each (the command's scalar options)."""
    body, side = _choice("body", body, BODIES), _choice("side", side, SIDES)
    numbers = {name: _scalar(name, v) for name, v in (("a", a), ("r", r), ("k", k), ("g", g), ("mu", mu))
               if v is not None}
    try:
        return Setup(body=body, side=side, **numbers)
    except ValueError as exc:  # a combination, e.g. r <= a inside
        raise ParameterError(str(exc)) from None


def _given(value) -> bool:
    """Whether an optional axis was given (None and an empty list are not)."""
    return value is not None and not (isinstance(value, (list, tuple)) and len(value) == 0)


def _segment(name: str, item) -> Segment:
    """One value or ``start:stop:step`` range of ``name``, every value allowed
    (a range is monotone: its ends decide, and it is never built)."""
    if isinstance(item, str) and ":" not in item:
        seg = Segment(params.check(name, item), 0.0, 1, None)
    elif isinstance(item, str):
        try:
            seg = parse_segment(item, name)
        except RangeError as exc:
            raise ParameterError(str(exc).split(": ", 1)[-1], name) from None
    else:
        seg = Segment(float(_values(name, item)), 0.0, 1, None)
    reason = params.first_problem(name, [seg.first, seg.last])
    if not reason and params.PARAMS[name].nonzero and Axis([seg]).contains_zero():
        reason = f"{name} must not be 0 ({params.PARAMS[name].allowed()})"
    if reason:
        raise ParameterError(reason, name)
    return seg


def _axis(name: str, value, default=None) -> Axis:
    """An axis of a grid from a value, a list or array of values, or text as
    on the command line (``"5:175:1"``, or a list mixing values and ranges,
    in order).  Never materialised; ``default`` (None: NaN, "not given")
    when ``value`` is not given."""
    if not _given(value):
        return Axis.of([math.nan if default is None else default])
    items = [value] if isinstance(value, str) else value
    if isinstance(items, (list, tuple)) and any(isinstance(v, str) for v in items):
        return Axis([_segment(name, v) for v in items])
    return _ValuesAxis(np.atleast_1d(_values(name, value)).reshape(-1))


def _one_default(name: str, value) -> float | None:
    """A default for an input file's missing ``name`` column: one value."""
    if not _given(value):
        return None
    axis = _axis(name, value)
    if len(axis) != 1:
        raise ParameterError(f"with an input file, {name} may give one default value, not a list or range", name)
    return float(axis.take(np.zeros(1, dtype=np.int64))[0])


def _grid_size(axes: dict) -> int:
    try:
        return grid_size(axes)
    except RangeError as exc:
        raise ParameterError(str(exc)) from None


class Chunks:
    """The tables of a streamed result, one per chunk of requests, in order:
    an iterator (``for table in chunks``) that knows how far it has got.

    ``total`` is the number of requests (grid points; None when they are
    read from a file as they come) and ``done`` the number evaluated so far
    (the command line's progress bar).  :meth:`table` joins what is left
    into one :class:`Table` (small results only)."""

    def __init__(self, pairs: Iterator[tuple[int, Table]], total: int | None = None):
        self._pairs = iter(pairs)
        self.total = total
        self.done = 0

    def __iter__(self) -> Chunks:
        return self

    def __next__(self) -> Table:
        n, table = next(self._pairs)
        self.done += n
        return table

    def table(self) -> Table:
        """Every remaining chunk as one table."""
        return Table.concat(self)

    def to_arrow(self):
        """Every remaining chunk as one ``pyarrow.Table``, converted chunk by
        chunk (never the whole result as numpy and Arrow at once); the
        types of :meth:`Table.to_arrow`, fixed by the first chunk."""
        from deathsphere.table import frames

        return frames.arrow_concat(self, "Chunks.to_arrow")[0]

    def to_polars(self):
        """Every remaining chunk as one ``polars.DataFrame`` (through :meth:`to_arrow`)."""
        from deathsphere.table import frames

        frames.require("polars", "Chunks.to_polars")
        return frames.polars_frame(frames.arrow_concat(self, "Chunks.to_polars")[0], "Chunks.to_polars")

    def to_pandas(self):
        """Every remaining chunk as one ``pandas.DataFrame`` (through
        :meth:`to_arrow`; the types of :meth:`Table.to_pandas`)."""
        from deathsphere.table import frames

        frames.require("pandas", "Chunks.to_pandas")
        arrow, first = frames.arrow_concat(self, "Chunks.to_pandas")
        return frames.pandas_frame(arrow, first, "Chunks.to_pandas")


def _raise_if_all_invalid(table: Table) -> Table:
    """A call none of whose rows can be computed is bad input, not data: raise
    the first row's reason (for one request that is the only reason)."""
    status = table["status"]
    if len(table) and np.all(status == "invalid"):
        raise ParameterError(str(table["reason"][0]))
    return table


# ---------------------------------------------------------------------------
# commands


def orbit(theta, alpha=None, *, body: str = "wheel", side: str = "inside", a=A, r=R, k=None, g=G,
          mu=INF, omega3=None, omega=None, speed=None, stability: bool = True) -> Table:
    """Steady horizontal orbits: ``deathsphere orbit``.

    McDonald (1993): the fit, eq. (0) (outside: eq. 81); r', eq. (8b); the
    spins, eq. (13); the rate Omega and the forces, eqs. (29)-(36) (outside
    the contact condition is eq. 83); a rolling sphere, eqs. (55)-(59).
    Stability (``stability=True``) is beyond the paper: docs/stability.md.

    Parameters
    ----------
    theta : float or array_like
        Polar angle of the contact point from the upward vertical [deg], 0..180.
    alpha : float or array_like, optional
        Wheel: tilt of the wheel below the orbit plane [deg], any angle
        (reduced to (-180, 180]; 205 = -155).  A wheel needs exactly one of
        ``alpha``, ``speed`` and ``omega``; a sphere and a particle take none.
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
        Wheel: centre speed v_cm [m/s]; every tilt alpha giving it, one row each.
    stability : bool
        Fill the stability columns (exact linearisation); False is faster.

    All numeric arguments broadcast against each other like numpy arrays.

    Returns
    -------
    Table
        The columns of ``deathsphere orbit --format csv`` (docs/contract.md),
        one row per element of the broadcast, in row-major order, and
        ``table.shape`` the broadcast shape (``table.grid("v_cm_m_s")``
        gives a column in that shape).  Where one request can have several
        answers -- a sphere given ``omega3`` (two roots of eq. 55) or a
        wheel given ``speed`` or ``omega`` (one row per tilt) -- the rows
        cannot keep a rectangular shape: the table is flat (``shape ==
        (len(table),)``) and ``input_row`` is 1 + the request's flat index
        in the broadcast, shared by its rows.

    Raises
    ------
    ParameterError
        A value outside its parameter's allowed set, wherever it is in an
        array (the command line refuses such an option as a whole), e.g.
        ``theta (polar angle) must be 0..180 deg (got 200)``; or a call none
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
    deathsphere.params.ParameterError: theta (polar angle) must be 0..180 deg (got 200)
    """
    body, side = _choice("body", body, BODIES), _choice("side", side, SIDES)
    given = {"theta": theta, "alpha": alpha, "a": a, "r": r, "k": k, "g": g, "mu": mu, "omega3": omega3,
             "omega": omega, "speed": speed}
    shape, flat = _broadcast({name: _values(name, v) for name, v in given.items() if v is not None})
    n = math.prod(shape)
    table = _raise_if_all_invalid(evaluate(make_requests(n, body=body, side=side, **flat), stability=bool(stability)))
    several = (body == "wheel" and alpha is None) or (body == "sphere" and omega3 is not None)
    return table if several else Table(table.columns, shape=shape)


def vertical(theta, v_top=None, *, phidot_top=None, side: str = "inside", a=A, r=R, k=0.5, g=G, mu=INF,
             points=None, stability: bool = True) -> Table:
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
        As for :func:`orbit`.

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
    from deathsphere.results.vertical import evaluate_vertical, vertical_points, vertical_requests

    side = _choice("side", side, SIDES)
    given = {"theta": theta, "v_top": v_top, "phidot_top": phidot_top, "a": a, "r": r, "k": k, "g": g, "mu": mu}
    shape, flat = _broadcast({name: _values(name, v) for name, v in given.items() if v is not None})
    n = math.prod(shape)
    req = vertical_requests(n, side=side, **flat)
    if points is None:
        return Table(_raise_if_all_invalid(evaluate_vertical(req, stability=bool(stability))).columns, shape=shape)
    points = int(_scalar("points", points))
    table = _raise_if_all_invalid(vertical_points(req, points))
    return Table(table.columns, shape=shape + (points,)) if len(table) == n * points else table


def _vertical_setup(side, a, r, k, g, mu) -> dict:
    """The scalar options of a vertical orbit, checked (a wheel; r > a inside)."""
    setup = _setup("wheel", side, a, r, k, g, mu)
    return dict(side=setup.side, a=setup.a, r=setup.r, k=setup.k, g=setup.g, mu=setup.mu)


def _vertical_work(points: int | None, stability: bool):
    """What one batch of vertical requests becomes: summary rows, or the
    orbit point by point in slices of at most :data:`POINT_ROWS` rows."""
    from deathsphere.results.vertical import evaluate_vertical, vertical_points

    if points is None:
        return lambda batches: ((n, evaluate_vertical(req, stability=stability)) for n, req in batches)

    def sliced(batches):
        for n, req in batches:
            for start in range(0, points, POINT_ROWS):
                last = start + POINT_ROWS >= points
                yield (n if last else 0), vertical_points(req, points, start, start + POINT_ROWS)
    return sliced


def _vertical_chunk(points: int | None) -> int:
    return 256 if points is None else max(1, POINT_ROWS // points)


def vertical_sweep(theta=None, v_top=None, *, phidot_top=None, side: str = "inside", a=A, r=R, k=0.5, g=G, mu=INF,
                   points=None, stability: bool = True) -> Chunks:
    """Every combination of cone angles and top speeds, chunk by chunk:
    ``deathsphere vertical`` (the physics of :func:`vertical`).

    Parameters
    ----------
    theta, v_top, phidot_top : float, array_like or str
        Axes of the grid (theta outer), as for :func:`sweep`: values,
        arrays, ``"start:stop:step"`` text or a list mixing them.  Give
        exactly one of ``v_top`` [m/s] and ``phidot_top`` [rad/s].
    side, a, r, k, g, mu, points, stability : as for :func:`vertical` (one value each).

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
    from deathsphere.results.vertical import vertical_requests

    fixed = _vertical_setup(side, a, r, k, g, mu)
    points = None if points is None else int(_scalar("points", points))
    if not _given(theta):
        raise ParameterError("theta is required: one or more values or start:stop:step ranges", "theta",
                             missing=True)
    if _given(v_top) == _given(phidot_top):
        raise ParameterError("give exactly one of v_top (m/s) and phidot_top (rad/s)",
                             "phidot_top" if _given(v_top) else "v_top")
    key, value = ("v_top", v_top) if _given(v_top) else ("phidot_top", phidot_top)
    axes = {"theta": _axis("theta", theta), key: _axis(key, value)}
    total = _grid_size(axes)
    batches = _grid_requests(axes, _vertical_chunk(points), vertical_requests, fixed)
    return Chunks(_vertical_work(points, bool(stability))(batches), total)


def vertical_input(source, *, theta=None, v_top=None, phidot_top=None, side: str = "inside", a=A, r=R, k=0.5,
                   g=G, mu=INF, points=None, stability: bool = True) -> Chunks:
    """Vertical orbits of the requests in a CSV file: ``deathsphere vertical --input FILE``.

    As :func:`orbit_input`, for :func:`vertical`: the header names
    ``theta`` and ``v_top`` or ``phidot_top`` (and optionally ``side``,
    ``a``, ``r``, ``k``, ``g``, ``mu``); the keyword arguments are the
    defaults for a missing column or an empty cell (one value each).  A
    result CSV of ``vertical`` is read too (``v_cm_m_s`` is the top speed).

    Examples
    --------
    >>> import os, tempfile, deathsphere
    >>> path = os.path.join(tempfile.mkdtemp(), "loops.csv")
    >>> _ = open(path, "w").write("theta,v_top\\n90,6\\n90,-1\\n")
    >>> t = deathsphere.vertical_input(path, stability=False).table()
    >>> t["status"].tolist()
    ['ok', 'invalid']
    """
    from deathsphere.results.vertical import COLUMNS as VERTICAL_COLUMNS
    from deathsphere.results.vertical import VERTICAL_FIELDS, vertical_requests

    defaults = _vertical_setup(side, a, r, k, g, mu)
    points = None if points is None else int(_scalar("points", points))
    for name, value in (("theta", theta), ("v_top", v_top), ("phidot_top", phidot_top)):
        value = _one_default(name, value)
        if value is not None:
            defaults[name] = value
    reader = _reader(source, VERTICAL_FIELDS, defaults, VERTICAL_ECHO, VERTICAL_COLUMNS)
    batches = _input_requests(reader, _vertical_chunk(points), vertical_requests)
    return Chunks(_vertical_work(points, bool(stability))(batches))


class _ValuesAxis(Axis):
    """An axis of explicit values (an array given to :func:`sweep`): a chunk
    indexes the array, however many values it holds."""

    def __init__(self, values: np.ndarray):
        super().__init__([])
        self._values = np.asarray(values, dtype=float).reshape(-1)

    def __len__(self) -> int:
        return int(self._values.size)

    def take(self, index) -> np.ndarray:
        return self._values[np.asarray(index, dtype=np.int64)]


def sweep(theta=None, alpha=None, *, a=A, r=R, k=None, body: str = "wheel", side: str = "inside", g=G, mu=INF,
          omega3=None, omega=None, speed=None, only=None, chunk_size: int = CHUNK, stability: bool = True,
          jobs: int = 1) -> Chunks:
    """Every combination of the axes, chunk by chunk: ``deathsphere sweep``
    (and ``deathsphere orbit`` given several values).

    The physics of :func:`orbit` (McDonald 1993 eqs. (0), (8b), (13),
    (29)-(36), (55)-(59), (81), (83)) over a cartesian grid that is never
    held in memory.

    Parameters
    ----------
    theta, alpha, a, r, k, omega3, omega, speed : float, array_like or str
        The axes (units as in :func:`orbit`): a value, a list or array of
        values, or the command line's text, one value or a range
        ``"start:stop:step"`` (stop included when on the grid, e.g.
        ``"5:175:1"``), or a list mixing both (the values of a repeated
        option, in order).  Grid order is a, r, k, theta, then speed,
        alpha, omega3 or omega fastest.
    body, side, g, mu : as for :func:`orbit` (one value each).
    only : str or list of str, optional
        Keep only rows with these statuses (``"ok"``, ``"no_fit"``, ...).
    chunk_size : int
        Grid points evaluated per chunk (memory stays flat).
    stability : bool
        Fill the stability columns.
    jobs : int
        Processes evaluating chunks (1..256); the chunks come back in grid
        order, the same tables as with one.

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
    body, side = _choice("body", body, BODIES), _choice("side", side, SIDES)
    g, mu = _scalar("g", g), _scalar("mu", mu)
    chunk_size, jobs = int(_scalar("chunk_size", chunk_size)), int(_scalar("jobs", jobs))
    keep = None
    if only is not None:
        keep = [_choice("only", s, STATUSES) for s in ([only] if isinstance(only, str) else only)]
    if not _given(theta):
        raise ParameterError("theta is required: one or more values or start:stop:step ranges", "theta",
                             missing=True)
    axes = {"a": _axis("a", a, A), "r": _axis("r", r, R), "k": _axis("k", k), "theta": _axis("theta", theta),
            "speed": _axis("speed", speed), "alpha": _axis("alpha", alpha), "omega3": _axis("omega3", omega3),
            "omega": _axis("omega", omega)}
    total = _grid_size(axes)
    if len(axes["a"]) == 1 and len(axes["r"]) == 1:
        # one body in one sphere: a combination that cannot be is bad input,
        # not a grid of invalid rows
        one = np.zeros(1, dtype=np.int64)
        _setup(body, side, axes["a"].take(one)[0], axes["r"].take(one)[0], None, g, mu)
    # which inputs the body takes is the same for every grid point: ask the
    # model's validator about the first one (with a and r that always fit,
    # so that only a per-point combination such as r <= a gives invalid rows)
    first = {name: axes[name].take(np.zeros(1, dtype=np.int64))
             for name in ("theta", "alpha", "k", "omega3", "omega", "speed")}
    reason = validate_requests(make_requests(1, body=body, side=side, a=1.0, r=2.0, g=g, mu=mu, **first))[0]
    if reason:
        raise ParameterError(reason)
    fixed = dict(body=body, side=side, g=g, mu=mu)
    work = partial(_evaluate_filtered, stability=bool(stability), keep=keep)
    return Chunks(_evaluated(_grid_requests(axes, chunk_size, make_requests, fixed), work, jobs), total)


def _grid_requests(axes: dict, chunk_size: int, make, fixed: dict) -> Iterator[tuple[int, dict]]:
    """``(n, requests)`` per chunk of the grid of ``axes``, numbered from 1 in grid order."""
    for first, grid in grid_chunks(axes, chunk_size):
        n = len(grid["theta"])
        yield n, make(n, input_row=np.arange(first + 1, first + n + 1), **fixed, **grid)


def _evaluated(batches, work, jobs: int = 1) -> Iterator[tuple[int, Table]]:
    """``(n, work(requests))`` per batch, in order; on ``jobs`` processes if > 1."""
    if jobs == 1:
        for n, req in batches:
            yield n, work(req)
        return
    from deathsphere.parallel import ordered_map

    counts = deque()

    def requests():
        for n, req in batches:
            counts.append(n)
            yield req

    for table in ordered_map(work, requests(), jobs):
        yield counts.popleft(), table


def _evaluate_filtered(req: dict, stability: bool, keep=None) -> Table:
    """Horizontal orbits of a request batch, keeping only the statuses ``keep``."""
    table = evaluate(req, stability=stability)
    if keep is not None:
        table = table[np.isin(table["status"], keep)]
    return table


def _input_requests(reader, chunk_size: int, make) -> Iterator[tuple[int, dict]]:
    """``(n, requests)`` per chunk of an input file's rows; a file with a
    header and no rows gives one empty batch, so that the output still has
    its header."""
    empty = True
    for part in reader.chunks(chunk_size):
        empty = False
        n = len(part.input_row)
        yield n, make(n, invalid=part.invalid, input_row=part.input_row, **part.values)
    if empty:
        yield 0, make(0, **{name: np.empty(0, dtype=object if name in ("body", "side") else float)
                            for name in reader.fields})


def _reader(source, fields: dict, defaults: dict, echo: dict, columns):
    """A streaming reader of the request CSV ``source`` (a path, or ``"-"``
    for standard input).  ``echo`` maps the output columns that echo an
    input back to that input, so that a result CSV can be fed back; every
    other output column in ``columns`` is read and ignored."""
    from deathsphere.inputs import InputError, RequestReader, open_input

    name = "stdin" if source == "-" else os.fspath(source)
    try:
        return RequestReader(open_input(os.fspath(source)), fields, defaults, source=name, aliases=echo,
                             ignore=[c for c in columns if c not in echo])
    except InputError as exc:
        raise ParameterError(str(exc), "input") from None


def orbit_input(source, *, theta=None, alpha=None, omega3=None, omega=None, speed=None, body: str = "wheel",
                side: str = "inside", a=A, r=R, k=None, g=G, mu=INF, stability: bool = True,
                chunk_size: int = CHUNK) -> Chunks:
    """Horizontal orbits of the requests in a CSV file: ``deathsphere orbit --input FILE``.

    The physics of :func:`orbit`, one request per line, streamed: a file of
    any length runs in the memory of one chunk.

    Parameters
    ----------
    source : str or path
        The CSV file, or ``"-"`` for standard input.  Its header names the
        inputs (``theta``, ``alpha``, ``omega3``, ``omega``, ``speed``,
        ``body``, ``side``, ``a``, ``r``, ``k``, ``g``, ``mu``); an output
        CSV of ``orbit`` is read too (``theta_deg``, ``alpha_deg``, ...
        echo their inputs; its other columns are ignored).
    theta, alpha, omega3, omega, speed, body, side, a, r, k, g, mu
        One value each: the default for a column the file lacks or a cell
        left empty.
    stability, chunk_size : as for :func:`sweep`.

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
    setup = _setup(body, side, a, r, k, g, mu)
    chunk_size = int(_scalar("chunk_size", chunk_size))
    defaults = dict(body=setup.body, side=setup.side, a=setup.a, r=setup.r, k=k, g=setup.g, mu=setup.mu)
    if k is not None:
        defaults["k"] = setup.k
    for name, value in (("theta", theta), ("alpha", alpha), ("omega3", omega3), ("omega", omega),
                        ("speed", speed)):
        value = _one_default(name, value)
        if value is not None:
            defaults[name] = value
    from deathsphere.inputs import ALIASES

    reader = _reader(source, REQUEST_FIELDS, defaults, ALIASES, COLUMNS)
    work = partial(_evaluate_filtered, stability=bool(stability))
    return Chunks(_evaluated(_input_requests(reader, chunk_size, make_requests), work))


def _ratio(a, r, side) -> tuple[float, float]:
    """The body radius over the sphere radius (all the map depends on), to
    15 significant digits so that ``-a 0.3 -r 3`` is the 0.1 a user reads
    (0.3 / 3.0 is 0.09999999999999999 in float64), and the inertia factor."""
    side = _choice("side", side, SIDES)
    setup = _setup("wheel", side, a, r, None, G, INF)
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
    values = {name: _scalar(name, v) for name, v in (("k", k), ("mu", mu), ("max_g", max_g), ("step", step),
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
    values = {name: _scalar(name, v) for name, v in (("k", k), ("mu", mu), ("max_g", max_g))}
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
    values = {name: _scalar(name, v) for name, v in (("k", k), ("mu", mu), ("max_g", max_g))}
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

    setup = _setup("wheel", side, a, r, k, g, mu)
    max_g = _scalar("max_g", max_g)
    if not _given(theta):
        return highest_orbit_table(setup, max_g)
    thetas = _axis("theta", theta)
    if len(thetas) > MAX_LIMIT_THETAS:
        raise ParameterError(f"theta: {len(thetas)} values, more than {MAX_LIMIT_THETAS} (each is a root search)",
                             "theta")
    return intervals_table(setup, thetas.values(), max_g)


def stability(theta, alpha, *, a=A, r=R, k=None, g=G, mu=INF, side: str = "inside") -> Table:
    """One wheel orbit's exact stability beside the paper's results: ``deathsphere stability``.

    The exact verdict, growth rate and nutation frequencies (the equations of
    motion linearised about the orbit) are beyond the paper
    (docs/stability.md); then the paper's results as printed and as
    corrected: the equator, eqs. (133)-(138); small wheels, eqs.
    (202)-(207); near the poles, eq. (208).

    Parameters
    ----------
    theta : float
        Polar angle of the orbit [deg], 0..180.
    alpha : float
        Tilt of the wheel [deg], any angle.
    a, r, k, g, mu, side : as for :func:`orbit` (one value each).

    Returns
    -------
    Table
        The rows of ``deathsphere stability --format csv``: ``source``,
        ``equation``, ``quantity``, ``paper``, ``corrected``, ``exact``,
        ``deviation``, ``note``, ...

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.stability(90, 45)
    >>> row = [r for r in t if r["quantity"] == "verdict" and r["source"] == "exact"][0]
    >>> row["exact"]
    'stable'
    """
    from deathsphere.results.stability_report import stability_report

    setup = _setup("wheel", side, a, r, k, g, mu)
    return stability_report(setup, _scalar("theta", theta), _scalar("alpha", alpha))


def simulate(theta, alpha=None, *, body: str = "wheel", side: str = "inside", a=A, r=R, k=None, g=G, mu=INF,
             omega3=None, omega=None, branch: int = 0, vertical: bool = False, v_top=None, perturb=0.0,
             periods=20.0, points_per_period=100, method: str = "DOP853", rtol: float = 1e-10,
             atol: float | None = None, frame: str = "turning") -> tuple[Table, Table]:
    """Integrate the exact equations of motion from a steady orbit: ``deathsphere simulate``.

    Beyond the paper (docs/simulation.md): the Newton-Euler equations of a
    body rolling without slipping, eqs. (2)-(7b) in general form, are
    integrated with scipy's solve_ivp from the steady orbit of :func:`orbit`
    (or, with ``vertical``, of :func:`vertical`), optionally kicked off it.

    Parameters
    ----------
    theta : float
        Polar angle of the contact point [deg] (vertical: the cone angle).
    alpha : float, optional
        Wheel: tilt of the steady orbit [deg].
    body : {"wheel", "sphere"}
    side, a, r, k, g, mu : as for :func:`orbit` (k > 0); the run stops with
        ``slips`` when the friction needed exceeds ``mu``.
    omega3, omega : float, optional
        Sphere: spin about the contact normal, or the signed orbital rate [rad/s].
    branch : {0, 1}
        Sphere with ``omega3``: the root of eq. (55) (0 slow, 1 fast).
    vertical : bool
        A vertical orbit of a wheel started at the top with ``v_top`` [m/s].
    perturb : float
        Kick off the steady orbit [deg], -60..60: the wheel tilted by this
        about its direction of travel (a sphere: its contact point moved
        this far down the meridian); rolling and contact still hold.
    periods : float
        Run length in periods of the steady orbit (vertical: laps).
    points_per_period : int
        Rows per period, 2..100000.
    method : {"DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA"}
    rtol, atol : float
        solve_ivp's tolerances (atol defaults to rtol, per scaled component).
    frame : {"turning", "lab"}

    Returns
    -------
    (Table, Table)
        The time series (``deathsphere simulate --format csv``: ``t_s``,
        ``theta_deg``, ``alpha_deg``, forces, drifts) and the one-row
        summary (``--summary-only``: ``status`` completed, contact_lost,
        slips, ...).

    Examples
    --------
    >>> import deathsphere
    >>> series, summary = deathsphere.simulate(60, 10, periods=0.1, points_per_period=20)
    >>> len(series), str(summary["status"][0])
    (3, 'completed')
    """
    return prepare_simulation(theta, alpha, body=body, side=side, a=a, r=r, k=k, g=g, mu=mu, omega3=omega3,
                              omega=omega, branch=branch, vertical=vertical, v_top=v_top, perturb=perturb,
                              periods=periods, points_per_period=points_per_period, method=method, rtol=rtol,
                              atol=atol, frame=frame).run()


def prepare_simulation(theta, alpha=None, *, body: str = "wheel", side: str = "inside", a=A, r=R, k=None, g=G,
                       mu=INF, omega3=None, omega=None, branch: int = 0, vertical: bool = False, v_top=None,
                       perturb=0.0, periods=20.0, points_per_period=100, method: str = "DOP853",
                       rtol: float = 1e-10, atol: float | None = None, frame: str = "turning",
                       record_states: bool = False):
    """The validated :class:`deathsphere.simulation.Simulation` behind
    :func:`simulate` (same parameters), not yet run: for streaming the time
    series chunk by chunk (``sim.chunks()``, then ``sim.summary()``), as the
    command line does; ``record_states`` keeps the full states for the 3-D
    view.  Bad input raises :class:`ParameterError`.

    Examples
    --------
    >>> sim = prepare_simulation(60, 10, periods=0.1, points_per_period=20)
    >>> sum(len(chunk) for chunk in sim.chunks()), str(sim.summary()["status"][0])
    (3, 'completed')
    """
    from deathsphere import simulation

    setup = _setup(body, side, a, r, k, g, mu)
    theta = _scalar("theta", theta)
    alpha, omega3, omega, v_top = (None if v is None else _scalar(name, v) for name, v in
                                   (("alpha", alpha), ("omega3", omega3), ("omega", omega), ("v_top", v_top)))
    perturb, periods = _scalar("perturb", perturb), _scalar("periods", periods)
    points_per_period = int(_scalar("points_per_period", points_per_period))
    method = _choice("method", method, METHODS_LOWER)
    method = METHODS[METHODS_LOWER.index(method)]
    frame = _choice("frame", frame, FRAMES)
    rtol, atol = _scalar("rtol", rtol), _optional("atol", atol)
    if isinstance(branch, bool) or branch not in (0, 1):
        raise ParameterError(f"branch must be 0 (slow root of eq. 55) or 1 (fast root) (got {branch!r})")
    # which inputs each kind of run takes (the command line's rules, in words
    # naming the parameters of this function)
    if setup.body == "particle":
        raise ParameterError("simulate covers a wheel or a sphere (a particle has no rolling dynamics)")
    if vertical:
        if setup.body != "wheel" or alpha is not None or v_top is None:
            raise ParameterError("vertical=True simulates a wheel: give theta and v_top (no alpha)")
    elif v_top is not None:
        raise ParameterError("v_top is for vertical orbits (vertical=True)")
    elif setup.body == "wheel" and (alpha is None or omega3 is not None or omega is not None):
        raise ParameterError("a wheel's steady orbit needs alpha (deg), and no omega3 or omega")
    elif setup.body == "sphere" and (alpha is not None or (omega3 is None) == (omega is None)):
        raise ParameterError("a sphere's steady orbit needs exactly one of omega3 and omega (no alpha)")
    if setup.k == 0:
        raise ParameterError("simulate needs k > 0: at k = 0 the equations of motion are singular")
    try:
        if vertical:
            starts = simulation.vertical_starts(setup, theta, v_top, perturb_deg=perturb)
        elif setup.body == "wheel":
            starts = simulation.horizontal_starts(setup, theta, params.reduce_angle(alpha), perturb_deg=perturb)
        else:
            starts = simulation.horizontal_starts(setup, theta, omega3=omega3, omega=omega, branch=branch,
                                                  perturb_deg=perturb)
        sim = simulation.Simulation(starts, periods=periods, points_per_period=points_per_period, method=method,
                                    rtol=rtol, atol=atol, frame=frame, record_states=record_states)
    except ValueError as exc:  # the simulation's own checks (method, frame, tolerances)
        raise ParameterError(str(exc)) from None
    return sim


def table1() -> Table:
    """The paper's Table 1 beside the values recomputed from eqs. (29), (35), (36):
    ``deathsphere table1``.

    Wheel a = 0.3 m, k = 1/2 in a sphere r = 3.0 m, standard gravity; the
    ``note`` column names every disagreement (docs/errata.md).

    Returns
    -------
    Table
        Ten rows, one per printed orbit: the printed mu, v_cm and "No. of
        g's", the computed values, whether each printed value is reproduced,
        and a note.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.table1()
    >>> len(t), t[3]["v_cm_printed_m_s"], round(t[3]["v_cm_computed_m_s"], 2), t[3]["v_cm_agrees"]
    (10, 7.9, 7.88, True)
    """
    from deathsphere.results.table1 import table1 as compute

    return compute()


def verify(claims=None, *, jobs: int = 1, progress=None) -> Table:
    """Check the paper's quantitative claims: ``deathsphere verify``.

    Parameters
    ----------
    claims : str or list of str, optional
        Claim ids (as ``--claim``); all by default.
    jobs : int
        Processes checking claims (the same table as with one).
    progress : callable, optional
        ``progress(claim)`` as each claim is taken up (one process) or done.

    Returns
    -------
    Table
        One row per claim: ``id``, ``section``, ``equation``, ``claim``,
        ``verdict`` (confirmed, corrected or refuted, docs/errata.md) and
        the ``evidence``.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.verify("T1-v")
    >>> t[0]["verdict"]
    'confirmed'
    """
    from deathsphere.results.verify import CLAIMS, run

    ids = None if not _given(claims) else ([claims] if isinstance(claims, str) else list(claims))
    known = {c.id for c in CLAIMS}
    for c in ids or ():
        if c not in known:
            raise ParameterError(f"unknown claim {c!r}; known: {' '.join(sorted(known))}", "claims")
    return run(ids, progress=progress, jobs=int(_scalar("jobs", jobs)))


def n_claims(claims=None) -> int:
    """How many claims :func:`verify` checks for ``claims`` (a progress bar's total)."""
    from deathsphere.results.verify import CLAIMS

    return len(CLAIMS) if not _given(claims) else (1 if isinstance(claims, str) else len(claims))
