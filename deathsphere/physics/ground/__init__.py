"""The grounds bodies roll on (the protocol in :mod:`.protocol`): the globe,
the wall of death's drum, the well of death's cone and flat ground."""

from deathsphere.physics.ground.cone import Cone
from deathsphere.physics.ground.cylinder import Cylinder
from deathsphere.physics.ground.plane import Plane
from deathsphere.physics.ground.protocol import Ground, meridian_frame
from deathsphere.physics.ground.sphere import Sphere

__all__ = ["Ground", "Sphere", "Cylinder", "Cone", "Plane", "meridian_frame"]
