"""The paper's wheel in steady orbits on each arena, in one run: orbits per
second of physics.revolution.wheel_orbit on the drum, the cone, a profile
sampled from that cone (its spline found by height at every lane) and, for
scale, the globe's own path (physics.wheel.horizontal_orbit), with each
time's ratio to the cone's (docs/surfaces.md, "Performance").  A profile
with a neck (rho = 2 - 0.9 sin(0.9 z), 121 samples) shows the rim's global
check at work: its lanes the tangent ball does not hold are sampled
(docs/surfaces.md eq. S4g).

    PYTHONPATH=. python3 benchmarks/bench_surfaces.py [--n 200000] [--repeat 5]
"""

import argparse

import numpy as np

from deathsphere.physics.ground import Cone, Cylinder, Profile
from deathsphere.physics.revolution import wheel_orbit
from deathsphere.physics.wheel import horizontal_orbit
from timing import best_of



def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=200_000, help="orbits per call")
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    rng = np.random.default_rng(1)
    height, alpha = rng.uniform(0.1, 7.9, args.n), np.radians(rng.uniform(5.0, 60.0, args.n))
    cone = Cone(3.0, np.radians(80.0), 8.0)
    rho, z = cone.contact(np.linspace(0.0, 8.0, 101))
    profile = Profile(rho, z)
    zz = np.linspace(0.0, 6.0, 121)
    neck = Profile(2.0 - 0.9 * np.sin(0.9 * zz), zz)
    neck_height = height * (6.0 / 8.0)

    def forget():
        profile._last = None      # every call finds its lanes afresh, as a new request would
        neck._last = None

    times = {
        "drum": best_of(lambda: wheel_orbit(Cylinder(3.0, 8.0), height, alpha, 0.3, 0.5, 9.80665), args.repeat),
        "cone 80 deg": best_of(lambda: wheel_orbit(cone, height, alpha, 0.3, 0.5, 9.80665), args.repeat),
        "profile (the cone, 101 samples)": best_of(lambda: wheel_orbit(profile, height, alpha, 0.3, 0.5, 9.80665),
                                                   args.repeat, forget),
        "profile with a neck (121 samples)": best_of(lambda: wheel_orbit(neck, neck_height, alpha, 0.3, 0.5,
                                                                         9.80665), args.repeat, forget),
        "globe (sphere path)": best_of(lambda: horizontal_orbit(np.radians(rng.uniform(30, 150, args.n)), alpha, 0.3,
                                                                3.0, 0.5, 9.80665), args.repeat),
    }
    base = times["cone 80 deg"]
    print(f"{'arena':34s} {'M orbits/s':>11s} {'time / cone':>12s}")
    for name, t in times.items():
        print(f"{name:34s} {args.n / t / 1e6:11.2f} {t / base:12.2f}")


if __name__ == "__main__":
    main()
