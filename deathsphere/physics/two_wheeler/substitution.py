"""``xreplace`` for the derivation's large expressions, each distinct
subtree rebuilt once (beyond the paper; docs/two-wheeler.md sec. 5).

sympy's ``xreplace`` walks an expression as a tree: a subtree shared by
many terms -- the bicycle's expressions share most of theirs, the sines and
cosines of the angles and the products of them -- is walked and rebuilt
once per occurrence.  This walks it once, in the same order, with the same
rule (a node found in the rule is replaced, else rebuilt from its replaced
arguments when one of them changed, else kept), so the result is the same
expression sympy's gives.  Like the derivation, this needs sympy.
"""

from __future__ import annotations

import sympy as sm

__all__ = ["xreplace"]


def xreplace(x, rule: dict):
    """``x.xreplace(rule)`` for a sympy expression or matrix, the walk
    shared by every element (a tool of the derivation, docs/two-wheeler.md
    sec. 5: no physics of its own)."""
    memo = {}

    def walk(e):
        try:
            return memo[id(e)][1:]
        except KeyError:
            pass
        if e in rule:
            out = rule[e], True
        else:
            args, changed = [], False
            for a in e.args:
                if isinstance(a, sm.Basic):
                    a, c = walk(a)
                    changed |= c
                args.append(a)
            out = (e.func(*args), True) if changed else (e, False)
        memo[id(e)] = (e, *out)      # e kept alive, so its id is its own
        return out

    if not rule:
        return x
    if isinstance(x, sm.MatrixBase):
        return x.applyfunc(lambda e: walk(e)[0])
    return walk(x)[0]
