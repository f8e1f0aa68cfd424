"""One orbit's exact stability beside the paper's: ``stability``."""

from __future__ import annotations

from deathsphere.api.arguments import INF, A, G, R, checked_scalar, checked_setup
from deathsphere.table import Table


def stability(theta, alpha, *, a=A, r=R, k=None, g=G, mu=INF, side: str = "inside") -> Table:
    """One wheel orbit's exact stability beside the paper's results: ``deathsphere stability``.

    The exact verdict, growth rate and nutation frequencies (the equations of
    motion linearised about the orbit) are beyond the paper
    (docs/stability.md); then the paper's results as printed and as
    corrected: the equator, eqs. (133)-(138); small wheels, eqs.
    (202)-(207); near the poles, eq. (208).

    Parameters
    ----------
    theta : float
        Polar angle of the orbit [deg], 0..180.
    alpha : float
        Tilt of the wheel [deg], any angle.
    a, r, k, g, mu, side : as for :func:`orbit` (one value each).

    Returns
    -------
    Table
        The rows of ``deathsphere stability --format csv``: ``source``,
        ``equation``, ``quantity``, ``paper``, ``corrected``, ``exact``,
        ``deviation``, ``note``, ...

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.stability(90, 45)
    >>> row = [r for r in t if r["quantity"] == "verdict" and r["source"] == "exact"][0]
    >>> row["exact"]
    'stable'
    """
    from deathsphere.results.stability_report import stability_report

    setup = checked_setup("wheel", side, a, r, k, g, mu)
    return stability_report(setup, checked_scalar("theta", theta), checked_scalar("alpha", alpha))
