"""The shaft's line with its defaults, decided once for ``balance``, ``whirl``, ``rollcheck``
and ``gyrocompass``: its direction and a point of it, given, else the body's ``shaft``, else
body z through the origin (each command words where they came from)."""

from __future__ import annotations

from typing import Any

__all__ = ["shaft_axis", "shaft_point"]


def shaft_axis(body: Any, given: Any) -> tuple[tuple[float, float, float], str]:
    """The shaft's direction: the one ``given``, else the body's ``shaft``, else body z; with
    where it came from, ``"given"``, ``"body"`` or ``"default"``."""
    if given is not None:
        return tuple(float(x) for x in given), "given"  # type: ignore[return-value]
    if body is not None and body.shaft is not None:
        return tuple(float(x) for x in body.shaft.axis), "body"  # type: ignore[return-value]
    return (0.0, 0.0, 1.0), "default"


def shaft_point(body: Any, given: Any) -> tuple[Any, str]:
    """A point of the shaft's line: the one ``given`` (``"com"``, ``"origin"`` or x, y, z),
    else the body's ``shaft.through``, else the origin; with where it came from, as
    :func:`shaft_axis` says it."""
    if isinstance(given, str):
        return given, "given"
    if given is not None:
        return tuple(float(x) for x in given), "given"
    if body is not None and body.shaft is not None:
        return tuple(float(x) for x in body.shaft.through), "body"
    return (0.0, 0.0, 0.0), "default"
