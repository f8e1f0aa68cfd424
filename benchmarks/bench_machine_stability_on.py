"""The single-contact machine's stability on any ground against the globe's
own equations: lanes analysed per second (docs/machine.md, "On any ground").

    PYTHONPATH=. python3 benchmarks/bench_machine_stability_on.py [--n 4096] [--repeat 3]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from deathsphere.physics import machine_dynamics as md
from deathsphere.physics import machine_dynamics_on as mo
from deathsphere.physics.ground import Cylinder, Sphere
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.records.machine_presets import PRESETS


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=4096)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    p = machine_arrays(PRESETS["stunt125"])
    rng = np.random.default_rng(0)
    n = args.n
    globe, drum = Sphere(2.4384), Cylinder(4.8768)
    theta, alpha = np.radians(rng.uniform(95, 130, n)), np.radians(rng.uniform(10, 40, n))
    heights, tilts = rng.uniform(0.5, 3.0, n), np.radians(rng.uniform(5, 30, n))
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        md.machine_stability(theta, alpha, globe, 9.81, p)
        t1 = time.perf_counter()
        mo.machine_stability_on(globe.height(theta), alpha, globe, 9.81, p)
        t2 = time.perf_counter()
        mo.machine_stability_on(heights, tilts, drum, 9.81, p)
        t3 = time.perf_counter()
        print(f"globe's own {n / (t1 - t0):8.0f} lanes/s   general on the globe {n / (t2 - t1):8.0f} lanes/s   "
              f"drum {n / (t3 - t2):8.0f} lanes/s")


if __name__ == "__main__":
    main()
