"""The result type: ordered named columns of equal length (:class:`Table`).

Every command's result is a Table; its columns are the contract's
(docs/contract.md).  This module is a leaf of the package: it imports only
numpy and the cell formatting of :mod:`deathsphere.table.cells`, so every
layer (physics results, the API, the writers, the views) may use it.
"""

from __future__ import annotations

import math

import numpy as np

from deathsphere.table.cells import cell_value, csv_text, python_values
from deathsphere.table.frames import (
    arrow_table,
    pandas_frame,
    polars_frame,
    require,
    xarray_dataset,
)
from deathsphere.table.reasons import reason_column

#: Text columns that pass the gate of :func:`reason_column`: the reasons, and
#: the texts a row echoes as its request gave them (an ``--input`` cell).
ECHOED_TEXT = frozenset({"reason", "body", "side", "machine"})


class Table:
    """Ordered named columns of equal-length arrays (the result type).

    ``table["v_cm_m_s"]`` is a column: a flat float64 array, one value per
    row, except for a table of one request (:attr:`shape` ``()``, e.g.
    ``orbit(60, 10)``), whose columns are 0-d arrays (``float(t["v_cm_m_s"])``
    works); ``table.names`` the column order; ``len(table)`` the number of
    rows.  Undefined values are NaN in float columns and "" or None in text
    columns: empty in CSV, null in JSON, Parquet and the dataframe exports,
    None in row dicts.  The columns are read-only: the table is a result,
    and its CSV, views and exports always show what was computed (the
    arrays handed to the constructor are taken as they are, not copied, and
    made read-only).

    ``table[i]`` (an int) is row i as a dict, like ``for row in table``
    and :meth:`to_dicts`; a slice, boolean mask or integer array selects
    rows and gives a flat :class:`Table`.  :attr:`shape` is the shape of the
    input the rows came from (the broadcast shape of the arguments of
    :func:`deathsphere.orbit`, else ``(len(table),)``); :meth:`grid` gives a
    column in that shape.  :meth:`to_arrow`, :meth:`to_polars`,
    :meth:`to_pandas` and :meth:`to_xarray` hand the table to the
    dataframe libraries (the ``dataframes`` extra).

    Examples
    --------
    >>> t = Table({"x": np.array([1.0, 2.0, np.nan, 4.0]), "s": np.array(["a", "b", "c", ""], dtype=object)},
    ...           shape=(2, 2))
    >>> t[2], t[3]
    ({'x': None, 's': 'c'}, {'x': 4.0, 's': None})
    >>> [row["s"] for row in t]
    ['a', 'b', 'c', None]
    >>> t.grid("x")
    array([[ 1.,  2.],
           [nan,  4.]])
    >>> print(t.to_csv(), end="")
    x,s
    1.0,a
    2.0,b
    ,c
    4.0,
    >>> t["x"][0] = 5.0
    Traceback (most recent call last):
    ...
    ValueError: assignment destination is read-only
    """

    #: Rows shown by ``repr`` (a notebook cell) and ``_repr_html_``.
    REPR_ROWS = 5

    def __init__(self, columns: dict[str, np.ndarray], shape: tuple[int, ...] | None = None,
                 axes: tuple[str | None, ...] | None = None):
        columns = {name: np.asarray(col) for name, col in columns.items()}
        lengths = {len(v) for v in columns.values()}
        if len(lengths) > 1:
            raise ValueError(f"columns of unequal length: {lengths}")
        for col in columns.values():
            col.flags.writeable = False
        for name in ECHOED_TEXT.intersection(columns):
            # the one gate of every reason and every text a row echoes from
            # its request (docs/contract.md: no comma, no line break)
            columns[name] = reason_column(columns[name])
            columns[name].flags.writeable = False
        self.columns = columns
        n = len(self)
        shape = (n,) if shape is None else tuple(int(s) for s in shape)
        if math.prod(shape) != n:
            raise ValueError(f"shape {shape} does not hold {n} rows")
        self._shape = shape
        # the input column along each axis, where the producer knows it (a
        # column derived from an input varies along the same axis)
        self._axes = tuple(axes) if axes is not None and len(axes) == len(shape) else None

    @property
    def axes(self) -> tuple[str | None, ...] | None:
        """The input column given along each axis of :attr:`shape` (None
        where the producer did not say): the names :meth:`to_xarray` gives
        the dimensions."""
        return getattr(self, "_axes", None)

    def __setstate__(self, state: dict) -> None:
        # unpickled arrays (a table back from a --jobs worker) are writable again
        self.__dict__.update(state)
        for col in self.columns.values():
            col.flags.writeable = False

    @classmethod
    def concat(cls, tables) -> Table:
        """Tables with the same columns, one after another (e.g. the chunks
        of a streamed result); a single table is returned as it is."""
        tables = list(tables)
        if len(tables) == 1:
            return tables[0]
        if not tables:
            return cls({})
        return cls({n: np.concatenate([t.columns[n] for t in tables]) for n in tables[0].names})

    @property
    def names(self) -> list[str]:
        return list(self.columns)

    @property
    def shape(self) -> tuple[int, ...]:
        """The shape the rows fill, row-major (``len(table) == prod(shape)``)."""
        return self._shape

    def __len__(self) -> int:
        return len(next(iter(self.columns.values()))) if self.columns else 0

    def __getitem__(self, key):
        """A column by name (0-d when :attr:`shape` is ``()``, else flat), a
        row dict by int index, a flat Table by slice or mask (a mask may also
        have the table's shape, as ``table.grid(name) == value`` has)."""
        if isinstance(key, str):
            col = self.columns[key]
            # one request, one value: a scalar-like column, as numpy gives for
            # a 0-d input (float() of a 1-element array fails in numpy 2)
            return col.reshape(()) if self._shape == () else col
        if isinstance(key, (int, np.integer)) and not isinstance(key, bool):
            n = len(self)
            i = int(key) + n if key < 0 else int(key)
            if not 0 <= i < n:
                raise IndexError(f"row {int(key)} of a table of {n} rows")
            return {name: cell_value(col[i]) for name, col in self.columns.items()}
        if isinstance(key, (bool, np.bool_)) and self._shape == ():
            key = np.array(key)  # the mask of a scalar table (t["status"] == "ok" is one bool)
        if isinstance(key, slice) or isinstance(key, (list, np.ndarray)):
            if isinstance(key, np.ndarray) and key.dtype == bool and key.shape == self._shape:
                key = key.reshape(-1)
            return Table({name: col[key] for name, col in self.columns.items()})
        raise TypeError(f"a Table is indexed by a column name, a row number, a slice or a mask (got {key!r})")

    def __contains__(self, name: str) -> bool:
        return name in self.columns

    def __iter__(self):
        """Rows as dicts, in order (NaN and empty text -> None)."""
        cols = [(n, python_values(c)) for n, c in self.columns.items()]
        for i in range(len(self)):
            yield {n: v[i] for n, v in cols}

    def grid(self, name: str) -> np.ndarray:
        """Column ``name`` reshaped to :attr:`shape` (e.g. theta x alpha)."""
        return self.columns[name].reshape(self._shape)

    def to_dicts(self) -> list[dict]:
        """Rows as dicts (NaN and empty text -> None), for notebooks and JSON."""
        return list(self)

    def records(self) -> list[dict]:
        """The same as :meth:`to_dicts` (the older name)."""
        return self.to_dicts()

    def to_csv(self, path_or_buf=None) -> str | None:
        """The table as the command line writes it with ``--format csv`` (the
        same bytes).  Returns the text when ``path_or_buf`` is None; else
        writes it to that path or open text file and returns None."""
        text = csv_text(self, header=True)
        if path_or_buf is None:
            return text
        if hasattr(path_or_buf, "write"):
            path_or_buf.write(text)
        else:
            from deathsphere.writers.atomic import atomic_file

            # newline="": the CLI's line ends, whatever the platform; the
            # file appears only when complete, as every file written here
            with atomic_file(path_or_buf, "w", encoding="utf-8", newline="") as out:
                out.write(text)
        return None

    def to_arrow(self):
        """A ``pyarrow.Table``: the columns in order, text as string, whole
        numbers (``input_row``, ``branch``) int64, the rest float64, and
        every undefined value (NaN, empty text, None) a null.  The Parquet
        output (``--output F.parquet``) is this table, chunk by chunk."""
        return arrow_table(self, method="Table.to_arrow")

    def to_polars(self):
        """A ``polars.DataFrame`` (through :meth:`to_arrow`: the same types
        and nulls)."""
        require("polars", "Table.to_polars")
        return polars_frame(arrow_table(self, method="Table.to_polars"))

    def to_pandas(self):
        """A ``pandas.DataFrame`` (through :meth:`to_arrow`): text columns
        of pandas' ``string`` dtype (``pd.NA`` where undefined), ``branch``
        nullable ``Int64``, floats float64 with NaN."""
        require("pandas", "Table.to_pandas")
        return pandas_frame(arrow_table(self, method="Table.to_pandas"), self)

    def to_xarray(self):
        """An ``xarray.Dataset``.  A grid (:attr:`shape` of two axes or more)
        keeps its axes as dimensions, each named after the one input column
        that varies along it (``theta_deg``, ``alpha_deg``, ...) or after
        the input its producer names (:attr:`axes`), which becomes its
        coordinate, else ``dim_0``, ``dim_1``, ...; any other table has one
        dimension, ``row``.  Text is object (None where undefined),
        ``branch`` float64 (NaN where undefined); a number's variable has
        its unit, read off its name, in the attribute ``units`` (``"m/s"``
        for ``v_cm_m_s``, ``"1"`` for a plain number)."""
        return xarray_dataset(self)

    def _summary_line(self) -> str:
        shape = "" if self._shape == (len(self),) else f", shape {self._shape}"
        return f"Table: {len(self)} rows x {len(self.columns)} columns{shape}"

    def _head_cells(self) -> tuple[list[str], list[list[str]], int]:
        """Header names, the first rows' cells as text, and the row count shown."""
        shown = min(len(self), self.REPR_ROWS)
        head = self[:shown] if shown < len(self) else self
        return self.names, [[_cell_text(v) for v in row.values()] for row in head], shown

    def __repr__(self) -> str:
        """A text table of the first rows: one line per row, or, for a table
        wider than :data:`_REPR_WIDE` columns, one line per column (rows
        across), which stays readable in a notebook or a terminal."""
        names, rows, shown = self._head_cells()
        lines = [self._summary_line()]
        if len(names) > _REPR_WIDE:
            grid = [[name] + [row[j] for row in rows] for j, name in enumerate(names)]
        else:
            grid = [names] + rows
        if grid and grid[0]:
            widths = [max(len(r[j]) for r in grid) for j in range(len(grid[0]))]
            lines += ["  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in grid]
        if shown < len(self):
            lines.append(f"... ({len(self) - shown} more row{'' if len(self) - shown == 1 else 's'})")
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        """An HTML table of the first rows, for Jupyter."""
        from html import escape

        names, rows, shown = self._head_cells()
        head = "".join(f"<th>{escape(n)}</th>" for n in names)
        body = "".join("<tr>" + "".join(f"<td>{escape(c)}</td>" for c in row) + "</tr>" for row in rows)
        more = f"<p>... {len(self) - shown} more rows</p>" if shown < len(self) else ""
        return (f"<p>{escape(self._summary_line())}</p><table><thead><tr>{head}</tr></thead>"
                f"<tbody>{body}</tbody></table>{more}")


#: Tables wider than this show one line per column in ``repr``.
_REPR_WIDE = 8
#: Text cells longer than this are cut in ``repr``.
_REPR_TEXT = 40


def _cell_text(v) -> str:
    if v is None:
        return ""
    if isinstance(v, float):
        return f"{v:.6g}"
    text = str(v)
    return text if len(text) <= _REPR_TEXT else text[: _REPR_TEXT - 3] + "..."

