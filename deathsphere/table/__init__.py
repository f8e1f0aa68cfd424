"""Result tables: the :class:`Table` type and the text of its cells."""

from deathsphere.table.table import Table

__all__ = ["Table"]
