"""How nearly a body is symmetric about an axis: the test behind "nearly symmetric" bodies.

A heavy top, a gyrocompass rotor and a rolling wheel are modelled as bodies of revolution;
a body from CAD is one only to its modelling accuracy. This module measures the departures,
so a command can answer for the *symmetrised* body (the moments across averaged, the
coupling dropped) within a tolerance, say how far that may be off, and refuse beyond it.

With J about the point (tensor convention), n the unit axis, (e1, e2) across it:
C = n·J·n; I1 <= I2 the eigenvalues of [ei·J·ej], Ī their mean; ``relative`` = (I2 - I1)/Ī;
``coupling`` = |[e1·J·n, e2·J·n]|, ``coupling_relative`` = coupling/Ī, ``principal_tilt`` =
½ atan2(2 coupling, |C - Ī|); ``com_offset`` the com's distance from the axis,
``com_offset_relative`` over the radius of gyration sqrt(trace(J_com)/(2 m)) or a given
size. A body passes ``tolerance`` when all three are at most it; below :data:`ROUND_OFF`
nothing is said (Goldstein, Poole and Safko, *Classical Mechanics*, 3rd ed., §5.3-5.4)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


#: departures below this are rounding: the body is symmetric and nothing is reported
ROUND_OFF = 1e-6
#: the default tolerance of ``--symmetry-tol``: 1 % (a CAD body symmetric to 0.01 % passes
#: with a warning; a box 10 % out of square is refused)
DEFAULT_TOLERANCE = 0.01
#: the largest tolerance accepted: beyond 10 % a "symmetrised" body is a different body
MAX_TOLERANCE = 0.1


def inertia_about(mass: float, com, inertia_com, point) -> np.ndarray:
    """kg m², the inertia tensor about ``point`` (m) from the one about the com:
    J_P = J_com + m (|d|² E - d dᵀ), d = com - point (parallel-axis theorem)."""
    c = np.asarray(com, dtype=float).reshape(3)
    p = np.asarray(point, dtype=float).reshape(3)
    J = np.asarray(inertia_com, dtype=float).reshape(3, 3)
    J = 0.5 * (J + J.T)
    d = c - p
    return J + mass * (float(d @ d) * np.eye(3) - np.outer(d, d))


@dataclass(frozen=True)
class AxialSymmetry:
    """How symmetric a body is about an axis through a point (the module docstring's
    quantities): ``axis`` n, ``point`` (m), ``inertia`` J about it, ``axial`` C, ``transverse``
    (I1, I2), ``mean``, ``transverse_axes``, ``relative``, ``coupling``, ``coupling_relative``,
    ``com_offset`` (m), ``com_offset_relative`` and its ``size`` (m)."""

    axis: tuple[float, float, float]
    point: tuple[float, float, float]
    inertia: tuple[tuple[float, float, float], ...]
    axial: float
    transverse: tuple[float, float]
    mean: float
    transverse_axes: tuple[tuple[float, float, float], tuple[float, float, float]]
    relative: float
    coupling: float
    coupling_relative: float
    com_offset: float
    com_offset_relative: float
    size: float

    @property
    def departure(self) -> float:
        """The largest of the three relative departures."""
        return max(self.relative, self.coupling_relative, self.com_offset_relative)

    @property
    def principal_tilt(self) -> float:
        """rad, the angle from the axis to the nearest principal axis of J:
        ½ atan2(2 coupling, |C - mean|)."""
        return 0.5 * math.atan2(2.0 * self.coupling, abs(self.axial - self.mean))

    @property
    def exact(self) -> bool:
        """Symmetric to rounding (every departure at most :data:`ROUND_OFF`)."""
        return self.departure <= ROUND_OFF

    def to_json(self, tolerance: float) -> dict:
        """The JSON ``asymmetry`` object of the commands that accept a nearly symmetric body."""
        return {
            "transverse_moments": [float(self.transverse[0]), float(self.transverse[1])],
            "relative": float(self.relative),
            "coupling": float(self.coupling),
            "coupling_relative": float(self.coupling_relative),
            "principal_axis_tilt": float(self.principal_tilt),
            "com_offset": float(self.com_offset),
            "com_offset_relative": float(self.com_offset_relative),
            "tolerance": float(tolerance),
        }

    def percent(self, size_name: str = "the body's size") -> str:
        """The departures in words: 'the moments across it differ by 0.012 %, ...';
        ``size_name`` names the length scale of the com offset (``"the rim radius"``)."""
        parts = [f"the moments across it differ by {pct(self.relative)}"]
        if self.coupling_relative > ROUND_OFF:
            parts.append(f"its products of inertia with the plane across are {pct(self.coupling_relative)} "
                         "of the moment across")
        if self.com_offset_relative > ROUND_OFF:
            parts.append(f"the centre of mass is {pct(self.com_offset_relative)} of {size_name} "
                         "off it")
        return ", ".join(parts)


class Asymmetric(ValueError):
    """The body departs from symmetry about the axis by more than the tolerance; the
    message gives the numbers and names the tolerance as ``{symmetry_tol}`` (a template the
    caller spells: the API's parameter, the command line's ``--symmetry-tol``).

    Attributes
    ----------
    symmetry : AxialSymmetry
    tolerance : float
    """

    def __init__(self, message: str, symmetry: AxialSymmetry, tolerance: float) -> None:
        super().__init__(message)
        self.symmetry = symmetry
        self.tolerance = tolerance


def axial_moments(inertia_com, axis, axis_name: str,
                  zero: str) -> tuple[np.ndarray, np.ndarray, float, float]:
    """(J, n, C, A) of a body's tensor about its com (symmetrised) and the unit ``axis``:
    C = n·J·n, A the mean of the two moments across n. ValueError, naming the ``axis_name``
    ("axle", "spin axis"), for a non-finite tensor or axis, a zero tensor (``zero`` says why
    that cannot be) or a moment <= 0."""
    J = np.asarray(inertia_com, dtype=float).reshape(3, 3)
    if not np.all(np.isfinite(J)):
        raise ValueError("the centre of mass and the inertia tensor must be finite")
    J = 0.5 * (J + J.T)
    n = np.asarray(axis, dtype=float).reshape(3)
    nn = float(np.linalg.norm(n))
    if not math.isfinite(nn) or nn == 0.0:
        raise ValueError(f"the {axis_name} direction must be a non-zero finite vector")
    n = n / nn
    C = float(n @ J @ n)
    E = across(n)
    A1, A2 = (float(x) for x in np.linalg.eigvalsh(E @ J @ E.T))
    if not max(abs(A1), abs(A2), abs(C)) > 0.0:
        raise ValueError(f"the inertia tensor is zero: a point mass {zero}")
    A = 0.5 * (A1 + A2)
    if C <= 0.0 or A <= 0.0:
        raise ValueError(
            f"the moments about and across the {axis_name} must be positive, got C = {C:.6g} "
            f"and A = {A:.6g} kg m²"
        )
    return J, n, C, A


def pct(x: float) -> str:
    """``x`` as a percentage, 2 digits (messages)."""
    return f"{100.0 * x:.2g} %"


def across(n: np.ndarray) -> np.ndarray:
    """(2, 3): an orthonormal basis (e1, e2 = n × e1) of the plane across the unit vector
    ``n``; e1 is the body axis least aligned with ``n``, made normal to it (Gram–Schmidt)."""
    k = int(np.argmin(np.abs(n)))
    e1 = np.zeros(3)
    e1[k] = 1.0
    e1 = e1 - (e1 @ n) * n
    e1 /= np.linalg.norm(e1)
    return np.array([e1, np.cross(n, e1)])


def about_axis(mass: float, com, inertia_com, point, axis, *, size: float | None = None) -> AxialSymmetry:
    """Measure how symmetric a body is about the line through ``point`` along ``axis``.

    ``mass`` (kg), ``com`` (m), ``inertia_com`` (kg m², tensor), ``point`` (m), ``axis`` (any
    length), ``size`` (m, default the radius of gyration): an :class:`AxialSymmetry`.
    ValueError for a zero or non-finite axis or input, or a zero moment across the axis."""
    n = np.asarray(axis, dtype=float).reshape(3)
    nn = float(np.linalg.norm(n))
    if not (math.isfinite(nn) and nn > 0.0):
        raise ValueError("the axis must be a non-zero finite vector")
    n = n / nn
    J = inertia_about(mass, com, inertia_com, point)
    if not np.all(np.isfinite(J)):
        raise ValueError("the com, the point and the inertia tensor must be finite numbers")
    C = float(n @ J @ n)
    k = int(np.argmin(np.abs(n)))
    e1 = np.cross(n, np.eye(3)[k])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    E = np.array([e1, e2])
    block = E @ J @ E.T
    vals, vecs = np.linalg.eigh(0.5 * (block + block.T))
    I1, I2 = float(vals[0]), float(vals[1])
    mean = 0.5 * (I1 + I2)
    if not mean > 0.0:
        raise ValueError("the moment of inertia across the axis is zero")
    axes = tuple(tuple(float(x) for x in (vecs[0, i] * e1 + vecs[1, i] * e2)) for i in (0, 1))
    cvec = E @ J @ n
    coupling = float(np.linalg.norm(cvec))
    c = np.asarray(com, dtype=float).reshape(3)
    d = c - np.asarray(point, dtype=float).reshape(3)
    off = float(np.linalg.norm(d - (d @ n) * n))
    if size is None:
        Jc = np.asarray(inertia_com, dtype=float).reshape(3, 3)
        size = math.sqrt(max(float(np.trace(Jc)), 0.0) / (2.0 * mass))
    return AxialSymmetry(
        axis=tuple(float(x) for x in n),  # type: ignore[arg-type]
        point=tuple(float(x) for x in np.asarray(point, dtype=float).reshape(3)),  # type: ignore[arg-type]
        inertia=tuple(tuple(float(x) for x in row) for row in J),  # type: ignore[arg-type]
        axial=C,
        transverse=(I1, I2),
        mean=mean,
        transverse_axes=axes,  # type: ignore[arg-type]
        relative=(I2 - I1) / mean,
        coupling=coupling,
        coupling_relative=coupling / mean,
        com_offset=off,
        com_offset_relative=off / size if size > 0.0 else (0.0 if off == 0.0 else math.inf),
        size=float(size),
    )


def require(sym: AxialSymmetry, tolerance: float, subject: str, needs: str) -> None:
    """Refuse a body beyond ``tolerance``: :class:`Asymmetric` with the numbers.

    ``subject`` names the axis (``"the pivot–com axis"``), ``needs`` what the model needs
    (``"a top"``). Each departure beyond the tolerance is named with its numbers and the
    option that sets the tolerance.
    """
    tol = max(tolerance, ROUND_OFF)
    opt = "{symmetry_tol}"  # the parameter, spelled by whoever shows the message (rbcli.errors.spell)
    allowed = f"{needs} needs them within {opt} ({pct(tolerance)})"
    I1, I2 = sym.transverse
    # enough digits that the two moments print differently
    digits = 3 if not 0.0 < sym.relative < 0.01 else min(17, math.ceil(-math.log10(sym.relative)) + 2)
    if sym.relative > tol:
        raise Asymmetric(
            f"the body is not symmetric about {subject}: the moments across it are "
            f"{short_num(I1, digits)} and {short_num(I2, digits)} kg m² (differ by {pct(sym.relative)}); {allowed}",
            sym, tolerance)
    if sym.coupling_relative > tol:
        tilt = math.degrees(sym.principal_tilt)
        raise Asymmetric(
            f"{subject} is not a principal axis of the body: its products of inertia with the "
            f"plane across it are {short_num(sym.coupling)} kg m² ({pct(sym.coupling_relative)} of the "
            f"moment across, {short_num(sym.mean)} kg m²; the nearest principal axis is {tilt:.3g}° "
            f"away); {allowed}", sym, tolerance)
    if sym.com_offset_relative > tol:
        raise Asymmetric(
            f"the centre of mass is {short_num(sym.com_offset)} m off {subject} "
            f"({pct(sym.com_offset_relative)} of the body's size, {short_num(sym.size)} m); {allowed}",
            sym, tolerance)


def short_num(x: float, digits: int = 3) -> str:
    """A short number for messages: 1.2e-3, 0.04, 22 (``digits`` significant figures)."""
    x = float(x)
    if x == 0.0:
        return "0"
    if 1e-2 <= abs(x) < 1e4:
        return f"{x:.{digits}g}"
    mant, exp = f"{x:.{digits - 1}e}".split("e")
    mant = mant.rstrip("0").rstrip(".")
    return f"{mant}e{int(exp)}"
