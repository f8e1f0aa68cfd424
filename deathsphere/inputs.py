"""Reading orbit requests from a CSV whose header names the options.

The header (the first non-blank line) names request fields (``theta, alpha,
a, r, k, g, mu, body, side`` ...) or output column names that carry them
(``theta_deg, a_m, g_m_s2, mu_available`` ..., see :data:`ALIASES`).  Columns
the caller declares as ignored (a command's own output columns that are not
inputs, such as ``input_row, status, reason``) are read and discarded, so a
result CSV can be fed back in.  Any other column is an error: silently
ignoring it would hide a typo such as ``thetta``.

:class:`RequestReader` streams the rows in chunks and guarantees:

* every non-blank physical line after the header is exactly one row: nothing
  is dropped, merged or renumbered.  A quoted field never spans lines; a
  line ends at LF, CRLF or a lone CR (universal newlines);
* ``input_row`` is the line's position after the header (the first line
  after the header is 1).  Blank (empty or whitespace-only) lines yield no
  row but are counted, so numbers match the file.  A line of separators only
  (``,,``) is a row whose cells are all empty;
* a line that cannot be read (unclosed quote, wrong number of fields, longer
  than :data:`MAX_LINE_BYTES`, not text) and a cell that is not a number
  spoil only their own row: it comes with a one-line reason;
* the input is UTF-8 (a UTF-8 byte-order mark is dropped) or, when it starts
  with a UTF-16 byte-order mark, UTF-16 LE/BE, decoded incrementally;
* memory is bounded: the reader holds one read block and the current chunk,
  and a long line is consumed without holding more than
  :data:`MAX_LINE_BYTES` of it.

Problems with the input as a whole (cannot be opened or read, empty, bad
header) raise :class:`InputError` with a one-line message; header problems
are raised by the constructor, before any row is produced.  Range checks
(theta within 0..180 ...) are not done here: the batch validator does them.
"""

from __future__ import annotations

import codecs
import csv
import io
import math
import operator
import re
import sys
from dataclasses import dataclass
from itertools import repeat
from typing import BinaryIO, Iterable, Iterator

import numpy as np

from deathsphere.model import REQUEST_FIELDS
from deathsphere.params import CHUNK
from deathsphere.table.reasons import echo

ALIASES = {
    "theta_deg": "theta", "alpha_deg": "alpha", "a_m": "a", "r_m": "r", "g_m_s2": "g",
    "mu_available": "mu", "v_cm_m_s": "com_speed",
}
TEXT_FIELDS = ("body", "side")
#: Fields whose cells may be +-inf (every other number must be finite).
INFINITE_OK = ("mu",)

#: A longer line is consumed without being held and its row is invalid.
MAX_LINE_BYTES = 65536
#: Rows per chunk of :meth:`RequestReader.chunks`: the API's chunk.
CHUNK_ROWS = CHUNK
#: Bytes asked of the stream per read (one ``read1`` call: a pipe is not waited on to fill it).
READ_BYTES = 65536

# A line that could not be read is carried as NUL + reason: a readable line never contains NUL.
_MARK = "\x00"
_SURROGATE = re.compile("[\ud800-\udfff]")


class InputError(ValueError):
    """The input as a whole cannot be read (missing, empty, unknown column, ...).

    The message is one line."""


#: Field separators a header may use: a comma, or (a spreadsheet export where
#: the comma is the decimal mark) a semicolon, or a tab.
DELIMITERS = (",", ";", "\t")


def sniff_delimiter(header: str) -> str:
    """The separator of a CSV file from its header line: the header names
    the columns, so the separator is whichever of :data:`DELIMITERS` it
    holds (a comma when it holds several, or none: a one-column file)."""
    present = [d for d in DELIMITERS if d in header]
    return present[0] if len(present) == 1 else ","


def allowed_columns(fields=REQUEST_FIELDS, aliases=None) -> str:
    """The column names a header may use for ``fields``, comma-separated."""
    aliases = ALIASES if aliases is None else aliases
    return ", ".join(list(fields) + [a for a, f in aliases.items() if f in fields])


@dataclass
class RequestChunk:
    """Consecutive rows of a request CSV.

    ``input_row`` (int64): each row's line number after the header;
    ``values``: field -> float64 array (object array of lower-case str for
    ``body``/``side``), one entry per field, defaults where there is no
    column or the cell is empty (NaN for a field without default);
    ``invalid`` (object): why the row could not be read, '' if it was.
    """

    input_row: np.ndarray
    values: dict
    invalid: np.ndarray

    def __len__(self) -> int:
        return len(self.input_row)


def open_input(path: str) -> BinaryIO:
    """Open ``path`` for :class:`RequestReader` in binary mode; ``'-'`` is
    standard input.  Raises :class:`InputError` (one line) if it cannot."""
    if path == "-":
        stdin = sys.stdin
        if stdin is None or getattr(stdin, "closed", False):
            raise InputError("cannot read standard input: it is closed")
        return _binary(stdin)
    try:
        return open(path, "rb")  # noqa: SIM115 -- the caller closes it
    except (OSError, ValueError) as exc:
        raise InputError(f"cannot read input {path!r}: {_why(exc)}") from None


def _why(exc: BaseException) -> str:
    text = getattr(exc, "strerror", None) or str(exc) or type(exc).__name__
    return " ".join(text.split())


class _TextAsBytes(io.RawIOBase):
    """A text stream seen as UTF-8 bytes (for callers that hand over text)."""

    def __init__(self, stream):
        self._stream = stream

    def readable(self) -> bool:
        return True

    def read(self, size: int = -1) -> bytes:
        return self._stream.read(size).encode("utf-8", "surrogatepass")


def _binary(stream):
    if isinstance(stream, io.TextIOBase):
        buffer = getattr(stream, "buffer", None)
        return buffer if buffer is not None else _TextAsBytes(stream)
    return stream


class _Lines:
    """The physical lines of a byte stream, as lists of str per read block.

    A line that cannot be read is ``_MARK + reason``."""

    def __init__(self, stream, source: str):
        self.source = source
        self._read = getattr(stream, "read1", None) or stream.read
        self.encoding = "UTF-8"
        head = b""
        while len(head) < 3:
            more = self._raw()
            if not more:
                break
            head += more
        if head.startswith(codecs.BOM_UTF8):
            head = head[3:]
        elif head[:2] in (codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE):
            self.encoding = "UTF-16"
        self._head = head

    def _raw(self) -> bytes:
        try:
            data = self._read(READ_BYTES) or b""
            return data.encode("utf-8", "surrogatepass") if isinstance(data, str) else data
        except UnicodeDecodeError:  # a text stream that could not decode
            raise InputError(f"{self.source} is not UTF-8 or UTF-16 CSV text") from None
        except (OSError, ValueError) as exc:  # EIO, EISDIR, a closed stream ...
            raise InputError(f"cannot read {self.source}: {_why(exc)}") from None

    def _utf8_blocks(self) -> Iterator[bytes]:
        data = self._head or self._raw()  # the head is empty after a lone byte-order mark
        self._head = b""
        if self.encoding == "UTF-16":
            decoder = codecs.getincrementaldecoder("utf-16")("surrogatepass")
            while data:
                yield decoder.decode(data).encode("utf-8", "surrogatepass")
                data = self._raw()
            try:
                tail = decoder.decode(b"", final=True)
            except UnicodeDecodeError:  # an odd trailing byte
                tail = "\udcff"
            yield tail.encode("utf-8", "surrogatepass")
        else:
            while data:
                yield data
                data = self._raw()

    def blocks(self) -> Iterator[list[str]]:
        pending = b""     # the start of an unfinished line (at most MAX_LINE_BYTES)
        skipping = None   # reason, while consuming an overlong line
        cr = False        # a CR ended the previous block: CRLF may straddle blocks
        for data in self._utf8_blocks():
            if cr:
                data = b"\r" + data
            cr = data.endswith(b"\r")
            if cr:
                data = data[:-1]
            if b"\r" in data:
                data = data.replace(b"\r\n", b"\n").replace(b"\r", b"\n")
            last = data.rfind(b"\n")
            if last < 0:
                if skipping is None:
                    pending += data
                    if len(pending) > MAX_LINE_BYTES:
                        skipping, pending = self._overlong(pending), b""
                continue
            lines = []
            if skipping is not None:
                lines.append(_MARK + skipping)
                skipping = None
                first = data.find(b"\n")
                if first < last:
                    lines += self._decode(data[first + 1:last])
            else:
                lines += self._decode(pending + data[:last])
            pending = data[last + 1:]
            if len(pending) > MAX_LINE_BYTES:
                skipping, pending = self._overlong(pending), b""
            yield lines
        if skipping is not None:
            yield [_MARK + skipping]
        elif pending:
            yield self._decode(pending)

    @staticmethod
    def _overlong(start: bytes) -> str:
        return "line contains binary data" if b"\x00" in start else f"line longer than {MAX_LINE_BYTES} bytes"

    def _decode(self, blob: bytes) -> list[str]:
        """Lines of ``blob`` (LF-separated, no terminator at the end)."""
        text = blob.decode("utf-8", "surrogateescape")
        lines = text.split("\n")
        overlong = set()
        if len(blob) > MAX_LINE_BYTES:
            for i, line in enumerate(lines):
                if len(line) > MAX_LINE_BYTES // 4:
                    raw = line.encode("utf-8", "surrogateescape")
                    if len(raw) > MAX_LINE_BYTES:
                        lines[i] = _MARK + self._overlong(raw[:MAX_LINE_BYTES])
                        overlong.add(i)
        if _MARK in text or (not text.isascii() and _SURROGATE.search(text)):
            for i, line in enumerate(lines):
                if i in overlong:
                    continue
                if _MARK in line:
                    lines[i] = _MARK + "line contains binary data"
                elif _SURROGATE.search(line):
                    lines[i] = _MARK + f"line is not {self.encoding} text"
        return lines


def _quoting_problem(message: str) -> str:
    """A row's reason for the csv module's complaint, in words without a
    comma (its own message for text after a closing quote holds one)."""
    if "unexpected end" in message:
        return "unclosed quote"
    if "expected after" in message:
        return "bad quoting: text after a closing quote (a quoted field ends at the next separator)"
    return f"bad quoting: {echo(message)}"


class RequestReader:
    """Stream the rows of a request CSV (see the module docstring for the guarantees).

    ``fields``: name -> (default, unit, words), e.g. :data:`REQUEST_FIELDS`;
    the default is used where a field has no column or an empty cell (None
    means NaN).
    ``overrides``: field -> scalar applied to every row, over the file's
    column if it has one (an option given with ``--input``: a result CSV fed
    back with a new ``--mu`` takes that mu; such a column is not parsed).
    ``aliases``: other header names -> field (default :data:`ALIASES`).
    ``ignore``: header names read and discarded (a command's output columns);
    a name that is a field or an alias is read as that field even if listed.
    ``ignore_when``: alias -> header name: that alias is discarded instead
    when the header also holds that name (an output column whose meaning
    depends on the output it comes from).
    ``source``: the input's name in messages.

    The constructor reads up to and including the header and raises
    :class:`InputError` if the input is empty or the header is bad; rows
    come from :meth:`chunks`.  The stream is not closed.
    """

    def __init__(self, stream: BinaryIO, fields: dict, overrides: dict | None = None, *, source: str = "input",
                 aliases: dict | None = None, ignore: Iterable[str] = (), ignore_when: dict | None = None):
        self.source = source
        self.fields = dict(fields)
        self.aliases = ALIASES if aliases is None else dict(aliases)
        self._lines = _Lines(_binary(stream), source)
        self.encoding = self._lines.encoding
        self._blocks = self._lines.blocks()
        self._buf: list[str] = []
        self._pos = 0
        self._lineno = 0   # physical lines after the header consumed so far

        header = self._header_line()
        if header is None:
            raise InputError(f"{source} is empty: expected a header line naming the columns "
                             f"({allowed_columns(self.fields, self.aliases)})")
        if header.startswith(_MARK):
            if "longer than" in header:
                raise InputError(f"{source}: the header line is longer than {MAX_LINE_BYTES} bytes")
            raise InputError(f"{source} is not UTF-8 or UTF-16 CSV text")
        self.delimiter = sniff_delimiter(header)
        try:
            names = next(csv.reader((header,), strict=True, skipinitialspace=True, delimiter=self.delimiter))
        except csv.Error as exc:
            why = "an unclosed quote" if "unexpected end" in str(exc) else f"bad quoting ({exc})"
            raise InputError(f"{source}: the header line has {why}") from None
        self.header = [name.strip() for name in names]
        present = {name.lower() for name in self.header}
        for alias, marker in (ignore_when or {}).items():
            if marker.lower() in present:
                self.aliases = {a: f for a, f in self.aliases.items() if a.lower() != alias.lower()}
                ignore = [*ignore, alias]
        self.columns = self._match(self.header, ignore)
        self._overrides = {name: value for name, value in (overrides or {}).items()
                           if name in self.fields and value is not None}
        self._defaults = {name: spec[0] for name, spec in self.fields.items()}

    def _match(self, header: list[str], ignore: Iterable[str]) -> list[str | None]:
        ignored = {name.strip().lower() for name in ignore}
        fields_lower = {name.lower(): name for name in self.fields}
        aliases_lower = {a.lower(): f for a, f in self.aliases.items() if f in self.fields}
        columns: list[str | None] = []
        seen: dict[str, str] = {}
        for position, written in enumerate(header, 1):
            key = written.lower()
            field = fields_lower.get(key) or aliases_lower.get(key)
            if field is None and key in ignored:
                columns.append(None)
                continue
            if field is None:
                what = f"column {position} has no name" if not written else f"unknown column {written!r}"
                also = " (and this command's output columns, which are ignored)" if ignored else ""
                raise InputError(f"{self.source}: {what}; allowed: "
                                 f"{allowed_columns(self.fields, self.aliases)}{also}")
            if field in seen:
                both = f"{seen[field]!r}" if seen[field] == written else f"{seen[field]!r} and {written!r}"
                raise InputError(f"{self.source}: column {field!r} appears more than once ({both})")
            seen[field] = written
            columns.append(field)
        #: field -> its column's name as typed (an alias, another case): a cell's refusal names it
        self.typed = seen
        return columns

    def _header_line(self) -> str | None:
        while True:
            while self._pos < len(self._buf):
                line = self._buf[self._pos]
                self._pos += 1
                if line and not line.isspace():
                    return line
            block = next(self._blocks, None)
            if block is None:
                return None
            self._buf, self._pos = block, 0

    def chunks(self, rows: int = CHUNK_ROWS) -> Iterator[RequestChunk]:
        """The data rows, ``rows`` at a time (the last chunk may be shorter;
        no chunk is empty).  Reads the stream as it goes and holds only the
        current chunk; iterate once."""
        if rows < 1:
            raise ValueError("rows must be >= 1")
        texts: list[str] = []
        numbers: list[np.ndarray] = []
        while True:
            if self._pos >= len(self._buf):
                block = next(self._blocks, None)
                if block is None:
                    break
                self._buf, self._pos = block, 0
                continue
            part = self._buf[self._pos:self._pos + rows - len(texts)]
            self._pos += len(part)
            first = self._lineno + 1
            self._lineno += len(part)
            if "" not in part and not any(map(str.isspace, part)):
                texts += part
                numbers.append(np.arange(first, first + len(part), dtype=np.int64))
            else:
                keep = [bool(line) and not line.isspace() for line in part]
                texts += [line for line, k in zip(part, keep) if k]
                numbers.append(np.arange(first, first + len(part), dtype=np.int64)[np.array(keep, dtype=bool)])
            if len(texts) == rows:
                yield self._parse(texts, np.concatenate(numbers))
                texts, numbers = [], []
            if self._pos >= len(self._buf):
                self._buf, self._pos = [], 0  # let the block go
        if texts:
            yield self._parse(texts, np.concatenate(numbers))

    def _parse(self, texts: list[str], input_row: np.ndarray) -> RequestChunk:
        n, width = len(texts), len(self.columns)
        sep = self.delimiter
        invalid = np.full(n, "", dtype=object)
        flat_text = sep.join(texts)
        columns = None
        if '"' not in flat_text and _MARK not in flat_text:
            # fast path: no quoting, every line readable; one split if every row has `width` cells
            if list(map(str.count, texts, repeat(sep))).count(width - 1) == n:
                flat = flat_text.split(sep)
                columns = [flat[j::width] if name is not None else None for j, name in enumerate(self.columns)]
            else:
                cells = [text.split(sep) for text in texts]
        else:
            cells = self._split_quoted(texts, invalid, width, sep)
        del flat_text
        if columns is None:
            for i, row in enumerate(cells):
                if len(row) != width:
                    if not invalid[i]:
                        invalid[i] = f"row has {len(row)} fields but the header has {width}"
                    cells[i] = (row + [""] * width)[:width]
            columns = list(zip(*cells)) if n else [()] * width
            del cells
        values = {}
        for name, column in zip(self.columns, columns):
            if name is not None and name not in self._overrides:
                if sep != "," and name not in TEXT_FIELDS:
                    # a spreadsheet that separates fields with ';' writes 6,5 for 6.5
                    column = [cell.replace(",", ".") for cell in column]
                values[name] = self._convert(name, column, invalid)
        for name in self.fields:
            if name not in values:
                default = self._overrides.get(name, self._defaults[name])
                if name in TEXT_FIELDS:
                    values[name] = np.full(n, default, dtype=object)
                else:
                    values[name] = np.full(n, math.nan if default is None else float(default))
        values = {name: values[name] for name in self.fields}
        return RequestChunk(input_row=input_row, values=values, invalid=invalid)

    @staticmethod
    def _split_quoted(texts: list[str], invalid: np.ndarray, width: int, sep: str = ",") -> list[list[str]]:
        """Cells of lines some of which are quoted or unreadable; each line on its own."""
        cells: list[list[str] | None] = [None] * len(texts)
        readable = []
        for i, text in enumerate(texts):
            if text.startswith(_MARK):
                invalid[i] = text[1:]
                cells[i] = [""] * width
            else:
                readable.append(i)
        lines = [texts[i] for i in readable]
        try:  # one reader for all lines: right if it gives one row per line (no quote left open)
            rows = list(csv.reader(lines, strict=True, skipinitialspace=True, delimiter=sep))
        except csv.Error:
            rows = []
        if len(rows) == len(lines):
            for i, row in zip(readable, rows):
                cells[i] = row
            return cells
        for i, text in zip(readable, lines):
            try:
                cells[i] = next(csv.reader((text,), strict=True, skipinitialspace=True, delimiter=sep))
            except csv.Error as exc:
                invalid[i] = _quoting_problem(str(exc))
                cells[i] = [""] * width
        return cells

    def _convert(self, name: str, column, invalid: np.ndarray) -> np.ndarray:
        n = len(column)
        default = self._defaults[name]
        if name in TEXT_FIELDS:
            out = np.empty(n, dtype=object)
            out[:] = [cell.strip().lower() or default for cell in column]
            return out
        default = math.nan if default is None else float(default)
        infinite_ok = name in INFINITE_OK
        empty = None
        try:
            if "" in column:
                raise ValueError
            out = np.fromiter(map(float, column), dtype=np.float64, count=n)
        except ValueError:  # empty cells (take the default) or an unreadable one
            column = list(map(str.strip, column))
            empty = np.fromiter(map(operator.not_, column), dtype=bool, count=n)
            try:
                out = np.fromiter(map(float, [cell or "0" for cell in column]), dtype=np.float64, count=n)
            except ValueError:
                return self._convert_cells(name, column, invalid, default, infinite_ok, self.typed.get(name, name))
        bad = np.isnan(out) if infinite_ok else ~np.isfinite(out)
        if empty is not None:
            bad &= ~empty
            out[empty] = default
        if bad.any():
            for i in np.flatnonzero(bad):
                if not invalid[i]:
                    invalid[i] = f"{self.typed.get(name, name)}: {echo(column[i].strip())} is not a finite number"
            out[bad] = math.nan
        return out

    @staticmethod
    def _convert_cells(name, column, invalid, default, infinite_ok, typed) -> np.ndarray:
        """Cells one by one (some are not plain numbers): a unit suffix or a
        typographic minus is read as the command line's option reads it;
        a refusal names the column ``typed`` (as its header wrote it)."""
        from deathsphere import units
        from deathsphere.params import PARAMS

        kind = PARAMS[name].kind if name in PARAMS else "none"
        out = np.empty(len(column))
        for i, cell in enumerate(column):
            if not cell:
                out[i] = default
                continue
            try:
                number = units.parse_value(cell, kind, typed)
            except ValueError as exc:
                if not invalid[i]:
                    # a unit of the wrong kind: the units' own words; else the cell is no number
                    words = str(exc)
                    invalid[i] = (f"{typed}: {echo(cell)} is not a number" if "must be a number" in words
                                  or "takes no unit" in words or "unknown unit" in words else words)
                number = math.nan
            else:
                if math.isnan(number) or (math.isinf(number) and not infinite_ok):
                    if not invalid[i]:
                        invalid[i] = f"{typed}: {echo(cell)} is not a finite number"
                    number = math.nan
            out[i] = number
        return out
