"""Every word of the 3-D view is readable in a small window: no text is
drawn smaller than 12 CSS px at 800x600 (a laptop's browser beside a
terminal, a projector's smallest mode), in the normal and projector modes."""

import pytest
from view_page import page_layout
from viewer_cases import run_case

from deathsphere.simulation.frames import body_frames
from deathsphere.viewer import write_view

#: The least font size a reader is asked to read [CSS px].
SMALLEST_READABLE_PX = 12


@pytest.mark.parametrize("size, fragment", [((800, 600), ""), ((800, 600), "p")])
def test_no_text_below_12_px(tmp_path, browser, size, fragment):
    series, summary, states, _ = run_case("wheel_kicked", periods=1)
    out = tmp_path / "orbit.html"
    write_view(out, series, summary, body_frames(summary, states))
    layout, attrs, dom = page_layout(browser, out, *size, fragment=fragment, budget_ms=500)
    assert attrs["errors"] == "0", dom[-3000:]
    px, where = layout["smallest_text"]
    assert px >= SMALLEST_READABLE_PX, (size, fragment, px, where)
