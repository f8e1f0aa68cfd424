"""Table 1 of McDonald (1993): the printed values and their recomputation.

Provenance: transcribed from the ``table1`` tabular of the paper's LaTeX
source (tests/paper/data/table1.tex holds that environment verbatim, and
tests/paper/test_table1.py checks this transcription against it).  Values are kept as printed strings so
that the printed precision is known: "0.96" has two decimals, "48" none.

Setup of the table: wheel of radius 0.3 m, k = 1/2, inside a sphere of
radius 3.0 m.  The paper does not state g; standard gravity is used (the
printed v_cm agree at their precision for any g in 9.80..9.81 m/s^2).
"""

from __future__ import annotations

import numpy as np

from deathsphere.model import Setup, Table
from deathsphere.table.cells import decimals

#: (theta deg, alpha deg, mu, v_cm m/s, "No. of g's") as printed.
PRINTED = (
    ("15", "5", "16.1", "4.8", "48"),
    ("30", "5", "2.82", "8.0", "53"),
    ("45", "10", "2.15", "7.0", "27"),
    ("60", "10", "1.19", "7.9", "27"),
    ("60", "25", "3.45", "4.9", "10"),
    ("75", "15", "0.96", "6.8", "18"),
    ("75", "30", "2.13", "4.7", "8"),
    ("90", "25", "0.96", "5.3", "10"),
    ("90", "45", "2.04", "3.7", "5"),
    ("135", "60", "0.56", "2.3", "3"),
)


def agrees(computed, printed: str) -> np.ndarray:
    """True where ``computed`` rounds to ``printed`` at the printed precision
    (|computed - printed| <= half a unit in the last printed place)."""
    half_unit = 0.5 * 10.0 ** -decimals(printed)
    return np.abs(np.asarray(computed) - float(printed)) <= half_unit * (1 + 1e-9)


def table1_comparison(setup: Setup | None = None) -> Table:
    """Printed Table 1 beside the values computed from eqs. (29), (35), (36).

    Columns: the printed mu, v_cm and "No. of g's", the computed mu_required,
    v_cm and acceleration (in g and in m/s^2), whether each printed value is
    reproduced at its precision, and a note naming any disagreement.  The
    printed "No. of g's" column is compared both with the acceleration in g
    (what the caption says) and in m/s^2 (what the numbers are; see
    docs/errata.md).
    """
    setup = setup or Setup()
    theta = np.array([float(row[0]) for row in PRINTED])
    alpha = np.array([float(row[1]) for row in PRINTED])
    orbit = setup.orbit(theta, alpha)
    mu, v, acc_g, acc = (orbit[c] for c in ("mu_required", "v_cm_m_s", "accel_g", "accel_m_s2"))
    cols = {
        "theta_deg": theta, "alpha_deg": alpha,
        "mu_printed": np.array([float(r[2]) for r in PRINTED]), "mu_computed": mu,
        "v_cm_printed_m_s": np.array([float(r[3]) for r in PRINTED]), "v_cm_computed_m_s": v,
        "gs_printed": np.array([float(r[4]) for r in PRINTED]),
        "accel_g_computed": acc_g, "accel_m_s2_computed": acc,
    }
    mu_ok = np.array([agrees(mu[i], r[2]) for i, r in enumerate(PRINTED)])
    v_ok = np.array([agrees(v[i], r[3]) for i, r in enumerate(PRINTED)])
    g_is_g = np.array([agrees(acc_g[i], r[4]) for i, r in enumerate(PRINTED)])
    g_is_si = np.array([agrees(acc[i], r[4]) for i, r in enumerate(PRINTED)])
    notes = []
    for i, row in enumerate(PRINTED):
        words = []
        if not mu_ok[i]:
            words.append(f"mu printed {row[2]} but eq. 35 gives {mu[i]:.4g} (last digit; erratum T1-mu)")
        if not v_ok[i]:
            words.append(f"v_cm printed {row[3]} but r' Omega = {v[i]:.3g} m/s")
        if g_is_si[i] and not g_is_g[i]:
            words.append(f"'No. of g's' {row[4]} is the acceleration in m/s^2 ({acc[i]:.3g}); in g it is {acc_g[i]:.3g} (erratum T1-g)")
        elif not g_is_g[i]:
            words.append(f"'No. of g's' {row[4]} matches neither {acc_g[i]:.3g} g nor {acc[i]:.3g} m/s^2")
        notes.append("; ".join(words) if words else "agrees")
    cols.update({
        "mu_agrees": mu_ok, "v_cm_agrees": v_ok,
        "gs_column_is_g": g_is_g, "gs_column_is_m_s2": g_is_si,
        "note": np.array(notes, dtype=object),
    })
    return Table(cols)
