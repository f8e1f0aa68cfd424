"""The matplotlib figure of the allowed region (deathsphere.plot): the clear
error when the optional extra is missing (always tested, by hiding
matplotlib), and the image itself when matplotlib is installed."""

import sys

import numpy as np
import pytest

from deathsphere import plot


def test_missing_matplotlib_names_the_extra(monkeypatch, tmp_path):
    monkeypatch.setitem(sys.modules, "matplotlib", None)     # "import matplotlib" now fails
    with pytest.raises(plot.PlotExtraMissing, match=r"pip install 'deathsphere\[plot\]'") as info:
        plot.plot_map(0.3, 3.0, 0.5, output=tmp_path / "map.png")
    assert isinstance(info.value, ImportError)
    assert not (tmp_path / "map.png").exists()
    with pytest.raises(plot.PlotExtraMissing):
        plot.boundary_polylines(0.3, 3.0, 0.5)


def test_output_suffix_is_checked_first(tmp_path):
    with pytest.raises(ValueError, match=r"\.png, \.svg or \.pdf"):
        plot.plot_map(0.3, 3.0, 0.5, output=tmp_path / "map.jpg")


def test_writes_png_and_svg(tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "map.png"
    fig = plot.plot_map(0.3, 3.0, 0.5, output=out, mu=1.0, max_g=5.0)
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
    curves = plot.boundary_polylines(a, r, 0.5, resolution=(181, 121))
    assert set(curves) == {"eq0", "eq29", "eq33"}
    th, al = np.concatenate([t for t, _ in curves["eq0"]]), np.concatenate([x for _, x in curves["eq0"]])
    assert th.size > 100
    assert np.allclose(np.sin(th - al), a / r, atol=1e-12)   # eq. (0) as an equality
    # the alpha = 0 and 90 deg lines of eq. (29) are there
    al29 = np.concatenate([x for _, x in curves["eq29"]])
    assert np.any(np.abs(al29) < 1e-12) and np.any(np.abs(al29 - np.pi / 2) < 1e-12)


def test_stability_margin_sign_is_the_verdict():
    from deathsphere.physics.stability import stability_margin
    from deathsphere.physics import region
    from deathsphere.physics.stability import Verdict, wheel_stability

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
    fig = plot.plot_map(a, r, 0.5, stability=True, stability_resolution_deg=0.5, output=tmp_path / "s.png")
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
    plain = plot.plot_map(a, r, 0.5)
    assert "allowed" in [t.get_text() for t in plain.axes[0].get_legend().get_texts()]
    assert not any(ln.get_color() == plot.STABILITY_STYLE["color"] for ln in plain.axes[0].lines)
