"""The motorcycle presets of the two-wheeler: a vehicle's published totals
(mass, centre of mass and inertia of motorcycle and rider together) and
its front assembly converted to the benchmark's parameters (Table 1's but gravity, the run's) (beyond the
paper; docs/two-wheeler.md sec. 1.1-1.3).

The Whipple model's rear frame B is what remains of the whole once the
front assembly is taken out (parallel-axis theorem); the wheels' masses
stay in the frames that carry them (mR = mF = 0), their spin inertias are
IRyy and IFyy, which is exact in the Whipple model (sec. 1.1).  Each preset
is the keyword arguments of a :class:`~deathsphere.records.two_wheeler.TwoWheeler`
but its name.
"""

from __future__ import annotations

import math

import numpy as np

from deathsphere.errors import ParameterError
from deathsphere.records.machine_presets import stunt125
from deathsphere.records.two_wheeler import TwoWheeler, benchmark_two_wheeler

__all__ = ["COSSALTER_TABLE_7_2", "inertia_tensor", "front_assembly", "whipple_parameters", "sport_tourer",
           "stunt125_steer", "PRESETS", "TWO_WHEELERS", "as_two_wheeler"]

#: V. Cossalter, Motorcycle Dynamics, 2nd ed. (2006), Table 7.2 p. 260, the
#: sport touring motorcycle with its rider, SI (caster in degrees): the
#: numbers this conversion uses, as printed (docs/two-wheeler.md sec. 1.2).
COSSALTER_TABLE_7_2 = {
    "wheelbase": 1.448, "caster_deg": 26.80, "normal_trail": 0.105,
    "vehicle_mass": 195.0,                              # without rider
    "mass": 270.0, "b": 0.688, "h": 0.640,              # with rider: CoM ahead of the rear contact, height
    "Ixx": 35.5, "Ixz": -1.7, "Izz": 59.3,              # with rider, about its CoM
    "front_mass": 34.0, "e_f": 0.025, "h_f": 0.600,     # front assembly: CoM ahead of the steer axis, height
    "front_steer_inertia": 0.83,                        # front assembly about the steer axis
    "front_spin_inertia": 0.600, "rear_spin_inertia": 0.800,
    "front_radius": 0.294, "rear_radius": 0.299,
}

#: Estimate: the rms lateral spread of a motorcycle's and rider's mass [m];
#: a body thin across would have I_yy = I_xx + I_zz, this one I_xx + I_zz -
#: 2 m s^2 (s = 0.12 m is what stunt125's moments 25 + 20 - 40 kg m^2 imply).
LATERAL_SPREAD = 0.12
#: Estimate: the front assembly's radius of gyration about axes through its
#: mass centre across the steer axis [m] (its mass is mostly at the two ends,
#: the front axle and the handlebar, some 0.35 m below and above it).
FRONT_GYRATION = 0.35
#: Estimate: the top of the sport tourer's rider's head (x, z) [m] from the
#: rear contact, z down: 0.55 m above and 0.2 m ahead of the rider's mass
#: centre that Table 7.2 implies (0.60 m, 1.05 m high; the rider leans forward).
SPORT_TOURER_HEAD = (0.80, -1.60)


def inertia_tensor(ixx, iyy, izz, ixz) -> np.ndarray:
    """The inertia tensor in the benchmark's axes (x forward, z down) from
    its entries; the plane of symmetry makes the xy and yz entries zero."""
    return np.array([[ixx, 0.0, ixz], [0.0, iyy, 0.0], [ixz, 0.0, izz]], dtype=float)


def _parallel_axis(mass: float, offset) -> np.ndarray:
    """What the parallel-axis theorem adds to a tensor moved by ``offset``
    from the mass centre: m (|d|^2 E - d d^T)."""
    d = np.asarray(offset, dtype=float)
    return mass * (d @ d * np.eye(3) - np.outer(d, d))


def front_assembly(*, mass, ahead, height, steer_inertia, across_inertia, w, c, lam):
    """The front assembly's mass centre (x, z) and its inertia tensor about
    it, in the benchmark's axes, from its mass, its mass centre's distance
    ``ahead`` of the steer axis (perpendicular to it) and ``height`` above
    the ground, its moment ``steer_inertia`` about the steer axis and
    ``across_inertia`` about every axis through its mass centre across the
    steer axis (the steer axis a principal axis: an estimate)."""
    x = w + c - height * math.tan(lam) + ahead / math.cos(lam)
    s = np.array([math.sin(lam), 0.0, math.cos(lam)])      # the steer axis, pointing down
    central = steer_inertia - mass * ahead**2               # about the parallel axis through the mass centre
    tensor = central * np.outer(s, s) + across_inertia * (np.eye(3) - np.outer(s, s))
    return x, -height, tensor


def whipple_parameters(*, mass, x, z, inertia, front, w, c, lam, rR, rF, IRyy, IFyy) -> dict:
    """The benchmark's parameters (Table 1's but gravity, the run's) of a vehicle with its rider from its
    totals, wheels locked (``mass``, mass centre (``x``, ``z``) from the
    rear contact, ``inertia`` the 3 x 3 tensor about it, benchmark axes)
    and its front assembly ``front`` = (mass, x, z, tensor about its mass
    centre, the front wheel included): the rear frame B is the rest; the
    wheels' masses and diametral moments stay in their frames (mR = mF =
    IRxx = IFxx = 0), their spin inertias are IRyy and IFyy
    (docs/two-wheeler.md sec. 1.1)."""
    m_f, x_f, z_f, i_f = front
    m_b = mass - m_f
    x_b, z_b = (mass * x - m_f * x_f) / m_b, (mass * z - m_f * z_f) / m_b
    # the whole about its mass centre, less the front assembly and the wheels' spin, moved to B's mass centre
    rest = (np.asarray(inertia, dtype=float) - i_f - _parallel_axis(m_f, (x_f - x, 0.0, z_f - z))
            - inertia_tensor(0.0, IRyy + IFyy, 0.0, 0.0))
    i_b = rest - _parallel_axis(m_b, (x_b - x, 0.0, z_b - z))
    return dict(w=w, c=c, lam=lam, rR=rR, mR=0.0, IRxx=0.0, IRyy=IRyy,
                xB=x_b, zB=z_b, mB=m_b, IBxx=i_b[0, 0], IByy=i_b[1, 1], IBzz=i_b[2, 2], IBxz=i_b[0, 2],
                xH=x_f, zH=z_f, mH=m_f, IHxx=i_f[0, 0], IHyy=i_f[1, 1], IHzz=i_f[2, 2], IHxz=i_f[0, 2],
                rF=rF, mF=0.0, IFxx=0.0, IFyy=IFyy)


def sport_tourer() -> dict:
    """The sport touring motorcycle with rider of Cossalter (2006) Table 7.2
    in the benchmark's parameters (docs/two-wheeler.md sec. 1.2): the trail
    c = a_n / cos(caster), the steer axis tilt the caster angle, Ixz the
    tensor's entry as printed; the pitch moments, the front assembly's
    moments across the steer axis and the head point are estimates."""
    t = COSSALTER_TABLE_7_2
    lam = math.radians(t["caster_deg"])
    w, c = t["wheelbase"], t["normal_trail"] / math.cos(lam)
    m = t["mass"]
    iyy = t["Ixx"] + t["Izz"] - 2 * m * LATERAL_SPREAD**2
    front = front_assembly(mass=t["front_mass"], ahead=t["e_f"], height=t["h_f"],
                           steer_inertia=t["front_steer_inertia"],
                           across_inertia=t["front_mass"] * FRONT_GYRATION**2, w=w, c=c, lam=lam)
    whole = inertia_tensor(t["Ixx"], iyy, t["Izz"], t["Ixz"])
    values = whipple_parameters(mass=m, x=t["b"], z=-t["h"], inertia=whole, front=(t["front_mass"], *front),
                                w=w, c=c, lam=lam, rR=t["rear_radius"],
                                rF=t["front_radius"], IRyy=t["rear_spin_inertia"], IFyy=t["front_spin_inertia"])
    return values | dict(
        head=SPORT_TOURER_HEAD,
        source="Cossalter (2006) Motorcycle Dynamics 2nd ed. Table 7.2 p. 260 (sport touring motorcycle with rider) "
               "converted; pitch moments; front inertia off the steer axis and head point estimates "
               "(docs/two-wheeler.md sec. 1.2)")


#: A published 125 cc machine's steering geometry (docs/two-wheeler.md
#: sec. 1.3): the Honda CBR125R's road test, "25 degrees of rake, 3.4
#: inches of trail and a 51-inch wheelbase" (wheel base [m], steer axis
#: tilt [deg], trail [m], exact from the inches); the share of the weight on
#: the front wheel is an estimate.
STUNT_GEOMETRY = {"wheelbase": 51 * 0.0254, "steer_axis_tilt_deg": 25.0, "trail": 3.4 * 0.0254, "front_share": 0.45}
#: Tyres 70/100-19 (front) and 90/100-16 (rear): rim radius + section
#: height (width x aspect ratio 100 %) [m], and the section widths [m].
STUNT_TYRES = {"front_radius": 19 * 0.0254 / 2 + 0.070, "rear_radius": 16 * 0.0254 / 2 + 0.090,
               "front_width": 0.070, "rear_width": 0.090}
#: The motorcycle's mass without its rider [kg] (stunt125's source: 90 kg
#: bike + 75 kg rider).
STUNT_BIKE_MASS = 90.0


def stunt125_steer() -> dict:
    """A light 125 cc stunt motorcycle with rider as the Whipple model, with
    stunt125's total mass, centre-of-mass height, inertia and spin inertia
    (docs/two-wheeler.md sec. 1.3): its front assembly is the sport
    tourer's scaled (mass by the motorcycles' masses, lengths by the front
    wheels' radii), the rear frame the rest; the steering geometry a
    published 125 cc machine's."""
    one = stunt125()
    geo, tyres, t = STUNT_GEOMETRY, STUNT_TYRES, COSSALTER_TABLE_7_2
    w, c, lam = geo["wheelbase"], geo["trail"], math.radians(geo["steer_axis_tilt_deg"])
    r_f, r_r = tyres["front_radius"], tyres["rear_radius"]
    mass_scale = STUNT_BIKE_MASS / t["vehicle_mass"]
    length_scale = r_f / t["front_radius"]
    m_f = t["front_mass"] * mass_scale
    front = front_assembly(mass=m_f, ahead=t["e_f"] * length_scale, height=t["h_f"] * length_scale,
                           steer_inertia=t["front_steer_inertia"] * mass_scale * length_scale**2,
                           across_inertia=m_f * (FRONT_GYRATION * length_scale)**2, w=w, c=c, lam=lam)
    # the spin inertia split as the tyres' section width x radius^2 (tyre and rim carry most of it)
    front_part = tyres["front_width"] * r_f**2 / (tyres["front_width"] * r_f**2 + tyres["rear_width"] * r_r**2)
    x = geo["front_share"] * w
    values = whipple_parameters(mass=one.mass, x=x, z=-one.h, inertia=np.diag(one.inertia), front=(m_f, *front),
                                w=w, c=c, lam=lam, rR=r_r, rF=r_f, IRyy=one.spin_inertia * (1 - front_part),
                                IFyy=one.spin_inertia * front_part)
    return values | dict(
        head=(x, -one.head),
        source="stunt125's totals (estimates) as the Whipple model: front assembly scaled from sport-tourer; wheel "
               "base 51 in; rake 25 deg; trail 3.4 in from a Honda CBR125R road test; 45 % front weight an estimate "
               "(docs/two-wheeler.md sec. 1.3)")


#: The presets' names and builders, in the order ``deathsphere machines``
#: lists them (the names known without building them: ``--machine``'s choices).
PRESETS = {"sport-tourer": sport_tourer, "stunt125-steer": stunt125_steer}
#: Every two-wheeler preset's name, known without building one: the
#: benchmark bicycle's (its single-contact model is ``benchmark-bicycle-rigid``), then the motorcycles'.
NAMES = ("benchmark-bicycle", *PRESETS)


#: The two-wheeler presets, by name (``--machine`` with ``--flat`` or
#: ``--steer``; docs/two-wheeler.md sec. 1): the benchmark bicycle, then the
#: motorcycles above.
TWO_WHEELERS = {t.name: t for t in (benchmark_two_wheeler(),
                                    *(TwoWheeler(**build(), name=name) for name, build in PRESETS.items()))}


def as_two_wheeler(machine) -> TwoWheeler:
    """A :class:`TwoWheeler` from one or a preset's name; else one line saying which are."""
    if isinstance(machine, TwoWheeler):
        return machine
    name = getattr(machine, "name", machine)
    if isinstance(machine, str) and machine.strip().lower() in TWO_WHEELERS:
        return TWO_WHEELERS[machine.strip().lower()]
    raise ParameterError(f"flat and steer need a two-wheeler ({' | '.join(TWO_WHEELERS)} or a "
                         f"deathsphere.TwoWheeler); {name!r} is a single-contact machine", "machine")
