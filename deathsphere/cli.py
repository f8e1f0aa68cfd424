"""The ``deathsphere`` command line: parse options, call the model, render.

No physics here.  Every command shares :func:`body_options` and
:func:`output_options`; usage errors become one line on stderr with exit
status 2 (:func:`main`), results go to stdout, diagnostics to stderr.
"""

from __future__ import annotations

import math
import os
import sys

import click
import numpy as np
from rich.console import Console

from deathsphere import __version__
from deathsphere.constants import BODIES, SIDES, STANDARD_GRAVITY, TABLE1_SPHERE_RADIUS, TABLE1_WHEEL_RADIUS
from deathsphere.exitcodes import ExitCode
from deathsphere.grid import RangeError, grid_chunks, grid_size, parse_many
from deathsphere.inputs import InputError, read_requests, read_table
from deathsphere.model import Setup, Table, angle_problem, evaluate, make_requests
from deathsphere.render import FORMATS, write_csv, write_json, write_ndjson, write_rich_table

CONTEXT = {"help_option_names": ["-h", "--help"], "max_content_width": 100}

#: Largest grid ``orbit`` evaluates in one go; bigger ones belong to ``sweep``.
ORBIT_MAX_ROWS = 1_000_000


ORBIT_TITLES = {
    "wheel": "Horizontal orbits of a wheel (McDonald 1993, eqs. 0, 29-36)",
    "sphere": "Horizontal orbits of a rolling sphere (McDonald 1993, eqs. 55-59)",
    "particle": "Horizontal orbits of a sliding particle (frictionless)",
}


def stdout_console() -> Console:
    # rich honours NO_COLOR and TERM=dumb itself
    return Console(highlight=False)


def stderr_console() -> Console:
    return Console(stderr=True, highlight=False)


# ---------------------------------------------------------------------------
# shared options


def output_options(formats=FORMATS):
    def decorator(f):
        return click.option(
            "--format", "fmt", type=click.Choice(formats, case_sensitive=False), default=None,
            help="Output format [default: table on a terminal, csv when piped].")(f)
    return decorator


def body_options(f):
    options = [
        click.option("--body", type=click.Choice(BODIES, case_sensitive=False), default="wheel",
                     show_default=True, help="Rolling body."),
        click.option("--side", type=click.Choice(SIDES, case_sensitive=False), default="inside",
                     show_default=True, help="Body inside or outside the fixed sphere."),
        click.option("-a", "--wheel-radius", "a", type=float, default=TABLE1_WHEEL_RADIUS, show_default=True,
                     metavar="M", help="Body radius a [m]."),
        click.option("-r", "--sphere-radius", "r", type=float, default=TABLE1_SPHERE_RADIUS, show_default=True,
                     metavar="M", help="Fixed sphere radius r [m]."),
        click.option("-k", "--inertia", "k", type=float, default=None, metavar="K",
                     help="Inertia factor k: I11 = 2 k m a^2 for a wheel, I = k m a^2 for a sphere "
                          "[default: 0.5 wheel, 0.4 sphere]."),
        click.option("-g", "--gravity", "g", type=float, default=STANDARD_GRAVITY, show_default=True,
                     metavar="M_S2", help="Gravitational acceleration [m/s^2]."),
        click.option("--mu", type=float, default=math.inf, metavar="MU",
                     help="Friction coefficient available; orbits needing more have status 'slips' "
                          "[default: unlimited]."),
    ]
    for option in reversed(options):
        f = option(f)
    return f


def make_setup(body, side, a, r, k, g, mu) -> Setup:
    try:
        return Setup(body=body.lower(), side=side.lower(), a=a, r=r, k=k, g=g, mu=mu)
    except ValueError as exc:
        raise click.UsageError(str(exc)) from None


def parse_angles(texts, name: str, max_values: int | None = None):
    try:
        values = parse_many(texts, f"--{name}", max_values)
    except RangeError as exc:
        raise click.BadParameter(str(exc).split(": ", 1)[-1], param_hint=f"'--{name}'") from None
    for v in values:
        problem = angle_problem(name, float(v))
        if problem:
            raise click.BadParameter(problem, param_hint=f"'--{name}'")
    return values


def parse_rates(texts, name: str, max_values: int | None = None):
    try:
        return parse_many(texts, f"--{name}", max_values)
    except RangeError as exc:
        raise click.BadParameter(str(exc).split(": ", 1)[-1], param_hint=f"'--{name}'") from None


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


def choose_format(fmt: str | None) -> str:
    if fmt:
        return fmt.lower()
    return "table" if sys.stdout.isatty() else "csv"


def emit(chunks, fmt: str, title: str | None = None) -> int:
    """Write tables in the chosen format to stdout; returns the row count."""
    out = sys.stdout
    if fmt == "csv":
        return write_csv(chunks, out)
    if fmt == "json":
        return write_json(chunks, out)
    if fmt == "ndjson":
        return write_ndjson(chunks, out)
    tables = list(chunks)
    table = tables[0] if len(tables) == 1 else Table({n: np.concatenate([t[n] for t in tables]) for n in tables[0].names})
    return write_rich_table(table, stdout_console(), title)


class DeathsphereGroup(click.Group):
    """A click group whose ``main`` turns every usage error into one line on
    stderr with exit status 2, and a closed pipe or Ctrl-C into a quiet stop.
    (Done here rather than in a wrapper so that click's CliRunner sees it.)"""

    def main(self, args=None, prog_name=None, complete_var=None, standalone_mode=True, **extra):
        try:
            code = super().main(args=args, prog_name=prog_name or "deathsphere",
                                complete_var=complete_var, standalone_mode=False, **extra)
        except click.exceptions.UsageError as exc:
            command = exc.ctx.command_path if exc.ctx is not None else "deathsphere"
            fail(f"{one_line(exc.format_message())} (see '{command} --help')")
        except click.exceptions.ClickException as exc:  # e.g. a missing --input file
            fail(one_line(exc.format_message()))
        except (click.exceptions.Abort, KeyboardInterrupt):
            click.echo("deathsphere: interrupted", err=True)
            sys.exit(130)
        except BrokenPipeError:
            # the reader went away (e.g. `| head`): stop quietly, and keep
            # Python from complaining when it flushes stdout at exit
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            sys.exit(ExitCode.OK)
        sys.exit(code or 0)


def one_line(message: str) -> str:
    return " ".join(message.split())


def fail(message: str):
    click.echo(f"deathsphere: error: {message}", err=True)
    sys.exit(ExitCode.USAGE)


# ---------------------------------------------------------------------------
# commands


@click.group(cls=DeathsphereGroup, context_settings=CONTEXT)
@click.version_option(__version__, "-V", "--version", prog_name="deathsphere")
def cli():
    """Orbits of a wheel or sphere rolling without slipping on a fixed sphere:
    the motorcycle "globe of death" as physics, after K. T. McDonald,
    "Circular Orbits Inside the Sphere of Death" (1993).

    \b
    Examples:
      deathsphere orbit --theta 60 --alpha 10          one orbit, every quantity
      deathsphere orbit --theta 30:90:15 --alpha 10 --format csv
      deathsphere vertical --theta 90 --v-top 6         a vertical loop
      deathsphere orbit --body sphere --theta 60 --omega3 40
      deathsphere sweep --theta 5:175:1 --alpha 1:89:1 --only ok
      deathsphere map                                   the allowed region (paper's figure)
      deathsphere limits --mu 1 --max-g 5               the highest orbit a rider can hold
      deathsphere table1                                the paper's Table 1, checked
      deathsphere verify                                every claim of the paper, checked
      deathsphere simulate --theta 60 --alpha 10        integrate the exact equations
    """


@cli.command()
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
@output_options()
def orbit(theta, alpha, omega3, omega, speed, input_file, body, side, a, r, k, g, mu, fmt):
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
    table = evaluate(req)
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
@click.option("--chunk-size", type=click.IntRange(1, 10_000_000), default=16384, show_default=True,
              help="Orbits evaluated per chunk; memory stays flat whatever the grid size.")
@output_options(("csv", "ndjson", "json"))
def sweep(theta, alpha, a_values, r_values, k_values, body, side, g, mu, only, chunk_size, fmt):
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
            table = evaluate(req)
            if keep:
                mask = np.isin(table["status"], list(keep))
                table = Table({name: col[mask] for name, col in table.columns.items()})
            yield table
            advance(n)

    fmt = (fmt or "csv").lower()
    if sys.stderr.isatty():
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

        with Progress(TextColumn("sweep"), BarColumn(), MofNCompleteColumn(), TimeRemainingColumn(),
                      console=stderr_console(), transient=True) as progress:
            task = progress.add_task("sweep", total=total)
            emit(chunks(lambda n: progress.advance(task, n)), fmt)
    else:
        emit(chunks(lambda n: None), fmt)


@cli.command("vertical")
@click.option("--theta", multiple=True, metavar="DEG",
              help="Cone angle of the orbit about the horizontal axis, 0..180 (90 = a vertical great circle).")
@click.option("--v-top", "v_top", multiple=True, metavar="M_S", help="Speed of the wheel's centre at the top.")
@click.option("--phidot-top", "phidot_top", multiple=True, metavar="RAD_S", help="Orbital rate at the top.")
@click.option("--side", type=click.Choice(SIDES, case_sensitive=False), default="inside", show_default=True,
              help="Wheel inside or outside the sphere (outside it leaves the surface, eq. 82).")
@click.option("-a", "--wheel-radius", "a", type=float, default=TABLE1_WHEEL_RADIUS, show_default=True, metavar="M")
@click.option("-r", "--sphere-radius", "r", type=float, default=TABLE1_SPHERE_RADIUS, show_default=True,
              metavar="M")
@click.option("-k", "--inertia", "k", type=float, default=0.5, show_default=True, metavar="K",
              help="Inertia factor, I11 = 2 k m a^2.")
@click.option("-g", "--gravity", "g", type=float, default=STANDARD_GRAVITY, show_default=True, metavar="M_S2")
@click.option("--mu", type=float, default=math.inf, metavar="MU", help="Friction available [default: unlimited].")
@click.option("--points", type=click.IntRange(2, 1_000_000), default=None, metavar="N",
              help="Print the orbit point by point at N azimuths phi from the top (0) to 360 deg.")
@click.option("--input", "input_file", type=click.File("r"), default=None, metavar="FILE|-",
              help="CSV of requests (theta, v_top or phidot_top, side, a, r, k, g, mu); '-' reads stdin.")
@output_options()
def vertical_command(theta, v_top, phidot_top, side, a, r, k, g, mu, points, input_file, fmt):
    """Vertical orbit of a wheel: contact all round (eq. 28a), forces and friction (eqs. 27-28b).

    Reports the least top speed for contact, the normal force and friction
    needed round the orbit, the worst point (where mu peaks) and the lap time
    (an elliptic integral).  Outside the sphere no vertical orbit closes: the
    row gives where the wheel leaves the surface (from rest: eq. 82).
    Rates and speeds are at the top; forces and mu_required at the worst point.

    \b
    Examples:
      deathsphere vertical --theta 90 --v-top 6
      deathsphere vertical --theta 60 --v-top 4:8:1 --mu 1.5
      deathsphere vertical --theta 90 --v-top 6 --points 13 --format csv
      deathsphere vertical --side outside --theta 90 --v-top 0
    """
    from deathsphere.vertical import VERTICAL_FIELDS, evaluate_vertical, vertical_points, vertical_requests

    setup = make_setup("wheel", side, a, r, k, g, mu)
    fmt = choose_format(fmt)
    defaults = dict(side=setup.side, a=setup.a, r=setup.r, k=setup.k, g=setup.g, mu=setup.mu)
    if input_file is not None:
        if theta or v_top or phidot_top:
            raise click.UsageError("with --input, give theta and v_top/phidot_top as CSV columns")
        try:
            n, values, invalid = read_table(input_file, defaults, getattr(input_file, "name", "input"),
                                            VERTICAL_FIELDS)
        except InputError as exc:
            raise click.UsageError(str(exc)) from None
        req = vertical_requests(n, invalid=invalid, **values)
    else:
        if not theta:
            raise click.UsageError("give --theta DEG (or --input FILE)")
        if bool(v_top) == bool(phidot_top):
            raise click.UsageError("give exactly one of --v-top M_S and --phidot-top RAD_S")
        speeds = parse_rates(v_top, "v-top") if v_top else parse_rates(phidot_top, "phidot-top")
        if v_top and (speeds < 0).any():
            raise click.BadParameter("the top speed must be >= 0 m/s", param_hint="'--v-top'")
        axes = {"theta": parse_angles(theta, "theta", ORBIT_MAX_ROWS), "speed": speeds}
        if grid_size(axes) > ORBIT_MAX_ROWS:
            raise click.UsageError(f"{grid_size(axes)} orbits is more than `vertical` holds at once")
        _, grid = next(grid_chunks(axes, grid_size(axes)))
        key = "v_top" if v_top else "phidot_top"
        req = vertical_requests(len(grid["theta"]), theta=grid["theta"], **{key: grid["speed"]}, **defaults)
    if points:
        table = vertical_points(req, points)
        emit([table], fmt, title="Vertical orbit point by point (eqs. 27, 28, 28b; phi from the top)")
    else:
        table = evaluate_vertical(req)
        if fmt == "table":
            from deathsphere.render import vertical_view

            stdout_console().print(vertical_view(table))
        else:
            emit([table], fmt)
    if (table["status"] == "invalid").any():
        stderr_console().print("deathsphere: some input rows are invalid; see their reason column", style="yellow")
        sys.exit(ExitCode.INVALID_ROWS)


@cli.command("map")
@click.option("--a-over-r", "a_over_r", type=float, default=0.1, show_default=True,
              help="Wheel radius over sphere radius (the paper's figure: 0.1).")
@click.option("-k", "--inertia", "k", type=float, default=0.5, show_default=True, metavar="K")
@click.option("--side", type=click.Choice(SIDES, case_sensitive=False), default="inside", show_default=True)
@click.option("--mu", type=float, default=math.inf, metavar="MU", help="Also draw the friction limit mu_required = MU.")
@click.option("--max-g", "max_g", type=float, default=math.inf, metavar="G",
              help="Also draw the g-load limit accel_g = G.")
@click.option("--output", type=click.Path(dir_okay=False, writable=True), default=None, metavar="FILE",
              help="Write the figure to FILE (.png, .svg or .pdf); needs pip install 'deathsphere[plot]'.")
@click.option("--step", type=click.FloatRange(0.001, 10.0), default=0.5, show_default=True, metavar="DEG",
              help="theta step of the boundary data (--format csv/json).")
@output_options()
def map_command(a_over_r, k, side, mu, max_g, output, step, fmt):
    """The allowed (theta, alpha) region of horizontal wheel orbits: the paper's figure.

    Bounded by eq. (0) (the wheel fits), eq. (29) (Omega^2 > 0) and eq. (33)
    (contact); outside the sphere by eqs. (81), (29), (83).  With --mu or
    --max-g the friction and g-load limits are drawn too.  On a terminal a
    character plot; --format csv/json prints the boundary curves as data
    (root-found to 1e-9 rad); --output writes a figure.

    \b
    Examples:
      deathsphere map
      deathsphere map --mu 1 --max-g 5
      deathsphere map --format csv --step 1 | head
      deathsphere map --output map.png
    """
    side = side.lower()
    if not (math.isfinite(a_over_r) and 0 < a_over_r and (a_over_r < 1 or side == "outside")):
        raise click.BadParameter("must be > 0 (and < 1 inside the sphere)", param_hint="'--a-over-r'")
    make_setup("wheel", side, a_over_r, 1.0, k, STANDARD_GRAVITY, mu)
    if not max_g > 0:
        raise click.BadParameter("must be > 0 (inf: no limit)", param_hint="'--max-g'")
    outside = side == "outside"
    if output is not None:
        from deathsphere.plot import PlotExtraMissing, plot_map

        try:
            plot_map(a_over_r, 1.0, k, outside=outside, mu=mu, max_g=max_g, output=output)
        except PlotExtraMissing as exc:
            fail(one_line(str(exc)))
        except ValueError as exc:
            raise click.BadParameter(str(exc), param_hint="'--output'") from None
        stderr_console().print(f"deathsphere: wrote {output}")
        return
    fmt = choose_format(fmt)
    if fmt == "table":
        from deathsphere.charplot import char_map, to_rich

        width = max(40, min(stdout_console().width, 100))
        stdout_console().print(to_rich(char_map(a_over_r, 1.0, k, outside=outside, mu=mu, max_g=max_g,
                                                width=width)), end="")
        return
    from deathsphere.limits import boundary_table

    emit([boundary_table(a_over_r, k, outside, mu, max_g, step)], fmt)


@cli.command("limits")
@click.option("--theta", multiple=True, metavar="DEG",
              help="Polar angle(s) of the orbit; without it: the highest orbit possible.")
@click.option("--max-g", "max_g", type=float, default=math.inf, metavar="G",
              help="Largest centre acceleration the rider takes, in g [default: unlimited].")
@body_options
@output_options()
def limits_command(theta, max_g, body, side, a, r, k, g, mu, fmt):
    """Which tilts alpha give a feasible orbit at theta, and at what speeds (beyond the paper).

    With --theta: the interval(s) of alpha where the wheel fits, Omega^2 > 0
    and it keeps contact, within --mu and --max-g, with the speed range over
    each.  Without --theta: the highest orbit possible (smallest theta) with
    its alpha and speed.  Method: docs/limits.md.

    \b
    Examples:
      deathsphere limits --theta 60 --mu 1.2
      deathsphere limits --mu 1 --max-g 5
    """
    from deathsphere.limits import highest_orbit_table, intervals_table

    setup = make_setup(body, side, a, r, k, g, mu)
    if setup.body != "wheel":
        raise click.UsageError("limits are computed for a wheel (--body wheel)")
    if not max_g > 0:
        raise click.BadParameter("must be > 0 (inf: no limit)", param_hint="'--max-g'")
    fmt = choose_format(fmt)
    if theta:
        table = intervals_table(setup, parse_angles(theta, "theta", 100_000), max_g)
        title = "Feasible tilts (fit, Omega^2 > 0, contact, mu, g-load)"
    else:
        table = highest_orbit_table(setup, max_g)
        title = "The highest orbit possible (smallest theta with a feasible tilt)"
    emit([table], fmt, title=title)


@cli.command("verify")
@click.option("--claim", "claims", multiple=True, metavar="ID", help="Check only this claim (repeatable).")
@output_options()
def verify_command(claims, fmt):
    """Check every quantitative claim of the paper: a checklist with the evidence.

    Each claim (Table 1, the inequalities and limits of each section, the
    figure, ...) is recomputed from this package's physics and marked
    confirmed, corrected (right in substance, wrong in a sign, a factor, a
    label or a digit: see docs/errata.md) or refuted, with numbers.

    \b
    Examples:
      deathsphere verify
      deathsphere verify --claim T1-g --claim E28
      deathsphere verify --format csv
    """
    from deathsphere import verify

    known = {c.id for c in verify.CLAIMS}
    for c in claims:
        if c not in known:
            raise click.BadParameter(f"unknown claim {c!r}; known: {' '.join(sorted(known))}",
                                     param_hint="'--claim'")
    fmt = choose_format(fmt)
    ids = list(claims) or None
    if sys.stderr.isatty():
        from rich.progress import Progress

        total = len(ids or verify.CLAIMS)
        with Progress(console=stderr_console(), transient=True) as progress:
            task = progress.add_task("checking claims", total=total)
            table = verify.run(ids, progress=lambda c: progress.update(task, advance=1, description=c.id))
    else:
        table = verify.run(ids)
    if fmt == "table":
        from deathsphere.render import checklist_view

        stdout_console().print(checklist_view(table, verify.counts(table)))
    else:
        emit([table], fmt)


@cli.command("simulate")
@click.option("--theta", required=True, type=float, metavar="DEG",
              help="Polar angle of the contact point (vertical orbits: the cone angle, 90 = great circle).")
@click.option("--alpha", type=float, default=None, metavar="DEG", help="Wheel: tilt of the steady orbit.")
@click.option("--omega3", type=float, default=None, metavar="RAD_S", help="Sphere: spin about the contact normal.")
@click.option("--omega", type=float, default=None, metavar="RAD_S", help="Sphere: the signed orbital rate instead.")
@click.option("--branch", type=click.IntRange(0, 1), default=0, show_default=True,
              help="Sphere with --omega3: root of eq. 55 (0 slow, 1 fast).")
@click.option("--vertical", is_flag=True, help="A vertical orbit of a wheel, started at the top with --v-top.")
@click.option("--v-top", "v_top", type=float, default=None, metavar="M_S", help="Vertical: speed at the top.")
@click.option("--perturb", type=float, default=0.0, show_default=True, metavar="EPS",
              help="Kick off the steady orbit [rad]: the wheel tilted by EPS about its direction of travel "
                   "(a sphere: its contact point moved EPS down the meridian); rolling and contact still hold.")
@click.option("--periods", type=click.FloatRange(0, 1e6, min_open=True), default=20.0, show_default=True,
              help="How long: periods of the steady orbit (vertical: laps).")
@click.option("--points-per-period", type=click.IntRange(2, 100_000), default=100, show_default=True)
@click.option("--method", type=click.Choice(("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA")), default="DOP853",
              show_default=True, help="scipy.integrate.solve_ivp method.")
@click.option("--rtol", type=click.FloatRange(1e-14, 1e-2), default=1e-10, show_default=True)
@click.option("--atol", type=click.FloatRange(1e-16, 1.0), default=None, help="[default: = rtol, per scaled component]")
@click.option("--frame", type=click.Choice(("turning", "lab")), default="turning", show_default=True,
              help="Integrate in the frame turning with the steady orbit, or in the lab.")
@click.option("--summary-only", is_flag=True, help="With csv/json/ndjson: print the summary rows, not the time series.")
@click.option("--output", type=click.Path(dir_okay=False, writable=True), default=None, metavar="FILE",
              help="Plot theta, alpha and the contact point's track to FILE (.png/.svg/.pdf; plot extra).")
@body_options
@output_options()
def simulate_command(theta, alpha, omega3, omega, branch, vertical, v_top, perturb, periods, points_per_period,
                     method, rtol, atol, frame, summary_only, output, body, side, a, r, k, g, mu, fmt):
    """Integrate the exact equations of motion from a steady orbit (beyond the paper).

    The rigid-body equations of a wheel or sphere rolling without slipping
    (eqs. 2-7b in general form, docs/dynamics.md) are integrated with
    scipy.integrate.solve_ivp.  The run stops with status contact_lost when
    the normal force reaches zero and slips when the friction needed exceeds
    --mu; otherwise completed.  On a terminal: the summary (drift of theta
    and alpha, least normal force, most friction, energy and constraint
    drift, method and tolerances).  Piped: the time series as CSV, the
    summary on stderr.

    \b
    Examples:
      deathsphere simulate --theta 60 --alpha 10 --periods 20
      deathsphere simulate --theta 60 --alpha 10 --perturb 0.05 --format csv > run.csv
      deathsphere simulate --theta 90 --alpha 80 --perturb 1e-6    (unstable: loses contact)
      deathsphere simulate --vertical --theta 90 --v-top 5.2
      deathsphere simulate --body sphere --theta 60 --omega3 40
    """
    from deathsphere import simulation
    from deathsphere.render import simulation_view

    setup = make_setup(body, side, a, r, k, g, mu)
    if setup.body == "particle":
        raise click.UsageError("simulate covers a wheel or a sphere (a particle has no rolling dynamics)")
    if vertical:
        if setup.body != "wheel" or alpha is not None or v_top is None:
            raise click.UsageError("--vertical simulates a wheel: give --theta and --v-top (no --alpha)")
        if v_top < 0:
            raise click.BadParameter("must be >= 0", param_hint="'--v-top'")
    elif v_top is not None:
        raise click.UsageError("--v-top is for --vertical orbits")
    elif setup.body == "wheel" and (alpha is None or omega3 is not None or omega is not None):
        raise click.UsageError("a wheel's steady orbit needs --alpha DEG")
    elif setup.body == "sphere" and (alpha is not None or (omega3 is None) == (omega is None)):
        raise click.UsageError("a sphere's steady orbit needs exactly one of --omega3 and --omega")
    problem = angle_problem("theta", theta) or (angle_problem("alpha", alpha) if alpha is not None else "")
    if problem:
        raise click.UsageError(problem)
    for name, value in (("perturb", perturb), ("omega3", omega3), ("omega", omega), ("v-top", v_top)):
        if value is not None and not math.isfinite(value):
            raise click.BadParameter("must be a finite number", param_hint=f"'--{name}'")
    try:
        if vertical:
            starts = simulation.vertical_starts(setup, theta, v_top, perturb=perturb)
        elif setup.body == "wheel":
            starts = simulation.horizontal_starts(setup, theta, alpha, perturb=perturb)
        else:
            starts = simulation.horizontal_starts(setup, theta, omega3=omega3, omega=omega, branch=branch,
                                                  perturb=perturb)
        sim = simulation.Simulation(starts, periods=periods, points_per_period=points_per_period, method=method,
                                    rtol=rtol, atol=atol, frame=frame)
    except ValueError as exc:
        raise click.UsageError(str(exc)) from None
    fmt = choose_format(fmt)
    series = []

    def chunks(advance):
        for table in sim.chunks(progress=advance):
            if output is not None:
                series.append(table)
            yield table

    def run(advance):
        if fmt == "table" or summary_only:
            for _ in chunks(advance):
                pass
        else:
            emit(chunks(advance), fmt)

    if sys.stderr.isatty():
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

        with Progress(TextColumn("simulate"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
                      console=stderr_console(), transient=True) as progress:
            task = progress.add_task("simulate", total=sim.n_chunks)
            run(lambda done, total: progress.update(task, completed=done, total=total))
    else:
        run(lambda done, total: None)
    summary = sim.summary()
    if fmt == "table":
        stdout_console().print(simulation_view(summary))
    elif summary_only:
        emit([summary], fmt)
    else:
        stderr_console().print(simulation_view(summary))
    if output is not None:
        from deathsphere.plot import PlotExtraMissing
        from deathsphere.plot_simulation import plot_simulation

        try:
            plot_simulation(simulation.concat_tables(series), summary, output=output)
        except PlotExtraMissing as exc:
            fail(one_line(str(exc)))
        except ValueError as exc:
            raise click.BadParameter(str(exc), param_hint="'--output'") from None
        stderr_console().print(f"deathsphere: wrote {output}")


@cli.command("table1")
@output_options()
def table1_command(fmt):
    """The paper's Table 1: printed mu, v_cm and "No. of g's" beside the computed values.

    Wheel a = 0.3 m, k = 1/2 in a sphere r = 3.0 m, standard gravity.  The
    note column names every disagreement; docs/errata.md explains them.

    \b
    Example:
      deathsphere table1
      deathsphere table1 --format csv
    """
    from deathsphere.render import table1_view
    from deathsphere.table1 import PRINTED, table1

    table = table1()
    fmt = choose_format(fmt)
    if fmt == "table":
        stdout_console().print(table1_view(table, PRINTED))
    else:
        emit([table], fmt)


# ---------------------------------------------------------------------------
# entry point


def main(argv=None) -> None:
    """Console-script entry point (see :class:`DeathsphereGroup` for exit codes)."""
    cli.main(args=argv)
