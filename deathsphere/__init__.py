"""deathsphere: orbits of bodies rolling without slipping on a fixed sphere.

Implements and checks K. T. McDonald, *Circular Orbits Inside the Sphere of
Death* (1993).  The Python API mirrors the command line, one function per
command with the same parameters (:mod:`deathsphere.api`, docs/api.md)::

    >>> import deathsphere
    >>> t = deathsphere.orbit(60, 10)
    >>> round(float(t["v_cm_m_s"][0]), 2)
    7.88

The pure-numpy physics lives in :mod:`deathsphere.physics`;
:mod:`deathsphere.model` wraps it in a validated :class:`Setup` and the
result :class:`Table`; :mod:`deathsphere.cli` is the command line.
"""

import sys
import types
from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("deathsphere")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0.0.0+unknown"

from deathsphere.model import Setup, Table, horizontal_orbit  # noqa: E402
from deathsphere.params import ParameterError  # noqa: E402
from deathsphere import api  # noqa: E402
from deathsphere.api import orbit, region, simulate, stability, sweep  # noqa: E402

#: Commands whose name is also a module of this package (deathsphere.vertical,
#: .limits, .table1, .verify hold the code behind them).  The package
#: attribute can hold only one of the two, and the import system rebinds it
#: to the module whenever the module is first imported, so a plain function
#: binding would vanish (or replace the module that code such as
#: ``from deathsphere import verify`` expects).  Instead the attribute is
#: always the module, made callable: ``deathsphere.vertical(60, 6)`` calls
#: :func:`deathsphere.api.vertical`, and ``deathsphere.verify.CLAIMS`` is
#: still the module's.  The modules are imported on first use, so that
#: ``import deathsphere`` (and every command line start) stays fast.
_COMMAND_MODULES = ("vertical", "limits", "table1", "verify")


class _CommandModule(types.ModuleType):
    """A module that is also the API function of the command of its name."""

    def __call__(self, *args, **kwargs):
        return getattr(api, self.__name__.rpartition(".")[2])(*args, **kwargs)

    @property
    def __signature__(self):  # inspect.signature(deathsphere.vertical) shows the function's
        import inspect

        return inspect.signature(getattr(api, self.__name__.rpartition(".")[2]))


class _Package(types.ModuleType):
    def __setattr__(self, name, value):
        # the import system binds a submodule here when it is first imported
        if name in _COMMAND_MODULES and isinstance(value, types.ModuleType):
            value.__class__ = _CommandModule
        super().__setattr__(name, value)

    def __getattr__(self, name):  # a command module not imported yet
        if name in _COMMAND_MODULES:
            import importlib

            return importlib.import_module(f"{__name__}.{name}")
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


sys.modules[__name__].__class__ = _Package
for _name in _COMMAND_MODULES:  # any imported before this point (e.g. by the model)
    if f"{__name__}.{_name}" in sys.modules:
        setattr(sys.modules[__name__], _name, sys.modules[f"{__name__}.{_name}"])

__all__ = ["orbit", "vertical", "sweep", "region", "limits", "stability", "simulate", "table1", "verify",
           "Table", "ParameterError", "Setup", "horizontal_orbit", "__version__"]
