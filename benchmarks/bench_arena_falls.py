"""Falls on the wall of death (docs/show.md sec. 11): a Monte Carlo of 10^5
falls in the shipped worked act (three riders on a 32 ft drum) and in the
shipped bowl (a profile, whose flights' landings are certified by the gap's
Lipschitz bound: physics/first_touch.py), against the
show's target for the globe (under a minute for 10^5, bench_show.py), and
the flight alone (physics.landing.landing_on) per flight.

    PYTHONPATH=. OMP_NUM_THREADS=1 python3 benchmarks/bench_arena_falls.py [--falls 100000] [--repeat 3]
"""

import argparse
import os
import sys
from pathlib import Path

import numpy as np

for name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):  # one core, as the target says
    os.environ.setdefault(name, "1")

sys.path.insert(0, str(Path(__file__).resolve().parent))
from timing import best_of  # noqa: E402

from deathsphere.api.shows import show  # noqa: E402
from deathsphere.physics.ground import Cylinder  # noqa: E402
from deathsphere.physics.landing import landing_on  # noqa: E402

FALLS_TARGET_S = 60.0
PLAN = Path(__file__).resolve().parents[1] / "examples" / "wall_of_death.toml"
BOWL = Path(__file__).resolve().parents[1] / "examples" / "bowl_of_death.toml"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--falls", type=int, default=100_000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    act = show(str(PLAN))
    t_mc = best_of(lambda: act.falls(args.falls, seed=1), args.repeat)
    print(f"Monte Carlo of {args.falls} falls on the drum: {t_mc:.2f} s (target {FALLS_TARGET_S:.0f} s for 10^5: "
          f"{t_mc / FALLS_TARGET_S * 100_000 / args.falls:.3f} of it)")
    bowl = show(str(BOWL))
    t_bowl = best_of(lambda: bowl.falls(args.falls, seed=1), args.repeat)
    print(f"Monte Carlo of {args.falls} falls in the bowl (a profile): {t_bowl:.2f} s")
    rng = np.random.default_rng(0)
    n = args.falls
    radius = 16 * 0.3048
    rho, phi = rng.uniform(0.2, 0.95, n) * radius, rng.uniform(0, 2 * np.pi, n)
    x0 = np.stack([rho * np.cos(phi), rho * np.sin(phi), rng.uniform(0.1, 3.6, n)])
    v0 = np.stack([rng.normal(size=n) * 6, rng.normal(size=n) * 6, np.zeros(n)])
    drum = Cylinder(radius, 12 * 0.3048)
    t_fly = best_of(lambda: landing_on(x0, v0, drum, 9.80665), args.repeat)
    print(f"landing_on, {n} flights in the drum: {t_fly:.3f} s ({t_fly / n * 1e6:.2f} us a flight)")


if __name__ == "__main__":
    main()
