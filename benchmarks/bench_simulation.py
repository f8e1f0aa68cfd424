"""Simulation wall time: 20 periods of a Table 1 orbit at rtol 1e-10,
and how the cost grows with the number of bodies integrated at once.

Run:  python benchmarks/bench_simulation.py [--periods 20] [--rtol 1e-10]
                                            [--bodies 1,10,100,1000] [--points-per-period 20]

Prints
1. one body on Table 1's orbit theta = 60, alpha = 10 deg (wheel inside,
   a = 0.3 m, r = 3 m, k = 1/2), steady, DOP853: wall time, steps, right-hand
   side evaluations and drifts, in the turning frame (the default, where the
   steady orbit is a fixed point) and in the lab frame;
2. N bodies on that orbit, each tilted by its own kick (0 .. 1e-6 rad, so
   the bodies differ), integrated together in ONE solve_ivp call (state of
   9 N rows, one vectorised right-hand side): wall time, time per body and
   the ratio to N = 1, per frame.  The time series is produced (sampled at
   --points-per-period) and discarded, as the CLI would stream it.
"""

from __future__ import annotations

import argparse
import platform
import time

import numpy as np

from deathsphere.model import Setup
from deathsphere.simulation import Simulation, horizontal_starts

THETA, ALPHA = 60.0, 10.0


def one_run(n: int, frame: str, periods: float, rtol: float, ppp: int, kick: float = 1e-6):
    kicks = np.linspace(0.0, kick, n) if n > 1 else np.array([kick if kick else 0.0])
    starts = horizontal_starts(Setup(), THETA, ALPHA, perturb=kicks)
    sim = Simulation(starts, periods=periods, points_per_period=ppp, rtol=rtol, frame=frame)
    t0 = time.perf_counter()
    rows = 0
    for chunk in sim.chunks():
        rows += len(chunk)
    wall = time.perf_counter() - t0
    return wall, rows, sim.summary()


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--periods", type=float, default=20.0)
    p.add_argument("--rtol", type=float, default=1e-10)
    p.add_argument("--bodies", default="1,10,100,1000")
    p.add_argument("--points-per-period", type=int, default=20)
    p.add_argument("--frames", default="turning,lab")
    args = p.parse_args()
    sizes = [int(x) for x in args.bodies.split(",")]
    frames = args.frames.split(",")
    print(f"python {platform.python_version()}, numpy {np.__version__}, {platform.machine()}")
    print(f"Table 1 orbit theta = {THETA:g}, alpha = {ALPHA:g} deg; {args.periods:g} periods; DOP853, "
          f"rtol = atol = {args.rtol:g}; {args.points_per_period} output points per period\n")

    print("1. one steady body")
    print(f"{'frame':>8} {'wall s':>8} {'steps':>7} {'f evals':>8} {'theta drift rad':>16} "
          f"{'alpha drift rad':>16} {'|dE|/E':>9} {'constraint':>10}")
    for frame in frames:
        wall, rows, s = one_run(1, frame, args.periods, args.rtol, args.points_per_period, kick=0.0)
        print(f"{frame:>8} {wall:8.2f} {s['n_steps'][0]:7d} {s['n_fev'][0]:8d} "
              f"{np.deg2rad(s['max_theta_drift_deg'][0]):16.2e} {np.deg2rad(s['max_alpha_drift_deg'][0]):16.2e} "
              f"{s['max_abs_energy_drift'][0]:9.1e} {s['max_constraint_residual'][0]:10.1e}")

    print("\n2. N kicked bodies in one vectorised solve_ivp call")
    print(f"{'frame':>8} {'N':>6} {'wall s':>8} {'steps':>7} {'f evals':>8} {'ms/body':>9} "
          f"{'x N=1':>7} {'speed-up vs N runs':>19} {'rows':>9}")
    for frame in frames:
        base = None
        for n in sizes:
            wall, rows, s = one_run(n, frame, args.periods, args.rtol, args.points_per_period)
            base = base if base is not None else wall
            print(f"{frame:>8} {n:6d} {wall:8.2f} {s['n_steps'][0]:7d} {s['n_fev'][0]:8d} "
                  f"{1e3 * wall / n:9.2f} {wall / base:7.2f} {n * base / wall:19.1f} {rows:9d}")


if __name__ == "__main__":
    main()
