"""``deathsphere orbit`` and ``deathsphere sweep``: horizontal orbits, one
batch at a time or streamed in chunks (:func:`deathsphere.api.sweep`,
:func:`deathsphere.api.orbit_input`)."""

from __future__ import annotations

import click

from deathsphere import api
from deathsphere.cli.base import OutputPath, choose_format, cli, finish, given, say_written, stream
from deathsphere.cli.options import (
    body_option,
    display_units,
    input_option,
    jobs_option,
    only_option,
    output_options,
    param_option,
    params_options,
    scheduler_option,
    setup_options,
    single,
    surface_options,
    stability_option,
    units_option,
)

ORBIT_TITLES = {
    "wheel": "Horizontal orbits of a wheel (McDonald 1993, eqs. 0, 29-36)",
    "sphere": "Horizontal orbits of a rolling sphere (McDonald 1993, eqs. 55-59)",
    "particle": "Horizontal orbits of a sliding particle (frictionless)",
}

#: The inputs of a horizontal orbit: grid axes on the command line.
AXES = ("theta", "alpha", "omega3", "omega", "speed", "com_speed")
#: The columns an --input file may name.
INPUT_FIELDS = "theta, alpha, omega3, omega, speed, com_speed, body, side, a, r, k, g, mu, max_g, height"


def one_hold(alpha, speed, com_speed, omega):
    """A wheel's orbit held one way: at most one of --alpha, --speed (the
    contact's), --com-speed (the centre's) and --omega, the refusal naming
    the second given."""
    holds = [name for name, values in (("alpha", alpha), ("speed", speed), ("com_speed", com_speed),
                                       ("omega", omega)) if values]
    if len(holds) > 1:
        raise click.UsageError(f"--{holds[1].replace('_', '-')}: give one of --alpha, --speed (the contact's), "
                               "--com-speed (the centre's) and --omega (the rate)")


def orbit_options(f):
    """The options orbit and sweep share: one vocabulary."""
    for option in reversed([
        params_options("theta", "alpha", "omega3", "omega", multiple=AXES),
        param_option("speed", multiple=True),
        param_option("com_speed", multiple=True),
        input_option(INPUT_FIELDS),
        body_option(),
        setup_options(multiple=("a", "r", "diameter", "k")),
        surface_options(),
        param_option("max_g"),
        only_option(api.STATUSES),
        stability_option(),
    ]):
        f = option(f)
    return f


def orbit_chunks(input, stability, only, options, **more):
    """The API call behind orbit and sweep: a file of requests or a grid."""
    if input is not None:
        for name in ("a", "r", "diameter", "k", "height", "turn_radius"):  # one value each with a file
            if name in options:
                options[name] = options[name] if len(options[name]) != 1 else options[name][0]
        return api.orbit_input(input, stability=stability, only=only or None, **options, **more)
    return api.sweep(stability=stability, only=only or None, **options, **more)


@cli.command("orbit", short_help="Steady horizontal orbits: rate, speed, spin, forces, friction, load.")
@orbit_options
@output_options()
@units_option()
def orbit_command(theta, alpha, omega3, omega, speed, com_speed, input, body, side, a, r, diameter, k, g, mu,
                  surface, wall_angle, wall_height, profile, height, turn_radius, max_g, only, stability, fmt, units):
    """Steady horizontal orbit(s): rate (eq. 29), speed, spin, forces, friction, load.

    All combinations of the --theta and --alpha values are evaluated.  Each
    row has a status: ok, no_fit (eq. 0/81), no_orbit (Omega^2 <= 0, eq. 29),
    no_contact (eq. 33/83), slips (needs more than --mu), over_g (more than
    --max-g) or invalid (bad input row); the reason column says why.

    \b
    Bodies: a wheel (default; needs one of --alpha, --speed, --com-speed and
    --omega), a rolling sphere (--body sphere; needs --omega3 or --omega;
    sec. 4-5) and a frictionless sliding particle (--body particle; needs
    only --theta).
    --side outside puts the body on the outside of the sphere (sec. 3, 5).

    \b
    Surfaces (docs/surfaces.md): the globe (default), --surface cylinder
    (the wall of death), cone (the well of death, a board track), plane or
    profile; a lane there is its --height above the lowest point (on flat
    ground its --turn-radius); a wheel's --speed, --com-speed or --omega
    gives every tilt there too (docs/surfaces.md eq. S2).

    \b
    Examples:
      deathsphere orbit --theta 60 --alpha 10
      deathsphere orbit --theta 60 --alpha 5:40:5 --mu 1 --format csv
      deathsphere orbit --theta 90 --speed 40km/h --diameter 16ft
      deathsphere orbit --theta 90 --com-speed 40km/h --diameter 16ft
      deathsphere orbit --body sphere --theta 60 --omega3 80
      deathsphere orbit --body particle --theta 120:170:10
      deathsphere orbit --surface cylinder --diameter 32ft --height 2 --alpha 10
      printf 'theta,alpha\\n60,10\\n90,25\\n' | deathsphere orbit --input -
    """
    one_hold(alpha, speed, com_speed, omega)
    options = given(theta=theta, alpha=alpha, omega3=omega3, omega=omega, speed=speed, com_speed=com_speed,
                    body=body, side=side, a=a, r=r, diameter=diameter, k=k, g=g, mu=mu, max_g=max_g, surface=surface,
                    wall_angle=wall_angle, wall_height=wall_height, profile=profile, height=height,
                    turn_radius=turn_radius)
    chunks = orbit_chunks(input, stability, only, options)
    title = "Horizontal orbits" if input is not None else ORBIT_TITLES[(body or "wheel").lower()]
    finish(stream(chunks, choose_format(fmt), label="orbits", title=title,
                  units=display_units(units, click.get_current_context().params)))


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


@cli.command("sweep", short_help="Stream a grid of orbits as CSV, NDJSON, JSON or Parquet.")
@orbit_options
@param_option("chunk_size", help="Orbits evaluated per chunk; memory stays flat whatever the grid size (above "
              "131072, ~256 MiB a chunk, N is clamped to it).")
@jobs_option()
@scheduler_option()
@single("--output", type=OutputPath(SWEEP_FORMATS), default=None, metavar="FILE",
        help="Write to FILE (.csv, .ndjson, .json or .parquet; the format follows the extension) instead "
             "of stdout.  Parquet needs the fast extra.")
@output_options(tuple(SWEEP_FORMATS))
def sweep_command(theta, alpha, omega3, omega, speed, com_speed, input, body, side, a, r, diameter, k, g, mu,
                  surface, wall_angle, wall_height, profile, height, turn_radius, max_g, only, stability, chunk_size,
                  jobs, scheduler, output, fmt):
    """Stream a grid of orbits (all combinations) as CSV, NDJSON, JSON or Parquet.

    The options of orbit; -a, -r, --diameter and -k may be grid axes too.
    Rows come out in grid order (a, r, k, theta, then speed, alpha, omega3
    or omega fastest) as they are computed, chunk by chunk, so output
    starts at once and memory stays flat.  A combination that is not
    allowed (r <= a inside) is an invalid row, like a bad --input row
    (exit status 1).  A progress bar shows on stderr when it is a terminal.

    \b
    Examples:
      deathsphere sweep --theta 5:175:1 --alpha 1:89:1 --only ok | head
      deathsphere sweep --theta 60 --alpha 1:50:1 -a 0.1 -a 0.3 --format ndjson
      deathsphere sweep --body sphere --theta 30:150:10 --omega3 60:120:20
      deathsphere sweep --surface plane --turn-radius 5:50:5 --alpha 45:85:5
      deathsphere sweep --theta 0:180:0.25 --alpha 0:90:0.25 --output grid.parquet
      deathsphere sweep --theta 0:180:0.1 --alpha 0:90:1 --scheduler tcp://h:8786
    """
    fmt = sweep_format(fmt, output)
    one_hold(alpha, speed, com_speed, omega)
    options = given(theta=theta, alpha=alpha, omega3=omega3, omega=omega, speed=speed, com_speed=com_speed,
                    body=body, side=side, a=a, r=r, diameter=diameter, k=k, g=g, mu=mu, max_g=max_g, surface=surface,
                    wall_angle=wall_angle, wall_height=wall_height, profile=profile, height=height,
                    turn_radius=turn_radius)
    chunks = orbit_chunks(input, stability, only, options, **given(chunk_size=chunk_size, jobs=jobs,
                                                                        scheduler=scheduler))
    tally = stream(chunks, fmt, label="sweep", output=output)
    if output is not None:
        say_written(output, rows=tally.rows)
    finish(tally)
