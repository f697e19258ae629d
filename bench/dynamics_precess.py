"""Speed and accuracy of ``rbcli precess``'s exact motion against a numerical integration.

Usage::

    .venv/bin/python bench/dynamics_precess.py [--repeat 5] [--times 10000] [--periods 1e6]

Body I = diag(1, 2, 3) kg m^2, w0 = (1, 0.1, 0.2) rad/s (physics sheet case P4, period
11.2050 s). In one process, alternating, REPEAT times each:

(a) exact: ``omega_at`` and ``attitude_at`` (rbcli.core.freemotion, Jacobi elliptic
    functions and the elliptic integral of the third kind) at TIMES times spread evenly
    over PERIODS periods (default 10^4 times over 10^6 periods, t up to 1.1e7 s);
(b) numerical, the honest peer: ``scipy.integrate.solve_ivp`` with DOP853 at rtol 1e-10
    (atol 1e-12 of each component's scale) over 100 periods, state (w, R) with
    R' = R [w]x, in the body frame with the full tensor. (RK45 at its default tolerances,
    the peer of earlier versions, drifts by 7e-2: a weak comparison.)
(c) optionally, when ``import mujoco`` works: MuJoCo (a free body, no gravity, RK4 at
    1000 steps per period) over 10 periods, stepped from Python.

Reported: the median wall time of each, the ratio exact / DOP853 (the goal is < 1: the
exact motion at 10^4 times over 10^6 periods costs less than the integration of 100), the
invariant errors of each along its own points: max |T - T0|/T0, max ||L| - |L0||/|L0| and
max |R (I w) - L0|/|L0| (L fixed in space), and the difference of DOP853 from the exact
motion at its points (|dw|/|w| and the attitude angle). Goal: exact < 1e-10. The last line
is one JSON object with every number.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from rbcli.core import freemotion as fm  # noqa: E402
from rbcli.core import freepath  # noqa: E402
from rbcli.core.rotation import quat_to_matrix  # noqa: E402

INERTIA = np.diag([1.0, 2.0, 3.0])
OMEGA0 = np.array([1.0, 0.1, 0.2])


def invariants(w: np.ndarray, R: np.ndarray) -> dict:
    """Largest relative errors of T, |L| and L in space along (N,3) w and (N,3,3) R."""
    M = w @ INERTIA
    L0 = INERTIA @ OMEGA0
    G0 = float(np.linalg.norm(L0))
    T0 = 0.5 * float(OMEGA0 @ L0)
    T = 0.5 * np.einsum("ij,ij->i", w, M)
    G = np.linalg.norm(M, axis=1)
    Ls = np.einsum("nij,nj->ni", R, M)
    return {
        "energy": float(np.max(np.abs(T - T0)) / T0),
        "momentum": float(np.max(np.abs(G - G0)) / G0),
        "L_space": float(np.max(np.linalg.norm(Ls - L0, axis=1)) / G0),
    }


def run_exact(times: int, periods: float) -> tuple[float, dict]:
    t0 = time.perf_counter()
    motion = fm.analyse(INERTIA, OMEGA0)
    t = np.linspace(0.0, periods * motion.period, times)
    w = freepath.omega_at(motion, t)
    q = freepath.attitude_at(motion, t)
    elapsed = time.perf_counter() - t0
    return elapsed, invariants(w, quat_to_matrix(q))


def _rhs():
    Jinv = np.linalg.inv(INERTIA)

    def rhs(_t, y):
        w = y[:3]
        R = y[3:].reshape(3, 3)
        dw = Jinv @ np.cross(INERTIA @ w, w)
        W = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
        return np.concatenate([dw, (R @ W).ravel()])

    return rhs


def run_dop853(periods: float) -> tuple[float, dict, int, dict]:
    """DOP853 at rtol 1e-10 over ``periods`` periods; also its difference from the exact
    motion at its own points (not timed)."""
    from scipy.integrate import solve_ivp

    motion = fm.analyse(INERTIA, OMEGA0)  # not timed: the integration is
    wn = float(np.linalg.norm(OMEGA0))
    atol = np.concatenate([np.full(3, 1e-12 * wn), np.full(9, 1e-12)])
    t0 = time.perf_counter()
    sol = solve_ivp(_rhs(), (0.0, periods * motion.period), np.concatenate([OMEGA0, np.eye(3).ravel()]),
                    method="DOP853", rtol=1e-10, atol=atol)
    elapsed = time.perf_counter() - t0
    w = sol.y[:3].T
    R = sol.y[3:].T.reshape(-1, 3, 3)
    w_ex = freepath.omega_at(motion, sol.t)
    R_ex = quat_to_matrix(freepath.attitude_at(motion, sol.t))
    # the angle of R_ex^T R as in freemotion.verify: 2 asin(|R_ex - R|_F / (2 sqrt 2)) (an
    # arccos of the trace would read the integrator's loss of orthogonality, ~1e-9, as
    # sqrt(2e-9) = 4e-5 rad)
    ang = 2.0 * np.arcsin(np.minimum(np.linalg.norm(R_ex - R, axis=(1, 2)) / (2.0 * np.sqrt(2.0)), 1.0))
    diff = {"omega": float(np.max(np.linalg.norm(w - w_ex, axis=1) / np.linalg.norm(w_ex, axis=1))),
            "attitude_rad": float(np.max(ang))}
    return elapsed, invariants(w, R), int(sol.nfev), diff


def run_mujoco(periods: float, steps_per_period: int = 1000) -> tuple[float, dict] | None:
    """MuJoCo's RK4 on a free body (no gravity) with this inertia, or None without mujoco."""
    try:
        import mujoco
    except ImportError:
        return None
    period = fm.analyse(INERTIA, OMEGA0).period
    dt = period / steps_per_period
    xml = (f'<mujoco><option gravity="0 0 0" integrator="RK4" timestep="{dt!r}"/><worldbody>'
           '<body><freejoint/><inertial pos="0 0 0" mass="1" diaginertia="1 2 3"/></body>'
           "</worldbody></mujoco>")
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    data.qvel[3:6] = OMEGA0  # a free joint's angular velocity is in the body's local frame
    n = int(round(periods * steps_per_period))
    ws, qs = [], []
    t0 = time.perf_counter()
    for i in range(n):
        mujoco.mj_step(model, data)
        if i % 10 == 9:
            ws.append(data.qvel[3:6].copy())
            qs.append(data.qpos[3:7].copy())
    elapsed = time.perf_counter() - t0
    return elapsed, invariants(np.array(ws), quat_to_matrix(np.array(qs)))


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--times", type=int, default=10_000)
    ap.add_argument("--periods", type=float, default=1e6)
    ap.add_argument("--dop-periods", type=float, default=100.0)
    ap.add_argument("--mujoco-periods", type=float, default=10.0)
    args = ap.parse_args(argv)

    run_exact(100, 10.0)  # warm-up: imports and caches
    ex_times, dp_times, mj_times = [], [], []
    ex_err = dp_err = dp_diff = mj_err = None
    nfev = 0
    for _ in range(args.repeat):
        dt, ex_err = run_exact(args.times, args.periods)
        ex_times.append(dt)
        dt, dp_err, nfev, dp_diff = run_dop853(args.dop_periods)
        dp_times.append(dt)
        mj = run_mujoco(args.mujoco_periods)
        if mj is not None:
            mj_times.append(mj[0])
            mj_err = mj[1]
    ex_med = statistics.median(ex_times)
    dp_med = statistics.median(dp_times)
    mj_med = statistics.median(mj_times) if mj_times else None
    ratio = ex_med / dp_med
    ex_worst = max(ex_err.values())
    print(f"body I = (1, 2, 3) kg m^2, w0 = (1, 0.1, 0.2) rad/s (sheet P4), {args.repeat} runs each")
    print(f"  exact : {args.times} times over {args.periods:.3g} periods   median {ex_med * 1e3:8.2f} ms   "
          f"errors T {ex_err['energy']:.2e}  |L| {ex_err['momentum']:.2e}  L in space {ex_err['L_space']:.2e}")
    print(f"  DOP853: {args.dop_periods:.3g} periods, rtol 1e-10 ({nfev} evaluations)   median "
          f"{dp_med * 1e3:8.2f} ms   errors T {dp_err['energy']:.2e}  |L| {dp_err['momentum']:.2e}  "
          f"L in space {dp_err['L_space']:.2e}; from the exact motion |dw|/|w| {dp_diff['omega']:.1e}, "
          f"attitude {dp_diff['attitude_rad']:.1e} rad")
    if mj_med is not None:
        print(f"  MuJoCo: {args.mujoco_periods:.3g} periods, RK4, 1000 steps/period   median {mj_med * 1e3:8.2f} ms   "
              f"errors T {mj_err['energy']:.2e}  |L| {mj_err['momentum']:.2e}  L in space {mj_err['L_space']:.2e}")
    else:
        print("  MuJoCo: not installed (optional)")
    ok = ratio < 1.0 and ex_worst < 1e-10
    print(f"  time ratio exact/DOP853: {ratio:.3f} (goal < 1); exact invariants {ex_worst:.1e} (goal < 1e-10); "
          f"{'PASS' if ok else 'FAIL'}")
    print(json.dumps({
        "times": args.times, "periods": args.periods, "dop_periods": args.dop_periods, "repeat": args.repeat,
        "exact_median_s": ex_med, "dop853_median_s": dp_med, "ratio": ratio, "dop853_nfev": nfev,
        "exact_errors": ex_err, "dop853_errors": dp_err, "dop853_vs_exact": dp_diff,
        "mujoco_periods": args.mujoco_periods if mj_med is not None else None,
        "mujoco_median_s": mj_med, "mujoco_errors": mj_err, "pass": ok,
    }))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
