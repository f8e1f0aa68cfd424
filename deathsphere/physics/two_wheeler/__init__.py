"""The Whipple bicycle: two knife-edge wheels, a rear frame and a steered
front frame (Meijaard, Papadopoulos, Ruina & Schwab 2007), on flat ground,
inside a sphere and inside any surface of revolution (beyond the paper;
docs/two-wheeler.md).

==================  ==============================================
module              concept
==================  ==============================================
``parameters``      the benchmark's 26 parameters (Table 1)
``derivation``      Kane's method in sympy; the generator of
                    ``_generated.py`` (needs sympy; not imported at
                    run time)
``_generated``      the numeric equations, printed by the generator
``grounds``         what the equations need of each ground, and the
                    general path of a surface of revolution
``rim_contact``     the front rim point that touches a ground, from
                    its implicit function
``motion``          the constraints imposed: pitch, dependent speeds,
                    accelerations, energy
``linear``          the benchmark's M, C1, K0, K2, eigenvalues, weave
                    and capsize speeds from the nonlinear equations
``geometry``        the frames and points as numpy vectors (forces,
                    speeds, the rider's head, the 3-D view's rims
                    and frame lines)
``steady``          steady turns on the globe's lanes (and flat
                    circles): every turn for a speed or a steer torque
``holds``           whether a lane holds the bicycle at each of
                    many speeds (a show's fall, its speed bands)
``stability``       their eigenvalues in the turning frame, steer free
                    or locked, and a verdict
``simulate``        the nonlinear motion integrated from a turn or
                    straight running, kicked, steer by torque,
                    rider or lock; events
==================  ==============================================
"""
