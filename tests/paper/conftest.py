"""The paper's Table 1 as printed, in its LaTeX form (tests/paper/data/,
copied verbatim from the paper's source with its provenance noted there)."""

from pathlib import Path

import pytest

TABLE1_TEX = Path(__file__).resolve().parent / "data" / "table1.tex"


@pytest.fixture(scope="session")
def paper_tex() -> str:
    return TABLE1_TEX.read_text()
