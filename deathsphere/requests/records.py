"""The request records: frozen, one concept each.  A value is a number, or
an array of them for a grid of requests (ride's axes broadcast); its unit
and bounds are the registry's (:data:`deathsphere.params.PARAMS`) and were
checked by the decoder that built the record."""

from __future__ import annotations

import math
from dataclasses import dataclass

from deathsphere.constants import STANDARD_GRAVITY, TABLE1_WHEEL_RADIUS
from deathsphere.physics.ground import Sphere
from deathsphere.records.machine import Machine
from deathsphere.records.paper_bodies import WHEEL, PaperBodyKind


@dataclass(frozen=True)
class Theta:
    """Where a horizontal lane runs: the contact's polar angle from the
    upward vertical [deg] (registry ``theta``)."""

    theta: object


@dataclass(frozen=True)
class Height:
    """Where a horizontal lane runs: the contact's height above the globe's
    floor [m] (registry ``height``), within the globe."""

    height: object


@dataclass(frozen=True)
class Tilt:
    """How a horizontal lane is held: the machine's tilt alpha [deg]."""

    alpha: object


@dataclass(frozen=True)
class ContactSpeed:
    """How a horizontal lane is held: the contact's speed along the ground
    [m/s] (what a speedometer reads; registry ``speed``).  On a steady
    orbit the contact runs round its parallel, so it fixes the rate
    Omega = v / (r sin(theta)) (every tilt giving that rate)."""

    speed: object
    #: which of the tilts giving it a run starts on (0: the first in
    #: increasing alpha); ride lists them all
    branch: int = 0


@dataclass(frozen=True)
class ComSpeed:
    """How a horizontal lane is held: the centre of mass's speed [m/s]
    (registry ``com_speed``; every tilt giving it)."""

    speed: object
    #: which of the tilts giving it a run starts on (0: the first in
    #: increasing alpha); ride lists them all
    branch: int = 0


#: The centre speed under the name the paper's bodies' requests use (orbit,
#: sweep and simulate's ``speed`` is still the wheel's centre speed).
Speed = ComSpeed


@dataclass(frozen=True)
class Period:
    """How a horizontal lane is held: its lap time T [s] (registry
    ``period``), the rate Omega = 2 pi / T (every tilt giving it)."""

    period: object
    branch: int = 0


@dataclass(frozen=True)
class SameLap:
    """How a show's horizontal lane is held: the lap time of the rider
    ``name`` of the same plan (resolved when that rider's lane is built)."""

    name: str


@dataclass(frozen=True)
class Rate:
    """How a horizontal lane is held: the orbital rate Omega [rad/s] (a
    wheel: the tilt ``branch`` giving it; a sphere: its root ``branch``)."""

    omega: object
    branch: int = 0


@dataclass(frozen=True)
class Spin:
    """How a sphere's horizontal lane is held: its spin omega3 [rad/s]
    about the radius to the contact, the orbit's root ``branch``."""

    omega3: object
    branch: int = 0


@dataclass(frozen=True)
class PaperBody:
    """One of the paper's bodies: ``kind`` its record (the wheel or the
    ball, :mod:`deathsphere.records.paper_bodies`) of radius ``a`` [m] and
    inertia factor ``k`` (None: the body's own), rolling on the
    ``"inside"`` or ``"outside"`` of the globe (the run's ground)."""

    kind: PaperBodyKind = WHEEL
    side: str = "inside"
    a: float = TABLE1_WHEEL_RADIUS
    k: float | None = None


@dataclass(frozen=True)
class Horizontal:
    """A steady horizontal orbit: where (by theta or height) and how (by
    tilt, the contact's or the centre of mass's speed, the lap time, the
    lap of another rider, the rate or the spin)."""

    at: Theta | Height
    by: Tilt | ContactSpeed | ComSpeed | Period | SameLap | Rate | Spin

    kind = "horizontal"


@dataclass(frozen=True)
class Vertical:
    """A vertical loop: the centre of mass's speed at the top [m/s], the
    loop's plane's azimuth [deg] and its cone angle theta [deg] (90: a great
    circle, as a show's loopers ride)."""

    v_top: object
    azimuth: float = 0.0
    theta: object = 90.0

    kind = "vertical"


@dataclass(frozen=True)
class RiderRequest:
    """One rider's request: its body (a machine record, or one of the
    paper's bodies to simulate), its lane, its direction (+1 ccw, -1 cw
    seen from above), its phase at t = 0 [deg] (a horizontal lane's azimuth
    of the contact, a loop's angle from the top), a kick (a start's
    perturbation, None: none) and its name (a show's)."""

    body: Machine | PaperBody
    lane: Horizontal | Vertical
    direction: int = 1
    phase: float = 0.0
    kick: object = None
    name: str = ""


@dataclass(frozen=True)
class Solver:
    """The integrator's options: scipy's method and its tolerances (atol
    None: = rtol)."""

    method: str = "DOP853"
    rtol: float = 1e-10
    atol: float | None = None


@dataclass(frozen=True)
class Run:
    """What every rider of a request shares: the ground (the globe), gravity
    [m/s^2], the limits (friction available mu, the largest load max_g [g];
    inf: no limit), the solver and the run's length (a duration [s] or a
    number of periods; None: the command's own)."""

    ground: Sphere
    g: object = STANDARD_GRAVITY
    mu: object = math.inf
    max_g: object = math.inf
    solver: Solver | None = None
    duration: float | None = None
    periods: float | None = None

    @property
    def r(self):
        """The globe's radius [m]."""
        return self.ground.radius
