"""Read the data a 3-D view page embeds, and load pages in a real browser."""

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


def dump_dom(binary, html_path, budget_ms=3000):
    """The page's DOM after ``budget_ms`` of virtual time in headless mode
    (virtual time: no wall-clock waits, the same on a slow machine)."""
    with tempfile.TemporaryDirectory() as profile:
        res = subprocess.run(
            [binary, "--headless", "--disable-gpu", "--no-sandbox", "--no-first-run",
             f"--user-data-dir={profile}", f"--virtual-time-budget={budget_ms}", "--dump-dom",
             "file://" + os.path.abspath(html_path)],
            capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stderr[-2000:]
    return res.stdout


def body_attributes(dom: str) -> dict:
    m = re.search(r"<body([^>]*)>", dom)
    assert m, dom[:500]
    return dict(re.findall(r'data-([a-z]+)="([^"]*)"', m.group(1)))


#: (browser, window width) -> the strip of the window the page does not get [px], once measured.
_STRIPS = {}


def page_layout(binary, html_path, width, height, fragment="", budget_ms=3000):
    """The page's own record of where its parts are (``data-layout``: boxes
    [left, top, width, height] in CSS pixels) in a viewport of width x
    height, and its <body> attributes.  Headless Chromium's window size
    includes a strip the page does not get: measured once and added (once
    per browser and width in a test session; a page that gets another
    height is measured again)."""
    target = "file://" + os.path.abspath(html_path) + (f"#{fragment}" if fragment else "")

    def measure(h):
        with tempfile.TemporaryDirectory() as profile:
            res = subprocess.run(
                [binary, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 f"--user-data-dir={profile}", f"--window-size={width},{h}", f"--virtual-time-budget={budget_ms}",
                 "--dump-dom", target],
                capture_output=True, text=True, timeout=120)
        assert res.returncode == 0, res.stderr[-2000:]
        attrs = body_attributes(res.stdout)
        return json.loads(attrs["layout"].replace("&quot;", '"')), attrs, res.stdout

    strip = _STRIPS.get((binary, width), 0)
    layout, attrs, dom = measure(height + strip)
    missing = height - layout["window"][1]
    if missing:
        strip += missing
        layout, attrs, dom = measure(height + strip)
    _STRIPS[(binary, width)] = strip
    return layout, attrs, dom


def readout(track: dict, key: str) -> str:
    """A panel readout's values (base64) in a page's track."""
    return next(r for r in track["panel"] if r["key"] == key)["values"]


def point_set(track: dict, key: str) -> str:
    """A point set's coordinates (base64, frame-major) in a page's track."""
    return track["points"][key]["xyz"]
