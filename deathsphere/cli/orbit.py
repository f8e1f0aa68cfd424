"""``deathsphere orbit`` and ``deathsphere sweep``: horizontal orbits, one
batch at a time or streamed in chunks."""

from __future__ import annotations

import math
import sys

import click
import numpy as np

from deathsphere.cli.base import (
    ORBIT_MAX_ROWS,
    body_options,
    choose_format,
    cli,
    emit,
    evaluate_in_chunks,
    make_setup,
    output_options,
    parse_angles,
    parse_rates,
    progress,
    stderr_console,
)
from deathsphere.constants import (
    BODIES,
    SIDES,
    STANDARD_GRAVITY,
    TABLE1_SPHERE_RADIUS,
    TABLE1_WHEEL_RADIUS,
)
from deathsphere.exitcodes import ExitCode
from deathsphere.grid import RangeError, grid_chunks, grid_size, parse_many
from deathsphere.inputs import InputError, read_requests
from deathsphere.model import Table, evaluate, make_requests


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
    elif body == "sphere":
        if alpha:
            raise click.UsageError("a sphere's tilt is fixed (theta - 90 deg); give --omega3 or --omega, not --alpha")
        if bool(omega3) == bool(omega):
            raise click.UsageError("give exactly one of --omega3 RAD_S and --omega RAD_S for a sphere")
    elif alpha or omega3 or omega:
        raise click.UsageError("a particle takes only --theta (no --alpha, --omega3 or --omega)")


@cli.command(short_help="Steady horizontal orbits: rate, speed, spin, forces, friction, g-load, stability.")
@click.option("--theta", multiple=True, metavar="DEG",
              help="Polar angle of the contact point from the upward vertical, 0..180 (90 = equator). "
                   "Repeat it or give start:stop:step.")
@click.option("--alpha", multiple=True, metavar="DEG",
              help="Tilt of the wheel's diameter through the contact point below the orbit plane, "
                   "-180..180. Repeat it or give start:stop:step.")
@click.option("--omega3", multiple=True, metavar="RAD_S",
              help="Sphere: spin about the contact normal (axis 3, centre to contact point); "
                   "eq. 55 gives up to two orbit rates, one row each (branch 0 slow, 1 fast).")
@click.option("--omega", multiple=True, metavar="RAD_S",
              help="The orbital rate Omega. Wheel: eq. 29 is solved for every tilt alpha giving it (one row "
                   "each). Sphere: signed about the upward vertical; omega3 follows from eq. 55.")
@click.option("--speed", multiple=True, metavar="M_S",
              help="Wheel: the centre speed v_cm; eq. 29 is solved for every tilt alpha giving it (one row each, "
                   "branch = root number in increasing alpha).")
@click.option("--input", "input_file", type=click.File("r"), default=None, metavar="FILE|-",
              help="CSV of requests, one orbit per row; its header names the options "
                   "(theta, alpha, a, r, k, g, mu, body, side, omega3, omega). '-' reads stdin.")
@body_options
@stability_option
@output_options()
def orbit(theta, alpha, omega3, omega, speed, input_file, body, side, a, r, k, g, mu, with_stability, fmt):
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
      deathsphere orbit --body sphere --theta 60 --omega3 40
      deathsphere orbit --body particle --theta 120:170:10
      printf 'theta,alpha\\n60,10\\n90,25\\n' | deathsphere orbit --input -
    """
    setup = make_setup(body, side, a, r, k, g, mu)
    fmt = choose_format(fmt)
    defaults = dict(body=setup.body, side=setup.side, a=setup.a, r=setup.r, k=k, g=setup.g, mu=setup.mu)
    if input_file is not None:
        for name, values in (("theta", theta), ("alpha", alpha), ("omega3", omega3), ("omega", omega),
                             ("speed", speed)):
            if len(values) > 1 or any(":" in v for v in values):
                raise click.UsageError(f"with --input, --{name} may give one default value, not a list or range")
        if theta:
            defaults["theta"] = float(parse_angles(theta, "theta")[0])
        if alpha:
            defaults["alpha"] = float(parse_angles(alpha, "alpha")[0])
        for name, values in (("omega3", omega3), ("omega", omega), ("speed", speed)):
            if values:
                defaults[name] = float(parse_rates(values, name)[0])
        try:
            req = read_requests(input_file, defaults, source=getattr(input_file, "name", "input"))
        except InputError as exc:
            raise click.UsageError(str(exc)) from None
    else:
        if not theta:
            raise click.UsageError("give --theta DEG (or --input FILE)")
        check_body_inputs(setup.body, alpha, omega3, omega, speed)
        axes = {
            "speed": parse_rates(speed, "speed", ORBIT_MAX_ROWS) if speed else np.array([math.nan]),
            "theta": parse_angles(theta, "theta", ORBIT_MAX_ROWS),
            "alpha": parse_angles(alpha, "alpha", ORBIT_MAX_ROWS) if alpha else np.array([math.nan]),
            "omega3": parse_rates(omega3, "omega3", ORBIT_MAX_ROWS) if omega3 else np.array([math.nan]),
            "omega": parse_rates(omega, "omega", ORBIT_MAX_ROWS) if omega else np.array([math.nan]),
        }
        if grid_size(axes) > ORBIT_MAX_ROWS:
            raise click.UsageError(f"{grid_size(axes)} orbits is more than `orbit` holds at once "
                                   f"({ORBIT_MAX_ROWS}); use `deathsphere sweep`, which streams")
        _, grid = next(grid_chunks(axes, grid_size(axes)))
        defaults.update(grid)
        req = make_requests(grid_size(axes), **defaults)
    table = evaluate_in_chunks(req, lambda sub: evaluate(sub, stability=with_stability), "orbits", CHUNK)
    emit([table], fmt, title=ORBIT_TITLES[setup.body] if input_file is None else "Horizontal orbits")
    if (table["status"] == "invalid").any():
        n_bad = int((table["status"] == "invalid").sum())
        stderr_console().print(f"deathsphere: {n_bad} input row(s) invalid; see their reason column",
                               style="yellow")
        sys.exit(ExitCode.INVALID_ROWS)


def parse_parameter(texts, name: str, default: float) -> np.ndarray:
    if not texts:
        return np.array([default])
    try:
        return parse_many(texts, f"-{name}")
    except RangeError as exc:
        raise click.BadParameter(str(exc).split(": ", 1)[-1], param_hint=f"'-{name}'") from None


STATUSES = ("ok", "no_fit", "no_orbit", "no_contact", "slips")


@cli.command()
@click.option("--theta", multiple=True, required=True, metavar="DEG",
              help="Polar angle(s) of the contact point, 0..180; values or start:stop:step.")
@click.option("--alpha", multiple=True, metavar="DEG", help="Tilt angle(s) of the wheel, -180..180.")
@click.option("-a", "--wheel-radius", "a_values", multiple=True, metavar="M",
              help=f"Body radius [m], values or ranges [default: {TABLE1_WHEEL_RADIUS}].")
@click.option("-r", "--sphere-radius", "r_values", multiple=True, metavar="M",
              help=f"Sphere radius [m], values or ranges [default: {TABLE1_SPHERE_RADIUS}].")
@click.option("-k", "--inertia", "k_values", multiple=True, metavar="K",
              help="Inertia factor(s) [default: 0.5 wheel, 0.4 sphere].")
@click.option("--body", type=click.Choice(BODIES, case_sensitive=False), default="wheel", show_default=True)
@click.option("--side", type=click.Choice(SIDES, case_sensitive=False), default="inside", show_default=True)
@click.option("-g", "--gravity", "g", type=float, default=STANDARD_GRAVITY, show_default=True, metavar="M_S2")
@click.option("--mu", type=float, default=math.inf, metavar="MU", help="Friction available [default: unlimited].")
@click.option("--only", multiple=True, type=click.Choice(STATUSES, case_sensitive=False),
              help="Keep only rows with this status (repeatable), e.g. --only ok.")
@click.option("--chunk-size", type=click.IntRange(1, 10_000_000), default=CHUNK, show_default=True,
              help="Orbits evaluated per chunk; memory stays flat whatever the grid size.")
@stability_option
@output_options(("csv", "ndjson", "json"))
def sweep(theta, alpha, a_values, r_values, k_values, body, side, g, mu, only, chunk_size, with_stability, fmt):
    """Stream a grid of orbits (all combinations) as CSV or NDJSON.

    Rows come out in grid order (a, r, k, theta, alpha; alpha fastest) as
    they are computed, chunk by chunk, so output starts at once and memory
    stays flat.  A progress bar shows on stderr when it is a terminal.

    \b
    Examples:
      deathsphere sweep --theta 5:175:1 --alpha 1:89:1 --only ok | sort -t, -k21,21g | head
      deathsphere sweep --theta 60 --alpha 1:50:1 -a 0.1 -a 0.3 -a 0.6 --format ndjson
    """
    body, side = body.lower(), side.lower()
    thetas = parse_angles(theta, "theta")
    if body == "wheel" and not alpha:
        raise click.UsageError("give --alpha DEG (values or start:stop:step) for a wheel")
    alphas = parse_angles(alpha, "alpha") if alpha else np.array([math.nan])
    axes = {
        "a": parse_parameter(a_values, "a", TABLE1_WHEEL_RADIUS),
        "r": parse_parameter(r_values, "r", TABLE1_SPHERE_RADIUS),
        "k": parse_parameter(k_values, "k", math.nan),
        "theta": thetas,
        "alpha": alphas,
    }
    for a in axes["a"]:
        for r in axes["r"]:
            for k in axes["k"]:
                make_setup(body, side, float(a), float(r), None if math.isnan(k) else float(k), g, mu)
    total = grid_size(axes)
    keep = {s.lower() for s in only}

    def chunks(advance):
        for first, grid in grid_chunks(axes, chunk_size):
            n = len(grid["theta"])
            req = make_requests(n, input_row=np.arange(first + 1, first + n + 1), body=body, side=side,
                                g=g, mu=mu, **grid)
            table = evaluate(req, stability=with_stability)
            if keep:
                mask = np.isin(table["status"], list(keep))
                table = Table({name: col[mask] for name, col in table.columns.items()})
            yield table
            advance(n)

    with progress("sweep", total) as bar:
        emit(chunks(bar.advance), (fmt or "csv").lower())
