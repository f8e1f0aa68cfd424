"""Requests as records: what a rider rides (its body and its lane) and the
run it rides in (the ground, gravity, the limits, the solver), declared once
and built by one decoder from keys as typed: a show plan's tables, the
command line's options or the API's keywords (docs/api.md, "Requests").

A lane is a tagged union, so which of theta and height, and which of alpha
and speed, a rider gave is a matter of structure, decided once in
:mod:`.decode`."""

from deathsphere.requests.records import (
    Height,
    Horizontal,
    PaperBody,
    Rate,
    RiderRequest,
    Run,
    Solver,
    Speed,
    Spin,
    Theta,
    Tilt,
    Vertical,
)

__all__ = ["Height", "Horizontal", "PaperBody", "Rate", "RiderRequest", "Run", "Solver", "Speed", "Spin", "Theta", "Tilt", "Vertical"]
