"""rbcli.core.symmetry: how nearly a body is symmetric about an axis (issue 14 item 2).

Oracles: the textbook moments of a solid cylinder (m(3r² + h²)/12 across, m r²/2 about its
axis) and of a point mass, the parallel-axis theorem, and numpy's eigenvalues of the 2×2
block across the axis, all written here; and, for the real-body integration of
``top --verify``, the closed form itself on an exactly symmetric body.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rbcli.core import symmetry as sy
from rbcli.core.top import analyse
from rbcli.core.topbody import TopParams, top_from_body
from rbcli.core.topverify import verify_real_body

RHO = 7850.0


def cylinder(r, h, z):
    """mass, com and inertia about the com of a steel cylinder along z centred at (0, 0, z)."""
    m = RHO * math.pi * r * r * h
    return m, np.array([0.0, 0.0, z]), np.diag([m * (3 * r * r + h * h) / 12] * 2 + [m * r * r / 2])


def flywheel(screw=0.0015, x=0.04):
    """examples/cad_flywheel.yaml assembled by hand: mass, com, inertia about the com."""
    parts = [cylinder(0.1, 0.03, 0.12), cylinder(0.006, 0.15, 0.075),
             (screw, np.array([x, 0.0, 0.12]), np.zeros((3, 3)))]
    M = sum(p[0] for p in parts)
    G = sum(p[0] * p[1] for p in parts) / M
    J = np.zeros((3, 3))
    for m, c, Jc in parts:
        d = c - G
        J += Jc + m * (d @ d * np.eye(3) - np.outer(d, d))
    return M, G, J


def oracle_transverse(M, G, J, P):
    """The two moments across the pivot–com axis about P, by numpy."""
    d = G - P
    Jp = J + M * (d @ d * np.eye(3) - np.outer(d, d))
    e3 = d / np.linalg.norm(d)
    e1 = np.cross(e3, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(e3, e1)
    B = np.array([[e1 @ Jp @ e1, e1 @ Jp @ e2], [e2 @ Jp @ e1, e2 @ Jp @ e2]])
    return np.linalg.eigvalsh(B)


def test_flywheel_measured_against_the_textbook():
    M, G, J = flywheel()
    P = np.zeros(3)
    s = sy.about_axis(M, G, J, P, G - P)
    I1, I2 = oracle_transverse(M, G, J, P)
    assert s.transverse == pytest.approx((I1, I2), rel=1e-13)
    assert s.mean == pytest.approx(0.5 * (I1 + I2), rel=1e-14)
    assert s.relative == pytest.approx((I2 - I1) / (0.5 * (I1 + I2)), rel=1e-7)
    assert 1e-5 < s.relative < 1e-4  # "symmetric to 0.01 %": a few 1e-5 about the pivot
    assert s.com_offset < 1e-15  # the axis runs through the com by construction
    assert not s.exact
    # about the com and the shaft (z): the screw alone breaks the symmetry, m x² apart
    g = sy.about_axis(M, G, J, G, [0, 0, 1])
    assert g.transverse[1] - g.transverse[0] == pytest.approx(
        0.0015 * 0.04**2 * (1 - 0.0015 / M), rel=1e-6)  # the screw's m x² about the com


def test_a_symmetric_body_is_exact_and_the_com_offset_is_measured():
    m, c, J = cylinder(0.1, 0.03, 0.0)
    s = sy.about_axis(m, c, J, [0, 0, -0.1], [0, 0, 1])
    assert s.exact and s.relative == 0.0 and s.coupling == 0.0
    # the same cylinder about a parallel line 1 mm away: the com is off the axis
    off = sy.about_axis(m, c, J, [0.001, 0, 0], [0, 0, 1], size=0.1)
    assert off.com_offset == pytest.approx(0.001, rel=1e-12)
    assert off.com_offset_relative == pytest.approx(0.01, rel=1e-12)


def test_beyond_the_tolerance_is_refused_with_the_numbers_and_the_option():
    M, G, J = flywheel(screw=1.0, x=0.09)  # a 1 kg lump on the rim: a few % out
    s = sy.about_axis(M, G, J, np.zeros(3), G)
    with pytest.raises(sy.Asymmetric) as exc:
        sy.require(s, 0.01, "the pivot–com axis", "a top")
    msg = str(exc.value)  # the parameter as a template the caller spells ({symmetry_tol})
    assert "{symmetry_tol} (1 %)" in msg and "a top needs" in msg
    assert "not" in msg and "kg m²" in msg
    assert exc.value.symmetry is s and exc.value.tolerance == 0.01


def test_top_from_body_symmetrises_within_the_tolerance():
    M, G, J = flywheel()
    with pytest.raises(ValueError, match="symmetry_tol"):
        top_from_body(M, G, J, np.zeros(3))  # the core's own default: rounding only
    p = top_from_body(M, G, J, np.zeros(3), sym_rtol=0.01)
    I1, I2 = oracle_transverse(M, G, J, np.zeros(3))
    assert p.I == pytest.approx(0.5 * (I1 + I2), rel=1e-13)
    assert p.asymmetry is not None and p.asymmetry.transverse == pytest.approx((I1, I2), rel=1e-13)


def test_real_body_integration_reproduces_the_closed_form_of_a_symmetric_body():
    # an exactly symmetric top (the course's) given an asymmetry record with equal moments:
    # the full rigid-body integration must then follow the closed form to round-off
    m_, l_, I, Is = 0.5, 0.04, 1.2e-3, 4.0e-4
    Ic = I - m_ * l_ * l_
    sym = sy.about_axis(m_, [0, 0, l_], np.diag([Ic, Ic, Is]), [0, 0, 0], [0, 0, 1])
    p = TopParams(mass=m_, length=l_, I=I, Is=Is, axis=(0.0, 0.0, 1.0), pivot=(0.0, 0.0, 0.0),
                  com=(0.0, 0.0, l_), asymmetry=sym)
    for phi_dot in (0.0, 10.0):
        mo = analyse(p, 150.0, math.radians(30), 0.5, phi_dot, 9.81)
        rb = verify_real_body(mo, periods=2)
        assert rb.max_axis_error < 1e-10, rb
        assert rb.energy_drift < 1e-12


def test_real_body_of_the_flywheel_differs_by_the_order_of_its_asymmetry():
    M, G, J = flywheel()
    p = top_from_body(M, G, J, np.zeros(3), sym_rtol=0.01)
    mo = analyse(p, 1500 * math.pi / 30, math.radians(60), g=9.80665)
    rb = verify_real_body(mo)
    tilt = p.asymmetry.principal_tilt
    assert 1e-6 < tilt < 1e-4
    # the real body's axis departs from the symmetrised closed form by a few times the tilt
    # of its principal axis, far above the integration's own error (the energy drift)
    assert tilt < rb.max_axis_error < 20 * tilt
    assert rb.energy_drift < 1e-11
