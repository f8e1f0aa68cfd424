"""Locate the paper's LaTeX source (shared/ sits beside the project)."""

from pathlib import Path

import pytest

PAPER = Path(__file__).resolve().parents[3] / "shared" / "paper" / "sphere-of-death.tex"


@pytest.fixture(scope="session")
def paper_tex() -> str:
    assert PAPER.exists(), f"the paper's source is expected at {PAPER} (shared/ beside the project)"
    return PAPER.read_text()
