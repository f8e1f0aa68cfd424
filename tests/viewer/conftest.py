import pytest
from devtools_pipe import Chromium
from view_page import browser_binary


@pytest.fixture(scope="session")
def browser():
    """The headless browser the 3-D view is checked in: one process for the
    test session (per test worker), each page a tab of it, closed with its
    temporary profile at the session's end (the project's CI installs
    Debian's chromium; elsewhere the check says what it needs)."""
    binary = browser_binary()
    if binary is None:
        pytest.skip("no chromium/chrome binary on PATH: the real-browser check of the 3-D viewer needs one")
    chromium = Chromium(binary)
    try:
        yield chromium
    finally:
        chromium.close()
