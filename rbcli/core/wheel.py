"""A body of revolution reduced to what rolling needs (:class:`Wheel`: the mass, A across the
axle and C about it, both about the com; :func:`wheel_from_body`), and the checks of the
rolling inputs that name the parameter at fault (:func:`check_geometry`, :func:`param_finite`,
:func:`blame`). Physics sheet ``dynamics.md`` §3; SI."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from rbcli.core.rim import fmt_length as _fmt_length
from rbcli.core.symmetry import ROUND_OFF, AxialSymmetry, Asymmetric, about_axis, axial_moments, pct
from rbcli.errors import InputError, ParamError

__all__ = ["STANDARD_GRAVITY", "Wheel", "wheel_from_body", "check_geometry", "param_finite",
           "blame", "opt_float"]

STANDARD_GRAVITY = 9.80665  # m/s^2


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


def blame(params: tuple[str, ...], message: str) -> Exception:
    """The error for bad values of the parameters ``params`` (the first one is ``param``):
    a :class:`rbcli.errors.ParamError` for one, an InputError naming each parameter for more
    (``{circle}, {speed}: ...``: the Python API spells them as parameters, the command line
    as options, :func:`rbcli.errors.spell`). Callers ``raise`` it."""
    if len(params) == 1:
        return ParamError(params[0], message)
    return InputError(", ".join("{%s}" % p for p in params) + ": " + message, param=params[0])


def param_finite(param: str, what: str, x: float) -> float:
    """``x`` as a float; a ParamError naming ``param`` ("``what`` must be a finite number")
    when it is not finite."""
    x = float(x)
    if not math.isfinite(x):
        raise blame((param,), f"{what} must be a finite number, got {x!r}")
    return x


def check_geometry(a: float, r: float, g: float) -> tuple[float, float, float]:
    """a, r, g checked; errors are ParamErrors naming ``radius``, ``tyre_radius``, ``g``."""
    a = param_finite("radius", "the rim radius a", a)
    if a <= 0.0:
        raise blame(("radius",), f"the rim radius a must be positive, got {a:.6g}")
    r = param_finite("tyre_radius", "the tyre radius r", r)
    g = param_finite("g", "gravity g", g)
    if g <= 0.0:
        raise blame(("g",), f"gravity g must be positive, got {g:.6g}")
    if r < 0.0:
        raise blame(("tyre_radius",), f"the tyre radius r must be >= 0 (0 = knife edge), got {r:.6g} m")
    if r > a:
        raise blame(
            ("tyre_radius",),
            f"the tyre radius r = {r:.6g} m must be at most the rim radius a = {a:.6g} m "
            "(r = a is a sphere)",
        )
    return a, r, g


def _vec(v: Any) -> tuple[float, float, float]:
    a = np.asarray(v, dtype=float).reshape(3)
    return (float(a[0]), float(a[1]), float(a[2]))


def opt_float(x: float | None) -> float | None:
    """None stays None; anything else becomes a float (for ``to_json``)."""
    return None if x is None else float(x)


# --- the wheel


@dataclass(frozen=True)
class Wheel:
    """Mass properties of a body of revolution, reduced to what rolling needs.

    Attributes
    ----------
    mass : float — kg, > 0
    A, C : float — kg m^2, the moments across and about the axle, about the com; 0 < C <= 2 A
    com, axle : tuple of 3 floats — m, the com; the unit axle (body frame)
    com_offset : float — m, distance of the com from the axle line (below tolerance)
    asymmetry : AxialSymmetry or None — the departures of a wheel accepted as nearly of
        revolution (:mod:`rbcli.core.symmetry`); None for one of revolution to rounding

    ``Wheel(mass=1, A=0.25, C=0.5)`` is a thin disk of unit mass and radius 1."""

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
    com : (3,) array_like — m, centre of mass, body frame
    inertia_com : (3, 3) array_like — kg m^2, about the com (tensor convention)
    axle : (3,) array_like — axle direction, body frame (any length); default body z
    sym_rtol : float — how far from a body of revolution it may be (a fraction; default 1e-6):
        of the mean moment across, the spread of the two moments across and the coupling
    axle_through : (3,) array_like or None — m, a point of the axle line; default the origin
    radius : float or None — m, the rim radius, the scale of the com test (default sqrt(C/m))
    off_axis_rtol : float or None — the com may be this times ``radius`` off the axle line
        (default ``sym_rtol``)

    Returns
    -------
    Wheel — the symmetrised wheel, with ``asymmetry`` set, when a departure is above 1e-6

    Raises
    ------
    rbcli.core.symmetry.Asymmetric (a ValueError)
        not of revolution about the axle within the tolerance, with the numbers.
    ValueError
        zero axle, zero or negative moments.

    Notes
    -----
    With n the unit axle: C = n.I.n; A1 <= A2 the eigenvalues of I across n, Ā their mean,
    δ = (A2 - A1)/Ā; the coupling |(1 - n nᵀ) I n|; e the com's distance from the axle.
    Rolling depends on m, G and I only (sheet §3), so the answer is for the symmetrised wheel
    (A = Ā, products dropped, com on the axle). Its error, first order: s_c ∝ sqrt(A)
    (:func:`straight`) and the real A swings between A1 and A2, so s_c is off by at most
    1 - sqrt(1 - δ/2) <= δ/(4 - δ); the coupling moves the moments by at most itself (Weyl;
    Horn and Johnson, *Matrix Analysis*, Theorem 4.3.1); e moves s_c by about e/(2 (a - r))."""
    m = _positive("the mass", mass)
    G = np.asarray(com, dtype=float).reshape(3)
    if not np.all(np.isfinite(G)):
        raise ValueError("the centre of mass and the inertia tensor must be finite")
    J, n, C, A = axial_moments(inertia_com, axle, "axle", "cannot roll on a rim")
    P = np.zeros(3) if axle_through is None else np.asarray(axle_through, dtype=float)
    P = P.reshape(3)
    d = G - P
    offset = float(np.linalg.norm(d - (d @ n) * n))
    L = math.sqrt(C / m) if radius is None else _positive("the rim radius", radius)
    sym = about_axis(m, G, J, G, n, size=L)  # the moments about the com
    sym = dataclasses.replace(sym, com_offset=offset, com_offset_relative=offset / L)
    _require(sym, sym_rtol, sym_rtol if off_axis_rtol is None else off_axis_rtol, n, P,
             axle_through is None, "the rim radius" if radius is not None else
             "the radius of gyration about the axle, sqrt(C/m),")
    return Wheel(mass=m, A=A, C=C, com=_vec(G), axle=_vec(n), com_offset=offset,
                 asymmetry=None if sym.exact else sym)


def _require(sym: AxialSymmetry, tol: float, off_tol: float, n: Any, P: Any, origin: bool,
             scale: str) -> None:
    """Refuse a wheel beyond the tolerance: :class:`Asymmetric` with the numbers, in the
    order products, moments, com (the first that fails); ``scale`` names ``sym.size``."""
    opt = "{symmetry_tol}"  # the parameter, spelled by whoever shows the message (rbcli.errors.spell)
    tol_r, off_r = max(tol, ROUND_OFF), max(off_tol, ROUND_OFF)
    if sym.coupling_relative > tol_r:
        raise Asymmetric(
            "not a body of revolution about the axle: the axle is not a principal axis "
            f"(product of inertia {sym.coupling:.6g} kg m², {pct(sym.coupling_relative)} of the "
            f"moment across, {sym.mean:.6g} kg m²; the nearest principal axis is "
            f"{math.degrees(sym.principal_tilt):.3g}° away); a rolling wheel needs it within "
            f"{opt} ({pct(tol)})", sym, tol)
    if sym.relative > tol_r:
        I1, I2 = sym.transverse
        # enough digits that the two moments print differently
        digits = 6 if not 0.0 < sym.relative < 1e-4 else min(17, math.ceil(-math.log10(sym.relative)) + 2)
        raise Asymmetric(
            "not a body of revolution about the axle: the moments across it are "
            f"{I1:.{digits}g} and {I2:.{digits}g} kg m² (differ by {pct(sym.relative)}); a "
            f"rolling wheel needs them within {opt} ({pct(tol)})", sym, tol)
    if sym.com_offset_relative > off_r:
        def _pt(v: Any) -> str:
            return "[" + ", ".join(f"{float(x):.6g}" for x in v) + "]"

        where = "the body origin" if origin else f"{_pt(P)} m"
        raise Asymmetric(
            f"the centre of mass is {_fmt_length(sym.com_offset)} off the axle (the axle line "
            f"runs along {_pt(n)} through {where}; {pct(sym.com_offset_relative)} of {scale} "
            f"{_fmt_length(sym.size)}); a rolling wheel needs its centre of mass on the axle, "
            f"within {opt} ({pct(off_tol)}) of {scale.rstrip(',')}", sym, off_tol)
