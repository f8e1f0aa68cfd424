"""The house's layers, read from the source (imports inside functions
count): physics <- model <- results, simulation <- api <- cli, with the
result table and the writers beside them and the views consuming tables.
No module imports one above it, and no import circle exists."""

import ast
import functools
import pathlib

from source_trees import tree

import deathsphere

ROOT = pathlib.Path(deathsphere.__file__).parent


@functools.cache
def _modules() -> dict[str, set[str]]:
    """module -> the deathsphere modules it imports (anywhere in its body);
    read once, when a test first asks (not at collection, on every worker)."""
    names = {}
    for path in ROOT.rglob("*.py"):
        rel = path.relative_to(ROOT.parent).with_suffix("")
        name = ".".join(rel.parts).removesuffix(".__init__")
        names[name] = path
    graph = {}
    for name, path in names.items():
        package = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
        targets = set()
        for node in ast.walk(tree(path)):
            if isinstance(node, ast.Import):
                targets |= {a.name for a in node.names}
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    parts = package.split(".")[: len(package.split(".")) - node.level + 1]
                    base = ".".join(parts + ([base] if base else []))
                found = {f"{base}.{a.name}" for a in node.names} & set(names)
                targets |= found or {base}
        graph[name] = {t for t in targets if t in names and t != name}
    return graph


class _Graph:
    """The import graph, read when first used."""

    def __getitem__(self, module):
        return _modules()[module]

    def __contains__(self, module):
        return module in _modules()

    def __iter__(self):
        return iter(_modules())

    def items(self):
        return _modules().items()


GRAPH = _Graph()


def _layer(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "deathsphere"


#: What each layer may import (besides itself).  The bottom: errors,
#: constants and the lazy loader, which import nothing of the package.
BOTTOM = {"errors", "constants", "exitcodes"}
ALLOWED = {
    "physics": {"constants"},       # standard gravity and the paper's setup are physical constants
    "table": set(),
    "errors": set(),
    "constants": set(),
    "exitcodes": set(),
    "units": {"errors"},
    "params": {"units", "errors", "constants"},
    "grid": set(),
    # the one chunker of a grid of requests: an outer product of the grid's axes
    "chunker": {"grid"},
    # the two-wheeler's derivation written out as the numpy code the physics core ships
    "codegen": {"physics"},
    # a dask cluster is the other place parallel work can run (the distributed extra)
    "parallel": {"cluster"},
    "cluster": {"errors", "memory"},
    "memory": set(),
    "threads": set(),
    "topics": set(),
    # a body's record is validated with the registry; its parameter files are text read once
    "records": {"physics", "params", "units", "errors", "constants", "table"},
    # the paper's bodies are records, named by a word in one place: the requests' decoder
    "model": {"physics", "table", "params", "constants", "errors", "records", "requests"},
    # a request (a rider and its run) is decoded once, from keys as typed, into records of bodies and grounds
    "requests": {"physics", "records", "params", "units", "errors", "constants"},
    "inputs": {"model", "params", "errors", "units", "table"},
    # verify checks claims about motion with the simulator
    "results": {"physics", "model", "table", "params", "constants", "parallel", "simulation", "records", "requests"},
    "simulation": {"physics", "model", "table", "params", "constants", "records", "requests"},
    "writers": {"table", "model"},
    "render": {"table", "model", "constants", "params"},
    "viewer": {"table", "render"},
    "api": {"physics", "model", "table", "params", "constants", "grid", "chunker", "inputs", "results", "simulation",
            "parallel", "cluster", "units", "errors", "act", "records", "requests"},
    # the show's parts (an act of several riders) compute on the machine's physics and records
    "act": {"physics", "records", "requests", "table", "params", "units", "errors", "constants", "parallel",
            "cluster"},
    "__main__": {"cli"},
    # the option parser reads the unit a value was typed in, to show it back beside SI (docs/units.md)
    "cli": {"api", "render", "viewer", "writers", "table", "params", "constants", "exitcodes", "errors", "topics",
            "memory", "threads", "units"},
}


#: Modules that import nothing of the package, usable from any layer: the
#: lazy loader, and the one way a file is written (whole or not at all).
ANYWHERE = {"deathsphere.physics.lazy", "deathsphere.writers.atomic"}


def test_anywhere_modules_import_nothing_of_the_package():
    assert {m: GRAPH[m] for m in ANYWHERE if GRAPH[m]} == {}


def test_no_module_imports_a_layer_above_it():
    wrong = []
    for module, targets in GRAPH.items():
        layer = _layer(module)
        if layer == "deathsphere":
            continue
        for target in targets:
            other = _layer(target)
            if other in (layer, "deathsphere") or target in ANYWHERE:
                continue
            if other not in ALLOWED.get(layer, set()):
                wrong.append(f"{module} -> {target}")
    assert wrong == []


def test_no_import_circle():
    index, low, stack, on, cycles = {}, {}, [], set(), []

    def visit(v, counter=[0]):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in GRAPH[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            part = []
            while True:
                w = stack.pop()
                on.discard(w)
                part.append(w)
                if w == v:
                    break
            if len(part) > 1:
                cycles.append(sorted(part))

    for v in GRAPH:
        if v not in index:
            visit(v)
    assert cycles == []


def test_the_probe_sees_imports_inside_functions():
    """The graph counts function-level imports (the circle this guards
    against ran through them)."""
    assert "deathsphere.results.stability_report" in GRAPH["deathsphere.api.orbit_stability"]
