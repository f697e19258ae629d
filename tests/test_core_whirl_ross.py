"""rbcli.core.whirl against ROSS (Rotordynamic Open Source Software, github.com/petrobras/ross,
``pip install ross-rotordynamics``), an optional peer: skipped when it is not installed.

ROSS models a flexible shaft by Timoshenko finite elements (rigid disks, linear bearings).
A rigid rotor is its limit as the shaft's modulus E grows: here a fat, light uniform shaft
(8 elements, 0.8 m, 150 mm, 1250 kg/m^3) with two disks, one overhung, on two anisotropic
damped bearings. Its flexibility moves the rigid-body eigenvalues by ~k_bearing/k_shaft
(~1e-5 at E = 2e11 Pa), proportionally to 1/E; three runs at E = 2e11, 2e12, 2e13 Pa and
Richardson extrapolation in 1/E (two levels: f = f_0 + a/E + b/E^2) remove that, leaving
the FE eigen-solve's round-off, which grows with the stiffness contrast: measured 1e-10 to
5e-9 of |lambda| (at E = 2e15 it would be ~1e-7, which is why the extrapolation stops at
2e13). The tolerance, 2e-8, is four times the largest residual measured.

The rigid rotor here is built from the same parts by hand: the shaft's mass, It = m(3r^2 +
L^2)/12 and Ip = m r^2/2 (ROSS's consistent mass matrix and rotary inertia reproduce a
rigid motion's kinetic energy exactly) plus the disks' m, Id (about their centres) and Ip.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

ross = pytest.importorskip("ross")

from rbcli.core import whirl as W  # noqa: E402
from rbcli.core.whirl.response import bearing_motion  # noqa: E402

RHO, OD, LE, N_EL = 1250.0, 0.15, 0.1, 8
DISKS = [(2, 20.0, 0.15, 0.28), (7, 12.0, 0.09, 0.16)]  # node, m, Id, Ip
BEARINGS = [(1, 2e6, 3e6, 300.0, 250.0), (6, 1.5e6, 1.2e6, 200.0, 200.0)]  # node, kxx, kyy, cxx, cyy
MODULI = (2e11, 2e12, 2e13)
TOL = 2e-8  # see the module docstring


def _rotor(E: float, bearings=None):
    """The ROSS rotor at modulus E; ``bearings``: ROSS BearingElement keyword dicts (default
    the anisotropic damped pair of BEARINGS)."""
    if bearings is None:
        bearings = [dict(n=n, kxx=kx, kyy=ky, cxx=cx, cyy=cy) for n, kx, ky, cx, cy in BEARINGS]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        mat = ross.Material(name=f"stiff{E:g}", rho=RHO, E=E, G_s=E / 2.6)
        shaft = [ross.ShaftElement(L=LE, idl=0.0, odl=OD, material=mat, n=i) for i in range(N_EL)]
        disks = [ross.DiskElement(n=n, m=m, Id=Id, Ip=Ip) for n, m, Id, Ip in DISKS]
        return ross.Rotor(shaft, disks, [ross.BearingElement(**b) for b in bearings])


def _rigid(bearings=None) -> W.Rotor:
    L = N_EL * LE
    ms = RHO * math.pi * (OD / 2) ** 2 * L
    parts = [(ms, L / 2)] + [(m, n * LE) for n, m, _, _ in DISKS]
    M = sum(m for m, _ in parts)
    zG = sum(m * z for m, z in parts) / M
    It = ms * (3 * (OD / 2) ** 2 + L * L) / 12 + ms * (L / 2 - zG) ** 2 + sum(
        Id + m * (n * LE - zG) ** 2 for n, m, Id, _ in DISKS)
    Ip = ms * (OD / 2) ** 2 / 2 + sum(Ip for *_, Ip in DISKS)
    if bearings is None:
        bearings = tuple(W.Bearing(n * LE, kx, ky, 0.0, 0.0, cx, cy) for n, kx, ky, cx, cy in BEARINGS)
    return W.Rotor(M, It, Ip, zG, bearings)


def _extrapolate(f1, f2, f3):
    """f(E) = f0 + a/E + b/E^2 sampled at E, 10 E, 100 E -> f0."""
    r1, r2 = (10 * f2 - f1) / 9, (10 * f3 - f2) / 9
    return (100 * r2 - r1) / 99


def _ross_lams(speed, bearings=None):
    """ROSS's four rigid-body roots (Im > 0) at ``speed``, extrapolated to the rigid limit."""
    def at(E):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            modal = _rotor(E, bearings).run_modal(speed=speed, num_modes=16, sparse=False)
        lam = np.asarray(modal.evalues)
        lam = lam[(lam.imag > 0) & (np.abs(lam) < 2000.0)]  # the four rigid-body modes
        return np.array(sorted(lam, key=lambda x: x.imag))

    return _extrapolate(*(at(E) for E in MODULI))


def _mine(rotor, speed):
    lam = [m.eigenvalue if m.eigenvalue.imag > 0 else m.eigenvalue.conjugate() for m in W.modes_at(rotor, speed)]
    return np.array(sorted(lam, key=lambda x: x.imag))


@pytest.mark.parametrize("speed", [0.0, 250.0, 600.0])
def test_damped_eigenvalues_agree_with_ross_at_the_rigid_limit(speed):
    got, mine = _ross_lams(speed), _mine(_rigid(), speed)
    assert len(got) == len(mine) == 4
    np.testing.assert_allclose(np.abs(got - mine) / np.abs(mine), 0.0, atol=TOL)


@pytest.mark.parametrize("q", [4e5, -4e5])
@pytest.mark.parametrize("speed", [0.0, 400.0])
def test_full_2x2_bearings_agree_with_ross_both_signs_of_the_cross_coupling(q, speed):
    """Every coefficient of both bearings, kxy != -kyx and cross-coupled damping, q of both
    signs (the follower force that feeds forward whirl, and the one that feeds backward)."""
    spec = [(1, 2e6, 3e6, q, -0.7 * q, 300.0, 250.0, 40.0, 60.0), (6, 1.5e6, 1.2e6, 0.5 * q, -q, 200.0, 200.0, -20.0, 10.0)]
    ross_b = [dict(n=n, kxx=kx, kyy=ky, kxy=kxy, kyx=kyx, cxx=cx, cyy=cy, cxy=cxy, cyx=cyx)
              for n, kx, ky, kxy, kyx, cx, cy, cxy, cyx in spec]
    mine_b = tuple(W.Bearing(n * LE, kx, ky, kxy, kyx, cx, cy, cxy, cyx) for n, kx, ky, kxy, kyx, cx, cy, cxy, cyx in spec)
    got, mine = _ross_lams(speed, ross_b), _mine(_rigid(mine_b), speed)
    np.testing.assert_allclose(np.abs(got - mine) / np.abs(mine), 0.0, atol=TOL)


def _journal_tables(load=None):
    """The published plain journal bearing of tests/test_core_whirl_bearings.py (Someya's
    Table 1) under ``load`` (default: the example's): (speeds, (S, 8))."""
    import test_core_whirl_bearings as T

    return T.journal_table() if load is None else T.journal_table(load)


@pytest.mark.parametrize("speed", [40.0, 333.3, 700.0])
def test_bearings_tabled_against_speed_agree_with_ross(speed):
    """Two oil-film bearings (8 coefficients against speed, interpolated linearly: ROSS's
    interpolation="linear") at speeds between the table's rows."""
    sp, v = _journal_tables()
    ross_b = [dict(n=n, speed=sp, interpolation="linear",
                   **{k: v[:, j] for j, k in enumerate(("kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy"))})
              for n in (1, 6)]
    mine_b = tuple(W.BearingTable(n * LE, sp, v) for n in (1, 6))
    got, mine = _ross_lams(speed, ross_b), _mine(_rigid(mine_b), speed)
    # an overdamped pair is not (Im > 0) a whirl in either: compare the whirling roots
    got = got[np.abs(got.imag) > 1e-6 * np.abs(got)]
    mine = mine[np.abs(mine.imag) > 0.0]
    assert len(got) == len(mine) > 0
    np.testing.assert_allclose(np.abs(got - mine) / np.abs(mine), 0.0, atol=TOL)


def test_unbalance_response_agrees_with_ross_at_the_rigid_limit():
    """1e-3 kg m at 0 deg on the overhung disk (node 7): the bearing displacements x, y."""
    freqs = np.array([100.0, 180.0, 260.0, 400.0])

    def ross_resp(E):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            rot = _rotor(E)
            try:  # ROSS 3.1 names the speeds speed_range (earlier: frequency)
                res = rot.run_unbalance_response(node=7, unbalance_magnitude=1e-3, unbalance_phase=0.0,
                                                 speed_range=freqs)
            except TypeError:
                res = rot.run_unbalance_response(node=7, unbalance_magnitude=1e-3, unbalance_phase=0.0,
                                                 frequency=freqs)
        nd = rot.number_dof
        return np.array([[res.forced_resp[n * nd + j] for j in (0, 1)] for n in (1, 6)])

    runs = [ross_resp(E) for E in MODULI]
    rigid = _rigid()
    D, _ = bearing_motion(rigid, W.Forcing.from_planes(rigid.z_com, [(7 * LE, 1e-3 + 0j)]), freqs)
    mine = D.transpose(0, 2, 1)  # (bearing, direction, speed)
    amp = _extrapolate(*(np.abs(r) for r in runs))
    np.testing.assert_allclose(amp, np.abs(mine), rtol=TOL)
    # the same phase convention (x = Re(X e^{i W t}), the unbalance at 0 on +x at t = 0): the
    # stiffest run's phases agree to its flexibility error (~1e-4 rad)
    dphi = np.angle(runs[-1] * np.conj(mine))
    assert float(np.max(np.abs(dphi))) < 1e-3


def test_the_threshold_of_instability_of_oil_film_bearings_agrees_with_ross():
    """The same bearings loaded to twice this rotor's weight (so that the film whips
    within the table): the onset speed, a root of the largest Re lambda, by ROSS (its
    roots at the rigid limit, Brent to 1e-9) and by rbcli (followed by shape, Brent).
    The tolerance: ROSS's roots carry ~2e-8 of |lambda| (TOL), and the threshold moves by
    that over d(Re lambda)/d(Omega) ~ 0.1: ~1e-7 of the speed; 1e-6 leaves a decade."""
    from scipy.optimize import brentq

    from rbcli.core.whirl.stability import stability

    M = sum(m for _, m, _, _ in DISKS) + RHO * math.pi * (OD / 2) ** 2 * N_EL * LE
    sp, v = _journal_tables(2 * M * 9.80665)
    ross_b = [dict(n=n, speed=sp, interpolation="linear",
                   **{k: v[:, j] for j, k in enumerate(("kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy"))})
              for n in (1, 6)]
    rigid = _rigid(tuple(W.BearingTable(n * LE, sp, v) for n in (1, 6)))
    cb = W.campbell(rigid, np.linspace(sp[0], sp[-1], 101))
    onsets = [t for t in stability(cb, W.track(cb)).thresholds if t.change == "onset"]
    assert len(onsets) == 1
    got = onsets[0].speed
    want = brentq(lambda x: float(np.max(_ross_lams(x, ross_b).real)), 0.97 * got, sp[-1], xtol=1e-9 * got)
    assert got == pytest.approx(want, rel=1e-6)
