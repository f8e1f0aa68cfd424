"""Profile files: CSV samples of a meridian, read into a Profile in metres;
what is not such a file is refused in one line naming the file and row."""

import numpy as np
import pytest

from deathsphere.errors import ParameterError
from deathsphere.records.profile_files import profile_file


def _write(tmp_path, text, name="bowl.csv"):
    path = tmp_path / name
    path.write_bytes(text if isinstance(text, bytes) else text.encode())
    return path


def test_a_profile_in_feet_is_read_in_metres(tmp_path):
    path = _write(tmp_path, "rho_ft,z_ft\n16,0\n16,5\n16,10\n16,20\n")
    profile = profile_file(path)
    assert np.allclose(profile.contact(3.048)[0], 16 * 0.3048, rtol=1e-15)
    assert np.isclose(profile.highest_lane, 20 * 0.3048, rtol=1e-15)


@pytest.mark.parametrize("text, words", [
    ("", "empty"),
    ("\n\n", "empty"),
    (b"rho_m,z_m\n\x00\x01\x02\n", "not a text file"),
    (b"rho_m,z_m\n\xff\xfe1,2\n", "not UTF-8"),
    ("radius,height\n1,0\n1,1\n1,2\n1,3\n", "the header must name the columns rho_UNIT,z_UNIT"),
    ("rho_kg,z_m\n1,0\n1,1\n1,2\n1,3\n", "column 'rho_kg'"),
    ("rho_m,z_m\n1,0\n1,1\n1\n1,3\n", "row 3: two values expected"),
    ("rho_m,z_m\n1,0\n1,one\n1,2\n1,3\n", "row 2: not two numbers"),
    ("rho_m,z_m\n1,0\n1,1\n1,0.5\n1,3\n", "row 3: z must rise strictly"),
    ("rho_m,z_m\n1,0\n1,1\n2,2\n3,2.2\n4,2.4\n", "row 2: the meridian turns by 45"),
    ("rho_m,z_m\n1,0\n1,1\n", "at least 4 points"),
])
def test_bad_profile_files_are_refused_in_one_line(tmp_path, text, words):
    with pytest.raises(ParameterError, match=words) as err:
        profile_file(_write(tmp_path, text))
    message = str(err.value)
    assert message.startswith("profile file bowl.csv: ") and "\n" not in message and err.value.param == "profile"


def test_a_missing_file_is_named(tmp_path):
    with pytest.raises(ParameterError, match="cannot read the profile file"):
        profile_file(tmp_path / "none.csv")
