"""Principal moments and axes of an inertia tensor, with deterministic conventions.

Moments ascending; ``axes`` rows the unit axes, a proper rotation whose signs make it the
one nearest the body frame (a body tilted 0.5° has axes 0.5° from its body axes; SPEC §3's
"largest component positive" only breaks exact ties). Where moments coincide (to
``DEGENERATE_RTOL``) the axes are aligned with the body axes where possible."""

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
    """Principal decomposition of an inertia tensor: ``moments`` (kg m^2, ascending), ``axes``
    (rows, a proper rotation nearest the identity), ``symmetry`` ("asymmetric", "symmetric",
    "spherical"), ``unique_axis`` (for "symmetric", the index of the moment that differs) and
    ``free_axes`` (the axes free to choose)."""

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
    """Principal moments (ascending) and axes of a symmetric 3x3 inertia tensor (kg m^2):
    :class:`PrincipalAxes`; ValueError for anything but a finite 3x3 matrix. ``eigh`` gives the
    eigenbasis; in a degenerate plane the body axis projecting most on it is projected and
    normalised, the other completes the plane."""
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
    """Each principal axis's tilt from its nearest body axis: (tilt_deg, degrees in
    [0, 54.7356°]; nearest, 0 = x, 1 = y, 2 = z).

    With j the largest |component| of the unit axis u: atan2(sqrt(Σ_{k≠j} u_k²), |u_j|) (exact
    near 0°; below :data:`TILT_ROUND_OFF` it reads 0). The headline of a nearly aligned body,
    whose rotation to axes 1, 2, 3 may be ~90° (issue 24)."""
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
    mass, reference — kg; m, the point the moments are about
    axes_info : PrincipalAxes
    stable, stability — free rotation about each axis: stable (bool); "stable", "unstable" or
        "neutral"
    equivalent_box, equivalent_ellipsoid : (3,) ndarray — m, the uniform box's sides and
        ellipsoid's semi-axes with the same mass and moments
    rotation_axis, rotation_angle_deg — the rotation taking the body axes to axes 1, 2, 3
    tilt_deg, tilt_axis — :func:`axis_tilts`"""

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

    Free rotation about the largest and smallest moment is stable, about the intermediate one
    unstable (e'' = -k W² e, k = (Ij - Ik)(Ij - Il)/(Ik Il); Landau & Lifshitz §37); about an
    axis of a symmetric body's equal pair neutral (k = 0), spherical stable. Equivalent box:
    ``a² = 6 (I₂ + I₃ − I₁)/m``; ellipsoid: ``a² = 5 (I₂ + I₃ − I₁)/(2 m)``."""
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
