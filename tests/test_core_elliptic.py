"""rbcli.core.elliptic against mpmath at high precision, across the whole modulus range.

The references are computed by mpmath at 60 significant digits (80 or more where 1 − m is
below 1e-40, so that ``1 - mc`` is represented exactly) from the SAME double inputs, so a
difference is the error of our double-precision evaluation, not of the inputs. Errors are
counted in units of eps = 2.22e-16 relative to the reference, or, where the function is
ill-conditioned, relative to its condition scale (see each test).
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from conftest import sample, sampled_params

from rbcli.core import elliptic as E

EPS = float(np.finfo(float).eps)
#: parameters 1 - m from 0.5 down to 1e-300: the separatrix region (1 - m < 1e-12, where
#: scipy.special.ellipj, which rounds 1 - m from m, has lost every digit) is most of the list
MCS = [1.0, 0.5, 1e-1, 1e-3, 1e-4, 1.0001e-4, 9.999e-5, 1e-6, 1e-10, 1e-12, 1e-13, 1e-15,
       1e-16, 3e-17, 1e-20, 1e-40, 1e-100, 1e-300]


def _dps(mc: float) -> int:
    """Working digits so that 1 - mc is exact in mpmath (and 40 more to spare)."""
    return max(60, int(-math.log10(mc)) + 40) if mc > 0 else 60


def _rel(val: float, ref) -> float:
    """|val - ref| / |ref| in units of eps."""
    return float(abs(mp.mpf(val) - ref) / abs(ref)) / EPS


def _log_uniform(rng: np.random.Generator, n: int, lo: float, hi: float) -> np.ndarray:
    return 10.0 ** rng.uniform(lo, hi, n)


# ----------------------------------------------------------------------------- Carlson forms


@pytest.mark.sampled
def test_carlson_forms_match_mpmath_over_16_decades():
    """R_F, R_J, R_D, R_C (and its principal value) at 400 random argument sets spanning
    1e-8 .. 1e8 (each argument independently, so ratios up to 1e16 occur).

    Tolerance 8 eps: duplication takes at most ~30 steps, each rounding its sums, but the
    errors are damped by the factor 1/4 per step (the later steps carry less weight), and
    Carlson (1995) bounds the truncation of the series at ~1e-18 for our stopping spread
    1e-3; the observed maximum is ~3 eps (scipy's R_J reaches 16 000 eps on this set when
    p << x, y, z: our R_J uses the cancellation-free R_C(alpha, beta) terms).
    """
    rng = np.random.default_rng(20261125)
    with mp.workdps(40):
        for _ in range(sample(80, 400)):  # the first 80 of the 400 by default
            x, y, z, p = _log_uniform(rng, 4, -8, 8)
            assert _rel(E.elliprf(x, y, z), mp.elliprf(x, y, z)) < 8
            assert _rel(E.elliprj(x, y, z, p), mp.elliprj(x, y, z, p)) < 8
            assert _rel(E.elliprc(x, y), mp.elliprc(x, y)) < 8
            assert _rel(E.elliprc(x, -y), mp.re(mp.elliprc(x, -y))) < 8


def test_carlson_forms_with_a_zero_argument_and_vectorised():
    """x = 0 (the complete integrals) and array broadcasting; tolerance as above."""
    mcs = np.array([m for m in MCS if m > 0])
    rf = E.elliprf(0.0, mcs, 1.0)
    rj = E.elliprj(0.0, mcs, 1.0, 4.0)
    assert rf.shape == rj.shape == mcs.shape
    for i, mc in enumerate(mcs):
        with mp.workdps(_dps(mc)):
            assert _rel(rf[i], mp.elliprf(0, mc, 1)) < 8
            assert _rel(rj[i], mp.elliprj(0, mc, 1, 4)) < 8
    assert E.elliprf(0.0, 0.0, 1.0) == math.inf  # two zeros: K(1) diverges
    assert math.isnan(E.elliprj(1.0, 2.0, 3.0, -1.0))  # the principal value is not provided


# ----------------------------------------------------------------------------- Legendre forms


@pytest.mark.parametrize("mc", MCS)
def test_complete_K_to_an_ulp_or_two_down_to_1_minus_m_of_1e_300(mc):
    """K(m) from the complement: 4 eps. K = R_F(0, mc, 1) is perfectly conditioned in mc
    (relative change of K <= relative change of mc / (2 K)) and R_F is good to ~3 eps."""
    m = 1.0 - mc
    with mp.workdps(_dps(mc)):
        ref = mp.ellipk(1 - mp.mpf(mc))
        assert _rel(E.ellipk(m, mc), ref) < 4


def test_K_at_the_separatrix_is_infinite_and_parameters_are_checked():
    assert E.ellipk(1.0, 0.0) == math.inf
    with pytest.raises(ValueError):
        E.ellipk(1.5)
    with pytest.raises(ValueError):
        E.ellipj(0.3, -0.1)


_PI_N = [-50.0, -9.99, -3.0, -1.0, -0.5, -5.7e-5, 0.0, 0.3, 0.9]
_PI_MC = [0.7, 1e-3, 1e-10, 1e-15]


# by default half the (n, mc) grid, every n and every mc among it; all under -m slow
@pytest.mark.parametrize("n, mc", sampled_params([(n, mc) for mc in _PI_MC for n in _PI_N],
                                                 lambda p: (_PI_N.index(p[0]) + _PI_MC.index(p[1])) % 2 == 0,
                                                 ids=lambda p: f"{p[1]}-{p[0]}", multi=True))
def test_complete_and_incomplete_Pi(n, mc):
    """Pi(n|m) and Pi(n; phi|m) for |phi| <= pi/2 from (sin phi, cos phi).

    Tolerance 16 eps: Pi is the sum of two Carlson terms (each ~3 eps) that have opposite
    signs for n < 0; for -1 <= n < 0 they do not cancel by more than a factor ~2 (|n/3 s^3
    R_J| <= |s R_F| there), and for n < -1 the DLMF 19.7.9 form adds two positive terms.
    Incomplete values are compared on the condition scale |Pi| + |phi dPi/dphi| (phi is
    rounded when sin and cos are formed from it).
    """
    m = 1.0 - mc
    with mp.workdps(_dps(mc)):
        mm = 1 - mp.mpf(mc)
        assert _rel(E.ellippi(n, m, mc), mp.ellippi(n, mm)) < 16
        phis = np.linspace(-0.5 * math.pi, 0.5 * math.pi, 14)  # 0 excluded
        s, c = np.sin(phis), np.abs(np.cos(phis))
        got = E.ellippi_sc(n, s, c, m, mc)
        for ph, g in zip(phis, got):
            ref = mp.ellippi(n, mp.mpf(ph), mm)
            sp = mp.sin(ph)
            deriv = 1 / ((1 - n * sp**2) * mp.sqrt(1 - mm * sp**2))
            cond = abs(ref) + abs(mp.mpf(ph) * deriv)
            assert float(abs(mp.mpf(g) - ref) / cond) / EPS < 16


# ----------------------------------------------------------------------------- Jacobi functions


@pytest.mark.parametrize("mc", [1.0, 0.5, 1e-3, 1.0001e-4, 9.999e-5, 1e-6, 1e-10, 1e-12, 1e-13,
                                1e-15, 1e-16, 1e-20, 1e-40])
def test_jacobi_sn_cn_dn_am_over_a_whole_period(mc):
    """sn, cn, dn and am at 48 points of (-4K, 4K], both branches of the algorithm
    (mc above and below 1e-4) and deep into the separatrix region.

    Tolerance: 4 eps of the condition scale |f(u)| + |u f'(u)| (u is a double: its own
    rounding eps |u| moves f by eps |u f'(u)|, so no evaluation can do better; this is the
    "cn(2K) = -2" failure of scipy at 1 - m = 1e-10 made quantitative). am: 4 eps of
    |am| + |u| dn(u). Observed maximum: 1.4.
    """
    m = 1.0 - mc
    K = E.ellipk(m, mc)
    us = np.linspace(-4.0 * K, 4.0 * K, 48)  # even: u = 0 (all exact) not included
    sn, cn, dn, am = E.ellipj(us, m, mc)
    with mp.workdps(_dps(mc)):
        mm = 1 - mp.mpf(mc)
        Kmp = mp.ellipk(mm)
        for i, u in enumerate(us):
            U = mp.mpf(u)
            s = mp.ellipfun("sn", U, m=mm)
            c = mp.ellipfun("cn", U, m=mm)
            d = mp.ellipfun("dn", U, m=mm)
            for val, ref, der in ((sn[i], s, c * d), (cn[i], c, s * d), (dn[i], d, mm * s * c)):
                scale = abs(ref) + abs(U * der)
                assert float(abs(mp.mpf(val) - ref) / scale) / EPS < 4, (u, val, ref)
            # am(u) = atan2(sn, cn) + k pi on the sheet nearest pi u / (2K): am(u) - pi u/(2K)
            # is 2K-periodic, 0 at multiples of K and below pi/2 in size
            a_ref = mp.atan2(s, c)
            a_ref += mp.nint((mp.pi * U / (2 * Kmp) - a_ref) / mp.pi) * mp.pi
            assert float(abs(mp.mpf(am[i]) - a_ref) / (abs(a_ref) + abs(U) * d)) / EPS < 4


def test_jacobi_at_m_1_and_m_0_are_the_hyperbolic_and_circular_functions():
    u = np.linspace(-30.0, 30.0, 61)
    sn, cn, dn, am = E.ellipj(u, 1.0, 0.0)
    np.testing.assert_array_equal(sn, np.tanh(u))
    np.testing.assert_array_equal(cn, 1.0 / np.cosh(u))
    np.testing.assert_array_equal(dn, cn)
    np.testing.assert_allclose(am, np.arctan(np.sinh(u)), rtol=0, atol=1e-15)
    u = np.linspace(-7.0, 7.0, 29)
    sn, cn, dn, am = E.ellipj(u, 0.0, 1.0)
    sn, cn, dn, am = E.ellipj(u, 0.0, 1.0)
    np.testing.assert_array_equal(sn, np.sin(u))
    np.testing.assert_array_equal(cn, np.cos(u))
    np.testing.assert_array_equal(dn, np.ones_like(u))
    np.testing.assert_array_equal(am, u)


def test_scalar_in_scalar_out():
    sn, cn, dn, am = E.ellipj(0.5, 0.3)
    assert all(isinstance(v, float) for v in (sn, cn, dn, am))
    assert isinstance(E.elliprf(1.0, 2.0, 3.0), float)


def test_no_scipy_needed():
    """The module's source never names scipy.special in an import (issue 16)."""
    import inspect

    src = inspect.getsource(E)
    assert "import scipy" not in src and "from scipy" not in src
