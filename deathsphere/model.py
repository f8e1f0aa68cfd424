"""The user-facing model: a validated :class:`Setup`, orbit requests, and the
result :class:`Table` of ordered named columns (the column contract, docs/contract.md).

Data flows one way: requests (degrees, per-row parameters) are validated here,
grouped by body, handed to the pure physics in :mod:`deathsphere.physics`
(radians), and the results are scattered back into one table in input order.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from deathsphere import params
from deathsphere.constants import (
    BODIES,
    SIDES,
    STANDARD_GRAVITY,
    TABLE1_SPHERE_RADIUS,
    TABLE1_WHEEL_RADIUS,
)

# Only the wheel here: the region's root finder and the other bodies are
# imported where used, so that a command loads only what it evaluates.
from deathsphere.physics import wheel
from deathsphere.physics.geometry import too_big_inside
from deathsphere.physics.stability import methods
from deathsphere.physics.status import REASON_TEXT, STATUS_LABELS, Reason, Status
from deathsphere.records.paper_bodies import BALL, PAPER_BODIES, PARTICLE, WHEEL, Ball, PaperBodyKind, Particle, Wheel
from deathsphere.requests.decode import as_typed, paper_body_codes, paper_body_named, text_codes
from deathsphere.table import Table
from deathsphere.table.reasons import echo

#: The contract's columns, in order (docs/contract.md).  Add, never rename or reorder.
COLUMNS = (
    "input_row", "body", "side", "theta_deg", "alpha_deg", "a_m", "r_m", "k", "g_m_s2",
    "status", "reason",
    "r_prime_m", "omega_rad_s", "period_s", "v_cm_m_s", "spin_rad_s", "accel_m_s2",
    "accel_g", "normal_per_mass_m_s2", "friction_per_mass_m_s2", "mu_required",
    # extensions (appended; see CHANGELOG.md)
    "mu_available", "omega3_rad_s", "branch",
    "stability", "stability_method", "growth_rate_1_s", "freq_slow_rad_s", "freq_fast_rad_s",
    "omega3_min_real_rad_s", "omega3_min_contact_rad_s", "max_accel_g",
    # the load a rider feels (|a - g| / g, what --max-g limits) and that limit by its own name
    "load_g", "max_g",
    # what a disturbance does on an analysed orbit: neutral (the paper's stable), damped or growing
    "stability_kind",
    # the arena (docs/surfaces.md): which surface, the lane's height, the contact's distance from the axis
    # and the wall's angle from the horizontal there (on the sphere 180 - theta)
    "surface", "height_m", "rho_contact_m", "wall_angle_deg",
    # the contact's speed along the ground, Omega rho_contact (a speedometer's reading; what speed gives)
    "v_contact_m_s",
)

#: Columns holding text; ``branch`` holds ints or None; every other column is
#: float64 (input_row is int).
TEXT_COLUMNS = frozenset({"body", "side", "status", "reason", "stability", "stability_method", "stability_kind",
                          "surface"})

#: Physics output key -> contract column.
_PHYSICS_COLUMNS = {
    "r_prime": "r_prime_m",
    "omega": "omega_rad_s",
    "period": "period_s",
    "v_cm": "v_cm_m_s",
    "spin": "spin_rad_s",
    "accel": "accel_m_s2",
    "accel_g": "accel_g",
    "load_g": "load_g",
    "normal": "normal_per_mass_m_s2",
    "friction": "friction_per_mass_m_s2",
    "mu_required": "mu_required",
    "omega3": "omega3_rad_s",
    "omega3_min_real": "omega3_min_real_rad_s",        # sphere: eq. (56)
    "omega3_min_contact": "omega3_min_contact_rad_s",  # sphere: eqs. (56), (58)/(59)
}

#: Request fields: name -> (default, unit, what it is), from the parameter
#: registry (body and side are the two text fields).
REQUEST_FIELDS = {
    "body": (WHEEL.word, "", " | ".join(BODIES)),
    "side": ("inside", "", "inside | outside"),
    **{name: (params.PARAMS[name].default, params.PARAMS[name].unit, params.PARAMS[name].what)
       for name in ("theta", "alpha", "a", "r", "k", "g", "mu", "max_g", "omega3", "omega", "speed", "com_speed",
                     "height")},
}


@dataclass(frozen=True)
class Setup:
    """A validated body-on-sphere configuration.

    Parameters are SI: ``a`` body radius [m], ``r`` sphere radius [m], ``k``
    inertia factor (wheel: I11 = 2 k m a^2; sphere: I = k m a^2; default by
    body, see :data:`deathsphere.constants.DEFAULT_INERTIA`), ``g`` [m/s^2],
    ``body`` one of the paper's body records (:mod:`deathsphere.records.paper_bodies`;
    a word naming one is decoded),
    ``mu`` friction coefficient available (``inf``: unlimited).  Raises
    ``ValueError`` with a clear message for invalid values; a physically
    impossible orbit is never an error (it is a status).

    >>> Setup().a, Setup().r, Setup().k
    (0.3, 3.0, 0.5)
    """

    body: PaperBodyKind | str = WHEEL
    side: str = "inside"
    a: float = TABLE1_WHEEL_RADIUS
    r: float = TABLE1_SPHERE_RADIUS
    k: float | None = None
    g: float = STANDARD_GRAVITY
    mu: float = math.inf

    def __post_init__(self):
        body = self.body if isinstance(self.body, PaperBodyKind) else paper_body_named(self.body)
        if body is None:
            raise ValueError(f"body must be one of {' | '.join(BODIES)} (got {self.body!r})")
        object.__setattr__(self, "body", body)
        k = body.default_k if self.k is None else self.k
        object.__setattr__(self, "k", k)
        problem = validate_scalars(body, self.side, self.a, self.r, k, self.g, self.mu)
        if problem:
            raise ValueError(problem)
        for name in ("a", "r", "k", "g", "mu"):
            object.__setattr__(self, name, float(getattr(self, name)))

    def orbit(self, theta_deg, alpha_deg=None, *, omega3=None, omega=None, speed=None, com_speed=None,
              stability: bool = True) -> Table:
        """Steady horizontal orbits of this body and sphere, broadcast.

        McDonald (1993) eqs. (0), (8b), (13), (29)-(36) for a wheel (inside
        or outside, eqs. (81), (83)); a sphere given ``omega3`` or ``omega``,
        eqs. (55)-(59); a particle given only theta.  Angles in degrees.  The
        arguments broadcast (``theta[:, None], alpha[None, :]`` for a grid) and
        the :class:`Table` keeps that shape where one request gives one row.
        The same rows as :func:`deathsphere.orbit` with this setup's options;
        the results layer uses this (it sits below the API).  Raises
        :class:`~deathsphere.params.ParameterError` when no row can be computed.

        Examples
        --------
        >>> t = Setup().orbit(60, 10)
        >>> round(float(t["v_cm_m_s"]), 2), str(t["status"])
        (7.88, 'ok')
        """
        given = {name: np.asarray(v, dtype=float) for name, v in
                 (("theta", theta_deg), ("alpha", alpha_deg), ("omega3", omega3), ("omega", omega),
                  ("speed", speed), ("com_speed", com_speed)) if v is not None}
        try:
            shape = np.broadcast_shapes(*(v.shape for v in given.values()))
        except ValueError:
            raise params.ParameterError("the arguments cannot be broadcast together") from None
        n = math.prod(shape)
        flat = {name: np.broadcast_to(v, shape).reshape(-1) for name, v in given.items()}
        req = make_requests(n, body=self.body.word, side=self.side, a=self.a, r=self.r, k=self.k, g=self.g,
                            mu=self.mu, **flat)
        table = evaluate(req, stability=stability)
        if len(table) and np.all(table["status"] == "invalid"):
            raise params.ParameterError(str(table["reason"][0]))
        return Table(table.columns, shape=shape) if len(table) == n else table


def validate_scalars(body, side, a, r, k, g, mu=math.inf) -> str:
    """The first problem with one set of parameters, in words ('' if none);
    ``body`` a paper body's record."""
    if not isinstance(body, PaperBodyKind):
        return f"body must be one of {' | '.join(BODIES)} (got {body!r})"
    if side not in SIDES:
        return f"side must be one of {' | '.join(SIDES)} (got {side!r})"
    for name, value in (("a", a), ("r", r), ("k", k), ("g", g), ("mu", mu)):
        if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
            return f"{name} must be a number (got {value!r})"
        problem = params.first_problem(name, [value])
        if problem:
            return problem
    return _combination_problem(side, a, r)


def _combination_problem(side, a, r) -> str:
    if too_big_inside(a, r, side == "outside"):
        return f"r (sphere radius) must be > a = {a:g} m for a body inside (got {params.shown_number(float(r))})"
    return ""


# ---------------------------------------------------------------------------
# requests: per-row parameters, vectorised validation, evaluation


def _as_array(value, n, dtype):
    arr = np.asarray(value, dtype=dtype)
    return np.broadcast_to(arr, (n,)).copy() if arr.shape != (n,) else arr.copy()


def make_requests(n: int, invalid: np.ndarray | None = None, input_row=None, typed=None, **fields) -> dict:
    """Build a request batch of ``n`` rows from scalars or length-n arrays.

    ``fields`` are the :data:`REQUEST_FIELDS` (theta and alpha in degrees);
    missing ones take their defaults; ``k=None`` or NaN means "by body".
    ``invalid`` is an object array of reasons ('' for rows parsed fine);
    ``typed``: field -> the name an input file's header gave its column
    (a row's refusal names it as typed).
    ``ground`` (not a column: one for the batch) is the arena when it is not
    the globe of radius ``r`` (docs/surfaces.md): a lane is then its
    ``height``.
    """
    req = {"ground": fields.get("ground")}
    for name, (default, _, _) in REQUEST_FIELDS.items():
        value = fields.get(name, default)
        if isinstance(value, PaperBodyKind):
            value = value.word      # the batch's body column is the words it prints
        if name in ("body", "side"):
            req[name] = _as_array(value, n, object)
        else:
            req[name] = _as_array(np.nan if value is None else value, n, float)
    req["input_row"] = np.arange(1, n + 1) if input_row is None else _as_array(input_row, n, np.int64)
    req["invalid"] = _as_array("" if invalid is None else invalid, n, object)
    req["typed"] = dict(typed or {})
    return req


def fixed_bank_angle(theta_deg, outside):
    """A sphere's bank angle [deg]: theta - 90 inside, theta + 90 outside
    (sec. 4); ``outside`` booleans."""
    return theta_deg + np.where(outside, 90.0, -90.0)


def validate_requests(req: dict) -> np.ndarray:
    """Reason each row is invalid ('' for valid rows), without raising.

    Each value is checked against its domain in :mod:`deathsphere.params`
    (vectorised), then the combinations (which inputs a body takes, r > a
    inside).  Words are built only for the rows that fail.
    """
    body, side = req["body"], req["side"]
    # the text columns as codes, kept for the solvers (:func:`evaluate`)
    req["body_code"] = body_code = paper_body_codes(body)
    side_code = text_codes(side, SIDES)
    req["outside"] = outside = side_code == SIDES.index("outside")
    k = req["k"].copy()
    by_body = np.isnan(k)
    k[by_body] = _DEFAULT_K[body_code[by_body]]   # an unknown body (code -1) keeps NaN
    req["k"] = k
    reason = req["invalid"].copy()
    pending = reason == ""
    typed = req.get("typed", {})
    ground = req.get("ground")
    height = req["height"] if "height" in req else np.full(body.size, np.nan)
    checks = [
        (body_code < 0, lambda i: f"body must be one of {' | '.join(BODIES)} (got {echo(body[i])})"),
        (side_code < 0, lambda i: f"side must be one of {' | '.join(SIDES)} (got {echo(side[i])})"),
    ] + (_globe_lane_checks(req, height) if ground is None else _ground_lane_checks(req, height, ground))
    if ground is None:
        _theta_from_height(req, height)

    def domain(name, given=None):
        # only the values given are checked (an optional input left empty is
        # NaN in every row, and would otherwise cost a message per row), and
        # words only for the rows that fail
        values = req[name]
        if given is None and values.size and np.all(values == values[0]):
            # one value in every row (a, r, g, mu in a sweep): check it once
            bad = np.full(values.size, bool(params.failing(name, values[:1])[0]))
        else:
            bad = params.failing(name, values)
            if given is not None:
                bad &= given
        checks.append((bad, lambda i: as_typed(name, params.problems(name, values[i:i + 1])[0], typed)))

    for name in ("theta", "a", "r", "k", "g", "mu", "max_g") if ground is None else ("a", "k", "g", "mu", "max_g"):
        domain(name)
    domain("height", ~np.isnan(height))
    if ground is None:
        with np.errstate(invalid="ignore"):
            checks.append((too_big_inside(req["a"], req["r"], side_code != SIDES.index("inside")),
                           lambda i: _combination_problem(side[i], req["a"][i], req["r"][i])))
    alpha, omega3, omega, speed = req["alpha"], req["omega3"], req["omega"], req["speed"]
    is_wheel, is_sphere = body_code == WHEEL.code, body_code == BALL.code
    targets = sum((~np.isnan(req[key])).astype(int) for key in WHEEL.held_by)
    checks.append((is_wheel & (targets != 1),
                   lambda i: "a wheel needs exactly one of alpha | speed (m/s: the contact's) | com_speed (m/s: "
                             "the centre's) | omega (rad/s)"))
    com_speed = req["com_speed"]
    for name, v in (("alpha", alpha), ("speed", speed), ("com_speed", com_speed), ("omega", omega),
                    ("omega3", omega3)):
        domain(name, ~np.isnan(v))
    with np.errstate(invalid="ignore"):
        checks.append((is_wheel & (omega < 0),
                       lambda i: f"a wheel's omega is its rate about the vertical: > 0 (got {params.shown_number(float(omega[i]))})"))
    checks.append((~is_wheel & ~np.isnan(speed), lambda i: "speed is an input for a wheel only"))
    checks.append((~is_wheel & ~np.isnan(com_speed), lambda i: "com_speed is an input for a wheel only"))
    checks.append((is_sphere & (sum((~np.isnan(req[key])).astype(int) for key in BALL.held_by) != 1),
                   lambda i: "a sphere needs exactly one of omega3 (spin) and omega (orbital rate)"))
    checks.append((~is_sphere & ~np.isnan(omega3), lambda i: "omega3 is an input for a sphere only"))
    # a result CSV fed back carries a sphere's fixed bank angle as alpha_deg: that one is accepted
    tilted_sphere = is_sphere & ~np.isnan(alpha)
    if tilted_sphere.any() and ground is None:
        with np.errstate(invalid="ignore"):
            tilted_sphere &= np.abs(params.reduce_angle(alpha - fixed_bank_angle(req["theta"], outside))) >= 1e-9
    checks.append((tilted_sphere,
                   lambda i: "a sphere's tilt is fixed (theta - 90 deg inside; theta + 90 deg outside): no alpha"))
    checks.append(((body_code == PARTICLE.code) & ~(np.isnan(alpha) & np.isnan(omega)),
                   lambda i: "a particle takes only theta (no alpha or omega)"))
    for failed, words in checks:
        hit = pending & failed
        for i in np.flatnonzero(hit):  # only the (few) bad rows get words
            reason[i] = words(i)
        pending &= ~hit
    return reason


def _lane_word(ground) -> str:
    # on flat ground a lane is the turn's radius (the plane has no wall to climb)
    return "height" if hasattr(ground, "highest_lane") else "turn_radius"


def _globe_lane_checks(req, height):
    """The globe's lane: theta, or its height above the floor (not both)."""
    theta = req["theta"]
    return [
        (np.isnan(theta) & np.isnan(height), lambda i: "theta is missing (give --theta or a theta column)"),
        # both agree in a result CSV fed back: theta is kept
        (~np.isnan(theta) & ~np.isnan(height)
         & ~(np.abs(height - req["r"] * (1 + np.cos(np.radians(theta)))) <= 1e-9 * req["r"]),
         lambda i: "give the lane's theta or its height, not both"),
        (np.isnan(theta) & (height > 2 * req["r"]),
         lambda i: f"height must be 0..{params.shown_number(2 * float(req['r'][i]))} m on the sphere "
                   f"(its diameter; got {params.shown_number(float(height[i]))})"),
    ]


def _ground_lane_checks(req, height, ground):
    """A lane on another surface: its height (on flat ground its turn radius), never theta."""
    word = _lane_word(ground)
    return [
        (~np.isnan(req["theta"]), lambda i: f"theta is the sphere's polar angle: on the {ground.name} give the "
                                            f"lane's {word}"),
        (np.isnan(height), lambda i: f"{word} is missing: on the {ground.name} a lane is its {word}"),
    ]


def _theta_from_height(req, height):
    """A globe's lane given by its height: theta = arccos(height / r - 1)
    (the Sphere's own conversion), where it is on the globe."""
    from deathsphere.physics.ground import Sphere

    with np.errstate(invalid="ignore"):
        rows = np.isnan(req["theta"]) & (height >= 0) & (height <= 2 * req["r"])
    if rows.any():
        req["theta"] = req["theta"].copy()
        req["theta"][rows] = np.degrees(Sphere(1.0).theta(height[rows] / req["r"][rows]))


def _wheel(req, rows):
    tilted = rows[~np.isnan(req["alpha"][rows])]
    parts = []
    if tilted.size:
        sel = {key: req[key][tilted] for key in ("theta_rad", "alpha_rad", "a", "r", "k", "g", "mu")}
        res = wheel.horizontal_orbit(
            sel["theta_rad"], sel["alpha_rad"], sel["a"], sel["r"], sel["k"], sel["g"],
            outside=req["outside"][tilted], mu=sel["mu"])
        parts.append((tilted, np.full(tilted.size, -1), res))
    solve = rows[np.isnan(req["alpha"][rows])]
    if solve.size:
        parts.extend(_wheel_solved(req, solve))
    return parts


def _wheel_solved(req, rows):
    """Speed or rate given: every alpha of eq. (29), one row per root (branch
    = root index, in increasing alpha); a request with no root gives one
    no_orbit row.  A contact speed v (``speed``, along the ground) fixes
    the rate Omega = v / rho_P, rho_P = r sin(theta) the parallel the
    contact runs round, and is solved as that rate; with the contact on
    the axis no rate gives it (no_orbit, contact_on_axis).  A centre speed
    (``com_speed``) is solved as v_cm = |r'| Omega.  One vectorised call per
    distinct setup and target kind."""
    from deathsphere.physics import region
    from deathsphere.physics.ground import Sphere
    from deathsphere.physics.machine_lanes import contact_rate

    outside = req["outside"][rows].astype(float)
    # 0: rate, 1: centre speed, 2: contact speed
    kind = np.where(~np.isnan(req["com_speed"][rows]), 1.0, np.where(~np.isnan(req["speed"][rows]), 2.0, 0.0))
    setups = np.column_stack([req[key][rows] for key in ("a", "r", "k", "g", "mu")] + [outside, kind])
    unique, inverse = np.unique(setups, axis=0, return_inverse=True)
    parts = []
    for u, (a, r, k, g, mu, out, how) in enumerate(unique):
        sub = rows[inverse.reshape(-1) == u]
        if how == 1:
            target = {"speed": req["com_speed"][sub]}
        elif how == 2:
            rate = contact_rate(req["theta_rad"][sub], req["speed"][sub], Sphere(float(r)))
            on_axis = np.isnan(rate)
            if on_axis.any():
                axis = sub[on_axis]
                parts.append((axis, np.full(axis.size, -1), {
                    "status": np.full(axis.size, Status.NO_ORBIT, dtype=np.int8),
                    "reason": np.full(axis.size, Reason.CONTACT_ON_AXIS, dtype=np.int8)}))
                sub, rate = sub[~on_axis], rate[~on_axis]
                if not sub.size:
                    continue
            target = {"omega": rate}
        else:
            target = {"omega": req["omega"][sub]}
        res = region.solve_alpha(req["theta_rad"][sub], a, r, k, g, outside=bool(out), mu=mu, **target)
        count = np.asarray(res["count"]).reshape(-1)
        roots = res["alpha"].reshape(sub.size, -1)
        row_i, root_j = np.nonzero(np.arange(roots.shape[1])[None, :] < count[:, None])
        flat = {key: np.asarray(v).reshape(sub.size, -1)[row_i, root_j] for key, v in res.items()
                if key not in ("count",) and np.size(v) == roots.size}
        flat["alpha_deg"] = np.rad2deg(flat.pop("alpha"))
        parts.append((sub[row_i], root_j, flat))
        none = sub[count == 0]
        if none.size:
            parts.append((none, np.full(none.size, -1), {
                "status": np.full(none.size, Status.NO_ORBIT, dtype=np.int8),
                "reason": np.full(none.size, Reason.NO_ALPHA_FOR_RATE, dtype=np.int8)}))
    return parts


def _sphere(req, rows):
    """Spin given: both roots of eq. (55), one row each; rate given: one row."""
    from deathsphere.physics import sphere

    outside = req["outside"][rows]
    sel = {key: req[key][rows] for key in ("theta_rad", "a", "r", "k", "g", "mu", "omega3", "omega")}
    theta = sel["theta_rad"]
    spun = ~np.isnan(sel["omega3"])
    parts = []
    if spun.any():
        m = spun
        res = sphere.sphere_orbit(theta[m], sel["omega3"][m], sel["a"][m], sel["r"][m],
                                  sel["k"][m], sel["g"][m], outside[m], sel["mu"][m])
        res = {key: np.asarray(v).reshape(-1) for key, v in res.items()}
        parts.append((np.repeat(rows[m], 2), res["branch"].astype(int), res))
    if (~spun).any():
        m = ~spun
        res = sphere.sphere_orbit_from_rate(theta[m], sel["omega"][m], sel["a"][m], sel["r"][m],
                                            sel["k"][m], sel["g"][m], outside[m], sel["mu"][m])
        parts.append((rows[m], np.asarray(res["branch"]).astype(int), res))
    return parts


def _particle(req, rows):
    from deathsphere.physics import particle

    res = particle.particle_orbit(req["theta_rad"][rows], req["r"][rows], req["g"][rows],
                                  outside=req["outside"][rows], mu=req["mu"][rows])
    return [(rows, np.full(rows.size, -1), res)]


#: The solver of each of the paper's bodies, by its record's type.
SOLVERS = {Wheel: _wheel, Ball: _sphere, Particle: _particle}
#: Each body code's inertia factor when none is given (the last entry:
#: code -1, a word naming no body, keeps NaN; its row is invalid).
_DEFAULT_K = np.array([body.default_k for body in PAPER_BODIES] + [np.nan])


def _ground_wheel(req, rows):
    """A wheel on another surface: its tilt given, one row; its speed or rate
    given, every tilt of S2 (docs/surfaces.md), one row per root as on the
    globe (:func:`_ground_wheel_solved`)."""
    from deathsphere.physics import revolution

    tilted = rows[~np.isnan(req["alpha"][rows])]
    parts = []
    if tilted.size:
        res = revolution.wheel_orbit(req["ground"], *(req[key][tilted] for key in ("height", "alpha_rad", "a", "k",
                                                                                    "g")),
                                     outside=req["outside"][tilted], mu=req["mu"][tilted])
        parts.append((tilted, np.full(tilted.size, -1), res))
    solve = rows[np.isnan(req["alpha"][rows])]
    if solve.size:
        parts.extend(_ground_wheel_solved(req, solve))
    return parts


def _ground_wheel_solved(req, rows):
    """Speed or rate given on another surface: every alpha of S2, one row per
    root (branch = root index, in increasing alpha); a request with no root
    gives one row with the reason (no root, off the wall, no tilt fits, a
    contact speed on the axis).  One vectorised call per kind of target."""
    from deathsphere.physics.revolution_tilt import wheel_tilts

    parts = []
    for name in ("com_speed", "speed", "omega"):
        sub = rows[~np.isnan(req[name][rows])]
        if name != "omega":
            rows = rows[np.isnan(req[name][rows])]      # a row's target is the first of its kind found
        if not sub.size:
            continue
        res = wheel_tilts(req["ground"], req["height"][sub], req["a"][sub], req["k"][sub], req["g"][sub],
                          outside=req["outside"][sub], mu=req["mu"][sub], **{name: req[name][sub]})
        count = res["count"]
        roots = res["alpha"]
        row_i, root_j = np.nonzero(np.arange(roots.shape[1])[None, :] < count[:, None])
        flat = {key: value[row_i, root_j] for key, value in res.items() if np.shape(value) == roots.shape}
        flat["alpha_deg"] = np.rad2deg(flat.pop("alpha"))
        parts.append((sub[row_i], root_j, flat))
        none = count == 0
        if none.any():
            parts.append((sub[none], np.full(int(none.sum()), -1), {
                "status": res["unsolved_status"][none], "reason": res["unsolved_reason"][none],
                **{key: value[none] for key, value in res["lane"].items()}}))
    return parts


def _ground_ball(req, rows):
    """A ball on another surface (docs/surfaces.md S6): as on the sphere,
    both roots of a spin, one row of a rate."""
    from deathsphere.physics import revolution

    sel = {key: req[key][rows] for key in ("height", "a", "k", "g", "mu", "omega3", "omega")}
    outside = req["outside"][rows]
    spun = ~np.isnan(sel["omega3"])
    parts = []
    for m, solve in ((spun, revolution.ball_orbit), (~spun, revolution.ball_orbit_from_rate)):
        if not m.any():
            continue
        second = sel["omega3"][m] if solve is revolution.ball_orbit else sel["omega"][m]
        res = solve(req["ground"], sel["height"][m], second, sel["a"][m], sel["k"][m], sel["g"][m],
                    outside=outside[m], mu=sel["mu"][m])
        res = {key: np.asarray(v).reshape(-1) for key, v in res.items()}
        res["alpha_deg"] = np.degrees(res.pop("alpha"))       # the ball's bank, 90 - beta inside
        source = np.repeat(rows[m], 2) if solve is revolution.ball_orbit else rows[m]
        parts.append((source, res["branch"].astype(int), res))
    return parts


def _ground_particle(req, rows):
    from deathsphere.physics import revolution

    res = revolution.particle_orbit(req["ground"], req["height"][rows], req["g"][rows], outside=req["outside"][rows],
                                    mu=req["mu"][rows])
    return [(rows, np.full(rows.size, -1), res)]


#: The solvers on a surface other than the globe (docs/surfaces.md).
GROUND_SOLVERS = {Wheel: _ground_wheel, Ball: _ground_ball, Particle: _ground_particle}


def evaluate(req: dict, stability: bool = True) -> Table:
    """Evaluate a request batch, in input order.

    Every request yields one row, except where one request has several
    answers, each a row with the request's ``input_row`` and its ``branch``:
    a sphere given its spin omega3 (the roots of eq. (55): 0 slow, 1 fast)
    and a wheel given its speed or rate (every alpha of eq. (29), in
    increasing alpha; none: one ``no_orbit`` row).  With ``stability`` the
    exact linear stability of every orbit that exists with contact (status
    ok or slips) fills the stability columns (:func:`add_stability`).  Invalid requests come out with
    status ``invalid`` and the reason; the rest are computed, grouped by body
    (a handful of vectorised calls, no loop over orbits).
    """
    invalid = validate_requests(req)
    # degrees become radians here, once, for every solver and the stability
    # analysis (the physics is in radians; the degrees are kept to be echoed)
    req["theta_rad"] = np.deg2rad(req["theta"])
    req["alpha_rad"] = np.deg2rad(params.reduce_angle(req["alpha"]))
    ok = invalid == ""
    body, body_code = req["body"], req["body_code"]
    bad = np.flatnonzero(~ok)
    parts = [(bad, np.full(bad.size, -1), None)]
    ground = req.get("ground")
    solvers = SOLVERS if ground is None else GROUND_SOLVERS
    for one in PAPER_BODIES:
        rows = np.flatnonzero(ok & (body_code == one.code))
        if rows.size:
            parts.extend(solvers[type(one)](req, rows))

    source = np.concatenate([p[0] for p in parts]).astype(np.int64)
    branch = np.concatenate([p[1] for p in parts]).astype(np.int64)
    m = source.size
    out = {name: np.full(m, np.nan) for name in _PHYSICS_COLUMNS.values()}
    status = np.full(m, Status.INVALID, dtype=np.int8)
    reason = np.empty(m, dtype=object)
    alpha = req["alpha"][source].copy()
    alpha_rad = req["alpha_rad"][source].copy()
    lane = {"rho_contact_m": np.full(m, np.nan), "wall_angle_deg": np.full(m, np.nan), "z": np.full(m, np.nan)}
    start = 0
    for rows, _, res in parts:
        span = slice(start, start + rows.size)
        start += rows.size
        if res is None:
            reason[span] = invalid[rows]
            continue
        for key, column in _PHYSICS_COLUMNS.items():
            if key in res:
                out[column][span] = res[key]
        status[span] = res["status"]
        reason[span] = REASON_TEXT[res["reason"]]
        if "rho_contact" in res:  # a lane on another surface
            lane["rho_contact_m"][span] = res["rho_contact"]
            lane["wall_angle_deg"][span] = np.degrees(res["wall_angle"])
            lane["z"][span] = res["z_contact"]
        if "alpha_deg" in res:  # a wheel's tilt solved from its speed or rate
            alpha[span] = res["alpha_deg"]
            # the orbit analysed is the orbit printed: the tilt as its degrees read back
            alpha_rad[span] = np.deg2rad(params.reduce_angle(res["alpha_deg"]))

    order = np.lexsort((branch, source))
    pick = source[order]
    # text compared once per request, not per row and column (an object
    # comparison costs a Python call per element)
    is_sphere, is_particle = body_code == BALL.code, body_code == PARTICLE.code
    if is_sphere.any() and ground is None:
        sphere_alpha = fixed_bank_angle(req["theta"], req["outside"])
        alpha = np.where(is_sphere[source], sphere_alpha[source], alpha)
    particle = is_particle[pick]
    columns = {
        "input_row": req["input_row"][pick].astype(np.int64),
        "body": body[pick].astype(object, copy=False),
        "side": req["side"][pick].astype(object, copy=False),
        "theta_deg": req["theta"][pick],
        "alpha_deg": np.where(particle, np.nan, alpha[order]),
        "a_m": np.where(particle, np.nan, req["a"][pick]),
        "r_m": req["r"][pick] if ground is None else np.full(pick.size, float(getattr(ground, "radius", np.nan))),
        "k": req["k"][pick],
        "g_m_s2": req["g"][pick],
        "status": STATUS_LABELS[status[order]],
        "reason": reason[order],
    }
    for key in _PHYSICS_COLUMNS.values():
        columns[key] = out[key][order]
    # inf ("no limit") is not representable in JSON: empty/null means no --mu given
    columns["mu_available"] = np.where(np.isinf(req["mu"][pick]), np.nan, req["mu"][pick])
    max_g = req["max_g"][pick]
    columns["max_g"] = np.where(np.isinf(max_g), np.nan, max_g)
    # the limit's first column, kept for scripts (the same number)
    columns["max_accel_g"] = columns["max_g"]
    # the load limit comes last in the order of failures (docs/contract.md):
    # an orbit that is otherwise ok but presses the rider past max_g
    with np.errstate(invalid="ignore"):
        over = (status[order] == Status.OK) & (columns["load_g"] > max_g)
    columns["status"][over] = "over_g"
    columns["reason"][over] = REASON_TEXT[Reason.OVER_G]
    columns["branch"] = np.full(len(pick), None, dtype=object)
    rooted = np.flatnonzero(branch[order] >= 0)  # a row per root: its index (Python ints, as the contract prints)
    columns["branch"][rooted] = branch[order][rooted].tolist()
    codes = status[order]
    codes[over] = Status.OVER_G
    demoted = finite_or_blank(columns)
    if demoted is not None:
        codes[demoted] = Status.INVALID
    if ground is not None:
        columns.update(add_stability_on(columns, ground, req["height"][pick], alpha_rad[order], codes,
                                        body_code[pick], req["outside"][pick]) if stability
                       else _no_stability(len(pick)))
    else:
        columns.update(add_stability(columns, req["theta_rad"][pick], alpha_rad[order], codes,
                                     body_code[pick], req["outside"][pick]) if stability
                       else _no_stability(len(pick)))
    columns.update(_lane_columns(req, ground, pick, {key: value[order] for key, value in lane.items()},
                                 codes != Status.INVALID))
    # the contact runs round the parallel of radius rho_contact at the rate Omega (any body, any ground)
    columns["v_contact_m_s"] = np.abs(columns["omega_rad_s"]) * columns["rho_contact_m"]
    echo_given(columns, {column: req[name][pick] for name, column in ECHOED.items()}, codes != Status.INVALID)
    return Table({name: columns[name] for name in COLUMNS})


def _lane_columns(req, ground, pick, lane, valid):
    """The arena's columns (docs/contract.md): the surface, the lane's height
    above its lowest point, the contact's distance from the axis and the
    wall angle there; on the globe from theta (height r (1 + cos theta),
    rho r sin theta, wall angle 180 - theta)."""
    n = pick.size
    if ground is None:
        theta, r = req["theta"][pick], req["r"][pick]
        rad = np.radians(theta)
        given = req["height"][pick] if "height" in req else np.full(n, np.nan)
        height = np.where(valid, np.where(np.isnan(given), r * (1 + np.cos(rad)), given), np.nan)
        rho = np.where(valid, r * np.sin(rad), np.nan)
        wall = np.where(valid, 180.0 - theta, np.nan)
        return {"surface": np.full(n, "sphere", dtype=object), "height_m": height, "rho_contact_m": rho,
                "wall_angle_deg": wall}
    given = req["height"][pick]
    # the lane's height as the ground places it (on flat ground 0: its lane is a turn radius)
    placed = lane["z"] - ground.lowest
    flat = not hasattr(ground, "highest_lane")
    height = np.where(valid, placed if flat else given, np.nan)
    return {"surface": np.full(n, ground.name, dtype=object), "height_m": height,
            "rho_contact_m": lane["rho_contact_m"], "wall_angle_deg": lane["wall_angle_deg"]}


#: Statuses of a steady orbit that exists with contact (it may need more
#: friction or load than allowed): its stability is analysed.
LIVE_CODES = (Status.OK, Status.SLIPS, Status.OVER_G)
LIVE_STATUSES = tuple(code.label for code in LIVE_CODES)
#: Request fields a row prints as given, and their columns (docs/contract.md,
#: "Inputs are echoed as given").
ECHOED = {"speed": "v_contact_m_s", "com_speed": "v_cm_m_s", "omega": "omega_rad_s", "omega3": "omega3_rad_s"}


def echo_given(columns: dict, given: dict, valid: np.ndarray | None = None) -> None:
    """Print a quantity a request fixes as given, in every row that is not
    ``invalid``, whatever its status: a solved root reproduces a wheel's
    speed or rate only to the last bits, and a row with no orbit (no root,
    a pole, no fit) computes none, yet it is still the answer to that
    request (two requests must not give identical rows).  ``given``:
    column -> the requested values per row (NaN where not given); ``valid``
    the rows that are not ``invalid``, when known."""
    if valid is None:
        valid = columns["status"] != "invalid"
    for column, target in given.items():
        columns[column] = np.where(valid & ~np.isnan(target), target, columns[column])


#: The reason of a row whose result left float64's range (a backstop: the
#: input domains of :mod:`deathsphere.params` are chosen so that it never fires).
OVERFLOW_REASON = "a result overflowed float64 (inputs outside the representable range)"


def finite_or_blank(columns: dict) -> np.ndarray | None:
    """No row carries inf: an infinite value becomes empty, and a row that
    claimed an orbit (ok, slips) with one becomes ``invalid`` with the
    reason; returns those rows (None when no value was infinite)."""
    hit = np.zeros(len(columns["status"]), dtype=bool)
    for name, col in columns.items():
        if isinstance(col, np.ndarray) and col.dtype.kind == "f":
            inf = np.isinf(col)
            if inf.any():
                col[inf] = np.nan
                hit |= inf
    if not hit.any():
        return None
    claimed = hit & np.isin(columns["status"], LIVE_STATUSES)
    columns["status"][claimed] = "invalid"
    columns["reason"][claimed] = OVERFLOW_REASON
    return claimed


def _no_stability(n: int) -> dict:
    blank = np.full(n, "", dtype=object)
    return {"stability": blank, "stability_method": blank.copy(), "growth_rate_1_s": np.full(n, np.nan),
            "freq_slow_rad_s": np.full(n, np.nan), "freq_fast_rad_s": np.full(n, np.nan),
            "stability_kind": blank.copy()}


#: ``stability_method`` values.
EXACT_METHOD = methods.EXACT
NOT_ANALYSED_K0 = methods.NOT_ANALYSED_K0


def _stability_columns(columns: dict, status: np.ndarray, body_code: np.ndarray, solve, not_analysed=None) -> dict:
    """The stability columns from ``solve(body, rows)`` (the exact
    linearisation's dict for those rows of that body, a wheel's or a
    ball's) where the steady orbit exists with contact; a sliding particle,
    k = 0 and the rows of ``not_analysed`` (mask, method) are ``unknown``
    with the reason as the method."""
    from deathsphere.physics import stability as exact
    from deathsphere.physics.stability.verdict import stability_kind

    out = _no_stability(len(columns["status"]))
    live = np.isin(status, LIVE_CODES)
    particle = body_code == PARTICLE.code
    skipped = [(live & (columns["k"] == 0) & ~particle, NOT_ANALYSED_K0)]
    if not_analysed is not None:
        skipped.append((live & not_analysed[0] & ~particle, not_analysed[1]))
    for mask, method in skipped:
        out["stability"][mask] = "unknown"
        out["stability_method"][mask] = method
        live &= ~mask
    for one in (WHEEL, BALL):
        rows = np.flatnonzero(live & (body_code == one.code))
        if not rows.size:
            continue
        res = solve(one, rows)
        out["stability"][rows] = exact.VERDICT_LABELS[res["verdict"]]
        out["stability_method"][rows] = EXACT_METHOD
        out["growth_rate_1_s"][rows] = res["growth_rate"]
        out["freq_slow_rad_s"][rows] = res["freq_slow"]
        out["freq_fast_rad_s"][rows] = res["freq_fast"]
        out["stability_kind"][rows] = stability_kind(res["growth_rate"], res["rate_scale"])
    rows = np.flatnonzero(live & particle)
    out["stability"][rows] = "unknown"
    out["stability_method"][rows] = methods.NOT_ANALYSED_PARTICLE
    return out


def add_stability_on(columns: dict, ground, height: np.ndarray, alpha_rad: np.ndarray, status: np.ndarray,
                     body_code: np.ndarray, outside: np.ndarray) -> dict:
    """The stability columns of orbits on a ground other than the globe:
    the exact linearisation of the equations of motion on any ground
    (docs/dynamics.md sec. 7; physics.stability.wheel_stability_on and
    ball_stability_on), as :func:`add_stability` on the sphere, inside
    and outside; a sliding particle is not analysed."""
    from deathsphere.physics import stability as exact

    par = {key: columns[col] for key, col in (("a", "a_m"), ("k", "k"), ("g", "g_m_s2"))}
    solvers = {WHEEL: (exact.wheel_stability_on, alpha_rad), BALL: (exact.ball_stability_on, columns["omega_rad_s"])}

    outside = np.asarray(outside, dtype=bool)

    def solve(one, rows):
        solver, second = solvers[one]
        return solver(ground, height[rows], second[rows], *(par[key][rows] for key in ("a", "k", "g")),
                      outside=outside[rows])

    return _stability_columns(columns, status, body_code, solve)


def add_stability(columns: dict, theta_rad: np.ndarray, alpha_rad: np.ndarray, status: np.ndarray,
                  body_code: np.ndarray, outside: np.ndarray) -> dict:
    """The stability columns for rows whose steady orbit exists with contact.

    Beyond the paper (docs/stability.md): the exact equations of motion
    linearised about the orbit in the frame turning with it, with the neutral
    modes of the symmetry and of the family of orbits removed; growth rate
    = max Re(eigenvalue) [1/s], the two nutation frequencies [rad/s] in the
    turning frame.  A sliding particle is not analysed (``unknown``).
    ``theta_rad`` and ``alpha_rad`` are each row's angles as the request's
    radians (converted once, in :func:`evaluate`), not read back from the
    degree columns; ``status`` (int8 :class:`Status` codes), ``body_code``
    (:func:`deathsphere.requests.decode.paper_body_codes`) and ``outside`` are each row's too.
    """
    from deathsphere.physics import stability as exact

    par = {key: columns[col] for key, col in (("a", "a_m"), ("r", "r_m"), ("k", "k"), ("g", "g_m_s2"))}
    # a wheel's orbit is fixed by its tilt, a ball's by its orbital rate (eqs. 29, 55)
    solvers = {WHEEL: (exact.wheel_stability, alpha_rad), BALL: (exact.sphere_stability, columns["omega_rad_s"])}

    def solve(one, rows):
        solver, second = solvers[one]
        return solver(theta_rad[rows], second[rows], *(par[key][rows] for key in ("a", "r", "k", "g")),
                      outside=outside[rows])

    return _stability_columns(columns, status, body_code, solve)
