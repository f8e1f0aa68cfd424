"""Latency of every command end to end, as a user runs it, against its goal.

    python benchmarks/bench_latency.py [--repeat 5] [--slow-repeat 3] [--floquet] [--no-compile]

Each command runs as a subprocess (the interpreter of this run,
``-m deathsphere``) with its defaults and ``--format csv``, output to
/dev/null, the commands interleaved round by round (a change of load hits
all alike).  Printed per command: the median and least wall time, the
median as a ratio to ``python -c "import numpy"`` measured in the same run
(so that figures from a loaded machine can be compared), the peak resident
memory of the command (its process and the worker processes it waited
for), the goal and whether the median meets it.  ``--repeat`` runs each
(default 5); the ``verify`` and ``verify.run`` rows, the slow ones,
run ``--slow-repeat`` times (default 3).

Goals: orbit, table1, stability and map within 2.0x ``import numpy``; a
unit suffix (``-r 8ft``, ``--speed 40km/h --diameter 16ft``) within 0.2 s
of the same command without one;
vertical within 0.5 s; simulate (20 periods of a Table 1 orbit) within
0.5 s of integration (``wall_time_s`` of its summary, median of
``--repeat`` runs with ``--summary-only``); verify within 5 s and 200 MB;
limits within 1 s.  Timed without a goal: the sweep of a small grid;
``verify --jobs 2`` against ``verify`` and ``verify.run(jobs=1)`` against
``verify.run(jobs=2)`` (the checklist on one and on two processes, from the
command line and through the Python API); ``map --stability`` (the
stability boundary as data) with ``--jobs 1`` and ``--jobs 2``, on the globe
and off it (the default 361 lanes of a 32-ft drum 12 ft tall and of
examples/bowl.csv; slow rows).

The package runs from bytecode, as an installed one does: before timing,
the benchmark compiles its modules (``compileall``, what ``pip install``
does for a regular install; Python also caches bytecode at the first import
unless ``PYTHONDONTWRITEBYTECODE`` is set, as it is on some machines, where
every start would otherwise compile the package's source again).
``--no-compile`` times the tree as found and prints how many of its modules
have bytecode (delete the ``__pycache__`` folders first to time a start
from source).

``--floquet`` adds, in-process, the vertical orbit's Floquet analysis
(stability.vertical_floquet, median of --repeat) against the method as
first written (tests/physics/test_floquet.py: RK4 on all nine directions,
one run), with the largest multiplier deviation between the two.
benchmarks/README.md records its runs; docs/performance.md quotes them.
"""

from __future__ import annotations

import argparse
import compileall
import csv
import datetime
import importlib.util
import io
import os
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

DS = [sys.executable, "-m", "deathsphere"]
API_VERIFY = "from deathsphere.results import verify; verify.run(jobs={})"

MAP_DRUM = ["map", "--surface", "cylinder", "--diameter", "32ft", "--wall-height", "12ft", "--stability",
            "--format", "csv"]
MAP_BOWL = ["map", "--surface", "profile", "--profile", str(Path(__file__).resolve().parents[1] / "examples" /
                                                            "bowl.csv"), "--stability", "--format", "csv"]
#: name -> (command, slow, goal); goal is ("x numpy", limit), ("s", limit) or None
COMMANDS = {
    "import numpy": ([sys.executable, "-c", "import numpy"], False, None),
    "orbit": (DS + ["orbit", "--theta", "60", "--alpha", "10", "--format", "csv"], False, ("x numpy", 2.0)),
    # a crew's units: the suffix costs at most UNIT_SUFFIX_GOAL_S over the same command without one
    "orbit -r 8ft": (DS + ["orbit", "--theta", "60", "--alpha", "10", "-r", "8ft", "--format", "csv"], False,
                     ("x numpy", 2.0)),
    "ride": (DS + ["ride", "--theta", "90", "--speed", "11.1", "-r", "2.4384", "--format", "csv"], False, None),
    "ride 16ft 40km/h": (DS + ["ride", "--theta", "90", "--speed", "40km/h", "--diameter", "16ft", "--format",
                               "csv"], False, None),
    "table1": (DS + ["table1", "--format", "csv"], False, ("x numpy", 2.0)),
    "stability": (DS + ["stability", "--theta", "90", "--alpha", "45", "--format", "csv"], False,
                  ("x numpy", 2.0)),
    "map": (DS + ["map", "--format", "csv"], False, ("x numpy", 2.0)),
    "vertical": (DS + ["vertical", "--theta", "90", "--v-top", "6", "--format", "csv"], False, ("s", 0.5)),
    "simulate": (DS + ["simulate", "--theta", "60", "--alpha", "10", "--periods", "20", "--format", "csv"],
                 False, None),
    "limits": (DS + ["limits", "--mu", "1", "--max-g", "5", "--format", "csv"], False, ("s", 1.0)),
    "sweep": (DS + ["sweep", "--theta", "0:180:1", "--alpha", "0:90:1", "--format", "csv"], False, None),
    "map --stability -j1": (DS + ["map", "--stability", "--format", "csv", "--jobs", "1"], False, None),
    "map --stability -j2": (DS + ["map", "--stability", "--format", "csv", "--jobs", "2"], False, None),
    # off the globe: the default 361 lanes of a 32-ft drum and of the bowl's profile
    "map drum --stab -j1": (DS + MAP_DRUM + ["--jobs", "1"], True, None),
    "map drum --stab -j2": (DS + MAP_DRUM + ["--jobs", "2"], True, None),
    "map bowl --stab -j1": (DS + MAP_BOWL + ["--jobs", "1"], True, None),
    "map bowl --stab -j2": (DS + MAP_BOWL + ["--jobs", "2"], True, None),
    "verify": (DS + ["verify", "--format", "csv"], True, ("s", 5.0)),
    "verify --jobs 2": (DS + ["verify", "--format", "csv", "--jobs", "2"], True, None),
    "verify.run(jobs=1)": ([sys.executable, "-c", API_VERIFY.format(1)], True, None),
    "verify.run(jobs=2)": ([sys.executable, "-c", API_VERIFY.format(2)], True, None),
}
#: the summary of the simulate run, for the integrator's own time
SIMULATE_SUMMARY = DS + ["simulate", "--theta", "60", "--alpha", "10", "--periods", "20", "--summary-only",
                         "--format", "csv"]
SIMULATE_GOAL_S = 0.5
#: What a unit suffix may add to a command [s] (median with it less median without)
UNIT_SUFFIX_GOAL_S = 0.2
VERIFY_GOAL_MB = 200.0


def run(cmd, stdout=subprocess.DEVNULL) -> tuple[float, float]:
    """Wall time [s] and peak resident memory [MB] of one run of ``cmd``
    (the process and the children it waited for: os.wait4's rusage)."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=stdout, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    err = proc.stderr.read().decode(errors="replace")
    proc.stderr.close()
    if proc.returncode:
        raise SystemExit(f"{' '.join(cmd)} failed ({proc.returncode}):\n{err}")
    # ru_maxrss is in kB on Linux, in bytes on macOS
    mb = usage.ru_maxrss / (1024 * 1024 if sys.platform == "darwin" else 1024)
    return wall, mb


def package_bytecode(compile_it: bool) -> str:
    """Compile the package's modules (unless ``compile_it`` is false) and say
    how many of them have bytecode that Python will use."""
    root = Path(importlib.util.find_spec("deathsphere").origin).parent
    if compile_it:
        compileall.compile_dir(root, quiet=1)
    sources = sorted(root.rglob("*.py"))
    cached = sum(Path(importlib.util.cache_from_source(f)).is_file()
                 and Path(importlib.util.cache_from_source(f)).stat().st_mtime >= f.stat().st_mtime
                 for f in sources)
    how = "compiled by this run (compileall)" if compile_it else "as found"
    dont_write = os.environ.get("PYTHONDONTWRITEBYTECODE") or "unset"
    return (f"package bytecode: {how}, {cached} of {len(sources)} modules have it "
            f"(PYTHONDONTWRITEBYTECODE={dont_write})")


def integration_time() -> float:
    """The integrator's wall time [s] of the simulate command, from its summary."""
    out = subprocess.run(SIMULATE_SUMMARY, check=True, capture_output=True, text=True).stdout
    (row,) = csv.DictReader(io.StringIO(out))
    return float(row["wall_time_s"])


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--repeat", type=int, default=5)
    p.add_argument("--slow-repeat", type=int, default=3)
    p.add_argument("--floquet", action="store_true", help="also the in-process Floquet comparison")
    p.add_argument("--no-compile", action="store_true",
                   help="time the package as found, without compiling its bytecode first")
    args = p.parse_args()
    print(f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC, python {platform.python_version()}, "
          f"{platform.machine()}, {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f} at start")
    print(package_bytecode(not args.no_compile))
    walls = {name: [] for name in COMMANDS}
    peaks = {name: [] for name in COMMANDS}
    integration = []
    for i in range(max(args.repeat, args.slow_repeat)):     # interleaved rounds
        for name, (cmd, slow, _) in COMMANDS.items():
            if i < (args.slow_repeat if slow else args.repeat):
                wall, mb = run(cmd)
                walls[name].append(wall)
                peaks[name].append(mb)
        if i < args.repeat:
            integration.append(integration_time())
    load_end = os.getloadavg()[0]

    numpy_s = statistics.median(walls["import numpy"])
    sim_s = statistics.median(integration)
    print(f"\n{'command':<20} {'runs':>4} {'median s':>9} {'min s':>7} {'x numpy':>8} {'peak MB':>8}  "
          f"{'goal':<28} met")
    verdicts = {}
    for name, (cmd, _, goal) in COMMANDS.items():
        med = statistics.median(walls[name])
        ratio = med / numpy_s
        peak = max(peaks[name])
        if goal is None:
            text, met = "-", None
        elif goal[0] == "x numpy":
            text, met = f"<= {goal[1]:.1f}x import numpy", ratio <= goal[1]
        else:
            text, met = f"<= {goal[1]:g} s", med <= goal[1]
        if name == "verify":
            text += f", <= {VERIFY_GOAL_MB:.0f} MB"
            met = met and peak <= VERIFY_GOAL_MB
        if name == "simulate":
            text, met = f"integration <= {SIMULATE_GOAL_S:g} s", sim_s <= SIMULATE_GOAL_S
        verdicts[name] = met
        print(f"{name:<20} {len(walls[name]):4d} {med:9.3f} {min(walls[name]):7.3f} {ratio:8.2f} {peak:8.1f}  "
              f"{text:<28} {'-' if met is None else ('yes' if met else 'NO')}")
    print(f"\nsimulate: the integrator's own wall time (summary wall_time_s), median of {len(integration)}: "
          f"{sim_s:.3f} s (least {min(integration):.3f} s)")
    for label, one_name, two_name in (("verify", "verify", "verify --jobs 2"),
                                      ("verify.run", "verify.run(jobs=1)", "verify.run(jobs=2)"),
                                      ("map --stability", "map --stability -j1", "map --stability -j2"),
                                      ("map drum --stability", "map drum --stab -j1", "map drum --stab -j2"),
                                      ("map bowl --stability", "map bowl --stab -j1", "map bowl --stab -j2")):
        one, two = (statistics.median(walls[n]) for n in (one_name, two_name))
        print(f"{label}: 2 processes take {two / one:.2f}x the wall time of 1")
    for with_unit, without in (("orbit -r 8ft", "orbit"), ("ride 16ft 40km/h", "ride")):
        cost = statistics.median(walls[with_unit]) - statistics.median(walls[without])
        verdicts[f"suffix cost of {with_unit!r}"] = cost <= UNIT_SUFFIX_GOAL_S
        print(f"unit suffix: {with_unit!r} takes {cost:+.3f} s over {without!r} ({cost / numpy_s:+.2f}x import "
              f"numpy; goal <= {UNIT_SUFFIX_GOAL_S:g} s: {'yes' if cost <= UNIT_SUFFIX_GOAL_S else 'NO'})")
    met = [n for n, v in verdicts.items() if v]
    missed = [n for n, v in verdicts.items() if v is False]
    print(f"goals met: {', '.join(met) or 'none'}; not met: {', '.join(missed) or 'none'}")
    print(f"load average {load_end:.2f} at the end")
    print("\ncommands:")
    for name, (cmd, _, _) in COMMANDS.items():
        shown = ["deathsphere"] + cmd[3:] if cmd[:3] == DS else ["python"] + cmd[1:]
        print(f"  {name:<20} {' '.join(shown)}")

    if args.floquet:
        floquet(args.repeat)


def floquet(repeat: int):
    import numpy as np

    from deathsphere.constants import STANDARD_GRAVITY
    from deathsphere.physics import stability as st

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "physics"))
    from test_floquet import _match, floquet_reference

    orbit = (np.pi / 2, 6.0 / 2.7, 0.3, 3.0, 0.5, STANDARD_GRAVITY)
    runs = []
    for _ in range(repeat):
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
