"""Start-up loads only what a command evaluates.

The interactive commands start within 2x ``import numpy`` (docs/performance.md,
measured by benchmarks/bench_latency.py, never timed here).  What keeps them
there is that nothing is imported that the command does not need; these
tests check that property by the modules a fresh interpreter holds after
each command, so an eager import added anywhere shows up as a failure.
"""

import json
import subprocess
import sys

import pytest

#: Run one command in a fresh interpreter, its output to a string, and print
#: the modules loaded afterwards (as JSON) on stdout.
PROBE = """
import contextlib, io, json, sys
sys.argv = ["deathsphere", *json.loads(sys.argv[1])]
from deathsphere.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    try:
        main()
    except SystemExit as exc:
        if exc.code:
            raise
print(json.dumps(sorted(sys.modules)))
"""

#: Never needed to write a csv: terminal drawing, figures, the integrator,
#: the installed metadata (the version string is static), the input reader.
NEVER = ("rich", "matplotlib", "scipy", "importlib.metadata", "deathsphere.simulation", "deathsphere.inputs",
         "deathsphere.viewer", "pint", "polars", "pyarrow", "pandas", "xarray")


def loaded(*args: str) -> set[str]:
    out = subprocess.run([sys.executable, "-c", PROBE, json.dumps([*args, "--format", "csv"])],
                         capture_output=True, text=True, check=True).stdout
    return set(json.loads(out))


def _prefixed(modules: set[str], names) -> list[str]:
    return sorted(m for m in modules if any(m == n or m.startswith(n + ".") for n in names))


@pytest.mark.parametrize("args, also_never", [
    (("orbit", "--theta", "60", "--alpha", "10"),
     ("deathsphere.physics.region", "deathsphere.physics.stability.floquet", "deathsphere.physics.particle",
      "deathsphere.physics.stability.paper", "deathsphere.parallel", "concurrent")),
    (("table1",), ("deathsphere.physics.stability.floquet", "deathsphere.results.verify")),
    (("stability", "--theta", "90", "--alpha", "45"),
     ("deathsphere.physics.stability.floquet", "deathsphere.physics.region")),
    (("map",), ("deathsphere.physics.stability.margin", "deathsphere.physics.stability.floquet")),
])
def test_an_interactive_command_loads_only_what_it_evaluates(args, also_never):
    modules = loaded(*args)
    assert "deathsphere.api" in modules          # the probe did run the command
    assert _prefixed(modules, NEVER + also_never) == []


def test_importing_the_package_loads_no_physics():
    """``import deathsphere`` is cheap; its names load on first use.  (The lazy
    loader lives at the bottom layer, in the physics package, whose
    ``__init__`` is documentation only, so that every layer may use it.)"""
    code = ("import json, sys, deathsphere; before = sorted(m for m in sys.modules if m.startswith('deathsphere')); "
            "deathsphere.orbit; print(json.dumps([before, 'deathsphere.api' in sys.modules]))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert json.loads(out) == [["deathsphere", "deathsphere.physics", "deathsphere.physics.lazy"], True]


def test_lazy_names_are_the_modules_objects():
    import deathsphere
    from deathsphere import api, model, params
    from deathsphere.physics import stability
    from deathsphere.physics.stability import floquet, horizontal

    assert deathsphere.orbit is api.orbit and deathsphere.Table is model.Table
    assert deathsphere.ParameterError is params.ParameterError
    assert stability.vertical_floquet is floquet.vertical_floquet
    assert stability.wheel_stability is horizontal.wheel_stability
    assert set(deathsphere.__all__) <= set(dir(deathsphere))
    assert set(stability.__all__) <= set(dir(stability))
    with pytest.raises(AttributeError, match="no attribute 'not_a_name'"):
        stability.not_a_name  # noqa: B018
