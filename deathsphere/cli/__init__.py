"""The ``deathsphere`` command line (click): see :mod:`deathsphere.cli.base`."""

from deathsphere.cli import docs, orbit, paper, region, simulate, stability, vertical  # noqa: F401  (register the commands)
from deathsphere.cli.base import cli, main

__all__ = ["cli", "main"]
