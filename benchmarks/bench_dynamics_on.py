"""The wheel on the drum and on the cones at 80 and 100 degrees, 3 laps
along the integrator from a steady orbit with its spin raised by 1e-3:
the largest energy drift relative to the kinetic energy, the largest gap
to the surface [m] and the wall time (physics/dynamics_on.py).

    python benchmarks/bench_dynamics_on.py
"""

import time

import numpy as np

from deathsphere.physics import dynamics_on as don
from deathsphere.physics.ground import Cone, Cylinder
from deathsphere.simulation.integrator import integrate

A, K, G = 0.3, 0.5, 9.81

for ground in (Cylinder(5.0), Cone(5.0, np.radians(80)), Cone(5.0, np.radians(100))):
    X0, om = don.wheel_orbit_state_on(ground, 2.0, np.radians(20), A, K, G)
    X0 = X0.copy()
    X0[6:9] *= 1.0 + 1e-3
    p = don.ground_body(ground, A, K, G)
    T = 3 * 2 * np.pi / om
    t0 = time.perf_counter()
    sol = integrate(don.ode_on(p), (0.0, T), X0.reshape(-1), (), method="DOP853", rtol=1e-12, atol=1e-13,
                    t_eval=np.linspace(0.0, T, 200)).sol
    wall = time.perf_counter() - t0
    E = don.energy_on(sol.y, p)
    v = A * np.cross(don.contact_on(sol.y, p)[0], sol.y[6:9], axis=0)
    kinetic = 0.5 * np.sum(v * v, axis=0) + 0.5 * K * A ** 2 * np.sum(sol.y[6:9] ** 2, axis=0)
    print(f"{ground.name:8s} wall angle {np.degrees(ground.wall_angle(2.0)):6.1f} deg  Omega {om:.4f} rad/s  "
          f"energy drift/KE {np.max(np.abs(E - E[0])) / np.min(kinetic):.2e}  "
          f"gap {np.max(np.abs(don.gap_on(sol.y, p))):.2e} m  {wall:.1f} s")
