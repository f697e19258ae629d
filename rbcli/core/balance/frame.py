"""The shaft frame of a rotor and its unbalance about the shaft (sheet §2.1-§2.4).

:func:`shaft_frame` fixes the rotor's frame (e_z along the shaft, e_x the 0° mark);
:func:`unbalance` gives the static, moment and couple unbalance, the tilt of the nearest
principal axis and the ideal balanced verdicts; :func:`add_point_masses` the same for the
rotor with point masses added (the corrected rotor).
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from rbcli.core.balance.common import (
    BALANCE_RTOL, FRAME_SWITCH_COS, TILT_GAP_RTOL, BalanceValueError, angle_of, check_sense,
    finite, positive, readonly, report_deg, vec3,
)
from rbcli.core.principal import DEGENERATE_RTOL


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

    def to_body(self, points: object) -> np.ndarray:
        """Shaft-frame coordinates (..., 3) -> body-frame point(s) (..., 3), m."""
        s = np.asarray(points, dtype=float)
        return s @ self.rotation + self.origin

def shaft_frame(
    axis: object = (0.0, 0.0, 1.0),
    through: object = (0.0, 0.0, 0.0),
    *,
    reference: object | None = None,
    zero_mark_deg: float = 0.0,
) -> ShaftFrame:
    """The rotor-fixed shaft frame (e_x, e_y, e_z) of a shaft along ``axis`` through ``through``
    (z = 0 there), with the 0° mark along ``reference`` (its part across the shaft; default the
    rule below) turned by ``zero_mark_deg`` about +e_z. ValueError for a zero or non-finite
    axis, or a reference along the shaft.

    ``e_x`` is body x projected across e_z, or body y when ``|e_z . x| > 0.9`` (projection
    >= 0.436, the switch away from the axes and diagonals); ``e_y = e_z x e_x``. A shaft along
    +z gives the body frame."""
    a = vec3(axis, "shaft axis", "axis")
    n = float(np.linalg.norm(a))
    if not n > 0.0:
        raise BalanceValueError("axis", "shaft axis must be a non-zero vector")
    o = vec3(through, "shaft point (through)", "through")
    ez = a / n
    if reference is not None:
        ref = vec3(reference, "reference mark direction", "reference")
        p = ref - float(ref @ ez) * ez
        pn = float(np.linalg.norm(p))
        if not pn > 1e-6 * float(np.linalg.norm(ref)):
            raise BalanceValueError("reference", "reference mark direction must not be parallel to the shaft")
    else:
        base = np.array([1.0, 0.0, 0.0])
        if abs(ez[0]) > FRAME_SWITCH_COS:
            base = np.array([0.0, 1.0, 0.0])
        p = base - float(base @ ez) * ez
        pn = float(np.linalg.norm(p))
    ex = p / pn
    ey = np.cross(ez, ex)
    th = math.radians(finite(zero_mark_deg, "zero_mark_deg"))
    if th != 0.0:
        c, s = math.cos(th), math.sin(th)
        ex, ey = c * ex + s * ey, -s * ex + c * ey
    return ShaftFrame(readonly(np.vstack([ex, ey, ez])), readonly(o))


# --- unbalance of a rotor


@dataclass(frozen=True, eq=False)
class Unbalance:
    """Unbalance of a rigid rotor about a shaft (sheet §2.3, §2.4).

    Attributes
    ----------
    mass, com, inertia_com — kg, m, kg m^2: the input (body frame, tensor about the com)
    frame : ShaftFrame
    angle_sense : str — "with" or "against" (the ``*_deg`` angles)
    com_shaft, inertia_shaft — (x_G, y_G, z_G) (m) and the tensor about the com, shaft axes
    static, moment, couple : complex — U (kg m), P about z = 0 and P_G about the com (kg m^2)
    eccentricity : float — m, |U|/M
    tilt_deg, tilt_azimuth_deg : float — deg, from the shaft to the nearest principal axis, and
        where its +z end leans (shaft frame; 0.0 when undefined: ``tilt_azimuth_defined``)
    tilt_well_defined : bool — False when that axis's moment is within TILT_GAP_RTOL of another
    principal_gap : float — kg m^2, its moment's distance from the others
    length_scale : float — m, max(sqrt(trace J_G / M), |com - through|)
    tol_eccentricity, tol_couple — BALANCE_RTOL * length_scale (m), rtol * trace(J_G) (kg m^2)
    statically_balanced, dynamically_balanced : bool — e <= tol; and |P_G| <= tol_couple
    rtol : float
    warnings : tuple of str"""

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
        return angle_of(z, tol, self.angle_sense)

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


def _tilt(J_body: np.ndarray, frame: ShaftFrame) -> tuple[float, complex, float, float]:
    """Tilt (rad) of the nearest principal axis, its shaft-frame lean (complex), gap, max |moment|.

    v is the projection of e_z onto the eigenspace (moments equal to DEGENERATE_RTOL merged)
    nearest it; tilt = atan2(|v_perp|, v_z). numpy's eigh basis, not principal_axes (its
    snapping would hide small tilts).
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
    inertia_com : (3, 3) array_like — kg m^2, TENSOR about the com, body frame
    axis, through : (3,) array_like — the shaft (default body z) and its point z = 0 (m)
    reference, zero_mark_deg : see :func:`shaft_frame`
    angle_sense : {"with", "against"} — report angles with or against rotation
    rtol : float — relative tolerance of the ideal balanced verdicts (default 1e-9)

    Raises
    ------
    ValueError
        non-positive or non-finite mass, bad shapes, zero axis, bad angle_sense.

    Notes
    -----
    Sheet §2.3, in shaft axes: ``D_xz,G = -J[0, 2]``, ``D_yz,G = -J[1, 2]``,
    ``U = M (x_G + i y_G)``, ``P_G = D_xz,G + i D_yz,G``, ``P = P_G + z_G U``. Tilt (§2.4): the
    eigenvector (or eigenspace) of J_G nearest the shaft, ``tilt = atan2(|e_perp|, e_z)``.
    Verdicts, ideal (to the arithmetic and the input): statically balanced iff
    ``e <= rtol * l``, dynamically iff also ``|P_G| <= rtol * trace(J_G)``, with
    ``l = max(sqrt(trace J_G / M), |com - through|)``; real tolerances: :func:`iso_check`."""
    M = positive(mass, "mass")
    c = vec3(com, "com")
    J = np.asarray(inertia_com, dtype=float)
    if J.shape != (3, 3):
        raise BalanceValueError("inertia_com", f"inertia_com must be 3x3, got shape {J.shape}")
    if not np.all(np.isfinite(J)):
        raise BalanceValueError("inertia_com", "inertia_com must be finite")
    J = 0.5 * (J + J.T)
    sense = check_sense(angle_sense)
    rtol = finite(rtol, "rtol")
    if rtol < 0.0:
        raise BalanceValueError("rtol", "rtol must not be negative")
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
    az = report_deg(math.degrees(cmath.phase(lean)), sense) if az_ok else 0.0
    warns: list[str] = []
    if not well:
        warns.append(
            "the rotor is (nearly) isotropic about its com: the principal moment of the axis "
            "nearest the shaft is within 1e-6 of another, so its principal axes are ill-defined "
            "and tilt_deg is not meaningful; judge dynamic balance by couple_unbalance"
        )
    return Unbalance(
        mass=M,
        com=readonly(c),
        inertia_com=readonly(J),
        frame=frame,
        angle_sense=sense,
        com_shaft=readonly(s),
        inertia_shaft=readonly(Js),
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
    """Equivalent unbalances (U_1, U_2) in planes z1 != z2 (kg m; what a balancing machine
    shows) of U (kg m) and P about z = 0 (kg m^2): U_1 + U_2 = U, z1 U_1 + z2 U_2 = P (sheet §2.5;
    also the bearing forces over Omega^2, §2.6, and the ISO quantity, §1.5)."""
    z1 = finite(z1, "plane position", "planes")
    z2 = finite(z2, "plane position", "planes")
    if z1 == z2:
        raise BalanceValueError("planes", "the two planes must be at different positions along the shaft")
    d = z2 - z1
    return (z2 * static - moment) / d, (moment - z1 * static) / d


def add_point_masses(unb: Unbalance, points: Sequence[tuple[float, object]]) -> Unbalance:
    """Unbalance of the rotor with point masses (kg, position m in the body frame) added: the
    same shaft, mark, angle sense and rtol; mass, com and tensor by the parallel-axis theorem
    (sheet §2.2)."""
    M = unb.mass
    c = np.array(unb.com)
    pts = [(float(m), vec3(p, "point position", "points")) for m, p in points]
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
