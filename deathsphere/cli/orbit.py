"""``deathsphere orbit`` and ``deathsphere sweep``: horizontal orbits, one
batch at a time or streamed in chunks."""

from __future__ import annotations

import math
from collections import deque
from functools import partial

import click
import numpy as np

from deathsphere.cli.base import (
    OutputPath,
    Quantity,
    Values,
    axis,
    body_options,
    choose_format,
    cli,
    finish,
    input_option,
    make_setup,
    open_requests,
    output_options,
    run_batches,
)
from deathsphere.constants import (
    BODIES,
    SIDES,
    STANDARD_GRAVITY,
    TABLE1_SPHERE_RADIUS,
    TABLE1_WHEEL_RADIUS,
)
from deathsphere.render import compiled
from deathsphere.grid import RangeError, grid_chunks, grid_size
from deathsphere.model import COLUMNS, REQUEST_FIELDS, Table, evaluate, make_requests

#: Output columns that echo an input (read back under these names); every
#: other output column is ignored when a result CSV is fed to --input.
ECHO_COLUMNS = ("body", "side", "theta_deg", "alpha_deg", "a_m", "r_m", "k", "g_m_s2", "mu_available")
IGNORED_COLUMNS = tuple(c for c in COLUMNS if c not in ECHO_COLUMNS)


def stability_option(f):
    return click.option(
        "--stability/--no-stability", "with_stability", default=True, show_default=True,
        help="Fill the stability columns from the exact linearisation (docs/stability.md); "
             "--no-stability leaves them empty and runs faster.")(f)


#: Orbits per evaluation: a cache-friendly size (docs/performance.md), and a
#: progress bar ticks per chunk.
CHUNK = 16384

ORBIT_TITLES = {
    "wheel": "Horizontal orbits of a wheel (McDonald 1993, eqs. 0, 29-36)",
    "sphere": "Horizontal orbits of a rolling sphere (McDonald 1993, eqs. 55-59)",
    "particle": "Horizontal orbits of a sliding particle (frictionless)",
}


def check_body_inputs(body: str, alpha, omega3, omega, speed) -> None:
    """Which of --alpha, --speed, --omega3, --omega each body takes (usage error if wrong)."""
    if body != "wheel" and speed:
        raise click.UsageError("--speed is for a wheel (eq. 29 is solved for alpha)")
    if body == "wheel":
        if omega3:
            raise click.UsageError("--omega3 is for --body sphere; a wheel takes --alpha, --speed or --omega")
        if (bool(alpha) + bool(speed) + bool(omega)) != 1:
            raise click.UsageError("give exactly one of --alpha DEG, --speed M_S and --omega RAD_S for a wheel "
                                   "(or --input FILE)")
        if any(min(seg.first, seg.last) <= 0 for seg in omega):
            raise click.UsageError("a wheel's --omega is its rate about the vertical: it must be > 0 rad/s")
    elif body == "sphere":
        if alpha:
            raise click.UsageError("a sphere's tilt is fixed (theta - 90 deg); give --omega3 or --omega, not --alpha")
        if bool(omega3) == bool(omega):
            raise click.UsageError("give exactly one of --omega3 RAD_S and --omega RAD_S for a sphere")
    elif alpha or omega3 or omega:
        raise click.UsageError("a particle takes only --theta (no --alpha, --omega3 or --omega)")


def grid_batches(axes: dict, chunk: int, **fixed):
    """``(n, request)`` per chunk of the cartesian grid of ``axes`` (lazy),
    rows numbered from 1 in grid order (its size is checked by :func:`_total`
    before any work)."""
    for first, grid in grid_chunks(axes, chunk):
        n = len(grid["theta"])
        yield n, make_requests(n, input_row=np.arange(first + 1, first + n + 1), **fixed, **grid)


def input_batches(reader, chunk: int, make=make_requests):
    """``(n, request)`` per chunk of ``--input`` rows (streamed); a file with
    a header and no rows gives one empty batch, so the output still has its
    header."""
    empty = True
    for part in reader.chunks(chunk):
        n = len(part.input_row)
        empty = False
        yield n, make(n, invalid=part.invalid, input_row=part.input_row, **part.values)
    if empty:
        yield 0, make(0, **{name: np.empty(0, dtype=object if name in ("body", "side") else float)
                            for name in reader.fields})


def _total(axes: dict) -> int:
    try:
        return grid_size(axes)
    except RangeError as exc:
        raise click.UsageError(str(exc)) from None


def _one_default(name: str, segments) -> float | None:
    if not segments:
        return None
    if len(segments) > 1 or segments[0].n > 1:
        raise click.UsageError(f"with --input, --{name} may give one default value, not a list or range")
    return segments[0].first


@cli.command(short_help="Steady horizontal orbits: rate, speed, spin, forces, friction, g-load, stability.")
@click.option("--theta", multiple=True, type=Values("theta"), metavar="DEG",
              help="Polar angle of the contact point from the upward vertical, 0..180 (90 = equator). "
                   "Repeat it or give start:stop:step.")
@click.option("--alpha", multiple=True, type=Values("alpha"), metavar="DEG",
              help="Tilt of the wheel's diameter through the contact point below the orbit plane; any "
                   "angle (205 = -155). Repeat it or give start:stop:step.")
@click.option("--omega3", multiple=True, type=Values("omega3"), metavar="RAD_S",
              help="Sphere: spin about the contact normal (axis 3, centre to contact point); "
                   "eq. 55 gives up to two orbit rates, one row each (branch 0 slow, 1 fast).")
@click.option("--omega", multiple=True, type=Values("omega"), metavar="RAD_S",
              help="The orbital rate Omega. Wheel (> 0): eq. 29 is solved for every tilt alpha giving it "
                   "(one row each). Sphere: signed about the upward vertical; omega3 follows from eq. 55.")
@click.option("--speed", multiple=True, type=Values("speed"), metavar="M_S",
              help="Wheel: the centre speed v_cm; eq. 29 is solved for every tilt alpha giving it (one row each, "
                   "branch = root number in increasing alpha).")
@input_option("theta, alpha, a, r, k, g, mu, body, side, omega3, omega, speed")
@body_options
@stability_option
@output_options()
def orbit(theta, alpha, omega3, omega, speed, input_path, body, side, a, r, k, g, mu, with_stability, fmt):
    """Steady horizontal orbit(s): rate (eq. 29), speed, spin, forces, friction, g-load.

    All combinations of the --theta and --alpha values are evaluated.  Each
    row has a status: ok, no_fit (eq. 0/81), no_orbit (Omega^2 <= 0, eq. 29),
    no_contact (eq. 33/83), slips (needs more than --mu) or invalid (bad
    input row); the reason column says why.

    \b
    Bodies: a wheel (default; needs --alpha), a rolling sphere (--body
    sphere; needs --omega3 or --omega; sec. 4-5) and a frictionless sliding
    particle (--body particle; needs only --theta).  --side outside puts the
    body on the outside of the sphere (sec. 3, 5).

    \b
    Examples:
      deathsphere orbit --theta 60 --alpha 10
      deathsphere orbit --theta 60 --alpha 5:40:5 --mu 1 --format csv
      deathsphere orbit --theta 60 --speed 7     every tilt alpha at 7 m/s (eq. 29 solved)
      deathsphere orbit --body sphere --theta 60 --omega3 80
      deathsphere orbit --body particle --theta 120:170:10
      printf 'theta,alpha\\n60,10\\n90,25\\n' | deathsphere orbit --input -
    """
    setup = make_setup(body, side, a, r, k, g, mu)
    fmt = choose_format(fmt)
    defaults = dict(body=setup.body, side=setup.side, a=setup.a, r=setup.r, k=k, g=setup.g, mu=setup.mu)
    if input_path is not None:
        for name, values in (("theta", theta), ("alpha", alpha), ("omega3", omega3), ("omega", omega),
                             ("speed", speed)):
            value = _one_default(name, values)
            if value is not None:
                defaults[name] = value
        reader = open_requests(input_path, REQUEST_FIELDS, defaults, ignore=IGNORED_COLUMNS)
        batches, total, title = input_batches(reader, CHUNK), None, "Horizontal orbits"
    else:
        if not theta:
            raise click.UsageError("give --theta DEG (or --input FILE)")
        check_body_inputs(setup.body, alpha, omega3, omega, speed)
        axes = {"speed": axis(speed), "theta": axis(theta), "alpha": axis(alpha), "omega3": axis(omega3),
                "omega": axis(omega)}
        batches, total = grid_batches(axes, CHUNK, **defaults), _total(axes)
        title = ORBIT_TITLES[setup.body]
    tally = run_batches(batches, lambda req: evaluate(req, stability=with_stability), fmt, label="orbits",
                        total=total, title=title)
    finish(tally)


STATUSES = ("ok", "no_fit", "no_orbit", "no_contact", "slips", "invalid")

#: What ``sweep --output`` writes, by extension.
SWEEP_FORMATS = ("csv", "ndjson", "json", "parquet")


class SweepOutput(OutputPath):
    """``sweep --output``: a .csv, .ndjson, .json or .parquet file; Parquet
    needs pyarrow, from the ``fast`` extra (refused before any work)."""

    def __init__(self):
        super().__init__({ext: None for ext in SWEEP_FORMATS})

    def convert(self, value, param, ctx):
        path = super().convert(value, param, ctx)
        if path.lower().endswith(".parquet") and not compiled.parquet_available():
            raise click.UsageError("writing .parquet needs pyarrow: pip install 'deathsphere[fast]'")
        return path


def sweep_format(fmt: str | None, output: str | None) -> str:
    """The format of a sweep: as given, else the --output file's extension, else CSV."""
    ext = output.rsplit(".", 1)[-1].lower() if output else None
    fmt = (fmt or ext or "csv").lower()
    if fmt == "parquet" and output is None:
        raise click.UsageError("--format parquet writes a file: give --output FILE.parquet")
    if ext is not None and ext != fmt:
        raise click.UsageError(f"--format {fmt} does not match the --output file {output!r} (.{ext})")
    return fmt


def _evaluate_chunk(req: dict, stability: bool) -> Table:
    return evaluate(req, stability=stability)


def parallel_results(batches, work, jobs: int):
    """``(n, result)`` per batch, ``work(request)`` evaluated on ``jobs``
    processes and handed back in input order, so the output is that of one
    process.  At most two chunks per process are in flight: enough to keep
    every process busy while the writer catches up, and memory stays flat."""
    from concurrent.futures import ProcessPoolExecutor

    pending = deque()
    pool = ProcessPoolExecutor(jobs)
    try:
        for n, req in batches:
            pending.append((n, pool.submit(work, req)))
            if len(pending) >= 2 * jobs:
                n, done = pending.popleft()
                yield n, done.result()
        while pending:
            n, done = pending.popleft()
            yield n, done.result()
    finally:
        # a reader gone (`| head`), a failed write or Ctrl-C: drop queued chunks
        pool.shutdown(wait=True, cancel_futures=True)


@cli.command()
@click.option("--theta", multiple=True, required=True, type=Values("theta"), metavar="DEG",
              help="Polar angle(s) of the contact point, 0..180; values or start:stop:step.")
@click.option("--alpha", multiple=True, type=Values("alpha"), metavar="DEG",
              help="Wheel: tilt angle(s), any angle (reduced to -180..180).")
@click.option("--omega3", multiple=True, type=Values("omega3"), metavar="RAD_S",
              help="Sphere: spin(s) about the contact normal (eq. 55: up to two rows each).")
@click.option("--omega", multiple=True, type=Values("omega"), metavar="RAD_S",
              help="Sphere: signed orbital rate(s) instead of --omega3.")
@click.option("-a", "--wheel-radius", "a_values", multiple=True, type=Values("a"), metavar="M",
              help=f"Body radius [m], values or ranges [default: {TABLE1_WHEEL_RADIUS}].")
@click.option("-r", "--sphere-radius", "r_values", multiple=True, type=Values("r"), metavar="M",
              help=f"Sphere radius [m], values or ranges [default: {TABLE1_SPHERE_RADIUS}].")
@click.option("-k", "--inertia", "k_values", multiple=True, type=Values("k"), metavar="K",
              help="Inertia factor(s) [default: 0.5 wheel, 0.4 sphere].")
@click.option("--body", type=click.Choice(BODIES, case_sensitive=False), default="wheel", show_default=True)
@click.option("--side", type=click.Choice(SIDES, case_sensitive=False), default="inside", show_default=True)
@click.option("-g", "--gravity", "g", type=Quantity("g"), default=STANDARD_GRAVITY, show_default=True,
              metavar="M_S2")
@click.option("--mu", type=Quantity("mu"), default=math.inf, metavar="MU", help="Friction available [default: unlimited].")
@click.option("--only", multiple=True, type=click.Choice(STATUSES, case_sensitive=False),
              help="Keep only rows with this status (repeatable), e.g. --only ok.")
@click.option("--chunk-size", type=click.IntRange(1, 10_000_000), default=CHUNK, show_default=True,
              help="Orbits evaluated per chunk; memory stays flat whatever the grid size.")
@click.option("--jobs", type=click.IntRange(1, 256), default=1, show_default=True,
              help="Processes evaluating chunks; the output is the same as with one.")
@click.option("--output", type=SweepOutput(), default=None, metavar="FILE",
              help="Write to FILE (.csv, .ndjson, .json or .parquet; the format follows the "
                   "extension) instead of stdout.  Parquet needs the fast extra.")
@stability_option
@output_options(SWEEP_FORMATS)
def sweep(theta, alpha, omega3, omega, a_values, r_values, k_values, body, side, g, mu, only, chunk_size,
          jobs, output, with_stability, fmt):
    """Stream a grid of orbits (all combinations) as CSV, NDJSON, JSON or Parquet.

    Rows come out in grid order (a, r, k, theta, then alpha, omega3 or
    omega fastest) as they are computed, chunk by chunk, so output starts
    at once and memory stays flat.  A combination that is not allowed
    (r <= a inside) is an invalid row, like a bad --input row (exit status 1).
    A progress bar shows on stderr when it is a terminal.

    \b
    Examples:
      deathsphere sweep --theta 5:175:1 --alpha 1:89:1 --only ok | sort -t, -k21,21g | head
      deathsphere sweep --theta 60 --alpha 1:50:1 -a 0.1 -a 0.3 -a 0.6 --format ndjson
      deathsphere sweep --body sphere --theta 30:150:10 --omega3 60:120:20
      deathsphere sweep --theta 0:180:0.25 --alpha 0:90:0.25 --jobs 2 --output grid.parquet
    """
    fmt = sweep_format(fmt, output)
    body, side = body.lower(), side.lower()
    if body == "wheel" and not alpha:
        raise click.UsageError("give --alpha DEG (values or start:stop:step) for a wheel")
    check_body_inputs(body, alpha, omega3, omega, ())
    axes = {"a": axis(a_values, TABLE1_WHEEL_RADIUS), "r": axis(r_values, TABLE1_SPHERE_RADIUS),
            "k": axis(k_values), "theta": axis(theta), "alpha": axis(alpha), "omega3": axis(omega3),
            "omega": axis(omega)}
    keep = {s.lower() for s in only}

    def keep_rows(table):
        mask = np.isin(table["status"], list(keep))
        return Table({name: col[mask] for name, col in table.columns.items()})

    total = _total(axes)
    batches = grid_batches(axes, chunk_size, body=body, side=side, g=g, mu=mu)
    work = partial(_evaluate_chunk, stability=with_stability)
    if jobs > 1:
        batches, work = parallel_results(batches, work, jobs), None
    tally = run_batches(batches, work or (lambda table: table), fmt, label="sweep", total=total,
                        keep=keep_rows if keep else None, output=output)
    finish(tally)
