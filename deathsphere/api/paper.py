"""The paper itself: ``table1`` and ``verify``."""

from __future__ import annotations

from deathsphere.api.arguments import checked_scalar, is_given
from deathsphere.params import ParameterError
from deathsphere.table import Table


def table1() -> Table:
    """The paper's Table 1 beside the values recomputed from eqs. (29), (35), (36):
    ``deathsphere table1``.

    Wheel a = 0.3 m, k = 1/2 in a sphere r = 3.0 m, standard gravity; the
    ``note`` column names every disagreement (docs/errata.md).

    Returns
    -------
    Table
        Ten rows, one per printed orbit: the printed mu, v_cm and "No. of
        g's", the computed values, whether each printed value is reproduced,
        and a note.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.table1()
    >>> len(t), t[3]["v_cm_printed_m_s"], round(t[3]["v_cm_computed_m_s"], 2), t[3]["v_cm_agrees"]
    (10, 7.9, 7.88, True)
    """
    from deathsphere.results.table1 import table1_comparison as compute

    return compute()


def verify(claims=None, *, jobs: int = 1, progress=None) -> Table:
    """Check the paper's quantitative claims: ``deathsphere verify``.

    Parameters
    ----------
    claims : str or list of str, optional
        Claim ids (as ``--claim``); all by default.
    jobs : int
        Processes checking claims (the same table as with one).
    progress : callable, optional
        ``progress(claim)`` as each claim is taken up (one process) or done.

    Returns
    -------
    Table
        One row per claim: ``id``, ``section``, ``equation``, ``claim``,
        ``verdict`` (confirmed, corrected or refuted, docs/errata.md) and
        the ``evidence``.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.verify("T1-v")
    >>> t[0]["verdict"]
    'confirmed'
    """
    from deathsphere.results.verify import CLAIMS, run

    ids = None if not is_given(claims) else ([claims] if isinstance(claims, str) else list(claims))
    known = {c.id for c in CLAIMS}
    for c in ids or ():
        if c not in known:
            raise ParameterError(f"unknown claim {c!r}; known: {' '.join(sorted(known))}", "claims")
    return run(ids, progress=progress, jobs=int(checked_scalar("jobs", jobs)))


def n_claims(claims=None) -> int:
    """How many claims :func:`verify` checks for ``claims`` (a progress bar's total)."""
    from deathsphere.results.verify import CLAIMS

    return len(CLAIMS) if not is_given(claims) else (1 if isinstance(claims, str) else len(claims))


def verify_counts(table: Table) -> dict[str, int]:
    """How many claims of a :func:`verify` table are confirmed, corrected
    and refuted (in that order)."""
    from deathsphere.results.verify import counts

    return counts(table)


def table1_printed() -> tuple[tuple[str, ...], ...]:
    """Table 1 as printed, row by row, as text (theta, alpha, mu, v_cm, "No.
    of g's"): the digits a printed value carries decide how it is compared
    and shown."""
    from deathsphere.results.table1 import PRINTED

    return PRINTED
