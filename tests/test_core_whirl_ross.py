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


def _rotor(E: float):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        mat = ross.Material(name=f"stiff{E:g}", rho=RHO, E=E, G_s=E / 2.6)
        shaft = [ross.ShaftElement(L=LE, idl=0.0, odl=OD, material=mat, n=i) for i in range(N_EL)]
        disks = [ross.DiskElement(n=n, m=m, Id=Id, Ip=Ip) for n, m, Id, Ip in DISKS]
        brgs = [ross.BearingElement(n=n, kxx=kx, kyy=ky, cxx=cx, cyy=cy) for n, kx, ky, cx, cy in BEARINGS]
        return ross.Rotor(shaft, disks, brgs)


def _rigid() -> W.Rotor:
    L = N_EL * LE
    ms = RHO * math.pi * (OD / 2) ** 2 * L
    parts = [(ms, L / 2)] + [(m, n * LE) for n, m, _, _ in DISKS]
    M = sum(m for m, _ in parts)
    zG = sum(m * z for m, z in parts) / M
    It = ms * (3 * (OD / 2) ** 2 + L * L) / 12 + ms * (L / 2 - zG) ** 2 + sum(
        Id + m * (n * LE - zG) ** 2 for n, m, Id, _ in DISKS)
    Ip = ms * (OD / 2) ** 2 / 2 + sum(Ip for *_, Ip in DISKS)
    return W.Rotor(M, It, Ip, zG, tuple(W.Bearing(n * LE, kx, ky, 0.0, 0.0, cx, cy)
                                       for n, kx, ky, cx, cy in BEARINGS))


def _extrapolate(f1, f2, f3):
    """f(E) = f0 + a/E + b/E^2 sampled at E, 10 E, 100 E -> f0."""
    r1, r2 = (10 * f2 - f1) / 9, (10 * f3 - f2) / 9
    return (100 * r2 - r1) / 99


@pytest.mark.parametrize("speed", [0.0, 250.0, 600.0])
def test_damped_eigenvalues_agree_with_ross_at_the_rigid_limit(speed):
    def ross_lams(E):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            modal = _rotor(E).run_modal(speed=speed, num_modes=16, sparse=False)
        lam = np.asarray(modal.evalues)
        lam = lam[(lam.imag > 0) & (np.abs(lam) < 2000.0)]  # the four rigid-body modes
        return np.array(sorted(lam, key=lambda x: x.imag))

    got = _extrapolate(*(ross_lams(E) for E in MODULI))
    mine = [m.eigenvalue if m.eigenvalue.imag > 0 else m.eigenvalue.conjugate()
            for m in W.modes_at(_rigid(), speed)]
    mine = np.array(sorted(mine, key=lambda x: x.imag))
    assert len(got) == len(mine) == 4
    np.testing.assert_allclose(np.abs(got - mine) / np.abs(mine), 0.0, atol=TOL)


def test_unbalance_response_agrees_with_ross_at_the_rigid_limit():
    """1e-3 kg m at 0 deg on the overhung disk (node 7): the bearing displacements x, y."""
    freqs = np.array([100.0, 180.0, 260.0, 400.0])

    def ross_resp(E):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            rot = _rotor(E)
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
