"""The small-body paths of issue 16 (a batch of 1000 files of 1-4 parts), bit for bit
against the numpy code they replace: combine's weights reused; snap's edges."""

from __future__ import annotations

import numpy as np
import pytest

from rbcli.api.inertia import snap
from rbcli.core import inertia as ci
from rbcli.model import Part


def test_snap_of_a_list_and_of_nothing():
    assert snap([1.0, 1e-20, -0.0]).tolist() == [1.0, 0.0, 0.0]
    with pytest.raises(ValueError):  # numpy's max of nothing, as before
        snap(np.zeros(0))


def _combine_weights_abs(parts):
    """combine's com with the weights |m| always taken (as it was): the oracle."""
    m = np.array([-p.mass if p.subtract else p.mass for p in parts], dtype=float)
    c = np.array([p.com for p in parts], dtype=float).reshape(len(parts), 3)
    total = float(m.sum())
    w = np.abs(m)
    origin = (w @ c) / w.sum()
    rel = c - origin
    return origin + (m @ rel) / total


@pytest.mark.parametrize("seed", range(30))
def test_combine_com_without_holes_is_the_abs_weights_one(seed):
    rng = np.random.default_rng(100 + seed)
    parts = []
    for i in range(int(rng.integers(1, 9))):
        A = rng.standard_normal((3, 3))
        parts.append(Part(name=f"p{i}", shape="point", mass=float(rng.uniform(1e-3, 1e3)),
                          subtract=bool(seed % 2 and i == 1),
                          com=rng.standard_normal(3) * 10.0 ** rng.integers(-3, 4),
                          inertia_com=A @ A.T))
    if sum(-p.mass if p.subtract else p.mass for p in parts) <= 0:
        pytest.skip("holes heavier than the rest")
    assert ci.combine(parts).com.tobytes() == _combine_weights_abs(parts).tobytes()
