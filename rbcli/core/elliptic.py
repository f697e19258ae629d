"""Elliptic integrals and Jacobi elliptic functions in plain numpy, from (m, 1 − m).

Every elliptic function rbcli uses (free motion, the heavy top), without scipy
(``scipy.special`` costs ~0.3 s of CPU at import). A function of the parameter takes ``m``
and, optionally, ``mc = 1 − m`` from the caller's cancellation-free formula: near the
separatrix ``1 − m`` rounded from ``m`` has lost its digits (``scipy.special.ellipj``
returns ``cn(2K) = −2`` for ``1 − m = 1e-10``); here K, sn, cn, dn keep full relative
precision down to ``mc`` ~ 1e-300.

Sources: B. C. Carlson, "Numerical computation of real or complex elliptic integrals",
Numer. Algorithms 10 (1995) 13–26 (duplication, the series of R_F, R_C, R_J); DLMF §19.2,
§19.7, §19.20, §19.25 (Legendre forms in Carlson form, principal values, n < −1); Abramowitz
& Stegun §16.4 (AGM), §16.8 (quarter-period shift), §16.14–16.15 (m → 1)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

__all__ = [
    "elliprc",
    "elliprf",
    "elliprj",
    "ellipk",
    "ellippi",
    "ellippi_sc",
    "ellipj",
    "jacobi_reduced",
]

_EPS = float(np.finfo(float).eps)
#: duplication stops when every argument is within this fraction of their mean; the series
#: then truncates at degree 6 in that fraction: (1e-3)^6 = 1e-18 relative, below round-off.
_SPREAD = 1e-3
#: the duplication converges geometrically (each step quarters the spread once the arguments
#: are of one order; a spread of 1e300 needs ~10 steps to get there); never more than this
_MAX_STEPS = 100


def _arr(x: Any) -> np.ndarray:
    return np.asarray(x, dtype=float)


def _out(x: np.ndarray) -> Any:
    return float(x) if x.ndim == 0 else x


# --- Carlson symmetric forms


def _rc_pos(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """R_C(x, y) for x >= 0, y > 0 by duplication (Carlson 1995, algorithm for R_C)."""
    x, y = np.broadcast_arrays(x, y)
    x = x.astype(float, copy=True)
    y = y.astype(float, copy=True)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        for _ in range(_MAX_STEPS):
            a = (x + 2.0 * y) / 3.0
            if not np.any(np.abs(y - x) > _SPREAD * a):
                break
            lam = 2.0 * np.sqrt(x) * np.sqrt(y) + y
            x = 0.25 * (x + lam)
            y = 0.25 * (y + lam)
        a = (x + 2.0 * y) / 3.0
        s = (y - a) / a
        # R_C = A^(-1/2) (1 + 3s²/10 + s³/7 + 3s⁴/8 + 9s⁵/22 + ...), next term 159 s⁶/208
        return (1.0 + s * s * (0.3 + s * (1.0 / 7.0 + s * (0.375 + s * (9.0 / 22.0))))) / np.sqrt(a)


def elliprc(x: Any, y: Any) -> Any:
    """Carlson's R_C(x, y) = R_F(x, y, y) = ½ ∫₀^∞ (t + x)^(−1/2) (t + y)^(−1) dt, x >= 0,
    y != 0 (y < 0: the Cauchy principal value, DLMF 19.2.20)."""
    x = _arr(x)
    y = _arr(y)
    neg = y < 0.0
    with np.errstate(invalid="ignore", divide="ignore"):
        xx = np.where(neg, x - y, x)
        yy = np.where(neg, -y, y)
        out = _rc_pos(xx, yy)
        out = np.where(neg, np.sqrt(x / (x - y)) * out, out)
    return _out(np.asarray(out))


def elliprf(x: Any, y: Any, z: Any) -> Any:
    """Carlson's R_F(x, y, z) = ½ ∫₀^∞ [(t + x)(t + y)(t + z)]^(−1/2) dt, arguments >= 0, at most
    one 0 (``inf`` when two are). Carlson (1995) §2: duplicate ``x ← (x + λ)/4`` until the
    arguments agree to 1e-3, then ``(1 − E2/10 + E3/14 + E2²/24 − 3 E2 E3/44) / √A``; a few ulp
    (tested against mpmath)."""
    x, y, z = np.broadcast_arrays(_arr(x), _arr(y), _arr(z))
    x = x.astype(float, copy=True)
    y = y.astype(float, copy=True)
    z = z.astype(float, copy=True)
    a0 = (x + y + z) / 3.0
    a = a0.copy()
    dx, dy = a0 - x, a0 - y
    f = 1.0  # 4^(-steps)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        for _ in range(_MAX_STEPS):
            spread = np.maximum(np.maximum(np.abs(a - x), np.abs(a - y)), np.abs(a - z))
            if not np.any(spread > _SPREAD * a):
                break
            sx, sy, sz = np.sqrt(x), np.sqrt(y), np.sqrt(z)
            lam = sx * (sy + sz) + sy * sz
            x = 0.25 * (x + lam)
            y = 0.25 * (y + lam)
            z = 0.25 * (z + lam)
            a = 0.25 * (a + lam)
            f *= 0.25
        X = dx * f / a
        Y = dy * f / a
        Z = -(X + Y)
        e2 = X * Y - Z * Z
        e3 = X * Y * Z
        out = (1.0 - 0.1 * e2 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / np.sqrt(a)
        zeros = (x == 0.0).astype(int) + (y == 0.0).astype(int) + (z == 0.0).astype(int)
        out = np.where(zeros >= 2, np.inf, out)
    return _out(np.asarray(out))


def elliprj(x: Any, y: Any, z: Any, p: Any) -> Any:
    """Carlson's R_J(x, y, z, p) = (3/2) ∫₀^∞ [(t + x)(t + y)(t + z)]^(−1/2) (t + p)^(−1) dt,
    x, y, z >= 0 (at most one 0), p > 0 (p < 0 gives NaN).

    Carlson (1995) §2 duplication, accumulating ``3 Σ 4^(−k) R_C(α_k, β_k)`` with
    ``α_k = (p_k(√x_k + √y_k + √z_k) + √x_k√y_k√z_k)²``, ``β_k = p_k (p_k + λ_k)²`` (Carlson,
    Numer. Math. 33 (1979) 1–16: positive terms, where 1995's form cancels for p ≪ x, y, z),
    then the degree-5 series."""
    x, y, z, p = np.broadcast_arrays(_arr(x), _arr(y), _arr(z), _arr(p))
    x = x.astype(float, copy=True)
    y = y.astype(float, copy=True)
    z = z.astype(float, copy=True)
    p = np.where(p > 0.0, p, np.nan).astype(float)
    a0 = (x + y + z + 2.0 * p) / 5.0
    a = a0.copy()
    dx, dy, dz = a0 - x, a0 - y, a0 - z
    total = np.zeros_like(a0)
    f = 1.0  # 4^(-k)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore", under="ignore"):
        for _ in range(_MAX_STEPS):
            spread = np.maximum.reduce([np.abs(a - x), np.abs(a - y), np.abs(a - z), np.abs(a - p)])
            if not np.any(spread > _SPREAD * a):
                break
            sx, sy, sz, sp = np.sqrt(x), np.sqrt(y), np.sqrt(z), np.sqrt(p)
            lam = sx * (sy + sz) + sy * sz
            # R_C(α, β) with α = (p(√x + √y + √z) + √x√y√z)², β = p (p + λ)²: both sums of
            # positive terms (Carlson's 1 + δ/d² cancels when p ≪ x, y, z)
            alpha = p * (sx + sy + sz) + sx * sy * sz
            alpha = alpha * alpha
            beta = p * (p + lam) * (p + lam)
            total = total + f * _rc_pos(alpha, beta)
            x = 0.25 * (x + lam)
            y = 0.25 * (y + lam)
            z = 0.25 * (z + lam)
            p = 0.25 * (p + lam)
            a = 0.25 * (a + lam)
            f *= 0.25
        X = dx * f / a
        Y = dy * f / a
        Z = dz * f / a
        P = -0.5 * (X + Y + Z)
        xyz = X * Y * Z
        e2 = X * Y + X * Z + Y * Z - 3.0 * P * P
        e3 = xyz + 2.0 * e2 * P + 4.0 * P * P * P
        e4 = (2.0 * xyz + e2 * P + 3.0 * P * P * P) * P
        e5 = xyz * P * P
        series = (1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0 - 3.0 * e4 / 22.0
                  - 9.0 * e2 * e3 / 52.0 + 3.0 * e5 / 26.0)
        out = f * series / (a * np.sqrt(a)) + 3.0 * total
    return _out(np.asarray(out))


# --- Legendre forms


def _params(m: float, mc: float | None) -> tuple[float, float]:
    m = float(m)
    mc = 1.0 - m if mc is None else float(mc)
    if not (0.0 <= m <= 1.0 and 0.0 <= mc <= 1.0):
        raise ValueError(f"the parameter must satisfy 0 <= m <= 1 (got m = {m!r}, 1 - m = {mc!r})")
    return m, mc


def ellipk(m: float, mc: float | None = None) -> float:
    """K(m) = R_F(0, 1 − m, 1) (DLMF 19.25.1), 0 <= m <= 1, ``mc`` = 1 − m from the caller
    (default ``1 − m``); ``inf`` at mc = 0."""
    _, mc = _params(m, mc)
    if mc == 0.0:
        return math.inf
    return float(elliprf(0.0, mc, 1.0))


def ellippi_sc(n: float, s: Any, c: Any, m: float, mc: float | None = None,
               n1: float | None = None) -> Any:
    """Incomplete Π(n; φ|m) for |φ| <= π/2, from s = sin φ and c = cos φ >= 0 (n < 1; ``mc``,
    ``n1`` the caller's 1 − m and 1 − n).

    ``Π = s R_F(c², Δ², 1) + (n/3) s³ R_J(c², Δ², 1, c² + (1 − n) s²)``, ``Δ² = c² + (1 − m) s²``
    (DLMF 19.25.14); for n < −1, ``n ω = m`` (DLMF 19.7.9) gives positive terms:
    ``Π = −(ω/3) s³ R_J(c², Δ², 1, 1 − ω s²) + s R_C(c² Δ², (1 − n s²)(1 − ω s²))``."""
    m, mc = _params(m, mc)
    n = float(n)
    n1 = 1.0 - n if n1 is None else float(n1)
    s = _arr(s)
    c = _arr(c)
    c2, s2 = c * c, s * s
    y = c2 + mc * s2
    if n < -1.0:
        om = m / n
        out = -(om / 3.0) * s * s2 * _arr(elliprj(c2, y, 1.0, 1.0 - om * s2))
        out = out + s * _arr(elliprc(c2 * y, (c2 + n1 * s2) * (1.0 - om * s2)))
        return _out(np.asarray(out))
    out = s * _arr(elliprf(c2, y, 1.0))
    if n != 0.0:
        out = out + (n / 3.0) * s * s2 * _arr(elliprj(c2, y, 1.0, c2 + n1 * s2))
    return _out(np.asarray(out))


def ellippi(n: float, m: float, mc: float | None = None, n1: float | None = None) -> float:
    """Complete elliptic integral of the third kind Π(n|m), n < 1 (DLMF 19.25.2).

    ``Π(n|m) = R_F(0, 1 − m, 1) + (n/3) R_J(0, 1 − m, 1, 1 − n)``; for n < −1 through the
    cancellation-free form of :func:`ellippi_sc` at φ = π/2. ``mc``, ``n1``: the complements
    1 − m and 1 − n as computed by the caller.
    """
    m, mc = _params(m, mc)
    n = float(n)
    n1 = 1.0 - n if n1 is None else float(n1)
    if n < -1.0:
        return float(ellippi_sc(n, 1.0, 0.0, m, mc, n1))
    out = float(elliprf(0.0, mc, 1.0))
    if n != 0.0:
        out += n / 3.0 * float(elliprj(0.0, mc, 1.0, n1))
    return out


# --- Jacobi elliptic functions


def _sncndn_half(u: np.ndarray, m: float, mc: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """sn, cn, dn(u | m) for 0 <= u <= K/2, from m and mc = 1 - m: the AGM (A&S 16.4) from
    b0 = sqrt(mc) for mc > 1e-4, else one ascending Landen step (A&S 16.14) and the m -> 1
    expansions (A&S 16.15), whose error is below round-off for v <= K/2."""
    if mc > 1e-4:
        a = [1.0]
        c = [math.sqrt(m)]
        b = math.sqrt(mc)
        while abs(c[-1]) > _EPS * a[-1] and len(a) < 64:
            an = 0.5 * (a[-1] + b)
            cn_ = 0.5 * (a[-1] - b) if len(a) == 1 else c[-1] * c[-1] / (4.0 * an)
            b = math.sqrt(a[-1] * b)
            a.append(an)
            c.append(cn_)
        n = len(a) - 1
        phi = (2.0**n) * a[n] * u
        for i in range(n, 0, -1):
            phi = 0.5 * (np.arcsin(np.clip(c[i] * np.sin(phi) / a[i], -1.0, 1.0)) + phi)
        sn = np.sin(phi)
        cn = np.cos(phi)
        return sn, cn, np.sqrt(cn * cn + mc * sn * sn)
    k = math.sqrt(m)
    r = mc / (1.0 + k) ** 2
    mu1 = r * r
    mu = 1.0 - mu1
    v = u / (1.0 + r)
    th = np.tanh(v)
    e = np.exp(-v)
    sech = 2.0 * e / (1.0 + e * e)
    shch = 0.5 * np.sinh(2.0 * v)
    snv = th + 0.25 * mu1 * (shch - v) * sech * sech
    cnv = sech - 0.25 * mu1 * (shch - v) * th * sech
    dnv = sech + 0.25 * mu1 * (shch + v) * th * sech
    sn = (1.0 + r) * snv * cnv / dnv
    cn = ((1.0 + r) / mu) * (dnv * dnv - r) / dnv
    dn = ((1.0 - r) / mu) * (dnv * dnv + r) / dnv
    return sn, cn, dn


def jacobi_reduced(tau: Any, K: float, m: float, mc: float) -> tuple[np.ndarray, ...]:
    """sn, cn, dn(τ | m) with the half-period reduction exposed (0 <= m < 1; ``K`` from
    :func:`ellipk` with the same ``mc``; keep |τ| a few K).

    Returns ``sn, cn, dn, j, snu, cnu``: τ = u + 2Kj, |u| <= K, ``cnu >= 0`` (so
    ``am(τ) = atan2(snu, cnu) + jπ``). On (K/2, K] through ``u' = K − u`` (A&S 16.8), which keeps
    small cn and dn accurate."""
    tau = _arr(tau)
    j = np.rint(tau / (2.0 * K))
    u = tau - 2.0 * K * j
    sgn = np.where(u < 0.0, -1.0, 1.0)
    w = np.minimum(np.abs(u), K)
    near = w > 0.5 * K
    w2 = np.where(near, K - w, w)
    s, c, d = _sncndn_half(w2, m, mc)
    kp = math.sqrt(mc)
    snu = sgn * np.where(near, c / d, s)
    cnu = np.where(near, kp * s / d, c)
    dn = np.where(near, kp / d, d)
    par = np.where(np.mod(j, 2.0) == 0.0, 1.0, -1.0)
    return par * snu, par * cnu, dn, j, snu, cnu


def ellipj(u: Any, m: float, mc: float | None = None) -> tuple[Any, Any, Any, Any]:
    """Jacobi sn, cn, dn and the amplitude am (rad, continuous: am(u + 2K) = am(u) + π) of u at
    m (0 <= m <= 1; ``mc`` = 1 − m from the caller near m = 1, which ``scipy.special.ellipj``
    rounds). At mc = 0: tanh, sech, sech, the Gudermannian; at m = 0: sin, cos, 1, u. Reduced to
    |u| <= K/2 (A&S 16.8), then :func:`_sncndn_half`."""
    m, mc = _params(m, mc)
    uu = _arr(u)
    if mc == 0.0:
        sech = 1.0 / np.cosh(uu)
        return (_out(np.tanh(uu)), _out(sech), _out(sech.copy()),
                _out(np.arctan(np.sinh(uu))))
    if m == 0.0:
        return _out(np.sin(uu)), _out(np.cos(uu)), _out(np.ones_like(uu)), _out(uu.copy())
    K = ellipk(m, mc)
    # reduce modulo 4K first (sn, cn have period 4K), keeping the count for am
    j4 = np.floor((uu + 2.0 * K) / (4.0 * K))
    ur = uu - 4.0 * K * j4
    sn, cn, dn, j2, snu, cnu = jacobi_reduced(ur, K, m, mc)
    am = np.arctan2(snu, cnu) + math.pi * (j2 + 2.0 * j4)
    return _out(sn), _out(cn), _out(dn), _out(am)
