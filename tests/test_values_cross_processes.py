"""Values that cross processes (issue 34 item 4): a body, every result and every rbcli error
pickle and unpickle to equal values, still deeply immutable; a sweep through a process
pool gives the JSON of the same sweep in-process, and an error raised in a worker arrives
as itself (not ``BrokenProcessPool``).
"""

from __future__ import annotations

import dataclasses
import json
import multiprocessing
import pickle
from collections.abc import Mapping
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest

import rbcli
from conftest import EXAMPLES, sampled_params
from rbcli.errors import InputError, Location, NonFiniteResult, ParamError, RbcliError

CYLINDER = "{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}"

#: every public function that returns a result, called as a user would: (function, body file
#: or inline body or None, options, one option changed: a different value, an unequal result)
CASES = {
    "inertia": (rbcli.inertia, "cube.yaml", dict(omega="0,0,300 rpm"), dict(omega="0,0,301 rpm")),
    "principal": (rbcli.principal, "square_lamina.yaml", {}, dict(about="origin")),
    "balance": (rbcli.balance, "two_disk_rotor.yaml", dict(planes="0,400 mm", radius="100 mm", speed="3000 rpm",
                                                        bearings="-50,450 mm", grade="G6.3"), dict(radius="101 mm")),
    "field_balance": (rbcli.field_balance, None, dict(initial="6.0@30", trial="10 g@0", run="4.0@110"),
                      dict(run="4.0@111")),
    "precess": (rbcli.precess, "book.yaml", dict(omega=[0.01, 1, 0.01], at=2), dict(at=3)),
    "top": (rbcli.top, "top.yaml", dict(spin=150, theta=30), dict(theta=31)),
    "gyrocompass": (rbcli.gyrocompass, "gyroscope.yaml", dict(spin="6000 rpm", latitude=30), dict(latitude=31)),
    "rollcheck": (rbcli.rollcheck, "penny.yaml", dict(rolling_speed="10 cm/s"), dict(rolling_speed="11 cm/s")),
    "whirl": (rbcli.whirl, CYLINDER, dict(bearings="-0.2,0.2", stiffness=1e6, points=11), dict(stiffness=2e6)),
    "report": (rbcli.report, "top.yaml", dict(spin=150, theta=30), dict(theta=31)),
}


def call(name: str, changed: bool = False):
    fn, src, kwargs, change = CASES[name]
    body = () if src is None else (rbcli.load_text(src) if src.startswith("{") else rbcli.load(EXAMPLES / src),)
    return fn(*body, **{**kwargs, **(change if changed else {})})


#: bodies of every kind of part: primitives, a given tensor, a mesh, includes, units
BODIES = ["cube.yaml", "two_disk_rotor.yaml", "cad_block.yaml", "housing.yaml", "rotor_mm.yaml",
          "spoked_wheel.yaml", "top.yaml"]


def same(a, b, path="") -> None:
    """``a`` and ``b`` are equal values, deeply: the same types, arrays equal (NaN where
    NaN), the fields of dataclasses, the items of mappings and sequences, other values by
    ``==``; and every array of ``b`` is read-only."""
    assert type(a) is type(b), f"{path}: {type(a).__name__} != {type(b).__name__}"
    if isinstance(a, np.ndarray):
        assert not b.flags.writeable, f"{path}: a writable array after unpickling"
        assert a.dtype == b.dtype and np.array_equal(a, b, equal_nan=a.dtype.kind in "fc"), path
    elif dataclasses.is_dataclass(a):
        for f in dataclasses.fields(a):
            if f.compare:  # (a Param's check, a function, is not part of its value)
                    same(getattr(a, f.name), getattr(b, f.name), f"{path}.{f.name}")
    elif isinstance(a, Mapping):
        assert list(a) == list(b), path
        for k in a:
            same(a[k], b[k], f"{path}[{k!r}]")
    elif isinstance(a, (list, tuple)):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            same(x, y, f"{path}[{i}]")
    elif isinstance(a, float) and a != a:
        assert b != b, path
    else:
        assert a == b, f"{path}: {a!r} != {b!r}"


def roundtrip(value):
    return pickle.loads(pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL))


@pytest.mark.parametrize("name", BODIES)
def test_a_body_pickles_to_an_equal_read_only_body(name):
    body = rbcli.load(EXAMPLES / name)
    back = roundtrip(body)
    same(body, back)
    with pytest.raises(ValueError):  # read-only
        back.parts[0].com[0] = 1.0
    with pytest.raises(TypeError):
        back.units["length"] = "km"  # type: ignore[index]
    # the mass properties the loader left on the body come along: the same numbers, bit for bit
    assert rbcli.inertia(back).to_json() == rbcli.inertia(body).to_json()


@pytest.mark.parametrize("name", list(CASES))
def test_every_result_pickles_to_an_equal_frozen_value(name):
    result = call(name)
    back = roundtrip(result)
    same(result, back)
    assert json.dumps(back.to_json()) == json.dumps(result.to_json())
    assert back.return_code == result.return_code
    for f in dataclasses.fields(back):  # still deeply immutable
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(back, f.name, None)


@pytest.mark.parametrize("name", sorted(p.name for p in EXAMPLES.glob("*.yaml")))
def test_a_body_equals_itself_pickled_and_loaded_again_and_not_a_changed_one(name):
    body = rbcli.load(EXAMPLES / name)
    assert body == roundtrip(body) and body == rbcli.load(EXAMPLES / name)
    assert not body != rbcli.load(EXAMPLES / name)
    part = body.parts[0]  # one array element changed by 1e-12 m: unequal (arrays by value)
    nudged = dataclasses.replace(part, com=part.com + [1e-12, 0, 0])
    assert body != dataclasses.replace(body, parts=(nudged, *body.parts[1:]))
    with pytest.raises(TypeError, match="unhashable"):
        hash(body)


def test_a_body_changed_by_replace_is_unequal():
    body = rbcli.load(EXAMPLES / "two_disk_rotor.yaml")
    assert body.replace(0) == body.replace(0) and body.replace(0, mass=3) != body.replace(0)


@pytest.mark.parametrize("name", list(CASES))
def test_a_result_equals_itself_pickled_and_made_again_and_not_one_of_another_option(name):
    result = call(name)
    assert result == roundtrip(result) and result == call(name)
    assert result != call(name, changed=True) and not result == call(name, changed=True)
    assert result != rbcli.load(EXAMPLES / "cube.yaml")  # another type
    with pytest.raises(TypeError, match="unhashable"):
        hash(result)


def test_value_equality_takes_nan_as_nan_and_arrays_by_shape_and_value():
    from rbcli.body.partmodel import same

    nan = float("nan")
    assert same((nan, np.array([1.0, nan])), (nan, np.array([1.0, nan])))
    assert not same(np.zeros(3), np.zeros((1, 3))) and not same(np.zeros(3), (0.0, 0.0, 0.0))
    assert same({"a": [np.arange(2)]}, {"a": [np.arange(2)]}) and not same({"a": 1}, {"b": 1})
    assert same(np.array(["x"]), np.array(["x"]))  # a text array: no NaN test (it would raise)


def test_a_read_only_mapping_in_a_result_stays_read_only_and_pickles():
    from rbcli.api.result import Record, frozen

    m = frozen({"a": np.arange(3.0), "b": [1, {"c": 2}]})
    with pytest.raises(TypeError):
        m["a"] = 1  # type: ignore[index]
    assert not m["a"].flags.writeable and m["b"][1]["c"] == 2
    back = roundtrip(m)
    same(m, back)
    refrozen = frozen(back)
    assert not refrozen["a"].flags.writeable
    rec = roundtrip(Record({"angle_deg": 3.0}))
    assert rec.angle_deg == 3.0 and rec == {"angle_deg": 3.0}


def _errors() -> list[BaseException]:
    """One instance of every rbcli error class (the hierarchy, walked)."""
    from rbcli.api.result import jsonable
    from rbcli.interrupts import Terminated
    from rbcli.io.reader import ReadError, read_regular

    try:
        jsonable({"a": [1.0, float("nan")]})
    except NonFiniteResult as exc:
        nonfinite = exc
    made = [
        InputError("{speed}: too fast", Location("r.yaml", 3, 7), param="speed"),
        ParamError("planes", "the two planes must differ", Location("job.yaml", 2)),
        NonFiniteResult("a result is not finite"),
        nonfinite,
        ReadError("missing.yaml", "no such file"),
        Terminated(15),
    ]
    seen = {type(e) for e in made}

    def walk(cls):
        for sub in cls.__subclasses__():
            yield sub
            yield from walk(sub)

    for cls in set(walk(RbcliError)) - seen:  # any other: made as a ParamError is
        e = (OSError if issubclass(cls, OSError) else Exception).__new__(cls, "{x}: why")
        RbcliError.__init__(e, "{x}: why", Location("f", 1, 2))
        e.param = "x"
        made.append(e)
    try:  # an error that is an OSError too, with its errno and file name
        read_regular("/no/such/file.yaml", 100)
    except ReadError as exc:
        made.append(exc)
    return made


@pytest.mark.parametrize("error", _errors(), ids=lambda e: type(e).__name__)
def test_every_error_pickles_with_its_message_location_and_parameter(error):
    back = roundtrip(error)
    assert type(back) is type(error)
    assert str(back) == str(error) and back.args == error.args
    for attr in ("message", "where", "param", "template", "reason", "path", "signum", "errno", "filename"):
        if hasattr(error, attr):
            assert getattr(back, attr) == getattr(error, attr), attr
    if isinstance(error, RbcliError):
        from rbcli.errors import option_name

        assert back.spelled(option_name) == error.spelled(option_name)


# ----------------------------------------------------------------------------- a process pool


def _spin_sweep(body, spin):
    """A worker's job: the top at one spin (body and result cross the process boundary)."""
    return rbcli.top(body, spin=spin, theta=30)


@pytest.mark.parametrize("start", sampled_params(["fork", "spawn"], lambda m: m == "fork"))
def test_a_sweep_through_a_process_pool_gives_the_json_of_the_same_sweep_in_process(start):
    body = rbcli.load(EXAMPLES / "top.yaml")
    spins = ["100 rpm", 150, "2000 rpm", 80.5]
    here = [json.dumps(_spin_sweep(body, s).to_json()) for s in spins]
    # either way the arguments and the results are pickled (the pool's queues); spawn's
    # workers are new interpreters too (~1.5 s to start: the full run only)
    with ProcessPoolExecutor(2, mp_context=multiprocessing.get_context(start)) as pool:
        results = list(pool.map(_spin_sweep, [body] * len(spins), spins))
        with pytest.raises(InputError) as info:
            pool.submit(_spin_sweep, body, "fast").result()
    assert [json.dumps(r.to_json()) for r in results] == here
    err = info.value
    assert type(err) is ParamError and err.param == "spin" and str(err).startswith("spin: ")
