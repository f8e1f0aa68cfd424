"""deathsphere: orbits of bodies rolling without slipping on a fixed sphere.

Implements and checks K. T. McDonald, *Circular Orbits Inside the Sphere of
Death* (1993).  The Python API mirrors the command line, one function per
command with the same parameters (:mod:`deathsphere.api`, docs/api.md)::

    >>> import deathsphere
    >>> t = deathsphere.orbit(60, 10)
    >>> round(float(t["v_cm_m_s"]), 2)
    7.88

The pure-numpy physics lives in :mod:`deathsphere.physics`;
:mod:`deathsphere.model` wraps it in a validated :class:`Setup` and the
result :class:`Table`; :mod:`deathsphere.cli` is the command line.
"""

#: The one place the version is written (pyproject.toml reads it from here):
#: a static string, because asking the installed metadata costs ~50 ms at
#: every start of the command.
__version__ = "0.1.0"

from deathsphere.physics.lazy import lazy_exports  # noqa: E402

#: Where each public name lives; imported on first use, so that a command's
#: start-up loads only what it evaluates.
_HOME = {
    "Chunks": "api",
    "limits": "api",
    "orbit": "api",
    "orbit_input": "api",
    "prepare_simulation": "api",
    "region": "api",
    "region_cells": "api",
    "region_curves": "api",
    "simulate": "api",
    "animation_options": "api",
    "stability": "api",
    "sweep": "api",
    "table1": "api",
    "verify": "api",
    "vertical": "api",
    "vertical_input": "api",
    "vertical_sweep": "api",
    "ride": "api",
    "show": "api",
    "ride_summary": "api",
    "ride_sweep": "api",
    "Machine": "api",
    "TwoWheeler": "api",
    "machines_table": "api",
    "machine_file": "api",
    "two_wheeler_file": "api",
    "two_wheeler_text": "api",
    "limits_input": "api",
    "stability_input": "api",
    "Setup": "model",
    "Table": "model",
    "ParameterError": "params",
    "docs_topics": "topics",
    "doc_text": "topics",
}

#: Submodules reachable as attributes, as when this package imported them.
_MODULES = ("api", "model", "params", "constants", "physics")

__all__ = [*_HOME, "__version__"]
__getattr__, __dir__ = lazy_exports(globals(), _HOME, _MODULES)
