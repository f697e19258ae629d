"""The small-body paths of issue 16 (a batch of 1000 files of 1-4 parts), bit for bit
against the numpy code they replace: snap in Python floats, combine's weights reused."""

from __future__ import annotations

import numpy as np
import pytest

from rbcli.api.reference import snap
from rbcli.core import inertia as ci
from rbcli.body.partmodel import Part


def _snap_numpy(values, scale=None, rtol=1e-14):
    """snap as it was: numpy on the whole array (the oracle)."""
    a = np.array(values, dtype=float)
    mag = np.abs(a)
    s = float(mag.max()) if scale is None else scale
    a[mag <= rtol * s] = 0.0
    a[a == 0.0] = 0.0
    return a


SPECIAL = [0.0, -0.0, 1e-300, -1e-20, 5e-324, np.inf, -np.inf, np.nan, 1e308, -3.0]


@pytest.mark.parametrize("seed", range(40))
def test_snap_is_the_numpy_one(seed):
    rng = np.random.default_rng(seed)
    shape = [(3, 3), (3,), (2, 3, 3), (1,)][seed % 4]
    a = rng.standard_normal(shape) * 10.0 ** rng.integers(-20, 20, size=shape)
    if seed % 3:  # some special entries
        flat = a.reshape(-1)
        for i in rng.integers(0, flat.size, size=rng.integers(1, 3)):
            flat[i] = SPECIAL[rng.integers(0, len(SPECIAL))]
    for kw in ({}, {"scale": 1.0, "rtol": 1e-15}, {"scale": float(rng.uniform(0, 1e3))}):
        new, old = snap(a, **kw), _snap_numpy(a, **kw)
        assert new.shape == old.shape and new.dtype == old.dtype
        assert new.tobytes() == old.tobytes()  # every bit, the sign of zeros included


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
