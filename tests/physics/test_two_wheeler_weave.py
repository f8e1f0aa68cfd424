"""The weave speed of bicycles other than the benchmark: the speed where
the weave's complex pair of eigenvalues crosses into the left half plane
(Meijaard et al. 2007, sec. 5), checked against the eigenvalues themselves.

The Hurwitz determinant the solver roots also vanishes wherever two real
eigenvalues sum to zero: BicycleParameters' Browser bicycle has a real
pair +-3.69 1/s at 0.51 m/s, once reported as its weave speed.  The
independent check here bisects on the largest real part of the complex
eigenvalues (the oscillatory modes) alone.  Data: tests/data/README.md."""

from pathlib import Path

import numpy as np
import pytest

import deathsphere

DATA = Path(__file__).resolve().parents[1] / "data"
#: The benchmark's published figures are at g = 9.81 m/s^2, as BicycleParameters' files give it.
G_BENCHMARK = 9.81


def _eigenvalues(machine, speeds):
    t = deathsphere.ride(machine=machine, flat=True, speed=np.asarray(speeds, dtype=float), g=G_BENCHMARK)
    re = np.stack([np.asarray(t[f"eig_{i}_re"], dtype=float).reshape(-1) for i in range(1, 5)], axis=-1)
    im = np.stack([np.asarray(t[f"eig_{i}_im"], dtype=float).reshape(-1) for i in range(1, 5)], axis=-1)
    return re, im


def _oscillation_growth(machine, speeds):
    """The largest real part among the complex eigenvalues at each speed (-inf where all are real)."""
    re, im = _eigenvalues(machine, speeds)
    return np.where(np.abs(im) > 1e-9, re, -np.inf).max(axis=-1)


def _weave_by_bisection(machine, low, high):
    """Where the oscillations' largest real part turns negative, by bisection
    on [low, high] (positive at low, negative at high)."""
    assert _oscillation_growth(machine, [low])[0] > 0 > _oscillation_growth(machine, [high])[0]
    for _ in range(60):
        mid = 0.5 * (low + high)
        if _oscillation_growth(machine, [mid])[0] > 0:
            low = mid
        else:
            high = mid
    return 0.5 * (low + high)


@pytest.mark.parametrize("name, bracket", [("Browser", (3.5, 5.0)), ("Fisher", (3.5, 6.5))])
def test_weave_speed_is_where_the_oscillation_turns_stable(name, bracket):
    machine = deathsphere.two_wheeler_file(DATA / f"{name}Benchmark.txt")
    (summary,) = list(deathsphere.ride(machine=machine, flat=True, speed=np.arange(0.0, 10.05, 0.1), g=G_BENCHMARK,
                                       summary=True))
    expected = _weave_by_bisection(machine, *bracket)
    assert summary["weave_speed_m_s"] == pytest.approx(expected, abs=1e-7)
    # the weave grows just below it and decays just above
    below, above = _oscillation_growth(machine, [expected * (1 - 1e-4), expected * (1 + 1e-4)])
    assert below > 0 > above


def test_browser_has_the_real_pair_that_once_fooled_the_root():
    """At 0.51 m/s two real eigenvalues of the Browser bicycle sum to zero:
    the Hurwitz determinant has a root there which is no weave crossing."""
    machine = deathsphere.two_wheeler_file(DATA / "BrowserBenchmark.txt")
    re, im = _eigenvalues(machine, [0.5146])
    assert np.all(np.abs(im) < 1e-12)                       # every eigenvalue real
    pair = np.sort(re[0])
    assert np.min(np.abs(pair[:, None] + pair[None, :]) + 10 * np.eye(4)) < 1e-2   # two of them sum to zero
    (summary,) = list(deathsphere.ride(machine=machine, flat=True, speed=np.arange(0.0, 10.05, 0.1), g=G_BENCHMARK,
                                       summary=True))
    assert summary["weave_speed_m_s"] > 4.0


def test_the_benchmarks_weave_speed_is_unchanged():
    (summary,) = list(deathsphere.ride(machine="benchmark-bicycle", flat=True, speed=np.arange(0.0, 10.05, 0.5),
                                       g=G_BENCHMARK, summary=True))
    assert summary["weave_speed_m_s"] == pytest.approx(4.29238253634111, abs=1e-12)
