"""The ``deathsphere`` command line (click): see :mod:`deathsphere.cli.base`."""

from deathsphere.cli import orbit, paper, region, simulate, vertical  # noqa: F401,E402  (register the commands)
from deathsphere.cli.base import cli, main

__all__ = ["cli", "main"]
