"""The benchmark bicycle's eigenvalues against speed (Meijaard,
Papadopoulos, Ruina & Schwab 2007, Figure 3), drawn from what
``deathsphere ride --machine benchmark-bicycle --flat --speed 0:10:0.01``
prints: the real parts black, the imaginary parts' magnitudes blue, the
weave and capsize speeds from ``--summary`` dashed (docs/two-wheeler.md
sec. 10).  Needs matplotlib (the plot extra).

    PYTHONPATH=. python3 benchmarks/two_wheeler_eigenvalues.py [--output deathsphere/docs/two-wheeler-eigenvalues.png]
"""

import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import deathsphere  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", default="deathsphere/docs/two-wheeler-eigenvalues.png")
    args = parser.parse_args()
    # the benchmark's figure is at its gravity, g = 9.81 (Table 1): the run is given it
    table = deathsphere.ride(machine="benchmark-bicycle", flat=True, speed="0:10:0.01", g=9.81)
    summary = deathsphere.ride(machine="benchmark-bicycle", flat=True, speed="0:10:0.01", summary=True, g=9.81)
    v = np.asarray(table["speed_m_s"], float)
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=120)
    for i in range(1, 5):
        re, im = np.asarray(table[f"eig_{i}_re"], float), np.asarray(table[f"eig_{i}_im"], float)
        ax.plot(v, re, ".", ms=1.5, color="k")
        ax.plot(v, np.abs(im), ".", ms=0.8, color="tab:blue")
    weave, capsize = float(summary["weave_speed_m_s"][0]), float(summary["capsize_speed_m_s"][0])
    ax.axvspan(weave, capsize, color="tab:green", alpha=0.12, lw=0)
    for x, name in ((weave, "weave"), (capsize, "capsize")):
        ax.axvline(x, ls="--", lw=0.8, color="tab:green")
        ax.text(x, 9.3, f" {name} {x:.4f} m/s", fontsize=8, color="tab:green", rotation=90, va="top")
    ax.axhline(0, lw=0.6, color="0.5")
    ax.set_xlim(0, 10)
    ax.set_ylim(-10, 10)
    ax.set_xlabel("rear contact speed v (m/s)")
    ax.set_ylabel("eigenvalues (1/s): real part (black), |imaginary part| (blue)")
    ax.set_title("benchmark bicycle, upright straight running (Meijaard et al. 2007, Fig. 3)", fontsize=10)
    fig.tight_layout()
    fig.savefig(args.output)
    print(f"wrote {args.output}: weave {weave!r} m/s, capsize {capsize!r} m/s")


if __name__ == "__main__":
    main()
