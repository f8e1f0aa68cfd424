"""The source files the suite's code scans, parsed once per process: the
hygiene, layer and one-definition checks each walk every module of the
package (and the hygiene checks every test module), and parsing them all
takes about a second each time."""

import ast
import functools
from pathlib import Path


@functools.cache
def _tree(path: Path) -> ast.Module:
    return ast.parse(path.read_text(encoding="utf-8"))


def tree(path) -> ast.Module:
    """The parsed module at ``path`` (shared: walk it, do not change it)."""
    return _tree(Path(path).resolve())
