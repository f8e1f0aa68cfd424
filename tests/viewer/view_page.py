"""Read the data a 3-D view page embeds, and load pages in a real browser
(the session's shared one, ``devtools_pipe.Chromium``, or a process of
their own)."""

import json
import os
import re
import shutil
import subprocess
import tempfile

BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable", "chrome")


def page_data(page: str) -> dict:
    """The JSON the page's script reads (``var DATA = {...};``)."""
    m = re.search(r"var DATA = (\{.*?\});\n", page, flags=re.S)
    assert m, "no embedded data in the page"
    return json.loads(m.group(1))


def browser_binary():
    for name in BROWSERS:
        path = shutil.which(name)
        if path:
            return path
    return None


#: The viewport a page read whole gets [CSS px]: the one a separate
#: ``chromium --headless --dump-dom`` process gives it (its 800 x 600
#: window less the window's own strip), so that the shared browser's pages
#: are drawn as they were in a process of their own.
DOM_VIEWPORT = (780, 437)


def page_url(html_path, fragment="") -> str:
    return "file://" + os.path.abspath(html_path) + (f"#{fragment}" if fragment else "")


def dump_dom(browser, html_path, budget_ms=3000):
    """The page's DOM after ``budget_ms`` of virtual time in the session's
    headless browser (virtual time: no wall-clock waits, the same on a slow
    machine)."""
    return browser.dom(page_url(html_path), budget_ms, DOM_VIEWPORT)


def body_attributes(dom: str) -> dict:
    m = re.search(r"<body([^>]*)>", dom)
    assert m, dom[:500]
    return dict(re.findall(r'data-([a-z]+)="([^"]*)"', m.group(1)))


def layout_of(dom: str):
    """A DOM's ``data-layout`` (read), its <body> attributes and the DOM."""
    attrs = body_attributes(dom)
    return json.loads(attrs["layout"].replace("&quot;", '"')), attrs, dom


def page_layout(browser, html_path, width, height, fragment="", budget_ms=3000):
    """The page's own record of where its parts are (``data-layout``: boxes
    [left, top, width, height] in CSS pixels) in a viewport of width x
    height, its <body> attributes and its DOM."""
    return layout_of(browser.dom(page_url(html_path, fragment), budget_ms, (width, height)))


# ---------------------------------------------------------------- a browser process per page
# The way pages were loaded before the session shared one browser, kept to
# check the shared browser against.

def dump_dom_by_process(binary, url, budget_ms, window=None):
    """The DOM ``chromium --headless --dump-dom`` prints for ``url`` after
    ``budget_ms`` of virtual time, in a process of its own (``window``:
    its ``--window-size``)."""
    size = [f"--window-size={window[0]},{window[1]}"] if window else []
    with tempfile.TemporaryDirectory() as profile:
        res = subprocess.run(
            [binary, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             f"--user-data-dir={profile}", *size, f"--virtual-time-budget={budget_ms}",
             "--dump-dom", url],
            capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stderr[-2000:]
    return res.stdout


def readout(track: dict, key: str) -> str:
    """A panel readout's values (base64) in a page's track."""
    return next(r for r in track["panel"] if r["key"] == key)["values"]


def point_set(track: dict, key: str) -> str:
    """A point set's coordinates (base64, frame-major) in a page's track."""
    return track["points"][key]["xyz"]
