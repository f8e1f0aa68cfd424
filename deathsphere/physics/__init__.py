"""Pure, vectorised physics of McDonald (1993): numpy arrays in, arrays out.

Angles are in radians, lengths in metres, times in seconds throughout this
sub-package; degree conversion and validation happen in :mod:`deathsphere.model`.
Nothing here prints, reads files or raises for a physically impossible orbit:
impossibility is reported as a status code (:mod:`deathsphere.physics.status`).
"""
