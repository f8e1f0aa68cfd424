"""The bodies' records: one validated record per body (a single-contact
machine, a two-wheeler), their named parameter sets (presets) and the files
they are read from.  A record holds the body only: no gravity and no ground,
which belong to the run.  Records sit below the API and the show, which
both take them; the physics reads their fields and never imports them."""
