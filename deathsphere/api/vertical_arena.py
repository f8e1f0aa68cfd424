"""The arena of ``vertical``: a vertical loop runs over the top of its
ground, so it needs a surface that closes over the rider.  The globe does
(McDonald 1993 eqs. 26-28b); so does a profile whose meridian meets the
axis at its lowest and its highest point, the loop then running in a
meridian plane (beyond the paper: docs/surfaces.md, "S9-S12. A vertical
loop inside a closed profile").  A drum, a cone and flat ground do not
close over the rider, and a profile open at the top does not: they are
refused in one line, as is a ground that closes over the top but not below
(a cone leaning in, a dome on a floor) or meets the axis at a corner."""

from __future__ import annotations

import math

from deathsphere.params import ParameterError

def closes_over_top(ground) -> bool:
    """True when the ground's highest lane is on its axis (a finite top
    whose contact has rho = 0): a loop could run over it."""
    top = float(getattr(ground, "highest_lane", math.inf))
    if not math.isfinite(top):
        return False
    import numpy as np

    # how close to the axis, relative to the widest lane scanned (the loop's own tolerance)
    from deathsphere.physics.meridian_loop import AXIS_TOL

    rho_top, _ = ground.contact(np.array([top]))
    rho_all, _ = ground.contact(np.linspace(0.0, top, 33))
    return bool(abs(float(rho_top[0])) <= AXIS_TOL * max(float(np.max(rho_all)), 1.0))


def _named(surface, wall_angle, wall_height, profile) -> str:
    """The keyword a refusal names: ``surface`` if typed, else the shape keyword that named a wall."""
    if surface is not None:
        return "surface"
    return next(name for name, value in (("wall_angle", wall_angle), ("wall_height", wall_height),
                                         ("profile", profile)) if value is not None)


def loop_arena(surface=None, r=None, diameter=None, wall_angle=None, wall_height=None, profile=None):
    """None on the globe; on a profile that closes at both ends its loop
    (:class:`~deathsphere.physics.vertical_orbit_on.Loop`, sampled once);
    elsewhere a ParameterError naming ``surface`` (or the shape keyword
    that names a wall), saying why no vertical loop is computed there."""
    from deathsphere.requests.arena import arena, names_a_wall

    if not names_a_wall(surface, wall_angle, wall_height, profile):
        return None
    named = _named(surface, wall_angle, wall_height, profile)
    return loop_of(arena(surface, r, diameter, wall_angle, wall_height, profile), named)


def loop_of(ground, named: str):
    """The loop of ``ground`` (:class:`~deathsphere.physics.meridian_loop.Loop`,
    sampled once) if it closes at both ends, else a ParameterError naming
    ``named`` (the keyword typed), saying why no vertical loop is computed
    there (the paper's wheel's and the machine's alike)."""
    if closes_over_top(ground) and hasattr(ground, "meridian"):
        from deathsphere.physics.meridian_loop import Loop, loop_closure

        why = loop_closure(ground)
        if why:
            raise ParameterError(f"no vertical loop: {why} (loops are computed on the sphere and on a profile "
                                 "closed at both ends)", named)
        return Loop.of(ground)
    raise ParameterError(f"a vertical loop runs over the top of its ground and the {ground.name} does not close "
                         "over the rider (no ground above the top of the loop): loops are computed on the sphere "
                         "and on a profile closed at both ends", named)


def refuse_off_globe(surface=None, r=None, diameter=None, wall_angle=None, wall_height=None, profile=None):
    """Nothing on the globe; elsewhere a ParameterError naming ``surface``
    (or the shape keyword that names a wall): why a vertical loop solved on
    the sphere only is not computed there."""
    from deathsphere.requests.arena import arena, names_a_wall

    if not names_a_wall(surface, wall_angle, wall_height, profile):
        return
    ground = arena(surface, r, diameter, wall_angle, wall_height, profile)
    raise ParameterError(f"this vertical loop is solved on the sphere only: not on a {ground.name}",
                         _named(surface, wall_angle, wall_height, profile))
