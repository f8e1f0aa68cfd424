"""Survey: the paper's stability claims against the exact linearisation.

McDonald (1993) sec. 2.3 (wheel inside), sec. 3 (wheel outside), secs. 4-5
(sphere).  Prints, claim by claim, what the exact linear stability analysis
of deathsphere.physics.stability finds over grids of theta, alpha,
a/r in {0.01, 0.1, 0.3, 0.6} and k in {1/4, 1/2}.  Every figure quoted in
docs/stability.md comes from this script:

    python benchmarks/stability_survey.py            # all sections
    python benchmarks/stability_survey.py equator    # one section

Sections: table1 tolerance equator small large pole outside vertical sphere.
Runs in about a minute on one core.
"""

import sys
import time

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics import dynamics as dyn
from deathsphere.physics import stability as st
from deathsphere.physics.geometry import r_prime
from deathsphere.physics.wheel import horizontal_orbit

G = STANDARD_GRAVITY
A_OVER_R = (0.01, 0.1, 0.3, 0.6)
KS = (0.25, 0.5)
S, U, N = st.Verdict.STABLE, st.Verdict.UNSTABLE, st.Verdict.UNKNOWN


def header(title):
    print()
    print("=" * 78)
    print(title)
    print("=" * 78)


def pct(n, d):
    return f"{n}/{d} ({100.0 * n / d:.1f}%)" if d else "0/0"


def inside_grid(a_r, k, dth=2.0, dal=1.0):
    th, al = np.meshgrid(np.radians(np.arange(dth, 180, dth)),
                         np.radians(np.arange(dal / 2, 90, dal)), indexing="ij")
    h = horizontal_orbit(th, al, a_r, 1.0, k, G)
    ok = h["status"] == 0
    return th[ok], al[ok], h, ok


def section_table1():
    header("Table 1 (a = 0.3 m, r = 3 m, k = 1/2): exact stability of the printed orbits")
    T1 = [(15, 5), (30, 5), (45, 10), (60, 10), (60, 25), (75, 15), (75, 30),
          (90, 25), (90, 45), (135, 60)]
    th, al = np.radians(np.array(T1, float)).T
    res = st.wheel_stability(th, al, 0.3, 3.0, 0.5, G)
    print(" theta alpha  Omega   verdict   growth     slow    fast   (rad/s, turning frame)")
    for i, (t, a) in enumerate(T1):
        print(f"  {t:4d} {a:4d}  {res['omega'][i]:6.3f}  {st.VERDICT_LABELS[res['verdict'][i]]:8s}"
              f" {res['growth_rate'][i]:8.1e}  {res['freq_slow'][i]:6.3f} {res['freq_fast'][i]:7.3f}")


def section_equator():
    header("Claim (sec. 2.3.3, eqs. 127-138): 'all steady orbits at the equator are stable'")
    al = np.radians(np.arange(0.25, 90, 0.25))
    print(" a/r   k    orbits  exact stable      unstable for alpha >=   printed eq.135 stable"
          "   printed C>0")
    for a_r in A_OVER_R:
        for k in KS:
            h = horizontal_orbit(np.pi / 2, al, a_r, 1.0, k, G)
            ok = h["status"] == 0
            ex = st.wheel_stability(np.pi / 2, al[ok], a_r, 1.0, k, G)
            pp = st.equator_paper(al[ok], a_r, 1.0, k, G)
            n = ok.sum()
            uns = ex["verdict"] == U
            first = np.degrees(al[ok][uns].min()) if uns.any() else np.nan
            print(f" {a_r:4.2f} {k:4.2f}  {n:6d}  {pct((ex['verdict'] == S).sum(), n):18s}"
                  f"  {first:6.2f} deg            {pct(pp['stable_printed'].sum(), n):16s}"
                  f"  {pct((pp['C'] > 0).sum(), n)}")
    print("\n Frequencies on the equator, stable orbits: relative deviation from exact")
    print(" a/r   k   | printed eq.135 slow  fast (median, max |dev|) | closed form (exact) max |dev|")
    for a_r in A_OVER_R:
        for k in KS:
            h = horizontal_orbit(np.pi / 2, al, a_r, 1.0, k, G)
            ok = h["status"] == 0
            ex = st.wheel_stability(np.pi / 2, al[ok], a_r, 1.0, k, G)
            pp = st.equator_paper(al[ok], a_r, 1.0, k, G)
            cf = st.equator_exact_closed_form(al[ok], a_r, 1.0, k, G)
            s = ex["verdict"] == S
            ds = np.abs(pp["freq_slow"][s] / ex["freq_slow"][s] - 1)
            df = np.abs(pp["freq_fast"][s] / ex["freq_fast"][s] - 1)
            cs = np.abs(cf["freq_slow"][s] / ex["freq_slow"][s] - 1).max()
            cfast = np.abs(cf["freq_fast"][s] / ex["freq_fast"][s] - 1).max()
            print(f" {a_r:4.2f} {k:4.2f}  |  {np.nanmedian(ds):6.1%} {np.nanmax(ds):7.1%}"
                  f"   {np.nanmedian(df):6.1%} {np.nanmax(df):7.1%}          |  {max(cs, cfast):.1e}")
    # the two routes to the printed roots agree (eqs. 135-138 = det of eq. 133)
    pp = st.equator_paper(al, 0.1, 1.0, 0.5, G)
    d = np.nanmax(np.abs(pp["omega2_det"] - pp["omega2_closed"]) / np.abs(pp["omega2_closed"]))
    print(f"\n printed closed forms (136)-(138) vs numerical det of printed (133): max rel diff {d:.1e}")


def section_small():
    header("Claim (sec. 2.3.4, eqs. 201-207): 'all orbits for small wheels are stable'")
    print(" a/r   k  | orbits with a/r' <= 0.05 | exact stable | unstable only where")
    for a_r in (0.001, 0.01):
        for k in KS:
            th, al, h, ok = inside_grid(a_r, k, dth=1.0, dal=0.25)
            rp = np.sin(th) - a_r * np.cos(al)
            v = a_r / np.abs(rp) <= 0.05
            ex = st.wheel_stability(th[v], al[v], a_r, 1.0, k, G)
            uns = ex["verdict"] == U
            where = (f"alpha >= {np.degrees(al[v][uns].min()):.2f} deg "
                     f"(Omega^2 a/g <= {np.max(ex['omega'][uns] ** 2 * a_r / G):.2e})"
                     if uns.any() else "-")
            print(f" {a_r:5.3f} {k:4.2f} | {v.sum():8d}                 | "
                  f"{pct((ex['verdict'] == S).sum(), v.sum()):17s} | {where}")
    print("\n Slow nutation frequency vs exact (stable orbits, a/r' <= 0.05):")
    print(" a/r    k   | eq. 207 median |dev|  max |dev| | corrected (E5) median  max | fast (E5) max")
    for a_r in (0.001, 0.01):
        for k in KS:
            th, al, h, ok = inside_grid(a_r, k, dth=1.0, dal=0.25)
            rp = np.sin(th) - a_r * np.cos(al)
            v = (a_r / np.abs(rp) <= 0.05) & (al < np.radians(85))
            ex = st.wheel_stability(th[v], al[v], a_r, 1.0, k, G)
            p = st.small_wheel_paper(th[v], al[v], a_r, 1.0, k, G)
            c = st.small_wheel_corrected(th[v], al[v], a_r, 1.0, k, G)
            s = ex["verdict"] == S
            d7 = np.abs(p["freq"][s] / ex["freq_slow"][s] - 1)
            dc = np.abs(c["freq_slow"][s] / ex["freq_slow"][s] - 1)
            dfst = np.abs(c["freq_fast"][s] / ex["freq_fast"][s] - 1)
            print(f" {a_r:5.3f} {k:4.2f} |   {np.median(d7):7.1%}        {np.max(d7):7.1%} |"
                  f"   {np.median(dc):.1e}   {np.max(dc):.1e} |  {np.max(dfst):.1e}")
    print("   (alpha < 85 deg; the corrected forms are leading order in a/r')")


def section_large():
    header("Conjecture (after eq. 207, abstract): death-defying orbits of large wheels"
           "\n(above the equator) are stable")
    print(" a/r   k  | orbits theta<90 | exact stable      | of them with r' >= 5a: stable"
          " | unstable ones: smallest theta, alpha range")
    for a_r in A_OVER_R:
        for k in KS:
            th, al, h, ok = inside_grid(a_r, k)
            up = th < np.pi / 2 - 1e-9
            ex = st.wheel_stability(th[up], al[up], a_r, 1.0, k, G)
            rp = np.sin(th[up]) - a_r * np.cos(al[up])
            far = rp >= 5 * a_r
            s = ex["verdict"] == S
            uns = ex["verdict"] == U
            info = (f"{np.degrees(th[up][uns].min()):.0f} deg, alpha "
                    f"{np.degrees(al[up][uns].min()):.1f}-{np.degrees(al[up][uns].max()):.1f}"
                    if uns.any() else "-")
            print(f" {a_r:4.2f} {k:4.2f} | {up.sum():6d}          | {pct(s.sum(), up.sum()):17s} |"
                  f" {pct((s & far).sum(), far.sum()):22s} | {info}")
    print("\n Where instability sets in at fixed theta (a/r = 0.3, k = 1/2): smallest unstable alpha")
    th = np.radians(np.array([20.0, 30, 45, 60, 75, 90, 120, 150]))
    al = np.radians(np.arange(0.1, 90, 0.1))
    TH, AL = np.meshgrid(th, al, indexing="ij")
    h = horizontal_orbit(TH, AL, 0.3, 1.0, 0.5, G)
    ex = st.wheel_stability(TH, AL, 0.3, 1.0, 0.5, G)
    for i in range(th.size):
        ok = h["status"][i] == 0
        uns = ok & (ex["verdict"][i] == U)
        if ok.any():
            lo, hi = np.degrees(AL[i][ok].min()), np.degrees(AL[i][ok].max())
            first = f"{np.degrees(AL[i][uns].min()):5.1f}" if uns.any() else "  -  "
            print(f"   theta {np.degrees(th[i]):5.1f}: orbits alpha {lo:5.1f}-{hi:5.1f},"
                  f" unstable from alpha {first}")


def section_pole():
    header("Claim (eq. 208): near the poles (r' <~ a) stability needs Omega above a minimum,"
           "\nOmega^2 > g/((2k+1) a)")
    # (i) the rolling-disk criterion itself: a wide circle on a nearly flat floor
    print(" (i) eq. 208 as a rolling-disk criterion: wheel on a circle of radius 100 a at the"
          "\n     bottom of a sphere r = 1e5 a (locally a floor); exact threshold of the spin"
          " w1^2 a/g:")
    for k in KS:
        a, r = 1.0, 1e5
        th = np.pi - 1e-3
        al = np.radians(np.linspace(89.0, 89.999, 40001))
        ex = st.wheel_stability(th, al, a, r, k, G)
        rp = r_prime(th, al, a, r)
        w1sq = (rp * ex["omega"]) ** 2 * a / G
        i = np.nonzero((ex["verdict"][:-1] == S) & (ex["verdict"][1:] == U))[0][0]
        print(f"     k = {k:4.2f}: exact {w1sq[i]:.4f}   paper 1/(2k+1) = {1 / (2 * k + 1):.4f}"
              f"   disk 1/(2(2k+1)) = {1 / (2 * (2 * k + 1)):.4f}")
    # (ii) near-pole orbits
    print("\n (ii) orbits with |r'| <= a (bottom pole; no such orbit keeps contact near the top):")
    print(" a/r   k  | orbits | exact stable | stable set = {Omega > Omega_c} at each theta |"
          " Omega_c^2 a/g (min median max) | eq.208 verdict agrees | disk agrees")
    for a_r in (0.1, 0.3, 0.6):
        for k in KS:
            th = np.radians(np.arange(120.0, 180.0, 0.5))
            al = np.radians(np.arange(0.05, 90, 0.1))
            TH, AL = np.meshgrid(th, al, indexing="ij")
            h = horizontal_orbit(TH, AL, a_r, 1.0, k, G)
            rp = np.sin(TH) - a_r * np.cos(AL)
            near = (h["status"] == 0) & (np.abs(rp) <= a_r)
            ex = st.wheel_stability(TH, AL, a_r, 1.0, k, G)
            pole = st.near_pole_paper(TH, AL, a_r, 1.0, k, G)
            v = ex["verdict"]
            om2 = ex["omega"] ** 2 * a_r / G
            monotone, crit = 0, []
            cols = 0
            for i in range(th.size):
                m = near[i]
                if m.sum() < 2:
                    continue
                cols += 1
                o, vv = om2[i][m], v[i][m]
                order = np.argsort(o)
                o, vv = o[order], vv[order]
                st_ = vv == S
                if st_.any() and (~st_).any():
                    c = 0.5 * (o[~st_].max() + o[st_].min())
                    if o[~st_].max() < o[st_].min():
                        monotone += 1
                        crit.append(c)
                elif st_.all():
                    monotone += 1
            n = near.sum()
            agree_p = (pole["stable_printed"][near] == (v[near] == S)).sum()
            agree_d = (pole["stable_disk"][near] == (v[near] == S)).sum()
            cr = (f"{np.min(crit):.2f} {np.median(crit):.2f} {np.max(crit):.1f}"
                  if crit else "-")
            print(f" {a_r:4.2f} {k:4.2f} | {n:6d} | {pct((v[near] == S).sum(), n):14s} |"
                  f" {pct(monotone, cols):43s} | {cr:23s} | {pct(agree_p, n):16s} | {pct(agree_d, n)}")
        print(f"           (eq. 208: Omega^2 a/g > 1/(2k+1) = {1 / 1.5:.3f} (k=1/4), {1 / 2:.3f} (k=1/2))")


def section_outside():
    header("Wheel outside (sec. 3): remarks after eq. (84)")
    print(" a/r   k  | orbits | alpha in [80,90) deg: unstable | alpha within 10 deg of 180+theta:"
          " stable | other orbits stable")
    for a_r in A_OVER_R:
        for k in KS:
            th, al = np.meshgrid(np.radians(np.arange(1.0, 180, 2.0)),
                                 np.radians(np.arange(0.25, 360, 0.5)), indexing="ij")
            h = horizontal_orbit(th, al, a_r, 1.0, k, G, outside=True)
            ok = h["status"] == 0
            ex = st.wheel_stability(th[ok], al[ok], a_r, 1.0, k, G, outside=True)
            d = np.degrees(al[ok] - th[ok])
            adeg = np.degrees(al[ok])
            near90 = (adeg >= 80) & (adeg < 90)
            nearpi = d >= 170
            other = ~near90 & ~nearpi
            v = ex["verdict"]
            print(f" {a_r:4.2f} {k:4.2f} | {ok.sum():6d} | {pct((v[near90] == U).sum(), near90.sum()):30s} |"
                  f" {pct((v[nearpi] == S).sum(), nearpi.sum()):33s} | {pct((v[other] == S).sum(), other.sum())}")


def section_vertical():
    header("Claim (sec. 2.3.1, eqs. 100-106): 'all vertical orbits for which the wheel"
           "\nremains in contact with the sphere are stable'")
    fac = np.array([1.001, 1.05, 1.1, 1.2, 1.35, 1.5, 2.0, 3.0, 5.0])
    print(" phidot0 = f sqrt(g/r') (contact needs f > 1, eq. 28a), f in",
          ", ".join(f"{x:g}" for x in fac), "; 12 theta from asin(a/r) to 90 deg")
    print(" frozen top: 'paper' = its stated test B^2 + 4AC > 0; '(103a) roots > 0' = both printed"
          " roots positive")
    print(" a/r   k  | orbits | paper stable | (103a) roots > 0 | corrected (E1) stable |"
          " Floquet (exact) stable | unstable (theta deg, f, max|mu|)")
    t0 = time.time()
    for a_r in (0.1, 0.3, 0.6):
        for k in KS:
            thmin = np.arcsin(a_r)
            th = thmin + (np.pi / 2 - thmin) * np.linspace(0.05, 1.0, 12)
            TH, F = np.meshgrid(th, fac, indexing="ij")
            rp = np.sin(TH) - a_r
            PD = F * np.sqrt(G / rp)
            vp = st.vertical_paper(TH, PD, a_r, 1.0, k, G)
            fl = st.vertical_floquet(TH, PD, a_r, 1.0, k, G)
            n = TH.size
            uns = fl["verdict"] == U
            ex = ", ".join(f"({np.degrees(t):.1f}, {f:g}, {m:.3f})" for t, f, m in
                           zip(TH[uns][:3], F[uns][:3], fl["max_abs"][uns][:3]))
            pos = (vp["omega2_printed"].real > 0).all(axis=0).sum()
            print(f" {a_r:4.2f} {k:4.2f} | {n:6d} | {pct(vp['stable_printed'].sum(), n):12s} |"
                  f" {pct(pos, n):16s} | {pct(vp['stable'].sum(), n):21s} |"
                  f" {pct((fl['verdict'] == S).sum(), n):22s} | {uns.sum()}: {ex}")
    print(f" (Floquet: {time.time() - t0:.0f} s)")
    # B^2 >= 4AC (the condition the corrected eq. 103 adds) over a wide grid
    TH, F = np.meshgrid(np.linspace(0.02, np.pi / 2, 400), np.linspace(1.0, 10.0, 400), indexing="ij")
    worst = np.inf
    for a_r in A_OVER_R:
        for k in KS:
            ok = np.sin(TH) > a_r
            rp = np.where(ok, np.sin(TH) - a_r, 1.0)
            vp = st.vertical_paper(TH, F * np.sqrt(G / rp), a_r, 1.0, k, G)
            m = (vp["B"] ** 2 - 4 * vp["A"] * vp["C"]) / vp["B"] ** 2
            worst = min(worst, np.min(m[ok]))
    print(f" corrected frozen-top analysis: min (B^2 - 4AC)/B^2 over all grids in contact = {worst:.3f}"
          " (> 0: eq. 106 suffices)")


def section_sphere():
    header("Sphere (secs. 4-5): horizontal orbits inside and outside are stable")
    print(" side     a/r   k    | orbits in contact | exact stable | closed form max |dev|")
    for outside in (False, True):
        for a_r in A_OVER_R:
            for k in (0.4, 2 / 3):
                th, lo = np.meshgrid(np.radians(np.arange(1, 180, 1.0)), np.linspace(-3, 3, 121),
                                     indexing="ij")
                Om = 10 ** lo * np.sqrt(G)
                X, w3 = dyn.sphere_orbit_state(th, Om, a_r, 1.0, k, G, outside)
                p = dyn.body_params(a_r, 1.0, k, G, outside=outside, sphere=True)
                contact = dyn.contact_force(X, p)["normal"] > 0
                ex = st.sphere_stability(th[contact], Om[contact], a_r, 1.0, k, G, outside)
                cf = st.sphere_nutation_closed_form(th[contact], Om[contact], a_r, 1.0, k, G, outside)
                dev = np.max(np.abs(cf / ex["freq_fast"] - 1))
                side = "outside" if outside else "inside"
                print(f" {side:8s} {a_r:4.2f} {k:5.3f} | {contact.sum():17d} |"
                      f" {pct((ex['verdict'] == S).sum(), contact.sum()):12s} | {dev:.1e}")


def section_tolerance():
    header("Verdict tolerance: growth rate / rate scale on all status-ok orbits"
           "\n(theta 1..179 by 1 deg, alpha by 0.5 deg, inside and outside, all a/r and k)")
    worst_stable, best_unstable, unknown, n = 0.0, np.inf, 0, 0
    for outside in (False, True):
        for a_r in A_OVER_R:
            for k in KS:
                th, al = np.meshgrid(np.radians(np.arange(1.0, 180, 1.0)),
                                     np.radians(np.arange(0.25, 360 if outside else 90, 0.5)),
                                     indexing="ij")
                h = horizontal_orbit(th, al, a_r, 1.0, k, G, outside=outside)
                ok = h["status"] == 0
                ex = st.wheel_stability(th[ok], al[ok], a_r, 1.0, k, G, outside)
                rel = ex["growth_rate"] / ex["rate_scale"]
                s, u = ex["verdict"] == S, ex["verdict"] == U
                worst_stable = max(worst_stable, rel[s].max())
                best_unstable = min(best_unstable, rel[u].min())
                unknown += (ex["verdict"] == N).sum()
                n += ok.sum()
    print(f" orbits {n}: largest on a stable orbit {worst_stable:.1e} (STABLE_TOL {st.STABLE_TOL:g}),"
          f" smallest on an unstable one {best_unstable:.1e} (UNSTABLE_TOL {st.UNSTABLE_TOL:g}),"
          f" unknown {unknown}")


SECTIONS = {"table1": section_table1, "tolerance": section_tolerance, "equator": section_equator, "small": section_small,
            "large": section_large, "pole": section_pole, "outside": section_outside,
            "vertical": section_vertical, "sphere": section_sphere}


def main(argv):
    names = argv[1:] or list(SECTIONS)
    t0 = time.time()
    for name in names:
        SECTIONS[name]()
    print(f"\n(total {time.time() - t0:.0f} s)")


if __name__ == "__main__":
    main(sys.argv)
