"""How big a body is: the yardstick of the plausibility warnings (issue 13).

A number typed in the wrong unit (``--radius 180`` meant in mm, read in m) is usually
off by a factor of 25 to 1000, so a value far outside the body's own size is worth a
warning. The size used is the body's bounding box built from its parts: each part
counts as a ball around its centre of mass whose radius is the part's outer radius (a
round part) or the half-diagonal of its equivalent uniform box, ``sqrt(1.5 tr(J) / m)``
(a box of sides a, b, c has ``tr(J) = m (a² + b² + c²) / 6``; its half-diagonal is
``sqrt(a² + b² + c²) / 2``). Holes are left out (they lie inside the material).

Only numpy.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np

#: how many body sizes away a point or a radius may be before rbcli warns
FAR = 10.0
#: m/s, the speed of sound in air at 20 °C: a rim faster than this is worth a warning
SPEED_OF_SOUND = 343.0


@dataclass(frozen=True)
class BodyScale:
    """The axis-aligned box (body frame, m) that holds every part's ball.

    Attributes
    ----------
    low, high : (3,) ndarray — m, the corners of the box
    """

    low: np.ndarray
    high: np.ndarray

    @property
    def centre(self) -> np.ndarray:
        """m, the middle of the box."""
        return 0.5 * (self.low + self.high)

    @property
    def size(self) -> float:
        """m, the largest side of the box (never 0: a single point mass has size 0, so the
        smallest size used is 1e-300 m, and nothing is then 'far' only by comparison)."""
        return max(float(np.max(self.high - self.low)), 1e-300)

    @property
    def half_diagonal(self) -> float:
        """m, half the diagonal of the box: no point of the body is farther from its centre."""
        return 0.5 * float(np.linalg.norm(self.high - self.low))

    def far(self, point: Sequence[float]) -> float | None:
        """The distance (m) of ``point`` from the box's centre when it is more than
        :data:`FAR` sizes, else None."""
        d = float(np.linalg.norm(np.asarray(point, dtype=float) - self.centre))
        return d if d > FAR * self.size else None


def body_scale(parts: Sequence[Any]) -> BodyScale:
    """The :class:`BodyScale` of a body's parts (holes left out): each part a ball around
    its com of radius ``max(sqrt(1.5 tr(J) / m), outer radius)`` (see the module)."""
    solid = [p for p in parts if not p.subtract] or list(parts)
    n = len(solid)
    coms = np.array([p.com for p in solid], dtype=float).reshape(-1, 3)
    J = np.array([p.inertia_com for p in solid], dtype=float).reshape(n, 3, 3)
    mass = np.array([p.mass for p in solid], dtype=float)
    radius = np.array([float(p.radius or 0.0) for p in solid]).reshape(n)
    trace = J[:, 0, 0] + J[:, 1, 1] + J[:, 2, 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.sqrt(np.maximum(1.5 * trace / np.where(mass > 0, mass, 1.0), 0.0))
    reach = np.maximum(np.where(mass > 0, r, 0.0), radius)[:, None]
    return BodyScale((coms - reach).min(axis=0), (coms + reach).max(axis=0))
