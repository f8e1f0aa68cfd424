"""Result tables streamed into one Parquet file through pyarrow (the
optional ``fast`` extra: ``pip install 'deathsphere[fast]'``).

Nothing here is imported until Parquet is asked for: pyarrow takes a
noticeable time to import.
"""

from __future__ import annotations

import importlib.util
from typing import Iterable

import numpy as np

from deathsphere.model import TEXT_COLUMNS


def parquet_available() -> bool:
    return importlib.util.find_spec("pyarrow") is not None


def _arrow_type(pa, name: str, values: np.ndarray):
    kind = values.dtype.kind
    if name in TEXT_COLUMNS or kind in "US":
        return pa.string()
    if kind == "f":
        return pa.float64()
    if kind in "iu" or kind == "O":  # object non-text columns hold ints or None (branch)
        return pa.int64()
    if kind == "b":
        return pa.bool_()
    raise TypeError(f"column {name!r}: no Parquet type for {values.dtype}")


def _arrow_column(pa, values: np.ndarray, kind):
    if pa.types.is_floating(kind):
        return pa.array(values, type=kind, from_pandas=True)  # NaN -> null, as CSV's empty cell
    if values.dtype.kind == "O":
        return pa.array(values.tolist(), type=kind)
    return pa.array(values, type=kind)


def write_parquet(chunks: Iterable, path: str) -> int:
    """Stream tables into one Parquet file, one row group per chunk, so
    memory stays that of a chunk.  Undefined values are nulls; text columns
    are strings, ``input_row`` and ``branch`` int64, the rest float64."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    rows = 0
    writer = schema = None
    try:
        for table in chunks:
            if schema is None:
                schema = pa.schema([(n, _arrow_type(pa, n, table[n])) for n in table.names])
                writer = pq.ParquetWriter(path, schema)
            if len(table) == 0:
                continue
            batch = pa.table([_arrow_column(pa, table[f.name], f.type) for f in schema], schema=schema)
            writer.write_table(batch, row_group_size=len(table))
            rows += len(table)
    finally:
        if writer is not None:
            writer.close()
    if writer is None:  # no chunk at all: still a valid, empty file
        pq.write_table(pa.table({}), path)
    return rows
