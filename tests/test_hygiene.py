"""The test suite's own hygiene: no stand-in modules for real dependencies,
no clock in a unit test (timings live in benchmarks/), property tests
drawn the same way on every run."""

import ast
import pathlib

from hypothesis import settings

TESTS = pathlib.Path(__file__).parent


def _sources():
    return [(path, path.read_text(encoding="utf-8")) for path in TESTS.rglob("*.py")]


def test_hypothesis_is_derandomized():
    assert settings.default.derandomize


def test_no_test_puts_a_stand_in_module_into_sys_modules():
    """A monkeypatched sys.modules entry may only be None (which makes the
    real import fail, to test the missing-extra message), never a fake."""
    for path, text in _sources():
        for node in ast.walk(ast.parse(text)):
            if (isinstance(node, ast.Call) and getattr(node.func, "attr", "") == "setitem"
                    and node.args and "sys.modules" in ast.unparse(node.args[0])):
                assert isinstance(node.args[2], ast.Constant) and node.args[2].value is None, \
                    f"{path.name}:{node.lineno} puts a stand-in module into sys.modules"


def test_no_unit_test_asserts_on_the_clock():
    """Timings are measured in benchmarks/, not asserted in tests: a shared,
    noisy machine makes such an assertion flaky."""
    for path, text in _sources():
        if path.name == "test_hygiene.py":
            continue
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.Assert):
                source = ast.unparse(node.test)
                assert "perf_counter" not in source and "time.time" not in source and "monotonic" not in source, \
                    f"{path.name}:{node.lineno} asserts on the clock"
