"""The test suite's own hygiene: no stand-in modules for real dependencies,
no clock in a unit test (timings live in benchmarks/), property tests
drawn the same way on every run."""

import ast
import pathlib

from hypothesis import settings
from source_trees import tree

TESTS = pathlib.Path(__file__).parent


def _sources():
    return [(path, tree(path)) for path in TESTS.rglob("*.py")]


def test_hypothesis_is_derandomized():
    assert settings.default.derandomize


def test_no_test_puts_a_stand_in_module_into_sys_modules():
    """A monkeypatched sys.modules entry may only be None (which makes the
    real import fail, to test the missing-extra message), never a fake."""
    for path, module in _sources():
        for node in ast.walk(module):
            if (isinstance(node, ast.Call) and getattr(node.func, "attr", "") == "setitem"
                    and node.args and "sys.modules" in ast.unparse(node.args[0])):
                assert isinstance(node.args[2], ast.Constant) and node.args[2].value is None, \
                    f"{path.name}:{node.lineno} puts a stand-in module into sys.modules"


def test_no_unit_test_asserts_on_the_clock():
    """Timings are measured in benchmarks/, not asserted in tests: a shared,
    noisy machine makes such an assertion flaky."""
    for path, module in _sources():
        if path.name == "test_hygiene.py":
            continue
        for node in ast.walk(module):
            if isinstance(node, ast.Assert):
                source = ast.unparse(node.test)
                assert "perf_counter" not in source and "time.time" not in source and "monotonic" not in source, \
                    f"{path.name}:{node.lineno} asserts on the clock"


# ---------------------------------------------------------------------------
# the package: no body tested by its name outside the decoder

PACKAGE = TESTS.parent / "deathsphere"
#: The words that name the paper's bodies (``--body``, a CSV's ``body`` column).
BODY_WORDS = frozenset({"wheel", "sphere", "particle"})
#: Where a word may be compared with them: the decoder, which turns words
#: into body records, and the terminal views, which label a finished
#: table's rows by the text its ``body`` column prints (output, not input).
MAY_COMPARE_BODY_WORDS = ("requests/decode.py", "requests/arena.py", "render/")
#: Where the same words name something else, by the name of the value
#: compared: the 3-D scene's data format (a ground's or a drawing item's
#: ``kind``: "sphere" the globe, "wheel" a drawn disc) and the two-wheeler's
#: symbolic ``surface`` (the globe again).
OTHER_MEANINGS = {"viewer/": ("kind",), "physics/two_wheeler/": ("surface",)}


def _name_of(node) -> str | None:
    """What a compared value is called: a variable, an attribute or a
    constant key (``x``, ``item.kind``, ``ground["kind"]``)."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return node.attr
    if isinstance(node, ast.Subscript) and isinstance(node.slice, ast.Constant):
        return str(node.slice.value)
    return None


def _body_word_comparisons(module: str | ast.Module, other_meanings=()) -> list[int]:
    """The lines of ``module`` (source text or its parsed tree) that compare a value with a body's word
    (``==``, ``!=``, ``in``, ``not in``, a ``case``; the word alone or in a
    literal tuple, list or set), but for values called one of
    ``other_meanings``."""
    def names_a_body(node) -> bool:
        if isinstance(node, ast.Constant):
            return node.value in BODY_WORDS
        if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
            return any(names_a_body(e) for e in node.elts)
        return False

    lines = []
    for node in ast.walk(ast.parse(module) if isinstance(module, str) else module):
        if isinstance(node, ast.Compare):
            sides = (node.left, *node.comparators)
            if (any(names_a_body(side) for side in sides)
                    and not any(_name_of(side) in other_meanings for side in sides)):
                lines.append(node.lineno)
        elif isinstance(node, ast.MatchValue) and names_a_body(node.value):
            lines.append(node.lineno)
        elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "index"
              and any(names_a_body(arg) for arg in node.args)):
            lines.append(node.lineno)         # a body's code looked up by its word: BODIES.index("wheel")
        elif isinstance(node, ast.For) and isinstance(node.iter, (ast.Tuple, ast.List)) and names_a_body(node.iter):
            lines.append(node.lineno)         # for name in ("wheel", "sphere"): ... then tested by name
    return sorted(set(lines))


def test_the_scan_finds_a_body_tested_by_its_name():
    """The detector itself: each way of testing a body by its word is found,
    and dispatch on a record, or a word written as a column's value, is not."""
    tested = ('if body == "wheel": pass\nif "sphere" != b: pass\nif b in ("wheel", "sphere"): pass\n'
              'match b:\n    case "particle": pass\ncode == BODIES.index("sphere")\nfor name in ("wheel", "sphere"): pass\n')
    assert _body_word_comparisons(tested) == [1, 2, 3, 5, 6, 7]
    assert _body_word_comparisons('isinstance(body, Wheel)\ncolumns = {"body": "wheel"}\n') == []
    # a scene's drawing kind is its data format where that is the meaning, a body's name elsewhere
    assert _body_word_comparisons('item["kind"] == "wheel"\n', ("kind",)) == []
    assert _body_word_comparisons('body.kind == "wheel"\n') == [1]


def test_no_body_is_tested_by_its_name_outside_the_decoder():
    """A body's behaviour is its record's (deathsphere.records.paper_bodies);
    a word becomes a record in one place, deathsphere/requests/decode.py."""
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE).as_posix()
        if rel.startswith(MAY_COMPARE_BODY_WORDS):
            continue
        meanings = next((names for where, names in OTHER_MEANINGS.items() if rel.startswith(where)), ())
        found += [f"{rel}:{line}" for line in _body_word_comparisons(tree(path), meanings)]
    assert found == []


# ---------------------------------------------------------------------------
# the package: long keyword lists only at the edges

#: Parameters a function may take (self, *args and **kwargs aside) unless it
#: is an adapter: a command's click callback (one parameter per option) or
#: one of the API's public keyword functions, which pack what a notebook
#: types into requests and records for what lies beneath them.
MOST_PARAMETERS = 12
KEYWORD_ADAPTERS = {
    "api/orbits.py": {"orbit", "sweep", "orbit_input"},
    "api/vertical_orbits.py": {"vertical", "vertical_sweep", "vertical_input"},
    "api/region_limits.py": {"region", "limits", "limits_input"},
    "api/orbit_stability.py": {"stability"},
    "api/rides.py": {"ride"},
    "api/ride_streams.py": {"ride_sweep"},
    "api/simulation.py": {"simulate"},
    "api/two_wheelers.py": {"simulate_two_wheeler"},
    "api/two_wheeler_streams.py": {"two_wheeler_ride_sweep"},
}


def _parameter_count(function: ast.FunctionDef | ast.AsyncFunctionDef) -> int:
    args = function.args
    names = [a.arg for a in args.posonlyargs + args.args + args.kwonlyargs]
    return len(names) - (1 if names and names[0] in ("self", "cls") else 0)


def test_only_the_adapters_take_more_than_twelve_parameters():
    long_lists = []
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE).as_posix()
        for node in ast.walk(tree(path)):
            if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                continue
            if _parameter_count(node) <= MOST_PARAMETERS or node.name in KEYWORD_ADAPTERS.get(rel, ()):
                continue
            if rel.startswith("cli/") and node.name.endswith("_command"):
                continue
            long_lists.append(f"{rel}:{node.lineno} {node.name} ({_parameter_count(node)})")
    assert long_lists == []


def test_the_parameter_count_leaves_out_self_and_the_starred():
    tree = ast.parse("class C:\n    def m(self, a, /, b, *args, c, **kw): pass\ndef f(a, b=1, *, c): pass\n")
    counts = {n.name: _parameter_count(n) for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)}
    assert counts == {"m": 3, "f": 3}
