"""The two-wheeler's numeric code, written from its symbolic derivation:
the equations of ``deathsphere.physics.two_wheeler.derivation``, common
subexpressions eliminated (sympy.cse) and written out as numpy source for
``deathsphere/physics/two_wheeler/_generated.py`` (beyond the paper;
docs/two-wheeler.md sec. 5): only the functions, which import their
runtime (the batch's shape, the evaluation in blocks) from
``physics/two_wheeler/_blocks.py``.  Not physics: the physics core derives, this
turns the result into text (``tools/generate_two_wheeler.py`` writes it),
so it needs sympy as the derivation does.
"""

from __future__ import annotations

from pathlib import Path

import sympy as sm

from deathsphere.physics.two_wheeler import derivation as _derivation
from deathsphere.physics.two_wheeler.derivation import SURFACES, Derivation, derive
from deathsphere.physics.two_wheeler.substitution import xreplace

__all__ = ["GENERATED", "generated_functions", "generated_source"]

#: The shipped file the code is written to.
GENERATED = Path(_derivation.__file__).with_name("_generated.py")

_HEADER = '''"""Numeric equations of motion of the Whipple bicycle: GENERATED, do not edit.

Printed by ``python tools/generate_two_wheeler.py --write``
from the Kane's-method derivation in ``derivation.py`` (sympy {version}):
common subexpressions eliminated (sympy.cse), then printed as numpy code.
Beyond the paper; docs/two-wheeler.md sec. 3-5 documents the coordinates,
the constraints and every sign.

Every function takes q (8, ...) and, where it needs them, u (8, ...) -- the
generalised coordinates and speeds, a trailing batch axis broadcast -- the
parameters p in PARAMETER_NAMES order (then the sphere's radius r, or a
revolution's meridian at the rear contact and the front rim angle), each a
float or an array broadcasting against the batch.  Only functions analytic in their
arguments are used (sin, cos, sqrt, powers), so complex-step derivatives
pass through.
"""

import numpy

from deathsphere.physics.two_wheeler._blocks import BLOCK_BYTES, batch as _batch, in_blocks as _in_blocks  # noqa: F401

SURFACES = {surfaces!r}
'''


def _printer():
    from sympy.printing.numpy import NumPyPrinter

    return NumPyPrinter({"fully_qualified_modules": True, "inline": True})


def _plain(derivation: Derivation):
    """Replace q(t), u(t) by plain symbols q0.., u0.. for printing."""
    n = len(derivation.q)
    qs = sm.symbols(f"q0:{n}")
    us = sm.symbols(f"u0:{n}")
    return dict(zip(derivation.q, qs)) | dict(zip(derivation.u, us)), qs, us


def _function(name, doc, args, unpack, outputs, printer):
    """Source of one function: CSE over every output, then the outputs
    assembled into arrays of shape (rows, cols, *batch) or (rows, *batch).

    ``outputs`` is a list of (shape, sympy Matrix, symmetric)."""
    flat = []
    for shape, matrix, symmetric in outputs:
        for i in range(shape[0]):
            for j in range(shape[1] if len(shape) == 2 else 1):
                if symmetric and j < i:
                    continue
                flat.append(matrix[i, j] if len(shape) == 2 else matrix[i])
    replacements, reduced = sm.cse(flat, symbols=sm.numbered_symbols("x"), order="none")
    lines = [f"@_in_blocks({args.index('p')})", f"def {name}({', '.join(args)}):", f'    """{doc}"""']
    lines += [f"    {line}" for line in unpack]
    lines += [f"    {sym} = {printer.doprint(expr)}" for sym, expr in replacements]
    it = iter(reduced)
    names = []
    for k, (shape, matrix, symmetric) in enumerate(outputs):
        out = f"out{k}"
        names.append(out)
        lines.append(f"    {out} = numpy.zeros({tuple(shape)} + shape, dtype=dtype)")
        for i in range(shape[0]):
            for j in range(shape[1] if len(shape) == 2 else 1):
                if symmetric and j < i:
                    continue
                expr = next(it)
                if expr == 0:
                    continue
                index = f"{i}, {j}" if len(shape) == 2 else f"{i}"
                lines.append(f"    {out}[{index}] = {printer.doprint(expr)}")
                if symmetric and j > i:
                    lines.append(f"    {out}[{j}, {i}] = {out}[{i}, {j}]")
    lines.append(f"    return {', '.join(names)}")
    return "\n".join(lines) + "\n"


def generated_functions(derivation: Derivation) -> str:
    """The numeric functions of one surface, as Python source (beyond the
    paper; docs/two-wheeler.md sec. 5)."""
    printer = _printer()
    plain, qs, us = _plain(derivation)
    params = [str(s) for s in derivation.parameters]
    unpack_q = [f"{', '.join(map(str, qs))}, = q"]
    unpack_u = [f"{', '.join(map(str, us))}, = u"]
    unpack_p = [f"{', '.join(params)}, = p"]
    s = derivation.surface

    def sub(m):
        return xreplace(sm.Matrix(m), plain)

    T = derivation.steer_torque
    equations = [((8, 8), sub(derivation.mass_matrix), True), ((8,), sub(derivation.forcing), False),
                 ((5, 8), sub(derivation.constraint_matrix), False), ((5,), sub(derivation.constraint_bias), False)]
    if derivation.holonomic is None:
        # a revolution's front contact: psi's part of the bias and what psi's rate is found from
        equations += [((5,), sub(derivation.constraint_dpsi), False),
                      ((3,), sub(derivation.front_point_velocity), False),
                      ((3,), sub(derivation.front_frame_rate), False)]
        doc = ("Kane's equations with all eight speeds free, M u' = f, and the rolling constraints B u = 0 at "
               "the rim angle psi_F: returns M (8, 8), f (8), B (5, 8), B' u at constant psi_F (5), "
               "d(B u)/d psi_F (5), the velocity of the front frame's point at the front contact (3) and the "
               "front frame's angular velocity (3), in N.")
        contact = _function(f"{s}_front_rim",
                            "The front wheel's centre, its frame's E.x and E.z, then their pitch derivatives, "
                            "in N: shape (18, ...).",
                            ["q", "p"], unpack_q + unpack_p + ["shape, dtype = _batch(q, *p)"],
                            [((18,), sub(derivation.front_rim), False)], printer)
    else:
        doc = ("Kane's equations with all eight speeds free, M u' = f, and the rolling "
               "constraints B u = 0 with B' u: returns M (8, 8), f (8), B (5, 8), B' u (5).")
        contact = _function(f"{s}_holonomic",
                            "The front contact's holonomic constraint h(q) = 0 and dh/dpitch: returns "
                            "(h, dh/dpitch), each of shape (1, ...).",
                            ["q", "p"], unpack_q + unpack_p + ["shape, dtype = _batch(q, *p)"],
                            [((1,), sub([derivation.holonomic]), False),
                             ((1,), sub([derivation.holonomic_dpitch]), False)], printer)
    parts = [
        _function(f"{s}_equations", doc, ["q", "u", "p", str(T)],
                  unpack_q + unpack_u + unpack_p + ["shape, dtype = _batch(q, u, " + str(T) + ", *p)"],
                  equations, printer),
        contact,
        _function(f"{s}_energy",
                  "Kinetic and potential energy: returns (T, V), each of shape (1, ...).",
                  ["q", "u", "p"], unpack_q + unpack_u + unpack_p + ["shape, dtype = _batch(q, u, *p)"],
                  [((1,), sub([derivation.kinetic]), False),
                   ((1,), sub([derivation.potential]), False)], printer),
        _function(f"{s}_front_contact",
                  "The front contact point in the inertial frame N (z down): shape (3, ...).",
                  ["q", "p"], unpack_q + unpack_p + ["shape, dtype = _batch(q, *p)"],
                  [((3,), sub(derivation.front_contact), False)], printer),
        # the dependent speeds need B alone, a twentieth of the equations' cost
        _function(f"{s}_constraint_matrix",
                  "The rolling constraints' matrix B (5, 8) of B u = 0 alone, as in "
                  f"{s}_equations.",
                  ["q", "p"], unpack_q + unpack_p + ["shape, dtype = _batch(q, *p)"],
                  [((5, 8), sub(derivation.constraint_matrix), False)], printer),
        # a steady turn's speed-free part (gravity, the steer torque) without the speeds' terms
        _function(f"{s}_forcing_at_rest",
                  "The forcing f (8) of Kane's equations at rest (u = 0): gravity and the steer torque.",
                  ["q", "p", str(T)], unpack_q + unpack_p + ["shape, dtype = _batch(q, " + str(T) + ", *p)"],
                  [((8,), xreplace(sub(derivation.forcing), {x: 0 for x in us}), False)], printer),
    ]
    return "\n\n".join(parts)


def generated_source(surfaces=SURFACES, derivations=None) -> str:
    """The whole text of ``_generated.py`` (beyond the paper;
    docs/two-wheeler.md sec. 5)."""
    derivations = derivations or {s: derive(s) for s in surfaces}
    text = _HEADER.format(version=sm.__version__, surfaces=tuple(surfaces))
    for s in surfaces:
        text += "\n\n" + generated_functions(derivations[s])
    return text
