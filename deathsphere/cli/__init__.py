"""The ``deathsphere`` command line (click): see :mod:`deathsphere.cli.base`."""

from deathsphere.cli import (  # noqa: F401  (register the commands)
    docs,
    map_limits,
    orbit,
    paper,
    ride,
    show,
    simulate,
    stability,
    vertical,
)
from deathsphere.cli.base import cli, main

__all__ = ["cli", "main"]
