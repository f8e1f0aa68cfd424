"""The commands whose output is pinned byte for byte (tests/test_golden.py).

One case per command and body: every table the CLI prints as CSV.  A case's
file is ``tests/golden/NAME.csv``; ``python tests/golden/cases.py`` writes
them afresh, which is done only on purpose (a change of output that a commit
names and explains).  The show's plan is a copy of ``show --example`` kept
here, so that editing the example does not move these files.
"""

from __future__ import annotations

from pathlib import Path

HERE = Path(__file__).parent
PLAN = str(HERE / "act.toml")
#: The wall of death's act of docs/show.md sec. 11 (a plan's [arena]).
WALL = str(HERE / "wall.toml")
#: The same act as shipped to users (examples/; a test holds it equal to WALL), one rider falling.
WALL_EXAMPLE = str(HERE.parents[1] / "examples" / "wall_of_death.toml")

CASES = {
    "orbit_wheel_grid": ["orbit", "--theta", "30:150:30", "--alpha", "5", "--alpha", "10", "--mu", "1", "--max-g", "5"],
    "orbit_sphere": ["orbit", "--body", "sphere", "--theta", "60", "--omega3", "80"],
    "orbit_particle": ["orbit", "--body", "particle", "--theta", "100:170:10"],
    "orbit_outside": ["orbit", "--side", "outside", "--theta", "30", "--alpha", "80"],
    "orbit_speed": ["orbit", "--theta", "60", "--com-speed", "7"],
    "sweep": ["sweep", "--theta", "5:175:10", "--alpha", "1:89:8"],
    "vertical": ["vertical", "--theta", "90", "--v-top", "6"],
    "vertical_points": ["vertical", "--theta", "60", "--v-top", "6", "--points", "13"],
    "vertical_outside": ["vertical", "--side", "outside", "--theta", "90", "--v-top", "0"],
    "map": ["map"],
    "limits_highest": ["limits", "--mu", "1", "--max-g", "5"],
    "limits_theta": ["limits", "--theta", "60"],
    "stability": ["stability", "--theta", "90", "--alpha", "45"],
    "table1": ["table1"],
    "machines": ["machines"],
    "verify_claim": ["verify", "--claim", "T1-v"],
    "ride_lap": ["ride", "--theta", "90", "--speed", "30km/h", "--diameter", "16ft"],
    "ride_grid": ["ride", "--diameter", "16ft", "--height", "0:2.4:0.4m", "--speed", "5:35:5km/h", "--mu", "1",
                  "--max-g", "5"],
    "ride_summary": ["ride", "--diameter", "16ft", "--height", "0:2.4:0.4m", "--speed", "5:35:5km/h", "--mu", "1",
                     "--max-g", "5", "--summary"],
    "ride_vertical": ["ride", "--vertical", "--theta", "90", "--v-top", "30km/h", "--diameter", "16ft", "--mu", "1",
                      "--max-g", "5"],
    "ride_bicycle_single_contact": ["ride", "--machine", "benchmark-bicycle-rigid", "--theta", "90", "--speed", "20km/h",
                                    "--diameter", "16ft"],
    "ride_paper_wheel": ["ride", "--machine", "paper-wheel", "--theta", "60", "--speed", "7"],
    "ride_flat": ["ride", "--machine", "benchmark-bicycle", "--flat", "--speed", "0:10:0.5"],
    "ride_flat_summary": ["ride", "--machine", "benchmark-bicycle", "--flat", "--speed", "0:10:0.5", "--summary"],
    "ride_steer_torque": ["ride", "--machine", "benchmark-bicycle", "--steer-torque", "0", "--diameter", "16ft",
                          "--height", "1"],
    "ride_steer_free": ["ride", "--machine", "stunt125-steer", "--steer", "free", "--diameter", "16ft", "--height",
                        "1:2:1", "--speed", "8:12:2"],
    "ride_steer_free_summary": ["ride", "--machine", "stunt125-steer", "--steer", "free", "--diameter", "16ft",
                                "--height", "1:2:1", "--speed", "8:12:2", "--summary"],
    "ride_steer_locked": ["ride", "--machine", "sport-tourer", "--steer", "locked", "--diameter", "16ft", "--height",
                          "1", "--speed", "40:65:3km/h"],
    "show_riders": ["show", PLAN, "--table", "riders"],
    "show_pairs": ["show", PLAN, "--table", "pairs"],
    "show_phase_auto": ["show", PLAN, "--phase", "auto", "--table", "pairs"],
    "show_fall": ["show", PLAN, "--fail", "Ben@1.2:0.3", "--table", "falls"],
    "show_monte_carlo": ["show", PLAN, "--monte-carlo", "20", "--seed", "1", "--table", "falls"],
    "show_monte_carlo_summary": ["show", PLAN, "--monte-carlo", "20", "--seed", "1", "--table", "summary"],
    "show_wall_riders": ["show", WALL, "--table", "riders"],
    "show_wall_pairs": ["show", WALL, "--table", "pairs"],
    "show_wall_fall": ["show", WALL_EXAMPLE, "--fail", "Ben@1.2:0.5", "--table", "falls"],
    "show_wall_monte_carlo_summary": ["show", WALL_EXAMPLE, "--monte-carlo", "20", "--seed", "1", "--table", "summary"],
    "simulate_wheel": ["simulate", "--theta", "60", "--alpha", "10", "--periods", "1", "--perturb", "1"],
    "simulate_sphere": ["simulate", "--body", "sphere", "--theta", "60", "--omega3", "80", "--periods", "1"],
    "simulate_vertical": ["simulate", "--vertical", "--theta", "90", "--v-top", "6", "--periods", "1"],
    "simulate_machine": ["simulate", "--machine", "stunt125", "--diameter", "16ft", "--theta", "100", "--com-speed",
                         "25km/h", "--periods", "0.1", "--perturb", "0.5"],
    "simulate_two_wheeler": ["simulate", "--machine", "stunt125-steer", "--steer", "free", "--diameter", "16ft",
                             "--height", "2", "--speed", "9", "--perturb", "0.2", "--steer-gains", "20,20",
                             "--periods", "0.5"],
    "simulate_two_wheeler_flat": ["simulate", "--machine", "benchmark-bicycle", "--flat", "--speed", "5",
                                  "--perturb", "0.5", "--duration", "1"],
}


def output(args):
    """What ``deathsphere ARGS --format csv`` writes on stdout, run in-process."""
    from click.testing import CliRunner

    from deathsphere.cli import cli

    result = CliRunner().invoke(cli, [*args, "--format", "csv"], catch_exceptions=False)
    assert result.exit_code == 0, (args, result.exit_code, result.stderr)
    return result.stdout_bytes


def path(name):
    return HERE / f"{name}.csv"


if __name__ == "__main__":
    for name, args in CASES.items():
        path(name).write_bytes(output(args))
        print(name, path(name).stat().st_size)
