"""Machine files (``--machine-file``): a machine's parameters in a small
TOML file or a one-row CSV file, over a preset's values (docs/machine.md
sec. 7).  Here the file becomes its keys and values as typed (the
two-wheeler's files are read by the same reader); the requests' decoder
(:func:`deathsphere.requests.decode.decode_machine_file`) makes them a
machine, each value checked once against the registry and a refusal
naming the key as typed."""

from __future__ import annotations

from deathsphere.errors import ParameterError

#: Keys of a machine file (TOML or CSV) -> registry parameter.
FILE_KEYS = {"mass": "mass", "com_height": "com_height", "wheel_radius": "a", "tyre_radius": "tyre_radius",
             "roll_inertia": "roll_inertia", "pitch_inertia": "pitch_inertia", "yaw_inertia": "yaw_inertia",
             "spin_inertia": "spin_inertia", "head_height": "head_height", "width": "width"}


def machine_file_data(path) -> tuple[dict, "pathlib.Path"]:
    """The keys and values of a machine file, TOML (``.toml``: ``key =
    value`` lines) or CSV (a header naming the keys, one row of values),
    and its path; what is not such a file is refused in one line
    (:func:`~deathsphere.requests.decode.decode_machine_file`; the
    two-wheeler's files read them too)."""
    import csv
    import tomllib

    text, p = machine_file_text(path)
    if p.suffix.lower() == ".toml":
        try:
            return tomllib.loads(text), p
        except tomllib.TOMLDecodeError as exc:
            raise ParameterError(f"machine file {p.name}: not TOML ({exc})", "machine_file") from None
    rows = [r for r in csv.reader(text.splitlines()) if any(c.strip() for c in r)]
    if len(rows) != 2 or len(rows[0]) != len(rows[1]):
        raise ParameterError(f"machine file {p.name}: a CSV machine file is a header and one row of values",
                             "machine_file")
    keys = [k.strip() for k in rows[0]]
    twice = next((k for i, k in enumerate(keys) if k in keys[:i]), None)
    if twice is not None:
        raise ParameterError(f"machine file {p.name}: key {twice!r} is given twice (which one is meant?)",
                             "machine_file")
    return dict(zip(keys, (v.strip() for v in rows[1]))), p


def machine_file_text(path) -> tuple[str, "pathlib.Path"]:
    """A machine file's text and path; a file that cannot be read, or is
    not text, is refused in one line."""
    import pathlib

    p = pathlib.Path(path)
    try:
        raw = p.read_bytes()
    except OSError as exc:
        raise ParameterError(f"cannot read the machine file {str(path)!r}: {exc.strerror}", "machine_file") from None
    return _machine_text(raw, p.name), p


def _machine_text(raw: bytes, name: str) -> str:
    """A machine file's text: UTF-8, its byte-order mark dropped (a
    spreadsheet's export), or UTF-16 with a byte-order mark; anything else
    is refused in one line."""
    import codecs

    encoding = "utf-16" if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)) else "utf-8-sig"
    try:
        return raw.decode(encoding)
    except UnicodeDecodeError as exc:
        shown = encoding.upper().replace("-SIG", "")
        raise ParameterError(f"machine file {name}: not {shown} text (byte {exc.start}: "
                             f"{raw[exc.start:exc.start + 1]!r}); save it as UTF-8", "machine_file") from None


def file_source(name: str) -> str:
    """A machine's source when its file gives none: the file's name,
    written as a reason is (no comma, one line: every output row echoes it)."""
    from deathsphere.table.reasons import reason_text

    return reason_text(f"file {name}")
