"""Bodies built in code (issue 22 item 1): ``rbcli.parts`` and ``rbcli.Body.from_parts``.

- the constructors are the registry's shapes, each taking exactly the keys the body file
  takes for its shape (a new shape without its constructor fails here);
- a body from parts is the body of the same YAML written by hand, bit for bit (the oracle is
  the file reader, on text written independently of rbcli.parts);
- a mistake gets the message the YAML gets, located at the call (``parts[2] (cylinder
  'bore')``), never a file:line:col;
- a part spec is a small frozen value.
"""

from __future__ import annotations

import copy
import inspect
import pickle
import textwrap

import numpy as np
import pytest

import rbcli
from rbcli import parts as P
from rbcli.core.shapes import IO_SHAPES, SHAPES
from rbcli.body.partlist import part_keys

CONSTRUCTORS = {n: getattr(P, n) for n in P.__all__ if inspect.isfunction(getattr(P, n))}


def _kwargs(fn) -> set[str]:
    sig = inspect.signature(fn)
    assert all(p.kind is p.KEYWORD_ONLY for p in sig.parameters.values()), fn.__name__
    return {"from" if n == "from_" else n for n in sig.parameters}


def test_one_constructor_per_shape_of_the_registry():
    assert set(CONSTRUCTORS) == {*SHAPES, *IO_SHAPES}


@pytest.mark.parametrize("shape", [*SHAPES, *IO_SHAPES])
def test_each_constructor_takes_the_keys_the_body_file_takes(shape):
    assert _kwargs(CONSTRUCTORS[shape]) == set(part_keys(shape)) - {"shape"}


@pytest.mark.parametrize("shape", [*SHAPES, *IO_SHAPES])
def test_each_constructor_documents_each_of_its_keys(shape):
    fn = CONSTRUCTORS[shape]
    doc = inspect.getdoc(fn)
    section = doc.split("Parameters\n----------\n", 1)[1].split("\n\nReturns", 1)[0]
    documented = set()
    for line in section.splitlines():
        if line and not line.startswith(" "):
            documented |= {n.strip() for n in line.split(":", 1)[0].split(",")}
    assert {"from" if n == "from_" else n for n in documented} == _kwargs(fn)


def test_the_registry_check_would_see_a_new_shape(monkeypatch):
    """The agreement above cannot pass vacuously: a shape added to the registry alone is
    found missing."""
    monkeypatch.setitem(SHAPES, "prism", SHAPES["box"])
    assert set(CONSTRUCTORS) != {*SHAPES, *IO_SHAPES}


# ----------------------------------------------------------------------------- same as YAML

#: (the part in code, the same part as a body file writes it, by hand)
SAME = [
    (P.point(name="w", mass="20 g", at=["350 mm", 0, 0.1]),
     "{name: w, shape: point, mass: 20 g, at: [350 mm, 0, 0.1]}"),
    (P.rod(length=1.5, linear_density=2, axis=[1, 1, 0]),
     "{shape: rod, length: 1.5, linear_density: 2, axis: [1, 1, 0]}"),
    (P.rod(from_=[0, 0, 0], to=[0.3, 0.4, 1.2], mass=3),
     "{shape: rod, from: [0, 0, 0], to: [0.3, 0.4, 1.2], mass: 3}"),
    (P.ring(diameter="600 mm", mass=2, rotate={"axis": [0, 1, 0], "angle": "30 deg"}),
     "{shape: ring, diameter: 600 mm, mass: 2, rotate: {axis: [0, 1, 0], angle: 30 deg}}"),
    (P.disk(radius=0.3, inner_radius=0.1, areal_density=7.5, at=[0, 0, 0.2]),
     "{shape: disk, radius: 0.3, inner_radius: 0.1, areal_density: 7.5, at: [0, 0, 0.2]}"),
    (P.plate(size=[0.3, 0.4], thickness="5 mm", density=2700,
             rotate={"euler": [10, 20, 30], "seq": "ZYX"}),
     "{shape: plate, size: [0.3, 0.4], thickness: 5 mm, density: 2700, "
     "rotate: {euler: [10, 20, 30], seq: ZYX}}"),
    (P.triangle(vertices=[[0, 0, 0], [1, 0, 0], [0, 2, 0]], areal_density=3),
     "{shape: triangle, vertices: [[0, 0, 0], [1, 0, 0], [0, 2, 0]], areal_density: 3}"),
    (P.box(size=[0.1, 0.2, 0.3], mass=2, rotate={"quaternion": [1, 0.1, 0.2, 0.3]}),
     "{shape: box, size: [0.1, 0.2, 0.3], mass: 2, rotate: {quaternion: [1, 0.1, 0.2, 0.3]}}"),
    (P.cylinder(radius="50 mm", length="400 mm", inner_radius="20 mm", density="7850 kg/m^3"),
     "{shape: cylinder, radius: 50 mm, length: 400 mm, inner_radius: 20 mm, density: 7850 kg/m^3}"),
    (P.cylinder(radius=0.05, length=0.4, shell=True, areal_density=12),
     "{shape: cylinder, radius: 0.05, length: 0.4, shell: true, areal_density: 12}"),
    (P.sphere(radius=0.1, inner_radius=0.09, density=1000),
     "{shape: sphere, radius: 0.1, inner_radius: 0.09, density: 1000}"),
    (P.hemisphere(radius=0.1, mass=1, at=[0.1, 0.2, 0.3]),
     "{shape: hemisphere, radius: 0.1, mass: 1, at: [0.1, 0.2, 0.3]}"),
    (P.cone(radius=0.1, height=0.4, mass=3, axis=[0, -1, 0]),
     "{shape: cone, radius: 0.1, height: 0.4, mass: 3, axis: [0, -1, 0]}"),
    (P.ellipsoid(semi_axes=[0.1, 0.2, 0.3], mass=5,
                 rotate={"matrix": [[0, -1, 0], [1, 0, 0], [0, 0, 1]]}),
     "{shape: ellipsoid, semi_axes: [0.1, 0.2, 0.3], mass: 5, "
     "rotate: {matrix: [[0, -1, 0], [1, 0, 0], [0, 0, 1]]}}"),
    (P.torus(major_radius=0.3, minor_radius=0.05, density=900),
     "{shape: torus, major_radius: 0.3, minor_radius: 0.05, density: 900}"),
    (P.given(mass=2, com=[0.01, 0, 0], inertia={"Ixx": 0.01, "Iyy": 0.02, "Izz": 0.025,
                                                 "Ixy": 0.001, "convention": "positive"}),
     "{shape: given, mass: 2, com: [0.01, 0, 0], "
     "inertia: {Ixx: 0.01, Iyy: 0.02, Izz: 0.025, Ixy: 0.001, convention: positive}}"),
    (P.mesh(file="examples/housing.stl", units="mm", density="2700 kg/m^3"),
     "{shape: mesh, file: examples/housing.stl, units: mm, density: 2700 kg/m^3}"),
    (P.include(name="w", file="examples/car_wheel.yaml", at=[0, 0, 1]),
     "{name: w, shape: include, file: examples/car_wheel.yaml, at: [0, 0, 1]}"),
]


def _same_bits(a, b) -> None:
    """Two bodies with the same parts and mass properties, to the last bit."""
    from rbcli.core.inertia import body_mass_props

    ma, mb = body_mass_props(a), body_mass_props(b)
    assert np.float64(ma.mass).tobytes() == np.float64(mb.mass).tobytes()
    assert ma.com.tobytes() == mb.com.tobytes()
    assert ma.inertia_com.tobytes() == mb.inertia_com.tobytes()
    assert [p.name for p in a.parts] == [p.name for p in b.parts]
    for p, q in zip(a.parts, b.parts):
        assert (p.shape, p.mass, p.subtract, p.radius) == (q.shape, q.mass, q.subtract, q.radius)
        assert p.com.tobytes() == q.com.tobytes() and p.inertia_com.tobytes() == q.inertia_com.tobytes()


@pytest.mark.parametrize("units", [None, {"length": "mm", "mass": "g"}], ids=["SI", "mm-g"])
@pytest.mark.parametrize("spec,yaml", SAME, ids=[s.shape + str(i) for i, (s, _) in enumerate(SAME)])
def test_a_body_of_parts_is_the_body_of_the_same_yaml(spec, yaml, units, monkeypatch):
    from conftest import ROOT

    monkeypatch.chdir(ROOT)
    head = "" if units is None else "units: {length: mm, mass: g}\n"
    text = f"name: b\n{head}parts:\n  - {yaml}\n  - {{shape: point, mass: 1, at: [1, 2, 3]}}\n"
    b_yaml = rbcli.load_text(text)
    b_code = rbcli.Body.from_parts([spec, P.point(mass=1, at=[1, 2, 3])], name="b", units=units)
    _same_bits(b_code, b_yaml)
    assert b_code.units == b_yaml.units and b_code.name == "b"
    assert b_code.warnings == () or all("parts[" in w for w in b_code.warnings)


def test_body_keys_are_the_body_files(monkeypatch):
    text = textwrap.dedent("""\
        name: rotor
        description: a disk on a shaft
        units: {length: mm}
        parts:
          - {name: disk, shape: disk, radius: 100, mass: 5, at: [0, 0, 200]}
        reference: [0, 0, 100]
        shaft: {axis: [0, 0, 2], through: [0, 0, 10]}
        pivot: [0, 0, 0]
        rim_radius: 100
        """)
    a = rbcli.load_text(text)
    b = rbcli.Body.from_parts([P.disk(name="disk", radius=100, mass=5, at=[0, 0, 200])],
                              name="rotor", description="a disk on a shaft", units={"length": "mm"},
                              reference=[0, 0, 100], shaft={"axis": [0, 0, 2], "through": [0, 0, 10]},
                              pivot=[0, 0, 0], rim_radius=100)
    _same_bits(a, b)
    for f in ("name", "description", "reference_is_com", "rim_radius"):
        assert getattr(a, f) == getattr(b, f), f
    assert a.reference.tolist() == b.reference.tolist() and a.pivot.tolist() == b.pivot.tolist()
    assert a.shaft.axis.tolist() == b.shaft.axis.tolist() == [0.0, 0.0, 1.0]
    assert a.shaft.through.tolist() == b.shaft.through.tolist() == [0.0, 0.0, 0.01]
    assert rbcli.balance(a).to_json() == rbcli.balance(b).to_json()
    assert rbcli.Body.from_parts([P.point(mass=1)], reference="com").reference_is_com


def test_numpy_values_are_the_numbers_they_hold():
    a = rbcli.Body.from_parts([P.box(size=np.array([0.1, 0.2, 0.3]), mass=np.float32(2.5),
                                     at=np.arange(3, dtype=np.int64))])
    b = rbcli.Body.from_parts([P.box(size=[0.1, 0.2, 0.3], mass=2.5, at=[0, 1, 2])])
    _same_bits(a, b)


# ----------------------------------------------------------------------------- messages

#: (the part in code, its YAML, where from_parts locates the mistake)
BAD = [
    (P.disk(name="web", radius="-150 mm", mass=2), "{name: web, shape: disk, radius: -150 mm, mass: 2}"),
    (P.disk(radius=0.1), "{shape: disk, radius: 0.1}"),
    (P.disk(radius=0.1, density=2), "{shape: disk, radius: 0.1, density: 2}"),
    (P.cylinder(name="bore", radius=0.01, length=0.1, subtract=True, cut_from="nothing"),
     "{name: bore, shape: cylinder, radius: 0.01, length: 0.1, subtract: true, cut_from: nothing}"),
    (P.box(size=[1, 2], mass=1), "{shape: box, size: [1, 2], mass: 1}"),
    (P.box(size=[1, 2, 3], mass=1, axis=[0, 0, 1], rotate={"axis": [0, 0, 1], "angle": 1}),
     "{shape: box, size: [1, 2, 3], mass: 1, axis: [0, 0, 1], rotate: {axis: [0, 0, 1], angle: 1}}"),
    (P.box(size=[1, 2, 3], mass="2 m"), "{shape: box, size: [1, 2, 3], mass: 2 m}"),
    (P.box(size=[1, 2, 3], mass=float("nan")), "{shape: box, size: [1, 2, 3], mass: .nan}"),
    (P.box(size=[1, 2, 3], mass=True), "{shape: box, size: [1, 2, 3], mass: true}"),
    (P.box(size=[1, 2, 3], mass=None, density=None), "{shape: box, size: [1, 2, 3]}"),
    (P.sphere(radius=1, inner_radius=2, mass=1), "{shape: sphere, radius: 1, inner_radius: 2, mass: 1}"),
    (P.torus(major_radius=0.1, minor_radius=0.2, mass=1), "{shape: torus, major_radius: 0.1, minor_radius: 0.2, mass: 1}"),
    (P.rod(from_=[0, 0, 0], to=[0, 0, 0], mass=1), "{shape: rod, from: [0, 0, 0], to: [0, 0, 0], mass: 1}"),
    (P.given(mass=1, inertia=[[1, 0, 0], [0, 1, 0], [0, 0, 3]]),
     "{shape: given, mass: 1, inertia: [[1, 0, 0], [0, 1, 0], [0, 0, 3]]}"),
    (P.mesh(file="examples/missing.stl", density=1), "{shape: mesh, file: examples/missing.stl, density: 1}"),
    (P.include(file="examples/"), "{shape: include, file: examples/}"),
    (P.point(mass=1, rotate={"euler": [1, 2, 3], "seq": "ZZZ"}),
     "{shape: point, mass: 1, rotate: {euler: [1, 2, 3], seq: ZZZ}}"),
]


@pytest.mark.parametrize("spec,yaml", BAD, ids=[f"{s.shape}{i}" for i, (s, _) in enumerate(BAD)])
def test_a_mistake_gets_the_yaml_message_located_at_the_call(spec, yaml, monkeypatch):
    from conftest import ROOT

    monkeypatch.chdir(ROOT)
    good = P.box(name="ok", size=[1, 1, 1], mass=1)
    with pytest.raises(rbcli.InputError) as from_yaml:
        rbcli.load_text(f"parts:\n  - {{name: ok, shape: box, size: [1, 1, 1], mass: 1}}\n  - {yaml}\n")
    with pytest.raises(rbcli.InputError) as from_code:
        rbcli.Body.from_parts([good, spec])
    # a value is quoted as it was written: Python's True and nan, YAML's true and .nan
    expected = from_yaml.value.message.replace("'true'", "'True'").replace(" .nan", " nan")
    assert from_code.value.message == expected
    shown = f" '{spec.name}'" if spec.name else ""
    assert str(from_code.value.where) == f"parts[1] ({spec.shape}{shown})"
    assert str(from_code.value) == f"parts[1] ({spec.shape}{shown}): {expected}"
    assert str(from_yaml.value.where).startswith("<text>:3:")  # the YAML's is file:line:col


def test_body_level_mistakes_are_located_by_the_parameter():
    disk = P.disk(radius=0.1, mass=1)
    with pytest.raises(rbcli.InputError, match=r"^shaft: shaft needs 'axis'$"):
        rbcli.Body.from_parts([disk], shaft={"through": [0, 0, 0]})
    with pytest.raises(rbcli.InputError, match=r"^shaft\.axis: shaft axis must be a non-zero vector$"):
        rbcli.Body.from_parts([disk], shaft={"axis": [0, 0, 0]})
    with pytest.raises(rbcli.InputError, match=r"^units\.length: units: length is 'kg', which is a mass"):
        rbcli.Body.from_parts([disk], units={"length": "kg"})
    with pytest.raises(rbcli.InputError, match=r"^rim_radius: rim_radius must be positive"):
        rbcli.Body.from_parts([disk], rim_radius=-1)
    with pytest.raises(rbcli.InputError, match=r"^pivot: pivot must be a point"):
        rbcli.Body.from_parts([disk], pivot="com")
    with pytest.raises(rbcli.InputError, match=r"^parts: parts is empty"):
        rbcli.Body.from_parts([])
    with pytest.raises(rbcli.InputError, match=r"two parts are named 'a'"):
        rbcli.Body.from_parts([P.point(name="a", mass=1), P.point(name="a", mass=1)])


@pytest.mark.parametrize("call,param", [
    (lambda: rbcli.Body.from_parts(P.point(mass=1)), "parts"),
    (lambda: rbcli.Body.from_parts("box"), "parts"),
    (lambda: rbcli.Body.from_parts([5]), "parts[0]"),
    (lambda: rbcli.Body.from_parts([None]), "parts[0]"),
    (lambda: rbcli.Body.from_parts([P.point(mass=1)], name=5), "name"),
    (lambda: rbcli.Body.from_parts([P.point(mass=1)], base_dir=5), "base_dir"),
    (lambda: rbcli.Body.from_parts([P.point(mass=1)], shaft={"axis": {1, 2, 3}}), "shaft.axis"),
    (lambda: P.box(size=[1, 2, 3j]), "size[2]"),
    (lambda: P.box(size=[1, 2, 3], mass=object()), "mass"),
    (lambda: P.box(name=b"x"), "name"),
    (lambda: P.box(rotate={1: 2}), "rotate"),
], ids=lambda x: x if isinstance(x, str) else "")
def test_a_wrong_type_is_a_type_error_naming_where_it_is(call, param):
    with pytest.raises(TypeError) as exc:
        call()
    assert str(exc.value).startswith(f"{param}: "), str(exc.value)


def test_the_part_budget_is_checked_before_the_parts_are_read(monkeypatch):
    monkeypatch.setenv("RBCLI_MAX_PARTS", "10")
    p = P.point(mass=1)
    with pytest.raises(rbcli.InputError, match="more than 10 parts"):
        rbcli.Body.from_parts([p] * 11)
    assert len(rbcli.Body.from_parts([p.replace(name=f"p{i}") for i in range(10)]).parts) == 10


# ----------------------------------------------------------------------------- a spec is a value


def test_a_part_spec_is_a_small_frozen_value():
    a = P.disk(name="d", radius="100 mm", mass=2, at=[0, 0, 0.1])
    assert a == P.disk(name="d", radius="100 mm", mass=2, at=(0, 0, 0.1))
    assert hash(a) == hash(P.disk(name="d", radius="100 mm", mass=2, at=(0, 0, 0.1)))
    assert a != P.disk(name="d", radius="100 mm", mass=3, at=[0, 0, 0.1])
    assert dict(a) == {"name": "d", "shape": "disk", "radius": "100 mm", "mass": 2, "at": (0, 0, 0.1)}
    assert a.shape == "disk" and a.name == "d" and P.disk(radius=1).name is None
    with pytest.raises(AttributeError):
        a.shape = "box"  # type: ignore[misc]
    with pytest.raises(TypeError):
        a["mass"] = 3  # type: ignore[index]
    assert pickle.loads(pickle.dumps(a)) == a and copy.deepcopy(a) == a
    b = a.replace(mass=None, density=1000)
    assert "mass" not in b and b["density"] == 1000 and a["mass"] == 2
    assert repr(a) == "rbcli.parts.disk(name='d', radius='100 mm', mass=2, at=[0, 0, 0.1])"
    assert repr(P.rod(from_=[0, 0, 0], to=[1, 0, 0])) == "rbcli.parts.rod(from_=[0, 0, 0], to=[1, 0, 0])"


def test_a_spec_does_not_see_later_changes_to_what_it_was_made_of():
    at = [0, 0, 0.1]
    arr = np.array([0.1, 0.2, 0.3])
    a = P.box(size=arr, mass=1, at=at)
    at[2] = 5
    arr[0] = 7
    assert a["at"] == (0, 0, 0.1) and a["size"] == (0.1, 0.2, 0.3)
    assert type(a["size"][0]) is float


def test_a_numpy_scalar_in_a_spec_is_a_python_number():
    a = P.box(size=[np.float64(1), np.int32(2), np.float32(0.5)], mass=np.int64(3), subtract=np.bool_(False))
    assert [type(x) for x in a["size"]] == [float, int, float]
    assert type(a["mass"]) is int and a["subtract"] is False


def test_rbcli_parts_is_lazily_importable():
    import subprocess
    import sys

    from conftest import ROOT

    code = ("import rbcli, sys; assert 'rbcli.parts' not in sys.modules; p = rbcli.parts.point(mass=1); "
            "print(sorted(m for m in ('numpy', 'scipy', 'matplotlib') if m in sys.modules))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    assert r.stdout.strip() == "[]"  # a part spec needs no numpy
    assert "parts" in rbcli.__all__ and "load_data" in rbcli.__all__
