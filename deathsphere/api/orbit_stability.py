"""Orbits' exact stability beside the paper's results: ``stability``."""

from __future__ import annotations

from deathsphere.api.arguments import CHUNK, INF, A, G, R
from deathsphere.api.orbits import orbit, orbit_input
from deathsphere.api.streams import Chunks
from deathsphere.table import Table


def _report(table: Table) -> Table:
    from deathsphere.results.stability_report import stability_report

    return stability_report(table)


def stability(theta=None, alpha=None, *, body: str = "wheel", side: str = "inside", a=A, r=R, k=None, g=G, mu=INF,
              omega3=None, omega=None, speed=None, diameter=None, com_speed=None, surface="sphere", height=None,
              wall_angle=None, wall_height=None, profile=None, turn_radius=None) -> Table:
    """Orbits' exact stability beside the paper's results: ``deathsphere stability``.

    The exact verdict, growth rate and nutation frequencies (the equations of
    motion linearised about the orbit) are beyond the paper
    (docs/stability.md); then, for a wheel, the paper's results as printed
    and as corrected: the equator, eqs. (133)-(138); small wheels, eqs.
    (202)-(207); near the poles, eq. (208).  The orbits are those of
    :func:`deathsphere.orbit` with the same arguments (McDonald 1993 eqs.
    (29)-(36), (55)-(59)): they broadcast, and a wheel given ``speed`` (the
    contact's), ``com_speed`` (the centre's) or ``omega`` has one orbit per
    tilt that gives it.

    Parameters
    ----------
    theta, alpha, body, side, a, r, k, g, mu, omega3, omega, speed, com_speed, diameter
        As for :func:`deathsphere.orbit`.
    surface, height, wall_angle, wall_height, profile, turn_radius
        The arena and the lane, as for :func:`deathsphere.orbit`
        (docs/surfaces.md).  The paper's results are the globe's: off it
        each orbit has its exact rows only, and their note says so.

    Returns
    -------
    Table
        The rows of ``deathsphere stability --format csv``, orbit after orbit
        (``input_row`` and ``branch`` say which): the exact rows (``source``
        exact: the orbit's status, growth rate, frequencies, verdict) and,
        for a wheel whose orbit exists with contact, each paper result
        (``source``, ``equation``, ``quantity``, ``paper``, ``corrected``,
        ``exact``, ``deviation``, ``applies``, ``validity``, ``note``).

    Raises
    ------
    ParameterError
        As for :func:`deathsphere.orbit`.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.stability(90, 45)
    >>> row = [r for r in t if r["quantity"] == "verdict" and r["source"] == "exact"][0]
    >>> row["exact"]
    'stable'
    >>> t = deathsphere.stability(90, [45, 80])
    >>> [r["exact"] for r in t if r["quantity"] == "verdict" and r["source"] == "exact"]
    ['stable', 'unstable']
    """
    orbits = orbit(theta, alpha, body=body, side=side, a=a, r=r, k=k, g=g, mu=mu, omega3=omega3, omega=omega,
                   speed=speed, com_speed=com_speed, diameter=diameter, stability=True, surface=surface,
                   height=height, wall_angle=wall_angle, wall_height=wall_height, profile=profile,
                   turn_radius=turn_radius)
    return _report(Table(orbits.columns))


def stability_input(source, *, chunk_size: int = CHUNK, **options) -> Chunks:
    """The stability report of every request in a CSV file: ``deathsphere
    stability --input FILE``.  The file and ``options`` are those of
    :func:`deathsphere.orbit_input` (an option given applies to every row);
    each chunk of orbits gives its report rows, orbit after orbit."""
    chunks = orbit_input(source, chunk_size=chunk_size, stability=True, **options)
    return Chunks((n, _report(table)) for n, table in _counted(chunks))


def _counted(chunks: Chunks):
    """``(requests, table)`` per chunk of a :class:`Chunks`, from its count."""
    before = 0
    for table in chunks:
        yield chunks.done - before, table
        before = chunks.done
