"""rbcli.core.roots.brentq takes scipy.optimize.brentq's steps: the same float, bit for bit."""

import numpy as np
import pytest

from rbcli.core.roots import brentq


def test_same_float_as_scipy_on_random_cubics():
    scipy_brentq = pytest.importorskip("scipy.optimize").brentq
    rng = np.random.default_rng(16)
    eps4 = 4.0 * np.finfo(float).eps
    for _ in range(400):
        c = rng.normal(size=4) * 10.0 ** rng.integers(-6, 6, size=4)
        f = lambda x, c=c: ((c[0] * x + c[1]) * x + c[2]) * x + c[3]  # noqa: E731
        a, b = sorted(rng.normal(size=2) * 10.0 ** rng.integers(-3, 3))
        if np.sign(f(a)) == np.sign(f(b)):
            continue
        for xtol in (1e-300, 2e-12):
            want = scipy_brentq(f, a, b, xtol=xtol, rtol=eps4, maxiter=500)
            assert brentq(f, a, b, xtol=xtol, rtol=eps4, maxiter=500) == want


def test_errors():
    with pytest.raises(ValueError):
        brentq(lambda x: x * x + 1.0, -1.0, 1.0)
    with pytest.raises(RuntimeError):
        brentq(lambda x: x ** 3 - 2.0, 0.0, 3.0, xtol=0.0, rtol=0.0, maxiter=2)
    assert brentq(lambda x: x, 0.0, 1.0) == 0.0


@pytest.mark.parametrize("fscale, xscale", [(1e-300, 1.0), (1.0, 1e200), (1e-200, 1e80)])
def test_a_denominator_that_underflows_bisects_as_scipy_does(fscale, xscale):
    # the extrapolation's denominator (a product of two slopes and a difference of values)
    # underflows to 0 for tiny values or wide brackets (whirl on 1e160 N/m bearings): C's
    # division gives inf or NaN and scipy bisects; the port raised ZeroDivisionError
    f = lambda x: fscale * (np.exp(x / xscale - 1.0) - 1.5)  # noqa: E731
    x = brentq(f, 0.0, 3.0 * xscale, xtol=1e-14 * xscale, rtol=8.881784197001252e-16)
    assert x == pytest.approx(xscale * (1.0 + np.log(1.5)), rel=1e-13)  # xtol + rtol: ~1e-14
    scipy_brentq = pytest.importorskip("scipy.optimize").brentq
    assert x == scipy_brentq(f, 0.0, 3.0 * xscale, xtol=1e-14 * xscale, rtol=8.881784197001252e-16)
