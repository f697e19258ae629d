"""The heavy top's motion in time: its Euler angles and their rates at any times.

:func:`path_at` and :func:`state_at` evaluate the closed form of :func:`rbcli.core.top.analyse`
(Jacobi functions for the tilt, Π in Carlson's form, DLMF §19.25, for the angles), so a time
10^6 periods ahead costs what the first period costs (Goldstein, Poole and Safko §5.7;
physics sheet ``dynamics.md`` §2)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from rbcli.core.elliptic import ellipj, elliprc, elliprf, elliprj

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.core.top import TopMotion


def carlson_F(phi: np.ndarray, m1: float) -> np.ndarray:
    """F(φ|m) for |φ| <= π/2, from RF, with m1 = 1 - m given exactly (the top's phase at t = 0)."""
    s = np.sin(phi)
    c = np.cos(phi)
    return s * elliprf(c * c, c * c + m1 * s * s, 1.0)


def carlson_Pi(n: float, n1: float, phi: np.ndarray, m1: float) -> np.ndarray:
    """Π(n; φ|m) for |φ| <= π/2 (sheet §0): s RF(c², 1-ms², 1) + n/3 s³ RJ(c², 1-ms², 1, 1-ns²).

    ``n1 = 1 - n`` and ``m1 = 1 - m`` are passed separately so that 1 - m s² = c² + m1 s²
    and 1 - n s² = c² + n1 s² keep their digits.
    """
    s = np.sin(phi)
    c = np.cos(phi)
    c2 = c * c
    s2 = s * s
    y = c2 + m1 * s2
    if n < -1.0:
        # F and n/3 s³ RJ nearly cancel for n ≪ -1. Use n·ω = m (DLMF 19.7.9 in Carlson form):
        # Π(n) = F - Π(ω) + s RC(c²Δ², (1-ns²)(1-ωs²)) and F - Π(ω) = -ω/3 s³ RJ(.., 1-ωs²),
        # two positive terms.
        om = (1.0 - m1) / n
        out = -(om / 3.0) * s * s2 * elliprj(c2, y, 1.0, 1.0 - om * s2)
        return out + s * elliprc(c2 * y, (c2 + n1 * s2) * (1.0 - om * s2))
    out = s * elliprf(c2, y, 1.0)
    if n != 0.0:
        out = out + (n / 3.0) * s * s2 * elliprj(c2, y, 1.0, c2 + n1 * s2)
    return out


def complete_Pi(n: float, n1: float, m1: float) -> float:
    """Π(n|m) = RF(0, 1-m, 1) + n/3 RJ(0, 1-m, 1, 1-n) (sheet §0); see carlson_Pi for n < -1."""
    if n < -1.0:
        return float(carlson_Pi(n, n1, np.asarray(0.5 * np.pi), m1))
    out = float(elliprf(0.0, m1, 1.0))
    if n != 0.0:
        out += n / 3.0 * float(elliprj(0.0, m1, 1.0, n1))
    return out


def path_at(motion: TopMotion, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The exact Euler angles (θ, φ, ψ) of the top at times ``t`` (s, any shape): θ from the
    upward vertical, φ and ψ continuous from 0 at t = 0.

    u(t) = u1 + (u2-u1) sn²(τ|m), τ = λ t + τ0; φ(t) = [cp ΔΠ(n+) + cm ΔΠ(n-)]/λ,
    ψ(t) = (S - a) t - [cp ΔΠ(n+) - cm ΔΠ(n-)]/λ, ΔΠ(n) = Π(n; am τ|m) - Π(n; am τ0|m), with
    τ = τr + 2Kj and Π(n; am τ) = Π(n; am τr) + 2j Π(n|m) (sheet §2 "Closed form")."""
    theta, phi, psi, _sn, _cn = _path(motion, t)
    return theta, phi, psi


def _path(motion: TopMotion, t: np.ndarray) -> tuple[np.ndarray, ...]:
    """θ, φ, ψ as :func:`path_at`, and sn τ, cn τ of the reduced phase τr (for the rates)."""
    e = motion.elliptic
    tt = np.asarray(t, dtype=float)
    if not np.isfinite(e.K):
        raise ValueError("the motion is on the separatrix (m = 1): no periodic closed form")
    tau = e.lam * tt + e.tau0
    j = np.rint(tau / (2.0 * e.K))
    tau_r = tau - 2.0 * e.K * j
    sn, cn, _dn, ph = ellipj(tau_r, e.m, e.m1)
    ph = np.clip(ph, -0.5 * np.pi, 0.5 * np.pi)
    # 1 - u = (1 - u2) + (u2 - u1) cn² and 1 + u = (1 + u1) + (u2 - u1) sn²: sums of
    # non-negative terms, accurate near either pole
    one_minus_u = e.one_minus_u2 + e.band * cn * cn
    one_plus_u = e.one_plus_u1 + e.band * sn * sn
    theta = 2.0 * np.arctan2(np.sqrt(one_minus_u), np.sqrt(one_plus_u))

    # the phase at t = 0 reduced and evaluated exactly as at any t (not the stored atan2
    # value, equal to it within ~1 ulp), so that φ(0) and ψ(0) are exactly 0
    j0 = float(np.rint(e.tau0 / (2.0 * e.K)))
    am0 = np.clip(ellipj(e.tau0 - 2.0 * e.K * j0, e.m, e.m1)[3], -0.5 * np.pi, 0.5 * np.pi)

    def dPi(n: float, n1: float, Pc: float) -> np.ndarray:
        now = carlson_Pi(n, n1, ph, e.m1) + 2.0 * j * Pc
        return now - (carlson_Pi(n, n1, am0, e.m1) + 2.0 * j0 * Pc)

    zero = np.zeros_like(tt)
    dp = dPi(e.n_plus, e.n_plus1, e.Pi_plus) if e.cp != 0.0 else zero
    dm = dPi(e.n_minus, e.n_minus1, e.Pi_minus) if e.cm != 0.0 else zero
    phi = (e.cp * dp + e.cm * dm) / e.lam
    psi = (motion.spin - motion.a) * tt - (e.cp * dp - e.cm * dm) / e.lam
    if e.top_jump:  # u = 1 at τ = K (mod 2K): φ += ±π, ψ -= ±π per passage
        k = np.floor((tau - e.K) / (2.0 * e.K)) - math.floor((e.tau0 - e.K) / (2.0 * e.K))
        phi = phi + e.top_jump * np.pi * k
        psi = psi - e.top_jump * np.pi * k
    if e.bottom_jump:  # u = -1 at τ = 0 (mod 2K): φ += ±π, ψ += ±π per passage
        k = np.floor(tau / (2.0 * e.K)) - math.floor(e.tau0 / (2.0 * e.K))
        phi = phi + e.bottom_jump * np.pi * k
        psi = psi + e.bottom_jump * np.pi * k
    return theta, phi, psi, sn, cn


@dataclass(frozen=True)
class TopState:
    """The top at given times (every array has the shape of ``t``).

    Attributes
    ----------
    t : ndarray — s
    theta : ndarray — rad, tilt of the axis from the upward vertical
    phi, psi : ndarray — rad, precession and spin angles, continuous, 0 at t = 0
    theta_dot, phi_dot, psi_dot : ndarray — rad/s, their rates (ψ' = S - φ' cos θ)
    """

    t: np.ndarray
    theta: np.ndarray
    phi: np.ndarray
    psi: np.ndarray
    theta_dot: np.ndarray
    phi_dot: np.ndarray
    psi_dot: np.ndarray

    @property
    def axis(self) -> np.ndarray:
        """Unit symmetry axis in space, shape ``t.shape + (3,)``: (sin θ cos φ, sin θ sin φ,
        cos θ), z up."""
        st = np.sin(self.theta)
        return np.stack([st * np.cos(self.phi), st * np.sin(self.phi), np.cos(self.theta)], axis=-1)


def state_at(motion: TopMotion, t: np.ndarray) -> TopState:
    """The exact Euler angles and their rates at times ``t`` (s): u' = 2 λ (u2 - u1) sn cn dn,
    θ' = -u'/sin θ, φ' = (b - a u)/(1 - u²), ψ' = S - φ' u (Goldstein §5.7); NaN where the axis
    passes exactly through a pole."""
    e = motion.elliptic
    tt = np.asarray(t, dtype=float)
    theta, phi, psi, sn, cn = _path(motion, tt)
    one_minus_u = e.one_minus_u2 + e.band * cn * cn
    one_plus_u = e.one_plus_u1 + e.band * sn * sn
    dn = np.sqrt(e.m1 + e.m * cn * cn)
    sin_theta = np.sqrt(one_minus_u * one_plus_u)
    u = 1.0 - one_minus_u
    with np.errstate(divide="ignore", invalid="ignore"):
        theta_dot = -2.0 * e.lam * e.band * sn * cn * dn / sin_theta
        phi_dot = (motion.b - motion.a * u) / (one_minus_u * one_plus_u)
    theta_dot = np.where(e.band == 0.0, 0.0, theta_dot)
    psi_dot = motion.spin - phi_dot * u
    return TopState(t=tt, theta=theta, phi=phi, psi=psi, theta_dot=theta_dot, phi_dot=phi_dot,
                    psi_dot=psi_dot)
