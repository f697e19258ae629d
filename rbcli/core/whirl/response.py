"""Unbalance response of the rigid rotor, its peaks, amplification factors and the
API separation margins.

Forcing (physics sheet ``whirl.md``): a static unbalance U (kg m) and a couple unbalance
P_G = D_xz + i D_yz (kg m², about the com), fixed in the rotor and turning at Omega, force
(x, y, theta_x, theta_y) with complex amplitudes ``Omega^2 (U, -i U, i P_G, P_G)``; plane
unbalances U_k at z_k add up to U = sum U_k and P_G = sum (z_k - z_G) U_k.

Steady state: ``(K - Omega^2 M + i Omega (C + Omega G)) Q = F``. At bearing i the axis
moves by ``D = T_i Q`` and pushes it with ``F_i = (K_i + i Omega C_i) D``; the orbit's
forward and backward parts are ``D_f = (D_x + i D_y)/2``, ``D_b = conj(D_x - i D_y)/2``,
its amplitude the semi-major axis ``|D_f| + |D_b|``, its phase arg D_f (the high spot,
from the 0° mark with the rotation). Stiff bearings tend to balance's rigid forces
``F_1 = Omega^2 (z_2 U - P)/(z_2 - z_1)``, ``F_2 = Omega^2 (P - z_1 U)/(z_2 - z_1)``.

Amplification factor (API 684, 2nd ed., SP6.8.2.1; API 617, 8th ed., §6.8.2.4):
``AF = Nc / (N2 - N1)`` with N1, N2 the half-power points, all roots by Brent's method.
Separation margin (API 617 §6.8.2.5 / API 684 SP6.8.2.10, as ROSS's ``api_report.py``): none
for AF < 2.5; else ``min(16, 17 (1 - 1/(AF - 1.5)))`` % below N_min and
``min(26, 10 + 17 (1 - 1/(AF - 1.5)))`` % above N_max (check against a licensed copy
before claiming conformity)."""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.roots import brentq
from rbcli.core.whirl.model import Rotor

__all__ = ["Forcing", "Response", "response", "Peak", "peaks", "required_margin", "Margin",
           "margin", "SQRT_HALF"]

SQRT_HALF = 1.0 / math.sqrt(2.0)
_GOLD = (math.sqrt(5.0) - 1.0) / 2.0


@dataclass(frozen=True, eq=False)
class Forcing:
    """The unbalance that drives the response.

    Attributes
    ----------
    static : complex — kg m, U (rotor frame)
    couple : complex — kg m², P_G about the com (rotor frame)
    """

    static: complex
    couple: complex

    @classmethod
    def from_planes(cls, z_com: float, planes: list[tuple[float, complex]]) -> "Forcing":
        """Unbalances U_k (kg m, complex in the rotor frame) at z_k (m):
        U = sum U_k, P_G = sum (z_k - z_G) U_k."""
        U = sum((u for _, u in planes), 0j)
        P = sum(((z - z_com) * u for z, u in planes), 0j)
        return cls(complex(U), complex(P))

    @property
    def zero(self) -> bool:
        return self.static == 0.0 and self.couple == 0.0


def _amplitudes(rotor: Rotor, forcing: Forcing, speeds: np.ndarray) -> np.ndarray:
    """(N, 4) complex ndarray: Q at each speed. At a singular dynamic stiffness (an undamped
    critical speed) NaN if the unbalance drives that mode, else the least-norm solution."""
    W = np.asarray(speeds, dtype=float)
    M, G = rotor.M(), rotor.G()
    K, C = rotor.matrices(W)
    Z = (K - (W**2)[:, None, None] * M[None, :, :]
         + 1j * W[:, None, None] * (C + W[:, None, None] * G[None, :, :]))
    F = (W**2)[:, None] * forcing_vector(forcing)[None, :]
    try:
        return np.linalg.solve(Z, F[:, :, None])[:, :, 0]
    except np.linalg.LinAlgError:  # one speed at least is exactly critical: each on its own
        out = np.full((len(W), 4), np.nan, dtype=complex)
        for j in range(len(W)):
            try:
                out[j] = np.linalg.solve(Z[j], F[j])
            except np.linalg.LinAlgError:
                x = np.linalg.lstsq(Z[j], F[j], rcond=None)[0]
                # F in the range of Z to round-off (1e-9 of the terms' scale, far above the
                # ~1e-16 of an exact solve, far below a driven mode's residual ~|F|)
                if np.linalg.norm(Z[j] @ x - F[j]) <= 1e-9 * (np.linalg.norm(Z[j]) * np.linalg.norm(x) + np.linalg.norm(F[j])):
                    out[j] = x
        return out


def _orbit(Dx: np.ndarray, Dy: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(semi-major axis, semi-minor axis, phase deg in [0, 360)) of Re((Dx, Dy) e^{iwt})."""
    Df = 0.5 * (Dx + 1j * Dy)
    Db = 0.5 * np.conj(Dx - 1j * Dy)
    major = np.abs(Df) + np.abs(Db)
    minor = np.abs(np.abs(Df) - np.abs(Db))
    phase = np.degrees(np.angle(Df)) % 360.0
    phase = np.where(np.abs(Df) > 0.0, phase, 0.0)
    return major, minor, phase


@dataclass(frozen=True, eq=False)
class Response:
    """Unbalance response at each speed, per bearing: ``speeds`` (N,) rad/s; ``displacement``
    and ``displacement_minor`` (n_b, N) m (the orbit's semi-axes), ``displacement_phase_deg``
    (the high spot, rotor frame); ``force`` (N) and ``force_phase_deg``."""

    speeds: np.ndarray
    displacement: np.ndarray
    displacement_minor: np.ndarray
    displacement_phase_deg: np.ndarray
    force: np.ndarray
    force_phase_deg: np.ndarray


def bearing_motion(rotor: Rotor, forcing: Forcing, speeds) -> tuple[np.ndarray, np.ndarray]:
    """(D, F): complex amplitudes (n_b, N, 2) of each bearing's displacement (m) and of the
    force the rotor exerts on it (N), in x and y."""
    W = np.asarray(speeds, dtype=float)
    Q = _amplitudes(rotor, forcing, W)
    Ds, Fs = [], []
    for b, a in zip(rotor.bearings, rotor.arms()):
        Dx = Q[:, 0] + a * Q[:, 3]
        Dy = Q[:, 1] - a * Q[:, 2]
        D = np.stack([Dx, Dy], axis=1)
        v = b.coefficients(W).reshape(-1, 2, 2, 2)  # (N, K/C, row, column)
        F = np.einsum("nij,nj->ni", v[:, 0], D) + 1j * W[:, None] * np.einsum("nij,nj->ni", v[:, 1], D)
        Ds.append(D)
        Fs.append(F)
    return np.array(Ds), np.array(Fs)


def response(rotor: Rotor, forcing: Forcing, speeds) -> Response:
    """The unbalance response at ``speeds`` (rad/s, (N,)); see the module docstring.
    A speed where the response is unbounded (exactly an undamped critical speed) is left
    out."""
    W = np.array(speeds, dtype=float)
    Q = _amplitudes(rotor, forcing, W)
    W = W[np.all(np.isfinite(Q), axis=1)]
    D, F = bearing_motion(rotor, forcing, W)
    dm, dn, dp = _orbit(D[:, :, 0], D[:, :, 1])
    fm, _, fp = _orbit(F[:, :, 0], F[:, :, 1])
    arrays = [W, dm, dn, dp, fm, fp]
    for a in arrays:
        a.setflags(write=False)
    return Response(*arrays)


def amplitude(rotor: Rotor, forcing: Forcing, bearing: int, speed: float) -> float:
    """m, the semi-major axis of bearing ``bearing``'s orbit at one speed."""
    return amplitude_slope(rotor, forcing, bearing, speed)[0]


def amplitude_slope(rotor: Rotor, forcing: Forcing, bearing: int, speed: float) -> tuple[float, float]:
    """(A, dA/dOmega): the semi-major axis (m) of bearing ``bearing``'s orbit at ``speed``
    and its derivative with the speed (m s/rad), exactly.

    ``Q = Z^-1 F`` with ``Z = K - W^2 M + i W (C + W G)``, ``F = W^2 f``; so
    ``dQ = Z^-1 (2 W f - dZ Q)`` with ``dZ = K' - 2 W M + i (C + W C' + 2 W G)`` (K', C':
    the tables' slopes in the speed, 0 for constant bearings). The orbit's parts
    ``D_f = (D_x + i D_y)/2``, ``D_b = conj(D_x - i D_y)/2`` and ``A = |D_f| + |D_b|``, so
    ``dA = Re(conj(D_f) dD_f)/|D_f| + Re(conj(D_b) dD_b)/|D_b|``."""
    W = float(speed)
    M, G = rotor.M(), rotor.G()
    (K,), (C,) = rotor.matrices([W])
    Z = K - W * W * M + 1j * W * (C + W * G)
    dZ = -2.0 * W * M + 1j * (C + 2.0 * W * G)
    if rotor.varying:
        (dK,), (dC,) = rotor.matrices([W], slope=True)
        dZ = dZ + dK + 1j * W * dC
    f = forcing_vector(forcing)
    Q = np.linalg.solve(Z, W * W * f)
    dQ = np.linalg.solve(Z, 2.0 * W * f - dZ @ Q)
    a = float(rotor.arms()[bearing])
    Dx, Dy = Q[0] + a * Q[3], Q[1] - a * Q[2]
    dDx, dDy = dQ[0] + a * dQ[3], dQ[1] - a * dQ[2]
    parts = ((0.5 * (Dx + 1j * Dy), 0.5 * (dDx + 1j * dDy)),
             (0.5 * np.conj(Dx - 1j * Dy), 0.5 * np.conj(dDx - 1j * dDy)))
    A = dA = 0.0
    for d, dd in parts:
        r = abs(d)
        A += r
        if r > 0.0:
            dA += float((np.conj(d) * dd).real) / r
    return float(A), float(dA)


def forcing_vector(forcing: Forcing) -> np.ndarray:
    """(4,) complex: the amplitudes per Omega^2 of the forces and moments on (x, y,
    theta_x, theta_y), (U, -i U, i P_G, P_G)."""
    U, P = forcing.static, forcing.couple
    return np.array([U, -1j * U, 1j * P, P], dtype=complex)


def excitation(rotor: Rotor, forcing: Forcing, speed: float, eigenvalue: complex, whirl: str) -> float:
    """How much the unbalance drives the undamped order-1 mode of ``eigenvalue`` at its critical
    ``speed``, relative: |y^H f| / (|y| |f|), y the left null vector of
    Z(lambda) = lambda^2 M + lambda Omega G + K (tilts scaled by sqrt(It/m)). On isotropic
    bearings Z is taken in directional coordinates, where the unbalance is forward forcing:
    0 along a backward mode. 0 without unbalance."""
    r = rotor.at(speed).conservative_part()
    rho = math.sqrt(r.It / r.mass)
    if r.isotropic:
        if whirl == "backward":
            return 0.0
        S = np.diag([1.0, 1.0 / rho])
        lam = complex(eigenvalue.real, abs(eigenvalue.imag))
        Z = lam * lam * np.diag([r.mass, r.It]) + r.complex_matrices([speed])[0][0]
        Z[1, 1] -= 1j * lam * speed * r.Ip
        f = np.array([forcing.static, forcing.couple]) @ S
    else:
        S = np.diag([1.0, 1.0, 1.0 / rho, 1.0 / rho])
        lam = complex(eigenvalue.real, abs(eigenvalue.imag))
        Z = lam * lam * r.M() + lam * speed * r.G() + r.K()
        f = forcing_vector(forcing) @ S
    nf = float(np.linalg.norm(f))
    if nf == 0.0:
        return 0.0
    y = np.linalg.svd(S @ Z @ S)[0][:, -1]
    return float(abs(np.vdot(y, f)) / (float(np.linalg.norm(y)) * nf))


#: a critical speed is driven by the unbalance when :func:`excitation` exceeds this (the
#: round-off of an undriven one is ~1e-16)
EXCITED_RTOL = 1e-8


# --- peaks


@dataclass(frozen=True, eq=False)
class Peak:
    """A resonance peak of one bearing's response: ``bearing`` (index), ``speed`` Nc (rad/s),
    ``amplitude`` (m, semi-major axis), ``half_power`` (N1, N2) rad/s (None when the curve does
    not fall to 1/sqrt(2) on both sides) and ``amplification_factor`` Nc/(N2 - N1) or None."""

    bearing: int
    speed: float
    amplitude: float
    half_power: tuple[float, float] | None
    amplification_factor: float | None


def _golden_max(f, a: float, b: float, tol: float) -> float:
    """The maximiser of a unimodal f on [a, b] to ``tol`` (golden-section search)."""
    c = b - _GOLD * (b - a)
    d = a + _GOLD * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(200):
        if b - a <= tol:
            break
        if fc >= fd:
            b, d, fd = d, c, fc
            c = b - _GOLD * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + _GOLD * (b - a)
            fd = f(d)
    return 0.5 * (a + b)


def _peak(rotor: Rotor, forcing: Forcing, i: int, lo: float, hi: float) -> float:
    """The speed of the amplitude's maximum in [lo, hi]: the root of its exact slope by
    Brent's method when the slope changes sign there (to ~1e-15 of the speed), else
    golden-section search on the amplitude (to ~1e-8: the maximum is flat)."""
    slope = lambda x: amplitude_slope(rotor, forcing, i, x)[1]  # noqa: E731
    s_lo, s_hi = slope(lo), slope(hi)
    if s_lo > 0.0 > s_hi:
        return brentq(slope, lo, hi, xtol=1e-14 * hi, rtol=4e-16)
    return _golden_max(lambda x: amplitude(rotor, forcing, i, x), lo, hi, 1e-12 * hi)


def _half_power(f, Nc: float, level: float, grid: np.ndarray, amps: np.ndarray, j: int,
                direction: int, limit: float) -> float | None:
    """The speed beside the peak (grid index j) where f = level, going down (direction -1)
    or up (+1); None when the curve turns up again first."""
    g = lambda x: f(x) - level  # noqa: E731
    prev_x, prev_a = Nc, f(Nc)
    k = j + direction
    while 0 <= k < len(grid):
        x, a = float(grid[k]), float(amps[k])
        if a <= level:
            lo, hi = (x, prev_x) if x < prev_x else (prev_x, x)
            return brentq(g, lo, hi, xtol=1e-12 * Nc, rtol=4e-16)
        if a > prev_a:  # rising again: another peak before the half-power point
            return None
        prev_x, prev_a = x, a
        k += direction
    # beyond the grid: step on (down to 0, up to ``limit``)
    x = prev_x
    for _ in range(200):
        x = x * 0.9 if direction < 0 else x * 1.1
        if direction > 0 and x > limit:
            return None
        a = f(x) if x > 0.0 else 0.0
        if a <= level:
            lo, hi = (x, prev_x) if x < prev_x else (prev_x, x)
            return brentq(g, lo, hi, xtol=1e-12 * Nc, rtol=4e-16)
        if a > prev_a:
            return None
        prev_x, prev_a = x, a
    return None


def peaks(rotor: Rotor, forcing: Forcing, res: Response) -> list[Peak]:
    """The resonance peaks of every bearing's amplitude over ``res.speeds``, refined, with
    their half-power points and amplification factors (module docstring). A peak is a grid
    point higher than its neighbours (not the range's ends); undamped, there are none.
    """
    out = []
    W = res.speeds
    # the response is linear in the forcing: solved for one scaled by a power of 2 (exact)
    # to amplitudes near 1, so that the root solves' products of values neither under- nor
    # overflow (an unbalance of 1e-300 kg m)
    e = math.frexp(float(np.max(res.displacement, initial=0.0)))[1]
    k = math.ldexp(1.0, -min(max(e, -1000), 1000))
    forcing = Forcing(k * forcing.static, k * forcing.couple)
    for i in range(len(rotor.bearings)):
        amps = k * res.displacement[i]
        f = lambda x, i=i: amplitude(rotor, forcing, i, x)  # noqa: E731
        for j in range(1, len(W) - 1):
            if not (amps[j] > amps[j - 1] and amps[j] >= amps[j + 1]):
                continue
            Nc = _peak(rotor, forcing, i, float(W[j - 1]), float(W[j + 1]))
            A = f(Nc)
            level = SQRT_HALF * A
            N1 = _half_power(f, Nc, level, W, amps, j, -1, 0.0)
            N2 = _half_power(f, Nc, level, W, amps, j, +1, 10.0 * Nc)
            if N1 is None or N2 is None or not N2 > N1:
                out.append(Peak(i, Nc, A / k, None, None))
            else:
                out.append(Peak(i, Nc, A / k, (N1, N2), Nc / (N2 - N1)))
    return out


# --- API margins


def required_margin(af: float | None, position: str) -> float:
    """%, the separation margin the API rule asks of a critical speed with amplification
    factor ``af`` (None: undamped, infinite) lying ``position`` ("below" the minimum
    operating speed or "above" the maximum continuous speed); 0 when AF < 2.5."""
    if af is not None and af < 2.5:
        return 0.0
    base = 17.0 if af is None else 17.0 * (1.0 - 1.0 / (af - 1.5))
    return min(16.0, base) if position == "below" else min(26.0, 10.0 + base)


@dataclass(frozen=True, eq=False)
class Margin:
    """One critical speed judged against the operating range: ``speed`` Nc (rad/s),
    ``amplification_factor`` (None: undamped), ``position`` ("below", "above", "within"),
    ``margin_percent`` and ``required_percent`` (%), ``passed``."""

    speed: float
    amplification_factor: float | None
    position: str
    margin_percent: float
    required_percent: float
    passed: bool


def margin(speed: float, af: float | None, n_min: float, n_max: float) -> Margin:
    """The API 617 / 684 separation margin check of a critical speed ``speed`` (rad/s) with
    amplification factor ``af`` against the operating range [n_min, n_max] (rad/s)."""
    if speed < n_min:
        pos, actual = "below", 100.0 * (n_min - speed) / n_min
    elif speed > n_max:
        pos, actual = "above", 100.0 * (speed - n_max) / n_max
    else:
        pos, actual = "within", 0.0
    if pos == "within":
        req = 0.0 if (af is not None and af < 2.5) else required_margin(af, "below")
        ok = af is not None and af < 2.5
    else:
        req = required_margin(af, pos)
        ok = actual >= req
    return Margin(float(speed), af, pos, float(actual), float(req), bool(ok))


def phase_deg(z: complex) -> float:
    """deg in [0, 360) of a complex number (0 for 0)."""
    return math.degrees(cmath.phase(z)) % 360.0 if z != 0 else 0.0
