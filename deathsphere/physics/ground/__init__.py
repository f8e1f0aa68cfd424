"""The grounds bodies roll on (the protocol in :mod:`.protocol`): the globe,
the wall of death's drum, the well of death's cone, flat ground and any
profile sampled from its meridian."""

from deathsphere.physics.ground.cone import Cone
from deathsphere.physics.ground.cylinder import Cylinder
from deathsphere.physics.ground.plane import Plane
from deathsphere.physics.ground.profile import Profile
from deathsphere.physics.ground.protocol import Ground, meridian_frame
from deathsphere.physics.ground.sphere import Sphere

__all__ = ["Ground", "Sphere", "Cylinder", "Cone", "Plane", "Profile", "meridian_frame"]
