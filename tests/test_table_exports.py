"""A Table in the dataframe libraries (pandas, polars, pyarrow, xarray: the
test extra installs them), nulls for undefined text in every output but
CSV, scalar columns for one request, and read-only columns."""

import csv
import io
import json
import pickle
import sys

import numpy as np
import pandas as pd
import polars as pl
import pyarrow as pa
import pyarrow.parquet as pq
import pytest
import xarray as xr
from click.testing import CliRunner

import deathsphere
from deathsphere.api import Chunks
from deathsphere.cli import cli
from deathsphere.model import COLUMNS, TEXT_COLUMNS
from deathsphere.table import Table
from deathsphere.writers.parquet import write_parquet
from deathsphere.writers.stream import write_json, write_ndjson

THETA = np.arange(0, 181, 30.0)[:, None]
ALPHA = [5.0, 30.0, 80.0]
STATUSES = {"ok", "slips", "no_contact", "no_orbit", "no_fit", "invalid"}


@pytest.fixture(scope="module")
def grid():
    return deathsphere.orbit(THETA, ALPHA, mu=1)


@pytest.fixture(scope="module")
def table(grid):
    """Every status; ``branch`` ints (the sphere's roots) and None (wheels)."""
    sphere = deathsphere.orbit(60, body="sphere", omega3=[80, 30], mu=1)
    bad = deathsphere.orbit([60, 60], 10, a=[0.3, 5.0])  # r <= a: invalid
    t = Table.concat([grid, sphere, bad])
    assert set(t["status"].tolist()) == STATUSES
    assert {type(b) for b in t["branch"].tolist()} == {int, type(None)}
    return t


def csv_empty(table):
    """Column -> which of its cells CSV leaves empty."""
    rows = list(csv.reader(io.StringIO(table.to_csv())))
    return {name: [row[j] == "" for row in rows[1:]] for j, name in enumerate(rows[0])}


def expected_type(name):
    return "int" if name in ("input_row", "branch") else "text" if name in TEXT_COLUMNS else "float"


def test_arrow_types_nulls_and_values(table):
    arrow = table.to_arrow()
    assert isinstance(arrow, pa.Table) and arrow.column_names == table.names == list(COLUMNS)
    kinds = {"int": pa.int64(), "text": pa.string(), "float": pa.float64()}
    empty = csv_empty(table)
    rows = table.to_dicts()
    for name in table.names:
        assert arrow.schema.field(name).type == kinds[expected_type(name)], name
        values = arrow.column(name).to_pylist()
        assert [v is None for v in values] == empty[name], name
        assert values == [row[name] for row in rows], name
    # the undefined text of ok rows (reason) and of rows not analysed (stability) is null
    assert arrow.column("reason").null_count == table["status"].tolist().count("ok")
    assert 0 < arrow.column("stability").null_count < len(table)


def test_polars_from_the_same_arrow_table(table):
    frame = table.to_polars()
    assert isinstance(frame, pl.DataFrame) and frame.columns == table.names
    kinds = {"int": pl.Int64, "text": pl.String, "float": pl.Float64}
    assert frame.dtypes == [kinds[expected_type(n)] for n in table.names]
    empty = csv_empty(table)
    assert {n: frame[n].is_null().to_list() for n in table.names} == empty
    assert frame.to_dicts() == table.to_dicts()


def test_pandas_types_and_nulls(table):
    frame = table.to_pandas()
    assert isinstance(frame, pd.DataFrame) and list(frame.columns) == table.names
    for name in table.names:
        dtype = frame[name].dtype
        if name == "branch":
            assert dtype == pd.Int64Dtype()
        elif name == "input_row":
            assert dtype == np.int64
        elif name in TEXT_COLUMNS:
            assert dtype == pd.StringDtype()
        else:
            assert dtype == np.float64, name
    assert {n: frame[n].isna().tolist() for n in table.names} == csv_empty(table)
    for name in table.names:
        col = table.columns[name]
        if col.dtype == np.float64:
            np.testing.assert_array_equal(frame[name].to_numpy(), col)
        else:
            assert [None if v is pd.NA else v for v in frame[name].tolist()] == [r[name] for r in table], name
    # an export is the caller's: changing it leaves the table as computed
    frame.loc[0, "v_cm_m_s"] = -1.0
    assert table["v_cm_m_s"][0] != -1.0


def test_xarray_keeps_the_grid_axes_as_named_dimensions(grid):
    ds = grid.to_xarray()
    assert isinstance(ds, xr.Dataset)
    assert dict(ds.sizes) == {"theta_deg": 7, "alpha_deg": 3}
    assert ds["theta_deg"].values.tolist() == THETA[:, 0].tolist() and ds["alpha_deg"].values.tolist() == ALPHA
    assert set(ds.coords) == {"theta_deg", "alpha_deg"}
    assert list(ds.data_vars) == [n for n in grid.names if n not in ("theta_deg", "alpha_deg")]
    assert ds["v_cm_m_s"].dims == ("theta_deg", "alpha_deg")
    np.testing.assert_array_equal(ds["v_cm_m_s"].values, grid.grid("v_cm_m_s"))
    assert ds["status"].values.tolist() == grid.grid("status").tolist()
    # undefined text is xarray's missing value, as a float's NaN is
    assert ds["reason"].isnull().values.tolist() == (grid.grid("reason") == "").tolist()
    assert ds["branch"].dtype == np.float64 and bool(ds["branch"].isnull().all())
    one = ds.sel(theta_deg=60.0, alpha_deg=30.0)
    assert float(one["v_cm_m_s"]) == float(deathsphere.orbit(60, 30, mu=1)["v_cm_m_s"])


def test_xarray_names_an_ambiguous_axis_dim_and_a_flat_table_row(table):
    # theta and r both change along the first axis: which names it is not clear
    ds = deathsphere.orbit([[60.0], [90.0]], [5.0, 10.0], r=[[3.0], [4.0]], stability=False).to_xarray()
    assert ds["v_cm_m_s"].dims == ("dim_0", "alpha_deg")
    flat = table.to_xarray()
    assert dict(flat.sizes) == {"row": len(table)} and not flat.coords
    assert flat["branch"].values[-6:-2].tolist() == [0.0, 1.0, 0.0, 1.0]


def test_an_input_given_as_a_2d_array_names_no_axis():
    """A producer names each axis after the one input along it (Table.axes);
    an input that varies along both axes of a 2-D array is neither's
    coordinate: the dimensions stay distinct, dim_0 and dim_1."""
    height = np.array([[1.0, 1.5], [2.0, 2.5]])
    t = Table({"height_m": height.reshape(-1), "x": np.arange(4.0)}, shape=(2, 2), axes=("height_m", "height_m"))
    ds = t.to_xarray()
    assert ds["x"].dims == ("dim_0", "dim_1") and not ds.coords
    np.testing.assert_array_equal(ds["height_m"].values, height)
    # along one axis alone it is that axis's coordinate, once
    rows = Table({"height_m": np.repeat([1.0, 2.0], 2), "x": np.arange(4.0)}, shape=(2, 2),
                 axes=("height_m", None))
    assert rows.to_xarray()["x"].dims == ("height_m", "dim_1")


def test_vertical_points_axis_is_named_after_phi():
    ds = deathsphere.vertical(90, [6, 7], points=5).to_xarray()
    # the speed changes around the loop: no input column follows the first axis alone
    assert dict(ds.sizes) == {"dim_0": 2, "phi_deg": 5}
    assert ds["phi_deg"].values.tolist() == [0.0, 90.0, 180.0, 270.0, 360.0]


def test_mixed_object_columns_export():
    """The stability comparison's object columns hold text, numbers and None
    together; each gets one type (text as CSV writes it)."""
    t = deathsphere.stability(60, 10)
    frame = t.to_polars()
    assert frame["applies"].dtype == pl.Boolean and frame["validity"].dtype == pl.Float64
    assert frame["exact"].dtype == pl.String and frame["units"].null_count() > 0
    assert frame["exact"].to_list() == [None if c == "" else c for c in csv_empty_text(t, "exact")]


def csv_empty_text(table, name):
    rows = list(csv.reader(io.StringIO(table.to_csv())))
    j = rows[0].index(name)
    return [row[j] for row in rows[1:]]


def test_chunks_concatenate_through_arrow(table):
    # a first chunk without a branch must not make branch text for the rest
    wheels, spheres = table[table["body"] == "wheel"], table[table["body"] == "sphere"]
    assert all(b is None for b in wheels["branch"].tolist())

    def chunks():
        return Chunks(iter([(len(wheels), wheels), (len(spheres), spheres)]))

    whole = Table.concat([wheels, spheres])
    assert chunks().to_arrow().equals(whole.to_arrow())
    assert chunks().to_polars().equals(whole.to_polars())
    frame = chunks().to_pandas()
    pd.testing.assert_frame_equal(frame, whole.to_pandas())
    assert frame["branch"].dtype == pd.Int64Dtype() and frame["branch"].notna().sum() == len(spheres)
    swept = deathsphere.sweep("10:170:40", "5:85:40", chunk_size=4, stability=False)
    assert swept.to_polars().equals(deathsphere.sweep("10:170:40", "5:85:40", stability=False).table().to_polars())


@pytest.mark.parametrize("module, call", [
    ("pandas", lambda t: t.to_pandas()),
    ("polars", lambda t: t.to_polars()),
    ("pyarrow", lambda t: t.to_arrow()),
    ("pyarrow", lambda t: t.to_polars()),
    ("xarray", lambda t: t.to_xarray()),
    ("polars", lambda t: Chunks(iter([(len(t), t)])).to_polars()),
])
def test_a_missing_library_names_the_extra(grid, module, call, monkeypatch):
    monkeypatch.setitem(sys.modules, module, None)  # "import <module>" now fails
    with pytest.raises(ImportError) as err:
        call(grid)
    message = str(err.value)
    assert "\n" not in message and f"needs {module}: pip install 'deathsphere[dataframes]'" in message


# ---------------------------------------------------------------------------
# empty text is null, except in CSV


def test_json_ndjson_parquet_and_dicts_give_null_for_empty_text(table, tmp_path):
    dicts = table.to_dicts()
    ok = [i for i, s in enumerate(table["status"].tolist()) if s == "ok"]
    assert ok and all(dicts[i]["reason"] is None for i in ok)
    assert table[ok[0]] == dicts[ok[0]] and list(table)[ok[0]] == dicts[ok[0]]
    out = io.StringIO()
    write_json([table], out)
    assert json.loads(out.getvalue()) == dicts
    out = io.StringIO()
    write_ndjson([table], out)
    assert [json.loads(line) for line in out.getvalue().splitlines()] == dicts
    path = tmp_path / "t.parquet"
    write_parquet([table[:5], table[5:]], str(path))
    assert pq.read_table(path).equals(table.to_arrow())


@pytest.mark.parametrize("extra, column", [([], "reason"), (["--no-stability"], "stability")])
def test_the_command_line_writes_null(extra, column):
    res = CliRunner().invoke(cli, ["orbit", "--theta", "60", "--alpha", "10", "--format", "json", *extra])
    (row,) = json.loads(res.stdout)
    assert res.exit_code == 0 and row["status"] == "ok" and row[column] is None
    csv_text = CliRunner().invoke(cli, ["orbit", "--theta", "60", "--alpha", "10", *extra, "--format", "csv"]).stdout
    assert csv_text.splitlines()[1].split(",")[COLUMNS.index(column)] == ""


def test_csv_writes_none_and_empty_text_alike():
    t = Table({"s": np.array(["a", "", None], dtype=object), "x": np.array([1.0, np.nan, 2.0])})
    assert t.to_csv() == "s,x\na,1.0\n,\n,2.0\n"
    assert [row["s"] for row in t] == ["a", None, None]
    assert t.to_arrow().column("s").to_pylist() == ["a", None, None]


# ---------------------------------------------------------------------------
# scalar columns, read-only columns


def test_one_request_gives_scalar_columns(grid):
    t = deathsphere.orbit(60, 10)
    assert t.shape == () and len(t) == 1
    v = t["v_cm_m_s"]
    assert v.shape == () and float(v) == t[0]["v_cm_m_s"] == t.columns["v_cm_m_s"][0]
    status = t["status"]
    assert status.shape == () and str(status) == "ok" and status == "ok"
    assert t[t["status"] == "ok"].to_csv() == t.to_csv()
    # a grid's columns stay flat (one value per row); grid() gives the shape
    assert grid["v_cm_m_s"].shape == (len(grid),) and grid.grid("v_cm_m_s").shape == (7, 3)
    assert len(grid[grid.grid("status") == "ok"]) == grid["status"].tolist().count("ok")


def test_columns_are_read_only(grid):
    csv_before = grid.to_csv()
    v = grid["v_cm_m_s"]
    with pytest.raises(ValueError, match="read-only"):
        v *= 3.6
    for column in (grid["status"], grid.grid("v_cm_m_s"), grid.columns["branch"], grid[2:4]["theta_deg"],
                   deathsphere.orbit(60, 10)["v_cm_m_s"]):
        with pytest.raises(ValueError, match="read-only"):
            column[...] = column.copy()
    assert grid.to_csv() == csv_before
    # a copy is the caller's to change
    speed = grid["v_cm_m_s"].copy()
    speed *= 3.6
    assert np.array_equal(speed, grid["v_cm_m_s"] * 3.6, equal_nan=True)


def test_a_table_from_another_process_stays_read_only(grid):
    """--jobs hands tables back pickled, and unpickled arrays are writable."""
    back = pickle.loads(pickle.dumps(grid))
    assert back.to_csv() == grid.to_csv() and back.shape == grid.shape
    assert not any(col.flags.writeable for col in back.columns.values())


def test_a_table_freezes_the_arrays_it_is_given():
    x = np.arange(3.0)
    t = Table({"x": x})
    with pytest.raises(ValueError, match="read-only"):
        x[0] = 9.0
    assert t["x"].tolist() == [0.0, 1.0, 2.0]
    joined = Table.concat([t, t])
    assert not joined["x"].flags.writeable and joined["x"].tolist() == [0.0, 1.0, 2.0] * 2
