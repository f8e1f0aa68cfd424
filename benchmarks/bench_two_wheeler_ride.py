"""The two-wheeler's steady turns with their stability, the API against the
command line (docs/two-wheeler.md sec. 8.6): a grid of heights x rear
speeds on a 16-foot globe, ``deathsphere.ride`` called once in this process
against ``deathsphere ride --steer free ... --format csv > /dev/null`` run
as a command (its start-up included), each the best of ``--repeat`` runs,
in one run, and their ratio (the target: the command within 1.5x of the
call).

    PYTHONPATH=. python3 benchmarks/bench_two_wheeler_ride.py [--side 100] [--repeat 3] [--chunk N ...] [--before REV] [--drum]

``--side 100`` is 10^4 turns requested: heights 0.2:3.962:0.038 m and
speeds 5:19.85:0.15 m/s, 100 values each.  ``--chunk N ...`` times the
streamed ride (what the command runs) in this process too, with N requests
per chunk (in whole lanes: 100 is one lane, as the command streamed before),
to show what the chunk size costs apart from the start-up and the writing.
``--before REV`` times the command of the package as it was at git
revision REV too (extracted into a temporary directory), in the same run,
and checks that both commands write the same bytes.  ``--drum`` times the
same grid on a 16-foot drum (the wall of death's: the same diameter, the
heights up its wall) too, the API and the command, against the globe's API
(the target: the drum within 2x of the globe; docs/two-wheeler.md sec. 12.6).
"""

import argparse
import io
import os
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

import numpy as np

import deathsphere
from timing import best_of

MACHINE = "stunt125-steer"



def ranges(side):
    """The grid's two ranges as the command line types them, ``side`` values each."""
    return f"0.2:{0.2 + 0.038 * (side - 1):.3f}:0.038", f"5:{5 + 0.15 * (side - 1):.2f}:0.15"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--side", type=int, default=100, help="heights and speeds, each (side^2 turns asked)")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--chunk", type=int, nargs="*", default=[], help="also the streamed ride with these chunk sizes")
    ap.add_argument("--before", default=None, metavar="REV", help="also the command at git revision REV")
    ap.add_argument("--drum", action="store_true", help="also the same grid on a 16-foot drum")
    args = ap.parse_args()
    height, speed = ranges(args.side)
    from deathsphere.grid import parse_values

    h, v = parse_values(height), parse_values(speed)
    assert h.size == v.size == args.side, (h.size, v.size)
    ask = dict(machine=MACHINE, steer="free", diameter="16ft")
    # the API broadcasts: a column of heights and a row of speeds is the grid
    api_rows = len(deathsphere.ride(**ask, height=h[:, None], speed=v[None, :]))
    t_api = best_of(lambda: deathsphere.ride(**ask, height=h[:, None], speed=v[None, :]), args.repeat)
    command = [sys.executable, "-m", "deathsphere", "ride", "--machine", MACHINE, "--steer", "free",
               "--diameter", "16ft", "--height", height, "--speed", speed, "--format", "csv"]
    root = Path(__file__).resolve().parent.parent

    def cli(package, out=os.devnull):
        with open(out, "w") as sink:
            # run in the package's directory: python -m puts the working directory first on the path
            subprocess.run(command, stdout=sink, check=True, cwd=package,
                           env={**os.environ, "PYTHONPATH": str(package)})

    t_cli = best_of(lambda: cli(root), args.repeat)
    t_start = best_of(lambda: subprocess.run([sys.executable, "-c", "import deathsphere.cli"], check=True,
                                             env={**os.environ, "PYTHONPATH": str(root)}), args.repeat)
    print(f"grid: {h.size} heights x {v.size} speeds = {h.size * v.size} turns asked, {api_rows} rows")
    print(f"API deathsphere.ride:          {t_api:7.3f} s")
    print(f"CLI ride --format csv:         {t_cli:7.3f} s  (start-up: import deathsphere.cli {t_start:.3f} s)")
    if args.before is not None:
        with tempfile.TemporaryDirectory() as tmp:
            archive = subprocess.run(["git", "-C", str(root), "archive", args.before, "deathsphere"], check=True,
                                     capture_output=True).stdout
            with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
                tar.extractall(Path(tmp, "old"), filter="data")
            t_old = best_of(lambda: cli(Path(tmp, "old")), args.repeat)
            cli(Path(tmp, "old"), Path(tmp, "old.csv"))
            cli(root, Path(tmp, "new.csv"))
            same = Path(tmp, "old.csv").read_bytes() == Path(tmp, "new.csv").read_bytes()
        print(f"CLI at {args.before}:      {t_old:7.3f} s  ({t_old / t_api:.2f}x the API; output "
              f"{'the same bytes' if same else 'DIFFERS'})")
    from deathsphere.api.two_wheeler_streams import two_wheeler_ride_sweep

    for size in args.chunk:
        t_sweep = best_of(lambda: two_wheeler_ride_sweep(**ask, height=height, speed=speed,
                                                         chunk_size=size).table(), args.repeat)
        print(f"streamed, chunk {size:>6}:        {t_sweep:7.3f} s  ({t_sweep / t_api:.2f}x the API)")
    print(f"CLI / API: {t_cli / t_api:.2f}x  (target <= 1.5x)")
    if args.drum:
        drum = dict(ask, surface="cylinder")
        drum_rows = len(deathsphere.ride(**drum, height=h[:, None], speed=v[None, :]))
        t_drum = best_of(lambda: deathsphere.ride(**drum, height=h[:, None], speed=v[None, :]), args.repeat)
        drum_command = command[:-2] + ["--surface", "cylinder", "--format", "csv"]
        t_drum_cli = best_of(lambda: subprocess.run(drum_command, stdout=subprocess.DEVNULL, check=True, cwd=root,
                                                    env={**os.environ, "PYTHONPATH": str(root)}), args.repeat)
        print(f"drum API deathsphere.ride:     {t_drum:7.3f} s  ({drum_rows} rows)")
        print(f"drum CLI ride --format csv:    {t_drum_cli:7.3f} s")
        print(f"drum / globe (API): {t_drum / t_api:.2f}x  (target <= 2x)")
        print(f"drum CLI / API: {t_drum_cli / t_drum:.2f}x  (target <= 1.5x)")
    print(f"load average: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
