"""Grounds sampled from shapes whose answers are known, for the tests that
check a profile against them: a profile is only its samples, so the same
sampling is written once."""

import numpy as np

from deathsphere.physics.ground import Profile


def sampled_sphere(radius: float, samples: int = 2001) -> Profile:
    """The globe of ``radius`` [m] sampled at ``samples`` points from its
    bottom to its top (a meridian closed at both ends: a loop's profile)."""
    t = np.linspace(np.pi, 0.0, samples)
    return Profile(np.abs(radius * np.sin(t)), radius * np.cos(t))
