"""What every process of the suite does before it collects a test.

Bytecode is cached.  Each worker of a parallel run imports the suite's
test modules (pytest rewrites their asserts) and the package's modules (the
doctest collection imports every one); with no cached bytecode
(PYTHONDONTWRITEBYTECODE set) each worker parses, rewrites and compiles all
of them again, about 5 s of CPU a worker on every run.  The caches go to
``__pycache__`` (ignored by git), as in any run without that variable;
the command-line processes the tests start read them.

Collection of the package's docstring examples (``--doctest-modules``).
Collecting a module's doctests imports it.  The modules below hold the
two-wheeler's symbolic derivation: importing them imports sympy (about 2 s
per worker, paid by every worker of a parallel run before its first test),
and they have no docstring example to run.  The tests that re-derive the
shipped code (tests/physics/test_two_wheeler.py) import them, so their
import is still checked; a module here that gains an example is collected
again.
"""

import sys
from pathlib import Path

sys.dont_write_bytecode = False

SYMBOLIC = {Path(__file__).parent / "deathsphere" / name for name in (
    "codegen.py", "physics/two_wheeler/derivation.py")}


def pytest_ignore_collect(collection_path, config):
    if collection_path in SYMBOLIC:
        return ">>>" not in collection_path.read_text(encoding="utf-8") or None
    return None
