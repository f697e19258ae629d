"""``rbcli.precess``: the Python API gives the command's JSON, typed fields, and a motion
that samples the exact solution (checked against an independent DOP853 integration)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import rbcli
from conftest import as_cli, sampled_params
from rbcli.errors import option_name
from rbcli.api.precess import PrecessResult

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted(p.stem for p in (ROOT / "examples").glob("*.yaml"))
#: a general omega, one near the intermediate axis, one about z, one with units
OMEGAS = ["0.3,1,0.2", "0.01,1,0.01", "0,0,10", "0,0,300 rpm"]


def _without_file(d: dict) -> dict:
    return {k: v for k, v in d.items() if k != "file"}


# by default every example with one of the omegas in turn (and every omega with six
# examples); every pair under -m slow
@pytest.mark.parametrize("name, omega", sampled_params(
    [(n, w) for n in EXAMPLES for w in OMEGAS], lambda nw: (EXAMPLES.index(nw[0]) - OMEGAS.index(nw[1])) % 4 == 0,
    ids=lambda nw: f"{nw[0]}-{nw[1]}", multi=True))
def test_to_json_is_the_cli_json(cli, name, omega):
    path = f"examples/{name}.yaml"
    r = cli("precess", path, "--omega", omega, "--json")
    body = rbcli.load(ROOT / path)
    if r.code == 2:  # the same refusal, with the same message
        with pytest.raises(rbcli.InputError) as exc:
            rbcli.precess(body, omega=omega)
        assert r.err == f"rbcli: {exc.value.spelled(option_name)}\n"
        return
    assert r.code == 0, r.err
    res = rbcli.precess(body, omega=omega)
    assert as_cli(res.to_json()) == _without_file(r.json())
    assert list(r.json())[list(r.json()).index("name") + 1] == "file"  # where the CLI puts it


@pytest.mark.parametrize("name", sampled_params(["book", "frisbee", "rectangular_block", "football"], [0, 3],
                                                ids=["book", "frisbee", "rectangular_block", "football"]))
def test_to_json_with_at_and_verify_is_the_cli_json(cli, name):
    path = f"examples/{name}.yaml"
    args = ("--omega", "0.3,1,0.2", "--at", "2.5 min", "--verify")
    r = cli("precess", path, *args, "--json")
    assert r.code == 0, r.err
    res = rbcli.precess(rbcli.load(ROOT / path), omega="0.3,1,0.2", at="2.5 min", verify=True)
    assert as_cli(res.to_json()) == _without_file(r.json())
    assert res.return_code == 0 and res.check is not None and res.check.ok


def test_typed_fields_and_sampling():
    body = rbcli.load(ROOT / "examples/book.yaml")
    res = rbcli.precess(body, omega=[0.01, 1, 0.01], at=1e9, duration=60.0, samples=7)
    assert isinstance(res, PrecessResult)
    o = res.options
    assert (o.omega, o.at, o.duration, o.samples, o.verify) == ((0.01, 1.0, 0.01), 1e9, 60.0, 7, False)
    assert o.given == ("omega", "at", "duration", "samples")
    # what the table echoes: the values as understood, angular speeds also in rpm
    from rbcli.render.echo import echo_rows

    assert echo_rows(res.options, body.units) == [
        ("--omega", "0.01, 1, 0.01 (0.095493, 9.5493, 0.095493 rpm)", "rad/s"),
        ("--at", "1e+09", "s"), ("--duration", "60", "s")]
    m = res.motion
    assert m.case == "circulates_max" and m.flip_interval == pytest.approx(19.5529, rel=1e-5)
    assert isinstance(m.period, float)
    st = res.at(1e9)
    assert st.omega.shape == (3,) and st.quaternion.shape == (4,) and st.rotation_matrix.shape == (3, 3)
    np.testing.assert_array_equal(st.omega, res.state.omega)
    np.testing.assert_array_equal(res.to_json()["at"]["omega"], res.state.omega)
    many = res.motion.at(np.array([0.0, 1.0, 2.0]))
    assert many.omega.shape == (3, 3) and many.quaternion.shape == (3, 4)
    np.testing.assert_array_equal(many.omega[0], [0.01, 1.0, 0.01])  # exactly the initial value
    s = res.series()
    assert s.shape == (7, 11) and s[0, 0] == 0.0 and s[-1, 0] == 60.0
    np.testing.assert_array_equal(s[:, 1:4], res.at(s[:, 0]).omega)
    # the series keeps the quaternion's sign continuous
    assert np.all(np.einsum("ij,ij->i", s[1:, 7:], s[:-1, 7:]) > 0)
    # L in space (R L_body) is the constant L at every time: round-off only (1e-13 of |L|)
    Ls = np.einsum("nij,nj->ni", many.rotation_matrix, many.angular_momentum)
    np.testing.assert_allclose(Ls, np.tile(m.angular_momentum, (3, 1)), rtol=0,
                               atol=1e-13 * m.angular_momentum_norm)


def test_series_needs_a_span():
    res = rbcli.precess(rbcli.load(ROOT / "examples/book.yaml"), omega=[0.3, 1, 0.2])
    with pytest.raises(rbcli.InputError, match="duration"):
        res.series()
    assert res.series(duration=1.0).shape == (1001, 11)


def _dop853(J: np.ndarray, w0: np.ndarray, ts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Independent integration of Euler's equations and the attitude, body frame:
    J w' = (J w) x w, R' = R [w]x, R(0) = 1 (DOP853 at rtol 1e-10, atol 1e-12 of the scale)."""
    from scipy.integrate import solve_ivp

    Jinv = np.linalg.inv(J)

    def rhs(_t, y):
        w = y[:3]
        R = y[3:].reshape(3, 3)
        W = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
        return np.concatenate([Jinv @ np.cross(J @ w, w), (R @ W).ravel()])

    wn = float(np.linalg.norm(w0))
    atol = np.concatenate([np.full(3, 1e-12 * wn), np.full(9, 1e-12)])
    sol = solve_ivp(rhs, (0.0, ts[-1]), np.concatenate([w0, np.eye(3).ravel()]), method="DOP853",
                    rtol=1e-10, atol=atol, t_eval=ts)
    assert sol.success
    return sol.y[:3].T, sol.y[3:].T.reshape(-1, 3, 3)


@pytest.mark.parametrize("name, omega", [
    ("book", [0.3, 1.0, 0.2]),            # asymmetric, circles axis 3
    ("book", [0.01, 1.0, 0.01]),          # near the intermediate axis: flips
    ("rectangular_block", [1.0, 0.1, 0.2]),  # circles axis 1
    ("frisbee", [0.871557, 0.0, 9.96195]),   # symmetric oblate
    ("football", [1.73648, 0.0, 9.84808]),   # symmetric prolate
])
def test_motion_at_matches_an_independent_dop853_integration(name, omega):
    """result.at(t) against DOP853 at rtol 1e-10 over 3 periods (or 3 flip intervals).

    Tolerance 1e-8 (relative for omega, rad for the attitude): DOP853's own global error at
    rtol 1e-10 over 3 periods is what is measured — 2e-13 .. 4e-11 in omega and
    4e-11 .. 1.7e-9 in the attitude (the largest near the intermediate axis, where the
    integrator's error grows by ~1/k' per pass: k' = 0.014 for the book at 0.01,1,0.01) —
    while the exact solution's own error is ~1e-14; 1e-8 leaves a factor 6 over the worst.
    """
    body = rbcli.load(ROOT / f"examples/{name}.yaml")
    res = rbcli.precess(body, omega=omega)
    m = res.motion
    span = 3.0 * (m.period or 2 * math.pi / float(np.linalg.norm(omega)))
    ts = np.linspace(0.0, span, 301)
    w_num, R_num = _dop853(m.inertia, np.array(omega, dtype=float), ts)
    st = res.at(ts)
    wmag = np.linalg.norm(st.omega, axis=1)
    assert float(np.max(np.linalg.norm(st.omega - w_num, axis=1) / wmag)) < 1e-8
    dR = np.einsum("nji,njk->nik", st.rotation_matrix, R_num) - np.eye(3)
    assert float(np.max(np.abs(dR))) < 1e-8


def test_errors_are_the_cli_messages(cli):
    body = rbcli.load(ROOT / "examples/book.yaml")
    cases = [
        (dict(omega=None), ("examples/book.yaml",)),
        (dict(omega="1,2"), ("examples/book.yaml", "--omega", "1,2")),
        (dict(omega=[1, 0, 0], samples=1), ("examples/book.yaml", "--omega", "1,0,0", "--samples", "1",
                                            "--csv", "-", "--duration", "1")),
        (dict(omega=[1, 0, 0], duration="-1 s"), ("examples/book.yaml", "--omega", "1,0,0", "--duration=-1 s",
                                                  "--plot", "x.svg")),
        (dict(omega=[1, 0, 0], at="1e20"), ("examples/book.yaml", "--omega", "1,0,0", "--at", "1e20")),
        (dict(omega="1e200,0,0"), ("examples/book.yaml", "--omega", "1e200,0,0")),
    ]
    for kwargs, args in cases:
        r = cli("precess", *args)
        assert r.code == 2, (args, r.err)
        with pytest.raises(rbcli.InputError) as exc:
            rbcli.precess(body, **kwargs)
        assert r.err == f"rbcli: {exc.value.spelled(option_name)}\n", args
    with pytest.raises(TypeError, match="^samples: expected an int, got str$"):
        rbcli.precess(body, omega=[1, 0, 0], samples="x")  # a count is an int in Python
    point = rbcli.load_text("{shape: point, mass: 1}")
    with pytest.raises(rbcli.InputError, match="positive definite"):
        rbcli.precess(point, omega=[1, 0, 0])
