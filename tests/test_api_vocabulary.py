"""One vocabulary (issue 22): every key of a result's JSON is an attribute of the result with
that value, nested objects read by attribute too (``r.corrections[0].angle_deg``), and the
results are values (frozen fields, read-only arrays)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import rbcli
from rbcli.api.result import Record, jsonable

CASES = [
    ("inertia", "examples/square_lamina.yaml", dict(axis=[1, 1, 0], omega=[1, 0, 0])),
    ("principal", "examples/two_blade_fan.yaml", {}),
    ("balance", "examples/two_disk_rotor.yaml",
     dict(planes="0,400 mm", radius="100 mm", speed="3000 rpm", bearings="0,400 mm", grade="G6.3")),
    ("balance", "examples/fan_impeller.yaml", dict(planes="-10,10 mm", radius="150 mm", positions=6, mass_step="0.5 g")),
    ("precess", "examples/book.yaml", dict(omega=[0.01, 1, 0.01])),
    ("precess", "examples/frisbee.yaml", dict(omega=[0, 1, 30])),
    ("top", "examples/top.yaml", dict(spin=150, theta=30)),
    ("gyrocompass", "examples/gyroscope.yaml", dict(spin="6000 rpm", latitude=30)),
    ("rollcheck", "examples/penny.yaml", dict(speed="3 m/s")),
    ("report", "examples/top.yaml", dict(spin=150, theta=30)),
]


def _result(cmd, path, kw):
    return getattr(rbcli, cmd)(rbcli.load(path), **kw)


@pytest.mark.parametrize("cmd, path, kw", CASES, ids=[f"{c}-{p.split('/')[-1]}" for c, p, _ in CASES])
def test_every_json_key_is_an_attribute_with_its_value(cmd, path, kw):
    r = _result(cmd, path, kw)
    d = r.to_json()
    assert d, cmd
    for key, value in d.items():
        assert jsonable(getattr(r, key)) == value, key


def test_nested_objects_read_by_attribute():
    r = _result(*CASES[2])
    c = r.corrections[0]
    assert isinstance(c, Record) and c.angle_deg == c["angle_deg"] == r.to_json()["corrections"][0]["angle_deg"]
    assert r.bearing_forces[1].force == r.to_json()["bearing_forces"][1]["force"]
    assert r.static_unbalance == r.to_json()["static_unbalance"] and isinstance(r.static_unbalance, float)
    with pytest.raises(AttributeError, match="no key 'nope'"):
        c.nope  # noqa: B018
    with pytest.raises(AttributeError, match="read-only"):
        c.mass = 1.0
    with pytest.raises(AttributeError, match="JSON keys: mass"):
        r.nope  # noqa: B018


@pytest.mark.parametrize("cmd, path, kw", CASES[:4], ids=[c for c, _, _ in CASES[:4]])
def test_results_are_values(cmd, path, kw):
    r = _result(cmd, path, kw)
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.warnings = ()  # type: ignore[misc]
    arrays = [getattr(r, f.name) for f in dataclasses.fields(r)
              if isinstance(getattr(r, f.name), np.ndarray)]
    for a in arrays:
        with pytest.raises(ValueError):
            a[...] = 0.0
    before = r.to_json()
    for a in arrays:  # a copy a caller takes and changes is its own
        b = a.copy()
        b[...] = 7.0
    assert r.to_json() == before
