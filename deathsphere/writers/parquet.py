"""Result tables streamed into one Parquet file through pyarrow (the
optional ``fast`` extra: ``pip install 'deathsphere[fast]'``).

Nothing here is imported until Parquet is asked for: pyarrow takes a
noticeable time to import.
"""

from __future__ import annotations

import importlib.util
from typing import Iterable

from deathsphere.table import frames
from deathsphere.writers.atomic import atomic_path
from deathsphere.writers.behind import WriteBehind


def parquet_available() -> bool:
    return importlib.util.find_spec("pyarrow") is not None


def write_parquet(chunks: Iterable, path: str) -> int:
    """Stream tables into one Parquet file, one row group per chunk, so
    memory stays that of a chunk.  Each chunk is :meth:`Table.to_arrow
    <deathsphere.table.Table.to_arrow>` with the first chunk's schema:
    undefined values (NaN, empty text) are nulls; text columns are strings,
    ``input_row`` and ``branch`` int64, the rest float64.  The file
    appears under ``path`` only when complete (:mod:`deathsphere.writers.atomic`)."""
    with atomic_path(path) as temp:
        return _write_parquet(chunks, temp)


def _write_parquet(chunks: Iterable, path: str) -> int:
    import threading

    # pyarrow's import and its first conversion (which imports pandas, if
    # installed: ~0.25 s together) on a thread while the first chunk is evaluated
    warm = threading.Thread(target=_warm_up_pyarrow, name="deathsphere-pyarrow", daemon=True)
    warm.start()
    rows = 0
    writer = schema = None
    # the row groups are encoded, compressed and written on a thread while
    # the next chunk is evaluated (pyarrow does it without Python's lock)
    behind = WriteBehind()
    try:
        for table in chunks:
            if schema is None:
                warm.join()
                import pyarrow as pa
                import pyarrow.parquet as pq

                schema = frames.arrow_schema(table)
                # dictionaries for the text columns only: a float column of
                # distinct results would be dictionary-encoded in vain (pyarrow
                # tries it, then falls back), the chunk's costliest step
                text = [f.name for f in schema if pa.types.is_string(f.type)]
                writer = pq.ParquetWriter(path, schema, use_dictionary=text)
            if len(table) == 0:
                continue
            behind.put(writer.write_table, frames.arrow_table(table, schema), row_group_size=len(table))
            rows += len(table)
        behind.wait()
    finally:
        behind.close()
        if writer is not None:
            writer.close()
    if writer is None:  # no chunk at all: still a valid, empty file
        import pyarrow as pa
        import pyarrow.parquet as pq

        pq.write_table(pa.table({}), path)
    return rows


def _warm_up_pyarrow() -> None:
    """Import what :func:`write_parquet` needs; a failure is left for the
    writer's own import to report (a thread would print a traceback)."""
    try:
        import numpy as np
        import pyarrow as pa
        import pyarrow.parquet  # noqa: F401

        pa.array(np.zeros(1), mask=np.zeros(1, dtype=bool))
    except Exception:
        pass
