"""Sweep throughput and memory.

Run:  python benchmarks/bench_sweep.py [--rows 1000000] [--big 10000000]

Prints
1. rows/s of deathsphere's writers -- the pure-Python CSV writer, the
   compiled one (polars, the fast extra) and Parquet (pyarrow) -- against
   numpy.savetxt of the same float columns (savetxt gets the easier job:
   no text columns, no empty cells), all to /dev/null (Parquet to a
   temporary file), in one process, interleaved, best of --repeat;
2. peak resident memory of `deathsphere sweep` processes of 1e5 and --big
   orbits to /dev/null, and of --big orbits to Parquet (each in its own
   child, so ru_maxrss is its own).
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

from deathsphere.chunker import grid_chunks
from deathsphere.model import TEXT_COLUMNS, evaluate, make_requests
from deathsphere.writers import parquet, polars_csv
from deathsphere.writers.stream import write_csv

CHUNK = 16384


def tables(rows: int):
    side = int(np.ceil(np.sqrt(rows)))
    axes = {"theta": np.linspace(0, 180, side), "alpha": np.linspace(-90, 90, side)}
    produced = 0
    for chunk in grid_chunks(axes, CHUNK):
        if produced >= rows:
            return
        grid, first = chunk.values(), chunk.first
        n = min(len(grid["theta"]), rows - produced)
        yield evaluate(make_requests(n, input_row=np.arange(first + 1, first + n + 1),
                                     theta=grid["theta"][:n], alpha=grid["alpha"][:n]))
        produced += n


def peak_rss_mb(n_theta: int, n_alpha: int, *extra: str) -> tuple[float, float]:
    """Peak RSS [MB] and wall time [s] of one sweep process to /dev/null
    (or where ``extra`` says, e.g. --output FILE.parquet)."""
    code = (
        "import resource, subprocess, sys, time\n"
        "t = time.perf_counter()\n"
        f"subprocess.run([sys.executable, '-m', 'deathsphere', 'sweep', '--theta', '0:180:{180 / (n_theta - 1)!r}',"
        f" '--alpha', '-90:90:{180 / (n_alpha - 1)!r}', *{list(extra)!r}], stdout=subprocess.DEVNULL, check=True)\n"
        "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024, time.perf_counter() - t)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    rss, wall = map(float, out.split())
    return rss, wall


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--rows", type=int, default=1_000_000)
    p.add_argument("--big", type=int, default=10_000_000)
    p.add_argument("--repeat", type=int, default=3)
    args = p.parse_args()

    chunks = list(tables(args.rows))
    floats = [n for n in chunks[0].names if n not in TEXT_COLUMNS]

    def savetxt(out):
        for c in chunks:
            np.savetxt(out, np.column_stack([c[n].astype(float) for n in floats]), fmt="%.17g", delimiter=",")

    runs = {"savetxt": lambda out: savetxt(out),
            "pure-Python CSV": lambda out: write_csv(iter(chunks), out, compiled=False)}
    if polars_csv.csv_available():
        runs["compiled CSV"] = lambda out: write_csv(iter(chunks), out, compiled=True)
    folder = tempfile.mkdtemp()
    if parquet.parquet_available():
        runs["Parquet"] = lambda out: parquet.write_parquet(iter(chunks), os.path.join(folder, "b.parquet"))
    best = dict.fromkeys(runs, float("inf"))
    with open(os.devnull, "w") as devnull:
        for _ in range(args.repeat):  # interleaved: a busy moment of the machine hits all of them
            for name, run in runs.items():
                t = time.perf_counter()
                run(devnull)
                best[name] = min(best[name], time.perf_counter() - t)
    print(f"{args.rows:,} rows, {len(chunks[0].names)} columns ({len(floats)} for savetxt), best of {args.repeat}:")
    for name, seconds in best.items():
        print(f"  {name:16s}: {args.rows / seconds:12,.0f} rows/s ({seconds:.2f} s)  "
              f"{best['savetxt'] / seconds:5.2f}x savetxt")
    if "compiled CSV" in best:
        print(f"compiled / pure-Python CSV: {best['pure-Python CSV'] / best['compiled CSV']:.2f}x")
        print(f"goal compiled CSV >= 4x savetxt: {'met' if best['savetxt'] / best['compiled CSV'] >= 4 else 'NOT met'}")
    else:
        print("compiled CSV: not measured (pip install 'deathsphere[fast]')")

    small = peak_rss_mb(317, 316)                     # ~1e5 orbits
    side = int(np.ceil(np.sqrt(args.big)))
    big = peak_rss_mb(side, side)
    print(f"peak RSS, sweep of {317 * 316:>12,} orbits: {small[0]:7.1f} MB  ({small[1]:.1f} s)")
    print(f"peak RSS, sweep of {side * side:>12,} orbits: {big[0]:7.1f} MB  ({big[1]:.1f} s, "
          f"{side * side / big[1]:,.0f} rows/s end to end)")
    print(f"memory growth: {big[0] - small[0]:+.1f} MB (goal: within 20 MB)")
    if parquet.parquet_available():
        to_parquet = peak_rss_mb(side, side, "--no-stability", "--output", os.path.join(folder, "big.parquet"))
        size = os.path.getsize(os.path.join(folder, "big.parquet")) / 1e6
        print(f"peak RSS, sweep of {side * side:>12,} orbits to Parquet (--no-stability): {to_parquet[0]:7.1f} MB "
              f"({to_parquet[1]:.1f} s, file {size:.0f} MB)")
    shutil.rmtree(folder)


if __name__ == "__main__":
    main()
