"""Rotation matrices from the ways a user can write an orientation.

A rotation ``R`` maps a part's LOCAL coordinates to the BODY frame, ``x_body = at + R @
x_local`` (its columns are the local axes in the body frame). Every constructor returns a
proper (3, 3) rotation (orthonormal to ~1e-15) or raises ValueError with a lower-case
message. Quaternions are ``[w, x, y, z]`` (scalar first, Hamilton, ``R(q) v = q v q*``),
shape (..., 4), canonical sign ``w >= 0``. numpy only (scipy's ``Rotation`` costs ~270 ms of
start-up); scipy is the test oracle."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

__all__ = [
    "identity",
    "axis_to_z",
    "axis_angle",
    "euler",
    "quaternion",
    "from_matrix",
    "euler_intrinsic",
    "unit_rows",
    "axis_to_z_rows",
    "axis_angle_rows",
    "euler_rows",
    "quaternion_rows",
    "nearest_rotation_rows",
    "surely_rotation",
    "from_specs",
    "quat_multiply",
    "quat_conjugate",
    "quat_about_axis",
    "quat_canonical",
    "quat_from_matrix",
    "quat_to_matrix",
    "quat_to_axis_angle",
    "matrix_to_axis_angle",
]


def _vector(v: object, n: int, what: str, message: str | None = None) -> np.ndarray:
    """``v`` as a finite float vector of ``n`` components, or ValueError naming ``what``
    (``message`` instead, when given, for every fault)."""
    try:
        a = np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(message or f"{what} must be a list of {n} numbers") from None
    if a.shape != (n,):
        raise ValueError(message or f"{what} must have {n} components, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError(message or f"{what} must be finite")
    return a


def identity() -> np.ndarray:
    """The identity rotation, (3, 3)."""
    return np.eye(3)


def axis_to_z(direction: Sequence[float] | np.ndarray) -> np.ndarray:
    """The rotation that turns local +z onto ``direction`` (a part's ``axis: [x, y, z]``).

    The minimal rotation, about ``n = e_z x d / |e_z x d|`` by the angle between them (Rodrigues,
    with ``cos θ = d_z``, ``sin θ = hypot(d_x, d_y)``: orthonormal even for ``d`` within 1e-12
    of −z); the identity along +z, the half turn about +x, ``diag(1, −1, −1)``, along −z.
    ValueError for a zero or non-finite vector."""
    v = _vector(direction, 3, "axis", "axis must be a non-zero vector")
    if not v.any():
        raise ValueError("axis must be a non-zero vector")
    return axis_to_z_rows(v[None])[0]


def axis_angle(axis: Sequence[float] | np.ndarray, angle_rad: float) -> np.ndarray:
    """The rotation by ``angle_rad`` about ``axis`` (right-hand rule; any non-zero length).

    Rodrigues' formula with ``1 − cos θ = 2 sin²(θ/2)`` (no cancellation at small angles); equal
    to scipy's ``Rotation.from_rotvec(θ n)``. ValueError for a zero or non-finite axis or angle."""
    a = _vector(axis, 3, "axis", "axis must be a non-zero vector")
    if not a.any():
        raise ValueError("axis must be a non-zero vector")
    try:
        theta = float(angle_rad)
    except (TypeError, ValueError):
        raise ValueError("angle must be a number") from None
    if not math.isfinite(theta):
        raise ValueError("angle must be finite")
    return axis_angle_rows(a[None], np.array([theta]))[0]


_EULER_HELP = (
    "1 to 3 letters, all from xyz (extrinsic, fixed axes) or all from XYZ "
    "(intrinsic, moving axes), consecutive letters different, e.g. ZYX, ZXZ, xyz"
)


def euler_intrinsic(seq: str) -> bool:
    """Whether the Euler sequence ``seq`` is intrinsic (``XYZ`` letters) or extrinsic
    (``xyz``); ValueError (saying what is allowed) for an invalid sequence."""
    if not isinstance(seq, str) or not 1 <= len(seq) <= 3:
        raise ValueError(f"euler sequence {seq!r} is not valid: use {_EULER_HELP}")
    if set(seq) <= set("xyz"):
        intrinsic = False
    elif set(seq) <= set("XYZ"):
        intrinsic = True
    else:
        raise ValueError(f"euler sequence {seq!r} is not valid: use {_EULER_HELP}")
    if any(seq[i] == seq[i + 1] for i in range(len(seq) - 1)):
        raise ValueError(
            f"euler sequence {seq!r} is not valid: consecutive letters must differ; "
            f"use {_EULER_HELP}"
        )
    return intrinsic


def euler(angles_rad: float | Sequence[float] | np.ndarray, seq: str) -> np.ndarray:
    """The rotation of an Euler-angle sequence, exactly as scipy defines it.

    Parameters
    ----------
    angles_rad : float or (len(seq),) array_like — rad, one per letter
    seq : str — 1 to 3 letters from ``xyz`` (extrinsic, fixed axes) or ``XYZ`` (intrinsic,
        turned axes), consecutive letters different

    Returns
    -------
    (3, 3) ndarray — ``Rotation.from_euler(seq, angles_rad).as_matrix()`` to round-off

    Notes
    -----
    Intrinsic ``"ABC"`` is ``R_A(α) R_B(β) R_C(γ)``, extrinsic ``"abc"`` ``R_c(γ) R_b(β) R_a(α)``
    (Shuster, "A survey of attitude representations", 1993, §2). ValueError for an invalid
    sequence, a wrong number of angles or a non-finite angle."""
    euler_intrinsic(seq)
    try:
        a = np.asarray(angles_rad, dtype=float)
    except (TypeError, ValueError):
        raise ValueError("euler angles must be numbers") from None
    if a.ndim == 0 and len(seq) == 1:
        a = a.reshape(1)
    if a.shape != (len(seq),):
        raise ValueError(
            f"euler sequence {seq!r} needs {len(seq)} angle{'s' if len(seq) > 1 else ''}, "
            f"got {a.size}"
        )
    if not np.all(np.isfinite(a)):
        raise ValueError("euler angles must be finite")
    return euler_rows(a[None], seq)[0]


def quaternion(q_wxyz: Sequence[float] | np.ndarray) -> np.ndarray:
    """The rotation of a quaternion written scalar-first, ``[w, x, y, z]`` (any non-zero norm:
    it is normalised first; ``q`` and ``−q`` are the same rotation; scipy's ``from_quat`` is
    scalar-LAST). ``R = (w² − v·v) I + 2 v vᵀ + 2 w [v]x``. ValueError for a zero, non-finite or
    wrongly sized quaternion."""
    q = _vector(q_wxyz, 4, "quaternion")
    if not q.any():
        raise ValueError("quaternion must be non-zero")
    return quaternion_rows(q[None])[0]


def _short(x: float) -> str:
    """``3.2e-2`` style: two significant figures, no zero padding in the exponent."""
    mant, exp = f"{x:.1e}".split("e")
    return f"{mant}e{int(exp)}"


def from_matrix(m: Sequence[Sequence[float]] | np.ndarray, tol: float = 1e-6) -> np.ndarray:
    """Accept a user's 3x3 matrix as a rotation and return the nearest exact one.

    ``tol`` is the largest accepted ``max |MᵀM − I|`` (1e-6: typed with 6-7 figures). The result
    is the orthogonal polar factor ``U Vᵀ`` of the SVD, nearest in the Frobenius norm (Higham
    1986), so the user's rounding does not leak into later results. ValueError: "rotation matrix
    is not orthonormal (|MᵀM − I| = 3.2e-2)", "... is a reflection (det = -1), not a rotation",
    a wrong shape or non-finite entries."""
    try:
        a = np.asarray(m, dtype=float)
    except (TypeError, ValueError):
        raise ValueError("rotation matrix must be a 3x3 list of numbers") from None
    if a.shape != (3, 3):
        raise ValueError(f"rotation matrix must be 3x3, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise ValueError("rotation matrix must be finite")
    if not (math.isfinite(tol) and tol >= 0):
        raise ValueError("tolerance must be a finite number >= 0")
    err = float(np.max(np.abs(a.T @ a - np.eye(3))))
    if err > tol:
        raise ValueError(f"rotation matrix is not orthonormal (|MᵀM − I| = {_short(err)})")
    det = float(np.linalg.det(a))
    if det <= 0:
        raise ValueError(f"rotation matrix is a reflection (det = {det:.3g}), not a rotation")
    r = nearest_rotation_rows(a[None])[0]
    if np.linalg.det(r) < 0:  # cannot happen for err <= tol < 1 and det > 0; be safe
        raise ValueError(f"rotation matrix is a reflection (det = {det:.3g}), not a rotation")
    return r


# --- many rotations at once: each ``*_rows`` function returns the (k, 3, 3) stack of its
# one-rotation namesake (which calls it with one row); the body loader makes all its parts'
# rotations of one kind in one call. Inputs are float arrays already checked finite and
# non-zero. sin, cos and hypot are math's, per row (numpy's may differ in the last bit).


#: the identity, made once (read-only)
_EYE = np.eye(3)
_EYE.setflags(write=False)


def unit_rows(v: np.ndarray) -> np.ndarray:
    """Each row of ``v`` (k, n) divided by its length (no zero rows): first by its largest
    magnitude, so that the squared length neither overflows nor underflows."""
    w = v / np.abs(v).max(axis=1)[:, None]
    return w / np.sqrt(np.vecdot(w, w))[:, None]


def _rodrigues_rows(n: np.ndarray, c: np.ndarray, s: np.ndarray, one_minus_c: np.ndarray) -> np.ndarray:
    """R = c I + s [n]x + (1 - c) n nᵀ for each unit axis n (k, 3) (Rodrigues' formula);
    ``one_minus_c`` is given so that callers compute it without cancellation."""
    x, y, z = n[:, 0], n[:, 1], n[:, 2]
    cross = np.zeros((len(n), 3, 3))  # [n]x of each row
    cross[:, 0, 1] = -z
    cross[:, 0, 2] = y
    cross[:, 1, 0] = z
    cross[:, 1, 2] = -x
    cross[:, 2, 0] = -y
    cross[:, 2, 1] = x
    return (c[:, None, None] * _EYE + s[:, None, None] * cross
            + one_minus_c[:, None, None] * (n[:, :, None] * n[:, None, :]))


def axis_to_z_rows(directions: np.ndarray) -> np.ndarray:
    """:func:`axis_to_z` of each row of ``directions`` (k, 3): ``sin θ = hypot(d_x, d_y)``
    and ``1 − cos θ`` as ``s² / (1 + c)`` for c > 0 (which keeps digits near +z), else
    ``1 − c``."""
    d = unit_rows(np.asarray(directions, dtype=float).reshape(-1, 3))
    x, y, c = d[:, 0], d[:, 1], d[:, 2]
    along = (x == 0.0) & (y == 0.0)  # exactly along +z or -z: no minimal axis
    out = np.empty((len(d), 3, 3))
    out[along] = np.where(c[along, None, None] > 0, _EYE, np.diag([1.0, -1.0, -1.0]))
    tilted = ~along
    if tilted.any():
        x, y, c = x[tilted], y[tilted], c[tilted]
        n = unit_rows(np.stack([-y, x, np.zeros(len(x))], axis=1))  # e_z × d
        s = np.array([math.hypot(a, b) for a, b in zip(x.tolist(), y.tolist())])
        with np.errstate(divide="ignore", invalid="ignore"):  # the branch not taken
            one_minus_c = np.where(c > 0, s * s / (1.0 + c), 1.0 - c)
        out[tilted] = _rodrigues_rows(n, c, s, one_minus_c)
    return out


def axis_angle_rows(axes: np.ndarray, angles_rad: np.ndarray) -> np.ndarray:
    """:func:`axis_angle` of each row of ``axes`` (k, 3) with its angle (k,):
    ``1 − cos θ = 2 sin²(θ/2)``."""
    n = unit_rows(np.asarray(axes, dtype=float).reshape(-1, 3))
    theta = np.asarray(angles_rad, dtype=float).reshape(-1).tolist()
    half = np.array([math.sin(t / 2.0) for t in theta])
    c = np.array([math.cos(t) for t in theta])
    s = np.array([math.sin(t) for t in theta])
    return _rodrigues_rows(n, c, s, 2.0 * half * half)


def _elementary_rows(axis: str, angles: list[float]) -> np.ndarray:
    """The right-hand rotations by ``angles`` about the coordinate axis ``axis`` (x, y, z)."""
    e = np.zeros((len(angles), 3, 3))
    c = np.array([math.cos(a) for a in angles]).reshape(-1)
    s = np.array([math.sin(a) for a in angles]).reshape(-1)
    i, j = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}[axis]
    e[:, 3 - i - j, 3 - i - j] = 1.0
    e[:, i, i] = c
    e[:, j, j] = c
    e[:, i, j] = -s
    e[:, j, i] = s
    return e


def euler_rows(angles_rad: np.ndarray, seq: str) -> np.ndarray:
    """:func:`euler` of each row of ``angles_rad`` (k, len(seq)), one valid sequence."""
    intrinsic = euler_intrinsic(seq)
    a = np.asarray(angles_rad, dtype=float).reshape(-1, len(seq))
    r = np.zeros((len(a), 3, 3))
    r[:] = _EYE
    for col, letter in enumerate(seq.lower()):
        e = _elementary_rows(letter, a[:, col].tolist())
        r = r @ e if intrinsic else e @ r
    return r


def quaternion_rows(q_wxyz: np.ndarray) -> np.ndarray:
    """:func:`quaternion` of each row of ``q_wxyz`` (k, 4)."""
    u = unit_rows(np.asarray(q_wxyz, dtype=float).reshape(-1, 4))
    w, x, y, z = u[:, 0], u[:, 1], u[:, 2], u[:, 3]
    R = np.empty((len(u), 3, 3))
    R[:, 0, 0] = 1.0 - 2.0 * (y * y + z * z)
    R[:, 0, 1] = 2.0 * (x * y - w * z)
    R[:, 0, 2] = 2.0 * (x * z + w * y)
    R[:, 1, 0] = 2.0 * (x * y + w * z)
    R[:, 1, 1] = 1.0 - 2.0 * (x * x + z * z)
    R[:, 1, 2] = 2.0 * (y * z - w * x)
    R[:, 2, 0] = 2.0 * (x * z - w * y)
    R[:, 2, 1] = 2.0 * (y * z + w * x)
    R[:, 2, 2] = 1.0 - 2.0 * (x * x + y * y)
    return R


def nearest_rotation_rows(m: np.ndarray) -> np.ndarray:
    """The result of :func:`from_matrix` for each matrix of ``m`` (k, 3, 3), which the
    caller has already accepted (orthonormal within the tolerance, det > 0)."""
    u, _, vt = np.linalg.svd(np.asarray(m, dtype=float).reshape(-1, 3, 3))
    return u @ vt


def surely_rotation(rows: list[list[float]]) -> bool:
    """Whether :func:`from_matrix` surely accepts the 3x3 matrix ``rows`` with its default
    tolerance: orthonormal to 1e-7 (the tolerance is 1e-6; round-off here is ~1e-16) with
    det > 0.5. When not, call :func:`from_matrix` for its exact verdict and message."""
    a = np.array(rows, dtype=float)
    return bool(np.abs(a.T @ a - _EYE).max() < 1e-7 and np.linalg.det(a) > 0.5)


def from_specs(specs: list) -> np.ndarray:
    """The (n, 3, 3) rotations of ``n`` checked specs, made per kind for all at once.

    A spec is None (no rotation), ``("axis", direction)`` (:func:`axis_to_z` of the unit
    direction), ``("axis-angle", axis, angle_rad)`` (:func:`axis_angle` of the unit axis),
    ``("euler", angles_rad, seq)``, ``("quaternion", q_wxyz)``, ``("matrix", rows)`` (one
    :func:`surely_rotation` accepts) or ``("R", matrix)`` (made already). Vectors are
    lists of finite floats, not all zero.
    """
    out = np.empty((len(specs), 3, 3))
    out[:] = _EYE
    groups: dict = {}
    for i, spec in enumerate(specs):
        if spec is not None:
            key = (spec[0], spec[2]) if spec[0] == "euler" else (spec[0], "")
            groups.setdefault(key, []).append(i)
    for (kind, seq), idx in groups.items():
        out[idx] = _kind_rows(kind, seq, [specs[i] for i in idx])
    return out


def _kind_rows(kind: str, seq: str, specs: list) -> np.ndarray:
    """The (k, 3, 3) rotations of :func:`from_specs` for ``specs`` of one kind."""
    vectors = np.array([s[1] for s in specs], dtype=float)
    if kind == "R":
        return vectors
    if kind == "axis":
        return axis_to_z_rows(unit_rows(vectors))
    if kind == "axis-angle":
        return axis_angle_rows(unit_rows(vectors), np.array([s[2] for s in specs]))
    if kind == "euler":
        return euler_rows(vectors, seq)
    if kind == "quaternion":
        return quaternion_rows(vectors)
    return nearest_rotation_rows(vectors)


# --- quaternions and axis-angle ([w, x, y, z], scalar first; arrays broadcast over (..., 4))


def quat_multiply(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Hamilton product ``p q`` of quaternion arrays (..., 4), broadcasting.

    ``R(p q) = R(p) R(q)``: ``q`` is applied first.
    """
    p = np.asarray(p, dtype=float)
    q = np.asarray(q, dtype=float)
    pw, px, py, pz = p[..., 0], p[..., 1], p[..., 2], p[..., 3]
    qw, qx, qy, qz = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack(
        [
            pw * qw - px * qx - py * qy - pz * qz,
            pw * qx + px * qw + py * qz - pz * qy,
            pw * qy - px * qz + py * qw + pz * qx,
            pw * qz + px * qy - py * qx + pz * qw,
        ],
        axis=-1,
    )


def quat_conjugate(q: np.ndarray) -> np.ndarray:
    """``q*`` = ``[w, -x, -y, -z]`` (the inverse rotation for a unit quaternion)."""
    out = np.array(q, dtype=float, copy=True)
    out[..., 1:] *= -1.0
    return out


def quat_about_axis(axis: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """Quaternions (N, 4) of rotations by ``angle`` (N,) rad about the unit ``axis`` (3,)."""
    half = 0.5 * np.atleast_1d(np.asarray(angle, dtype=float))
    s = np.sin(half)
    return np.concatenate([np.cos(half)[:, None], s[:, None] * np.asarray(axis, dtype=float)[None, :]],
                          axis=1)


def quat_canonical(q: np.ndarray) -> np.ndarray:
    """Normalise and choose the sign with ``w >= 0`` (q and -q are the same rotation)."""
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    return np.where(q[..., :1] < 0.0, -q, q)


def _shepperd(R: np.ndarray) -> tuple[float, float, float, float]:
    """Unnormalised quaternion (w, x, y, z) of a proper rotation matrix, Shepperd's method.

    The largest of 1 + tr, 1 + 2 R_ii - tr is square-rooted, so no division is by a small
    number at any angle (S. W. Shepperd, "Quaternion from rotation matrix", J. Guidance
    and Control 1 (1978) 223-224).
    """
    R = np.asarray(R, dtype=float)
    tr = float(np.trace(R))
    k = int(np.argmax([tr, R[0, 0], R[1, 1], R[2, 2]]))
    if k == 0:
        w = 0.5 * math.sqrt(max(1.0 + tr, 0.0))
        return (w, (R[2, 1] - R[1, 2]) / (4 * w), (R[0, 2] - R[2, 0]) / (4 * w),
                (R[1, 0] - R[0, 1]) / (4 * w))
    if k == 1:
        x = 0.5 * math.sqrt(max(1.0 + 2 * R[0, 0] - tr, 0.0))
        return ((R[2, 1] - R[1, 2]) / (4 * x), x, (R[0, 1] + R[1, 0]) / (4 * x),
                (R[0, 2] + R[2, 0]) / (4 * x))
    if k == 2:
        y = 0.5 * math.sqrt(max(1.0 + 2 * R[1, 1] - tr, 0.0))
        return ((R[0, 2] - R[2, 0]) / (4 * y), (R[0, 1] + R[1, 0]) / (4 * y), y,
                (R[1, 2] + R[2, 1]) / (4 * y))
    z = 0.5 * math.sqrt(max(1.0 + 2 * R[2, 2] - tr, 0.0))
    return ((R[1, 0] - R[0, 1]) / (4 * z), (R[0, 2] + R[2, 0]) / (4 * z),
            (R[1, 2] + R[2, 1]) / (4 * z), z)


def quat_from_matrix(R: np.ndarray) -> np.ndarray:
    """Canonical unit quaternion (4,) of a proper rotation matrix (3, 3); Shepperd's method."""
    return quat_canonical(np.array(_shepperd(R), dtype=float))


def quat_to_matrix(q: np.ndarray) -> np.ndarray:
    """Rotation matrices (..., 3, 3) of quaternions (..., 4) (normalised here).

    ``R = (w² − v·v) I + 2 v vᵀ + 2 w [v]x`` written out, with ``R v = q v q*``.
    """
    q = np.asarray(q, dtype=float)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    R = np.empty(q.shape[:-1] + (3, 3))
    R[..., 0, 0] = 1 - 2 * (y * y + z * z)
    R[..., 0, 1] = 2 * (x * y - w * z)
    R[..., 0, 2] = 2 * (x * z + w * y)
    R[..., 1, 0] = 2 * (x * y + w * z)
    R[..., 1, 1] = 1 - 2 * (x * x + z * z)
    R[..., 1, 2] = 2 * (y * z - w * x)
    R[..., 2, 0] = 2 * (x * z - w * y)
    R[..., 2, 1] = 2 * (y * z + w * x)
    R[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return R


def quat_to_axis_angle(q: np.ndarray) -> tuple[np.ndarray | None, float]:
    """Unit axis (or None for no rotation) and angle in [0, π] rad of one quaternion (4,).

    ``angle = 2 atan2(|v|, |w|)`` (accurate at every angle, unlike ``2 acos w``); the axis
    is ``sign(w) v/|v|`` so that the angle is at most π.
    """
    q = np.asarray(q, dtype=float)
    v = q[1:]
    s = float(np.linalg.norm(v))
    angle = 2.0 * math.atan2(s, abs(float(q[0])))
    if s == 0.0:
        return None, angle
    return (np.sign(q[0]) if q[0] != 0 else 1.0) * v / s, angle


def matrix_to_axis_angle(R: np.ndarray) -> tuple[np.ndarray, float]:
    """Unit axis and angle (rad, in [0, π]) of a proper rotation matrix.

    Through Shepperd's quaternion (robust at every angle); for an angle below ~1e-15 rad
    the axis is undefined and ``[0, 0, 1]`` is returned with angle 0.
    """
    w, x, y, z = _shepperd(R)
    v = np.array([x, y, z], dtype=float)
    if w < 0:
        w, v = -w, -v
    s = float(np.linalg.norm(v))
    if s < 1e-15:
        return np.array([0.0, 0.0, 1.0]), 0.0
    return v / s, float(2.0 * np.arctan2(s, w))
