"""Vertical loops inside a closed profile against the globe's closed forms:
rows per second of the paper's wheel's ``vertical_sweep`` over top speeds
(docs/surfaces.md eqs. S9-S12; the summary without stability) and of the
single-contact machine's ``ride(90, vertical=True, v_top=...)`` (docs/machine.md
eqs. M25-M30 against M21-M24), on the ellipsoid of tests/data and on the
globe, and the share of the loop's sampling (once a command); then the
wheel's loops with their Floquet stability (docs/stability.md sec. 2.1),
``--floquet-rows`` of them inside the ellipsoid in one run, against the
globe's.

    PYTHONPATH=. OMP_NUM_THREADS=1 python3 benchmarks/bench_vertical_on.py [--rows 10000] [--repeat 3]
        [--floquet-rows 20]
"""

import argparse
import os
import sys
from pathlib import Path

for name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):  # one core
    os.environ.setdefault(name, "1")

sys.path.insert(0, str(Path(__file__).resolve().parent))
import numpy as np  # noqa: E402
from timing import best_of  # noqa: E402

import deathsphere  # noqa: E402
from deathsphere.physics.meridian_loop import Loop  # noqa: E402
from deathsphere.records.profile_files import profile_file  # noqa: E402

ELLIPSOID = Path(__file__).resolve().parents[1] / "tests" / "data" / "ellipsoid_dome.csv"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=10_000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--floquet-rows", type=int, default=20)
    args = parser.parse_args()
    speeds = np.linspace(7.1, 40.0, args.rows)
    ground = profile_file(str(ELLIPSOID))
    on_profile = best_of(lambda: deathsphere.vertical_sweep(90, speeds, surface="profile", profile=ground,
                                                            stability=False).table(), args.repeat)
    globe = best_of(lambda: deathsphere.vertical_sweep(90, speeds, stability=False).table(), args.repeat)
    sampling = best_of(lambda: Loop.of(ground), args.repeat)
    machine_speeds = np.linspace(5.0, 40.0, args.rows)
    machine_on = best_of(lambda: deathsphere.ride(90, vertical=True, v_top=machine_speeds, surface="profile",
                                                  profile=ground, mu=0.8, max_g=8), args.repeat)
    machine_globe = best_of(lambda: deathsphere.ride(90, vertical=True, v_top=machine_speeds, diameter="16ft", mu=0.8,
                                                     max_g=8), args.repeat)
    stable_speeds = np.linspace(7.1, 12.0, args.floquet_rows)
    floquet_on = best_of(lambda: deathsphere.vertical_sweep(90, stable_speeds, surface="profile", profile=ground)
                         .table(), 1)
    floquet_globe = best_of(lambda: deathsphere.vertical_sweep(90, stable_speeds).table(), 1)
    print(f"{args.rows} loops inside the ellipsoid: {on_profile:.3f} s ({args.rows / on_profile:,.0f} rows/s)")
    print(f"{args.rows} loops on the globe:         {globe:.3f} s ({args.rows / globe:,.0f} rows/s)")
    print(f"the loop's sampling (1024 intervals), once a command: {sampling * 1e3:.1f} ms")
    print(f"{args.rows} machine's loops inside the ellipsoid: {machine_on:.3f} s "
          f"({args.rows / machine_on:,.0f} loops/s)")
    print(f"{args.rows} machine's loops in a 16-ft globe:     {machine_globe:.3f} s "
          f"({args.rows / machine_globe:,.0f} loops/s)")
    print(f"{args.floquet_rows} loops inside the ellipsoid with their Floquet stability, one run: {floquet_on:.2f} s "
          f"({args.floquet_rows / floquet_on:.2f} loops/s)")
    print(f"{args.floquet_rows} loops on the globe with their Floquet stability, one run:     {floquet_globe:.2f} s "
          f"({args.floquet_rows / floquet_globe:.2f} loops/s)")


if __name__ == "__main__":
    main()
