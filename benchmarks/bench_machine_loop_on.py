"""The machine's vertical loop inside a closed profile (docs/machine.md eqs.
M25-M30) against the globe's closed forms (M21-M24): loops per second of
``ride(90, vertical=True, v_top=...)`` inside the ellipsoid of tests/data
and in a 16-ft globe.

    PYTHONPATH=. OMP_NUM_THREADS=1 python3 benchmarks/bench_machine_loop_on.py [--rows 10000] [--repeat 3]
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
from deathsphere.records.profile_files import profile_file  # noqa: E402

ELLIPSOID = Path(__file__).resolve().parents[1] / "tests" / "data" / "ellipsoid_dome.csv"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=10_000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    speeds = np.linspace(5.0, 40.0, args.rows)
    ground = profile_file(str(ELLIPSOID))
    on_profile = best_of(lambda: deathsphere.ride(90, vertical=True, v_top=speeds, surface="profile",
                                                  profile=ground, mu=0.8, max_g=8), args.repeat)
    globe = best_of(lambda: deathsphere.ride(90, vertical=True, v_top=speeds, diameter="16ft", mu=0.8, max_g=8),
                    args.repeat)
    print(f"{args.rows} loops inside the ellipsoid: {on_profile:.3f} s ({args.rows / on_profile:,.0f} loops/s)")
    print(f"{args.rows} loops in a 16-ft globe:     {globe:.3f} s ({args.rows / globe:,.0f} loops/s)")


if __name__ == "__main__":
    main()
