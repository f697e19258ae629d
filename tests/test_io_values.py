"""Bodies are values (issues 22, 23, 27): a library call leaves the garbage collector alone,
Part and Outline are plain frozen dataclasses, and a body is deeply immutable — every array
of a Body, its Parts, their Outlines and its Shaft read-only whatever path built it, and
``Part.extra`` and ``Body.units`` mappings that cannot be changed: one body, one answer.
"""

from __future__ import annotations

import dataclasses
import gc
from pathlib import Path

import numpy as np
import pytest

import rbcli
from rbcli.errors import Location
from rbcli.body.model import Body
from rbcli.body.partmodel import Outline, Part, Shaft

ROOT = Path(__file__).resolve().parent.parent


def _include_tree(tmp_path: Path) -> Path:
    (tmp_path / "sub.yaml").write_text(
        "parts:\n  - {name: b, shape: box, mass: 1, size: [0.1, 0.2, 0.3], at: [0.5, 0, 0]}\n"
        "  - {name: g, shape: given, mass: 2, inertia: {Ixx: 0.1, Iyy: 0.2, Izz: 0.25}}\n")
    top = tmp_path / "top.yaml"
    top.write_text(
        "units: {length: mm}\nreference: [1, 2, 3]\npivot: [0, 0, 1]\n"
        "shaft: {axis: [0, 0, 1], through: [0, 0, 5]}\nparts:\n"
        "  - {name: s, shape: include, file: sub.yaml, at: [0, 0, 100], rotate: {axis: [0, 0, 1], angle: 90}}\n"
        "  - {name: r, shape: rod, from: [0, 0, 0], to: [0, 0, 50], mass: 1}\n"
        f"  - {{name: m, shape: mesh, file: {ROOT / 'examples' / 'housing.stl'}, units: mm, density: 2700}}\n")
    return top


def _bodies(tmp_path: Path) -> dict[str, Body]:
    return {
        "examples/top.yaml": rbcli.load(ROOT / "examples" / "top.yaml"),
        "examples/housing.yaml": rbcli.load(ROOT / "examples" / "housing.yaml"),
        "examples/earth.yaml": rbcli.load(ROOT / "examples" / "earth.yaml"),
        "one-part text": rbcli.load_text("{shape: cylinder, radius: 0.1, length: 0.3, mass: 2}"),
        "includes, given, mesh, shaft": rbcli.load(_include_tree(tmp_path)),
    }


def _arrays(obj, seen=None):
    """Every ndarray reachable from a body through its fields (parts, outlines, shaft)."""
    seen = set() if seen is None else seen
    if id(obj) in seen:
        return
    seen.add(id(obj))
    if isinstance(obj, np.ndarray):
        yield obj
    elif dataclasses.is_dataclass(obj):
        for f in dataclasses.fields(obj):
            yield from _arrays(getattr(obj, f.name), seen)
    elif isinstance(obj, (tuple, list)):
        for x in obj:
            yield from _arrays(x, seen)


# ----------------------------------------------------------------------------- the collector


def test_loading_leaves_the_garbage_collector_alone(tmp_path, monkeypatch):
    calls = []
    for name in ("disable", "enable", "freeze", "unfreeze", "set_threshold", "collect"):
        real = getattr(gc, name)
        monkeypatch.setattr(gc, name, lambda *a, _n=name, _r=real: calls.append(_n) or _r(*a))
    bodies = _bodies(tmp_path)
    assert len(bodies) == 5 and gc.isenabled()
    assert calls == []


def test_part_and_outline_are_plain_frozen_dataclasses():
    # no twin classes made quickly by swapping __class__: the dataclasses' own constructors
    import rbcli.body.model as model

    assert not hasattr(Part, "positional") and not hasattr(Outline, "of_frozen")
    assert not hasattr(model, "_twin")
    for cls in (Part, Outline, Body, Shaft):
        assert dataclasses.is_dataclass(cls) and cls.__dataclass_params__.frozen


# ----------------------------------------------------------------------------- deeply immutable


def test_every_array_of_a_loaded_body_is_read_only(tmp_path):
    for what, body in _bodies(tmp_path).items():
        arrays = list(_arrays(body))
        assert len(arrays) >= 3 * len(body.parts), what  # the walk reaches the parts' arrays
        assert [a for a in arrays if a.flags.writeable] == [], what


def test_changing_a_part_of_a_loaded_body_raises_and_the_answers_stay(tmp_path):
    b = rbcli.load(ROOT / "examples" / "top.yaml")
    before = rbcli.inertia(b).to_json()
    with pytest.raises(ValueError, match="read-only"):
        b.parts[0].com[2] = 10
    with pytest.raises(ValueError, match="read-only"):
        b.parts[0].inertia_com[0, 0] = 10
    with pytest.raises(ValueError, match="read-only"):
        b.parts[0].outline.at[0] = 1
    with pytest.raises(dataclasses.FrozenInstanceError):
        b.parts[0].mass = 5  # type: ignore[misc]
    assert rbcli.inertia(b).to_json() == before  # one body, one answer


def test_extra_and_units_are_read_only_mappings(tmp_path):
    b = rbcli.load(_include_tree(tmp_path))
    mesh = next(p for p in b.parts if p.shape == "mesh")
    assert mesh.extra["triangles"] == 32
    with pytest.raises(TypeError):
        mesh.extra["triangles"] = 1  # type: ignore[index]
    with pytest.raises(TypeError):
        b.parts[0].extra["x"] = 1  # type: ignore[index]
    assert b.units == {"length": "mm"}
    with pytest.raises(TypeError):
        b.units["length"] = "km"  # type: ignore[index]
    # what bare numbers mean stays what the file said
    assert rbcli.inertia(b, about="1,0,0").to_json() == rbcli.inertia(b, about="1,0,0").to_json()


def test_bodies_built_in_code_are_frozen_too():
    """Part, Outline, Shaft and Body made by hand (or by dataclasses.replace) from writable
    arrays and dicts keep read-only copies: changing what was passed in changes nothing."""
    com, J, axis, at = np.array([0.0, 0, 1]), np.eye(3), np.array([0.0, 0, 1]), np.zeros(3)
    extra = {"volume": 1.0}
    o = Outline("box", (("size", (1.0, 1.0, 1.0)),), at, np.eye(3))
    p = Part("p", "box", 1.0, False, com, J, 1.0, "volume", None, axis, extra, Location("f", 1, 1), o)
    units = {"length": "mm"}
    body = Body("b", "<code>", "", (p,), reference=np.array([1.0, 2, 3]), pivot=np.zeros(3),
                shaft=Shaft(np.array([0.0, 0, 1]), np.zeros(3)), units=units)
    com[2] = 99.0
    J[0, 0] = 99.0
    at[0] = 99.0
    extra["volume"] = 99.0
    units["length"] = "km"
    assert p.com[2] == 1.0 and p.inertia_com[0, 0] == 1.0 and o.at[0] == 0.0
    assert p.extra == {"volume": 1.0} and body.units == {"length": "mm"}
    assert [a for a in _arrays(body) if a.flags.writeable] == []
    q = dataclasses.replace(p, com=np.array([1.0, 2.0, 3.0]), extra={"area": 2.0})
    assert not q.com.flags.writeable
    with pytest.raises(TypeError):
        q.extra["area"] = 3.0  # type: ignore[index]
    with pytest.raises(ValueError, match="read-only"):
        body.shaft.axis[0] = 1.0
