"""A :class:`~deathsphere.table.Table` as the dataframe libraries hold it:
Arrow, polars, pandas and xarray (the optional ``dataframes`` extra:
``pip install 'deathsphere[dataframes]'``).

There is one conversion, to Arrow (:func:`arrow_table`): each column gets
the type :func:`deathsphere.table.cells.column_kind` gives it, undefined
values (NaN, None, empty text) become nulls, and the Parquet writer writes
exactly that table.  polars and pandas are built from it, so the four agree
on types and nulls by construction.  xarray has no nulls but NaN and keeps
a grid's axes, so it is built from the numpy columns (:func:`xarray_dataset`).

Each library is imported only when its export is asked for: pyarrow,
polars and pandas each take a noticeable time to import.
"""

from __future__ import annotations

import importlib

import numpy as np

from deathsphere.table.cells import (
    column_kind,
    is_undefined_text,
    one_text,
    text_cells,
    undefined_text_mask,
)

#: The extra that installs every library below.
EXTRA = "dataframes"


def require(module: str, method: str):
    """Import ``module`` for ``method`` (e.g. "Table.to_pandas"), or raise a
    one-line ImportError that names the extra to install."""
    try:
        return importlib.import_module(module)
    except ImportError:
        raise ImportError(f"{method}() needs {module}: pip install 'deathsphere[{EXTRA}]'") from None


def _arrow_types(pa) -> dict:
    return {"float": pa.float64(), "int": pa.int64(), "bool": pa.bool_(), "text": pa.string()}


def arrow_schema(table, method: str = "Table.to_arrow"):
    """The Arrow schema of a table: text columns string, whole numbers int64
    (``branch`` too, nulls where it is None), flags bool, the rest float64."""
    pa = require("pyarrow", method)
    types = _arrow_types(pa)
    return pa.schema([(n, types[column_kind(n, table.columns[n])]) for n in table.names])


def _arrow_column(pa, values: np.ndarray, kind):
    if values.dtype.kind == "O" and len(values) and one_text(values):
        # made in Arrow from one value, not converted row by row (branch None too)
        if is_undefined_text(values[0]):
            return pa.nulls(len(values), type=kind)
        if pa.types.is_string(kind):
            return pa.repeat(pa.scalar(values[0], type=kind), len(values))
    if pa.types.is_string(kind):
        if values.dtype.kind in "US" or values.dtype.kind == "O":
            try:
                return pa.array(values, type=kind, mask=undefined_text_mask(values))
            except (pa.ArrowInvalid, pa.ArrowTypeError, TypeError):
                pass  # cells that are not str (a number in a text column): written as CSV writes them
        return pa.array(text_cells(values), type=kind)
    if values.dtype.kind == "O":
        # None, and NaN in an object column of floats, are nulls (a mask,
        # not from_pandas: that imports pandas, 0.15 s, for nothing)
        items = [None if x is None or (isinstance(x, float) and x != x) else x for x in values.tolist()]
        return pa.array(items, type=kind)
    if pa.types.is_floating(kind):
        return pa.array(values, type=kind, mask=np.isnan(values))  # NaN -> null, as CSV's empty cell
    return pa.array(values, type=kind)


def arrow_table(table, schema=None, method: str = "Table.to_arrow"):
    """The table as a ``pyarrow.Table``; ``schema`` (the first chunk's, when
    chunks are joined or streamed into one file) fixes the types."""
    pa = require("pyarrow", method)
    if schema is None:
        schema = arrow_schema(table, method)
    return pa.table([_arrow_column(pa, table.columns[f.name], f.type) for f in schema], schema=schema)


def arrow_concat(tables, method: str = "Table.to_arrow"):
    """Tables with the same columns (the chunks of a stream) as one
    ``pyarrow.Table``, converted one at a time so that only Arrow's compact
    copy of the rows converted so far is held, never all of them as numpy
    and Arrow at once.  Also returns the first table (None for none), whose
    numpy types :func:`pandas_frame` needs."""
    pa = require("pyarrow", method)
    parts, first, schema = [], None, None
    for table in tables:
        if first is None:
            first, schema = table, arrow_schema(table, method)
        parts.append(arrow_table(table, schema, method))
    if not parts:
        return pa.table({}), None
    return pa.concat_tables(parts), first


def polars_frame(arrow, method: str = "Table.to_polars"):
    pl = require("polars", method)
    require("pyarrow", method)
    return pl.from_arrow(arrow)


def pandas_frame(arrow, like, method: str = "Table.to_pandas"):
    """A ``pandas.DataFrame`` from the Arrow table of ``like`` (a Table with
    the same columns): text as pandas' string dtype (``pd.NA`` for null),
    whole numbers and flags of object columns (``branch``) as the nullable
    ``Int64`` and ``boolean``; columns numpy already types as int or bool
    cannot hold a null and keep numpy's ``int64`` and ``bool``; floats stay
    float64 with NaN."""
    pd = require("pandas", method)
    require("pyarrow", method)
    import pyarrow as pa

    nullable = {pa.string(): pd.StringDtype(), pa.int64(): pd.Int64Dtype(), pa.bool_(): pd.BooleanDtype()}
    frame = arrow.to_pandas(types_mapper=nullable.get)
    exact = {} if like is None else {n: ("bool" if like.columns[n].dtype.kind == "b" else "int64")
                                      for n in like.names if like.columns[n].dtype.kind in "iub"}
    return frame.astype(exact) if exact else frame


def _varied_axes(values: np.ndarray) -> list[int]:
    """The axes a grid of values changes along."""
    axes = []
    for d in range(values.ndim):
        first = np.take(values, [0], axis=d)
        same = (values == first) | (np.isnan(values) & np.isnan(first))
        if not same.all():
            axes.append(d)
    return axes


def _varies_along(values: np.ndarray) -> int | None:
    """The one axis a grid of values changes along (None: none, or several)."""
    axes = _varied_axes(values)
    return axes[0] if len(axes) == 1 else None


#: Columns that echo a request's inputs, or the position along a requested
#: curve (``vertical``'s ``points``): the candidates for naming a grid's axis.
AXIS_COLUMNS = ("theta_deg", "alpha_deg", "a_m", "r_m", "k", "g_m_s2", "mu_available",
                "omega3_rad_s", "omega_rad_s", "v_cm_m_s", "phi_deg")


def axis_names(table) -> tuple[list[str], dict[str, int]]:
    """The dimension names of a grid table and the columns that become its
    coordinates (column -> axis): an axis along which exactly one input
    column of :data:`AXIS_COLUMNS` varies, and nothing else of them, is
    named after it, or after the input its producer names
    (:attr:`~Table.axes`) where that column varies along it alone; any
    other axis is ``dim_<i>``, and no name is given twice."""
    shape = table.shape
    named = table.axes or (None,) * len(shape)
    along: dict[int, list[str]] = {}
    for name in AXIS_COLUMNS:
        if name in table and table.columns[name].dtype.kind == "f":
            d = _varies_along(table.grid(name))
            if d is not None:
                along.setdefault(d, []).append(name)
    dims = [f"dim_{d}" for d in range(len(shape))]
    coords = {}
    for d, names in along.items():
        if len(names) == 1 and named[d] is None:
            dims[d] = names[0]
            coords[names[0]] = d
    for d, name in enumerate(named):
        # the producer's name, where its column is that axis's coordinate: it changes along that axis alone
        # (or nowhere), and names no other (an input given as a 2-D array varies along both: neither is it)
        if name is not None and name in table and name not in coords and \
                _varied_axes(table.grid(name)) in ([d], []):
            dims[d] = name
            coords[name] = d
    return dims, coords


#: Column-name endings that are units, longest first (the names' convention:
#: docs/contract.md, "units in the names").
UNIT_SUFFIXES = (("_kg_m2", "kg m^2"), ("_m_s2", "m/s^2"), ("_rad_s", "rad/s"), ("_km_h", "km/h"),
                 ("_m_s", "m/s"), ("_1_s", "1/s"), ("_deg", "deg"), ("_kg", "kg"), ("_s", "s"), ("_m", "m"),
                 ("_g", "g"))


def column_unit(name: str) -> str:
    """The unit a column's name ends with; ``"1"`` (dimensionless, as CF
    and pint write it) for a plain number (``mu_required``, ``k``)."""
    for suffix, unit in UNIT_SUFFIXES:
        if name.endswith(suffix) and len(name) > len(suffix):
            return unit
    return "1"


def _xarray_values(name: str, values: np.ndarray) -> np.ndarray:
    """A column as xarray holds it: numbers as numpy (a nullable integer
    column as float64 with NaN, xarray's only missing value), text and
    flags as objects with None for undefined."""
    kind = column_kind(name, values)
    if values.dtype.kind in "fiub":
        return values
    if kind in ("int", "float"):
        return np.array([np.nan if v is None else v for v in values.tolist()], dtype=np.float64)
    if kind == "bool":
        return values
    return np.array(text_cells(values), dtype=object)


def xarray_dataset(table, method: str = "Table.to_xarray"):
    """An ``xarray.Dataset``: a grid (a :attr:`~Table.shape` of more than one
    axis) keeps its axes as dimensions, named and given coordinates by
    :func:`axis_names`; any other table has one dimension, ``row``."""
    xr = require("xarray", method)
    shape = table.shape
    if len(shape) < 2:
        dims, coords = ["row"], {}
        shape = (len(table),)
    else:
        dims, coords = axis_names(table)
    data_vars, coord_vars = {}, {}
    for name in table.names:
        values = _xarray_values(name, table.columns[name])
        attrs = {"units": column_unit(name)} if values.dtype.kind in "fiu" else {}
        if name in coords:
            d = coords[name]
            index = tuple(slice(None) if i == d else 0 for i in range(len(shape)))
            coord_vars[name] = (name, values.reshape(shape)[index].copy(), attrs)
        else:
            # a copy: the dataset is the caller's to change, the table's columns are not
            data_vars[name] = (dims, values.reshape(shape).copy(), attrs)
    return xr.Dataset(data_vars, coords=coord_vars)
