import pytest
from view_page import browser_binary


@pytest.fixture(scope="module")
def browser():
    """The headless browser the 3-D view is checked in (the project's CI
    installs Debian's chromium; elsewhere the check says what it needs)."""
    binary = browser_binary()
    if binary is None:
        pytest.skip("no chromium/chrome binary on PATH: the real-browser check of the 3-D viewer needs one")
    return binary
