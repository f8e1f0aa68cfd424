"""``deathsphere vertical``: vertical orbits of a wheel (:func:`deathsphere.api.vertical_sweep`,
:func:`deathsphere.api.vertical_input`)."""

from __future__ import annotations

import click

from deathsphere import api
from deathsphere.cli.base import choose_format, cli, finish, given, stream
from deathsphere.cli.options import (
    display_units,
    input_option,
    only_option,
    output_options,
    param_option,
    params_options,
    setup_options,
    stability_option,
    surface_options,
    units_option,
)


@cli.command("vertical", short_help="Vertical orbit of a wheel: contact, forces, friction, worst point, lap time.")
@param_option("theta", multiple=True, help="Cone angle of the orbit about the horizontal axis, 0..180 (90 = a "
              "vertical great circle).")
@params_options("v_top", "phidot_top", multiple=("v_top", "phidot_top"))
@setup_options()
@surface_options(lanes=False)
@param_option("points")
@input_option("theta, v_top or phidot_top, phi (where that speed is: deg from the top, 0), side, a, r, k, g, mu")
@only_option(api.STATUSES)
@stability_option(help="Exact stability by Floquet analysis over one lap, on the globe or inside a closed profile "
                       "(docs/stability.md).")
@output_options()
@units_option()
def vertical_command(theta, v_top, phidot_top, side, a, r, diameter, k, g, mu, surface, wall_angle, wall_height,
                     profile, points, input, only, stability, fmt, units):
    """Vertical orbit of a wheel: contact all round (eq. 28a), forces and friction (eqs. 27-28b).

    Reports the least top speed for contact, the normal force and friction
    needed round the orbit, the worst point (where mu peaks) and the lap time
    (an elliptic integral).  Outside the sphere no vertical orbit closes: the
    row gives where the wheel leaves the surface (from rest: eq. 82).
    Rates and speeds are at the top; forces and mu_required at the worst point.

    \b
    Examples:
      deathsphere vertical --theta 90 --v-top 6
      deathsphere vertical --theta 60 --v-top 4:8:1 --mu 1.5
      deathsphere vertical --theta 90 --v-top 6 --points 13 --format csv
      deathsphere vertical --side outside --theta 90 --v-top 0

    A vertical loop needs a surface that closes over the top: the globe, or
    a profile closed at both ends (--surface profile --profile FILE.csv, its
    meridian on the axis at its lowest and highest point), where the loop
    runs in a meridian plane (--theta 90, inside; docs/surfaces.md eqs.
    S9-S12).  --surface cylinder, cone or
    plane is refused (none closes over the rider), and so is a profile open
    at the top or standing on a floor.
    """
    options = given(theta=theta, v_top=v_top, phidot_top=phidot_top, side=side, a=a, r=r, diameter=diameter, k=k,
                    g=g, mu=mu, points=points, surface=surface, wall_angle=wall_angle, wall_height=wall_height,
                    profile=profile)
    if input is not None:
        chunks = api.vertical_input(input, stability=stability, only=only or None, **options)
    else:
        chunks = api.vertical_sweep(stability=stability, only=only or None, **options)
    fmt = choose_format(fmt)
    title, view = "Vertical orbit point by point (eqs. 27, 28, 28b; phi from the top)", None
    shown = display_units(units, click.get_current_context().params)
    if points is None and fmt == "table":
        from functools import partial

        from deathsphere.render.orbit_views import vertical_view

        title, view = None, partial(vertical_view, units=shown)
    finish(stream(chunks, fmt, label="vertical orbits", title=title, view=view, units=shown))
