"""The documentation site (mkdocs.yml) builds from the shipped docs and the
docstrings with no warning at all (``strict: true``): a broken link between
docs, a figure not shipped, a docstring mkdocstrings cannot parse all fail
here.  The build takes about 1.5 s."""

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: The docs extra's packages (the test extra includes it).
MISSING = [m for m in ("mkdocs", "material", "mkdocstrings_handlers") if importlib.util.find_spec(m) is None]


@pytest.mark.skipif(bool(MISSING), reason=f"the docs extra is not installed (no {', '.join(MISSING)}): "
                                          "pip install -e '.[docs]'")
def test_the_site_builds_strict(tmp_path):
    env = {**os.environ, "NO_MKDOCS_2_WARNING": "1"}
    proc = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-f", str(ROOT / "mkdocs.yml"),
                           "-d", str(tmp_path / "site")], capture_output=True, text=True, env=env, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert "WARNING" not in proc.stderr, proc.stderr
    reference = (tmp_path / "site" / "reference" / "index.html").read_text(encoding="utf-8")
    assert "deathsphere.api.orbit" in reference and "deathsphere.physics.wheel" in reference


def test_the_nav_lists_every_shipped_doc():
    nav = (ROOT / "mkdocs.yml").read_text(encoding="utf-8").split("\nnav:", 1)[1]
    shipped = {p.name for p in (ROOT / "deathsphere" / "docs").glob("*.md")}
    assert {name for name in shipped if f": {name}" in nav} == shipped
