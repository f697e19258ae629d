"""Two-plane corrections, their rounding, fixed positions and the residual (sheet §2.5).

:func:`corrections` gives the two masses to add (and the single-plane static correction),
:func:`round_corrections` rounds them to a mass and angle step, :func:`split_corrections`
puts them on n equally spaced positions (holes, blades); every result carries the residual
of the rotor with exactly those masses added (sheet §1.5 step 4).
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.balance.common import (
    LARGE_CORRECTION_FRACTION, NARROW_PLANE_FRACTION, BalanceValueError, angle_of, finite,
    internal_deg, pair, positive, wrap_deg,
)
from rbcli.core.balance.frame import Unbalance, add_point_masses, plane_unbalances


@dataclass(frozen=True, eq=False)
class PlaneCorrection:
    """One correction mass to ADD (or remove at ``remove_angle_deg``): ``name`` ("A", "B",
    "static"), ``z`` (m; None for the static one), ``radius`` (m), ``unbalance`` C (kg m),
    ``mass`` |C|/radius (kg), ``angle_deg`` (reported sense; ``angle_defined`` False when
    zero)."""

    name: str
    z: float | None
    radius: float
    unbalance: complex
    mass: float
    angle_deg: float
    angle_defined: bool
    remove_angle_deg: float

def _plane_correction(
    name: str, z: float | None, radius: float, C: complex, tol: float, sense: str
) -> PlaneCorrection:
    a, ok = angle_of(C, tol, sense)
    return PlaneCorrection(
        name=name,
        z=z,
        radius=radius,
        unbalance=C,
        mass=abs(C) / radius,
        angle_deg=a,
        angle_defined=ok,
        remove_angle_deg=wrap_deg(a + 180.0) if ok else 0.0,
    )


@dataclass(frozen=True, eq=False)
class Residual:
    """Unbalance of the rotor with corrections added (sheet §1.5 step 4): ``mass`` (kg),
    ``static`` U + sum C (kg m), ``moment`` about z = 0 and ``couple`` about the new com
    (kg m^2), ``planes``, ``plane_unbalances`` (kg m, §2.5), ``eccentricity`` (m), the
    tolerances of the angle flags and ``angle_sense``."""

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

@dataclass(frozen=True, eq=False)
class Corrections:
    """Two-plane correction of a rotor (sheet §2.5), possibly rounded.

    Attributes
    ----------
    source : Unbalance — the rotor corrected
    planes, radii : (float, float) — m, z_A, z_B and r_A, r_B
    a, b : PlaneCorrection — masses to add in planes A and B
    static : PlaneCorrection — the single-plane correction C = -U at r_A
    narrow_planes, narrow_ratio, narrow_reference, narrow_reference_kind — the narrow-plane rule:
        |z_B - z_A| against NARROW_PLANE_FRACTION of the bearing span or the rotor's length
    bearings : (float, float) or None — m, as given for that rule
    residual : Residual — the rotor with a and b added
    rounded, mass_step, angle_step_deg, ideal — the rounding (kg, deg) and the unrounded
    warnings : tuple of str"""

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
        b1, b2 = pair(bearings, "bearings")
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
    bz = None if bearings is None else pair(bearings, "bearings")
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

    ``unb`` the Unbalance; ``planes`` (z_A, z_B) m, distinct; ``radii`` r or (r_A, r_B) m, > 0;
    ``bearings`` (z_1, z_2) m for the narrow-plane rule only. ValueError for equal planes, a
    radius <= 0, non-finite numbers.

    Notes
    -----
    Sheet §2.5: ``U + C_A + C_B = 0``, ``P + z_A C_A + z_B C_B = 0``, so
    ``C_A = (P - z_B U)/(z_B - z_A)``, ``C_B = (z_A U - P)/(z_B - z_A)``, ``m = |C|/r`` at
    ``arg C``. Narrow planes (§7.9): ``|z_B - z_A| < 0.2 L``, L the bearing span or
    ``sqrt(6 (J_xx + J_yy - J_zz)/M)``."""
    zA, zB = pair(planes, "planes")
    if zA == zB:
        raise BalanceValueError("planes", "the two correction planes must be at different positions (z_A == z_B)")
    if np.ndim(radii) == 0:  # type: ignore[arg-type]
        r = finite(radii, "radius", "radii")
        rA, rB = r, r
    else:
        rA, rB = pair(radii, "radii")
    for r in (rA, rB):
        if not r > 0.0:
            raise BalanceValueError("radii", f"correction radius must be positive, got {r:g}")
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
        m = _round_to(m, mass_step, "mass_step", "kg")
    reported = pc.angle_deg
    if angle_step is not None and pc.angle_defined:
        reported = wrap_deg(_round_to(reported, angle_step, "angle_step_deg", "degrees"))
    if pc.angle_defined:
        phi = math.radians(internal_deg(reported, sense))
    else:  # a zero correction: keep its (meaningless) direction
        phi = cmath.phase(pc.unbalance)
    C = complex(cmath.rect(m * pc.radius, phi))
    a, ok = (reported, True) if (pc.angle_defined and m > 0.0) else angle_of(C, tol, sense)
    return PlaneCorrection(
        name=pc.name,
        z=pc.z,
        radius=pc.radius,
        unbalance=C,
        mass=m,
        angle_deg=a,
        angle_defined=ok,
        remove_angle_deg=wrap_deg(a + 180.0) if ok else 0.0,
    )


def _round_to(x: float, step: float, param: str, unit: str) -> float:
    """``x`` rounded half up to a multiple of ``step``; a step too small for ``x`` (more
    multiples than a float can count) is ``param``'s fault."""
    q = x / step + 0.5
    if not math.isfinite(q):
        raise BalanceValueError(
            param, f"the step {step:g} {unit} is too small to round {x:g} {unit} to a multiple of it")
    return math.floor(q) * step


def round_corrections(
    corr: Corrections,
    mass_step: float | None = None,
    angle_step_deg: float | None = None,
    *,
    bearings: object | None = None,
) -> Corrections:
    """Round correction masses (to ``mass_step`` kg) and reported angles (to ``angle_step_deg``,
    in the reported sense) of ``corr`` (its ideal ones), and recompute the residual with the
    ROUNDED masses (sheet §1.5 step 4: ``U_res = U + C_A' + C_B'``, ``P_res = P + z_A C_A' +
    z_B C_B'``); ``bearings`` as :func:`corrections`."""
    if mass_step is not None:
        mass_step = positive(mass_step, "mass step", "mass_step")
    if angle_step_deg is not None:
        angle_step_deg = positive(angle_step_deg, "angle step", "angle_step_deg")
        if angle_step_deg > 360.0:
            raise BalanceValueError("angle_step_deg", "angle step must not exceed 360 degrees")
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



# --- splitting and radius change


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
    m = finite(mass, "mass")
    phi = math.radians(finite(angle_deg, "angle", "angle_deg"))
    a1 = math.radians(finite(angle1_deg, "angle", "angle1_deg"))
    a2 = math.radians(finite(angle2_deg, "angle", "angle2_deg"))
    den = math.sin(a2 - a1)
    if abs(den) < 1e-12:
        raise BalanceValueError("angle2_deg", "cannot split onto two positions that coincide or are opposite")
    m1 = m * math.sin(a2 - phi) / den
    m2 = m * math.sin(phi - a1) / den
    return Split((m1, m2), (_plain_wrap(angle1_deg), _plain_wrap(angle2_deg)), (-1, -1))


def _plain_wrap(a: float) -> float:
    """Angle in [0, 360) without wrap_deg's snap of the last 1e-9 deg to 0: a position
    angle is where a mass goes, and moving it by 1e-9 deg is a vector error of 1.7e-11 m."""
    a = math.fmod(float(a), 360.0)
    if a < 0.0:
        a += 360.0
    return 0.0 if a >= 360.0 else a + 0.0


def split_to_positions(
    mass: float, angle_deg: float, n_positions: int, offset_deg: float = 0.0
) -> Split:
    """Split a mass onto the two neighbouring of n equally spaced positions at
    ``offset_deg + k * 360/n``: a Split, both masses >= 0 (sheet §2.5, T22: 18 g @ 100 deg onto 8
    positions -> 14.6009 g @ 90 deg, 4.4204 g @ 135 deg)."""
    m = finite(mass, "mass")
    if m < 0.0:
        raise BalanceValueError("mass", "mass to split must not be negative")
    if int(n_positions) != n_positions or n_positions < 3:
        raise BalanceValueError("n_positions", "n_positions must be an integer >= 3")
    n = int(n_positions)
    pitch = 360.0 / n
    if abs(math.sin(math.radians(pitch))) < 1e-12:
        raise BalanceValueError(
            "n_positions",
            f"{n} positions are too many: their pitch ({pitch:.3g}°) is too small to split a "
            "mass onto two of them",
        )
    off = finite(offset_deg, "offset", "offset_deg")
    # plain wrap into [0, 360): wrap_deg's snap of the last 1e-9 deg to 0 would move the
    # mass by up to 1e-9 deg, i.e. a vector error of ~1.7e-11 m
    rel = math.fmod(finite(angle_deg, "angle", "angle_deg") - off, 360.0)
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
    """Two-plane corrections split onto n equally spaced positions: ``ideal``, ``n_positions``,
    ``pitch_deg``, ``offset_deg`` (position 1's angle), ``splits`` (per plane, the masses at
    1-based ``positions``), ``mass_step`` and ``corrections`` (each plane's net and the
    residual with all four masses)."""

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
                phi = math.radians(internal_deg(a, unb.angle_sense))
                s = np.array([pc.radius * math.cos(phi), pc.radius * math.sin(phi), pc.z])
                out.append((pc.name, int(k), float(m), unb.frame.to_body(s)))
        return tuple(out)

def split_corrections(
    corr: Corrections,
    n_positions: int,
    *,
    mass_step: float | None = None,
    offset_deg: float = 0.0,
) -> PositionCorrections:
    """Split each plane's correction onto the two neighbouring of ``n_positions`` fixed positions
    (position 1 at ``offset_deg``), each mass rounded to ``mass_step`` when given.

    Sheet §2.5: ``m1 = |C| sin(a2 - phi)/sin(a2 - a1)``, ``m2 = |C| sin(phi - a1)/sin(a2 - a1)``;
    after rounding each plane's net correction is their vector sum and the residual that of
    the rotor with all the masses added."""
    if mass_step is not None:
        mass_step = positive(mass_step, "mass step", "mass_step")
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
            ms = tuple(_round_to(m, mass_step, "mass_step", "kg") for m in ms)
        pos = tuple(k + 1 for k in sp.positions)
        sp = Split((ms[0], ms[1]), sp.angles_deg, (pos[0], pos[1]))
        C = sum(
            (complex(cmath.rect(m * pc.radius, math.radians(internal_deg(a, s))))
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
        offset_deg=wrap_deg(finite(offset_deg, "offset", "offset_deg")),
        splits=(splits[0], splits[1]),
        mass_step=mass_step,
        corrections=net,
    )


def mass_at_radius(mass: float, radius: float, new_radius: float) -> float:
    """The mass giving the same unbalance at another radius: ``m r / r_new`` (sheet §2.5)."""
    return finite(mass, "mass") * positive(radius, "radius", "radius") / positive(new_radius, "new radius", "new_radius")
