"""The Python API: one function per command of the command line, one module
per family of commands (orbits, vertical, region, stability, simulate, paper).

Each function takes the command's options as parameters of the same names
and units (angles in degrees, everything else SI) and returns what the
command prints with ``--format csv``, as a :class:`~deathsphere.model.Table`
with the same columns and values (docs/api.md, docs/contract.md):

=====================  =======================================
command                function
=====================  =======================================
``deathsphere orbit``  :func:`orbit`
``vertical``           :func:`vertical`
``sweep``              :func:`sweep` (an iterator of chunks)
``map --format csv``   :func:`region`
``limits``             :func:`limits`
``stability``          :func:`stability`
``simulate``           :func:`simulate` (series and summary)
``ride``               :func:`ride`; streamed: :func:`ride_sweep`
``table1``             :func:`table1`
``verify``             :func:`verify`
=====================  =======================================

Bad input raises :class:`~deathsphere.params.ParameterError` (a
``ValueError``) with the one-line reason the command line prints after
``Invalid value for '--option':``.  Arrays broadcast like numpy's; the rules
for an array with some bad elements are in :func:`orbit` ("Raises").
"""

from deathsphere.physics.lazy import lazy_exports

#: Where each public name lives; imported on first use, so that a command
#: loads only the family it calls.
_HOME = {
    "orbit": "orbits", "sweep": "orbits", "orbit_input": "orbits",
    "vertical": "vertical_orbits", "vertical_sweep": "vertical_orbits", "vertical_input": "vertical_orbits",
    "VERTICAL_ECHO": "vertical_orbits", "POINT_ROWS": "vertical_orbits",
    "region": "region_limits", "region_cells": "region_limits", "region_curves": "region_limits", "limits": "region_limits", "limits_input": "region_limits",
    "MAX_LIMIT_THETAS": "region_limits",
    "stability": "orbit_stability", "stability_input": "orbit_stability",
    "simulate": "simulation", "prepare_simulation": "simulation", "simulation_request": "simulation", "SimulationOptions": "simulation", "animation_options": "simulation", "METHODS": "simulation", "FRAMES": "simulation",
    "table1": "paper", "verify": "paper", "n_claims": "paper", "verify_counts": "paper",
    "table1_printed": "paper",
    "Chunks": "streams",
    "A": "arguments", "R": "arguments", "G": "arguments", "INF": "arguments", "CHUNK": "arguments",
    "STATUSES": "arguments", "ParameterError": "arguments",
    "ride": "rides", "ride_summary": "rides", "ride_sweep": "ride_streams", "Machine": "machines", "TwoWheeler": "two_wheelers", "machines_table": "two_wheelers",
    "machine_file": "machines", "PRESETS": "machines",
    "two_wheeler_file": "two_wheelers", "two_wheeler_text": "two_wheelers",
    "show": "shows", "ShowResult": "shows",
}
_MODULES = ("arguments", "streams", "orbits", "vertical_orbits", "region_limits", "orbit_stability", "simulation",
            "paper", "rides", "ride_streams", "machines", "two_wheelers", "shows")

__all__ = ["orbit", "sweep", "orbit_input", "vertical", "vertical_sweep", "vertical_input", "region",
           "region_cells", "region_curves", "limits", "limits_input", "stability", "stability_input", "simulate", "prepare_simulation", "simulation_request", "SimulationOptions", "animation_options", "table1",
           "verify", "Chunks", "ParameterError", "ride", "ride_sweep", "ride_summary", "Machine", "TwoWheeler", "machines_table", "machine_file", "show",
           "two_wheeler_file", "two_wheeler_text"]
__getattr__, __dir__ = lazy_exports(globals(), _HOME, _MODULES)
