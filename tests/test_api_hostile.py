"""The Python API under hostile callers (issue 27 item 1; issue 22 items 2 and 5).

Every public function of ``rbcli.__all__`` and every method of a result that takes
arguments is driven with the hostile argument classes of the audit — None, a dict, a path
string, an int, a bool, a namespace, a huge int, NaN and inf, -0.0, cyclic containers, numpy
subclasses and 0-d arrays, a huge array, bytes, objects whose ``__float__``, ``__index__`` or
``__len__`` raise — one parameter at a time, the others valid. Only a result, a
``TypeError`` or an ``rbcli.InputError`` may come out; an error names the parameter; no
message and no warning speaks the command line's ``--flags`` (issue 22 item 2: outside quoted
user text); a huge argument is refused by its size, quickly. Eight threads calling at once get
what one thread gets, errors included.
"""

from __future__ import annotations

import inspect
import itertools
import math
import re
import threading
import time
import types
from collections.abc import Sequence

import numpy as np
import pytest

import rbcli
from conftest import EXAMPLES, sample, sampled_params


class BadFloat(float):
    """A float whose __float__ raises."""

    def __float__(self):
        raise RuntimeError("__float__ says no")


class BadIndex:
    """An integer-like object whose __index__ raises."""

    def __index__(self):
        raise RuntimeError("__index__ says no")


class BadLen(list):
    """A list whose __len__ raises."""

    def __len__(self):
        raise RuntimeError("__len__ says no")


class HugeSeq(Sequence):
    """A sequence that says it has 10^12 items (reading them would never end)."""

    def __len__(self):
        return 10**12

    def __getitem__(self, i):
        if not 0 <= i < 10**12:
            raise IndexError(i)
        return 0.0


class SubArray(np.ndarray):
    """A numpy subclass."""


def _cyclic_list():
    c: list = [1.0]
    c.append(c)
    return c


def _cyclic_dict():
    d: dict = {}
    d["d"] = d
    return d


HOSTILE = {
    "None": None,
    "dict": {"parts": [{"shape": "point", "mass": 1}]},
    "str-path": str(EXAMPLES / "cube.yaml"),
    "int": 5,
    "bool": True,
    "namespace": types.SimpleNamespace(x=1.0),
    "huge-int": 10**400,
    "huge-int-str-limit": 10**5000,
    "nan": math.nan,
    "inf": math.inf,
    "-inf": -math.inf,
    "-0.0": -0.0,
    "1e300": 1e300,
    "-1e300": -1e300,
    "1e-300": 1e-300,
    "huge-str-number": "1e300 m",
    "cyclic-list": _cyclic_list(),
    "cyclic-dict": _cyclic_dict(),
    "matrix": np.array([[1.0, 2.0, 3.0]]).view(np.matrix),  # np.matrix() warns; the class is the point
    "subarray": np.arange(3.0).view(SubArray),
    "masked": np.ma.array([1.0, 2.0, 3.0], mask=[False, True, False]),
    "0-d": np.array(2.0),
    "0-d-object": np.array(None, dtype=object),
    "np-float32": np.float32(2.5),
    "np-int64": np.int64(7),
    "np-bool": np.bool_(True),
    "object-array": np.array([1, "a", None], dtype=object),
    "huge-array": np.zeros(10**7),
    "huge-list": [0.0] * (10**6 + 1),  # one more than the most times at(t) takes
    "huge-seq": HugeSeq(),
    "huge-str": "1," * 10**6,
    "huge-str-list": ["1" * 9_999] * 10_000,  # each string short enough, 10^8 characters in all
    "bytes": b"1,0,0",
    "bad-float": BadFloat(1.0),
    "bad-index": BadIndex(),
    "bad-len": BadLen([1.0, 2.0, 3.0]),
    "nested": [[1.0, 2.0], [3.0]],
    "nan-list": [math.nan, 0.0, 1.0],
    "escape": "\x1b[31m1\n2",
    "braces": "{spin} {{",
    "flag-text": "--spin",
    "complex": 1 + 2j,
    "set": {1.0, 2.0, 3.0},
    "generator": (x for x in (1.0, 2.0, 3.0)),
}

_BODIES: dict[str, rbcli.Body] = {}


def body(name: str) -> rbcli.Body:
    if name not in _BODIES:
        _BODIES[name] = rbcli.load(EXAMPLES / name)
    return _BODIES[name]


CYLINDER = "{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}"

#: function -> (the body's file or None, the valid keyword arguments, the parameters to
#: drive); the body is the first positional argument
CALLS = {
    "inertia": ("cube.yaml", {}, ["body", "about", "axis", "omega"]),
    "principal": ("square_lamina.yaml", {}, ["body", "about"]),
    "balance": ("two_disk_rotor.yaml", dict(planes="0,400 mm", radius="100 mm"),
                ["body", "shaft", "through", "mark", "zero_mark_deg", "angle_sense", "planes",
                 "radius", "mass_step", "angle_step", "positions", "speed", "bearings", "g",
                 "grade", "tolerance_planes"]),
    "field_balance": (None, dict(initial="6.0@30", trial="10 g@0", run="4.0@110"),
                      ["initial", "trial", "run", "cumulative", "trial_radius", "radius", "job",
                       "method", "weights", "mass_step", "angle_step", "positions", "phase",
                       "angle_sense", "rotation", "measure", "severity", "group", "foundation",
                       "coefficients", "suggest_trial", "rotor_mass", "rotor", "bearing_load",
                       "trial_fraction", "speed", "full", "drawer", "max_weights", "max_mass", "limit",
                       "robust"]),
    "whirl": (CYLINDER, dict(bearings="-0.2,0.2", stiffness=1e6, points=11),
              ["body", "bearings", "stiffness", "stiffness_y", "cross_stiffness", "stiffness_xy",
               "stiffness_yx", "damping", "damping_y", "damping_xy", "damping_yx", "speed_range",
               "points", "orders", "map_stiffness", "speed", "unbalance", "unbalance_planes",
               "shaft", "through", "symmetry_tol"]),
    "precess": ("book.yaml", dict(omega=[0.01, 1, 0.01]),
                ["body", "omega", "at", "duration", "samples", "verify"]),
    "top": ("top.yaml", dict(spin=150, theta=30),
            ["body", "pivot", "spin", "theta", "theta_dot", "phi_dot", "g", "verify",
             "symmetry_tol", "duration", "samples"]),
    "gyrocompass": ("gyroscope.yaml", dict(spin="6000 rpm", latitude=30),
                    ["body", "ratio", "shaft", "spin", "latitude", "earth_rate", "symmetry_tol"]),
    "rollcheck": ("penny.yaml", dict(rolling_speed="10 cm/s"),
                  ["body", "shaft", "through", "rim_radius", "tyre_radius", "g", "rolling_speed",
                   "spin", "lean", "circle", "symmetry_tol"]),
    "report": ("top.yaml", dict(spin=150, theta=30),
               ["body", "shaft", "through", "planes", "radius", "bearings", "grade", "speed",
                "stiffness", "damping", "omega", "pivot", "spin", "theta", "theta_dot",
                "phi_dot", "rim_radius", "tyre_radius", "g", "symmetry_tol"]),
    "report_text": ("top.yaml", dict(spin=150, theta=30, format="md"),
                    ["body", "format", "digits", "units", "spin"]),
    "write_report": ("top.yaml", dict(spin=150, theta=30),
                     ["body", "path", "force", "format", "digits", "units", "progress", "spin"]),
}

#: report_text's and write_report's **options: report's parameters
KINDS_OF_REPORT = set(CALLS["report"][2])

#: the parameters not to be driven with a verify=True-like flag value that runs a long check
SLOW_VALID = {("top", "verify"), ("precess", "verify")}


def _base(name: str) -> tuple[rbcli.Body | None, dict]:
    src, kw, _ = CALLS[name]
    b = None if src is None else (rbcli.load_text(src) if src.startswith("{") else body(src))
    return b, dict(kw)


def _quoted_out(text: str) -> str:
    """``text`` without the user's text it quotes ('...')."""
    return re.sub(r"'[^']*'", "''", text)


_COUNTER = itertools.count()


def _call(name: str, param: str, value, tmp_path) -> tuple[str, str, bool]:
    """(outcome, text, located): "ok" and the warnings, or the exception's class and
    message (located: an error in a file the argument names)."""
    b, kw = _base(name)
    args: list = [] if CALLS[name][0] is None else [b]
    if name == "write_report":
        args.append(tmp_path / f"r{next(_COUNTER)}.md")
    if param == "body":
        args[0] = value
    elif param == "path":
        args[1] = value
    else:
        kw[param] = value
    try:
        r = getattr(rbcli, name)(*args, **kw)
    except TypeError as exc:
        return "TypeError", str(exc), False
    except rbcli.InputError as exc:
        return "InputError", str(exc), exc.where is not None
    warnings = " | ".join(str(w) for w in getattr(r, "warnings", ()) or ())
    return "ok", warnings, False


def _names(text: str, param: str) -> bool:
    return re.search(rf"(?<![a-z_]){param}(?![a-z_])", text) is not None


def _check(name: str, param: str, key: str, outcome: str, text: str, seconds: float,
           located: bool = False, others: tuple[str, ...] = ()) -> None:
    """A TypeError names the parameter; an InputError names it, or — for a value of the
    right type that asks for something else — the parameter it needs (``others``: the
    function's parameters), or is located in a file the argument names."""
    where = f"{name}({param}={key})"
    if outcome == "TypeError":
        assert _names(text, param), f"{where}: the message does not name {param}: {text}"
    elif outcome == "InputError" and not located:
        assert any(_names(text, p) for p in (param, *others)), \
            f"{where}: the message names no parameter: {text}"
    assert "--" not in _quoted_out(text), f"{where}: {text}"
    assert len(text) < 3000, f"{where}: a message of {len(text)} characters"
    if key.startswith("huge"):
        assert seconds < 2.0, f"{where}: {seconds:.1f} s for a value refused by its size"


def _drive(name: str, param: str, tmp_path) -> list[str]:
    """Call ``name`` with each hostile value of ``param``; the failures, in words."""
    bad = []
    for key, value in HOSTILE.items():
        if (name, param) in SLOW_VALID and key in ("bool", "np-bool"):
            continue  # verify=True: a valid value, a numerical integration (tested elsewhere)
        if key == "generator":
            value = (x for x in (1.0, 2.0, 3.0))  # a fresh one each time
        t0 = time.perf_counter()
        try:
            outcome, text, located = _call(name, param, value, tmp_path)
        except BaseException as exc:  # noqa: BLE001 - what the test is looking for
            bad.append(f"{name}({param}={key}): {type(exc).__name__}: {str(exc)[:300]}")
            continue
        try:
            _check(name, param, key, outcome, text, time.perf_counter() - t0, located,
                   tuple(CALLS[name][2]) + tuple(CALLS[name][1]))
        except AssertionError as exc:
            bad.append(str(exc)[:500])
    return bad


#: the (function, parameter) pairs: every parameter; report's options are the services',
#: driven through report by default (a report runs every section: the rest in the full run)
PAIRS = [(f, p) for f, (_, _, ps) in CALLS.items() for p in ps]
_CHEAP = {"inertia", "principal", "balance", "field_balance", "precess", "top", "gyrocompass",
          "rollcheck", "whirl"}


def _kept(pair) -> bool:
    f, p = pair  # report_text's and write_report's spin: report's (its own pair), 5 s each
    return f in _CHEAP or p in ("body", "format", "digits", "units", "path", "force",
                                "progress", "planes", "omega") or (f, p) == ("report", "spin")


@pytest.mark.parametrize("pair", sampled_params(PAIRS, _kept, ids=lambda v: f"{v[0]}-{v[1]}"))
def test_hostile_arguments_give_a_type_error_or_an_input_error(pair, tmp_path):
    name, param = pair
    bad = _drive(name, param, tmp_path)
    assert not bad, "\n".join(bad)


def test_every_public_function_and_parameter_is_driven():
    # load and load_text read files and text (tests/test_hostile_inputs.py drives them),
    # load_data Python data (tests/test_api_load_data.py drives it with hostile mappings)
    functions = ({n for n in rbcli.__all__ if inspect.isfunction(getattr(rbcli, n))}
                 - {"load", "load_text", "load_data"})
    assert functions == set(CALLS)
    for name, (_, _, driven) in CALLS.items():
        params = {p.name for p in inspect.signature(getattr(rbcli, name)).parameters.values()
                  if p.kind is not inspect.Parameter.VAR_KEYWORD}
        assert params <= set(driven) | {"options"}, (name, params - set(driven))
        assert set(driven) <= params | set(KINDS_OF_REPORT), name


def test_the_hostile_classes_are_what_the_audit_names():
    # the test can fail: each class reaches the door as what it claims to be
    assert isinstance(HOSTILE["subarray"], np.ndarray) and type(HOSTILE["subarray"]) is not np.ndarray
    assert HOSTILE["0-d"].shape == () and HOSTILE["huge-array"].size == 10**7
    with pytest.raises(RuntimeError):
        float(HOSTILE["bad-float"])
    with pytest.raises(RuntimeError):
        len(HOSTILE["bad-len"])
    c = HOSTILE["cyclic-list"]
    assert c[1] is c


# ----------------------------------------------------------------------------- methods


def _results():
    return {
        "precess": rbcli.precess(body("book.yaml"), omega=[0.01, 1, 0.01], duration=1),
        "top": rbcli.top(body("top.yaml"), spin=150, theta=30),
        "inertia": rbcli.inertia(body("cube.yaml")),
        "report": rbcli.report(body("top.yaml"), spin=150, theta=30),
    }


METHODS = [
    ("precess", "at", "t"), ("precess", "series", "duration"), ("precess", "series", "samples"),
    ("precess", "series_blocks", "duration"), ("precess", "series_blocks", "samples"),
    ("top", "at", "t"), ("top", "sample", "duration"), ("top", "sample", "points"),
    ("inertia", "inertial", "principal"), ("report", "section", "key"),
]


@pytest.mark.parametrize("kind, method, param", METHODS, ids=lambda v: str(v))
def test_result_methods_check_their_arguments(kind, method, param):
    r = _results()[kind]
    valid = {"duration": 1.0, "samples": 3, "points": 3, "t": 0.5, "principal": False, "key": "parts"}
    bad = []
    for key, value in HOSTILE.items():
        if key == "generator":
            value = (x for x in (1.0, 2.0, 3.0))
        kw = {param: value}
        if method in ("series", "series_blocks", "sample"):
            other = {"series": "samples", "series_blocks": "samples", "sample": "points"}[method]
            if param != "duration":
                kw["duration"] = valid["duration"]
            elif other not in kw:
                kw[other] = 3
        t0 = time.perf_counter()
        try:
            out = getattr(r, method)(**kw)
            if method == "series_blocks":
                list(out)
            outcome, text = "ok", ""
        except TypeError as exc:
            outcome, text = "TypeError", str(exc)
        except rbcli.InputError as exc:
            outcome, text = "InputError", str(exc)
        except KeyError as exc:  # section(): a key no section has is a KeyError, as in a mapping
            outcome, text = ("ok", "") if method == "section" else ("KeyError", str(exc))
            if method != "section":
                bad.append(f"{method}({param}={key}): KeyError {exc}")
        except BaseException as exc:  # noqa: BLE001 - what the test is looking for
            bad.append(f"{method}({param}={key}): {type(exc).__name__}: {str(exc)[:300]}")
            continue
        try:
            _check(f"{kind}.{method}", param, key, outcome, text, time.perf_counter() - t0)
        except AssertionError as exc:
            bad.append(str(exc)[:500])
    assert not bad, "\n".join(bad)


def test_methods_without_arguments_still_work():
    b = body("penny.yaml")
    assert rbcli.rollcheck(b, rolling_speed="10 cm/s").curves() is not None
    assert rbcli.balance(body("two_disk_rotor.yaml"), planes="0,400 mm", radius="100 mm").diagram().panels


def test_at_refuses_non_finite_times_naming_t():
    r = rbcli.precess(body("book.yaml"), omega=[0.01, 1, 0.01])
    for t in (math.nan, math.inf, [0.0, math.nan]):
        with pytest.raises(rbcli.InputError, match="^t: ") as info:
            r.at(t)
        assert isinstance(info.value, ValueError)
    top = rbcli.top(body("top.yaml"), spin=150, theta=30)
    with pytest.raises(rbcli.InputError, match="^t: "):
        top.at(np.array([[0.0, math.inf]]))
    # a time and a quantity string mean the same instant
    assert np.array_equal(r.at("2 min").omega, r.at(120.0).omega)
    assert top.at(np.zeros((2, 3))).theta.shape == (2, 3)  # any shape, as documented


def test_a_flag_is_a_bool(tmp_path):
    out = tmp_path / "e.html"
    out.write_text("keep me")
    for bad in ("false", "no", "0", 0, 1, None, "True"):
        with pytest.raises(TypeError, match="^force: expected True or False"):
            rbcli.write_report(body("top.yaml"), out, force=bad, spin=150, theta=30)
    assert out.read_text() == "keep me"  # nothing computed, nothing written
    with pytest.raises(TypeError, match="^verify: "):
        rbcli.top(body("top.yaml"), spin=150, theta=30, verify="false")


def test_a_huge_array_is_refused_by_its_size_in_one_short_line():
    b = body("cube.yaml")
    t0 = time.perf_counter()
    with pytest.raises(rbcli.InputError) as info:
        rbcli.inertia(b, about=np.zeros(10**7))
    assert time.perf_counter() - t0 < 1.0  # by the size, not by reading 10^7 numbers (~3 s)
    text = str(info.value)
    assert text.startswith("about: ") and "10000000" in text and len(text) < 200


def test_a_huge_int_is_an_input_error_not_an_overflow():
    with pytest.raises(rbcli.InputError, match="^spin: an integer of about 401 digits"):
        rbcli.top(body("top.yaml"), spin=10**400, theta=30)


@pytest.mark.sampled
def test_eight_threads_get_the_answers_of_one_hostile_or_not(tmp_path):
    pairs = [("inertia", "about"), ("balance", "positions"), ("top", "spin"), ("precess", "at"),
             ("rollcheck", "lean"), ("gyrocompass", "latitude")]
    keys = list(HOSTILE)[: sample(12, len(HOSTILE))]

    def outcomes():
        got = []
        for name, param in pairs:
            for key in keys:
                value = HOSTILE[key] if key != "generator" else (x for x in (1.0, 2.0, 3.0))
                got.append(_call(name, param, value, tmp_path))
        return got

    expected = outcomes()
    results: dict[int, list] = {}
    errors: list[BaseException] = []
    start = threading.Barrier(8)

    def work(i: int) -> None:
        try:
            start.wait()
            results[i] = outcomes()
        except BaseException as exc:  # noqa: BLE001 - reported below
            errors.append(exc)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=600)
    assert not errors, errors
    assert len(results) == 8 and all(got == expected for got in results.values())


# ----------------------------------------------------------------------------- hand-made bodies


def _handmade() -> dict[str, tuple[rbcli.Body, str]]:
    """Bodies made in code that hold what no loaded body holds (issue 34 item 3), and what
    the refusal must say."""
    import dataclasses

    b = body("top.yaml")
    p = b.parts[0]

    def with_part(**kw):
        return dataclasses.replace(b, parts=(dataclasses.replace(p, **kw), *b.parts[1:]))

    return {
        "no-parts": (dataclasses.replace(b, parts=()), "no parts"),
        "nan-mass": (with_part(mass=math.nan), "part 1: its mass is nan"),
        "negative-mass": (with_part(mass=-1.0), "part 1: its mass is -1.0"),
        "text-mass": (with_part(mass="1"), "part 1: its mass is '1'"),
        "2x2-tensor": (with_part(inertia_com=np.eye(2)), "part 1: its inertia_com is not a finite (3, 3)"),
        "nan-com": (with_part(com=np.array([math.nan, 0, 0])), "part 1: its com is not a finite (3,)"),
        "None-part": (dataclasses.replace(b, parts=(None,)), "part 1 is NoneType, not a Part"),
        "nan-reference": (dataclasses.replace(b, reference=np.array([0, math.nan, 0])), "reference"),
        "2-pivot": (dataclasses.replace(b, pivot=np.zeros(2)), "pivot"),
        "text-shaft": (dataclasses.replace(b, shaft="z"), "shaft"),
        "nan-rim": (dataclasses.replace(b, rim_radius=math.nan), "rim_radius is nan"),
    }


@pytest.mark.parametrize("case", list(_handmade()))
def test_a_hand_made_body_is_refused_at_the_door_saying_what_is_wrong(case):
    bad, says = _handmade()[case]
    for name, (src, kw, _) in CALLS.items():
        if src is None:
            continue
        args = [bad] + ([EXAMPLES / "never-written.md"] if name == "write_report" else [])
        with pytest.raises((TypeError, rbcli.InputError)) as info:
            getattr(rbcli, name)(*args, **kw)
        text = str(info.value)
        assert text.startswith("body: ") and says in text, (name, text)
        assert isinstance(info.value, TypeError) == (case == "None-part"), (name, text)
    assert not (EXAMPLES / "never-written.md").exists()


# ----------------------------------------------------------------------------- numbers


#: a valid value of each numeric parameter; each number in it is replaced in turn by each
#: of NUMBERS (a count by each of COUNTS), so that the value reaches the reader and the
#: physics in the shape the parameter takes (issue 34 item 3: no exit 70 from any number)
SAMPLES = {
    "about": [0.01, 0.02, 0.03], "axis": [0, 0, 1], "omega": [0.01, 1, 0.01], "shaft": [0, 0, 1],
    "through": [0, 0, 0.1], "mark": [1, 0, 0], "zero_mark_deg": 10, "planes": [0, 0.4],
    "radius": [0.1, 0.1], "mass_step": 0.001, "angle_step": 15, "positions": 8,
    "speed": "3000 rpm", "bearings": [-0.05, 0.45], "g": 9.8, "grade": "G6.3", "at": 2,
    "duration": 1, "samples": 11, "pivot": [0, 0, 0], "spin": 150, "theta": 30,
    "theta_dot": 0.1, "phi_dot": 0.1, "ratio": 2, "latitude": 30, "earth_rate": 7.29e-5,
    "symmetry_tol": 0.01, "rim_radius": 0.01, "tyre_radius": 0.001, "rolling_speed": 0.1,
    "lean": 10, "circle": 1, "stiffness": [1e6, 2e6], "damping": [500, 600], "digits": 6,
}
NUMBERS = {"0": 0.0, "-0": -0.0, "tiny": 5e-324, "-tiny": -5e-324, "huge": 1.7976931348623157e308,
           "-huge": -1.7976931348623157e308, "inf": math.inf, "-inf": -math.inf, "nan": math.nan}
COUNTS = {"0": 0, "-1": -1, "2^63": 2**63, "10^18": 10**18}

#: the calls the numbers go into (whirl and field_balance: tests/test_whirl_hostile.py and
#: the field-balance suites); the report twice, so that every section runs: the heavy top's,
#: and a rotor's balance, whirl and free precession
NUMBER_CALLS = {
    **{f: CALLS[f][:2] for f in ("inertia", "principal", "precess", "top", "gyrocompass", "rollcheck",
                                 "report", "report_text")},
    "balance": ("two_disk_rotor.yaml", dict(planes="0,400 mm", radius="100 mm", speed="3000 rpm",
                                            bearings="-50,450 mm")),
    "report-rotor": ("two_disk_rotor.yaml", dict(planes="0,400 mm", radius="100 mm", bearings="-50,450 mm",
                                                 stiffness=1e6, damping=500, speed="3000 rpm",
                                                 omega=[0, 0, 10], grade="G6.3")),
    "gyrocompass-ratio": (None, dict(spin="6000 rpm", latitude=30)),  # the ratio instead of a body
}


#: a base argument a driven parameter replaces (a rolling wheel's speed follows from its spin)
INSTEAD = {("rollcheck", "spin"): "rolling_speed"}


def _number_call(call: str, param: str, value):
    src, kw = NUMBER_CALLS[call]
    kw = {k: v for k, v in kw.items() if INSTEAD.get((call, param)) != k}
    return getattr(rbcli, call.split("-")[0])(body(src) if src else None, **{**kw, param: value})


def numbers_in(sample):
    """(name, value): ``sample`` with its numbers replaced — every one at once and each on its
    own, as numbers and as text."""
    if isinstance(sample, int):
        yield from COUNTS.items()
        return
    for key, x in NUMBERS.items():
        if isinstance(sample, str):  # the number in a quantity text
            yield f"'{key}'", re.sub(r"[0-9.]+", repr(x), sample, count=1)
        elif isinstance(sample, list):
            yield f"all {key}", [x] * len(sample)
            yield f"'all {key}'", ",".join([repr(x)] * len(sample))
            for i in range(len(sample)):
                yield f"[{i}] {key}", [*sample[:i], x, *sample[i + 1:]]
        else:
            yield key, x
            yield f"'{key}'", repr(x)


#: the report's parameters driven through the heavy top's report (the others: the rotor's)
TOP_REPORT = {"pivot", "spin", "theta", "theta_dot", "phi_dot", "g", "symmetry_tol", "rim_radius", "tyre_radius"}
NUMBER_PAIRS = [(call, p) for call in NUMBER_CALLS
                for p in inspect.signature(getattr(rbcli, call.split("-")[0])).parameters
                if p in SAMPLES and (p == "ratio") == (NUMBER_CALLS[call][0] is None)
                and (not call.startswith("report") or (p in TOP_REPORT) == (call == "report"))]


@pytest.mark.parametrize("pair", sampled_params(NUMBER_PAIRS, lambda v: not v[0].startswith("report") or v[1] in (
    "speed", "through", "stiffness", "spin", "digits"), ids=lambda v: f"{v[0]}-{v[1]}"))
def test_zero_tiny_huge_inf_and_nan_in_every_parameter_give_an_answer_or_an_input_error(pair):
    call, param = pair
    bad = []
    for key, value in numbers_in(SAMPLES[param]):
        try:
            r = _number_call(call, param, value)
            text = " | ".join(str(w) for w in getattr(r, "warnings", ()) or ())
        except (TypeError, rbcli.InputError) as exc:
            text = str(exc)
        except BaseException as exc:  # noqa: BLE001 - what the test is looking for
            bad.append(f"{call}({param}={key}): {type(exc).__name__}: {str(exc)[:300]}")
            continue
        if "--" in _quoted_out(text) or len(text) > 3000 or "has a unit on some" in text:  # (numbers only)
            bad.append(f"{call}({param}={key}): {text[:300]}")
    assert not bad, "\n".join(bad)


@pytest.mark.sampled
def test_the_number_samples_are_valid_values():
    # each sample is a value its functions take as it is: the replacements are the only change
    for call, param in NUMBER_PAIRS[: sample(len([p for p in NUMBER_PAIRS if "report" not in p[0]]), None)]:
        _number_call(call, param, SAMPLES[param])
    assert {p for _, p in NUMBER_PAIRS} == set(SAMPLES)


#: the report's options on the command line, each with the numbers as typed (a unit where
#: the option needs one); the rotor's report runs every section but the heavy top's
REPORT_ARGS = ["examples/two_disk_rotor.yaml", "--planes", "0,400 mm", "--radius", "100 mm", "--bearings",
               "-50,450 mm", "--stiffness", "1e6", "--damping", "500", "--speed", "3000 rpm",
               "--omega", "0,0,10", "--grade", "G6.3"]
TYPED = ["0", "5e-324", "1e308", "1e160", "inf", "nan"]
REPORT_OPTIONS = [("--shaft", "0,0,{}"), ("--through", "{},0,0"), ("--planes", "0,{}"), ("--radius", "{}"),
                  ("--bearings", "{},0.45"), ("--grade", "G{}"), ("--speed", "{} rpm"), ("--stiffness", "{}"),
                  ("--damping", "{}"), ("--omega", "0,{},1"), ("--g", "{}"), ("--rim-radius", "{}"),
                  ("--tyre-radius", "{}"), ("--symmetry-tol", "{}"), ("--digits", "{}")]


@pytest.mark.parametrize("option", sampled_params(REPORT_OPTIONS, lambda o: o[0] == "--speed", ids=lambda o: o[0]))
def test_the_report_options_take_any_number_without_exit_70(cli, tmp_path, option):
    flag, form = option
    for n in TYPED:
        args = list(REPORT_ARGS)
        if flag in args:
            args[args.index(flag) + 1] = form.format(n)
        else:
            args += [flag, form.format(n)]
        r = cli("report", *args, "-o", str(tmp_path / "r.html"), "--force")
        assert r.code in (0, 1, 2), (flag, n, r.code, r.err[-1000:])
        assert r.code != 2 or r.err.count("\n") == 1, (flag, n, r.err[-1000:])  # one line
