"""``deathsphere simulate``: the exact equations of motion, integrated."""

from __future__ import annotations

import click


from deathsphere.cli.base import (
    OutputPath,
    Quantity,
    body_options,
    choose_format,
    cli,
    emit,
    fail,
    one_line,
    output_options,
    progress,
    stderr_console,
    stdout_console,
)

#: --output formats and the package each needs: still figures of the run,
#: and the 3-D view (html needs nothing beyond the core).
OUTPUTS = {"png": "matplotlib", "svg": "matplotlib", "pdf": "matplotlib",
           "html": None, "gif": "matplotlib", "mp4": "matplotlib"}


def _preflight_output(output) -> bool:
    """Before anything is integrated (the path, extension and the plot extra
    are already checked by :class:`OutputPath`): an .mp4 also needs its
    encoder.  Returns True for a 3-D view, False for a figure."""
    from deathsphere.viewer import VIEW_FORMATS, ViewerUnavailable, check_view_output, view_format

    if view_format(output) not in VIEW_FORMATS:
        return False
    try:
        check_view_output(output)
    except ViewerUnavailable as exc:
        fail(one_line(str(exc)))
    return True


@cli.command("simulate")
@click.option("--theta", required=True, type=Quantity("theta"), metavar="DEG",
              help="Polar angle of the contact point (vertical orbits: the cone angle, 90 = great circle).")
@click.option("--alpha", type=Quantity("alpha"), default=None, metavar="DEG",
              help="Wheel: tilt of the steady orbit, any angle (205 = -155).")
@click.option("--omega3", type=Quantity("omega3"), default=None, metavar="RAD_S",
              help="Sphere: spin about the contact normal.")
@click.option("--omega", type=Quantity("omega"), default=None, metavar="RAD_S",
              help="Sphere: the signed orbital rate instead.")
@click.option("--branch", type=click.IntRange(0, 1), default=0, show_default=True,
              help="Sphere with --omega3: root of eq. 55 (0 slow, 1 fast).")
@click.option("--vertical", is_flag=True, help="A vertical orbit of a wheel, started at the top with --v-top.")
@click.option("--v-top", "v_top", type=Quantity("v_top"), default=None, metavar="M_S",
              help="Vertical: speed at the top, >= 0.")
@click.option("--perturb", type=Quantity("perturb"), default=0.0, show_default=True, metavar="EPS",
              help="Kick off the steady orbit [rad]: the wheel tilted by EPS about its direction of travel "
                   "(a sphere: its contact point moved EPS down the meridian); rolling and contact still hold.")
@click.option("--periods", type=Quantity("periods"), default=20.0, show_default=True,
              help="How long: periods of the steady orbit (vertical: laps), > 0.")
@click.option("--points-per-period", type=Quantity("points_per_period"), default=100, show_default=True,
              help="Output rows per period, 2..100000.")
@click.option("--method", type=click.Choice(("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA")), default="DOP853",
              show_default=True, help="scipy.integrate.solve_ivp method.")
@click.option("--rtol", type=click.FloatRange(1e-14, 1e-2), default=1e-10, show_default=True)
@click.option("--atol", type=click.FloatRange(1e-16, 1.0), default=None, help="[default: = rtol, per scaled component]")
@click.option("--frame", type=click.Choice(("turning", "lab")), default="turning", show_default=True,
              help="Integrate in the frame turning with the steady orbit, or in the lab.")
@click.option("--summary-only", is_flag=True, help="With csv/json/ndjson: print the summary rows, not the time series.")
@click.option("--output", type=OutputPath(OUTPUTS), default=None, metavar="FILE",
              help="Plot theta, alpha and the contact point's track to FILE (.png/.svg/.pdf; plot extra), "
                   "or write the 3-D view: .html (interactive, self-contained), .gif (plot extra), "
                   ".mp4 (plot extra and ffmpeg).")
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
      deathsphere simulate --body sphere --theta 60 --omega3 80 --branch 1
      deathsphere simulate --theta 90 --alpha 80 --perturb 1e-3 --output orbit.html   (3-D view)
    """
    from deathsphere import simulation
    from deathsphere.api import prepare_simulation
    from deathsphere.render.simulation_view import simulation_view

    view = output is not None and _preflight_output(output)
    sim = prepare_simulation(theta, alpha, body=body.lower(), side=side.lower(), a=a, r=r, k=k, g=g, mu=mu,
                             omega3=omega3, omega=omega, branch=branch, vertical=vertical, v_top=v_top,
                             perturb=perturb, periods=periods, points_per_period=points_per_period,
                             method=method, rtol=rtol, atol=atol, frame=frame, record_states=view)
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

    with progress("simulate", sim.n_chunks) as bar:
        run(bar.update)
    summary = sim.summary()
    if fmt == "table":
        stdout_console().print(simulation_view(summary))
    elif summary_only:
        emit([summary], fmt)
    else:
        stderr_console().print(simulation_view(summary))
    if view:
        from deathsphere.viewer import write_view

        size = write_view(output, simulation.concat_tables(series), summary, sim.sample_states())
        stderr_console().print(f"deathsphere: wrote {output} ({size / 1e6:.2f} MB)", soft_wrap=True)
    elif output is not None:
        from deathsphere.render.figures import PlotExtraMissing
        from deathsphere.render.simulation_figure import plot_simulation

        try:
            plot_simulation(simulation.concat_tables(series), summary, output=output)
        except PlotExtraMissing as exc:
            fail(one_line(str(exc)))
        stderr_console().print(f"deathsphere: wrote {output}")
