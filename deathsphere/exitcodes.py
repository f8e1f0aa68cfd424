"""Exit statuses of the command line, defined once (docs/contract.md, "Exit status")."""

from enum import IntEnum


class ExitCode(IntEnum):
    OK = 0  # the command ran (infeasible orbits are data, not failures); also when the reader of a pipe stopped early
    INVALID_ROWS = 1  # some input rows were invalid (they are still in the output, with their reason)
    USAGE = 2  # bad options, unreadable input or an unusable --output: refused before any work
    OUTPUT = 3  # the results could not be written (stdout closed, disk full, ...)
    INTERRUPTED = 130  # Ctrl-C (SIGINT): 128 + 2, as a shell reports a process ended by it
    TERMINATED = 143  # SIGTERM: 128 + 15, after the clean-up (no partial file left)
