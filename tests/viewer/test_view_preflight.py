"""simulate --output: the extension decides figure or 3-D view, and what
cannot be written here is refused in one line, exit 2, before any
integration."""

import sys

import pytest

import deathsphere.viewer as viewer
from deathsphere import simulation

ARGS = ("simulate", "--theta", "60", "--alpha", "10", "--periods", "0.2")


@pytest.fixture
def no_integration(monkeypatch):
    def refuse(self, *args, **kwargs):
        raise AssertionError("integrated although the output was refused")

    monkeypatch.setattr(simulation.Simulation, "chunks", refuse)


def _one_error_line(res, *words):
    assert res.exit_code == 2
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("deathsphere: error: "), res.stderr
    for w in words:
        assert w in lines[0]


def test_unknown_extension(run, no_integration, tmp_path):
    res = run(*ARGS, "--output", str(tmp_path / "x.xyz"))
    _one_error_line(res, ".png, .svg, .pdf, .html, .gif, .mp4, .csv, .json or .ndjson", "x.xyz")
    assert not (tmp_path / "x.xyz").exists()


@pytest.mark.parametrize("name", ["x.gif", "x.mp4", "x.png"])
def test_missing_plot_extra(run, no_integration, tmp_path, monkeypatch, name):
    monkeypatch.setitem(sys.modules, "matplotlib", None)          # "import matplotlib" now fails
    res = run(*ARGS, "--output", str(tmp_path / name))
    _one_error_line(res, "pip install 'deathsphere[plot]'")


def test_mp4_without_an_encoder(run, no_integration, tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    monkeypatch.setattr(viewer, "has_ffmpeg", lambda: False)
    res = run(*ARGS, "--output", str(tmp_path / "x.mp4"))
    _one_error_line(res, "ffmpeg")


def test_html_needs_no_extra(run, tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    out = tmp_path / "Orbit.HTML"
    res = run(*ARGS, "--output", str(out))
    assert res.exit_code == 0 and out.read_bytes().startswith(b"<!DOCTYPE html>")
