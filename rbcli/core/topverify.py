"""``top --verify``: the closed form of :mod:`rbcli.core.top` against a numerical integration.

Pure physics, SI units. The equations of motion of a rigid body on a fixed pivot in
uniform gravity are integrated with DOP853 (Hairer, Nørsett and Wanner, *Solving Ordinary
Differential Equations I*, 2nd ed., §II.10; scipy.integrate.DOP853) in a form with no
Euler angles, and the result is compared with the closed form at evenly spaced times.
The verdict's rule is :meth:`VerifyResult.passed`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rbcli.core.checks import json_float
from rbcli.core.top import TopMotion
from rbcli.core.toppath import path_at

#: the closed form and the integration must agree this well (axis chord, rad) ...
AXIS_TOL = 1e-6
#: ... and the energy may drift at most this much (relative to T0 + m g l), or the check
#: fails (exit status 1)
ENERGY_TOL = 1e-9
#: the most integrator steps one check may take (the course's top needs about 400; each
#: step costs about 0.2 ms, so the bound is a few seconds)
MAX_STEPS = 20_000
PERIODS_TEXT = "3"


@dataclass(frozen=True)
class VerifyResult:
    """Closed form against a direct integration of the equations of motion.

    Attributes
    ----------
    t_end, samples, rtol, nfev — s integrated (``periods`` nutation periods), comparison times,
        DOP853's tolerance, right-hand-side evaluations
    max_axis_error : float — rad (chord), max |e3_closed - e3_numeric|
    max_theta_error, max_phi_error, max_psi_error : float — rad (φ, ψ modulo 2π)
    energy_drift : float — max |E - E0| / (T0 + m g l)
    p_phi_drift, p_psi_drift : float — max drift of L·ẑ and L·e3, relative to |L0|
    theta_min, theta_max : float — rad, the tilt range the integrator saw
    mean_precession_rate : float — rad/s, from the integrator
    axis_tolerance, energy_tolerance : float — what passes"""

    t_end: float
    samples: int
    rtol: float
    max_axis_error: float
    max_theta_error: float
    max_phi_error: float
    max_psi_error: float
    energy_drift: float
    p_phi_drift: float
    p_psi_drift: float
    theta_min: float
    theta_max: float
    mean_precession_rate: float
    nfev: int
    axis_tolerance: float = AXIS_TOL
    energy_tolerance: float = ENERGY_TOL

    @property
    def passed(self) -> bool:
        """The verdict: the axis within ``axis_tolerance`` and the energy drift within
        ``energy_tolerance``."""
        return self.max_axis_error <= self.axis_tolerance and self.energy_drift <= self.energy_tolerance

    def to_json(self) -> dict:
        return {
            "t_end": json_float(self.t_end),
            "samples": int(self.samples),
            "rtol": float(self.rtol),
            "max_axis_error": json_float(self.max_axis_error),
            "max_theta_error_deg": json_float(math.degrees(self.max_theta_error)),
            "max_phi_error_deg": json_float(math.degrees(self.max_phi_error)),
            "max_psi_error_deg": json_float(math.degrees(self.max_psi_error)),
            "energy_drift": json_float(self.energy_drift),
            "p_phi_drift": json_float(self.p_phi_drift),
            "p_psi_drift": json_float(self.p_psi_drift),
            "theta_min_deg": json_float(math.degrees(self.theta_min)),
            "theta_max_deg": json_float(math.degrees(self.theta_max)),
            "mean_precession_rate": json_float(self.mean_precession_rate),
            "nfev": int(self.nfev),
            "axis_tolerance": float(self.axis_tolerance),
            "energy_tolerance": float(self.energy_tolerance),
            "pass": bool(self.passed),
        }


class TooLong(ValueError):
    """The integration cannot finish in the allowed number of steps; the message says why
    (the span and how many times the body turns in it) and what to do."""


def _what(motion: TopMotion, T: float) -> str:
    turns = abs(motion.spin) * T / (2.0 * math.pi)
    return (f"{PERIODS_TEXT} nutation periods are {T:.4g} s, in which the body turns about "
            f"its axis {turns:.4g} times")


def integrate(rhs, y0: np.ndarray, T: float, ts: np.ndarray, *, rtol: float, atol: float,
              max_steps: int | None = None, what: str = "") -> tuple[np.ndarray, int]:
    """DOP853 from t = 0 to ``T`` (the steps and dense output of ``solve_ivp(...,
    method="DOP853", t_eval=ts)``) with at most ``max_steps`` steps: the states at ``ts``
    (len(ts), len(y0)) and the right-hand-side evaluations. :class:`TooLong` beyond it."""
    from scipy.integrate import DOP853

    limit = MAX_STEPS if max_steps is None else int(max_steps)
    solver = DOP853(rhs, 0.0, y0, T, rtol=rtol, atol=atol)
    ys = []
    i = steps = 0
    while solver.status == "running":
        if steps >= limit:
            raise TooLong(
                f"the numerical integration cannot finish in {limit} steps ({what}; it reached "
                f"t = {solver.t:.4g} s): this motion is too long to check step by step; run "
                "without {verify} (the closed form is exact and does not need it)"
            )
        solver.step()
        steps += 1
        if solver.status == "failed":  # pragma: no cover - DOP853 on a smooth ODE
            raise RuntimeError("numerical integration failed")
        k = int(np.searchsorted(ts, solver.t, side="right"))
        if k > i:
            ys.append(solver.dense_output()(ts[i:k]))
            i = k
    return np.hstack(ys).T, int(solver.nfev)


def _wrap(x: np.ndarray) -> np.ndarray:
    return (x + np.pi) % (2.0 * np.pi) - np.pi


def verify(
    motion: TopMotion,
    periods: float = 3,
    *,
    rtol: float = 1e-12,
    samples_per_period: int = 200,
    axis_tol: float | None = None,
    energy_tol: float | None = None,
    max_steps: int | None = None,
) -> VerifyResult:
    """Integrate the top's equations of motion numerically and compare with the closed form.

    ``periods`` nutation periods at DOP853 ``rtol`` (absolute rtol/10 on a state of order 1),
    ``samples_per_period`` comparison times; the verdict's ``axis_tol`` and ``energy_tol``
    (default :data:`AXIS_TOL`, :data:`ENERGY_TOL`). :class:`TooLong` beyond ``max_steps``
    (default :data:`MAX_STEPS`). Returns a :class:`VerifyResult`.

    Notes
    -----
    No Euler angles: the state is the axis e3, a body-fixed e1 across it and L about the pivot,
    in space axes (z up): ω = (L - (L·e3)e3)/I + (L·e3/Is) e3, e3' = (L × e3)/I, e1' = ω × e1,
    L' = m g l ẑ × e3, from R0 = Ry(θ0) and ω0 = φ0' ẑ + θ0' ŷ + (S - φ0' cos θ0) e3. Angles are
    read back as θ = atan2(|e3 × ẑ|, e3·ẑ), φ = atan2(e3y, e3x), ψ = atan2(e1·n2, e1·n1)."""
    if not (periods > 0 and math.isfinite(periods)):
        raise ValueError(f"periods must be a positive number, not {periods}")
    if motion.nutation_period is None:
        raise ValueError("the motion has no finite nutation period to integrate over")
    p = motion.params
    I, Is = p.I, p.Is
    mgl = p.mass * motion.g * p.length
    S = motion.spin
    th0, thd, w = motion.theta0, motion.theta_dot0, motion.phi_dot0
    c0, s0 = math.cos(th0), math.sin(th0)
    e3 = np.array([s0, 0.0, c0])
    e1 = np.array([c0, 0.0, -s0])
    zhat = np.array([0.0, 0.0, 1.0])
    om = w * zhat + thd * np.array([0.0, 1.0, 0.0]) + (S - w * c0) * e3
    om3 = float(om @ e3)
    L = I * (om - om3 * e3) + Is * om3 * e3
    Ls = float(np.linalg.norm(L))  # > 0 since Is S != 0

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        # plain floats: a step costs ~12 calls, and numpy's small-array overhead dominated
        n0, n1, n2, e0, e1_, e2, l0, l1, l2 = y.tolist()
        l0, l1, l2 = l0 * Ls, l1 * Ls, l2 * Ls
        L3 = l0 * n0 + l1 * n1 + l2 * n2
        k = L3 / Is
        w0 = (l0 - L3 * n0) / I + k * n0
        w1 = (l1 - L3 * n1) / I + k * n1
        w2 = (l2 - L3 * n2) / I + k * n2
        return np.array([
            w1 * n2 - w2 * n1, w2 * n0 - w0 * n2, w0 * n1 - w1 * n0,
            w1 * e2 - w2 * e1_, w2 * e0 - w0 * e2, w0 * e1_ - w1 * e0,
            mgl * -n1 / Ls, mgl * n0 / Ls, 0.0,
        ])

    T = float(motion.nutation_period) * float(periods)
    n_s = max(int(math.ceil(samples_per_period * periods)), 2) + 1
    ts = np.linspace(0.0, T, n_s)
    y0 = np.concatenate([e3, e1, L / Ls])
    Y, nfev = integrate(rhs, y0, T, ts, rtol=rtol, atol=rtol * 0.1, max_steps=max_steps,
                        what=_what(motion, T))
    n = Y[:, 0:3]
    e = Y[:, 3:6]
    Lv = Y[:, 6:9] * Ls

    theta_n = np.arctan2(np.hypot(n[:, 0], n[:, 1]), n[:, 2])
    phi_n = np.unwrap(np.arctan2(n[:, 1], n[:, 0]))
    phi_n -= phi_n[0]
    ct, st = np.cos(theta_n), np.sin(theta_n)
    cf, sf = np.cos(phi_n), np.sin(phi_n)
    n1 = np.stack([ct * cf, ct * sf, -st], axis=-1)
    n2 = np.stack([-sf, cf, np.zeros_like(sf)], axis=-1)
    psi_n = np.arctan2(np.sum(e * n2, axis=1), np.sum(e * n1, axis=1))

    theta_c, phi_c, psi_c = path_at(motion, ts)
    stc = np.sin(theta_c)
    axis_c = np.stack([stc * np.cos(phi_c), stc * np.sin(phi_c), np.cos(theta_c)], axis=-1)

    L3 = np.sum(Lv * n, axis=1)
    Lperp2 = np.sum(Lv * Lv, axis=1) - L3**2
    E = 0.5 * Lperp2 / I + 0.5 * L3**2 / Is + mgl * n[:, 2]
    T0 = 0.5 * Lperp2[0] / I + 0.5 * L3[0] ** 2 / Is
    return VerifyResult(
        t_end=T,
        samples=n_s,
        rtol=rtol,
        max_axis_error=float(np.max(np.linalg.norm(axis_c - n, axis=1))),
        max_theta_error=float(np.max(np.abs(theta_c - theta_n))),
        max_phi_error=float(np.max(np.abs(_wrap(phi_c - phi_n)))),
        max_psi_error=float(np.max(np.abs(_wrap(psi_c - psi_n)))),
        energy_drift=float(np.max(np.abs(E - E[0])) / (T0 + mgl)),
        p_phi_drift=float(np.max(np.abs(Lv[:, 2] - Lv[0, 2])) / Ls),
        p_psi_drift=float(np.max(np.abs(L3 - L3[0])) / Ls),
        theta_min=float(np.min(theta_n)),
        theta_max=float(np.max(theta_n)),
        mean_precession_rate=float(phi_n[-1] / T),
        nfev=int(nfev),
        axis_tolerance=AXIS_TOL if axis_tol is None else float(axis_tol),
        energy_tolerance=ENERGY_TOL if energy_tol is None else float(energy_tol),
    )


# --- the real (unsymmetrised) body


@dataclass(frozen=True)
class RealBodyCheck:
    """The real (unsymmetrised) body integrated from the same start, against the symmetrised
    closed form: ``t_end`` (s), ``samples``, ``max_axis_error`` (rad, chord),
    ``max_theta_error``, ``max_phi_error`` (rad), ``energy_drift`` (the integration's
    accuracy) and ``nfev``."""

    t_end: float
    samples: int
    max_axis_error: float
    max_theta_error: float
    max_phi_error: float
    energy_drift: float
    nfev: int

    def to_json(self) -> dict:
        return {
            "t_end": json_float(self.t_end),
            "samples": int(self.samples),
            "max_axis_error": json_float(self.max_axis_error),
            "max_theta_error_deg": json_float(math.degrees(self.max_theta_error)),
            "max_phi_error_deg": json_float(math.degrees(self.max_phi_error)),
            "energy_drift": json_float(self.energy_drift),
            "nfev": int(self.nfev),
        }


def verify_real_body(
    motion: TopMotion,
    periods: float = 3,
    *,
    rtol: float = 1e-12,
    samples_per_period: int = 200,
    max_steps: int | None = None,
) -> RealBodyCheck:
    """Integrate the real body of a nearly symmetric top and compare with the closed form.

    ``motion.params.asymmetry`` holds the real tensor J about the pivot (body axes) and e3.
    Euler's equations with the gravity torque (Goldstein §5.5): J ω' = τ - ω × (J ω),
    τ = l e3 × (-m g Rᵀ ẑ), and the attitude quaternion q' = ½ q ⊗ (0, ω), by DOP853 from the
    closed form's start. ValueError without an asymmetry record or a finite nutation period;
    :class:`TooLong` beyond ``max_steps``."""
    sym = motion.params.asymmetry
    if sym is None:
        raise ValueError("the top has no record of its real inertia (it is symmetric)")
    if motion.nutation_period is None:
        raise ValueError("the motion has no finite nutation period to integrate over")
    p = motion.params
    mg = p.mass * motion.g
    l_ = p.length
    J = np.array(sym.inertia, dtype=float)
    Ji = np.linalg.inv(J)
    e3b = np.array(sym.axis, dtype=float)
    e1b = np.array(sym.transverse_axes[0], dtype=float)
    e1b = e1b - (e1b @ e3b) * e3b
    e1b /= np.linalg.norm(e1b)
    e2b = np.cross(e3b, e1b)
    th0, thd, w = motion.theta0, motion.theta_dot0, motion.phi_dot0
    c0, s0 = math.cos(th0), math.sin(th0)
    e3s = np.array([s0, 0.0, c0])
    R0 = np.column_stack([[c0, 0.0, -s0], [0.0, 1.0, 0.0], e3s]) @ np.vstack([e1b, e2b, e3b])
    om_s = w * np.array([0.0, 0.0, 1.0]) + thd * np.array([0.0, 1.0, 0.0]) + (motion.spin - w * c0) * e3s
    om_b = R0.T @ om_s
    Ws = float(np.linalg.norm(om_b))
    q0 = _quat_from_matrix(R0)
    rb = (l_ * e3b).tolist()
    Jl, Jil = J.tolist(), Ji.tolist()

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        a, b, c, d, x, yy, z = y.tolist()
        x, yy, z = x * Ws, yy * Ws, z * Ws
        n2 = a * a + b * b + c * c + d * d
        # space ẑ in body axes: the third row of R(q) (q unnormalised: divided by |q|²)
        zx = 2.0 * (b * d - a * c) / n2
        zy = 2.0 * (c * d + a * b) / n2
        zz = (a * a - b * b - c * c + d * d) / n2
        fx, fy, fz = -mg * zx, -mg * zy, -mg * zz
        tx = rb[1] * fz - rb[2] * fy
        ty = rb[2] * fx - rb[0] * fz
        tz = rb[0] * fy - rb[1] * fx
        hx = Jl[0][0] * x + Jl[0][1] * yy + Jl[0][2] * z
        hy = Jl[1][0] * x + Jl[1][1] * yy + Jl[1][2] * z
        hz = Jl[2][0] * x + Jl[2][1] * yy + Jl[2][2] * z
        gx = tx - (yy * hz - z * hy)
        gy = ty - (z * hx - x * hz)
        gz = tz - (x * hy - yy * hx)
        return np.array([
            0.5 * (-b * x - c * yy - d * z),
            0.5 * (a * x + c * z - d * yy),
            0.5 * (a * yy + d * x - b * z),
            0.5 * (a * z + b * yy - c * x),
            (Jil[0][0] * gx + Jil[0][1] * gy + Jil[0][2] * gz) / Ws,
            (Jil[1][0] * gx + Jil[1][1] * gy + Jil[1][2] * gz) / Ws,
            (Jil[2][0] * gx + Jil[2][1] * gy + Jil[2][2] * gz) / Ws,
        ])

    T = float(motion.nutation_period) * float(periods)
    n_s = max(int(math.ceil(samples_per_period * periods)), 2) + 1
    ts = np.linspace(0.0, T, n_s)
    y0 = np.concatenate([q0, om_b / Ws])
    Y, nfev = integrate(rhs, y0, T, ts, rtol=rtol, atol=rtol * 0.1, max_steps=max_steps,
                        what=_what(motion, T))
    q = Y[:, 0:4] / np.linalg.norm(Y[:, 0:4], axis=1)[:, None]
    om = Y[:, 4:7] * Ws
    R = _quat_to_matrix(q)
    axis_n = R @ e3b
    theta_n = np.arctan2(np.hypot(axis_n[:, 0], axis_n[:, 1]), axis_n[:, 2])
    phi_n = np.unwrap(np.arctan2(axis_n[:, 1], axis_n[:, 0]))
    phi_n -= phi_n[0]
    theta_c, phi_c, _ = path_at(motion, ts)
    stc = np.sin(theta_c)
    axis_c = np.stack([stc * np.cos(phi_c), stc * np.sin(phi_c), np.cos(theta_c)], axis=-1)
    kinetic = 0.5 * np.einsum("ni,ij,nj->n", om, J, om)
    E = kinetic + mg * l_ * axis_n[:, 2]
    return RealBodyCheck(
        t_end=T,
        samples=n_s,
        max_axis_error=float(np.max(np.linalg.norm(axis_c - axis_n, axis=1))),
        max_theta_error=float(np.max(np.abs(theta_c - theta_n))),
        max_phi_error=float(np.max(np.abs(_wrap(phi_c - phi_n)))),
        energy_drift=float(np.max(np.abs(E - E[0])) / (kinetic[0] + mg * l_)),
        nfev=int(nfev),
    )


def _quat_to_matrix(q: np.ndarray) -> np.ndarray:
    """Rotation matrices (n, 3, 3) of unit quaternions (n, 4) [w, x, y, z] (Hamilton)."""
    w, x, y, z = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], axis=-1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], axis=-1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], axis=-1),
    ], axis=-2)


def _quat_from_matrix(R: np.ndarray) -> np.ndarray:
    """The unit quaternion [w, x, y, z] of a rotation matrix (Shepperd's method: the largest
    of the four squared components first, so no division by a small number)."""
    tr = float(np.trace(R))
    cands = [1.0 + tr, 1.0 + R[0, 0] - R[1, 1] - R[2, 2], 1.0 - R[0, 0] + R[1, 1] - R[2, 2],
             1.0 - R[0, 0] - R[1, 1] + R[2, 2]]
    k = int(np.argmax(cands))
    s = 2.0 * math.sqrt(cands[k])
    if k == 0:
        q = [0.25 * s, (R[2, 1] - R[1, 2]) / s, (R[0, 2] - R[2, 0]) / s, (R[1, 0] - R[0, 1]) / s]
    elif k == 1:
        q = [(R[2, 1] - R[1, 2]) / s, 0.25 * s, (R[0, 1] + R[1, 0]) / s, (R[0, 2] + R[2, 0]) / s]
    elif k == 2:
        q = [(R[0, 2] - R[2, 0]) / s, (R[0, 1] + R[1, 0]) / s, 0.25 * s, (R[1, 2] + R[2, 1]) / s]
    else:
        q = [(R[1, 0] - R[0, 1]) / s, (R[0, 2] + R[2, 0]) / s, (R[1, 2] + R[2, 1]) / s, 0.25 * s]
    return np.array(q) / math.sqrt(sum(v * v for v in q))
