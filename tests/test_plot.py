"""The matplotlib figure of the allowed region (deathsphere.results.region_map
curves drawn by deathsphere.render.map_figure): the clear error when the
optional extra is missing (always tested, by hiding matplotlib or
contourpy), and the image itself when matplotlib is installed."""

import sys

import numpy as np
import pytest

from deathsphere.render import map_figure as plot
from deathsphere.render.figures import PlotExtraMissing
from deathsphere.results import region_map
from deathsphere.results.region_map import boundary_polylines, curve_map


@pytest.fixture(scope="module")
def paper_curves():
    pytest.importorskip("contourpy")
    return curve_map(0.3, 3.0, 0.5)


def test_missing_matplotlib_names_the_extra(monkeypatch, tmp_path, paper_curves):
    monkeypatch.setitem(sys.modules, "matplotlib", None)     # "import matplotlib" now fails
    with pytest.raises(PlotExtraMissing, match=r"pip install 'deathsphere\[plot\]'") as info:
        plot.plot_map(paper_curves, output=tmp_path / "map.png")
    assert isinstance(info.value, ImportError)
    assert not (tmp_path / "map.png").exists()
    monkeypatch.setitem(sys.modules, "contourpy", None)      # the curve tracer comes with matplotlib
    with pytest.raises(ImportError, match=r"pip install 'deathsphere\[plot\]'"):
        boundary_polylines(0.3, 3.0, 0.5)
    with pytest.raises(ImportError, match="contourpy"):
        curve_map(0.3, 3.0, 0.5)


def test_output_suffix_is_checked_first(tmp_path, paper_curves, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)     # the suffix is refused before matplotlib is needed
    with pytest.raises(ValueError, match=r"\.png, \.svg or \.pdf"):
        plot.plot_map(paper_curves, output=tmp_path / "map.jpg")


def test_curve_map_holds_what_the_figure_draws(paper_curves):
    c = paper_curves
    assert c.alpha_range_deg == (-5.0, 95.0) and not c.stability and c.margin is None
    assert c.interval_theta_deg.size == region_map.INTERVAL_THETAS
    assert c.interval_lo_deg.shape == c.interval_hi_deg.shape and c.interval_count.max() >= 1
    # every allowed interval is feasible at its midpoint
    from deathsphere.physics import region

    i, j = np.nonzero(np.arange(c.interval_lo_deg.shape[1]) < c.interval_count[:, None])
    mid = np.deg2rad(0.5 * (c.interval_lo_deg[i, j] + c.interval_hi_deg[i, j]))
    assert i.size > 1000 and region.feasible(np.deg2rad(c.interval_theta_deg[i]), mid, 0.3, 3.0, 0.5).all()
    assert set(c.boundaries) == {"eq0", "eq29", "eq33"}


def test_writes_png_and_svg(tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "map.png"
    fig = plot.plot_map(curve_map(0.3, 3.0, 0.5, mu=1.0, max_g=5.0), output=out)
    data = out.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 20_000
    labels = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    for eq in ("eq. (0)", "eq. (29)", "eq. (33)", "eq. (35)", "eq. (36)"):
        assert any(eq in label for label in labels), eq
    assert fig.axes[0].get_xlim() == (0.0, 180.0)
    svg = tmp_path / "map.svg"
    fig.savefig(svg)
    assert b"<svg" in svg.read_bytes()[:500]


def test_drawn_curves_lie_on_the_boundaries():
    pytest.importorskip("contourpy")
    a, r = 0.3, 3.0
    curves = boundary_polylines(a, r, 0.5, resolution=(181, 121))
    assert set(curves) == {"eq0", "eq29", "eq33"}
    th, al = np.concatenate([t for t, _ in curves["eq0"]]), np.concatenate([x for _, x in curves["eq0"]])
    assert th.size > 100
    assert np.allclose(np.sin(th - al), a / r, atol=1e-12)   # eq. (0) as an equality
    # the alpha = 0 and 90 deg lines of eq. (29) are there
    al29 = np.concatenate([x for _, x in curves["eq29"]])
    assert np.any(np.abs(al29) < 1e-12) and np.any(np.abs(al29 - np.pi / 2) < 1e-12)


def test_stability_margin_sign_is_the_verdict():
    from deathsphere.physics import region
    from deathsphere.physics.stability import Verdict, stability_margin, wheel_stability

    for outside, hi in ((False, 90.0), (True, 270.0)):
        T, A = np.meshgrid(np.deg2rad(np.arange(1.0, 180.0, 2.0)), np.deg2rad(np.arange(0.3, hi, 2.0)))
        ok = region.feasible(T, A, 0.9, 3.0, 0.5, outside=outside)
        verdict = wheel_stability(T[ok], A[ok], 0.9, 3.0, 0.5, 9.80665, outside)["verdict"]
        margin = stability_margin(T[ok], A[ok], 0.9, 3.0, 0.5, 9.80665, outside)
        assert np.any(verdict == Verdict.STABLE) and np.any(verdict == Verdict.UNSTABLE)
        assert np.array_equal(margin < 0, verdict == Verdict.UNSTABLE)
        assert np.array_equal(margin > 0, verdict == Verdict.STABLE)


def test_stability_figure_shades_and_draws_the_boundary(tmp_path):
    pytest.importorskip("matplotlib")
    from deathsphere.physics.stability import Verdict, wheel_stability

    a, r = 0.9, 3.0                                    # a/r = 0.3
    fig = plot.plot_map(curve_map(a, r, 0.5, stability=True, resolution=0.5), output=tmp_path / "s.png")
    assert (tmp_path / "s.png").read_bytes()[:4] == b"\x89PNG"
    ax = fig.axes[0]
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    for label in ("stability boundary (exact linearisation)", "allowed, stable", "allowed, unstable"):
        assert label in labels
    assert ax.get_title().startswith("Stability")
    lines = [ln for ln in ax.lines if ln.get_color() == plot.STABILITY_STYLE["color"]]
    t = np.concatenate([ln.get_xdata() for ln in lines])
    x = np.concatenate([ln.get_ydata() for ln in lines])
    assert t.size > 500
    # the drawn curve separates stable from unstable orbits: both within +-0.05 deg
    corners = np.stack([wheel_stability(np.deg2rad(t + dt), np.deg2rad(x + dx), a, r, 0.5, 9.80665)["verdict"]
                        for dt in (-0.05, 0.05) for dx in (-0.05, 0.05)])
    both = np.any(corners == Verdict.STABLE, axis=0) & np.any(corners == Verdict.UNSTABLE, axis=0)
    assert np.mean(both) > 0.97
    # the plain figure has no stability entries
    plain = plot.plot_map(curve_map(a, r, 0.5))
    assert "allowed" in [t.get_text() for t in plain.axes[0].get_legend().get_texts()]
    assert not any(ln.get_color() == plot.STABILITY_STYLE["color"] for ln in plain.axes[0].lines)
