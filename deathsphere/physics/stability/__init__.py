"""Linear stability of steady orbits: exact, and the paper's results.

One module per question (docs/stability.md):

=================  ==========================================================
module             concept
=================  ==========================================================
``verdict``        the verdict codes and the tolerances that decide them
``reduction``      exact Jacobians reduced to the complement of the neutral
                   directions; growth rate and frequencies from them
``frequencies``    nutation frequencies from a polynomial quadratic in w^2
``horizontal``     exact linear stability of horizontal orbits of a wheel and
                   of a sphere (beyond the paper)
``margin``         a signed stability margin over (theta, alpha) and the
                   stability boundary (beyond the paper; ``map --stability``)
``floquet``        exact stability of vertical orbits by Floquet analysis
                   (beyond the paper), with the order-8 tableau ``rk8``
``paper``          the paper's results as printed and corrected: vertical
                   orbits eqs. (100)-(106), the equator eqs. (127)-(138),
                   small wheels eqs. (201)-(207), near the poles eq. (208)
``closed_forms``   closed forms of exact results: the sphere's nutation,
                   the equator's exact nutation (erratum E4)
``comparison``     every applicable paper result beside the exact one
                   (the numbers of ``deathsphere stability``)
=================  ==========================================================

The public functions are re-exported here, so ``from
deathsphere.physics.stability import wheel_stability`` works as well as the
full module path.
"""

from deathsphere.physics.stability.closed_forms import (
    equator_exact_closed_form, sphere_nutation_closed_form)
from deathsphere.physics.stability.comparison import (
    EQUATOR_TOL, SMALL_WHEEL_VALIDITY, compare_with_paper)
from deathsphere.physics.stability.floquet import (
    FLOQUET_STABLE_TOL, FLOQUET_UNSTABLE_TOL, vertical_floquet)
from deathsphere.physics.stability.horizontal import (
    CHUNK, sphere_stability, wheel_reduced_jacobian, wheel_stability)
from deathsphere.physics.stability.margin import (
    STABILITY_ALPHA_STEP_DEG, stability_boundary_alphas, stability_margin)
from deathsphere.physics.stability.paper import (
    equator_coefficients, equator_matrix, equator_paper, equator_printed_abc, near_pole_paper,
    small_wheel_corrected, small_wheel_paper, vertical_paper)
from deathsphere.physics.stability.verdict import (
    STABLE_TOL, UNSTABLE_TOL, VERDICT_LABELS, Verdict)

__all__ = [
    "Verdict", "VERDICT_LABELS", "STABLE_TOL", "UNSTABLE_TOL", "CHUNK",
    "wheel_stability", "sphere_stability", "wheel_reduced_jacobian",
    "stability_margin", "stability_boundary_alphas", "STABILITY_ALPHA_STEP_DEG",
    "FLOQUET_STABLE_TOL", "FLOQUET_UNSTABLE_TOL", "vertical_floquet",
    "vertical_paper", "equator_coefficients", "equator_matrix", "equator_printed_abc",
    "equator_paper", "small_wheel_paper", "small_wheel_corrected", "near_pole_paper",
    "sphere_nutation_closed_form", "equator_exact_closed_form",
    "SMALL_WHEEL_VALIDITY", "EQUATOR_TOL", "compare_with_paper",
]
