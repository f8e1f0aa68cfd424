"""Pure, vectorised physics of McDonald (1993): numpy arrays in, arrays out.

Angles are in radians, lengths in metres, times in seconds throughout this
sub-package; degree conversion and validation happen in :mod:`deathsphere.model`.
Nothing here prints, reads files or raises for a physically impossible orbit:
impossibility is reported as a status code (:mod:`deathsphere.physics.status`).

Map of the package
------------------

==================  ==========================================  ==================
module              concept                                     paper
==================  ==========================================  ==================
``geometry``        fit conditions, the orbit radius r'         eqs. (0), (8b), (81)
``status``          status and reason codes of an orbit         --
``wheel``           steady horizontal orbits of a wheel         eqs. (13), (29)-(36),
                                                                (81), (83)
``region``          the allowed (theta, alpha) region, its      fig. "alpha_wh",
                    boundaries, the highest orbit, the tilt     eqs. (0), (29), (33),
                    for a speed                                 (35), (36)
``trig_roots``      all zeros of trigonometric polynomials      beyond the paper
                    (the root finder behind ``region``)
``vertical_orbit``  vertical orbits of a wheel: speed, forces,  eqs. (26)-(28b),
                    lap time, release and slip                  (82)
``sphere``          horizontal orbits of a rolling sphere       eqs. (41)-(59)
``particle``        horizontal orbits of a sliding particle     intro, sec. 2.2.1
``vectors``         3-vector algebra on axis 0 (complex-step    --
                    safe)
``dynamics``        exact equations of motion of any motion,    eqs. (2)-(7b),
                    steady-orbit states, contact force          beyond the paper
``stability``       linear stability, exact and the paper's     sec. 2.3, beyond
                    (a sub-package; see its docstring)          the paper
==================  ==========================================  ==================

Symbols (one name per quantity in every signature)
--------------------------------------------------

=============  =========  ===================================================
name           unit       meaning
=============  =========  ===================================================
``theta``      rad        polar angle of the contact point from the upward
                          vertical through the sphere's centre; for a
                          vertical orbit the cone angle about the horizontal
                          axis z'
``alpha``      rad        tilt of the wheel's axis 3 below the orbit plane
``a``          m          radius of the rolling body
``r``          m          radius of the fixed sphere
``k``          --         inertia factor: wheel I11 = 2 k m a^2 (eq. 1),
                          sphere I = k m a^2 (sec. 4)
``g``          m/s^2      gravity (default ``constants.STANDARD_GRAVITY``)
``outside``    bool       the body rolls on the outside of the sphere
``mu``         --         friction coefficient available (inf: unlimited)
``max_g``      --         largest load allowed (inf: unlimited)
``omega``      rad/s      Omega, the rate of a horizontal orbit about the
                          vertical (signed for the sphere, eq. 55)
``omega3``     rad/s      a sphere's spin w.e3 about the axis to the contact
``phidot_top`` rad/s      a vertical orbit's rate at its top (phi = 0)
``phi``        rad        azimuth along a vertical orbit from its top
``speed``      m/s        speed of the body's centre, v_cm = |r'| Omega
r' (``rp``)    m          distance of the centre from the orbit axis, eq. (8b)
=============  =========  ===================================================
"""
