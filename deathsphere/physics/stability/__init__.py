"""Linear stability of steady orbits: exact, and the paper's results.

One module per question (docs/stability.md):

=================  ==========================================================
module             concept
=================  ==========================================================
``methods``        the labels of ``stability_method`` and their sentences
``verdict``        the verdict codes and the tolerances that decide them
``reduction``      exact Jacobians reduced to the complement of the neutral
                   directions; growth rate and frequencies from them
``frequencies``    nutation frequencies from a polynomial quadratic in w^2
``horizontal``     exact linear stability of horizontal orbits of a wheel and
                   of a sphere (beyond the paper)
``on_ground``      exact linear stability of a wheel's and a ball's steady
                   orbits on any ground (beyond the paper)
``margin``         a signed stability margin over (theta, alpha) and the
                   stability boundary (beyond the paper; ``map --stability``)
``floquet``        exact stability of vertical orbits by Floquet analysis
                   (beyond the paper), with the order-8 tableau ``rk8``
``loop_floquet``   the same for a wheel's vertical loop inside a closed
                   profile (beyond the paper)
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
full module path.  They are loaded on first use (PEP 562): ``orbit`` needs
only ``horizontal``, and a command should not pay at start-up for the
Floquet analysis and the paper's formulas it does not evaluate.
"""

from deathsphere.physics.lazy import lazy_exports

#: Where each public name lives.
_HOME = {
    "equator_exact_closed_form": "closed_forms",
    "sphere_nutation_closed_form": "closed_forms",
    "EQUATOR_TOL": "comparison",
    "SMALL_WHEEL_VALIDITY": "comparison",
    "compare_with_paper": "comparison",
    "FLOQUET_STABLE_TOL": "floquet",
    "FLOQUET_UNSTABLE_TOL": "floquet",
    "vertical_floquet": "floquet",
    "loop_floquet_on": "loop_floquet",
    "CHUNK": "horizontal",
    "sphere_stability": "horizontal",
    "wheel_reduced_jacobian": "horizontal",
    "wheel_stability": "horizontal",
    "ball_stability_on": "on_ground",
    "wheel_stability_on": "on_ground",
    "STABILITY_ALPHA_STEP_DEG": "margin",
    "stability_boundary_alphas": "margin",
    "stability_margin": "margin",
    "equator_coefficients": "paper",
    "equator_matrix": "paper",
    "equator_paper": "paper",
    "equator_printed_abc": "paper",
    "near_pole_paper": "paper",
    "small_wheel_corrected": "paper",
    "small_wheel_paper": "paper",
    "vertical_paper": "paper",
    "STABLE_TOL": "verdict",
    "UNSTABLE_TOL": "verdict",
    "VERDICT_LABELS": "verdict",
    "Verdict": "verdict",
}

#: The submodules, reachable as attributes as if they had been imported here.
_MODULES = ("methods", "verdict", "reduction", "frequencies", "horizontal", "on_ground", "margin", "floquet", "loop_floquet", "rk8", "paper",
            "closed_forms", "comparison")

__all__ = list(_HOME)
__getattr__, __dir__ = lazy_exports(globals(), _HOME, _MODULES)
