"""The figure of a two-wheeler's run (``deathsphere simulate --machine
benchmark-bicycle --steer free --output run.png|.svg|.pdf``; beyond the
paper, docs/two-wheeler.md sec. 10.1): lean, steer, steer torque and the
contact forces against time, drawn with matplotlib (the ``plot`` extra)
from the columns of :func:`deathsphere.api.two_wheelers.simulate_two_wheeler`.
"""

from __future__ import annotations

import numpy as np

from deathsphere.render.figures import figure_format, import_matplotlib, save_figure
from deathsphere.table import Table

__all__ = ["plot_two_wheeler_run"]

#: statuses that end a run early, marked at the last row
_EVENTS = {"contact_lost": "contact lost", "slips": "slips", "failed": "failed"}


def plot_two_wheeler_run(series: Table, summary: Table, *, output=None, dpi=150):
    """Four panels against t [s]: the lean from the wall's normal and the
    steer [deg], each with the steady turn's value dashed; the steer
    torque [N m]; the normal and friction forces per unit mass at each
    wheel [m/s^2] (contact needs the normal > 0).  An early end (contact
    lost, slip) is marked on every panel.  Returns the matplotlib Figure;
    writes ``output`` (.png, .svg or .pdf) whole or not at all.  Raises
    :class:`~deathsphere.render.figures.PlotExtraMissing` without
    matplotlib."""
    fmt = figure_format(output) if output is not None else None
    import_matplotlib()
    from matplotlib.figure import Figure

    row = summary[0]
    t = np.asarray(series["t_s"], dtype=np.float64)
    fig = Figure(figsize=(10.0, 7.0), layout="constrained")
    (ax_lean, ax_steer), (ax_torque, ax_force) = fig.subplots(2, 2, sharex=True)
    for ax, column, steady, label in ((ax_lean, "lean_surface_deg", row["lean_surface_deg"],
                                       "lean from the wall's normal [deg]"),
                                      (ax_steer, "steer_deg", row["steer_deg"], "steer [deg]"),
                                      (ax_torque, "steer_torque_n_m", row["steer_torque_n_m"],
                                       "steer torque [N m]")):
        ax.plot(t, series[column], color="C0", lw=1.2)
        ax.axhline(steady, color="0.45", lw=0.9, ls="--", label="steady turn")
        ax.set_ylabel(label)
    ax_lean.legend(fontsize=8)
    for column, colour, style, label in (("normal_rear_per_mass_m_s2", "C0", "-", "normal, rear"),
                                         ("normal_front_per_mass_m_s2", "C1", "-", "normal, front"),
                                         ("friction_rear_per_mass_m_s2", "C0", ":", "friction, rear"),
                                         ("friction_front_per_mass_m_s2", "C1", ":", "friction, front")):
        ax_force.plot(t, series[column], color=colour, ls=style, lw=1.2, label=label)
    ax_force.axhline(0.0, color="0.5", lw=0.8)
    ax_force.set_ylabel(r"force / mass [m/s$^2$]")
    ax_force.legend(fontsize=8)
    event = _EVENTS.get(str(row["status"]))
    for ax in (ax_lean, ax_steer, ax_torque, ax_force):
        ax.grid(True, color="0.88", lw=0.5)
        if event and t.size:
            ax.axvline(t[-1], color="#c0392b", lw=1.2)
    for ax in (ax_torque, ax_force):
        ax.set_xlabel("t [s]")
    if event:
        ax_lean.annotate(f"{event} at t = {t[-1]:.3f} s", (t[-1], 0.5), xycoords=("data", "axes fraction"),
                         ha="right", color="#c0392b", fontsize=9)
    control = {"rider": f"rider {row['k_lean_n_m_rad']:g} N m/rad, {row['k_rate_n_m_s_rad']:g} N m s/rad",
               "hands-free": "hands free"}.get(str(row["control"]), "steady steer torque held")
    fig.suptitle(f"{row['machine']}: theta = {row['theta_deg']:.4g} deg, {row['v_rear_m_s']:.4g} m/s, globe of "
                 f"{2 * row['r_m']:.4g} m, kick {row['perturb_deg']:g} deg, {control}: "
                 f"{str(row['status']).replace('_', ' ')}", fontsize=11)
    if output is not None:
        save_figure(fig, output, fmt, dpi)
    return fig
