"""The heavy top at the edges of double precision (issue 27: ``top --theta-dot 1e300`` ended
in exit 70, ``brentq: not converged in 500 iterations``).

Every start value either gives a motion whose numbers are finite, or a
:class:`rbcli.core.top.TopInputError` (a ParamError: exit 2) naming the parameter that is
out of range; never another exception. Where a motion is given it is checked against
closed forms that do not use the root finder: a top whose tilt rate dwarfs gravity and spin
turns head over heels at that rate, so its nutation period is 2π/|θ0'|; the cubic's three
roots satisfy Vieta's relations.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from rbcli.core.top import TopInputError, analyse
from rbcli.core.topbody import TopParams

#: the worked example's top (physics sheet dynamics.md §2.1)
TOP = TopParams(mass=0.5, length=0.04, I=1.2e-3, Is=4.0e-4)
G = 9.81


def _motion_or_refusal(S, theta_deg, thd, phid):
    try:
        return analyse(TOP, S, math.radians(theta_deg), thd, phid, G)
    except TopInputError as exc:
        return exc


@pytest.mark.parametrize("value", [1e300, -1e300, 1e155, 1.7e308])
def test_a_huge_tilt_rate_is_refused_naming_it(value):
    err = _motion_or_refusal(150.0, 30.0, value, 0.0)
    assert isinstance(err, TopInputError), err
    assert err.param == "theta_dot"
    assert "too large" in str(err) and "double precision" in str(err)


@pytest.mark.parametrize("param,kw", [("phi_dot", dict(phid=-1e200)), ("spin", dict(S=1e200))])
def test_the_dominant_rate_is_the_one_named(param, kw):
    args = dict(S=150.0, theta_deg=30.0, thd=0.0, phid=0.0) | kw
    err = _motion_or_refusal(**args)
    assert isinstance(err, TopInputError) and err.param == param, err


def test_a_vanishing_spin_is_refused_naming_the_spin():
    # m g l/(Is S) overflows: the body is a spherical pendulum to double precision
    err = _motion_or_refusal(1e-300, 30.0, 0.0, 0.0)
    assert isinstance(err, TopInputError) and err.param == "spin", err
    assert "too small" in str(err)


def _extreme_grid(step: int) -> None:
    values = [0.0] + [s * 10.0**e for e in range(-320, 309, step) for s in (1.0, -1.0)]
    for theta in (1e-6, 30.0, 90.0, 179.9999):
        for thd, phid, S in itertools.product(values, values, (150.0, 1e-5, 1e5)):
            out = _motion_or_refusal(S, theta, thd, phid)
            if isinstance(out, TopInputError):
                continue
            doc = out.to_json()
            for k in ("theta1_deg", "theta2_deg", "critical_spin", "horizontal_precession_rate"):
                assert doc[k] is not None and math.isfinite(doc[k]), (theta, thd, phid, S, k)
            assert all(math.isfinite(u) for u in doc["turning_points"]), (theta, thd, phid, S)


def test_every_extreme_start_is_a_motion_or_a_refusal():
    """A grid of start values over the whole double range (with 0 and both signs; every
    96th decade here, every 16th under ``-m slow``), at tilts near the poles, at 30° and
    horizontal: only motions with finite numbers or TopInputErrors. (Before: RuntimeError
    from Brent's method for θ0' >= 1e155 and for θ0' = 1e-144 at θ0 = 1e-6°, a math domain
    error at θ0' = 1e66, NaN turning points for θ0' from 1e78 to 1e153, ZeroDivisionError
    and OverflowError for tiny spins.)"""
    _extreme_grid(96)


@pytest.mark.slow
def test_every_extreme_start_is_a_motion_or_a_refusal_finely():
    _extreme_grid(16)


@pytest.mark.parametrize("thd", [1e66, 1e80, 1e120, 1e150])
def test_a_top_whirled_head_over_heels_turns_at_its_tilt_rate(thd):
    """θ0' ≫ a, sqrt(β): gravity and spin change the rate by (a/θ0')² ~ 1e-129 at most, so
    the axis turns through both poles at |θ0'| and u returns every 2π/|θ0'| (independent of
    the elliptic solution). The turning points u1 = -1, u2 = 1 to rounding, and the large
    root satisfies Vieta's sum x1 + x2 + x3 = -c2/β (the polish kept it, not NaN)."""
    m = analyse(TOP, 150.0, math.radians(30.0), thd, 0.0, G)
    # one nutation period is a full turn at |θ0'|; 1e-12: the elliptic K and λ to ~1e-15
    # each, and the period of a few ulp more from the pole corrections
    assert m.nutation_period * thd == pytest.approx(2.0 * math.pi, rel=1e-12)
    assert m.u1 == pytest.approx(-1.0, abs=1e-12) and m.u2 == pytest.approx(1.0, abs=1e-12)
    u0 = math.cos(math.radians(30.0))
    s0sq = math.sin(math.radians(30.0)) ** 2
    A0 = thd * thd
    c2 = 2.0 * u0 * m.beta - A0 - m.a * m.a
    # Vieta's sum in x = u - u0; 1e-12 relative: x3 ~ 1e129 and more, the other two ~1
    x_sum = (m.u1 - u0) + (m.u2 - u0) + (m.u3 - u0)
    assert x_sum == pytest.approx(-c2 / m.beta, rel=1e-12)
    # and the product x1 x2 x3 = -c0/β, c0 = sin²θ0 θ0'² (relative 1e-9: x1 x2 is a
    # product of 1 + u0 and 1 - u0 rounded near the poles, ~1e-15 each, and x3's digits)
    x_prod = (m.u1 - u0) * (m.u2 - u0) * (m.u3 - u0)
    assert x_prod == pytest.approx(-s0sq * A0 / m.beta, rel=1e-9)


def test_a_tiny_tilt_rate_near_the_pole_converges():
    """θ0 = 1e-6°, θ0' = 1e-144 rad/s: the upper root sits at ~3e-291 where the cubic's
    values are subnormal (Brent's method crept there in steps of 5e-301 and gave up). The
    root is -c0/c1 to rounding (the cubic is linear there); the motion is the release from
    rest at θ0 to within that."""
    th0 = math.radians(1e-6)
    m = analyse(TOP, 150.0, th0, 1e-144, 0.0, G)
    rest = analyse(TOP, 150.0, th0, 0.0, 0.0, G)
    # the θ0' = 1e-144 motion differs from release from rest by ~1e-290 relative
    np.testing.assert_allclose([m.theta1, m.theta2], [rest.theta1, rest.theta2], rtol=1e-14)


def test_cli_refuses_a_huge_tilt_rate_with_one_line(cli_proc):
    r = cli_proc("top", "examples/top.yaml", "--spin", "150", "--theta", "30",
                 "--theta-dot", "1e300")
    assert r.code == 2, r.err
    assert r.err.count("\n") == 1 and r.err.startswith("rbcli: --theta-dot: the initial tilt rate 1e+300 rad/s"), r.err
    assert r.out == ""


@pytest.mark.parametrize("value", ["1e300", "-1e300"])
def test_report_leaves_out_the_top_with_the_reason(cli_proc, tmp_path, value):
    out = tmp_path / "r.md"
    r = cli_proc("report", "examples/top.yaml", "--spin", "150", "--theta", "30",
                 f"--theta-dot={value}", "-o", out)
    assert r.code == 0 and "internal error" not in r.err, r.err
    text = out.read_text(encoding="utf-8")
    assert "heavy top: not computed: " in text and "too large" in text
