"""Physical constants and the paper's reference setup, defined once.

Values are SI.  Table 1 of McDonald (1993) uses a wheel of radius 0.3 m with
k = 1/2 (mass on the rim) in a sphere of radius 3.0 m.
"""

#: Standard acceleration of gravity [m/s^2] (3rd CGPM 1901, ISO 80000-3).
STANDARD_GRAVITY = 9.80665

#: Table 1's wheel radius a [m] and sphere radius r [m].
TABLE1_WHEEL_RADIUS = 0.3
TABLE1_SPHERE_RADIUS = 3.0

#: Inertia factor k by body when none is given: a wheel with its mass on the
#: rim (I11 = 2 k m a^2, k = 1/2, Table 1); a solid ball (I = k m a^2,
#: k = 2/5, sec. 4); a point particle has no rotational inertia.
DEFAULT_INERTIA = {"wheel": 0.5, "sphere": 0.4, "particle": 0.0}

BODIES = ("wheel", "sphere", "particle")
SIDES = ("inside", "outside")
