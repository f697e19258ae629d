"""Steady circular rolling of a knife-edge wheel leaning into the turn (``rollcheck --lean/--circle``).

Physics sheet ``dynamics.md`` §3.3: the wheel rolls on a circle, its centre G at radius R_G,
leaning inwards by beta, turning at Omega. :func:`circle` (lean and radius),
:func:`lean_for` (radius and speed), :func:`radius_for` (lean and speed) give the motion and
its lean stiffness kappa (> 0: neutrally stable); :func:`stability_map` and
:func:`circle_arrays` grids for figures. Knife edge only; radians, SI."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from rbcli.core.wheel import STANDARD_GRAVITY, Wheel, blame, check_geometry, opt_float, param_finite

__all__ = ["CircleMotion", "circle", "lean_for", "radius_for", "stability_map", "circle_arrays"]


@dataclass(frozen=True)
class CircleMotion:
    """Steady circular rolling of a knife-edge wheel leaning into the turn.

    Attributes
    ----------
    lean : float — rad, beta, in [0, pi/2)
    radius, contact_radius : float — m, R_G and R_P = R_G + a sin(beta)
    turn_rate, spin : float — rad/s, Omega >= 0 and omega_3 = Omega R_G / a
    speed : float — m/s, v = Omega R_G
    kappa : float — N m, lean stiffness (sheet §3.3); stable : bool — kappa > 0
    lean_frequency, growth_rate — sqrt(±kappa / (A + m a^2)) (rad/s, 1/s), or None
    rim_radius, g : float — m, m/s^2"""

    lean: float
    radius: float
    turn_rate: float
    spin: float
    speed: float
    contact_radius: float
    kappa: float
    stable: bool
    lean_frequency: float | None
    growth_rate: float | None
    rim_radius: float
    g: float

    @property
    def lean_deg(self) -> float:
        return math.degrees(self.lean)

    def to_json(self) -> dict[str, Any]:
        """SPEC ``circle`` keys ``lean_deg``, ``radius``, ``turn_rate``, ``spin``,
        ``speed``, ``stable`` plus ``contact_radius``, ``kappa``, ``lean_frequency``,
        ``lean_frequency_hz``, ``growth_rate``."""
        f = self.lean_frequency
        return {
            "lean_deg": float(self.lean_deg),
            "radius": float(self.radius),
            "turn_rate": float(self.turn_rate),
            "spin": float(self.spin),
            "speed": float(self.speed),
            "stable": bool(self.stable),
            "contact_radius": float(self.contact_radius),
            "kappa": float(self.kappa),
            "lean_frequency": opt_float(f),
            "lean_frequency_hz": None if f is None else float(f) / (2.0 * math.pi),
            "growth_rate": opt_float(self.growth_rate),
        }


def circle_arrays(
    m: float, A: float, C: float, a: float, g: float, beta: Any, RG: Any
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Omega, omega_3 and kappa of steady circles (vectorised; beta in [0, pi/2), RG >= 0).

    beta = 0 gives Omega = 0 (the wheel standing upright at rest, whatever R_G).
    """
    beta, RG = np.broadcast_arrays(np.asarray(beta, dtype=float), np.asarray(RG, dtype=float))
    sb, cb = np.sin(beta), np.cos(beta)
    Cc = C + m * a * a
    den = A * a * sb + Cc * RG
    num = m * g * a * a * np.tan(beta)
    with np.errstate(divide="ignore", invalid="ignore"):
        W2 = np.where(beta > 0.0, num / np.where(den > 0.0, den, 1.0), 0.0)
    W = np.sqrt(W2)
    w3 = W * RG / a
    return W, w3, _kappa(m, A, C, a, g, beta, W, w3)


def _kappa(m: float, A: float, C: float, a: float, g: float, beta: Any, W: Any, w3: Any) -> Any:
    """kappa (N m) of the steady circle at lean beta, turn rate W, spin w3 (sheet §3.3)."""
    sb, cb = np.sin(beta), np.cos(beta)
    Cc = C + m * a * a
    W2 = W * W
    return (
        A * W2 * np.cos(2.0 * beta)
        - Cc * W * w3 * sb
        - m * g * a * cb
        + (2.0 * A * W * sb + Cc * w3) * (2.0 * A * W * sb + C * w3) / A
        + m * a * a * W2 * cb * cb
    )


def _knife_edge_only(r: float) -> None:
    r = param_finite("tyre_radius", "the tyre radius r", r)
    if r != 0.0:
        raise blame(("tyre_radius",),
            "steady circular rolling is computed for a knife-edge rim only (tyre radius 0): "
            "the physics sheet gives the circle relation and its stability for r = 0, and "
            f"a rounded rim (r = {r:.6g} m) changes both beyond a simple a -> a - r"
        )


def _make_circle(
    wheel: Wheel, a: float, g: float, beta: float, RG: float, v: float | None = None
) -> CircleMotion:
    W, w3, k = circle_arrays(wheel.mass, wheel.A, wheel.C, a, g, beta, RG)
    W, w3, k = float(W), float(w3), float(k)
    if v is not None and RG > 0.0:
        # lean_for: the speed and the circle are the given data and the lean the solved
        # unknown. Near 90° one ulp of the lean moves tan(beta), hence Omega, by far more
        # than round-off, so report Omega = v / R_G and omega_3 = v / a exactly and take
        # kappa at those rates (the relation holds to the lean's float resolution).
        W, w3 = v / RG, v / a
        k = float(_kappa(wheel.mass, wheel.A, wheel.C, a, g, beta, W, w3))
    Ac = wheel.A + wheel.mass * a * a
    stable = k > 0.0
    return CircleMotion(
        lean=beta,
        radius=RG,
        turn_rate=W,
        spin=w3,
        speed=W * RG,
        contact_radius=RG + a * math.sin(beta),
        kappa=k,
        stable=stable,
        lean_frequency=math.sqrt(k / Ac) if stable else None,
        growth_rate=None if stable else math.sqrt(-k / Ac),
        rim_radius=a,
        g=g,
    )


def _check_lean(beta: float) -> float:
    beta = param_finite("lean", "the lean", beta)
    if not 0.0 <= beta < 0.5 * math.pi:
        raise blame(("lean",),
            f"the lean must be inwards, from 0° up to (not including) 90°; got "
            f"{math.degrees(beta):.6g}°"
        )
    return beta


def _check_RG(RG: float) -> float:
    RG = param_finite("circle", "the circle radius", RG)
    if RG < 0.0:
        raise blame(("circle",), f"the circle radius must be >= 0, got {RG:.6g} m")
    return RG


def circle(
    wheel: Wheel,
    a: float,
    lean_rad: float,
    R_G: float,
    g: float = STANDARD_GRAVITY,
    *,
    r: float = 0.0,
) -> CircleMotion:
    """Steady circular rolling at lean beta with the centre on a circle of radius R_G.

    Parameters
    ----------
    wheel : Wheel — A and C about the centre G
    a : float — m, rim radius
    lean_rad : float — rad, inward lean from the vertical, 0 <= beta < pi/2
    R_G : float — m, radius of the centre's circle, >= 0 (0: spinning in place)
    g : float — m/s^2
    r : float — m, tyre radius; only 0 (knife edge)

    Notes
    -----
    Sheet §3.3 (knife edge), with v = a omega_3 = Omega R_G:
    Omega^2 = m g a^2 tan(beta) / (A a sin(beta) + (C + m a^2) R_G), R_P = R_G + a sin(beta);
    stable (neutrally) iff
    kappa = A Omega^2 cos 2beta - (C + m a^2) Omega omega_3 sin beta - m g a cos beta
            + (2 A Omega sin beta + (C + m a^2) omega_3)(2 A Omega sin beta + C omega_3)/A
            + m a^2 Omega^2 cos^2 beta > 0,
    the lean oscillating at sqrt(kappa / (A + m a^2)). beta = 0 is the wheel upright at rest
    (kappa = -m g a); straight rolling is the limit R_G -> oo (:func:`at_speed`)."""
    _knife_edge_only(r)
    a, _, g = check_geometry(a, 0.0, g)
    return _make_circle(wheel, a, g, _check_lean(lean_rad), _check_RG(R_G))


def lean_for(
    wheel: Wheel,
    a: float,
    v: float,
    R_G: float,
    g: float = STANDARD_GRAVITY,
    *,
    r: float = 0.0,
    params: tuple[str, ...] = ("circle", "speed"),
) -> CircleMotion:
    """The steady circle with its centre moving at speed v on a circle of radius R_G: the lean
    solving Omega(beta) R_G = |v| (monotonic in beta for R_G > 0: one root, by Brent).

    v = 0 with R_G > 0 is upright at rest; R_G = 0 with v != 0 has no lean, and with v = 0 every
    lean: an InputError naming ``params`` (default ``("circle", "speed")``), as for a lean too
    near 90° or 0 to resolve. Knife edge only. Sheet §3.3."""
    from scipy.optimize import brentq

    _knife_edge_only(r)
    a, _, g = check_geometry(a, 0.0, g)
    v = abs(param_finite(params[-1], "the speed", v))
    RG = _check_RG(R_G)
    if RG == 0.0:
        if v == 0.0:
            raise blame(params,
                "spinning in place (circle radius 0) has the centre at rest at every lean: "
                "give the lean instead of the speed"
            )
        raise blame(
            params,
            f"no lean in (0°, 90°) gives speed {v:.6g} m/s on a circle of radius 0: "
            "spinning in place the centre does not move (its speed is 0)"
        )
    if v == 0.0:
        return _make_circle(wheel, a, g, 0.0, RG)
    m, A, C = wheel.mass, wheel.A, wheel.C

    def f(beta: float) -> float:
        W, _, _ = circle_arrays(m, A, C, a, g, beta, RG)
        ratio = float(W) * RG / v
        if ratio == 0.0 or ratio == math.inf:  # under- or overflow: still the right sign
            return -800.0 if ratio == 0.0 else 800.0
        return math.log(ratio)

    lo = 1e-300
    # the small-lean solution tan(beta) ~ (C + m a^2) v^2 / (m g a^2 R_G) underestimates
    # only slightly; start from below it
    approx = math.atan((C + m * a * a) * v * v / (m * g * a * a * RG))
    lo = max(lo, 0.5 * approx)
    if f(lo) > 0.0:
        lo = 1e-300
        if f(lo) > 0.0:
            # tan(beta) ~ (C + m a^2) v^2 / (m g a^2 R_G), in logarithms (it underflows)
            e10 = (math.log10(C + m * a * a) + 2.0 * math.log10(v)
                   - math.log10(m * g * a * a * RG))
            raise blame(
                params,
                f"the speed {v:.6g} m/s is too small for a circle of radius {RG:.6g} m: the "
                f"steady circle would lean about 1e{math.floor(e10)} rad, below the smallest "
                f"lean that can be resolved ({lo:g} rad); give a larger speed, or the lean "
                "instead of the speed",
            )
    hi = 0.5 * math.pi * (1.0 - 1e-15)
    if not f(hi) > 0.0:
        raise blame(
            params,
            f"no lean in (0°, 90°) can be resolved for speed {v:.6g} m/s on a circle of "
            f"radius {RG:.6g} m: the wheel would have to lie flat"
        )
    beta = brentq(f, lo, hi, xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=500)
    return _make_circle(wheel, a, g, float(beta), RG, v=v)


def radius_for(
    wheel: Wheel,
    a: float,
    v: float,
    lean_rad: float,
    g: float = STANDARD_GRAVITY,
    *,
    r: float = 0.0,
    params: tuple[str, ...] = ("lean", "speed"),
) -> CircleMotion:
    """The steady circle at lean beta whose centre moves at speed |v|.

    Solves v^2 (A a sin beta + (C + m a^2) R_G) = m g a^2 tan(beta) R_G^2 (sheet §3.3) for
    R_G >= 0 in closed form (the positive root of the quadratic, cancellation free):
    R_G = [c v^2 + sqrt(c^2 v^4 + 4 K v^2 A a sin beta)] / (2 K), c = C + m a^2,
    K = m g a^2 tan beta. v = 0 gives R_G = 0 (spinning in place). beta = 0 with v != 0 is
    straight rolling (R_G -> oo): an :class:`rbcli.errors.InputError` naming ``params`` (the
    parameters that gave the lean and the speed). Knife edge only.
    """
    _knife_edge_only(r)
    a, _, g = check_geometry(a, 0.0, g)
    v = abs(param_finite(params[-1], "the speed", v))
    beta = _check_lean(lean_rad)
    m, A, C = wheel.mass, wheel.A, wheel.C
    if beta == 0.0:
        if v == 0.0:
            return _make_circle(wheel, a, g, 0.0, 0.0)
        raise blame(
            params,
            "an upright wheel (lean 0) moving at a speed rolls straight (circle radius "
            "infinite): use the straight-rolling verdict"
        )
    c = C + m * a * a
    K = m * g * a * a * math.tan(beta)
    v2 = v * v
    RG = (c * v2 + math.sqrt(c * c * v2 * v2 + 4.0 * K * v2 * A * a * math.sin(beta))) / (2 * K)
    return _make_circle(wheel, a, g, beta, RG)


def stability_map(wheel: Wheel, a: float, g: float, leans: Any, radii: Any) -> np.ndarray:
    """kappa (N m) of steady circles, (N, M) for ``leans`` (rad) and ``radii`` R_G (m), as
    :func:`circle` (> 0 stable)."""
    a, _, g = check_geometry(a, 0.0, g)
    b = np.asarray(leans, dtype=float).reshape(-1)
    R = np.asarray(radii, dtype=float).reshape(-1)
    if not (np.all(np.isfinite(b)) and np.all((b >= 0.0) & (b < 0.5 * math.pi))):
        raise ValueError("every lean must be in [0°, 90°)")
    if not (np.all(np.isfinite(R)) and np.all(R >= 0.0)):
        raise ValueError("every circle radius must be finite and >= 0")
    _, _, k = circle_arrays(wheel.mass, wheel.A, wheel.C, a, g, b[:, None], R[None, :])
    return np.asarray(k, dtype=float)
