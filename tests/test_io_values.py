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

import rbcli
from rbcli.model import Body, Outline, Part, Shaft

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
    import rbcli.model as model

    assert not hasattr(Part, "positional") and not hasattr(Outline, "of_frozen")
    assert not hasattr(model, "_twin")
    for cls in (Part, Outline, Body, Shaft):
        assert dataclasses.is_dataclass(cls) and cls.__dataclass_params__.frozen
