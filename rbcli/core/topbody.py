"""A body reduced to a heavy symmetric top on a fixed pivot (``rbcli top``): :func:`top_from_body`
gives the :class:`TopParams` (l, I about the pivot, Is) the closed form of :mod:`rbcli.core.top`
needs, or refuses a body that is not a symmetric top about the pivot–com axis with the numbers
(:mod:`rbcli.core.symmetry`). SI; Goldstein, Poole and Safko, *Classical Mechanics*, 3rd ed.,
§5.7; physics sheet ``dynamics.md`` §2 "Setup", §4b item 6."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rbcli.core.checks import finite
from rbcli.core.symmetry import AxialSymmetry, about_axis, require, short_num

#: Pivot closer to the com than this fraction of the body's size: no top.
PIVOT_AT_COM_RTOL = 1e-9


class PivotAtCom(ValueError):
    """The pivot is at the centre of mass: there is no gravity torque, no heavy top."""


class NotATop(ValueError):
    """The body is not a symmetric top about the pivot–com axis (asymmetric, the axis not
    principal, or no moment about the axis); the message says how, with the numbers."""


@dataclass(frozen=True)
class TopParams:
    """Mass properties of a symmetric top about its pivot: ``mass`` (kg), ``length`` l from the
    pivot to the com (m), ``I`` across the axis (I_cm + m l²) and ``Is`` about it (kg m^2);
    with a body, ``axis`` e3 (pivot to com), ``pivot``, ``com`` (body frame) and ``asymmetry``
    (a nearly symmetric body's departures and real tensor; I is then the mean across)."""

    mass: float
    length: float
    I: float  # noqa: E741 - the sheet's name
    Is: float
    axis: tuple[float, float, float] | None = None
    pivot: tuple[float, float, float] | None = None
    com: tuple[float, float, float] | None = None
    asymmetry: AxialSymmetry | None = field(default=None, repr=False)

    def __post_init__(self) -> None:
        for name in ("mass", "length", "I", "Is"):
            v = finite(name, getattr(self, name))
            if v <= 0.0:
                raise ValueError(f"{name} of a top must be positive, not {v}")

    def to_json(self) -> dict:
        out: dict = {"mass": self.mass, "length": self.length, "I": self.I, "Is": self.Is}
        for k in ("axis", "pivot", "com"):
            v = getattr(self, k)
            out[k] = None if v is None else [float(c) for c in v]
        return out


def top_from_body(
    mass: float,
    com: np.ndarray,
    inertia_com: np.ndarray,
    pivot: np.ndarray,
    *,
    sym_rtol: float = 1e-6,
) -> TopParams:
    """Reduce a body's mass properties to a symmetric (or nearly symmetric) top on a pivot.

    Parameters
    ----------
    mass : float — kg, > 0
    com : (3,) array_like — m, centre of mass, body frame
    inertia_com : (3, 3) array_like — kg m^2, about the com (tensor convention)
    pivot : (3,) array_like — m, the fixed point, body frame
    sym_rtol : float — tolerance of "symmetric about the pivot–com axis"
        (:mod:`rbcli.core.symmetry`); within it, above rounding, the top is symmetrised and its
        departures kept in ``TopParams.asymmetry``

    Raises
    ------
    PivotAtCom
        the pivot at the com (to ``PIVOT_AT_COM_RTOL``): free precession, not a top.
    rbcli.core.symmetry.Asymmetric
        not symmetric about the axis within ``sym_rtol``, or no moment about it (a pendulum).
    ValueError
        a non-finite input or a mass <= 0.

    Notes
    -----
    e3 = (com - pivot)/l (SPEC §2 ``top``); I_pivot = I_com + m (l² E - d dᵀ); Is = e3·I·e3, the
    moments across the eigenvalues of I_pivot's block across e3 (sheet §2 "Setup", §4b item 6)."""
    m = finite("mass", mass)
    if m <= 0.0:
        raise ValueError(f"the mass of a top must be positive, not {m}")
    c = np.asarray(com, dtype=float).reshape(3)
    p = np.asarray(pivot, dtype=float).reshape(3)
    J = np.asarray(inertia_com, dtype=float).reshape(3, 3)
    if not (np.all(np.isfinite(c)) and np.all(np.isfinite(p)) and np.all(np.isfinite(J))):
        raise ValueError("the com, pivot and inertia tensor must be finite numbers")
    J = 0.5 * (J + J.T)
    d = c - p
    length = float(np.linalg.norm(d))
    r_gyr = math.sqrt(max(float(np.trace(J)), 0.0) / (2.0 * m))
    size = max(r_gyr, float(np.linalg.norm(c)), float(np.linalg.norm(p)))
    if length == 0.0 or length <= PIVOT_AT_COM_RTOL * size:
        raise PivotAtCom(
            f"the pivot is at the centre of mass (they are {short_num(length)} m apart): gravity "
            "exerts no torque about it, so this is not a heavy top; for torque-free motion "
            "use `rbcli precess`"
        )
    e3 = d / length
    Ip = J + m * (length**2 * np.eye(3) - np.outer(d, d))
    Is = float(e3 @ Ip @ e3)
    # a basis of the transverse plane
    k = int(np.argmin(np.abs(e3)))
    e1 = np.cross(e3, np.eye(3)[k])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(e3, e1)
    mean = 0.5 * (float(e1 @ Ip @ e1) + float(e2 @ Ip @ e2))  # the symmetrised moment across
    if mean <= 0.0:
        raise NotATop("the moment of inertia across the pivot–com axis is zero")
    sym = about_axis(m, c, J, p, e3)
    require(sym, sym_rtol, "the pivot–com axis", "a top")
    if Is <= 1e-12 * mean:
        raise NotATop(
            f"the body has no moment of inertia about the pivot–com axis (Is = {short_num(Is)} "
            "kg m²: a point mass or a thin rod along the axis): it cannot carry spin, so it "
            "is a spherical pendulum, not a top"
        )
    return TopParams(
        mass=m,
        length=length,
        I=mean,
        Is=Is,
        axis=tuple(float(v) for v in e3),  # type: ignore[arg-type]
        pivot=tuple(float(v) for v in p),  # type: ignore[arg-type]
        com=tuple(float(v) for v in c),  # type: ignore[arg-type]
        asymmetry=None if sym.exact else sym,
    )
