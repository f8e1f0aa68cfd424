"""``deathsphere simulate``: the exact equations of motion, integrated."""

from __future__ import annotations

import click

from deathsphere import api
from deathsphere.cli.base import (
    OutputPath,
    choose_format,
    cli,
    emit,
    fail,
    given,
    one_line,
    progress,
    stderr_console,
    stdout_console,
)
from deathsphere.cli.options import (
    MACHINE_OPTIONS,
    body_option,
    display_units,
    machine_from_options,
    machine_options,
    output_options,
    param_option,
    params_options,
    setup_options,
    single,
    surface_options,
    units_option,
)
from deathsphere.table import Table

#: --output formats and the package each needs: still figures of the run,
#: the 3-D view (html needs nothing beyond the core), and the time series
#: (or, with --summary-only, the summary) as a table file.
OUTPUTS = {"png": "matplotlib", "svg": "matplotlib", "pdf": "matplotlib",
           "html": None, "gif": "matplotlib", "mp4": "matplotlib", "csv": None, "json": None, "ndjson": None}
#: --output extensions that are tables
TABLE_OUTPUTS = ("csv", "json", "ndjson")


def _preflight_output(output) -> bool:
    """Before anything is integrated (the path, extension and the plot extra
    are already checked by :class:`OutputPath`): an .mp4 also needs its
    encoder.  Returns True for a 3-D view, False for a figure."""
    from deathsphere.viewer import (
        VIEW_FORMATS,
        ViewerUnavailable,
        check_view_output,
        view_format,
    )

    if view_format(output) not in VIEW_FORMATS:
        return False
    try:
        check_view_output(output)
    except ViewerUnavailable as exc:
        fail(one_line(str(exc)))
    return True


@cli.command("simulate")
@param_option("theta", help="Polar angle of the contact point (a vertical orbit: the cone angle, "
              "90 = great circle).")
@param_option("height")
@param_option("alpha")
@param_option("speed")
@param_option("com_speed")
@params_options("omega", "omega3")
@single("--branch", type=click.IntRange(0, None), default=0,
        help="Which orbit when several give the request: a sphere with --omega3, the root of eq. 55 (0 slow, "
             "1 fast); a wheel with --speed or --omega, the tilt (0 first, in increasing alpha) [default: 0].")
@click.option("--vertical", is_flag=True, help="A vertical orbit of a wheel, started at the top with --v-top.")
@params_options("v_top", "perturb", "periods", "points_per_period")
@single("--method", type=click.Choice(api.METHODS, case_sensitive=False), default="DOP853",
        help="scipy.integrate.solve_ivp method [default: DOP853].")
@params_options("rtol", "atol", "max_steps")
@single("--frame", type=click.Choice(api.FRAMES), default="turning",
        help="Integrate in the frame turning with the steady orbit, or in the lab [default: turning].")
@click.option("--summary-only", is_flag=True, help="With csv/json/ndjson: print the summary rows, not the time series.")
@single("--output", type=OutputPath(OUTPUTS), default=None, metavar="FILE",
        help="Plot theta, alpha and the contact point's track to FILE (.png/.svg/.pdf; plot extra), write "
             "the 3-D view: .html (interactive, self-contained), .gif (plot extra), .mp4 (plot extra and "
             "ffmpeg), or the time series: .csv/.json/.ndjson.  A two-wheeler's figure plots lean, steer, "
             "steer torque and contact forces; its view draws both wheels, the frames, the rider's head and "
             "the contacts' paths.  Nothing is printed on stdout then.")
@params_options("loop_seconds", "playback")
@body_option(("wheel", "sphere"))
@machine_options(without=("a",), machine_help="Simulate a machine (motorcycle and rider) instead: a preset (see "
                 "'deathsphere machines'), its wheel radius -a, changed by the machine options "
                 "(docs/machine.md sec. 5).  Horizontal orbits: --alpha, --speed (its contact's, as ride's) or "
                 "--com-speed (its centre of mass's).")
@single("--steer", type=click.Choice(("free", "locked"), case_sensitive=False), default=None,
        help="A two-wheeler (--machine benchmark-bicycle) from its steady turn at --theta/--height and --speed "
             "(the rear contact's): free, the steer held by a torque (the turn's steady torque unless "
             "--steer-gains or --hands-free), or locked at the turn's steer (docs/two-wheeler.md sec. 10.1).")
@click.option("--flat", is_flag=True, default=False,
              help="A two-wheeler on flat ground: from upright straight running at --speed, or from the steady "
                   "turn of --turn-radius.")
@params_options("turn_radius", "duration", "perturb_lean_rate", "perturb_steer_rate")
@single("--steer-gains", default=None, metavar="K_LEAN,K_RATE",
        help="A two-wheeler's rider: steer torque = steady torque + K_LEAN (lean - steady lean) + K_RATE "
             "lean rate [N m/rad, N m s/rad]; positive steers into the fall.")
@click.option("--hands-free", is_flag=True, default=False, help="A two-wheeler with no steer torque at all.")
@setup_options()
@surface_options(lanes=False)
@output_options()
@units_option()
def simulate_command(theta, height, steer, flat, turn_radius, duration, perturb_lean_rate, perturb_steer_rate,
                     steer_gains, hands_free, alpha, speed, com_speed, omega, omega3, branch, vertical, v_top, perturb, periods,
                     points_per_period, method, rtol, atol, max_steps, frame, summary_only, output, loop_seconds,
                     playback, body, machine,
                     machine_file, mass, com_height, tyre_radius, roll_inertia, pitch_inertia, yaw_inertia,
                     spin_inertia, head_height, side, a, r, diameter, k, g, mu, surface, wall_angle, wall_height,
                     profile, fmt, units):
    """Integrate the exact equations of motion from a steady orbit (beyond the paper).

    The rigid-body equations of a wheel or sphere rolling without slipping
    (eqs. 2-7b in general form, docs/dynamics.md) are integrated with
    scipy.integrate.solve_ivp.  The run stops with status contact_lost when
    the normal force reaches zero and slips when the friction needed exceeds
    --mu; otherwise completed.  On a terminal: the summary (drift of theta
    and alpha, least normal force, most friction, energy and constraint
    drift, method and tolerances).  Piped: the time series as CSV, the
    summary on stderr.  With --output nothing goes to stdout: the file
    is the output, and stderr says where it went (and, on a terminal,
    shows the summary).

    Off the globe (--surface cylinder, cone, plane or profile, docs/
    surfaces.md): the paper's wheel (--alpha, or --speed, --com-speed or
    --omega with --branch) or ball (--omega3 and --branch, or --omega)
    inside or, with --side outside, round a drum's outside or on a cone's
    or a dome's roof (flat ground has one side), from the steady orbit on
    the lane --height (flat ground: --turn-radius); the run also stops with
    hits_floor (the body's lowest point reaches the floor at the wall's
    foot) or over_the_top (the contact passes --wall-height), and --perturb
    tilts a wheel about its direction of travel or turns a ball's velocity
    up the wall (docs/simulation.md, "On any ground").

    A two-wheeler (--machine benchmark-bicycle with --steer free|locked,
    --steer-gains, --hands-free or --flat): the Whipple bicycle's nonlinear
    equations from its steady turn at --theta/--height and --speed (with
    --flat: from upright straight running at --speed, or the turn of
    --turn-radius), kicked by --perturb degrees of lean,
    --perturb-lean-rate and --perturb-steer-rate deg/s, for --periods of
    the turn or --duration seconds (straight running: 5 s unless given;
    --points-per-period is then rows per second) (docs/two-wheeler.md
    sec. 10.1).  On a drum, a cone or a profile (--surface cylinder, cone,
    profile; a two-wheeler's preset such as stunt125-steer): from the
    steady turn at --height up the wall, the run also stopping with
    hits_floor (a wheel reaches the floor) or over_the_top (the rear
    contact passes --wall-height) (docs/two-wheeler.md sec. 12.7).
    The benchmark's case (the first --flat example below): a
    half-degree kick hands-free at 5 m/s, inside the self-stable window
    4.29-6.02 m/s, dies away at the rate of the largest eigenvalue that
    'deathsphere ride --machine benchmark-bicycle --flat --speed 5' gives
    (-0.32 1/s); at 3 m/s it grows.  On the globe --output run.html
    shows its wheels, frames and rider in the globe (on a wall: in the
    drum, the cone or the profile, drawn from its meridian).

    \b
    Examples:
      deathsphere simulate --theta 60 --alpha 10 --periods 20
      deathsphere simulate --theta 60 --alpha 10 --perturb 3 --format csv
      deathsphere simulate --theta 90 --alpha 80 --perturb 1e-4  (loses contact)
      deathsphere simulate --vertical --theta 90 --v-top 5.2
      deathsphere simulate --body sphere --theta 60 --omega3 80 --branch 1
      deathsphere simulate --theta 90 --speed 40km/h --diameter 16ft
      deathsphere simulate --theta 90 --com-speed 40km/h --diameter 16ft
      deathsphere simulate --theta 90 --alpha 80 --perturb 0.06 --output o.html
      deathsphere simulate --machine stunt125 --theta 60 --speed 30km/h -r 8ft
      deathsphere simulate --machine stunt125 --theta 90 --alpha 15 --output v.gif
      deathsphere simulate --surface cylinder --diameter 32ft --height 2 \\
          --alpha 10 --perturb 2
      deathsphere simulate --surface cylinder --diameter 32ft --height 2 \\
          --body sphere --omega 6 --perturb 1 --output bob.html
      deathsphere simulate --theta 60 --alpha 10 --output run.mp4 \\
          --loop-seconds 4 --playback 0.5
      deathsphere simulate --machine benchmark-bicycle --steer free \\
          --height 1 --speed 5 --diameter 16ft --perturb 0.2 \\
          --periods 1 --steer-gains 10,10
      deathsphere simulate --machine benchmark-bicycle --steer free \\
          --theta 100 --speed 9 --diameter 16ft --perturb 0.2 \\
          --steer-gains 10,10 --output run.html
      deathsphere simulate --machine benchmark-bicycle --flat --speed 5 \\
          --perturb 0.5
      deathsphere simulate --machine stunt125-steer --steer free \\
          --surface cylinder --diameter 32ft --height 2m --speed 60km/h \\
          --perturb 1 --output wall.html
      deathsphere simulate --machine benchmark-bicycle --flat --speed 3 \\
          --perturb 0.5 --duration 10 --summary-only  (grows, falls)
      deathsphere simulate --machine benchmark-bicycle --flat --speed 5 \\
          --turn-radius 10 --steer locked --perturb-lean-rate 5
    """
    from deathsphere.render.simulation_view import simulation_view
    from deathsphere.viewer import view_format

    shown = display_units(units, click.get_current_context().params)

    from deathsphere.api.two_wheelers import is_two_wheeler_file
    from deathsphere.api.two_wheelers import is_two_wheeler

    # a surface but the globe: the paper's bodies on it, their lane --height (flat ground: --turn-radius)
    from deathsphere.api.simulation import names_a_wall

    arena = given(surface=surface, wall_angle=wall_angle, wall_height=wall_height, profile=profile)
    on_arena = bool(arena) and names_a_wall(**arena)
    two_wheeler_only = given(flat=flat or None, turn_radius=None if on_arena else turn_radius, duration=duration,
                             perturb_lean_rate=perturb_lean_rate, perturb_steer_rate=perturb_steer_rate)
    two_wheeler_file = machine_file is not None and is_two_wheeler_file(machine_file)
    if (steer is not None or steer_gains is not None or hands_free or two_wheeler_only or is_two_wheeler(machine)
            or two_wheeler_file):
        refused = [flag for flag, value in (("--alpha", alpha), ("--com-speed", com_speed), ("--omega", omega),
                                            ("--omega3", omega3),
                                            ("--vertical", vertical or None), ("--v-top", v_top), ("--body", body),
                                            ("--machine-file", None if two_wheeler_file else machine_file),
                                            ("-a", a), ("-k", k),
                                            ("--side", side), ("--loop-seconds", loop_seconds),
                                            ("--playback", playback), ("--max-steps", max_steps))
                   if value is not None]
        refused += [MACHINE_OPTIONS[name] for name in given(mass=mass, com_height=com_height,
                                                            tyre_radius=tyre_radius, roll_inertia=roll_inertia,
                                                            pitch_inertia=pitch_inertia, yaw_inertia=yaw_inertia,
                                                            spin_inertia=spin_inertia, head_height=head_height)]
        if frame != "turning":
            refused.append("--frame")
        if refused:
            fail(f"{', '.join(refused)} not for a two-wheeler's run: give --machine, --steer free|locked, "
                 "--theta or --height (or --flat and --turn-radius), --speed, -r/--diameter, --surface, "
                 "--wall-angle, --wall-height, --profile, -g, --mu, --branch, "
                 "--perturb, --perturb-lean-rate, --perturb-steer-rate, --periods or --duration, "
                 "--points-per-period, --steer-gains or --hands-free, --method, --rtol, --atol")
        if two_wheeler_file:
            machine = machine_from_options(machine, machine_file)
        _two_wheeler(machine, steer, steer_gains, hands_free, summary_only, output, fmt, shown,
                     **given(theta=theta, height=height, speed=speed, r=r, diameter=diameter, g=g, mu=mu,
                             branch=branch, perturb=perturb, periods=periods,
                             points_per_period=points_per_period, method=method, rtol=rtol, atol=atol, **arena),
                     # on an arena --turn-radius was not counted as a two-wheeler's: passed, for the API to refuse
                     **two_wheeler_only, **(given(turn_radius=turn_radius) if on_arena else {}))
        return
    if height is not None and not on_arena:
        raise click.UsageError("--height is a two-wheeler's lane (with --steer) or one off the globe (with "
                               "--surface); on the sphere give --theta")
    holds = [name for name, value in (("--alpha", alpha), ("--speed", speed), ("--com-speed", com_speed),
                                      ("--omega", omega), ("--omega3", omega3)) if value is not None]
    if len(holds) > 1:
        raise click.UsageError(f"{holds[1]}: give one of --alpha, --speed (the contact's), --com-speed (the "
                               "centre's), --omega and --omega3")

    overrides = {"mass": mass, "com_height": com_height, "tyre_radius": tyre_radius, "roll_inertia": roll_inertia,
                 "pitch_inertia": pitch_inertia, "yaw_inertia": yaw_inertia, "spin_inertia": spin_inertia,
                 "head_height": head_height}
    chosen = None
    if machine is not None or machine_file is not None:
        # -a is the wheel's radius: a machine's, as ride's --wheel-radius
        chosen, a = machine_from_options(machine, machine_file, a=a, **overrides), None
    elif given(**overrides):
        flags = [MACHINE_OPTIONS[name] for name in given(**overrides)]
        what = "is a machine option" if len(flags) == 1 else "are machine options"
        raise click.UsageError(f"{', '.join(flags)} {what}: give --machine (or --machine-file)")
    loop = api.animation_options(output, **given(loop_seconds=loop_seconds, playback=playback))
    view = output is not None and _preflight_output(output)
    rider, run, options = api.simulation_request({
        "theta": theta, "branch": branch, "vertical": vertical, "method": method, "frame": frame,
        "record_states": view,
        **given(alpha=alpha, speed=speed, com_speed=com_speed, body=body, side=side, a=a, r=r, diameter=diameter, k=k, g=g, mu=mu,
                omega3=omega3, omega=omega,
                v_top=v_top, perturb=perturb, periods=periods, points_per_period=points_per_period, rtol=rtol,
                atol=atol, max_steps=max_steps, machine=chosen, height=height, turn_radius=turn_radius, **arena)})
    sim = api.prepare_simulation(rider, run, options)
    fmt = choose_format(fmt)
    table_file = view_format(output) if output is not None and view_format(output) in TABLE_OUTPUTS else None
    series = []

    def chunks(advance):
        for table in sim.chunks(progress=advance):
            if output is not None and table_file is None:
                series.append(table)
            yield table

    def run(advance):
        if table_file is not None and not summary_only:
            emit(chunks(advance), table_file, output=output)
        elif output is not None or fmt == "table" or summary_only:
            for _ in chunks(advance):
                pass
        else:
            emit(chunks(advance), fmt)

    with progress("simulate", sim.n_progress) as bar:
        run(bar.update)
    summary = sim.summary()
    if output is not None:
        # the file is the output: stdout stays empty (a pipe downstream
        # gets nothing it did not ask for); the summary on a terminal only
        if stderr_console().is_terminal:
            stderr_console().print(simulation_view(summary, shown))
    elif fmt == "table":
        stdout_console().print(simulation_view(summary, shown))
    elif summary_only:
        emit([summary], fmt)
    else:
        stderr_console().print(simulation_view(summary, shown))
    if table_file is not None:
        if summary_only:
            emit([summary], table_file, output=output)
        stderr_console().print(f"deathsphere: wrote {output}", soft_wrap=True)
    elif view:
        from deathsphere.viewer import write_view

        with progress("frames", None) as bar:
            size = write_view(output, Table.concat(series), summary, sim.view_frames(), progress=bar.update,
                              ground=sim.ground, **loop)
        stderr_console().print(f"deathsphere: wrote {output} ({size / 1e6:.2f} MB)", soft_wrap=True)
    elif output is not None:
        from deathsphere.render.figures import PlotExtraMissing
        from deathsphere.render.simulation_figure import plot_simulation

        try:
            plot_simulation(Table.concat(series), summary, output=output)
        except PlotExtraMissing as exc:
            fail(one_line(str(exc)))
        stderr_console().print(f"deathsphere: wrote {output}", soft_wrap=True)


def _two_wheeler(machine, steer, steer_gains, hands_free, summary_only, output, fmt, units, **options):
    """``simulate`` of a two-wheeler: the API validates, the series (or the
    summary) is the output, the summary on a terminal (docs/two-wheeler.md
    sec. 10.1)."""
    import numpy as np

    from deathsphere.viewer import view_format

    from deathsphere.api.two_wheelers import simulate_two_wheeler

    table_file = output is not None and view_format(output) in TABLE_OUTPUTS
    if options.get("flat") and output is not None and view_format(output) in ("gif", "mp4"):
        fail(f"a run on flat ground is drawn as a page (.html), not a loop (.{view_format(output)})")
    view = output is not None and not table_file and _preflight_output(output)
    with progress("simulate", 100) as bar:
        series, summary, *frames = simulate_two_wheeler(
            "benchmark-bicycle" if machine is None else machine, steer="free" if steer is None else steer,
            steer_gains=steer_gains, hands_free=hands_free, view=view, progress=bar.update, **options)
    start = "upright straight running" if np.isnan(summary["period_s"][0]) else "its steady turn"
    title = f"{summary['machine'][0]}: simulated from {start} (docs/two-wheeler.md sec. 10.1)"
    fmt = choose_format(fmt)
    if output is not None:
        if table_file:
            emit([summary if summary_only else series], view_format(output), output=output)
            stderr_console().print(f"deathsphere: wrote {output}", soft_wrap=True)
        elif view:
            from deathsphere.viewer import write_scene
            from deathsphere.viewer.two_wheeler_scene import two_wheeler_scene

            with progress("frames", None) as bar:
                size = write_scene(output, two_wheeler_scene(series, summary, frames[0]), progress=bar.update)
            stderr_console().print(f"deathsphere: wrote {output} ({size / 1e6:.2f} MB)", soft_wrap=True)
        else:
            from deathsphere.render.figures import PlotExtraMissing
            from deathsphere.render.two_wheeler_figure import plot_two_wheeler_run

            try:
                plot_two_wheeler_run(series, summary, output=output)
            except PlotExtraMissing as exc:
                fail(one_line(str(exc)))
            stderr_console().print(f"deathsphere: wrote {output}", soft_wrap=True)
        if stderr_console().is_terminal:
            emit_to_stderr(summary, title)
    elif fmt == "table" or summary_only:
        emit([summary], fmt, title, units=units)
    else:
        emit([series], fmt)
        emit_to_stderr(summary, title)


def emit_to_stderr(summary, title):
    """The summary's verdict in one line on stderr (the series went to stdout)."""
    status, t_event = summary["status"][0], summary["t_event_s"][0]
    when = f" at t = {t_event:.4g} s" if status != "completed" else ""
    stderr_console().print(f"deathsphere: {title}: {status}{when}, most lean deviation "
                           f"{summary['max_lean_deviation_deg'][0]:.4g} deg", soft_wrap=True)
