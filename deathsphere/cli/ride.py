"""``deathsphere ride`` and ``deathsphere machines``: a motorcycle and rider
(a machine) on steady horizontal orbits inside the globe
(:func:`deathsphere.api.ride`, docs/machine.md)."""

from __future__ import annotations

import click
import numpy as np

from deathsphere import api
from deathsphere.cli.base import OutputPath, choose_format, cli, collect, emit, finish, stream
from deathsphere.cli.options import (
    jobs_option,
    machine_from_options,
    machine_options,
    only_option,
    output_options,
    param_option,
    scheduler_option,
    single,
    stability_option,
)
from deathsphere.cli.orbit import SWEEP_FORMATS, sweep_format
from deathsphere.writers.stream import FORMATS

def _axis(name: str, values):
    """The values of a repeated option (values and start:stop:step ranges,
    with unit suffixes), as one flat array."""
    from deathsphere.api.arguments import checked_axis

    axis = checked_axis(name, list(values))
    return axis.take(np.arange(len(axis)))


@cli.command("ride", short_help="A motorcycle and rider on horizontal orbits: lean, speed, load, clearance.")
@param_option("theta", multiple=True)
@param_option("height", multiple=True)
@param_option("alpha", multiple=True, help="Tilt of the machine's up-axis above the orbit plane (lean from "
              "the vertical = 90 - alpha).")
@param_option("speed", multiple=True, help="Speed of the centre of mass; every tilt giving it, one row each.")
@machine_options()
@param_option("r")
@param_option("diameter")
@param_option("g")
@param_option("mu")
@param_option("max_g", help="Largest load_g (|contact force| / (m g), what the rider feels); an orbit over "
              "it has status over_g.")
@click.option("--vertical", is_flag=True, default=False,
              help="A vertical loop instead: --theta is its cone angle (90 = a great circle), --v-top the "
                   "speed of the centre of mass at the top.")
@param_option("v_top", multiple=True, help="Vertical loop: speed of the centre of mass at the top, >= 0.")
@click.option("--summary", is_flag=True, default=False,
              help="The rider's table: per height (or theta), the speeds that are ok with lean, load, "
                   "friction and head clearance.")
@only_option(api.STATUSES)
@stability_option()
@jobs_option()
@scheduler_option()
@single("--output", type=OutputPath(SWEEP_FORMATS), default=None, metavar="FILE",
        help="Write to FILE (.csv, .ndjson, .json or .parquet; the format follows the extension) instead "
             "of stdout.  Parquet needs the fast extra.")
@output_options(FORMATS + ("parquet",))
def ride_command(theta, height, alpha, speed, machine, machine_file, mass, com_height, a, tyre_radius,
                 roll_inertia, pitch_inertia, yaw_inertia, spin_inertia, head_height, r, diameter, g, mu, max_g,
                 vertical, v_top, summary, only, stability, jobs, scheduler, output, fmt):
    """A machine (motorcycle and rider) on steady horizontal orbits inside the globe.

    Every combination of the --theta (or --height) and --alpha (or --speed)
    values.  Each row: the orbit rate and period, the speed of the centre of
    mass and of the contact, the wheels' spin, the force on the tyre (normal,
    friction, mu needed), the load the rider feels (load_g) and the clearance
    of the rider's head from the globe (docs/machine.md).  An unsteered
    machine is expected to be unstable on most orbits: a rider steers.

    \b
    Examples:
      deathsphere ride --theta 90 --speed 40km/h --diameter 16ft
      deathsphere ride --height 1.2m --alpha 10:30:5 --machine benchmark-bicycle
      deathsphere ride --diameter 16ft --height 0:2.4:0.2m --speed 30:70:5km/h \\
          --mu 1 --max-g 5 --summary
      deathsphere ride --machine-file my-bike.toml --theta 90 --speed 35km/h
      deathsphere ride --vertical --theta 90 --v-top 20:40:5km/h --diameter 16ft
      deathsphere ride --theta 0:180:0.1 --alpha -90:90:0.1 --jobs 2 --output ride.parquet
    """
    fmt = sweep_format(fmt, output) if output is not None or fmt == "parquet" else choose_format(fmt)
    chosen = machine_from_options(machine, machine_file, mass=mass, com_height=com_height, a=a,
                                  tyre_radius=tyre_radius, roll_inertia=roll_inertia, pitch_inertia=pitch_inertia,
                                  yaw_inertia=yaw_inertia, spin_inertia=spin_inertia, head_height=head_height)
    setup = {k: v for k, v in (("r", r), ("diameter", diameter), ("g", g)) if v is not None}
    if vertical:
        if not theta or not v_top or height or alpha or speed or summary:
            raise click.UsageError("--vertical takes --theta (the loop's cone angle) and --v-top only")
        table = api.ride(_axis("theta", theta)[:, None], vertical=True, v_top=_axis("v_top", v_top)[None, :],
                         machine=chosen, only=only or None, **setup)
        emit([table], fmt, f"Vertical loops of {chosen.name} (docs/machine.md sec. 10)", output=output)
        return
    if theta and height:
        raise click.UsageError("give --theta or --height, not both")
    if not theta and not height:
        raise click.UsageError("give --theta or --height (the contact's height above the floor)")
    if alpha and speed:
        raise click.UsageError("give --alpha or --speed, not both")
    if not alpha and not speed:
        raise click.UsageError("give --alpha or --speed")
    where = {"theta": list(theta)} if theta else {"height": list(height)}
    how = {"alpha": list(alpha)} if alpha else {"speed": list(speed)}
    setup = {k: v for k, v in (("r", r), ("diameter", diameter), ("g", g), ("mu", mu), ("max_g", max_g))
             if v is not None}
    chunks = api.ride_sweep(**where, **how, machine=chosen, stability=stability,
                            only=None if summary else (only or None), jobs=jobs or 1, scheduler=scheduler, **setup)
    if summary:
        table = api.ride_summary(collect(chunks, "ride"))
        emit([table], fmt, f"Feasible speeds by height: {chosen.name} (docs/machine.md)", output=output)
        return
    title = f"Horizontal orbits of {chosen.name} (docs/machine.md eqs. M1-M12)"
    finish(stream(chunks, fmt, label="ride", title=title, output=output))


@cli.command("machines", short_help="The preset machines of 'ride' with their parameters and sources.")
@output_options()
def machines_command(fmt):
    """The preset machines of 'deathsphere ride': mass, centre-of-mass height,
    wheel and tyre radii, inertias, head height and where each comes from
    (docs/machine.md sec. 7).

    \b
    Examples:
      deathsphere machines
      deathsphere machines --format csv
    """
    emit([api.machines_table()], choose_format(fmt), "Preset machines (docs/machine.md sec. 7)")
