"""The exact torque-free motion in time: ω(t), the attitude R(t) and the precession angle.

:func:`omega_at` and :func:`attitude_at` evaluate the closed
forms whose constants :func:`rbcli.core.freemotion.analyse` computes, at any array of times
(the cost does not grow with ``t``: no numerical integration; the phase is reduced modulo
the period). Conventions as in :mod:`rbcli.core.freemotion` (principal frame, ``R(0) = 1``,
quaternions ``[w, x, y, z]`` scalar first, canonicalised to ``w >= 0``).

Sources: physics sheet ``dynamics.md`` §1.1–1.2 — Landau & Lifshitz §37; Celledoni, Fassò,
Säfström & Zanna (2008) with Leroy's corrections (Principia, ``documentation/Celledoni.tex``).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.core.elliptic import ellippi_sc
from rbcli.core.elliptic import jacobi_reduced as _jacobi
from rbcli.core.rotation import quat_about_axis as _qaxis
from rbcli.core.rotation import quat_canonical as _qcanon
from rbcli.core.rotation import quat_multiply as _qmul

if TYPE_CHECKING:
    from rbcli.core.freemotion import FreeMotion

__all__ = ["omega_at", "attitude_at", "big_phase", "ll_quat", "CASE_REST",
           "CASE_SPHERICAL", "CASE_STEADY", "CASE_MAX", "CASE_MIN", "CASE_SEPARATRIX"]

#: ``FreeMotion.case`` values: the kinds of motion :func:`rbcli.core.freemotion.analyse` tells
#: apart, each evaluated in its own way here.
CASE_REST = "rest"  # omega = 0
CASE_SPHERICAL = "spherical"  # I1 = I2 = I3: steady rotation about omega0
CASE_STEADY = "steady"  # omega0 along a principal axis: omega constant
CASE_MAX = "circulates_max"  # omega circles axis 3 (largest moment); symmetric oblate too
CASE_MIN = "circulates_min"  # omega circles axis 1 (smallest moment); symmetric prolate too
CASE_SEPARATRIX = "separatrix"  # G^2 = 2 T I2: homoclinic, not periodic

_TWO_PI = 2.0 * math.pi


def big_phase(j: np.ndarray, per: float) -> np.ndarray:
    """``j * per`` reduced modulo 2 pi without forming the huge product first."""
    return np.fmod(j * math.fmod(per, _TWO_PI), _TWO_PI)


def _times(t: Any) -> np.ndarray:
    tt = np.atleast_1d(np.asarray(t, dtype=float))
    if tt.ndim != 1:
        raise ValueError("t must be a number or a 1-d array of times")
    if not np.all(np.isfinite(tt)):
        raise ValueError("times must be finite")
    return tt


def _elliptic_state(motion: FreeMotion, t: np.ndarray) -> dict[str, np.ndarray]:
    """Principal-frame omega and the reduced phase data of an elliptic / separatrix motion."""
    el = motion.elliptic
    assert el is not None
    A1, A2, A3 = el.amplitudes
    tau = el.lam * t + el.tau0
    if el.kind == "separatrix":
        s1, s3 = el.signs
        a = np.abs(tau)
        e2 = np.exp(-2.0 * a)
        sech = 2.0 * np.exp(-a) / (1.0 + e2)
        th = np.tanh(tau)
        w = np.stack([s1 * A1 * sech, s1 * s3 * A2 * th, s3 * A3 * sech], axis=1)
        return {"w": w, "tanh": th}
    K = float(el.K)  # type: ignore[arg-type]
    j4 = np.floor((tau + 2.0 * K) / (4.0 * K))
    taur = tau - 4.0 * K * j4
    sn, cn, dn, j2, snu, cnu = _jacobi(taur, K, el.m, el.mc)
    s = el.signs[0]
    if el.kind == "3":
        w = np.stack([A1 * cn, s * A2 * sn, s * A3 * dn], axis=1)
    else:
        w = np.stack([s * A1 * dn, s * A2 * sn, A3 * cn], axis=1)
    return {"w": w, "j4": j4, "taur": taur, "j2": j2, "snu": snu, "cnu": cnu, "dnu": dn}


def omega_at(motion: FreeMotion, t: Any, *, frame: str = "body") -> np.ndarray:
    """Exact angular velocity (rad/s, (N, 3)) at the times ``t`` (s, any size: the phase is
    reduced modulo the period) in the body frame, or ``frame="principal"``. Sheet §1.1–1.2:
    sn, cn, dn of tau = lambda t + tau0; sech/tanh on the separatrix; w_perp exp(i (W t +
    delta)) for a symmetric body."""
    tt = _times(t)
    if frame not in ("body", "principal"):
        raise ValueError("frame must be 'body' or 'principal'")
    axes = motion.axes
    if motion.elliptic is not None:
        wp = _elliptic_state(motion, tt)["w"]
    elif motion.symmetry == "symmetric" and motion.case in (CASE_MAX, CASE_MIN):
        u = int(motion.symmetry_index)  # type: ignore[arg-type]
        a, b = (u + 1) % 3, (u + 2) % 3  # cyclic: (a, b, u) right-handed
        w0 = motion.omega0_principal
        ang = float(motion.precession_rate) * tt  # type: ignore[arg-type]
        ca, sa = np.cos(ang), np.sin(ang)
        wp = np.empty((tt.size, 3))
        wp[:, a] = w0[a] * ca - w0[b] * sa
        wp[:, b] = w0[a] * sa + w0[b] * ca
        wp[:, u] = w0[u]
    else:
        wp = np.tile(motion.omega0_principal, (tt.size, 1))
    return wp if frame == "principal" else wp @ axes


def _phi_parts(
    motion: FreeMotion, t: np.ndarray, st: dict[str, np.ndarray] | None
) -> tuple[np.ndarray, np.ndarray]:
    """phi(t) - phi(0) = j4 * (Delta phi per period) + local; returns (j4, local)."""
    el = motion.elliptic
    assert el is not None
    if st is None:
        st = _elliptic_state(motion, t)
    if el.kind == "separatrix":
        r = math.sqrt(-el.n)
        local = el._G / motion.moments[1] * t + el.coeff * (np.arctan(r * st["tanh"]) - el._pi_tau0)
        return np.zeros_like(t), local
    pi_tau = ellippi_sc(el.n, st["snu"], st["cnu"], el.m, el.mc) + 2.0 * st["j2"] * el.pi_complete
    local = (el._G / el._Ic) * (st["taur"] - el.tau0) / el.lam + el.coeff * (pi_tau - el._pi_tau0)
    return st["j4"], local


def attitude_at(motion: FreeMotion, t: Any) -> np.ndarray:
    """Exact orientation: quaternions ``[w, x, y, z]`` (N, 4), ``w >= 0``, of the body-to-space
    R(t), R(0) = 1, so ``R(t) @ (I omega(t)) = motion.angular_momentum`` for every t.

    Notes
    -----
    Asymmetric (sheet §1.2): with the dn axis c last (a proper permutation Pm),
    R_ZL(t) = Rz(phi) Rx(theta) Rz(psi) Pm (Z along L, M_c = G cos theta, psi = atan2(M_a, M_b),
    phi reduced as j4 Delta phi + local), R(t) = P^T R_ZL(0)^T R_ZL(t) P, P = ``motion.axes``.
    Symmetric: Rot(L^, (G/I) t) Rot(e_s, -W t). Steady, spherical: Rot(omega^, |omega| t)."""
    tt = _times(t)
    el = motion.elliptic
    if el is not None:
        st = _elliptic_state(motion, tt)
        j4, local = _phi_parts(motion, tt, st)
        per = el.precession_per_period
        phi = local if per is None else local + big_phase(j4, per)
        Mrel = (motion.moments * st["w"])[:, list(el._perm)]
        q = ll_quat(phi, Mrel, el._G)
        q = _qmul(_qmul(el._q_left[None, :], q), el._q_right[None, :])
        return _qcanon(q)
    if motion.case == CASE_REST:
        out = np.zeros((tt.size, 4))
        out[:, 0] = 1.0
        return out
    if motion.symmetry == "symmetric" and motion.case in (CASE_MAX, CASE_MIN):
        G = motion.angular_momentum_norm
        Lhat = motion.angular_momentum / G
        e = motion.symmetry_axis
        phid = float(motion.space_precession_rate)  # type: ignore[arg-type]
        W = float(motion.precession_rate)  # type: ignore[arg-type]
        q = _qmul(_qaxis(Lhat, np.fmod(phid * tt, 2 * _TWO_PI)),
                  _qaxis(e, np.fmod(-W * tt, 2 * _TWO_PI)))  # type: ignore[arg-type]
        return _qcanon(q)
    # steady rotation (any body) and spherical bodies: rotation about omega0
    wn = float(np.linalg.norm(motion.omega0_principal))
    axis = (motion.omega0_principal @ motion.axes) / wn
    return _qcanon(_qaxis(axis, np.fmod(wn * tt, 2 * _TWO_PI)))


def ll_quat(phi: np.ndarray, Mrel: np.ndarray, G: float) -> np.ndarray:
    """qz(phi) qx(theta) qz(psi) with cos theta = Mc/G, psi = atan2(Ma, Mb) (Landau–Lifshitz).

    Half-angles of theta use G +- Mc = rho^2/(G -+ Mc), rho^2 = Ma^2 + Mb^2, on the side that
    cancels, so theta near 0 or pi keeps full precision.
    """
    Ma, Mb, Mc = Mrel[:, 0], Mrel[:, 1], Mrel[:, 2]
    rho2 = Ma * Ma + Mb * Mb
    big = G + np.abs(Mc)
    small = rho2 / big
    gp = np.where(Mc >= 0, big, small)  # G + Mc
    gm = np.where(Mc >= 0, small, big)  # G - Mc
    ch = np.sqrt(gp / (2 * G))
    sh = np.sqrt(gm / (2 * G))
    psi = np.arctan2(Ma, Mb)
    hp = 0.5 * (phi + psi)
    hm = 0.5 * (phi - psi)
    # qz(phi) qx(theta) qz(psi) in closed form
    return np.stack(
        [ch * np.cos(hp), sh * np.cos(hm), sh * np.sin(hm), ch * np.sin(hp)], axis=-1
    )
