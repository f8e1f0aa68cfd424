"""Names a package re-exports from its submodules, imported on first use.

A command's start-up should load only what the command evaluates:
``import deathsphere`` need not import the simulator, and ``orbit`` need not
import the Floquet analysis of vertical orbits.  A package lists where each
public name lives and gets the module-level ``__getattr__`` and ``__dir__``
of PEP 562, so ``from package import name`` and ``package.name`` work as if
the package had imported everything.
"""

from __future__ import annotations

import importlib


def lazy_exports(namespace: dict, homes: dict[str, str], modules: tuple[str, ...] = ()):
    """``(__getattr__, __dir__)`` for the package whose globals are ``namespace``.

    ``homes`` maps each public name to the submodule (relative name) that
    defines it; ``modules`` are submodules reachable as attributes.  A name
    is looked up once: its value is then stored in the package's globals.
    """
    package = namespace["__name__"]

    def __getattr__(name):
        if name in modules:
            return importlib.import_module(f"{package}.{name}")
        try:
            home = homes[name]
        except KeyError:
            raise AttributeError(f"module {package!r} has no attribute {name!r}") from None
        value = getattr(importlib.import_module(f"{package}.{home}"), name)
        namespace[name] = value
        return value

    def __dir__():
        return sorted(set(namespace) | set(homes) | set(modules))

    return __getattr__, __dir__
