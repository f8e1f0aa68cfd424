"""Figures of a simulation: theta(t), alpha(t), the normal force
and the track of the contact point, drawn with matplotlib.

Beyond the paper: the time series come from
:mod:`deathsphere.simulation` (exact equations of motion, docs/simulation.md).
matplotlib is optional (``pip install 'deathsphere[plot]'``) and imported
only when a figure is made; without it :func:`plot_simulation` raises
:class:`deathsphere.render.figures.PlotExtraMissing`.
"""

from __future__ import annotations

import numpy as np

from deathsphere.render.figures import (
    FORMATS,
    PlotExtraMissing,
    figure_format,
    import_matplotlib,
    save_figure,
)
from deathsphere.table import Table

#: the events off the globe, where the body still presses on the wall
_WALL_ENDS = ("hits_floor", "over_the_top")

__all__ = ["plot_simulation", "PlotExtraMissing", "FORMATS", "MAX_LEGEND"]

#: at most this many bodies get a legend entry
MAX_LEGEND = 10

_EVENT_STYLE = {"contact_lost": dict(marker="x", color="#c0392b"),
                "slips": dict(marker="D", color="#d35400"),
                "failed": dict(marker="s", color="black"),
                "hits_floor": dict(marker="v", color="#8e44ad"),
                "over_the_top": dict(marker="^", color="#8e44ad")}


def plot_simulation(series: Table, summary: Table | None = None, *, output=None, title=None, dpi=150):
    """Figure of a simulated run: four panels sharing the bodies' colours.

    1. theta(t): polar angle of the contact point about the orbit axis [deg]
       (off the globe, where the series has ``height_m``: the contact's
       height above the ground's lowest point [m], here and in panel 4)
    2. alpha(t): tilt of axis 3 below the orbit plane, eq. (11) [deg]
    3. normal force per unit mass against t [m/s^2] (contact needs > 0)
    4. the contact point's track: theta against its azimuth phi [deg]
       (a steady orbit is a horizontal line; phi from the top for vertical
       orbits)

    Events (contact lost, slip) from ``summary`` are marked.  Small
    variations are shown with matplotlib's axis offset (e.g. "+6e1").

    Parameters
    ----------
    series : Table   time series (:data:`deathsphere.simulation.SERIES_COLUMNS`)
    summary : Table or None   (:data:`deathsphere.simulation.SUMMARY_COLUMNS`)
    output : path ending in .png, .svg or .pdf, or None (no file written)
    title : str or None;  dpi : int (raster output)

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    PlotExtraMissing  when matplotlib is not installed
    ValueError        for an output name that is not .png/.svg/.pdf, or a
                      series without the needed columns
    """
    fmt = figure_format(output) if output is not None else None
    needed = ("input_row", "t_s", "phi_deg", "theta_deg", "alpha_deg", "normal_per_mass_m_s2")
    missing = [c for c in needed if c not in series]
    if missing:
        raise ValueError(f"series lacks columns: {', '.join(missing)}")
    import_matplotlib()
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    fig = Figure(figsize=(10.0, 7.0), layout="constrained")
    axes = fig.subplots(2, 2)
    ax_th, ax_al, ax_n, ax_tr = axes[0, 0], axes[0, 1], axes[1, 0], axes[1, 1]
    rows = series["input_row"]
    bodies = np.unique(rows)
    colours = [f"C{i % 10}" for i in range(bodies.size)]
    events = {}
    if summary is not None and "event_time_s" in summary:
        for i, row in enumerate(summary["input_row"]):
            st = str(summary["status"][i])
            if st in _EVENT_STYLE and np.isfinite(summary["event_time_s"][i]):
                events[int(row)] = (st, i)
    # off the globe the lane is the contact's height (no polar angle there)
    lane, lane_label = (("height_m", "contact height [m]") if "height_m" in series
                        else ("theta_deg", r"$\theta$ [deg]"))
    for body, colour in zip(bodies, colours):
        m = rows == body
        t = series["t_s"][m]
        label = f"body {int(body)}" if bodies.size <= MAX_LEGEND else None
        kw = dict(color=colour, lw=1.0)
        ax_th.plot(t, series[lane][m], label=label, **kw)
        ax_al.plot(t, series["alpha_deg"][m], **kw)
        ax_n.plot(t, series["normal_per_mass_m_s2"][m], **kw)
        ax_tr.plot(series["phi_deg"][m], series[lane][m], **kw)
        if int(body) in events:
            st, i = events[int(body)]
            style = dict(_EVENT_STYLE[st], ls="", ms=7, mew=1.5, zorder=5)
            te = summary["event_time_s"][i]
            # the event is the body's last row
            at = series[lane][m][-1] if lane == "height_m" else summary["event_theta_deg"][i]
            ax_th.plot([te], [at], **style)
            ax_al.plot([te], [summary["event_alpha_deg"][i]], **style)
            # a wall's end comes with the body still pressing on the wall
            ax_n.plot([te], [series["normal_per_mass_m_s2"][m][-1] if st in _WALL_ENDS else 0.0], **style)
            ax_tr.plot([summary["event_phi_deg"][i]], [at], **style)
    ax_n.axhline(0.0, color="0.5", lw=0.8, ls="--")
    ax_th.set_ylabel(r"polar angle of contact $\theta$ [deg]" if lane == "theta_deg" else lane_label)
    ax_al.set_ylabel(r"tilt $\alpha$ [deg] (eq. 11)")
    ax_n.set_ylabel(r"normal force / mass [m/s$^2$]")
    for ax in (ax_th, ax_al, ax_n):
        ax.set_xlabel("t [s]")
    ax_tr.set_xlabel(r"azimuth of contact $\phi$ [deg]")
    ax_tr.set_ylabel(lane_label)
    ax_tr.set_title("track of the contact point", fontsize=10)
    for ax in (ax_th, ax_al, ax_n, ax_tr):
        ax.grid(True, color="0.88", lw=0.5)
    handles = []
    for st in sorted({v[0] for v in events.values()}):
        handles.append(Line2D([], [], ls="", mew=1.5, label=st.replace("_", " "), **_EVENT_STYLE[st]))
    if bodies.size <= MAX_LEGEND and (bodies.size > 1 or handles):
        ax_th.legend(handles=ax_th.get_legend_handles_labels()[0] + handles, fontsize=8)
    if title is None:
        title = _default_title(summary, bodies.size)
    fig.suptitle(title, fontsize=11)
    if output is not None:
        save_figure(fig, output, fmt, dpi)
    return fig


def _default_title(summary, n_bodies):
    if summary is None or len(summary) == 0:
        return f"Simulation of {n_bodies} bod{'y' if n_bodies == 1 else 'ies'}"
    if len(summary) == 1:
        s = {name: summary[name][0] for name in summary.names}
        lane = (f"on the {s['surface']}, height {s['height_m']:g} m" if "surface" in s
                else f"theta = {s['theta_deg']:g} deg")
        what = (f"{s['body']} {s['side']}, {s['orbit']} orbit, {lane}"
                + (f", alpha = {s['alpha_deg']:g} deg" if s["body"] == "wheel" else ""))
        kick = s["perturb_deg"] + s["perturb_theta_deg"] if "perturb_deg" in summary else 0.0
        extra = f", kick {s['perturb_deg']:g} deg" if kick else ""
        return f"{what}{extra}: {s['status'].replace('_', ' ')} ({s['method']}, rtol {s['rtol']:g})"
    counts = {}
    for st in summary["status"]:
        counts[str(st)] = counts.get(str(st), 0) + 1
    return f"Simulation of {len(summary)} bodies: " + ", ".join(f"{v} {k.replace('_', ' ')}"
                                                               for k, v in counts.items())
