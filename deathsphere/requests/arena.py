"""The arena a rider rides in, from the keywords a user types: the globe, the
wall of death's drum or the well of death's cone (beyond the paper; docs/
machine.md, "On any surface of revolution").  The one place a surface's
name becomes a ground of the ground protocol."""

from __future__ import annotations

import math

from deathsphere.errors import ParameterError
from deathsphere.params import PARAMS, choice, problems
from deathsphere.physics.ground import Cone, Cylinder, Sphere
from deathsphere.units import parse_value

__all__ = ["SURFACES", "arena", "names_a_wall"]

#: The surfaces a machine rides on, by the name typed (``--surface``).
SURFACES = PARAMS["surface"].choices


def _one(name: str, raw, kind: str) -> float:
    """One value of the registry's ``name``, a number or text with a unit;
    refused in one line naming the keyword."""
    if isinstance(raw, bool):
        raise ParameterError(f"{name} takes one number (got {raw!r})", name)
    if isinstance(raw, (list, tuple)) and len(raw) == 1:
        raw = raw[0]
    try:
        value = parse_value(raw, kind, name) if isinstance(raw, str) else float(raw)
    except ParameterError:
        raise
    except (TypeError, ValueError):
        raise ParameterError(f"{name} takes one number (got {raw!r})", name) from None
    reason = problems(name, [value])[0]
    if reason:
        raise ParameterError(reason, name)
    return value


def arena(surface="sphere", r=None, diameter=None, wall_angle=None, wall_height=None):
    """The ground named ``surface`` (``sphere``, ``cylinder``, ``cone``) of
    radius ``r`` [m] or ``diameter`` (one of them; for the drum and the
    cone, the radius where the wall meets the floor), its wall at
    ``wall_angle`` [deg] from the horizontal (the cone's; the drum's is 90)
    up to ``wall_height`` [m] (None: no top).  Values may be text with a
    unit (``"32ft"``).  A keyword the surface does not take is refused in
    one line naming it."""
    name = choice("surface", surface if surface is not None else "sphere", SURFACES)
    if r is not None and diameter is not None:
        raise ParameterError("give the radius r or the diameter, not both", "diameter")
    if r is None and diameter is None:
        raise ParameterError(f"a {name} needs its size: give r or diameter", "diameter", missing=True)
    radius = _one("r", r, "length") if diameter is None else _one("diameter", diameter, "length") / 2.0
    if name == "sphere":
        for key, value in (("wall_angle", wall_angle), ("wall_height", wall_height)):
            if value is not None:
                raise ParameterError(f"{key} is a drum's or a cone's (surface cylinder or cone), not the "
                                     "sphere's", key)
        return Sphere(radius)
    top = math.inf if wall_height is None else _one("wall_height", wall_height, "length")
    if name == "cylinder":
        if wall_angle is not None and _one("wall_angle", wall_angle, "angle") != 90.0:
            raise ParameterError("a cylinder's wall is vertical (wall_angle 90): give surface cone for another "
                                 "angle", "wall_angle")
        return Cylinder(radius, top)
    if wall_angle is None:
        raise ParameterError("a cone needs its wall_angle (degrees from the horizontal, > 0 and < 180)",
                             "wall_angle", missing=True)
    return Cone(radius, math.radians(_one("wall_angle", wall_angle, "angle")), top)


def names_a_wall(surface=None, wall_angle=None, wall_height=None) -> bool:
    """True when the keywords ask for a drum or a cone (a surface other than
    the globe, or a wall's option), False for the globe; an unknown surface
    is refused in one line."""
    name = choice("surface", surface if surface is not None else "sphere", SURFACES)
    return wall_angle is not None or wall_height is not None or name != "sphere"
