"""Cost of the Whipple bicycle's generated equations (docs/two-wheeler.md
sec. 5): time per state of the generated equations, of the constrained
accelerations and of the pitch's Newton solve over a batch of states, and
of the benchmark's matrices; with --derive, the symbolic derivation too
(needs sympy).

    PYTHONPATH=. python3 benchmarks/bench_two_wheeler.py [--n 10000] [--repeat 5] [--derive]
"""

import argparse
import time

import numpy as np

from deathsphere.physics.two_wheeler import _generated, linear, motion
from deathsphere.physics.two_wheeler.parameters import benchmark_bicycle


def best_of(fn, repeat):
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=10_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--derive", action="store_true", help="time the symbolic derivation (sympy)")
    args = ap.parse_args()
    bicycle = benchmark_bicycle()
    p = motion.parameter_values(bicycle)
    rng = np.random.default_rng(1)
    q = rng.uniform(-0.3, 0.3, (8, args.n))
    u = rng.uniform(-2.0, 2.0, (8, args.n))
    q_wall = q + np.array([np.pi / 2] + [0.0] * 7)[:, None]    # around the equator of a 3 m sphere
    p_wall = motion.parameter_values(bicycle, "sphere", 3.0)
    for name, fn in (("flat_equations", lambda: _generated.flat_equations(q, u, p, 0.0)),
                     ("sphere_equations", lambda: _generated.sphere_equations(q_wall, u, p_wall, 0.0)),
                     ("accelerations", lambda: motion.accelerations(q, u, p)),
                     ("pitch (Newton)", lambda: motion.pitch(q, p))):
        seconds = best_of(fn, args.repeat)
        print(f"{name:16s} {seconds / args.n * 1e6:8.2f} us/state  (batch {args.n})")
    seconds = best_of(lambda: linear.benchmark_matrices(bicycle), args.repeat)
    print(f"{'M, C1, K0, K2':16s} {seconds * 1e3:8.2f} ms")
    if args.derive:
        from deathsphere.physics.two_wheeler import derivation

        for surface in derivation.SURFACES:
            t0, c0 = time.perf_counter(), time.process_time()
            derivation.derive(surface)
            print(f"derive {surface:9s} {time.perf_counter() - t0:8.1f} s  ({time.process_time() - c0:.1f} s CPU)")


if __name__ == "__main__":
    main()
