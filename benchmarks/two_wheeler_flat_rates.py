"""The benchmark bicycle's nonlinear run from upright straight running on
flat ground against its linear eigenvalues (docs/two-wheeler.md sec. 10.1):
a small kick in lean, hands-free, at each speed; once the faster modes have
died, the lean grows or decays at the rate of the largest real part of the
eigenvalues that ``deathsphere ride --machine benchmark-bicycle --flat``
gives.  The rate is fitted to the log of the lean's envelope: the peaks of
|lean| where the leading mode oscillates (the weave), |lean| itself where
it does not (the capsize mode).

The fit starts when the next mode is 6 e-folds below the leading one
(t0 = 6 / gap of real parts) and lasts 8 s, or until the lean passes 2
degrees.  Stable speeds are kicked by 0.5 degrees (the benchmark's case),
unstable ones by 1e-4 degrees so that the window stays at small leans.

    PYTHONPATH=. python3 benchmarks/two_wheeler_flat_rates.py [--speeds 3,4,5,...]
"""

import argparse
import time

import numpy as np

import deathsphere
from deathsphere.api.two_wheelers import simulate_two_wheeler

SPEEDS = (3.0, 3.5, 4.0, 4.5, 5.0, 5.5, 6.0, 6.5, 7.0, 8.0, 10.0)
WINDOW = 8.0
LARGEST_LEAN = np.radians(2.0)


def envelope_rate(t, lean, oscillating):
    """The slope of log |lean|; oscillating, of the log of its peaks."""
    a = np.abs(lean)
    keep = np.ones(a.shape, bool)
    if oscillating:
        keep[1:-1] = (a[1:-1] > a[:-2]) & (a[1:-1] >= a[2:])
        keep[[0, -1]] = False
    return np.polyfit(t[keep], np.log(a[keep]), 1)[0], int(keep.sum())


def measure(speed):
    # the benchmark's case at its gravity, g = 9.81 (Table 1)
    eig = deathsphere.ride(machine="benchmark-bicycle", flat=True, speed=speed, g=9.81)
    values = np.array([complex(eig[f"eig_{k}_re"][0], eig[f"eig_{k}_im"][0]) for k in range(1, 5)])
    lead = values[0]
    gap = lead.real - max(v.real for v in values if abs(v.real - lead.real) > 1e-9)
    t0 = 6.0 / gap
    kick = 0.5 if str(eig["stability"][0]) == "stable" else 1e-4
    start = time.perf_counter()
    series, summary = simulate_two_wheeler("benchmark-bicycle", flat=True, speed=speed, g=9.81, perturb=kick,
                                           hands_free=True, duration=t0 + WINDOW, points_per_period=200,
                                           rtol=1e-10, atol=1e-14)
    wall = time.perf_counter() - start
    t, lean = np.asarray(series["t_s"]), np.radians(np.asarray(series["lean_surface_deg"]))
    past = np.flatnonzero(np.abs(lean) > LARGEST_LEAN)
    t1 = t[past[0]] if past.size else t[-1]
    window = (t >= t0) & (t <= t1)
    rate, n = envelope_rate(t[window], lean[window], lead.imag != 0)
    return {"speed": speed, "lead": lead, "mode": "weave" if lead.imag else "capsize", "rate": rate,
            "error": (rate - lead.real) / abs(lead.real), "t0": t0, "t1": t1, "n": n, "kick": kick,
            "status": str(summary["status"][0]), "drift": float(summary["max_energy_drift"][0]), "wall": wall}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--speeds", default=",".join(f"{v:g}" for v in SPEEDS))
    args = parser.parse_args()
    print("| speed m/s | leading eigenvalue 1/s | mode | fitted rate 1/s | relative error | fit window s "
          "| kick deg | energy drift |")
    print("|---|---|---|---|---|---|---|---|")
    for v in (float(x) for x in args.speeds.split(",")):
        m = measure(v)
        lead = m["lead"]
        shown = f"{lead.real:+.4f} ± {abs(lead.imag):.4f}i" if lead.imag else f"{lead.real:+.4f}"
        print(f"| {v:g} | {shown} | {m['mode']} | {m['rate']:+.4f} | {m['error']:+.2%} | "
              f"{m['t0']:.1f}-{m['t1']:.1f} ({m['n']} points) | {m['kick']:g} | {m['drift']:.0e} |", flush=True)


if __name__ == "__main__":
    main()
