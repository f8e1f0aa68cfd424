"""The allowed tilts on lanes off the globe against the globe's own region
code: lanes (thetas) per second, best of five, in one run.

    PYTHONPATH=. python3 benchmarks/bench_lane_limits.py
"""

import math
import time

import numpy as np

from deathsphere.physics import lane_region, region
from deathsphere.physics.ground import Cone, Cylinder, Sphere

N = 20_000
G0 = 9.80665


def best(fn, repeat=5):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    theta = np.linspace(0.2, 3.0, N)
    globe = Sphere(3.0)
    heights = globe.height(theta)
    cases = {
        "globe (region.allowed_alpha)": lambda: region.allowed_alpha(theta, 0.3, 3.0, 0.5, G0, False, 1.0, 5.0),
        "globe through the lanes": lambda: lane_region.allowed_alpha_on(globe, heights, 0.3, 0.5, G0, False, 1.0, 5.0),
        "drum": lambda: lane_region.allowed_alpha_on(Cylinder(4.8768, 6.0), np.linspace(0, 6, N), 0.3, 0.5, G0,
                                                     False, 1.0, 5.0),
        "cone, 80 degrees": lambda: lane_region.allowed_alpha_on(Cone(3.0, math.radians(80), 8.0),
                                                                 np.linspace(0, 8, N), 0.3, 0.5, G0, False, 1.0, 5.0),
    }
    print(f"{N} lanes, mu = 1, max_g = 5; best of five")
    for name, fn in cases.items():
        t = best(fn)
        print(f"{name:32s} {N / t / 1e3:8.1f} k lanes/s")
    t = best(lambda: lane_region.lane_range(Cone(3.0, math.radians(80), 8.0), 0.3, 0.5, G0, False, 1.0, 5.0), 3)
    print(f"{'lane_range on that cone':32s} {t:8.3f} s")


if __name__ == "__main__":
    main()
