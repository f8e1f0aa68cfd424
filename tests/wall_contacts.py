"""Where a simulated wheel or ball touches a ground, found the long way
(for the tests of runs on any ground, inside or outside): the rim's point
nearest the wall by sampling and golden-section steps on the ground's own
distance function, the ball's by that distance's gradient; and the
energy of a state from its contact, independent of the equations of
motion that moved it."""

import numpy as np

G = 9.80665


def rim(c, e1, a, angle):
    """Points of the rim circle (radius a about c, normal e1) at ``angle`` (n,)."""
    e1 = e1 / np.linalg.norm(e1, axis=0)
    ref = np.where(np.abs(e1[2]) < 0.9, 1.0, 0.0) * np.array([0.0, 0.0, 1.0])[:, None] + \
        np.where(np.abs(e1[2]) < 0.9, 0.0, 1.0) * np.array([1.0, 0.0, 0.0])[:, None]
    u = np.cross(e1, ref, axis=0)
    u /= np.linalg.norm(u, axis=0)
    v = np.cross(e1, u, axis=0)
    return c + a * (np.cos(angle) * u + np.sin(angle) * v)


def distance(ground, pts, outside=False):
    """A point's distance from the wall on the body's side: the ground's
    clearance (measured inside), negated on the outside."""
    clearance = ground.clearance(np.hypot(pts[0], pts[1]), pts[2])
    return -clearance if outside else clearance


def wheel_contact(ground, c, e1, a, outside=False):
    """The rim's point nearest the wall and its distance: the least of 720
    samples, then golden-section steps on its bracket."""
    n = c.shape[1]
    grid = np.linspace(0.0, 2 * np.pi, 720, endpoint=False)
    values = np.stack([distance(ground, rim(c, e1, a, np.full(n, t)), outside) for t in grid])
    best = grid[np.argmin(values, axis=0)]
    lo, hi = best - 2 * np.pi / 720, best + 2 * np.pi / 720
    ratio = (np.sqrt(5.0) - 1) / 2
    for _ in range(60):
        x1, x2 = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
        left = distance(ground, rim(c, e1, a, x1), outside) < distance(ground, rim(c, e1, a, x2), outside)
        hi, lo = np.where(left, x2, hi), np.where(left, lo, x1)
    p = rim(c, e1, a, 0.5 * (lo + hi))
    return p, distance(ground, p, outside)


def ball_contact(ground, c, a, outside=False):
    """The ball's contact (its centre moved a down the distance's gradient)
    and its gap; the gradient by a central difference whose step balances its
    round-off (eps |distance| / h) and its truncation (h^2 / 6 of the third
    derivative)."""
    gap = distance(ground, c, outside) - a
    h = 1e-5
    grad = np.stack([(distance(ground, c + h * e[:, None], outside) - distance(ground, c - h * e[:, None], outside))
                     / (2 * h) for e in np.eye(3)])
    return c - a * grad / np.linalg.norm(grad, axis=0), gap


def state_energy(state, p, a, k, ball, g=G):
    """(energy, kinetic energy) per unit mass of states (9, n): the centre's
    velocity from rolling about the contact p, the spin's k m a^2."""
    c, e1, w = state[0:3], state[3:6] / np.linalg.norm(state[3:6], axis=0), state[6:9]
    v = np.cross(w, c - p, axis=0)
    w1 = np.sum(w * e1, axis=0)
    rot = 0.5 * k * a * a * (np.sum(w * w, axis=0) + (0.0 if ball else w1 * w1))
    kinetic = 0.5 * np.sum(v * v, axis=0) + rot
    return kinetic + g * c[2], kinetic
