"""The machine's steady orbits on the globe by the sphere's equations
(physics.machine.ride_orbit, M1-M11) and by the equations on any surface
of revolution (physics.machine_surface.ride_orbit_on, MS1-MS7) over the
same 10^6-orbit grid, in one run: orbits per second of each and the ratio
of their times (docs/machine.md, "On any surface of revolution").

    PYTHONPATH=. python3 benchmarks/bench_machine_surface.py [--n 1000] [--repeat 5]
"""

import argparse

import numpy as np

from deathsphere.physics.ground import Sphere
from deathsphere.physics.machine import ride_orbit
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.physics.machine_surface import ride_orbit_on
from deathsphere.records.machine_presets import PRESETS
from timing import best_of

CHUNK = 1 << 14       # as api.rides evaluates them



def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1000, help="grid side: n x n orbits")
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    m, globe, g = machine_arrays(PRESETS["stunt125"]), Sphere(8 * 0.3048), 9.80665
    theta, alpha = np.meshgrid(np.radians(np.linspace(5, 175, args.n)), np.radians(np.linspace(-80, 80, args.n)),
                               indexing="ij")
    theta, alpha = theta.ravel(), alpha.ravel()
    height = globe.height(theta)
    theta = globe.theta(height)           # the same lanes for both
    spans = [slice(i, i + CHUNK) for i in range(0, theta.size, CHUNK)]
    sphere = best_of(lambda: [ride_orbit(theta[s], alpha[s], globe, g, m) for s in spans], args.repeat)
    general = best_of(lambda: [ride_orbit_on(height[s], alpha[s], globe, g, m) for s in spans], args.repeat)
    n = theta.size
    print(f"{n} orbits: sphere's equations {n / sphere / 1e6:.2f} M/s, any surface's {n / general / 1e6:.2f} M/s, "
          f"time ratio any/sphere {general / sphere:.2f}")


if __name__ == "__main__":
    main()
