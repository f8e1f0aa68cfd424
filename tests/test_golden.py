"""Every table the CLI prints stays byte-identical to the pinned copy
(tests/golden/): a refactor moves code, never a number.  A golden file is
rewritten only on purpose (``python tests/golden/cases.py``), and the commit
that does so says why."""

import pytest

from golden.cases import CASES, output, path


@pytest.mark.parametrize("name", sorted(CASES))
def test_output_is_the_pinned_one(name):
    expected = path(name).read_bytes()
    assert expected, f"{path(name)} is empty: a pinned output must hold a table"
    got = output(CASES[name])
    if got != expected:
        got_lines, want_lines = got.decode().splitlines(), expected.decode().splitlines()
        first = next((i for i, (a, b) in enumerate(zip(got_lines, want_lines)) if a != b),
                     min(len(got_lines), len(want_lines)))
        pytest.fail(f"{name}: line {first + 1} differs (got {len(got_lines)} lines, pinned {len(want_lines)})\n"
                    f"got:    {got_lines[first] if first < len(got_lines) else '<end>'}\n"
                    f"pinned: {want_lines[first] if first < len(want_lines) else '<end>'}")
