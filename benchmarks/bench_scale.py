"""A fine map on one machine and on a cluster: ratios to numpy.savetxt.

Run:  python benchmarks/bench_scale.py [--step 0.15] [--repeat 2] [--cluster]

Prints, from one run on one machine (ratios only mean anything within a run):

1. the time ``numpy.savetxt`` takes to write the sweep's rows (1201 x 1201 =
   1.44 M at the default step) as 31 float columns (every column but
   ``input_row``, text columns as codes; ``%.17g``) to /dev/null, and
   polars writing the same float matrix (the compiled writer's limit);
2. ``deathsphere sweep --theta 0:180:STEP --alpha -90:90:STEP`` end to end,
   each a process of its own under ``/usr/bin/time -v`` (wall time, user and
   system CPU, peak RSS, minor page faults): CSV to /dev/null with and
   without stability, Parquet with and without, and ``--jobs 2``; each as
   ``savetxt time / its time`` (higher is faster);
3. with ``--cluster``: the same CSV sweep on a local dask scheduler with 2
   workers started by dask's own commands (``dask scheduler``, ``dask
   worker``), its bytes compared with the local run's, and the rate per worker;
4. ``orbit --input`` of 10^6 requests with stability: peak RSS.
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

from deathsphere import api
from deathsphere.model import TEXT_COLUMNS

TIME = "/usr/bin/time"


def float_matrix(table) -> np.ndarray:
    """The 31 columns after input_row as floats (text as codes of its distinct values)."""
    cols = []
    for name in table.names[1:]:
        v = table[name]
        if name in TEXT_COLUMNS:
            v = np.unique(v.astype(str), return_inverse=True)[1]
        elif v.dtype == object:
            v = np.array([np.nan if b is None else b for b in v.tolist()], dtype=float)
        cols.append(np.asarray(v, dtype=float))
    return np.column_stack(cols)


def savetxt_seconds(mats, repeat: int) -> tuple[float, float]:
    import polars as pl

    best_np = best_pl = float("inf")
    with open(os.devnull, "w") as out:
        for _ in range(repeat):
            t = time.perf_counter()
            for m in mats:
                np.savetxt(out, m, fmt="%.17g", delimiter=",")
            best_np = min(best_np, time.perf_counter() - t)
            t = time.perf_counter()
            for m in mats:
                out.write(pl.DataFrame(m).fill_nan(None).write_csv(include_header=False))
            best_pl = min(best_pl, time.perf_counter() - t)
    return best_np, best_pl


#: The tree measured: this checkout (``--before DIR`` adds another).  The
#: processes run in a neutral directory: ``python -m`` puts the working
#: directory first on sys.path, which would shadow PYTHONPATH.
HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def timed(args: list[str], stdout=subprocess.DEVNULL, env=None) -> dict:
    """One process under /usr/bin/time -v: wall, user, sys [s], peak RSS [MB], minor faults."""
    env = env or dict(os.environ, PYTHONPATH=HERE)
    with tempfile.NamedTemporaryFile("r", suffix=".txt") as log:
        subprocess.run([TIME, "-v", "-o", log.name, *args], stdout=stdout, check=True, env=env,
                       cwd=tempfile.gettempdir())
        text = log.read()

    def field(label):
        line = next(line for line in text.splitlines() if line.strip().startswith(label))
        return line.rsplit(": ", 1)[1].strip()

    h, m, s = (["0"] + field("Elapsed (wall clock) time").split(":"))[-3:]
    return {"wall": int(h) * 3600 + int(m) * 60 + float(s), "user": float(field("User time")),
            "sys": float(field("System time")), "rss": int(field("Maximum resident set size")) / 1024,
            "faults": int(field("Minor (reclaiming a frame) page faults"))}


def best(args, repeat, **kw) -> dict:
    runs = [timed(args, **kw) for _ in range(repeat)]
    return min(runs, key=lambda r: r["wall"])


def row(label: str, r: dict, savetxt: float) -> None:
    print(f"  {label:44s} {r['wall']:6.2f} s  {savetxt / r['wall']:5.2f}x savetxt   user {r['user']:5.2f} s "
          f"sys {r['sys']:4.2f} s  peak {r['rss']:6.1f} MB  {r['faults']:>8,} minor faults")


def cluster_run(sweep: list[str], repeat: int, reference: str) -> None:
    port = 8786 + os.getpid() % 1000
    address = f"tcp://127.0.0.1:{port}"
    procs = [subprocess.Popen(["dask", "scheduler", "--port", str(port), "--dashboard-address", ":0"],
                              stderr=subprocess.DEVNULL)]
    try:
        time.sleep(3)
        for _ in range(2):
            procs.append(subprocess.Popen(["dask", "worker", address, "--nthreads", "1", "--nworkers", "1",
                                           "--dashboard-address", ":0"], stderr=subprocess.DEVNULL,
                                          env=dict(os.environ, PYTHONPATH=HERE), cwd=tempfile.gettempdir()))
        time.sleep(5)
        with tempfile.NamedTemporaryFile("w+b", suffix=".csv") as out:
            r = best([*sweep, "--scheduler", address], repeat, stdout=out)
            out.seek(0)
            same = out.read() == reference
        print(f"  local dask scheduler + 2 workers (1 thread each): {r['wall']:.2f} s wall, "
              f"client CPU {r['user'] + r['sys']:.2f} s, peak client RSS {r['rss']:.1f} MB; "
              f"bytes equal to the local run: {same}")
        return r
    finally:
        for p in reversed(procs):
            p.terminate()
        for p in procs:
            p.wait()


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--step", type=float, default=0.15)
    p.add_argument("--repeat", type=int, default=2)
    p.add_argument("--cluster", action="store_true")
    p.add_argument("--input-rows", type=int, default=1_000_000)
    p.add_argument("--before", metavar="DIR", help="also run the sweeps and the input stream with the package "
                   "in DIR first on PYTHONPATH (e.g. `git archive REV deathsphere | tar -x -C DIR`)")
    args = p.parse_args()

    step = repr(args.step)
    mats = [float_matrix(t) for t in api.sweep(f"0:180:{step}", f"-90:90:{step}")]
    rows = sum(len(m) for m in mats)
    savetxt, polars_alone = savetxt_seconds(mats, args.repeat)
    del mats
    print(f"{rows:,} rows, 31 float columns, best of {args.repeat}:")
    print(f"  numpy.savetxt ('%.17g') to /dev/null          {savetxt:6.2f} s  1.00x savetxt")
    print(f"  polars write_csv of the same floats           {polars_alone:6.2f} s  "
          f"{savetxt / polars_alone:5.2f}x savetxt")
    sweep = [sys.executable, "-m", "deathsphere", "sweep", "--theta", f"0:180:{step}", "--alpha", f"-90:90:{step}"]
    folder = tempfile.mkdtemp()
    parquet = os.path.join(folder, "grid.parquet")
    print("deathsphere sweep, best of", args.repeat)
    trees = [("", None)]
    if args.before:
        trees.insert(0, ("before: ", dict(os.environ, PYTHONPATH=os.path.abspath(args.before))))
    for label, extra in (("CSV --no-stability", ["--no-stability"]), ("CSV with stability", []),
                         ("Parquet --no-stability", ["--no-stability", "--output", parquet]),
                         ("Parquet with stability", ["--output", parquet]),
                         ("CSV --no-stability --jobs 2", ["--no-stability", "--jobs", "2"]),
                         ("CSV with stability --jobs 2", ["--jobs", "2"])):
        for prefix, env in trees:  # interleaved: a busy moment hits both
            row(prefix + label, best([*sweep, *extra], args.repeat, env=env), savetxt)
    if args.cluster:
        reference = subprocess.run(sweep, capture_output=True, check=True, env=dict(os.environ, PYTHONPATH=HERE),
                                   cwd=tempfile.gettempdir()).stdout
        r = cluster_run(sweep, 1, reference)
        print(f"  per worker: {rows / r['wall'] / 2:,.0f} orbits/s with stability (CSV written by the client); "
              f"10^9 orbits on N such workers: ~{1e9 / (rows / r['wall'] / 2) / 60:,.0f} / N minutes")
    requests = os.path.join(folder, "requests.csv")
    rng = np.random.default_rng(1)
    n = args.input_rows
    with open(requests, "w") as f:
        f.write("theta,alpha,mu\n")
        np.savetxt(f, np.column_stack([rng.uniform(1, 179, n), rng.uniform(-30, 95, n), rng.uniform(0.2, 2, n)]),
                   fmt="%.6g", delimiter=",")
    for prefix, env in trees:
        r = timed([sys.executable, "-m", "deathsphere", "orbit", "--input", requests, "--format", "csv"], env=env)
        print(f"{prefix}orbit --input of {n:,} requests with stability: peak RSS {r['rss']:.1f} MB (goal < 150), "
              f"{r['wall']:.2f} s, {r['faults']:,} minor faults")
    shutil.rmtree(folder)


if __name__ == "__main__":
    main()
