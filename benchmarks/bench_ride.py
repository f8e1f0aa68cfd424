"""Throughput of ``deathsphere.ride`` against ``deathsphere.orbit`` over the
same 10^6-orbit grid (docs/machine.md, "Performance"): prints orbits per
second of each and their ratio (the target: ride at least half of orbit's).

    PYTHONPATH=. python3 benchmarks/bench_ride.py [--n 1000000] [--stability] [--repeat 3]
"""

import argparse
import time

import numpy as np

import deathsphere


def best_of(fn, repeat=3):
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--stability", action="store_true", help="both with their stability columns")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    side = int(round(np.sqrt(args.n)))
    theta = np.linspace(5, 175, side)[:, None]
    alpha = np.linspace(-80, 80, side)[None, :]
    n = side * side
    t_orbit = best_of(lambda: deathsphere.orbit(theta, alpha, r=3.0, stability=args.stability), args.repeat)
    t_ride = best_of(lambda: deathsphere.ride(theta, alpha, machine="paper-wheel", r=3.0,
                                              stability=args.stability), args.repeat)
    print(f"orbits: {n}")
    print(f"orbit: {t_orbit:.3f} s  {n / t_orbit:,.0f} orbits/s")
    print(f"ride:  {t_ride:.3f} s  {n / t_ride:,.0f} orbits/s")
    print(f"ride/orbit throughput ratio: {t_orbit / t_ride:.2f}")


if __name__ == "__main__":
    main()
