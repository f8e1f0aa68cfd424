"""Where the Whipple bicycle's points are, numerically: the frames of
docs/two-wheeler.md sec. 2 as numpy vectors in the inertial frame N (z down),
for steady-turn forces, speeds and the rider's head (beyond the paper;
docs/two-wheeler.md sec. 2 and 8).

The derivation (``derivation.py``) builds the same frames in sympy; the
generated code exports only the front contact, which a test compares with
:func:`points` here.  Vectors are arrays (3, ...) with a trailing batch.
"""

from __future__ import annotations

import numpy as np

__all__ = ["frames", "points"]


def _rotate(v, axis, angle):
    """Rodrigues: v turned by angle about the unit vector axis (right hand)."""
    c, s = np.cos(angle), np.sin(angle)
    return v * c + np.cross(axis, v, axis=0) * s + axis * np.sum(axis * v, axis=0) * (1 - c)


def frames(q, lam, surface: str = "sphere"):
    """The unit vectors (x, y, z) of the tangent frame T, the heading frame Y,
    the lean frame L, the rear frame C and the front frame E in N, and the
    steer axis s (beyond the paper; docs/two-wheeler.md sec. 2)."""
    q = np.asarray(q)
    one, zero = np.ones_like(q[0]), np.zeros_like(q[0])
    if surface == "flat":
        Tx, Ty, Tz = (np.stack(v) for v in ((one, zero, zero), (zero, one, zero), (zero, zero, one)))
    else:
        th, az = q[0], q[1]
        Tz = np.stack([np.sin(th) * np.cos(az), np.sin(th) * np.sin(az), -np.cos(th)])
        Ty = np.stack([-np.sin(az), np.cos(az), zero])
        Tx = np.cross(Ty, Tz, axis=0)
    h, lean, pitch, steer = q[2], q[3], q[4], q[6]
    Yx, Yy, Yz = np.cos(h) * Tx + np.sin(h) * Ty, -np.sin(h) * Tx + np.cos(h) * Ty, Tz
    Lx, Ly, Lz = Yx, np.cos(lean) * Yy + np.sin(lean) * Yz, -np.sin(lean) * Yy + np.cos(lean) * Yz
    Cx, Cy, Cz = np.cos(pitch) * Lx - np.sin(pitch) * Lz, Ly, np.sin(pitch) * Lx + np.cos(pitch) * Lz
    s = np.sin(lam) * Cx + np.cos(lam) * Cz
    E = tuple(_rotate(v, s, steer) for v in (Cx, Cy, Cz))
    return {"T": (Tx, Ty, Tz), "Y": (Yx, Yy, Yz), "L": (Lx, Ly, Lz), "C": (Cx, Cy, Cz), "E": E, "s": s}


def points(q, parameters, r=None, surface: str = "sphere", head=(0.3, -1.7)):
    """The rear contact P, the wheel centres, the mass centres, the rider's
    head point and the front contact Q (farthest front rim point from O) in
    N, each (3, ...), and the frames (beyond the paper; docs/two-wheeler.md
    sec. 2, 3.2).  ``head`` = (x, z) of the head point in the rear frame,
    measured as xB, zB (from the rear contact upright, z down)."""
    p = parameters
    f = frames(q, p.lam, surface)
    Cx, Cz = f["C"][0], f["C"][2]
    Ex, Ey, Ez = f["E"]
    if surface == "flat":
        P = np.stack([q[0], q[1], np.zeros_like(q[0])])
    else:
        P = r * f["T"][2]
    rear = P - p.rR * f["L"][2]
    S = rear + (p.w + p.c) * Cx + p.rR * Cz
    front = S - p.c * Ex - p.rF * Ez
    # flat: the lowest rim point (towards N.z); sphere: the farthest from O (towards d = front - O)
    d = front if surface != "flat" else np.stack([np.zeros_like(q[0])] * 2 + [np.ones_like(q[0])])
    k = d - np.sum(d * Ey, axis=0) * Ey
    Q = front + p.rF * k / np.sqrt(np.sum(k * k, axis=0))
    return {
        "P": P, "rear_wheel": rear, "front_wheel": front, "Q": Q,
        "rear_frame": rear + p.xB * Cx + (p.zB + p.rR) * Cz,
        "front_frame": S + (p.xH - p.w - p.c) * Ex + p.zH * Ez,
        "head": rear + head[0] * Cx + (head[1] + p.rR) * Cz,
        "frames": f,
    }
