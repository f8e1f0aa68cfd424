"""The package's error for bad input, defined once at the bottom of the
house so that every layer that checks input can raise it (the parameter
registry, the unit parser, the API) without importing one another."""


class ParameterError(ValueError):
    """An input value outside its allowed set; the message is one line
    saying what is wrong and what is allowed.  ``param`` names the
    parameter at fault (as in the API and the command line's ``--name``),
    or is None for a rule between several; ``missing`` says that it was
    required and not given."""

    # shown as deathsphere.ParameterError, the name users catch it by
    __module__ = "deathsphere"

    def __init__(self, message: str, param: str | None = None, missing: bool = False):
        super().__init__(message)
        self.param = param
        self.missing = missing
