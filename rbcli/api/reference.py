"""What the services share: the snapping of round-off to zero, and the shaft's line with its
defaults (:func:`shaft_axis`, :func:`shaft_point`: ``balance``, ``whirl``, ``rollcheck``,
``gyrocompass``). The point an inertia is taken about is :class:`rbcli.api.inertia.Reference`.

numpy loads on first use, not when this module is imported.
"""

from __future__ import annotations

from typing import Any

__all__ = ["snap", "shaft_axis", "shaft_point"]


def snap(values: Any, scale: float | None = None, rtol: float = 1e-14) -> Any:
    """``values`` as a float ndarray with entries below ``rtol`` times the largest magnitude
    (or ``scale``) set to exactly 0 (round-off, e.g. a product of inertia of 1e-18 next to
    moments of 1): what JSON and tables show."""
    import numpy as np

    a = np.asarray(values, dtype=float)
    flat = a.ravel().tolist()
    if flat and (scale is not None or all(map(float.__eq__, flat, flat))):  # no NaN: numpy's max is NaN
        # the same comparisons on the same floats, in Python: faster for a 3x3 (a batch)
        limit = rtol * (max(map(abs, flat)) if scale is None else scale)
        out = np.array([0.0 if abs(x) <= limit or x == 0.0 else x for x in flat])
        out.shape = a.shape
        return out
    a = a.copy()  # the caller's values stay as they are
    mag = np.abs(a)
    s = float(mag.max()) if scale is None else scale
    a[mag <= rtol * s] = 0.0
    a[a == 0.0] = 0.0  # no negative zeros
    return a


def shaft_axis(body: Any, given: Any) -> tuple[tuple[float, float, float], str]:
    """The shaft's direction: the one ``given``, else the body's ``shaft``, else body z; with
    where it came from, ``"given"``, ``"body"`` or ``"default"`` (each command words it)."""
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
