"""The machine's physics called with its numbers one by one, as the tests
write them (r, g, mass, h, a, t, I_pitch, I_yaw, J, head): each helper
builds the sphere and the machine's arrays and calls the physics."""

from typing import NamedTuple

import numpy as np

from deathsphere.physics import machine_dynamics, machine_motion
from deathsphere.physics.ground import Sphere
from deathsphere.physics.machine import ride_orbit, solve_alpha_for_speed, vertical_loop
from deathsphere.physics.machine_arrays import MachineArrays


def arrays(mass, h, a, t, pitch=0.0, yaw=0.0, spin=0.0, head=None, roll=0.0) -> MachineArrays:
    return MachineArrays(*(np.asarray(x, dtype=float) for x in
                           (mass, h, a, t, roll, pitch, yaw, spin, h if head is None else head)))


def orbit(theta, alpha, r, g, mass, h, a, t, inertia_pitch, inertia_yaw, spin_inertia, head, mu=np.inf,
          max_g=np.inf):
    return ride_orbit(theta, alpha, Sphere(np.asarray(r, dtype=float)), g,
                      arrays(mass, h, a, t, inertia_pitch, inertia_yaw, spin_inertia, head), mu, max_g)


def tilts(theta, speed, r, g, mass, h, a, t, inertia_pitch, inertia_yaw, spin_inertia):
    return solve_alpha_for_speed(theta, speed, Sphere(np.asarray(r, dtype=float)), g,
                                 arrays(mass, h, a, t, inertia_pitch, inertia_yaw, spin_inertia))


def loop(theta, v_top, r, g, mass, h, a, t, inertia_pitch, spin_inertia, head, mu=np.inf, max_g=np.inf):
    return vertical_loop(theta, v_top, Sphere(np.asarray(r, dtype=float)), g,
                         arrays(mass, h, a, t, inertia_pitch, 0.0, spin_inertia, head), mu, max_g)


def keywords(mass, h, a, t, inertia_pitch, inertia_yaw, spin_inertia, head=None):
    """The keywords of :func:`orbit` as a dict (the tests' machine dicts)."""
    return dict(mass=mass, h=h, a=a, t=t, inertia_pitch=inertia_pitch, inertia_yaw=inertia_yaw,
                spin_inertia=spin_inertia, head=head)


class Params(NamedTuple):
    """(a, t, r, h, g, mass, I_roll, I_pitch, I_yaw, J), the order the tests
    write a machine in its globe; :meth:`run` the physics' arguments."""

    a: object
    t: object
    r: object
    h: object
    g: object
    mass: object
    roll: object
    pitch: object
    yaw: object
    spin: object

    def run(self):
        """(ground, g, machine arrays) of the equations of motion."""
        machine = MachineArrays(*(np.asarray(x, dtype=float) for x in
                                  (self.mass, self.h, self.a, self.t, self.roll, self.pitch, self.yaw, self.spin,
                                   self.h)))
        return Sphere(np.asarray(self.r, dtype=float)), np.asarray(self.g, dtype=float), machine


def rhs(state, p: Params, frame_rate=0.0, forces=False):
    return machine_dynamics.machine_rhs(state, *p.run(), frame_rate, forces)


def orbit_state(theta, alpha, p: Params):
    return machine_dynamics.machine_orbit_state(theta, alpha, *p.run())


def stability(theta, alpha, p: Params):
    return machine_dynamics.machine_stability(theta, alpha, *p.run())


def jacobian(theta, alpha, p: Params):
    return machine_dynamics.machine_jacobian(theta, alpha, *p.run())


def start(theta, alpha, d_alpha, p: Params):
    return machine_motion.machine_start(theta, alpha, d_alpha, *p.run())


def energy(state, p: Params):
    ground, g, machine = p.run()
    return machine_motion.machine_energy(state, g, machine)


def residuals(state, p: Params):
    ground, _, machine = p.run()
    return machine_motion.machine_residuals(state, ground, machine)


def project(state, p: Params):
    ground, _, machine = p.run()
    return machine_motion.machine_project(state, ground, machine)
