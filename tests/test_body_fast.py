"""The loader's fast path (parts placed in batches, rotations per kind, the vectorised
:func:`rbcli.core.inertia.combine`) against a straightforward independent computation on
the generated 1000-part body of bench/large_bodies.py (every shape, every placement form,
units, density strings, holes with ``cut_from``).

The oracle reads the file with PyYAML, converts its few units by hand, builds every
rotation with scipy's ``Rotation`` (not rbcli's formulas), places each part with one numpy
product per part and sums the body in a plain loop. Only the shapes' per-unit-mass
inertia comes from :func:`rbcli.core.shapes.geometry` (the public one-part path, tested
against textbook values in test_core_shapes.py).

Tolerance: scipy and rbcli build the same rotations by different formulas (quaternions,
Rodrigues, SVD), each correct to a few ulp (~1e-16); placing a part (R J Rᵀ, at + R c) and
summing 1000 parallel-axis terms of similar size add a few ulp more. 1e-14 relative to the
largest entry of the quantity compared (the largest com coordinate, the largest entry of
the tensor) is ~50 ulp: room for that round-off, far below any real mistake (a wrong sign
or axis moves entries by their own size).
"""

from __future__ import annotations

import importlib.util
import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

from rbcli.core import shapes as shp
from rbcli.core.inertia import body_mass_props, combine
from rbcli.body.model import load_text

ROOT = Path(__file__).resolve().parent.parent
RTOL = 1e-14  # see the module docstring

spatial = pytest.importorskip("scipy.spatial.transform")
scipy = pytest.importorskip("scipy")
import scipy.linalg  # noqa: E402


def _body_text(n: int) -> str:
    sys.path.insert(0, str(ROOT / "bench"))
    try:
        spec = importlib.util.spec_from_file_location("large_bodies_gen", ROOT / "bench" / "large_bodies.py")
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)  # type: ignore[union-attr]
    finally:
        sys.path.remove(str(ROOT / "bench"))
    return mod.body_text(n)


# the units the generated file uses: bare lengths in mm, masses in kg, angles in degrees
UNITS = {"mm": 1e-3, "cm": 1e-2, "kg": 1.0, "lb": 0.45359237, "kg/m^3": 1.0, "g/cm^3": 1000.0,
         "kg/m^2": 1.0, "kg/m": 1.0}


def _si(x, bare: float) -> float:
    if isinstance(x, str):
        number, unit = x.split(" ", 1)
        return float(number) * UNITS[unit]
    return float(x) * bare


def _rotation(part: dict) -> np.ndarray:
    R = spatial.Rotation
    if "axis" in part:
        d = np.array(part["axis"], dtype=float)
        d /= np.linalg.norm(d)
        z = np.array([0.0, 0.0, 1.0])
        k = np.cross(z, d)
        s = np.linalg.norm(k)
        if s == 0.0:
            return np.eye(3) if d[2] > 0 else np.diag([1.0, -1.0, -1.0])
        return R.from_rotvec(k / s * math.atan2(s, d[2])).as_matrix()
    if "rotate" not in part:
        return np.eye(3)
    r = part["rotate"]
    if "angle" in r:
        a = np.array(r["axis"], dtype=float)
        return R.from_rotvec(a / np.linalg.norm(a) * math.radians(r["angle"])).as_matrix()
    if "euler" in r:
        return R.from_euler(r["seq"], r["euler"], degrees=True).as_matrix()
    if "quaternion" in r:
        w, x, y, z = r["quaternion"]
        return R.from_quat([x, y, z, w]).as_matrix()
    # the nearest rotation (the matrix is typed with 12 digits): scipy's polar decomposition
    # (scipy's Rotation.from_matrix rounds off differently, by ~1e-12 here)
    return scipy.linalg.polar(np.array(r["matrix"], dtype=float))[0]


def _oracle(text: str):
    doc = yaml.safe_load(text)
    mm = 1e-3
    densities = {}
    parts = []
    for p in doc["parts"]:
        shape = p["shape"]
        params = {}
        for key in ("radius", "inner_radius", "length", "height", "thickness"):
            if key in p:
                params[key] = _si(p[key], mm)
        for key in ("size", "semi_axes"):
            if key in p:
                params[key] = [_si(x, mm) for x in p[key]]
        if "vertices" in p:
            params["vertices"] = [[_si(x, mm) for x in v] for v in p["vertices"]]
        geo = shp.geometry(shape, **params)
        if "mass" in p:
            mass = _si(p["mass"], 1.0)
            density = None
        else:
            key = next(k for k in ("density", "areal_density", "linear_density", "cut_from") if k in p)
            density = densities[p["cut_from"]] if key == "cut_from" else _si(p[key], 1.0)
            mass = density * geo.measure
        densities[p["name"]] = density
        R = _rotation(p)
        at = np.array([_si(x, mm) for x in p.get("at", [0, 0, 0])])
        parts.append((p["name"], mass, bool(p.get("subtract", False)), at + R @ geo.com,
                      R @ (mass * geo.unit_inertia) @ R.T))
    sign = np.array([-1.0 if s else 1.0 for _n, _m, s, _c, _J in parts])
    m = np.array([m for _n, m, _s, _c, _J in parts]) * sign
    c = np.array([c for *_x, c, _J in parts])
    total = m.sum()
    com = (m @ c) / total
    J = np.zeros((3, 3))
    for (_n, mi, s, ci, Ji) in parts:
        d = ci - com
        J += (-1.0 if s else 1.0) * (Ji + mi * (d @ d * np.eye(3) - np.outer(d, d)))
    return parts, total, com, J


def _close(a, b, what: str) -> None:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = float(np.max(np.abs(b)))
    err = float(np.max(np.abs(a - b)))
    assert err <= RTOL * scale, f"{what}: {err:.3g} > {RTOL:g} x {scale:.3g}"


@pytest.fixture(scope="module")
def generated():
    text = _body_text(1000)
    return load_text(text, "<bench>", ROOT), _oracle(text)


def test_every_part_is_placed_as_the_oracle_places_it(generated):
    body, (parts, _total, _com, _J) = generated
    assert [p.name for p in body.parts] == [name for name, *_ in parts]
    for p, (name, mass, subtract, com, J) in zip(body.parts, parts):
        assert p.subtract == subtract
        assert p.mass == pytest.approx(mass, rel=RTOL), name
        _close(p.com, com, f"{name} com")
        _close(p.inertia_com, J, f"{name} inertia")


def test_the_body_sums_as_the_oracle_sums(generated):
    body, (_parts, total, com, J) = generated
    mp = body_mass_props(body)
    assert mp.mass == pytest.approx(total, rel=RTOL)
    _close(mp.com, com, "com")
    _close(mp.inertia_com, J, "inertia about the com")


def test_the_kept_mass_properties_are_combine_s(generated):
    """What the loader keeps on the body is exactly what combine gives, and the caller gets
    copies (changing them does not change the next answer)."""
    body, _oracle_result = generated
    mp = combine(body.parts)
    kept = body_mass_props(body)
    assert kept.mass == mp.mass
    assert np.array_equal(kept.com, mp.com) and np.array_equal(kept.inertia_com, mp.inertia_com)
    kept.com[:] = 0.0
    kept.inertia_com[:] = 0.0
    again = body_mass_props(body)
    assert np.array_equal(again.com, mp.com) and np.array_equal(again.inertia_com, mp.inertia_com)


def test_combine_is_the_loop_it_replaced(generated):
    """combine sums its terms in part order: bit for bit the plain loop of before."""
    body, _oracle_result = generated
    parts = body.parts
    m = np.array([p.signed_mass for p in parts])
    c = np.array([p.com for p in parts], dtype=float)
    total = float(m.sum())
    w = np.abs(m)
    origin = (w @ c) / w.sum()
    rel = c - origin
    com_rel = (m @ rel) / total
    d = rel - com_rel
    J = np.zeros((3, 3))
    for p, mi, di in zip(parts, m, d):
        J += (-1.0 if p.subtract else 1.0) * np.asarray(p.inertia_com, dtype=float)
        J += mi * (float(di @ di) * np.eye(3) - np.outer(di, di))
    J = 0.5 * (J + J.T)
    mp = combine(parts)
    assert mp.mass == total
    assert np.array_equal(mp.com, origin + com_rel)
    assert np.array_equal(mp.inertia_com, J)


def test_a_body_with_other_parts_does_not_reuse_the_kept_mass_properties(generated):
    import dataclasses

    body, _oracle_result = generated
    half = dataclasses.replace(body, parts=body.parts[:500])
    mp = body_mass_props(half)
    again = combine(body.parts[:500])
    assert mp.mass == again.mass and np.array_equal(mp.inertia_com, again.inertia_com)
    assert mp.mass != body_mass_props(body).mass


@pytest.mark.parametrize("batch", [1, 7])
def test_the_batch_size_does_not_change_a_number(monkeypatch, batch):
    """Parts placed one or 7 at a time, or all at once, are the same to the last bit (numpy
    makes the same BLAS call for each matrix of a stack). One at a time takes the paths for
    a batch of one kind (placing._units of diagonal inertias only, rotation.from_specs of
    one kind or of none); all at once the mixed ones."""
    import rbcli.body.partlist as partlist

    text = _body_text(200)
    whole = load_text(text, "<bench>", ROOT)
    monkeypatch.setattr(partlist, "BATCH", batch)
    small = load_text(text, "<bench>", ROOT)
    for a, b in zip(whole.parts, small.parts, strict=True):
        assert a.name == b.name and a.mass == b.mass
        for x, y in ((a.com, b.com), (a.inertia_com, b.inertia_com), (a.axis, b.axis),
                     (a.outline.at, b.outline.at), (a.outline.R, b.outline.R)):
            assert np.array_equal(x, y), a.name


@pytest.mark.parametrize("eps", [0.0, 3e-8, 4e-7, 2e-6])
def test_a_typed_rotation_matrix_is_judged_as_from_matrix_judges_it(eps):
    """The loader's quick check (rot.surely_rotation) only ever says yes when from_matrix
    would: near the tolerance (1e-6) it leaves the verdict, and the message, to it."""
    from rbcli.core import rotation as rot
    from rbcli.errors import InputError

    c, s = math.cos(0.3), math.sin(0.3)
    m = [[c * (1 + eps), -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
    text = f"{{shape: point, mass: 1, at: [1, 2, 3], rotate: {{matrix: {m!r}}}}}"
    try:
        R = rot.from_matrix(np.array(m))
    except ValueError as exc:
        with pytest.raises(InputError, match=f"rotation matrix: {re.escape(str(exc))}"):
            load_text(text, "<t>", ROOT)
        return
    body = load_text(text, "<t>", ROOT)
    assert np.array_equal(body.parts[0].outline.R, R)


def test_included_parts_are_placed_bit_for_bit_as_before():
    """An include's use moves its file's parts as one body.placing.Stack (Stack.moved): the
    outlines as ``at + R o.at`` and ``R o.R`` one part at a time, exactly, signs of zeros
    included; the parts as the loader placed them before Stacks (``at + coms Rᵀ`` and
    ``einsum(R, Js, R)`` over all the file's parts, from arrays of its finished Parts); for
    random placements and the identity, and a part without an outline."""
    from rbcli.core import rotation as rot
    from rbcli.body.placing import Stack
    from rbcli.body.partmodel import Part

    body = load_text(_body_text(300), "<gen>", ROOT)
    dot = Part("dot", "point", 1.0, False, np.array([1.0, -0.0, 2.0]), np.zeros((3, 3)))
    parts = [*body.parts, dot]
    stack = Stack.of(parts)
    coms = np.array([p.com for p in parts])
    Js = np.array([p.inertia_com for p in parts])
    axes = np.array([p.axis for p in parts])
    rng = np.random.default_rng(7)
    for k in range(10):
        at = rng.normal(size=3) if k else np.zeros(3)
        R = rot.axis_angle(rng.normal(size=3), rng.uniform(-3, 3)) if k else np.eye(3)
        moved = stack.moved(at, R, "inc/").parts()
        assert np.array_equal(np.array([p.com for p in moved]), at + coms @ R.T)
        assert np.array_equal(np.array([p.inertia_com for p in moved]), np.einsum("ij,njk,lk->nil", R, Js, R))
        assert np.array_equal(np.array([p.axis for p in moved]), axes @ R.T)
        for p, n in zip(parts, moved, strict=True):
            assert n.name == "inc/" + p.name
            assert (n.shape, n.mass, n.subtract, n.measure, n.where, n.extra) == (
                p.shape, p.mass, p.subtract, p.measure, p.where, p.extra)
            o = p.outline
            if o is None:
                assert n.outline is None
                continue
            ref_at, ref_R = at + R @ o.at, R @ o.R
            assert np.array_equal(ref_at, n.outline.at) and np.array_equal(ref_R, n.outline.R)
            assert np.array_equal(np.signbit(ref_at), np.signbit(n.outline.at))
            assert (n.outline.kind, n.outline.dims) == (o.kind, o.dims)
            assert not n.outline.at.flags.writeable and not n.outline.R.flags.writeable


def test_a_body_of_formula_shapes_never_fails_the_physical_check(generated):
    # The loader checks the body's inertia (tensor_problem) only when a part is subtracted
    # or not a formula shape (bodyfile._may_be_impossible): a sum of physically possible
    # tensors is one. Here every run of 1 to 4 consecutive added formula-shape parts of
    # the generated body (every shape, every placement), and all of them, pass the check
    # the loader skips, with its own tolerance (1e-7).
    from rbcli.core.inertia import tensor_problem
    from rbcli.body.bodyfile import _may_be_impossible

    body, _ = generated
    sure = [p for p in body.parts if not p.subtract and p.shape in shp.FORMULA_SHAPES]
    assert {p.shape for p in sure} == set(shp.FORMULA_SHAPES) - {"torus"}  # the torus: below
    runs = [sure[i:i + k] for k in (1, 2, 3, 4) for i in range(0, len(sure) - k + 1)] + [sure]
    for run in runs:
        assert not _may_be_impossible(tuple(run))
        with np.errstate(over="ignore", invalid="ignore"):
            J = combine(run).inertia_com
        assert tensor_problem(J, rtol=1e-7) is None, [p.name for p in run]
    # thin shapes (a moment equal to the sum of the other two) and point masses: on the edge
    for text in ("{shape: rod, mass: 1, length: 1}", "{shape: disk, mass: 1, radius: 1}",
                 "{shape: point, mass: 1}", "{shape: torus, mass: 1, major_radius: 2, minor_radius: 1e-9}",
                 "{parts: [{shape: point, mass: 1, at: [1, 0, 0]}, {shape: point, mass: 3, at: [0, 2e-9, 0]}]}",
                 "{parts: [{shape: plate, mass: 1, size: [1, 2e-9]}, {shape: rod, mass: 2, length: 3, axis: [1, 1, 1]}]}"):
        b = load_text(text, "<t>", ROOT)
        assert not _may_be_impossible(b.parts)
        assert tensor_problem(combine(b.parts).inertia_com, rtol=1e-7) is None, text


def test_the_physical_check_runs_for_holes_meshes_and_given_parts():
    from rbcli.errors import InputError
    from rbcli.body.bodyfile import _may_be_impossible

    hole = load_text("{parts: [{shape: box, mass: 2, size: [1, 1, 1]}, "
                     "{shape: box, mass: 1, size: [0.5, 0.5, 0.5], subtract: true}]}", "<t>", ROOT)
    assert _may_be_impossible(hole.parts)
    given = load_text("{shape: given, mass: 1, inertia: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}", "<t>", ROOT)
    assert _may_be_impossible(given.parts)
    # a hole outside its material: refused with the message of the check
    with pytest.raises(InputError, match="not physically possible"):
        load_text("{parts: [{shape: sphere, mass: 10, radius: 1}, "
                  "{shape: point, mass: 1, at: [0, 0, 5], subtract: true}]}", "<t>", ROOT)


