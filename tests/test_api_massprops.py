"""The Python API of ``inertia`` and ``principal``: the same answers as the command line.

``rbcli.inertia(body, ...).to_json()`` must be exactly the object ``rbcli inertia ... --json``
prints, less ``"file"`` (and the same for ``principal``), on every example and for option
sets in every form the API accepts (SI numbers, sequences, strings as typed).
"""

from __future__ import annotations

import numpy as np
import pytest

import rbcli
from rbcli.errors import option_name
from conftest import as_cli, EXAMPLES
from rbcli.api import inertia as api
from rbcli.api import principal as api_p

ALL = sorted(p.name for p in EXAMPLES.glob("*.yaml"))


def _cli_json(cli, *args: str) -> dict:
    r = cli(*args, "--json")
    assert r.code == 0, r.err
    d = r.json()
    assert list(d).index("file") == list(d).index("name") + 1  # "file" right after "name"
    d.pop("file")
    return d


@pytest.mark.parametrize("name", ALL)
def test_inertia_to_json_is_the_cli_json_on_every_example(cli, name):
    path = EXAMPLES / name
    assert as_cli(rbcli.inertia(rbcli.load(path)).to_json()) == _cli_json(cli, "inertia", str(path))


@pytest.mark.parametrize("name", ALL)
def test_principal_to_json_is_the_cli_json_on_every_example(cli, name):
    path = EXAMPLES / name
    assert as_cli(rbcli.principal(rbcli.load(path)).to_json()) == _cli_json(cli, "principal", str(path))


@pytest.mark.parametrize("kwargs, args", [
    ({"about": "origin", "axis": [1, 1, 0]}, ("--about", "origin", "--axis", "1,1,0")),
    ({"about": "1,1,0", "omega": "0,0,300 rpm", "axis": "z"},
     ("--about", "1,1,0", "--omega", "0,0,300 rpm", "--axis", "z")),
    # a Python number is SI; a bare number typed on the command line is in the body's units
    ({"about": [0.5, 0.5, 0.0], "omega": [1.0, 0.0, 0.0]}, ("--about", "0.5,0.5,0 m", "--omega", "1,0,0")),
    ({"about": "com", "axis": "1e-320,1e-320,0"}, ("--about", "com", "--axis", "1e-320,1e-320,0")),
    ({"about": "100,0,5 mm"}, ("--about", "100,0,5 mm")),
])
@pytest.mark.parametrize("name", ["square_lamina.yaml", "bracket.yaml", "two_disk_rotor.yaml"])
def test_inertia_options_in_every_form(cli, name, kwargs, args):
    path = EXAMPLES / name
    got = rbcli.inertia(rbcli.load(path), **kwargs).to_json()
    assert got == _cli_json(cli, "inertia", str(path), *args)


@pytest.mark.parametrize("about", ["origin", "com", "0.1,0.2,0.3", "1,2,3 cm"])
def test_principal_about(cli, about):
    path = EXAMPLES / "square_lamina.yaml"
    assert as_cli(rbcli.principal(rbcli.load(path), about=about).to_json()) == _cli_json(
        cli, "principal", str(path), "--about", about)


def test_typed_fields_and_labels():
    lamina = rbcli.load(EXAMPLES / "square_lamina.yaml")  # 1 kg, 1 m, corner at the origin
    r = rbcli.inertia(lamina, about="origin", axis=[1, 1, 0], omega="0,0,2")
    assert isinstance(r, api.InertiaResult) and r.return_code == 0 and r.warnings == ()
    assert r.mass == pytest.approx(1.0) and r.reference_label == "the origin"
    np.testing.assert_allclose(r.com, [0.5, 0.5, 0.0])
    np.testing.assert_allclose(r.inertia, [[1 / 3, -1 / 4, 0], [-1 / 4, 1 / 3, 0], [0, 0, 2 / 3]], atol=1e-15)
    assert r.axis_moment == pytest.approx(1 / 12)
    assert r.kinetic_energy == pytest.approx(0.5 * 4 * 2 / 3)
    assert rbcli.inertia(lamina, about="com").reference_label == "the com"
    assert rbcli.inertia(lamina, about=[1, 2, 3]).reference_label == "[1, 2, 3]"
    assert rbcli.inertia(lamina, about="1,2,3 mm").reference_label == "[1,2,3 mm]"
    p = rbcli.principal(lamina, about="origin")
    assert isinstance(p, api_p.PrincipalResult) and p.symmetry == "asymmetric"
    assert p.moments == pytest.approx([1 / 12, 7 / 12, 2 / 3])
    np.testing.assert_allclose(p.axes @ p.axes.T, np.eye(3), atol=1e-15)
    assert p.stable == (True, False, True) and p.free_axes == ()


def test_body_reference_defaults_and_their_labels():
    at = rbcli.load_text("reference: [0, 0, 1]\nparts:\n  - {shape: point, mass: 2}\n")
    r = rbcli.inertia(at)
    assert r.reference_label == "the body's reference point" and r.inertia[0, 0] == pytest.approx(2.0)
    com = rbcli.load_text("reference: com\nparts:\n  - {shape: point, mass: 2, at: [0, 0, 1]}\n")
    assert rbcli.inertia(com).reference_label == "the com"
    plain = rbcli.load_text("{shape: point, mass: 2, at: [0, 0, 1]}")
    assert rbcli.inertia(plain).reference_label == "the origin"
    assert rbcli.principal(plain).reference_label == "the com"  # principal: the com by default
    opts = api.parse(at, about="1,0,0 mm", axis="z", omega="0,0,60 rpm")
    ref = api.Reference.of(at, opts)
    assert ref.point == pytest.approx((0.001, 0.0, 0.0)) and ref.param == "about"
    assert ref.label == "[1,0,0 mm]" and opts.given == ("about", "axis", "omega")
    assert opts.axis == (0.0, 0.0, 1.0) and opts.omega == pytest.approx((0.0, 0.0, 2 * np.pi))


@pytest.mark.parametrize("cmd, kwargs, args", [
    ("inertia", {"about": "1,2"}, ("--about", "1,2")),
    ("inertia", {"axis": [0, 0, 0]}, ("--axis", "0,0,0")),
    ("inertia", {"omega": "1 Hz,0,0"}, ("--omega", "1 Hz,0,0")),
    ("inertia", {"omega": [1e300, 0, 0]}, ("--omega", "1e300,0,0")),
    ("inertia", {"about": "1e300,0,0"}, ("--about", "1e300,0,0")),
    ("principal", {"about": "1e300,0,0"}, ("--about", "1e300,0,0")),
    ("principal", {"about": "middle"}, ("--about", "middle")),
])
def test_errors_carry_the_cli_message(cli, cmd, kwargs, args):
    path = EXAMPLES / "square_lamina.yaml"
    with pytest.raises(rbcli.InputError) as info:
        getattr(rbcli, cmd)(rbcli.load(path), **kwargs)
    r = cli(cmd, str(path), *args)
    assert r.code == 2 and r.err == f"rbcli: {info.value.spelled(option_name)}\n"


def test_an_overflow_names_the_parameter_not_the_message():
    """The body's own reference point is blamed as such; --about as --about."""
    import dataclasses

    body = rbcli.load_text("reference: [1, 0, 0]\nparts:\n  - {shape: point, mass: 1}\n")
    far = dataclasses.replace(body, reference=np.array([1e200, 0.0, 0.0]))  # beyond any file's limits
    with pytest.raises(rbcli.ParamError) as info:
        rbcli.inertia(far)
    assert info.value.param == "body_reference"
    assert str(info.value).startswith("the body's reference point: the inertia about this point overflows")
    lamina = rbcli.load(EXAMPLES / "square_lamina.yaml")
    with pytest.raises(rbcli.ParamError) as info:
        rbcli.principal(lamina, about=[1e300, 0, 0])
    assert info.value.param == "about" and info.value.spelled(option_name).startswith("--about: ")
    with pytest.raises(rbcli.ParamError) as info:
        rbcli.inertia(lamina, omega=[1e300, 0, 0])
    assert info.value.param == "omega"


def test_many_bodies_json_lines_are_the_api_results(cli):
    paths = [EXAMPLES / "cube.yaml", EXAMPLES / "square_lamina.yaml"]
    docs = cli("inertia", *map(str, paths), "--json").json()
    for p, d in zip(paths, docs):
        d.pop("file")
        assert as_cli(rbcli.inertia(rbcli.load(p)).to_json()) == d


@pytest.mark.parametrize("cmd, args", [("inertia", ("--axis", "0,0,0")), ("inertia", ("--omega", "1,2")),
                                       ("principal", ("--about", "1,2"))])
def test_a_bad_option_is_one_line_before_any_body(cli, cmd, args):
    """The options are checked once before the bodies are read (then per body, where the
    body's defaults count): several bodies still get one line, not one per body."""
    r = cli(cmd, str(EXAMPLES / "cube.yaml"), str(EXAMPLES / "nope.yaml"), *args)
    assert r.code == 2 and r.out == "" and r.err.count("\n") == 1 and args[0] in r.err
