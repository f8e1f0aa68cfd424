"""Nutation frequencies from a characteristic polynomial that is quadratic
in w^2 (the paper's biquadratic determinants, eqs. 103, 135, and the exact
reduced polynomial w^4 - e2 w^2 + e4): its roots, and the frequencies where
both are real and positive (stable).  Beyond the paper as code; the
equations are the paper's (sec. 2.3) and docs/stability.md.
"""

from __future__ import annotations

import numpy as np

__all__ = ["quadratic_roots", "both_real_positive", "real_frequencies", "nutation_from_invariants"]


def quadratic_roots(A, B, C):
    """Roots x of A x^2 + B x + C = 0 as complex arrays (larger real part
    first).  Used for omega^2 of the paper's biquadratic determinants.

    Beyond the paper: a numerical tool of the stability analysis (docs/stability.md sec. 1, 3).
    """
    A, B, C = (np.asarray(x, dtype=complex) for x in (A, B, C))
    disc = np.sqrt(B * B - 4 * A * C)
    with np.errstate(divide="ignore", invalid="ignore"):
        x1 = (-B + disc) / (2 * A)
        x2 = (-B - disc) / (2 * A)
    swap = x2.real > x1.real
    return np.where(swap, x2, x1), np.where(swap, x1, x2)


def both_real_positive(x1, x2, rtol=1e-12):
    """True where both roots are real (to rtol) and positive.

    Beyond the paper: a numerical tool of the stability analysis (docs/stability.md sec. 1, 3).
    """
    scale = np.abs(x1) + np.abs(x2)
    real = (np.abs(x1.imag) <= rtol * scale) & (np.abs(x2.imag) <= rtol * scale)
    return real & (x1.real > 0) & (x2.real > 0)


def real_frequencies(x1, x2):
    """Frequencies sqrt(omega^2) (slow, fast) where both roots are real and
    positive, else NaN.

    Beyond the paper: a numerical tool of the stability analysis (docs/stability.md sec. 1, 3).
    """
    ok = both_real_positive(x1, x2)
    lo = np.where(ok, np.minimum(x1.real, x2.real), np.nan)
    hi = np.where(ok, np.maximum(x1.real, x2.real), np.nan)
    with np.errstate(invalid="ignore"):
        return np.sqrt(lo), np.sqrt(hi)


def nutation_from_invariants(e2, e4):
    """Roots w^2 of w^4 - e2 w^2 + e4 = 0 (the reduced characteristic
    polynomial lambda^4 + e2 lambda^2 + e4, lambda = i w): returns
    (x1, x2, stable, slow, fast), the two roots (complex), the verdict (both
    real and positive: e2 > 0, e4 > 0, e2^2 >= 4 e4) and the frequencies.

    Beyond the paper: a numerical tool of the stability analysis (docs/stability.md sec. 1, 3).
    """
    x1, x2 = quadratic_roots(np.ones_like(e2), -e2, e4)
    stable = (e2 > 0) & (e4 > 0) & (e2 * e2 >= 4 * e4)
    slow, fast = real_frequencies(x1, x2)
    return x1, x2, stable, slow, fast
