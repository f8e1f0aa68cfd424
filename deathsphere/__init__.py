"""deathsphere: orbits of bodies rolling without slipping on a fixed sphere.

Implements and checks K. T. McDonald, *Circular Orbits Inside the Sphere of
Death* (1993).  The pure-numpy physics lives in :mod:`deathsphere.physics`;
:mod:`deathsphere.model` wraps it in a validated :class:`Setup` and named
result columns; :mod:`deathsphere.cli` is the command line.
"""

#: The one place the version is written (pyproject.toml reads it from here):
#: a static string, because asking the installed metadata costs ~50 ms at
#: every start of the command.
__version__ = "0.1.0"

from deathsphere.model import Setup, Table, horizontal_orbit  # noqa: E402

__all__ = ["Setup", "Table", "horizontal_orbit", "__version__"]
