"""Every applicable stability result of the paper beside the exact one, per
horizontal orbit of a wheel: the numbers behind ``deathsphere stability``
(beyond the paper; docs/stability.md).  Pure: arrays in, arrays out; the
report's prose is built in :mod:`deathsphere.results.stability_report`.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.geometry import r_prime
from deathsphere.physics.stability.closed_forms import equator_exact_closed_form
from deathsphere.physics.stability.horizontal import wheel_stability
from deathsphere.physics.stability.paper import (
    equator_paper,
    near_pole_paper,
    small_wheel_corrected,
    small_wheel_paper,
)
from deathsphere.physics.stability.verdict import Verdict

__all__ = ["SMALL_WHEEL_VALIDITY", "EQUATOR_TOL", "compare_with_paper"]


def _rel(x, ref):
    with np.errstate(divide="ignore", invalid="ignore"):
        return (x - ref) / np.abs(ref)


#: a/|r'| below which the small-wheel results (eq. 201, a << r'_0) are
#: flagged as applicable in :func:`compare_with_paper`.
SMALL_WHEEL_VALIDITY = 0.05
#: |theta - pi/2| [rad] within which an orbit counts as "on the equator".
EQUATOR_TOL = 1e-9


def compare_with_paper(theta, alpha, a, r, k, g, outside=False):
    """Every applicable stability result of the paper beside the exact one,
    per horizontal orbit of a wheel (for the ``stability`` command).

    Returns ``(exact, results)``: ``exact`` is the dict of
    :func:`wheel_stability`; ``results`` maps a result name to a dict with

    ``equation`` (str) the paper's equation(s), ``quantity`` (str) what is
    compared, ``units``, ``paper`` (array) the paper's value as printed,
    ``corrected`` (array) the corrected formula's value (NaN if none),
    ``exact`` (array) the exact value, ``deviation`` (array) relative
    deviation (paper - exact)/|exact| for frequencies, or 0/1 (agree /
    disagree) for verdicts, ``corrected_deviation`` likewise,
    ``applies`` (bool array) where the paper states the result holds
    (elsewhere the arrays hold NaN, and UNKNOWN for verdicts),
    ``validity`` (array) the measure of its approximation (NaN if exact
    in principle), ``note`` (str).

    Names: ``equator_slow``, ``equator_fast``, ``equator_verdict``
    (eqs. 133-138, theta = pi/2); ``small_wheel_slow``, ``small_wheel_fast``,
    ``small_wheel_verdict`` (eqs. 201-207; validity a/|r'|);
    ``near_pole_verdict`` (eq. 208, r' <= a).  Verdict arrays hold
    :class:`Verdict` codes.  All apply to the wheel inside only (sec. 2.3;
    sec. 3 says the analysis carries over "formally" but gives no result).
    Fit/contact are not checked: combine with
    :func:`deathsphere.physics.wheel.horizontal_orbit`.
    """
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (theta, alpha, a, r, k, g)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    ex = wheel_stability(theta, alpha, a, r, k, g, outside)
    exists = np.isfinite(ex["growth_rate"])
    S, U, N = Verdict.STABLE, Verdict.UNSTABLE, Verdict.UNKNOWN

    def verdict_of(stable_bool, defined):
        return np.where(defined, np.where(stable_bool, S, U), N).astype(np.int8)

    inside = ~outside        # sec. 2.3 is about the wheel inside (sec. 3: "formally" only)
    on_eq = (np.abs(theta - np.pi / 2) <= EQUATOR_TOL) & inside
    eqp = equator_paper(alpha, a, r, k, g)
    eqc = equator_exact_closed_form(alpha, a, r, k, g)
    eq_def = np.isfinite(eqp["Omega"]) & exists
    sw = small_wheel_paper(theta, alpha, a, r, k, g)
    swc = small_wheel_corrected(theta, alpha, a, r, k, g)
    np_ = near_pole_paper(theta, alpha, a, r, k, g)
    sw_def = exists & np.isfinite(sw["omega2_first"]) & inside
    results = {
        "equator_slow": dict(
            equation="133-138", quantity="slow nutation frequency", units="rad/s",
            paper=eqp["freq_slow"], corrected=eqc["freq_slow"], exact=ex["freq_slow"],
            applies=on_eq & eq_def, validity=np.full(theta.shape, np.nan),
            note="printed eq. (133) drops the tilt of axis 3 out of the t-u plane (E4)"),
        "equator_fast": dict(
            equation="133-138", quantity="fast nutation frequency", units="rad/s",
            paper=eqp["freq_fast"], corrected=eqc["freq_fast"], exact=ex["freq_fast"],
            applies=on_eq & eq_def, validity=np.full(theta.shape, np.nan),
            note="printed eq. (133) drops the tilt of axis 3 out of the t-u plane (E4)"),
        "equator_verdict": dict(
            equation="135", quantity="verdict (both w^2 real > 0)", units="",
            paper=verdict_of(eqp["stable_printed"], eq_def),
            corrected=verdict_of(eqc["stable"], eq_def), exact=ex["verdict"],
            applies=on_eq & eq_def, validity=np.full(theta.shape, np.nan),
            note="the paper: all equatorial orbits stable"),
        "small_wheel_slow": dict(
            equation="207", quantity="slow nutation frequency", units="rad/s",
            paper=sw["freq"], corrected=swc["freq_slow"], exact=ex["freq_slow"],
            applies=sw_def & (sw["validity"] <= SMALL_WHEEL_VALIDITY), validity=sw["validity"],
            note="eq. (207) inherits E4; corrected: Omega^2 [1 + 3 sin a tan a sin th / sin(th - a)] (E5)"),
        "small_wheel_fast": dict(
            equation="(none)", quantity="fast nutation frequency", units="rad/s",
            paper=np.full(theta.shape, np.nan), corrected=swc["freq_fast"], exact=ex["freq_fast"],
            applies=sw_def & (sw["validity"] <= SMALL_WHEEL_VALIDITY), validity=sw["validity"],
            note="the paper gives no fast mode; corrected: 2(2k+1)/(k+1) (r' Omega/a)^2"),
        "small_wheel_verdict": dict(
            equation="207", quantity="verdict (w^2 > 0)", units="",
            paper=verdict_of(sw["stable_printed"], sw_def),
            corrected=verdict_of((swc["omega2_slow"] > 0) & (swc["omega2_fast"] > 0), sw_def),
            exact=ex["verdict"],
            applies=sw_def & (sw["validity"] <= SMALL_WHEEL_VALIDITY), validity=sw["validity"],
            note="the paper: all small-wheel orbits stable"),
        "near_pole_verdict": dict(
            equation="208", quantity="verdict (Omega^2 > threshold)", units="",
            paper=verdict_of(np_["stable_printed"], exists),
            corrected=verdict_of(np_["stable_disk"], exists), exact=ex["verdict"],
            applies=np_["applies"] & exists & inside,
            validity=np.abs(r_prime(theta, alpha, a, r)) / a,
            note="eq. (208) is the rolling-disk criterion offered by analogy; "
                 "the disk's own threshold is g/(2(2k+1)a) (E6)"),
    }
    for res in results.values():
        _restrict(res, ex["verdict"])
    return ex, results


def _restrict(res, exact_verdict):
    """Add the deviations to one result of :func:`compare_with_paper` and
    blank every array where the result does not apply (NaN; UNKNOWN for
    verdicts)."""
    ap = res["applies"]
    if res["units"]:
        res["deviation"] = _rel(res["paper"], res["exact"])
        res["corrected_deviation"] = _rel(res["corrected"], res["exact"])
        for key in ("paper", "corrected", "exact", "deviation", "corrected_deviation"):
            res[key] = np.where(ap, res[key], np.nan)
    else:
        res["deviation"] = np.where(ap, _disagree(res["paper"], exact_verdict), np.nan)
        res["corrected_deviation"] = np.where(ap, _disagree(res["corrected"], exact_verdict), np.nan)
        for key in ("paper", "corrected", "exact"):
            res[key] = np.where(ap, res[key], Verdict.UNKNOWN).astype(np.int8)


def _disagree(v, exact_verdict):
    """1.0 where two known verdicts differ, 0.0 where they agree, NaN where
    either is unknown."""
    N = Verdict.UNKNOWN
    known = (v != N) & (exact_verdict != N)
    return np.where(known, (v != exact_verdict).astype(float), np.nan)
