"""``stability_method`` is a short label, one per way, the same in every
command; its sentence is in the docs and the ``methods`` table, and
``stability_kind`` says what kind of stable an analysed row is."""

from __future__ import annotations

import numpy as np

import deathsphere
from deathsphere.physics.ground import Profile
from deathsphere.physics.stability.methods import METHOD_TEXT, method_text


def _methods(table) -> set:
    return {m for m in np.ravel(table["stability_method"]).tolist() if m}


def test_every_method_a_command_writes_is_a_documented_short_label():
    contract = deathsphere.doc_text("contract")
    tables = [
        deathsphere.orbit(theta=[60, 120], alpha=[10, 40]),
        deathsphere.orbit(theta=[60, 120], omega=8.0, body="sphere"),
        deathsphere.orbit(theta=100, body="particle"),
        deathsphere.orbit(theta=60, alpha=10, k=0.0),
        deathsphere.orbit(alpha=10, surface="cylinder", diameter=10, height=1.0, side="outside"),
        deathsphere.ride(theta=[90, 100], speed=8.0, diameter="16ft"),
        deathsphere.ride(height=1.0, speed=12.0, surface="cylinder", diameter="32ft"),
        deathsphere.ride(height=1.0, com_speed=10.0, surface="profile",
                         profile=Profile([5.0, 5.0, 5.0, 5.0], [0.0, 1.0, 2.0, 3.0])),
    ]
    seen = set().union(*(_methods(t) for t in tables))
    assert seen <= set(METHOD_TEXT), seen - set(METHOD_TEXT)
    assert {"exact-linearisation", "exact-linearisation-steer-locked", "not-analysed-particle",
            "not-analysed-k0"} <= seen
    # a machine on a profile is analysed on the profile's parallel surface: the label is no longer written
    assert "not-analysed-profile" not in seen
    for label in METHOD_TEXT:
        assert len(label) <= 32 and " " not in label
        assert f"`{label}`" in contract
        assert method_text(label) != label


def test_the_machines_rows_say_what_kind_of_stable_they_are():
    t = deathsphere.ride(theta=np.arange(92.0, 170.0, 4.0), speed=9.0, diameter="16ft")
    analysed = t["stability_method"] == "exact-linearisation-steer-locked"
    assert analysed.any()
    kinds = t["stability_kind"][analysed]
    # the machine conserves energy: a stable orbit's disturbance persists (neutral), an unstable one grows
    stable = t["stability"][analysed] == "stable"
    assert stable.any() and not stable.all()
    assert set(kinds[stable].tolist()) <= {"neutral"}
    assert set(kinds[~stable & (t["stability"][analysed] == "unstable")].tolist()) <= {"growing"}
    assert not any(t["stability_kind"][~analysed].tolist())
