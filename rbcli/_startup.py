"""A cheaper equivalent, for modules on every command's start-up path, of ``re.compile``:
:class:`LazyRe`, a pattern compiled on its first use (the start-up goals of bench/README.md,
"Start-up": ``re.compile`` costs 0.1-0.4 ms a pattern, paid by every run although most use
few of them). Standard library only."""

from __future__ import annotations

from typing import Any

__all__ = ["LazyRe"]


class LazyRe:
    """A regular expression compiled on its first use: ``NAME = LazyRe(r"...")`` at module
    level instead of ``re.compile``. ``match``, ``fullmatch``, ``search``, ``sub`` and any
    other attribute are the compiled pattern's own; after the first use they are plain
    instance attributes, as fast as the compiled pattern's."""

    def __init__(self, pattern: str, flags: int = 0) -> None:
        self._args = (pattern, flags)

    def __getattr__(self, name: str) -> Any:  # only until the pattern is compiled
        if name.startswith("__"):
            raise AttributeError(name)
        import re

        compiled = re.compile(*self._args)
        for method in ("match", "fullmatch", "search", "sub", "finditer", "findall", "split",
                       "pattern", "flags"):
            setattr(self, method, getattr(compiled, method))
        return getattr(compiled, name)

    def __repr__(self) -> str:
        return f"LazyRe({self._args[0]!r})"
