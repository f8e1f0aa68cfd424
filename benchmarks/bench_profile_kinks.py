"""What the restarts at a profile's knots cost and buy (docs/simulation.md,
"On any ground"): the paper's ball and wheel kicked on a lane of the bowl
z = rho^2 / (2 * 3 m) sampled at 41 points, three laps at rtol 1e-12, with
the integration restarted where a contact crosses a knot and without (the
ground model's ``kinks`` turned off): wall time, steps and right-hand-side
calls of each, and the energy's largest drift over the kinetic energy, read
from the recorded states with the tests' own geometry (tests/wall_contacts.py).

    PYTHONPATH=. OMP_NUM_THREADS=1 python3 benchmarks/bench_profile_kinks.py
"""

import os
import sys
import time
from pathlib import Path

for name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):  # one core
    os.environ.setdefault(name, "1")

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
import numpy as np  # noqa: E402
from wall_contacts import ball_contact, state_energy, wheel_contact  # noqa: E402

import deathsphere.simulation.bodies as bodies  # noqa: E402
from deathsphere.api.simulation import prepare_simulation, simulation_request  # noqa: E402
from deathsphere.physics.ground import Profile  # noqa: E402

RHO = np.linspace(0.0, 4.0, 41)
BOWL = Profile(RHO, RHO ** 2 / 6.0)
BODIES = {"ball": dict(body="sphere", omega=3, a=1.0), "wheel": dict(alpha=20, a=2.0)}


def run(body: str):
    typed = BODIES[body]
    sim = prepare_simulation(*simulation_request({"record_states": True, "points_per_period": 50, "surface": BOWL,
                                                  "height": 1.5, "perturb": 1, "periods": 3, "rtol": 1e-12,
                                                  **typed}))
    start = time.perf_counter()
    _, summary = sim.run()
    seconds = time.perf_counter() - start
    states, a, ground = sim.sample_states()["state"], typed["a"], sim.starts.params.ground
    ball = body == "ball"
    p = ball_contact(ground, states[0:3], a)[0] if ball else wheel_contact(ground, states[0:3], states[3:6], a)[0]
    energy, kinetic = state_energy(states, p, a, float(summary["k"][0]), ball)
    drift = float(np.max(np.abs(energy - energy[0])) / np.min(kinetic))
    return seconds, int(summary["n_steps"][0]), int(summary["n_fev"][0]), drift


def main():
    restarts = bodies._OnGround.kinks
    for body in BODIES:
        bodies._OnGround.kinks = restarts
        on = run(body)
        bodies._OnGround.kinks = lambda self, p: None
        off = run(body)
        bodies._OnGround.kinks = restarts
        print(f"{body}: restarts {on[0]:.2f} s, {on[1]} steps, {on[2]} calls, drift {on[3]:.2e} | "
              f"none {off[0]:.2f} s, {off[1]} steps, {off[2]} calls, drift {off[3]:.2e} | "
              f"time ratio {on[0] / off[0]:.2f}")


if __name__ == "__main__":
    main()
