"""How a request's keys were typed, so that a refusal names what was typed:
a show plan's key under its table (``rider 'Ana': speed: ...``), or, with
no table, the registry's name, which the command line shows as its option
(``--speed``) and the API as its keyword."""

from __future__ import annotations

from dataclasses import dataclass

from deathsphere.errors import ParameterError


@dataclass(frozen=True)
class Keys:
    """``where``: the table the keys were typed in (``"globe"``, ``"rider
    'Ana'"``, ``"machine file bike.toml"``), None for options and keywords;
    ``param``: the option a refusal is reported under when the keys were
    typed in a file that option names (``machine_file``; None: the key)."""

    where: str | None = None
    param: str | None = None

    def fail(self, key: str | None, what: str, missing: bool = False):
        """Refuse in one line naming ``key`` (raises ParameterError)."""
        if self.where is None:
            raise ParameterError(what, self.param or key, missing=missing)
        raise ParameterError(f"{self.where}: {key}: {what}" if key else f"{self.where}: {what}", self.param or key)

    def refuse(self, key: str, predicate: str):
        """Refuse ``key`` with what is wrong with it (``"is not a key of a
        vertical lane"``): under a table after the key, else after its name."""
        self.fail(key, predicate if self.where is not None else f"{key} {predicate}")
