"""Where the Whipple bicycle's points are, numerically: the frames of
docs/two-wheeler.md sec. 2 as numpy vectors in the inertial frame N (z down),
for steady-turn forces, speeds, the rider's head and the drawing of a run
(beyond the paper; docs/two-wheeler.md sec. 2, 8 and 10.1).

The derivation (``derivation.py``) builds the same frames in sympy; the
generated code exports only the front contact, which a test compares with
:func:`points` here.  Vectors are arrays (3, ...) with a trailing batch.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.two_wheeler import grounds

__all__ = ["frames", "points", "outline", "RIM_POINTS"]

#: Points per wheel rim in :func:`outline`.
RIM_POINTS = 32


def _rotate(v, axis, angle):
    """Rodrigues: v turned by angle about the unit vector axis (right hand)."""
    c, s = np.cos(angle), np.sin(angle)
    return v * c + np.cross(axis, v, axis=0) * s + axis * np.sum(axis * v, axis=0) * (1 - c)


def frames(q, lam, ground):
    """The unit vectors (x, y, z) of the tangent frame T, the heading frame Y,
    the lean frame L, the rear frame C and the front frame E in N, and the
    steer axis s, on ``ground`` (a Plane or a Sphere; beyond the paper;
    docs/two-wheeler.md sec. 2)."""
    q = np.asarray(q)
    one, zero = np.ones_like(q[0]), np.zeros_like(q[0])
    Tx, Ty, Tz = grounds.of(ground).tangent_frame(q, one, zero)
    h, lean, pitch, steer = q[2], q[3], q[4], q[6]
    Yx, Yy, Yz = np.cos(h) * Tx + np.sin(h) * Ty, -np.sin(h) * Tx + np.cos(h) * Ty, Tz
    Lx, Ly, Lz = Yx, np.cos(lean) * Yy + np.sin(lean) * Yz, -np.sin(lean) * Yy + np.cos(lean) * Yz
    Cx, Cy, Cz = np.cos(pitch) * Lx - np.sin(pitch) * Lz, Ly, np.sin(pitch) * Lx + np.cos(pitch) * Lz
    s = np.sin(lam) * Cx + np.cos(lam) * Cz
    E = tuple(_rotate(v, s, steer) for v in (Cx, Cy, Cz))
    return {"T": (Tx, Ty, Tz), "Y": (Yx, Yy, Yz), "L": (Lx, Ly, Lz), "C": (Cx, Cy, Cz), "E": E, "s": s}


def points(q, parameters, ground, head=(0.3, -1.7)):
    """The rear contact P, the wheel centres, the mass centres, the rider's
    head point and the front contact Q (farthest front rim point from O) in
    N, each (3, ...), and the frames, on ``ground`` (beyond the paper;
    docs/two-wheeler.md sec. 2, 3.2).  ``head`` = (x, z) of the head point
    in the rear frame, measured as xB, zB (from the rear contact upright, z
    down)."""
    p = parameters
    on = grounds.of(ground)
    f = frames(q, p.lam, ground)
    Cx, Cz = f["C"][0], f["C"][2]
    Ex, Ey, Ez = f["E"]
    P = on.rear_contact(q, f)
    rear = P - p.rR * f["L"][2]
    S = rear + (p.w + p.c) * Cx + p.rR * Cz
    front = S - p.c * Ex - p.rF * Ez
    # flat: the lowest rim point (towards N.z); sphere: the farthest from O (towards d = front - O); a
    # revolution: where the rim is tangent to the ground
    d = on.farthest(front, q, f, p.rF)
    k = d - np.sum(d * Ey, axis=0) * Ey
    Q = front + p.rF * k / np.sqrt(np.sum(k * k, axis=0))
    return {
        "P": P, "rear_wheel": rear, "front_wheel": front, "Q": Q,
        "rear_frame": rear + p.xB * Cx + (p.zB + p.rR) * Cz,
        "front_frame": S + (p.xH - p.w - p.c) * Ex + p.zH * Ez,
        "head": rear + head[0] * Cx + (head[1] + p.rR) * Cz,
        "frames": f,
    }


def _rim(centre, radius, start, normal, beta):
    """The circle of ``radius`` about ``centre`` in the plane normal to the
    unit ``normal``, from the in-plane unit ``start`` at the angles ``beta``
    (n,): (3, n, ...)."""
    ahead = np.cross(normal, start, axis=0)
    b = beta.reshape((1, -1) + (1,) * (centre.ndim - 1))
    return centre[:, None] + radius * (np.cos(b) * start[:, None] + np.sin(b) * ahead[:, None])


def outline(q, parameters, ground, head=(0.3, -1.7), n_rim: int = RIM_POINTS):
    """The points that draw the bicycle at the coordinates q (8, ...), in N,
    each (3, ...), and the two rims (3, n_rim, ...) (beyond the paper;
    docs/two-wheeler.md sec. 2 and 10.1).

    ``rear_rim``: the rear wheel's circle (radius rR about its centre, in
    the rear frame's plane L.x, L.z) from the rear contact P; ``front_rim``:
    the front wheel's (rF, in the front frame's plane E.x, E.z) from the
    front contact Q.  The head tube is the steer axis from the height of the
    front wheel's top, 2 rF, to that of the rear frame's mass centre (-zB)
    but at least 2.2 rF (heights from the rear contact upright, along the
    rear frame's -C.z): ``steer_bottom``, ``steer_top``; the handlebar's
    ends ``bar_left``, ``bar_right`` lie w/4 either side of ``steer_top``
    along the front axle E.y (a drawing's proportions, not parameters).
    With those of :func:`points`: ``P``, ``Q``, ``rear_wheel``,
    ``front_wheel``, ``rear_frame``, ``front_frame``, ``head``."""
    p = parameters
    pts = points(q, p, ground, head)
    f = pts.pop("frames")
    Lx, Ly, Lz = f["L"]
    Cx, Cz = f["C"][0], f["C"][2]
    Ey = f["E"][1]
    rear, front = pts["rear_wheel"], pts["front_wheel"]
    beta = np.linspace(0.0, 2 * np.pi, int(n_rim), endpoint=False)
    toward_q = (pts["Q"] - front) / p.rF
    pts["rear_rim"] = _rim(rear, p.rR, Lz, Ly, beta)
    pts["front_rim"] = _rim(front, p.rF, toward_q, Ey, beta)

    def on_steer_axis(z):
        # the steer axis's point at height -z: it meets height 0 at S = (w + c, 0)
        return rear + (p.w + p.c + z * np.tan(p.lam)) * Cx + (z + p.rR) * Cz

    pts["steer_bottom"] = on_steer_axis(-2 * p.rF)
    pts["steer_top"] = on_steer_axis(min(p.zB, -2.2 * p.rF))
    pts["bar_left"] = pts["steer_top"] - 0.25 * p.w * Ey
    pts["bar_right"] = pts["steer_top"] + 0.25 * p.w * Ey
    return pts
