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

#: The allowed region's boundaries (docs/limits.md): name -> its label (inside,
#: outside), the equation it comes from and what holds on it.  The one text
#: every table, map and plot uses (words, not physics: defined here so that
#: the results and the views share them without the views importing physics).
BOUNDARY_LABELS = {
    "eq0": ("eq. (0): the wheel fits", "eq. (81): the wheel fits"),
    "eq29": ("eq. (29): Omega^2 = 0 or diverges", "eq. (29): Omega^2 = 0 or diverges"),
    "eq33": ("eq. (33): normal force = 0", "eq. (83): normal force = 0"),
    "mu": ("eq. (35): mu_required = mu", "eq. (35): mu_required = mu"),
    "max_g": ("load_g = max_g (eq. (32) with eq. (36))", "load_g = max_g (eq. (32) with eq. (36))"),
}
