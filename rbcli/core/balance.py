"""Rigid-rotor balancing about a shaft: unbalance, corrections, bearing loads, ISO 21940-11.

Everything here follows the physics sheet ``physics/balance.md`` (cited as "sheet §n").

Frames and signs
----------------
The body is given by its mass properties in the BODY frame, SI: ``mass`` (kg), ``com``
(3,) m, ``inertia_com`` (3, 3) kg m^2 in the TENSOR convention (off-diagonals are
``-∫xy dm``, about the com).

A shaft is an axis direction (any non-zero length) through a point ``through``. Positions
along the shaft (correction planes, bearings) are signed distances ``z`` along the unit axis
measured from ``through``. The SHAFT FRAME (see :func:`shaft_frame`) has ``e_z`` along the
shaft, ``e_x`` the reference mark ("0 degrees") and ``e_y = e_z x e_x``. Angles are measured
about +e_z from +e_x towards +e_y, which is the direction of rotation for a positive speed
(SPEC §2, sheet §2.1). For the default shaft (body z through the origin) the shaft frame is
the body frame. ``angle_sense="against"`` reports every angle as ``360 - angle`` (shops that
count against rotation); all complex quantities stored in result objects stay in the
"with rotation" sense, only the ``*_deg`` numbers are flipped.

Complex notation in the plane at right angles to the shaft: ``w = x + i y`` (sheet §2.1).
The PRODUCT ``D_xz = +∫xz dm`` is the negative of the TENSOR element ``J_xz``; the two are
kept apart by name (sheet §2.1, §7.1):

* static unbalance      ``U = M (x_G + i y_G)``                                  kg m
* moment unbalance      ``P = M z_G (x_G + i y_G) + (D_xz,G + i D_yz,G)``        kg m^2, about z = 0
* couple unbalance      ``P_G = P - z_G U = D_xz,G + i D_yz,G = -(J_xz,G + i J_yz,G)``
  (about the com)

A correction ``C`` is the unbalance (kg m) to ADD in a plane: a mass ``|C|/r`` at angle
``arg C`` (remove the same mass at ``arg C + 180 deg``).
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from rbcli.core.principal import DEGENERATE_RTOL

STANDARD_GRAVITY = 9.80665
"""m/s^2, the default g (SPEC §2)."""

BALANCE_RTOL = 1e-9
"""Relative tolerance of the ideal (geometric) balanced verdicts; see :func:`unbalance`."""

TILT_GAP_RTOL = 1e-6
"""Principal moments closer than this (relative to the largest) make the tilt ill-defined."""

FRAME_SWITCH_COS = 0.9
"""Body x is the reference mark unless |cos(shaft, body x)| exceeds this; then body y."""

NARROW_PLANE_FRACTION = 0.2
"""Correction planes closer than this fraction of the reference length are 'narrow' (sheet §7.9)."""

LARGE_CORRECTION_FRACTION = 0.1
"""Warn when the two-plane correction masses add up to more than this fraction of the rotor mass."""

ISO_GRADE_MIN = 0.4
ISO_GRADE_MAX = 4000.0
"""mm/s, the range of ISO 21940-11 balance quality grades (sheet §1.3)."""

ISO_CLAMP = (0.3, 0.7)
"""Inboard allocation limits, fractions of U_per (sheet §1.4a)."""

ISO_OUTBOARD_FLOOR = 0.3
"""Floor of the far share for outboard rotors, fraction of U_per (sheet §1.4c; rbcli's rule)."""

FIELD_COND_WARN = 50.0
"""Warn when the 2-norm condition number of the influence matrix exceeds this (sheet §7.10)."""

SMALL_RESPONSE_AMPLITUDE = 0.25
SMALL_RESPONSE_PHASE_DEG = 25.0
"""A trial run is 'small' unless the amplitude changed by >= 25 % or the phase by >= 25 deg."""

ANGLE_SENSES = ("with", "against")


# ----------------------------------------------------------------------------------------
# small helpers
# ----------------------------------------------------------------------------------------


def _vec3(v: object, name: str) -> np.ndarray:
    a = np.asarray(v, dtype=float)
    if a.shape != (3,):
        raise ValueError(f"{name} must be a 3-vector, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{name} must be finite")
    return a


def _finite(x: object, name: str) -> float:
    try:
        v = float(x)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number") from None
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite")
    return v


def _positive(x: object, name: str) -> float:
    v = _finite(x, name)
    if v <= 0.0:
        raise ValueError(f"{name} must be positive, got {v:g}")
    return v


def _pair(v: object, name: str) -> tuple[float, float]:
    if np.ndim(v) == 0:  # type: ignore[arg-type]
        raise ValueError(f"{name} must be two numbers")
    seq = list(v)  # type: ignore[call-overload]
    if len(seq) != 2:
        raise ValueError(f"{name} must be two numbers, got {len(seq)}")
    return _finite(seq[0], name), _finite(seq[1], name)


def _check_sense(angle_sense: str) -> str:
    if angle_sense not in ANGLE_SENSES:
        raise ValueError(f"angle_sense must be 'with' or 'against', got {angle_sense!r}")
    return angle_sense


def _wrap_deg(a: float) -> float:
    """Angle in [0, 360); within 1e-9 deg below 360 counts as 0."""
    a = math.fmod(a, 360.0)
    if a < 0.0:
        a += 360.0
    if a >= 360.0 - 1e-9:  # -1e-17 + 360 rounds to 360; 359.9999999999999 would print as 360
        a = 0.0
    return a + 0.0  # no -0.0


def _report_deg(phi_deg: float, sense: str) -> float:
    """Internal ('with' rotation) angle -> reported angle in [0, 360)."""
    return _wrap_deg(-phi_deg if sense == "against" else phi_deg)


def _internal_deg(reported_deg: float, sense: str) -> float:
    """Reported angle -> internal ('with' rotation) angle in [0, 360)."""
    return _report_deg(reported_deg, sense)  # the map is its own inverse


def _angle(z: complex, tol: float, sense: str = "with") -> tuple[float, bool]:
    """Reported angle (deg, [0, 360)) of a complex number and whether it is defined.

    ``|z| <= tol`` -> ``(0.0, False)``: the angle of a zero (to tolerance) quantity is
    undefined and reported as 0.0 with a false flag (never NaN).
    """
    if not abs(z) > tol:
        return 0.0, False
    return _report_deg(math.degrees(cmath.phase(z)), sense), True


def _phasor_json(z: complex, tol: float = 0.0, sense: str = "with") -> dict:
    a, ok = _angle(z, tol, sense)
    return {"magnitude": float(abs(z)), "angle_deg": a, "angle_defined": ok}


def _f(x: float) -> float | None:
    """Plain finite float, or None."""
    x = float(x)
    return x if math.isfinite(x) else None


def _readonly(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


def phasor(amplitude: float, phase_deg: float) -> complex:
    """Complex number ``amplitude * exp(i * phase)``.

    Parameters
    ----------
    amplitude : float — any unit (g, µm, mm/s, ...)
    phase_deg : float — degrees

    Returns
    -------
    complex
    """
    return complex(cmath.rect(float(amplitude), math.radians(float(phase_deg))))


# ----------------------------------------------------------------------------------------
# the shaft frame
# ----------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class ShaftFrame:
    """A shaft and its rotor-fixed frame.

    Attributes
    ----------
    rotation : (3, 3) ndarray — rows are e_x, e_y, e_z in body components; a proper rotation.
        Shaft coordinates of a body point r are ``s = rotation @ (r - origin)``.
    origin : (3,) ndarray — m, the point ``through`` (z = 0 on the shaft), body frame
    """

    rotation: np.ndarray
    origin: np.ndarray

    @property
    def axis(self) -> np.ndarray:
        """(3,) unit shaft direction e_z, body frame."""
        return self.rotation[2]

    def to_shaft(self, points: object) -> np.ndarray:
        """Body-frame point(s) (..., 3) -> shaft-frame coordinates (..., 3), m."""
        p = np.asarray(points, dtype=float)
        return (p - self.origin) @ self.rotation.T

    def to_body(self, points: object) -> np.ndarray:
        """Shaft-frame coordinates (..., 3) -> body-frame point(s) (..., 3), m."""
        s = np.asarray(points, dtype=float)
        return s @ self.rotation + self.origin

    def to_json(self) -> dict:
        return {
            "axis": [float(v) for v in self.rotation[2]],
            "through": [float(v) for v in self.origin],
            "x_axis": [float(v) for v in self.rotation[0]],
            "y_axis": [float(v) for v in self.rotation[1]],
        }


def shaft_frame(
    axis: object = (0.0, 0.0, 1.0),
    through: object = (0.0, 0.0, 0.0),
    *,
    reference: object | None = None,
    zero_mark_deg: float = 0.0,
) -> ShaftFrame:
    """The rotor-fixed shaft frame (e_x, e_y, e_z) of a shaft.

    Parameters
    ----------
    axis : (3,) array_like — shaft direction, body frame, any non-zero length
    through : (3,) array_like — m, a point of the shaft, body frame; z = 0 there
    reference : (3,) array_like, optional — direction of the reference mark (body frame);
        only its part at right angles to the shaft is used. Default: the rule below.
    zero_mark_deg : float — deg; the reference mark is turned this far about +e_z from
        the direction the rule (or ``reference``) gives

    Returns
    -------
    ShaftFrame

    Raises
    ------
    ValueError
        zero or non-finite axis; ``reference`` parallel to the shaft.

    Notes
    -----
    Rule (deterministic, continuous near every body axis):
    ``e_z = axis/|axis|``; ``e_x`` = body x projected at right angles to e_z and
    normalised, unless ``|e_z . x| > 0.9`` (the shaft within 25.8 deg of body x), when body
    y projected is used instead; ``e_y = e_z x e_x``. The projection used always has length
    >= 0.436, so e_x is well conditioned, and the switch lies away from the body axes and
    the 45-degree diagonals. Consequences: shaft along +z -> the body frame exactly;
    shaft along x -> e_x = body y, e_y = body z; shaft along y -> e_x = body x,
    e_y = -body z. Sheet §2.1 asks for the mark to be explicit for a general shaft: pass
    ``reference`` to fix it.
    """
    a = _vec3(axis, "shaft axis")
    n = float(np.linalg.norm(a))
    if not n > 0.0:
        raise ValueError("shaft axis must be a non-zero vector")
    o = _vec3(through, "shaft point (through)")
    ez = a / n
    if reference is not None:
        ref = _vec3(reference, "reference mark direction")
        p = ref - float(ref @ ez) * ez
        pn = float(np.linalg.norm(p))
        if not pn > 1e-6 * float(np.linalg.norm(ref)):
            raise ValueError("reference mark direction must not be parallel to the shaft")
    else:
        base = np.array([1.0, 0.0, 0.0])
        if abs(ez[0]) > FRAME_SWITCH_COS:
            base = np.array([0.0, 1.0, 0.0])
        p = base - float(base @ ez) * ez
        pn = float(np.linalg.norm(p))
    ex = p / pn
    ey = np.cross(ez, ex)
    th = math.radians(_finite(zero_mark_deg, "zero_mark_deg"))
    if th != 0.0:
        c, s = math.cos(th), math.sin(th)
        ex, ey = c * ex + s * ey, -s * ex + c * ey
    return ShaftFrame(_readonly(np.vstack([ex, ey, ez])), _readonly(o))


# ----------------------------------------------------------------------------------------
# unbalance of a rotor
# ----------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class Unbalance:
    """Unbalance of a rigid rotor about a shaft (sheet §2.3, §2.4).

    Attributes
    ----------
    mass : float — kg
    com : (3,) ndarray — m, body frame (input, kept so corrections can be applied)
    inertia_com : (3, 3) ndarray — kg m^2, tensor about the com, body frame (input)
    frame : ShaftFrame
    angle_sense : str — "with" or "against" (how ``*_deg`` angles are reported)
    com_shaft : (3,) ndarray — m, (x_G, y_G, z_G) of the com in the shaft frame
    inertia_shaft : (3, 3) ndarray — kg m^2, tensor about the com in shaft axes
    static : complex — kg m, U = M (x_G + i y_G)
    moment : complex — kg m^2, P about z = 0
    couple : complex — kg m^2, P_G = P - z_G U, about the com
    eccentricity : float — m, distance of the com from the shaft, |U|/M
    tilt_deg : float — deg, angle between the shaft and the nearest principal axis (about the com)
    tilt_azimuth_deg : float — deg, direction (shaft frame, reported sense) the +z end of
        that principal axis leans toward; 0.0 when undefined
    tilt_azimuth_defined : bool
    tilt_well_defined : bool — False when the rotor is (nearly) isotropic about the com:
        the moment of the nearest principal axis is within TILT_GAP_RTOL of another, its
        principal axes are ill-defined and tilt_deg says nothing useful
    principal_gap : float — kg m^2, distance of the nearest axis's principal moment from
        the other principal moments (0.0 when all are equal)
    length_scale : float — m, max(sqrt(trace J_G / M), |com - through|)
    tol_eccentricity : float — m, BALANCE_RTOL * length_scale (rtol as given)
    tol_couple : float — kg m^2, rtol * trace(J_G)
    statically_balanced : bool — eccentricity <= tol_eccentricity
    dynamically_balanced : bool — statically balanced and |P_G| <= tol_couple
    rtol : float
    warnings : tuple[str, ...]
    """

    mass: float
    com: np.ndarray
    inertia_com: np.ndarray
    frame: ShaftFrame
    angle_sense: str
    com_shaft: np.ndarray
    inertia_shaft: np.ndarray
    static: complex
    moment: complex
    couple: complex
    eccentricity: float
    tilt_deg: float
    tilt_azimuth_deg: float
    tilt_azimuth_defined: bool
    tilt_well_defined: bool
    principal_gap: float
    length_scale: float
    tol_eccentricity: float
    tol_couple: float
    statically_balanced: bool
    dynamically_balanced: bool
    rtol: float
    warnings: tuple[str, ...]

    # --- tolerances on derived quantities (used to decide whether an angle is defined) ---
    @property
    def tol_static(self) -> float:
        """kg m — tolerance on |U| (mass * tol_eccentricity)."""
        return self.mass * self.tol_eccentricity

    @property
    def tol_moment(self) -> float:
        """kg m^2 — tolerance on |P| about z = 0."""
        return self.tol_couple + abs(float(self.com_shaft[2])) * self.tol_static

    def plane_tolerance(self, z1: float, z2: float) -> float:
        """kg m — tolerance on an equivalent unbalance in planes z1, z2 (sheet §2.5 form)."""
        d = abs(z2 - z1)
        if d == 0.0:
            return math.inf
        return (self.tol_moment + max(abs(z1), abs(z2)) * self.tol_static) / d

    # --- derived numbers ---
    @property
    def static_unbalance(self) -> float:
        """kg m, |U|."""
        return abs(self.static)

    @property
    def couple_unbalance(self) -> float:
        """kg m^2, |P_G| (about the com)."""
        return abs(self.couple)

    @property
    def moment_unbalance(self) -> float:
        """kg m^2, |P| about z = 0."""
        return abs(self.moment)

    def angle_of(self, z: complex, tol: float) -> tuple[float, bool]:
        """Reported angle (deg) of a complex quantity in this rotor's frame, and whether defined."""
        return _angle(z, tol, self.angle_sense)

    @property
    def static_angle_deg(self) -> float:
        return self.angle_of(self.static, self.tol_static)[0]

    @property
    def static_angle_defined(self) -> bool:
        return self.angle_of(self.static, self.tol_static)[1]

    @property
    def couple_angle_deg(self) -> float:
        return self.angle_of(self.couple, self.tol_couple)[0]

    @property
    def couple_angle_defined(self) -> bool:
        return self.angle_of(self.couple, self.tol_couple)[1]

    @property
    def axial_length(self) -> float:
        """m — length of the uniform rod with the rotor's axial second moment about the com.

        ``L_eq = sqrt(12 ∫(z - z_G)^2 dm / M) = sqrt(6 (J_xx + J_yy - J_zz) / M)`` (shaft axes).
        """
        J = self.inertia_shaft
        s = max(float(J[0, 0] + J[1, 1] - J[2, 2]), 0.0)
        return math.sqrt(6.0 * s / self.mass)

    def moment_about(self, z0: float) -> complex:
        """kg m^2 — moment unbalance about z = z0: ``P(z0) = P - z0 U`` (sheet §7.2)."""
        return self.moment - float(z0) * self.static

    def to_json(self) -> dict:
        sa, sok = self.angle_of(self.static, self.tol_static)
        ca, cok = self.angle_of(self.couple, self.tol_couple)
        ma, mok = self.angle_of(self.moment, self.tol_moment)
        return {
            "mass": float(self.mass),
            "eccentricity": float(self.eccentricity),
            "static_unbalance": float(abs(self.static)),
            "static_unbalance_angle_deg": sa,
            "static_unbalance_angle_defined": sok,
            "couple_unbalance": float(abs(self.couple)),
            "couple_unbalance_angle_deg": ca,
            "couple_unbalance_angle_defined": cok,
            "moment_unbalance": float(abs(self.moment)),
            "moment_unbalance_angle_deg": ma,
            "moment_unbalance_angle_defined": mok,
            "tilt_deg": float(self.tilt_deg),
            "tilt_azimuth_deg": float(self.tilt_azimuth_deg),
            "tilt_azimuth_defined": bool(self.tilt_azimuth_defined),
            "tilt_well_defined": bool(self.tilt_well_defined),
            "principal_gap": float(self.principal_gap),
            "statically_balanced": bool(self.statically_balanced),
            "dynamically_balanced": bool(self.dynamically_balanced),
            "tolerances": {
                "eccentricity": float(self.tol_eccentricity),
                "couple_unbalance": float(self.tol_couple),
                "rtol": float(self.rtol),
                "rule": (
                    "statically balanced: eccentricity <= rtol * max(sqrt(trace(J_G)/M), "
                    "|com - through|); dynamically balanced: also couple <= rtol * trace(J_G)"
                ),
            },
            "com_shaft": [float(v) for v in self.com_shaft],
            "shaft": self.frame.to_json(),
            "angle_sense": self.angle_sense,
            "warnings": list(self.warnings),
        }


def _tilt(J_body: np.ndarray, frame: ShaftFrame) -> tuple[float, complex, float, float]:
    """Tilt (rad) of the nearest principal axis, its shaft-frame lean (complex), gap, max |moment|.

    The eigenspace (a line, a plane or all of space when moments coincide to
    DEGENERATE_RTOL, as in :func:`rbcli.core.principal.principal_axes`) with the largest
    projection of e_z is the nearest principal direction; v is the projection of e_z onto it
    (so v . e_z >= 0). tilt = atan2(|v_perp|, v_z) is exact and accurate for small angles.
    numpy's eigh basis is used directly: principal_axes snaps an axis within 1e-12 of a body
    axis in |cos| (1.4e-6 rad) onto it, which would hide small tilts.
    """
    w, V = np.linalg.eigh(0.5 * (J_body + J_body.T))
    axes = V.T  # rows: unit eigenvectors, moments ascending
    scale = max(float(np.max(np.abs(w))), np.finfo(float).tiny)

    def close(i: int, j: int) -> bool:
        return abs(float(w[i]) - float(w[j])) <= DEGENERATE_RTOL * scale

    if close(0, 1) and close(1, 2):
        groups: list[tuple[int, ...]] = [(0, 1, 2)]
    elif close(0, 1):
        groups = [(0, 1), (2,)]
    elif close(1, 2):
        groups = [(0,), (1, 2)]
    else:
        groups = [(0,), (1,), (2,)]
    ez = frame.rotation[2]
    best, best_w, best_v = groups[0], -1.0, ez
    for g in groups:
        comps = axes[list(g)] @ ez
        wt = float(comps @ comps)
        if wt > best_w:
            best, best_w = g, wt
            best_v = ez if len(g) == 3 else comps @ axes[list(g)]
    vs = frame.rotation @ best_v
    tilt = math.atan2(math.hypot(vs[0], vs[1]), vs[2])
    lam = float(np.mean(w[list(best)]))
    others = [abs(lam - float(w[k])) for k in range(3) if k not in best]
    gap = min(others) if others else 0.0
    return tilt, complex(vs[0], vs[1]), gap, float(np.max(np.abs(w)))


def unbalance(
    mass: float,
    com: object,
    inertia_com: object,
    axis: object = (0.0, 0.0, 1.0),
    through: object = (0.0, 0.0, 0.0),
    *,
    reference: object | None = None,
    zero_mark_deg: float = 0.0,
    angle_sense: str = "with",
    rtol: float = BALANCE_RTOL,
) -> Unbalance:
    """Static, moment and couple unbalance of a rigid rotor about a shaft.

    Parameters
    ----------
    mass : float — kg, > 0
    com : (3,) array_like — m, centre of mass, body frame
    inertia_com : (3, 3) array_like — kg m^2, inertia TENSOR about the com, body frame
        (off-diagonals -∫xy dm)
    axis : (3,) array_like — shaft direction, body frame (default body z)
    through : (3,) array_like — m, a point of the shaft, body frame (default origin); z = 0
    reference, zero_mark_deg : see :func:`shaft_frame`
    angle_sense : {"with", "against"} — report angles with or against rotation
    rtol : float — relative tolerance of the ideal balanced verdicts (default 1e-9)

    Returns
    -------
    Unbalance

    Raises
    ------
    ValueError
        non-positive or non-finite mass, bad shapes, zero axis, bad angle_sense.

    Notes
    -----
    Sheet §2.3 with the parallel-axis theorem: in shaft axes, with (x_G, y_G, z_G) the com
    and J the tensor about the com, ``D_xz,G = -J[0, 2]``, ``D_yz,G = -J[1, 2]``,

    ``U = M (x_G + i y_G)``, ``P_G = D_xz,G + i D_yz,G``, ``P = P_G + z_G U`` (about z = 0).

    Tilt (sheet §2.4): eigenvectors of J_G; the one with the largest |e_z| component
    (a degenerate eigenspace is handled as a whole: the tilt is the angle from the shaft to
    the eigenspace). ``tilt = atan2(|e_perp|, e_z)``; its azimuth is arg(e_x + i e_y) with e
    oriented so that e_z > 0.

    Verdicts (one rule, here): with ``l = max(sqrt(trace J_G / M), |com - through|)`` —
    a size of the rotor that also bounds the round-off of the shaft-frame coordinates —
    statically balanced iff ``e <= rtol * l``; dynamically balanced iff also
    ``|P_G| <= rtol * trace(J_G)`` (= rtol M l_g^2). These are ideal (geometric) verdicts:
    "balanced to the accuracy of the arithmetic and the input". Tolerances for real
    rotors come from an ISO grade (:func:`iso_check`).
    """
    M = _positive(mass, "mass")
    c = _vec3(com, "com")
    J = np.asarray(inertia_com, dtype=float)
    if J.shape != (3, 3):
        raise ValueError(f"inertia_com must be 3x3, got shape {J.shape}")
    if not np.all(np.isfinite(J)):
        raise ValueError("inertia_com must be finite")
    J = 0.5 * (J + J.T)
    sense = _check_sense(angle_sense)
    rtol = _finite(rtol, "rtol")
    if rtol < 0.0:
        raise ValueError("rtol must not be negative")
    frame = shaft_frame(axis, through, reference=reference, zero_mark_deg=zero_mark_deg)
    R = frame.rotation
    d = c - frame.origin
    s = R @ d
    Js = R @ J @ R.T
    Js = 0.5 * (Js + Js.T)
    xg, yg, zg = (float(v) for v in s)
    U = complex(M * xg, M * yg)
    PG = complex(-Js[0, 2], -Js[1, 2])  # D = -J (sheet §2.1)
    P = zg * U + PG
    ecc = math.hypot(xg, yg)
    tr = max(float(np.trace(J)), 0.0)
    lg = math.sqrt(tr / M)
    length = max(lg, float(np.linalg.norm(d)))
    tol_e = rtol * length
    tol_c = rtol * tr
    stat = ecc <= tol_e
    dyn = stat and abs(PG) <= tol_c

    tilt, lean, gap, lam_max = _tilt(J, frame)
    well = gap > TILT_GAP_RTOL * lam_max
    az_ok = abs(PG) > tol_c and tilt > 0.0
    az = _report_deg(math.degrees(cmath.phase(lean)), sense) if az_ok else 0.0
    warns: list[str] = []
    if not well:
        warns.append(
            "the rotor is (nearly) isotropic about its com: the principal moment of the axis "
            "nearest the shaft is within 1e-6 of another, so its principal axes are ill-defined "
            "and tilt_deg is not meaningful; judge dynamic balance by couple_unbalance"
        )
    return Unbalance(
        mass=M,
        com=_readonly(c),
        inertia_com=_readonly(J),
        frame=frame,
        angle_sense=sense,
        com_shaft=_readonly(s),
        inertia_shaft=_readonly(Js),
        static=U,
        moment=P,
        couple=PG,
        eccentricity=ecc,
        tilt_deg=math.degrees(tilt),
        tilt_azimuth_deg=az,
        tilt_azimuth_defined=az_ok,
        tilt_well_defined=well,
        principal_gap=gap,
        length_scale=length,
        tol_eccentricity=tol_e,
        tol_couple=tol_c,
        statically_balanced=stat,
        dynamically_balanced=dyn,
        rtol=rtol,
        warnings=tuple(warns),
    )


def plane_unbalances(
    static: complex, moment: complex, z1: float, z2: float
) -> tuple[complex, complex]:
    """Equivalent unbalances in two planes (what a balancing machine shows), kg m.

    Parameters
    ----------
    static : complex — kg m, U
    moment : complex — kg m^2, P about z = 0
    z1, z2 : float — m, plane positions, z1 != z2

    Returns
    -------
    (U_1, U_2) : complex — kg m, with U_1 + U_2 = U and z1 U_1 + z2 U_2 = P

    Notes
    -----
    Sheet §2.5: ``U_1 = (z2 U - P)/(z2 - z1)``, ``U_2 = (P - z1 U)/(z2 - z1)``. The same
    numbers are the bearing forces divided by Omega^2 (sheet §2.6) and the ISO tolerance
    quantity (sheet §1.5).
    """
    z1 = _finite(z1, "plane position")
    z2 = _finite(z2, "plane position")
    if z1 == z2:
        raise ValueError("the two planes must be at different positions along the shaft")
    d = z2 - z1
    return (z2 * static - moment) / d, (moment - z1 * static) / d


# ----------------------------------------------------------------------------------------
# corrections
# ----------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class PlaneCorrection:
    """One correction mass to ADD (remove it at ``remove_angle_deg``).

    Attributes
    ----------
    name : str — "A", "B" or "static"
    z : float | None — m, plane position along the shaft (None for the static correction,
        which may go in any plane)
    radius : float — m
    unbalance : complex — kg m, the correction C (shaft frame, 'with rotation' sense)
    mass : float — kg, |C| / radius
    angle_deg : float — deg, reported sense, [0, 360); 0.0 when undefined
    angle_defined : bool — False when the correction is zero (to tolerance)
    remove_angle_deg : float — deg, angle_deg + 180 (mod 360)
    """

    name: str
    z: float | None
    radius: float
    unbalance: complex
    mass: float
    angle_deg: float
    angle_defined: bool
    remove_angle_deg: float

    def to_json(self) -> dict:
        return {
            "plane": None if self.z is None else float(self.z),
            "name": self.name,
            "mass": float(self.mass),
            "radius": float(self.radius),
            "angle_deg": float(self.angle_deg),
            "angle_defined": bool(self.angle_defined),
            "remove_angle_deg": float(self.remove_angle_deg),
            "unbalance": float(abs(self.unbalance)),
        }


def _plane_correction(
    name: str, z: float | None, radius: float, C: complex, tol: float, sense: str
) -> PlaneCorrection:
    a, ok = _angle(C, tol, sense)
    return PlaneCorrection(
        name=name,
        z=z,
        radius=radius,
        unbalance=C,
        mass=abs(C) / radius,
        angle_deg=a,
        angle_defined=ok,
        remove_angle_deg=_wrap_deg(a + 180.0) if ok else 0.0,
    )


@dataclass(frozen=True, eq=False)
class Residual:
    """Unbalance of the rotor with corrections added (sheet §1.5 step 4).

    Attributes
    ----------
    mass : float — kg, rotor plus correction masses
    static : complex — kg m, U + sum C
    moment : complex — kg m^2, P + sum z C, about z = 0
    couple : complex — kg m^2, about the com of the corrected rotor
    planes : (float, float) — m, the correction planes
    plane_unbalances : (complex, complex) — kg m, equivalent residual unbalances in the
        correction planes (sheet §2.5)
    eccentricity : float — m, |static| / mass
    tol_static, tol_couple, tol_plane : float — tolerances used for the angle flags
    angle_sense : str
    """

    mass: float
    static: complex
    moment: complex
    couple: complex
    planes: tuple[float, float]
    plane_unbalances: tuple[complex, complex]
    eccentricity: float
    tol_static: float
    tol_couple: float
    tol_plane: float
    angle_sense: str

    def to_json(self) -> dict:
        s = self.angle_sense
        st = _phasor_json(self.static, self.tol_static, s)
        cp = _phasor_json(self.couple, self.tol_couple, s)
        planes = []
        for z, u in zip(self.planes, self.plane_unbalances):
            pj = _phasor_json(u, self.tol_plane, s)
            planes.append(
                {
                    "plane": float(z),
                    "unbalance": pj["magnitude"],
                    "angle_deg": pj["angle_deg"],
                    "angle_defined": pj["angle_defined"],
                }
            )
        return {
            "mass": float(self.mass),
            "eccentricity": float(self.eccentricity),
            "static_unbalance": st["magnitude"],
            "static_unbalance_angle_deg": st["angle_deg"],
            "static_unbalance_angle_defined": st["angle_defined"],
            "couple_unbalance": cp["magnitude"],
            "couple_unbalance_angle_deg": cp["angle_deg"],
            "couple_unbalance_angle_defined": cp["angle_defined"],
            "planes": planes,
        }


@dataclass(frozen=True, eq=False)
class Corrections:
    """Two-plane correction of a rotor (sheet §2.5), possibly rounded.

    Attributes
    ----------
    source : Unbalance — the rotor corrected
    planes : (float, float) — m, z_A, z_B
    radii : (float, float) — m, r_A, r_B
    a, b : PlaneCorrection — masses to add in planes A and B
    static : PlaneCorrection — single-plane (static) correction C = -U at radius r_A; it
        leaves the moment P + z C uncorrected
    narrow_planes : bool — |z_B - z_A| < NARROW_PLANE_FRACTION * narrow_reference
    narrow_ratio : float | None — |z_B - z_A| / narrow_reference (None if the reference is 0)
    narrow_reference : float — m, the bearing span if bearings were given, else the rotor's
        equivalent axial length (Unbalance.axial_length)
    narrow_reference_kind : str — "bearing span" or "rotor axial length"
    bearings : (float, float) | None — m, the bearings given for the narrow-plane rule
    residual : Residual — the rotor with a and b added (zero to round-off unless rounded)
    rounded : bool
    mass_step : float | None — kg
    angle_step_deg : float | None — deg
    ideal : Corrections | None — the unrounded corrections (when rounded)
    warnings : tuple[str, ...]
    """

    source: Unbalance
    planes: tuple[float, float]
    radii: tuple[float, float]
    a: PlaneCorrection
    b: PlaneCorrection
    static: PlaneCorrection
    narrow_planes: bool
    narrow_ratio: float | None
    narrow_reference: float
    narrow_reference_kind: str
    bearings: tuple[float, float] | None
    residual: Residual
    rounded: bool
    mass_step: float | None
    angle_step_deg: float | None
    ideal: Corrections | None
    warnings: tuple[str, ...]

    @property
    def pair(self) -> tuple[PlaneCorrection, PlaneCorrection]:
        return (self.a, self.b)

    def to_json(self) -> dict:
        return {
            "corrections": [self.a.to_json(), self.b.to_json()],
            "static_correction": self.static.to_json(),
            "narrow_planes": bool(self.narrow_planes),
            "narrow_ratio": None if self.narrow_ratio is None else _f(self.narrow_ratio),
            "narrow_reference": float(self.narrow_reference),
            "narrow_reference_kind": self.narrow_reference_kind,
            "residual": self.residual.to_json(),
            "rounded": bool(self.rounded),
            "mass_step": None if self.mass_step is None else float(self.mass_step),
            "angle_step_deg": None if self.angle_step_deg is None else float(self.angle_step_deg),
            "ideal": (
                None if self.ideal is None else [self.ideal.a.to_json(), self.ideal.b.to_json()]
            ),
            "angle_sense": self.source.angle_sense,
            "warnings": list(self.warnings),
        }


def _residual(
    unb: Unbalance,
    planes: tuple[float, float],
    a: PlaneCorrection,
    b: PlaneCorrection,
    added: tuple[float, float] | None = None,
) -> Residual:
    """Residual of the rotor with corrections a, b added; ``added`` = the masses actually
    added in each plane (kg) when they differ from |C|/r (masses split onto positions)."""
    zA, zB = planes
    mA, mB = (a.mass, b.mass) if added is None else added
    Ures = unb.static + a.unbalance + b.unbalance
    Pres = unb.moment + zA * a.unbalance + zB * b.unbalance
    Mn = unb.mass + mA + mB
    zg = (unb.mass * float(unb.com_shaft[2]) + mA * zA + mB * zB) / Mn
    PGres = Pres - zg * Ures
    ua, ub = plane_unbalances(Ures, Pres, zA, zB)
    return Residual(
        mass=Mn,
        static=Ures,
        moment=Pres,
        couple=PGres,
        planes=(zA, zB),
        plane_unbalances=(ua, ub),
        eccentricity=abs(Ures) / Mn,
        tol_static=unb.tol_static,
        tol_couple=unb.tol_couple + abs(zg) * unb.tol_static,
        tol_plane=unb.plane_tolerance(zA, zB),
        angle_sense=unb.angle_sense,
    )


def _narrow(
    unb: Unbalance, planes: tuple[float, float], bearings: object | None
) -> tuple[bool, float | None, float, str]:
    dz = abs(planes[1] - planes[0])
    if bearings is not None:
        b1, b2 = _pair(bearings, "bearings")
        ref, kind = abs(b2 - b1), "bearing span"
    else:
        ref, kind = unb.axial_length, "rotor axial length"
    if not ref > 0.0:
        return False, None, ref, kind
    return dz < NARROW_PLANE_FRACTION * ref, dz / ref, ref, kind


def _finish(
    unb: Unbalance,
    planes: tuple[float, float],
    radii: tuple[float, float],
    a: PlaneCorrection,
    b: PlaneCorrection,
    static: PlaneCorrection,
    bearings: object | None,
    rounded: bool,
    mass_step: float | None,
    angle_step_deg: float | None,
    ideal: Corrections | None,
    added: tuple[float, float] | None = None,
) -> Corrections:
    bz = None if bearings is None else _pair(bearings, "bearings")
    narrow, ratio, ref, kind = _narrow(unb, planes, bz)
    warns: list[str] = []
    if narrow:
        warns.append(
            f"correction planes are close together ({abs(planes[1] - planes[0]):.4g} m, "
            f"less than {NARROW_PLANE_FRACTION:g} of the {kind} {ref:.4g} m): the couple needs "
            "large masses and angle errors are amplified"
        )
    if (sum(added) if added is not None else a.mass + b.mass) > LARGE_CORRECTION_FRACTION * unb.mass:
        warns.append(
            "the correction masses add up to more than "
            f"{LARGE_CORRECTION_FRACTION:.0%} of the rotor mass: use larger radii or planes "
            "further apart"
        )
    return Corrections(
        source=unb,
        planes=planes,
        radii=radii,
        a=a,
        b=b,
        static=static,
        narrow_planes=narrow,
        narrow_ratio=ratio,
        narrow_reference=ref,
        narrow_reference_kind=kind,
        bearings=bz,
        residual=_residual(unb, planes, a, b, added),
        rounded=rounded,
        mass_step=mass_step,
        angle_step_deg=angle_step_deg,
        ideal=ideal,
        warnings=tuple(warns),
    )


def corrections(
    unb: Unbalance,
    planes: object,
    radii: object,
    *,
    bearings: object | None = None,
) -> Corrections:
    """Two-plane correction masses and angles to ADD, and the single-plane static correction.

    Parameters
    ----------
    unb : Unbalance
    planes : (z_A, z_B) — m, correction planes along the shaft, z_A != z_B
    radii : float or (r_A, r_B) — m, > 0, radius at which each mass is fixed
    bearings : (z_1, z_2), optional — m; only used for the narrow-plane rule

    Returns
    -------
    Corrections

    Raises
    ------
    ValueError
        z_A == z_B; a radius <= 0; non-finite numbers.

    Notes
    -----
    Sheet §2.5: cancel force and moment, ``U + C_A + C_B = 0``, ``P + z_A C_A + z_B C_B = 0``:

    ``C_A = (P - z_B U)/(z_B - z_A)``, ``C_B = (z_A U - P)/(z_B - z_A)``,
    ``m = |C|/r`` at ``arg C`` (remove at +180 deg). Static correction ``C = -U`` at r_A.

    Narrow planes (sheet §7.9): warned when ``|z_B - z_A| < 0.2 L`` with L the bearing span
    when bearings are given, else the rotor's equivalent axial length
    ``sqrt(6 (J_xx + J_yy - J_zz)/M)`` (never narrow for a rotor of zero axial extent).
    """
    zA, zB = _pair(planes, "planes")
    if zA == zB:
        raise ValueError("the two correction planes must be at different positions (z_A == z_B)")
    if np.ndim(radii) == 0:  # type: ignore[arg-type]
        r = _finite(radii, "radius")
        rA, rB = r, r
    else:
        rA, rB = _pair(radii, "radii")
    for r in (rA, rB):
        if not r > 0.0:
            raise ValueError(f"correction radius must be positive, got {r:g}")
    U, P = unb.static, unb.moment
    dz = zB - zA
    CA = (P - zB * U) / dz
    CB = (zA * U - P) / dz
    tol = unb.plane_tolerance(zA, zB)
    s = unb.angle_sense
    a = _plane_correction("A", zA, rA, CA, tol, s)
    b = _plane_correction("B", zB, rB, CB, tol, s)
    st = _plane_correction("static", None, rA, -U, unb.tol_static, s)
    return _finish(unb, (zA, zB), (rA, rB), a, b, st, bearings, False, None, None, None)


def _round_one(
    pc: PlaneCorrection,
    mass_step: float | None,
    angle_step: float | None,
    sense: str,
    tol: float,
) -> PlaneCorrection:
    m = pc.mass
    if mass_step is not None:
        m = math.floor(m / mass_step + 0.5) * mass_step
    reported = pc.angle_deg
    if angle_step is not None and pc.angle_defined:
        reported = _wrap_deg(math.floor(reported / angle_step + 0.5) * angle_step)
    if pc.angle_defined:
        phi = math.radians(_internal_deg(reported, sense))
    else:  # a zero correction: keep its (meaningless) direction
        phi = cmath.phase(pc.unbalance)
    C = complex(cmath.rect(m * pc.radius, phi))
    a, ok = (reported, True) if (pc.angle_defined and m > 0.0) else _angle(C, tol, sense)
    return PlaneCorrection(
        name=pc.name,
        z=pc.z,
        radius=pc.radius,
        unbalance=C,
        mass=m,
        angle_deg=a,
        angle_defined=ok,
        remove_angle_deg=_wrap_deg(a + 180.0) if ok else 0.0,
    )


def round_corrections(
    corr: Corrections,
    mass_step: float | None = None,
    angle_step_deg: float | None = None,
    *,
    bearings: object | None = None,
) -> Corrections:
    """Round correction masses and angles, and recompute the residual.

    Parameters
    ----------
    corr : Corrections — ideal (or already rounded: the ideal ones are rounded again)
    mass_step : float, optional — kg, > 0; masses go to the nearest multiple
    angle_step_deg : float, optional — deg, in (0, 360]; reported angles go to the nearest
        multiple (in the reported sense, so "against" shops get their own multiples)
    bearings : (z_1, z_2), optional — for the narrow-plane rule, as in :func:`corrections`;
        default: the bearings the ideal corrections were computed with

    Returns
    -------
    Corrections — ``rounded=True``, ``ideal`` = the unrounded corrections, and
    ``residual`` = the unbalance of the rotor with the ROUNDED masses added (sheet §1.5
    step 4): ``U_res = U + C_A' + C_B'``, ``P_res = P + z_A C_A' + z_B C_B'``.
    """
    if mass_step is not None:
        mass_step = _positive(mass_step, "mass step")
    if angle_step_deg is not None:
        angle_step_deg = _positive(angle_step_deg, "angle step")
        if angle_step_deg > 360.0:
            raise ValueError("angle step must not exceed 360 degrees")
    ideal = corr.ideal if corr.ideal is not None else corr
    unb = ideal.source
    if bearings is None:
        bearings = ideal.bearings
    s = unb.angle_sense
    tol = unb.plane_tolerance(*ideal.planes)
    a = _round_one(ideal.a, mass_step, angle_step_deg, s, tol)
    b = _round_one(ideal.b, mass_step, angle_step_deg, s, tol)
    st = _round_one(ideal.static, mass_step, angle_step_deg, s, unb.tol_static)
    return _finish(
        unb, ideal.planes, ideal.radii, a, b, st, bearings, True, mass_step, angle_step_deg, ideal
    )


def correction_points(corr: Corrections) -> tuple[tuple[float, np.ndarray], ...]:
    """The correction masses as point masses in the BODY frame (for ``--apply``).

    Returns
    -------
    tuple of (mass kg, (3,) ndarray position m) — planes A and B; zero masses left out.
    Position: shaft coordinates (r cos phi, r sin phi, z) with phi = arg C, taken to the body.
    """
    out = []
    fr = corr.source.frame
    for pc in (corr.a, corr.b):
        if pc.mass <= 0.0:
            continue
        phi = cmath.phase(pc.unbalance)
        assert pc.z is not None
        s = np.array([pc.radius * math.cos(phi), pc.radius * math.sin(phi), pc.z])
        out.append((float(pc.mass), fr.to_body(s)))
    return tuple(out)


def apply_corrections(corr: Corrections) -> Unbalance:
    """Unbalance of the rotor with the correction masses added as point masses.

    The full mass properties are rebuilt (parallel-axis theorem) and analysed with the same
    shaft, mark, sense and rtol; so the tilt after correction is available too.
    """
    return add_point_masses(corr.source, correction_points(corr))


def add_point_masses(unb: Unbalance, points: Sequence[tuple[float, object]]) -> Unbalance:
    """Unbalance of the rotor with point masses added.

    Parameters
    ----------
    unb : Unbalance
    points : sequence of (mass kg, (3,) position m, body frame)

    Returns
    -------
    Unbalance — same shaft, reference mark, angle sense and rtol.

    Notes
    -----
    Mass, com and the tensor about the new com by the parallel-axis theorem (sheet §2.2,
    a point mass has J = 0 about itself).
    """
    M = unb.mass
    c = np.array(unb.com)
    pts = [(float(m), _vec3(p, "point position")) for m, p in points]
    Mn = M + sum(m for m, _ in pts)
    cn = (M * c + sum(m * p for m, p in pts)) / Mn

    def shift(m: float, d: np.ndarray) -> np.ndarray:
        return m * (float(d @ d) * np.eye(3) - np.outer(d, d))

    Jn = np.array(unb.inertia_com) + shift(M, c - cn)
    for m, p in pts:
        Jn = Jn + shift(m, p - cn)
    fr = unb.frame
    return unbalance(
        Mn,
        cn,
        Jn,
        fr.axis,
        fr.origin,
        reference=fr.rotation[0],
        angle_sense=unb.angle_sense,
        rtol=unb.rtol,
    )


# ----------------------------------------------------------------------------------------
# splitting and radius change
# ----------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Split:
    """A mass split onto two fixed angular positions (sheet §2.5, 'component correction').

    Attributes
    ----------
    masses : (float, float) — same unit as the input mass
    angles_deg : (float, float) — deg, [0, 360), same convention as the input angle
    positions : (int, int) — position indices k (angle = offset + k 360/n); (-1, -1) from
        :func:`split_between`
    """

    masses: tuple[float, float]
    angles_deg: tuple[float, float]
    positions: tuple[int, int]

    def to_json(self) -> dict:
        return {
            "masses": [float(m) for m in self.masses],
            "angles_deg": [float(a) for a in self.angles_deg],
            "positions": list(self.positions),
        }


def split_between(mass: float, angle_deg: float, angle1_deg: float, angle2_deg: float) -> Split:
    """Split a mass at ``angle_deg`` into masses at two given angles (same radius).

    ``m1 = m sin(a2 - phi)/sin(a2 - a1)``, ``m2 = m sin(phi - a1)/sin(a2 - a1)`` (sheet
    §2.5). The vector sum of the two equals the original. A negative mass means that
    mass removed (phi outside the sector between a1 and a2).

    Raises
    ------
    ValueError
        the two angles coincide or are opposite (sin(a2 - a1) = 0).
    """
    m = _finite(mass, "mass")
    phi = math.radians(_finite(angle_deg, "angle"))
    a1 = math.radians(_finite(angle1_deg, "angle"))
    a2 = math.radians(_finite(angle2_deg, "angle"))
    den = math.sin(a2 - a1)
    if abs(den) < 1e-12:
        raise ValueError("cannot split onto two positions that coincide or are opposite")
    m1 = m * math.sin(a2 - phi) / den
    m2 = m * math.sin(phi - a1) / den
    return Split((m1, m2), (_plain_wrap(angle1_deg), _plain_wrap(angle2_deg)), (-1, -1))


def _plain_wrap(a: float) -> float:
    """Angle in [0, 360) without _wrap_deg's snap of the last 1e-9 deg to 0: a position
    angle is where a mass goes, and moving it by 1e-9 deg is a vector error of 1.7e-11 m."""
    a = math.fmod(float(a), 360.0)
    if a < 0.0:
        a += 360.0
    return 0.0 if a >= 360.0 else a + 0.0


def split_to_positions(
    mass: float, angle_deg: float, n_positions: int, offset_deg: float = 0.0
) -> Split:
    """Split a mass onto the two neighbouring of n equally spaced positions (blades, holes).

    Parameters
    ----------
    mass : float — any unit, >= 0
    angle_deg : float — deg, where the mass should go
    n_positions : int — >= 3, positions at ``offset_deg + k * 360/n``, k = 0..n-1
    offset_deg : float — deg, angle of position 0

    Returns
    -------
    Split — masses (both >= 0) at positions k and k+1 (mod n) with angle between them.

    Notes
    -----
    Sheet §2.5, T22: 18 g @ 100 deg onto 8 positions (every 45 deg) -> 14.6009 g @ 90 deg,
    4.4204 g @ 135 deg.
    """
    m = _finite(mass, "mass")
    if m < 0.0:
        raise ValueError("mass to split must not be negative")
    if int(n_positions) != n_positions or n_positions < 3:
        raise ValueError("n_positions must be an integer >= 3")
    n = int(n_positions)
    pitch = 360.0 / n
    off = _finite(offset_deg, "offset")
    # plain wrap into [0, 360): _wrap_deg's snap of the last 1e-9 deg to 0 would move the
    # mass by up to 1e-9 deg, i.e. a vector error of ~1.7e-11 m
    rel = math.fmod(_finite(angle_deg, "angle") - off, 360.0)
    if rel < 0.0:
        rel += 360.0
    k = int(math.floor(rel / pitch))
    frac = rel / pitch - k
    if k >= n:  # rel within round-off of 360
        k, frac = n - 1, 1.0
    a1 = off + k * pitch
    a2 = a1 + pitch
    sp = split_between(m, off + rel, a1, a2)
    m1, m2 = sp.masses
    if frac == 0.0:
        m1, m2 = m, 0.0
    # the positions' angles from their indices (a1 + pitch can land a hair below 360 for
    # position 0, e.g. n = 34)
    angles = (_plain_wrap(off + k * pitch), _plain_wrap(off + ((k + 1) % n) * pitch))
    return Split((max(m1, 0.0), max(m2, 0.0)), angles, (k, (k + 1) % n))


@dataclass(frozen=True, eq=False)
class PositionCorrections:
    """Two-plane corrections split onto n equally spaced positions (holes, blades).

    Attributes
    ----------
    ideal : Corrections — the unrounded two-plane corrections that were split
    n_positions : int
    pitch_deg : float — deg, 360 / n
    offset_deg : float — deg, reported angle of position 1 (default 0: on the mark)
    splits : (Split, Split) — planes A and B: masses (kg, rounded if ``mass_step``) at
        reported angles; ``positions`` are 1-based position numbers (position k sits at
        offset + (k - 1) pitch in the reported sense)
    mass_step : float | None — kg
    corrections : Corrections — each plane's net correction (the vector sum of its two
        masses) with the residual of the rotor with all four masses added (their real
        masses in the com shift); ``rounded`` iff ``mass_step`` was given
    """

    ideal: Corrections
    n_positions: int
    pitch_deg: float
    offset_deg: float
    splits: tuple[Split, Split]
    mass_step: float | None
    corrections: Corrections

    def points(self) -> tuple[tuple[str, int, float, np.ndarray], ...]:
        """(plane name, position number, mass kg, (3,) body-frame position m); zero masses left out."""
        out = []
        unb = self.ideal.source
        for pc, sp in zip(self.ideal.pair, self.splits):
            assert pc.z is not None
            for m, a, k in zip(sp.masses, sp.angles_deg, sp.positions):
                if m <= 0.0:
                    continue
                phi = math.radians(_internal_deg(a, unb.angle_sense))
                s = np.array([pc.radius * math.cos(phi), pc.radius * math.sin(phi), pc.z])
                out.append((pc.name, int(k), float(m), unb.frame.to_body(s)))
        return tuple(out)

    def to_json(self) -> dict:
        rows = []
        for pc, sp in zip(self.ideal.pair, self.splits):
            for m, a, k in zip(sp.masses, sp.angles_deg, sp.positions):
                rows.append(
                    {
                        "plane": float(pc.z) if pc.z is not None else None,
                        "name": pc.name,
                        "position": int(k),
                        "angle_deg": float(a),
                        "mass": float(m),
                        "radius": float(pc.radius),
                    }
                )
        return {
            "n_positions": int(self.n_positions),
            "pitch_deg": float(self.pitch_deg),
            "offset_deg": float(self.offset_deg),
            "masses": rows,
            "mass_step": None if self.mass_step is None else float(self.mass_step),
            "rounded": self.mass_step is not None,
            "residual": self.corrections.residual.to_json(),
        }


def split_corrections(
    corr: Corrections,
    n_positions: int,
    *,
    mass_step: float | None = None,
    offset_deg: float = 0.0,
) -> PositionCorrections:
    """Split each plane's correction onto the two neighbouring of n fixed positions.

    Parameters
    ----------
    corr : Corrections — ideal (or rounded: its ideal corrections are split)
    n_positions : int — >= 3, equally spaced positions per plane (holes, blades)
    mass_step : float, optional — kg, > 0; each split mass rounded half-up to a multiple
    offset_deg : float — deg, reported angle of position 1 (default 0: on the reference mark)

    Returns
    -------
    PositionCorrections

    Notes
    -----
    Sheet §2.5 ("fixed positions"): ``m1 = |C| sin(a2 - phi)/sin(a2 - a1)``,
    ``m2 = |C| sin(phi - a1)/sin(a2 - a1)`` (:func:`split_to_positions`), in the reported
    angle sense (the set of positions is the same in either sense). The two masses sum to C
    exactly; after rounding, each plane's net correction is their vector sum and the residual
    (sheet §1.5 step 4) is that of the rotor with all the masses added.
    """
    if mass_step is not None:
        mass_step = _positive(mass_step, "mass step")
    ideal = corr.ideal if corr.ideal is not None else corr
    unb = ideal.source
    s = unb.angle_sense
    tol = unb.plane_tolerance(*ideal.planes)
    n = int(n_positions)
    splits = []
    nets = []
    added = []
    for pc in ideal.pair:
        sp = split_to_positions(pc.mass if pc.angle_defined else 0.0, pc.angle_deg, n, offset_deg)
        ms = sp.masses
        if mass_step is not None:
            ms = tuple(math.floor(m / mass_step + 0.5) * mass_step for m in ms)
        pos = tuple(k + 1 for k in sp.positions)
        sp = Split((ms[0], ms[1]), sp.angles_deg, (pos[0], pos[1]))
        C = sum(
            (complex(cmath.rect(m * pc.radius, math.radians(_internal_deg(a, s))))
             for m, a in zip(sp.masses, sp.angles_deg)),
            0j,
        )
        splits.append(sp)
        nets.append(_plane_correction(pc.name, pc.z, pc.radius, C, tol, s))
        added.append(ms[0] + ms[1])
    st = ideal.static
    rounded = mass_step is not None
    net = _finish(
        unb, ideal.planes, ideal.radii, nets[0], nets[1], st, ideal.bearings, rounded,
        mass_step, None, ideal if rounded else None, (added[0], added[1]),
    )
    return PositionCorrections(
        ideal=ideal,
        n_positions=n,
        pitch_deg=360.0 / n,
        offset_deg=_wrap_deg(_finite(offset_deg, "offset")),
        splits=(splits[0], splits[1]),
        mass_step=mass_step,
        corrections=net,
    )


def mass_at_radius(mass: float, radius: float, new_radius: float) -> float:
    """The mass giving the same unbalance at another radius: ``m r / r_new`` (sheet §2.5)."""
    return _finite(mass, "mass") * _positive(radius, "radius") / _positive(new_radius, "new radius")


# ----------------------------------------------------------------------------------------
# bearing forces at speed
# ----------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class BearingForces:
    """Rotating bearing forces, static gravity loads and the dynamic torque at a speed.

    Attributes
    ----------
    speed : float — rad/s, as given (omega = speed e_z)
    bearings : (float, float) | None — m, bearing positions along the shaft
    forces : (complex, complex) | () — N, force the rotor exerts on each bearing, rotor-fixed
        shaft frame ('with' sense)
    plane_unbalances : (complex, complex) | () — kg m, equivalent unbalance in each bearing
        plane, F_i / Omega^2 (the ISO tolerance quantity)
    static_loads : (float, float) | () — N, gravity loads (shaft horizontal), positive =
        the bearing carries the rotor's weight downward; negative = hold-down (overhung)
    g : float — m/s^2
    centrifugal_force : complex — N, total rotating force Omega^2 U (= F_1 + F_2)
    angular_momentum : (3,) ndarray — kg m^2/s, L = J_G omega about the com, shaft frame
    torque : (3,) ndarray — N m, omega x L about the com, shaft frame (rotor-fixed): the
        torque the supports must apply to keep the rotor turning about the shaft
    torque_origin : (3,) ndarray — N m, the same about the shaft point z = 0 (sheet §2.6 N_O)
    tol_force : float — N, tolerance used for the angle flags
    angle_sense : str
    """

    speed: float
    bearings: tuple[float, float] | None
    forces: tuple[complex, ...]
    plane_unbalances: tuple[complex, ...]
    static_loads: tuple[float, ...]
    g: float
    centrifugal_force: complex
    angular_momentum: np.ndarray
    torque: np.ndarray
    torque_origin: np.ndarray
    tol_force: float
    angle_sense: str

    def to_json(self) -> dict:
        rows = []
        if self.bearings is not None:
            for i, (z, F, u, W) in enumerate(
                zip(self.bearings, self.forces, self.plane_unbalances, self.static_loads)
            ):
                pj = _phasor_json(F, self.tol_force, self.angle_sense)
                rows.append(
                    {
                        "plane": float(z),
                        "name": str(i + 1),
                        "force": pj["magnitude"],
                        "angle_deg": pj["angle_deg"],
                        "angle_defined": pj["angle_defined"],
                        "equivalent_unbalance": float(abs(u)),
                        "static_load": float(W),
                    }
                )
        return {
            "speed": float(self.speed),
            "bearing_forces": rows,
            "g": float(self.g),
            "static_load_assumption": "shaft horizontal, gravity at right angles to it",
            "centrifugal_force": float(abs(self.centrifugal_force)),
            "angular_momentum": [float(v) + 0.0 for v in self.angular_momentum],
            "torque": [float(v) + 0.0 for v in self.torque],
            "torque_magnitude": float(np.linalg.norm(self.torque)),
            "torque_origin": [float(v) + 0.0 for v in self.torque_origin],
            "frame": "shaft (rotor-fixed)",
        }


def bearing_forces(
    unb: Unbalance,
    speed: float,
    bearings: object | None = None,
    *,
    g: float = STANDARD_GRAVITY,
) -> BearingForces:
    """Rotating bearing forces (rotor-fixed), static loads and the torque omega x L.

    Parameters
    ----------
    unb : Unbalance
    speed : float — rad/s, Omega (sign irrelevant for the forces; omega = Omega e_z)
    bearings : (z_1, z_2), optional — m, z_1 != z_2
    g : float — m/s^2, for the static loads

    Returns
    -------
    BearingForces

    Notes
    -----
    Sheet §2.6: ``F_1 = Omega^2 (z_2 U - P)/(z_2 - z_1)``,
    ``F_2 = Omega^2 (P - z_1 U)/(z_2 - z_1)``,
    the force each bearing receives from the rotor, fixed in the rotor frame (it turns with
    the rotor in the lab). Static loads by the lever rule on M g:
    ``W_1 = M g (z_2 - z_G)/(z_2 - z_1)``, ``W_2 = M g (z_G - z_1)/(z_2 - z_1)`` (shaft
    horizontal; W_i < 0 on the far bearing of an overhung rotor). Torque: L = J_G omega,
    N_G = omega x L about the com; about z = 0, N_O = omega x (J_O omega) =
    Omega^2 (D_yz, -D_xz, 0) with D about z = 0 (i.e. N_x + i N_y = -i Omega^2 P).
    """
    W = _finite(speed, "speed")
    gg = _finite(g, "g")
    U, P = unb.static, unb.moment
    om = np.array([0.0, 0.0, W])
    L = np.array(unb.inertia_shaft) @ om
    N = np.cross(om, L)
    NO = np.array([W * W * P.imag, -W * W * P.real, 0.0])
    forces: tuple[complex, ...] = ()
    pu: tuple[complex, ...] = ()
    loads: tuple[float, ...] = ()
    bz: tuple[float, float] | None = None
    tol = 0.0
    if bearings is not None:
        z1, z2 = _pair(bearings, "bearings")
        if z1 == z2:
            raise ValueError("the two bearings must be at different positions along the shaft")
        u1, u2 = plane_unbalances(U, P, z1, z2)
        forces = (W * W * u1, W * W * u2)
        pu = (u1, u2)
        zg = float(unb.com_shaft[2])
        Mg = unb.mass * gg
        loads = (Mg * (z2 - zg) / (z2 - z1), Mg * (zg - z1) / (z2 - z1))
        bz = (z1, z2)
        tol = W * W * unb.plane_tolerance(z1, z2)
    return BearingForces(
        speed=W,
        bearings=bz,
        forces=forces,
        plane_unbalances=pu,
        static_loads=loads,
        g=gg,
        centrifugal_force=W * W * U,
        angular_momentum=_readonly(L),
        torque=_readonly(N),
        torque_origin=_readonly(NO),
        tol_force=tol,
        angle_sense=unb.angle_sense,
    )


# ----------------------------------------------------------------------------------------
# ISO 21940-11
# ----------------------------------------------------------------------------------------


def permissible_unbalance(grade: float, speed: float, mass: float) -> tuple[float, float]:
    """ISO 21940-11 permissible specific and total residual unbalance.

    Parameters
    ----------
    grade : float — G in mm/s (the number in "G 6.3"), 0.4 <= G <= 4000
    speed : float — rad/s, maximum service speed Omega, > 0
    mass : float — kg, rotor mass

    Returns
    -------
    (e_per, U_per) : (float, float) — m and kg m

    Notes
    -----
    Sheet §1.2: ``e_per = G / Omega`` with G in m/s (G[mm/s] * 1e-3), ``U_per = e_per M``.
    Shop form: U_per[g mm] = 9549.2966 G M[kg] / n[rpm].
    """
    G = _finite(grade, "grade")
    if not ISO_GRADE_MIN <= G <= ISO_GRADE_MAX:
        raise ValueError(
            f"balance grade must be between G {ISO_GRADE_MIN:g} and G {ISO_GRADE_MAX:g} "
            f"(mm/s), got {G:g}"
        )
    W = _positive(speed, "speed")
    M = _positive(mass, "mass")
    e = G * 1e-3 / W
    return e, e * M


def achieved_grade(residual_unbalance: float, mass: float, speed: float) -> float:
    """Achieved balance grade of a residual unbalance, mm/s.

    Parameters
    ----------
    residual_unbalance : float — kg m
    mass : float — kg
    speed : float — rad/s

    Notes
    -----
    Sheet §1.2: ``G = |U| / M * Omega`` (m/s), times 1e3 for mm/s.
    """
    U = abs(_finite(residual_unbalance, "unbalance"))
    return U / _positive(mass, "mass") * abs(_finite(speed, "speed")) * 1e3


@dataclass(frozen=True)
class Allocation:
    """Allocation of U_per to two tolerance planes (sheet §1.4).

    Attributes
    ----------
    allowed : (float, float) — kg m, U_per share of each plane (in the order given)
    unclamped : (float, float) — kg m, before the clamp/floor
    kind : str — "inboard" (com between the planes, inclusive) or "outboard"
    rule : str — the rule, in words
    rbcli_rule : bool — True for the outboard rule (derived by rbcli, not from the ISO text)
    """

    allowed: tuple[float, float]
    unclamped: tuple[float, float]
    kind: str
    rule: str
    rbcli_rule: bool

    def to_json(self) -> dict:
        return {
            "allowed": [float(v) for v in self.allowed],
            "unclamped": [float(v) for v in self.unclamped],
            "kind": self.kind,
            "rule": self.rule,
            "rbcli_rule": bool(self.rbcli_rule),
        }


def allocate_permissible(
    u_per: float,
    com_z: float,
    planes: object,
    *,
    clamp: tuple[float, float] = ISO_CLAMP,
    outboard_floor: float = ISO_OUTBOARD_FLOOR,
) -> Allocation:
    """Split U_per between two tolerance planes by the lever rule (sheet §1.4).

    Parameters
    ----------
    u_per : float — kg m (any unit; the shares come out in the same unit)
    com_z : float — m, com position along the shaft
    planes : (z_1, z_2) — m, z_1 != z_2 (normally the bearings)
    clamp : (lo, hi) — inboard limits as fractions of U_per (default 0.3, 0.7)
    outboard_floor : float — floor of the far share for outboard rotors, fraction of U_per

    Returns
    -------
    Allocation

    Notes
    -----
    Inboard (com between the planes, ends included), ISO 21940-11 / CEMB / Vibromera:
    ``U_1 = U_per L_2/L``, ``U_2 = U_per L_1/L`` (L_i = |z_G - z_i|, L = |z_2 - z_1|), then
    each clamped to [0.3, 0.7] U_per. Outboard (sheet §1.4c, rbcli's own rule): each plane
    gets the load U_per at the com would put on it, ``U_near = U_per L_far/L``,
    ``U_far = U_per L_near/L``, the far share floored at 0.3 U_per.
    """
    Up = _finite(u_per, "permissible unbalance")
    zg = _finite(com_z, "com position")
    z1, z2 = _pair(planes, "tolerance planes")
    if z1 == z2:
        raise ValueError("the two tolerance planes must be at different positions")
    lo, hi = clamp
    L = abs(z2 - z1)
    L1, L2 = abs(zg - z1), abs(z2 - zg)
    if min(z1, z2) <= zg <= max(z1, z2):
        raw = (Up * L2 / L, Up * L1 / L)
        allowed = tuple(min(max(v, lo * Up), hi * Up) for v in raw)
        rule = (
            f"ISO 21940-11 lever rule on the com position between the planes, each share clamped "
            f"to {lo:g}..{hi:g} of U_per"
        )
        return Allocation((allowed[0], allowed[1]), raw, "inboard", rule, False)
    # the same lever rule; only the far share (the smaller one) gets a floor
    raw = (Up * L2 / L, Up * L1 / L)
    if L1 <= L2:  # plane 1 is the near one
        allowed2 = (raw[0], max(raw[1], outboard_floor * Up))
    else:
        allowed2 = (max(raw[0], outboard_floor * Up), raw[1])
    rule = (
        "rbcli's own rule for outboard rotors (the ISO clause was not available): each plane "
        "gets the load U_per at the com would put on it (lever rule), the far plane's share "
        f"floored at {outboard_floor:g} of U_per"
    )
    return Allocation(allowed2, raw, "outboard", rule, True)


@dataclass(frozen=True)
class IsoState:
    """ISO evaluation of one state of the rotor (before or after correction).

    Attributes
    ----------
    residual : (complex, complex) — kg m, exact equivalent unbalance in each tolerance plane
    ratio : (float, float) — |residual_i| / allowed_i
    achieved_grade : (float, float) — mm/s, G |U_i| / U_per,i
    static_unbalance : float — kg m, |U| of this state
    static_achieved_grade : float — mm/s, |U|/M Omega
    passed : bool — both ratios <= 1
    """

    residual: tuple[complex, complex]
    ratio: tuple[float, float]
    achieved_grade: tuple[float, float]
    static_unbalance: float
    static_achieved_grade: float
    passed: bool

    def to_json(self, tol: float = 0.0, sense: str = "with") -> dict:
        return {
            "residual": [float(abs(u)) for u in self.residual],
            "residual_angle_deg": [_angle(u, tol, sense)[0] for u in self.residual],
            "residual_angle_defined": [_angle(u, tol, sense)[1] for u in self.residual],
            "ratio": [_f(r) for r in self.ratio],
            "achieved_grade": [_f(g) for g in self.achieved_grade],
            "static_unbalance": float(self.static_unbalance),
            "static_achieved_grade": float(self.static_achieved_grade),
            "pass": bool(self.passed),
        }


@dataclass(frozen=True, eq=False)
class IsoCheck:
    """ISO 21940-11 check of a rotor (sheet §1.5).

    Attributes
    ----------
    grade : float — mm/s (the G number)
    speed : float — rad/s, maximum service speed
    mass : float — kg, rotor mass U_per is based on (the uncorrected rotor)
    permissible_eccentricity : float — m, e_per
    permissible_unbalance : float — kg m, U_per
    planes : (float, float) — m, tolerance planes
    planes_are : str — "bearing" or "correction"
    allocation : Allocation
    before : IsoState — the rotor as given: what ``passed`` judges
    after : IsoState | None — a prediction: the rotor with the corrections added (rounded
        ones if rounded); it never sets the verdict
    after_state : str | None — "after corrections" or "after rounded corrections"
    passed : bool — the verdict on the rotor as given (``before.passed``)
    tol_plane : float — kg m, for the angle flags
    angle_sense : str
    warnings : tuple[str, ...]
    """

    grade: float
    speed: float
    mass: float
    permissible_eccentricity: float
    permissible_unbalance: float
    planes: tuple[float, float]
    planes_are: str
    allocation: Allocation
    before: IsoState
    after: IsoState | None
    after_state: str | None
    passed: bool
    tol_plane: float
    angle_sense: str
    warnings: tuple[str, ...]

    def to_json(self) -> dict:
        st = self.before  # residual, ratio, pass: the rotor as given (SPEC §3)
        after = None
        if self.after is not None:
            after = self.after.to_json(self.tol_plane, self.angle_sense)
            after["state"] = self.after_state
            after["prediction"] = True
        return {
            "grade": float(self.grade),
            "grade_si": float(self.grade) * 1e-3,
            "speed": float(self.speed),
            "mass": float(self.mass),
            "permissible_eccentricity": float(self.permissible_eccentricity),
            "permissible_unbalance": float(self.permissible_unbalance),
            "allowed": [float(v) for v in self.allocation.allowed],
            "residual": [float(abs(u)) for u in st.residual],
            "ratio": [_f(r) for r in st.ratio],
            "achieved_grade": [_f(g) for g in st.achieved_grade],
            "static_achieved_grade": float(st.static_achieved_grade),
            "pass": bool(self.passed),
            "judged": "as given",
            "planes": [float(z) for z in self.planes],
            "planes_are": self.planes_are,
            "allocation": self.allocation.to_json(),
            "before": self.before.to_json(self.tol_plane, self.angle_sense),
            "after": after,
            "warnings": list(self.warnings),
        }


def _iso_state(
    U: complex,
    P: complex,
    M: float,
    planes: tuple[float, float],
    alloc: Allocation,
    G: float,
    W: float,
) -> IsoState:
    u1, u2 = plane_unbalances(U, P, *planes)
    res = (u1, u2)
    ratio = tuple(
        abs(u) / a if a > 0 else (0.0 if abs(u) == 0 else math.inf)
        for u, a in zip(res, alloc.allowed)
    )
    ach = tuple(G * r for r in ratio)
    return IsoState(
        residual=res,
        ratio=(ratio[0], ratio[1]),
        achieved_grade=(ach[0], ach[1]),
        static_unbalance=abs(U),
        static_achieved_grade=achieved_grade(abs(U), M, W),
        passed=all(r <= 1.0 for r in ratio),
    )


def iso_check(
    unb: Unbalance,
    grade: float,
    speed: float,
    planes: object,
    *,
    planes_are: str = "bearing",
    corrections: Corrections | None = None,
    clamp: tuple[float, float] = ISO_CLAMP,
    outboard_floor: float = ISO_OUTBOARD_FLOOR,
) -> IsoCheck:
    """ISO 21940-11 pass/fail of a rotor with exact residuals in two tolerance planes.

    Parameters
    ----------
    unb : Unbalance
    grade : float — G in mm/s, 0.4 <= G <= 4000 (else ValueError)
    speed : float — rad/s, maximum service speed, > 0
    planes : (z_1, z_2) — m, tolerance planes: the bearings (ISO 21940-11) or, with
        ``planes_are="correction"``, the correction planes (older practice, sheet §1.4b)
    corrections : Corrections, optional — if given, the rotor with these (ideal or
        rounded) corrections added is evaluated too (``after``, a prediction); the verdict
        stays that of the rotor as given
    clamp, outboard_floor : see :func:`allocate_permissible`

    Returns
    -------
    IsoCheck

    Notes
    -----
    Sheet §1.5: U_per = e_per M (uncorrected mass); allocation by the lever rule on the com
    (§1.4); the exact residual unbalance in each plane is
    ``U_1 = (z_2 U - P)/(z_2 - z_1)``, ``U_2 = (P - z_1 U)/(z_2 - z_1)`` (= F_i / Omega^2);
    ratio_i = |U_i| / U_per,i; PASS iff both <= 1. Achieved grade per plane
    ``G |U_i| / U_per,i``; whole-rotor static ``|U|/M Omega`` (both mm/s).
    """
    if planes_are not in ("bearing", "correction"):
        raise ValueError("planes_are must be 'bearing' or 'correction'")
    e_per, U_per = permissible_unbalance(grade, speed, unb.mass)
    G = float(grade)
    W = float(speed)
    z1, z2 = _pair(planes, "tolerance planes")
    if z1 == z2:
        raise ValueError("the two tolerance planes must be at different positions")
    alloc = allocate_permissible(
        U_per, float(unb.com_shaft[2]), (z1, z2), clamp=clamp, outboard_floor=outboard_floor
    )
    before = _iso_state(unb.static, unb.moment, unb.mass, (z1, z2), alloc, G, W)
    after = None
    after_state = None
    if corrections is not None:
        src = corrections.source
        if (src.mass, src.static, src.moment) != (unb.mass, unb.static, unb.moment):
            raise ValueError("the corrections were computed for another rotor")
        r = corrections.residual
        after = _iso_state(r.static, r.moment, r.mass, (z1, z2), alloc, G, W)
        after_state = "after rounded corrections" if corrections.rounded else "after corrections"
    warns = []
    if alloc.rbcli_rule:
        warns.append("the com lies outside the tolerance planes: allocation uses " + alloc.rule)
    return IsoCheck(
        grade=G,
        speed=W,
        mass=unb.mass,
        permissible_eccentricity=e_per,
        permissible_unbalance=U_per,
        planes=(z1, z2),
        planes_are=planes_are,
        allocation=alloc,
        before=before,
        after=after,
        after_state=after_state,
        passed=before.passed,
        tol_plane=unb.plane_tolerance(z1, z2),
        angle_sense=unb.angle_sense,
        warnings=tuple(warns),
    )


# ----------------------------------------------------------------------------------------
# influence-coefficient field balancing
# ----------------------------------------------------------------------------------------


def _small_response(v0: complex, v1: complex) -> bool:
    """Rule of thumb (sheet §5.1): small unless amplitude changed >= 25 % or phase >= 25 deg."""
    a0, a1 = abs(v0), abs(v1)
    if a0 == 0.0:
        return a1 == 0.0
    amp = abs(a1 - a0) / a0
    if a1 == 0.0:
        return amp < SMALL_RESPONSE_AMPLITUDE
    dphi = abs(math.degrees(cmath.phase(v1 / v0)))
    return amp < SMALL_RESPONSE_AMPLITUDE and dphi < SMALL_RESPONSE_PHASE_DEG


@dataclass(frozen=True)
class FieldSinglePlane:
    """Single-plane influence-coefficient result (sheet §5.1).

    Attributes
    ----------
    influence : complex — H = (V1 - V0)/T, vibration unit per mass unit
    correction : complex — W = -V0/H, with the trial removed (mass unit of the trial)
    mass : float — |W|
    angle_deg : float — deg, arg W in [0, 360) (same sense as the trial angle and phases)
    correction_trial_on : complex — W - T, to add if the trial stays on
    mass_trial_on : float
    angle_trial_on_deg : float
    predicted_residual : complex — V0 + H W (0 for the linear model)
    small_response : bool
    warnings : tuple[str, ...]
    """

    influence: complex
    correction: complex
    mass: float
    angle_deg: float
    correction_trial_on: complex
    mass_trial_on: float
    angle_trial_on_deg: float
    predicted_residual: complex
    small_response: bool
    warnings: tuple[str, ...]

    def to_json(self) -> dict:
        return {
            "influence": _phasor_json(self.influence),
            "mass": float(self.mass),
            "angle_deg": float(self.angle_deg),
            "mass_trial_on": float(self.mass_trial_on),
            "angle_trial_on_deg": float(self.angle_trial_on_deg),
            "predicted_residual": float(abs(self.predicted_residual)),
            "small_response": bool(self.small_response),
            "warnings": list(self.warnings),
        }


def _complex(v: object, name: str) -> complex:
    try:
        z = complex(v)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a complex number (amplitude and phase)") from None
    if not (math.isfinite(z.real) and math.isfinite(z.imag)):
        raise ValueError(f"{name} must be finite")
    return z


def field_single_plane(v0: complex, v1: complex, trial: complex) -> FieldSinglePlane:
    """Single-plane field balancing from two runs (sheet §5.1).

    Parameters
    ----------
    v0 : complex — reading without trial, amplitude * exp(i phase) (any vibration unit)
    v1 : complex — reading with the trial on
    trial : complex — trial mass * exp(i angle) (any mass unit; the same angle sense as the phase)

    Returns
    -------
    FieldSinglePlane

    Raises
    ------
    ValueError
        zero trial; the trial changed nothing (V1 == V0).

    Notes
    -----
    ``H = (V1 - V0)/T``, ``W = -V0/H``; trial left on: ``W - T``.
    """
    V0, V1, T = _complex(v0, "v0"), _complex(v1, "v1"), _complex(trial, "trial")
    if T == 0:
        raise ValueError("the trial mass must not be zero")
    if V1 == V0:
        raise ValueError(
            "the trial run gave the same reading as the initial run; no influence coefficient"
        )
    H = (V1 - V0) / T
    W = -V0 / H
    Won = W - T
    small = _small_response(V0, V1)
    warns = []
    if small:
        warns.append(
            "the trial changed the reading by less than 25 % in amplitude and 25 deg in phase: "
            "use a larger trial mass"
        )
    return FieldSinglePlane(
        influence=H,
        correction=W,
        mass=abs(W),
        angle_deg=_angle(W, 0.0)[0],
        correction_trial_on=Won,
        mass_trial_on=abs(Won),
        angle_trial_on_deg=_angle(Won, 0.0)[0],
        predicted_residual=V0 + H * W,
        small_response=small,
        warnings=tuple(warns),
    )


@dataclass(frozen=True, eq=False)
class FieldTwoPlane:
    """Two-plane influence-coefficient result (sheet §5.1).

    Attributes
    ----------
    influence : (2, 2) complex ndarray — alpha[i, j], response of sensor i per unit trial
        in plane j
    corrections : (2,) complex ndarray — W_A, W_B (trials removed), mass unit of the trials
    masses : (float, float)
    angles_deg : (float, float) — [0, 360), same sense as the trial angles and phases
    corrections_trials_on : (2,) complex ndarray — W - T per plane, if that plane's trial stays on
    cond : float — 2-norm condition number of alpha
    det : complex
    ill_conditioned : bool — cond > FIELD_COND_WARN
    small_response : (bool, bool) — per trial run, no sensor changed by >= 25 % / 25 deg
    predicted_residual : (2,) complex ndarray — V0 + alpha W (0 in the linear model)
    cumulative : bool
    warnings : tuple[str, ...]
    """

    influence: np.ndarray
    corrections: np.ndarray
    masses: tuple[float, float]
    angles_deg: tuple[float, float]
    corrections_trials_on: np.ndarray
    cond: float
    det: complex
    ill_conditioned: bool
    small_response: tuple[bool, bool]
    predicted_residual: np.ndarray
    cumulative: bool
    warnings: tuple[str, ...]

    def to_json(self) -> dict:
        return {
            "influence": [[_phasor_json(complex(a)) for a in row] for row in self.influence],
            "masses": [float(m) for m in self.masses],
            "angles_deg": [float(a) for a in self.angles_deg],
            "masses_trials_on": [float(abs(w)) for w in self.corrections_trials_on],
            "angles_trials_on_deg": [
                _angle(complex(w), 0.0)[0] for w in self.corrections_trials_on
            ],
            "cond": _f(self.cond),
            "ill_conditioned": bool(self.ill_conditioned),
            "small_response": list(self.small_response),
            "predicted_residual": [float(abs(v)) for v in self.predicted_residual],
            "cumulative": bool(self.cumulative),
            "warnings": list(self.warnings),
        }


def field_two_plane(
    v0: Sequence[complex],
    va: Sequence[complex],
    vb: Sequence[complex],
    trial_a: complex,
    trial_b: complex,
    *,
    cumulative: bool = False,
) -> FieldTwoPlane:
    """Two-plane field balancing from three runs (2 sensors, sheet §5.1).

    Parameters
    ----------
    v0 : (2,) complex — sensor readings without trials
    va : (2,) complex — with trial A
    vb : (2,) complex — with trial B (trial A removed, unless ``cumulative``)
    trial_a, trial_b : complex — trial mass * exp(i angle), planes A and B
    cumulative : bool — trial A was left on during run B: the B column uses VB - VA

    Returns
    -------
    FieldTwoPlane

    Raises
    ------
    ValueError
        a zero trial; a singular influence matrix.

    Notes
    -----
    ``alpha_iA = (V_iA - V_i0)/T_A``, ``alpha_iB = (V_iB - V_i0)/T_B`` (or ``V_iB - V_iA``),
    ``W = -alpha^{-1} V0``. Warns when cond(alpha) > 50 (sheet §7.10).
    """
    V0 = np.array([_complex(v, "v0") for v in v0], dtype=complex)
    VA = np.array([_complex(v, "va") for v in va], dtype=complex)
    VB = np.array([_complex(v, "vb") for v in vb], dtype=complex)
    for arr, nm in ((V0, "v0"), (VA, "va"), (VB, "vb")):
        if arr.shape != (2,):
            raise ValueError(f"{nm} must hold two sensor readings")
    TA, TB = _complex(trial_a, "trial_a"), _complex(trial_b, "trial_b")
    if TA == 0 or TB == 0:
        raise ValueError("trial masses must not be zero")
    refB = VA if cumulative else V0
    alpha = np.column_stack([(VA - V0) / TA, (VB - refB) / TB])
    det = complex(alpha[0, 0] * alpha[1, 1] - alpha[0, 1] * alpha[1, 0])
    scale = float(np.max(np.abs(alpha)))
    if not scale > 0.0 or abs(det) <= 1e-14 * scale * scale:
        raise ValueError(
            "the influence matrix is singular: the trial runs do not separate the two planes"
        )
    W = np.linalg.solve(alpha, -V0)
    cond = float(np.linalg.cond(alpha))
    small = (
        all(_small_response(V0[i], VA[i]) for i in range(2)),
        all(_small_response(refB[i], VB[i]) for i in range(2)),
    )
    warns = []
    if cond > FIELD_COND_WARN:
        warns.append(
            f"the influence matrix is ill-conditioned (cond = {cond:.3g} > "
            f"{FIELD_COND_WARN:g}): the planes are not well separated"
        )
    for name, sm in zip("AB", small):
        if sm:
            warns.append(
                f"trial {name} changed no reading by 25 % in amplitude or 25 deg in phase: "
                "use a larger trial mass"
            )
    Won = W - np.array([TA, TB])
    return FieldTwoPlane(
        influence=alpha,
        corrections=W,
        masses=(float(abs(W[0])), float(abs(W[1]))),
        angles_deg=(_angle(complex(W[0]), 0.0)[0], _angle(complex(W[1]), 0.0)[0]),
        corrections_trials_on=Won,
        cond=cond,
        det=det,
        ill_conditioned=cond > FIELD_COND_WARN,
        small_response=small,
        predicted_residual=V0 + alpha @ W,
        cumulative=bool(cumulative),
        warnings=tuple(warns),
    )


# ----------------------------------------------------------------------------------------
# the `balance` JSON document (SPEC §3)
# ----------------------------------------------------------------------------------------


def balance_json(
    unb: Unbalance,
    corrections: Corrections | None = None,
    forces: BearingForces | None = None,
    iso: IsoCheck | None = None,
) -> dict:
    """The JSON document of ``rbcli balance --json`` (SPEC §3), SI units, no NaN.

    Keys: everything of :meth:`Unbalance.to_json` (``mass``, ``eccentricity``,
    ``static_unbalance``, ``static_unbalance_angle_deg``, ``couple_unbalance``, ``tilt_deg``,
    ``statically_balanced``, ``dynamically_balanced``, ...); with corrections:
    ``corrections`` [{``plane`` (z, m), ``name``, ``mass``, ``radius``, ``angle_deg``, ...}],
    ``static_correction``, ``correction_details``; with forces: ``bearing_forces``
    [{``plane``, ``name``, ``force``, ``angle_deg``, ``static_load``, ...}] (only when
    bearings were given) and ``dynamics`` (speed, angular momentum, torque); with iso:
    ``iso`` {``grade``, ``permissible_unbalance``, ``allowed`` [2], ``residual`` [2],
    ``pass``, ...} (the rotor as given; ``iso.after`` predicts the corrected rotor).
    """
    d = unb.to_json()
    if corrections is not None:
        cj = corrections.to_json()
        d["corrections"] = cj.pop("corrections")
        d["static_correction"] = cj.pop("static_correction")
        d["correction_details"] = cj
    if forces is not None:
        fj = forces.to_json()
        rows = fj.pop("bearing_forces")
        if forces.bearings is not None:
            d["bearing_forces"] = rows
        d["dynamics"] = fj
    if iso is not None:
        d["iso"] = iso.to_json()
    return d
