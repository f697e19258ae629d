"""Rolling stability of a wheel, disk or hoop on a rough horizontal floor (``rollcheck``).

Model (physics sheet ``dynamics.md`` §3): a rigid body of revolution of mass m, centre of
mass G on its axle, rolls without slipping (and without pivot friction or rolling
resistance) on a horizontal floor. It touches the floor along a circle of radius a in its
mid-plane (a *knife-edge* rim), or, generalised, along a toroidal rim whose tube radius is
r (0 <= r < a; r = 0 is the knife edge). Energy is conserved; there is no damping, so
"stable" always means **neutral stability (undamped)**: a small lean oscillates with
bounded amplitude, it does not decay.

Which moments enter (sheet §3.2 and checklist §4b.8):

- A — the diametral moment of inertia, across the axle, **about the centre G**;
- C — the axial moment, about the axle, **about the centre G**;
- C + m a^2 — the axial-direction moment **about the contact point** (parallel axis);
- A + m a^2 — the fore-aft moment about the contact point; it sets only the rates.

Angles are in radians in every argument and attribute; ``to_json`` adds ``*_deg`` keys.
All quantities are SI (m, kg, s, rad/s).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from rbcli.core.rim import fmt_length as _fmt_length
from rbcli.core.symmetry import ROUND_OFF, AxialSymmetry, Asymmetric, about_axis

STANDARD_GRAVITY = 9.80665  # m/s^2

MODEL_NOTE = (
    "knife-edge or toroidal rim rolling without slip; A and C about the centre G, "
    "C + m a^2 about the contact point; neutral stability (undamped)"
)


# --------------------------------------------------------------------------- helpers


def _finite(name: str, x: float) -> float:
    x = float(x)
    if not math.isfinite(x):
        raise ValueError(f"{name} must be a finite number, got {x!r}")
    return x


def _positive(name: str, x: float) -> float:
    x = _finite(name, x)
    if x <= 0.0:
        raise ValueError(f"{name} must be positive, got {x:.6g}")
    return x


def _blame(params: tuple[str, ...], message: str) -> Exception:
    """The error for bad values of the parameters ``params`` (the first one is ``param``):
    a :class:`rbcli.errors.ParamError` for one, an InputError naming each option for more
    (``--circle, --speed: ...``). Callers ``raise`` it."""
    from rbcli.errors import InputError, ParamError, option_name

    if len(params) == 1:
        return ParamError(params[0], message)
    return InputError(", ".join(option_name(p) for p in params) + ": " + message, param=params[0])


def _param_finite(param: str, what: str, x: float) -> float:
    x = float(x)
    if not math.isfinite(x):
        raise _blame((param,), f"{what} must be a finite number, got {x!r}")
    return x


def _check_geometry(a: float, r: float, g: float) -> tuple[float, float, float]:
    """a, r, g checked; errors are ParamErrors naming ``radius``, ``tyre_radius``, ``g``."""
    a = _param_finite("radius", "the rim radius a", a)
    if a <= 0.0:
        raise _blame(("radius",), f"the rim radius a must be positive, got {a:.6g}")
    r = _param_finite("tyre_radius", "the tyre radius r", r)
    g = _param_finite("g", "gravity g", g)
    if g <= 0.0:
        raise _blame(("g",), f"gravity g must be positive, got {g:.6g}")
    if r < 0.0:
        raise _blame(("tyre_radius",), f"the tyre radius r must be >= 0 (0 = knife edge), got {r:.6g} m")
    if r >= a:
        raise _blame(
            ("tyre_radius",),
            f"the tyre radius r = {r:.6g} m must be smaller than the rim radius a = {a:.6g} m",
        )
    return a, r, g


def _vec(v: Any) -> tuple[float, float, float]:
    a = np.asarray(v, dtype=float).reshape(3)
    return (float(a[0]), float(a[1]), float(a[2]))


def _opt(x: float | None) -> float | None:
    return None if x is None else float(x)


# --------------------------------------------------------------------------- the wheel


@dataclass(frozen=True)
class Wheel:
    """Mass properties of a body of revolution, reduced to what rolling needs.

    Attributes
    ----------
    mass : float — kg, > 0
    A : float — kg m^2, the diametral moment (across the axle) about the centre of mass G
    C : float — kg m^2, the axial moment (about the axle) about G; 0 < C <= 2 A
    com : tuple of 3 floats — m, the centre of mass in the body frame
    axle : tuple of 3 floats — the unit axle direction in the body frame
    com_offset : float — m, distance of the com from the axle line (below tolerance)
    asymmetry : AxialSymmetry or None — for a wheel accepted as nearly of revolution
        (departures above rounding, within the tolerance of :func:`wheel_from_body`): the
        two moments across the axle about the com, the products coupling the axle to the
        plane across it and the com's offset from the axle relative to the rim radius
        (:mod:`rbcli.core.symmetry`); None for a wheel of revolution to rounding

    Construct directly for textbook bodies (``Wheel(mass=1, A=0.25, C=0.5)`` is a thin
    disk of unit mass and radius 1) or from a general body with :func:`wheel_from_body`.
    """

    mass: float
    A: float
    C: float
    com: tuple[float, float, float] = (0.0, 0.0, 0.0)
    axle: tuple[float, float, float] = (0.0, 0.0, 1.0)
    com_offset: float = 0.0
    asymmetry: AxialSymmetry | None = field(default=None, repr=False, compare=False)

    def __post_init__(self) -> None:
        _positive("the mass", self.mass)
        _positive("the diametral moment A", self.A)
        _positive("the axial moment C", self.C)
        # a body of revolution has principal moments (A, A, C): the triangle
        # inequality allows C up to 2 A (a thin flat disk or hoop); 1e-9 for round-off
        if self.C > 2.0 * self.A * (1.0 + 1e-9):
            raise ValueError(
                f"not a physical body of revolution: the axial moment C = {self.C:.6g} "
                f"kg m² exceeds twice the diametral moment A = {self.A:.6g} kg m²"
            )

    def to_json(self) -> dict[str, Any]:
        """``mass``, ``I`` (= A), ``Is`` (= C), ``com``, ``axle``, ``com_offset``."""
        return {
            "mass": float(self.mass),
            "I": float(self.A),
            "Is": float(self.C),
            "com": [float(x) for x in self.com],
            "axle": [float(x) for x in self.axle],
            "com_offset": float(self.com_offset),
        }


def wheel_from_body(
    mass: float,
    com: Any,
    inertia_com: Any,
    axle: Any = (0.0, 0.0, 1.0),
    *,
    sym_rtol: float = ROUND_OFF,
    axle_through: Any = None,
    radius: float | None = None,
    off_axis_rtol: float | None = None,
) -> Wheel:
    """Reduce a body's mass properties to a :class:`Wheel` (A and C about the centre).

    Parameters
    ----------
    mass : float — kg
    com : (3,) array_like — m, centre of mass in the body frame
    inertia_com : (3, 3) array_like — kg m^2, inertia tensor about the com
        (tensor convention: off-diagonals are the negated products)
    axle : (3,) array_like — axle direction in the body frame (need not be unit);
        default body z
    sym_rtol : float — how far from a body of revolution the wheel may be (the
        ``--symmetry-tol``, a fraction; default 1e-6, rounding): the two moments across
        the axle may differ by this fraction of their mean, and the products of inertia
        coupling the axle to the plane across it may be this fraction of it
    axle_through : (3,) array_like or None — m, a point of the axle line in the body
        frame. **Default: the body origin** (the natural place to centre a wheel when it is
        modelled), so a wheel whose com is off the origin — an unbalanced wheel, or a
        wheel modelled away from the origin — is refused unless the axle point is given.
    radius : float or None — m, the rim radius; the length scale of the com test
        (default: the radius of gyration sqrt(C/m) about the axle)
    off_axis_rtol : float or None — the com may be off the axle line by at most
        ``off_axis_rtol * radius`` (default: ``sym_rtol``)

    Returns
    -------
    Wheel
        With ``asymmetry`` set when a departure is above rounding (1e-6) but within the
        tolerance: the wheel is then the *symmetrised* one.

    Raises
    ------
    rbcli.core.symmetry.Asymmetric (a ValueError)
        not a body of revolution about the axle within the tolerance (the moments across
        it differ, or the axle is not a principal axis, or the com is off the axle line),
        with the numbers and the option ``--symmetry-tol``.
    ValueError
        zero axle, zero or negative moments.

    Notes
    -----
    With n the unit axle: C = n.I.n; the two moments across the axle are the eigenvalues of
    I restricted to the plane normal to n, A1 <= A2, with mean Ā = (A1 + A2)/2 and
    relative spread δ = (A2 - A1)/Ā; the coupling is |(1 - n n^T) I n|; the com's offset
    e is its distance from the axle line (:func:`rbcli.core.symmetry.about_axis`, about
    the com, e relative to the rim radius). Rolling depends on the body only through m,
    G and the inertia (sheet §3), so a body within the tolerance is answered for the
    **symmetrised wheel**: A = Ā, C as measured, the products dropped and the com taken on
    the axle (the rim centre; the model has no place for an offset).

    How far that may be off (the bound :attr:`RollcheckResult.asymmetry_effect` reports;
    first order in the departures). The threshold is s_c² = m g (a - r) A / (C (C + m a²))
    (:func:`straight`), so s_c ∝ sqrt(A) with everything else fixed. As the real wheel
    turns, its moment about the horizontal fore-aft diameter swings between A1 and A2, so
    its threshold lies between the ones computed with A = A1 and A = A2, and
    |s_c(A_i)/s_c(Ā) - 1| = |sqrt(1 ± δ/2) - 1| <= 1 - sqrt(1 - δ/2) <= δ/(4 - δ) ≈ δ/4
    (using sqrt(1 - x) >= 1 - x); the critical speed a s_c alike. The products change the
    principal moments by at most the coupling (Weyl's inequality) and tilt the principal
    axis by about coupling/|C - Ā| (the wheel wobbles): of the order of the coupling
    relative to Ā. A com e off the axle makes the gravity lever swing between a - r - e
    and a - r + e: s_c by about e/(2 (a - r)). Sheet §3; the eigenvalue bound: Horn and
    Johnson, *Matrix Analysis*, 2nd ed., Theorem 4.3.1.
    """
    m = _positive("the mass", mass)
    G = np.asarray(com, dtype=float).reshape(3)
    J = np.asarray(inertia_com, dtype=float).reshape(3, 3)
    if not (np.all(np.isfinite(G)) and np.all(np.isfinite(J))):
        raise ValueError("the centre of mass and the inertia tensor must be finite")
    J = 0.5 * (J + J.T)
    n = np.asarray(axle, dtype=float).reshape(3)
    nn = float(np.linalg.norm(n))
    if not math.isfinite(nn) or nn == 0.0:
        raise ValueError("the axle direction must be a non-zero finite vector")
    n = n / nn
    C = float(n @ J @ n)
    # orthonormal basis (e1, e2) of the plane across the axle
    k = int(np.argmin(np.abs(n)))
    e1 = np.zeros(3)
    e1[k] = 1.0
    e1 = e1 - (e1 @ n) * n
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    E = np.array([e1, e2])
    across = np.linalg.eigvalsh(E @ J @ E.T)
    A1, A2 = float(across[0]), float(across[1])
    scale = max(abs(A1), abs(A2), abs(C))
    if not scale > 0.0:
        raise ValueError("the inertia tensor is zero: a point mass cannot roll on a rim")
    A = 0.5 * (A1 + A2)
    if C <= 0.0 or A <= 0.0:
        raise ValueError(
            f"the moments about and across the axle must be positive, got C = {C:.6g} "
            f"and A = {A:.6g} kg m²"
        )
    P = np.zeros(3) if axle_through is None else np.asarray(axle_through, dtype=float)
    P = P.reshape(3)
    d = G - P
    offset = float(np.linalg.norm(d - (d @ n) * n))
    L = math.sqrt(C / m) if radius is None else _positive("the rim radius", radius)
    sym = about_axis(m, G, J, G, n, size=L)  # the moments about the com
    sym = dataclasses.replace(sym, com_offset=offset, com_offset_relative=offset / L)
    _require(sym, sym_rtol, sym_rtol if off_axis_rtol is None else off_axis_rtol, n, P,
             axle_through is None)
    return Wheel(mass=m, A=A, C=C, com=_vec(G), axle=_vec(n), com_offset=offset,
                 asymmetry=None if sym.exact else sym)


def _pct(x: float) -> str:
    return f"{100.0 * x:.2g} %"


def _require(sym: AxialSymmetry, tol: float, off_tol: float, n: Any, P: Any, origin: bool) -> None:
    """Refuse a wheel beyond the tolerance: :class:`Asymmetric` with the numbers, in the
    order products, moments, com (the first that fails)."""
    from rbcli.errors import option_name

    opt = option_name("symmetry_tol")
    tol_r, off_r = max(tol, ROUND_OFF), max(off_tol, ROUND_OFF)
    if sym.coupling_relative > tol_r:
        raise Asymmetric(
            "not a body of revolution about the axle: the axle is not a principal axis "
            f"(product of inertia {sym.coupling:.6g} kg m², {_pct(sym.coupling_relative)} of the "
            f"moment across, {sym.mean:.6g} kg m²; the nearest principal axis is "
            f"{math.degrees(sym.principal_tilt):.3g}° away); a rolling wheel needs it within "
            f"{opt} ({_pct(tol)})", sym, tol)
    if sym.relative > tol_r:
        I1, I2 = sym.transverse
        # enough digits that the two moments print differently
        digits = 6 if not 0.0 < sym.relative < 1e-4 else min(17, math.ceil(-math.log10(sym.relative)) + 2)
        raise Asymmetric(
            "not a body of revolution about the axle: the moments across it are "
            f"{I1:.{digits}g} and {I2:.{digits}g} kg m² (differ by {_pct(sym.relative)}); a "
            f"rolling wheel needs them within {opt} ({_pct(tol)})", sym, tol)
    if sym.com_offset_relative > off_r:
        def _pt(v: Any) -> str:
            return "[" + ", ".join(f"{float(x):.6g}" for x in v) + "]"

        where = "the body origin" if origin else f"{_pt(P)} m"
        raise Asymmetric(
            f"the centre of mass is {_fmt_length(sym.com_offset)} off the axle (the axle line "
            f"runs along {_pt(n)} through {where}; {_pct(sym.com_offset_relative)} of the rim "
            f"radius {_fmt_length(sym.size)}); a rolling wheel needs its centre of mass on the "
            f"axle, within {opt} ({_pct(off_tol)}) of the rim radius", sym, off_tol)


# --------------------------------------------------------------------------- straight


@dataclass(frozen=True)
class StraightRolling:
    """Threshold of stable straight upright rolling.

    Attributes
    ----------
    wheel : Wheel
    radius : float — m, rim radius a (G to contact point when upright)
    tyre_radius : float — m, tube radius r of a rounded rim (0 = knife edge)
    g : float — m/s^2
    critical_spin : float — rad/s, s_c = sqrt(m g (a - r) A / (C (C + m a^2)))
    critical_speed : float — m/s, v_c = a s_c
    C_contact : float — kg m^2, C + m a^2 (axial direction, about the contact point)
    A_contact : float — kg m^2, A + m a^2 (fore-aft axis, about the contact point)
    """

    wheel: Wheel
    radius: float
    tyre_radius: float
    g: float
    critical_spin: float
    critical_speed: float
    C_contact: float
    A_contact: float

    def nu2(self, spin: Any) -> Any:
        """Squared lean-oscillation frequency (rad^2/s^2) at spin(s) s (rad/s), sheet §3.2.

        nu^2 = [C (C + m a^2) s^2 - A m g (a - r)] / [A (A + m a^2)]
             = C (C + m a^2) (s^2 - s_c^2) / [A (A + m a^2)].
        """
        s = np.asarray(spin, dtype=float)
        w = self.wheel
        sc = self.critical_spin
        out = w.C * self.C_contact * (s * s - sc * sc) / (w.A * self.A_contact)
        return float(out) if out.ndim == 0 else out

    def to_json(self) -> dict[str, Any]:
        """SPEC keys ``radius``, ``mass``, ``I``, ``Is``, ``critical_spin``,
        ``critical_speed`` plus ``tyre_radius``, ``g``, ``I_contact``, ``Is_contact``,
        ``model``."""
        return {
            "radius": float(self.radius),
            "tyre_radius": float(self.tyre_radius),
            "mass": float(self.wheel.mass),
            "I": float(self.wheel.A),
            "Is": float(self.wheel.C),
            "I_contact": float(self.A_contact),
            "Is_contact": float(self.C_contact),
            "g": float(self.g),
            "critical_spin": float(self.critical_spin),
            "critical_speed": float(self.critical_speed),
            "model": MODEL_NOTE,
        }


def straight(wheel: Wheel, a: float, r: float = 0.0, g: float = STANDARD_GRAVITY) -> StraightRolling:
    """Critical spin and speed for stable straight upright rolling.

    Parameters
    ----------
    wheel : Wheel — A and C about the centre G
    a : float — m, rim radius (centre to contact point when upright), > 0
    r : float — m, tube radius of a rounded (toroidal) rim, 0 <= r < a; 0 = knife edge
    g : float — m/s^2, > 0

    Returns
    -------
    StraightRolling

    Notes
    -----
    Sheet §3.2: linearising about upright rolling at spin s gives
    lambda^2 [A (A + m a^2) lambda^2 + C (C + m a^2) s^2 - A m g (a - r)] = 0, so the lean
    stays bounded (neutral stability, undamped) iff
    s^2 > s_c^2 = m g (a - r) A / [C (C + m a^2)], and v_c = a s_c.
    A and C are about the centre G; C + m a^2 is the axial moment about the contact
    point. A rounded rim only weakens gravity (a -> a - r in the gravity term).
    Thin disk: s_c^2 = g/(3a); hoop: s_c^2 = g/(4a).
    """
    a, r, g = _check_geometry(a, r, g)
    m, A, C = wheel.mass, wheel.A, wheel.C
    Cc = C + m * a * a
    Ac = A + m * a * a
    sc = math.sqrt(m * g * (a - r) * A / (C * Cc))
    return StraightRolling(wheel, a, r, g, sc, a * sc, Cc, Ac)


@dataclass(frozen=True)
class Verdict:
    """Straight rolling at a given speed.

    Attributes
    ----------
    speed : float — m/s, speed of the centre as given (negative = rolling backwards)
    spin : float — rad/s, spin about the axle, speed / a (same sign as speed)
    stable : bool — |spin| > s_c: the lean stays bounded (neutral stability, undamped).
        Exactly at s_c the lean drifts (a repeated zero root): **not stable**.
    margin : float — |speed| / v_c (> 1 stable)
    nu2 : float — rad^2/s^2, squared lean-oscillation frequency (sheet §3.2)
    lean_frequency : float or None — rad/s, sqrt(nu2) when nu2 > 0, else None
    lean_frequency_hz : float or None — Hz, lean_frequency / (2 pi)
    growth_rate : float or None — 1/s, sqrt(-nu2) when nu2 <= 0 (0.0 exactly at the
        threshold, where the lean grows linearly, not exponentially), else None
    backwards : bool — the speed (or spin) was negative; |spin| was used (the stability
        of straight rolling does not depend on the direction)
    """

    speed: float
    spin: float
    stable: bool
    margin: float
    nu2: float
    lean_frequency: float | None
    lean_frequency_hz: float | None
    growth_rate: float | None
    backwards: bool

    def to_json(self) -> dict[str, Any]:
        """SPEC keys ``speed``, ``stable``, ``margin`` plus ``spin``, ``lean_frequency``,
        ``lean_frequency_hz``, ``growth_rate``, ``lean_frequency_squared``, ``backwards``."""
        return {
            "speed": float(self.speed),
            "spin": float(self.spin),
            "stable": bool(self.stable),
            "margin": float(self.margin),
            "lean_frequency": _opt(self.lean_frequency),
            "lean_frequency_hz": _opt(self.lean_frequency_hz),
            "growth_rate": _opt(self.growth_rate),
            "lean_frequency_squared": float(self.nu2),
            "backwards": bool(self.backwards),
        }


def at_speed(
    straight: StraightRolling, v: float | None = None, spin: float | None = None
) -> Verdict:
    """Verdict on straight upright rolling at speed v (m/s) or spin (rad/s).

    Parameters
    ----------
    straight : StraightRolling
    v : float or None — m/s, speed of the centre
    spin : float or None — rad/s, spin about the axle (omega_3); v = a * spin

    Give one of them, or both when they agree (v = a spin to a relative 1e-9).
    A negative value means rolling backwards: the verdict uses |spin|.

    Notes
    -----
    nu^2 = [C (C + m a^2) s^2 - A m g (a - r)] / [A (A + m a^2)] (sheet §3.2), with A, C about
    the centre G and C + m a^2, A + m a^2 about the contact point. nu^2 > 0: the lean
    oscillates at nu (neutral stability, undamped); nu^2 < 0: it grows at sqrt(-nu^2).
    """
    a = straight.radius
    if v is None and spin is None:
        raise ValueError("give a speed or a spin")
    if v is not None:
        v = _param_finite("speed", "the speed", v)
    if spin is not None:
        spin = _param_finite("spin", "the spin", spin)
    if v is not None and spin is not None:
        if abs(v - a * spin) > 1e-9 * max(abs(v), abs(a * spin)):
            raise _blame(("speed", "spin"),
                f"the speed {v:.6g} m/s and the spin {spin:.6g} rad/s disagree: rolling "
                f"needs speed = radius x spin = {a * spin:.6g} m/s"
            )
    if spin is None:
        assert v is not None
        spin = v / a
    if v is None:
        v = a * spin
    s = abs(spin)
    nu2 = straight.nu2(s)
    stable = nu2 > 0.0
    freq = math.sqrt(nu2) if stable else None
    growth = None if stable else math.sqrt(-nu2)
    return Verdict(
        speed=v,
        spin=spin,
        stable=stable,
        margin=s / straight.critical_spin,
        nu2=nu2,
        lean_frequency=freq,
        lean_frequency_hz=None if freq is None else freq / (2.0 * math.pi),
        growth_rate=growth,
        backwards=(spin < 0.0),
    )


def margin_curve(wheel: Wheel, a: float, r: float, g: float, speeds: Any) -> np.ndarray:
    """Squared lean-oscillation frequency nu^2 (rad^2/s^2) against speed, for plots.

    Parameters
    ----------
    wheel : Wheel
    a, r : float — m, rim and tyre radius
    g : float — m/s^2
    speeds : (N,) array_like — m/s (sign ignored)

    Returns
    -------
    (N,) ndarray — nu^2 at each speed; > 0 stable (oscillation at sqrt(nu^2)),
    < 0 unstable (growth at sqrt(-nu^2)). Zero at +-v_c. Sheet §3.2.
    """
    st = straight(wheel, a, r, g)
    v = np.asarray(speeds, dtype=float)
    return np.asarray(st.nu2(v / a), dtype=float).reshape(v.shape)


# --------------------------------------------------------------------------- circles


@dataclass(frozen=True)
class CircleMotion:
    """Steady circular rolling of a knife-edge wheel leaning into the turn.

    Attributes
    ----------
    lean : float — rad, beta, inward lean of the wheel plane from the vertical, [0, pi/2)
    radius : float — m, R_G, radius of the circle of the centre G
    turn_rate : float — rad/s, Omega >= 0, heading (precession) rate about the vertical
    spin : float — rad/s, omega_3 = Omega R_G / a, spin about the axle (same sense as the
        travel)
    speed : float — m/s, v = Omega R_G = a omega_3, speed of the centre
    contact_radius : float — m, R_P = R_G + a sin(beta), circle of the contact point
    kappa : float — N m (kg m^2/s^2), lean stiffness of the steady motion (sheet §3.3)
    stable : bool — kappa > 0 (neutral stability, undamped; kappa = 0 counts as not stable)
    lean_frequency : float or None — rad/s, sqrt(kappa / (A + m a^2)) when stable
    growth_rate : float or None — 1/s, sqrt(-kappa / (A + m a^2)) when not stable
    rim_radius : float — m, a
    g : float — m/s^2
    """

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
            "lean_frequency": _opt(f),
            "lean_frequency_hz": None if f is None else float(f) / (2.0 * math.pi),
            "growth_rate": _opt(self.growth_rate),
        }


def _circle_arrays(
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
    r = _param_finite("tyre_radius", "the tyre radius r", r)
    if r != 0.0:
        raise _blame(("tyre_radius",),
            "steady circular rolling is computed for a knife-edge rim only (tyre radius 0): "
            "the physics sheet gives the circle relation and its stability for r = 0, and "
            f"a rounded rim (r = {r:.6g} m) changes both beyond a simple a -> a - r"
        )


def _make_circle(
    wheel: Wheel, a: float, g: float, beta: float, RG: float, v: float | None = None
) -> CircleMotion:
    W, w3, k = _circle_arrays(wheel.mass, wheel.A, wheel.C, a, g, beta, RG)
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
    beta = _param_finite("lean", "the lean", beta)
    if not 0.0 <= beta < 0.5 * math.pi:
        raise _blame(("lean",),
            f"the lean must be inwards, from 0° up to (not including) 90°; got "
            f"{math.degrees(beta):.6g}°"
        )
    return beta


def _check_RG(RG: float) -> float:
    RG = _param_finite("circle", "the circle radius", RG)
    if RG < 0.0:
        raise _blame(("circle",), f"the circle radius must be >= 0, got {RG:.6g} m")
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
    lean_rad : float — rad, beta, inward lean from the vertical, 0 <= beta < pi/2
    R_G : float — m, radius of the centre's circle, >= 0 (0 = spinning in place, Euler's
        disk)
    g : float — m/s^2
    r : float — m, tyre radius; only 0 (knife edge) is accepted, else ValueError

    Returns
    -------
    CircleMotion

    Notes
    -----
    Sheet §3.3 (knife edge):
    m g a sin(beta) = A Omega^2 sin(beta) cos(beta) + (C + m a^2) Omega omega_3 cos(beta),
    with v = a omega_3 = Omega R_G, i.e.
    Omega^2 = m g a^2 tan(beta) / (A a sin(beta) + (C + m a^2) R_G);
    R_P = R_G + a sin(beta). Stability (neutral, undamped) iff
    kappa = A Omega^2 cos 2beta - (C + m a^2) Omega omega_3 sin beta - m g a cos beta
            + (2 A Omega sin beta + (C + m a^2) omega_3)(2 A Omega sin beta + C omega_3)/A
            + m a^2 Omega^2 cos^2 beta > 0,
    the lean then oscillating at sqrt(kappa / (A + m a^2)). A, C about G; C + m a^2 and
    A + m a^2 about the contact point. Limits: R_G = 0 gives
    Omega^2 = m g a / (A cos beta) and kappa = (3 A sin^2 beta + m a^2 cos^2 beta) Omega^2;
    beta = 0, Omega = 0 gives sheet §3.2.

    beta = 0 exactly gives Omega = 0, omega_3 = 0, v = 0: the wheel standing upright at
    rest (kappa = -m g a, unstable). Straight rolling at speed v is the limit R_G -> oo
    (use :func:`at_speed`). At R_G = 0 and beta = 0 any turn rate is steady; Omega = 0 is
    reported (the R_G = 0 family tends to Omega^2 = m g a / A as beta -> 0+).
    """
    _knife_edge_only(r)
    a, _, g = _check_geometry(a, 0.0, g)
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
    """The steady circle with its centre moving at speed v on a circle of radius R_G.

    Solves Omega(beta) R_G = |v| for the lean beta in (0, pi/2) by ``scipy.optimize.brentq``
    (Omega from :func:`circle`). For R_G > 0 the left side increases monotonically from 0
    (beta -> 0) to infinity (beta -> pi/2), so exactly one lean exists for every v > 0.
    The direction of travel does not matter (a mirror image): |v| is used, and the result
    reports the positive speed.

    Special cases: v = 0 with R_G > 0 returns beta = 0 (standing upright at rest);
    R_G = 0 (spinning in place, the centre does not move) with v != 0 has no lean — a
    :class:`rbcli.errors.InputError` says so; R_G = 0 with v = 0 is satisfied by every lean —
    an InputError asks for the lean. A lean so close to 90° that it cannot be resolved, or so
    close to 0 that it is below the smallest float (a speed like 1e-300 m/s), also raises.
    These errors name ``params``, the parameters that gave the circle radius and the speed
    (default ``("circle", "speed")``). Knife edge only (r must be 0). Sheet §3.3.
    """
    from scipy.optimize import brentq

    _knife_edge_only(r)
    a, _, g = _check_geometry(a, 0.0, g)
    v = abs(_param_finite(params[-1], "the speed", v))
    RG = _check_RG(R_G)
    if RG == 0.0:
        if v == 0.0:
            raise _blame(params,
                "spinning in place (circle radius 0) has the centre at rest at every lean: "
                "give the lean instead of the speed"
            )
        raise _blame(
            params,
            f"no lean in (0°, 90°) gives speed {v:.6g} m/s on a circle of radius 0: "
            "spinning in place the centre does not move (its speed is 0)"
        )
    if v == 0.0:
        return _make_circle(wheel, a, g, 0.0, RG)
    m, A, C = wheel.mass, wheel.A, wheel.C

    def f(beta: float) -> float:
        W, _, _ = _circle_arrays(m, A, C, a, g, beta, RG)
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
            raise _blame(
                params,
                f"the speed {v:.6g} m/s is too small for a circle of radius {RG:.6g} m: the "
                f"steady circle would lean about 1e{math.floor(e10)} rad, below the smallest "
                f"lean that can be resolved ({lo:g} rad); give a larger speed, or the lean "
                "instead of the speed",
            )
    hi = 0.5 * math.pi * (1.0 - 1e-15)
    if not f(hi) > 0.0:
        raise _blame(
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
    a, _, g = _check_geometry(a, 0.0, g)
    v = abs(_param_finite(params[-1], "the speed", v))
    beta = _check_lean(lean_rad)
    m, A, C = wheel.mass, wheel.A, wheel.C
    if beta == 0.0:
        if v == 0.0:
            return _make_circle(wheel, a, g, 0.0, 0.0)
        raise _blame(
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
    """kappa (N m) of steady circles on a (lean, circle radius) grid, for plots.

    Parameters
    ----------
    wheel : Wheel
    a : float — m, rim radius (knife edge)
    g : float — m/s^2
    leans : (N,) array_like — rad, each in [0, pi/2)
    radii : (M,) array_like — m, R_G, each >= 0

    Returns
    -------
    (N, M) ndarray — kappa[i, j] for leans[i], radii[j]; > 0 stable (neutral, undamped).
    Same formula as :func:`circle` (sheet §3.3).
    """
    a, _, g = _check_geometry(a, 0.0, g)
    b = np.asarray(leans, dtype=float).reshape(-1)
    R = np.asarray(radii, dtype=float).reshape(-1)
    if not (np.all(np.isfinite(b)) and np.all((b >= 0.0) & (b < 0.5 * math.pi))):
        raise ValueError("every lean must be in [0°, 90°)")
    if not (np.all(np.isfinite(R)) and np.all(R >= 0.0)):
        raise ValueError("every circle radius must be finite and >= 0")
    _, _, k = _circle_arrays(wheel.mass, wheel.A, wheel.C, a, g, b[:, None], R[None, :])
    return np.asarray(k, dtype=float)


# --------------------------------------------------------------------------- the whole check


@dataclass(frozen=True)
class RollCheck:
    """Everything ``rbcli rollcheck`` answers: the threshold, and optionally a verdict at a
    speed and a steady circle.

    Attributes
    ----------
    straight : StraightRolling
    verdict : Verdict or None — when a speed or spin was given
    circle : CircleMotion or None — when a circle was asked for
    """

    straight: StraightRolling
    verdict: Verdict | None = None
    circle: CircleMotion | None = None

    def to_json(self) -> dict[str, Any]:
        """The ``rollcheck`` JSON document (SPEC §3): the keys of
        :meth:`StraightRolling.to_json`, then those of :meth:`Verdict.to_json` only when a
        speed was given, then ``circle`` (:meth:`CircleMotion.to_json`) only when asked."""
        out = self.straight.to_json()
        if self.verdict is not None:
            out.update(self.verdict.to_json())
        if self.circle is not None:
            out["circle"] = self.circle.to_json()
        return out


def rollcheck(
    wheel: Wheel,
    a: float,
    r: float = 0.0,
    g: float = STANDARD_GRAVITY,
    *,
    speed: float | None = None,
    spin: float | None = None,
    lean_rad: float | None = None,
    circle_radius: float | None = None,
) -> RollCheck:
    """Assemble a :class:`RollCheck`.

    - always: :func:`straight`;
    - ``speed`` and/or ``spin``: :func:`at_speed` (straight rolling at that speed);
    - ``lean_rad`` and ``circle_radius``: :func:`circle`;
    - ``circle_radius`` and a speed, no lean: :func:`lean_for`;
    - ``lean_rad`` and a speed, no circle radius: :func:`radius_for`;
    - ``lean_rad`` or ``circle_radius`` alone: :class:`rbcli.errors.ParamError`.
    A circle with a rounded rim (r > 0) raises a ParamError (knife edge only). Errors of
    the circle name the parameters given (``lean``, ``circle``, ``speed``, ``spin``).
    """
    st = straight(wheel, a, r, g)
    verdict = None
    if speed is not None or spin is not None:
        verdict = at_speed(st, v=speed, spin=spin)
    circ = None
    if lean_rad is not None or circle_radius is not None:
        if lean_rad is not None and circle_radius is not None:
            circ = circle(wheel, a, lean_rad, circle_radius, g, r=r)
        elif verdict is None:
            which = "lean" if lean_rad is not None else "circle radius"
            raise _blame(
                ("lean",) if lean_rad is not None else ("circle",),
                f"a steady circle needs two of lean, circle radius and speed; only the "
                f"{which} was given"
            )
        else:
            given = tuple(p for p, x in (("speed", speed), ("spin", spin)) if x is not None)
            if circle_radius is not None:
                circ = lean_for(wheel, a, verdict.speed, circle_radius, g, r=r,
                                params=("circle", *given))
            else:
                assert lean_rad is not None
                circ = radius_for(wheel, a, verdict.speed, lean_rad, g, r=r,
                                  params=("lean", *given))
    return RollCheck(st, verdict, circ)


# --------------------------------------------------------------------------- figure data


@dataclass(frozen=True)
class Curves:
    """The arrays of the ``rollcheck`` figure (:func:`curves`), ready to draw.

    Attributes
    ----------
    speeds : (N,) ndarray — m/s, speed of the centre from 0 to ``max(2.5 v_c, 1.25 |v|)``
    nu2 : (N,) ndarray — rad^2/s^2, squared lean frequency of straight rolling at each speed
    lean_frequency : (N,) ndarray — rad/s, sqrt(nu2) where nu2 > 0, else 0
    growth_rate : (N,) ndarray — 1/s, sqrt(-nu2) where nu2 < 0, else 0
    critical_speed : float — m/s, v_c
    circle_radii : (M,) ndarray or None — m, R_G from 0 to ``max(10 a, 2 R_G asked)``
        (only with a circle)
    circle_leans_deg : (K,) ndarray or None — degrees, 0.25 to 85
    circle_kappa : (K, M) ndarray or None — N m, lean stiffness of each steady circle
        (> 0 stable)
    circle_speed : (K, M) ndarray or None — m/s, speed of the centre Omega R_G on each
    """

    speeds: np.ndarray
    nu2: np.ndarray
    lean_frequency: np.ndarray
    growth_rate: np.ndarray
    critical_speed: float
    circle_radii: np.ndarray | None = None
    circle_leans_deg: np.ndarray | None = None
    circle_kappa: np.ndarray | None = None
    circle_speed: np.ndarray | None = None


def curves(check: RollCheck, n_speeds: int = 501, n_leans: int = 200, n_radii: int = 220) -> Curves:
    """The figure's arrays for a :class:`RollCheck`: nu^2 against speed (:func:`margin_curve`)
    and, when a circle was asked for, kappa and the speed of the centre on a (lean, circle
    radius) grid (:func:`stability_map`, sheet §3.3)."""
    st = check.straight
    w = st.wheel
    vc = st.critical_speed
    vmax = 2.5 * vc
    if check.verdict is not None:
        vmax = max(vmax, 1.25 * abs(check.verdict.speed))
    speeds = np.linspace(0.0, vmax, n_speeds)
    nu2 = margin_curve(w, st.radius, st.tyre_radius, st.g, speeds)
    out = dict(speeds=speeds, nu2=nu2, lean_frequency=np.sqrt(np.clip(nu2, 0.0, None)),
               growth_rate=np.sqrt(np.clip(-nu2, 0.0, None)), critical_speed=vc)
    if check.circle is not None:
        a = st.radius
        rmax = max(10.0 * a, 2.0 * check.circle.radius)
        leans_deg = np.linspace(0.25, 85.0, n_leans)
        radii = np.linspace(0.0, rmax, n_radii)
        kappa = stability_map(w, a, st.g, np.radians(leans_deg), radii)
        W, _, _ = _circle_arrays(w.mass, w.A, w.C, a, st.g, np.radians(leans_deg)[:, None],
                                 radii[None, :])
        out.update(circle_radii=radii, circle_leans_deg=leans_deg, circle_kappa=kappa,
                   circle_speed=W * radii[None, :])
    return Curves(**out)
