"""The Whipple bicycle: two knife-edge wheels, a rear frame and a steered
front frame (Meijaard, Papadopoulos, Ruina & Schwab 2007), on flat ground
and, in its derivation, inside a sphere (beyond the paper;
docs/two-wheeler.md).

==================  ==============================================
module              concept
==================  ==============================================
``parameters``      the benchmark's 26 parameters (Table 1)
``derivation``      Kane's method in sympy; the generator of
                    ``_generated.py`` (needs sympy; not imported at
                    run time)
``_generated``      the numeric equations, printed by the generator
``motion``          the constraints imposed: pitch, dependent speeds,
                    accelerations, energy
``linear``          the benchmark's M, C1, K0, K2, eigenvalues, weave
                    and capsize speeds from the nonlinear equations
==================  ==============================================
"""
