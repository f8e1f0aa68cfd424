"""Promises of docs/contract.md at its edges: reasons without commas, the
requested quantities echoed in every row, no false root of eq. (29), no
friction coefficient without contact, memory bounded per call and per chunk,
and ``vertical --input`` reading both of its own outputs back."""

from __future__ import annotations

import csv
import io
import math

import numpy as np
import pytest
from click.testing import CliRunner

import deathsphere
from deathsphere import params
from deathsphere.api.orbits import MAX_CHUNK_ROWS
from deathsphere.cli import cli
from deathsphere.inputs import RequestReader
from deathsphere.model import (
    OVERFLOW_REASON,
    REQUEST_FIELDS,
    evaluate,
    make_requests,
    validate_requests,
)
from deathsphere.physics import region, wheel
from deathsphere.physics.status import REASON_TEXT, Reason
from deathsphere.results.vertical import VERTICAL_FIELDS, validate_vertical, vertical_requests
from deathsphere.simulation.status import (
    NO_FIT_VERTICAL_REASON,
    RunStatus,
    failed_reason,
)
from deathsphere.table import Table
from deathsphere.table.reasons import echo

G = 9.80665


def run(*args, stdin=None):
    res = CliRunner().invoke(cli, list(args), input=stdin, catch_exceptions=False)
    return res, list(csv.DictReader(io.StringIO(res.stdout)))


# --------------------------------------------------------------------------
# reasons hold no comma


def _model_reasons() -> list[str]:
    """A request breaking each rule of model.validate_requests (and the
    vertical validator), with user text holding commas where text is echoed."""
    nan = math.nan
    cases = [
        dict(body="bi,ke", theta=60, alpha=10), dict(side="in,side", theta=60, alpha=10),
        dict(alpha=10), dict(theta=200, alpha=10), dict(theta=60, alpha=10, a=-1), dict(theta=60, alpha=10, r=0),
        dict(theta=60, alpha=10, k=-1), dict(theta=60, alpha=10, g=0), dict(theta=60, alpha=10, mu=-1),
        dict(theta=60, alpha=10, a=3.0, r=3.0), dict(theta=60), dict(theta=60, alpha=10, speed=5),
        dict(theta=60, alpha=2e6), dict(theta=60, speed=-1), dict(theta=60, omega=-1),
        dict(theta=60, omega3=1e10, body="sphere"), dict(theta=60, body="sphere", speed=3),
        dict(theta=60, body="sphere"), dict(theta=60, body="sphere", omega3=1, omega=1),
        dict(theta=60, alpha=10, omega3=1), dict(theta=60, body="sphere", omega3=80, alpha=10),
        dict(theta=60, body="particle", alpha=10), dict(theta=nan, alpha=10),
    ]
    reasons = []
    for case in cases:
        reasons += list(validate_requests(make_requests(1, **case)))
    for case in (dict(theta=90), dict(theta=90, v_top=1, phidot_top=1), dict(theta=90, v_top=-1),
                 dict(theta=90, phidot_top=2e9)):
        reasons += list(validate_vertical(vertical_requests(1, **case)))
    return reasons


def _input_reasons() -> list[str]:
    """The reader's reason for each kind of hostile line or cell."""
    body = ('theta,alpha,body\n"6,0",10,wheel\n60,"1,0",wheel\n60,10,"bi,ke"\n60,"10\n"60"x,10,wheel\n'
            '60,10\n60,10,wheel,extra\n60,\x00,wheel\n' + "60," + "9" * 70000 + ",wheel\n60,nan,wheel\n"
            '60,"in,f",wheel\n60,"' + "," * 60 + '",wheel\n')
    reader = RequestReader(io.BytesIO(body.encode("utf-8", "surrogatepass")), REQUEST_FIELDS, {})
    reasons = []
    for chunk in reader.chunks():
        reasons += list(chunk.invalid)
        req = make_requests(len(chunk), invalid=chunk.invalid, input_row=chunk.input_row, **chunk.values)
        reasons += list(validate_requests(req))
    reasons += list(RequestReader(io.BytesIO(b"theta,v_top\n9,0,1\n"), VERTICAL_FIELDS, {}).chunks().__next__().invalid)
    return reasons


def test_every_reason_text_the_package_can_emit_has_no_comma():
    fixed = list(REASON_TEXT) + [NO_FIT_VERTICAL_REASON, OVERFLOW_REASON] + [s.reason for s in RunStatus]
    problems = []
    for name in params.PARAMS:
        problems += list(params.problems(name, [math.nan, -math.inf, math.inf, -1e300, 1e300, 0.5, 0.0, -1.0]))
    model, read = _model_reasons(), _input_reasons()
    assert all(model) and len([r for r in read if r]) >= 12
    texts = [t for t in fixed + problems + model + read if t]
    assert [t for t in texts if "," in t] == []
    # the user's text is still there, recoverable: a comma shows as \x2c
    assert "theta: '6\\x2c0' is not a number" in read
    assert any("(got 'bi\\x2cke')" in t for t in read + model)


def test_a_reason_from_outside_the_package_passes_the_gate():
    table = Table({"reason": np.array([failed_reason("step size too small, t = 1.0\nretry"), ""], dtype=object)})
    assert list(table["reason"]) == ["integrator failed: step size too small; t = 1.0 retry", ""]
    assert "," not in Table({"reason": np.array(["a, b"])})["reason"][0]


def test_echo_is_a_literal_whose_commas_are_escaped():
    assert echo("6,0") == "'6\\x2c0'"
    assert echo("a\\x2c") == "'a\\\\x2c'"      # a backslash typed by the user stays told apart
    assert echo("x" * 100).endswith("...'") and len(echo("x" * 100)) < 50


def test_orbit_input_echoes_hostile_cells_without_commas():
    res, rows = run("orbit", "--input", "-", "--format", "csv", "--no-stability",
                    stdin='theta,alpha,body\n"6,0",10,wheel\n60,10,"bi,ke"\n60,10,wheel\n')
    assert res.exit_code == 1
    assert [r["reason"] for r in rows[:2]] == ["theta: '6\\x2c0' is not a number",
                                                "body must be one of wheel | sphere | particle (got 'bi\\x2cke')"]
    lines = res.stdout.splitlines()
    assert all(line.count(",") == lines[0].count(",") for line in lines if "bi,ke" not in line)


@pytest.mark.parametrize("args, words", [
    (["--theta", "60"], "exactly one of alpha"),
    (["--body", "sphere", "--theta", "60", "--omega3", "80", "--alpha", "10"], "tilt is fixed"),
])
def test_fixed_reasons_that_had_commas(args, words):
    # one row of a batch (invalid, with its reason), so that the reason is a cell
    res, rows = run("orbit", "--input", "-", "--format", "csv", *args,
                    stdin="theta\n60\n")
    assert words in rows[0]["reason"] and "," not in rows[0]["reason"]


# --------------------------------------------------------------------------
# a quantity a request fixes is printed as given


def test_requested_speed_is_echoed_in_a_no_orbit_row():
    _, rows = run("orbit", "--theta", "0", "--com-speed", "1e6", "--com-speed", "7", "--format", "csv")
    assert [r["v_cm_m_s"] for r in rows] == ["1000000.0", "7.0"]
    assert [r["status"] for r in rows] == ["no_orbit", "no_orbit"]
    # the contact's speed, on the axis: no rate gives it, and it is echoed where the contact's speed is
    _, rows = run("orbit", "--theta", "0", "--speed", "1e6", "--speed", "7", "--format", "csv")
    assert [r["v_contact_m_s"] for r in rows] == ["1000000.0", "7.0"]
    assert [(r["status"], r["reason"]) for r in rows] == [("no_orbit", REASON_TEXT[Reason.CONTACT_ON_AXIS])] * 2


def test_every_echoed_request_appears_whatever_the_status():
    t = deathsphere.orbit([0, 60], omega=[1e7, 3.0], stability=False)
    assert t["omega_rad_s"].tolist()[:1] == [1e7] and 3.0 in t["omega_rad_s"].tolist()
    s = deathsphere.orbit(0, body="sphere", omega=3.0, stability=False)        # a pole: no orbit
    assert str(s["status"]) == "no_orbit" and float(s["omega_rad_s"]) == 3.0
    s = deathsphere.orbit([0, 30], body="sphere", omega3=[1.0, 0.001], stability=False)
    assert set(s["omega3_rad_s"].tolist()) == {1.0, 0.001}
    v = deathsphere.vertical(5, [1.0, 2.0], stability=False)                    # does not fit
    assert v["status"].tolist() == ["no_fit", "no_fit"] and v["v_cm_m_s"].tolist() == [1.0, 2.0]
    w = deathsphere.vertical(5, phidot_top=[1.0, 2.0], stability=False)
    assert w["omega_rad_s"].tolist() == [1.0, 2.0]


def test_the_top_speed_is_echoed_in_the_points_output():
    _, rows = run("vertical", "--theta", "90", "--v-top", "6", "--points", "3", "--format", "csv")
    assert [r["v_cm_m_s"] for r in rows][::2] == ["6.0", "6.0"]          # phi = 0 and 360 deg
    _, rows = run("vertical", "--theta", "37", "--phidot-top", "4.1", "--points", "2", "--format", "csv")
    assert [r["omega_rad_s"] for r in rows] == ["4.1", "4.1"]


# --------------------------------------------------------------------------
# no root of eq. (29) at a singular point


@pytest.mark.parametrize("theta", ["0", "180"])
def test_a_singular_point_is_not_a_tilt(theta):
    _, rows = run("orbit", "--theta", theta, "--com-speed", "7", "--format", "csv")
    assert len(rows) == 1
    row = rows[0]
    assert (row["status"], row["alpha_deg"], row["r_prime_m"]) == ("no_orbit", "", "")
    assert row["reason"] == REASON_TEXT[Reason.NO_ALPHA_FOR_RATE]


def test_a_huge_rate_has_no_tilt_in_float64():
    _, rows = run("orbit", "--theta", "60", "--omega", "1e7", "--format", "csv")
    assert [(r["status"], r["alpha_deg"]) for r in rows] == [("no_orbit", "")]


def test_every_root_reproduces_its_target():
    rng = np.random.default_rng(11)
    theta = np.deg2rad(np.concatenate([[0.0, 180.0, 0.001, 179.999, 1.0, 60.0], rng.uniform(0, 180, 60)]))
    for outside in (False, True):
        for kind, target in (("speed", 10.0 ** rng.uniform(-2, 9, theta.size)),
                             ("omega", 10.0 ** rng.uniform(-2, 9, theta.size))):
            sol = region.solve_alpha(theta, 0.3, 3.0, 0.5, G, outside=outside, alpha_range=(-np.pi, np.pi),
                                     **{kind: target})
            found = np.isfinite(sol["alpha"])
            assert np.array_equal(np.sum(found, axis=1), sol["count"])
            assert np.all(found[:, :-1] >= found[:, 1:])                 # kept roots first
            alpha = np.where(found, sol["alpha"], 0.0)
            orb = wheel.horizontal_orbit(theta[:, None], alpha, 0.3, 3.0, 0.5, G, outside)
            got = orb["v_cm" if kind == "speed" else "omega"][found]
            want = np.broadcast_to(target[:, None], found.shape)[found]
            assert np.all(np.abs(got - want) <= region.ROOT_MATCH_RTOL * want)
            assert np.all(np.diff(sol["alpha"], axis=1)[found[:, 1:]] > 0)


# --------------------------------------------------------------------------
# no friction coefficient without contact


@pytest.mark.parametrize("body, extra", [("wheel", {"alpha": np.arange(-175.0, 180.0, 5.0)[None, :]}),
                                         ("sphere", {"omega": np.array([-30.0, -3.0, 0.5, 3.0, 30.0])[None, :]}),
                                         ("particle", {})])
@pytest.mark.parametrize("side", ["inside", "outside"])
def test_no_contact_rows_have_no_mu_required(body, side, extra):
    theta = np.arange(0.0, 181.0, 5.0)[:, None]
    t = deathsphere.orbit(theta, body=body, side=side, stability=False, **extra)
    no_contact = t["status"] == "no_contact"
    assert no_contact.any() or (body, side) == ("particle", "inside")   # inside, a particle only slides off
    assert np.all(np.isnan(t["mu_required"][no_contact]))
    live = np.isin(t["status"], ("ok", "slips"))
    assert np.all(np.isfinite(t["mu_required"][live]))


def test_no_contact_mu_required_is_empty_on_the_command_line():
    _, rows = run("orbit", "--body", "particle", "--side", "outside", "--theta", "100", "--format", "csv")
    assert (rows[0]["status"], rows[0]["mu_required"]) == ("no_contact", "")


# --------------------------------------------------------------------------
# memory


def test_a_broadcast_too_large_is_refused_before_allocation():
    with pytest.raises(params.ParameterError, match=r"at most \d+ rows.*10000000000.*sweep\(\)"):
        deathsphere.orbit(np.zeros((100000, 1)) + 60, np.zeros((1, 100000)) + 10)
    with pytest.raises(params.ParameterError, match=r"vertical_sweep\(\)"):
        deathsphere.vertical(np.zeros((1000, 1)) + 60, np.zeros((1, 1000)) + 6)
    with pytest.raises(params.ParameterError, match=r"vertical_sweep\(\)"):
        deathsphere.vertical(np.zeros(100) + 60, 6, points=1_000_000)


def test_a_huge_chunk_size_is_clamped():
    chunks = deathsphere.sweep("0:180:0.1", "-90:90:0.25", chunk_size=10_000_000, stability=False)
    assert chunks.total > MAX_CHUNK_ROWS
    assert len(next(chunks)) == MAX_CHUNK_ROWS


# --------------------------------------------------------------------------
# vertical --input reads both of its outputs


def test_vertical_reads_its_points_output_back(tmp_path):
    res, points = run("vertical", "--theta", "90", "--v-top", "6", "--points", "5", "--format", "csv")
    path = tmp_path / "p.csv"
    path.write_text(res.stdout)
    res, rows = run("vertical", "--input", str(path), "--v-top", "6", "--format", "csv", "--no-stability")
    assert res.exit_code == 0
    assert [r["input_row"] for r in rows] == ["1", "2", "3", "4", "5"]
    assert {r["theta_deg"] for r in rows} == {p["theta_deg"] for p in points} == {"90.0"}
    # the speed at phi is not the top speed: it is not read as one
    assert {r["v_cm_m_s"] for r in rows} == {"6.0"} and {r["status"] for r in rows} == {"ok"}
    # without --v-top each point's own speed asks for its orbit (eq. 27 back to the top)
    res, rows = run("vertical", "--input", str(path), "--format", "csv", "--no-stability")
    assert res.exit_code == 0 and len(rows) == 5 and {r["status"] for r in rows} == {"ok"}
    assert [float(r["v_cm_m_s"]) for r in rows] == pytest.approx([6.0] * 5, rel=1e-12)


def test_vertical_reads_its_summary_output_back(tmp_path):
    res, first = run("vertical", "--theta", "60", "--theta", "90", "--v-top", "6", "--v-top", "7.5",
                     "--format", "csv", "--no-stability")
    path = tmp_path / "s.csv"
    path.write_text(res.stdout)
    res, again = run("vertical", "--input", str(path), "--format", "csv", "--no-stability")
    assert res.exit_code == 0 and len(again) == len(first) == 4
    for a, b in zip(first, again):
        assert {k: a[k] for k in ("theta_deg", "v_cm_m_s", "a_m", "r_m", "status")} == \
               {k: b[k] for k in ("theta_deg", "v_cm_m_s", "a_m", "r_m", "status")}


def test_evaluate_keeps_input_rows_for_wheels_solved_for():
    t = evaluate(make_requests(3, theta=np.array([0.0, 60.0, 180.0]), speed=7.0), stability=False)
    assert sorted(set(t["input_row"].tolist())) == [1, 2, 3]


def test_the_equator_reason_names_k_when_k_is_what_vanishes():
    t = deathsphere.orbit(90, body="sphere", omega3=5.0, k=0.0, stability=False)
    assert "k omega_3" in str(t["reason"][0])


def test_simulate_echoes_its_tilt_as_given():
    from deathsphere.api.simulation import prepare_simulation, simulation_request

    sim = prepare_simulation(*simulation_request(dict(theta=60, alpha=10.123456789, periods=0.01, points_per_period=4)))
    list(sim.chunks())
    assert sim.summary()["alpha_deg"][0] == 10.123456789


def test_a_value_just_past_a_bound_is_echoed_as_given(run):
    """A height a hair above the globe's diameter says what was typed, not a
    rounded 6 that looks allowed."""
    out = run("ride", "--speed", "8", "-r", "3", "--height", "6.0000001", "--format", "csv")
    assert out.exit_code == 2 and "6.0000001" in out.stderr
    out = run("ride", "--machine", "stunt125-steer", "--steer", "free", "-r", "3", "--height", "6.0000001",
              "--speed", "8", "--format", "csv")
    assert out.exit_code == 2 and "6.0000001" in out.stderr
