"""Principal moments and axes of an inertia tensor, with deterministic conventions.

Conventions (SPEC §3): moments ascending; rows of ``axes`` are the unit axes; each of
the first two axes has its largest-magnitude component positive; the third completes
a right-handed set. Where moments coincide (to a relative ``DEGENERATE_RTOL``) the
eigenspace is a plane or all of space, and the axes are chosen aligned with the body
axes where that is possible.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

DEGENERATE_RTOL = 1e-9


@dataclass(frozen=True)
class PrincipalAxes:
    """Principal decomposition of an inertia tensor.

    Attributes
    ----------
    moments : (3,) ndarray — kg m^2, ascending
    axes : (3, 3) ndarray — row i is the unit axis of ``moments[i]`` (body frame);
        ``axes`` is a proper rotation matrix (det +1) taking body to principal coordinates
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

    Notes
    -----
    ``numpy.linalg.eigh`` gives an orthonormal eigenbasis. For a degenerate pair the
    basis of the shared plane is re-chosen: the body axis with the largest projection
    on the plane is projected and normalised, and the other completes the plane.
    """
    J = np.asarray(inertia, dtype=float)
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
        # snap the unique axis to a body axis if it is one to round-off
        k = int(np.argmax(np.abs(n)))
        if abs(abs(n[k]) - 1.0) < 1e-12:
            n = E[k].copy()
        proj = E - np.outer(E @ n, n)  # body axes projected on the plane
        norms = np.linalg.norm(proj, axis=1)
        k = int(np.argmax(norms))
        a = _sign_fix(proj[k] / norms[k])
        b = _sign_fix(np.cross(n, a))
        axes = np.empty((3, 3))
        axes[u] = n
        axes[pair[0]] = a
        axes[pair[1]] = b
        pm = float(np.mean(w[list(pair)]))
        moments = w.copy()
        moments[list(pair)] = pm
        axes = _right_handed(axes)
        return PrincipalAxes(moments, axes, "symmetric", u, pair)
    axes = np.array([_sign_fix(v[:, 0]), _sign_fix(v[:, 1]), np.zeros(3)])
    axes = _right_handed(axes)
    return PrincipalAxes(w.copy(), axes, "asymmetric", None, ())


def _right_handed(axes: np.ndarray) -> np.ndarray:
    out = axes.copy()
    out[0] = _sign_fix(out[0])
    out[1] = _sign_fix(out[1])
    out[2] = np.cross(out[0], out[1])
    return out
