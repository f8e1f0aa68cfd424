"""One orbit's stability: the exact answer beside each of the paper's results.

Beyond the paper for the exact part (docs/stability.md sec. 1); the paper's
results are eqs. (133)-(138) (equator), (202)-(207) (small wheels) and (208)
(near the poles), each as printed and as corrected, with where it applies
and how far it is from the exact value.  Physics:
:func:`deathsphere.physics.stability.compare_with_paper`.
"""

from __future__ import annotations

import numpy as np

from deathsphere import params
from deathsphere.model import EXACT_METHOD, LIVE_STATUSES
from deathsphere.physics.stability.methods import method_text
from deathsphere.physics import stability as exact_stability
from deathsphere.records.paper_bodies import WHEEL
from deathsphere.requests.decode import paper_body_codes
from deathsphere.table import Table

#: The report's columns (appended to, never reordered: input_row, body and
#: branch came when the report took several orbits at once).
COLUMNS = ("theta_deg", "alpha_deg", "source", "equation", "quantity", "units", "applies", "validity",
           "paper", "corrected", "exact", "deviation", "note", "side", "a_m", "r_m", "k", "g_m_s2",
           "validity_limit", "input_row", "body", "branch")

_VERDICT = exact_stability.VERDICT_LABELS

#: The exact rows: (quantity, orbit-table column, units).
_EXACT = (("growth rate (max Re of the eigenvalues)", "growth_rate_1_s", "1/s"),
          ("slow nutation frequency", "freq_slow_rad_s", "rad/s"),
          ("fast nutation frequency", "freq_fast_rad_s", "rad/s"),
          ("verdict", "stability", ""))
_EXACT_NOTE = "docs/stability.md sec. 1 (frequencies in the frame turning with the orbit)"


def _cells(values, verdict: bool) -> np.ndarray:
    """Report cells (object) from a result array: verdict codes as labels, NaN as None."""
    values = np.asarray(values)
    if verdict:
        return np.asarray(_VERDICT, dtype=object)[values.astype(int)]
    out = values.astype(object)
    out[np.isnan(values.astype(float))] = None
    return out


def stability_report(orbits: Table) -> Table:
    """The stability report of every orbit of ``orbits`` (the table of
    :func:`deathsphere.model.evaluate` with its stability columns), orbit
    after orbit.

    Each orbit gives the exact rows -- its status, then the growth rate,
    the two nutation frequencies and the verdict of the exact linearisation
    (read from the orbit's stability columns) -- and, for a wheel whose
    orbit exists with contact, every paper result: ``applies`` says whether
    its premise holds here; ``validity`` is the parameter that decides it
    (a/r' for small wheels, |r'|/a near the poles), ``validity_limit`` the
    value up to which it applies; ``deviation`` is (paper - exact)/exact, or
    1/0 for a verdict that differs/agrees.  A sphere's orbits have only the
    exact rows (the paper's stability results are the wheel's).  Vectorised:
    one call of :func:`deathsphere.physics.stability.compare_with_paper`
    for every wheel orbit.
    """
    n = len(orbits)
    status, reason = orbits["status"].astype(object), orbits["reason"].astype(object)
    live = np.isin(status, LIVE_STATUSES)
    analysed = live & (orbits["stability_method"] == EXACT_METHOD)
    why_not = np.where(live, [method_text(m) for m in orbits["stability_method"].tolist()],
                       [f"no steady orbit with contact here ({s}: {w})" for s, w in zip(status, reason)])
    blank = np.full(n, None, dtype=object)
    kinds = [dict(source="exact", equation="0 29 33", quantity="orbit status", units="", applies=np.ones(n, bool),
                  validity=blank, paper=blank, corrected=blank, exact=status, deviation=blank,
                  note=np.where(reason == "", "a steady orbit with contact", reason), validity_limit=blank,
                  present=np.ones(n, bool))]
    for quantity, column, units in _EXACT:
        cells = orbits[column].astype(object) if column == "stability" else _cells(orbits[column], False)
        kinds.append(dict(source="exact", equation="2-7b linearised", quantity=quantity, units=units,
                          applies=analysed, validity=blank, paper=blank, corrected=blank,
                          exact=np.where(analysed, cells, None), deviation=blank,
                          note=np.where(analysed, _EXACT_NOTE, why_not), validity_limit=blank,
                          present=np.ones(n, bool)))
    wheels = np.flatnonzero(analysed & (paper_body_codes(orbits["body"]) == WHEEL.code))
    if wheels.size:
        theta = np.deg2rad(orbits["theta_deg"][wheels])
        alpha = np.deg2rad(params.reduce_angle(orbits["alpha_deg"][wheels]))
        _, results = exact_stability.compare_with_paper(
            theta, alpha, orbits["a_m"][wheels], orbits["r_m"][wheels], orbits["k"][wheels],
            orbits["g_m_s2"][wheels], outside=orbits["side"][wheels] == "outside")
        present = np.zeros(n, bool)
        present[wheels] = True
        for name, res in results.items():
            verdict = name.endswith("verdict")

            def spread(values, fill=None):
                out = np.full(n, fill, dtype=object)
                out[wheels] = values
                return out
            validity = np.asarray(res["validity"], dtype=float)
            limit = exact_stability.SMALL_WHEEL_VALIDITY if "small_wheel" in name else 1.0
            kinds.append(dict(
                source=f"paper: {name.rsplit('_', 1)[0].replace('_', ' ')}", equation=res["equation"],
                quantity=res["quantity"], units=res["units"], applies=spread(np.asarray(res["applies"], bool), False),
                validity=spread(_cells(validity, False)),
                paper=spread(_cells(res["paper"], verdict)), corrected=spread(_cells(res["corrected"], verdict)),
                exact=spread(_cells(res["exact"], verdict)), deviation=spread(_cells(res["deviation"], False)),
                note=res["note"],
                # the premise holds for validity below this (a/r' for small wheels, r'/a near the poles)
                validity_limit=spread(np.where(np.isnan(validity), None, limit).astype(object)),
                present=present))
    # orbit after orbit: a (orbits x kinds) grid read row-major, rows absent for an orbit dropped
    present = np.stack([np.broadcast_to(kind["present"], n) for kind in kinds], axis=1).reshape(-1)
    which = np.repeat(np.arange(n), len(kinds))[present]

    def column(key):
        grid = np.empty((n, len(kinds)), dtype=object)
        for j, kind in enumerate(kinds):
            grid[:, j] = np.broadcast_to(np.asarray(kind[key], dtype=object), n)
        return grid.reshape(-1)[present]
    table = {key: column(key) for key in ("source", "equation", "quantity", "units", "applies", "validity",
                                          "paper", "corrected", "exact", "deviation", "note", "validity_limit")}
    table["applies"] = table["applies"].astype(bool)
    for name in ("theta_deg", "alpha_deg", "a_m", "r_m", "k", "g_m_s2"):
        table[name] = np.asarray(orbits[name], dtype=float)[which]
    table["side"] = orbits["side"].astype(object)[which]
    table["body"] = orbits["body"].astype(object)[which]
    table["input_row"] = np.asarray(orbits["input_row"], dtype=np.int64)[which]
    table["branch"] = orbits["branch"].astype(object)[which]
    return Table({name: table[name] for name in COLUMNS})
