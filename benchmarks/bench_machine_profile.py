"""The single-contact machine's steady lanes with their stability on a lane
grid, in one run: `ride`'s table (stability columns filled) on the 80-degree
cone of a 32-ft well and on a profile sampled from that cone (101 samples:
its crown point on the profile's parallel surface by the meridian,
docs/machine.md "On a profile"), with the time's ratio to the cone's, and
the stability's own share (the same table without stability taken off).

    PYTHONPATH=. python3 benchmarks/bench_machine_profile.py [--heights 550] [--tilts 60] [--repeat 3]
"""

import argparse

import numpy as np

import deathsphere
from deathsphere.physics.ground import Cone, Profile
from timing import best_of


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--heights", type=int, default=550, help="lanes' heights in 0.5..6 m")
    ap.add_argument("--tilts", type=int, default=60, help="tilts in 10..40 deg")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    height = np.linspace(0.5, 6.0, args.heights)[:, None]
    alpha = np.linspace(10.0, 40.0, args.tilts)[None, :]
    cone = Cone(16 * 0.3048, np.radians(80.0), 8.0)
    rho, z = cone.contact(np.linspace(0.0, 8.0, 101))
    profile = Profile(rho, z)
    arena = {"cone 80 deg": dict(surface="cone", wall_angle=80, diameter="32ft", wall_height=8),
             "profile (the cone, 101 samples)": dict(surface="profile", profile=profile)}

    def forget():
        profile._last = None      # every call finds its lanes afresh, as a new request would

    times = {}
    for name, kw in arena.items():
        for stability in (True, False):
            times[name, stability] = best_of(
                lambda: deathsphere.ride(machine="stunt125", height=height, alpha=alpha, stability=stability, **kw),
                args.repeat, forget)
    rows = height.size * alpha.size
    base, base_st = times["cone 80 deg", True], times["cone 80 deg", True] - times["cone 80 deg", False]
    print(f"{rows} lanes of stunt125 with stability")
    print(f"{'arena':34s} {'k lanes/s':>10s} {'time / cone':>12s} {'stability / cone':>17s}")
    for name in arena:
        t, st = times[name, True], times[name, True] - times[name, False]
        print(f"{name:34s} {rows / t / 1e3:10.1f} {t / base:12.2f} {st / base_st:17.2f}")


if __name__ == "__main__":
    main()
