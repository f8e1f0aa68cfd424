"""The HTML 3-D view in a real headless browser (Chromium or Chrome): it
loads without script errors and its animation advances.

The page records script errors (window "error" events) and the current
frame index as attributes of <body>; the browser runs with a virtual time
budget and dumps the DOM.  Skipped only where no browser binary is on PATH.

The pages are tabs of one browser shared by the test session; two tests
check that browser itself: its read of a page is the one a browser process
of its own (``--dump-dom``) prints, and closed it leaves no process and no
profile behind.
"""

import time
from pathlib import Path

import pytest
from devtools_pipe import Chromium
from view_page import body_attributes, dump_dom, dump_dom_by_process, layout_of, page_url
from viewer_cases import run_case

from deathsphere.simulation.frames import body_frames
from deathsphere.viewer import write_view


@pytest.mark.parametrize("name", ["wheel_kicked", "sphere_inside", "vertical", "unstable"])
def test_page_loads_without_errors_and_animates(tmp_path, browser, name):
    series, summary, states, _ = run_case(name, periods=1)
    out = tmp_path / "orbit.html"
    write_view(out, series, summary, body_frames(summary, states))
    attrs = body_attributes(dump_dom(browser, out))
    assert attrs["errors"] == "0", dump_dom(browser, out)[-3000:]
    assert attrs["ready"] == "1"
    assert int(attrs["frame"]) > 0 and float(attrs["time"]) > 0


def test_a_broken_page_is_caught(tmp_path, browser):
    """The harness itself: a page whose script fails reports it."""
    series, summary, states, _ = run_case("wheel_inside", periods=0.2)
    out = tmp_path / "broken.html"
    write_view(out, series, summary, body_frames(summary, states))
    page = out.read_text(encoding="utf-8")
    out.write_text(page.replace("var DATA = {", "var DATA = {bodies: null, x: {", 1), encoding="utf-8")
    attrs = body_attributes(dump_dom(browser, out, budget_ms=500))
    assert int(attrs["errors"]) >= 1 and attrs["ready"] == "0" and attrs["frame"] == "0"


def test_the_shared_browser_reads_a_page_as_a_process_of_its_own_does(tmp_path, browser):
    """The harness itself: a page paused at its run's end (#end: nothing on
    it moves with the clock) reads the same, byte for byte, in a tab of the
    session's browser given the viewport a separate ``chromium --headless
    --window-size=800,600 --dump-dom`` process gave it, as in that process."""
    series, summary, states, _ = run_case("unstable", periods=1)
    out = tmp_path / "u.html"
    write_view(out, series, summary, body_frames(summary, states), title="contact lost")
    url = page_url(out, "end")
    alone = dump_dom_by_process(browser.binary, url, budget_ms=500, window=(800, 600))
    layout, attrs, _ = layout_of(alone)
    assert attrs["ready"] == "1" and attrs["errors"] == "0" and int(attrs["ink"]) > 500
    shared = browser.dom(url, 500, tuple(layout["window"]))
    assert shared == alone


def _alive_in_group(group: int) -> list[str]:
    """The processes of a process group that are not yet dead (zombies,
    waiting for their new parent to reap them, are): from /proc."""
    alive = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            text = stat.read_text()
        except OSError:
            continue                                   # ended meanwhile
        state, _, pgrp = text.rsplit(")", 1)[1].split()[:3]
        if int(pgrp) == group and state != "Z":
            alive.append(text.split(" ", 2)[1])
    return alive


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads the processes from /proc (Linux)")
def test_a_closed_browser_leaves_no_process_and_no_profile(browser):
    """The harness itself: closing the shared browser ends every process it
    started (its helpers share its process group) and removes its profile."""
    chromium = Chromium(browser.binary)
    group, profile = chromium.process.pid, Path(chromium.profile)
    assert _alive_in_group(group) and profile.is_dir()
    chromium.close()
    # SIGKILL is delivered asynchronously: a helper of the group may take a moment to die
    deadline = time.monotonic() + 5
    while _alive_in_group(group) and time.monotonic() < deadline:
        time.sleep(0.02)
    assert _alive_in_group(group) == [] and not profile.exists()
    assert chromium.process.returncode is not None
