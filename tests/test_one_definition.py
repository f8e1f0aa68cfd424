"""A public function or class is defined in one module of the package, so
that a fix made to it is made everywhere.  The physics' per-body modules
are the exception by design: each body's ``omega_squared`` or
``contact_force`` is that body's own equation of the paper."""

import ast
from collections import defaultdict
from pathlib import Path

from source_trees import tree

PACKAGE = Path(__file__).resolve().parents[1] / "deathsphere"
#: Where one name is one equation per body.
PER_BODY = PACKAGE / "physics"


def definitions(root: Path) -> dict[str, list[str]]:
    """Public module-level function and class names -> the modules defining them."""
    found = defaultdict(list)
    for path in sorted(root.rglob("*.py")):
        for node in tree(path).body:
            if isinstance(node, (ast.FunctionDef, ast.ClassDef)) and not node.name.startswith("_"):
                found[node.name].append(str(path.relative_to(root.parent)))
    return found


#: Names a crew or a caller reads that must name one thing in the whole
#: package, the physics included (a shared name read two ways is a wrong table).
ONE_THING = ("feasible", "verdict", "simulate", "benchmark_bicycle")


def test_the_names_read_two_ways_once_name_one_thing():
    found = definitions(PACKAGE)
    assert {name: found[name] for name in ONE_THING if len(found.get(name, [])) > 1} == {}


def test_each_public_name_is_defined_once_outside_the_per_body_physics():
    twice = {name: where for name, where in definitions(PACKAGE).items()
             if len([w for w in where if not (PACKAGE.parent / w).is_relative_to(PER_BODY)]) > 1}
    assert not twice, twice


def test_the_check_sees_a_name_defined_twice(tmp_path):
    package = tmp_path / "pkg"
    package.mkdir()
    for name in ("one.py", "two.py"):
        (package / name).write_text("def ordered_map():\n    pass\n\n\ndef _private():\n    pass\n")
    assert definitions(package) == {"ordered_map": ["pkg/one.py", "pkg/two.py"]}
