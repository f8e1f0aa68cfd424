"""``deathsphere orbit`` and ``deathsphere sweep``: horizontal orbits, one
batch at a time or streamed in chunks (:func:`deathsphere.api.sweep`,
:func:`deathsphere.api.orbit_input`)."""

from __future__ import annotations

import click

from deathsphere import api
from deathsphere.cli.base import (
    OutputPath,
    body_options,
    choose_format,
    cli,
    finish,
    given,
    input_option,
    jobs_option,
    number_option,
    output_options,
    stability_option,
    stream,
    values_option,
)
from deathsphere.constants import BODIES, SIDES

ORBIT_TITLES = {
    "wheel": "Horizontal orbits of a wheel (McDonald 1993, eqs. 0, 29-36)",
    "sphere": "Horizontal orbits of a rolling sphere (McDonald 1993, eqs. 55-59)",
    "particle": "Horizontal orbits of a sliding particle (frictionless)",
}

THETA_HELP = ("Polar angle of the contact point from the upward vertical, 0..180 (90 = equator). "
              "Repeat it or give start:stop:step.")
ALPHA_HELP = ("Wheel: tilt of the wheel's diameter through the contact point below the orbit plane; any "
              "angle (205 = -155). Repeat it or give start:stop:step.")
OMEGA3_HELP = ("Sphere: spin about the contact normal (axis 3, centre to contact point); eq. 55 gives up to "
               "two orbit rates, one row each (branch 0 slow, 1 fast).")
OMEGA_HELP = ("The orbital rate Omega. Wheel (> 0): eq. 29 is solved for every tilt alpha giving it (one row "
              "each). Sphere: signed about the upward vertical; omega3 follows from eq. 55.")
SPEED_HELP = ("Wheel: the centre speed v_cm; eq. 29 is solved for every tilt alpha giving it (one row each, "
              "branch = root number in increasing alpha).")


@cli.command(short_help="Steady horizontal orbits: rate, speed, spin, forces, friction, g-load, stability.")
@values_option("theta", "DEG", THETA_HELP)
@values_option("alpha", "DEG", ALPHA_HELP)
@values_option("omega3", "RAD_S", OMEGA3_HELP)
@values_option("omega", "RAD_S", OMEGA_HELP)
@values_option("speed", "M_S", SPEED_HELP)
@input_option("theta, alpha, a, r, k, g, mu, body, side, omega3, omega, speed")
@body_options()
@stability_option()
@output_options()
def orbit(theta, alpha, omega3, omega, speed, input, body, side, a, r, k, g, mu, stability, fmt):
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
    options = given(theta=theta, alpha=alpha, omega3=omega3, omega=omega, speed=speed, body=body, side=side,
                    a=a, r=r, k=k, g=g, mu=mu)
    if input is not None:
        chunks, title = api.orbit_input(input, stability=stability, **options), "Horizontal orbits"
    else:
        chunks, title = api.sweep(stability=stability, **options), ORBIT_TITLES[body]
    finish(stream(chunks, choose_format(fmt), label="orbits", title=title))


#: What ``sweep --output`` writes, by extension (Parquet needs pyarrow, the fast extra).
SWEEP_FORMATS = {"csv": None, "ndjson": None, "json": None, "parquet": None}


def sweep_format(fmt: str | None, output: str | None) -> str:
    """The format of a sweep: as given, else the --output file's extension, else CSV."""
    ext = output.rsplit(".", 1)[-1].lower() if output else None
    fmt = (fmt or ext or "csv").lower()
    if fmt == "parquet" and output is None:
        raise click.UsageError("--format parquet writes a file: give --output FILE.parquet")
    if ext is not None and ext != fmt:
        raise click.UsageError(f"--format {fmt} does not match the --output file {output!r} (.{ext})")
    if fmt == "parquet":
        from deathsphere.writers import parquet

        if not parquet.parquet_available():
            raise click.UsageError("writing .parquet needs pyarrow: pip install 'deathsphere[fast]'")
    return fmt


@cli.command()
@values_option("theta", "DEG", "Polar angle(s) of the contact point, 0..180; values or start:stop:step.",
               required=True)
@values_option("alpha", "DEG", "Wheel: tilt angle(s), any angle (reduced to -180..180).")
@values_option("omega3", "RAD_S", "Sphere: spin(s) about the contact normal (eq. 55: up to two rows each).")
@values_option("omega", "RAD_S", "Sphere: signed orbital rate(s) instead of --omega3.")
@values_option("a", "M", f"Body radius [m], values or ranges [default: {api.A}].", ("-a", "--wheel-radius"))
@values_option("r", "M", f"Sphere radius [m], values or ranges [default: {api.R}].", ("-r", "--sphere-radius"))
@values_option("k", "K", "Inertia factor(s) [default: 0.5 wheel, 0.4 sphere].", ("-k", "--inertia"))
@click.option("--body", type=click.Choice(BODIES, case_sensitive=False), default="wheel", show_default=True)
@click.option("--side", type=click.Choice(SIDES, case_sensitive=False), default="inside", show_default=True)
@number_option("g", "M_S2", "Gravitational acceleration [m/s^2].", ("-g", "--gravity"), str(api.G))
@number_option("mu", "MU", "Friction available.", None, "unlimited")
@click.option("--only", multiple=True, type=click.Choice(api.STATUSES, case_sensitive=False),
              help="Keep only rows with this status (repeatable), e.g. --only ok.")
@number_option("chunk_size", "N", "Orbits evaluated per chunk; memory stays flat whatever the grid size "
               "(above 131072, ~256 MiB a chunk, N is clamped to it; the output is the same).",
               None, str(api.CHUNK))
@jobs_option("evaluating chunks")
@click.option("--output", type=OutputPath(SWEEP_FORMATS), default=None, metavar="FILE",
              help="Write to FILE (.csv, .ndjson, .json or .parquet; the format follows the "
                   "extension) instead of stdout.  Parquet needs the fast extra.")
@stability_option()
@output_options(tuple(SWEEP_FORMATS))
def sweep(theta, alpha, omega3, omega, a, r, k, body, side, g, mu, only, chunk_size, jobs, output, stability,
          fmt):
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
    chunks = api.sweep(stability=stability, **given(theta=theta, alpha=alpha, omega3=omega3, omega=omega, a=a,
                                                    r=r, k=k, body=body, side=side, g=g, mu=mu, only=only,
                                                    chunk_size=chunk_size, jobs=jobs))
    finish(stream(chunks, fmt, label="sweep", output=output))
