"""``rbcli.top`` and ``rbcli.gyrocompass``: the Python API gives what the command line prints.

Every comparison is against ``rbcli top ... --json`` (less ``file``) run through the ``cli``
fixture; the errors carry the command line's one-line message. The motion's sampling
(``result.at``) is checked against the JSON's turning points and against finite
differences of its own angles.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import rbcli
from conftest import as_cli
from rbcli.errors import option_name
from rbcli.errors import InputError

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted(p.name for p in (ROOT / "examples").glob("*.yaml"))


@pytest.fixture(autouse=True)
def _at_the_root(monkeypatch):
    """Bodies load by the relative path the command line is given (their source label)."""
    monkeypatch.chdir(ROOT)


def cli_json(cli, *args):
    r = cli(*args, "--json")
    assert r.code in (0, 1), r.err
    d = r.json()
    d.pop("file", None)
    return d


def cli_error(cli, *args) -> str:
    r = cli(*args)
    assert r.code == 2 and r.out == "", (r.code, r.out)
    assert r.err.startswith("rbcli: ") and r.err.count("\n") == 1, r.err
    return r.err[len("rbcli: "):].rstrip("\n")


# (CLI arguments, API keywords): several spins, tilts and starts on both bodies with a pivot
TOP_CASES = [
    (["--spin", "150", "--theta", "30", "--g", "9.81"], dict(spin=150, theta=30, g=9.81)),
    (["--spin", "150", "--theta", "30"], dict(spin=150, theta=30)),
    (["--spin", "3000 rpm", "--theta", "90"], dict(spin="3000 rpm", theta=90)),
    (["--spin", "-200", "--theta", "120"], dict(spin=-200, theta=120)),
    (["--spin", "1000", "--theta", "0.5"], dict(spin=1000, theta=0.5)),
    (["--spin", "40", "--theta", "60"], dict(spin=40, theta=60)),
    (["--spin", "150", "--theta", "0.3 rad", "--phi-dot", "10"], dict(spin=150, theta="0.3 rad", phi_dot=10)),
    (["--spin", "150", "--theta", "30", "--theta-dot", "1", "--phi-dot", "-2 rad/s"],
     dict(spin=150, theta=30, theta_dot=1, phi_dot="-2 rad/s")),
    (["--spin", "150", "--theta", "30", "--pivot", "0,0,-10 mm"], dict(spin=150, theta=30, pivot="0,0,-10 mm")),
    (["--spin", "150", "--theta", "30", "--pivot", "origin"], dict(spin=150, theta=30, pivot="origin")),
    (["--spin", "150", "--theta", "30", "--verify"], dict(spin=150, theta=30, verify=True)),
]


@pytest.mark.parametrize("example", ["top.yaml", "gyroscope.yaml"])
@pytest.mark.parametrize("args, kw", TOP_CASES, ids=[" ".join(a) for a, _ in TOP_CASES])
def test_top_to_json_is_the_cli_json(cli, example, args, kw):
    path = f"examples/{example}"
    r = rbcli.top(rbcli.load(path), **kw)
    assert as_cli(r.to_json()) == cli_json(cli, "top", path, *args)
    assert r.return_code == 0


@pytest.mark.parametrize("example", EXAMPLES)
def test_top_on_every_example_answers_or_refuses_as_the_cli(cli, example):
    path = f"examples/{example}"
    args = ["--spin", "150", "--theta", "30"]
    r = cli("top", path, *args, "--json")
    body = rbcli.load(path)
    if r.code == 0:
        d = r.json()
        d.pop("file")
        assert as_cli(rbcli.top(body, spin=150, theta=30).to_json()) == d
    else:
        assert r.code == 2
        with pytest.raises(InputError) as exc:
            rbcli.top(body, spin=150, theta=30)
        error = r.err.splitlines()[-1]  # after the loader's warnings (a welded mesh), if any
        assert exc.value.spelled(option_name) == error[len("rbcli: "):]


TOP_ERRORS = [
    (["--spin", "0", "--theta", "30"], dict(spin=0, theta=30), "spin"),
    (["--spin", "150", "--theta", "0"], dict(spin=150, theta=0), "theta"),
    (["--spin", "150", "--theta", "190"], dict(spin=150, theta="190"), "theta"),
    (["--spin", "150", "--theta", "30", "--g", "-9.81"], dict(spin=150, theta=30, g="-9.81"), "g"),
    (["--spin", "3 m", "--theta", "30"], dict(spin="3 m", theta=30), None),
    (["--spin", "150", "--theta", "30", "--pivot", "com"], dict(spin=150, theta=30, pivot="com"), "pivot"),
    (["--spin", "150", "--theta", "30", "--pivot", "1,2"], dict(spin=150, theta=30, pivot="1,2"), None),
    (["--spin", "1e200", "--theta", "30"], dict(spin=1e200, theta=30), "spin"),
]


@pytest.mark.parametrize("args, kw, param", TOP_ERRORS, ids=[" ".join(a) for a, _, _ in TOP_ERRORS])
def test_top_errors_carry_the_cli_message(cli, args, kw, param):
    msg = cli_error(cli, "top", "examples/top.yaml", *args)
    with pytest.raises(InputError) as exc:
        rbcli.top(rbcli.load("examples/top.yaml"), **kw)
    assert exc.value.spelled(option_name) == msg
    if param is not None:
        assert exc.value.param == param


def test_missing_spin_or_theta_in_the_options_say_what_the_cli_says(cli):
    from rbcli.api.top import parse

    body = rbcli.load("examples/top.yaml")
    for args, kw in ((["--theta", "30"], dict(theta=30)), (["--spin", "150"], dict(spin=150))):
        msg = cli_error(cli, "top", "examples/top.yaml", *args)
        with pytest.raises(InputError) as exc:
            parse(body, **kw)
        assert exc.value.spelled(option_name) == msg


def test_options_read_the_values_and_the_result_says_where_the_pivot_came_from():
    from rbcli.api.top import parse

    top = rbcli.load("examples/top.yaml")
    o = parse(top, spin="3000 rpm", theta=30)
    assert o.pivot is None and o.given == ("spin", "theta")
    assert o.spin == pytest.approx(100 * math.pi, rel=1e-15)
    assert o.theta == pytest.approx(math.radians(30), rel=1e-15)
    assert (o.theta_dot, o.phi_dot, o.g, o.samples) == (0.0, 0.0, 9.80665, 600)
    assert rbcli.top(top, spin="3000 rpm", theta=30).pivot_source == "the body's pivot"
    r = rbcli.top(top, spin=150, theta=30, pivot="0,0,-20 mm")
    assert r.options.pivot == pytest.approx((0.0, 0.0, -0.02)) and r.pivot_source == "pivot"
    assert r.params.pivot == pytest.approx((0.0, 0.0, -0.02))
    disk = rbcli.load_text("{shape: disk, radius: 0.1, mass: 1, at: [0, 0, 0.05]}")
    r = rbcli.top(disk, spin=150, theta=30)
    assert r.params.pivot == pytest.approx((0.0, 0.0, 0.0))
    assert r.pivot_source == "the origin, as no pivot was given"


def test_the_result_samples_the_motion():
    r = rbcli.top(rbcli.load("examples/top.yaml"), spin=150, theta=30, g=9.81)
    m = r.motion
    # the sheet's case T1: released from rest at 30°, θ2 = 34.5082°, T_n = 0.142133 s, cusps
    assert math.degrees(m.theta2) == pytest.approx(34.5082, abs=5e-5)
    assert m.nutation_period == pytest.approx(0.142133, abs=5e-7) and m.path == "cusps"
    s0 = r.at(0.0)
    assert float(s0.theta) == pytest.approx(math.radians(30), rel=1e-14)
    assert float(s0.phi) == 0.0 and float(s0.psi) == 0.0
    assert float(s0.phi_dot) == pytest.approx(0.0, abs=1e-12) and float(s0.psi_dot) == pytest.approx(150.0)
    half = r.at(m.nutation_period / 2)  # the greatest tilt
    assert float(half.theta) == pytest.approx(m.theta2, rel=1e-12)
    # rates against central differences of the exact angles
    t = np.linspace(0.01, 0.4, 40)
    h = 1e-6
    s, a, b = r.at(t), r.at(t + h), r.at(t - h)
    for rate, angle in (("theta_dot", "theta"), ("phi_dot", "phi"), ("psi_dot", "psi")):
        fd = (getattr(a, angle) - getattr(b, angle)) / (2 * h)
        assert getattr(s, rate) == pytest.approx(fd, rel=1e-6, abs=1e-6 * np.max(np.abs(fd)))
    assert s.axis.shape == (40, 3) and np.allclose(np.linalg.norm(s.axis, axis=1), 1.0)
    assert r.motion.at(t).theta == pytest.approx(s.theta)
    assert r.default_duration() == pytest.approx(3 * m.nutation_period)
    assert len(r.sample(r.default_duration()).t) == 2000
    assert r.steady_estimates == r.to_json()["steady_precession_estimates"]


def test_verify_result_and_return_code(monkeypatch):
    import rbcli.core.topverify as tv

    body = rbcli.load("examples/top.yaml")
    r = rbcli.top(body, spin=150, theta=30, verify=True)
    assert r.verify.passed and r.return_code == 0 and r.verify.max_axis_error < 1e-10
    monkeypatch.setattr(tv, "AXIS_TOL", 0.0)
    r = rbcli.top(body, spin=150, theta=30, verify=True)
    assert not r.verify.passed and r.return_code == 1
    assert r.to_json()["verify"]["pass"] is False


# ----------------------------------------------------------------------------- gyrocompass


GYRO_CASES = [
    (["--ratio", "2", "--spin", "6000 rpm", "--latitude", "30"], None, dict(ratio=2, spin="6000 rpm", latitude=30)),
    (["--ratio", "2", "--spin", "20000 rpm", "--latitude", "45"], None, dict(ratio="2", spin="20000 rpm", latitude=45)),
    (["--ratio", "1.5", "--spin", "-300", "--latitude", "-60", "--earth-rate", "1e-4"], None,
     dict(ratio=1.5, spin=-300, latitude=-60, earth_rate=1e-4)),
    (["--ratio", "2", "--spin", "6000 rpm", "--latitude", "90"], None, dict(ratio=2, spin="6000 rpm", latitude=90)),
    (["--spin", "6000 rpm", "--latitude", "30"], "examples/gyroscope.yaml", dict(spin="6000 rpm", latitude=30)),
    (["--spin", "100", "--latitude", "0.5 rad"], "examples/top.yaml", dict(spin=100, latitude="0.5 rad")),
    (["--spin", "6000 rpm", "--latitude", "30"], "examples/penny.yaml", dict(spin="6000 rpm", latitude=30)),
    (["--spin", "6000 rpm", "--latitude", "30", "--axis", "z"], "examples/frisbee.yaml",
     dict(spin="6000 rpm", latitude=30, shaft="z")),
]


@pytest.mark.parametrize("args, path, kw", GYRO_CASES, ids=[" ".join(a) for a, _, _ in GYRO_CASES])
def test_gyrocompass_to_json_is_the_cli_json(cli, args, path, kw):
    body = rbcli.load(path) if path else None
    r = rbcli.gyrocompass(body, **kw)
    assert as_cli(r.to_json()) == cli_json(cli, "gyrocompass", *([path] if path else []), *args)
    assert r.return_code == 0


def test_gyrocompass_typed_fields():
    r = rbcli.gyrocompass(rbcli.load_text("{shape: disk, radius: 0.1, mass: 1}"), spin="6000 rpm", latitude=30)
    # a thin disk: C = m R²/2, A = m R²/4 (C/A = 2); the sheet's case T8: T = 22.3040 s
    assert r.C == pytest.approx(0.005, rel=1e-14) and r.A == pytest.approx(0.0025, rel=1e-14)
    assert r.swing.C_over_A == pytest.approx(2.0, rel=1e-14)
    assert r.swing.period == pytest.approx(22.3040, abs=5e-5) and r.swing.settles_to == "north"
    assert r.axis_source == "body z (default)" and r.axis == (0.0, 0.0, 1.0)


GYRO_ERRORS = [
    (["--ratio", "2", "--spin", "0", "--latitude", "3"], None, dict(ratio=2, spin=0, latitude=3)),
    (["--ratio", "-1", "--spin", "10", "--latitude", "3"], None, dict(ratio=-1, spin=10, latitude=3)),
    (["--ratio", "2", "--spin", "10", "--latitude", "95"], None, dict(ratio=2, spin=10, latitude=95)),
    (["--spin", "10", "--latitude", "3"], None, dict(spin=10, latitude=3)),
    (["--ratio", "2", "--spin", "10", "--latitude", "3"], "examples/gyroscope.yaml", dict(ratio=2, spin=10, latitude=3)),
    (["--spin", "100", "--latitude", "30"], "examples/rectangular_block.yaml", dict(spin=100, latitude=30)),
]


@pytest.mark.parametrize("args, path, kw", GYRO_ERRORS, ids=[" ".join(a) for a, _, _ in GYRO_ERRORS])
def test_gyrocompass_errors_carry_the_cli_message(cli, args, path, kw):
    msg = cli_error(cli, "gyrocompass", *([path] if path else []), *args)
    body = rbcli.load(path) if path else None
    with pytest.raises(InputError) as exc:
        rbcli.gyrocompass(body, **kw)
    assert exc.value.spelled(option_name) == msg


# ----------------------------------------------------------------------------- nearly symmetric bodies


@pytest.mark.parametrize("args, kw", [
    (["--spin", "1500 rpm", "--theta", "60"], dict(spin="1500 rpm", theta=60)),
    (["--spin", "1500 rpm", "--theta", "60", "--verify"], dict(spin="1500 rpm", theta=60, verify=True)),
    (["--spin", "1500 rpm", "--theta", "60", "--symmetry-tol", "0.5 %"], dict(spin="1500 rpm", theta=60, symmetry_tol="0.5 %")),
])
def test_nearly_symmetric_top_to_json_is_the_cli_json(cli, args, kw):
    r = rbcli.top(rbcli.load("examples/cad_flywheel.yaml"), **kw)
    assert as_cli(r.to_json()) == cli_json(cli, "top", "examples/cad_flywheel.yaml", *args)
    assert len(r.warnings) == 1 and r.asymmetry is not None
    assert cli("top", "examples/cad_flywheel.yaml", *args).err == f"rbcli: {r.warnings[0].spelled(option_name)}\n"


def test_nearly_symmetric_errors_and_gyrocompass(cli):
    body = rbcli.load("examples/cad_flywheel.yaml")
    msg = cli_error(cli, "top", "examples/cad_flywheel.yaml", "--spin", "1500 rpm", "--theta", "60",
                    "--symmetry-tol", "0.001%")
    with pytest.raises(InputError) as exc:
        rbcli.top(body, spin="1500 rpm", theta=60, symmetry_tol=1e-5)
    assert exc.value.spelled(option_name) == msg
    g = rbcli.gyrocompass(body, spin="6000 rpm", latitude=45)
    assert as_cli(g.to_json()) == cli_json(cli, "gyrocompass", "examples/cad_flywheel.yaml", "--spin", "6000 rpm",
                                   "--latitude", "45")
    assert g.asymmetry is not None and len(g.warnings) == 1
    with pytest.raises(InputError) as exc:
        rbcli.gyrocompass(body, spin=100, latitude=45, symmetry_tol="20 %")
    assert exc.value.param == "symmetry_tol"
