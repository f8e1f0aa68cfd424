"""The command line's options, built from the one parameter registry
(:data:`deathsphere.params.PARAMS`): every command that takes ``--mu`` takes
the same ``--mu``, with the same flags, help text, metavar and default.

Values are handed to the API as typed (text, perhaps with a unit suffix:
``--speed 40km/h``); the API checks and converts them, once.  An option that
takes one value and is given twice is a usage error rather than a silent
"last one wins" (:func:`single`).
"""

from __future__ import annotations

import click

from deathsphere.constants import BODIES, SIDES
from deathsphere.params import PARAMS
from deathsphere.writers.stream import FORMATS

#: How each kind's help names the unit suffixes it takes.
UNIT_HINTS = {
    "length": "m; or ft, in, cm, mm: 8ft",
    "speed": "m/s; or km/h, mph: 40km/h",
    "rate": "rad/s; or rpm, deg/s: 30rpm",
    "angle": "deg; or rad: 0.2rad",
    "acceleration": "m/s^2",
    "mass": "kg; or lb: 350lb",
    "load": "g; a trailing g is allowed: 5g",
}


def _once(ctx, param, value):
    """The one value of an option declared ``multiple`` only so that a
    second use can be caught: given twice, a usage error naming both."""
    if value is None or value == ():
        return param.metadata_default
    if len(value) > 1:
        shown = ", ".join(str(v) for v in value)
        raise click.BadParameter(f"given {len(value)} times ({shown}); it takes one value", ctx=ctx, param=param)
    return value[0]


class SingleOption(click.Option):
    """An option of one value that refuses to be given twice."""

    def __init__(self, *args, default=None, **kwargs):
        kwargs.setdefault("callback", _once)
        super().__init__(*args, multiple=True, **kwargs)
        self.metadata_default = default


def single(*flags, default=None, **kwargs):
    """``click.option`` for one value, given at most once."""
    return click.option(*flags, cls=SingleOption, default=default, **kwargs)


def _help(name: str, help: str | None, multiple: bool) -> str:
    p = PARAMS[name]
    text = help or p.help
    hint = UNIT_HINTS.get(p.kind)
    if hint:
        text += f" [{hint}]"
    if multiple:
        text += " Repeat it or give start:stop:step."
    if p.shown_default is not None:
        text += f" [default: {p.shown_default}]"
    return text


def param_option(name: str, *, multiple: bool = False, required: bool = False, help: str | None = None):
    """The option of registry parameter ``name``: its flags, metavar and help
    (``help`` overrides the text where a command gives the symbol another
    meaning, e.g. theta as a vertical orbit's cone angle).  ``multiple``:
    values and ranges, repeatable (a grid axis)."""
    p = PARAMS[name]
    text = _help(name, help, multiple)
    if multiple:
        return click.option(*p.cli_flags, name, multiple=True, metavar=p.metavar, required=required, help=text)
    return single(*p.cli_flags, name, metavar=p.metavar, required=required, help=text)


def params_options(*names: str, multiple=()):
    """Several registry options at once, in the order given."""
    def decorator(f):
        for name in reversed(names):
            f = param_option(name, multiple=name in multiple)(f)
        return f
    return decorator


def body_option(bodies=BODIES):
    # no default here: not given, the API's applies (with --input: the file's column)
    return single("--body", type=click.Choice(bodies, case_sensitive=False), default=None,
                  help=f"Rolling body: {', '.join(bodies)} [default: wheel].")


def side_option():
    return single("--side", type=click.Choice(SIDES, case_sensitive=False), default=None,
                  help="Body inside or outside the fixed sphere [default: inside].")


def setup_options(*, multiple=(), gravity: bool = True, friction: bool = True):
    """The setup every physics command takes: --side, -a, -r or --diameter,
    -k, -g, --mu (``multiple``: those that are grid axes)."""
    names = ["a", "r", "diameter", "k"] + (["g"] if gravity else []) + (["mu"] if friction else [])

    def decorator(f):
        f = params_options(*names, multiple=multiple)(f)
        return side_option()(f)
    return decorator


def surface_options(lanes: bool = True):
    """The arena of orbit, sweep, limits, map, stability, simulate and
    vertical (docs/surfaces.md): --surface and its shape; the lane on it is
    --height (or --turn-radius on flat ground), grid axes here (``lanes``;
    simulate, which has its own single --height and --turn-radius, and
    vertical, whose loop is not a parallel, leave them out)."""
    from deathsphere.api.orbits import SURFACES

    def decorator(f):
        for option in reversed([
            single("--surface", type=click.Choice(SURFACES, case_sensitive=False), default=None,
                   help="The surface rolled on: sphere (the globe, -r or --diameter), cylinder (the wall of "
                        "death: --diameter, --wall-height), cone (the well of death, a board track: --diameter "
                        "at the floor, --wall-angle, --wall-height), plane (flat ground: --turn-radius) or "
                        "profile (--profile FILE) [default: sphere]."),
            param_option("wall_angle"),
            param_option("wall_height"),
            single("--profile", "profile", default=None, metavar="FILE",
                   help="With --surface profile: a CSV of the meridian's points from the lowest up, header "
                        "rho_m,z_m (or rho_ft,z_ft ...; docs/surfaces.md)."),
        ] + ([param_option("height", multiple=True), param_option("turn_radius", multiple=True)] if lanes else [])):
            f = option(f)
        return f
    return decorator


def output_options(formats=FORMATS):
    return single("--format", "fmt", type=click.Choice(formats, case_sensitive=False), default=None,
                  help="Output format [default: table on a terminal, csv when piped].")


def stability_option(default: bool = True, help: str | None = None):
    return click.option(
        "--stability/--no-stability", "stability", default=default, show_default=True,
        help=help or "Fill the stability columns from the exact linearisation (docs/stability.md); "
                     "--no-stability leaves them empty and runs faster.")


def jobs_option():
    return param_option("jobs")


def scheduler_option():
    return single(
        "--scheduler", default=None, metavar="ADDRESS",
        help="Evaluate on the dask.distributed cluster whose scheduler is at ADDRESS (tcp://host:8786; the "
             "distributed extra); the output is that of a local run.  Not with --jobs.  A scheduler that does "
             "not answer within 5 s is a usage error (importing distributed adds a few "
             "seconds before that).")


def only_option(statuses):
    return click.option("--only", multiple=True, type=click.Choice(statuses, case_sensitive=False),
                        help="Keep only rows with this status (repeatable), e.g. --only ok.")


def input_option(fields: str):
    return single(
        "--input", "input", default=None, metavar="FILE|-",
        help=f"CSV of requests, one per line ('-' reads stdin); its header names the options ({fields}); "
             "its own output CSV is read too, and ',', ';' or tab separates the fields.  Every line after "
             "the header gives one row; a bad line is an invalid row with its reason.  An option given "
             "with --input applies to every row, over the file's column.")


#: The machine's overrides: registry parameter -> option flag (``ride``,
#: ``simulate --machine``).
MACHINE_OPTIONS = {"mass": "--mass", "com_height": "--com-height", "a": "--wheel-radius",
                   "tyre_radius": "--tyre-radius", "roll_inertia": "--roll-inertia",
                   "pitch_inertia": "--pitch-inertia", "yaw_inertia": "--yaw-inertia",
                   "spin_inertia": "--spin-inertia", "head_height": "--head-height"}


def _machine_option(name: str, flag: str):
    p = PARAMS[name]
    text = p.help.removeprefix("Ride: ")
    if name == "a":
        text = "Wheel radius to the tyre's crown."
    hint = UNIT_HINTS.get(p.kind)
    text += (f" [{hint}]" if hint else f" [{p.unit}]") + " [default: the machine's]"
    return single(flag, name, metavar=p.metavar, help=text)


def machine_options(*, without=(), machine_help: str = "A preset machine (see 'deathsphere machines') "
                                                            "[default: stunt125]."):
    """--machine, --machine-file and the machine's overrides (those of
    :data:`MACHINE_OPTIONS` not in ``without``: a command whose setup
    already takes ``-a/--wheel-radius`` leaves ``a`` out)."""
    from deathsphere.api.machines import PRESETS
    from deathsphere.api.two_wheelers import TWO_WHEELER_NAMES

    names = tuple(PRESETS) + tuple(TWO_WHEELER_NAMES)

    def decorator(f):
        for name, flag in reversed(list(MACHINE_OPTIONS.items())):
            if name not in without:
                f = _machine_option(name, flag)(f)
        f = single("--machine-file", "machine_file", default=None, metavar="FILE",
                   help="A machine from a TOML or CSV file (keys mass, com_height, wheel_radius, tyre_radius, "
                        "roll_inertia, pitch_inertia, yaw_inertia, spin_inertia, head_height, name, source; "
                        "missing keys from --machine), or a two-wheeler's: the benchmark's 26 names as keys, or a "
                        "BicycleParameters <Name>Benchmark.txt (docs/two-wheeler.md sec. 1.4).")(f)
        # the names in the help, not the metavar: six of them do not fit a line of 80 columns
        return single("--machine", "machine", type=click.Choice(names, case_sensitive=False), metavar="NAME",
                      default=None, help=f"{machine_help} One of {', '.join(names)}.")(f)
    return decorator


def machine_from_options(machine, machine_file, **overrides):
    """The Machine the options name: the preset ``machine`` (stunt125 if
    none), or ``machine_file`` (its missing keys from the preset), with the
    override options given (registry names; None: not given); a
    two-wheeler's preset or file gives its TwoWheeler, as it is."""
    from deathsphere import api
    from deathsphere.api.two_wheelers import read_machine_file
    from deathsphere.api.two_wheelers import TWO_WHEELERS, TwoWheeler

    name = (machine or api.machines.DEFAULT_MACHINE).lower()
    chosen = read_machine_file(machine_file, base=name) if machine_file else api.PRESETS.get(name) or TWO_WHEELERS[name]
    if not isinstance(chosen, TwoWheeler):
        return chosen.with_overrides(**overrides)
    given = [MACHINE_OPTIONS[k] for k, v in overrides.items() if v is not None and k in MACHINE_OPTIONS]
    if given:
        raise api.ParameterError(f"{', '.join(given)} not for a two-wheeler ({chosen.name}): its parameters are the "
                                 "benchmark's 26 (docs/two-wheeler.md sec. 1.4)", "machine")
    return chosen


#: What ``--units`` can ask of a terminal view (docs/units.md).
UNIT_SYSTEMS = ("as-typed", "si", "metric", "imperial")
#: The units of each system by kind; the API's own (m, kg) are not listed:
#: they are the SI figure itself.
SYSTEM_UNITS = {"metric": {"speed": "km/h", "rate": "rpm"},
                "imperial": {"length": "ft", "speed": "mph", "rate": "rpm", "mass": "lb"}}
#: The kinds a view shows in another unit beside SI.
SHOWN_KINDS = ("length", "speed", "rate", "angle", "mass")


def units_option():
    return single(
        "--units", "units", type=click.Choice(UNIT_SYSTEMS, case_sensitive=False), default=None,
        help="Units of the terminal view, beside SI: as-typed (a value typed with a unit, 16ft or 40km/h, "
             "comes back in it), si (SI alone), metric (m, km/h, rpm, kg) or imperial (ft, mph, rpm, lb) "
             "[default: as-typed].  CSV, JSON and Parquet are SI whatever it says.")


def _typed_unit(text) -> str | None:
    from deathsphere.units import split_unit

    try:
        return split_unit(str(text))[1] if isinstance(text, str) else None
    except ValueError:  # a malformed number: the API says what is wrong with it
        return None


def _factor_words(unit: str, kind: str) -> str:
    """The factor from the API's unit to ``unit`` for a view's source
    column: ``× 3.6`` (km/h), ``÷ 0.3048`` (ft); π's as ``60/2π`` (rpm)."""
    from deathsphere.units import exact_factor

    by_pi = {"rpm": "× 60/2π", "deg/s": "× 180/π", "rad": "× π/180"}
    if unit in by_pi:
        return by_pi[unit]
    f = exact_factor(unit, kind)
    if _decimal(1 / f):
        return f"× {_decimal(1 / f)}"
    return f"÷ {_decimal(f)}" if _decimal(f) else ""


def _decimal(x) -> str:
    """An exact fraction as a decimal of at most 8 places (0.3048), or ''."""
    places = next((k for k in range(9) if (x * 10**k).denominator == 1), None)
    return "" if places is None else repr(float(x)).removesuffix(".0")


def _display_unit(unit: str, kind: str):
    from deathsphere.render.display_units import DisplayUnit
    from deathsphere.units import per_api_unit

    return DisplayUnit(unit, per_api_unit(unit, kind), _factor_words(unit, kind))


def display_units(system: str | None, typed: dict):
    """The :class:`~deathsphere.render.display_units.DisplayUnits` a
    terminal view is handed: ``--units``' ``system`` and the options as
    typed (``typed``: option name -> text, or a tuple of texts, None when
    not given; only the registry's dimensional ones count).

    As typed, an option typed in a unit other than the API's shows in it,
    and a kind's quantities that were not typed (a head clearance) show in
    the one unit every value of that kind was typed in, if there is one.
    A unit that cannot be read is left to the API to refuse."""
    given = []
    for name, value in typed.items():
        p = PARAMS.get(name)
        if p is not None and value is not None and value != ():
            given.append((name, p.kind, value if isinstance(value, tuple) else (value,)))
    return _units_as_typed(system, given)


def plan_display_units(system: str | None, typed: dict):
    """The same for a show: ``typed`` the plan's dimensional values as
    typed, ``{name: (kind, values)}`` (a number in the API's unit, a text
    with its unit), a key typed by several riders being as an option typed
    as a range: shown in its unit when every value was typed in the one
    unit."""
    return _units_as_typed(system, [(name, kind, tuple(values)) for name, (kind, values) in typed.items()])


def _units_as_typed(system: str | None, given):
    """``given``: (name, kind, texts) of each value typed."""
    from deathsphere.render.display_units import DisplayUnits
    from deathsphere.units import KINDS

    system = (system or "as-typed").lower()
    if system == "si":
        return DisplayUnits(crew=False)
    if system in SYSTEM_UNITS:
        return DisplayUnits(kinds={kind: _display_unit(unit, kind) for kind, unit in SYSTEM_UNITS[system].items()},
                            crew=False)
    per_option, per_kind = {}, {}
    for name, kind, texts in given:
        if kind not in SHOWN_KINDS:
            continue
        found = {_typed_unit(text) for text in texts}
        found = {KINDS[kind] if u is None or u == KINDS[kind] else u.strip() for u in found}
        per_kind.setdefault(kind, set()).update(found)
        if len(found) == 1 and found != {KINDS[kind]}:
            per_option[name] = (found.pop(), kind)
    try:
        return DisplayUnits(
            typed={name: _display_unit(unit, kind) for name, (unit, kind) in per_option.items()},
            kinds={kind: _display_unit(units.pop(), kind) for kind, units in per_kind.items()
                   if len(units) == 1 and units != {KINDS[kind]}})
    except ValueError:  # a unit the API refuses (ParameterError), with its reason, once it reads it
        return DisplayUnits()
