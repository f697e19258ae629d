"""``rbcli.balance`` and ``rbcli.field_balance``: the Python API is the command.

For every example body (default options) and every option set the README documents, the
API's ``to_json()`` equals what ``rbcli balance ... --json`` prints, less ``file``; errors
are InputErrors with the command line's message and the parameter at fault; the results
are frozen and carry typed fields.
"""

from __future__ import annotations

import dataclasses
import math

import pytest

import rbcli
from rbcli.errors import option_name
from rbcli.errors import InputError, NonFiniteResult, ParamError

from conftest import as_cli, EXAMPLES

BODIES = sorted(p.name for p in EXAMPLES.glob("*.yaml"))

#: (example, CLI arguments, API keyword arguments): the README's and the man page's command lines
DOCUMENTED = [
    ("car_wheel.yaml", ["--planes=-100,100mm", "--speed", "1500 rpm", "--bearings=-50,150mm"],
     dict(planes="-100,100mm", speed="1500 rpm", bearings="-50,150mm")),
    ("car_wheel.yaml", ["--planes=-100,100mm", "--speed", "1500 rpm", "--bearings=-50,150mm", "--grade",
                        "G40", "--mass-step", "5 g"],
     dict(planes="-100,100mm", speed="1500 rpm", bearings="-50,150mm", grade="G40", mass_step="5 g")),
    ("two_disk_rotor.yaml", ["--planes", "0,400mm", "--radius", "100mm", "--speed", "3000 rpm",
                             "--bearings", "0,400mm", "--grade", "G6.3"],
     dict(planes="0,400mm", radius="100mm", speed="3000 rpm", bearings="0,400mm", grade="G6.3")),
    ("fan_impeller.yaml", ["--bearings", "0,200mm", "--speed", "1480 rpm", "--grade", "G6.3"],
     dict(bearings="0,200mm", speed="1480 rpm", grade="G6.3")),
    ("fan_impeller.yaml", ["--planes", "320,380mm", "--radius", "190mm", "--bearings", "0,200mm",
                           "--speed", "1480 rpm", "--grade", "G6.3", "--positions", "6",
                           "--mass-step", "0.5 g"],
     dict(planes="320,380mm", radius="190mm", bearings="0,200mm", speed="1480 rpm", grade="G6.3",
          positions=6, mass_step="0.5 g")),
    ("car_wheel.yaml", ["--planes=-100,100mm", "--mass-step", "5 g"],
     dict(planes="-100,100mm", mass_step="5 g")),
    ("two_disk_rotor.yaml", ["--planes", "0,400mm", "--radius", "100mm", "--angle-sense", "against",
                             "--zero-mark-deg", "30", "--angle-step", "15", "--tolerance-planes",
                             "corrections", "--grade", "G2.5", "--speed", "3000 rpm"],
     dict(planes="0,400mm", radius="100mm", angle_sense="against", zero_mark_deg="30",
          angle_step="15", tolerance_planes="corrections", grade="G2.5", speed="3000 rpm")),
    ("two_disk_rotor.yaml", ["--shaft", "1,0,0", "--through", "com", "--mark", "0,0,1", "--g", "9.81"],
     dict(shaft="1,0,0", through="com", mark="0,0,1", g="9.81")),
    ("two_disk_rotor.yaml", ["--planes", "0,400", "--radius", "100,120", "--speed", "300",
                             "--bearings", "0,0.4 m"],  # bare lengths in the body's mm
     dict(planes=[0, 0.4], radius=[0.1, 0.12], speed=300, bearings=[0.0, 0.4])),
]

FIELD = [
    (["--initial", "6.0@30", "--trial", "10 g@0", "--run", "4.0@110"],
     dict(initial="6.0@30", trial="10 g@0", run="4.0@110")),
    (["--initial", "170@112,53@78", "--trial", "1.15 g@0", "--run", "235@94,58@68", "--trial", "1.15 g@0",
      "--run", "185@115,77@104"],
     dict(initial="170@112,53@78", trial=["1.15 g@0", "1.15 g@0"], run=["235@94,58@68", "185@115,77@104"])),
    (["--initial", "6.0@30", "--trial", "10 g@0", "--run", "4.0@110", "--trial-radius", "100mm",
      "--radius", "125mm"],
     dict(initial="6.0@30", trial="10 g@0", run="4.0@110", trial_radius="100mm", radius="125mm")),
    (["--initial", "10@0,10@0", "--trial", "5 g@0", "--run", "20@0,20@0", "--trial", "5 g@0", "--run",
      "20@1,20@0", "--cumulative"],
     dict(initial="10@0,10@0", trial=["5 g@0", "5 g@0"], run=["20@0,20@0", "20@1,20@0"], cumulative=True)),
    # readings with units (converted to SI) and a bare trial mass (grams)
    (["--initial", "6 mm@30", "--trial", "10@0", "--run", "4000 um@110"],
     dict(initial="6 mm@30", trial="10@0", run="4000 um@110")),
    (["--initial", "6.0 mm/s@30", "--trial", "10 g@0", "--run", "0.2 in/s@110"],
     dict(initial=["6.0 mm/s@30"], trial=["10 g@0"], run=["0.2 in/s@110"])),
]


def _without_file(d: dict) -> dict:
    return {k: v for k, v in d.items() if k != "file"}


@pytest.mark.parametrize("name", BODIES)
def test_every_example_with_default_options(cli, name):
    r = cli("balance", f"examples/{name}", "--json")
    res = rbcli.balance(rbcli.load(EXAMPLES / name))
    assert as_cli(res.to_json()) == _without_file(r.json())
    assert res.return_code == r.code == 0


@pytest.mark.parametrize("name, args, kwargs", DOCUMENTED)
def test_documented_option_sets(cli, name, args, kwargs):
    r = cli("balance", f"examples/{name}", *args, "--json")
    res = rbcli.balance(rbcli.load(EXAMPLES / name), **kwargs)
    assert as_cli(res.to_json()) == _without_file(r.json())
    assert res.return_code == r.code
    # the warnings the command prints are the result's, in order
    assert [ln.removeprefix("rbcli: warning: ") for ln in r.err.splitlines()] == list(res.warnings)


@pytest.mark.parametrize("args, kwargs", FIELD)
def test_field_balance_documented(cli, args, kwargs):
    r = cli("field-balance", *args, "--json")
    assert r.code == 0, r.err
    assert as_cli(rbcli.field_balance(**kwargs).to_json()) == r.json()


def test_typed_fields_and_frozen():
    body = rbcli.load(EXAMPLES / "two_disk_rotor.yaml")
    r = rbcli.balance(body, planes=[0.0, 0.4], radius=0.1, speed="3000 rpm", bearings="0,400 mm",
                      grade="G6.3")
    # the README's numbers: 8.5 g at 208.072° and 12.2577 g at 258.232°; FAIL as given
    a, b = r.corrections
    assert a.mass == pytest.approx(8.5e-3, rel=1e-6) and a.angle_deg == pytest.approx(208.072, abs=1e-3)
    assert b.mass == pytest.approx(12.2577e-3, rel=1e-5) and b.angle_deg == pytest.approx(258.232, abs=1e-3)
    assert r.options.speed == pytest.approx(3000 * math.pi / 30) and r.options.bearings == (0.0, 0.4)
    assert [b.plane for b in r.bearings] == [0.0, 0.4]  # the JSON's "bearings"
    assert r.iso_check is not None and not r.iso_check.passed and r.return_code == 1
    assert r.iso["pass"] is False and r.iso.grade == 6.3  # the JSON's "iso" ("pass" is a keyword)
    assert r.shaft_source == "the body's shaft" and r.radius_source == "radius"
    assert isinstance(r.warnings, tuple)
    assert [x.plane for x in r.added] == ["A", "B"] and r.corrected is not None
    assert r.corrected.static_unbalance < 1e-12
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.warnings = ()  # type: ignore[misc]
    # numbers are SI, strings are read as the command line reads them
    s = rbcli.balance(body, planes="0,400 mm", radius="100 mm", speed=3000 * math.pi / 30,
                      bearings=[0, 0.4], grade=6.3)
    assert s.to_json() == r.to_json()
    # the body's defaults and their provenance
    w = rbcli.balance(rbcli.load(EXAMPLES / "car_wheel.yaml"), planes="-100,100")  # the body's mm
    assert w.radius_source == "the body's rim_radius" and w.corrections[0].radius == 0.2


def test_field_typed_fields():
    r = rbcli.field_balance(initial="6.0@30", trial="10 g@0", run="4.0@110")
    (c,) = r.corrections
    # sheet §5.2 (T19): W = 9.0800 g @ 36.594°
    assert c.mass == pytest.approx(9.08e-3, rel=1e-4) and c.angle_deg == pytest.approx(36.594, abs=1e-3)
    assert r.planes == 1 and r.return_code == 0 and r.cond is None
    assert r.reading_kind is None and r.reading_unit is None
    u = rbcli.field_balance(initial="6 mm@30", trial="10 g@0", run="4000 um@110")
    assert u.reading_kind == "displacement" and u.reading_unit == "m"
    assert u.initial[0] == pytest.approx(0.006 * complex(math.cos(math.pi / 6), 0.5), rel=1e-15)
    assert u.corrections[0].mass == pytest.approx(c.mass, rel=1e-14)
    # the polar diagrams: a dial of readings (O, O+T, the trial's effect, the prediction), then the masses
    from rbcli.render.field.plot import plot
    from rbcli.render.units import ShopUnits

    fig = plot(u, ShopUnits(None), (1e-6, "µm"))
    assert [ax.get_title() for ax in fig.axes] == ["reading 1 [µm]", "plane A: masses [g]"]
    assert [t.get_text() for t in fig.axes[0].get_legend().get_texts()][0] == "O: 6000 µm at 30°"


@pytest.mark.parametrize("kwargs, param", [
    (dict(planes="0.1,0.1", radius="0.2"), "planes"),
    (dict(planes="0,0.4"), "planes"),  # no --radius and no rim_radius in the file
    (dict(radius="0.1"), "radius"),
    (dict(planes="0,0.1", radius="0.1", positions=2), "positions"),
    (dict(planes="0,0.1", radius="0.1", positions=10**18), "positions"),
    (dict(planes="0,0.1", radius="0.1", mass_step="1e-320"), "mass_step"),
    (dict(planes="0,0.1", radius="0.1", angle_step="1e-320"), "angle_step"),
    (dict(grade="G6.3", bearings="0,1"), "grade"),
    (dict(shaft="z", mark="0,0,1"), "mark"),
    (dict(shaft="0,0,0"), "shaft"),
    (dict(angle_sense="clockwise"), None),
    (dict(speed=0), "speed"),
])
def test_errors_are_the_command_lines(cli, kwargs, param):
    body = rbcli.load(EXAMPLES / "two_disk_rotor.yaml")
    with pytest.raises(InputError) as exc:
        rbcli.balance(body, **kwargs)
    args = []
    for k, v in kwargs.items():
        text = v if isinstance(v, str) else str(v)
        args.append(f"--{k.replace('_', '-')}={text}")
    r = cli("balance", "examples/two_disk_rotor.yaml", *args)
    assert r.code == 2 and r.err == f"rbcli: {exc.value.spelled(option_name)}\n"
    if param is not None:
        assert exc.value.param == param and exc.value.spelled(option_name).startswith(f"--{param.replace('_', '-')}: ")


def test_positions_blames_positions_not_planes(cli):
    # issue 15: a huge --positions used to blame --planes
    r = cli("balance", "examples/two_disk_rotor.yaml", "--planes", "0,0.4", "--radius", "0.1",
            "--positions", str(10**18))
    assert r.code == 2 and r.err.startswith("rbcli: --positions: ")


def test_overflow_is_a_non_finite_result():
    body = rbcli.load(EXAMPLES / "car_wheel.yaml")
    with pytest.raises(NonFiniteResult) as exc:
        rbcli.balance(body, planes="-100,100mm", speed="1e300 rpm", bearings="0,1")
    assert "the result overflows" in str(exc.value)


@pytest.mark.parametrize("kwargs, param", [
    (dict(initial="6@30", trial="0 g@0", run="4@110"), "trial"),
    (dict(initial="6@30", trial="10 g@0", run="6@30"), "run"),
    (dict(initial="6@30", trial="10 g@0", run=["4@110", "5@3"]), "run"),
    (dict(initial="1@0,1@0", trial=["1 g@0", "1 g@0"], run=["2@0,2@0", "3@0,3@0"]), "run"),
])
def test_field_errors(cli, kwargs, param):
    with pytest.raises(ParamError) as exc:
        rbcli.field_balance(**kwargs)
    assert exc.value.param == param
    args = []
    for k, v in kwargs.items():
        for x in ([v] if isinstance(v, str) else v):
            args += [f"--{k}", x]
    r = cli("field-balance", *args)
    assert r.code == 2 and r.err == f"rbcli: {exc.value.spelled(option_name)}\n"


def test_bearings_close_together_warn():
    """Bearings closer than 0.2 of the rotor's length are named with their span and that
    length (the forces are right, only large); the README's bearing sets are not."""
    b = rbcli.load(EXAMPLES / "fan_rotor.yaml")
    near = rbcli.balance(b, bearings="0,0.001 mm", speed="1480 rpm")
    (w,) = [str(x) for x in near.warnings if "apart" in str(x)]
    assert w.startswith("bearings 0.001 mm apart, less than 0.2 of the rotor's length along the shaft (")
    assert abs(near.bearing_forces[0].force) > 1e7  # ~1.1e8 N: the couple over 1 µm
    for name, _, kwargs in DOCUMENTED:
        if "bearings" in kwargs:
            r = rbcli.balance(rbcli.load(EXAMPLES / name), **kwargs)
            assert not [x for x in r.warnings if "apart" in str(x)], name
