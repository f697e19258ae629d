"""Darlow's plane-significance factors (rbcli.core.field.significance).

Oracles: the factor is |R_kk| / |u_k| of a QR factorisation of the influence matrix with
its columns in the test's order (numpy's Householder QR: a different algorithm from the
module's Gram-Schmidt); hsbalance's ``ill_condition`` (where installed) flags the same
planes for two planes and for Darlow's published example.
"""

from __future__ import annotations

import numpy as np
import pytest

from rbcli.core.field.significance import SIGNIFICANCE_LIMIT, plane_significance
from test_field_solve import DARLOW_ALPHA, FOILES_ALPHA, M


def _qr_factors(A: np.ndarray) -> np.ndarray:
    norms = np.linalg.norm(A, axis=0)
    order = np.argsort(-norms, kind="stable")
    _, R = np.linalg.qr(A[:, order])
    out = np.empty(A.shape[1])
    out[order] = np.abs(np.diag(R)) / norms[order]
    return out


@pytest.mark.parametrize("seed", range(10))
def test_factors_equal_qr(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(2, 12))
    p = int(rng.integers(1, n + 1))
    A = rng.normal(size=(n, p)) + 1j * rng.normal(size=(n, p))
    s = plane_significance(A)
    # both orthogonalise the same columns in the same order: round-off of a few eps
    np.testing.assert_allclose(s.factors, _qr_factors(A), atol=1e-12)
    assert s.factors[s.order[0]] == 1.0


def test_darlow_example_flags_the_dependent_plane():
    s = plane_significance(DARLOW_ALPHA)
    # planes 2 and 3 differ in one sensor: the smaller of the two (plane 2) adds little
    np.testing.assert_allclose(s.factors, _qr_factors(DARLOW_ALPHA), atol=1e-12)
    assert s.flagged == (1,)
    assert s.factors[1] < SIGNIFICANCE_LIMIT < s.factors[0]


def test_independent_and_dependent_columns():
    # orthogonal columns: every factor 1; a column that is a multiple of another: 0
    A = np.array([[1, 0], [0, 1j], [0, 0]], dtype=complex)
    assert plane_significance(A).factors == pytest.approx([1, 1], abs=1e-15)
    B = np.array([[1, 2], [3, 6], [1j, 2j]], dtype=complex)
    s = plane_significance(B)
    assert s.factors[0] == pytest.approx(0.0, abs=1e-15) and s.flagged == (0,)
    assert plane_significance(FOILES_ALPHA).flagged == ()


@pytest.fixture
def hs_tools():
    return pytest.importorskip("hsbalance.tools")


def test_agrees_with_hsbalance(hs_tools):
    assert list(hs_tools.ill_condition(DARLOW_ALPHA)) == list(plane_significance(DARLOW_ALPHA).flagged)
    rng = np.random.default_rng(5)
    flagged_any = False
    for _ in range(200):
        A = rng.normal(size=(3, 2)) + 1j * rng.normal(size=(3, 2))
        # make some pairs nearly dependent, so both answers occur
        A[:, 1] = A[:, 0] * (rng.normal() + 1j * rng.normal()) + A[:, 1] * rng.uniform(0, 0.5)
        mine = plane_significance(A).flagged
        theirs = [int(i) for i in hs_tools.ill_condition(A)]
        assert list(mine) == theirs
        flagged_any = flagged_any or bool(mine)
    assert flagged_any
    # two planes of a published case, too
    bk = M(["78.43@58.4 15.34@145.3", "9.462@10.2 32.56@142.4"])
    assert list(hs_tools.ill_condition(bk)) == list(plane_significance(bk).flagged) == []


def test_every_plane_hsbalance_flags_is_flagged(hs_tools):
    """From three planes on hsbalance measures each column against the one before it only:
    its factor is never smaller than the distance from the span of all earlier columns, so
    it flags a subset of the planes flagged here."""
    rng = np.random.default_rng(9)
    more = 0
    for _ in range(500):
        n = int(rng.integers(3, 7))
        A = rng.normal(size=(n, 3)) + 1j * rng.normal(size=(n, 3))
        A[:, 2] = A[:, 1] * (1 + 0.2 * rng.normal()) + 0.3 * rng.normal() * A[:, 2]
        theirs = {int(i) for i in hs_tools.ill_condition(A)}
        mine = set(plane_significance(A).flagged)
        assert theirs <= mine
        more += mine != theirs
    assert more  # and the difference shows
