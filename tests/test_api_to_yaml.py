"""``Body.to_yaml`` (issue 22 item 1): a body file that reads back to the same mass, centre
of mass and inertia tensor, bit for bit — every example (its meshes and includes by path,
from another folder), generated bodies of ``rbcli.parts`` (hypothesis: units, holes,
placements, quantity strings, given parts, meshes, includes), bodies changed by
``Body.replace``/``Body.moved`` (checked against the same YAML written by hand), and
``BalanceResult.balanced_body()`` (what ``rbcli balance --apply`` writes)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import rbcli
from conftest import EXAMPLES, ROOT, sample
from rbcli import parts as P
from rbcli.io import yamlsafe as ys
from rbcli.body.document import dump


def _same_bits(a, b) -> None:
    """Two bodies with the same parts and mass properties, to the last bit, and the same
    defaults."""
    from rbcli.core.inertia import body_mass_props

    ma, mb = body_mass_props(a), body_mass_props(b)
    assert np.float64(ma.mass).tobytes() == np.float64(mb.mass).tobytes()
    assert ma.com.tobytes() == mb.com.tobytes()
    assert ma.inertia_com.tobytes() == mb.inertia_com.tobytes()
    assert [(p.name, p.shape, p.mass, p.subtract, p.radius) for p in a.parts] == \
        [(p.name, p.shape, p.mass, p.subtract, p.radius) for p in b.parts]
    for p, q in zip(a.parts, b.parts):
        assert p.com.tobytes() == q.com.tobytes() and p.inertia_com.tobytes() == q.inertia_com.tobytes()
    assert (a.name, a.description, dict(a.units), a.reference_is_com, a.rim_radius) == \
        (b.name, b.description, dict(b.units), b.reference_is_com, b.rim_radius)
    for f in ("reference", "pivot"):
        x, y = getattr(a, f), getattr(b, f)
        assert (x is None and y is None) or x.tobytes() == y.tobytes(), f
    assert (a.shaft is None) == (b.shaft is None)
    if a.shaft is not None:
        assert a.shaft.axis.tobytes() == b.shaft.axis.tobytes()
        assert a.shaft.through.tobytes() == b.shaft.through.tobytes()


EXAMPLE_FILES = sorted(EXAMPLES.glob("*.yaml"))


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.name)
def test_every_example_reads_back_bit_for_bit_from_another_folder(path, tmp_path):
    body = rbcli.load(path)
    out = tmp_path / "elsewhere" / "copy.yaml"
    out.parent.mkdir()
    text = body.to_yaml(base_dir=out.parent)
    out.write_text(text, encoding="utf-8")
    again = rbcli.load(out)
    _same_bits(body, again)
    assert again.inputs[1:] == body.inputs[1:]  # the same meshes and includes, by path
    assert again.to_yaml(base_dir=out.parent) == text  # written again: the same text


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.name)
def test_every_example_reads_back_from_the_current_folder(path, monkeypatch):
    monkeypatch.chdir(ROOT)
    body = rbcli.load(path.relative_to(ROOT))
    _same_bits(body, rbcli.load_text(body.to_yaml()))


def test_what_is_kept_and_what_is_not():
    text = ("# a comment\n{shape: box, size: [1e2, 200, 300], mass: '2 kg',   "
            "at: [0x10, 0, 0]}  # another\n")
    b = rbcli.load_text(text, units={"length": "mm"}, name="brick")
    assert b.to_yaml() == ("name: brick\nunits: {length: mm}\nparts:\n"
                           "- shape: box\n  size: [100.0, 200, 300]\n  mass: 2 kg\n  at: [16, 0, 0]\n")


def test_a_body_without_a_document_is_not_written():
    b = rbcli.load(EXAMPLES / "cube.yaml")
    with pytest.raises(rbcli.InputError, match="this body has no document"):
        dataclasses.replace(b, name="other").to_yaml()
    hand = rbcli.Body(name="x", source="<code>", text="", parts=b.parts)
    with pytest.raises(rbcli.InputError, match="this body has no document"):
        hand.to_yaml()
    with pytest.raises(rbcli.InputError, match="this body has no document"):
        hand.moved(0, at=[0, 0, 0])


def test_to_yaml_takes_a_folder():
    b = rbcli.load(EXAMPLES / "cube.yaml")
    with pytest.raises(TypeError, match=r"^base_dir: expected a folder"):
        b.to_yaml(base_dir=5)


def test_the_text_of_a_body_from_data_is_its_document():
    b = rbcli.Body.from_parts([P.disk(name="d", radius="10 cm", mass=1, at=[0, 0, 0.1])],
                              units={"mass": "g"}, shaft={"axis": [0, 0, 1]})
    assert b.source == "<data>"
    _same_bits(b, rbcli.load_text(b.text))
    assert b.text == b.to_yaml()


def test_includes_are_kept_by_path_and_meshes_read_again(tmp_path, monkeypatch):
    monkeypatch.chdir(ROOT)
    body = rbcli.Body.from_parts([
        P.include(name="front", file="examples/car_wheel.yaml", at=[0, 0, 1.2], axis=[1, 0, 0]),
        P.include(name="rear", file="examples/car_wheel.yaml"),
        P.mesh(name="housing", file="examples/housing.stl", units="mm", density=2700,
               at=[0.1, 0, 0], rotate={"euler": [10, 20, 30], "seq": "ZXZ"}),
        P.given(name="box", mass=2, com=[0, 0, 0.1], inertia=[[0.01, 0, 0], [0, 0.02, 0], [0, 0, 0.025]]),
    ])
    sub = tmp_path / "a" / "b"
    sub.mkdir(parents=True)
    text = body.to_yaml(base_dir=sub)
    (sub / "copy.yaml").write_text(text, encoding="utf-8")
    again = rbcli.load(sub / "copy.yaml")
    _same_bits(body, again)
    assert again.parts[0].name.startswith("front/")
    # kept as references to their files, relative to the new folder
    files = [p["file"] for p in ys.to_python(ys.load(text, "t"))["parts"] if "file" in p]
    assert [(sub / f).resolve() for f in files] == [
        (ROOT / "examples" / n).resolve() for n in ("car_wheel.yaml", "car_wheel.yaml", "housing.stl")]
    assert not any(f.startswith("/") for f in files)


def test_the_callers_units_and_the_files_name_are_written():
    b = rbcli.load_text("{shape: box, size: [100, 200, 300], mass: 2}", units={"length": "mm"})
    again = rbcli.load_text(b.to_yaml())
    _same_bits(b, again)
    c = rbcli.load(EXAMPLES / "cube.yaml")
    assert rbcli.load_text(c.to_yaml()).name == c.name


# ----------------------------------------------------------------------------- generated bodies

UNITS = [None, {"length": "mm"}, {"length": "in", "mass": "g"}, {"length": "cm", "mass": "lb", "angle": "rad"}]
_SIZE = st.floats(0.01, 10.0, allow_nan=False)


def _q(x: float, kind: str, draw) -> object:
    """``x`` as the file may write it: a bare number (the body's units) or a string with a unit."""
    form = draw(st.sampled_from(["bare", "bare", "unit"]))
    if form == "bare":
        return x
    unit = {"length": draw(st.sampled_from(["m", "mm", "in", "ft"])), "mass": draw(st.sampled_from(["kg", "g", "lb"])),
            "density": "kg/m^3", "areal_density": "kg/m^2", "linear_density": "kg/m"}[kind]
    return f"{x!r} {unit}"


@st.composite
def _orientation(draw) -> dict:
    kind = draw(st.sampled_from(["none", "axis", "axis-angle", "euler", "quaternion"]))
    vec = st.lists(st.floats(-1, 1), min_size=3, max_size=3).filter(lambda v: max(map(abs, v)) > 1e-3)
    if kind == "axis":
        return {"axis": draw(vec)}
    if kind == "axis-angle":
        return {"rotate": {"axis": draw(vec), "angle": draw(st.sampled_from([30, "30 deg", 0.7, "1 rad"]))}}
    if kind == "euler":
        return {"rotate": {"euler": draw(st.lists(st.floats(-180, 180), min_size=3, max_size=3)),
                           "seq": draw(st.sampled_from(["ZYX", "ZXZ", "XYZ"]))}}
    if kind == "quaternion":
        return {"rotate": {"quaternion": draw(st.lists(st.floats(-1, 1), min_size=4, max_size=4).filter(
            lambda q: max(map(abs, q)) > 1e-3))}}
    return {}


def _mass(draw, measure: str) -> dict:
    if draw(st.booleans()) or measure == "point":
        return {"mass": _q(draw(_SIZE), "mass", draw)}
    key = {"volume": "density", "area": "areal_density", "length": "linear_density"}[measure]
    return {key: _q(draw(st.floats(1.0, 8000.0)), key, draw)}


@st.composite
def _part(draw, i: int) -> list:
    shape = draw(st.sampled_from(["point", "rod", "ring", "disk", "plate", "box", "cylinder", "sphere",
                                  "hemisphere", "cone", "ellipsoid", "torus", "triangle", "given",
                                  "hole"]))
    name = f"p{i}"
    at = {"at": [_q(draw(st.floats(-5, 5)), "length", draw) for _ in range(3)]} if draw(st.booleans()) else {}
    turn = draw(_orientation())
    size = lambda: _q(draw(_SIZE), "length", draw)  # noqa: E731
    if shape == "given":
        a, b, c = (draw(_SIZE) for _ in range(3))
        m = draw(_SIZE)
        J = [[m * (b * b + c * c) / 5, 0, 0], [0, m * (a * a + c * c) / 5, 0], [0, 0, m * (a * a + b * b) / 5]]
        return [P.given(name=name, mass=m, inertia=J, com=[0.1, 0, 0], **at, **turn)]
    if shape == "hole":  # a box with a concentric box cut from it at its density
        a, b, c = (draw(_SIZE) for _ in range(3))
        rho = draw(st.floats(1.0, 8000.0))
        f = draw(st.floats(0.1, 0.9))
        outer = P.box(name=name, size=[a, b, c], density=rho, **at, **turn)
        hole = P.box(name=name + "h", size=[a * f, b * f, c * f], subtract=True, cut_from=name, **at, **turn)
        return [outer, hole]
    if shape == "point":
        return [P.point(name=name, **_mass(draw, "point"), **at)]
    if shape == "rod":
        return [P.rod(name=name, length=size(), **_mass(draw, "length"), **at, **turn)]
    if shape == "ring":
        return [P.ring(name=name, radius=size(), **_mass(draw, "length"), **at, **turn)]
    if shape == "disk":
        r = draw(_SIZE)
        inner = {"inner_radius": r * draw(st.floats(0.0, 0.9))} if draw(st.booleans()) else {}
        return [P.disk(name=name, radius=r, **inner, **_mass(draw, "area"), **at, **turn)]
    if shape == "plate":
        return [P.plate(name=name, size=[size(), size()], **_mass(draw, "area"), **at, **turn)]
    if shape == "box":
        return [P.box(name=name, size=[size(), size(), size()], **_mass(draw, "volume"), **at, **turn)]
    if shape == "cylinder":
        r = draw(_SIZE)
        inner = {"inner_radius": r * draw(st.floats(0.0, 0.9))} if draw(st.booleans()) else {}
        return [P.cylinder(name=name, radius=r, length=size(), **inner, **_mass(draw, "volume"), **at, **turn)]
    if shape == "sphere":
        return [P.sphere(name=name, radius=size(), **_mass(draw, "volume"), **at, **turn)]
    if shape == "hemisphere":
        return [P.hemisphere(name=name, diameter=size(), **_mass(draw, "volume"), **at, **turn)]
    if shape == "cone":
        return [P.cone(name=name, radius=size(), height=size(), **_mass(draw, "volume"), **at, **turn)]
    if shape == "ellipsoid":
        return [P.ellipsoid(name=name, semi_axes=[size(), size(), size()], **_mass(draw, "volume"), **at, **turn)]
    if shape == "torus":
        R = draw(_SIZE)
        return [P.torus(name=name, major_radius=R, minor_radius=R * draw(st.floats(0.05, 0.95)),
                        **_mass(draw, "volume"), **at, **turn)]
    pts = draw(st.lists(st.lists(st.floats(-1, 1), min_size=3, max_size=3), min_size=3, max_size=3))
    return [P.triangle(name=name, vertices=pts, **_mass(draw, "area"), **at, **turn)]


@st.composite
def _bodies(draw):
    n = draw(st.integers(1, 6))
    parts = [p for i in range(n) for p in draw(_part(i))]
    if draw(st.integers(0, 5)) == 0:
        parts.append(P.mesh(name="mesh", file="examples/housing.stl", units="mm", mass=1.4, **draw(_orientation())))
    if draw(st.integers(0, 5)) == 0:
        parts.append(P.include(name="inc", file="examples/top.yaml", **draw(_orientation())))
    extra = {}
    if draw(st.booleans()):
        extra["shaft"] = {"axis": [0, draw(st.floats(-1, 1)), 1], "through": [0, 0, draw(st.floats(-1, 1))]}
    if draw(st.booleans()):
        extra["reference"] = draw(st.sampled_from(["com", "origin", [0.1, 0.2, 0.3]]))
    return parts, draw(st.sampled_from(UNITS)), extra


@pytest.mark.sampled
@settings(max_examples=sample(40, 400), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_bodies())
def test_generated_bodies_read_back_bit_for_bit(case):
    parts, units, extra = case
    import os

    old = os.getcwd()
    os.chdir(ROOT)
    try:
        try:
            body = rbcli.Body.from_parts(parts, name="gen", units=units, **extra)
        except rbcli.InputError as exc:  # a degenerate triangle: refused, rightly
            assert "triangle" in str(exc) and "area" in str(exc), str(exc)
            assume(False)
        text = body.to_yaml()
        again = rbcli.load_text(text)
        _same_bits(body, again)
        # and the body is the body of its data
        _same_bits(body, rbcli.load_data(ys.to_python(ys.load(text, "t"))))
    finally:
        os.chdir(old)


_SCALARS = (st.none() | st.booleans() | st.integers(-(10**300) + 1, 10**300 - 1)
            | st.floats(allow_nan=False) | st.text(st.characters(exclude_categories=["Cs"])))
_DATA = st.recursive(_SCALARS, lambda ch: st.lists(ch, max_size=4)
                     | st.dictionaries(st.text(st.characters(exclude_categories=["Cs"]), max_size=8), ch, max_size=4),
                     max_leaves=20)


@pytest.mark.sampled
@settings(max_examples=sample(200, 3000), deadline=None)
@given(st.dictionaries(st.text(st.characters(exclude_categories=["Cs"]), max_size=8), _DATA, max_size=5))
def test_the_yaml_written_reads_back_to_the_same_data(data):
    """What :func:`dump` writes, rbcli's YAML 1.2 reader reads back to equal data (same
    types: a string that looks like a number stays a string; floats to the bit)."""
    text = dump(data)
    back = ys.to_python(ys.load(text, "t")) if data else {}
    assert _typed(back) == _typed(data)


def _typed(v):
    if isinstance(v, dict):
        return {k: _typed(x) for k, x in v.items()}
    if isinstance(v, list):
        return [_typed(x) for x in v]
    if isinstance(v, float):
        return ("float", np.float64(v).tobytes())
    return (type(v).__name__, v)


# ----------------------------------------------------------------------------- replace, moved


def _rotor(**kw):
    return rbcli.Body.from_parts([
        P.cylinder(name="shaft", radius="10 mm", length="400 mm", density="7850 kg/m^3", at=[0, 0, "200 mm"]),
        P.disk(name="disk", radius="100 mm", mass=5, at=[0, 0, "200 mm"]),
        P.disk(radius="80 mm", mass=3, at=[0, 0, "350 mm"], axis=[0, 0, 1]),
    ], name="rotor", shaft={"axis": [0, 0, 1]}, **kw)


ROTOR_YAML = """\
name: rotor
shaft: {{axis: [0, 0, 1]}}
parts:
  - {{name: shaft, shape: cylinder, radius: 10 mm, length: 400 mm, density: 7850 kg/m^3, at: [0, 0, 200 mm]}}
  - {{name: disk, shape: disk, radius: {r}, mass: {m}, at: {at}}}
  - {{shape: disk, radius: 80 mm, mass: 3, at: [0, 0, 350 mm], {turn}}}
"""


def test_replace_and_moved_are_the_yaml_with_the_change():
    rotor = _rotor()
    base = dict(r="100 mm", m=5, at="[0, 0, 200 mm]", turn="axis: [0, 0, 1]")
    cases = [
        (rotor.moved("disk", at=["1 mm", 0, "200 mm"]), {**base, "at": "[1 mm, 0, 200 mm]"}),
        (rotor.replace("disk", mass=6), {**base, "m": 6}),
        (rotor.replace(1, P.disk(name="disk", radius="120 mm", mass=5, at=[0, 0, "200 mm"])), {**base, "r": "120 mm"}),
        (rotor.moved("disk3", rotate={"axis": [1, 0, 0], "angle": "1 deg"}),
         {**base, "turn": "rotate: {axis: [1, 0, 0], angle: 1 deg}"}),
        (rotor.moved(-1, axis=[0, 0.01, 1]), {**base, "turn": "axis: [0, 0.01, 1]"}),
    ]
    for body, fields in cases:
        _same_bits(body, rbcli.load_text(ROTOR_YAML.format(**fields)))
    _same_bits(rotor, rbcli.load_text(ROTOR_YAML.format(**base)))  # the rotor itself: unchanged


def test_a_sweep_over_a_disks_offset_is_the_static_unbalance_of_each():
    rotor = _rotor()
    for e in (0.0, 0.5, 2.0):
        b = rotor.moved("disk", at=[f"{e} mm", 0, "200 mm"])
        # U = m e: 5 kg on the disk, to the round-off of e in mm (~1e-16 relative)
        assert abs(rbcli.balance(b).static_unbalance) == pytest.approx(5 * e * 1e-3, rel=1e-12, abs=1e-18)


def test_replace_and_moved_refuse_what_is_not_there():
    rotor = _rotor()
    with pytest.raises(rbcli.InputError, match=r"which: the body has no part named 'disc'; did you mean 'disk'\?"):
        rotor.moved("disc", at=[0, 0, 0])
    with pytest.raises(rbcli.InputError, match=r"which: the body has 3 parts; no part 3"):
        rotor.replace(3, mass=1)
    with pytest.raises(TypeError, match=r"^which: expected a part's name or its index"):
        rotor.replace(1.0, mass=1)
    with pytest.raises(TypeError, match=r"^part: expected a part"):
        rotor.replace("disk", 5)
    with pytest.raises(rbcli.InputError, match="give either 'axis' or 'rotate', not both"):
        rotor.moved("disk", axis=[1, 0, 0], rotate={"axis": [1, 0, 0], "angle": 1})
    with pytest.raises(rbcli.InputError, match=r"^parts\[1\]\.radius: part 'disk': radius must be greater than 0"):
        rotor.replace("disk", radius=-1)
    with pytest.raises(rbcli.InputError, match=r"'from'/'to'"):
        rbcli.Body.from_parts([P.rod(name="r", from_=[0, 0, 0], to=[1, 0, 0], mass=1)]).moved("r", at=[0, 0, 1])


def test_a_file_body_changed_keeps_its_folder_for_its_meshes(monkeypatch, tmp_path):
    monkeypatch.chdir(tmp_path)  # the housing's mesh is relative to examples/, not here
    housing = rbcli.load(EXAMPLES / "housing.yaml")
    moved = housing.moved("boss", at=["60 mm", "1 mm", "30 mm"])
    assert moved.parts[2].com.tolist()[1] == pytest.approx(0.001, rel=1e-15)
    _same_bits(moved, rbcli.load_text(moved.to_yaml()))


# ----------------------------------------------------------------------------- balanced_body


def test_balanced_body_is_what_apply_writes(cli, tmp_path):
    wheel = EXAMPLES / "car_wheel.yaml"
    out = tmp_path / "w.yaml"
    r = cli("balance", str(wheel), "--planes=-100,100mm", "--mass-step", "5 g", "--apply", str(out))
    assert r.code == 0, r.err
    res = rbcli.balance(rbcli.load(wheel), planes="-100,100mm", mass_step="5 g")
    body = res.balanced_body()
    text = out.read_text(encoding="utf-8")
    assert text.split("\n", 4)[4] == body.to_yaml(base_dir=tmp_path)  # after the 4-line header
    _same_bits(body, rbcli.load(out))
    assert [p.name for p in body.parts[-2:]] == ["balance A", "balance B"]
    assert [p.mass for p in body.parts[-2:]] == [a.mass for a in res.added]  # 5 g steps: exact in g


def test_the_balanced_body_balances_to_the_predicted_residual():
    rotor = rbcli.load(EXAMPLES / "two_disk_rotor.yaml")
    res = rbcli.balance(rotor, planes="0,400 mm", radius="100 mm", positions=6, mass_step="0.5 g")
    after = rbcli.balance(res.balanced_body(), planes="0,400 mm", radius="100 mm")
    predicted = res.corrected_unbalance
    # the masses are written to 15 significant figures: the residual agrees to that
    # (relative to the unbalance corrected, ~1e-15 of U as given)
    scale = abs(res.unbalance.static) + abs(res.unbalance.couple)
    assert abs(after.unbalance.static - predicted.static) < 1e-13 * scale
    assert abs(after.unbalance.couple - predicted.couple) < 1e-13 * scale
    assert [p.name for p in res.balanced_body().parts if p.name.startswith("balance")] == \
        [f"balance {a.plane} (position {a.position})" for a in res.added]


def test_balanced_body_needs_the_planes():
    res = rbcli.balance(rbcli.load(EXAMPLES / "two_disk_rotor.yaml"))
    with pytest.raises(rbcli.ParamError) as exc:
        res.balanced_body()
    assert exc.value.param == "planes" and "--" not in str(exc.value)


def test_balanced_body_names_do_not_clash():
    body = rbcli.Body.from_parts([P.disk(name="balance A", radius=0.1, mass=1, at=[0.001, 0, 0])],
                                 shaft={"axis": [0, 0, 1]})
    fitted = rbcli.balance(body, planes="-0.1,0.1", radius=0.1).balanced_body()
    assert [p.name for p in fitted.parts] == ["balance A", "balance A (2)", "balance B"]
    assert math.isclose(abs(rbcli.balance(fitted).static_unbalance), 0.0, abs_tol=1e-17)


def test_apply_writes_the_name_a_file_left_to_its_stem(cli, tmp_path):
    """A change of ``--apply`` (named in the commit): a file without ``name:`` is named by its
    stem; the balanced file keeps that name (read back as ``out``, it would have been ``out``)."""
    body = tmp_path / "wheel.yaml"
    body.write_text("parts:\n  - {shape: disk, radius: 0.2, mass: 5, at: [0.001, 0, 0]}\n", encoding="utf-8")
    out = tmp_path / "out.yaml"
    r = cli("balance", str(body), "--planes=-0.1,0.1", "--radius", "0.2", "--apply", str(out))
    assert r.code == 0, r.err
    assert rbcli.load(out).name == "wheel"
    assert "\nname: wheel\nparts:\n" in out.read_text(encoding="utf-8")
