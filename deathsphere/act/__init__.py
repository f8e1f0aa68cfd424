"""The show: several riders sharing one globe (docs/show.md).

``deathsphere.show(plan, ...)`` plans an act (:func:`deathsphere.api.shows.show`);
this package holds its parts: the plan
(:mod:`.plan`), the lanes (:mod:`.lanes`), the envelopes (:mod:`.envelope`),
the pairs' least clearance (:mod:`.pairs`) and the timing and drift
(:mod:`.timing`)."""
