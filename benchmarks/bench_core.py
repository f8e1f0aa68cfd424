"""Core throughput of the horizontal-orbit physics.

Measures orbits per second for the full output of
``deathsphere.physics.wheel.horizontal_orbit`` (r', Omega^2, Omega, period,
v_cm, spin, omega_3, accel, g-load, normal and friction force, mu_required,
status, reason) and compares it with

  (a) a straightforward per-orbit Python loop using the ``math`` module that
      computes the same quantities (the floor a vectorised core must beat);
  (b) a fused kernel of the same formulas compiled with numba, one pass per
      orbit and no temporaries (the practical ceiling; skipped with a message
      when numba is not installed), timed both writing into buffers reused
      from call to call and allocating its outputs per call as the core must;
  (c) ``fast_horizontal_orbit`` below: a hand-optimised numpy variant (sines
      and cosines computed once, scalar parameters kept scalar, no
      boolean-mask scatter for the status, temporaries reused via out=,
      internal chunking).  It motivated the changes now in wheel.py and is
      kept as the "how far can plain numpy go" reference;
  (d) with ``--old REV``: wheel.horizontal_orbit and status.first_failure as
      of git revision REV (read with ``git show``, nothing is checked out),
      for a before/after in the same run.

Each variant is checked against wheel.horizontal_orbit on a sample before it
is timed (same statuses, reasons, and values to 1e-12 relative), so the
figures compare equal work.  Each figure is the best of 2-3 runs (the
machine may be shared).  The core is timed on the whole array at once
(it chunks internally, wheel.CHUNK orbits) and fed by the caller in chunks
(2^14, 2^16 orbits), and with the per-row parameter arrays the model passes.
At the end, "where the time goes" on one chunk and the gap to the numba
kernel split into trigonometry, the rest of the arithmetic, and writing the
outputs.

Goals: core within 1.5x of the fused kernel, and >= 10x the loop.

Run:  python benchmarks/bench_core.py                 (10^7 orbits, ~1 min)
      python benchmarks/bench_core.py --old b3e6fb1   (and the core before the optimisation, ~2 min)
      python benchmarks/bench_core.py --n 1000000     (quicker)
"""

from __future__ import annotations

import argparse
import math
import subprocess
import sys
import time
import types
from pathlib import Path

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics import wheel
from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.status import Reason, Status, first_failure

A, R, K, G = 0.3, 3.0, 0.5, STANDARD_GRAVITY   # Table 1's wheel and sphere
KEYS = ("r_prime", "omega2", "omega", "period", "v_cm", "spin", "accel", "accel_g",
        "normal", "friction", "mu_required", "omega3")

# status / reason codes as plain ints (for the loop and the numba kernel)
S_OK, S_NO_FIT, S_NO_ORBIT, S_NO_CONTACT, S_SLIPS = (int(Status.OK), int(Status.NO_FIT),
                                                    int(Status.NO_ORBIT), int(Status.NO_CONTACT),
                                                    int(Status.SLIPS))
R_NONE = int(Reason.NONE)
R_FIT_IN, R_FIT_OUT = int(Reason.NO_FIT_INSIDE), int(Reason.NO_FIT_OUTSIDE)
R_IN_PLANE, R_ZERO_DEN = int(Reason.ALPHA_IN_ORBIT_PLANE), int(Reason.ZERO_DENOMINATOR)
R_OM_ZERO, R_OM_IMAG = int(Reason.OMEGA_ZERO), int(Reason.OMEGA_IMAGINARY)
R_CONTACT_IN, R_CONTACT_OUT = int(Reason.NO_CONTACT_INSIDE), int(Reason.NO_CONTACT_OUTSIDE)
R_SLIPS = int(Reason.SLIPS)


# ---------------------------------------------------------------------------
# (a) per-orbit Python loop with math
# ---------------------------------------------------------------------------

def orbit_python(theta, alpha, a, r, k, g, outside=False, mu=math.inf):
    """One orbit, the formulas of wheel.horizontal_orbit with the math module."""
    nan = math.nan
    st, ct = math.sin(theta), math.cos(theta)
    sa, ca = math.sin(alpha), math.cos(alpha)
    rp = r * st - a * ca
    fits = math.sin(alpha - theta) > 0.0 if outside else math.sin(theta - alpha) > a / r
    den = sa * ((2 * k + 1) * rp + k * a * ca)
    undefined = abs(den) <= SINGULAR * ((2 * k + 1) * r + (k + 1) * a)
    om2 = nan if undefined else g * ca / den
    om2_zero = (not undefined) and abs(om2) <= SINGULAR * g / r
    real = (not undefined) and (not om2_zero) and om2 > 0
    if real:
        omega = math.sqrt(om2)
        period = 2 * math.pi / omega
        cen = rp * om2
        f_r = -(cen * st - g * ct)
        f_t = -(cen * ct + g * st)
        normal = f_r if outside else -f_r
        mu_req = abs(f_t) / normal if normal > 0 else nan
        v_cm, spin, accel = abs(rp) * omega, rp * omega / a, abs(rp) * om2
        accel_g = accel / g
        omega3 = -omega * sa
    else:
        omega = period = f_t = normal = mu_req = v_cm = spin = accel = accel_g = omega3 = nan
    if not fits:
        status, reason = S_NO_FIT, (R_FIT_OUT if outside else R_FIT_IN)
    elif undefined:
        status, reason = S_NO_ORBIT, (R_IN_PLANE if abs(sa) <= SINGULAR else R_ZERO_DEN)
    elif om2_zero:
        status, reason = S_NO_ORBIT, R_OM_ZERO
    elif not real:
        status, reason = S_NO_ORBIT, R_OM_IMAG
    elif not normal > 0:
        status, reason = S_NO_CONTACT, (R_CONTACT_OUT if outside else R_CONTACT_IN)
    elif mu_req > mu:
        status, reason = S_SLIPS, R_SLIPS
    else:
        status, reason = S_OK, R_NONE
    return (rp, om2, omega, period, v_cm, spin, accel, accel_g, normal, f_t, mu_req, omega3,
            status, reason)


def run_python(theta, alpha, a, r, k, g, outside=False, mu=math.inf):
    rows = [orbit_python(t, al, a, r, k, g, outside, mu) for t, al in zip(theta.tolist(), alpha.tolist())]
    cols = list(zip(*rows))
    out = {key: np.array(cols[i], dtype=float) for i, key in enumerate(KEYS)}
    out["status"] = np.array(cols[len(KEYS)], dtype=np.int8)
    out["reason"] = np.array(cols[len(KEYS) + 1], dtype=np.int8)
    return out


# ---------------------------------------------------------------------------
# (c) optimised numpy variant
# ---------------------------------------------------------------------------

_FAST_CHUNK = 1 << 15


def fast_horizontal_orbit(theta, alpha, a, r, k, g, outside=False, mu=np.inf, out=None,
                          chunk=_FAST_CHUNK):
    """wheel.horizontal_orbit for 1-d theta, alpha and scalar a, r, k, g,
    outside, mu, with the same outputs.  Written before wheel.py was
    optimised, as suggestions for it; wheel.py now does 1-3 and chunks
    (4 without the out= buffers, see benchmarks/README.md):

    1. sin/cos of theta and alpha computed once (the core evaluated ~15
       transcendental functions per orbit: sin(theta) x3, cos(alpha) x4, ...);
    2. scalar parameters stay scalars (the core broadcast a, r, k, g, mu and
       outside to full arrays, so (2k+1), a/r, ... became full-array ops);
    3. status and reason computed branch-free as sums of 0/1 bytes times
       the codes (the conditions nest: no contact implies a real orbit ...),
       instead of boolean-mask scatter (status[hit] = ...) with a running
       'undecided' mask: a masked write with a random mask costs ~4-5 ns per
       element (branch mispredictions), a byte multiply-add ~0.1 ns;
    4. every temporary reused through out= buffers, in chunks of 2^15
       orbits so that the working set stays in cache.
    """
    theta = np.asarray(theta, dtype=float).reshape(-1)
    alpha = np.asarray(alpha, dtype=float).reshape(-1)
    n = theta.size
    if out is None:
        out = {key: np.empty(n) for key in KEYS}
        out["status"] = np.empty(n, dtype=np.int8)
        out["reason"] = np.empty(n, dtype=np.int8)
    c1, c2, c3 = 2 * k + 1, k * a, SINGULAR * ((2 * k + 1) * r + (k + 1) * a)
    zero_om2 = SINGULAR * g / r
    m = min(chunk, n)
    st, ct, sa, ca, t1, t2 = (np.empty(m) for _ in range(6))
    b1, b2, b3, b4, b5 = (np.empty(m, dtype=bool) for _ in range(5))
    fit_reason = R_FIT_OUT if outside else R_FIT_IN
    contact_reason = R_CONTACT_OUT if outside else R_CONTACT_IN
    with np.errstate(divide="ignore", invalid="ignore"):
        for s in range(0, n, chunk):
            e = min(s + chunk, n)
            L = e - s
            th, al = theta[s:e], alpha[s:e]
            st_, ct_, sa_, ca_, t1_, t2_ = st[:L], ct[:L], sa[:L], ca[:L], t1[:L], t2[:L]
            b1_, b2_, b3_, b4_, b5_ = b1[:L], b2[:L], b3[:L], b4[:L], b5[:L]
            o = {key: val[s:e] for key, val in out.items()}
            np.sin(th, out=st_)
            np.cos(th, out=ct_)
            np.sin(al, out=sa_)
            np.cos(al, out=ca_)
            rp = o["r_prime"]
            np.multiply(st_, r, out=rp)
            np.multiply(ca_, a, out=t1_)
            rp -= t1_                                       # r' = r sin(theta) - a cos(alpha)
            # fit, eq. (0) / (81)
            np.subtract(al, th, out=t1_) if outside else np.subtract(th, al, out=t1_)
            np.sin(t1_, out=t1_)
            np.greater(t1_, 0.0 if outside else a / r, out=b1_)      # b1 = fits
            # Omega^2, eq. (29)
            np.multiply(rp, c1, out=t1_)
            np.multiply(ca_, c2, out=t2_)
            t1_ += t2_
            t1_ *= sa_                                      # denominator
            np.abs(t1_, out=t2_)
            np.less_equal(t2_, c3, out=b2_)                 # b2 = undefined
            om2 = o["omega2"]
            np.multiply(ca_, g, out=om2)
            np.divide(om2, t1_, out=om2)
            np.copyto(om2, np.nan, where=b2_)
            np.abs(om2, out=t2_)
            np.less_equal(t2_, zero_om2, out=b3_)           # b3 = Omega^2 ~ 0 (NaN -> False)
            real = np.greater(om2, 0.0, out=b4_)            # NaN -> False
            real &= ~b3_
            # Omega^2 where real, NaN elsewhere, without a masked write:
            # 0 / (0 or 1) is NaN or 0, added to Omega^2
            om2r = t2_
            np.divide(0.0, real, out=om2r)
            om2r += om2
            omega = o["omega"]
            np.sqrt(om2r, out=omega)
            np.divide(2 * np.pi, omega, out=o["period"])
            np.abs(rp, out=t1_)
            np.multiply(t1_, omega, out=o["v_cm"])
            np.multiply(t1_, om2r, out=o["accel"])
            np.divide(o["accel"], g, out=o["accel_g"])
            np.multiply(rp, omega, out=o["spin"])
            o["spin"] /= a
            np.multiply(omega, sa_, out=o["omega3"])
            np.negative(o["omega3"], out=o["omega3"])       # omega_3 = -Omega sin(alpha)
            cen = om2r
            cen *= rp                                       # r' Omega^2 (NaN where not real)
            normal, fric = o["normal"], o["friction"]
            np.multiply(cen, st_, out=normal)
            np.multiply(ct_, g, out=t1_)
            normal -= t1_                                   # -F_r
            if outside:
                np.negative(normal, out=normal)
            np.multiply(cen, ct_, out=fric)
            np.multiply(st_, g, out=t1_)
            fric += t1_
            np.negative(fric, out=fric)                     # F_theta
            mu_req = o["mu_required"]
            contact = np.greater(normal, 0.0, out=b5_)
            np.abs(fric, out=mu_req)
            np.divide(mu_req, normal, out=mu_req)
            np.divide(0.0, contact, out=t1_)                # NaN where no contact
            mu_req += t1_
            # status and reason from 0/1 bytes (no masked writes: random masks
            # defeat branch prediction, ~4-5 ns per element and write)
            u = lambda x: x.view(np.uint8)                  # noqa: E731
            nf = b1_.copy()                                 # fits
            f1 = np.logical_not(b1_, out=b1_)               # 1 no fit
            f2 = np.logical_and(b2_, nf, out=b2_)           # 2a Omega^2 undefined
            f3 = np.logical_and(b3_, nf, out=b3_)           # 2b Omega^2 = 0
            f4 = np.logical_not(real, out=real)
            f4 &= nf                                        # 2  no orbit (contains 2a, 2b)
            f5 = np.logical_not(contact, out=contact)
            f5 &= nf
            f5 &= ~f4                                       # 3  no contact
            st8, rs8 = u(o["status"]), u(o["reason"])
            np.multiply(u(f1), np.uint8(S_NO_FIT), out=st8)
            st8 += u(f4) * np.uint8(S_NO_ORBIT)
            st8 += u(f5) * np.uint8(S_NO_CONTACT)
            np.multiply(u(f1), np.uint8(fit_reason), out=rs8)
            in_plane = np.abs(sa_) <= SINGULAR
            rs8 += u(f2) * (np.uint8(R_ZERO_DEN) - u(in_plane) * np.uint8(R_ZERO_DEN - R_IN_PLANE))
            rs8 += u(f3) * np.uint8(R_OM_ZERO)
            rs8 += u(f4 & ~f2 & ~f3) * np.uint8(R_OM_IMAG)
            rs8 += u(f5) * np.uint8(contact_reason)
            if np.isfinite(mu):
                f6 = np.greater(mu_req, mu)                 # 4  slips (NaN -> False)
                f6 &= nf
                st8 += u(f6) * np.uint8(S_SLIPS)
                rs8 += u(f6) * np.uint8(R_SLIPS)
    return out


# ---------------------------------------------------------------------------
# (b) fused numba kernel
# ---------------------------------------------------------------------------

def make_numba_kernel():
    """Compile the fused kernel, or return None when numba is missing."""
    try:
        import numba
    except ImportError:
        return None

    @numba.njit(cache=False, fastmath=False, nogil=True)
    def kernel(theta, alpha, a, r, k, g, outside, mu, o, status, reason):
        nan = np.nan
        c1, c2 = 2 * k + 1, k * a
        c3 = SINGULAR_ * ((2 * k + 1) * r + (k + 1) * a)
        zero_om2 = SINGULAR_ * g / r
        for i in range(theta.size):
            th, al = theta[i], alpha[i]
            st, ct = math.sin(th), math.cos(th)
            sa, ca = math.sin(al), math.cos(al)
            rp = r * st - a * ca
            fits = math.sin(al - th) > 0.0 if outside else math.sin(th - al) > a / r
            den = sa * (c1 * rp + c2 * ca)
            undefined = abs(den) <= c3
            om2 = nan if undefined else g * ca / den
            om2_zero = (not undefined) and abs(om2) <= zero_om2
            real = (not undefined) and (not om2_zero) and om2 > 0
            if real:
                omega = math.sqrt(om2)
                cen = rp * om2
                f_r = -(cen * st - g * ct)
                f_t = -(cen * ct + g * st)
                normal = f_r if outside else -f_r
                mu_req = abs(f_t) / normal if normal > 0 else nan
                o[0, i], o[1, i], o[2, i] = rp, om2, omega
                o[3, i] = 2 * math.pi / omega
                o[4, i], o[5, i] = abs(rp) * omega, rp * omega / a
                o[6, i] = abs(rp) * om2
                o[7, i] = abs(rp) * om2 / g
                o[8, i], o[9, i], o[10, i] = normal, f_t, mu_req
                o[11, i] = -omega * sa
            else:
                normal = mu_req = nan
                o[0, i], o[1, i] = rp, om2
                for j in range(2, 12):
                    o[j, i] = nan
            if not fits:
                status[i], reason[i] = S_NO_FIT_, (R_FIT_OUT_ if outside else R_FIT_IN_)
            elif undefined:
                status[i] = S_NO_ORBIT_
                reason[i] = R_IN_PLANE_ if abs(sa) <= SINGULAR_ else R_ZERO_DEN_
            elif om2_zero:
                status[i], reason[i] = S_NO_ORBIT_, R_OM_ZERO_
            elif not real:
                status[i], reason[i] = S_NO_ORBIT_, R_OM_IMAG_
            elif not normal > 0:
                status[i], reason[i] = S_NO_CONTACT_, (R_CONTACT_OUT_ if outside else R_CONTACT_IN_)
            elif mu_req > mu:
                status[i], reason[i] = S_SLIPS_, R_SLIPS_
            else:
                status[i], reason[i] = S_OK_, R_NONE_

    def run(theta, alpha, a, r, k, g, outside=False, mu=np.inf, out=None):
        n = theta.size
        if out is None:
            out = (np.empty((len(KEYS), n)), np.empty(n, dtype=np.int8), np.empty(n, dtype=np.int8))
        o, status, reason = out
        kernel(theta, alpha, a, r, k, g, outside, mu, o, status, reason)
        res = {key: o[i] for i, key in enumerate(KEYS)}
        res["status"], res["reason"] = status, reason
        return res

    @numba.njit(cache=False, fastmath=False, nogil=True)
    def trig_only(theta, alpha):
        """The five transcendental functions of the kernel and nothing else."""
        total = 0.0
        for i in range(theta.size):
            th, al = theta[i], alpha[i]
            total += math.sin(th) + math.cos(th) + math.sin(al) + math.cos(al) + math.sin(th - al)
        return total

    run.trig_only = trig_only
    return run


# the kernel reads these module globals as compile-time constants
SINGULAR_ = SINGULAR
S_OK_, S_NO_FIT_, S_NO_ORBIT_, S_NO_CONTACT_, S_SLIPS_ = S_OK, S_NO_FIT, S_NO_ORBIT, S_NO_CONTACT, S_SLIPS
R_NONE_, R_FIT_IN_, R_FIT_OUT_, R_IN_PLANE_, R_ZERO_DEN_ = R_NONE, R_FIT_IN, R_FIT_OUT, R_IN_PLANE, R_ZERO_DEN
R_OM_ZERO_, R_OM_IMAG_, R_CONTACT_IN_, R_CONTACT_OUT_, R_SLIPS_ = (R_OM_ZERO, R_OM_IMAG, R_CONTACT_IN,
                                                                  R_CONTACT_OUT, R_SLIPS)


# ---------------------------------------------------------------------------
# harness
# ---------------------------------------------------------------------------

def make_orbits(n, seed=1993):
    """theta in (1, 179) deg, alpha in (-30, 95) deg: every status occurs,
    about half the orbits feasible (Table 1's wheel and sphere)."""
    rng = np.random.default_rng(seed)
    theta = np.deg2rad(rng.uniform(1.0, 179.0, n))
    alpha = np.deg2rad(rng.uniform(-30.0, 95.0, n))
    # a few exact singular cases
    alpha[: n // 1000] = 0.0
    alpha[n // 1000: n // 500] = np.pi / 2
    return theta, alpha


def check_same(ref, got, name):
    for key in ("status", "reason"):
        bad = np.count_nonzero(np.asarray(ref[key]) != np.asarray(got[key]))
        if bad:
            raise SystemExit(f"{name}: {bad} {key} codes differ from wheel.horizontal_orbit")
    for key in KEYS:
        if not np.allclose(ref[key], got[key], rtol=1e-12, atol=0, equal_nan=True):
            raise SystemExit(f"{name}: {key} differs from wheel.horizontal_orbit")


def timeit(fn, repeat=1):
    best = math.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def first_failure_scatter(conditions):
    """status.first_failure as it was before the optimisation (boolean-mask
    scatter with a running 'undecided' mask), for the breakdown."""
    shape = np.broadcast_shapes(*(np.shape(c[0]) for c in conditions))
    status = np.full(shape, Status.OK, dtype=np.int8)
    reason = np.full(shape, Reason.NONE, dtype=np.int8)
    undecided = np.ones(shape, dtype=bool)
    for failed, st, why in conditions:
        hit = undecided & np.broadcast_to(failed, shape)
        status[hit] = st
        reason[hit] = np.broadcast_to(why, shape)[hit]
        undecided &= ~hit
    return status, reason


def load_old_core(rev):
    """wheel.horizontal_orbit as of git revision ``rev``, with that revision's
    status.first_failure (read with ``git show``; the working tree is not
    touched).  Geometry comes from the installed package."""
    root = Path(__file__).resolve().parent.parent

    def module(path, name):
        src = subprocess.run(["git", "show", f"{rev}:{path}"], cwd=root, capture_output=True,
                             text=True, check=True).stdout
        mod = types.ModuleType(name)
        exec(compile(src, f"{rev}:{path}", "exec"), mod.__dict__)
        return mod

    old_status = module("deathsphere/physics/status.py", "old_status")
    old_wheel = module("deathsphere/physics/wheel.py", "old_wheel")
    old_wheel.first_failure = old_status.first_failure
    return old_wheel.horizontal_orbit


def timeit_n(fn, number):
    t0 = time.perf_counter()
    for _ in range(number):
        fn()
    return (time.perf_counter() - t0) / number


def per_orbit_interleaved(fns, count, rounds=7, number=10):
    """Best time of each function in ns per orbit (of ``count``), the
    functions taking turns so that a burst of load elsewhere on the machine
    hits them all alike."""
    best = [math.inf] * len(fns)
    for _ in range(rounds):
        for i, fn in enumerate(fns):
            best[i] = min(best[i], timeit_n(fn, number))
    return [seconds * 1e9 / count for seconds in best]


def with_patched_wheel(fn, **replacements):
    """fn run with module globals of wheel replaced (restored afterwards)."""
    def run():
        saved = {name: getattr(wheel, name) for name in replacements}
        for name, value in replacements.items():
            setattr(wheel, name, value)
        try:
            fn()
        finally:
            for name, value in saved.items():
                setattr(wheel, name, value)
    return run


def breakdown(theta, alpha, mu, old_core=None, old_label="", chunk=wheel.CHUNK):
    """Where the core's time goes and what each change to it is worth, per
    orbit, on one cache-sized chunk, with the per-row parameter arrays the
    model passes."""
    th, al = theta[:chunk].copy(), alpha[:chunk].copy()
    c = th.size
    per_row = (np.full(c, A), np.full(c, R), np.full(c, K), np.full(c, G), np.zeros(c, bool), np.full(c, mu))
    core = lambda: wheel.horizontal_orbit(th, al, *per_row)                # noqa: E731
    rng = np.random.default_rng(0)
    fails = [(rng.random(c) < 0.2, Status.NO_FIT, np.ones(c, np.int8)) for _ in range(6)]
    th16, al16 = th[:16].copy(), al[:16].copy()
    items = [(f"core as of {old_label}", lambda: old_core(th, al, *per_row))] if old_core else []
    items += [
        ("wheel.horizontal_orbit", core),
        ("  the same, status by boolean-mask scatter (as before)",
         with_patched_wheel(core, first_failure=first_failure_scatter)),
        ("  the same, parameters kept as arrays, both fit sides (as before)",
         with_patched_wheel(core, _uniform=lambda x: x[()] if x.ndim == 0 else x)),
        ("  numpy: the 15 transcendental functions before", lambda: (
            [np.sin(th) for _ in range(4)], [np.cos(th) for _ in range(2)], [np.sin(al) for _ in range(3)],
            [np.cos(al) for _ in range(4)], np.sin(th - al), np.sin(al - th))),
        ("  numpy: the 5 transcendental functions now",
         lambda: (np.sin(th), np.cos(th), np.sin(al), np.cos(al), np.sin(th - al))),
        ("  per-call overhead of horizontal_orbit (16 orbits)",
         lambda: wheel.horizontal_orbit(th16, al16, A, R, K, G, False, mu)),
        ("  status.first_failure, 6 conditions of 20% (byte sums, now)", lambda: first_failure(fails)),
        ("  the same by boolean-mask scatter (first_failure before)", lambda: first_failure_scatter(fails)),
        ("fast_horizontal_orbit (c), scalar parameters",
         lambda: fast_horizontal_orbit(th, al, A, R, K, G, False, mu)),
    ]
    print(f"\nwhere the core's time goes (one chunk of {c:,} orbits, per-row parameters, ns per orbit;"
          f"\nthe overhead line is per call / {c:,}):")
    for (label, _), ns in zip(items, per_orbit_interleaved([fn for _, fn in items], c)):
        print(f"  {label:<66} {ns:7.1f}")


def chunks(theta, alpha, chunk):
    for s in range(0, theta.size, chunk):
        yield theta[s:s + chunk], alpha[s:s + chunk]


def core_chunked(theta, alpha, chunk, mu, core=None):
    core = core or wheel.horizontal_orbit
    for th, al in chunks(theta, alpha, chunk):
        core(th, al, A, R, K, G, False, mu)


def gap(theta, alpha, mu, numba_run, rate, chunk=wheel.CHUNK):
    """The gap between the core (whole array) and the numba kernel (fresh
    outputs per call), split into: the five transcendental functions and the
    rest of the arithmetic, both timed on one chunk that stays in cache, and
    what is left of the whole-array time: writing the outputs to fresh
    memory (page faults included).  ns per orbit."""
    th, al = theta[:chunk].copy(), alpha[:chunk].copy()
    buf = (np.empty((len(KEYS), chunk)), np.empty(chunk, dtype=np.int8), np.empty(chunk, dtype=np.int8))

    trig_np, trig_nb, core_cached, nb_cached = per_orbit_interleaved([
        lambda: (np.sin(th), np.cos(th), np.sin(al), np.cos(al), np.sin(th - al)),
        lambda: numba_run.trig_only(th, al),
        lambda: wheel.horizontal_orbit(th, al, A, R, K, G, False, mu),
        lambda: numba_run(th, al, A, R, K, G, False, mu, buf)], chunk)
    core_one = 1e9 / rate["core wheel.horizontal_orbit, one array"]
    nb_fresh = 1e9 / rate["(b) numba fused kernel, fresh outputs"]
    rows = [
        ("5 transcendental functions (one chunk, in cache)", trig_np, trig_nb),
        ("rest: arithmetic, status, call overhead (same)", core_cached - trig_np, nb_cached - trig_nb),
        ("writing outputs to fresh memory (whole array - chunk)", core_one - core_cached, nb_fresh - nb_cached),
        (f"total, {theta.size:,} orbits in one call", core_one, nb_fresh),
    ]
    print(f"\ngap to the fused kernel, ns per orbit (chunk = wheel.CHUNK = {chunk:,} orbits):")
    print(f"  {'':<56} {'core':>7} {'numba':>7} {'gap':>7}")
    for label, x, y in rows:
        print(f"  {label:<56} {x:7.1f} {y:7.1f} {x - y:7.1f}")
    print(f"  (the outputs are {len(KEYS) * 8 + 2} bytes per orbit, new memory on every call: the kernel's"
          f" page faults\n   make that line the one that varies most from run to run)")


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--n", type=int, default=10_000_000, help="orbits (default 10^7)")
    p.add_argument("--loop-n", type=int, default=200_000, help="orbits for the Python loop")
    p.add_argument("--mu", type=float, default=1.0, help="friction available (default 1)")
    p.add_argument("--old", metavar="REV", help="also time wheel.horizontal_orbit as of git revision REV")
    args = p.parse_args(argv)
    n, mu = args.n, args.mu
    theta, alpha = make_orbits(n)
    print(f"deathsphere core benchmark: {n:,} horizontal orbits, wheel inside, "
          f"a = {A} m, r = {R} m, k = {K}, mu = {mu:g}; numpy {np.__version__}, "
          f"python {sys.version.split()[0]}, single thread; wheel.CHUNK = {wheel.CHUNK:,}")

    # --- correctness of every variant on a sample -------------------------
    m = min(n, 200_000)
    ref = wheel.horizontal_orbit(theta[:m], alpha[:m], A, R, K, G, False, mu)
    mix = np.bincount(ref["status"], minlength=len(Status))
    print("status mix: " + ", ".join(f"{s.label} {mix[s] / m:.0%}" for s in Status if mix[s]))
    sub = {key: val[:20_000] for key, val in ref.items()}
    check_same(sub, run_python(theta[:20_000], alpha[:20_000], A, R, K, G, False, mu), "python loop")
    check_same(ref, fast_horizontal_orbit(theta[:m], alpha[:m], A, R, K, G, False, mu), "fast numpy")
    per_row = (np.full(n, A), np.full(n, R), np.full(n, K), np.full(n, G), np.zeros(n, bool), np.full(n, mu))
    check_same(ref, wheel.horizontal_orbit(theta[:m], alpha[:m], *(x[:m] for x in per_row)), "per-row parameters")
    old_core = None
    if args.old:
        old_core = load_old_core(args.old)
        check_same(ref, old_core(theta[:m], alpha[:m], A, R, K, G, False, mu), f"core as of {args.old}")
    numba_run = make_numba_kernel()
    if numba_run is not None:
        check_same(ref, numba_run(theta[:m], alpha[:m], A, R, K, G, False, mu), "numba kernel")
    print("all variants agree with wheel.horizontal_orbit on", f"{m:,}", "orbits\n")

    rows = []

    def report(label, seconds, count):
        rate = count / seconds
        rows.append((label, rate))
        print(f"  {label:<50} {rate / 1e6:8.2f} M orbits/s   ({seconds * 1e9 / count:7.1f} ns/orbit)")

    # --- (a) Python loop ---------------------------------------------------
    ln = min(args.loop_n, n)
    report(f"(a) python loop, math module ({ln:,})",
           timeit(lambda: run_python(theta[:ln], alpha[:ln], A, R, K, G, False, mu)), ln)

    # --- numpy core ----------------------------------------------------------
    report("core wheel.horizontal_orbit, one array",
           timeit(lambda: wheel.horizontal_orbit(theta, alpha, A, R, K, G, False, mu), repeat=3), n)
    for chunk in (1 << 14, 1 << 16):
        report(f"core wheel.horizontal_orbit, caller chunks of 2^{chunk.bit_length() - 1}",
               timeit(lambda: core_chunked(theta, alpha, chunk, mu), repeat=3), n)
    report("core, per-row parameter arrays (as the model)",
           timeit(lambda: wheel.horizontal_orbit(theta, alpha, *per_row), repeat=3), n)

    # --- (d) the core before -------------------------------------------------
    if old_core is not None:
        report(f"(d) core as of {args.old}, chunks of 2^14",
               timeit(lambda: core_chunked(theta, alpha, 1 << 14, mu, old_core), repeat=2), n)
        report(f"(d) core as of {args.old}, one array",
               timeit(lambda: old_core(theta, alpha, A, R, K, G, False, mu), repeat=2), n)

    # --- (c) optimised numpy -------------------------------------------------
    out = {key: np.empty(n) for key in KEYS}
    out["status"], out["reason"] = np.empty(n, dtype=np.int8), np.empty(n, dtype=np.int8)
    for chunk in (1 << 14, 1 << 16):
        report(f"(c) fast numpy variant, chunks of 2^{chunk.bit_length() - 1}",
               timeit(lambda: fast_horizontal_orbit(theta, alpha, A, R, K, G, False, mu, out, chunk), repeat=2), n)

    # --- (b) numba -----------------------------------------------------------
    if numba_run is None:
        print("  (b) numba fused kernel: skipped (numba is not installed; pip install numba)")
    else:
        buf = (np.empty((len(KEYS), n)), np.empty(n, dtype=np.int8), np.empty(n, dtype=np.int8))
        report("(b) numba fused kernel, buffers reused",
               timeit(lambda: numba_run(theta, alpha, A, R, K, G, False, mu, buf), repeat=3), n)
        del buf
        report("(b) numba fused kernel, fresh outputs",
               timeit(lambda: numba_run(theta, alpha, A, R, K, G, False, mu), repeat=3), n)

    rate = dict(rows)
    core = rate["core wheel.horizontal_orbit, one array"]
    caller = rate["core wheel.horizontal_orbit, caller chunks of 2^14"]
    fast_best = max(v for kk, v in rate.items() if kk.startswith("(c)"))
    loop = next(v for kk, v in rate.items() if kk.startswith("(a)"))
    print("\nratios (core = wheel.horizontal_orbit on the whole array, as the model calls it;"
          "\n        core fed in chunks = the same, the caller passing 2^14 orbits at a time as the sweep does):")
    print(f"  core / python loop                          = {core / loop:6.1f}x   (goal >= 10x)")
    print(f"  core fed in chunks / python loop            = {caller / loop:6.1f}x")
    print(f"  core / core fed in chunks                   = {core / caller:6.2f}x")
    print(f"  core per-row parameters / core              = {rate['core, per-row parameter arrays (as the model)'] / core:6.2f}x")
    print(f"  fast numpy (c, best) / core fed in chunks   = {fast_best / caller:6.2f}x")
    if old_core is not None:
        old_one = rate[f"(d) core as of {args.old}, one array"]
        old_chunk = rate[f"(d) core as of {args.old}, chunks of 2^14"]
        print(f"  {'core / core as of ' + args.old + ', one array':<43} = {core / old_one:6.1f}x")
        print(f"  {'core / core as of ' + args.old + ', both in chunks':<43} = {caller / old_chunk:6.1f}x")
    if numba_run is not None:
        nb_fresh = rate["(b) numba fused kernel, fresh outputs"]
        nb_reused = rate["(b) numba fused kernel, buffers reused"]
        print(f"  numba (fresh outputs) / core                = {nb_fresh / core:6.2f}x   (goal <= 1.5x)")
        print(f"  numba (buffers reused) / core fed in chunks = {nb_reused / caller:6.2f}x")
        gap(theta, alpha, mu, numba_run, rate)
    breakdown(theta, alpha, mu, old_core, args.old)


if __name__ == "__main__":
    main()
