"""Small checks every physics module shares: a finite number, and a float safe for JSON."""

from __future__ import annotations

import math


def finite(name: str, x: float) -> float:
    """``x`` as a float if it is a finite number.

    Raises
    ------
    ValueError
        naming ``name``, for a value that is not a number or not finite.
    """
    try:
        v = float(x)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number, not {x!r}") from None
    if not math.isfinite(v):
        raise ValueError(f"{name} must be a finite number, not {v}")
    return v


def json_float(x: float | None) -> float | None:
    """A JSON-safe float: None for None or a non-finite value."""
    if x is None:
        return None
    v = float(x)
    return v if math.isfinite(v) else None
