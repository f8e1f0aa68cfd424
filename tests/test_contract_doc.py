"""docs/contract.md's table of inputs states every parameter that
deathsphere.params checks, with its unit and the ends of its allowed
interval: the contract a user reads is the one the code enforces."""

import re
from pathlib import Path

from deathsphere.params import PARAMS

CONTRACT = Path(__file__).resolve().parents[1] / "deathsphere" / "docs" / "contract.md"
NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[+-]?\d+)?")


def _input_rows() -> dict[str, tuple[str, set[float]]]:
    """name -> (unit, the numbers of the allowed cell) for each name of the table."""
    lines = CONTRACT.read_text(encoding="utf-8").split("## Inputs", 1)[1].splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("|"))
    end = next(i for i in range(start, len(lines) + 1) if i == len(lines) or not lines[i].startswith("|"))
    rows = {}
    for line in lines[start + 2:end]:                      # after the header and its rule
        names_cell, unit_cell, allowed_cell = (cell.strip() for cell in line.strip("|").split("|")[:3])
        names = re.findall(r"`([a-z0-9_]+)`", names_cell)
        units = [u.strip() for u in unit_cell.split(",")]
        numbers = {float(x) for x in NUMBER.findall(allowed_cell)}
        for i, name in enumerate(names):
            rows[name] = (units[i] if len(units) == len(names) else units[0], numbers)
    return rows


def test_every_parameter_is_in_the_contract_with_its_unit_and_bounds():
    rows = _input_rows()
    assert set(PARAMS) <= set(rows), sorted(set(PARAMS) - set(rows))
    for name, param in PARAMS.items():
        unit, numbers = rows[name]
        assert unit.replace("²", "^2").replace("–", "") == param.unit, (name, unit, param.unit)
        if not param.allow_inf:                            # "or inf (no limit)" rows state the idea
            assert {param.lo, param.hi} <= numbers, (name, sorted(numbers), param.lo, param.hi)
