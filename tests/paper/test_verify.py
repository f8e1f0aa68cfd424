"""`deathsphere verify`: every claim's verdict, asserted.

The expected verdicts are the findings recorded in docs/errata.md (decided by
the derivations and tests cited there), not read back from the checker.
"""

import json

import numpy as np
import pytest

from deathsphere.physics.status import Status
from deathsphere.results import verify

EXPECTED = {
    "T1-v": "confirmed", "T1-mu": "corrected", "T1-g": "corrected",
    "E29": "confirmed", "E0": "confirmed", "Q": "confirmed", "A0": "confirmed", "UP": "confirmed",
    "P": "confirmed",
    "E28a": "confirmed", "E28b": "corrected", "E28": "corrected", "E82": "confirmed",
    "E56": "confirmed", "E58": "confirmed", "E58-text": "corrected", "E57": "corrected",
    "E59": "confirmed", "S5-spin": "corrected", "S3-class": "corrected", "FIG": "confirmed",
    # sec. 2.3 (docs/stability.md sec. 6, docs/errata.md E1-E9)
    "STAB-V": "refuted", "E103": "corrected", "STAB-EQ": "refuted", "E133": "refuted",
    "STAB-SMALL": "confirmed", "E207": "refuted", "STAB-LARGE": "refuted", "E208": "corrected",
    "STAB-OUT": "refuted", "STAB-SPH": "confirmed", "T1-stable": "confirmed",
}


@pytest.fixture(scope="module")
def checklist():
    return verify.run()


def test_every_claim_is_expected(checklist):
    assert set(checklist["id"]) == set(EXPECTED), "a claim was added or dropped: decide its verdict here"


@pytest.mark.parametrize("claim_id", sorted(EXPECTED))
def test_verdict(checklist, claim_id):
    i = list(checklist["id"]).index(claim_id)
    assert checklist["verdict"][i] == EXPECTED[claim_id], checklist["evidence"][i]
    assert checklist["evidence"][i]


def test_cli_checklist_and_counts(run):
    res = run("verify", "--claim", "T1-v", "--claim", "T1-g", "--format", "table", env={"COLUMNS": "120"})
    assert res.exit_code == 0
    assert "1 confirmed, 1 corrected, 0 refuted (2 claims)" in res.stdout
    data = json.loads(run("verify", "--claim", "E82", "--format", "json").stdout)
    assert data[0]["verdict"] == "confirmed" and "cos phi" in data[0]["evidence"]


def test_cli_unknown_claim(run):
    res = run("verify", "--claim", "nope")
    assert res.exit_code == 2 and "unknown claim" in res.stderr


def test_several_processes_give_the_same_table(checklist):
    # the survey claims (Q, UP share a cached survey; S3-class the outside
    # one), a root-finding one and a cheap one, on two processes
    ids = ["T1-v", "Q", "UP", "E82", "S3-class", "E28"]
    told = []
    table = verify.run(ids, jobs=2, progress=lambda claim: told.append(claim.id))
    assert sorted(told) == sorted(ids)
    rows = [i for i, c in enumerate(checklist["id"]) if c in ids]       # the order of the paper
    for column in ("id", "verdict", "evidence"):
        assert list(table[column]) == [checklist[column][i] for i in rows]


def test_figure_check_in_blocks_counts_every_neighbour_pair_once(monkeypatch):
    # Orbits made infeasible beyond a slanted line theta + alpha = 2 rad,
    # which none of the three curves follows: the changes of feasibility
    # there (along theta and along alpha) go unexplained, and their count
    # must not depend on how the grid is cut into blocks of rows.
    exact = verify.wheel.horizontal_orbit

    def cut(theta, alpha, *args, **kwargs):
        res = exact(theta, alpha, *args, **kwargs)
        res["status"] = np.where(theta + alpha > 2.0, Status.SLIPS, res["status"])
        return res

    monkeypatch.setattr(verify.wheel, "horizontal_orbit", cut)

    def unexplained(rows):
        monkeypatch.setattr(verify, "_FIGURE_ROWS", rows)
        evidence = verify.run(["FIG"])["evidence"][0]
        return int(evidence.rsplit("(", 1)[1].split()[0])

    whole = unexplained(1200)
    assert whole > 0
    assert unexplained(7) == whole
    assert unexplained(1199) == whole
