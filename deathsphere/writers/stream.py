"""Streaming writers of result tables: CSV, JSON and NDJSON.

Every writer takes an iterable of :class:`~deathsphere.table.Table` chunks so
that sweeps stream with flat memory; the header (CSV) or the opening bracket
(JSON) is written once.  The cells' text is :mod:`deathsphere.table.cells`'.

Nothing here imports rich: a command writing CSV or JSON does not pay for
the terminal views (:mod:`deathsphere.render`).
"""

from __future__ import annotations

from typing import IO, Iterable

from deathsphere.table.cells import csv_text, json_records
from deathsphere.writers.behind import WriteBehind

FORMATS = ("table", "csv", "json", "ndjson")


#: Which CSV writer formats a chunk: None picks per chunk (below), True
#: the compiled one (:mod:`deathsphere.writers.polars_csv`, the ``fast`` extra)
#: for every chunk, False the pure-Python one.  The bytes are the same
#: (tests/test_writers.py compares them), so chunks may mix.
COMPILED_CSV: bool | None = None

#: With COMPILED_CSV None the compiled writer takes over once an output is
#: this long (from the first chunk when the output is known to be at least
#: this long: a sweep's grid), and only for chunks of COMPILED_MIN_CHUNK
#: rows or more: importing polars costs ~0.2 s, which a short output
#: (`orbit`, a small sweep) would pay in latency, and polars' per-call cost
#: (~1 ms) is more than the pure-Python writer spends on a few hundred rows.
COMPILED_AFTER_ROWS = 20_000
COMPILED_MIN_CHUNK = 1024


def write_csv(chunks: Iterable, out: IO[str], compiled: bool | None = None, expected: int | None = None) -> int:
    """Stream tables as CSV: the header once, then every chunk's rows.
    ``compiled`` None takes :data:`COMPILED_CSV`; ``expected`` is the
    number of rows to come when known (None: unknown)."""
    mode = COMPILED_CSV if compiled is None else compiled
    fast = None
    # a long output known in advance takes the compiled writer at once: the
    # first COMPILED_AFTER_ROWS rows by the pure one would cost more than
    # importing polars
    rows = COMPILED_AFTER_ROWS if expected is not None and expected >= COMPILED_AFTER_ROWS else 0
    if mode or (mode is None and rows):
        _warm_up_polars()
    written = 0
    # the compiled writer writes bytes straight to a text file's buffer
    utf8 = (getattr(out, "encoding", None) or "").lower().replace("-", "") == "utf8"
    binary = getattr(out, "buffer", None) if utf8 else None
    behind = None
    try:
        for i, table in enumerate(chunks):
            text = csv_text
            if mode or (mode is None and rows >= COMPILED_AFTER_ROWS and len(table) >= COMPILED_MIN_CHUNK):
                if fast is None:
                    from deathsphere.writers import polars_csv

                    fast = polars_csv.polars_csv_text if polars_csv.csv_available() else False
                text = fast or csv_text
            if text is csv_text or binary is None:
                if behind is not None:
                    behind.wait()
                out.write(text(table, header=i == 0))
            elif expected is None:
                # a stream of unknown length (an --input file) keeps to one
                # chunk in memory: it holds the reader's blocks besides
                out.flush()  # what the text layer holds goes first
                text(table, header=i == 0, sink=binary)
            else:
                if behind is None:
                    out.flush()  # what the text layer holds goes first
                    behind = WriteBehind()
                behind.put(text, table, header=i == 0, sink=binary)
            rows += len(table)
            written += len(table)
        if behind is not None:
            behind.wait()
    finally:
        if behind is not None:
            behind.close()
    return written


def _warm_up_polars() -> None:
    """Import polars and check it against repr
    (:func:`deathsphere.writers.polars_csv.csv_available`, ~0.3 s, much of
    it in compiled code) on a thread while the first chunk is evaluated;
    the first compiled chunk waits for it (the check runs once, under a lock)."""
    import threading

    from deathsphere.writers import polars_csv

    threading.Thread(target=polars_csv.csv_available, name="deathsphere-polars", daemon=True).start()


def write_ndjson(chunks: Iterable, out: IO[str]) -> int:
    """Stream tables as NDJSON: one object per line."""
    rows = 0
    for table in chunks:
        lines = json_records(table)
        if lines:
            out.write("\n".join(lines) + "\n")
        rows += len(lines)
    return rows


def write_json(chunks: Iterable, out: IO[str]) -> int:
    """A JSON array of row objects, streamed chunk by chunk."""
    rows = 0
    out.write("[")
    for table in chunks:
        for line in json_records(table):
            out.write(("\n  " if rows == 0 else ",\n  ") + line)
            rows += 1
    out.write("\n]\n" if rows else "]\n")
    return rows
