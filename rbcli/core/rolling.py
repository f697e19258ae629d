"""Rolling stability of a wheel, disk or hoop on a rough horizontal floor (``rollcheck``).

Physics sheet ``dynamics.md`` §3: a rigid body of revolution (mass m, com G on its axle)
rolls without slipping on a floor, touching it along a circle of radius a (a *knife-edge*
rim) or a toroidal rim of tube radius r (0 <= r < a). No damping: "stable" means
neutral stability (undamped): a small lean oscillates, it does not decay. A and C are
about the centre G; C + m a^2 and A + m a^2 about the contact point (sheet §3.2, §4b.8).
Angles in radians; SI throughout."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from rbcli.core.rollcircle import CircleMotion, circle, circle_arrays, lean_for, radius_for, stability_map
from rbcli.core.rim import fmt_length
from rbcli.core.wheel import STANDARD_GRAVITY, Wheel, blame, check_geometry, opt_float, param_finite

MODEL_NOTE = (
    "knife-edge, toroidal, spherical or flat-band rim rolling without slip; A and C about the "
    "centre G, C + m a^2 about the contact point; neutral stability (undamped)"
)


# --- straight


@dataclass(frozen=True)
class StraightRolling:
    """Threshold of stable straight upright rolling.

    Attributes
    ----------
    wheel : Wheel; radius, tyre_radius : float — m, a and r; g : float — m/s^2
    critical_spin : float — rad/s, s_c = sqrt(m g (a - r) A / (C (C + m a^2))) (sphere: 0;
        band: the larger edge's, :func:`edge_critical_spin`)
    critical_speed : float — m/s, a s_c
    C_contact, A_contact : float — kg m^2, C + m a^2 and A + m a^2
    rim : str — ``"edge"``, ``"torus"``, ``"sphere"`` or ``"band"`` (a cylinder on its side)
    band : tuple of 2 floats or None — m, the band's edges from the plane of G
    static_lean_limit : float or None — rad, atan(min(c1, c2)/a): the band's weight holds it
    knife_edge_critical_spin : float or None — rad/s, for comparison (band only)"""

    wheel: Wheel
    radius: float
    tyre_radius: float
    g: float
    critical_spin: float
    critical_speed: float
    C_contact: float
    A_contact: float
    rim: str = "edge"
    band: tuple[float, float] | None = None
    static_lean_limit: float | None = None
    knife_edge_critical_spin: float | None = None

    def nu2(self, spin: Any) -> Any:
        """Squared lean-oscillation frequency (rad^2/s^2) at spin(s) s (rad/s).

        Edge, torus, sphere (sheet §3.2): nu^2 = [C (C + m a^2) s^2 - A m g (a - r)] /
        [A (A + m a^2)]. Band: the smaller of the two edges' (:func:`edge_nu2`): balanced
        on either edge the lean oscillates at least this fast, or grows.
        """
        s = np.asarray(spin, dtype=float)
        w = self.wheel
        if self.band is not None:
            out = np.minimum(*(edge_nu2(w, self.radius, c, self.g, s) for c in self.band))
        else:
            out = (w.C * self.C_contact * s * s - w.A * w.mass * self.g * (self.radius - self.tyre_radius)) / (
                w.A * self.A_contact)
        out = np.asarray(out, dtype=float)
        return float(out) if out.ndim == 0 else out

    def to_json(self) -> dict[str, Any]:
        """SPEC keys ``radius``, ``mass``, ``I``, ``Is``, ``critical_spin``,
        ``critical_speed`` plus ``tyre_radius``, ``g``, ``I_contact``, ``Is_contact``,
        ``model``, ``rim``; a band adds ``band_width``, ``band_edges`` (c1, c2),
        ``static_lean_limit_deg`` and ``knife_edge_critical_spin``,
        ``knife_edge_critical_speed``."""
        out = {
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
            "rim": self.rim,
        }
        if self.band is not None:
            assert self.static_lean_limit is not None and self.knife_edge_critical_spin is not None
            out.update({
                "band_width": float(self.band[0] + self.band[1]),
                "band_edges": [float(c) for c in self.band],
                "static_lean_limit_deg": math.degrees(self.static_lean_limit),
                "knife_edge_critical_spin": float(self.knife_edge_critical_spin),
                "knife_edge_critical_speed": float(self.radius * self.knife_edge_critical_spin),
            })
        return out


def straight(wheel: Wheel, a: float, r: float = 0.0, g: float = STANDARD_GRAVITY) -> StraightRolling:
    """Critical spin and speed for stable straight upright rolling on a round rim.

    ``wheel`` (A and C about G), rim radius ``a`` > 0, tube radius ``r`` (0 <= r <= a: 0 knife
    edge, a sphere), ``g`` (m/s^2): a :class:`StraightRolling`.

    Notes
    -----
    Sheet §3.2: lambda^2 [A (A + m a^2) lambda^2 + C (C + m a^2) s^2 - A m g (a - r)] = 0, so the
    lean stays bounded iff s^2 > s_c^2 = m g (a - r) A / [C (C + m a^2)]; v_c = a s_c (a rounded
    rim shortens the weight's lever to (a - r) sin(lean); tests/test_rollcheck_rims.py)."""
    a, r, g = check_geometry(a, r, g)
    m, A, C = wheel.mass, wheel.A, wheel.C
    Cc = C + m * a * a
    Ac = A + m * a * a
    sc = math.sqrt(m * g * (a - r) * A / (C * Cc))
    rim = "edge" if r == 0.0 else ("sphere" if r == a else "torus")
    return StraightRolling(wheel, a, r, g, sc, a * sc, Cc, Ac, rim=rim)


def _edge_terms(wheel: Wheel, a: float, c: float, g: float) -> tuple[float, float]:
    """(k2, k0) of nu^2 = k2 s^2 + k0 balanced on the edge at c (see :func:`edge_nu2`)."""
    m, A, C = wheel.mass, wheel.A, wheel.C
    l2 = a * a + c * c
    Cc = C + m * a * a
    delta = Cc * (A + m * c * c) - (m * a * c) ** 2
    k2 = C * Cc * (C + m * l2) / (delta * (A + m * l2))
    k0 = -m * g * math.sqrt(l2) / (A + m * l2)
    return k2, k0


def edge_nu2(wheel: Wheel, a: float, c: float, g: float, spin: Any) -> Any:
    """Squared lean frequency (rad^2/s^2) of straight rolling balanced on an edge circle of
    radius a, c (>= 0) along the axle from G, leaning atan(c/a) so that G is above the contact
    (l = sqrt(a^2 + c^2)). Linearising the vector equations of sheet §3.1 (contact-to-G
    a u - c n): nu^2 = k2 s^2 + k0, k2 = C (C + m a^2)(C + m l^2) / [Delta (A + m l^2)],
    k0 = -m g l / (A + m l^2), Delta = (C + m a^2)(A + m c^2) - m^2 a^2 c^2; c = 0 is §3.2's
    knife edge (tests/test_rollcheck_rims.py)."""
    k2, k0 = _edge_terms(wheel, a, c, g)
    s = np.asarray(spin, dtype=float)
    out = k2 * s * s + k0
    return float(out) if out.ndim == 0 else out


def edge_critical_spin(wheel: Wheel, a: float, c: float, g: float = STANDARD_GRAVITY) -> float:
    """rad/s: balanced on the edge at c, rolling is (neutrally) stable above
    s_e = sqrt(-k0/k2) = sqrt(m g l Delta / [C (C + m a^2)(C + m l^2)]) (:func:`edge_nu2`)."""
    k2, k0 = _edge_terms(wheel, a, c, g)
    return math.sqrt(-k0 / k2)


def band_rolling(wheel: Wheel, a: float, c1: float, c2: float, g: float = STANDARD_GRAVITY) -> StraightRolling:
    """Straight rolling on a flat band (a cylinder on its side, a thick coin, two wheels on
    an axle): ``a`` the band's radius, ``c1``, ``c2`` >= 0 its edges' distances from the plane of
    the com. A :class:`StraightRolling` with ``rim`` "band", critical above the larger edge's
    :func:`edge_critical_spin` (why: the man page of ``rbcli rollcheck``)."""
    a, _, g = check_geometry(a, 0.0, g)
    for name, c in (("c1", c1), ("c2", c2)):
        if not (math.isfinite(c) and c >= 0.0):
            raise ValueError(f"the band's edge distance {name} must be >= 0, got {c!r}")
    knife = straight(wheel, a, 0.0, g)
    se = max(edge_critical_spin(wheel, a, c1, g), edge_critical_spin(wheel, a, c2, g))
    return StraightRolling(wheel, a, 0.0, g, se, a * se, knife.C_contact, knife.A_contact,
                           rim="band", band=(float(c1), float(c2)),
                           static_lean_limit=math.atan2(min(c1, c2), a),
                           knife_edge_critical_spin=knife.critical_spin)


@dataclass(frozen=True)
class Verdict:
    """Straight rolling at a given speed.

    Attributes
    ----------
    speed, spin : float — m/s and rad/s (speed / a), as given (negative: backwards)
    stable : bool — |spin| > s_c (exactly at s_c the lean drifts: not stable)
    margin : float or None — |speed| / v_c; None for a sphere
    nu2 : float — rad^2/s^2, squared lean-oscillation frequency (sheet §3.2)
    lean_frequency, lean_frequency_hz — sqrt(nu2) (rad/s, Hz) when nu2 > 0, else None
    growth_rate : float or None — 1/s, sqrt(-nu2) when nu2 <= 0
    backwards : bool — the speed was negative (stability does not depend on it)"""

    speed: float
    spin: float
    stable: bool
    margin: float | None
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
            "margin": opt_float(self.margin),
            "lean_frequency": opt_float(self.lean_frequency),
            "lean_frequency_hz": opt_float(self.lean_frequency_hz),
            "growth_rate": opt_float(self.growth_rate),
            "lean_frequency_squared": float(self.nu2),
            "backwards": bool(self.backwards),
        }


def at_speed(
    straight: StraightRolling, v: float | None = None, spin: float | None = None
) -> Verdict:
    """Verdict on straight upright rolling at speed ``v`` (m/s) or ``spin`` (rad/s; v = a spin:
    one, or both when they agree to 1e-9; negative is backwards, |spin| is used): nu^2
    (:meth:`StraightRolling.nu2`) > 0 the lean oscillates at nu, < 0 it grows at sqrt(-nu^2)."""
    a = straight.radius
    if v is None and spin is None:
        raise ValueError("give a speed or a spin")
    if v is not None:
        v = param_finite("speed", "the speed", v)
    if spin is not None:
        spin = param_finite("spin", "the spin", spin)
    if v is not None and spin is not None:
        if abs(v - a * spin) > 1e-9 * max(abs(v), abs(a * spin)):
            raise blame(("speed", "spin"),
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
    sphere = straight.rim == "sphere"
    stable = nu2 > 0.0 or sphere  # a sphere at rest: nu^2 = 0, and nothing to fall
    freq = math.sqrt(max(nu2, 0.0)) if stable else None
    growth = None if stable else math.sqrt(-nu2)
    return Verdict(
        speed=v,
        spin=spin,
        stable=stable,
        margin=None if sphere else s / straight.critical_spin,
        nu2=nu2,
        lean_frequency=freq,
        lean_frequency_hz=None if freq is None else freq / (2.0 * math.pi),
        growth_rate=growth,
        backwards=(spin < 0.0),
    )


def nu2_curve(st: StraightRolling, speeds: Any) -> np.ndarray:
    """:meth:`StraightRolling.nu2` at the speeds (m/s, sign ignored): any rim, for plots."""
    v = np.asarray(speeds, dtype=float)
    return np.asarray(st.nu2(v / st.radius), dtype=float).reshape(v.shape)


# --- the whole check


@dataclass(frozen=True)
class RollCheck:
    """Everything ``rbcli rollcheck`` answers: ``straight`` (:class:`StraightRolling`),
    ``verdict`` (:class:`Verdict`, with a speed or spin) and ``circle`` (:class:`CircleMotion`,
    when asked for) or None."""

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
    band: tuple[float, float] | None = None,
) -> RollCheck:
    """Assemble a :class:`RollCheck`: :func:`straight` (or :func:`band_rolling` for a ``band``,
    r = 0); with a speed or spin :func:`at_speed`; with lean and circle :func:`circle`, circle
    and speed :func:`lean_for`, lean and speed :func:`radius_for`. A lean or circle alone, or
    a circle on a rounded rim or a band, is a ParamError naming the parameters given."""
    st = straight(wheel, a, r, g) if band is None else band_rolling(wheel, a, band[0], band[1], g)
    if band is not None and (lean_rad is not None or circle_radius is not None):
        raise blame(("lean",) if lean_rad is not None else ("circle",),
                    "steady circular rolling is computed for a knife-edge rim only: this rim is a "
                    f"flat band {fmt_length(band[0] + band[1])} wide")
    verdict = None
    if speed is not None or spin is not None:
        verdict = at_speed(st, v=speed, spin=spin)
    circ = None
    if lean_rad is not None or circle_radius is not None:
        if lean_rad is not None and circle_radius is not None:
            circ = circle(wheel, a, lean_rad, circle_radius, g, r=r)
        elif verdict is None:
            which = "lean" if lean_rad is not None else "circle radius"
            raise blame(
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


# --- figure data


@dataclass(frozen=True)
class Curves:
    """The arrays of the ``rollcheck`` figure (:func:`curves`): ``speeds`` (m/s, 0 to
    ``max(2.5 v_c, 1.25 |v|)``), ``nu2``, ``lean_frequency``, ``growth_rate`` at each,
    ``critical_speed``; with a circle ``circle_radii`` (m), ``circle_leans_deg`` (0.25 to 85),
    ``circle_kappa`` (N m) and ``circle_speed`` (m/s) on that grid."""

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
    """The figure's :class:`Curves` for a :class:`RollCheck` (circles: :func:`stability_map`,
    sheet §3.3)."""
    st = check.straight
    w = st.wheel
    vc = st.critical_speed
    vmax = 2.5 * vc if vc > 0.0 else 2.0 * math.sqrt(st.g * st.radius)  # a sphere: v_c = 0
    if check.verdict is not None:
        vmax = max(vmax, 1.25 * abs(check.verdict.speed))
    speeds = np.linspace(0.0, vmax, n_speeds)
    nu2 = nu2_curve(st, speeds)
    out = dict(speeds=speeds, nu2=nu2, lean_frequency=np.sqrt(np.clip(nu2, 0.0, None)),
               growth_rate=np.sqrt(np.clip(-nu2, 0.0, None)), critical_speed=vc)
    if check.circle is not None:
        a = st.radius
        rmax = max(10.0 * a, 2.0 * check.circle.radius)
        leans_deg = np.linspace(0.25, 85.0, n_leans)
        radii = np.linspace(0.0, rmax, n_radii)
        kappa = stability_map(w, a, st.g, np.radians(leans_deg), radii)
        W, _, _ = circle_arrays(w.mass, w.A, w.C, a, st.g, np.radians(leans_deg)[:, None],
                                 radii[None, :])
        out.update(circle_radii=radii, circle_leans_deg=leans_deg, circle_kappa=kappa,
                   circle_speed=W * radii[None, :])
    return Curves(**out)
