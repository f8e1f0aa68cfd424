"""The show: several riders sharing one globe (docs/show.md).

``deathsphere.show(plan, ...)`` plans an act (:func:`deathsphere.api.show.show`):
this package is callable as that function, and holds its parts: the plan
(:mod:`.plan`), the lanes (:mod:`.lanes`), the envelopes (:mod:`.envelope`),
the pairs' least clearance (:mod:`.pairs`) and the timing and drift
(:mod:`.timing`)."""

import sys
import types


class _CallableShow(types.ModuleType):
    """The package, callable as :func:`deathsphere.api.show.show` so that
    ``deathsphere.show(plan)`` plans an act as the other commands' functions do."""

    def __call__(self, plan, **options):
        from deathsphere.api.show import show

        return show(plan, **options)


sys.modules[__name__].__class__ = _CallableShow
