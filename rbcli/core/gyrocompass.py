"""The gyrocompass: the period of its swing about north and where it settles.

Pure physics in SI units. Model: a rotor of axial moment C and transverse moment A (both
about its centre of mass) spins at S about its axis; the axis is held horizontal and is
free to turn about the vertical, at latitude λ on the Earth rotating at Ω_E. The
horizontal component Ω_E cos λ of the Earth's rotation, acting on the rotor's angular
momentum C S, gives a torque that swings the axis about the meridian; the equation of
motion below is the standard undamped one (see e.g. https://en.wikipedia.org/wiki/Gyrocompass,
"Mathematical model"), with the centrifugal Ω_E² term kept.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rbcli.core.symmetry import AxialSymmetry, about_axis, axial_moments, require
from rbcli.core.checks import finite, json_float

#: Earth's sidereal rotation rate, rad/s (IERS conventions).
EARTH_RATE = 7.2921150e-5


@dataclass(frozen=True)
class Gyrocompass:
    """Small oscillation of a gyrocompass about the meridian: ``C_over_A``, ``spin`` (rad/s),
    ``latitude`` (rad), ``earth_rate`` Ω_E (rad/s), ``directive`` C S Ω_E cos λ / A (1/s²),
    ``omega0`` sqrt(|directive| - Ω_E² cos² λ) and ``omega0_approx`` sqrt(|directive|) (rad/s;
    None without a restoring torque), ``period`` (s) and ``settles_to`` ("north" for S > 0)."""

    C_over_A: float
    spin: float
    latitude: float
    earth_rate: float
    directive: float
    omega0: float | None
    omega0_approx: float | None
    period: float | None
    settles_to: str | None

    @property
    def horizontal_earth_rate(self) -> float:
        """rad/s, Ω_E cos λ (exactly 0 at a pole)."""
        return self.earth_rate * (0.0 if abs(self.latitude) >= 0.5 * math.pi else math.cos(self.latitude))

    @property
    def period_approx(self) -> float | None:
        """s, 2π/omega0_approx, the period from the usual estimate (None with no directive
        torque)."""
        return (2.0 * math.pi / self.omega0_approx) if (self.omega0_approx and self.period) else None

    def to_json(self) -> dict:
        return {
            "C_over_A": float(self.C_over_A),
            "spin": float(self.spin),
            "latitude_deg": math.degrees(self.latitude),
            "earth_rate": float(self.earth_rate),
            "directive": json_float(self.directive),
            "omega0": json_float(self.omega0),
            "omega0_approx": json_float(self.omega0_approx),
            "period": json_float(self.period),
            "settles_to": self.settles_to,
        }


def gyrocompass(
    C_over_A: float,
    spin_rad_s: float,
    latitude_rad: float,
    earth_rate: float = EARTH_RATE,
) -> Gyrocompass:
    """Period of small oscillation of a gyrocompass about north.

    ``C_over_A`` > 0, spin S (rad/s, nonzero), latitude λ (rad, [-π/2, π/2]), Earth rate Ω_E
    (rad/s, default sidereal): a Gyrocompass; ValueError out of range or on overflow.

    Notes
    -----
    Axis horizontal, free in azimuth α: A α'' = -C S Ω_E cos λ sin α + A Ω_E² cos²λ sin α cos α;
    about α = 0 (S > 0) or π (S < 0): ω0² = |C S Ω_E cos λ|/A - Ω_E² cos²λ, T = 2π/ω0."""
    r = finite("C_over_A", C_over_A)
    S = finite("spin", spin_rad_s)
    lat = finite("latitude", latitude_rad)
    W = finite("earth_rate", earth_rate)
    if r <= 0.0:
        raise ValueError(f"C/A must be positive, not {r}")
    if W <= 0.0:
        raise ValueError(f"the Earth's rotation rate must be positive, not {W}")
    if abs(lat) > 0.5 * math.pi * (1.0 + 1e-12):
        raise ValueError(f"latitude must be between -90 and 90 degrees, not {math.degrees(lat):.6g}")
    if S == 0.0:
        raise ValueError("a gyrocompass needs a spinning rotor: the spin is 0")
    cl = math.cos(lat) if abs(lat) < 0.5 * math.pi else 0.0
    k = r * S * W * cl
    w2 = abs(k) - (W * cl) * (W * cl)
    if not (math.isfinite(k) and math.isfinite(w2)):
        raise ValueError(
            f"the directive torque per unit moment C S W cos(latitude)/A overflows floating point "
            f"(C/A = {r:.6g}, spin {S:.6g} rad/s, Earth rate {W:.6g} rad/s); give values of a "
            "physical size"
        )
    if w2 > 0.0:
        w0: float | None = math.sqrt(w2)
        w0a: float | None = math.sqrt(abs(k))
        per: float | None = 2.0 * math.pi / w0
        where: str | None = "north" if S > 0 else "south"
    else:
        w0 = per = where = None
        w0a = math.sqrt(abs(k)) if k != 0.0 else None
    return Gyrocompass(
        C_over_A=r, spin=S, latitude=lat, earth_rate=W, directive=k, omega0=w0,
        omega0_approx=w0a, period=per, settles_to=where,
    )  # fmt: skip


@dataclass(frozen=True)
class Rotor:
    """A rotor's moments about its centre of mass.

    Attributes
    ----------
    C : float — kg m², about the spin axis
    A : float — kg m², across the spin axis (the mean of the two transverse moments)
    mass : float — kg
    axis : tuple[float, float, float] — the unit spin axis, body frame
    asymmetry : AxialSymmetry | None — for a rotor accepted as nearly symmetric (above
        rounding, within the tolerance): how far it departs; None when symmetric
    """

    C: float
    A: float
    mass: float
    axis: tuple[float, float, float]
    asymmetry: AxialSymmetry | None = None


def rotor_from_body(mass: float, com, inertia_com, axis, *, sym_rtol: float = 1e-6) -> Rotor:
    """C and A (:func:`rbcli.core.symmetry.axial_moments`, its ValueErrors) of a body (nearly)
    symmetric about its spin ``axis``; :class:`rbcli.core.symmetry.Asymmetric` beyond
    ``sym_rtol`` (:func:`rbcli.core.symmetry.require`)."""
    m = finite("the mass", mass)
    if m <= 0.0:
        raise ValueError(f"the mass must be positive, got {m:.6g}")
    J, n, C, A = axial_moments(inertia_com, axis, "spin axis", "cannot be a rotor")
    sym = about_axis(m, com, J, com, n)
    require(sym, sym_rtol, "its spin axis", "a gyrocompass rotor")
    return Rotor(C=C, A=A, mass=m, axis=tuple(float(x) for x in n),  # type: ignore[arg-type]
                 asymmetry=None if sym.exact else sym)
