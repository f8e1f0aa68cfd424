"""Zeros of real trigonometric polynomials, all of them, batched.

Beyond the paper (docs/limits.md): every boundary of the region of steady
orbits (:mod:`deathsphere.physics.region`) and every tilt giving a prescribed
speed is the zero set of a real trigonometric polynomial
f(x) = sum_{j=-N..N} h_j exp(i j x) (h_{-j} = conj(h_j)), one row of
coefficients per case.  This module finds those zeros.

Method.  With z = exp(i x), z^N f is an ordinary polynomial of degree 2N whose
unimodular roots (|z| = 1) are the real zeros x = arg z; all 2N roots come
at once as the eigenvalues of its companion matrix (batched over rows, one
``np.linalg.eigvals`` call per effective degree).  The degree of each row is
the outermost harmonic above DEGREE_TOL of the largest coefficient, so a
vanishing leading coefficient does not produce spurious roots at infinity.
Each candidate angle is then refined by bisection inside a bracket whose
ends are the midpoints to its neighbours, so that a sign change is required
and the refined zero satisfies f = 0 to about 1e-15 rad.  No zero of odd
multiplicity can be missed (f has at most 2N zeros per period, and all of
them are candidates); zeros of even multiplicity (tangencies) are not
reported.

:class:`TrigPoly2` builds the polynomials in two angles (theta, alpha) by
arithmetic (products are 2-D convolutions of the coefficient arrays), and
reduces them to rows in one angle at given values of the other.
"""

from __future__ import annotations

import numpy as np

__all__ = ["TWO_PI", "ROOT_XTOL", "MERGE_TOL", "TrigPoly2", "unit_powers", "evaluate_rows",
           "roots_in", "sorted_union", "UNIT_CIRCLE_TOL", "DEGREE_TOL"]

TWO_PI = 2.0 * np.pi

#: Refined roots are bisected to this bracket width [rad].
ROOT_XTOL = 1e-14

#: A root z of the companion polynomial counts as real (|z| = 1) within this.
UNIT_CIRCLE_TOL = 1e-6

#: Coefficients below this fraction of the largest are treated as zero when
#: deciding the degree of a trigonometric polynomial for one theta.
DEGREE_TOL = 1e-13

#: Zeros or breakpoints closer than this [rad] are merged (zero-width cells).
MERGE_TOL = 1e-13


# ---------------------------------------------------------------------------
# bivariate trigonometric polynomials
# ---------------------------------------------------------------------------

class TrigPoly2:
    """f(theta, alpha) = sum h[p, q] exp(i (p - P) theta) exp(i (q - Q) alpha),
    a real trigonometric polynomial of degree P in theta and Q in alpha.
    Products are 2-D convolutions of the coefficient arrays."""

    __slots__ = ("h",)

    def __init__(self, h):
        self.h = np.atleast_2d(np.asarray(h, dtype=complex))

    @property
    def deg(self):
        return (self.h.shape[0] - 1) // 2, (self.h.shape[1] - 1) // 2

    def _padded(self, p, q):
        dp, dq = p - self.deg[0], q - self.deg[1]
        return np.pad(self.h, ((dp, dp), (dq, dq)))

    @staticmethod
    def _lift(x):
        return x if isinstance(x, TrigPoly2) else TrigPoly2([[complex(x)]])

    def __add__(self, other):
        other = self._lift(other)
        p, q = max(self.deg[0], other.deg[0]), max(self.deg[1], other.deg[1])
        return TrigPoly2(self._padded(p, q) + other._padded(p, q))

    __radd__ = __add__

    def __neg__(self):
        return TrigPoly2(-self.h)

    def __sub__(self, other):
        return self + (-self._lift(other))

    def __rsub__(self, other):
        return self._lift(other) - self

    def __mul__(self, other):
        if not isinstance(other, TrigPoly2):
            return TrigPoly2(self.h * complex(other))
        a, b = self.h, other.h
        out = np.zeros((a.shape[0] + b.shape[0] - 1, a.shape[1] + b.shape[1] - 1), dtype=complex)
        for i in range(b.shape[0]):
            for j in range(b.shape[1]):
                if b[i, j] != 0:
                    out[i:i + a.shape[0], j:j + a.shape[1]] += a * b[i, j]
        return TrigPoly2(out)

    __rmul__ = __mul__

    def d_alpha(self):
        """Partial derivative with respect to alpha."""
        q = np.arange(-self.deg[1], self.deg[1] + 1)
        return TrigPoly2(self.h * (1j * q)[None, :])

    def d_theta(self):
        """Partial derivative with respect to theta."""
        p = np.arange(-self.deg[0], self.deg[0] + 1)
        return TrigPoly2(self.h * (1j * p)[:, None])

    def in_alpha(self, theta):
        """Coefficients (n, 2Q+1) of the polynomial in alpha at each theta."""
        theta = np.asarray(theta, dtype=float).reshape(-1)
        return unit_powers(theta, self.deg[0]) @ self.h

    def in_theta(self, alpha):
        """Coefficients (n, 2P+1) of the polynomial in theta at each alpha."""
        alpha = np.asarray(alpha, dtype=float).reshape(-1)
        return unit_powers(alpha, self.deg[1]) @ self.h.T

    def __call__(self, theta, alpha):
        """Values at (theta, alpha), broadcast."""
        th, al = np.broadcast_arrays(np.asarray(theta, dtype=float), np.asarray(alpha, dtype=float))
        rows = self.in_alpha(th.reshape(-1))
        val = np.sum(rows * unit_powers(al.reshape(-1), self.deg[1]), axis=1).real
        return val.reshape(th.shape)


def unit_powers(x, n):
    """exp(i j x) for j = -n .. n, shape (x.size, 2n + 1), by repeated
    multiplication (cheaper than exp of the outer product).

    Beyond the paper: the root finder of docs/limits.md sec. 2.
    """
    z = np.exp(1j * x)
    out = np.empty((x.size, 2 * n + 1), dtype=complex)
    out[:, n] = 1.0
    for j in range(1, n + 1):
        out[:, n + j] = out[:, n + j - 1] * z
        out[:, n - j] = np.conj(out[:, n + j])
    return out


# ---------------------------------------------------------------------------
# univariate evaluation and root finding, batched over rows
# ---------------------------------------------------------------------------

def evaluate_rows(h, x):
    """Real trigonometric polynomial with coefficient rows h (n, 2N+1) at
    x (n, m): sum_j h_j exp(i (j - N) x), taken real.

    Beyond the paper: the root finder of docs/limits.md sec. 2.
    """
    n2 = h.shape[1]
    N = (n2 - 1) // 2
    out = np.broadcast_to(h[:, N:N + 1].real, x.shape).copy()
    for j in range(1, N + 1):
        hj = h[:, N + j:N + j + 1]                     # exp(+i j x) coefficient
        out += 2.0 * (hj.real * np.cos(j * x) - hj.imag * np.sin(j * x))
    return out


def _candidate_roots(h):
    """Angles of the unimodular roots of z^N f(z), rows of h (n, 2N+1).
    Returns (n, 2N) with NaN where a root is not on the unit circle."""
    n, n2 = h.shape
    N = (n2 - 1) // 2
    out = np.full((n, 2 * N), np.nan)
    if N == 0 or n == 0:
        return out
    scale = np.max(np.abs(h), axis=1)
    safe = np.where(scale > 0, scale, 1.0)
    hn = h / safe[:, None]
    # effective degree: the outermost harmonic that is not negligible
    big = np.abs(hn) > DEGREE_TOL
    idx = np.arange(n2)
    eff = np.max(np.where(big, np.abs(idx - N), -1), axis=1)   # -1: f == 0
    for m in range(1, N + 1):
        rows = np.nonzero(eff == m)[0]
        if rows.size == 0:
            continue
        coef = hn[rows, N - m:N + m + 1]               # ascending powers z^0 .. z^2m
        lead = coef[:, -1]
        monic = coef[:, :-1] / lead[:, None]
        comp = np.zeros((rows.size, 2 * m, 2 * m), dtype=complex)
        if m * 2 > 1:
            comp[:, np.arange(1, 2 * m), np.arange(0, 2 * m - 1)] = 1.0
        comp[:, :, -1] = -monic
        z = np.linalg.eigvals(comp)
        on = np.abs(np.abs(z) - 1.0) < UNIT_CIRCLE_TOL
        out[rows, :2 * m] = np.where(on, np.angle(z), np.nan)
    return out


def _refine(h, left, right, fl, fr):
    """Bisection on brackets (n, m) with f(left) f(right) < 0."""
    for _ in range(80):
        width = right - left
        if not np.any(width > ROOT_XTOL * np.maximum(1.0, np.abs(left))):
            break
        mid = 0.5 * (left + right)
        fm = evaluate_rows(h, mid)
        same = np.sign(fm) == np.sign(fl)
        exact = fm == 0
        left = np.where(same | exact, mid, left)
        fl = np.where(same, fm, fl)
        right = np.where(same & ~exact, right, mid)
    return 0.5 * (left + right)


def roots_in(h, lo, hi):
    """All zeros of odd multiplicity of the real trigonometric polynomials
    with coefficient rows h (n, 2N+1) in the windows [lo, hi] (arrays (n,),
    hi - lo <= 2 pi).  Returns (n, m) sorted, NaN-padded.

    Beyond the paper: the root finder of docs/limits.md sec. 2.
    """
    h = np.asarray(h, dtype=complex)
    n = h.shape[0]
    lo = np.broadcast_to(np.asarray(lo, dtype=float), (n,))
    hi = np.broadcast_to(np.asarray(hi, dtype=float), (n,))
    ang = _candidate_roots(h)
    if ang.shape[1] == 0:
        return np.full((n, 0), np.nan)
    pad = 1e-7
    d = np.mod(ang - lo[:, None] + pad, TWO_PI) - pad
    cand = lo[:, None] + d
    cand = np.where(np.isfinite(cand) & (cand <= hi[:, None] + pad), cand, np.nan)
    cand = np.sort(cand, axis=1)
    m = cand.shape[1]
    # brackets: from the midpoint to the previous candidate to the midpoint
    # to the next one (window ends at the extremes)
    mids = 0.5 * (cand[:, :-1] + cand[:, 1:])
    left = np.concatenate([lo[:, None], mids], axis=1)
    right = np.concatenate([mids, np.full((n, 1), np.nan)], axis=1)
    right = np.where(np.isnan(right), hi[:, None], right)
    left = np.clip(left, lo[:, None], hi[:, None])
    right = np.clip(right, lo[:, None], hi[:, None])
    valid = np.isfinite(cand)
    left = np.where(valid, left, lo[:, None])
    right = np.where(valid, right, lo[:, None])
    fl = evaluate_rows(h, left)
    fr = evaluate_rows(h, right)
    zero_l = valid & (fl == 0)
    zero_r = valid & (fr == 0) & ~zero_l
    bracket = valid & (fl * fr < 0)
    root = _refine(h, np.where(bracket, left, 0.0), np.where(bracket, right, 0.0),
                   np.where(bracket, fl, 1.0), np.where(bracket, fr, -1.0))
    root = np.where(bracket, root, np.nan)
    root = np.where(zero_l, left, root)
    root = np.where(zero_r, right, root)
    root = np.sort(root, axis=1)
    # a root at a bracket end may have been found twice
    dup = np.zeros_like(root, dtype=bool)
    dup[:, 1:] = np.abs(np.diff(root, axis=1)) <= MERGE_TOL
    root = np.sort(np.where(dup, np.nan, root), axis=1)
    keep = max(1, int(np.max(np.sum(np.isfinite(root), axis=1), initial=0)))
    return root[:, :min(keep, m)]


def sorted_union(arrays, n):
    """Concatenate NaN-padded (n, m_i) arrays and sort each row (NaN last).

    Beyond the paper: the root finder of docs/limits.md sec. 2.
    """
    arrays = [np.asarray(x, dtype=float).reshape(n, -1) for x in arrays]
    if not arrays:
        return np.full((n, 0), np.nan)
    out = np.sort(np.concatenate(arrays, axis=1), axis=1)
    width = int(np.max(np.sum(np.isfinite(out), axis=1), initial=0))
    return out[:, :width]
