"""Cost of the Whipple bicycle's generated equations (docs/two-wheeler.md
sec. 5): time per state of the generated equations, of the constrained
accelerations and of the pitch's Newton solve over a batch of states, and
of the benchmark's matrices; with --derive, the symbolic derivation too
(needs sympy).  With --lanes N, steady turns alone and with their stability
for a grid of about N lanes (heights x speeds) on a 16-foot globe (sec.
8.6); with --against REV as well, the same grid computed by the package as
it was at git revision REV (extracted into a temporary directory, both runs
in subprocesses one after the other): the ratios of the times and the
largest differences of the answers; with --globe, the tables of sec. 8.5
(hands-free turns per height, and the stability of the turns with the steer
torque held).

    PYTHONPATH=. python3 benchmarks/bench_two_wheeler.py [--n 10000] [--repeat 5] [--derive]
    PYTHONPATH=. python3 benchmarks/bench_two_wheeler.py --lanes 10000 [--against REV]
    PYTHONPATH=. python3 benchmarks/bench_two_wheeler.py --globe
"""

import argparse
import io
import os
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

import numpy as np

from deathsphere.physics.ground import Cylinder, Sphere
from deathsphere.physics.two_wheeler import _generated, grounds, linear, motion, stability, steady
from deathsphere.physics.two_wheeler.parameters import BENCHMARK_GRAVITY, benchmark_bicycle

GLOBE = 2.4384      # 16 ft
SPHERE = Sphere(GLOBE)
#: Every table here is the benchmark bicycle's at the benchmark's gravity (Table 1).
G = BENCHMARK_GRAVITY


def best_of(fn, repeat):
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


#: What --lanes keeps of the answers, to compare two versions.
ANSWERS = ("lean", "steer", "steer_torque", "eigenvalues_free", "eigenvalues_locked")


def lanes(n, save=None):
    """Steady turns alone, then with their stability (steer free and
    locked), for a grid of about n lanes: sqrt(n) heights x sqrt(n) rear
    speeds; with ``save``, the times and the answers into that .npz file."""
    side = int(round(np.sqrt(n)))
    heights = np.linspace(0.2, 4.6, side)
    speeds = np.linspace(1.0, 15.0, side)
    H, V = np.meshgrid(heights, speeds, indexing="ij")
    theta = np.arccos(H.ravel() / GLOBE - 1)
    b = benchmark_bicycle()
    times = []
    for run in (lambda: steady.turns_for_speed(theta, V.ravel(), b, SPHERE, G),
                lambda: stability.turns_with_stability(theta, b, SPHERE, G, speed=V.ravel())):
        t0, c0 = time.perf_counter(), time.process_time()
        out = run()
        times.append((time.perf_counter() - t0, time.process_time() - c0))
    turns = int(np.isfinite(out["lean"]).sum())
    print(f"lanes {theta.size} ({side} heights x {side} speeds), turns {turns}")
    for name, (wall, cpu) in zip(("steady turns", "with stability"), times):
        print(f"  {name:15s} {wall:6.2f} s wall, {cpu:6.2f} s CPU, {cpu / theta.size * 1e3:.3f} ms CPU per lane")
    if save:
        np.savez(save, times=np.array(times), **{k: out[k] for k in ANSWERS})


def _run_lanes(n, package_root, save):
    """lanes(n) in a subprocess importing deathsphere from package_root."""
    env = dict(os.environ, PYTHONPATH=str(package_root))
    subprocess.run([sys.executable, __file__, "--lanes", str(n), "--save", str(save)], env=env, check=True)
    return np.load(save)


def _largest_difference(old, new):
    """max |old - new| (complex: the modulus) over the entries (lanes, turns[, k]) both give, and how many
    entries one gives and the other not."""
    k = min(old.shape[1], new.shape[1])
    a, b = old[:, :k], new[:, :k]
    both = np.isfinite(a) & np.isfinite(b)
    only = int((np.isfinite(a) != np.isfinite(b)).sum() + np.isfinite(old[:, k:]).sum() + np.isfinite(new[:, k:]).sum())
    return (float(np.abs(a - b)[both].max()) if both.any() else 0.0), only


def against(n, revision):
    """The grid of lanes(n) by the package at git revision ``revision`` and
    by this one: the ratio of the times, the largest differences."""
    root = Path(__file__).resolve().parent.parent
    with tempfile.TemporaryDirectory() as tmp:
        archive = subprocess.run(["git", "-C", str(root), "archive", revision, "deathsphere"], check=True,
                                 capture_output=True).stdout
        old_root = Path(tmp, "old")
        with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
            tar.extractall(old_root, filter="data")
        print(f"revision {revision}:")
        old = _run_lanes(n, old_root, Path(tmp, "old.npz"))
        print("this tree:")
        new = _run_lanes(n, root, Path(tmp, "new.npz"))
        for name, (t_old, t_new) in zip(("steady turns", "with stability"), zip(old["times"], new["times"])):
            print(f"{name:15s} old/new: {t_old[1] / t_new[1]:.2f} CPU, {t_old[0] / t_new[0]:.2f} wall")
        print("largest differences over the turns both give (and entries given by one only):")
        for key, unit in zip(ANSWERS, ("rad", "rad", "N m", "1/s", "1/s")):
            diff, only = _largest_difference(old[key], new[key])
            print(f"  {key:20s} {diff:.2e} {unit} ({only})")


def globe():
    """The tables of docs/two-wheeler.md sec. 8.5."""
    b = benchmark_bicycle()
    heights = np.round(np.arange(0.2, 4.61, 0.4), 1)
    theta = np.arccos(heights / GLOBE - 1)
    out = stability.turns_with_stability(theta, b, SPHERE, G, torque=0.0)
    print("hands-free turns (steer torque 0), 16-ft globe, benchmark bicycle, head (0.3, -1.7) m")
    print("height_m lean_deg steer_deg v_rear v_front v_cm normal_rear normal_front mu_rear mu_front head_m "
          "growth_free growth_locked")
    for i, j in zip(*np.nonzero(np.isfinite(out["lean"]))):
        print(f"{heights[i]:4.1f} {np.rad2deg(out['lean'][i, j]):7.1f} {np.rad2deg(out['steer'][i, j]):6.1f} "
              f"{out['v_rear'][i, j]:6.2f} {out['v_front'][i, j]:6.2f} {out['v_cm'][i, j]:6.2f} "
              f"{out['normal_rear'][i, j]:6.2f} {out['normal_front'][i, j]:6.2f} "
              f"{out['mu_required_rear'][i, j]:5.2f} {out['mu_required_front'][i, j]:5.2f} "
              f"{out['head_clearance'][i, j]:5.2f} {out['growth_free'][i, j]:6.2f} {out['growth_locked'][i, j]:6.2f}")
    speeds = np.arange(1.0, 20.01, 0.5)
    H, V = np.meshgrid(heights, speeds, indexing="ij")
    out = stability.turns_with_stability(np.arccos(H.ravel() / GLOBE - 1), b, SPHERE, G, speed=V.ravel())
    print("\nturns with the steady steer torque held, rear speeds 1-20 m/s")
    print("height_m stable_free stable_locked least_growth_free_1_s at_v_m_s lean_deg steer_torque_n_m "
          "torque_range_n_m")
    # every turn of every lane: (heights, speeds, turns)
    shape = H.shape + (out["lean"].shape[1],)
    growth, locked = (np.where(np.isfinite(out[k]), out[k], np.inf).reshape(shape)
                      for k in ("growth_free", "growth_locked"))
    torque, lean = out["steer_torque"].reshape(shape), out["lean"].reshape(shape)
    print(f"(at most {shape[2]} turns per lane)")
    for i, h in enumerate(heights):
        if not np.isfinite(growth[i]).any():
            print(f"{h:4.1f} no turn")
            continue
        k, t = np.unravel_index(np.argmin(growth[i]), growth[i].shape)
        print(f"{h:4.1f} {int((growth[i] < -stability.STABLE_BELOW).sum()):3d} "
              f"{int((locked[i] < -stability.STABLE_BELOW).sum()):3d} {growth[i, k, t]:7.3f} {speeds[k]:5.1f} "
              f"{np.rad2deg(lean[i, k, t]):6.1f} {torque[i, k, t]:6.2f} "
              f"{np.nanmin(torque[i]):6.2f}..{np.nanmax(torque[i]):6.2f}")


def single_contact():
    """ride's single-contact machine with the benchmark bicycle's mass, mass
    centre height and locked inertia (products and the mass centre's offset
    ahead of the rear contact dropped): its neutral speed bands per height."""
    from deathsphere.physics.ground import Sphere
    from deathsphere.physics.machine import ride_orbit
    from deathsphere.physics.machine_arrays import MachineArrays
    from deathsphere.physics.machine_dynamics import machine_stability

    b = benchmark_bicycle()
    bodies = [(b.mR, 0.0, -b.rR, b.IRxx, b.IRyy, b.IRxx), (b.mB, b.xB, b.zB, b.IBxx, b.IByy, b.IBzz),
              (b.mH, b.xH, b.zH, b.IHxx, b.IHyy, b.IHzz), (b.mF, b.w, -b.rF, b.IFxx, b.IFyy, b.IFxx)]
    m = sum(body[0] for body in bodies)
    xg = sum(mb * x for mb, x, *_ in bodies) / m
    zg = sum(mb * z for mb, _, z, *_ in bodies) / m
    roll = sum(ix + mb * (z - zg) ** 2 for mb, x, z, ix, iy, iz in bodies)
    pitch = sum(iy + mb * ((x - xg) ** 2 + (z - zg) ** 2) for mb, x, z, ix, iy, iz in bodies)
    yaw = sum(iz + mb * (x - xg) ** 2 for mb, x, z, ix, iy, iz in bodies)
    spin, a, h = b.IRyy + b.IFyy, b.rR, -zg
    print(f"\nsingle-contact machine: mass {m} kg, h {h:.4f} m, I_roll {roll:.3f}, I_pitch {pitch:.3f}, "
          f"I_yaw {yaw:.3f} kg m^2, J {spin}, a {a} m (mass centre {xg:.3f} m ahead of the contact, dropped)")
    print("height_m orbits_1_20_m_s neutral v_contact_m_s")
    machine = MachineArrays(*(np.asarray(x, dtype=float) for x in (m, h, a, 0.0, roll, pitch, yaw, spin, 1.7)))
    globe = Sphere(GLOBE)
    alpha = np.deg2rad(np.linspace(-89.0, 179.0, 2000))
    for height in np.round(np.arange(0.2, 4.61, 0.4), 1):
        theta = np.arccos(height / GLOBE - 1)
        orbit = ride_orbit(theta, alpha, globe, G, machine)
        ok = np.isfinite(orbit["omega"]) & (orbit["status"] == 0)
        ok &= (orbit["v_contact"] > 1.0) & (orbit["v_contact"] < 20.0)
        if not ok.any():
            print(f"{height:4.1f} no orbit")
            continue
        growth = machine_stability(np.full(ok.sum(), theta), alpha[ok], globe, G, machine)["growth_rate"]
        v = orbit["v_contact"][ok][growth < stability.STABLE_BELOW]
        band = f"{v.min():.2f}..{v.max():.2f}" if v.size else "none"
        print(f"{height:4.1f} {int(ok.sum()):4d} {v.size:3d} {band}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=10_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--derive", action="store_true", help="time the symbolic derivation (sympy)")
    ap.add_argument("--lanes", type=int, default=0, help="time steady turns with stability for about this many lanes")
    ap.add_argument("--against", metavar="REV", help="with --lanes: compare with the package at git revision REV")
    ap.add_argument("--save", help=argparse.SUPPRESS)
    ap.add_argument("--globe", action="store_true", help="print the 16-foot globe's tables")
    args = ap.parse_args()
    if args.lanes and args.against:
        against(args.lanes, args.against)
        return
    if args.lanes:
        lanes(args.lanes, args.save)
        return
    if args.globe:
        globe()
        single_contact()
        return
    bicycle = benchmark_bicycle()
    p = motion.parameter_values(bicycle, G)
    rng = np.random.default_rng(1)
    q = rng.uniform(-0.3, 0.3, (8, args.n))
    u = rng.uniform(-2.0, 2.0, (8, args.n))
    q_wall = q + np.array([np.pi / 2] + [0.0] * 7)[:, None]    # around the equator of a 3 m sphere
    p_wall = motion.parameter_values(bicycle, G, Sphere(3.0))
    # the general path on the same sphere and on a 32-foot drum: the meridian read and the rim angle found per state
    general = grounds.OnRevolution(Sphere(3.0))
    q_general = q + np.array([3.0 * np.pi / 2] + [0.0] * 7)[:, None]
    drum = grounds.of(Cylinder(4.8768))
    q_drum = q + np.array([2.0] + [0.0] * 7)[:, None]
    for name, fn in (("flat_equations", lambda: _generated.flat_equations(q, u, p, 0.0)),
                     ("sphere_equations", lambda: _generated.sphere_equations(q_wall, u, p_wall, 0.0)),
                     ("sphere, general", lambda: general.equations(q_general, u, p, 0.0)),
                     ("drum equations", lambda: drum.equations(q_drum, u, p, 0.0)),
                     ("accelerations", lambda: motion.accelerations(q, u, p)),
                     ("pitch (Newton)", lambda: motion.pitch(q, p))):
        seconds = best_of(fn, args.repeat)
        print(f"{name:16s} {seconds / args.n * 1e6:8.2f} us/state  (batch {args.n})")
    seconds = best_of(lambda: linear.benchmark_matrices(bicycle, G), args.repeat)
    print(f"{'M, C1, K0, K2':16s} {seconds * 1e3:8.2f} ms")
    if args.derive:
        from deathsphere.physics.two_wheeler import derivation

        for surface in derivation.SURFACES:
            t0, c0 = time.perf_counter(), time.process_time()
            derivation.derive(surface)
            print(f"derive {surface:9s} {time.perf_counter() - t0:8.1f} s  ({time.process_time() - c0:.1f} s CPU)")


if __name__ == "__main__":
    main()
