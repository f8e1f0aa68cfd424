"""Every input parameter of every command, its unit and its allowed values,
defined once and checked once (docs/contract.md, "Inputs").

The command line, ``--input`` rows and the Python API all validate through
this module: :func:`problems` checks a whole array of values at once (no
loop over rows) and returns the reason each value is refused ('' where it
is fine); the API (:mod:`deathsphere.api.arguments`) raises
:class:`ParameterError` with that reason, the one line the command line prints.

Why the magnitude bounds: every dimensional input lies within 1e-9..1e9 of
its SI unit.  Products of a few such numbers (Omega^2 r', v^2 / r', ...)
then stay far inside float64's range, so no result of an accepted input
overflows to inf or underflows to a denormal; a wheel of 1e-320 m or a spin
of 1e308 rad/s is refused with the reason, instead of giving ``inf`` in a
row marked ``ok``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from deathsphere.constants import (
    STANDARD_GRAVITY,
    TABLE1_SPHERE_RADIUS,
    TABLE1_WHEEL_RADIUS,
)
from deathsphere.errors import ParameterError  # noqa: F401  (raised by every check here; the API's error)

#: Dimensional inputs lie within [TINY, HUGE] in magnitude (see above).
TINY = 1e-9
HUGE = 1e9
#: The least relative tolerance scipy's solve_ivp honours (100 eps, about
#: 2.2e-14): it silently raises any smaller rtol to this, with a warning,
#: so a smaller one is refused rather than reported as if it had been used.
RTOL_MIN = 100 * np.finfo(float).eps


@dataclass(frozen=True)
class Param:
    """One input, defined once for the API's checks, the command line's
    options, the input files' columns and the docs' tables.

    ``name`` is the API's keyword and the command line's ``--name``;
    ``unit`` the unit the API takes it in; ``what`` a few words for
    messages; ``[lo, hi]`` the allowed interval (``lo_open`` / ``hi_open``
    exclude an end); ``nonzero`` refuses 0 (a signed rate); ``allow_inf``
    accepts +inf ("no limit"); ``integer`` wants whole numbers.

    The rest describe it to people and files: ``symbol`` as in the paper;
    ``kind`` the physical kind whose unit suffixes the option accepts
    (:mod:`deathsphere.units`: length, speed, rate, angle, acceleration,
    none); ``default`` the API's default (None: required, or chosen by the
    body); ``default_text`` how help shows it; ``help`` one sentence for
    ``--help`` and the docs; ``flags`` the command line's spellings (default
    ``--name``); ``metavar``; ``column`` the output column that echoes it,
    read back when a result CSV is fed in as ``--input``.
    """

    name: str
    unit: str
    what: str
    lo: float
    hi: float
    lo_open: bool = False
    hi_open: bool = False
    nonzero: bool = False
    allow_inf: bool = False
    integer: bool = False
    symbol: str = ""
    kind: str = "none"
    default: float | None = None
    default_text: str | None = None
    help: str = ""
    flags: tuple[str, ...] = ()
    metavar: str = "X"
    column: str | None = None
    #: a word among these instead of a number (the ground's kind: ``surface``)
    choices: tuple[str, ...] = ()

    def label(self) -> str:
        """``name (what)``, e.g. ``a (body radius)``."""
        return f"{self.name} ({self.what})"

    def allowed(self) -> str:
        """The allowed values in words, e.g. ``1e-09..1e+09 m``."""
        unit = f" {self.unit}" if self.unit else ""
        if self.choices:
            return " \\| ".join(self.choices)
        if self.allow_inf:
            return f">= {self.lo:g} or inf (no limit)"
        if self.integer:
            return f"a whole number {self.lo:g}..{self.hi:g}"
        if self.lo == -self.hi:
            lead = f"-{self.hi:g}..{self.hi:g}{unit}"
            return lead + (" and not 0" if self.nonzero else "")
        left = f"> {self.lo:g}" if self.lo_open else f"{self.lo:g}"
        if self.lo_open:
            return f"{left} and <= {self.hi:g}{unit}" if not self.hi_open else f"{left} and < {self.hi:g}{unit}"
        return f"{left}..{self.hi:g}{unit}" + (" (end excluded)" if self.hi_open else "")

    @property
    def cli_flags(self) -> tuple[str, ...]:
        return self.flags or (f"--{self.name.replace('_', '-')}",)

    @property
    def shown_default(self) -> str | None:
        """The default as ``--help`` shows it (None: no default to show)."""
        if self.default_text is not None:
            return self.default_text
        if self.default is None:
            return None
        return "unlimited" if math.isinf(self.default) else f"{self.default:g}"


def _length(name, what, symbol, lo=TINY, **more):
    return Param(name, "m", what, lo, HUGE, symbol=symbol, kind="length", metavar="M", **more)


#: A two-wheeler's body parameters (Table 1 of Meijaard et al. 2007) lie
#: within what any ridden two-wheeler and its riders can be, from a toy to
#: the heaviest show bike, not merely within float64's comfort (1e-9..1e9):
#: a mass up to 10 t (the heaviest ridden motorcycles weigh some 5 t, a
#: touring bike with two riders 0.6 t), a moment of inertia up to 1e5 kg m^2
#: (10 t at a 3 m radius of gyration), positions within 10 m of the rear
#: contact, a wheel base of 5 cm (a toy) to 10 m (the longest ridden bikes
#: are some 7 m), a wheel radius of 1 cm to 3 m (a penny-farthing's is
#: 0.75 m) and a trail within 2 m either way.  Beyond them the loads and
#: eigenvalues are numbers of no machine (and, far beyond, inf).
TW_MAX_MASS = 1e4
TW_MAX_INERTIA = 1e5
TW_MAX_POSITION = 10.0


def _body(body, what, moments):
    """A two-wheeler's body's mass m<body> and its inertia tensor's entries
    I<body><axes> in the benchmark's axes (kg m^2; a product of inertia, xz,
    of either sign), within a ridden two-wheeler's bounds (above)."""
    mass = Param(f"m{body}", "kg", f"{what} mass", 0.0, TW_MAX_MASS, symbol=f"m_{body}", kind="mass",
                 metavar="KG")
    return (mass, *(Param(f"I{body}{axes}", "kg m^2", f"{what} inertia {axes}",
                          -TW_MAX_INERTIA if axes == "xz" else 0.0, TW_MAX_INERTIA, symbol=f"I_{body}{axes}",
                          metavar="KG_M2") for axes in moments))


def _position(name, what, symbol):
    """A mass centre's coordinate from the rear contact (m), within a ridden two-wheeler's bounds (above)."""
    return Param(name, "m", what, -TW_MAX_POSITION, TW_MAX_POSITION, symbol=symbol, kind="length", metavar="M")


#: Every parameter, by name.  Angles are in degrees, as on the command line.
PARAMS: dict[str, Param] = {p.name: p for p in (
    Param("theta", "deg", "polar angle", 0.0, 180.0, symbol="θ", kind="angle", metavar="DEG", column="theta_deg",
          help="Polar angle of the contact point from the upward vertical, 0..180 (90 = the equator)."),
    # any angle is accepted and reduced to (-180, 180] for the physics
    Param("alpha", "deg", "tilt", -1e6, 1e6, symbol="α", kind="angle", metavar="DEG", column="alpha_deg",
          help="Wheel: tilt of the wheel's diameter through the contact point below the orbit plane; any "
               "angle (205 = -155)."),
    _length("a", "body radius", "a", default=TABLE1_WHEEL_RADIUS, flags=("-a", "--wheel-radius"), column="a_m",
            help="Radius of the rolling body (a wheel to its tyre's crown)."),
    _length("r", "sphere radius", "r", default=TABLE1_SPHERE_RADIUS, flags=("-r", "--sphere-radius"),
            column="r_m", help="Radius of the fixed sphere (the globe); or give --diameter."),
    _length("diameter", "sphere diameter", "2r",
            help="Diameter of the fixed sphere instead of -r (a globe is sold by its diameter: 16ft); with "
                 "--surface cylinder or cone the drum's, the cone's at the floor."),
    # the arena of orbit and sweep (docs/surfaces.md): a surface of revolution by its shape
    Param("wall_angle", "deg", "wall angle", 0.0, 180.0, lo_open=True, hi_open=True, symbol="β", kind="angle",
          metavar="DEG",
          column="wall_angle_deg",
          help="With --surface cone: the wall's angle from the horizontal, strictly between 0 and 180 (90 = a "
               "drum; about 80 a well of death, 45..60 a board track; over 90 it leans in)."),
    _length("wall_height", "wall height", "H", allow_inf=True,
            help="With --surface cylinder or cone: the wall's height above the floor; no lane above it "
                 "(default: no top)."),
    Param("k", "", "inertia factor", 0.0, 1e3, symbol="k", metavar="K", flags=("-k", "--inertia"), column="k",
          default_text="0.5 wheel, 0.4 sphere",
          help="Inertia factor: I11 = 2 k m a^2 for a wheel (eq. 1), I = k m a^2 for a sphere."),
    Param("g", "m/s^2", "gravity", TINY, HUGE, symbol="g", kind="acceleration", metavar="M_S2",
          default=STANDARD_GRAVITY, flags=("-g", "--gravity"), column="g_m_s2",
          help="Gravitational acceleration."),
    Param("mu", "", "friction coefficient", 0.0, math.inf, allow_inf=True, symbol="μ", metavar="MU",
          default=math.inf, column="mu_available",
          help="Friction coefficient available; an orbit needing more has status slips."),
    Param("max_g", "g", "largest load", TINY, math.inf, allow_inf=True, kind="load", metavar="G", default=math.inf,
          column="max_accel_g",
          help="Largest load on the rider, load_g = |contact force| / (m g), what the rider feels (on a "
               "horizontal orbit sqrt(1 + accel_g^2)); an orbit over it has status over_g."),
    Param("omega3", "rad/s", "spin", -HUGE, HUGE, symbol="ω3", kind="rate", metavar="RAD_S",
          help="Sphere: spin about the contact normal; eq. 55 gives up to two orbit rates, one row each "
               "(branch 0 slow, 1 fast)."),
    Param("omega", "rad/s", "orbital rate", -HUGE, HUGE, nonzero=True, symbol="Ω", kind="rate",
          metavar="RAD_S",
          help="Orbital rate Omega. Wheel (> 0): every tilt alpha giving it (eq. 29 solved, one row each). "
               "Sphere: signed about the upward vertical; omega3 follows (eq. 55)."),
    # one word, one point in every command: --speed is the contact's speed along the ground (a speedometer's
    # reading), --com-speed the centre of mass's (docs/contract.md)
    Param("speed", "m/s", "contact speed", TINY, HUGE, symbol="v", kind="speed", metavar="M_S",
          help="The contact's speed along the ground (a speedometer's); a two-wheeler's, its rear contact's. The "
               "contact runs round the parallel of radius r sin theta (rho_contact off the globe), so the lap rate "
               "is Omega = speed / (r sin theta); every tilt alpha giving it, one row each (branch = root number in increasing "
               "alpha). With the contact on the axis (theta 0 or 180) no orbit."),
    Param("com_speed", "m/s", "centre-of-mass speed", TINY, HUGE, symbol="v_cm", kind="speed", metavar="M_S",
          column="v_cm_m_s",
          help="The centre of mass's speed (a wheel's centre speed v_cm) instead of --speed (the contact's). "
               "Every tilt giving it, one row each (docs/machine.md eq. M12)."),
    Param("period", "s", "lap time", TINY, HUGE, symbol="T", kind="time", metavar="S", column="period_s",
          help="Ride and a show's plan: the lap time instead of --speed, Omega = 2 pi / T; every tilt giving "
               "it, one row each (docs/machine.md eq. M12r)."),
    Param("v_top", "m/s", "top speed", 0.0, HUGE, kind="speed", metavar="M_S",
          help="Vertical orbit: speed of the wheel's centre at the top, >= 0."),
    Param("phidot_top", "rad/s", "top rate", 0.0, HUGE, kind="rate", metavar="RAD_S",
          help="Vertical orbit: orbital rate at the top, >= 0."),
    Param("a_over_r", "", "body radius over sphere radius", TINY, HUGE, symbol="a/r"),
    Param("step", "deg", "theta step", 0.001, 10.0, kind="angle", metavar="DEG", default=0.5,
          help="theta step of the boundary data, 0.001..10."),
    Param("points", "", "points per orbit", 2, 1_000_000, integer=True, metavar="N",
          help="Give the orbit point by point at N azimuths phi from the top (0) to 360 deg, 2..1e6."),
    Param("periods", "", "run length in periods", 0.0, 1e6, lo_open=True, metavar="N", default=20.0,
          help="How long: periods of the steady orbit (vertical: laps), > 0."),
    Param("points_per_period", "", "rows per period", 2, 100_000, integer=True, metavar="N", default=100,
          help="Output rows per period, 2..100000."),
    Param("perturb", "deg", "kick", -60.0, 60.0, kind="angle", metavar="DEG", default=0.0,
          help="Kick off the steady orbit, -60..60 deg: the wheel tilted by this about its direction of "
               "travel (a sphere: its contact point moved this far down the meridian)."),
    Param("rtol", "", "relative tolerance", RTOL_MIN, 1e-2, metavar="TOL", default=1e-10,
          help="Relative tolerance of solve_ivp, 2.2e-14..1e-2."),
    Param("atol", "", "absolute tolerance", 1e-16, 1.0, metavar="TOL", default_text="= rtol",
          help="Absolute tolerance per scaled component, 1e-16..1."),
    Param("max_steps", "", "step budget", 1, 1e15, integer=True, metavar="N", default=1_000_000,
          help="Refuse, before it starts, a run estimated to need more integration steps."),
    Param("loop_seconds", "s", "loop length", 0.0, 600.0, lo_open=True, metavar="S", default=10.0,
          help="A .gif or .mp4 3-D view: the most seconds of loop (shown time; the run's last part if it is "
               "longer), > 0 and <= 600; the last frame is then held 1.5 s."),
    Param("playback", "", "playback factor", 1e-6, 1e6, metavar="X", default_text="chosen",
          help="A .gif or .mp4 3-D view: simulated seconds shown per second of loop (1 real time, 0.1 ten "
               "times slower), 1e-6..1e6; by default real time, or the slow motion in which nothing aliases between frames."),
    # the machine of `deathsphere ride` (docs/machine.md): a motorcycle and rider as one gyrostat
    Param("mass", "kg", "machine mass", TINY, HUGE, symbol="m", kind="mass", metavar="KG",
          help="Ride: total mass of machine, rider and wheels."),
    _length("com_height", "centre-of-mass height", "h", lo=0.0,
            help="Ride: height of the centre of mass above the contact along the up-axis (upright on flat "
                 "ground)."),
    _length("tyre_radius", "tyre crown radius", "t", lo=0.0,
            help="Ride: radius of the tyre's round crown (0: a knife-edge wheel); less than the wheel radius."),
    Param("roll_inertia", "kg m^2", "roll inertia", 0.0, HUGE, symbol="I_roll", metavar="KG_M2",
          help="Ride: moment of inertia of the whole machine, wheels locked, about the direction of travel "
               "through its centre of mass."),
    Param("pitch_inertia", "kg m^2", "pitch inertia", 0.0, HUGE, symbol="I_pitch", metavar="KG_M2",
          help="Ride: moment of inertia of the whole machine, wheels locked, about the axle direction "
               "through its centre of mass."),
    Param("yaw_inertia", "kg m^2", "yaw inertia", 0.0, HUGE, symbol="I_yaw", metavar="KG_M2",
          help="Ride: moment of inertia of the whole machine, wheels locked, about the up-axis through its "
               "centre of mass."),
    Param("spin_inertia", "kg m^2", "wheels' spin inertia", 0.0, HUGE, symbol="J", metavar="KG_M2",
          help="Ride: sum of the wheels' polar moments of inertia about their axles."),
    _length("head_height", "head height", "head", lo=0.0,
            help="Ride: height of the top of the rider's head above the contact along the up-axis."),
    _length("width", "machine width", "w", lo=0.0,
            help="Show: the machine's width, handlebar or rider's shoulders, whichever is wider: the diameter "
                 "of the rider's envelope (docs/show.md)."),
    _length("height", "contact height", "z", lo=0.0,
            help="Height of the contact point above the surface's lowest point (the globe's floor: 0 .. the "
                 "diameter) instead of --theta; on a drum, a cone or a profile (--surface) the lane."),
    # the arena every command rides in (docs/surfaces.md; docs/machine.md, "On any surface of revolution")
    Param("surface", "", "arena", 0.0, 0.0, choices=("sphere", "cylinder", "cone", "plane", "profile"),
          metavar="SURFACE", default_text="sphere",
          help="The arena: the globe (sphere), the wall of death's drum (cylinder), a well of death or a banked "
               "track (cone, with --wall-angle), flat ground (plane) or any surface of revolution from its "
               "meridian (profile, with --profile); --diameter its size at the floor."),
    # the two-wheeler of `deathsphere ride --flat/--steer` (docs/two-wheeler.md)
    Param("rear_speed", "m/s", "rear contact speed", 0.0, HUGE, symbol="v_rear", kind="speed", metavar="M_S"),
    Param("steer_torque", "N m", "steer torque", -HUGE, HUGE, symbol="T_δ", metavar="N_M",
          help="Ride, a two-wheeler on the globe: the steer torque the rider holds (0: hands-free); every "
               "steady turn held with it at each --theta/--height, one row each (instead of --speed)."),
    _length("turn_radius", "turn radius", "R_turn",
            help="Simulate, a two-wheeler on flat ground (--flat): start from the steady turn whose rear contact "
                 "runs on a circle of this radius, turning right (without it: upright straight running); orbit, "
                 "sweep, simulate, ride (a two-wheeler's steady turns too) with --surface plane: the contact's "
                 "distance from the turn's centre (a two-wheeler's, its rear contact's)."),
    Param("duration", "s", "run length in seconds", 0.0, 1e6, lo_open=True, metavar="S",
          help="Simulate, a two-wheeler: how long in seconds instead of --periods (straight running on flat "
               "ground has no period: 5 s unless given), > 0."),
    Param("perturb_lean_rate", "deg/s", "lean rate kick", -1000.0, 1000.0, metavar="DEG_S", default=0.0,
          help="Simulate, a two-wheeler: kick the lean rate by this, -1000..1000 deg/s (the dependent speeds "
               "follow from the rolling constraints)."),
    Param("perturb_steer_rate", "deg/s", "steer rate kick", -1000.0, 1000.0, metavar="DEG_S", default=0.0,
          help="Simulate, a two-wheeler with a free steer: kick the steer rate by this, -1000..1000 deg/s (the "
               "dependent speeds follow from the rolling constraints)."),
    # the two-wheeler's body (docs/two-wheeler.md sec. 1): Table 1 of Meijaard et al. (2007) by its names, SI,
    # positions from the rear contact upright, z down; its gravity is the run's g
    Param("w", "m", "wheel base", 0.05, 10.0, symbol="w", kind="length", metavar="M"),
    Param("c", "m", "trail", -2.0, 2.0, symbol="c", kind="length", metavar="M"),
    Param("lam", "rad", "steer axis tilt", -math.pi / 2, math.pi / 2, lo_open=True, hi_open=True, symbol="λ",
          kind="angle", metavar="RAD"),
    Param("rR", "m", "rear wheel radius", 0.01, 3.0, symbol="r_R", kind="length", metavar="M"),
    *_body("R", "rear wheel", ("xx", "yy")),
    _position("xB", "rear frame mass centre x", "x_B"),
    _position("zB", "rear frame mass centre z down", "z_B"),
    *_body("B", "rear frame", ("xx", "yy", "zz", "xz")),
    _position("xH", "front frame mass centre x", "x_H"),
    _position("zH", "front frame mass centre z down", "z_H"),
    *_body("H", "front frame", ("xx", "yy", "zz", "xz")),
    Param("rF", "m", "front wheel radius", 0.01, 3.0, symbol="r_F", kind="length", metavar="M"),
    *_body("F", "front wheel", ("xx", "yy")),
    Param("jobs", "", "processes", 1, 256, integer=True, metavar="N", default=1,
          help="Processes working in parallel; the output is the same as with one."),
    Param("chunk_size", "", "orbits evaluated per chunk", 1, 10_000_000, integer=True, metavar="N",
          default=16384, help="Orbits evaluated per chunk; memory stays flat whatever the grid size."),
)}

#: The defaults that several modules use by name.
CHUNK = int(PARAMS["chunk_size"].default)


def markdown_table() -> str:
    """The registry as the Markdown table of docs/contract.md, "Inputs"
    (a test keeps the doc equal to it): each parameter's option, unit and
    the suffixes it takes, allowed values, default and meaning."""
    from deathsphere.units import COMMON

    lines = ["| parameter | option | unit (suffixes) | allowed | default | meaning |",
             "|---|---|---|---|---|---|"]
    for p in PARAMS.values():
        unit = p.unit or "–"
        others = [u for u in COMMON.get(p.kind, ()) if u != p.unit]
        if others:
            unit += " (" + ", ".join(others) + ")"
        flags = ", ".join(f"`{f}`" for f in p.cli_flags) if p.help else "–"
        default = p.shown_default or "–"
        lines.append(f"| `{p.name}` | {flags} | {unit} | {p.allowed()} | {default} | {p.help or p.what} |")
    return "\n".join(lines) + "\n"


def shown_number(value) -> str:
    """A number as the user wrote it, to the last digit: the shortest text
    that reads back as the same float (``180.00000000000003``, ``200``,
    ``1e-10``), never rounded, so a message about a value just outside an
    interval shows why."""
    if isinstance(value, float):
        text = repr(value)
        return text[:-2] if text.endswith(".0") else text
    return repr(value)


def _words(p: Param, value) -> str:
    return f"{p.label()} must be {p.allowed()} (got {shown_number(value)})"


def problems(name: str, values) -> np.ndarray:
    """Why each of ``values`` is not an allowed ``name`` ('' where it is).

    Vectorised: masks decide which values fail, words are built only for
    those.  NaN counts as missing and is the caller's business (a batch
    fills defaults first), so it is refused here too: 'not a number'.
    """
    p = PARAMS[name]
    v = np.asarray(values, dtype=float).reshape(-1)
    out = np.full(v.size, "", dtype=object)
    for i in np.flatnonzero(failing(name, v)):
        out[i] = (f"{p.label()} must be a finite number ({p.allowed()})" if not np.isfinite(v[i])
                  and not (p.allow_inf and v[i] > 0) else _words(p, float(v[i])))
    return out


def failing(name: str, values) -> np.ndarray:
    """Which of ``values`` are not an allowed ``name``: the test of
    :func:`problems` without its words (a batch needs words only for the
    few that fail)."""
    p = PARAMS[name]
    v = np.asarray(values, dtype=float).reshape(-1)
    with np.errstate(invalid="ignore"):
        bad = np.isnan(v) | (np.isinf(v) & ~(p.allow_inf & (v > 0)))
        inside = (v > p.lo if p.lo_open else v >= p.lo) & (v < p.hi if p.hi_open else v <= p.hi)
        bad |= ~inside
        if p.nonzero:
            bad |= v == 0
        if p.integer:
            bad |= np.isfinite(v) & (v != np.round(v))
    return bad


def first_problem(name: str, values) -> str:
    """The first reason among ``values`` ('' if all are allowed)."""
    reasons = problems(name, values)
    hit = np.flatnonzero(reasons != "")
    return str(reasons[hit[0]]) if hit.size else ""


def reduce_angle(deg):
    """An angle in degrees reduced to (-180, 180]: the physics is periodic in
    alpha, and the tilt may be given either way round (205 = -155)."""
    x = np.asarray(deg, dtype=float)
    r = 180.0 - np.mod(180.0 - x, 360.0)
    return r if r.ndim else float(r)


def choice(name: str, value: str, allowed) -> str:
    """``value`` lower-cased if it is one of ``allowed``; else ParameterError."""
    text = str(value).strip().lower()
    if text not in allowed:
        raise ParameterError(f"{name} must be one of {' | '.join(allowed)} (got {value!r})", name)
    return text
