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


# ----------------------------------------------------------------------------------------
# Carlson symmetric forms
# ----------------------------------------------------------------------------------------


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
    """Carlson's degenerate integral R_C(x, y) = R_F(x, y, y).

    Parameters
    ----------
    x : float or array_like — >= 0
    y : float or array_like — != 0; for y < 0 the Cauchy principal value (DLMF 19.2.20)

    Returns
    -------
    float or ndarray — R_C(x, y) = ½ ∫₀^∞ (t + x)^(−1/2) (t + y)^(−1) dt
    """
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
    """Carlson's symmetric integral of the first kind R_F(x, y, z).

    Parameters
    ----------
    x, y, z : float or array_like — >= 0, at most one of them 0 (broadcast together)

    Returns
    -------
    float or ndarray — R_F = ½ ∫₀^∞ [(t + x)(t + y)(t + z)]^(−1/2) dt; ``inf`` when two
    arguments are 0.

    Notes
    -----
    Carlson (1995) §2: duplicate ``x ← (x + λ)/4`` (λ = √x√y + √x√z + √y√z) until the three
    arguments agree to 1e-3 of their mean, then the series
    ``(1 − E2/10 + E3/14 + E2²/24 − 3 E2 E3/44) / √A`` (truncation ~1e-18 relative).
    Relative error a few ulp (tests: against mpmath at 50 digits).
    """
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
    """Carlson's symmetric integral of the third kind R_J(x, y, z, p), p > 0.

    Parameters
    ----------
    x, y, z : float or array_like — >= 0, at most one of them 0
    p : float or array_like — > 0 (the principal value for p < 0 is not needed by rbcli;
        it gives NaN)

    Returns
    -------
    float or ndarray — R_J = (3/2) ∫₀^∞ [(t + x)(t + y)(t + z)]^(−1/2) (t + p)^(−1) dt

    Notes
    -----
    Carlson (1995) §2, algorithm for R_J: duplication, accumulating
    ``3 Σ 4^(−k) R_C(α_k, β_k)`` with ``α_k = (p_k(√x_k + √y_k + √z_k) + √x_k√y_k√z_k)²``,
    ``β_k = p_k (p_k + λ_k)²`` (the form of Carlson's earlier algorithm, "Computing elliptic
    integrals by duplication", Numer. Math. 33 (1979) 1–16: both sums of positive terms,
    where 1995's ``R_C(1, 1 + δ/d²)`` cancels for p ≪ x, y, z), then the degree-5 series in X, Y, Z, P.
    """
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


# ----------------------------------------------------------------------------------------
# Legendre forms
# ----------------------------------------------------------------------------------------


def _params(m: float, mc: float | None) -> tuple[float, float]:
    m = float(m)
    mc = 1.0 - m if mc is None else float(mc)
    if not (0.0 <= m <= 1.0 and 0.0 <= mc <= 1.0):
        raise ValueError(f"the parameter must satisfy 0 <= m <= 1 (got m = {m!r}, 1 - m = {mc!r})")
    return m, mc


def ellipk(m: float, mc: float | None = None) -> float:
    """Complete elliptic integral of the first kind K(m) = R_F(0, 1 − m, 1) (DLMF 19.25.1).

    Parameters
    ----------
    m : float — parameter m = k², 0 <= m <= 1
    mc : float, optional — 1 − m computed by the caller (keeps its digits near m = 1);
        default ``1 − m``

    Returns
    -------
    float — K(m); ``inf`` at m = 1 (mc = 0)
    """
    _, mc = _params(m, mc)
    if mc == 0.0:
        return math.inf
    return float(elliprf(0.0, mc, 1.0))


def ellippi_sc(n: float, s: Any, c: Any, m: float, mc: float | None = None,
               n1: float | None = None) -> Any:
    """Incomplete Π(n; φ|m) for |φ| <= π/2, from s = sin φ and c = cos φ >= 0.

    Parameters
    ----------
    n : float — characteristic, n < 1 (n sin²φ < 1)
    s, c : float or array_like — sin φ and cos φ (c >= 0); for φ = am u these are sn u, cn u
    m, mc : float — parameter and (optionally) its complement 1 − m as computed by the caller
    n1 : float, optional — 1 − n computed by the caller; default ``1 − n``

    Returns
    -------
    float or ndarray — ``Π = s R_F(c², Δ², 1) + (n/3) s³ R_J(c², Δ², 1, c² + (1 − n) s²)``
    with ``Δ² = c² + (1 − m) s²`` (DLMF 19.25.14). For n < −1 the two terms nearly cancel;
    there ``n ω = m`` (DLMF 19.7.9) turns it into two positive terms:
    ``Π = −(ω/3) s³ R_J(c², Δ², 1, 1 − ω s²) + s R_C(c² Δ², (1 − n s²)(1 − ω s²))``.
    """
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


# ----------------------------------------------------------------------------------------
# Jacobi elliptic functions
# ----------------------------------------------------------------------------------------


def _sncndn_half(u: np.ndarray, m: float, mc: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """sn, cn, dn(u | m) for 0 <= u <= K/2, from m AND its complement mc = 1 - m.

    * mc > 1e-4: the AGM / descending Landen scheme (A&S 16.4) started from b0 = sqrt(mc)
      (``scipy.special.ellipj`` starts from sqrt(1 - m) with m rounded, which fails as
      m -> 1), with ``dn = sqrt(cn^2 + mc sn^2)``.
    * mc <= 1e-4: one ascending Landen (Gauss) step (A&S 16.14) to the parameter
      mu = 1 - r^2, r = (1 - k)/(1 + k) = mc/(1 + k)^2, then the m -> 1 expansions
      (A&S 16.15) whose error O(r^4 e^{4v}) is below round-off for v <= K/2. The AGM loses
      ~eps/sqrt(k') in cn near K/2 (an asin of an argument near 1); this route does not.
    """
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
    """sn, cn, dn(τ | m) with the half-period reduction exposed (0 <= m < 1).

    Parameters
    ----------
    tau : array_like — argument (any real; accuracy is that of τ − 2Kj, so keep |τ| of the
        order of a few K when τ comes from a larger phase: reduce it modulo 4K first)
    K : float — K(m) (:func:`ellipk` with the same ``mc``)
    m, mc : float — the parameter and its complement 1 − m, each from its own formula

    Returns
    -------
    ``sn, cn, dn, j, snu, cnu`` (ndarrays): τ = u + 2Kj with |u| <= K, ``snu = sn(u)``,
    ``cnu = cn(u) >= 0`` (so ``am(u) = atan2(snu, cnu)`` is in [−π/2, π/2] and
    ``am(τ) = am(u) + jπ``). On (K/2, K] the values come from ``u' = K − u`` through
    ``sn = cn'/dn'``, ``cn = k' sn'/dn'``, ``dn = k'/dn'`` (A&S 16.8), which keeps cn and dn
    accurate where they are small.
    """
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
    """Jacobi elliptic functions sn, cn, dn and the amplitude am of u (any real) at m.

    Parameters
    ----------
    u : float or array_like — argument
    m : float — parameter m = k², 0 <= m <= 1
    mc : float, optional — 1 − m computed by the caller; give it near m = 1 (the reason this
        function exists: ``scipy.special.ellipj`` rounds 1 − m from m)

    Returns
    -------
    sn, cn, dn, am : float or ndarray — am in radians, continuous in u
        (am(u + 2K) = am(u) + π). At mc = 0: tanh, sech, sech and the Gudermannian; at
        m = 0: sin, cos, 1 and u.

    Notes
    -----
    The argument is reduced to |u| <= K/2 by the half-period and quarter-period relations
    (A&S 16.8), then descending Landen / AGM (A&S 16.4) for mc > 1e-4, or one ascending
    Landen step and the m → 1 expansions (A&S 16.14–16.15) for mc <= 1e-4.
    """
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
