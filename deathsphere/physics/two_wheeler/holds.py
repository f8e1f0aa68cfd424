"""Whether a two-wheeler's lane holds it at a speed: some steady turn at
the lane with that rear contact speed is ridden within the limits (beyond
the paper; docs/show.md sec. 13, "A two-wheeler's fall", and
docs/two-wheeler.md sec. 8 for the turns).

One call of :func:`deathsphere.physics.two_wheeler.steady.turns_for_speed`
over every (lane, speed) given: the lean curve is computed once per distinct
lane and serves all its speeds, so many speeds at a few lanes cost about as
much as one (the solver ``ride --steer --speed a:b:c`` evaluates its speeds
with; the show's speed bands and its falls call this).  A turn holds where :func:`steady.turn_status` gives it
``ok``: found, the head clear, both wheels pushing, each wheel's friction
within ``mu`` and the load within ``max_g`` (a show's fall passes
``max_g = inf``: a single-contact machine's fall asks friction only, and so
does this).
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.status import Status
from deathsphere.physics.two_wheeler import steady

__all__ = ["turn_holds"]


def turn_holds(lane, speed, parameters, ground, g, head, mu, max_g=np.inf) -> dict:
    """Whether the lanes ``lane`` (theta [rad] on a Sphere, the rear
    contact's height [m] on a drum, a cone or a profile) hold the
    two-wheeler ``parameters`` (a BicycleParameters, its rider's head
    ``head``) at the rear contact speeds ``speed`` [m/s] under gravity ``g``
    with friction ``mu`` and load ``max_g`` (module docstring); lane and
    speed broadcast to (n,).

    Returns dict: ``holds`` (n,) bool (False where the speed is not > 0 or
    not finite: no turn is sought there), ``lean`` (n,) [rad] the least
    |lean| from the wall's normal among the turns that hold (NaN where none
    does).  Beyond the paper (docs/show.md sec. 13).
    """
    lane, speed = (np.asarray(x, dtype=float).reshape(-1) for x in np.broadcast_arrays(lane, speed))
    out = steady.turns_for_speed(lane, speed, parameters, ground, g, head)
    codes, _ = steady.turn_status(np.isfinite(out["lean"]), out["head_clearance"], out["contact"] == 1,
                                  out["mu_required_rear"], out["mu_required_front"], out["load_g"], mu, max_g)
    ok = codes == Status.OK
    holds = ok.any(axis=1)
    # the turns table has at least one column (NaN-padded where none was found)
    k = np.argmin(np.where(ok, np.abs(out["lean"]), np.inf), axis=1)
    lean = np.where(holds, np.take_along_axis(out["lean"], k[:, None], axis=1)[:, 0], np.nan)
    return {"holds": holds, "lean": lean}
