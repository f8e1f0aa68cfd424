"""The words of a table's ``stability_method`` column: one short label per
way a row's stability was found (or why it was not), the same in every
command, and the sentence each stands for (docs/contract.md, "Stability").

A label is what a script compares; the sentence is what a person reads
(``deathsphere stability`` prints it as the note of a row it could not
analyse).  The kind of stability an analysed row has (``neutral``,
``damped``, ``growing``) is ``stability_kind``'s, not the method's.
"""

from __future__ import annotations

__all__ = [
    "EXACT", "EXACT_STEER_LOCKED", "FLOQUET", "NOT_ANALYSED_K0", "NOT_ANALYSED_PARTICLE",
    "NOT_ANALYSED_POINT_MASS", "NOT_ANALYSED_OFF_GLOBE", "NOT_ANALYSED_PROFILE", "NOT_ANALYSED_LOOP_OFF_GLOBE", "METHOD_TEXT", "method_text",
]

#: The exact linearisation of the steady orbit (docs/stability.md).
EXACT = "exact-linearisation"
#: The single-contact machine's exact linearisation, its steering locked (docs/machine.md sec. 5).
EXACT_STEER_LOCKED = "exact-linearisation-steer-locked"
#: A vertical orbit's Floquet multipliers, on the globe or inside a closed
#: profile (docs/stability.md sec. 2, 2.1).
FLOQUET = "floquet"
#: k = 0 (all the mass at the contact): the equations of motion are singular.
NOT_ANALYSED_K0 = "not-analysed-k0"
#: The frictionless particle slides: it has no rolling equations to linearise.
NOT_ANALYSED_PARTICLE = "not-analysed-particle"
#: A machine with no yaw inertia and no spinning wheels (the point-mass limit).
NOT_ANALYSED_POINT_MASS = "not-analysed-point-mass"
#: The single-contact machine on a surface other than the globe (no longer
#: written by ``ride``, whose drum, cone and flat ground are analysed; kept
#: so that a table written before reads back with its sentence).
NOT_ANALYSED_OFF_GLOBE = "not-analysed-off-globe"
#: The single-contact machine on a profile (no longer written by ``ride``,
#: whose profiles are analysed on their parallel surface, docs/machine.md,
#: "On a profile"; kept so that a table written before reads back with its
#: sentence).
NOT_ANALYSED_PROFILE = "not-analysed-profile"
#: The machine's vertical loop inside a closed profile: the loop is solved
#: (docs/machine.md eqs. M25-M30), not its stability (the wheel's loop
#: there is ``floquet``'s since its Floquet analysis on any closed profile,
#: docs/stability.md sec. 2.1; a table written before said this of it).
NOT_ANALYSED_LOOP_OFF_GLOBE = "not-analysed-loop"

#: What each label means, in a sentence.
METHOD_TEXT = {
    EXACT: "exact linearisation of the steady orbit (docs/stability.md)",
    EXACT_STEER_LOCKED: ("exact linearisation of the machine with its steering locked (docs/machine.md sec. 5): "
                         "an unsteered machine is unstable on most orbits; a rider steers"),
    FLOQUET: ("Floquet multipliers of the vertical orbit over one period, on the globe or inside a closed profile "
              "(docs/stability.md)"),
    NOT_ANALYSED_K0: "not analysed (k = 0: the equations of motion are singular)",
    NOT_ANALYSED_PARTICLE: "not analysed (sliding particle)",
    NOT_ANALYSED_POINT_MASS: ("not analysed: no yaw inertia and no spinning wheels: a turn about the up-axis moves "
                              "no mass and the equations of motion leave the yaw undetermined (the point-mass limit; "
                              "docs/machine.md sec. 5)"),
    NOT_ANALYSED_OFF_GLOBE: ("not analysed: the machine's stability is derived on the globe only "
                             "(docs/machine.md sec. 5)"),
    NOT_ANALYSED_PROFILE: ("not analysed: written before the machine's equations of motion took a profile's "
                           "parallel surface (docs/machine.md, \"On a profile\"); the same ride now fills the "
                           "stability columns"),
    NOT_ANALYSED_LOOP_OFF_GLOBE: ("not analysed: the machine's vertical loop inside a closed profile is solved "
                                  "(docs/machine.md eqs. M25-M30), not its stability; a wheel's loop there is "
                                  "analysed (floquet, docs/stability.md sec. 2.1) since it was written"),
}


def method_text(label: str) -> str:
    """The sentence a ``stability_method`` label stands for (the label itself if it has none); beyond the
    paper: the words of docs/contract.md, "Stability"."""
    return METHOD_TEXT.get(label, label)
