"""Every `deathsphere ...` command shown in the README runs and exits 0
(the part before any pipe; `printf ... |` feeds its text as stdin)."""

import re
import shlex
from pathlib import Path

import pytest
from shipped_plans import copy_plan

README = Path(__file__).resolve().parents[1] / "README.md"


def commands():
    blocks = re.findall(r"```\n(.*?)```", README.read_text(), flags=re.S)
    found = []
    for block in blocks:
        for line in block.splitlines():
            line = line.split("  #")[0].strip()
            stdin = None
            m = re.match(r"printf '([^']*)' \| (deathsphere .*)", line)
            if m:
                stdin, line = m.group(1).encode().decode("unicode_escape"), m.group(2)
            if line.startswith("deathsphere "):
                found.append((line.split(" | ")[0], stdin))
    return found


def test_readme_has_commands():
    assert len(commands()) >= 8


@pytest.mark.parametrize("line, stdin", commands())
def test_readme_command_runs(run, line, stdin, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)     # a command with --output FILE writes it here
    args = shlex.split(line)[1:]
    if args[0] == "show":  # a plan shipped in examples/, else the one `show --example` prints
        from deathsphere.api.shows import EXAMPLE_PLAN

        for arg in args[1:]:
            if arg.endswith(".toml"):
                copy_plan(README.parent / arg, tmp_path / arg, EXAMPLE_PLAN)
    if "sweep" in args:  # keep the suite fast: the same command on a coarser grid
        args = [re.sub(r"^(\d+):(\d+):1$", r"\1:\2:20", a) for a in args]
    res = run(*args, input=stdin)
    assert res.exit_code == 0, (line, res.stderr)
    if "--output" in args:      # the file is the output; stdout stays empty
        assert (tmp_path / args[args.index("--output") + 1]).stat().st_size > 0
    else:
        assert res.stdout.strip()
