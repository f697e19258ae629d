"""Principal moments and axes of an inertia tensor, with deterministic conventions.

Conventions: moments ascending; rows of ``axes`` are the unit axes, a right-handed set
(``axes`` is a proper rotation matrix); their signs are chosen so that this rotation is
the one nearest the body frame (largest trace, i.e. smallest rotation angle), so a body
tilted 0.5° has principal axes 0.5° from its body axes (issue 13, item 6; this replaces
SPEC §3's "largest component positive", which is kept only to break exact ties). Where
moments coincide (to a relative ``DEGENERATE_RTOL``) the eigenspace is a plane or all of
space, and the axes are chosen aligned with the body axes where that is possible.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rbcli.core.rotation import matrix_to_axis_angle

DEGENERATE_RTOL = 1e-9
#: sideways components of a unit principal axis up to this are round-off (8 ulp of 1): its
#: tilt from the body axis reads 0 (``numpy.linalg.eigh`` leaves ~1e-16 on an aligned axis)
TILT_ROUND_OFF = 8.0 * float(np.finfo(float).eps)


@dataclass(frozen=True)
class PrincipalAxes:
    """Principal decomposition of an inertia tensor.

    Attributes
    ----------
    moments : (3,) ndarray — kg m^2, ascending
    axes : (3, 3) ndarray — row i is the unit axis of ``moments[i]`` (body frame);
        ``axes`` is a proper rotation matrix (det +1) taking body to principal coordinates,
        with signs making it the one nearest the identity
    symmetry : str — "asymmetric", "symmetric" or "spherical"
    unique_axis : int | None — for "symmetric", the index (0 or 2) of the moment that differs
    free_axes : tuple[int, ...] — indices of axes that are free to choose (a degenerate eigenspace)
    """

    moments: np.ndarray
    axes: np.ndarray
    symmetry: str
    unique_axis: int | None
    free_axes: tuple[int, ...]


def _sign_fix(v: np.ndarray) -> np.ndarray:
    k = int(np.argmax(np.abs(v)))
    return -v if v[k] < 0 else v


def _close(a: float, b: float, scale: float) -> bool:
    return abs(a - b) <= DEGENERATE_RTOL * scale


def principal_axes(inertia: np.ndarray) -> PrincipalAxes:
    """Principal moments (ascending) and axes of a symmetric 3x3 inertia tensor.

    Parameters
    ----------
    inertia : (3, 3) array_like — kg m^2, tensor convention, symmetric

    Returns
    -------
    PrincipalAxes

    Raises
    ------
    ValueError
        If ``inertia`` is not a 3x3 matrix of finite numbers.

    Notes
    -----
    ``numpy.linalg.eigh`` gives an orthonormal eigenbasis. For a degenerate pair the
    basis of the shared plane is re-chosen: the body axis with the largest projection
    on the plane is projected and normalised, and the other completes the plane.
    """
    J = np.asarray(inertia, dtype=float)
    if J.shape != (3, 3) or not np.all(np.isfinite(J)):
        raise ValueError("the inertia tensor must be a 3x3 matrix of finite numbers")
    J = 0.5 * (J + J.T)
    w, v = np.linalg.eigh(J)
    scale = max(float(np.max(np.abs(w))), np.finfo(float).tiny)
    d01 = _close(w[0], w[1], scale)
    d12 = _close(w[1], w[2], scale)
    E = np.eye(3)
    if d01 and d12:
        mean = float(np.mean(w))
        return PrincipalAxes(np.full(3, mean), E.copy(), "spherical", None, (0, 1, 2))
    if d01 or d12:
        u = 2 if d01 else 0  # the unique moment
        pair = (0, 1) if d01 else (1, 2)
        n = _sign_fix(v[:, u])
        # snap the unique axis to a body axis if it is one to round-off: the other two
        # components (the sine of the angle from that body axis) below 1e-14. (Testing
        # |n_k| against 1 instead would snap axes up to ~1.4e-6 rad away, since
        # 1 - cos(t) ~ t^2/2, and move them by that much.)
        k = int(np.argmax(np.abs(n)))
        if float(np.max(np.abs(np.delete(n, k)))) <= 1e-14:
            n = E[k].copy()
        proj = E - np.outer(E @ n, n)  # body axes projected on the plane
        norms = np.linalg.norm(proj, axis=1)
        k = int(np.argmax(norms))
        a = _sign_fix(proj[k] / norms[k])
        b = _sign_fix(np.cross(n, a))
        # the two free axes in either order (their moments are equal): the frame nearer
        # the body frame wins, so a body tilted about one of its own axes reads as that tilt
        best = None
        for first, second in ((a, b), (b, a)):
            axes = np.empty((3, 3))
            axes[u] = n
            axes[pair[0]] = first
            axes[pair[1]] = second
            axes = _right_handed(axes)
            if best is None or np.trace(axes) > np.trace(best) + 1e-12:
                best = axes
        pm = float(np.mean(w[list(pair)]))
        moments = w.copy()
        moments[list(pair)] = pm
        return PrincipalAxes(moments, best, "symmetric", u, pair)
    axes = np.array([_sign_fix(v[:, 0]), _sign_fix(v[:, 1]), np.zeros(3)])
    axes = _right_handed(axes)
    return PrincipalAxes(w.copy(), axes, "asymmetric", None, ())


#: sign changes of the rows that keep a rotation proper (det +1)
_PROPER_FLIPS = (np.array([1.0, -1.0, -1.0]), np.array([-1.0, 1.0, -1.0]), np.array([-1.0, -1.0, 1.0]))


def _right_handed(axes: np.ndarray) -> np.ndarray:
    """The rows of ``axes`` (unit axes, each up to sign) with signs making a proper rotation
    nearest the identity.

    Of the four sign choices with det +1, the one with the largest trace
    (``trace R = 1 + 2 cos θ``: the smallest rotation angle θ from the body axes). Exact ties
    (within 1e-12, e.g. axes that are the body axes permuted) keep the first candidate: the
    first two axes with their largest component positive, the third their cross product.
    """
    out = axes.copy()
    out[0] = _sign_fix(out[0])
    out[1] = _sign_fix(out[1])
    out[2] = np.cross(out[0], out[1])
    out[2] /= np.linalg.norm(out[2])  # unit to round-off, like the other two
    best, best_trace = out, float(np.trace(out))
    for flip in _PROPER_FLIPS:
        cand = out * flip[:, None]
        tr = float(np.trace(cand))
        if tr > best_trace + 1e-12:
            best, best_trace = cand, tr
    return best


def axis_tilts(axes: np.ndarray) -> tuple[np.ndarray, tuple[int, int, int]]:
    """Each principal axis's tilt from its nearest body axis.

    Parameters
    ----------
    axes : (3, 3) array_like — row i is the unit principal axis i (body frame)

    Returns
    -------
    tilt_deg : (3,) ndarray — degrees, the angle between axis line i and the nearest body
        axis line (the sign of the direction ignored), in [0, 54.7356°]
    nearest : tuple of 3 int — the body axis (0 = x, 1 = y, 2 = z) each is nearest to

    Notes
    -----
    With j the largest |component| of the unit axis u, the tilt is
    atan2(sqrt(Σ_{k≠j} u_k²), |u_j|): exact near 0° where arccos(|u_j|) loses half its
    digits; a sideways part below :data:`TILT_ROUND_OFF` (round-off) reads 0. A line is at most arccos(1/√3) from all three body axes. This is the headline of
    a body whose principal axes are near its body axes: the ascending order of the moments
    may put axis 1 along body z, so the rotation taking the body axes to the principal
    axes 1, 2, 3 can be ~90° for a body tilted 0.5° (issue 24).
    """
    a = np.asarray(axes, dtype=float)
    nearest = tuple(int(k) for k in np.argmax(np.abs(a), axis=1))
    tilt = np.empty(3)
    for i, j in enumerate(nearest):
        others = [k for k in range(3) if k != j]
        off = float(np.linalg.norm(a[i, others]))
        # the round-off of an eigenvector's unit components (a few ulp) is no tilt
        off = 0.0 if off <= TILT_ROUND_OFF else off
        tilt[i] = np.degrees(np.arctan2(off, abs(a[i, j])))
    return tilt, (nearest[0], nearest[1], nearest[2])


@dataclass(frozen=True)
class PrincipalResult:
    """Answer of ``rbcli principal``.

    Attributes
    ----------
    mass : float — kg
    reference : (3,) ndarray — m, the point the moments are about
    axes_info : PrincipalAxes — moments (kg m^2, ascending) and axes (rows)
    stable : tuple[bool, bool, bool] — is free rotation about each axis stable (a neutral
        axis is not: see ``stability``)
    stability : tuple[str, str, str] — "stable", "unstable" or "neutral" per axis
    equivalent_box : (3,) ndarray — m, side along each principal axis of the uniform box
        with the same mass and principal moments
    equivalent_ellipsoid : (3,) ndarray — m, semi-axes of the same for a uniform ellipsoid
    rotation_axis : (3,) ndarray — unit axis of the rotation taking the body axes to the
        principal axes 1, 2, 3 in ascending order of the moments
    rotation_angle_deg : float — its angle (~90° or more when the ascending order permutes
        the body axes, however small the tilts)
    tilt_deg : (3,) ndarray — degrees, each principal axis from its nearest body axis
        (:func:`axis_tilts`)
    tilt_axis : tuple[int, int, int] — that body axis, 0 = x, 1 = y, 2 = z
    """

    mass: float
    reference: np.ndarray
    axes_info: PrincipalAxes
    stable: tuple[bool, bool, bool]
    stability: tuple[str, str, str]
    equivalent_box: np.ndarray
    equivalent_ellipsoid: np.ndarray
    rotation_axis: np.ndarray
    rotation_angle_deg: float
    tilt_deg: np.ndarray
    tilt_axis: tuple[int, int, int]

    @property
    def moments(self) -> np.ndarray:
        return self.axes_info.moments

    @property
    def axes(self) -> np.ndarray:
        return self.axes_info.axes

    @property
    def symmetry(self) -> str:
        return self.axes_info.symmetry

    @property
    def unique_axis(self) -> int | None:
        return self.axes_info.unique_axis

    @property
    def free_axes(self) -> tuple[int, ...]:
        return self.axes_info.free_axes

    @property
    def direction_angles_deg(self) -> np.ndarray:
        """(3, 3) angle of principal axis i from body axis j, degrees (by atan2, exact near 0°)."""
        a = self.axes
        out = np.empty((3, 3))
        for j in range(3):
            others = [k for k in range(3) if k != j]
            out[:, j] = np.degrees(np.arctan2(np.linalg.norm(a[:, others], axis=1), a[:, j]))
        return out


def principal_report(mass: float, inertia: np.ndarray, reference: np.ndarray) -> PrincipalResult:
    """Principal moments and axes of ``inertia`` (about ``reference``) with what they mean.

    Notes
    -----
    Stability of free rotation: about the largest and the smallest principal moment
    it is stable, about the intermediate one unstable (Euler's equations linearised,
    e'' = -k W² e with k = (Ij - Ik)(Ij - Il)/(Ik Il); Landau & Lifshitz §37). Where two
    moments are equal the body is symmetric and every axis of the equal pair is equally
    principal: rotation about the symmetry axis is stable, about an axis of the pair
    neutral (k = 0: a small disturbance makes the spin axis wander round the symmetry axis,
    through the whole plane of the pair; not stable); spherical: every axis is principal
    and any rotation steady, so stable.
    Equivalent uniform box of sides (a, b, c) along the principal axes:
    ``I₁ = m (b² + c²)/12`` … so ``a² = 6 (I₂ + I₃ − I₁)/m``; ellipsoid of semi-axes
    (a, b, c): ``I₁ = m (b² + c²)/5`` so ``a² = 5 (I₂ + I₃ − I₁)/(2 m)``.
    """
    pa = principal_axes(inertia)
    I1, I2, I3 = pa.moments
    words: tuple[str, str, str]
    if pa.symmetry == "asymmetric":
        words = ("stable", "unstable", "stable")
    elif pa.symmetry == "symmetric":
        words = tuple("stable" if i == pa.unique_axis else "neutral" for i in range(3))  # type: ignore[assignment]
    else:
        words = ("stable", "stable", "stable")
    stable = (words[0] == "stable", words[1] == "stable", words[2] == "stable")
    tilt, nearest = axis_tilts(pa.axes)
    s = np.array([I2 + I3 - I1, I1 + I3 - I2, I1 + I2 - I3])
    s = np.clip(s, 0.0, None)
    box = np.sqrt(s / mass) * np.sqrt(6.0)  # divide first: 6 s may overflow where s/m does not
    ell = np.sqrt(s / mass) * np.sqrt(2.5)
    axis, angle = matrix_to_axis_angle(pa.axes.T)
    return PrincipalResult(
        mass=float(mass),
        reference=np.asarray(reference, dtype=float),
        axes_info=pa,
        stable=stable,
        stability=words,
        equivalent_box=box,
        equivalent_ellipsoid=ell,
        rotation_axis=axis,
        rotation_angle_deg=float(np.degrees(angle)),
        tilt_deg=tilt,
        tilt_axis=nearest,
    )
