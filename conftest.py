"""Collection of the package's docstring examples (``--doctest-modules``).

Collecting a module's doctests imports it.  The modules below hold the
two-wheeler's symbolic derivation: importing them imports sympy (about 2 s
per worker, paid by every worker of a parallel run before its first test),
and they have no docstring example to run.  The tests that re-derive the
shipped code (tests/physics/test_two_wheeler.py) import them, so their
import is still checked; a module here that gains an example is collected
again.
"""

from pathlib import Path

SYMBOLIC = {Path(__file__).parent / "deathsphere" / name for name in (
    "codegen.py", "physics/two_wheeler/derivation.py")}


def pytest_ignore_collect(collection_path, config):
    if collection_path in SYMBOLIC:
        return ">>>" not in collection_path.read_text(encoding="utf-8") or None
    return None
