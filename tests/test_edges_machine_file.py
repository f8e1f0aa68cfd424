"""A machine file is read whatever a spreadsheet saved (UTF-8 with a
byte-order mark, UTF-16), refused in one line when it is not text or gives a
key twice; a name that the CSV output could not echo is refused; mass takes
lb and --max-g a trailing g."""

import codecs

import pytest

import deathsphere
from deathsphere.api.machines import Machine, machine_file
from deathsphere.params import ParameterError

LB = 0.45359237


def test_a_byte_order_mark_is_dropped(tmp_path):
    f = tmp_path / "bike.csv"
    f.write_bytes(codecs.BOM_UTF8 + b"mass,com_height\n200,0.8\n")
    assert machine_file(f).mass == 200.0


def test_utf16_with_its_mark_is_read(tmp_path):
    f = tmp_path / "bike.toml"
    f.write_bytes("mass = 210\n".encode("utf-16"))
    assert machine_file(f).mass == 210.0


def test_a_file_that_is_not_text_is_one_line(tmp_path):
    f = tmp_path / "bike.toml"
    f.write_bytes(b"mass = 1\xe9\n")
    with pytest.raises(ParameterError, match="not UTF-8 text .*byte 8"):
        machine_file(f)


def test_a_key_given_twice_is_refused(tmp_path):
    f = tmp_path / "bike.csv"
    f.write_text("mass,com_height,mass\n100,0.8,200\n")
    with pytest.raises(ParameterError, match="'mass' is given twice"):
        machine_file(f)


@pytest.mark.parametrize("name", ["our, bike", "two\nlines", "cr\rhere"])
def test_a_name_the_csv_cannot_echo_is_refused(name):
    with pytest.raises(ParameterError, match="holds a (comma|line break)"):
        Machine(mass=100, h=0.5, a=0.3, inertia=(10, 10, 10), spin_inertia=1, name=name)


def test_a_file_named_with_a_comma_needs_a_name_key(tmp_path):
    f = tmp_path / "our, bike.csv"
    f.write_text("mass\n100\n")
    with pytest.raises(ParameterError, match="give a name key"):
        machine_file(f)
    f.write_text("mass,name\n100,our bike\n")
    assert machine_file(f).name == "our bike"


def test_mass_in_pounds_and_max_g_with_its_g():
    m = Machine(mass="350lb", h=0.5, a=0.3, inertia=(10, 10, 10), spin_inertia=1)
    assert m.mass == 350 * LB
    with_g = deathsphere.ride(90, 10, machine="stunt125", max_g="5g")
    plain = deathsphere.ride(90, 10, machine="stunt125", max_g=5)
    assert float(with_g["max_g"]) == 5.0 and str(with_g["status"]) == str(plain["status"])
    with pytest.raises(ParameterError, match="kg is a mass"):
        deathsphere.ride(90, 10, machine="stunt125", max_g="5kg")


@pytest.mark.parametrize("text, key, words", [
    ("wheel_radius = -1\n", "wheel_radius", "must be 1e-09..1e+09 m (got -1)"),     # the registry's a, typed as its key
    ('mass = "8m"\n', "mass", "is a length"),
    ("mass = true\n", "mass", "must be a number"),
    ('base = "no-such-bike"\n', "base", "no-such-bike"),
])
def test_a_bad_value_is_refused_naming_the_file_and_its_key_as_typed(tmp_path, text, key, words):
    f = tmp_path / "bike.toml"
    f.write_text(text)
    with pytest.raises(ParameterError) as err:
        machine_file(f)
    assert str(err.value).startswith(f"machine file bike.toml: {key}: ") and words in str(err.value)
    assert err.value.param == "machine_file"       # the option that named the file, not --wheel-radius


def test_values_that_do_not_go_together_are_refused_under_the_file(tmp_path):
    f = tmp_path / "bike.csv"
    f.write_text("wheel_radius,tyre_radius\n0.3,0.35\n")
    with pytest.raises(ParameterError, match=r"^machine file bike.csv: tyre_radius t \(0.35 m\) must be less") as err:
        machine_file(f)
    assert err.value.param == "machine_file"


def test_the_command_line_names_the_file_option_for_a_bad_file_value(run, tmp_path):
    f = tmp_path / "bike.toml"
    f.write_text("wheel_radius = -1\n")
    result = run("ride", "--theta", "90", "--alpha", "10", "--machine-file", str(f))
    assert result.exit_code == 2 and "Traceback" not in result.stderr
    line, = [t for t in result.stderr.splitlines() if t.strip()]
    assert "Invalid value for '--machine-file': machine file bike.toml: wheel_radius: " in line
