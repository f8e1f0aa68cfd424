"""deathsphere: orbits of bodies rolling without slipping on a fixed sphere.

Implements and checks K. T. McDonald, *Circular Orbits Inside the Sphere of
Death* (1993).  The pure-numpy physics lives in :mod:`deathsphere.physics`;
:mod:`deathsphere.model` wraps it in a validated :class:`Setup` and named
result columns; :mod:`deathsphere.cli` is the command line.
"""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("deathsphere")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0.0.0+unknown"

from deathsphere.model import Setup, Table, horizontal_orbit  # noqa: E402

__all__ = ["Setup", "Table", "horizontal_orbit", "__version__"]
