"""The output side: result tables (and the map and simulation data) as
text, files and figures.  Nothing here computes physics; every module takes
tables (:class:`deathsphere.table.Table`) and data objects made by the API;
the file writers (CSV, JSON, Parquet) are :mod:`deathsphere.writers`.

* :mod:`~deathsphere.render.terminal_table`: the pieces of every terminal view
  (:class:`~deathsphere.render.terminal_table.FitTable`, number text, the row cap);
  the views: :mod:`~deathsphere.render.orbit_views` (orbits, vertical orbits,
  any table), :mod:`~deathsphere.render.paper_views` (Table 1, the checklist,
  stability), :mod:`~deathsphere.render.simulation_view`,
  :mod:`~deathsphere.render.ride_views` (``ride``, the rider's table,
  ``machines``).
* :mod:`~deathsphere.render.charplot`: the terminal character map of the
  allowed region.
* :mod:`~deathsphere.render.figures` (the optional matplotlib),
  :mod:`~deathsphere.render.map_figure`,
  :mod:`~deathsphere.render.simulation_figure`: figures.

This package imports nothing itself: importing a submodule pays only for
what that submodule needs.
"""
