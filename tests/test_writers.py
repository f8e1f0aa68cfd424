"""The compiled writers (polars CSV, pyarrow Parquet) against the pure-Python
ones: the same CSV bytes, Parquet holding the CSV's values with types, and
``sweep --jobs`` giving the output of one process."""

import csv
import io
import math
import os

import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

import deathsphere
from deathsphere.cli import cli
from deathsphere.model import COLUMNS, TEXT_COLUMNS, Table
from deathsphere.table import cells
from deathsphere.writers import parquet, polars_csv, stream

needs_polars = pytest.mark.skipif(not polars_csv.csv_available(),
                                  reason="the fast extra (polars) is not installed")
needs_pyarrow = pytest.mark.skipif(not parquet.parquet_available(),
                                   reason="the fast extra (pyarrow) is not installed")

#: Grids that between them give every status: wheels that fit and do not,
#: orbits above and below the equator, too little friction (--mu 1), both
#: sides, and a body bigger than the sphere (invalid rows).
STATUS_GRIDS = {
    "wheel": ["--theta", "0:180:7.5", "--alpha", "-180:180:7.5", "--mu", "1", "-a", "0.3", "-a", "4",
              "-a", "1e-9"],
    "wheel outside": ["--side", "outside", "--theta", "0:180:10", "--alpha", "-180:180:10", "--mu", "1",
                      "-a", "0.3", "-a", "4"],
    "sphere": ["--body", "sphere", "--theta", "0:180:7.5", "--omega3", "-120:120:15", "--mu", "1",
               "-a", "0.3", "-a", "4"],
    "sphere outside": ["--body", "sphere", "--side", "outside", "--theta", "0:180:15", "--omega", "-20:20:2.5",
                       "--mu", "0.5"],
    "particle": ["--body", "particle", "--theta", "0:180:2.5", "--mu", "1", "-a", "0.3", "-a", "4"],
}


def sweep(*args, compiled=True, monkeypatch=None):
    if monkeypatch is not None:
        monkeypatch.setattr(stream, "COMPILED_CSV", compiled)
    res = CliRunner().invoke(cli, ["sweep", *args], catch_exceptions=False)
    return res


@pytest.fixture(scope="module")
def pure_outputs():
    """Each status grid written by the pure-Python writer (the reference)."""
    outputs = {}
    saved = stream.COMPILED_CSV
    stream.COMPILED_CSV = False
    try:
        for name, args in STATUS_GRIDS.items():
            res = CliRunner().invoke(cli, ["sweep", "--chunk-size", "1000", *args], catch_exceptions=False)
            outputs[name] = (res.exit_code, res.stdout)
    finally:
        stream.COMPILED_CSV = saved
    return outputs


def test_status_grids_hold_every_status(pure_outputs):
    seen = set()
    for code, text in pure_outputs.values():
        seen |= {row["status"] for row in csv.DictReader(io.StringIO(text))}
    assert seen == {"ok", "no_fit", "no_orbit", "no_contact", "slips", "invalid"}


@needs_polars
@pytest.mark.parametrize("name", list(STATUS_GRIDS))
def test_compiled_csv_is_the_pure_csv_byte_for_byte(name, pure_outputs, monkeypatch):
    res = sweep("--chunk-size", "1000", *STATUS_GRIDS[name], compiled=True, monkeypatch=monkeypatch)
    assert (res.exit_code, res.stdout) == pure_outputs[name]


def test_pure_writer_is_used_when_asked_or_when_the_extra_is_missing(pure_outputs, monkeypatch):
    """The fallback runs even with polars installed: forced off, or with a
    polars that fails the repr check (or is absent)."""
    calls = []
    monkeypatch.setattr(polars_csv, "polars_csv_text", lambda *a, **k: calls.append(1) or "")
    res = sweep("--chunk-size", "1000", *STATUS_GRIDS["wheel"], compiled=False, monkeypatch=monkeypatch)
    assert (res.exit_code, res.stdout) == pure_outputs["wheel"]
    monkeypatch.setattr(polars_csv, "_csv_ok", False)
    res = sweep("--chunk-size", "1000", *STATUS_GRIDS["wheel"], compiled=True, monkeypatch=monkeypatch)
    assert (res.exit_code, res.stdout) == pure_outputs["wheel"]
    assert not calls


@needs_polars
def test_long_outputs_switch_writers_midway_without_a_seam(pure_outputs, monkeypatch):
    """By default short outputs stay pure-Python (no polars import); a long
    sweep (its grid size known) is compiled from its first chunk, and an
    output of unknown length switches to the compiled writer after some rows."""
    monkeypatch.setattr(stream, "COMPILED_AFTER_ROWS", 2500)
    monkeypatch.setattr(stream, "COMPILED_MIN_CHUNK", 600)
    used = []
    real = polars_csv.polars_csv_text
    monkeypatch.setattr(polars_csv, "polars_csv_text", lambda table, header, **kw: used.append(len(table)) or real(table, header, **kw))
    res = sweep("--chunk-size", "1000", *STATUS_GRIDS["wheel"], compiled=None, monkeypatch=monkeypatch)
    assert (res.exit_code, res.stdout) == pure_outputs["wheel"]
    assert used and sum(used) == res.stdout.count("\n") - 1  # every chunk compiled (all >= 600 rows)
    used.clear()
    tables = list(deathsphere.sweep(*STATUS_GRIDS["wheel"][1:4:2], mu=1, a=[0.3, 4, 1e-9], chunk_size=1000))
    out = io.StringIO()
    stream.write_csv(iter(tables), out)  # no expected size: a stream read as it comes
    assert out.getvalue() == pure_outputs["wheel"][1]
    assert used and sum(used) < out.getvalue().count("\n") - 2500
    used.clear()
    res = sweep("--theta", "0:180:10", "--alpha", "0:90:10", compiled=None, monkeypatch=monkeypatch)
    assert res.exit_code == 0 and not used


def test_a_polars_that_formats_unlike_repr_is_not_used(monkeypatch):
    monkeypatch.setattr(polars_csv, "_csv_ok", None)
    monkeypatch.setattr(polars_csv, "_polars_matches_repr", lambda: False)
    assert not polars_csv.csv_available()


# ---------------------------------------------------------------------------
# random tables

finite = st.floats(allow_nan=False, allow_infinity=False, allow_subnormal=True)
floats = st.one_of(finite, st.just(math.nan), st.just(-0.0), st.just(0.0),
                   st.sampled_from([5e-324, 1e-10, 9.99999e-11, 1e-5, 2.5e-5, 9.9999e-5, 1e-4, 1e15, 1e16,
                                    123456789012345.0, 1.7976931348623157e308, 1.5e20, 60.0]),
                   st.floats(min_value=1e-11, max_value=2e-4), st.floats(min_value=-2e-4, max_value=-1e-11),
                   st.floats(min_value=1e14, max_value=1e17))
texts = st.one_of(st.none(), st.sampled_from(["", "ok", "a,b", 'say "x"', "cr\rlf\n", " lead", "é"]),
                  st.text(alphabet=st.sampled_from(list('ab ,"\r\n\té')), max_size=6))


@st.composite
def tables(draw):
    n = draw(st.integers(0, 40))
    col = lambda s: draw(st.lists(s, min_size=n, max_size=n))  # noqa: E731
    return Table({
        "input_row": np.array(col(st.integers(-2**63, 2**63 - 1)), dtype=np.int64),
        "status": np.array(col(texts), dtype=object),
        "theta_deg": np.array(col(floats), dtype=float),    # the writer's repeating-values path
        "r_prime_m": np.array(col(floats), dtype=float),
        "mu_required": np.array(col(st.sampled_from([math.nan, 0.25])), dtype=float),  # constant path
        "branch": np.array(col(st.one_of(st.none(), st.integers(0, 3))), dtype=object),
        "reason": np.array(col(texts), dtype=object),
        "side": np.array([draw(texts)] * n, dtype=object),  # one value in every row: the repeated-text path
        "a_m": np.full(n, draw(floats)),                    # one value in every row: its text repeated
        "k": np.array([0.0] * (n - 1) + [-0.0] * (n > 0)),   # == everywhere, yet two texts: not repeated
    })


@needs_polars
@settings(max_examples=100, deadline=None)
@given(tables(), st.booleans())
def test_compiled_csv_equals_pure_csv_on_random_tables(table, header):
    assert polars_csv.polars_csv_text(table, header) == cells.csv_text(table, header)


@needs_polars
def test_compiled_float_text_is_repr_on_random_bit_patterns():
    """Every kind of double: random sign, exponent and mantissa bits."""
    rng = np.random.default_rng(20261123)
    x = rng.integers(0, 2**64, size=300_000, dtype=np.uint64).view(np.float64)
    x = x[np.isfinite(x)]
    # and numbers of the sizes results have
    y = rng.standard_normal(100_000) * 10.0 ** rng.integers(-12, 18, 100_000)
    for values in (x, y):
        table = Table({"x": values})
        assert polars_csv.polars_csv_text(table, False) == cells.csv_text(table, False)


# ---------------------------------------------------------------------------
# Parquet


def _typed(name, text):
    if text == "":  # undefined, text or not: a null
        return None
    if name in TEXT_COLUMNS:
        return text
    if name in ("input_row", "branch"):
        return int(text)
    return float(text)


@needs_pyarrow
def test_parquet_holds_the_csv_values_with_types(tmp_path, pure_outputs, monkeypatch):
    import pyarrow as pa
    import pyarrow.parquet as pq

    path = tmp_path / "grid.parquet"
    res = sweep("--chunk-size", "1000", *STATUS_GRIDS["wheel"], "--output", str(path), monkeypatch=monkeypatch)
    code, text = pure_outputs["wheel"]
    assert res.exit_code == code and res.stdout == ""
    rows = list(csv.reader(io.StringIO(text)))
    names, rows = rows[0], rows[1:]
    table = pq.read_table(path)
    assert table.column_names == list(COLUMNS) == names and table.num_rows == len(rows)
    meta = pq.ParquetFile(path).metadata
    assert meta.num_row_groups == math.ceil(len(rows) / 1000)  # one per chunk
    for i, name in enumerate(names):
        kind = table.schema.field(name).type
        expected = (pa.int64() if name in ("input_row", "branch") else
                    pa.string() if name in TEXT_COLUMNS else pa.float64())
        assert kind == expected, name
        values = table.column(name).to_pylist()
        assert values == [_typed(name, row[i]) for row in rows], name


@needs_pyarrow
def test_parquet_of_nothing_kept_is_an_empty_typed_file(tmp_path, monkeypatch):
    import pyarrow.parquet as pq

    path = tmp_path / "none.parquet"
    res = sweep("--theta", "0", "--alpha", "10", "--only", "ok", "--output", str(path), monkeypatch=monkeypatch)
    table = pq.read_table(path)
    assert res.exit_code == 0 and table.num_rows == 0 and table.column_names == list(COLUMNS)
    assert str(table.schema.field("theta_deg").type) == "double"


def test_parquet_without_the_extra_is_refused_before_any_work(tmp_path, monkeypatch):
    monkeypatch.setattr(parquet, "parquet_available", lambda: False)
    path = tmp_path / "grid.parquet"
    res = CliRunner().invoke(cli, ["sweep", "--theta", "0:180:1", "--alpha", "0:90:1", "--output", str(path)])
    assert res.exit_code == 2 and not path.exists()
    assert res.stderr.count("\n") == 1 and "deathsphere[fast]" in res.stderr and "pyarrow" in res.stderr


@pytest.mark.parametrize("args, message", [
    (["--format", "parquet"], "--output FILE.parquet"),
    (["--format", "csv", "--output", "x.parquet"], "does not match"),
    (["--output", "x.txt"], "must end in"),
])
def test_sweep_output_usage_errors(args, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    res = CliRunner().invoke(cli, ["sweep", "--theta", "60", "--alpha", "10", *args])
    assert res.exit_code == 2 and message in res.stderr and not os.listdir(tmp_path)


@pytest.mark.parametrize("ext", ["csv", "ndjson", "json"])
def test_sweep_output_file_holds_what_stdout_would(ext, tmp_path):
    args = ["sweep", "--theta", "0:180:30", "--alpha", "0:90:30", "--format", ext]
    path = tmp_path / f"grid.{ext}"
    to_stdout = CliRunner().invoke(cli, args)
    to_file = CliRunner().invoke(cli, [*args, "--output", str(path)])
    assert to_file.exit_code == to_stdout.exit_code == 0 and to_file.stdout == ""
    assert path.read_text(encoding="utf-8") == to_stdout.stdout


# ---------------------------------------------------------------------------
# --jobs


@pytest.mark.parametrize("extra", [[], ["--only", "ok", "--only", "slips", "--no-stability"], ["--format", "ndjson"]])
def test_sweep_jobs_gives_the_output_of_one_process(extra, pure_outputs):
    args = ["sweep", "--chunk-size", "700", *STATUS_GRIDS["wheel"], *extra]
    one = CliRunner().invoke(cli, [*args, "--jobs", "1"], catch_exceptions=False)
    two = CliRunner().invoke(cli, [*args, "--jobs", "3"], catch_exceptions=False)
    assert one.exit_code == two.exit_code == (0 if "--only" in extra else 1)  # the grid has invalid rows
    assert one.stdout == two.stdout and one.stdout.count("\n") > 100


@needs_pyarrow
def test_sweep_jobs_to_parquet_equals_one_process(tmp_path):
    import pyarrow.parquet as pq

    args = ["sweep", "--chunk-size", "500", "--theta", "0:180:5", "--alpha", "0:90:5"]
    for jobs in ("1", "2"):
        CliRunner().invoke(cli, [*args, "--jobs", jobs, "--output", str(tmp_path / f"{jobs}.parquet")],
                           catch_exceptions=False)
    assert pq.read_table(tmp_path / "1.parquet").equals(pq.read_table(tmp_path / "2.parquet"))


def test_the_file_writers_do_not_import_rich():
    """CSV and JSON output does not pay for the terminal views' rich."""
    import subprocess
    import sys

    code = ("import sys, deathsphere.writers.stream, deathsphere.writers.polars_csv, deathsphere.writers.parquet; "
            "print(sorted(m for m in sys.modules if m == 'rich' or m.startswith('rich.')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


@needs_polars
def test_compiled_writer_to_a_binary_buffer_writes_the_same_bytes(tmp_path):
    """A text file's chunks go to its binary buffer as bytes (no Python
    string per chunk): the same file as the pure-Python writer's, with an
    empty first chunk keeping its header."""
    tables = list(deathsphere.sweep("0:180:7.5", "-180:180:7.5", mu=1, a=[0.3, 4], chunk_size=1000))
    empty = tables[0][np.zeros(len(tables[0]), dtype=bool)]
    for chunks in (tables, [empty, *tables]):
        paths = []
        for compiled in (False, True):
            path = tmp_path / f"{compiled}.csv"
            with open(path, "w", encoding="utf-8", newline="") as out:
                stream.write_csv(iter(chunks), out, compiled=compiled)
            paths.append(path.read_bytes())
        assert paths[0] == paths[1] and paths[0].startswith(b"input_row,")
