"""The arena a run rides in: one ground record from the keywords (and so the
command line's options) that name a surface and its shape
(docs/surfaces.md): the globe, the wall of death's drum, the well of
death's cone, flat ground or a profile read from its file.  Every command
builds its ground here, so that a refusal names what was typed the same
way everywhere."""

from __future__ import annotations

import math

from deathsphere import params
from deathsphere.errors import ParameterError
from deathsphere.physics.ground import Cone, Cylinder, Ground, Plane, Profile, Sphere

__all__ = ["SURFACES", "SHAPE_KEYS", "arena", "is_globe", "lane_key", "names_a_wall", "refuse_above_top"]

#: The surfaces by name (``--surface``); the sphere is the paper's globe.
SURFACES = ("sphere", "cylinder", "cone", "plane", "profile")
#: The keywords that give a surface its shape, and the surfaces taking each.
SHAPE_KEYS = {
    "r": ("sphere", "cylinder", "cone"),
    "diameter": ("sphere", "cylinder", "cone"),
    "wall_angle": ("cone",),
    "wall_height": ("cylinder", "cone"),
    "profile": ("profile",),
}
#: What each surface must be given (besides the sphere's default radius).
_REQUIRED = {"cone": ("wall_angle",), "profile": ("profile",)}


def _one(name: str, value) -> float:
    """One allowed value of a shape keyword (a number or its text with a unit)."""
    from deathsphere import units

    kind = params.PARAMS[name].kind
    if isinstance(value, (list, tuple)):
        if len(value) != 1:
            raise ParameterError(f"{name} takes one value: one arena a run (got {len(value)})", name)
        value = value[0]
    if isinstance(value, str):
        value = units.parse_value(value, kind, name)
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} takes one number (got {value!r})", name) from None
    reason = params.first_problem(name, [number])
    if reason:
        raise ParameterError(reason, name)
    return number


def is_globe(surface) -> bool:
    """True for the default arena: the sphere by name (or not given) or a
    Sphere record."""
    return surface is None or isinstance(surface, Sphere) or (isinstance(surface, str)
                                                             and surface.strip().lower() == "sphere")


def arena(surface="sphere", r=None, diameter=None, wall_angle=None, wall_height=None, profile=None) -> Ground:
    """The ground record of ``surface`` and its shape.

    Parameters
    ----------
    surface : str or a ground record
        ``"sphere"`` (radius ``r`` or ``diameter``), ``"cylinder"`` (the
        drum: ``diameter``, optional ``wall_height``), ``"cone"``
        (``diameter`` at the floor, ``wall_angle`` [deg] strictly between
        0 and 180, optional ``wall_height``), ``"plane"`` (no shape) or
        ``"profile"`` (``profile``: a CSV file's path or a Profile); or a
        ground record (Sphere, Cylinder, Cone, Plane, Profile), returned as
        it is (no shape keywords with it).
    r, diameter, wall_height : float or text with a length unit ([m])
    wall_angle : float or text with an angle unit ([deg])

    Raises
    ------
    ParameterError
        One line naming the keyword: an unknown surface, a shape keyword
        the surface does not take, a missing one, a value out of bounds, a
        profile file that cannot be read.
    """
    given = {name: value for name, value in (("r", r), ("diameter", diameter), ("wall_angle", wall_angle),
                                             ("wall_height", wall_height), ("profile", profile))
             if value is not None}
    if isinstance(surface, Ground) and not isinstance(surface, (str, type)):
        if given:
            name = next(iter(given))
            raise ParameterError(f"{name}: the surface record given has its shape already; give the record or "
                                 "the shape keywords, not both", name)
        return surface
    if surface is None:
        surface = "sphere"
    if not isinstance(surface, str):
        raise ParameterError(f"surface must be one of {' | '.join(SURFACES)} or a ground record (got {surface!r})",
                             "surface")
    name = surface.strip().lower()
    if name not in SURFACES:
        raise ParameterError(f"surface must be one of {' | '.join(SURFACES)} (got {surface!r})", "surface")
    for key in given:
        if name not in SHAPE_KEYS[key]:
            takes = ", ".join(k for k, on in SHAPE_KEYS.items() if name in on) or "no shape keywords"
            raise ParameterError(f"{key} is not a shape of the {name} (it takes {takes})", key)
    for key in _REQUIRED.get(name, ()):
        if key not in given:
            raise ParameterError(f"a {name} needs its {key.replace('_', ' ')} ({key})", key, missing=True)
    if "r" in given and "diameter" in given:
        raise ParameterError(f"give the {name}'s radius r or its diameter, not both", "diameter")
    if name in ("cylinder", "cone") and "r" not in given and "diameter" not in given:
        raise ParameterError(f"a {name} needs its size: its diameter (or radius r) at the floor", "diameter",
                             missing=True)
    if name == "sphere":
        radius = _one("r", given["r"]) if "r" in given else (
            _one("diameter", given["diameter"]) / 2.0 if "diameter" in given else params.PARAMS["r"].default)
        return Sphere(radius)
    if name == "plane":
        return Plane()
    if name == "profile":
        if isinstance(given["profile"], Profile):
            return given["profile"]
        from deathsphere.records.profile_files import profile_file

        return profile_file(given["profile"])
    radius = _one("r", given["r"]) if "r" in given else _one("diameter", given["diameter"]) / 2.0
    top = _one("wall_height", given["wall_height"]) if "wall_height" in given else math.inf
    if name == "cylinder":
        return Cylinder(radius, top)
    return Cone(radius, math.radians(_one("wall_angle", given["wall_angle"])), top)


def lane_key(ground) -> str:
    """The keyword that names a lane on ``ground``: ``height`` (up a wall),
    or ``turn_radius`` on flat ground, which has no wall to climb (no
    highest lane)."""
    return "height" if hasattr(ground, "highest_lane") else "turn_radius"


def names_a_wall(surface=None, wall_angle=None, wall_height=None, profile=None) -> bool:
    """True when the keywords ask for an arena other than the globe (a
    surface other than the sphere, or a wall's or a profile's keyword);
    an unknown surface is refused in one line."""
    if surface is not None and not isinstance(surface, str):
        return not isinstance(surface, Sphere)
    name = (surface if surface is not None else "sphere").strip().lower()
    if name not in SURFACES:
        raise ParameterError(f"surface must be one of {' | '.join(SURFACES)} (got {surface!r})", "surface")
    return name != "sphere" or any(v is not None for v in (wall_angle, wall_height, profile))


def refuse_above_top(ground, highest: float, key: str = "height") -> None:
    """Refuse, naming ``key``, a lane typed above the ground's highest lane
    (a drum's or a cone's wall top, a leaning-in cone's apex, a profile's
    last sample): one meaning for every command.  A batch's rows are not
    refused here: each says ``no_fit`` with its reason instead."""
    top = getattr(ground, "highest_lane", math.inf)
    if highest > top:
        raise ParameterError(f"height must be at most {params.shown_number(top)} m on this {ground.name}, its "
                             f"highest lane (the wall's top, or a cone's apex; got {params.shown_number(highest)} m)",
                             key)
