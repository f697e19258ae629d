"""Field balancing under the shop's limits, a drawer and a bad reading (issue 36), against
independent solvers.

Oracles: cvxpy (installed with hsbalance; its conic solver stops when the objective is optimal
to ~1e-8 relative: the objectives agree to 1e-6, rbcli's no worse) for least squares and
min-max under mass and reading limits; hsbalance's ``Min_max(weight_const=...)`` for min-max
under mass limits; brute force over every choice, and scipy's MILP (HiGHS) on a polygon
around each residual's circle, for the drawer; a simulated rotor with one reading spoiled for
the robust fit. Both oracles skip cleanly without hsbalance.
"""

from __future__ import annotations

import itertools
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import rbcli
from rbcli.core.field.drawer import Plane, best_weights
from rbcli.core.field.solve import solve

from conftest import sampled_params

pytestmark = pytest.mark.filterwarnings("ignore:Using the Community license")
ROOT = Path(__file__).resolve().parents[1]
FAN_DRAWER = str(ROOT / "examples" / "jobs" / "fan-drawer.yaml")


def case(seed: int, n: int, p: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    return rng.normal(size=(n, p)) + 1j * rng.normal(size=(n, p)), rng.normal(size=n) + 1j * rng.normal(size=n)


def cvx(A, v, method, U=None, L=None):
    """The optimum by cvxpy: (objective, W)."""
    cp = pytest.importorskip("cvxpy")
    n, p = A.shape
    W = cp.Variable(p, complex=True)
    r = A @ W + v
    cons = [cp.abs(W[j]) <= U[j] for j in range(p) if U is not None and np.isfinite(U[j])]
    cons += [cp.abs(r[k]) <= L[k] for k in range(n) if L is not None and np.isfinite(L[k])]
    prob = cp.Problem(cp.Minimize(cp.norm(r, "inf") if method == "min-max" else cp.norm(r, 2)), cons)
    prob.solve(solver="CLARABEL")  # not Xpress where installed: it changes the floating-point state
    return float(prob.value), W.value


LIMITED = [(seed, method) for seed in range(6) for method in ("least-squares", "min-max")]


@pytest.mark.sampled
@pytest.mark.parametrize("seed, method", sampled_params(LIMITED, range(4), multi=True))
def test_limits_against_cvxpy(seed, method):
    A, v = case(seed, 9, 3)
    ls = solve(A, v)
    # limits that bind: the planes at 60 % of the unconstrained mass, two readings below theirs
    U = 0.6 * np.abs(ls.corrections)
    U[1] = np.inf
    L = np.full(9, np.inf)
    L[[0, 4]] = 0.9 * np.maximum(np.abs(ls.residuals[[0, 4]]), 0.2)
    s = solve(A, v, method, max_mass=U, limits=L)
    if not s.feasible:  # the least-violating correction (another test): no costs are said
        assert s.violation > 1.0 and s.without == ()
        return
    obj, W = cvx(A, v, method, U, L)
    # cvxpy's objective is optimal to ~1e-8 relative: they agree to 1e-6; its answer may
    # overstep the limits by its feasibility tolerance (~1e-8), lowering its objective by as much
    # times the multipliers: rbcli's (exact, the limits met to round-off) is no worse by 1e-7
    assert s.objective == pytest.approx(obj, rel=1e-6) and s.objective <= obj * (1 + 1e-7)
    assert np.all(np.abs(s.corrections) <= U * (1 + 1e-12)) and np.all(np.abs(s.residuals) <= L * (1 + 1e-12))
    assert s.active and len(s.without) == len(s.active)
    for (kind, i), without in zip(s.active, s.without):  # the cost: the objective without that limit
        U2 = U.copy() if kind != "mass" else np.where(np.arange(3) == i, np.inf, U)
        L2 = L.copy() if kind != "reading" else np.where(np.arange(9) == i, np.inf, L)
        assert without == pytest.approx(cvx(A, v, method, U2, L2)[0], rel=1e-6)
        assert without <= s.objective * (1 + 1e-9)  # a limit taken away never makes it worse


def test_infeasible_limits_give_the_least_violating_correction():
    A, v = case(3, 8, 2)
    L = np.full(8, 1e-3)  # no correction of two planes cancels eight readings
    s = solve(A, v, "least-squares", limits=L)
    assert not s.feasible and s.violation > 1.0 and s.without == ()
    # the least violation is min-max of |r_k| / L_k (all limits equal here): cvxpy's
    t, _ = cvx(A, v, "min-max")
    assert s.violation == pytest.approx(t / 1e-3, rel=1e-6)


def test_a_mass_limit_is_not_the_unconstrained_correction_clipped():
    """Clipping the unconstrained correction to the limit leaves more than the optimum under it."""
    A, v = case(11, 6, 2)
    free = solve(A, v)
    U = np.array([0.5 * abs(free.corrections[0]), np.inf])
    s = solve(A, v, max_mass=U)
    clipped = free.corrections.copy()
    clipped[0] *= U[0] / abs(clipped[0])
    clipped_obj = float(np.linalg.norm(v + A @ clipped))
    assert s.objective < clipped_obj * (1 - 1e-3), (s.objective, clipped_obj)
    assert ("mass", 0) in s.active


@pytest.mark.parametrize("seed", range(3))
def test_min_max_under_mass_limits_agrees_with_hsbalance(hs, seed):
    A, v = case(seed + 20, 10, 3)
    U = 0.5 * np.abs(solve(A, v, "min-max").corrections)
    alpha = hs.Alpha()
    alpha.add(direct_matrix=A)
    W = hs.Min_max(v[:, None], alpha, weight_const={j: U[j] for j in range(3)}).solve()[:, 0]
    s = solve(A, v, "min-max", max_mass=U)
    t_hs = float(np.max(np.abs(v + A @ W)))
    # hsbalance solves with cvxpy (optimal and feasible to ~1e-8): the same optimum to 1e-6,
    # rbcli's no worse than by what cvxpy may overstep a mass limit (see above)
    assert s.objective == pytest.approx(t_hs, rel=1e-6) and s.objective <= t_hs * (1 + 1e-7)


# --------------------------------------------------------------------- the drawer


def brute(A, v, w, method, planes, drawer, L):
    """Every choice of every plane (small drawers only)."""
    masses, counts = drawer
    per = []
    for pl in planes:
        units = [(h, s) for h in range(len(pl.angles)) for s in range(len(masses))]
        ch = []
        for k in range(pl.most + 1):
            for c in itertools.combinations_with_replacement(range(len(units)), k):
                hs_ = [units[u] for u in c]
                if any(sum(x[0] == h for x in hs_) > pl.per_hole for h, _ in hs_) or \
                        any(sum(x[1] == s for x in hs_) > counts[s] for _, s in hs_) or \
                        sum(masses[s] for _, s in hs_) > pl.max_mass:
                    continue
                ch.append((hs_, sum(masses[s] * pl.factor * np.exp(1j * pl.angles[h]) for h, s in hs_)))
        per.append(ch)
    best = (2, math.inf)
    for combo in itertools.product(*per):
        used = np.zeros(len(masses), int)
        for hs_, _ in combo:
            for _, s in hs_:
                used[s] += 1
        if np.any(used > counts):
            continue
        r = v + A @ np.array([z for _, z in combo])
        a = w * np.abs(r)
        g = math.sqrt(np.sum(a * a)) if method == "least-squares" else float(np.max(a))
        viol = float(np.max(np.abs(r) / L))
        best = min(best, (0, g) if viol <= 1 else (1, viol))
    return best


DRAWERS = list(range(24))


@pytest.mark.sampled
@pytest.mark.parametrize("seed", sampled_params(DRAWERS, range(8)))
def test_the_drawer_search_is_exact_against_brute_force(seed):
    rng = np.random.default_rng(seed)
    p = 1 + seed % 2
    n = int(rng.integers(p, 5))
    A, v = case(seed + 100, n, p)
    v *= 3
    S = int(rng.integers(1, 4))
    drawer = (np.round(rng.uniform(0.5, 3, S), 1), rng.integers(1, 3, S))
    planes = [Plane(tuple(np.sort(rng.uniform(0, 2 * np.pi, int(rng.integers(3, 6))))), float(rng.uniform(0.8, 1.2)),
                    int(rng.integers(1, 4)), int(rng.integers(1, 3)), float(rng.choice([np.inf, 4.0]))) for _ in range(p)]
    method = ("least-squares", "min-max")[seed % 2]
    L = np.where(rng.uniform(size=n) < 0.3, rng.uniform(0.5, 3, n), np.inf)
    start = solve(A, v, "min-max").corrections if method == "min-max" and n > p else None
    c = best_weights(A, v, np.ones(n), method, planes, [drawer], L, start=start)
    feasible, best = brute(A, v, np.ones(n), method, planes, drawer, L)
    # the same optimum to round-off of the sums (both evaluate the same products)
    if feasible == 0:
        assert c.violation <= 1.0 and c.objective == pytest.approx(best, rel=1e-12, abs=1e-15)
    else:
        assert c.violation == pytest.approx(best, rel=1e-12)


@pytest.mark.sampled
@pytest.mark.parametrize("seed", sampled_params(range(6), (0, 2)))
def test_the_drawer_search_against_scipy_milp(seed):
    """Min-max over a drawer as a MILP (HiGHS): integer counts of each size in each hole, and
    |r_k| replaced by its projections on K directions (a polygon inside the circle). The MILP's
    optimum bounds rbcli's from below, within cos(pi/K); rbcli's is no worse than the MILP's
    choice evaluated exactly."""
    from scipy.optimize import Bounds, LinearConstraint, milp

    A, v = case(seed + 200, 6, 2)
    v *= 4
    masses, counts = np.array([0.5, 1.0, 2.0, 5.0]), np.array([3, 3, 2, 1])
    H, K = 8, 64
    planes = [Plane(tuple(2 * np.pi * np.arange(H) / H), 1.0, 3) for _ in range(2)]
    c = best_weights(A, v, np.ones(6), "min-max", planes, [(masses, counts)], start=solve(A, v, "min-max").corrections)
    nv = 2 * H * len(masses)
    unit = np.array([masses[s] * np.exp(2j * np.pi * h / H) for j in range(2) for h in range(H) for s in range(4)])
    plane = np.repeat([0, 1], H * 4)
    R = A[:, plane] * unit  # r = v + R n
    rows, lo, hi = [], [], []
    for j in range(2):
        rows.append(np.r_[plane == j, 0].astype(float)), lo.append(0), hi.append(3)  # at most 3 weights a plane
        for h in range(H):  # one weight a hole
            a = np.zeros(nv + 1)
            a[j * H * 4 + h * 4: j * H * 4 + h * 4 + 4] = 1
            rows.append(a), lo.append(0), hi.append(1)
    for s in range(4):
        a = np.zeros(nv + 1)
        a[s:nv:4] = 1
        rows.append(a), lo.append(0), hi.append(counts[s])
    for k in range(6):
        for th in 2 * np.pi * np.arange(K) / K:
            e = np.exp(-1j * th)
            rows.append(np.r_[(e * R[k]).real, -1.0]), lo.append(-np.inf), hi.append(-(e * v[k]).real)
    res = milp(np.r_[np.zeros(nv), 1.0], integrality=np.r_[np.ones(nv), 0], bounds=Bounds(0, np.r_[np.ones(nv), np.inf]),
               constraints=LinearConstraint(np.array(rows), lo, hi), options={"mip_rel_gap": 1e-9})
    assert res.status == 0
    t_milp = float(res.x[-1])
    exact_of_milp = float(np.max(np.abs(v + R @ np.round(res.x[:nv]))))
    # HiGHS' feasibility tolerance (1e-7 relative) is the slack on the lower bound
    assert t_milp * (1 - 1e-7) <= c.objective <= exact_of_milp * (1 + 1e-12)
    assert c.objective <= t_milp / math.cos(math.pi / K) * (1 + 1e-7)


def test_a_realistic_drawer_is_searched_within_a_second(cli):
    """The README's example: 12 holes and 8 blades, four sizes, two weights a plane (the time
    is bench's to measure; this checks the answer and that it is a drawer's)."""
    res = rbcli.field_balance(job=FAN_DRAWER)
    f = res.fitted
    assert f.drawer is not None and f.drawer.violation <= 1.0
    masses = [round(m.mass * 1e3, 9) for p in f.planes for m in p.masses]
    assert set(masses) <= {2.0, 5.0, 10.0, 20.0} and all(len(p.masses) <= 2 for p in f.planes)
    assert sum(m.mass for m in f.planes[0].masses) <= 0.025 + 1e-12  # plane A: 25 g at most
    # the holes as the job file numbers them: A's hole 1 at 15°, counted against the angles
    assert f.drawer.planes[0].holes_deg[:3] == pytest.approx((15.0, 345.0, 315.0))
    for m in f.planes[0].masses:
        assert m.angle_deg == pytest.approx((15.0 - 30.0 * (m.position - 1)) % 360.0)
    # its predicted readings are those of the masses chosen, the limits met
    lim = {(r.sensor, r.speed): r.limit for r in res.limits.readings}
    for r in f.residuals:
        assert r.amplitude <= lim.get((r.sensor, r.speed), math.inf) * (1 + 1e-12)


# --------------------------------------------------------------------- a bad reading


def test_a_robust_fit_discounts_the_bad_reading_and_names_it():
    rng = np.random.default_rng(5)
    A = rng.normal(size=(10, 2)) + 1j * rng.normal(size=(10, 2))
    heavy = np.array([3 + 1j, -2 + 2j])
    v = A @ heavy + 0.01 * (rng.normal(size=10) + 1j * rng.normal(size=10))
    v[6] += 4.0  # one reading spoiled
    plain, rob = solve(A, v), solve(A, v, robust=True)
    assert np.argmin(rob.robust) == 6 and rob.robust[6] < 0.2 and np.sum(rob.robust < 1) <= 3
    # the robust correction is near the true one; plain least squares is pulled off by the bad reading
    assert np.max(np.abs(rob.corrections + heavy)) < 0.05 < np.max(np.abs(plain.corrections + heavy))


def test_the_robust_fit_is_named_in_the_output(cli):
    args = ["field-balance", "--initial", "1@0,1@180,0@0,2@90,9@45", "--trial", "1 g@0", "--run",
            "4@0,4@0,5@0,1@0,9@45", "--trial", "1 g@0", "--run", "1@180,3@180,3@180,2@0,9@40", "--robust", "huber"]
    d = cli(*args, "--json").json()
    assert d["robust"]["method"] == "huber" and len(d["robust"]["weights"]) == 5
    out = cli(*args)
    assert out.code == 0 and "robust fit (Huber)" in out.out


# --------------------------------------------------------------------- the same bytes everywhere


def test_the_api_is_the_command_line(cli):
    doc = cli("field-balance", FAN_DRAWER, "--json").json()
    assert doc == json.loads(json.dumps(rbcli.field_balance(job=FAN_DRAWER).to_json()))


@pytest.mark.slow
def test_the_same_bytes_for_any_blas_thread_count_and_from_the_api(cli_proc):
    """Min-max, limits and a drawer: the CLI's --json with OPENBLAS_NUM_THREADS 1, 2 and 8 and
    the API's to_json() in a process with 8 threads are the same bytes."""
    args = ["field-balance", FAN_DRAWER, "--method", "min-max", "--json"]
    job = Path(FAN_DRAWER).read_text().replace("method: least-squares\n", "")
    tmp = ROOT / "build" / "fan-drawer-minmax.yaml"
    tmp.parent.mkdir(exist_ok=True)
    tmp.write_text(job)
    args[1] = str(tmp)
    outs = set()
    for threads in ("1", "2", "8"):
        env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_NUM_THREADS"}
        env["OPENBLAS_NUM_THREADS"] = threads
        # a fresh interpreter for each: the thread count is read when numpy is imported
        r = subprocess.run([sys.executable, "-m", "rbcli", *args], capture_output=True, text=True, env=env,
                           cwd=ROOT, timeout=120)
        assert r.returncode == 0, r.stderr
        outs.add(r.stdout)
    code = ("import json, rbcli; from rbcli.render.jsonout import dumps; "
            f"print(dumps(rbcli.field_balance(job={str(tmp)!r}, method='min-max').to_json()), end='')")
    env["OPENBLAS_NUM_THREADS"] = "8"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=ROOT, timeout=120)
    assert r.returncode == 0, r.stderr
    assert len(outs) == 1, "the CLI's bytes differ with the thread count"
    assert r.stdout.strip() == outs.pop().strip()  # the API's to_json() is the CLI's --json


def test_the_job_sheet_shows_the_limits_and_the_drawer(cli, tmp_path):
    html = tmp_path / "sheet.html"
    assert cli("field-balance", FAN_DRAWER, "--report", str(html)).code == 0
    text = html.read_text()
    for what in ("trial masses", "limits (met)", "weights from the drawer", "numbered against the angles",
                 "objective without it", "12 holes at 240 mm", "limit [mm/s rms]"):
        assert what in text, what
