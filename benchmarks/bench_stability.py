"""Benchmark: exact stability verdict for a 10^5-orbit grid, one core.

    python benchmarks/bench_stability.py [n_theta n_alpha]

Grid: theta 1..179 deg x alpha 0.5..89.5 deg (default 317 x 317 = 100 489
orbits), a = 0.3 m, r = 3 m, k = 1/2, wheel inside.  Every orbit goes
through deathsphere.physics.stability.wheel_stability (orbits with no real
Omega or that do not fit come back NaN/unknown, at the same cost).  Prints
the best of three timings as orbits/s (target >= 1e4 on one core), and the
verdict counts.  Set OMP_NUM_THREADS=1 etc. to pin BLAS to one core; the
batched 4x4 / 9x5 LAPACK calls do not use threads anyway.
"""

import os
import sys
import time

for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(var, "1")

import numpy as np  # noqa: E402

from deathsphere.physics import stability as st  # noqa: E402
from deathsphere.physics.wheel import horizontal_orbit  # noqa: E402

G = 9.80665


def main(argv):
    n_th = int(argv[1]) if len(argv) > 1 else 317
    n_al = int(argv[2]) if len(argv) > 2 else 317
    th, al = np.meshgrid(np.radians(np.linspace(1, 179, n_th)),
                         np.radians(np.linspace(0.5, 89.5, n_al)), indexing="ij")
    n = th.size
    best = np.inf
    for _ in range(3):
        t0 = time.perf_counter()
        res = st.wheel_stability(th, al, 0.3, 3.0, 0.5, G)
        best = min(best, time.perf_counter() - t0)
    v = res["verdict"]
    ok = horizontal_orbit(th, al, 0.3, 3.0, 0.5, G)["status"] == 0
    print(f"orbits: {n}  (status ok: {ok.sum()})")
    print(f"best of 3: {best:.3f} s  ->  {n / best:,.0f} orbits/s")
    for code in st.Verdict:
        print(f"  {code.label:9s} all: {np.sum(v == code):6d}   status ok: {np.sum((v == code) & ok):6d}")


if __name__ == "__main__":
    main(sys.argv)
