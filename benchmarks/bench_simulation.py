"""Simulation wall time: 20 periods of a Table 1 orbit at rtol 1e-10, and how
the cost grows with the number of bodies integrated at once.

Run:  python benchmarks/bench_simulation.py [--periods 20] [--rtol 1e-10]
                                            [--bodies 1,10,100,1000] [--points-per-period 20]

Prints
0. the cost of one right-hand side call for one body: numpy on 9-element
   arrays (dynamics.rhs) against the one-body path on Python floats
   (dynamics.scalar_rates, the same equations), and the largest difference
   between them at random states;
1. one body on Table 1's orbit theta = 60, alpha = 10 deg (wheel inside,
   a = 0.3 m, r = 3 m, k = 1/2), steady, DOP853: wall time, steps, right-hand
   side evaluations and drifts, in the turning frame (the default, where the
   steady orbit is a fixed point) and in the lab frame;
2. N bodies on that orbit, each tilted by its own kick (0 .. 1e-6 rad, so
   the bodies differ), integrated together in ONE solve_ivp call (state of
   9 N rows, one vectorised right-hand side): wall time, time per body and
   the ratio to N = 1, per frame.  The time series is produced (sampled at
   --points-per-period) and discarded, as the CLI would stream it.
3. the one-body run of 1. with the one-body path switched off (right-hand
   side and event functions through numpy), against 1.: the speed-up and the
   largest deviation of the summary's drifts and extrema.
"""

from __future__ import annotations

import argparse
import platform
import time

import numpy as np

from deathsphere.model import Setup
from deathsphere.physics import dynamics as dyn
from deathsphere.simulation import Simulation, horizontal_starts

THETA, ALPHA = 60.0, 10.0


def one_run(n: int, frame: str, periods: float, rtol: float, ppp: int, kick: float = 1e-6):
    kicks = np.linspace(0.0, kick, n) if n > 1 else np.array([kick if kick else 0.0])
    starts = horizontal_starts(Setup(), THETA, ALPHA, perturb_deg=np.rad2deg(kicks))
    sim = Simulation(starts, periods=periods, points_per_period=ppp, rtol=rtol, frame=frame)
    t0 = time.perf_counter()
    rows = 0
    for chunk in sim.chunks():
        rows += len(chunk)
    wall = time.perf_counter() - t0
    return wall, rows, sim.summary()


def rhs_per_call(reps=2000):
    """Microseconds per right-hand side call, numpy vs Python floats, and
    their largest relative difference over random states near the orbit."""
    starts = horizontal_starts(Setup(), THETA, ALPHA)
    p = starts.params
    X = starts.state
    fr = starts.turning
    coef = dyn.scalar_coefficients(p)
    y = X[:, 0].tolist()
    t0 = time.perf_counter()
    for _ in range(reps):
        dyn.rhs(X, p, fr)
    t_np = (time.perf_counter() - t0) / reps
    t0 = time.perf_counter()
    for _ in range(reps):
        dyn.scalar_rates(y, coef, float(fr[0]))
    t_py = (time.perf_counter() - t0) / reps
    rng = np.random.default_rng(0)
    worst = 0.0
    for _ in range(200):
        Z = X * (1 + 0.1 * rng.normal(size=X.shape))
        a = dyn.rhs(Z, p, fr)[:, 0]
        b = np.array(dyn.scalar_rates(Z[:, 0].tolist(), coef, float(fr[0])))
        worst = max(worst, float(np.max(np.abs(a - b)) / np.max(np.abs(a))))
    return t_np, t_py, worst


class _NoScalar:
    """Switch the one-body path off: its functions raise, the callers fall
    back to numpy (as they do at a singular state)."""

    def __enter__(self):
        self.saved = dyn.scalar_rates, dyn.contact_values

        def off(*args, **kwargs):
            raise ZeroDivisionError

        dyn.scalar_rates = dyn.contact_values = off

    def __exit__(self, *exc):
        dyn.scalar_rates, dyn.contact_values = self.saved


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

    t_np, t_py, worst = rhs_per_call()
    print("0. right-hand side, one body, per call")
    print(f"   numpy (9-element arrays): {1e6 * t_np:8.1f} us")
    print(f"   Python floats:            {1e6 * t_py:8.1f} us   ({t_np / t_py:.1f}x faster)")
    print(f"   largest relative difference at 200 random states: {worst:.1e}\n")

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


    print("\n3. one steady body: one-body path (floats) vs numpy path, same run")
    print(f"{'frame':>8} {'floats s':>9} {'numpy s':>8} {'speed-up':>9} {'max |d drift| deg':>18} "
          f"{'max |d mu|':>11} {'steps':>11}")
    keys = ("max_theta_drift_deg", "max_alpha_drift_deg", "min_normal_per_mass_m_s2", "max_mu_required")
    for frame in frames:
        fast, _, s1 = one_run(1, frame, args.periods, args.rtol, args.points_per_period, kick=0.0)
        with _NoScalar():
            slow, _, s0 = one_run(1, frame, args.periods, args.rtol, args.points_per_period, kick=0.0)
        dd = max(abs(s1[k][0] - s0[k][0]) for k in keys[:2])
        dmu = abs(s1["max_mu_required"][0] - s0["max_mu_required"][0])
        print(f"{frame:>8} {fast:9.3f} {slow:8.3f} {slow / fast:9.1f} {dd:18.1e} {dmu:11.1e} "
              f"{s1['n_steps'][0]:5d}/{s0['n_steps'][0]:<5d}")


if __name__ == "__main__":
    main()
