"""``rbcli.load_data`` (a mapping already parsed) and the doors of ``rbcli.load`` and
``rbcli.load_text`` (issues 22 and 27): the checks and messages of a body file, located by
key path; hostile data (cycles, huge integers, keys that are not texts, numpy scalars,
deep nesting) never crashes — a wrong type is a ``TypeError`` naming where it is, a bad
value an ``rbcli.InputError``."""

from __future__ import annotations

import json
import threading
from collections import OrderedDict
from fractions import Fraction
from types import MappingProxyType, SimpleNamespace

import numpy as np
import pytest
import yaml

import rbcli
from conftest import EXAMPLES, ROOT


def _same(a, b) -> None:
    from rbcli.core.inertia import body_mass_props

    ma, mb = body_mass_props(a), body_mass_props(b)
    assert (ma.mass, ma.com.tobytes(), ma.inertia_com.tobytes()) == (mb.mass, mb.com.tobytes(), mb.inertia_com.tobytes())


EXAMPLE_FILES = sorted(EXAMPLES.glob("*.yaml"))


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.name)
def test_every_example_as_data_is_the_example(path):
    """The data of each example (what its YAML means, as plain Python data) is the body the
    file is, bit for bit, with the same warnings."""
    from rbcli.io import yamlsafe as ys

    data = ys.to_python(ys.load(path.read_text(encoding="utf-8"), path.name))
    a = rbcli.load(path)
    b = rbcli.load_data(data, name=path.stem, base_dir=path.parent)
    _same(a, b)
    assert b.name == a.name and b.units == a.units and b.inputs == a.inputs[1:]
    assert [w.split(": ", 1)[1] for w in b.warnings] == [w.split(": ", 1)[1] for w in a.warnings]


def test_json_data_reads_as_the_yaml_does():
    text = (EXAMPLES / "two_disk_rotor.yaml").read_text(encoding="utf-8")
    data = json.loads(json.dumps(yaml.safe_load(text)))
    _same(rbcli.load_data(data), rbcli.load_text(text))


def test_a_problem_is_located_by_its_key_path():
    def err(data, **kw):
        with pytest.raises(rbcli.InputError) as exc:
            rbcli.load_data(data, **kw)
        return str(exc.value)

    part = {"name": "rim", "shape": "ring", "radius": 0.3, "mass": 2}
    assert err({"parts": [part, {**part, "name": "hub", "radius": -1}]}).startswith(
        "parts[1].radius: part 'hub': radius must be greater than 0")
    assert err({"parts": [part], "shaft": {"axis": [0, 0, "x"]}}).startswith("shaft.axis[2]: ")
    assert err({"parts": [{**part, "rotate": {"axis": [0, 0, 1], "angel": 3}}]}).startswith(
        "parts[0].rotate.angel: unknown key 'angel' in rotate; did you mean 'angle'?")
    assert err({"parts": [{**part, "bad key": 1}]}).startswith("parts[0]['bad key']: unknown key")
    assert err({"part": []}).startswith("mapping: a body file needs 'parts:'")
    assert err({"parts": "ring"}).startswith("parts: parts must be a list of parts")
    assert err({"shape": "ring", "radius": 0.3}).startswith("mapping: part 'ring1' needs its mass")
    assert err({"parts": [part], "units": {"length": "kg"}}) == (
        "units.length: units: length is 'kg', which is a mass, not a length (e.g. m, mm, in)")


def test_the_messages_are_the_yaml_messages():
    text = "parts:\n  - {shape: box, size: [1, 2], mass: 1}\n"
    with pytest.raises(rbcli.InputError) as a:
        rbcli.load_text(text)
    with pytest.raises(rbcli.InputError) as b:
        rbcli.load_data(yaml.safe_load(text))
    assert a.value.message == b.value.message and str(b.value.where) == "parts[0].size"


# ----------------------------------------------------------------------------- hostile data


def _cyclic_list():
    x: list = []
    x.append(x)
    return {"parts": x}


def _cyclic_dict():
    d: dict = {"shape": "point", "mass": 1}
    d["at"] = d
    return {"parts": [d]}


def _deep():
    v: object = 0
    for _ in range(200):
        v = [v]
    return {"parts": [{"shape": "point", "mass": 1, "at": v}]}


def _very_deep():
    v: object = 0
    for _ in range(100_000):  # deeper than Python's recursion limit
        v = [v]
    return {"parts": [{"shape": "point", "mass": 1, "at": v}]}


INPUT_ERRORS = {
    "cyclic list": (_cyclic_list, "parts[0]: this list contains itself (a cycle)"),
    "cyclic mapping": (_cyclic_dict, "parts[0].at: this mapping contains itself (a cycle)"),
    "deep": (_deep, "nesting is too deep: more than 64 levels"),
    "very deep": (_very_deep, "nesting is too deep: more than 64 levels"),
    "huge int": (lambda: {"parts": [{"shape": "point", "mass": 10**400}]},
                 "parts[0].mass: number too long: more than 300 digits"),
    "huge int in a list": (lambda: {"parts": [{"shape": "point", "mass": 1, "at": [0, -10**5000, 0]}]},
                           "parts[0].at[1]: number too long"),
    "big int": (lambda: {"parts": [{"shape": "point", "mass": 10**299}]},
                "parts[0].mass: part 'point1': mass is too large"),
    "inf": (lambda: {"parts": [{"shape": "point", "mass": float("inf")}]},
            "parts[0].mass: part 'point1': mass must be finite, not inf"),
    "numpy nan": (lambda: {"parts": [{"shape": "point", "mass": np.float64("nan")}]},
                  "parts[0].mass: part 'point1': mass must be finite, not nan"),
    "lone surrogate": (lambda: {"parts": [{"shape": "point", "mass": 1, "name": "a\ud800"}]},
                       "parts[0].name: invalid character U+D800 (a lone surrogate)"),
    "bool for a number": (lambda: {"parts": [{"shape": "point", "mass": np.bool_(True)}]},
                          "parts[0].mass: part 'point1': mass must be a number or a quantity like '30 cm', not 'True'"),
    "none": (lambda: {"parts": [None]}, "parts[0]: part 1 must be a mapping (key: value), not nothing (null)"),
    "version": (lambda: {"rbcli": True, "parts": []}, "rbcli: this rbcli reads body format version 1, not True"),
}


@pytest.mark.parametrize("name", INPUT_ERRORS)
def test_hostile_values_are_input_errors(name):
    make, start = INPUT_ERRORS[name]
    with pytest.raises(rbcli.InputError) as exc:
        rbcli.load_data(make())
    assert str(exc.value).startswith(start) or (start.startswith("nesting") and start in str(exc.value)), str(exc.value)


TYPE_ERRORS = {
    "complex": ({"parts": [{"shape": "point", "mass": 1j}]}, "parts[0].mass: complex is not a value"),
    "numpy complex": ({"parts": [{"shape": "point", "mass": np.complex128(1)}]}, "parts[0].mass: complex128"),
    "set": ({"parts": [{"shape": "point", "mass": 1, "at": {1, 2, 3}}]}, "parts[0].at: set is not a value"),
    "object": ({"parts": [{"shape": "point", "mass": object()}]}, "parts[0].mass: object is not"),
    "bytes": ({"parts": [{"shape": "point", "mass": 1, "name": b"x"}]}, "parts[0].name: bytes is not"),
    "int key": ({"parts": [{1: 2}]}, "parts[0]: keys must be texts, not int (1)"),
    "tuple key": ({("a",): 2}, "mapping: keys must be texts, not tuple"),
    "none key": ({None: 2}, "mapping: keys must be texts, not NoneType"),
    "string array": ({"parts": [{"shape": "point", "mass": 1, "at": np.array(["a", "b", "c"])}]},
                     "parts[0].at: an array of <U1"),
    "namespace": ({"parts": [SimpleNamespace(shape="point")]}, "parts[0]: SimpleNamespace is not"),
}


@pytest.mark.parametrize("name", TYPE_ERRORS)
def test_a_value_no_body_file_holds_is_a_type_error_at_its_key_path(name):
    data, start = TYPE_ERRORS[name]
    with pytest.raises(TypeError) as exc:
        rbcli.load_data(data)
    assert str(exc.value).startswith(start), str(exc.value)


@pytest.mark.parametrize("arg", [None, 5, "body.yaml", ["parts"], SimpleNamespace(parts=[])])
def test_load_data_takes_a_mapping(arg):
    with pytest.raises(TypeError, match=r"^mapping: expected a mapping"):
        rbcli.load_data(arg)


def test_numpy_and_other_numbers_are_their_values():
    plain = {"units": {"length": "mm"}, "parts": [
        {"shape": "box", "size": [100, 200, 300], "mass": 2.5, "at": [1, 2, 3], "subtract": False},
        {"shape": "point", "mass": 0.5}]}
    odd = OrderedDict({"units": MappingProxyType({"length": np.str_("mm")}), "parts": (
        {"shape": "box", "size": np.array([100, 200, 300]), "mass": np.float32(2.5),
         "at": [np.int8(1), np.uint64(2), Fraction(3)], "subtract": np.bool_(False)},
        {"shape": "point", "mass": Fraction(1, 2)})})
    _same(rbcli.load_data(odd), rbcli.load_data(plain))
    _same(rbcli.load_data(plain), rbcli.load_text(yaml.safe_dump(plain)))


def test_the_data_is_read_once_later_changes_do_not_reach_the_body():
    data = {"parts": [{"shape": "point", "mass": 1, "at": [0, 0, 1]}]}
    b = rbcli.load_data(data)
    data["parts"][0]["at"][2] = 5
    assert b.parts[0].com.tolist() == [0.0, 0.0, 1.0]
    assert "at: [0, 0, 1]" in b.text


def test_load_data_from_threads_gives_one_threads_answer():
    data = yaml.safe_load((EXAMPLES / "fan_rotor.yaml").read_text(encoding="utf-8"))
    want = rbcli.inertia(rbcli.load_data(data)).to_json()
    got: list = []

    def work():
        got.append(rbcli.inertia(rbcli.load_data(data)).to_json())

    threads = [threading.Thread(target=work) for _ in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert got == [want] * 8


# ----------------------------------------------------------------------------- the doors


@pytest.mark.parametrize("kwargs,message", [
    ({"units": 5}, "units: expected a mapping of kinds to unit names"),
    ({"units": ["mm"]}, "units: expected a mapping of kinds to unit names"),
    ({"units": "mm"}, "units: expected a mapping of kinds to unit names"),
    ({"units": {"length": 5}}, "units: the unit of 'length' is a text such as 'mm', not int"),
    ({"units": {1: "mm"}}, "units: its keys are kinds"),
    ({"name": 5}, "name: expected a text (str), not int"),
    ({"base_dir": 5}, "base_dir: expected a path"),
])
@pytest.mark.parametrize("fn", ["load_text", "load_data"])
def test_a_wrong_argument_type_is_a_type_error_naming_it(fn, kwargs, message):
    arg = "{shape: point, mass: 1}" if fn == "load_text" else {"shape": "point", "mass": 1}
    with pytest.raises(TypeError) as exc:
        getattr(rbcli, fn)(arg, **kwargs)
    assert str(exc.value).startswith(message), str(exc.value)


@pytest.mark.parametrize("units,message", [
    ({"lenght": "mm"}, "units: unknown kind 'lenght'; allowed: length, mass, time, angle, angular_speed"),
    ({"length": "kg"}, "units: length is 'kg', which is a mass"),
    ({"mass": "furlong"}, "units: mass: "),
])
@pytest.mark.parametrize("fn", ["load_text", "load_data"])
def test_a_bad_unit_is_a_param_error(fn, units, message):
    arg = "{shape: point, mass: 1}" if fn == "load_text" else {"shape": "point", "mass": 1}
    with pytest.raises(rbcli.ParamError) as exc:
        getattr(rbcli, fn)(arg, units=units)
    assert exc.value.param == "units" and str(exc.value).startswith(message), str(exc.value)


@pytest.mark.parametrize("arg", [5, None, ["examples/cube.yaml"], b"examples/cube.yaml", 1.5])
def test_load_takes_a_path(arg):
    with pytest.raises(TypeError, match=r"^path: expected a path"):
        rbcli.load(arg)


@pytest.mark.parametrize("arg", [5, None, ["x"], {"shape": "point"}])
def test_load_text_takes_text(arg):
    with pytest.raises(TypeError, match=r"^text: expected YAML text"):
        rbcli.load_text(arg)


def test_load_refuses_an_empty_path():
    with pytest.raises(rbcli.ParamError, match=r"^path: an empty path names no file$"):
        rbcli.load("")


def test_the_doors_accept_what_they_document(tmp_path):
    from pathlib import Path

    cube = rbcli.load(Path(ROOT / "examples" / "cube.yaml"))
    assert rbcli.load_text(bytearray(b"{shape: point, mass: 1}")).parts[0].mass == 1.0
    b = rbcli.load_text("{shape: point, mass: 1, at: [1, 0, 0]}", units={"length": "mm"},
                        name="p", base_dir=tmp_path)
    assert b.parts[0].com.tolist() == [0.001, 0.0, 0.0] and b.name == "p"
    assert cube.name
