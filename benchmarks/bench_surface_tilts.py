"""The paper's wheel given its rate on each arena, in one run: requests per
second of physics.revolution_tilt.wheel_tilts (every tilt of eq. S2 in the
fit window of S4, each checked by the forward model) on the drum, the cone,
a profile sampled from that cone and the globe, and for scale the globe's
own solve (physics.region.solve_alpha) on the same lanes (docs/surfaces.md,
"S2 inverted").

    PYTHONPATH=. python3 benchmarks/bench_surface_tilts.py [--n 100000] [--repeat 5]
"""

import argparse

import numpy as np

from deathsphere.physics.ground import Cone, Cylinder, Profile, Sphere
from deathsphere.physics.region import solve_alpha
from deathsphere.physics.revolution_tilt import wheel_tilts
from timing import best_of


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=100_000, help="requests per call")
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    rng = np.random.default_rng(1)
    height, omega = rng.uniform(0.1, 5.9, args.n), rng.uniform(1.0, 8.0, args.n)
    cone = Cone(3.0, np.radians(80.0), 8.0)
    rho, z = cone.contact(np.linspace(0.0, 8.0, 101))
    profile = Profile(rho, z)
    globe = Sphere(3.0)
    theta = globe.theta(height)

    def forget():
        profile._last = None      # every call finds its lanes afresh, as a new request would

    g = 9.80665
    times = {
        "drum": best_of(lambda: wheel_tilts(Cylinder(3.0, 8.0), height, 0.3, 0.5, g, omega=omega), args.repeat),
        "cone 80 deg": best_of(lambda: wheel_tilts(cone, height, 0.3, 0.5, g, omega=omega), args.repeat),
        "profile (the cone, 101 samples)": best_of(lambda: wheel_tilts(profile, height, 0.3, 0.5, g, omega=omega),
                                                   args.repeat, forget),
        "globe (general path)": best_of(lambda: wheel_tilts(globe, height, 0.3, 0.5, g, omega=omega), args.repeat),
        "globe (region.solve_alpha)": best_of(lambda: solve_alpha(theta, 0.3, 3.0, 0.5, g, omega=omega),
                                              args.repeat),
    }
    base = times["cone 80 deg"]
    print(f"{'arena':34s} {'M requests/s':>13s} {'time / cone':>12s}")
    for name, t in times.items():
        print(f"{name:34s} {args.n / t / 1e6:13.3f} {t / base:12.2f}")


if __name__ == "__main__":
    main()
