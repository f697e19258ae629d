"""Mass properties of a body made of parts: mass, centre of mass, inertia tensors.

Sign convention: the inertia tensor is the tensor, ``J = ∫ (r·r E − r rᵀ) dm``; its
off-diagonal entries are the negated products of inertia (``Jxy = −∫ x y dm``).
An inertia is never without the point it is taken about: :class:`MassProps` keeps
the tensor about the centre of mass, and :func:`inertia_about` moves it.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # the parts' type only: core imports nothing above it
    from rbcli.body.partmodel import Part


class InputOverflow(ValueError):
    """An input that makes a result impossible or not finite.

    Attributes
    ----------
    param : str — the input at fault: ``"reference"``, ``"axis"`` or ``"omega"``
    """

    def __init__(self, param: str, message: str) -> None:
        super().__init__(message)
        self.param = param


@dataclass(frozen=True)
class MassProps:
    """Mass properties of a rigid body.

    Attributes
    ----------
    mass : float — kg
    com : (3,) ndarray — m, body frame
    inertia_com : (3, 3) ndarray — kg m^2, about the com, body axes, tensor convention
    """

    mass: float
    com: np.ndarray
    inertia_com: np.ndarray


#: the identity, made once (read-only)
_EYE = np.eye(3)
_EYE.setflags(write=False)


def shift_term(mass: float, d: np.ndarray) -> np.ndarray:
    """Parallel-axis term ``m (d·d E − d dᵀ)`` (kg m^2) for an offset ``d`` (m)."""
    d = np.asarray(d, dtype=float)
    return mass * (float(d @ d) * _EYE - d[:, None] * d[None, :])  # d dᵀ: np.outer's products


#: parts summed per step of :func:`combine`
_CHUNK = 4096


def combine(parts: Iterable[Part]) -> MassProps:
    """Mass properties of the union of ``parts`` (subtracted parts count negative).

    ``m = Σ sᵢ mᵢ``, ``c = Σ sᵢ mᵢ cᵢ / m``, ``J_c = Σ sᵢ [Jᵢ + mᵢ (dᵢ·dᵢ E − dᵢ dᵢᵀ)]``,
    ``dᵢ = cᵢ − c`` (Huygens–Steiner), offsets taken from a point near the parts (digits for
    bodies far from the origin), summed in part order by ``np.add.accumulate`` (the loop's
    numbers, bit for bit). ValueError for a mass that is not positive."""
    parts = list(parts)
    if not parts:
        raise ValueError("the body has no parts")
    n = len(parts)
    # sᵢ mᵢ (negation is exact: sᵢ × mᵢ's numbers), and the holes, whose tensors count negative
    m = np.array([-p.mass if p.subtract else p.mass for p in parts], dtype=float)
    holes = [i for i, p in enumerate(parts) if p.subtract]
    c = np.array([p.com for p in parts], dtype=float).reshape(n, 3)
    total = float(m.sum())
    if not total > 0.0:
        raise ValueError(
            f"the total mass is {total:.6g} kg; a body needs a positive mass "
            "(do the subtracted parts remove more than there is?)"
        )
    # a point near the parts, so that far-away bodies keep their digits
    w = np.abs(m)
    origin = (w @ c) / w.sum()
    rel = c - origin
    com_rel = (m @ rel) / total
    d = rel - com_rel
    J = np.zeros((3, 3))
    for a in range(0, n, _CHUNK):  # in chunks: a bounded memory for any number of parts
        b = min(a + _CHUNK, n)
        k = b - a
        dk, mk = d[a:b], m[a:b]
        # terms[0] = the sum so far, then per part: sᵢ Jᵢ, and mᵢ (dᵢ·dᵢ E − dᵢ dᵢᵀ)
        terms = np.empty((2 * k + 1, 3, 3))
        terms[0] = J
        own = np.array([p.inertia_com for p in parts[a:b]], dtype=float).reshape(k, 3, 3)
        mine = [i - a for i in holes if a <= i < b]
        if mine:
            own[mine] *= -1.0  # sᵢ Jᵢ (1.0 × Jᵢ is Jᵢ)
        terms[1::2] = own
        terms[2::2] = mk[:, None, None] * (np.vecdot(dk, dk)[:, None, None] * _EYE
                                           - dk[:, :, None] * dk[:, None, :])
        J = np.add.accumulate(terms, axis=0)[-1]
    J = 0.5 * (J + J.T)
    return MassProps(total, origin + com_rel, J)


def body_mass_props(body: Any) -> MassProps:
    """:func:`combine` of ``body.parts``, computed once per body.

    The loader leaves them on the :class:`rbcli.body.model.Body`; a body made otherwise gets
    them on first use. The arrays are the caller's own copies.
    """
    if not remembered(body):
        remember_mass_props(body, combine(body.parts))
    mp = body._mass_props[1]
    return MassProps(mp.mass, mp.com.copy(), mp.inertia_com.copy())


def remembered(body: Any) -> bool:
    """Whether ``body`` holds its parts' mass properties (the loader's, or an earlier call's)."""
    cached = getattr(body, "_mass_props", None)
    return cached is not None and cached[0] is body.parts


def remember_mass_props(body: Any, mp: MassProps) -> None:
    """Keep ``mp`` (the :func:`combine` of ``body.parts``) on ``body`` for
    :func:`body_mass_props` (not a field: ``dataclasses.replace`` does not carry it)."""
    try:
        object.__setattr__(body, "_mass_props", (body.parts, mp))
    except (AttributeError, TypeError):  # a body-like object without a __dict__
        pass


def part_contributions(parts: Iterable[Part], com: np.ndarray) -> np.ndarray:
    """Each part's contribution (n, 3, 3) (kg m^2, body axes) to the inertia about ``com``: its
    own inertia plus ``m (d·d E − d dᵀ)``, negated for a hole; they sum to ``inertia_com``."""
    com = np.asarray(com, dtype=float)
    out = [(-1.0 if p.subtract else 1.0)
           * (np.asarray(p.inertia_com, dtype=float) + shift_term(p.mass, np.asarray(p.com) - com))
           for p in parts]
    return np.array(out, dtype=float).reshape(-1, 3, 3)


def inertia_about(mp: MassProps, point: np.ndarray) -> np.ndarray:
    """Inertia tensor (kg m^2, body axes) about ``point`` (m)."""
    return mp.inertia_com + shift_term(mp.mass, np.asarray(point, dtype=float) - mp.com)


def checked_inertia_about(mp: MassProps, point: np.ndarray) -> np.ndarray:
    """:func:`inertia_about`, refusing a point so far away that ``m d²`` overflows.

    Raises
    ------
    InputOverflow
        with ``param = "reference"``.
    """
    with np.errstate(over="ignore", invalid="ignore"):
        J = inertia_about(mp, point)
    if not all(map(math.isfinite, J.ravel().tolist())):
        raise InputOverflow(
            "reference", "the inertia about this point overflows: the point is too far from the body"
        )
    return J


def unit_vector(v: np.ndarray, what: str = "the axis") -> np.ndarray:
    """``v / |v|``, exact for tiny (1e-320) and huge components alike.

    Raises
    ------
    ValueError
        If ``v`` is zero or not finite.
    """
    v = np.asarray(v, dtype=float)
    big = float(np.max(np.abs(v))) if v.size else 0.0
    if not (big > 0.0 and np.isfinite(big)):
        raise ValueError(f"{what} must be a non-zero, finite vector")
    v = v / big  # the largest component is now ±1: the norm neither under- nor overflows
    return v / np.linalg.norm(v)


def moment_about_axis(J: np.ndarray, axis: np.ndarray) -> float:
    """Moment of inertia ``n·J·n`` (kg m^2) about the unit vector of ``axis``."""
    n = unit_vector(axis)
    return float(n @ J @ n)


def tensor_problem(J: np.ndarray, rtol: float = 1e-9, *, unit: str = "kg·m²",
                   factor: float = 1.0) -> str | None:
    """Why ``J`` cannot be an inertia tensor, or None if it can.

    Checks symmetry, non-negative principal moments and the triangle inequality
    (each principal moment at most the sum of the other two), each to ``rtol``
    relative to the largest entry. Moments in the message are quoted as ``J / factor``
    followed by ``unit`` (e.g. ``factor=1e-9, unit="g·mm²"`` for a file in g and mm).
    """
    J = np.asarray(J, dtype=float)
    if J.shape != (3, 3) or not np.all(np.isfinite(J)):
        return "it must be a 3x3 matrix of finite numbers"
    scale = float(np.abs(J).max())
    if scale == 0.0:
        return None
    asym = float(np.abs(J - J.T).max())
    if asym > rtol * scale:
        return f"it is not symmetric (|J − Jᵀ| = {asym / factor:.3g} {unit})"
    w = np.linalg.eigvalsh(0.5 * (J + J.T))
    if w[0] < -rtol * scale:
        return f"it has a negative principal moment ({w[0] / factor:.6g} {unit})"
    if w[2] > w[0] + w[1] + rtol * scale:
        q = w / factor
        return (
            f"its principal moments ({q[0]:.6g}, {q[1]:.6g}, {q[2]:.6g} {unit}) break the "
            "triangle inequality: no mass distribution has one moment larger than "
            "the sum of the other two"
        )
    return None


@dataclass(frozen=True)
class InertiaResult:
    """Answer of ``rbcli inertia``: ``mass`` (kg), ``com`` and ``reference`` (m), ``inertia`` and
    ``inertia_com`` (kg m^2), and with an axis or ω ``axis``, ``axis_moment`` (``n·J·n``),
    ``omega``, ``angular_momentum`` (``L = J ω``), ``kinetic_energy`` (``ω·J·ω/2``),
    ``angle_L_omega_deg``."""

    mass: float
    com: np.ndarray
    reference: np.ndarray
    inertia: np.ndarray
    inertia_com: np.ndarray
    axis: np.ndarray | None = None
    axis_moment: float | None = None
    omega: np.ndarray | None = None
    angular_momentum: np.ndarray | None = None
    kinetic_energy: float | None = None
    angle_L_omega_deg: float | None = None


def angle_between_deg(a: np.ndarray, b: np.ndarray) -> float:
    """Angle between two vectors in degrees (0 when either is zero), by atan2 for accuracy."""
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    if not (np.any(a) and np.any(b)):
        return 0.0
    a, b = unit_vector(a, "a vector"), unit_vector(b, "a vector")
    return float(np.degrees(np.arctan2(np.linalg.norm(np.cross(a, b)), float(a @ b))))


def inertia_report(
    mp: MassProps,
    reference: np.ndarray,
    axis: np.ndarray | None = None,
    omega: np.ndarray | None = None,
) -> InertiaResult:
    """Inertia about a point, the moment about an axis through it, and L, T for a spin ω:
    ``J_P = J_G + m (d·d E − d dᵀ)``, ``I_n = n·J_P·n``, ``L = J_P ω``, ``T = ω·J_P·ω / 2``
    (Goldstein §5.3, §5.4). :class:`InputOverflow` (naming the input) for a zero or non-finite
    axis, or a result above 1e308."""
    ref = np.asarray(reference, dtype=float)
    J = checked_inertia_about(mp, ref)
    kw: dict = {}
    if axis is not None:
        try:
            n = unit_vector(axis)
        except ValueError as exc:
            raise InputOverflow("axis", str(exc)) from None
        kw["axis"] = n
        kw["axis_moment"] = moment_about_axis(J, n)
    if omega is not None:
        w = np.asarray(omega, dtype=float)
        with np.errstate(over="ignore", invalid="ignore"):
            L = J @ w
            T = 0.5 * float(w @ L)
        if not (np.all(np.isfinite(L)) and np.isfinite(T)):
            raise InputOverflow(
                "omega", "the angular momentum or kinetic energy overflows: the angular velocity is too large"
            )
        kw["omega"] = w
        kw["angular_momentum"] = L
        kw["kinetic_energy"] = T
        kw["angle_L_omega_deg"] = angle_between_deg(L, w)
    return InertiaResult(mp.mass, mp.com.copy(), ref, J, mp.inertia_com.copy(), **kw)
