"""The request CSV reader: one row per non-blank physical line, numbering,
encodings, streaming, and input errors that are one line, not tracebacks."""

import csv
import io
import math
import os
import re
import subprocess
import sys
import tracemalloc

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from deathsphere.inputs import (
    ALIASES,
    MAX_LINE_BYTES,
    InputError,
    RequestChunk,
    RequestReader,
    allowed_columns,
    open_input,
)
from deathsphere.model import COLUMNS, REQUEST_FIELDS

FIELDS = REQUEST_FIELDS


class Trickle:
    """A binary stream that hands out at most ``size`` bytes per read."""

    def __init__(self, data: bytes, size: int):
        self.data, self.size, self.pos = data, size, 0

    def read(self, n=-1):
        n = self.size if n is None or n < 0 else min(n, self.size)
        piece = self.data[self.pos:self.pos + n]
        self.pos += len(piece)
        return piece


def reader(data, defaults=None, fields=FIELDS, size=None, **kw):
    if isinstance(data, str):
        data = data.encode()
    stream = io.BytesIO(data) if size is None else Trickle(data, size)
    return RequestReader(stream, fields, {} if defaults is None else defaults, **kw)


def rows(data, defaults=None, fields=FIELDS, chunk=16384, size=None, **kw):
    """All chunks joined: (input_row list, values dict of lists, invalid list)."""
    chunks = list(reader(data, defaults, fields, size, **kw).chunks(chunk))
    assert all(isinstance(c, RequestChunk) and len(c) > 0 for c in chunks)
    numbers = [int(x) for c in chunks for x in c.input_row]
    values = {name: [v for c in chunks for v in c.values[name]] for name in fields}
    invalid = [r for c in chunks for r in c.invalid]
    return numbers, values, invalid


def same(a, b):
    return all((isinstance(x, float) and math.isnan(x) and math.isnan(y)) or x == y for x, y in zip(a, b)) \
        and len(a) == len(b)


# ---------------------------------------------------------------- encodings

@pytest.mark.parametrize("prefix", [b"", b"\xef\xbb\xbf"])
def test_utf8_with_or_without_byte_order_mark(prefix):
    numbers, values, invalid = rows(prefix + b"theta,alpha\n60,10\n")
    assert numbers == [1] and values["theta"] == [60.0] and values["alpha"] == [10.0] and invalid == [""]


@pytest.mark.parametrize("codec", ["utf-16", "utf-16-le", "utf-16-be"])
@pytest.mark.parametrize("size", [None, 1, 3])
def test_utf16_with_byte_order_mark(codec, size):
    text = "Theta,Body\r\n60,Sph\u00e8re\r\n\r\n70,\U0001d703\r\n80,wheel"
    bom = {"utf-16": "", "utf-16-le": "\ufeff", "utf-16-be": "\ufeff"}[codec]
    data = (bom + text).encode(codec)
    assert data[:2] in (b"\xff\xfe", b"\xfe\xff")
    r = reader(data, size=size)
    assert r.encoding == "UTF-16"
    numbers, values, invalid = rows(data, size=size)
    assert numbers == [1, 3, 4]
    assert values["theta"] == [60.0, 70.0, 80.0]
    assert values["body"] == ["sph\u00e8re", "\U0001d703", "wheel"]
    assert invalid == ["", "", ""]


def test_utf16_bad_data_spoils_only_its_line():
    data = "theta\n60\n".encode("utf-16") + b"\x00\xd8" + "\n70\n".encode("utf-16-le") + b"7"
    numbers, values, invalid = rows(data)
    assert numbers == [1, 2, 3, 4]
    assert invalid[0] == "" and invalid[2] == "" and values["theta"][2] == 70.0
    assert invalid[1] == "line is not UTF-16 text"   # a lone surrogate
    assert invalid[3] == "line is not UTF-16 text"   # an odd trailing byte


def test_utf16_without_byte_order_mark_is_not_text():
    with pytest.raises(InputError, match="not UTF-8 or UTF-16 CSV text"):
        reader("theta\n60\n".encode("utf-16-le"))


# ---------------------------------------------------------------- lines and numbering

@pytest.mark.parametrize("newline", ["\n", "\r\n", "\r"])
@pytest.mark.parametrize("size", [None, 1, 2])
def test_line_endings(newline, size):
    data = newline.join(["theta,alpha", "60,10", "", "70,20", "80,30"]) + newline
    numbers, values, invalid = rows(data, size=size)
    assert numbers == [1, 3, 4] and values["theta"] == [60.0, 70.0, 80.0] and invalid == ["", "", ""]


def test_no_row_for_the_trailing_newline_and_last_line_without_one():
    assert rows("theta\n60\n")[0] == [1]
    assert rows("theta\n60\n70")[0] == [1, 2]
    assert rows("theta\n60\r\n70\r")[0] == [1, 2]


def test_a_row_of_separators_is_a_row_and_keeps_the_numbering():
    numbers, values, invalid = rows("theta,alpha\n60,10\n,\n70,20\n")
    assert numbers == [1, 2, 3]
    assert same(values["theta"], [60.0, math.nan, 70.0]) and same(values["alpha"], [10.0, math.nan, 20.0])
    assert invalid == ["", "", ""]  # theta missing is for the validator to say


def test_blank_lines_yield_no_row_but_are_counted():
    numbers, values, _ = rows("\n  \ntheta\n\n60\n  \n\t\n70\n\n\n")
    assert numbers == [2, 5] and values["theta"] == [60.0, 70.0]


def test_unclosed_quote_spoils_only_its_row():
    numbers, values, invalid = rows('theta,alpha\n60,"10\n70,20\n"80", "30"\n90,"40"x\n')
    assert numbers == [1, 2, 3, 4]
    # reasons hold no comma (docs/contract.md): not the csv module's own words
    assert invalid == ["unclosed quote", "", "", "bad quoting: text after a closing quote (a quoted field ends at the next separator)"]
    assert values["theta"][1:3] == [70.0, 80.0] and values["alpha"][1:3] == [20.0, 30.0]


def test_quoted_cells_and_a_comma_inside_quotes():
    numbers, values, invalid = rows('"theta","body"\n"60","Wheel"\n70,"sphere, spun"\n')
    assert numbers == [1, 2] and values["theta"] == [60.0, 70.0]
    assert values["body"] == ["wheel", "sphere, spun"] and invalid == ["", ""]


def test_wrong_field_counts_spoil_only_their_rows():
    numbers, values, invalid = rows("theta,alpha\n60\n70,20\n80,30,40\n90,\n")
    assert numbers == [1, 2, 3, 4]
    assert invalid == ["row has 1 fields but the header has 2", "",
                       "row has 3 fields but the header has 2", ""]
    assert values["theta"] == [60.0, 70.0, 80.0, 90.0]


def test_chunks_of_a_given_size_keep_the_numbering():
    data = "theta\n" + "".join(f"{i}\n" if i % 4 else "\n" for i in range(1, 21))
    chunks = list(reader(data).chunks(3))
    assert [len(c) for c in chunks] == [3, 3, 3, 3, 3]
    numbers = np.concatenate([c.input_row for c in chunks])
    assert numbers.dtype == np.int64 and numbers.tolist() == [i for i in range(1, 21) if i % 4]
    assert np.concatenate([c.values["theta"] for c in chunks]).tolist() == [float(i) for i in numbers]


def test_header_only_gives_no_chunks():
    assert list(reader("theta,alpha\n").chunks()) == []


# ---------------------------------------------------------------- lines that cannot be read

def test_a_huge_line_spoils_only_its_row():
    numbers, values, invalid = rows(b"theta,alpha\n60,10\n" + b"7" * 200_000 + b",1\n80,30\n")
    assert numbers == [1, 2, 3] and invalid == ["", f"line longer than {MAX_LINE_BYTES} bytes", ""]
    assert values["theta"][2] == 80.0
    # the csv module's field limit (128 KiB) is never reached either
    numbers, _, invalid = rows(b'theta\n"' + b"7" * 140_000 + b'"\n5\n')
    assert numbers == [1, 2] and invalid[1] == ""


def test_a_line_just_within_the_bound_is_read():
    line = b"0" * (MAX_LINE_BYTES - 2) + b"60"
    numbers, values, invalid = rows(b"theta\n" + line + b"\n", size=1000)
    assert invalid == [""] and values["theta"] == [60.0]
    _, _, invalid = rows(b"theta\n" + b"0" + line + b"\n", size=1000)
    assert invalid == [f"line longer than {MAX_LINE_BYTES} bytes"]


class EndlessLine:
    """``theta\\n`` then one line of ``length`` bytes, made on demand, then ``\\n60\\n``."""

    def __init__(self, length):
        self.head, self.left, self.tail = b"theta\n", length, b"\n60\n"

    def read(self, n):
        if self.head:
            out, self.head = self.head, b""
            return out
        if self.left:
            k = min(n, self.left)
            self.left -= k
            return b"7" * k
        out, self.tail = self.tail, b""
        return out


def test_a_huge_line_is_not_held_in_memory():
    tracemalloc.start()
    try:
        r = RequestReader(EndlessLine(50_000_000), FIELDS, {})
        chunks = list(r.chunks())
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert [c.input_row.tolist() for c in chunks] == [[1, 2]]
    assert chunks[0].invalid.tolist() == [f"line longer than {MAX_LINE_BYTES} bytes", ""]
    assert peak < 4_000_000  # the line is 50 MB


def test_undecodable_and_binary_lines_spoil_only_their_rows():
    numbers, values, invalid = rows(b"theta,body\n60,w\xe9el\n6\x000,wheel\n70,wheel\n\xff\xfe\x00\x01\n")
    assert numbers == [1, 2, 3, 4]
    assert invalid == ["line is not UTF-8 text", "line contains binary data", "", "line contains binary data"]
    assert values["theta"][2] == 70.0


def test_bad_numbers_and_text_cells():
    data = "theta,alpha,mu,body,side\n60,abc,,SPHERE, Outside \n nan ,10,inf,,\n60,1e400,-inf,,\n60,10,nan,,\n"
    numbers, values, invalid = rows(data)
    assert numbers == [1, 2, 3, 4]
    assert invalid == ["alpha: 'abc' is not a number", "theta: 'nan' is not a finite number",
                       "alpha: '1e400' is not a finite number", "mu: 'nan' is not a finite number"]
    assert values["mu"][1:3] == [math.inf, -math.inf]  # mu alone may be infinite
    assert values["body"] == ["sphere", "wheel", "wheel", "wheel"]  # an empty cell takes the default
    assert values["side"] == ["outside", "inside", "inside", "inside"]


def test_long_bad_cell_is_shortened_in_the_reason():
    _, _, invalid = rows("theta\n" + "x" * 1000 + "\n")
    assert invalid[0].startswith("theta: 'xxx") and "is not a number" in invalid[0] and len(invalid[0]) < 80


# ---------------------------------------------------------------- values and defaults

def test_overrides_apply_to_every_row_and_defaults_fill_the_rest():
    """An option given with --input applies to every row, over the file's
    column; a field neither given nor in the file takes its default."""
    chunk, = reader("theta,a,k\n60,,\n70,0.2,0.5\n", {"a": 0.25, "g": 3.7, "k": None}).chunks()
    assert list(chunk.values) == list(FIELDS)
    assert chunk.values["a"].tolist() == [0.25, 0.25]  # the option wins over the column
    assert same(chunk.values["k"].tolist(), [math.nan, 0.5])  # None is no option; no default anywhere: NaN
    assert chunk.values["g"].tolist() == [3.7, 3.7]  # given, no column: broadcast
    assert chunk.values["r"].tolist() == [FIELDS["r"][0]] * 2  # the field's own default
    assert chunk.values["mu"].tolist() == [math.inf] * 2
    assert chunk.values["body"].dtype == object and chunk.values["body"].tolist() == ["wheel", "wheel"]
    assert all(chunk.values[name].dtype == np.float64 for name in FIELDS if name not in ("body", "side"))
    assert np.isnan(chunk.values["alpha"]).all() and chunk.invalid.dtype == object


def test_no_range_checks_here():
    _, values, invalid = rows("theta,a,mu\n500,-1,-3\n")
    assert invalid == [""] and values["theta"] == [500.0] and values["a"] == [-1.0]


# ---------------------------------------------------------------- header

def test_header_names_are_case_insensitive_and_aliases_work():
    numbers, values, invalid = rows(" Theta_Deg ,ALPHA, mu_available\n60,10,0.5\n")
    assert values["theta"] == [60.0] and values["alpha"] == [10.0] and values["mu"] == [0.5]


def test_unknown_column_names_it_and_lists_the_allowed_names():
    with pytest.raises(InputError) as err:
        reader("theta,thetta\n60,10\n")
    message = str(err.value)
    assert "unknown column 'thetta'" in message and allowed_columns(FIELDS) in message
    assert "\n" not in message


def test_a_nameless_column_is_an_error():
    with pytest.raises(InputError, match="column 2 has no name"):
        reader("theta,,alpha\n60,,10\n")


@pytest.mark.parametrize("header", ["theta,theta", "theta,THETA", "theta,theta_deg", "mu_available,mu"])
def test_a_field_twice_is_an_error(header):
    with pytest.raises(InputError, match="appears more than once"):
        reader(header + "\n1,2\n")


def test_output_columns_are_ignored_when_declared():
    out = io.StringIO()
    writer = csv.writer(out)
    writer.writerow(COLUMNS)
    row = dict.fromkeys(COLUMNS, "")
    row.update(input_row="7", body="sphere", side="inside", theta_deg="60", alpha_deg="", a_m="0.3",
               status="ok", reason="", v_cm_m_s="4.1", mu_available="inf", branch="1")
    writer.writerow([row[c] for c in COLUMNS])
    data = out.getvalue()
    with pytest.raises(InputError, match="unknown column 'input_row'"):
        reader(data)
    ignore = [c for c in COLUMNS if c not in FIELDS and c not in ALIASES]
    numbers, values, invalid = rows(data, ignore=ignore)
    assert numbers == [1] and invalid == [""]  # the file's own numbering, not its input_row column
    assert values["theta"] == [60.0] and values["a"] == [0.3] and values["body"] == ["sphere"]
    assert values["mu"] == [math.inf]
    # passing every output column is fine too: a field or alias wins over "ignore"
    assert rows(data, ignore=COLUMNS)[1]["theta"] == [60.0]


def test_custom_aliases():
    assert rows("polar\n60\n", aliases={"polar": "theta"})[1]["theta"] == [60.0]
    with pytest.raises(InputError, match="unknown column 'theta_deg'"):
        reader("theta_deg\n60\n", aliases={})


@pytest.mark.parametrize("data", [b"", b"\n\n  \r\n", b"\xef\xbb\xbf", "\r\n".encode("utf-16")])
def test_empty_input_is_an_error(data):
    with pytest.raises(InputError, match="is empty: expected a header line"):
        reader(data, source="x.csv")


@pytest.mark.parametrize("data", [b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR", b"\x00\x01\x02\x03", b"the\x00ta\n"])
def test_a_binary_header_is_an_error(data):
    with pytest.raises(InputError, match="^input is not UTF-8 or UTF-16 CSV text$"):
        reader(data)


def test_header_errors_come_before_any_row_is_read():
    with pytest.raises(InputError, match="unclosed quote"):
        reader('"theta,alpha\n60,10\n')
    with pytest.raises(InputError, match="header line is longer than"):
        reader(b"theta" * 20000 + b"\n1\n")


# ---------------------------------------------------------------- streaming

class Endless:
    """An endless request CSV made on demand; refuses to be read far ahead."""

    def __init__(self, limit):
        self.limit, self.served, self.row = limit, 0, 0
        self.buffer = b"theta,alpha\n"

    def read(self, n):
        while len(self.buffer) < n:
            self.row += 1
            self.buffer += b"%d,%d\n" % (self.row % 180, self.row % 90)
        out, self.buffer = self.buffer[:n], self.buffer[n:]
        self.served += len(out)
        if self.limit is not None and self.served > self.limit:
            raise AssertionError(f"read {self.served} bytes before the first chunk was used")
        return out


def test_the_first_chunk_comes_before_the_stream_ends():
    stream = Endless(limit=400_000)
    chunks = RequestReader(stream, FIELDS, {}).chunks(1000)
    first = next(chunks)
    assert first.input_row.tolist() == list(range(1, 1001))
    assert first.values["theta"][:3].tolist() == [1.0, 2.0, 3.0] and (first.invalid == "").all()
    stream.limit = None
    second = next(chunks)
    assert second.input_row[0] == 1001


def test_the_constructor_reads_only_as_far_as_the_header():
    stream = Endless(limit=70_000)  # one read block; parsing rows would need more
    r = RequestReader(stream, FIELDS, {})
    assert r.header == ["theta", "alpha"] and r.columns == ["theta", "alpha"]


# ---------------------------------------------------------------- opening and reading failures

def test_missing_file(tmp_path):
    with pytest.raises(InputError, match=r"^cannot read input '.*x\.csv': No such file or directory$"):
        open_input(str(tmp_path / "x.csv"))


def test_directory(tmp_path):
    with pytest.raises(InputError, match="^cannot read input .*: Is a directory$"):
        open_input(str(tmp_path))


def test_unreadable_file(tmp_path, monkeypatch):
    """A file the user may not read (simulated: the tests may run as root,
    who reads anything)."""
    path = tmp_path / "x.csv"
    path.write_text("theta\n60\n")

    def refuse(*args, **kwargs):
        raise PermissionError(13, "Permission denied", str(path))

    monkeypatch.setattr("builtins.open", refuse)
    with pytest.raises(InputError, match="Permission denied"):
        open_input(str(path))


def test_a_file_is_read(tmp_path):
    path = tmp_path / "x.csv"
    path.write_bytes(b"\xef\xbb\xbftheta\r\n60\r\n")
    with open_input(str(path)) as stream:
        assert rows(stream.read())[1]["theta"] == [60.0]


@pytest.mark.skipif(not os.path.exists("/proc/self/mem"), reason="needs /proc")
def test_io_error_while_reading_is_an_input_error():
    with open_input("/proc/self/mem") as stream:
        with pytest.raises(InputError, match="^cannot read /proc/self/mem: Input/output error$"):
            RequestReader(stream, FIELDS, {}, source="/proc/self/mem")


class FailsAfter:
    def __init__(self, data):
        self.data = data

    def read(self, n):
        if self.data:
            out, self.data = self.data, b""
            return out
        raise OSError(5, "Input/output error")


def test_io_error_after_the_header_is_an_input_error():
    chunks = RequestReader(FailsAfter(b"theta\n60\n"), FIELDS, {}, source="x.csv").chunks()
    with pytest.raises(InputError, match="^cannot read x.csv: Input/output error$"):
        list(chunks)


def test_closed_standard_input(monkeypatch):
    monkeypatch.setattr(sys, "stdin", None)
    with pytest.raises(InputError, match="^cannot read standard input: it is closed$"):
        open_input("-")
    closed = io.TextIOWrapper(io.BytesIO())
    closed.close()
    monkeypatch.setattr(sys, "stdin", closed)
    with pytest.raises(InputError, match="it is closed"):
        open_input("-")


def test_closed_standard_input_in_a_real_process():
    code = ("from deathsphere.inputs import open_input, InputError\n"
            "try:\n    open_input('-')\nexcept InputError as e:\n    print(e)\n")
    res = subprocess.run([sys.executable, "-c", code], capture_output=False, stdout=subprocess.PIPE,
                         preexec_fn=lambda: os.close(0), text=True, check=True)
    assert res.stdout.strip() == "cannot read standard input: it is closed"


def test_standard_input_is_binary(monkeypatch):
    stdin = io.TextIOWrapper(io.BytesIO("theta\n60\n".encode("utf-16")))
    monkeypatch.setattr(sys, "stdin", stdin)
    r = RequestReader(open_input("-"), FIELDS, {})
    assert r.encoding == "UTF-16" and [c.values["theta"].tolist() for c in r.chunks()] == [[60.0]]


# ---------------------------------------------------------------- property: lines <-> rows

CELLS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.integers(-1000, 1000).map(str),
    st.sampled_from(["", " ", "abc", "Wheel", "nan", "-inf", "inf", "1e400", "1_0", " 6 ", "\U0001d703",
                     '"', '""', '"5"', '"5', '5"', '"a,b"', ",", "\r", "\n", "\r\n", "\t", "\x0c"]),
)
LINES = st.lists(CELLS, max_size=6).map(",".join)
HEADER = ["theta", "alpha", "mu", "body"]


def expected_row(line: str, defaults: dict):
    """What the reader must make of one line (csv module on that line alone)."""
    try:
        cells = next(csv.reader((line,), strict=True, skipinitialspace=True))
    except csv.Error:
        return None
    if len(cells) != len(HEADER):
        return None
    out = {}
    for name, cell in zip(HEADER, cells):
        cell = cell.strip()
        if name == "body":
            out[name] = cell.lower() or defaults[name]
            continue
        if not cell:
            out[name] = defaults[name]
            continue
        try:
            number = float(cell)
        except ValueError:
            return None
        if math.isnan(number) or (math.isinf(number) and name != "mu"):
            return None
        out[name] = number
    return out


@settings(max_examples=300, deadline=None)
@given(lines=st.lists(LINES, max_size=12), newline=st.sampled_from(["\n", "\r\n", "\r"]),
       end=st.sampled_from(["", "\n", "\r\n"]), encoding=st.sampled_from(["utf-8", "utf-8-sig", "utf-16"]),
       size=st.one_of(st.none(), st.integers(1, 7)), chunk=st.integers(1, 5))
def test_every_non_blank_line_is_one_row_in_order(lines, newline, end, encoding, size, chunk):
    text = newline.join([",".join(HEADER)] + lines) + end
    data = text.encode(encoding, "surrogatepass")
    defaults = {"theta": 1.5, "alpha": -2.0, "mu": 0.5, "body": "particle"}
    fields = {name: (defaults.get(name, spec[0]), *spec[1:]) for name, spec in FIELDS.items()}
    numbers, values, invalid = rows(data, fields=fields, chunk=chunk, size=size)

    header, *physical = re.split(r"\r\n|\r|\n", text)  # a line ends at LF, CRLF or CR
    assert header == ",".join(HEADER)
    wanted = [i for i, line in enumerate(physical, 1) if line.strip()]
    assert numbers == wanted
    for k, number in enumerate(numbers):
        expect = expected_row(physical[number - 1], defaults)
        if expect is None:
            assert invalid[k] != ""
        else:
            assert invalid[k] == ""
            assert {name: values[name][k] for name in HEADER} == expect


@pytest.mark.parametrize("sep", [";", "\t"])
def test_a_spreadsheet_export_with_semicolons_or_tabs_is_read(sep):
    """Where the comma is the decimal mark a spreadsheet separates fields with
    ';' (or tabs): the header says which, and 6,5 in such a file is 6.5."""
    data = sep.join(["theta", "alpha", "body"]) + "\n" + sep.join(["60", "10,5", "wheel"]) + "\n" \
        + sep.join(["70", "oops", "sphere"]) + "\n"
    numbers, values, invalid = rows(data)
    assert numbers == [1, 2] and values["theta"] == [60.0, 70.0] and values["alpha"][0] == 10.5
    assert values["body"] == ["wheel", "sphere"] and invalid[0] == "" and "oops" in invalid[1]


def test_an_overridden_column_is_not_read():
    """A bad cell in a column an option replaces spoils nothing."""
    numbers, values, invalid = rows("theta,mu\n60,oops\n", {"mu": 0.5})
    assert invalid == [""] and values["mu"] == [0.5]
