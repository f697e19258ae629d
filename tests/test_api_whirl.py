"""``rbcli.whirl``: the Python API is the command; results are frozen values; invariants.

- the API's ``to_json()`` equals ``rbcli whirl ... --json`` less ``file`` for the
  documented command lines (README, man page);
- the result is frozen, its arrays read-only, its attribute names the JSON keys;
- bad input raises ParamError naming the parameter, never a ``--flag``;
- invariants (hypothesis): the frequencies, critical speeds and response amplitudes do
  not change when the body is turned about its shaft (isotropic bearings: the response
  phases turn with it), nor when body and bearings move along the shaft together, nor
  with the units the body is written in.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rbcli
from rbcli.errors import InputError, ParamError

from conftest import EXAMPLES, as_cli

CYL = "{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}"
DISK = "{shape: cylinder, radius: 0.3, length: 0.05, mass: 100}"
FAN = EXAMPLES / "fan_rotor.yaml"
FAN_ARGS = ["--bearings", "0,500mm", "--stiffness", "5 N/um", "--damping", "1 N*s/mm", "--speed",
            "1480 rpm", "--speed-range", "0,3000 rpm", "--orders", "1,2"]
FAN_KW = dict(bearings="0,500mm", stiffness="5 N/um", damping="1 N*s/mm", speed="1480 rpm",
              speed_range="0,3000 rpm", orders="1,2")

#: (body: a file or -e text, CLI arguments, API keyword arguments)
DOCUMENTED = [
    (CYL, ["--bearings=-0.2,0.2", "--stiffness", "1e6"], dict(bearings="-0.2,0.2", stiffness=1e6)),
    (DISK, ["--bearings=-0.1,0.1", "--stiffness", "2e6"], dict(bearings=[-0.1, 0.1], stiffness="2e6")),
    (FAN, FAN_ARGS, FAN_KW),
    (FAN, ["--bearings", "0,500", "--stiffness", "5e6,4e6", "--stiffness-y", "6e6", "--damping", "800",
           "--cross-stiffness", "2e5", "--speed", "1200,1600 rpm", "--points", "41",
           "--unbalance", "50 g*mm@0,30 g*mm@120", "--unbalance-planes", "710,800"],
     dict(bearings="0,500", stiffness=[5e6, 4e6], stiffness_y=6e6, damping=800.0, cross_stiffness="2e5",
          speed="1200,1600 rpm", points=41, unbalance=["50 g*mm@0", "30 g*mm@120"],
          unbalance_planes="710,800")),
]


def _load(src):
    return rbcli.load(src) if not isinstance(src, str) else rbcli.load_text(src, name="expr")


def _cli_body(src):
    return [str(src)] if not isinstance(src, str) else ["-e", src]


@pytest.mark.parametrize("src, args, kwargs", DOCUMENTED)
def test_api_json_is_the_commands(cli, src, args, kwargs):
    r = cli("whirl", *_cli_body(src), *args, "--json")
    res = rbcli.whirl(_load(src), **kwargs)
    d = r.json()
    assert d.pop("file") is not None
    assert as_cli(res.to_json()) == d  # warnings name options on the command line
    assert res.return_code == r.code
    assert [ln.split(": warning: ", 1)[1] for ln in r.err.splitlines()] == \
        [w.spelled(lambda p: "--" + p.replace("_", "-")) for w in res.warnings]


def test_result_is_a_frozen_value_with_read_only_arrays():
    res = rbcli.whirl(rbcli.load(FAN), **FAN_KW)
    with pytest.raises(dataclasses.FrozenInstanceError):
        res.speed = None  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        res.response.peaks = ()  # type: ignore[misc]
    for a in (res.campbell.speeds, res.campbell.frequencies, res.campbell.damping_ratio,
              res.response.speeds, res.response.bearings[0].displacement, res.response.bearings[1].force):
        assert isinstance(a, np.ndarray) and not a.flags.writeable
        with pytest.raises(ValueError):
            a[0] = 1.0
    d = res.to_json()
    # attribute names are the JSON keys (the hidden ones, for the tables, excepted)
    names = [f.name for f in dataclasses.fields(res) if f.metadata.get("json", True)]
    assert list(d) == names
    assert set(d["critical_speeds"][0]) == {f.name for f in dataclasses.fields(res.critical_speeds[0])}
    # SPEC §7: critical_speeds [{speed, mode, whirl}], campbell {speeds, frequencies, whirl, damping_ratio}
    for key in ("speed", "mode", "whirl"):
        assert key in d["critical_speeds"][0]
    for key in ("speeds", "frequencies", "whirl", "damping_ratio"):
        assert key in d["campbell"]
    assert len(d["campbell"]["frequencies"]) == 4 and len(d["campbell"]["frequencies"][0]) == len(d["campbell"]["speeds"])
    assert set(d["conventions"]) >= {"speeds", "frequencies", "whirl", "stiffness", "damping", "angles"}


def test_the_fan_example_numbers():
    """The README's fan: the header comment's numbers (computed here from the result, and
    the critical speeds independently from the body's mass properties by the closed form
    of an eigenproblem written out in tests/test_core_whirl.py is covered there)."""
    res = rbcli.whirl(rbcli.load(FAN), **FAN_KW)
    got = [(c.order, round(c.speed * 30 / math.pi, 1), c.mode, c.whirl) for c in res.critical_speeds]
    assert (1, 1958.8, "conical", "forward") in got and (1, 1715.0, "conical", "backward") in got
    fwd = [c for c in res.critical_speeds if c.order == 1 and c.whirl == "forward" and c.in_range][0]
    assert fwd.excited is True
    assert all(c.excited is False for c in res.critical_speeds if c.order == 1 and c.whirl == "backward")
    assert res.margins is not None and res.margins.passed is True and res.return_code == 0
    assert res.stability.stable_in_range and res.stability.stable_at_speed


@pytest.mark.parametrize("kwargs, param, says", [
    (dict(bearings="0", stiffness=1e6), "bearings", "two or more"),
    (dict(bearings="0.1,0.1", stiffness=1e6), "bearings", "all at one place"),
    (dict(bearings="0,0.1,0.1", stiffness=1e6), "bearings", "bearings 2 and 3 are both at"),
    (dict(bearings="-0.2,0.2", stiffness=-1e6), "stiffness", "must be positive"),
    (dict(bearings="-0.2,0.2", stiffness="1e6,0"), "stiffness", "bearing 2"),
    (dict(bearings="-0.2,0.2", stiffness="1e6,2e6,3e6"), "stiffness", "expected 1 or 2"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, damping=-5), "damping", "must not be negative"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, speed_range="100,100"), "speed_range", "empty range"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, speed_range="300,100"), "speed_range", "not a range"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, speed_range="-10,100"), "speed_range", "negative"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, speed_range="0"), "speed_range", "expected 2"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, speed=0), "speed", "positive"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, speed="200,100"), "speed", "min,max"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, orders="1,1.5"), "orders", "whole numbers"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, points=2), "points", "from 3"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, unbalance="1 g*mm@0"), "unbalance", "unbalance_planes"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, unbalance="1 g*mm@0", unbalance_planes="0,1"), "unbalance", "1 unbalance for 2 planes"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, unbalance="1 g*mm", unbalance_planes="0"), "unbalance", "amount@angle"),
    (dict(stiffness=1e6), "bearings", "needs the bearing positions"),
    (dict(bearings="-0.2,0.2"), "stiffness", "needs the bearing stiffness"),
    (dict(bearings="-0.2,0.2", stiffness="1e6 N"), "stiffness", "stiffness"),
    (dict(bearings="-0.2,0.2", stiffness=1e6, symmetry_tol="20 %"), "symmetry_tol", "must be from 0"),
    (dict(bearings="{ab}", stiffness=1e6), "bearings", "'{ab}' does not start with a number"),
])
def test_bad_values_name_the_parameter(kwargs, param, says):
    # a ParamError, or the option readers' InputError with ``param`` set
    with pytest.raises(InputError) as info:
        rbcli.whirl(rbcli.load_text(CYL), **kwargs)
    assert info.value.param == param
    assert says in str(info.value) and str(info.value).startswith(f"{param}: ")
    assert "--" not in str(info.value)
    if type(info.value) is not InputError:
        assert isinstance(info.value, ParamError)


def test_types_are_checked():
    with pytest.raises(TypeError):
        rbcli.whirl(rbcli.load_text(CYL), bearings="-0.2,0.2", stiffness=1e6, points=20.5)


def test_a_rotor_the_model_does_not_fit_is_refused_with_the_numbers():
    two_blades = ("{parts: [{shape: box, size: [0.6, 0.05, 0.02], mass: 2}, "
                  "{shape: cylinder, radius: 0.01, length: 0.4, mass: 0.5}]}")
    with pytest.raises(InputError) as info:
        rbcli.whirl(rbcli.load_text(two_blades), bearings="-0.15,0.15", stiffness=1e5)
    msg = str(info.value)
    assert "not symmetric about its shaft" in msg and "symmetry_tol" in msg and "--" not in msg
    point = "{shape: point, mass: 2}"
    with pytest.raises(InputError, match="no moment of inertia across"):
        rbcli.whirl(rbcli.load_text(point), bearings="-0.15,0.15", stiffness=1e5)


# --------------------------------------------------------------------- invariants

ROTOR = """
units: {{length: {L}, mass: kg}}
parts:
  - {{name: shaft, shape: cylinder, radius: {r_s}, length: {l_s}, mass: 12, at: [0, 0, {z_s}], rotate: {{axis: [0, 0, 1], angle: {turn}}}}}
  - {{name: disk, shape: cylinder, radius: {r_d}, length: {t_d}, mass: 20, at: [0, 0, {z_d}], rotate: {{axis: [0, 0, 1], angle: {turn}}}}}
  - {{name: spot, shape: point, mass: 0.01, at: [{x_p}, {y_p}, {z_d}]}}
"""


def _rotor_text(*, L="m", scale=1.0, turn=0.0, shift=0.0, r_d=0.2, z_d=0.5):
    c, s = math.cos(math.radians(turn)), math.sin(math.radians(turn))
    x, y = 0.15, 0.0
    return ROTOR.format(L=L, r_s=0.03 * scale, l_s=0.8 * scale, z_s=(0.4 + shift) * scale,
                        r_d=r_d * scale, t_d=0.04 * scale, z_d=(z_d + shift) * scale, turn=turn,
                        x_p=(c * x - s * y) * scale, y_p=(s * x + c * y) * scale)


KW = dict(stiffness=2e6, damping=300.0, speed_range="0,600", points=31, orders="1,2")


def _numbers(res):
    return (np.asarray(res.campbell.frequencies), [c.speed for c in res.critical_speeds],
            [np.asarray(b.displacement) for b in res.response.bearings])


@settings(max_examples=15, deadline=None)
@given(turn=st.floats(-180.0, 180.0), r_d=st.floats(0.08, 0.35), z_d=st.floats(0.3, 0.75))
def test_turning_the_body_about_its_shaft_changes_no_frequency(turn, r_d, z_d):
    a = rbcli.whirl(rbcli.load_text(_rotor_text(r_d=r_d, z_d=z_d)), bearings="0.1,0.6", **KW)
    b = rbcli.whirl(rbcli.load_text(_rotor_text(r_d=r_d, z_d=z_d, turn=turn)), bearings="0.1,0.6", **KW)
    fa, ca, ra = _numbers(a)
    fb, cb, rb = _numbers(b)
    # the same matrices up to the rotation's round-off in the tensor (~1e-16 relative), seen
    # through eigen-solves of condition ~1e3: 1e-10
    np.testing.assert_allclose(fb, fa, rtol=1e-10, atol=1e-10 * float(fa.max()))
    np.testing.assert_allclose(cb, ca, rtol=1e-10)
    for x, y in zip(ra, rb):
        np.testing.assert_allclose(y, x, rtol=1e-9, atol=1e-12 * float(x.max()))
    # the unbalance (the point mass) turned with the body: so did the high spot, by ``turn``
    for ba, bb in zip(a.response.bearings, b.response.bearings):
        d = (np.asarray(bb.displacement_phase_deg) - np.asarray(ba.displacement_phase_deg) - turn) % 360.0
        d = np.minimum(d, 360.0 - d)[1:]  # speed 0: no motion, no phase
        assert float(np.max(d)) < 1e-6


@settings(max_examples=10, deadline=None)
@given(shift=st.floats(-2.0, 2.0))
def test_moving_body_and_bearings_along_the_shaft_changes_nothing(shift):
    a = rbcli.whirl(rbcli.load_text(_rotor_text()), bearings="0.1,0.6", **KW)
    b = rbcli.whirl(rbcli.load_text(_rotor_text(shift=shift)), bearings=[0.1 + shift, 0.6 + shift], **KW)
    fa, ca, ra = _numbers(a)
    fb, cb, rb = _numbers(b)
    # bearing arms a_i = z_i - z_G lose ~eps |shift| / |a| to the subtraction: 1e-9
    np.testing.assert_allclose(fb, fa, rtol=1e-9, atol=1e-9 * float(fa.max()))
    np.testing.assert_allclose(cb, ca, rtol=1e-9)
    for x, y in zip(ra, rb):
        np.testing.assert_allclose(y, x, rtol=1e-8, atol=1e-10 * float(x.max()))


def test_the_units_a_body_is_written_in_change_nothing():
    a = rbcli.whirl(rbcli.load_text(_rotor_text()), bearings="0.1,0.6", **KW)
    b = rbcli.whirl(rbcli.load_text(_rotor_text(L="mm", scale=1000.0)), bearings="100,600", **KW)
    fa, ca, ra = _numbers(a)
    fb, cb, rb = _numbers(b)
    # mm -> m is exact per number (a power of ten, rounded once): the same rotor to ~1e-15
    np.testing.assert_allclose(fb, fa, rtol=1e-11)
    np.testing.assert_allclose(cb, ca, rtol=1e-11)
    for x, y in zip(ra, rb):
        np.testing.assert_allclose(y, x, rtol=1e-10, atol=1e-13 * float(x.max()))


def test_the_fan_critical_speeds_from_its_mass_properties_by_hand():
    """The fan's forward 1x critical speeds from rbcli.inertia's mass properties and the
    sheet's forward eigenproblem det(K_c - W^2 diag(m, It - Ip)) = 0, a quadratic in W^2
    written out here: (m (It - Ip)) W^4 - (m K11 + (It - Ip) K00) W^2 + det K = 0 with
    K = sum k [[1, a], [a, a^2]]. Round-off only (a quadratic formula): 1e-12."""
    body = rbcli.load(FAN)
    mp = rbcli.inertia(body, about="com")
    m, zG = mp.mass, mp.com[2]
    J = np.asarray(mp.inertia)
    It, Ip = 0.5 * (J[0, 0] + J[1, 1]), J[2, 2]
    k = 5e6
    K = sum(k * np.array([[1.0, a], [a, a * a]]) for a in (0.0 - zG, 0.5 - zG))
    A, B, C = m * (It - Ip), m * K[1, 1] + (It - Ip) * K[0, 0], np.linalg.det(K)
    roots = sorted(math.sqrt((B + s * math.sqrt(B * B - 4 * A * C)) / (2 * A)) for s in (-1, 1))
    res = rbcli.whirl(body, **FAN_KW)
    fwd = sorted(c.speed for c in res.critical_speeds if c.order == 1 and c.whirl == "forward")
    np.testing.assert_allclose(fwd, roots, rtol=1e-12)
    assert round(roots[0] * 30 / math.pi, 2) == 1958.84  # the README's and the header's digits


def test_every_json_key_is_an_attribute_with_its_value():
    """One vocabulary (issue 22): r.<key> is the JSON's value, nested values too."""
    from rbcli.api.result import jsonable

    r = rbcli.whirl(rbcli.load(FAN), **FAN_KW)
    d = r.to_json()
    for key, value in d.items():
        assert jsonable(getattr(r, key)) == value, key
    assert r.critical_speeds[0].speed == d["critical_speeds"][0]["speed"]
    assert r.margins.checks[0].required_margin_percent == d["margins"]["checks"][0]["required_margin_percent"]


def test_amplification_factor_by_half_power_where_it_exists_else_by_the_damping_ratio():
    """API 684: AF = Nc/(N2 - N1) where the response falls to 1/sqrt(2) of the peak on both
    sides before rising into another peak; where the bands overlap, AF = 1/(2 zeta) of the
    nearest driven critical speed's mode at its damped crossing (the basis said). Heavily
    damped (zeta ~ 0.22): AF < 2.5, critically damped, no margin needed."""
    body = rbcli.load_text(CYL)
    res = rbcli.whirl(body, bearings="-0.2,0.2", stiffness=1e6, damping=800, unbalance="50 g*mm@0",
                      unbalance_planes="0.15", speed="3000 rpm", speed_range="0,700")
    by_ratio = [p for p in res.response.peaks if p.basis == "damping ratio"]
    assert by_ratio and all(p.half_power is None for p in by_ratio)
    for p in by_ratio:
        crit = min((c for c in res.critical_speeds if c.order == 1 and c.excited),
                   key=lambda c: abs(c.damped_speed - p.speed))
        assert p.amplification_factor == pytest.approx(0.5 / crit.damping_ratio, rel=1e-12)
        assert p.mode == crit.mode
    checks = {(m.bearing, m.speed): m for m in res.margins.checks}
    for p in res.response.peaks:
        m = checks[(p.bearing, p.speed)]
        assert m.basis == p.basis and m.amplification_factor == p.amplification_factor
    heavy = rbcli.whirl(body, bearings="-0.2,0.2", stiffness=1e6, damping=2200, unbalance="50 g*mm@0",
                        unbalance_planes="0.3", speed="3000 rpm", speed_range="0,700")
    assert all(c.damping_ratio > 0.2 for c in heavy.critical_speeds)
    assert heavy.margins.checks and all(m.amplification_factor < 2.5 and m.required_margin_percent == 0.0
                                        and m.passed for m in heavy.margins.checks)


def test_bearings_from_the_body_file_and_options_over_them(cli):
    """examples/journal_rotor.yaml needs no options (its bearings: section and tables); the
    API is the command; an option overrides the coefficients it names at every speed and
    keeps the others; another number of --bearings drops the section."""
    path = EXAMPLES / "journal_rotor.yaml"
    r = cli("whirl", str(path), "--points", "21", "--json")
    res = rbcli.whirl(rbcli.load(path), points=21)
    assert as_cli(res.to_json()) == {k: v for k, v in r.json().items() if k != "file"}
    assert [b.name for b in res.bearings] == ["drive end", "non-drive end"]
    t = res.bearings[0].table
    assert t is not None and t.source.endswith("journal_bearing.csv") and len(t.speeds) == 12
    over = rbcli.whirl(rbcli.load(path), points=21, cross_stiffness=0, damping_xy="0")
    for b, ob in zip(res.bearings, over.bearings):
        assert list(ob.table.kxy) == [0.0] * 12 and list(ob.table.kyx) == [0.0] * 12
        assert list(ob.table.cxy) == [0.0] * 12
        assert list(ob.table.kxx) == list(b.table.kxx) and list(ob.table.cyx) == list(b.table.cyx)
    plain = rbcli.whirl(rbcli.load(path), bearings="100,500,900 mm", stiffness=2e7, points=21)
    assert all(b.table is None and b.name.startswith("bearing ") for b in plain.bearings)
    with pytest.raises(InputError, match="needs the bearing stiffness"):
        rbcli.whirl(rbcli.load(path), bearings="100,500,900 mm", points=21)
    data = rbcli.load_data({"parts": [{"shape": "cylinder", "radius": 0.1, "length": 0.6, "mass": 50}],
                            "bearings": [{"at": -0.2, "k": 1e6}, {"at": 0.2, "k": 1e6}]})
    assert [round(c.speed, 3) for c in rbcli.whirl(data).critical_speeds] == [200.0, 200.0, 206.559, 241.209]


def test_thresholds_and_critical_speeds_do_not_move_with_points():
    """Roots, not grid points: the onset of oil whip and the critical speeds are the same for
    21 and 401 speeds (to the root solve's 1e-12 of the speed)."""
    body = rbcli.load(EXAMPLES / "journal_rotor.yaml")
    a, b = rbcli.whirl(body, points=21), rbcli.whirl(body, points=401)
    assert a.stability.threshold_speed == pytest.approx(b.stability.threshold_speed, rel=1e-11)
    assert [t.change for t in a.stability.thresholds] == [t.change for t in b.stability.thresholds] == ["onset"]
    assert [c.speed for c in a.critical_speeds] == pytest.approx([c.speed for c in b.critical_speeds], rel=1e-11)


def test_an_undamped_rotor_exactly_at_a_critical_speed():
    # sqrt(2k/m) = sqrt(2e6/50) = 200 rad/s exactly: the cylindrical criticals (forward and
    # backward) of CYL on two 1e6 N/m bearings, where the dynamic stiffness is singular
    body = rbcli.load_text(CYL)
    kw = dict(bearings="-0.2,0.2", stiffness=1e6, speed=200)
    balanced = rbcli.whirl(body, **kw)  # nothing drives the mode: the response is zero
    assert all(a.displacement == 0.0 for a in balanced.response.at_speed)
    assert any("no critical speed is judged" in str(w) for w in balanced.warnings)
    with pytest.raises(InputError, match="200 rad/s is an undamped critical speed that the unbalance drives"):
        rbcli.whirl(body, unbalance="10 g*mm@0", unbalance_planes="0", **kw)
    # the fan's backward conical critical: synchronous unbalance does not drive a backward
    # mode, so the response there is finite and continuous with its neighbours'
    fan = rbcli.load(FAN)
    fkw = dict(bearings="0,500mm", stiffness="5 N/um")
    back = [c.speed for c in rbcli.whirl(fan, **fkw).critical_speeds if c.whirl == "backward"]
    at = rbcli.whirl(fan, speed=back[0], **fkw).response.at_speed[0].displacement
    near = rbcli.whirl(fan, speed=back[0] * (1 + 1e-9), **fkw).response.at_speed[0].displacement
    assert at == pytest.approx(near, rel=1e-6)  # 1e-9 off the critical moves a smooth response ~1e-9
