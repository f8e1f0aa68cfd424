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
from collections.abc import Iterator

import numpy as np

from deathsphere import params
from deathsphere.constants import (
    BODIES,
    SIDES,
    STANDARD_GRAVITY,
    TABLE1_SPHERE_RADIUS,
    TABLE1_WHEEL_RADIUS,
)
from deathsphere.grid import MAX_GRID_ROWS, Axis, RangeError, grid_chunks, grid_size, parse_segment
from deathsphere.model import Setup, Table, evaluate, make_requests, validate_requests
from deathsphere.params import ParameterError
from deathsphere.physics.status import STATUS_LABELS

__all__ = ["orbit", "vertical", "sweep", "region", "limits", "stability", "simulate", "table1", "verify",
           "ParameterError"]

G = STANDARD_GRAVITY
A = TABLE1_WHEEL_RADIUS
R = TABLE1_SPHERE_RADIUS
INF = math.inf

#: Orbits per chunk of :func:`sweep` (the command line's ``--chunk-size`` default).
CHUNK = 16384
#: Row statuses (``only=`` of :func:`sweep`).
STATUSES = tuple(str(s) for s in STATUS_LABELS)


# ---------------------------------------------------------------------------
# checking the arguments: every domain is in deathsphere.params, every
# combination rule in the model's validators; nothing is re-implemented here


def _values(name: str, value) -> np.ndarray:
    """``value`` (a number, list or array) as a float array whose every
    element is an allowed ``name``; else ParameterError with the reason."""
    if isinstance(value, str):
        raise ParameterError(f"{name} must be a number (got {value!r})")
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a number (got {value!r})") from None
    reason = params.first_problem(name, arr)
    if reason:
        raise ParameterError(reason)
    return arr


def _scalar(name: str, value) -> float:
    """One allowed value of ``name`` (an array of one element is not one value)."""
    if np.ndim(value) != 0:
        raise ParameterError(f"{name} takes one value (got an array of shape {np.shape(value)})")
    return params.check(name, value)


def _choice(name: str, value, allowed) -> str:
    if not isinstance(value, str):
        raise ParameterError(f"{name} must be one of {' | '.join(allowed)} (got {value!r})")
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
    >>> t.shape, str(t["status"][0]), round(float(t["v_cm_m_s"][0]), 2)
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
    >>> str(t["status"][0]), round(float(t["v_top_min_m_s"][0]), 3)
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


def _sweep_axis(name: str, value, default=None) -> Axis:
    """A sweep axis from values, an array, or the command line's text
    ``"start:stop:step"`` (lazy: never materialised)."""
    if value is None:
        return _ValuesAxis(np.array([math.nan if default is None else default]))
    if isinstance(value, str):
        try:
            seg = parse_segment(value, name)
        except RangeError as exc:
            raise ParameterError(str(exc).split(": ", 1)[-1]) from None
        axis = Axis([seg])
        reason = params.first_problem(name, [seg.first, seg.last])   # a range is monotone: its ends decide
        if not reason and params.PARAMS[name].nonzero and axis.contains_zero():
            reason = f"{name} must not be 0 ({params.PARAMS[name].allowed()})"
        if reason:
            raise ParameterError(reason)
        return axis
    return _ValuesAxis(np.atleast_1d(_values(name, value)))


def sweep(theta, alpha=None, *, a=A, r=R, k=None, body: str = "wheel", side: str = "inside", g=G, mu=INF,
          omega3=None, omega=None, only=None, chunk_size: int = CHUNK,
          stability: bool = True) -> Iterator[Table]:
    """Every combination of the axes, chunk by chunk: ``deathsphere sweep``.

    The physics of :func:`orbit` (McDonald 1993 eqs. (0), (8b), (13),
    (29)-(36), (55)-(59), (81), (83)) over a cartesian grid that is never
    held in memory.

    Parameters
    ----------
    theta, alpha, a, r, k, omega3, omega : float, array_like or str
        The axes (units as in :func:`orbit`): a value, a list or array of
        values, or the command line's text, one value or a range
        ``"start:stop:step"`` (stop included when on the grid, e.g.
        ``"5:175:1"``).  Grid order is a, r, k, theta, then alpha, omega3
        or omega fastest, as on the command line.
    body, side, g, mu : as for :func:`orbit` (one value each).
    only : str or list of str, optional
        Keep only rows with these statuses (``"ok"``, ``"no_fit"``, ...).
    chunk_size : int
        Grid points evaluated per chunk (memory stays flat).
    stability : bool
        Fill the stability columns.

    Returns
    -------
    iterator of Table
        One table per chunk of ``chunk_size`` grid points, in grid order
        (with ``only``, a chunk may be empty); ``input_row`` numbers the
        grid points from 1.  Together they are ``deathsphere sweep
        --format csv``.  A combination that is not allowed (r <= a inside)
        is an ``invalid`` row with the reason.

    Raises
    ------
    ParameterError
        At the call (before any chunk): a value outside its set, a bad
        range, or inputs the body does not take.

    Examples
    --------
    >>> import deathsphere
    >>> chunks = deathsphere.sweep("30:90:30", [5, 10], chunk_size=4, stability=False)
    >>> [len(c) for c in chunks]
    [4, 2]
    >>> ok = deathsphere.sweep(60, [10, 30, 60], only="ok", stability=False)
    >>> [row["alpha_deg"] for chunk in ok for row in chunk]
    [10.0, 30.0]
    """
    body, side = _choice("body", body, BODIES), _choice("side", side, SIDES)
    g, mu = _scalar("g", g), _scalar("mu", mu)
    chunk_size = int(_scalar("chunk_size", chunk_size))
    keep = None
    if only is not None:
        keep = [_choice("only", s, STATUSES) for s in ([only] if isinstance(only, str) else only)]
    axes = {"a": _sweep_axis("a", a, A), "r": _sweep_axis("r", r, R), "k": _sweep_axis("k", k),
            "theta": _sweep_axis("theta", theta), "alpha": _sweep_axis("alpha", alpha),
            "omega3": _sweep_axis("omega3", omega3), "omega": _sweep_axis("omega", omega)}
    total = grid_size(axes)
    if total > MAX_GRID_ROWS:
        raise ParameterError(f"the grid has {total:.3g} orbits, more than {MAX_GRID_ROWS:.0e}")
    # which inputs the body takes is the same for every grid point: ask the
    # model's validator about the first one (with a and r that always fit,
    # so that only a per-point combination such as r <= a gives invalid rows)
    first = {name: axes[name].take(np.zeros(1, dtype=np.int64)) for name in ("theta", "alpha", "k", "omega3", "omega")}
    reason = validate_requests(make_requests(1, body=body, side=side, a=1.0, r=2.0, g=g, mu=mu, **first))[0]
    if reason:
        raise ParameterError(reason)
    return _sweep_chunks(axes, chunk_size, keep, bool(stability), body=body, side=side, g=g, mu=mu)


def _sweep_chunks(axes, chunk_size, keep, with_stability, **fixed) -> Iterator[Table]:
    for first, grid in grid_chunks(axes, chunk_size):
        n = len(grid["theta"])
        table = evaluate(make_requests(n, input_row=np.arange(first + 1, first + n + 1), **fixed, **grid),
                         stability=with_stability)
        if keep is not None:
            mask = np.isin(table["status"], keep)
            table = Table({name: col[mask] for name, col in table.columns.items()})
        yield table


def region(a_over_r=0.1, *, k=0.5, side: str = "inside", mu=INF, max_g=INF, step=0.5,
           stability: bool = False) -> Table:
    """The allowed (theta, alpha) region of a wheel as data: ``deathsphere map --format csv``.

    Its boundaries are the paper's: eq. (0) (the wheel fits; outside eq. 81),
    eq. (29) (Omega^2 > 0) and eq. (33) (contact; outside eq. 83); the
    friction and g-load limits and the stability boundary are beyond the
    paper (docs/limits.md, docs/stability.md).

    Parameters
    ----------
    a_over_r : float
        Wheel radius over sphere radius (< 1 inside; the paper's figure: 0.1).
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

    Returns
    -------
    Table
        One row per boundary point: ``curve``, ``equation``, ``theta_deg``,
        ``alpha_deg`` (root-found to 1e-9 rad), ``a_over_r``, ``k``.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.region(step=10)
    >>> sorted(set(t["curve"]))
    ['eq0', 'eq29', 'eq33']
    """
    from deathsphere.results.limits import boundary_table

    side = _choice("side", side, SIDES)
    a_over_r = _scalar("a_over_r", a_over_r)
    if side == "inside" and not a_over_r < 1:
        raise ParameterError(f"a_over_r must be < 1 inside the sphere (got {a_over_r:g})")
    values = {name: _scalar(name, v) for name, v in (("k", k), ("mu", mu), ("max_g", max_g), ("step", step))}
    return boundary_table(a_over_r, values["k"], side == "outside", values["mu"], values["max_g"], values["step"],
                          stability=bool(stability))


def limits(theta=None, *, a=A, r=R, k=None, g=G, mu=INF, max_g=INF, side: str = "inside") -> Table:
    """The feasible tilts at theta, or the highest orbit: ``deathsphere limits``.

    Beyond the paper (method: docs/limits.md), from its conditions eqs. (0),
    (29), (33) (outside (81), (83)), the friction needed (eq. 35) and the
    g-load (eq. 36).

    Parameters
    ----------
    theta : float or array_like, optional
        Polar angle(s) of the orbit [deg].  Without it: the highest orbit
        possible (the smallest theta with a feasible tilt).
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
    if theta is None:
        return highest_orbit_table(setup, max_g)
    return intervals_table(setup, np.atleast_1d(_values("theta", theta)).reshape(-1), max_g)


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
        Kick off the steady orbit [rad], -1..1.
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
            starts = simulation.vertical_starts(setup, theta, v_top, perturb=perturb)
        elif setup.body == "wheel":
            starts = simulation.horizontal_starts(setup, theta, params.reduce_angle(alpha), perturb=perturb)
        else:
            starts = simulation.horizontal_starts(setup, theta, omega3=omega3, omega=omega, branch=branch,
                                                  perturb=perturb)
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


def verify(claims=None) -> Table:
    """Check the paper's quantitative claims: ``deathsphere verify``.

    Parameters
    ----------
    claims : str or list of str, optional
        Claim ids (as ``--claim``); all by default.

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

    ids = None if claims is None else ([claims] if isinstance(claims, str) else list(claims))
    known = {c.id for c in CLAIMS}
    for c in ids or ():
        if c not in known:
            raise ParameterError(f"unknown claim {c!r}; known: {' '.join(sorted(known))}")
    return run(ids)
