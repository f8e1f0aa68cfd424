"""The two-wheeler of ``deathsphere ride --flat`` and ``--steer``: the
Whipple bicycle in the benchmark's parameters (:class:`TwoWheeler`), its
presets, and its tables: the eigenvalues of upright straight running on
flat ground against speed, and the steady turns on the globe's lanes with
their stability (beyond the paper; docs/two-wheeler.md sec. 7-8 and 10).

A two-wheeler is validated once, at construction: a bad one raises
:class:`~deathsphere.ParameterError` with one line before any work.
"""

from __future__ import annotations

from collections.abc import Mapping

import math
import re
from dataclasses import dataclass

import numpy as np

from deathsphere.api.arguments import (INF, G, R, checked_array, checked_axis, checked_flag, checked_statuses,
                                       grid_shape, sphere_radius)
from deathsphere.api.machines import PRESETS
from deathsphere.params import ParameterError, shown_number
from deathsphere.physics.ground import Plane, Sphere
from deathsphere.physics.status import REASON_TEXT, STATUS_LABELS, Status
from deathsphere.records.two_wheeler import DEFAULT_HEAD, TwoWheeler, benchmark_two_wheeler
# the records' presets and files, as the command line and a notebook reach them
from deathsphere.records.two_wheeler_files import is_two_wheeler_file, two_wheeler_file, two_wheeler_text
from deathsphere.records.two_wheeler_presets import NAMES as TWO_WHEELER_NAMES
from deathsphere.records.two_wheeler_presets import TWO_WHEELERS, as_two_wheeler
from deathsphere.requests.arena import refuse_above_top
from deathsphere.requests.decode import read_machine_file
from deathsphere.table import Table

__all__ = ["TwoWheeler", "TWO_WHEELERS", "machines_table", "as_two_wheeler", "is_two_wheeler", "two_wheeler_only", "two_wheeler_ride", "STRAIGHT_COLUMNS",
           "STRAIGHT_SUMMARY_COLUMNS", "TURN_COLUMNS", "STEER_MODES", "simulate_two_wheeler", "CONTROLS",
           "SIMULATE_COLUMNS", "SIMULATE_SUMMARY_COLUMNS", "DEFAULT_HEAD"]

#: How the steer is held in the stability analysis (docs/two-wheeler.md sec. 8.3).
STEER_MODES = ("free", "locked")

#: Steady-turn requests (lanes x speeds or torques) one call answers: with
#: the stability each costs some 0.4 ms of CPU on a grid, and each distinct
#: lane some 10 ms for its lean curve (docs/two-wheeler.md sec. 8.6), so this
#: is 12 s on a grid of lanes x speeds, 5 minutes if no two lanes agree.
MAX_TURN_REQUESTS = 30_000
#: Speeds of straight running one call answers (a few microseconds each):
#: the table is held whole (some 0.25 KB a row) and ``ride --flat`` writes it
#: at once, near 2 KB a row at its peak, so this bounds the command at
#: about 1 GB (2e6 speeds ran out of memory).
MAX_STRAIGHT_SPEEDS = 500_000
#: Speeds whose eigenvalues are found together: the temporaries of a few
#: 4 x 4 matrices per speed stay small, the table is the only large array.
STRAIGHT_CHUNK = 1 << 14


#: What each kind of machine answers (the ``machines`` listing's last column).
SINGLE_CONTACT_ANSWERS = ("ride: lanes on the globe a drum or a cone and vertical loops; show; simulate (one rigid "
                          "frame and one contact; steer locked)")
TWO_WHEELER_ANSWERS = ("ride: steady turns in the globe with the steer free locked or held (stability; hands-free) "
                       "and straight running on flat ground (--flat); simulate with its steer")


def machines_table():
    """``deathsphere machines``: the presets, one row each: the
    single-contact machines, then the two-wheelers (kind ``two-wheeler``,
    their geometry in the appended columns; docs/two-wheeler.md sec. 10),
    each name one machine; ``answers`` the questions each kind answers."""
    two = [t.row() | {"answers": TWO_WHEELER_ANSWERS} for t in TWO_WHEELERS.values()]
    blank = {k: np.nan for k in list(two[0])[list(two[0]).index("kind") + 1:-1]}
    rows = [m.row() | {"kind": "single-contact"} | blank | {"answers": SINGLE_CONTACT_ANSWERS}
            for m in PRESETS.values()] + two
    cols = {}
    for key in rows[0]:
        vals = [r[key] for r in rows]
        cols[key] = np.array(vals, dtype=object if isinstance(vals[0], str) else float)
    return Table(cols)


def is_two_wheeler(machine) -> bool:
    """True for a :class:`TwoWheeler` or the name of a two-wheeler preset."""
    return isinstance(machine, TwoWheeler) or (isinstance(machine, str) and machine.strip().lower() in TWO_WHEELERS)


def two_wheeler_only(machine) -> bool:
    """True for the name of a preset that is a two-wheeler and not also a
    single-contact machine (``sport-tourer``): ``ride`` asks it the
    two-wheeler's questions without ``flat`` or ``steer``."""
    name = machine.strip().lower() if isinstance(machine, str) else None
    return name in TWO_WHEELERS and name not in PRESETS


# ---------------------------------------------------------------------------
# the tables

#: The columns of ``ride --flat``: upright straight running on flat ground.
STRAIGHT_COLUMNS = ("input_row", "machine", "steer", "speed_m_s", "g_m_s2", "stability", "growth_rate_1_s")
#: The columns ``ride --flat`` appends after the eigenvalues: what a disturbance does (docs/two-wheeler.md sec. 7).
STRAIGHT_APPENDED = ("stability_kind",)
#: The columns of ``ride --flat --summary``.
STRAIGHT_SUMMARY_COLUMNS = ("machine", "g_m_s2", "weave_speed_m_s", "capsize_speed_m_s", "speeds_tried",
                            "speeds_stable")
#: The columns of ``ride --steer`` on the globe (then the eigenvalues' columns).
TURN_COLUMNS = (
    "input_row", "machine", "theta_deg", "alpha_deg", "lean_deg", "r_m", "height_m", "g_m_s2", "status", "reason",
    "omega_rad_s", "period_s", "v_cm_m_s", "v_cm_km_h", "v_contact_m_s", "load_g", "head_clearance_m", "steer_deg",
    "steer_torque_n_m", "pitch_deg", "normal_rear_per_mass_m_s2", "normal_front_per_mass_m_s2", "mu_required_rear",
    "mu_required_front", "friction_rear_per_mass_m_s2", "friction_front_per_mass_m_s2", "lean_surface_deg",
    "v_rear_m_s", "v_front_m_s", "theta_front_deg", "steer", "stability", "growth_rate_1_s",
)


def _sorted_eigenvalues(values):
    """Largest real part first, ties by imaginary part, largest first (as
    ``stability.eigenvalues``)."""
    order = np.lexsort((-values.imag, -values.real), axis=-1)
    return np.take_along_axis(values, order, axis=-1)


def _eig_cols(values, k) -> dict:
    cols = {}
    for i in range(k):
        re = values[:, i].real.copy()
        # no eigenvalue (no turn, not analysed) is empty in both parts: nan + 0j has an imaginary part 0
        cols[f"eig_{i + 1}_re"], cols[f"eig_{i + 1}_im"] = re, np.where(np.isnan(re), np.nan, values[:, i].imag)
    return cols


def _values(name: str, value, limit: int, option: str | None = None, shaped: bool = False) -> np.ndarray:
    """The values asked for (values, ranges, units) as one flat array, or
    with ``shaped`` in the shape they were given (numbers and arrays keep
    theirs, to broadcast; text, a range or a list holding one, is a line of
    values), refused before they are built when there are more than ``limit``."""
    option = option or name
    if isinstance(value, (list, tuple, np.ndarray)) and np.size(value) == 0:
        return np.empty(0)      # none asked for: no row, as deathsphere.orbit answers an empty list
    text = isinstance(value, str) or (isinstance(value, (list, tuple))
                                      and any(isinstance(v, str) for v in np.ravel(np.asarray(value, dtype=object))))
    try:
        if shaped and not (text and ":" in str(value)):
            values = checked_array(name, value)
        else:
            axis = checked_axis(name, value if isinstance(value, (str, list, tuple)) else np.asarray(value))
            if len(axis) > limit:
                values = None
            else:
                values = np.asarray(axis.take(np.arange(len(axis))), dtype=float).reshape(-1)
    except ParameterError as exc:
        raise ParameterError(str(exc).replace(name, option, 1), option) from None
    count = len(axis) if values is None else values.size
    if count > limit:
        raise ParameterError(f"a two-wheeler takes at most {limit} values of {option} at once (got {count}): "
                             "split the range", option)
    return values


def _speeds(speed, limit: int, shaped: bool = False) -> np.ndarray:
    """The rear contact's speeds asked for."""
    if speed is None:
        raise ParameterError("give speed: the rear contact's speed(s) in m/s", "speed", missing=True)
    return _values("rear_speed", speed, limit, "speed", shaped)


def _straight_eigenvalues(m, v, steer: str) -> np.ndarray:
    """Upright straight running's eigenvalues at the speeds ``v``, largest real part first."""
    from deathsphere.physics.two_wheeler import linear

    if steer == "free":
        return _sorted_eigenvalues(linear.eigenvalues(m, v))
    # steer locked: the lean row alone, M_ll s^2 + v C1_ll s + g K0_ll + v^2 K2_ll = 0
    a, b, c = m.M[0, 0], v * m.C1[0, 0], m.g * m.K0[0, 0] + v**2 * m.K2[0, 0]
    root = np.sqrt((b * b - 4 * a * c).astype(complex))
    return _sorted_eigenvalues(np.stack([(-b + root) / (2 * a), (-b - root) / (2 * a)], axis=-1))


def _straight(t: TwoWheeler, g: float, speed, steer: str, summary: bool) -> Table:
    """Upright straight running on flat ground under gravity ``g``: the benchmark's eigenvalues
    against speed (Meijaard et al. 2007, Table 2 and Figure 3; docs/two-wheeler.md sec. 7)."""
    from deathsphere.physics.two_wheeler import linear, stability

    v = _speeds(speed, MAX_STRAIGHT_SPEEDS)
    m = linear.benchmark_matrices(t.parameters(), g)
    values = np.empty((v.size, 4 if steer == "free" else 2), dtype=complex)
    for start in range(0, v.size, STRAIGHT_CHUNK):
        values[start:start + STRAIGHT_CHUNK] = _straight_eigenvalues(m, v[start:start + STRAIGHT_CHUNK], steer)
    verdicts, growth = stability.verdict(values)
    if summary:
        ok = verdicts == "stable"
        high = max(10.0, float(v.max(initial=0.0)))
        return Table({"machine": np.array([t.name], dtype=object), "g_m_s2": np.array([g]),
                      # a motorcycle's speeds lie beyond a bicycle's 10 m/s: searched up to the fastest asked
                      "weave_speed_m_s": np.array([linear.weave_speed(m, high=high)]),
                      "capsize_speed_m_s": np.array([linear.capsize_speed(m, high=high)]),
                      "speeds_tried": np.array([v.size], dtype=np.int64),
                      "speeds_stable": np.array([int(ok.sum())], dtype=np.int64)})
    n = v.size
    cols = {"input_row": np.arange(n) + 1, "machine": np.full(n, t.name, dtype=object),
            "steer": np.full(n, steer, dtype=object), "speed_m_s": v, "g_m_s2": np.full(n, g),
            "stability": verdicts.astype(object), "growth_rate_1_s": growth}
    return Table(cols | _eig_cols(values, values.shape[-1]) | {"stability_kind": stability.kind(values)})


#: The columns ``ride --steer`` appends after the eigenvalues: the limits the
#: statuses were decided with (empty where none was given).
TURN_LIMIT_COLUMNS = ("mu_available", "max_g")
#: Then (docs/contract.md): what a disturbance does, and the lean named by
#: what it is measured from, the wall's normal at the rear contact
#: (``lean_surface_deg``) and the vertical (``lean_deg``).
TURN_APPENDED = ("stability_kind", "lean_wall_deg", "lean_vertical_deg")
#: The columns of ``ride --steer --summary``, the rider's table on the globe:
#: those of ride's rider's table that keep their meaning (the speeds are the
#: rear contact's, m/s), then the two-wheeler's own (docs/two-wheeler.md
#: sec. 10).
TURN_SUMMARY_COLUMNS = (
    "height_m", "theta_deg", "speeds_tried", "speeds_ok", "v_rear_min_m_s", "v_rear_max_m_s", "lean_min_deg",
    "lean_max_deg", "load_min_g", "load_max_g", "mu_max", "head_clearance_min_m", "limits", "mu_available",
    "max_g", "slips", "over_g", "head_hits", "no_contact", "no_orbit", "steer", "speeds_stable", "stable_v_min_m_s",
    "stable_v_max_m_s", "steer_torque_min_n_m", "steer_torque_max_n_m", "hands_free_turns", "hands_free_stable",
    "hands_free_v_rear_m_s", "hands_free_stable_v_rear_m_s", "lean_vertical_min_deg", "lean_vertical_max_deg",
    "lean_wall_min_deg", "lean_wall_max_deg", "stable_beyond_limits", "stable_beyond_v_min_m_s",
    "stable_beyond_v_max_m_s", "stable_load_min_g", "stable_load_max_g", "growth_min_1_s", "growth_max_1_s",
)
#: The statuses of a turn that is a turn but beyond the limits given
#: (--mu, --max-g): its stable speeds are not the rider's.
BEYOND_LIMITS = ("slips", "over_g")
#: Why the speeds that fail fail, counted per lane in the rider's table: the
#: column and the status it counts (the head's is ride's no_fit).
TURN_FAILURES = {"slips": "slips", "over_g": "over_g", "head_hits": "no_fit", "no_contact": "no_contact",
                 "no_orbit": "no_orbit"}
#: Lanes one streamed ride takes (each lane's speeds are evaluated together,
#: at most MAX_TURN_REQUESTS of them).
MAX_STREAMED_LANES = 1_000_000
#: Requests (lanes x speeds) per chunk of a streamed ride, in whole lanes (at
#: least one): the physics is vectorised over a chunk's requests, and with
#: the stability each costs some 0.35 ms on a grid (sec. 8.6), so a chunk is
#: under a second of work, a step of the progress bar and of ``--jobs``;
#: fewer, one lane of 100 speeds per chunk, made the command 2.5-3.7 times
#: slower than one API call (benchmarks/bench_two_wheeler_ride.py).
TURN_CHUNK = 2048
__all__ += ["TURN_LIMIT_COLUMNS", "TURN_APPENDED", "TURN_ARENA_COLUMNS", "STRAIGHT_APPENDED", "TURN_SUMMARY_COLUMNS", "TurnRequest",
            "TurnBatch", "turn_request", "turn_rows"]


def _lanes(theta, height, r, limit: int = MAX_TURN_REQUESTS, shaped: bool = False) -> tuple[np.ndarray, np.ndarray,
                                                                                             bool]:
    """The rear contacts' theta (rad) asked for, and their values as given
    (flat, or with ``shaped`` in the shape given: see :func:`_values`)."""
    if (theta is None) == (height is None):
        raise ParameterError("give exactly one of theta and height (the rear contact's height above the floor)",
                             "theta", missing=theta is None)
    if theta is not None:
        given = _values("theta", theta, limit, shaped=shaped)
        return np.radians(given), given, True
    given = _values("height", height, limit, shaped=shaped)
    if np.any(given > 2 * r):
        bad = float(given.reshape(-1)[np.argmax(given.reshape(-1) > 2 * r)])
        raise ParameterError(f"height (contact height) must be at most the globe's diameter {2 * r:g} m "
                             f"(got {shown_number(bad)})", "height")
    return np.arccos(np.clip(given / r - 1.0, -1.0, 1.0)), given, False


def _one_limit(name: str, value) -> float:
    """One value of the limit ``name`` (mu, max_g): a number or the command
    line's text; inf, the default, is no limit."""
    axis = checked_axis(name, value if isinstance(value, (str, list, tuple)) else np.asarray(value))
    if len(axis) != 1:
        raise ParameterError(f"a two-wheeler takes one {name} per call (got {len(axis)} values)", name)
    return float(axis.take(np.zeros(1, dtype=np.int64))[0])


#: ``steer="torque=T"`` (or "torque T", "torque:T"): the turns held with
#: the steer torque T, as ``steer_torque=T`` (docs/two-wheeler.md sec. 10).
_TORQUE_MODE = re.compile(r"\s*torque\s*[=: ]\s*(\S.*?)\s*", re.IGNORECASE)


def steer_request(steer, steer_torque) -> tuple:
    """(steer, steer_torque) with ``steer="torque=T"`` read as the steer
    free under the held torque T (``steer_torque=T``, values, a range or a
    unit as it takes them); any other ``steer`` is passed on."""
    m = _TORQUE_MODE.fullmatch(steer) if isinstance(steer, str) else None
    if m is None:
        return steer, steer_torque
    if steer_torque is not None:
        raise ParameterError("give the steer torque once: steer='torque=T' or steer_torque=T, not both",
                             "steer_torque")
    return "free", m.group(1)


def _machine(machine, steer, g) -> tuple[TwoWheeler, str, float]:
    """The two-wheeler, how its steer is held and the run's gravity."""
    t = as_two_wheeler(machine)
    if steer is None:
        steer = "free"
    if not isinstance(steer, str) or steer.strip().lower() not in STEER_MODES:
        raise ParameterError(f"steer must be one of {' | '.join(STEER_MODES)} or torque=T (N m) (got {steer!r})",
                             "steer")
    return t, steer.strip().lower(), _gravity(g)


def _gravity(g) -> float:
    """The run's gravity (m/s^2; standard gravity unless given), one per
    call: every two-wheeler runs under the gravity asked for, never its own."""
    return float(checked_array("g", g)) if np.ndim(g) == 0 else _one_g(g)


@dataclass(frozen=True, eq=False)
class TurnRequest:
    """A checked request of ``ride --steer`` (:func:`turn_request`): the
    lanes (the rear contact's theta, rad, and as given) and the rear speeds
    or steer torques tried there, arrays that broadcast together to
    :attr:`shape` (one request per element, as :func:`deathsphere.ride`
    broadcasts; a streamed request's are a column of lanes and a row of
    values, their outer product), the globe, the limits and what to give.
    :func:`turn_rows` answers it, whole or a :class:`TurnBatch` at a time."""

    machine: TwoWheeler
    g: float
    lanes: np.ndarray
    lanes_given: np.ndarray
    by_theta: bool
    values: np.ndarray
    by_torque: bool
    r: float
    steer: str
    stability: bool
    mu: float
    max_g: float
    summary: bool
    only: tuple | None = None
    #: the drum, the cone, the profile or flat ground ridden (None: the globe of radius r); a wall's lanes are
    #: heights, flat ground's the paths' curvatures (1 / the turn radius, as given in ``lanes_given``)
    wall: object = None

    @property
    def ground(self):
        """The ground record the turns are sought on: the wall, or the globe of radius r."""
        return Sphere(self.r) if self.wall is None else self.wall

    @property
    def shape(self) -> tuple[int, ...]:
        """The requests' shape: the lanes' and the values' broadcast together."""
        return np.broadcast_shapes(self.lanes.shape, self.values.shape)

    @property
    def total(self) -> int:
        """The requests (lanes x speeds, or torques, for a streamed one)."""
        return math.prod(self.shape)

    @property
    def axes(self) -> tuple[str | None, ...]:
        """The column that echoes the one input varying along each axis of
        :attr:`shape` (None where both or neither vary): a grid's axes, as
        :func:`deathsphere.ride` names a single-contact machine's."""
        ndim = len(self.shape)
        lane = (1,) * (ndim - self.lanes.ndim) + self.lanes.shape
        value = (1,) * (ndim - self.values.ndim) + self.values.shape
        at = "theta_deg" if self.by_theta else "rho_contact_m" if isinstance(self.wall, Plane) else "height_m"
        by = "steer_torque_n_m" if self.by_torque else "v_contact_m_s"
        return tuple(None if (lane[d] > 1) == (value[d] > 1) else by if value[d] > 1 else at for d in range(ndim))

    def batch(self) -> TurnBatch:
        """Every request, flat in row order (a lane of the rider's table:
        the requests that differ only along the axes where the values alone
        vary, as a single-contact machine's contact point)."""
        shape, ndim = self.shape, len(self.shape)
        lane = np.broadcast_to(self.lanes, shape).reshape(-1)
        if ndim == 0:
            group = np.zeros(1, dtype=np.int64)
        else:
            padded = (1,) * (ndim - self.lanes.ndim) + self.lanes.shape
            index = np.indices(shape).reshape(ndim, -1)
            index[[d for d in range(ndim) if padded[d] == 1]] = 0
            _, first, group = np.unique(np.ravel_multi_index(index, shape), return_index=True, return_inverse=True)
            rank = np.empty(first.size, dtype=np.int64)
            rank[np.argsort(first, kind="stable")] = np.arange(first.size)   # in the order asked
            group = rank[group.reshape(-1)]
        return TurnBatch(lane=lane, given=np.broadcast_to(self.lanes_given, shape).reshape(-1),
                         value=np.broadcast_to(self.values, shape).reshape(-1), first=0, group=group)


@dataclass(frozen=True, eq=False)
class TurnBatch:
    """Requests of a :class:`TurnRequest`, flat: each one's lane (rad), the
    lane as given and its speed or torque; ``first`` the requests before
    them (their ``input_row`` continues from it) and ``group`` each one's
    lane in the rider's table (0, 1, ... in order)."""

    lane: np.ndarray
    given: np.ndarray
    value: np.ndarray
    first: int
    group: np.ndarray

    def __len__(self) -> int:
        return self.lane.size


#: ``ride --steer``'s keys and their defaults (a key not given: its default).
TURN_KEYS = {"theta": None, "height": None, "speed": None, "steer_torque": None, "steer": None, "r": R,
             "diameter": None, "g": G, "mu": INF, "max_g": INF, "summary": False, "stability": True, "only": None,
             "surface": None, "wall_angle": None, "wall_height": None, "profile": None, "turn_radius": None}

#: The columns a two-wheeler's table on a drum, a cone or a profile appends (the single-contact ride's there).
TURN_ARENA_COLUMNS = ("surface", "rho_contact_m", "wall_angle_deg")


def turn_request(machine, typed: Mapping, streamed: bool = False) -> TurnRequest:
    """``ride --steer``'s request from its keys as typed (:data:`TURN_KEYS`,
    those of :func:`deathsphere.ride` for a two-wheeler), checked, every
    value, before any work: a bad one raises
    :class:`~deathsphere.ParameterError` in one line.  The lanes and the
    speeds (or torques) broadcast together, as :func:`deathsphere.ride`'s
    arguments, to at most MAX_TURN_REQUESTS requests; ``streamed`` (answered
    a chunk at a time): every lane with every value, their outer product,
    MAX_STREAMED_LANES lanes of at most MAX_TURN_REQUESTS values each."""
    unknown = sorted(set(typed) - set(TURN_KEYS))
    if unknown:
        raise TypeError(f"turn_request() got an unexpected key {unknown[0]!r}")
    given = {**TURN_KEYS, **typed}
    theta, height, speed, steer_torque, steer, r, diameter, g, mu, max_g, summary, stability, only = (
        given[key] for key in ("theta", "height", "speed", "steer_torque", "steer", "r", "diameter", "g", "mu",
                               "max_g", "summary", "stability", "only"))
    steer, steer_torque = steer_request(steer, steer_torque)
    t, steer, g = _machine(machine, steer, g)
    wall = _wall(given["surface"], r, diameter, given["wall_angle"], given["wall_height"], given["profile"])
    if wall is None:
        r = sphere_radius(r, diameter)
        r = float(checked_array("r", r)) if np.ndim(r) == 0 else None
        if r is None:
            raise ParameterError("a two-wheeler takes one sphere radius (or diameter) per call", "r")
    else:
        # the arena's radius at its floor (NaN on a profile: no radius to name, and each lane's own fit)
        from deathsphere.api.ride_surfaces import floor_radius

        r = floor_radius(wall)
    if max(t.rR, t.rF) >= r:
        # no lane of this globe has room for the wheel: refused as a single-contact machine's wheel is
        where = f"a sphere of radius {r:g} m" if wall is None else f"a {wall.name} of radius {r:g} m at its floor"
        raise ParameterError(f"the two-wheeler's wheels (rR = {t.rR:g} m, rF = {t.rF:g} m) do not fit in {where} "
                             "(needs r > rR and r > rF)", "diameter" if diameter is not None else "r")
    limit = MAX_STREAMED_LANES if streamed else MAX_TURN_REQUESTS
    turn_radius = given["turn_radius"]
    if isinstance(wall, Plane):
        lane, lane_given, by_theta = _plane_lanes(theta, height, turn_radius, limit, shaped=not streamed)
    elif turn_radius is not None:
        where = "the globe's lane is theta or height" if wall is None else f"on the {wall.name} give height"
        raise ParameterError(f"turn_radius is a turn's lane on flat ground (surface plane): {where}", "turn_radius")
    elif wall is None:
        lane, lane_given, by_theta = _lanes(theta, height, r, limit, shaped=not streamed)
    else:
        lane, lane_given, by_theta = _wall_lanes(wall, theta, height, limit, shaped=not streamed)
    if speed is not None and steer_torque is not None:
        raise ParameterError("give speed or steer_torque, not both (a torque picks the speeds)", "steer_torque")
    by_torque = steer_torque is not None
    if speed is None and steer_torque is None:
        raise ParameterError("give speed (the rear contact's, m/s) or steer_torque (N m; 0: hands-free)", "speed")
    value = (_values("steer_torque", steer_torque, MAX_TURN_REQUESTS, shaped=not streamed) if by_torque
             else _speeds(speed, MAX_TURN_REQUESTS, shaped=not streamed))
    if streamed:
        # every lane with every value: a column of lanes and a row of values broadcast to their outer product
        lane, lane_given = lane[:, None], lane_given[:, None]
    else:
        at = "theta" if by_theta else "turn_radius" if isinstance(wall, Plane) else "height"
        shape = grid_shape({at: lane, "steer_torque" if by_torque else "speed": value})
        if math.prod(shape) > MAX_TURN_REQUESTS:
            raise ParameterError(f"a two-wheeler's steady turns are sought for at most {MAX_TURN_REQUESTS} lanes "
                                 f"and speeds (or torques) at once (got {' x '.join(map(str, shape))}): split the "
                                 "grid, or stream it a few lanes at a time with deathsphere.api.two_wheeler_streams."
                                 "two_wheeler_ride_sweep (what 'deathsphere ride --steer' runs; --jobs N)",
                                 "steer_torque" if by_torque else "speed")
    stability, summary = checked_flag("stability", stability), checked_flag("summary", summary)
    if summary and by_torque:
        raise ParameterError("the rider's table (summary) is over rear speeds: give speed, not steer_torque (it "
                             "finds each lane's hands-free turns itself)", "steer_torque")
    if summary and not stability:
        raise ParameterError("the rider's table (summary) gives the stable speeds: it needs the stability "
                             "analysis, which stability=False skips", "stability")
    keep = checked_statuses(only)
    if summary and keep is not None:
        raise ParameterError("the rider's table (summary) counts every status: give only or summary, not both",
                             "only")
    return TurnRequest(machine=t, g=g, lanes=lane, lanes_given=lane_given, by_theta=by_theta, values=value,
                       by_torque=by_torque, r=r, steer=steer, stability=stability, mu=_one_limit("mu", mu),
                       max_g=_one_limit("max_g", max_g), summary=summary,
                       only=None if keep is None else tuple(keep), wall=wall)


def _wall(surface, r, diameter, wall_angle, wall_height, profile):
    """The drum, the cone, the profile or flat ground the two-wheeler rides
    (None: the globe), from the arena's keywords as typed (docs/two-wheeler.md
    sec. 12; flat ground's lanes are turn radii, sec. 12.8)."""
    from deathsphere.requests.arena import arena, names_a_wall

    if not names_a_wall(surface, wall_angle, wall_height, profile):
        return None
    ground = arena(surface, None if r is R else r, diameter, wall_angle, wall_height, profile)
    return None if isinstance(ground, Sphere) else ground


def _plane_lanes(theta, height, turn_radius, limit: int, shaped: bool):
    """Flat ground's lanes: the paths' curvatures 1 / turn_radius [1/m] (the
    steady-turn solver's lane on a plane) and the turn radii as given (the
    rear contact's distance from the turn's centre [m]); theta and height
    refused (a sphere's and a wall's)."""
    for key, value in (("theta", theta), ("height", height)):
        if value is not None:
            raise ParameterError(f"flat ground has no {key}: its lane is turn_radius (the rear contact's distance "
                                 "from the turn's centre)", key)
    if turn_radius is None:
        raise ParameterError("on flat ground give turn_radius (the rear contact's distance from the turn's centre)",
                             "turn_radius", missing=True)
    given = _values("turn_radius", turn_radius, limit, shaped=shaped)
    return 1.0 / np.asarray(given, dtype=float), given, False


def _wall_lanes(wall, theta, height, limit: int, shaped: bool):
    """The rear contacts' heights on a drum or a cone (the lane, m) and as
    given; theta refused (the globe's), a height above the wall's top (or a
    cone's apex) refused in one line naming height."""
    if theta is not None:
        raise ParameterError(f"theta is the globe's polar angle: on a {wall.name} give height (the rear contact's "
                             "height above the floor)", "theta")
    if height is None:
        raise ParameterError(f"give height (the rear contact's height above the {wall.name}'s floor)", "height",
                             missing=True)
    given = _values("height", height, limit, shaped=shaped)
    if np.size(given):
        refuse_above_top(wall, float(np.max(given)))
    return np.asarray(given, dtype=float), given, False


def turn_rows(request: TurnRequest, batch: TurnBatch | None = None) -> Table:
    """Every steady turn of the requests ``batch`` (None: the whole
    ``request``) at its lane and speed or steer torque, one row each, and
    its stability (docs/two-wheeler.md sec. 8); ``input_row`` numbers the
    whole request.  The whole request's table keeps its :attr:`~TurnRequest.shape`
    and axes when each request has one row, as :func:`deathsphere.ride`'s.
    With ``summary``: the rider's table of the batch's lanes instead."""
    from deathsphere.physics.two_wheeler import stability as tw_stability
    from deathsphere.physics.two_wheeler import steady

    t, r, steer = request.machine, request.r, request.steer
    whole = batch is None
    batch = request.batch() if whole else batch
    lanes, values, given = batch.lane, batch.value, batch.given
    by_theta, by_torque = request.by_theta, request.by_torque
    p, globe = t.parameters(), request.ground
    kwargs = {"torque": values} if by_torque else {"speed": values}
    if request.stability:
        out = tw_stability.turns_with_stability(lanes, p, globe, request.g, head=t.head, **kwargs)
    else:
        out = (steady.turns_for_torque(lanes, values, p, globe, request.g, t.head) if by_torque
               else steady.turns_for_speed(lanes, values, p, globe, request.g, t.head))
    found = np.isfinite(out["lean"])
    counts = found.sum(axis=1)
    req = np.repeat(np.arange(lanes.size), np.maximum(counts, 1))
    # each request's turns in order of lean, or its one row saying why none
    slot = np.concatenate([np.empty(0)] + [np.flatnonzero(f) if f.any() else [0] for f in found]).astype(np.int64)
    has = found[req, slot]
    n = req.size

    def pick(key):
        return np.where(has, np.asarray(out[key], float)[req, slot], np.nan)

    lean = pick("lean")
    th = lanes[req]
    on_wall = request.wall is not None
    on_plane = isinstance(request.wall, Plane)
    # the tilt from the inward horizontal, 90 deg - beta - the lean from the wall's normal (the globe's beta = 180 -
    # theta): the machine's alpha
    beta = np.degrees(request.wall.wall_angle(th)) if on_wall else 180.0 - np.degrees(th)
    alpha = 90.0 - beta - np.degrees(lean)
    contact = pick("contact") == 1
    omega = pick("omega")
    with np.errstate(divide="ignore"):
        period = np.where(has, 2 * np.pi / np.abs(np.where(omega == 0, np.nan, omega)), np.nan)
    cols = {
        "input_row": req + 1 + batch.first, "machine": np.full(n, t.name, dtype=object),
        "theta_deg": given[req] if by_theta else np.full(n, np.nan) if on_wall else np.degrees(th),
        "alpha_deg": np.where(has, alpha, np.nan),
        "lean_deg": np.where(has, 90.0 - alpha, np.nan), "r_m": np.full(n, r),
        # on flat ground the lane is the turn radius (rho_contact_m): the contact's height is 0, as ride's there
        "height_m": (r * (1 + np.cos(th)) if by_theta else np.zeros(n) if on_plane else given[req]),
        "g_m_s2": np.full(n, request.g),
        "omega_rad_s": omega, "period_s": period,
        "v_cm_m_s": pick("v_cm"), "v_cm_km_h": np.round(pick("v_cm") * 3.6, 9), "v_contact_m_s": pick("v_rear"),
        "load_g": pick("load_g"), "head_clearance_m": pick("head_clearance"),
        "steer_deg": np.degrees(pick("steer")), "steer_torque_n_m": pick("steer_torque"),
        "pitch_deg": np.degrees(pick("pitch")),
        "normal_rear_per_mass_m_s2": pick("normal_rear"), "normal_front_per_mass_m_s2": pick("normal_front"),
        # inf ("no push") is empty, as in every table
        "mu_required_rear": np.where(np.isinf(pick("mu_required_rear")), np.nan, pick("mu_required_rear")),
        "mu_required_front": np.where(np.isinf(pick("mu_required_front")), np.nan, pick("mu_required_front")),
        "friction_rear_per_mass_m_s2": pick("friction_rear"), "friction_front_per_mass_m_s2": pick("friction_front"),
        "lean_surface_deg": np.degrees(lean), "v_rear_m_s": pick("v_rear"), "v_front_m_s": pick("v_front"),
        # the front contact's polar angle is the globe's (on a wall: empty)
        "theta_front_deg": np.full(n, np.nan) if on_wall else np.degrees(pick("theta_front")),
        "steer": np.full(n, steer, dtype=object),
    }
    # the physics' status stage, in ride's order (no_orbit, no_fit: the head, no_contact, slips, over_g)
    codes, why = steady.turn_status(has, cols["head_clearance_m"], contact, cols["mu_required_rear"],
                                    cols["mu_required_front"], cols["load_g"], request.mu, request.max_g,
                                    why_none=np.asarray(out["reason"])[req])
    cols["status"], cols["reason"] = STATUS_LABELS[codes], REASON_TEXT[why]
    status = cols["status"]
    # what the request fixes is echoed as asked, not as recomputed, in every row, a turn found or not: two
    # requests that find none still differ (docs/contract.md, "Inputs are echoed as given")
    if by_torque:
        cols["steer_torque_n_m"] = values[req]
    else:
        cols["v_rear_m_s"] = cols["v_contact_m_s"] = values[req]
    k = tw_stability.eigenvalue_count(globe, steer)
    if request.stability:
        ev = np.where(has[:, None], out[f"eigenvalues_{steer}"][req, slot], np.nan + 0j)
        cols["stability"] = np.where(has, out[f"stability_{steer}"][req, slot], "").astype(object)
        cols["growth_rate_1_s"] = np.where(has, out[f"growth_{steer}"][req, slot], np.nan)
    else:
        ev = np.full((n, k), np.nan + 0j)
        cols["stability"], cols["growth_rate_1_s"] = np.full(n, "", dtype=object), np.full(n, np.nan)
    # inf ("no limit") is empty, as in every table
    limits = {c: np.full(n, np.nan if math.isinf(v) else v) for c, v in zip(TURN_LIMIT_COLUMNS,
                                                                          (request.mu, request.max_g))}
    # appended (docs/contract.md): what a disturbance does, and the lean by its two names, each saying from what
    appended = {"stability_kind": tw_stability.kind(ev), "lean_wall_deg": cols["lean_surface_deg"],
                "lean_vertical_deg": cols["lean_deg"]}
    if on_wall:
        # the arena's, as a single-contact machine's table there appends them (docs/contract.md)
        # (flat ground's lane is the path's curvature: the contact's distance from the turn's centre is its radius)
        rho, _ = request.wall.contact(given[req] if on_plane else th)
        appended |= {"surface": np.full(n, request.wall.name, dtype=object),
                     "rho_contact_m": np.asarray(rho, dtype=float) + np.zeros(n),
                     "wall_angle_deg": beta + np.zeros(n)}
    table = Table({c: cols[c] for c in TURN_COLUMNS} | _eig_cols(ev, k) | limits | appended)
    if whole and n == lanes.size and request.shape:   # one row per request: a grid keeps its shape
        table = Table(table.columns, shape=request.shape, axes=request.axes)
    if request.summary:
        return _turn_summary(request, table, batch)
    return table if request.only is None else table[np.isin(table["status"], request.only)]


def _hands_free(request: TurnRequest, lanes) -> dict:
    """Each lane's hands-free turns (steer torque 0, at whatever speed):
    their rear speeds (n, k), which are ok by the request's limits and
    which of those are stable with the steer free (sec. 8.2-8.3)."""
    from deathsphere.physics.two_wheeler import stability as tw_stability
    from deathsphere.physics.two_wheeler import steady

    t = request.machine
    out = tw_stability.turns_with_stability(lanes, t.parameters(), request.ground, request.g,
                                            torque=np.zeros(lanes.size), head=t.head)
    codes, _ = steady.turn_status(np.isfinite(out["lean"]), out["head_clearance"], out["contact"] == 1,
                                  out["mu_required_rear"], out["mu_required_front"], out["load_g"], request.mu,
                                  request.max_g)
    ok = codes == Status.OK
    return {"v_rear": out["v_rear"], "ok": ok, "stable": ok & (out["stability_free"] == "stable")}


def _speed_list(speeds) -> str:
    """Speeds in a cell, ascending, separated by spaces, each to round trip (never a comma: CSV)."""
    return " ".join(repr(float(v)) for v in np.sort(speeds))


def _turn_summary(request: TurnRequest, table: Table, batch: TurnBatch) -> Table:
    """The rider's table of the lanes of ``batch`` (one row each) from
    their rows ``table``: as ride's rider's table (docs/machine.md sec. 8)
    over the rear speeds tried, then the stable speeds, the steer torque
    and the lane's hands-free turns (docs/two-wheeler.md sec. 10)."""
    rq = np.asarray(table["input_row"], dtype=np.int64) - 1
    lane_of = batch.group[rq - batch.first]
    tried = np.bincount(batch.group, minlength=int(batch.group.max(initial=-1)) + 1)
    heads = np.unique(batch.group, return_index=True)[1]      # each lane's first request
    status = np.asarray(table["status"]).astype(str)
    ok = status == "ok"
    steady = np.asarray(table["stability"]).astype(str) == "stable"
    stable = ok & steady
    # stable turns the rider cannot take: they slip or load past max_g
    beyond = steady & np.isin(status, BEYOND_LIMITS)
    mu_needed = np.fmax(table["mu_required_rear"], table["mu_required_front"])
    lanes, lanes_given = batch.lane[heads], batch.given[heads]
    on_plane = isinstance(request.wall, Plane)
    free = _hands_free(request, lanes)
    rows = {c: [] for c in TURN_SUMMARY_COLUMNS}
    for i in range(heads.size):
        sel = lane_of == i
        on, fine, calm = rq[sel], ok[sel], stable[sel]

        def span(col, fn, mask=fine, values=None):
            vals = (np.asarray(table[col], dtype=float) if values is None else values)[sel][mask]
            return float(fn(vals)) if vals.size else math.nan

        theta = (float(lanes_given[i]) if request.by_theta else math.nan if request.wall is not None
                 else math.degrees(lanes[i]))
        rows["height_m"].append(request.r * (1 + math.cos(lanes[i])) if request.by_theta
                                else 0.0 if on_plane else float(lanes_given[i]))
        rows["theta_deg"].append(theta)
        rows["speeds_tried"].append(int(tried[i]))
        rows["speeds_ok"].append(int(np.unique(on[fine]).size))
        for lo, hi, col in (("v_rear_min_m_s", "v_rear_max_m_s", "v_rear_m_s"),
                            ("lean_min_deg", "lean_max_deg", "lean_deg"), ("load_min_g", "load_max_g", "load_g"),
                            ("lean_vertical_min_deg", "lean_vertical_max_deg", "lean_vertical_deg"),
                            ("lean_wall_min_deg", "lean_wall_max_deg", "lean_wall_deg"),
                            ("steer_torque_min_n_m", "steer_torque_max_n_m", "steer_torque_n_m")):
            rows[lo].append(span(col, np.min))
            rows[hi].append(span(col, np.max))
        rows["mu_max"].append(span("", np.max, values=mu_needed))
        rows["head_clearance_min_m"].append(span("head_clearance_m", np.min))
        rows["limits"].append(" ".join(sorted(set(status[sel][~fine].tolist()))))
        rows["mu_available"].append(math.nan if math.isinf(request.mu) else request.mu)
        rows["max_g"].append(math.nan if math.isinf(request.max_g) else request.max_g)
        failing = ~np.isin(on, on[fine])
        for col, name in TURN_FAILURES.items():
            rows[col].append(int(np.unique(on[(status[sel] == name) & failing]).size))
        rows["steer"].append(request.steer)
        rows["speeds_stable"].append(int(np.unique(on[calm]).size))
        rows["stable_v_min_m_s"].append(span("v_rear_m_s", np.min, calm))
        rows["stable_v_max_m_s"].append(span("v_rear_m_s", np.max, calm))
        # the speeds stable only beyond the limits (none of their turns both ok and stable)
        only_beyond = beyond[sel] & ~np.isin(on, on[calm])
        rows["stable_beyond_limits"].append(int(np.unique(on[only_beyond]).size))
        rows["stable_beyond_v_min_m_s"].append(span("v_rear_m_s", np.min, only_beyond))
        rows["stable_beyond_v_max_m_s"].append(span("v_rear_m_s", np.max, only_beyond))
        # what the stable band loads the rider with: without max_g it may be a band no rider takes
        rows["stable_load_min_g"].append(span("load_g", np.min, calm))
        rows["stable_load_max_g"].append(span("load_g", np.max, calm))
        # how fast a disturbance grows on the ok turns (the rider's time to act: ln 2 / growth to double)
        rows["growth_min_1_s"].append(span("growth_rate_1_s", np.min))
        rows["growth_max_1_s"].append(span("growth_rate_1_s", np.max))
        hands, still = free["v_rear"][i][free["ok"][i]], free["v_rear"][i][free["stable"][i]]
        rows["hands_free_turns"].append(int(hands.size))
        rows["hands_free_stable"].append(int(still.size))
        rows["hands_free_v_rear_m_s"].append(_speed_list(hands))
        rows["hands_free_stable_v_rear_m_s"].append(_speed_list(still))
    counts = {"speeds_tried", "speeds_ok", "speeds_stable", "hands_free_turns", "hands_free_stable",
              "stable_beyond_limits", *TURN_FAILURES}
    text = {"limits", "steer", "hands_free_v_rear_m_s", "hands_free_stable_v_rear_m_s"}
    table = {c: np.array(v, dtype=np.int64 if c in counts else object if c in text else float)
             for c, v in rows.items()}
    if on_plane:
        # flat ground's lane is its turn radius: appended (docs/contract.md), the heights being 0
        table["rho_contact_m"] = np.asarray(lanes_given, dtype=float)
    return Table(table)


#: The keys of a two-wheeler's ``ride`` as typed and their defaults: a turn's and ``flat``.
RIDE_KEYS = {**TURN_KEYS, "flat": False}


def two_wheeler_ride(machine, typed: Mapping) -> Table:
    """``ride`` for a two-wheeler (:func:`deathsphere.ride` with ``flat``,
    ``steer`` or ``steer_torque``; docs/two-wheeler.md sec. 10): on flat
    ground the eigenvalues of upright straight running at each rear contact
    speed (``summary``: the weave and capsize speeds); on the globe every
    steady turn at each lane and speed (or held with each steer torque),
    one row each, with its stability, the steer ``free`` (under its steady
    torque held constant; default) or ``locked``; a turn needing more
    friction than ``mu`` at either wheel has status ``slips``, one loading
    the rider more than ``max_g`` (load_g) ``over_g``; ``summary`` gives the
    rider's table, a row per lane (:data:`TURN_SUMMARY_COLUMNS`); ``only``
    keeps the turns of those statuses (ride's ``only``).  The lanes (theta
    or height) and the speeds (or torques) broadcast as numpy arrays, as a
    single-contact machine's do: ``height=[1, 2], speed=[8, 10]`` is two
    requests, a column of heights and a row of speeds their grid, whose
    table keeps its shape and axes (``table.shape``, ``to_xarray()``) when
    each request has one row; text (``"5:10:0.5"``, ``"16ft"``) is a line
    of values.  At most MAX_TURN_REQUESTS requests:
    :func:`two_wheeler_ride_sweep
    <deathsphere.api.two_wheeler_streams.two_wheeler_ride_sweep>` streams
    the outer product of more, as the command line does.
    ``typed``: :func:`deathsphere.ride`'s keys for a two-wheeler
    (:data:`RIDE_KEYS`; one not given: its default)."""
    unknown = sorted(set(typed) - set(RIDE_KEYS))
    if unknown:
        raise TypeError(f"two_wheeler_ride() got an unexpected key {unknown[0]!r}")
    given = {**RIDE_KEYS, **typed}
    theta, height, diameter, r, g, mu, max_g, summary, stability, only, flat = (
        given[key] for key in ("theta", "height", "diameter", "r", "g", "mu", "max_g", "summary", "stability",
                               "only", "flat"))
    steer, steer_torque = steer_request(given["steer"], given["steer_torque"])
    if checked_flag("flat", flat):
        t, steer, g = _machine(machine, steer, g)
        summary = checked_flag("summary", summary)
        checked_flag("stability", stability)    # straight running's eigenvalues are its table: always given
        if theta is not None or height is not None or diameter is not None or r is not R:
            raise ParameterError("flat ground has no lane and no sphere: give speed only (not theta, height, r "
                                 "or diameter)", "flat")
        if given["turn_radius"] is not None:
            raise ParameterError("flat is upright straight running: a steady turn on flat ground is surface plane "
                                 "with turn_radius (without flat)", "turn_radius")
        for key in ("surface", "wall_angle", "wall_height"):
            if given[key] is not None:
                raise ParameterError(f"flat ground is the arena of flat: {key} is not for it", key)
        if steer_torque is not None:
            raise ParameterError("on flat ground upright straight running is hands-free at every speed: "
                                 "steer_torque is for the globe", "steer_torque")
        if mu is not INF or max_g is not INF:
            raise ParameterError("upright straight running on flat ground needs no friction and loads the rider "
                                 "1 g: mu and max_g are for the globe", "mu" if mu is not INF else "max_g")
        if only is not None:
            raise ParameterError("upright straight running on flat ground has no status to keep: only is for the "
                                 "globe", "only")
        return _straight(t, g, given["speed"], steer, summary)
    turn = {key: given[key] for key in TURN_KEYS}       # the keywords as typed, the steer's read once
    return turn_rows(turn_request(machine, {**turn, "steer": steer, "steer_torque": steer_torque}))


def _one_g(g):
    raise ParameterError("a two-wheeler takes one gravity per call", "g")


# ---------------------------------------------------------------------------
# the nonlinear motion

#: How the steer is held in :func:`simulate_two_wheeler`.
CONTROLS = ("steady-torque", "rider", "hands-free", "locked")
#: The columns of the time series and of the summary of :func:`simulate_two_wheeler`.
SIMULATE_COLUMNS = ("t_s", "lean_surface_deg", "steer_deg", "heading_deg", "theta_rear_deg", "lean_rate_deg_s",
                    "steer_rate_deg_s", "v_rear_m_s", "steer_torque_n_m", "normal_rear_per_mass_m_s2",
                    "normal_front_per_mass_m_s2", "friction_rear_per_mass_m_s2", "friction_front_per_mass_m_s2",
                    "energy_drift", "constraint_residual_m", "lean_wall_deg")
SIMULATE_SUMMARY_COLUMNS = (
    "machine", "theta_deg", "height_m", "r_m", "v_rear_m_s", "lean_surface_deg", "steer_deg", "steer_torque_n_m",
    "period_s", "perturb_deg", "control", "k_lean_n_m_rad", "k_rate_n_m_s_rad", "mu", "status", "t_event_s",
    "t_end_s", "max_lean_deviation_deg", "final_lean_deviation_deg", "max_energy_drift",
    "max_constraint_residual_m", "min_normal_rear_per_mass_m_s2", "min_normal_front_per_mass_m_s2", "method",
    "rtol", "surface", "turn_radius_m", "steer", "perturb_lean_rate_deg_s", "perturb_steer_rate_deg_s",
    "lean_wall_deg", "lean_vertical_deg")
#: Rows per period of the turn, and periods, one call integrates at most.
MAX_SIMULATE_ROWS = 1_000_000
#: The rear wheel's travel one run integrates at most [m]: some 0.1 s of
#: work per metre on the globe (docs/two-wheeler.md sec. 10.1), so this is
#: minutes, some 300 laps of a 16-ft globe.
MAX_TRAVEL_M = 5_000.0
#: How long a run from straight running on flat ground lasts unless told (s):
#: the benchmark's weave (period 1.4 s at 5 m/s) goes round three times.
STRAIGHT_DURATION = 5.0


def _percent(progress):
    """``progress(done, total)`` told in per cent of the run's time."""
    return lambda t, t_end: progress(int(100 * t / t_end), 100)


def _gains(steer_gains) -> tuple[float, float]:
    """(k_lean, k_rate) from two numbers or their text "K_LEAN,K_RATE"."""
    values = steer_gains.split(",") if isinstance(steer_gains, str) else steer_gains
    ok = not isinstance(values, (bytes, dict)) and np.ndim(values) == 1 and len(values) == 2
    try:
        gains = tuple(float(v) for v in values) if ok else ()
    except (TypeError, ValueError):
        gains = ()
    if len(gains) != 2 or not all(math.isfinite(v) for v in gains):
        raise ParameterError(f"steer_gains must be two finite numbers K_LEAN,K_RATE (N m/rad, N m s/rad) "
                             f"(got {steer_gains!r})", "steer_gains")
    return gains


def simulate_two_wheeler(machine, *, theta=None, height=None, speed=None, r=R, diameter=None, g=G, mu=INF,
                         branch=0, perturb=0.0, periods=None, points_per_period=100, steer_gains=None,
                         hands_free=False, steer="free", method="DOP853", rtol=1e-10,
                         atol=None, flat=False, turn_radius=None, duration=None, perturb_lean_rate=0.0,
                         perturb_steer_rate=0.0, surface=None, wall_angle=None, wall_height=None, profile=None,
                         view=False, progress=None) -> tuple:
    """Integrate a two-wheeler's nonlinear equations on the globe, on flat
    ground or on a wall: ``deathsphere simulate --machine benchmark-bicycle
    --steer free``, ``--flat`` or ``--surface cylinder`` (beyond the paper;
    docs/two-wheeler.md sec. 10.1 and 12.7).

    On the globe from the steady turn at the rear contact's ``theta``
    [deg] or ``height`` [m] and rear contact ``speed`` [m/s] (the turn
    ``branch``, 0 first in increasing lean, as ``ride --steer`` lists
    them); ``flat``: from upright straight running at ``speed``, or with
    ``turn_radius`` [m] from the steady turn whose rear contact runs on that
    circle (turning right; ``branch`` as on the globe).  On a drum, a cone
    or a profile (``surface`` "cylinder", "cone" or "profile" with the
    arena's ``diameter`` or ``r``, ``wall_angle``, ``wall_height``,
    ``profile``, as :func:`deathsphere.ride` takes them): from the steady
    turn at the rear contact's ``height`` [m] up the wall (the turn ``ride``
    finds there).  The lean kicked by
    ``perturb`` [deg], the lean and steer rates by ``perturb_lean_rate``,
    ``perturb_steer_rate`` [deg/s], for ``periods`` periods of the turn
    (default 2) or ``duration`` [s] (straight running has no period: 5 s
    unless given; ``points_per_period`` is then rows per second).  The
    steer torque: the turn's steady torque held (default); with
    ``steer_gains`` = (k_lean [N m/rad], k_rate [N m s/rad]) a rider, T =
    T_steady + k_lean (lean - lean_steady) + k_rate lean_rate (positive
    gains steer into the fall); ``hands_free``: T = 0; ``steer="locked"``:
    the steer held at the turn's, its torque whatever the lock applies.
    The run stops with status ``contact_lost`` when a wheel's normal force
    reaches zero, ``slips`` when the friction needed exceeds ``mu`` at
    either wheel; on a wall also ``hits_floor`` when a wheel's lowest rim
    point reaches the floor at the wall's foot and ``over_the_top`` when the
    rear contact passes the wall's top (``wall_height``).  Off the globe the
    series gains ``height_m`` and ``rho_contact_m`` (the rear contact's), the
    summary ``rho_contact_m``, ``wall_angle_deg``, ``max_height_drift_m``
    and ``max_rho_drift_m`` (:data:`WALL_SERIES_COLUMNS`,
    :data:`WALL_SUMMARY_COLUMNS`).

    A run is at most :data:`MAX_TRAVEL_M` of the rear wheel's travel;
    ``progress(done, total)``, if given, is told the per cent of the run's
    time integrated now and then.

    Returns (series, summary): the time series (:data:`SIMULATE_COLUMNS`;
    ``energy_drift`` is the energy's change over the initial kinetic
    energy, conserved hands-free and with the steer locked) and one summary
    row (:data:`SIMULATE_SUMMARY_COLUMNS`).  With ``view``, a third item: what the 3-D view draws at every row of the series, ``t``
    [s] and the points of
    :func:`deathsphere.physics.two_wheeler.geometry.outline` [m] (the rims,
    frames and head, in the core's axes: origin the sphere's centre, z
    down).
    """
    typed = {key: value for key, value in locals().items() if key in RUN_KEYS}   # the keywords, as typed
    return two_wheeler_run(machine, typed, view=view, progress=progress)


#: The keys of a two-wheeler's run as typed (:func:`simulate_two_wheeler`'s
#: keywords but the machine, the view and the progress) and their defaults.
RUN_KEYS = {"theta": None, "height": None, "speed": None, "r": R, "diameter": None, "g": G, "mu": INF, "branch": 0,
            "perturb": 0.0, "periods": None, "points_per_period": 100, "steer_gains": None, "hands_free": False,
            "steer": "free", "method": "DOP853", "rtol": 1e-10, "atol": None, "flat": False, "turn_radius": None,
            "duration": None, "perturb_lean_rate": 0.0, "perturb_steer_rate": 0.0, "surface": None,
            "wall_angle": None, "wall_height": None, "profile": None}


def two_wheeler_run(machine, typed: Mapping, view=False, progress=None) -> tuple:
    """:func:`simulate_two_wheeler` from its keys as typed (:data:`RUN_KEYS`;
    one not given: its default): every value checked, the start found, the
    run integrated."""
    from deathsphere.api.arguments import checked_choice, checked_flag, checked_optional, checked_scalar
    from deathsphere.simulation.runner import METHODS
    from deathsphere.physics.two_wheeler import grounds, motion
    from deathsphere.physics.two_wheeler.simulate import Kick, Solver, Steering
    from deathsphere.simulation.two_wheeler import run_two_wheeler as integrate

    unknown = sorted(set(typed) - set(RUN_KEYS))
    if unknown:
        raise TypeError(f"two_wheeler_run() got an unexpected key {unknown[0]!r}")
    given = {**RUN_KEYS, **typed}
    (theta, height, speed, r, diameter, g, mu, branch, perturb, periods, points_per_period, steer_gains, hands_free,
     steer, method, rtol, atol, flat, turn_radius, duration, perturb_lean_rate, perturb_steer_rate, *_) = (
        given[key] for key in RUN_KEYS)
    t = as_two_wheeler(machine)
    if not isinstance(steer, str) or steer.strip().lower() not in STEER_MODES:
        raise ParameterError(f"steer must be one of {' | '.join(STEER_MODES)} (got {steer!r})", "steer")
    locked = steer.strip().lower() == "locked"
    flat, hands_free = checked_flag("flat", flat), checked_flag("hands_free", hands_free)
    if locked and (hands_free or steer_gains is not None):
        raise ParameterError("a locked steer's torque is whatever holds it: hands_free and steer_gains are for "
                             "steer free", "steer")
    g = checked_scalar("g", g)
    view = checked_flag("view", view)
    if hands_free and steer_gains is not None:
        raise ParameterError("hands_free is T = 0: give it or steer_gains, not both", "steer_gains")
    k_lean, k_rate = (0.0, 0.0) if steer_gains is None else _gains(steer_gains)
    perturb_lean_rate = checked_scalar("perturb_lean_rate", perturb_lean_rate)
    perturb_steer_rate = checked_scalar("perturb_steer_rate", perturb_steer_rate)
    if locked and perturb_steer_rate != 0:
        raise ParameterError("a locked steer has no steer rate to kick: perturb_steer_rate is for steer free",
                             "perturb_steer_rate")
    wall = _wall(given["surface"], r, diameter, given["wall_angle"], given["wall_height"], given["profile"])
    if isinstance(wall, Plane):
        raise ParameterError("a two-wheeler's run on flat ground is flat's (with turn_radius for a steady turn), "
                             "not surface plane's", "surface")
    if flat and wall is not None:
        raise ParameterError(f"flat is flat ground: the {wall.name}'s arena keywords are not for it", "flat")
    if flat and (theta is not None or height is not None or diameter is not None or r is not R):
        raise ParameterError("flat ground has no lane on a sphere: give speed and, for a turn, turn_radius "
                             "(not theta, height, r or diameter)", "flat")
    if not flat and turn_radius is not None:
        raise ParameterError("turn_radius is a turn on flat ground: pass flat (on the globe the lane is theta or "
                             f"height{'' if wall is None else f', on the {wall.name} height'})", "turn_radius")
    if periods is not None and duration is not None:
        raise ParameterError("give periods or duration, not both", "duration")
    straight = flat and turn_radius is None
    if straight and periods is not None:
        raise ParameterError("straight running on flat ground has no period: give duration (s) instead of "
                             "periods", "periods")
    if speed is None:
        raise ParameterError("give speed (the rear contact's, m/s): the steady turn or straight running the run "
                             "starts from", "speed", missing=True)
    speed = checked_scalar("speed", speed)
    if flat:
        theta_deg = h = r = math.nan
        radius = math.nan if straight else checked_scalar("turn_radius", turn_radius)
    elif wall is not None:
        theta_deg, radius = math.nan, math.nan
        r, h = _wall_lane(t, wall, theta, height, diameter)
    else:
        r = checked_scalar("r", sphere_radius(r, diameter))
        theta_deg, h = _lane(theta, height, r)
        radius = math.nan
    perturb = checked_scalar("perturb", perturb)
    duration = checked_optional("duration", duration)
    periods = None if periods is None else checked_scalar("periods", periods)
    points_per_period = int(checked_scalar("points_per_period", points_per_period))
    lower = tuple(m.lower() for m in METHODS)
    method = METHODS[lower.index(checked_choice("method", method, lower))]
    rtol, atol = checked_scalar("rtol", rtol), checked_optional("atol", atol)
    mu = checked_scalar("mu", mu)
    length_option = "duration" if duration is not None or straight else "periods"
    if straight and duration is None:
        duration = STRAIGHT_DURATION
    # rows per period of the turn; straight running has none: per second.  Checked
    # before the turn is sought where the period is not needed, after where it is
    if periods is not None or straight:
        _rows(periods if periods is not None else duration, points_per_period, "seconds" if straight else "periods",
              "duration" if straight else "periods")
    p = t.parameters()
    ground = Plane() if flat else Sphere(r) if wall is None else wall
    q, u, torque0, period = _start(t, p, g, speed, branch, ground, theta_deg, radius, h)
    if duration is None:
        duration = (2.0 if periods is None else periods) * period
    length = duration / (1.0 if straight else period)
    _rows(length, points_per_period, "seconds" if straight else "periods",
          "periods" if periods is not None else "duration")
    if speed * duration > MAX_TRAVEL_M:
        raise ParameterError(f"a run is at most {MAX_TRAVEL_M / 1000:g} km of the rear wheel's travel (speed x "
                             f"duration; some 0.1 s of work per m): {speed:g} m/s for {duration:.6g} s is "
                             f"{speed * duration / 1000:.6g} km: ask for fewer periods or a shorter duration",
                             length_option)
    n_points = max(int(round(length * points_per_period)) + 1, 2)
    steering = Steering(torque0=torque0, k_lean=k_lean, k_rate=k_rate, hands_free=hands_free, locked=locked)
    kick = Kick(math.radians(perturb), math.radians(perturb_lean_rate), math.radians(perturb_steer_rate))
    series, summary = integrate(p, q, u[list(motion.INDEPENDENT)], duration, ground=ground, g=g, steering=steering,
                                kick=kick, solver=Solver(method, rtol, atol, n_points), mu=mu,
                                progress=None if progress is None else _percent(progress))
    deg = np.degrees
    cols = {"t_s": series["t"], "lean_surface_deg": deg(series["lean"]), "steer_deg": deg(series["steer"]),
            "heading_deg": deg(series["heading"]), "theta_rear_deg": deg(series["theta_rear"]),
            "lean_rate_deg_s": deg(series["lean_rate"]), "steer_rate_deg_s": deg(series["steer_rate"]),
            "v_rear_m_s": series["v_rear"], "steer_torque_n_m": np.asarray(series["steer_torque"], float),
            "normal_rear_per_mass_m_s2": series["normal_rear"], "normal_front_per_mass_m_s2": series["normal_front"],
            "friction_rear_per_mass_m_s2": series["friction_rear"],
            "friction_front_per_mass_m_s2": series["friction_front"], "energy_drift": series["energy_drift"],
            "constraint_residual_m": series["constraint_residual"],
            # the lean by the name that says from what: the surface's normal at the rear contact (the series has no
            # lean from the vertical: off the steady turn the heading leaves the lane, docs/two-wheeler.md sec. 10.1)
            "lean_wall_deg": deg(series["lean"])}
    control = "locked" if locked else "hands-free" if hands_free else (
        "rider" if steer_gains is not None else "steady-torque")
    row = {"machine": t.name, "theta_deg": theta_deg, "height_m": h, "r_m": r,
           "v_rear_m_s": speed, "lean_surface_deg": math.degrees(q[motion.LEAN]),
           "steer_deg": math.degrees(q[motion.STEER]), "steer_torque_n_m": torque0, "period_s": period,
           "perturb_deg": perturb, "control": control, "k_lean_n_m_rad": k_lean, "k_rate_n_m_s_rad": k_rate,
           "mu": mu, "status": summary["status"], "t_event_s": summary["t_event"], "t_end_s": summary["t_end"],
           "max_lean_deviation_deg": math.degrees(summary["max_lean_deviation"]),
           "final_lean_deviation_deg": math.degrees(summary["final_lean_deviation"]),
           "max_energy_drift": summary["max_energy_drift"],
           "max_constraint_residual_m": summary["max_constraint_residual"],
           "min_normal_rear_per_mass_m_s2": summary["min_normal_rear"],
           "min_normal_front_per_mass_m_s2": summary["min_normal_front"], "method": method, "rtol": rtol,
           "surface": grounds.of(ground).surface if wall is None else wall.name, "turn_radius_m": radius, "steer": "locked" if locked else "free",
           "perturb_lean_rate_deg_s": perturb_lean_rate, "perturb_steer_rate_deg_s": perturb_steer_rate,
           "lean_wall_deg": math.degrees(q[motion.LEAN]),
           # the start's lean from the vertical: its steady turn runs along the lane (alpha as ride's), and on flat
           # ground the surface's normal is the vertical
           "lean_vertical_deg": math.degrees(q[motion.LEAN]) + (0.0 if flat else 180.0 - theta_deg)}
    series_columns, summary_columns = SIMULATE_COLUMNS, SIMULATE_SUMMARY_COLUMNS
    if wall is not None:
        # the arena's columns appended (docs/contract.md), as the paper's bodies' runs off the globe append them
        series_columns, summary_columns = (series_columns + WALL_SERIES_COLUMNS,
                                           summary_columns + WALL_SUMMARY_COLUMNS)
        cols, row = cols | _wall_series(wall, series["q"]), row | _wall_summary(wall, series["q"], h)
        # the start's lean from the vertical: the lean from the wall's normal plus the wall's angle (ride's)
        row["lean_vertical_deg"] = math.degrees(q[motion.LEAN]) + row["wall_angle_deg"]
    summary_table = Table({k: np.array([row[k]], dtype=object if isinstance(row[k], str) else float)
                           for k in summary_columns})
    tables = Table({k: np.asarray(cols[k], float) for k in series_columns}), summary_table
    if not view:
        return tables
    from deathsphere.physics.two_wheeler.geometry import outline

    # the ground record beside the points: the view draws a wall from its meridian
    return (*tables, {"t": series["t"], "ground": ground, **outline(series["q"], p, ground, t.head)})


#: The columns a run off the globe appends to the series and to the summary
#: (docs/contract.md): the rear contact's lane, as the paper's bodies' runs
#: there and ``ride``'s two-wheeler turns there name them.
WALL_SERIES_COLUMNS = ("height_m", "rho_contact_m")
WALL_SUMMARY_COLUMNS = ("rho_contact_m", "wall_angle_deg", "max_height_drift_m", "max_rho_drift_m")


def _wall_series(wall, q) -> dict:
    """The rear contact's height above the floor and distance from the axis at every row [m]."""
    from deathsphere.physics.two_wheeler import on_wall

    height, rho = on_wall.rear_lane(q, wall)
    return {"height_m": height, "rho_contact_m": rho}


def _wall_summary(wall, q, h) -> dict:
    """The lane's distance from the axis and wall angle [deg] at the start's height ``h``, and the most the
    rear contact's height and distance drift from them over the run [m]."""
    from deathsphere.physics.two_wheeler import on_wall

    height, rho = on_wall.rear_lane(q, wall)
    rho0 = float(np.asarray(wall.contact(h)[0], float))
    return {"rho_contact_m": rho0, "wall_angle_deg": math.degrees(float(wall.wall_angle(h))),
            "max_height_drift_m": float(np.max(np.abs(height - h))),
            "max_rho_drift_m": float(np.max(np.abs(rho - rho0)))}


def _wall_lane(t: TwoWheeler, wall, theta, height, diameter) -> tuple[float, float]:
    """(r_m, height_m) of a run on a wall: the arena's radius at its floor (NaN on a profile, as ride's), the
    rear contact's height up the wall, theta refused (the globe's), a height above the wall's top refused,
    and the wheels that do not fit refused as ride refuses them."""
    from deathsphere.api.ride_surfaces import floor_radius

    r = floor_radius(wall)
    if max(t.rR, t.rF) >= r:
        raise ParameterError(f"the two-wheeler's wheels (rR = {t.rR:g} m, rF = {t.rF:g} m) do not fit in a "
                             f"{wall.name} of radius {r:g} m at its floor (needs r > rR and r > rF)",
                             "diameter" if diameter is not None else "r")
    from deathsphere.api.arguments import checked_scalar

    if theta is not None:
        raise ParameterError(f"theta is the globe's polar angle: on a {wall.name} give height (the rear contact's "
                             "height above the floor)", "theta")
    if height is None:
        raise ParameterError(f"give height (the rear contact's height above the {wall.name}'s floor)", "height",
                             missing=True)
    h = checked_scalar("height", height)
    refuse_above_top(wall, h)
    return r, h


def _lane(theta, height, r) -> tuple[float, float]:
    """(theta_deg, height_m): the rear contact's lane on the globe from one of them."""
    from deathsphere.api.arguments import checked_scalar

    if (theta is None) == (height is None):
        raise ParameterError("give exactly one of theta and height (the rear contact's height above the floor)",
                             "theta", missing=theta is None)
    if theta is not None:
        theta_deg = checked_scalar("theta", theta)
        return theta_deg, r * (1 + math.cos(math.radians(theta_deg)))
    h = checked_scalar("height", height)
    if h > 2 * r:
        raise ParameterError(f"height (contact height) must be at most the globe's diameter {2 * r:g} m "
                             f"(got {shown_number(h)})", "height")
    return math.degrees(math.acos(min(max(h / r - 1.0, -1.0), 1.0))), h


def _rows(length, points_per_period, per, name):
    """Refuse a run of more than MAX_SIMULATE_ROWS rows: ``length`` periods
    of the turn (``per`` "periods") or seconds of straight running."""
    if length * points_per_period > MAX_SIMULATE_ROWS:
        raise ParameterError(f"a run is at most {MAX_SIMULATE_ROWS} rows: {length:.6g} {per} x "
                             f"{points_per_period} points_per_period is too many",
                             name)


def _start(t: TwoWheeler, p, g, speed, branch, ground, theta_deg, radius, height):
    """(q, u, steady steer torque, period) the run starts from: the steady
    turn at the lane (the globe's theta, flat ground's turn radius, a
    wall's height) and rear speed, or upright straight running (flat, no
    radius; no period)."""
    from deathsphere.physics.two_wheeler import motion, steady

    bad_branch = isinstance(branch, bool) or not isinstance(branch, (int, np.integer))
    flat = isinstance(ground, Plane)
    if flat and math.isnan(radius):
        if bad_branch or branch != 0:
            raise ParameterError(f"straight running is one state: branch must be 0 (got {branch!r})", "branch")
        q = steady.configuration(0.0, 0.0, 0.0, p, ground)
        u = motion.dependent_speeds(q, np.array([0.0, -speed / p.rR, 0.0]), motion.parameter_values(p, g, ground),
                                    ground)
        return q, u, 0.0, math.nan
    on_sphere = isinstance(ground, Sphere)
    lane = 1.0 / radius if flat else math.radians(theta_deg) if on_sphere else height
    turn = steady.turns_for_speed(lane, speed, p, ground, g, t.head)
    count = int(turn["count"][0])
    where = (f"turn radius {radius:g} m" if flat else f"theta = {theta_deg:g} deg" if on_sphere
             else f"height {height:g} m on the {ground.name}")
    if count == 0:
        hint = "" if flat else "; 'deathsphere ride --steer free' lists them"
        # the physics' reason is a code: its words, as ride's reason column gives them
        why = turn["reason"][0]
        why = REASON_TEXT[int(why)] if isinstance(why, (int, np.integer)) else why
        raise ParameterError(f"no steady turn at {where} and rear speed {speed:g} m/s "
                             f"({why or 'none found'}){hint}", "speed")
    if bad_branch or not 0 <= branch < count:
        raise ParameterError(f"branch must be one of the {count} steady turns at this lane and speed "
                             f"(0..{count - 1}, in increasing lean; got {branch!r})", "branch")
    omega = float(turn["omega"][0, branch])
    return (turn["q"][:, 0, branch], turn["u"][:, 0, branch], float(turn["steer_torque"][0, branch]),
            2 * math.pi / abs(omega))
