"""A two-wheeler from a file (docs/two-wheeler.md sec. 1.4): the
BicycleParameters library's benchmark format and the project's TOML/CSV
with the benchmark's names round-trip exactly, read what the library
writes (uncertainties, comments), take units and a preset as base, and
refuse a bad file in one line (exit status 2 on the command line)."""

import codecs
import csv
import io
import math
import re

import pytest

import deathsphere
from deathsphere import ParameterError
from deathsphere.records.two_wheeler_files import two_wheeler_file, two_wheeler_text
from deathsphere.requests.decode import read_machine_file
from deathsphere.api.two_wheelers import TWO_WHEELERS

#: Meijaard, Papadopoulos, Ruina & Schwab (2007), Table 1.
TABLE1 = dict(w=1.02, c=0.08, lam=math.pi / 10, g=9.81, rR=0.3, mR=2.0, IRxx=0.0603, IRyy=0.12, xB=0.3, zB=-0.9,
              mB=85.0, IBxx=9.2, IByy=11.0, IBzz=2.8, IBxz=2.4, xH=0.9, zH=-0.7, mH=4.0, IHxx=0.05892, IHyy=0.06,
              IHzz=0.00708, IHxz=-0.00756, rF=0.35, mF=3.0, IFxx=0.1405, IFyy=0.28)
#: Its body: the record holds no gravity (the run's), so a file's g is read and left out.
BODY = {k: v for k, v in TABLE1.items() if k != "g"}


def test_the_benchmark_in_bicycleparameters_format_reads_back_as_table_1(tmp_path):
    text = two_wheeler_text("benchmark-bicycle", "bicycleparameters")
    keys = [line.split(" = ")[0] for line in text.splitlines()]
    assert keys == sorted(TABLE1)                 # the library's writer sorts the names
    path = tmp_path / "BenchmarkBenchmark.txt"
    path.write_text(text)
    t = two_wheeler_file(path)
    assert t.benchmark_values() == BODY and t.name == "Benchmark" and not hasattr(t, "g")


@pytest.mark.parametrize("name", list(TWO_WHEELERS))
def test_every_preset_round_trips_through_toml(tmp_path, name):
    path = tmp_path / "bike.toml"
    path.write_text(two_wheeler_text(name))
    assert two_wheeler_file(path) == TWO_WHEELERS[name]


def test_what_the_library_writes_is_read(tmp_path):
    lines = [f"{k} = {v}+/-0.001" for k, v in TABLE1.items()]
    lines[0] = "# measured\nw = 1.02+/-0.002  # tape"
    lines[1] = "c = 0.079+/-0.001, 0.081+/-0.001"             # several values: averaged, as its reader does
    lines[6] = "IRxx = (6.03+/-0.01)e-02"                     # uncertainties' form for small numbers
    lines += ["yB = 0.0+/-0.0", "IRzz = 0.0603+/-0.0"]         # restating the Whipple model's symmetry
    path = tmp_path / "BrowserBenchmark.txt"
    path.write_text("\n".join(lines) + "\n\n")
    t = two_wheeler_file(path)
    assert t.benchmark_values() == pytest.approx(BODY, rel=1e-12) and t.name == "Browser"


def test_a_toml_file_takes_units_and_a_preset_as_base(tmp_path):
    path = tmp_path / "heavier.toml"
    path.write_text('base = "sport-tourer"\nmB = "600lb"\nlam = "30deg"\nw = "57in"\nhead_z = -1.7\n')
    t = read_machine_file(path)
    assert (t.mB, t.lam, t.w, t.head[1]) == pytest.approx((600 * 0.45359237, math.pi / 6, 57 * 0.0254, -1.7))
    assert t.IBxx == TWO_WHEELERS["sport-tourer"].IBxx and t.name == "heavier"
    single = tmp_path / "one.toml"
    single.write_text("mass = 120\n")                         # the single-contact machine's keys: a Machine
    assert read_machine_file(single).mass == 120.0


def test_a_spreadsheets_csv_with_a_byte_order_mark_is_read(tmp_path):
    path = tmp_path / "bike.csv"
    path.write_bytes(codecs.BOM_UTF8 + ("base,mB\nbenchmark-bicycle,90\n").encode())
    assert two_wheeler_file(path).mB == 90.0


@pytest.mark.parametrize("suffix, text, words", [
    (".txt", b"w = 1\xe9\n", "not UTF-8 text"),
    (".txt", b"w 1.02\n", "line 1 is not 'name = value'"),
    (".txt", b"w = wide\n", "'wide' is not a number"),
    (".txt", b"w = 1.02\nw = 1.03\n", "w is given twice"),
    (".txt", b"IGxx = 1\n", "'IGxx' is not one of the benchmark's 26"),
    (".txt", b"yB = 0.1\n", "yB must be 0"),
    (".txt", b"w = 1.02\n", "missing"),
    (".toml", b"w = 1.02\n", "missing: give all 25 of the benchmark's parameters but g"),
    (".toml", b'base = "sport-tourer"\ng = 9.81\n', "g is the run's gravity, not the two-wheeler's"),
    (".toml", b'base = "stunt125"\n', "base must be a two-wheeler preset"),
    (".toml", b'base = "sport-tourer"\nIBxx = "2kg"\n', "IBxx is a plain number"),
    (".toml", b'base = "sport-tourer"\nw = -1\n', "w (wheel base) must be 0.05..10 m (got -1)"),
    (".toml", b'base = "sport-tourer"\nwheels = 2\n', "unknown key 'wheels'"),
])
def test_a_bad_file_is_refused_in_one_line(tmp_path, suffix, text, words):
    path = tmp_path / f"bike{suffix}"
    path.write_bytes(text)
    with pytest.raises(ParameterError, match=re.escape(words)) as caught:
        two_wheeler_file(path)
    assert "\n" not in str(caught.value) and str(caught.value).startswith(f"machine file bike{suffix}:")


def test_the_command_line_rides_a_file_and_refuses_a_bad_one(run, tmp_path):
    path = tmp_path / "BenchmarkBenchmark.txt"
    path.write_text(two_wheeler_text("benchmark-bicycle", "bicycleparameters"))
    res = run("ride", "--machine-file", str(path), "--flat", "--speed", "0:10:0.5", "--summary", "--format", "csv")
    (row,) = csv.DictReader(io.StringIO(res.stdout))
    summary = deathsphere.ride(machine="benchmark-bicycle", flat=True, speed="0:10:0.5", summary=True)[0]
    assert res.exit_code == 0 and row["machine"] == "Benchmark"
    assert float(row["weave_speed_m_s"]) == summary["weave_speed_m_s"]
    path.write_text("w = 1.02\n")
    bad = run("ride", "--machine-file", str(path), "--flat", "--speed", "5")
    assert bad.exit_code == 2 and "--machine-file" in bad.output and len(bad.output.strip().splitlines()) == 1
