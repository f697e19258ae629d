"""How big a body is: the yardstick of the plausibility warnings (issue 13).

A number typed in the wrong unit is off by 25 to 1000, so a value far outside the body's
size is worth a warning. The size is the bounding box of the parts, each a ball about its
com of its outer radius (a round part) or its equivalent box's half-diagonal
``sqrt(1.5 tr(J) / m)``; holes are left out."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np

from rbcli.core.symmetry import across

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
        """m, the largest side of the box: 0 for a lone point mass (or points at one place)."""
        return float(np.max(self.high - self.low))

    def beyond(self, distance: float) -> bool:
        """Whether ``distance`` (m) is more than :data:`FAR` sizes; never for a body of size
        0 (a lone point mass has no size to judge a distance by)."""
        return 0.0 < FAR * self.size < distance

    def far(self, point: Sequence[float]) -> float | None:
        """The distance (m) of ``point`` from the box's centre when :meth:`beyond`, else None."""
        d = float(np.linalg.norm(np.asarray(point, dtype=float) - self.centre))
        return d if self.beyond(d) else None


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


# --- reach from an axis


def axis_reach(parts: Sequence[Any], axis: Sequence[float], through: Sequence[float]) -> float:
    """The largest distance (m) of the body's material (holes left out) from the line along
    ``axis`` through ``through`` (body frame): the fastest point moves at |omega| times it.

    The distance is convex, so it is largest at an extreme point of each part's outline:
    corners; circles (a quartic in exp(i t)); a sphere's centre plus radius; an ellipsoid's
    projected ellipse (a ``given`` part's equivalent one); a mesh outline's vertices; else the
    com plus the ball of :func:`body_scale`."""
    n = np.asarray(axis, dtype=float).reshape(3)
    n = n / np.linalg.norm(n)
    P = np.asarray(through, dtype=float).reshape(3)
    E = across(n)  # (2, 3): coordinates across the line
    solid = [p for p in parts if not p.subtract] or list(parts)
    balls = [_ball(p) for p in solid]
    ub = [float(np.linalg.norm(E @ (c - P))) + rho for c, rho in balls]
    best = max((float(np.linalg.norm(E @ (np.asarray(p.com, dtype=float) - P))) for p in solid), default=0.0)
    for i in sorted(range(len(solid)), key=lambda j: -ub[j]):
        if ub[i] < best:
            break
        best = max(best, _part_reach(solid[i], E, P, balls[i]))
    return best


def _ball(p: Any) -> tuple[np.ndarray, float]:
    """A ball holding the part: its local origin (body frame) and circumradius (m)."""
    o = getattr(p, "outline", None)
    if o is None or o.kind not in _RHO:
        c = np.asarray(p.com, dtype=float)
        m = float(p.mass)
        tr = float(np.trace(np.asarray(p.inertia_com, dtype=float)))
        r = math.sqrt(max(1.5 * tr / m, 0.0)) if m > 0 else 0.0
        return c, max(r, float(p.radius or 0.0))
    return np.asarray(o.at, dtype=float), _RHO[o.kind](dict(o.dims), o)


def _mesh_rho(d: dict, o: Any) -> float:
    V = o.vertices
    return 0.0 if V is None or len(V) == 0 else float(np.max(np.linalg.norm(V, axis=1)))


_RHO = {
    "point": lambda d, o: 0.0,
    "rod": lambda d, o: float(d["length"]) / 2,
    "ring": lambda d, o: float(d["radius"]),
    "disk": lambda d, o: float(d["radius"]),
    "plate": lambda d, o: 0.5 * math.sqrt(sum(float(x) ** 2 for x in d["size"]) + float(d.get("thickness") or 0.0) ** 2),
    "triangle": lambda d, o: float(np.max(np.linalg.norm(np.asarray(d["vertices"], dtype=float), axis=1))),
    "box": lambda d, o: 0.5 * math.sqrt(sum(float(x) ** 2 for x in d["size"])),
    "cylinder": lambda d, o: math.hypot(float(d["radius"]), float(d["length"]) / 2),
    "sphere": lambda d, o: float(d["radius"]),
    "hemisphere": lambda d, o: float(d["radius"]),
    "cone": lambda d, o: max(float(d["radius"]), float(d["height"])),
    "ellipsoid": lambda d, o: max(float(x) for x in d["semi_axes"]),
    "given": lambda d, o: max(float(x) for x in d["semi_axes"]),
    "torus": lambda d, o: float(d["major_radius"]) + float(d["minor_radius"]),
    "mesh": _mesh_rho,
}


def _corners(E: np.ndarray, P: np.ndarray, pts: np.ndarray) -> float:
    return float(np.max(np.linalg.norm((pts - P) @ E.T, axis=1)))


def _part_reach(p: Any, E: np.ndarray, P: np.ndarray, ball: tuple[np.ndarray, float]) -> float:
    """The largest distance of part ``p`` from the line (see :func:`axis_reach`)."""
    o = getattr(p, "outline", None)
    if o is None or o.kind not in _RHO or (o.kind == "mesh" and (o.vertices is None or len(o.vertices) == 0)):
        c, rho = ball
        return float(np.linalg.norm(E @ (c - P))) + rho
    d = dict(o.dims)
    at = np.asarray(o.at, dtype=float)
    R = np.asarray(o.R, dtype=float)
    kind = o.kind

    def body(local: Any) -> np.ndarray:
        return at + np.asarray(local, dtype=float).reshape(-1, 3) @ R.T

    def circle(centre: np.ndarray, r: float) -> float:
        return _ellipse_reach(E @ (centre - P), r * (E @ R[:, :2]))

    if kind == "point":
        return _corners(E, P, body([0.0, 0.0, 0.0]))
    if kind == "rod":
        h = float(d["length"]) / 2
        return _corners(E, P, body([[0, 0, -h], [0, 0, h]]))
    if kind in ("box", "plate"):
        a, b, c = ((*d["size"], d.get("thickness") or 0.0) if kind == "plate" else d["size"])
        s = np.array([float(a), float(b), float(c)]) / 2
        signs = np.array([[i, j, k] for i in (-1, 1) for j in (-1, 1) for k in (-1, 1)], dtype=float)
        return _corners(E, P, body(signs * s))
    if kind == "triangle":
        return _corners(E, P, body(d["vertices"]))
    if kind in ("ring", "disk"):
        return circle(at, float(d["radius"]))
    if kind == "cylinder":
        h = float(d["length"]) / 2
        r = float(d["radius"])
        return max(circle(at - h * R[:, 2], r), circle(at + h * R[:, 2], r))
    if kind == "cone":
        return max(circle(at, float(d["radius"])), _corners(E, P, body([0.0, 0.0, float(d["height"])])))
    if kind == "torus":
        return circle(at, float(d["major_radius"])) + float(d["minor_radius"])
    if kind == "sphere":
        return float(np.linalg.norm(E @ (at - P))) + float(d["radius"])
    if kind == "hemisphere":  # dome towards local +z, flat face at local z = 0
        r = float(d["radius"])
        y = E @ (at - P)
        dist = float(np.linalg.norm(y))
        away = E.T @ (y / dist) if dist > 0 else None
        dome = dist + r if away is None or float(away @ R[:, 2]) >= 0.0 else 0.0
        return max(dome, circle(at, r))
    if kind in ("ellipsoid", "given"):
        M = E @ (R * np.asarray([float(x) for x in d["semi_axes"]]))  # (2, 3)
        U, S, _ = np.linalg.svd(M)
        return _ellipse_reach(E @ (at - P), U * S[:2])
    # mesh
    return _corners(E, P, body(o.vertices))


def _ellipse_reach(p: np.ndarray, L: np.ndarray) -> float:
    """max over t of |p + L (cos t, sin t)|, p (2,), L (2, 2) (a circle or an ellipsoid seen
    along the line).

    |y(t)|² = A + B cos t + C sin t + D cos 2t + F sin 2t with a = Lᵀ p, G = Lᵀ L:
    A = |p|² + (G11 + G22)/2, B = 2 a1, C = 2 a2, D = (G11 - G22)/2, F = G12. Its
    derivative times z² (z = exp(i t)) is the quartic
    (F + iD) z⁴ + (C + iB)/2 z³ + (C - iB)/2 z + (F - iD); every stationary angle is the
    argument of a root (numpy.roots, polished by Newton steps on the derivative), and the
    largest value among them and the quarter turns is the maximum.
    """
    a = L.T @ p
    G = L.T @ L
    A = float(p @ p) + 0.5 * (G[0, 0] + G[1, 1])
    B, C = 2.0 * a[0], 2.0 * a[1]
    D, F = 0.5 * (G[0, 0] - G[1, 1]), G[0, 1]

    def f(t: np.ndarray) -> np.ndarray:
        return A + B * np.cos(t) + C * np.sin(t) + D * np.cos(2 * t) + F * np.sin(2 * t)

    def df(t: np.ndarray) -> np.ndarray:
        return -B * np.sin(t) + C * np.cos(t) - 2 * D * np.sin(2 * t) + 2 * F * np.cos(2 * t)

    def d2f(t: np.ndarray) -> np.ndarray:
        return -B * np.cos(t) - C * np.sin(t) - 4 * D * np.cos(2 * t) - 4 * F * np.sin(2 * t)

    coeffs = np.array([F + 1j * D, 0.5 * (C + 1j * B), 0.0, 0.5 * (C - 1j * B), F - 1j * D])
    t = np.linspace(0.0, 2.0 * np.pi, 8, endpoint=False)
    big = float(np.max(np.abs(coeffs)))
    if big > 1e-13 * abs(A):  # else |y(t)|² is constant to round-off
        # leading coefficients that are round-off of the others (a circle seen face-on has
        # D = F = 0 up to it) would put roots at ~1e300: drop them (the degree drops)
        c = coeffs / big
        while len(c) > 1 and abs(c[0]) <= 1e-13:
            c = c[1:]
        if len(c) > 1:
            roots = np.roots(c)
            t = np.concatenate([t, np.angle(roots[np.isfinite(roots)])])
    for _ in range(3):  # Newton on the derivative, only where it climbs (f'' < 0)
        h = d2f(t)
        step = np.where(h < 0, df(t) / np.where(h < 0, h, 1.0), 0.0)
        t = t - step
    return math.sqrt(max(float(np.max(f(t))), 0.0))
