"""A fall's words in the units the plan typed: a rider who swings on the
wall says how high in m and, where the plan typed the heights in ft, in ft
beside it (the falls view's title; docs/units.md)."""

import numpy as np

from deathsphere.render.display_units import AS_TYPED, DisplayUnit, DisplayUnits
from deathsphere.render.show_views import falls_view
from deathsphere.table import Table

FT = DisplayUnit("ft", 1 / 0.3048)


def _swing(height_m: float) -> Table:
    nan = np.array([np.nan])
    return Table({"rider": np.array(["Ana"], dtype=object), "t_fail_s": np.array([1.0]),
                  "speed_fraction": np.array([0.5]), "outcome": np.array(["swings"], dtype=object),
                  "swing_height_m": np.array([height_m]), "victim": np.array(["Ben"], dtype=object),
                  "min_clearance_m": nan, "t_min_s": nan, "hit": np.array([False]),
                  "crosses_lane": np.array([False])})


def test_a_swing_height_in_ft_beside_m_when_the_heights_were_typed_in_ft():
    view = falls_view(_swing(1.8288), units=DisplayUnits(typed={"height": FT}))
    # 6 ft is 1.8288 m exactly
    assert "up to 1.83 m (6.00 ft) above the floor" in view.title


def test_a_swing_height_in_m_alone_when_nothing_was_typed():
    view = falls_view(_swing(1.8288), units=AS_TYPED)
    assert "up to 1.83 m above the floor" in view.title and "ft" not in view.title
