"""The machine of ``deathsphere ride`` in the API: the record, its presets
and its files live in :mod:`deathsphere.records` (:mod:`~deathsphere.records.machine`,
:mod:`~deathsphere.records.machine_presets`,
:mod:`~deathsphere.records.machine_files`; a file becomes a machine in the
requests' decoder, :func:`machine_file`); their names are importable from
here too, as they were before the records had a layer of their own.
The ``deathsphere machines`` table is :func:`deathsphere.api.machines_table`.
"""

from __future__ import annotations

from deathsphere.records.machine import (
    ALIASES,
    FIELD_PARAMS,
    INERTIA_PARAMS,
    INERTIA_RTOL,
    UNECHOABLE,
    Machine,
    echoable_text,
)
from deathsphere.records.machine_files import FILE_KEYS, machine_file_data, machine_file_text
from deathsphere.records.machine_presets import (
    BENCHMARK_BODIES,
    BENCHMARK_HEAD_ESTIMATE,
    BENCHMARK_WHEELS,
    BENCHMARK_WIDTH_ESTIMATE,
    DEFAULT_MACHINE,
    PRESETS,
    as_machine,
    benchmark_bicycle_rigid,
    benchmark_totals,
    paper_wheel,
    stunt125,
)
from deathsphere.requests.decode import decode_machine_file as machine_file

__all__ = ["Machine", "PRESETS", "DEFAULT_MACHINE", "as_machine", "paper_wheel", "benchmark_bicycle_rigid", "stunt125",
           "benchmark_totals", "BENCHMARK_BODIES", "BENCHMARK_WHEELS", "BENCHMARK_HEAD_ESTIMATE",
           "BENCHMARK_WIDTH_ESTIMATE", "machine_file", "machine_file_data", "machine_file_text", "FILE_KEYS",
           "echoable_text", "UNECHOABLE", "FIELD_PARAMS", "INERTIA_PARAMS", "INERTIA_RTOL", "ALIASES"]
