"""The show's views in the units the plan typed and to the digits of each
quantity: a rider who swings on the wall says how high in m and, where the
plan typed the heights in ft, in ft beside it (the falls view's title); a
rider's θ to a tenth of a degree, as the pairs' (docs/units.md)."""

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


def test_the_riders_theta_to_a_tenth_of_a_degree_as_the_pairs():
    import io

    from rich.console import Console

    from deathsphere import show
    from deathsphere.render.show_views import riders_view

    result = show({"globe": {"diameter": 4.88, "duration": 10}, "rider": [
        {"name": "Ana", "lane": "horizontal", "theta": 115.2, "speed": 8.0},
        {"name": "Dee", "lane": "horizontal", "theta": 82.8, "period": 1.3}]})
    console = Console(width=200, record=True, file=io.StringIO())
    console.print(riders_view(result.riders, result=result))
    rows = {line.split()[0]: line for line in console.export_text().splitlines() if line.split()[:1] in (["Ana"], ["Dee"])}
    assert " 115.2 " in rows["Ana"] and " 82.8 " in rows["Dee"], rows
