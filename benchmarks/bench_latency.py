"""Latency of two commands end to end, as a user sees it.

    python benchmarks/bench_latency.py [--repeat 5]

Runs as subprocesses (the interpreter of this run, ``-m deathsphere``),
each ``--repeat`` times in turn, and prints the median wall time of

  numpy       python -c "import numpy"          (the floor: interpreter + numpy)
  vertical    deathsphere vertical --theta 90 --v-top 6   (with its Floquet stability)
  vertical-   the same with --no-stability
  simulate    deathsphere simulate --theta 60 --alpha 10 --periods 20

and each median as a ratio to ``import numpy`` measured in the same run, so
that figures from a loaded machine can be compared.  Then, in-process, the
vertical orbit's Floquet analysis alone (stability.vertical_floquet, median
of --repeat) against the method as first written (tests/physics/
test_floquet.py: RK4 on all nine directions, one run), with the largest
multiplier deviation between the two.  docs/performance.md quotes this
script.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

COMMANDS = {
    "numpy": [sys.executable, "-c", "import numpy"],
    "vertical": [sys.executable, "-m", "deathsphere", "vertical", "--theta", "90", "--v-top", "6"],
    "vertical-": [sys.executable, "-m", "deathsphere", "vertical", "--theta", "90", "--v-top", "6",
                  "--no-stability"],
    "simulate": [sys.executable, "-m", "deathsphere", "simulate", "--theta", "60", "--alpha", "10",
                 "--periods", "20"],
}


def wall(cmd) -> float:
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - t0


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--repeat", type=int, default=5)
    args = p.parse_args()
    print(f"python {platform.python_version()}, {platform.machine()}, {os.cpu_count()} CPUs, "
          f"load average {os.getloadavg()[0]:.2f} at start")
    times = {name: [] for name in COMMANDS}
    for _ in range(args.repeat):                 # interleaved: load changes hit all alike
        for name, cmd in COMMANDS.items():
            times[name].append(wall(cmd))
    med = {name: statistics.median(v) for name, v in times.items()}
    print(f"\n{'command':>10} {'median s':>9} {'min s':>7} {'x import numpy':>15}")
    for name in COMMANDS:
        print(f"{name:>10} {med[name]:9.3f} {min(times[name]):7.3f} {med[name] / med['numpy']:15.2f}")
    print(f"load average {os.getloadavg()[0]:.2f} at the end")

    import numpy as np

    from deathsphere.constants import STANDARD_GRAVITY
    from deathsphere.physics import stability as st

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "physics"))
    from test_floquet import _match, floquet_reference

    orbit = (np.pi / 2, 6.0 / 2.7, 0.3, 3.0, 0.5, STANDARD_GRAVITY)
    runs = []
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        new = st.vertical_floquet(*orbit)
        runs.append(time.perf_counter() - t0)
    t0 = time.perf_counter()
    ref = floquet_reference(*orbit)
    t_ref = time.perf_counter() - t0
    print("\nFloquet analysis of the vertical orbit theta = 90 deg, v_top = 6 m/s, in-process:")
    print(f"  current (half lap, order 8, 3 directions, floats): {statistics.median(runs):.3f} s (median)")
    print(f"  as first written (RK4, 9 directions, numpy):        {t_ref:.3f} s  "
          f"({t_ref / statistics.median(runs):.0f}x)")
    dev = _match(np.atleast_2d(new["multipliers"]), np.atleast_2d(ref["multipliers"]))
    print(f"  largest multiplier deviation: {dev:.1e} (the first version's RK4 error, docs/stability.md sec. 2)")


if __name__ == "__main__":
    main()
