"""Result tables of the commands beyond one horizontal orbit, one module per
command family: vertical orbits, the allowed region and the rider's limits,
the paper's Table 1, the checklist of the paper's claims, and one orbit's
stability beside the paper's results.  Each builds a
:class:`~deathsphere.model.Table` from :mod:`deathsphere.physics`; the
functions users call are in :mod:`deathsphere.api`.
"""
