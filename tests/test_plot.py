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
