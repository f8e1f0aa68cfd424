"""Requests as records: what a rider rides (its body and its lane) and the
run it rides in (the ground, gravity, the limits, the solver), declared once
and built by one decoder from keys as typed: a show plan's tables, the
command line's options or the API's keywords (docs/api.md, "Requests").

A lane is a tagged union, so which of theta and height, and which of the
tilt, the contact's or the centre's speed and the lap time, a rider gave is
a matter of structure, decided once in :mod:`.decode`."""

from deathsphere.requests.records import (
    ComSpeed,
    ContactSpeed,
    Height,
    Horizontal,
    PaperBody,
    Period,
    Rate,
    RiderRequest,
    Run,
    SameLap,
    Solver,
    Speed,
    Spin,
    Theta,
    Tilt,
    Vertical,
)

__all__ = ["ComSpeed", "ContactSpeed", "Height", "Horizontal", "PaperBody", "Period", "Rate", "RiderRequest", "Run",
           "SameLap", "Solver", "Speed", "Spin", "Theta", "Tilt", "Vertical"]
