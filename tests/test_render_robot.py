"""``inertia --format urdf|sdf|mjcf``: the ``<inertial>`` element, parsed back and compared with
``--json`` (body axes) and ``principal --json`` (``--principal``); orientation conventions
checked with scipy's Rotation (URDF/SDF rpy = extrinsic x-y-z, MJCF quat = w x y z); and an
optional MuJoCo round trip (skipped where MuJoCo is not installed).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import rbcli
from conftest import EXAMPLES
from rbcli.core.inertial import quaternion_wxyz, roll_pitch_yaw
from rbcli.render import robot

ALL = sorted(p.name for p in EXAMPLES.glob("*.yaml"))
FEW = ["two_blade_fan.yaml", "bracket.yaml", "car_wheel.yaml", "rectangular_block.yaml", "top.yaml"]


def floats(text: str) -> list[float]:
    return [float(x) for x in text.split()]


def parse(fmt: str, out: str) -> dict:
    """mass, com, rotation (columns = inertial axes in the link frame), inertia (in those axes)."""
    el = ET.fromstring(out)
    assert el.tag == "inertial"
    if fmt == "urdf":
        o, i = el.find("origin"), el.find("inertia").attrib
        com, rpy = floats(o.get("xyz")), floats(o.get("rpy"))
        R = Rotation.from_euler("xyz", rpy).as_matrix()  # lower case: extrinsic (fixed axes)
        mass = float(el.find("mass").get("value"))
        J = [[i["ixx"], i["ixy"], i["ixz"]], [i["ixy"], i["iyy"], i["iyz"]], [i["ixz"], i["iyz"], i["izz"]]]
    elif fmt == "sdf":
        pose = floats(el.find("pose").text)
        com, R = pose[:3], Rotation.from_euler("xyz", pose[3:]).as_matrix()
        mass = float(el.find("mass").text)
        g = {c.tag: c.text for c in el.find("inertia")}
        J = [[g["ixx"], g["ixy"], g["ixz"]], [g["ixy"], g["iyy"], g["iyz"]], [g["ixz"], g["iyz"], g["izz"]]]
    else:
        a = el.attrib
        com, mass = floats(a["pos"]), float(a["mass"])
        if "fullinertia" in a:
            xx, yy, zz, xy, xz, yz = floats(a["fullinertia"])
            J, R = [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]], np.eye(3)
        else:
            w, x, y, z = floats(a["quat"])
            R = Rotation.from_quat([x, y, z, w]).as_matrix()  # scipy: scalar last
            J = np.diag(floats(a["diaginertia"]))
    return {"mass": mass, "com": com, "R": np.asarray(R), "J": np.asarray(J, dtype=float)}


@pytest.mark.parametrize("fmt", robot.FORMATS)
@pytest.mark.parametrize("name", ALL)
def test_body_axes_element_is_the_json_exactly(cli, fmt, name):
    path = str(EXAMPLES / name)
    r = cli("inertia", path, "--format", fmt)
    assert r.code == 0 and all(": warning: " in line for line in r.err.splitlines()), r.err  # a weld
    assert r.out.startswith("<!-- rbcli inertia: ") and "the centre of mass" in r.out
    got, want = parse(fmt, r.out), cli("inertia", path, "--json").json()
    assert got["mass"] == want["mass"] and got["com"] == want["com"]  # full precision: exact
    assert got["J"].tolist() == want["inertia_com"] and np.array_equal(got["R"], np.eye(3))


@pytest.mark.parametrize("fmt", robot.FORMATS)
@pytest.mark.parametrize("name", FEW)
def test_principal_element_is_principal_json(cli, fmt, name):
    path = str(EXAMPLES / name)
    r = cli("inertia", path, "--format", fmt, "--principal")
    assert r.code == 0 and "principal moments" in r.out
    got, want = parse(fmt, r.out), cli("principal", path, "--json").json()
    assert got["com"] == want["reference"]
    np.testing.assert_array_equal(np.diag(got["J"]), want["moments"])
    assert np.count_nonzero(got["J"] - np.diag(np.diag(got["J"]))) == 0
    # the rotation's columns are the principal axes (rows of "axes")
    np.testing.assert_allclose(got["R"], np.array(want["axes"]).T, rtol=0, atol=1e-14)
    # and it turns the diagonal tensor back into the body-axes tensor of --json
    full = np.array(cli("inertia", path, "--json").json()["inertia_com"])
    back = got["R"] @ got["J"] @ got["R"].T
    np.testing.assert_allclose(back, full, rtol=0, atol=1e-13 * np.abs(full).max())


@pytest.mark.parametrize("seed", range(40))
def test_quaternion_and_rpy_follow_scipy_conventions(seed):
    R = Rotation.random(random_state=seed).as_matrix()
    q = quaternion_wxyz(R)
    assert q[0] >= 0 and np.linalg.norm(q) == pytest.approx(1.0)
    np.testing.assert_allclose(Rotation.from_quat([*q[1:], q[0]]).as_matrix(), R, atol=1e-14)
    rpy = roll_pitch_yaw(R)
    np.testing.assert_allclose(Rotation.from_euler("xyz", rpy).as_matrix(), R, atol=1e-14)
    # URDF's rpy: R = Rz(yaw) Ry(pitch) Rx(roll)
    Rz, Ry, Rx = (Rotation.from_euler(a, v).as_matrix() for a, v in zip("zyx", rpy[::-1]))
    np.testing.assert_allclose(Rz @ Ry @ Rx, R, atol=1e-14)


@pytest.mark.parametrize("pitch", [np.pi / 2, -np.pi / 2])
def test_rpy_at_gimbal_lock(pitch):
    R = Rotation.from_euler("xyz", [0.3, pitch, -0.4]).as_matrix()
    np.testing.assert_allclose(Rotation.from_euler("xyz", roll_pitch_yaw(R)).as_matrix(), R, atol=1e-12)


def test_api_gives_the_same_numbers_and_xml(cli):
    body = rbcli.load(EXAMPLES / "bracket.yaml")
    res = rbcli.inertia(body)
    for fmt in robot.FORMATS:
        for principal in (False, True):
            xml = robot.render(fmt, body.name, body.source, res.inertial(principal))
            args = ["--principal"] if principal else []
            assert cli("inertia", str(EXAMPLES / "bracket.yaml"), "--format", fmt, *args).out == xml
    ine = res.inertial(True)
    assert ine.principal and ine.mass == res.mass
    np.testing.assert_array_equal(np.diag(ine.inertia), rbcli.principal(body).moments)


def test_comment_is_valid_xml_whatever_the_name(cli):
    r = cli("inertia", "-e", "{name: 'a -- b -', shape: box, mass: 1, size: [1, 2, 3]}", "--format", "urdf")
    assert r.code == 0
    ET.fromstring(r.out)  # a '--' in the name would end the comment early
    assert "a - - b" in r.out


@pytest.mark.parametrize("args, message", [
    (("--format", "urdf", "--about", "origin"), "--about does not apply to --format urdf"),
    (("--format", "mjcf", "--units", "mm"), "--units does not apply to --format mjcf"),
    (("--format", "sdf", "--axis", "z"), "--axis does not apply to --format sdf"),
    (("--principal",), "--principal applies to --format urdf, sdf or mjcf, not to table"),
    (("--format", "xml"), "--format must be table, json, csv, urdf, sdf or mjcf, not 'xml'"),
    (("--json", "--format", "urdf"), "--json and --format urdf ask for two formats"),
    # the formats fix the sign (issue 24 item 6): positive products would be silently ignored
    (("--format", "urdf", "--products", "positive"), "--products positive does not apply to --format urdf"),
    (("--format", "sdf", "--products", "positive"), "--products positive does not apply to --format sdf"),
    (("--format", "mjcf", "--products", "positive", "--principal"),
     "--products positive does not apply to --format mjcf"),
])
def test_bad_combinations_exit_2(cli, args, message):
    r = cli("inertia", str(EXAMPLES / "cube.yaml"), *args)
    assert r.code == 2 and r.out == "" and message in r.err and r.err.count("\n") == 1


@pytest.mark.parametrize("fmt", robot.FORMATS)
def test_every_comment_states_the_off_diagonal_sign(cli, fmt):
    """URDF, SDF and MJCF alike say which sign the off-diagonals have (issue 24 item 6), and the
    number written is the tensor's entry itself (the two-blade fan's Jxy about its com is not 0)."""
    r = cli("inertia", str(EXAMPLES / "two_blade_fan.yaml"), "--format", fmt)
    assert "ixy = -(integral of x y dm)" in r.out
    J = np.array(cli("inertia", str(EXAMPLES / "two_blade_fan.yaml"), "--json").json()["inertia_com"])
    assert repr(float(J[0, 1])) in r.out and J[0, 1] != 0  # the tensor's entry, its sign as it is


def test_format_json_is_json_and_csv_is_one_table(cli):
    path = str(EXAMPLES / "square_lamina.yaml")
    for cmd in ("inertia", "principal"):
        assert cli(cmd, path, "--format", "json").out == cli(cmd, path, "--json").out
        csv = cli(cmd, path, "--format", "csv")
        assert csv.code == 0 and csv.out.startswith("quantity,value,text,unit\n")
    many = cli("inertia", str(EXAMPLES / "cube.yaml"), path, "--format", "csv").out
    assert many.startswith("file,quantity,value,text,unit\n") and path in many
    assert "\n\n" not in many and many.count("quantity") == 1  # one table, one header


# ----------------------------------------------------------------------------- MuJoCo


MUJOCO_OK = [n for n in FEW if n != "rectangular_block.yaml"] + ["cube.yaml", "housing.yaml"]


@pytest.mark.parametrize("principal", [False, True])
@pytest.mark.parametrize("name", MUJOCO_OK)
def test_mujoco_loads_the_mjcf_inertial(cli, name, principal):
    mujoco = pytest.importorskip("mujoco")
    path = str(EXAMPLES / name)
    args = ["--principal"] if principal else []
    element = cli("inertia", path, "--format", "mjcf", *args).out
    model = mujoco.MjModel.from_xml_string(
        f"<mujoco><worldbody><body name='b'><freejoint/>{element}</body></worldbody></mujoco>")
    pj, ij = cli("principal", path, "--json").json(), cli("inertia", path, "--json").json()
    np.testing.assert_allclose(model.body_ipos[1], ij["com"], rtol=0, atol=1e-15)
    assert model.body_mass[1] == pytest.approx(ij["mass"], rel=1e-15)
    scale = max(pj["moments"])
    np.testing.assert_allclose(np.sort(model.body_inertia[1]), pj["moments"], rtol=0, atol=1e-12 * scale)
    # MuJoCo's principal frame (body_iquat) turns its moments back into rbcli's tensor
    q = model.body_iquat[1]
    R = Rotation.from_quat([q[1], q[2], q[3], q[0]]).as_matrix()
    back = R @ np.diag(model.body_inertia[1]) @ R.T
    np.testing.assert_allclose(back, ij["inertia_com"], rtol=0, atol=1e-12 * scale)
