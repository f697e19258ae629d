"""Speed and accuracy of ``rbcli precess``'s exact motion against a numerical integration.

Usage::

    .venv/bin/python bench/dynamics_precess.py [--repeat 5] [--times 10000] [--periods 1e6]

Body I = diag(1, 2, 3) kg m^2, w0 = (1, 0.1, 0.2) rad/s (physics sheet case P4, period
11.2050 s). In one process, alternating, REPEAT times each:

(a) exact: ``omega_at`` and ``attitude_at`` (rbcli.core.freemotion, Jacobi elliptic
    functions and the elliptic integral of the third kind) at TIMES times spread evenly
    over PERIODS periods (default 10^4 times over 10^6 periods, t up to 1.1e7 s);
(b) numerical: ``scipy.integrate.solve_ivp`` with RK45 at its default tolerances
    (rtol 1e-3, atol 1e-6) over 100 periods, state (w, R) with R' = R [w]x, in the body frame
    with the full tensor (sheet §1.3's "RK45 default" row).

Reported: the median wall time of each, their ratio (exact / RK45: the goal is < 1), and
the invariant errors of each along its own points: max |T - T0|/T0, max ||L| - |L0||/|L0|
and max |R (I w) - L0|/|L0| (L fixed in space). Goal: exact < 1e-10 where RK45 drifts by
about 1e-2. The last line is one JSON object with every number.
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
    w = fm.omega_at(motion, t)
    q = fm.attitude_at(motion, t)
    elapsed = time.perf_counter() - t0
    return elapsed, invariants(w, quat_to_matrix(q))


def run_rk45(periods: float) -> tuple[float, dict, int]:
    from scipy.integrate import solve_ivp

    Jinv = np.linalg.inv(INERTIA)

    def rhs(_t, y):
        w = y[:3]
        R = y[3:].reshape(3, 3)
        dw = Jinv @ np.cross(INERTIA @ w, w)
        W = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
        return np.concatenate([dw, (R @ W).ravel()])

    period = fm.analyse(INERTIA, OMEGA0).period  # not timed: the integration is
    t0 = time.perf_counter()
    sol = solve_ivp(rhs, (0.0, periods * period), np.concatenate([OMEGA0, np.eye(3).ravel()]), method="RK45")
    elapsed = time.perf_counter() - t0
    w = sol.y[:3].T
    R = sol.y[3:].T.reshape(-1, 3, 3)
    return elapsed, invariants(w, R), int(sol.nfev)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--times", type=int, default=10_000)
    ap.add_argument("--periods", type=float, default=1e6)
    ap.add_argument("--rk-periods", type=float, default=100.0)
    args = ap.parse_args(argv)

    run_exact(100, 10.0)  # warm-up: imports (scipy.special) and caches
    ex_times, rk_times = [], []
    ex_err = rk_err = None
    nfev = 0
    for _ in range(args.repeat):
        dt, ex_err = run_exact(args.times, args.periods)
        ex_times.append(dt)
        dt, rk_err, nfev = run_rk45(args.rk_periods)
        rk_times.append(dt)
    ex_med = statistics.median(ex_times)
    rk_med = statistics.median(rk_times)
    ratio = ex_med / rk_med
    ex_worst = max(ex_err.values())
    rk_worst = max(rk_err.values())
    print(f"body I = (1, 2, 3) kg m^2, w0 = (1, 0.1, 0.2) rad/s (sheet P4), {args.repeat} runs each")
    print(f"  exact : {args.times} times over {args.periods:.3g} periods   median {ex_med * 1e3:8.2f} ms   "
          f"errors T {ex_err['energy']:.2e}  |L| {ex_err['momentum']:.2e}  L in space {ex_err['L_space']:.2e}")
    print(f"  RK45  : {args.rk_periods:.3g} periods, default tolerances ({nfev} evaluations)   median "
          f"{rk_med * 1e3:8.2f} ms   errors T {rk_err['energy']:.2e}  |L| {rk_err['momentum']:.2e}  "
          f"L in space {rk_err['L_space']:.2e}")
    ok = ratio < 1.0 and ex_worst < 1e-10
    print(f"  time ratio exact/RK45: {ratio:.3f} (goal < 1); exact invariants {ex_worst:.1e} (goal < 1e-10); "
          f"{'PASS' if ok else 'FAIL'}")
    print(json.dumps({
        "times": args.times, "periods": args.periods, "rk_periods": args.rk_periods, "repeat": args.repeat,
        "exact_median_s": ex_med, "rk45_median_s": rk_med, "ratio": ratio, "rk45_nfev": nfev,
        "exact_errors": ex_err, "rk45_errors": rk_err, "pass": ok,
    }))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
