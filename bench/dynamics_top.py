"""Speed and accuracy of ``rbcli top``'s exact motion against numerical integration.

Usage::

    python bench/dynamics_top.py [--repeat 3] [--times 10000] [--periods 1e6] [--json OUT]

The course top (examples/top.yaml, physics sheet T1): m = 0.5 kg, l = 0.04 m,
I = 1.2e-3 and Is = 4.0e-4 kg m^2 about the pivot, S = 150 rad/s, released from rest
at 30° with g = 9.81 (nutation period 0.1421 s). In one process, alternating, REPEAT
times each:

(a) exact: ``analyse`` + ``path_at`` (rbcli.core.top: Jacobi elliptic functions and
    Carlson's elliptic integrals) at TIMES times spread evenly over PERIODS nutation
    periods (default 10^4 times over 10^6 periods, t up to 1.4e5 s);
(b) RK45: ``scipy.integrate.solve_ivp`` at its default tolerances (rtol 1e-3,
    atol 1e-6) over 100 nutation periods;
(c) DOP853 at rtol 1e-12 (what ``rbcli top --verify`` uses) over 10 periods (DOP-PERIODS;
    ~1300 evaluations per period, so 100 periods would take most of the run).

The numerical state is Euler-angle free (this file's own right-hand side, written
from the sheet's equations): the axis e3, a body-fixed unit vector e1 normal to it,
and the angular momentum L about the pivot, in space axes, z up:
e3' = w x e3, e1' = w x e1, L' = m g l z x e3, w = (L - (L.e3) e3)/I + (L.e3/Is) e3.

Reported: median times and ratios; invariants along each solution (max relative
error of the energy E, of p_phi = L.z and of p_psi = L.e3, relative to the energy
scale Is S^2/2 + m g l and to |L0|): for the integrators from their own state (p_phi
is conserved exactly by this form: L' has no z component), for the exact motion
from its angles differentiated numerically (see ``exact_invariants``: in the first
100 periods and around 10^6 periods, where the round-off of phi ~ 5e5 rad, not the
closed form, sets the figure); and the largest difference between the closed-form
angles and each integrator's at the integrator's points. The last line is one JSON
object with every number.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from rbcli.core import top as tp  # noqa: E402
from rbcli.core import toppath  # noqa: E402
from rbcli.core.topbody import TopParams  # noqa: E402

PARAMS = TopParams(mass=0.5, length=0.04, I=1.2e-3, Is=4.0e-4)
SPIN, THETA0, G = 150.0, math.radians(30.0), 9.81


def motion():
    return tp.analyse(PARAMS, SPIN, THETA0, 0.0, 0.0, g=G)


def _invariants_from_angles(th, ph, ps, thd, phd, psd) -> dict:
    """Relative errors of E, p_phi, p_psi along angles and their rates (arrays)."""
    I, Is, mgl = PARAMS.I, PARAMS.Is, PARAMS.mass * G * PARAMS.length
    w3 = psd + phd * np.cos(th)
    E = 0.5 * I * (thd**2 + (phd * np.sin(th)) ** 2) + 0.5 * Is * w3**2 + mgl * np.cos(th)
    p_phi = I * phd * np.sin(th) ** 2 + Is * w3 * np.cos(th)
    p_psi = Is * w3
    E0 = 0.5 * Is * SPIN**2 + mgl * math.cos(THETA0)
    Ls = math.hypot(Is * SPIN * math.cos(THETA0), Is * SPIN * math.sin(THETA0))  # |L0| at rest
    pphi0 = Is * SPIN * math.cos(THETA0)
    return {
        "energy": float(np.max(np.abs(E - E0)) / (0.5 * Is * SPIN**2 + mgl)),
        "p_phi": float(np.max(np.abs(p_phi - pphi0)) / Ls),
        "p_psi": float(np.max(np.abs(p_psi - Is * SPIN)) / Ls),
    }


def run_exact(times: int, periods: float) -> tuple[float, np.ndarray]:
    t0 = time.perf_counter()
    m = motion()
    t = np.linspace(0.0, periods * m.nutation_period, times)
    th, ph, ps = toppath.path_at(m, t)
    elapsed = time.perf_counter() - t0
    return elapsed, t


def exact_invariants(t_end: float, n: int = 200) -> dict:
    """Invariants of the closed form from its angles, rates by 6-point central differences
    (h = T_n/100, truncation ~ (h w_n)^6/140 ~ 4e-10), on n times in the first 100
    nutation periods and on n times in the last 0.1 % before t_end. At the late times
    the round-off of phi itself (~eps |phi|, |phi| ~ 5e5 rad at 10^6 periods) divided
    by h limits the figure, not the closed form."""
    m = motion()
    h = m.nutation_period / 100.0
    out = {}
    for name, ts in (("first_100_periods", np.linspace(0.0, 100 * m.nutation_period, n)),
                     ("last_0.1_percent", np.linspace(0.999 * t_end, t_end, n))):
        a = {k: toppath.path_at(m, ts + k * h) for k in (-3, -2, -1, 0, 1, 2, 3)}

        def d(i, a=a):  # 6th-order central difference
            return (-a[-3][i] + 9 * a[-2][i] - 45 * a[-1][i] + 45 * a[1][i] - 9 * a[2][i] + a[3][i]) / (60 * h)

        th, ph, ps = a[0]
        out[name] = _invariants_from_angles(th, ph, ps, d(0), d(1), d(2))
    return out


def _rhs_factory():
    I, Is, mgl = PARAMS.I, PARAMS.Is, PARAMS.mass * G * PARAMS.length
    z = np.array([0.0, 0.0, 1.0])

    def rhs(_t, y):
        n, e, L = y[0:3], y[3:6], y[6:9]
        L3 = L @ n
        w = (L - L3 * n) / I + (L3 / Is) * n
        return np.concatenate([np.cross(w, n), np.cross(w, e), mgl * np.cross(z, n)])

    return rhs


def _y0() -> np.ndarray:
    c, s = math.cos(THETA0), math.sin(THETA0)
    e3 = np.array([s, 0.0, c])
    e1 = np.array([c, 0.0, -s])
    L = PARAMS.Is * SPIN * e3  # released from rest: w = S e3
    return np.concatenate([e3, e1, L])


def run_numeric(periods: float, method: str, rtol: float | None) -> tuple[float, object]:
    from scipy.integrate import solve_ivp

    T = motion().nutation_period * periods  # not timed: the integration is
    rhs = _rhs_factory()
    kw = {} if rtol is None else {"rtol": rtol, "atol": rtol * 1e-3}
    t0 = time.perf_counter()
    sol = solve_ivp(rhs, (0.0, T), _y0(), method=method, **kw)
    return time.perf_counter() - t0, sol


def numeric_errors(sol) -> dict:
    """Invariant drift of an integrator's own points and its angle differences from the
    closed form at those points."""
    I, Is, mgl = PARAMS.I, PARAMS.Is, PARAMS.mass * G * PARAMS.length
    n, e, L = sol.y[0:3].T, sol.y[3:6].T, sol.y[6:9].T
    L3 = np.einsum("ij,ij->i", L, n)
    Lp2 = np.einsum("ij,ij->i", L, L) - L3**2
    E = 0.5 * Lp2 / I + 0.5 * L3**2 / Is + mgl * n[:, 2]
    Ls = float(np.linalg.norm(L[0]))
    th_n = np.arctan2(np.hypot(n[:, 0], n[:, 1]), n[:, 2])
    ph_n = np.unwrap(np.arctan2(n[:, 1], n[:, 0]))
    ph_n -= ph_n[0]
    th_c, ph_c, _ = toppath.path_at(motion(), sol.t)
    axis_c = np.stack([np.sin(th_c) * np.cos(ph_c), np.sin(th_c) * np.sin(ph_c), np.cos(th_c)], -1)
    return {
        "energy": float(np.max(np.abs(E - E[0])) / (0.5 * Is * SPIN**2 + mgl)),
        "p_phi": float(np.max(np.abs(L[:, 2] - L[0, 2])) / Ls),
        "p_psi": float(np.max(np.abs(L3 - L3[0])) / Ls),
        "unit_axis": float(np.max(np.abs(np.linalg.norm(n, axis=1) - 1.0))),
        "max_theta_diff_deg": math.degrees(float(np.max(np.abs(th_c - th_n)))),
        "max_phi_diff_deg": math.degrees(float(np.max(np.abs(ph_c - ph_n)))),
        "max_axis_chord": float(np.max(np.linalg.norm(axis_c - n, axis=1))),
        "points": int(sol.t.size),
        "nfev": int(sol.nfev),
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--times", type=int, default=10_000)
    ap.add_argument("--periods", type=float, default=1e6)
    ap.add_argument("--rk-periods", type=float, default=100.0)
    ap.add_argument("--dop-periods", type=float, default=10.0)
    ap.add_argument("--json", type=Path)
    args = ap.parse_args(argv)

    run_exact(100, 10.0)  # warm-up: scipy.special, caches
    run_numeric(1.0, "RK45", None)
    times: dict[str, list[float]] = {"exact": [], "rk45": [], "dop853": []}
    sols = {}
    t_exact = None
    for _ in range(args.repeat):
        dt, t_exact = run_exact(args.times, args.periods)
        times["exact"].append(dt)
        dt, sols["rk45"] = run_numeric(args.rk_periods, "RK45", None)
        times["rk45"].append(dt)
        dt, sols["dop853"] = run_numeric(args.dop_periods, "DOP853", 1e-12)
        times["dop853"].append(dt)
    med = {k: statistics.median(v) for k, v in times.items()}
    ex = exact_invariants(float(t_exact[-1]))
    rk = numeric_errors(sols["rk45"])
    dp = numeric_errors(sols["dop853"])
    m = motion()
    res = {
        "top": "m 0.5 kg, l 0.04 m, I 1.2e-3, Is 4e-4 kg m^2, S 150 rad/s, theta0 30 deg, g 9.81",
        "nutation_period_s": m.nutation_period,
        "times": args.times, "periods": args.periods, "rk_periods": args.rk_periods,
        "dop_periods": args.dop_periods,
        "repeat": args.repeat,
        "exact_median_s": med["exact"], "rk45_median_s": med["rk45"], "dop853_median_s": med["dop853"],
        "ratio_exact_rk45": med["exact"] / med["rk45"],
        "ratio_exact_dop853": med["exact"] / med["dop853"],
        "rk45_s_per_100_periods": med["rk45"] * 100 / args.rk_periods,
        "dop853_s_per_100_periods": med["dop853"] * 100 / args.dop_periods,
        "exact_invariants_fd": ex, "rk45_errors": rk, "dop853_errors": dp,
    }
    print(f"top (sheet T1), nutation period {m.nutation_period:.6g} s, {args.repeat} runs each")
    print(f"  exact  : {args.times} times over {args.periods:.3g} periods  median {med['exact'] * 1e3:8.2f} ms")
    for k, e in ex.items():
        print(f"           invariants from its angles ({k}): E {e['energy']:.1e} p_phi {e['p_phi']:.1e}"
              f" p_psi {e['p_psi']:.1e}")
    for k, e, per in (("RK45", rk, args.rk_periods), ("DOP853", dp, args.dop_periods)):
        print(f"  {k:7s}: {per:.3g} periods, {e['nfev']} evaluations  median "
              f"{med[k.lower()] * 1e3:8.2f} ms  drift E {e['energy']:.1e} p_phi {e['p_phi']:.1e} "
              f"p_psi {e['p_psi']:.1e}; vs closed form theta {e['max_theta_diff_deg']:.1e} deg, "
              f"phi {e['max_phi_diff_deg']:.1e} deg")
    print(f"  time ratio exact/RK45 {res['ratio_exact_rk45']:.3f}, exact/DOP853 {res['ratio_exact_dop853']:.3f}")
    print(json.dumps(res))
    if args.json:
        args.json.write_text(json.dumps(res, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
