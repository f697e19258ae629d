"""The exact torque-free motion against a numerical integration (``precess --verify``).

:func:`verify` integrates Euler's equations and the attitude with scipy's DOP853 (imported
here only: the default path of ``precess`` loads no scipy) and compares them with the
closed forms of :mod:`rbcli.core.freemotion`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from rbcli.core.freemotion import FreeMotion
from rbcli.core.freepath import attitude_at, omega_at
from rbcli.core.rotation import quat_to_matrix

__all__ = ["VerifyResult", "verify"]

_TWO_PI = 2.0 * math.pi


@dataclass(frozen=True, eq=False)
class VerifyResult:
    """Exact solution against a numerical integration (:func:`verify`): ``t_end`` (s),
    ``samples``, ``rtol``, ``nfev``; ``omega_error`` (max relative), ``attitude_error`` (rad);
    the drifts of T, |L| and L in space along the numerical (``numeric_*``) and the exact
    (``exact_*``: round-off only) solutions; ``tol`` and ``ok`` (all of the exact's within it)."""

    t_end: float
    samples: int
    rtol: float
    nfev: int
    omega_error: float
    attitude_error: float
    numeric_energy_drift: float
    numeric_momentum_drift: float
    numeric_L_drift: float
    exact_energy_drift: float
    exact_momentum_drift: float
    exact_L_drift: float
    tol: float
    ok: bool

    def to_json(self) -> dict[str, Any]:
        """Plain-JSON form."""
        return {
            "t_end": float(self.t_end),
            "samples": int(self.samples),
            "rtol": float(self.rtol),
            "nfev": int(self.nfev),
            "omega_error": float(self.omega_error),
            "attitude_error": float(self.attitude_error),
            "numeric_energy_drift": float(self.numeric_energy_drift),
            "numeric_momentum_drift": float(self.numeric_momentum_drift),
            "numeric_L_drift": float(self.numeric_L_drift),
            "exact_energy_drift": float(self.exact_energy_drift),
            "exact_momentum_drift": float(self.exact_momentum_drift),
            "exact_L_drift": float(self.exact_L_drift),
            "tol": float(self.tol),
            "ok": bool(self.ok),
        }



# --- verification against numerical integration


def _char_time(motion: FreeMotion) -> float:
    if motion.period is not None:
        return motion.period
    if motion.elliptic is not None:
        return _TWO_PI / motion.elliptic.lam
    wn = float(np.linalg.norm(motion.omega0_principal))
    return _TWO_PI / wn if wn > 0 else 1.0


def verify(
    motion: FreeMotion,
    periods: float = 3,
    rtol: float = 1e-12,
    *,
    samples_per_period: int = 200,
    tol: float = 1e-8,
) -> VerifyResult:
    """Compare the exact motion with a DOP853 integration of Euler's equations and attitude.

    ``periods`` of omega (or characteristic times when not periodic), ``solve_ivp`` at ``rtol``
    (atol rtol/100 of each component's scale), ``samples_per_period`` comparison times, ``tol``
    the threshold of ``ok``: a VerifyResult.

    Notes
    -----
    Body frame, full tensor (independent of the principal decomposition): ``J w' = (J w) x w``,
    ``R' = R [w]x``, R(0) = 1 (sheet §1). Near the separatrix the integrator's own error grows
    by about 1/k' per passage, so a large omega_error there is the integrator's."""
    from scipy.integrate import solve_ivp

    J = motion.inertia
    Jinv = np.linalg.inv(J)
    w0 = motion.omega0_principal @ motion.axes
    wn = float(np.linalg.norm(w0))
    t_end = float(periods) * _char_time(motion)
    n = max(int(math.ceil(float(periods) * samples_per_period)), 2) + 1
    ts = np.linspace(0.0, t_end, n)

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        w = y[:3]
        R = y[3:].reshape(3, 3)
        dw = Jinv @ np.cross(J @ w, w)
        W = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
        return np.concatenate([dw, (R @ W).ravel()])

    y0 = np.concatenate([w0, np.eye(3).ravel()])
    atol = np.concatenate([np.full(3, rtol * 1e-2 * max(wn, 1e-300)), np.full(9, rtol * 1e-2)])
    sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=rtol, atol=atol,
                    t_eval=ts, dense_output=False)
    if not sol.success:  # pragma: no cover - DOP853 does not fail on this smooth system
        raise RuntimeError(f"integration failed: {sol.message}")
    w_num = sol.y[:3].T
    R_num = sol.y[3:].T.reshape(-1, 3, 3)
    w_ex = omega_at(motion, ts)
    R_ex = quat_to_matrix(attitude_at(motion, ts))

    wmag = np.linalg.norm(w_ex, axis=1)
    omega_err = float(np.max(np.linalg.norm(w_ex - w_num, axis=1) / np.where(wmag > 0, wmag, 1.0)))
    dR = np.linalg.norm(R_ex - R_num, axis=(1, 2))
    att_err = float(np.max(2.0 * np.arcsin(np.minimum(dR / (2.0 * math.sqrt(2.0)), 1.0))))

    L0 = J @ w0
    G0 = float(np.linalg.norm(L0))
    T0 = 0.5 * float(w0 @ L0)

    def drifts(w: np.ndarray, R: np.ndarray) -> tuple[float, float, float]:
        M = w @ J  # J symmetric: rows J w
        T = 0.5 * np.einsum("ij,ij->i", w, M)
        Gs = np.linalg.norm(M, axis=1)
        Ls = np.einsum("nij,nj->ni", R, M)
        dT = float(np.max(np.abs(T - T0))) / (T0 if T0 > 0 else 1.0)
        dG = float(np.max(np.abs(Gs - G0))) / (G0 if G0 > 0 else 1.0)
        dL = float(np.max(np.linalg.norm(Ls - L0, axis=1))) / (G0 if G0 > 0 else 1.0)
        return dT, dG, dL

    nT, nG, nL = drifts(w_num, R_num)
    eT, eG, eL = drifts(w_ex, R_ex)
    ok = all(x <= tol for x in (omega_err, att_err, eT, eG, eL))
    return VerifyResult(
        t_end=t_end, samples=n, rtol=rtol, nfev=int(sol.nfev), omega_error=omega_err,
        attitude_error=att_err, numeric_energy_drift=nT, numeric_momentum_drift=nG,
        numeric_L_drift=nL, exact_energy_drift=eT, exact_momentum_drift=eG, exact_L_drift=eL,
        tol=tol, ok=ok,
    )
