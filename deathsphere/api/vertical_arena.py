"""The arena of ``vertical``: a vertical loop runs over the top of its
ground, so it needs a surface that closes over the rider.  The globe does;
a drum, a cone and flat ground do not, and are refused; a profile (or a
cone's apex) that closes over the top is refused too: the loop's equations
(McDonald 1993 eqs. 27-28b) are solved on the sphere only
(docs/surfaces.md, "Work left")."""

from __future__ import annotations

import math

from deathsphere.params import ParameterError

#: A ground closes over the top when its highest lane's contact is this
#: close to the axis, relative to its widest lane scanned.
AXIS_TOL = 1e-9


def closes_over_top(ground) -> bool:
    """True when the ground's highest lane is on its axis (a finite top
    whose contact has rho = 0): a loop could run over it."""
    top = float(getattr(ground, "highest_lane", math.inf))
    if not math.isfinite(top):
        return False
    import numpy as np

    rho_top, _ = ground.contact(np.array([top]))
    rho_all, _ = ground.contact(np.linspace(0.0, top, 33))
    return bool(abs(float(rho_top[0])) <= AXIS_TOL * max(float(np.max(rho_all)), 1.0))


def refuse_off_globe(surface=None, r=None, diameter=None, wall_angle=None, wall_height=None, profile=None):
    """Nothing on the globe; elsewhere a ParameterError naming ``surface``
    (or the shape keyword that names a wall): why no vertical loop is
    computed there."""
    from deathsphere.requests.arena import arena, names_a_wall

    if not names_a_wall(surface, wall_angle, wall_height, profile):
        return
    named = "surface" if surface is not None else next(
        name for name, value in (("wall_angle", wall_angle), ("wall_height", wall_height), ("profile", profile))
        if value is not None)
    ground = arena(surface, r, diameter, wall_angle, wall_height, profile)
    if closes_over_top(ground):
        raise ParameterError(f"a vertical loop is solved on the sphere only (eqs. 27-28b): on a {ground.name} that "
                             "closes over the top it is not computed yet (use --surface sphere)", named)
    raise ParameterError(f"a vertical loop runs over the top of its ground and the {ground.name} does not close "
                         "over the rider (no ground above the top of the loop): only the sphere has vertical "
                         "orbits", named)
