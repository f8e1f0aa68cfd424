"""What every matplotlib figure of deathsphere shares: the optional
dependency and the output formats.

matplotlib is optional (``pip install 'deathsphere[plot]'``) and imported
only when a figure is made; without it :func:`import_matplotlib` raises
:class:`PlotExtraMissing`, an ImportError naming the extra.
"""

from __future__ import annotations

import importlib
from pathlib import Path

EXTRA_HINT = "pip install 'deathsphere[plot]'"
FORMATS = ("png", "svg", "pdf")


class PlotExtraMissing(ImportError):
    """matplotlib is not installed: the ``plot`` extra is needed."""


def import_matplotlib():
    """Import matplotlib (Agg backend unless one is chosen) or raise
    :class:`PlotExtraMissing` with the install hint."""
    try:
        mpl = importlib.import_module("matplotlib")
    except ImportError as exc:
        raise PlotExtraMissing(
            f"plotting needs matplotlib, which is not installed; install the extra: {EXTRA_HINT}"
        ) from exc
    return mpl


def figure_format(output) -> str:
    """The format named by the suffix of ``output`` (one of FORMATS), or
    ValueError."""
    suffix = Path(output).suffix.lower().lstrip(".")
    if suffix not in FORMATS:
        raise ValueError(f"output must end in .png, .svg or .pdf, got {str(output)!r}")
    return suffix


def save_figure(fig, output, fmt: str, dpi: int) -> None:
    """Save ``fig`` to ``output`` whole or not at all (a failed or
    interrupted save leaves no file under that name:
    :mod:`deathsphere.writers.atomic`)."""
    from deathsphere.writers.atomic import atomic_path

    with atomic_path(output) as temp:
        fig.savefig(temp, format=fmt, dpi=dpi)
