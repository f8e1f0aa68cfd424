"""``deathsphere ride`` and ``deathsphere machines``: a motorcycle and rider
(a machine) on steady horizontal orbits inside the globe
(:func:`deathsphere.api.ride`, docs/machine.md)."""

from __future__ import annotations

import click
import numpy as np

from deathsphere import api
from deathsphere.cli.base import OutputPath, choose_format, cli, emit, finish, pieces, say_written, stream
from deathsphere.cli.options import (
    display_units,
    jobs_option,
    machine_from_options,
    machine_options,
    only_option,
    output_options,
    param_option,
    scheduler_option,
    single,
    stability_option,
    units_option,
)
from deathsphere.cli.orbit import SWEEP_FORMATS, sweep_format
from deathsphere.writers.stream import FORMATS


def _view(name: str, **kwargs):
    """A terminal view of render.ride_views, imported only when a table is drawn."""
    def view(table, total_rows=None):
        from deathsphere.render import ride_views

        return getattr(ride_views, name)(table, total_rows=total_rows, **kwargs)
    return view


def _two_wheeler_view(name: str, title: str, units):
    """A terminal view of render.two_wheeler_views, imported only when a table is drawn."""
    def view(table, total_rows=None):
        from deathsphere.render import two_wheeler_views

        return getattr(two_wheeler_views, name)(table, total_rows=total_rows, title=title, units=units)
    return view


def setup_of(r, diameter, g, max_g) -> dict:
    """The globe's options given (the API's defaults apply to the others)."""
    return {k: v for k, v in (("r", r), ("diameter", diameter), ("g", g), ("max_g", max_g)) if v is not None}


def _axis(name: str, values):
    """The values of a repeated option (values and start:stop:step ranges,
    with unit suffixes), as one flat array."""
    from deathsphere.api.arguments import checked_axis

    axis = checked_axis(name, list(values))
    return axis.take(np.arange(len(axis)))


def _grid(where, how, mus):
    """The grid of a ride: the contact points (outer), each value of --mu,
    and the speeds, tilts or top speeds tried (inner); one --mu value
    leaves the grid two-dimensional."""
    if mus is None:
        return where[:, None], how[None, :], {}
    if mus.size == 1:
        return where[:, None], how[None, :], {"mu": float(mus[0])}
    return where[:, None, None], how[None, None, :], {"mu": mus[None, :, None]}


@cli.command("ride", short_help="A motorcycle and rider on horizontal orbits: lean, speed, load, clearance.")
@param_option("theta", multiple=True)
@param_option("height", multiple=True)
@param_option("alpha", multiple=True, help="Tilt of the machine's up-axis above the orbit plane (lean from "
              "the vertical = 90 - alpha).")
@param_option("speed", multiple=True)
@param_option("com_speed", multiple=True)
@param_option("period", multiple=True, help="The lap time instead of --speed (e.g. 1.3s), Omega = 2 pi / T; every "
              "tilt giving it, one row each.")
@machine_options()
@param_option("r")
@param_option("diameter")
@param_option("surface")
@param_option("wall_angle")
@param_option("wall_height")
@single("--profile", "profile", default=None, metavar="FILE",
        help="With --surface profile: a CSV of the meridian's points from the lowest up, header rho_m,z_m (or "
             "rho_ft,z_ft ...; docs/surfaces.md); a lane is its --height.")
@param_option("turn_radius", multiple=True, help="With --surface plane (flat ground): the contact's distance "
              "from the turn's centre (a two-wheeler's rear contact's), the lane instead of --height.")
@param_option("g")
@param_option("mu", multiple=True, help="Friction coefficient available; an orbit needing more has status "
              "slips (e.g. 0.8:1:0.1: each value a set of rows; the rider's table a row per height and value; a "
              "two-wheeler takes one value, at both wheels).")
@param_option("max_g", help="Largest load_g (|contact force| / (m g), what the rider feels); an orbit over "
              "it has status over_g.")
@click.option("--vertical", is_flag=True, default=False,
              help="A vertical loop instead: --theta is its cone angle (90 = a great circle), --v-top the "
                   "speed of the centre of mass at the top; with --surface profile, inside a profile closed at "
                   "both ends, --theta 90 only.")
@param_option("v_top", multiple=True, help="Vertical loop: speed of the centre of mass at the top, >= 0.")
@click.option("--summary", is_flag=True, default=False,
              help="The rider's table: per contact point (height or theta), how many speeds are ok, their "
                   "range, lean, load, friction needed and least head clearance, and why the others fail; "
                   "a two-wheeler's (--steer) adds its stable speeds, steer torques and hands-free speeds.")
@only_option(api.STATUSES)
@stability_option()
@click.option("--flat", is_flag=True, default=False,
              help="A two-wheeler (--machine benchmark-bicycle) on flat ground: the eigenvalues of upright "
                   "straight running at each --speed (the rear contact's); --summary: weave and capsize speeds.")
@single("--steer", default=None, metavar="free|locked|torque=T",
        help="A two-wheeler's steady turns on the globe (docs/two-wheeler.md), their stability with the steer "
             "free (its steady torque held) or locked; --speed is the rear contact's.  torque=T: the turns held "
             "with the steer torque T (N m; as --steer-torque T).")
@param_option("steer_torque", multiple=True)
@jobs_option()
@scheduler_option()
@single("--output", type=OutputPath(SWEEP_FORMATS), default=None, metavar="FILE",
        help="Write to FILE (.csv, .ndjson, .json or .parquet; the format follows the extension) instead "
             "of stdout.  Parquet needs the fast extra.")
@output_options(FORMATS + ("parquet",))
@units_option()
def ride_command(theta, height, alpha, speed, com_speed, period, machine, machine_file, mass, com_height, a,
                 tyre_radius, roll_inertia, pitch_inertia, yaw_inertia, spin_inertia, head_height, r, diameter,
                 surface, wall_angle, wall_height, profile, turn_radius, g, mu, max_g, vertical, v_top, summary, only, stability, flat,
                 steer, steer_torque, jobs, scheduler, output, fmt, units):
    """A machine (motorcycle and rider) on steady horizontal orbits inside the globe.

    Every combination of the --theta (or --height) and --alpha (or --speed,
    --com-speed, --period) values; --speed is the contact's (a
    speedometer's), --com-speed the centre of mass's.  Each row: the orbit
    rate and period, the speed of the centre of mass and of the contact, the
    wheels' spin, the force on the tyre (normal,
    friction, mu needed), the load the rider feels (load_g) and the clearance
    of the rider's head from the globe (docs/machine.md).  An unsteered
    machine is expected to be unstable on most orbits: a rider steers.

    \b
    Examples:
      deathsphere ride --theta 90 --speed 40km/h --diameter 16ft
      deathsphere ride --height 5ft --period 1.3s --diameter 16ft
      deathsphere ride --height 5ft --com-speed 30km/h --diameter 16ft
      deathsphere ride --height 1.2m --alpha 10:30:5 \\
          --machine benchmark-bicycle-rigid
      deathsphere ride --diameter 16ft --height 0:2.4:0.2m --speed 5:35:5km/h \\
          --mu 1 --max-g 5 --summary
      deathsphere ride --machine-file my-bike.toml --theta 90 --speed 35km/h
      deathsphere ride --diameter 16ft --height 1.2m --speed 10:30:5km/h \\
          --mu 0.8:1:0.1 --summary
      deathsphere ride --vertical --theta 90 --v-top 20:40:5km/h --diameter 16ft
      deathsphere ride --vertical --surface profile --profile examples/egg.csv \\
          --theta 90 --v-top 20:40:5km/h
      deathsphere ride --theta 0:180:0.1 --alpha -90:90:0.1 --jobs 2 \\
          --output ride.parquet
      deathsphere ride --machine stunt125 --surface cylinder --diameter 32ft \\
          --wall-height 12ft --height 5ft --speed 40km/h
      deathsphere ride --surface cone --wall-angle 80 --diameter 32ft \\
          --height 5ft --speed 30:80:10km/h --mu 1 --summary
      deathsphere ride --surface plane --turn-radius 10:50:10 --speed 30km/h
      deathsphere ride --machine stunt125-steer --surface plane \\
          --turn-radius 10 --speed 20km/h --steer free
      deathsphere ride --machine benchmark-bicycle --flat --speed 0:10:0.1
      deathsphere ride --machine benchmark-bicycle --flat --speed 0:10:0.1 \\
          --summary
      deathsphere ride --machine benchmark-bicycle --steer free \\
          --diameter 16ft --height 1:2:0.5 --speed 5:10:5
      deathsphere ride --machine benchmark-bicycle --steer-torque 0 \\
          --diameter 16ft --height 1
      deathsphere ride --machine benchmark-bicycle --steer free \\
          --diameter 16ft --height 1 --speed 3:12:1 --mu 0.8 \\
          --max-g 3.5 --summary
      deathsphere ride --machine stunt125-steer --surface cylinder \\
          --diameter 32ft --height 2m --speed 60km/h
    """
    from deathsphere.api.arguments import TILTS_PER_SPEED, refuse_large_grid, value_counts

    fmt = sweep_format(fmt, output) if output is not None or fmt == "parquet" else choose_format(fmt)
    shown = display_units(units, click.get_current_context().params)
    from deathsphere.api.two_wheelers import is_two_wheeler_file
    from deathsphere.api.two_wheelers import TWO_WHEELER_NAMES

    from deathsphere.api.ride_surfaces import names_a_wall

    on_wall = names_a_wall(surface, wall_angle, wall_height, profile)
    if turn_radius and not on_wall:
        raise click.BadParameter("the lane on flat ground (--surface plane); on the globe give --theta or --height",
                                 param_hint="'--turn-radius'")
    if flat or steer is not None or steer_torque or (machine or "").lower() in TWO_WHEELER_NAMES or (
            machine_file is not None and is_two_wheeler_file(machine_file)):
        # a two-wheeler (docs/two-wheeler.md): the API refuses what it does not take
        which = machine if machine_file is None and machine is not None else machine_from_options(machine,
                                                                                                   machine_file)
        overrides = dict(mass=mass, com_height=com_height, wheel_radius=a, tyre_radius=tyre_radius,
                         roll_inertia=roll_inertia, pitch_inertia=pitch_inertia, yaw_inertia=yaw_inertia,
                         spin_inertia=spin_inertia, head_height=head_height)
        lists = {k: list(v) for k, v in (("theta", theta), ("height", height), ("speed", speed),
                                         ("steer_torque", steer_torque), ("alpha", alpha), ("v_top", v_top),
                                         ("com_speed", com_speed), ("period", period), ("mu", mu),
                                         ("turn_radius", turn_radius)) if v}
        arena = {k: v for k, v in (("surface", surface), ("wall_angle", wall_angle), ("wall_height", wall_height),
                                   ("profile", profile)) if v is not None}
        given = dict(machine=which, steer=steer, summary=summary, stability=stability, only=only or None,
                     vertical=vertical, **lists, **setup_of(r, diameter, g, max_g), **arena,
                     **{k: v for k, v in overrides.items() if v is not None})
        name = getattr(which, "name", which)
        if flat:
            table = api.ride(flat=True, **given)
            title = f"{name}: straight running on flat ground (docs/two-wheeler.md sec. 7)"
            rows = emit([table], fmt, title, view=_two_wheeler_view("straight_view", title, shown), output=output)
            if output is not None:
                say_written(output, rows=rows)
            return
        # the globe's lanes stream a few at a time (flat memory, --jobs, --scheduler)
        from deathsphere.api.two_wheeler_streams import two_wheeler_ride_sweep

        chunks = two_wheeler_ride_sweep(**given, jobs=jobs or 1, scheduler=scheduler)
        arena_word = str(surface or "sphere").strip().lower()
        where = ("the globe" if not on_wall else "flat ground's circles" if arena_word == "plane"
                 else f"the {arena_word}'s wall")
        title = (f"{name}: the rider's table on {where}, per lane (docs/two-wheeler.md sec. 10)" if summary
                 else f"{name}: steady turns on {where} (docs/two-wheeler.md sec. " + ("12)" if on_wall else "8)"))
        finish(_written(stream(chunks, fmt, label="ride", title=title,
                               view=_two_wheeler_view("turns_view", title, shown), output=output), output))
        return
    chosen = machine_from_options(machine, machine_file, mass=mass, com_height=com_height, a=a,
                                  tyre_radius=tyre_radius, roll_inertia=roll_inertia, pitch_inertia=pitch_inertia,
                                  yaw_inertia=yaw_inertia, spin_inertia=spin_inertia, head_height=head_height)
    setup = {k: v for k, v in (("r", r), ("diameter", diameter), ("g", g), ("max_g", max_g)) if v is not None}
    mus = _axis("mu", mu) if mu else None
    if on_wall:
        if (jobs is not None and str(jobs).strip() != "1") or scheduler is not None:
            raise click.UsageError("--jobs and --scheduler spread the globe's grids: a drum's or a cone's ride is "
                                   "computed in one process (at most 2e+06 rows)")
        wall = {"surface": surface, "wall_angle": wall_angle, "wall_height": wall_height, "profile": profile}
        lane = {"theta": theta, "height": height, "turn_radius": turn_radius, "alpha": alpha, "speed": speed,
                "com_speed": com_speed, "period": period, "vertical": vertical, "v_top": v_top}
        return _ride_on_wall(chosen, wall, setup, mu, mus, lane,
                             {"summary": summary, "only": only, "stability": stability, "fmt": fmt,
                              "output": output, "shown": shown})
    if vertical:
        if not theta or not v_top or height or alpha or speed or com_speed or period or summary:
            raise click.UsageError("--vertical takes --theta (the loop's cone angle) and --v-top only")
        refuse_large_grid(value_counts({"theta": theta, "mu": mu, "v_top": v_top}), command="ride --vertical",
                          limit=api.rides.MAX_RIDE_ROWS)
        where, how, friction = _grid(_axis("theta", theta), _axis("v_top", v_top), mus)
        table = api.ride(where, vertical=True, v_top=how, machine=chosen, only=only or None, **friction, **setup)
        title = f"Vertical loops of {chosen.name} (docs/machine.md sec. 10)"
        # computed whole in well under a second; writing a million loops takes longer: the bar follows that
        _written(stream(pieces(table), fmt, label="ride --vertical", title=title,
                        view=_view("loop_view", title=title, units=shown), output=output), output)
        return
    if theta and height:
        raise click.UsageError("give --theta or --height, not both")
    if not theta and not height:
        raise click.UsageError("give --theta or --height (the contact's height above the floor)")
    holds = [(name, values) for name, values in (("alpha", alpha), ("speed", speed), ("com_speed", com_speed),
                                                 ("period", period)) if values]
    if len(holds) != 1:
        typed = f"--{holds[1][0].replace('_', '-')}: " if holds else ""
        raise click.UsageError(f"{typed}give exactly one of --alpha, --speed (the contact's), --com-speed (the "
                               "centre of mass's) and --period (the lap time)")
    at, by = ("theta", theta) if theta else ("height", height), holds[0]
    if summary or (mus is not None and mus.size > 1):
        # the rider's table and a range of mu keep the request's grid in memory (grouped by request)
        refuse_large_grid(value_counts({"theta": theta, "height": height, "mu": mu, by[0]: by[1]}),
                          command="ride", limit=api.rides.MAX_RIDE_ROWS,
                          per_point=TILTS_PER_SPEED if by[0] != "alpha" else 1)
        where, how, friction = _grid(_axis(*at), _axis(*by), mus)
        kwargs = dict(machine=chosen, stability=stability and not summary, only=only or None, summary=summary,
                      **friction, **setup)
        title = (f"Feasible speeds by height: {chosen.name} (docs/machine.md)" if summary
                 else f"Horizontal orbits of {chosen.name} (docs/machine.md eqs. M1-M12)")
        chunks = (_summary_chunks(at[0], where, by[0], how, kwargs) if summary
                  else pieces(api.ride(**{at[0]: where, by[0]: how}, **kwargs)))
        _written(stream(chunks, fmt, label="ride", title=title, view=_view("ride_view", title=title, units=shown),
                        output=output), output)
        return
    # one orbit per grid point and one mu: streamed chunk by chunk, as sweep (flat memory, --jobs, --scheduler)
    friction = {"mu": float(mus[0])} if mus is not None else {}
    chunks = api.ride_sweep(**{at[0]: list(at[1]), by[0]: list(by[1])}, machine=chosen, stability=stability,
                            only=only or None, jobs=jobs or 1, scheduler=scheduler, **friction, **setup)
    title = f"Horizontal orbits of {chosen.name} (docs/machine.md eqs. M1-M12)"
    finish(_written(stream(chunks, fmt, label="ride", title=title,
                           view=_view("ride_view", title=title, units=shown), output=output), output))


def _ride_on_wall(chosen, wall: dict, setup: dict, mu, mus, lane: dict, how_shown: dict):
    """``ride`` on a drum, a cone, flat ground or a profile (docs/machine.md, "On any surface of
    revolution"): the grid of heights, each --mu and the speeds or tilts,
    computed in one API call (a lane is refused there in one line: --theta,
    --vertical, a height above the wall) and rendered.  ``lane`` holds the
    lane's options as typed, ``how_shown`` what to compute and how to
    render (summary, only, stability, fmt, output, shown)."""
    theta, vertical, v_top = (lane[k] for k in ("theta", "vertical", "v_top"))
    # the lane is a height up the wall, or a turn radius on flat ground (the API refuses the one its ground lacks)
    at = ("turn_radius", lane["turn_radius"]) if lane["turn_radius"] else ("height", lane["height"])
    holds = [k for k in ("alpha", "speed", "com_speed", "period") if lane[k]]
    summary, only, stability, fmt, output, shown = (how_shown[k] for k in ("summary", "only", "stability", "fmt",
                                                                           "output", "shown"))
    from deathsphere.api.arguments import TILTS_PER_SPEED, refuse_large_grid, value_counts

    if vertical:
        # the machine's loop inside a profile closed over the top (docs/machine.md sec. 10, eqs. M25-M30)
        if not theta or not v_top or at[1] or holds or summary:
            raise click.UsageError("--vertical takes --theta 90 (the loop runs through the profile's axis) and "
                                   "--v-top only")
        refuse_large_grid(value_counts({"theta": theta, "mu": mu, "v_top": v_top}), command="ride --vertical",
                          limit=api.rides.MAX_RIDE_ROWS)
        where, how, friction = _grid(_axis("theta", theta), _axis("v_top", v_top), mus)
        table = api.ride(where, vertical=True, v_top=how, machine=chosen, only=only or None, **wall, **friction,
                         **setup)
        title = f"Vertical loops of {chosen.name} inside the {str(wall['surface']).strip().lower()} " \
                "(docs/machine.md sec. 10, eqs. M25-M30)"
        _written(stream(pieces(table), fmt, label="ride --vertical", title=title,
                        view=_view("loop_view", title=title, units=shown), output=output), output)
        return
    if v_top:
        raise click.UsageError("--v-top is a vertical loop's top speed: give --vertical")
    if theta:
        raise click.BadParameter("theta is the globe's polar angle: on a drum, a cone or a profile give --height "
                                 "(the contact's height above the floor), on flat ground --turn-radius",
                                 param_hint="'--theta'")
    if lane["height"] and lane["turn_radius"]:
        raise click.UsageError("give --height (up a wall) or --turn-radius (on flat ground), not both")
    if not at[1]:
        raise click.UsageError("give --height (the contact's height above the floor; on flat ground "
                               "--turn-radius, the contact's distance from the turn's centre)")
    if len(holds) != 1:
        typed = " and ".join("--" + k.replace("_", "-") for k in holds)
        raise click.UsageError("give exactly one of --alpha, --speed, --com-speed and --period"
                               + (f", not {typed}" if holds else ""))
    by = (holds[0], lane[holds[0]])
    refuse_large_grid(value_counts({at[0]: at[1], "mu": mu, by[0]: by[1]}), command="ride",
                      limit=api.rides.MAX_RIDE_ROWS, per_point=TILTS_PER_SPEED if by[0] != "alpha" else 1)
    where, how, friction = _grid(_axis(*at), _axis(*by), mus)
    table = api.ride(**{at[0]: where, by[0]: how}, machine=chosen, stability=stability and not summary,
                     only=only or None, summary=summary, **wall, **friction, **setup)
    kind = str(wall["surface"]).strip().lower()      # given: the API refuses a wall's option on the globe
    title = (f"Feasible speeds by height on the {kind}: {chosen.name} (docs/machine.md)" if summary
             else f"Laps of {chosen.name} on the {kind} (docs/machine.md eqs. MS1-MS7)")
    _written(stream(pieces(table), fmt, label="ride", title=title, view=_view("ride_view", title=title, units=shown),
                    output=output), output)


#: Orbits evaluated per piece of the rider's table: a progress bar's step
#: (about a second of work), never less than one contact point.
SUMMARY_PIECE_ORBITS = 10_000


def _summary_chunks(at: str, where, by: str, how, kwargs: dict):
    """The rider's table, a piece of contact points at a time (each of its
    rows is one contact point's, with every speed or tilt and every mu
    tried there: the pieces join into the table of the whole grid), as
    :class:`~deathsphere.api.streams.Chunks` for the progress bar."""
    from deathsphere.api.streams import Chunks

    per_point = how.size * (kwargs["mu"].size if "mu" in kwargs and np.ndim(kwargs["mu"]) else 1)
    step = max(1, SUMMARY_PIECE_ORBITS // max(per_point, 1))
    rows_per_point = per_point // how.size
    n = where.shape[0]

    def evaluated():
        for start in range(0, n, step):
            part = where[start:start + step]
            yield part.shape[0] * rows_per_point, api.ride(**{at: part, by: how}, **kwargs)
    return Chunks(evaluated(), total=n * rows_per_point)


def _written(tally, output):
    """After a table went to the file ``output`` (None: stdout), the line saying so."""
    if output is not None:
        say_written(output, rows=tally.rows)
    return tally


@cli.command("machines", short_help="The preset machines of 'ride' with their parameters and sources.")
@output_options()
@units_option()
def machines_command(fmt, units):
    """The preset machines of 'deathsphere ride': mass, centre-of-mass height,
    wheel and tyre radii, inertias, head height and where each comes from
    (docs/machine.md sec. 7); then the two-wheelers of 'ride --flat' and
    'ride --steer' (kind two-wheeler: wheel base, trail, steer axis tilt,
    wheel radii; docs/two-wheeler.md).

    \b
    Examples:
      deathsphere machines
      deathsphere machines --format csv
    """
    title = "Preset machines (docs/machine.md sec. 7)"
    emit([api.machines_table()], choose_format(fmt), title,
         view=_view("machines_view", title=title, units=display_units(units, {})))
