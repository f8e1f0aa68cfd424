"""The paper's three bodies as records, one type each: the wheel (a thin
disc, sec. 2), the ball (a rolling sphere, sec. 4) and the sliding
particle.  What differs between them is a class attribute looked up on the
record, so that no module tests a body by its name: the words that name
them (``--body sphere``, a CSV's ``body`` column) become records in one
place, the decoder (:mod:`deathsphere.requests.decode`).

A body's ``code`` is its index in :data:`PAPER_BODIES`: a request batch
carries one int8 code per row (comparing integers, not text, per row)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from deathsphere.constants import DEFAULT_INERTIA


@dataclass(frozen=True)
class PaperBodyKind:
    """One of the paper's bodies (no fields: its size and inertia factor
    are a request's).  ``word``: what a table's ``body`` column prints;
    ``default_k``: its inertia factor when none is given; ``rolls``: it has
    rolling dynamics (the runner integrates it); ``fixed_tilt``: its tilt
    follows from theta (a ball's bank angle), not a request's alpha;
    ``held_by``: the request's keys of which exactly one fixes its steady
    horizontal orbit at a theta (none: theta alone)."""

    word: ClassVar[str]
    default_k: ClassVar[float]
    rolls: ClassVar[bool]
    fixed_tilt: ClassVar[bool] = False
    held_by: ClassVar[tuple[str, ...]] = ()

    @property
    def code(self) -> int:
        """The body's index in :data:`PAPER_BODIES` (a batch's ``body_code``)."""
        return PAPER_BODIES.index(self)

    def __str__(self) -> str:
        return self.word


@dataclass(frozen=True)
class Wheel(PaperBodyKind):
    """The paper's wheel: I11 = 2 k m a^2, I22 = I33 = k m a^2 (eq. 1), its
    mass on the rim by default (k = 1/2, Table 1); held by its tilt alpha,
    its speed or its orbital rate (eqs. 29-36)."""

    word: ClassVar[str] = "wheel"
    default_k: ClassVar[float] = DEFAULT_INERTIA[word]
    rolls: ClassVar[bool] = True
    # its tilt, or its contact's speed, its centre's speed or its rate, eq. 29 solved for the tilt
    held_by: ClassVar[tuple[str, ...]] = ("alpha", "speed", "com_speed", "omega")


@dataclass(frozen=True)
class Ball(PaperBodyKind):
    """The paper's rolling sphere (sec. 4, eq. 41: I = k m a^2, solid by
    default, k = 2/5), its bank angle fixed by theta; held by its spin
    omega3 or its orbital rate (eqs. 55-59)."""

    word: ClassVar[str] = "sphere"
    default_k: ClassVar[float] = DEFAULT_INERTIA[word]
    rolls: ClassVar[bool] = True
    fixed_tilt: ClassVar[bool] = True
    # its spin about the contact normal or its orbital rate, eq. 55
    held_by: ClassVar[tuple[str, ...]] = ("omega3", "omega")


@dataclass(frozen=True)
class Particle(PaperBodyKind):
    """A particle sliding without friction: no rotational inertia, no
    rolling dynamics; held by theta alone."""

    word: ClassVar[str] = "particle"
    default_k: ClassVar[float] = DEFAULT_INERTIA[word]
    rolls: ClassVar[bool] = False


WHEEL, BALL, PARTICLE = Wheel(), Ball(), Particle()
#: The paper's bodies in the order of their codes (the order of
#: :data:`deathsphere.constants.BODIES`, the words ``--body`` takes).
PAPER_BODIES = (WHEEL, BALL, PARTICLE)
