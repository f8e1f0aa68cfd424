"""Property-based fuzzing of every command (docs/contract.md).

Random option values drawn from valid, boundary and hostile sets, and random
``--input`` CSV bodies (byte-order mark, CRLF, quotes, empty rows, wrong
field counts, binary).  Whatever comes in:

- no traceback, ever;
- the exit status is one of the documented ones;
- on exit status 2, exactly one line on stderr;
- with ``--input``, every non-blank line after the header comes out, in
  order, numbered by its position after the header;
- no ``ok`` row carries ``nan`` or ``inf``;
- no reason holds a comma (``awk -F,`` splits the CSV), whatever text the
  input file echoes into it.

Quick in CI (a bounded number of examples); set DEATHSPHERE_FUZZ_EXAMPLES
(e.g. 2000) for a deeper run.
"""

from __future__ import annotations

import csv
import io
import os

from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from deathsphere.cli import cli

EXAMPLES = int(os.environ.get("DEATHSPHERE_FUZZ_EXAMPLES", "25"))
FUZZ = settings(max_examples=EXAMPLES, deadline=None, derandomize=not os.environ.get("DEATHSPHERE_FUZZ_EXAMPLES"),
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
EXIT_STATUSES = {0, 1, 2, 3}

VALID = ["60", "10", "0.3", "3", "1", "45", "90", "5:40:5", "100"]
BOUNDARY = ["0", "180", "-180", "1e-9", "1e9", "inf", "-0", "0.5", "359.5", "2"]
HOSTILE = ["nan", "-inf", "1e308", "-1", "abc", "", "1e-320", "0:1e308:1e-300", "5:1:1", "1:2:0", "1:2",
           "0:180:1e-9", "\u00bd", "0x10", " 7 ", "1,5", "--theta"]
VALUE = st.sampled_from(VALID + BOUNDARY + HOSTILE)
FORMAT = st.sampled_from(["csv", "json", "ndjson", "table"])


def invoke(args, stdin=None):
    res = CliRunner().invoke(cli, args, input=stdin, catch_exceptions=True)
    return res


def check_common(res, args):
    assert res.exception is None or isinstance(res.exception, SystemExit), (args, repr(res.exception))
    assert "Traceback" not in res.stderr, (args, res.stderr)
    assert res.exit_code in EXIT_STATUSES, (args, res.exit_code, res.stderr)
    if res.exit_code == 2:
        lines = res.stderr.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("deathsphere: error: "), (args, res.stderr)


def csv_rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def check_ok_rows_finite(rows):
    for row in rows:
        if row.get("status") == "ok":
            bad = [k for k, v in row.items() if v is not None and v.strip().lower() in ("nan", "inf", "-inf")]
            assert not bad, row


def check_reasons_have_no_comma(rows):
    for row in rows:
        assert "," not in (row.get("reason") or ""), row


def options(draw, names):
    args = []
    for name in names:
        if draw(st.booleans()):
            args += [name, draw(VALUE)]
    return args


@st.composite
def orbit_args(draw):
    args = ["orbit", "--theta", draw(VALUE)]
    target = draw(st.sampled_from(["--alpha", "--speed", "--omega", "--omega3", None]))
    if target:
        args += [target, draw(VALUE)]
    args += options(draw, ["-a", "-r", "-k", "-g", "--mu"])
    args += ["--body", draw(st.sampled_from(["wheel", "sphere", "particle"])),
             "--side", draw(st.sampled_from(["inside", "outside"]))]
    if draw(st.booleans()):
        args.append("--no-stability")
    return args + ["--format", draw(FORMAT)]


@st.composite
def other_args(draw):
    command = draw(st.sampled_from(["sweep", "vertical", "limits", "map", "stability", "simulate", "table1"]))
    small = st.sampled_from(["60", "0", "180", "90", "10:30:10", "nan", "-5", "1e9", "abc", "0:1e308:1e-300"])
    if command == "sweep":
        args = ["sweep", "--theta", draw(small), "--alpha", draw(small)] + options(draw, ["-a", "-r", "-k", "--mu"])
        args += ["--format", draw(st.sampled_from(["csv", "json", "ndjson"]))]
    elif command == "vertical":
        args = ["vertical", "--theta", draw(small), draw(st.sampled_from(["--v-top", "--phidot-top"])), draw(VALUE)]
        args += options(draw, ["-k", "--mu", "-a"])
        if draw(st.booleans()):
            args += ["--points", draw(st.sampled_from(["2", "5", "0", "1e7", "x"]))]
        args += ["--no-stability", "--format", draw(FORMAT)]
    elif command == "limits":
        args = ["limits"] + (["--theta", draw(small)] if draw(st.booleans()) else [])
        args += options(draw, ["--mu", "--max-g", "-g"]) + ["--format", draw(FORMAT)]
    elif command == "map":
        args = ["map", "--step", draw(st.sampled_from(["5", "10", "nan", "0", "-1", "11", "abc"]))]
        args += options(draw, ["-a", "-r", "--mu", "--max-g", "-k"]) + ["--format", draw(FORMAT)]
    elif command == "stability":
        args = ["stability", "--theta", draw(VALUE), "--alpha", draw(VALUE)] + options(draw, ["-k", "-a"])
        args += ["--format", draw(FORMAT)]
    elif command == "simulate":
        args = ["simulate", "--theta", draw(VALUE), "--alpha", draw(VALUE), "--periods",
                draw(st.sampled_from(["0.01", "0.001", "0", "-1", "nan", "1e9"])),
                "--points-per-period", draw(st.sampled_from(["2", "10", "1", "x"]))]
        args += options(draw, ["-k", "--perturb", "--mu"]) + ["--format", draw(st.sampled_from(["csv", "json"]))]
    else:
        args = ["table1", "--format", draw(FORMAT)]
    return args


@FUZZ
@given(orbit_args())
def test_orbit_options_never_crash(args):
    res = invoke(args)
    check_common(res, args)
    if res.exit_code in (0, 1) and args[-1] == "csv":
        check_ok_rows_finite(csv_rows(res.stdout))
        check_reasons_have_no_comma(csv_rows(res.stdout))


@FUZZ
@given(other_args())
def test_every_command_never_crashes(args):
    res = invoke(args)
    check_common(res, args)
    if res.exit_code in (0, 1) and args[-1] == "csv":
        check_ok_rows_finite(csv_rows(res.stdout))
        check_reasons_have_no_comma(csv_rows(res.stdout))


CELLS = st.sampled_from(["60", "10", "90", "25", "0.3", "3", "", " ", "abc", "nan", "inf", "-1", "200",
                         '"60"', '"6,0"', '"unclosed', "wheel", "sphere", "outside", "\x00", "\u00e9", "1e308",
                         "405", "-175", '"bi,ke"', '"in,side"', '"60"x', '"1,2,3"', '","'])


@st.composite
def csv_bodies(draw):
    columns = draw(st.lists(st.sampled_from(["theta", "alpha", "a", "r", "k", "mu", "side", "body", "theta_deg",
                                              "status", "v_cm_m_s"]), min_size=1, max_size=4, unique=True))
    if "theta_deg" in columns and "theta" in columns:
        columns.remove("theta_deg")
    lines = [",".join(columns)]
    for _ in range(draw(st.integers(0, 12))):
        kind = draw(st.sampled_from(["row", "row", "row", "blank", "commas", "short", "long"]))
        if kind == "blank":
            lines.append(draw(st.sampled_from(["", "  "])))
        elif kind == "commas":
            lines.append("," * (len(columns) - 1))
        else:
            n = {"row": len(columns), "short": max(0, len(columns) - 1), "long": len(columns) + 1}[kind]
            lines.append(",".join(draw(CELLS) for _ in range(n)) if n else "")
    newline = draw(st.sampled_from(["\n", "\r\n"]))
    text = newline.join(lines) + draw(st.sampled_from([newline, ""]))
    data = text.encode("utf-8")
    if draw(st.booleans()):
        data = b"\xef\xbb\xbf" + data
    if draw(st.integers(0, 9)) == 0:
        data += b"\xff\xfe\x00binary\x00" + newline.encode()
    return data


def data_line_positions(data: bytes):
    """Positions (after the header) of the non-blank lines: what must come out."""
    text = data.decode("utf-8", errors="replace").lstrip("\ufeff")
    lines = text.replace("\r\n", "\n").split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    header = next(i for i, line in enumerate(lines) if line.strip())
    return [i - header for i in range(header + 1, len(lines)) if lines[i].strip()]


@FUZZ
@given(csv_bodies(), st.sampled_from(["orbit", "vertical"]))
def test_input_rows_are_never_lost(data, command):
    if command == "vertical" and b"alpha" in data.split(b"\n", 1)[0]:
        data = data.replace(b"alpha", b"v_top", 1)
    args = [command, "--input", "-", "--format", "csv"] + (["--no-stability"] if command == "vertical" else [])
    res = CliRunner().invoke(cli, args, input=data, catch_exceptions=True)
    check_common(res, args)
    if res.exit_code == 2:  # an unreadable header (e.g. a column the command does not take)
        return
    rows = csv_rows(res.stdout)
    numbers = [int(r["input_row"]) for r in rows]
    assert numbers == sorted(numbers)
    assert list(dict.fromkeys(numbers)) == data_line_positions(data)
    check_ok_rows_finite(rows)
    check_reasons_have_no_comma(rows)


#: Characters a hostile cell is made of: separators, quotes, escapes, digits
#: and letters, a line break inside a quoted field, non-ASCII.
HOSTILE_TEXT = st.text(alphabet=',;"\'\\ \t.-+eE0123456789abcdefgiknrwxyz\u00e9\u2028\n\x7f', max_size=24)


@FUZZ
@given(st.lists(st.tuples(HOSTILE_TEXT, HOSTILE_TEXT, HOSTILE_TEXT), min_size=1, max_size=8))
def test_hostile_cell_text_never_puts_a_comma_in_a_reason(cells):
    """Whatever a cell holds, the reason that echoes it has no comma, and
    every line still gives its row."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["theta", "alpha", "body"])
    for theta, alpha, body in cells:
        # a line break would make one request span two lines: not a row of its own
        writer.writerow([theta.replace("\n", " "), alpha.replace("\n", " "), body.replace("\n", " ")])
    args = ["orbit", "--input", "-", "--format", "csv", "--no-stability"]
    res = CliRunner().invoke(cli, args, input=out.getvalue(), catch_exceptions=True)
    check_common(res, args)
    rows = csv_rows(res.stdout)
    check_reasons_have_no_comma(rows)
    assert [int(r["input_row"]) for r in rows if r["branch"] in ("", "0")] == list(range(1, len(cells) + 1))
