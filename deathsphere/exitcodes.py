"""Exit statuses of the command line, defined once (design.md, "Exit status")."""

from enum import IntEnum


class ExitCode(IntEnum):
    OK = 0  # the command ran; infeasible orbits are data, not failures
    INVALID_ROWS = 1  # some input rows were invalid (they are still in the output)
    USAGE = 2  # bad options or unreadable input: nothing computed
