"""docs/contract.md's table of inputs is the parameter registry's: the
contract a user reads is the one the code enforces (one definition of each
parameter, deathsphere.params)."""

from pathlib import Path

from deathsphere.params import PARAMS, markdown_table

CONTRACT = Path(__file__).resolve().parents[1] / "deathsphere" / "docs" / "contract.md"


def test_the_inputs_table_is_the_registrys():
    text = CONTRACT.read_text(encoding="utf-8")
    assert markdown_table() in text


def test_every_parameter_is_in_the_table_with_its_unit_and_bounds():
    table = markdown_table()
    for name, param in PARAMS.items():
        (row,) = [line for line in table.splitlines() if line.startswith(f"| `{name}` |")]
        assert param.allowed() in row and (param.unit or "–") in row
