"""One orbit's stability: the exact answer beside each of the paper's results.

Beyond the paper for the exact part (docs/stability.md sec. 1); the paper's
results are eqs. (133)-(138) (equator), (202)-(207) (small wheels) and (208)
(near the poles), each as printed and as corrected, with where it applies
and how far it is from the exact value.  Physics:
:func:`deathsphere.physics.stability.compare_with_paper`.
"""

from __future__ import annotations

import math

import numpy as np

from deathsphere import params
from deathsphere.model import Setup, Table, evaluate, make_requests
from deathsphere.physics import stability as exact_stability

COLUMNS = ("theta_deg", "alpha_deg", "source", "equation", "quantity", "units", "applies", "validity",
           "paper", "corrected", "exact", "deviation", "note", "side", "a_m", "r_m", "k", "g_m_s2",
           "validity_limit")

_VERDICT = exact_stability.VERDICT_LABELS


def _value(x, verdict: bool):
    x = np.asarray(x).item()
    if verdict:
        return str(_VERDICT[int(x)])
    return None if (isinstance(x, float) and math.isnan(x)) else float(x)


def stability_report(setup: Setup, theta_deg: float, alpha_deg: float) -> Table:
    """Rows: the exact growth rate, nutation frequencies and verdict, then
    every paper result (``applies`` says whether its premise holds here;
    ``validity`` is the parameter that decides it: a/r' for small wheels,
    applying up to SMALL_WHEEL_VALIDITY, and |r'|/a near the poles, applying
    up to 1, the limit given as ``validity_limit``; ``deviation`` is (paper - exact)/exact, or 1/0 for a verdict
    that differs/agrees)."""
    theta, alpha = math.radians(theta_deg), math.radians(params.reduce_angle(alpha_deg))
    orbit = evaluate(make_requests(1, body="wheel", side=setup.side, theta=theta_deg, alpha=alpha_deg, a=setup.a,
                                   r=setup.r, k=setup.k, g=setup.g, mu=setup.mu), stability=False)
    status, reason = str(orbit["status"][0]), str(orbit["reason"][0])
    exists = status in ("ok", "slips")
    # without a steady orbit with contact (or at k = 0, where the equations
    # of motion are singular) there is nothing to linearise about
    analysed = exists and setup.k > 0
    why_not = (f"no steady orbit with contact here ({status}: {reason})" if not exists
               else "not analysed: k = 0 makes the equations of motion singular")
    exact, results = ({}, {}) if not analysed else exact_stability.compare_with_paper(
        theta, alpha, setup.a, setup.r, setup.k, setup.g, outside=setup.side == "outside")
    rows = [{"source": "exact", "equation": "0, 29, 33", "quantity": "orbit status", "units": "",
             "applies": True, "validity": None, "paper": None, "corrected": None, "exact": status,
             "deviation": None, "note": reason or "a steady orbit with contact"}]
    for quantity, key, units in (("growth rate, max Re(eigenvalue)", "growth_rate", "1/s"),
                                 ("slow nutation frequency", "freq_slow", "rad/s"),
                                 ("fast nutation frequency", "freq_fast", "rad/s"),
                                 ("verdict", "verdict", "")):
        rows.append({"source": "exact", "equation": "2-7b linearised", "quantity": quantity, "units": units,
                     "applies": analysed, "validity": None, "paper": None, "corrected": None,
                     "exact": _value(exact[key], key == "verdict") if analysed else None, "deviation": None,
                     "note": "docs/stability.md sec. 1 (frequencies in the frame turning with the orbit)"
                     if analysed else why_not})
    for name, res in results.items():
        verdict = name.endswith("verdict")
        validity = np.asarray(res["validity"]).item()
        rows.append({"source": f"paper: {name.rsplit('_', 1)[0].replace('_', ' ')}", "equation": res["equation"],
                     "quantity": res["quantity"], "units": res["units"], "applies": bool(res["applies"]),
                     "validity": None if math.isnan(validity) else validity,
                     # the premise holds for validity below this (a/r' for small wheels, r'/a near the poles)
                     "validity_limit": None if math.isnan(validity) else (
                         exact_stability.SMALL_WHEEL_VALIDITY if "small_wheel" in name else 1.0),
                     "paper": _value(res["paper"], verdict), "corrected": _value(res["corrected"], verdict),
                     "exact": _value(res["exact"], verdict),
                     "deviation": _value(res["deviation"], False), "note": res["note"]})
    table = {name: np.array([row.get(name) for row in rows], dtype=object) for name in COLUMNS}
    table["theta_deg"] = np.full(len(rows), float(theta_deg))
    table["alpha_deg"] = np.full(len(rows), float(alpha_deg))
    # the orbit's setup echoed, as every command echoes its inputs
    table["side"] = np.full(len(rows), setup.side, dtype=object)
    for name, value in (("a_m", setup.a), ("r_m", setup.r), ("k", setup.k), ("g_m_s2", setup.g)):
        table[name] = np.full(len(rows), float(value))
    return Table(table)
