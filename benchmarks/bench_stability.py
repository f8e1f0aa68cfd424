"""Benchmark: exact stability verdict for a 10^5-orbit grid, one core.

    python benchmarks/bench_stability.py [n_theta n_alpha]

Grid: theta 1..179 deg x alpha 0.5..89.5 deg (default 317 x 317 = 100 489
orbits), a = 0.3 m, r = 3 m, k = 1/2, wheel inside.  Every orbit goes
through deathsphere.physics.stability.wheel_stability (orbits with no real
Omega or that do not fit come back NaN/unknown, at the same cost).  Prints
the best of three timings as orbits/s (target >= 1.5e5 on one core) for the
current implementation and, in the same run, for the reference
implementation as first written (tests/physics/stability_reference.py:
complete QR, np.linalg.eigvals), their ratio, the verdict counts, the
verdicts that differ and the largest frequency deviation.  Set
OMP_NUM_THREADS=1 etc. to pin BLAS to one core (done here by default).
"""

import os
import sys
import time
from pathlib import Path

for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(var, "1")

import numpy as np  # noqa: E402

from deathsphere.constants import STANDARD_GRAVITY  # noqa: E402
from deathsphere.physics import stability as st  # noqa: E402
from deathsphere.physics.wheel import horizontal_orbit  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "physics"))
from stability_reference import wheel_stability_ref  # noqa: E402

G = STANDARD_GRAVITY


def best_of(f, args, reps=3):
    best = np.inf
    for _ in range(reps):
        t0 = time.perf_counter()
        res = f(*args)
        best = min(best, time.perf_counter() - t0)
    return best, res


def main(argv):
    n_th = int(argv[1]) if len(argv) > 1 else 317
    n_al = int(argv[2]) if len(argv) > 2 else 317
    th, al = np.meshgrid(np.radians(np.linspace(1, 179, n_th)),
                         np.radians(np.linspace(0.5, 89.5, n_al)), indexing="ij")
    n = th.size
    args = (th, al, 0.3, 3.0, 0.5, G)
    t_ref, ref = best_of(wheel_stability_ref, args)
    t_new, res = best_of(st.wheel_stability, args)
    v = res["verdict"]
    ok = horizontal_orbit(th, al, 0.3, 3.0, 0.5, G)["status"] == 0
    print(f"orbits: {n}  (status ok: {ok.sum()})")
    print(f"reference (QR + eigvals), best of 3: {t_ref:.3f} s  ->  {n / t_ref:,.0f} orbits/s")
    print(f"current, best of 3:                  {t_new:.3f} s  ->  {n / t_new:,.0f} orbits/s")
    print(f"speed-up (same run): {t_ref / t_new:.2f}x")
    for code in st.Verdict:
        print(f"  {code.label:9s} all: {np.sum(v == code):6d}   status ok: {np.sum((v == code) & ok):6d}")
    live = np.isfinite(ref["growth_rate"])
    print(f"verdicts changed: {np.sum(v != ref['verdict'])} of {n}")
    for key in ("freq_slow", "freq_fast"):
        d = np.abs(res[key][live] - ref[key][live])
        stable = ref["verdict"][live] == st.Verdict.STABLE
        rel = d[stable] / ref[key][live][stable]
        size = (ref["freq_fast"] + ref["growth_rate"])[live]
        print(f"  {key}: max relative deviation, stable orbits {np.max(rel):.1e}; "
              f"all orbits, relative to the eigenvalue's size {np.max(d / size):.1e}")


if __name__ == "__main__":
    main(sys.argv)
