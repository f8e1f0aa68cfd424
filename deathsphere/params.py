"""Every input parameter of every command, its unit and its allowed values,
defined once and checked once (docs/contract.md, "Inputs").

The command line, ``--input`` rows and the Python API all validate through
this module: :func:`problems` checks a whole array of values at once (no
loop over rows) and returns the reason each value is refused ('' where it
is fine); :func:`check` does the same for one value and raises
:class:`ParameterError` with the one-line message the command line prints.

Why the magnitude bounds: every dimensional input lies within 1e-9..1e9 of
its SI unit.  Products of a few such numbers (Omega^2 r', v^2 / r', ...)
then stay far inside float64's range, so no result of an accepted input
overflows to inf or underflows to a denormal; a wheel of 1e-320 m or a spin
of 1e308 rad/s is refused with the reason, instead of giving ``inf`` in a
row marked ``ok``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: Dimensional inputs lie within [TINY, HUGE] in magnitude (see above).
TINY = 1e-9
HUGE = 1e9
#: The least relative tolerance scipy's solve_ivp honours (100 eps, about
#: 2.2e-14): it silently raises any smaller rtol to this, with a warning,
#: so a smaller one is refused rather than reported as if it had been used.
RTOL_MIN = 100 * np.finfo(float).eps


class ParameterError(ValueError):
    """An input value outside its allowed set; the message is one line
    saying what is wrong and what is allowed.  ``param`` names the
    parameter at fault (as in the API and the command line's ``--name``),
    or is None for a rule between several; ``missing`` says that it was
    required and not given."""

    def __init__(self, message: str, param: str | None = None, missing: bool = False):
        super().__init__(message)
        self.param = param
        self.missing = missing


@dataclass(frozen=True)
class Param:
    """One input: ``name`` as in the API and CLI (``--name``), ``unit``,
    what it is, and its allowed interval ``[lo, hi]`` (``lo_open`` /
    ``hi_open`` exclude an end).  ``nonzero`` refuses 0 (a signed rate);
    ``allow_inf`` accepts +inf ("no limit"); ``integer`` wants whole numbers."""

    name: str
    unit: str
    what: str
    lo: float
    hi: float
    lo_open: bool = False
    hi_open: bool = False
    nonzero: bool = False
    allow_inf: bool = False
    integer: bool = False

    def label(self) -> str:
        """``name (what)``, e.g. ``a (body radius)``."""
        return f"{self.name} ({self.what})"

    def allowed(self) -> str:
        """The allowed values in words, e.g. ``1e-09..1e+09 m``."""
        unit = f" {self.unit}" if self.unit else ""
        if self.allow_inf:
            return f">= {self.lo:g} or inf (no limit)"
        if self.integer:
            return f"a whole number {self.lo:g}..{self.hi:g}"
        if self.lo == -self.hi:
            lead = f"-{self.hi:g}..{self.hi:g}{unit}"
            return lead + (" and not 0" if self.nonzero else "")
        left = f"> {self.lo:g}" if self.lo_open else f"{self.lo:g}"
        if self.lo_open:
            return f"{left} and <= {self.hi:g}{unit}" if not self.hi_open else f"{left} and < {self.hi:g}{unit}"
        return f"{left}..{self.hi:g}{unit}" + (" (end excluded)" if self.hi_open else "")


def _positive(name, unit, what):
    return Param(name, unit, what, TINY, HUGE)


#: Every parameter, by name.  Angles are in degrees, as on the command line.
PARAMS: dict[str, Param] = {p.name: p for p in (
    Param("theta", "deg", "polar angle", 0.0, 180.0),
    # any angle is accepted and reduced to (-180, 180] for the physics
    Param("alpha", "deg", "tilt", -1e6, 1e6),
    _positive("a", "m", "body radius"),
    _positive("r", "m", "sphere radius"),
    Param("k", "", "inertia factor", 0.0, 1e3),
    _positive("g", "m/s^2", "gravity"),
    Param("mu", "", "friction coefficient", 0.0, math.inf, allow_inf=True),
    Param("max_g", "g", "largest g-load", TINY, math.inf, allow_inf=True),
    Param("omega3", "rad/s", "spin", -HUGE, HUGE),
    Param("omega", "rad/s", "orbital rate", -HUGE, HUGE, nonzero=True),
    _positive("speed", "m/s", "centre speed"),
    Param("v_top", "m/s", "top speed", 0.0, HUGE),
    Param("phidot_top", "rad/s", "top rate", 0.0, HUGE),
    Param("a_over_r", "", "body radius over sphere radius", TINY, HUGE),
    Param("step", "deg", "theta step", 0.001, 10.0),
    Param("points", "", "points per orbit", 2, 1_000_000, integer=True),
    Param("periods", "", "run length in periods", 0.0, 1e6, lo_open=True),
    Param("points_per_period", "", "rows per period", 2, 100_000, integer=True),
    Param("perturb", "deg", "kick", -60.0, 60.0),
    Param("rtol", "", "relative tolerance", RTOL_MIN, 1e-2),
    Param("atol", "", "absolute tolerance", 1e-16, 1.0),
    Param("max_steps", "", "step budget", 1, 1e15, integer=True),
    Param("jobs", "", "processes", 1, 256, integer=True),
    Param("chunk_size", "", "orbits evaluated per chunk", 1, 10_000_000, integer=True),
)}


def _words(p: Param, value) -> str:
    shown = f"{value:g}" if isinstance(value, float) else repr(value)
    return f"{p.label()} must be {p.allowed()} (got {shown})"


def problems(name: str, values) -> np.ndarray:
    """Why each of ``values`` is not an allowed ``name`` ('' where it is).

    Vectorised: masks decide which values fail, words are built only for
    those.  NaN counts as missing and is the caller's business (a batch
    fills defaults first), so it is refused here too: 'not a number'.
    """
    p = PARAMS[name]
    v = np.asarray(values, dtype=float).reshape(-1)
    out = np.full(v.size, "", dtype=object)
    with np.errstate(invalid="ignore"):
        bad = np.isnan(v) | (np.isinf(v) & ~(p.allow_inf & (v > 0)))
        inside = (v > p.lo if p.lo_open else v >= p.lo) & (v < p.hi if p.hi_open else v <= p.hi)
        bad |= ~inside
        if p.nonzero:
            bad |= v == 0
        if p.integer:
            bad |= np.isfinite(v) & (v != np.round(v))
    for i in np.flatnonzero(bad):
        out[i] = (f"{p.label()} must be a finite number ({p.allowed()})" if not np.isfinite(v[i])
                  and not (p.allow_inf and v[i] > 0) else _words(p, float(v[i])))
    return out


def check(name: str, value) -> float:
    """``value`` as a float if it is an allowed ``name``; else
    :class:`ParameterError` with the one-line reason."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        try:
            value = float(value)
        except (TypeError, ValueError):
            raise ParameterError(f"{name} must be a number (got {value!r})", name) from None
    reason = problems(name, [value])[0]
    if reason:
        raise ParameterError(reason, name)
    return float(value)


def first_problem(name: str, values) -> str:
    """The first reason among ``values`` ('' if all are allowed)."""
    reasons = problems(name, values)
    hit = np.flatnonzero(reasons != "")
    return str(reasons[hit[0]]) if hit.size else ""


def reduce_angle(deg):
    """An angle in degrees reduced to (-180, 180]: the physics is periodic in
    alpha, and the tilt may be given either way round (205 = -155)."""
    x = np.asarray(deg, dtype=float)
    r = 180.0 - np.mod(180.0 - x, 360.0)
    return r if r.ndim else float(r)


def choice(name: str, value: str, allowed) -> str:
    """``value`` lower-cased if it is one of ``allowed``; else ParameterError."""
    text = str(value).strip().lower()
    if text not in allowed:
        raise ParameterError(f"{name} must be one of {' | '.join(allowed)} (got {value!r})", name)
    return text
