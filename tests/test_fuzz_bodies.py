"""Fuzz-style tests: whatever a body file holds, loading it ends in a body or a located
InputError (exit 2), never any other exception, never a numpy warning on standard error.

Inputs (and, since issue 15, unit expressions with nested powers and option values, each
within a 2 s deadline): random text and bytes, YAML-ish text, and random mutations of the bundled
examples (lines deleted, duplicated, swapped, re-indented; numbers replaced by strings,
booleans, nulls, huge, tiny, negative or non-finite values, quantities of the wrong
dimension; tags, anchors and flow punctuation inserted; keys renamed to other keys; random
unicode). A few mutated files also go through a real ``python -m rbcli`` process.
"""

from __future__ import annotations

import os
import random
import re
import warnings
from pathlib import Path

import pytest

from conftest import sample
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rbcli.errors import InputError
from rbcli.body.model import load_text

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.yaml"))
TEXTS = [p.read_text(encoding="utf-8") for p in EXAMPLES]

TOKENS = [
    "true", "false", "null", "~", "", "0", "-1", "-0.0", "1e999", "-1e999", "1e300", "1e61", "1e-320",
    ".inf", "-.inf", ".nan", "0x1F", "0o17", "017", "1:30", "no", "yes", "on", "'x'", '"3 Hz"', "'1 rpm'",
    "'12 deg'", "'1e400 m'", "'5 kg/m^3'", "'2 lb'", "'-3 mm'", "[1, 2]", "[]", "{}", "{a: 1}", "[[1, 2, 3]]",
    "!!python/object/apply:os.system ['true']", "!!str 1", "&a 1", "*a", "<<: {x: 1}", "? complex",
    "{", "}", "[", "]", ":", ",", "- ", "-", "#", "|", ">", "'", '"', "\t", "%YAML 1.2", "---", "...",
    "\u2028", "\x85", "\ufeff", "\x00", "\x1b", "é", "😀", "1" * 400,
    "shape: include\n    file: cube.yaml", "shape: include\n    file: nothere.yaml", "shape: given",
    "subtract: true", "cut_from: base", "cut_from: nothere", "axis: [0, 0, 0]", "rotate: {quaternion: [0, 0, 0, 0]}",
    "rotate: {euler: [1, 2, 3], seq: ZZZ}", "rotate: {matrix: [[1, 0, 0], [0, 1, 0], [0, 0, -1]]}",
    "units: {length: mm}", "units: {length: kg}", "rbcli: 2", "reference: com", "pivot: com",
]
KEYS = [
    "name", "shape", "size", "mass", "density", "areal_density", "linear_density", "at", "axis", "rotate",
    "radius", "inner_radius", "length", "height", "thickness", "shell", "from", "to", "vertices",
    "semi_axes", "major_radius", "minor_radius", "com", "inertia", "file", "subtract", "cut_from",
    "units", "parts", "reference", "shaft", "pivot", "rim_radius", "rbcli", "description", "colour",
]
NUMBER = re.compile(r"-?\d+(\.\d+)?")
KEY = re.compile(r"\b[a-z_]+(?=:)")


@st.composite
def mutated(draw) -> str:
    lines = draw(st.sampled_from(TEXTS)).split("\n")
    for _ in range(draw(st.integers(1, 4))):
        i = draw(st.integers(0, len(lines) - 1))
        op = draw(st.sampled_from(["delete", "duplicate", "swap", "number", "insert", "unicode", "key", "indent"]))
        if op == "delete" and len(lines) > 1:
            del lines[i]
        elif op == "duplicate":
            lines.insert(i, lines[draw(st.integers(0, len(lines) - 1))])
        elif op == "swap":
            j = draw(st.integers(0, len(lines) - 1))
            lines[i], lines[j] = lines[j], lines[i]
        elif op == "number":
            token = draw(st.sampled_from(TOKENS))
            lines[i] = NUMBER.sub(lambda m: token, lines[i], count=1)
        elif op == "insert":
            k = draw(st.integers(0, len(lines[i])))
            lines[i] = lines[i][:k] + draw(st.sampled_from(TOKENS)) + lines[i][k:]
        elif op == "unicode":
            k = draw(st.integers(0, len(lines[i])))
            lines[i] = lines[i][:k] + draw(st.text(min_size=1, max_size=3)) + lines[i][k:]
        elif op == "key":
            key = draw(st.sampled_from(KEYS))
            lines[i] = KEY.sub(lambda m: key, lines[i], count=1)
        else:
            lines[i] = " " * draw(st.integers(0, 6)) + lines[i].lstrip()
    return "\n".join(lines)


def load_or_input_error(data: str | bytes) -> None:
    """The property: a body, or an InputError with a location; nothing else, no warnings."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # numpy overflow/invalid would be noise
        try:
            body = load_text(data, "fuzz.yaml", ROOT / "examples")
        except InputError as exc:
            assert exc.where is not None and exc.where.file, exc
            assert "\n" not in str(exc) and exc.message, repr(str(exc))
            return
    assert body.parts  # a loaded body always has parts


FUZZ = settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@FUZZ
@given(text=mutated())
def test_mutated_examples_load_or_give_an_input_error(text):
    load_or_input_error(text)


@settings(max_examples=150, deadline=None)
@given(text=st.text(max_size=300))
def test_random_text_loads_or_gives_an_input_error(text):
    load_or_input_error(text)


YAMLISH = st.text(alphabet=list("parts:shape box{}[],-&*!|>'\"#\n 0123456789.e+-mass:size\t~nul"), max_size=200)


@settings(max_examples=150, deadline=None)
@given(text=YAMLISH)
def test_yaml_like_text_loads_or_gives_an_input_error(text):
    load_or_input_error(text)


@settings(max_examples=100, deadline=None)
@given(data=st.binary(max_size=200))
def test_random_bytes_load_or_give_an_input_error(data):
    load_or_input_error(data)


def test_hostile_classics():
    nested = "parts: " + "[" * 10000 + "]" * 10000
    billion_laughs = "a: &a [1, 1]\nb: &b [*a, *a]\nc: [*b, *b]\nparts: *c\n"
    for text in (nested, billion_laughs, "parts:\n  - {shape: point, mass: !!python/object/apply:os.system ['true']}\n",
                 "\x00" * 10, "---\nparts: []\n---\nparts: []\n", "1" * 10_000):
        load_or_input_error(text)


def test_mutated_files_through_a_real_process(cli_proc, tmp_path):
    rng = random.Random(20240613)  # fixed: the same files every run
    files = []
    for k in range(25):
        lines = rng.choice(TEXTS).split("\n")
        for _ in range(rng.randint(1, 3)):
            i = rng.randrange(len(lines))
            token = rng.choice(TOKENS)
            if rng.random() < 0.5:
                lines[i] = NUMBER.sub(lambda m: token, lines[i], count=1)
            else:
                j = rng.randint(0, len(lines[i]))
                lines[i] = lines[i][:j] + token + lines[i][j:]
        f = tmp_path / f"m{k}.yaml"
        f.write_text("\n".join(lines), encoding="utf-8", errors="surrogatepass")
        files.append(str(f))
    r = cli_proc("inertia", "--json", *files, env={"NO_COLOR": None})
    assert r.code in (0, 2), r.err
    assert "Traceback" not in r.err and "Warning" not in r.err
    for line in r.err.splitlines():
        assert line.startswith("rbcli: "), line
    # every file either printed a result or gave exactly one error line
    assert len(r.out.splitlines()) + len(r.err.splitlines()) == len(files)


# --------------------------------------------------------------------------- units and options
# issue 15: nested powers never take long. Every generated expression is read within the
# hypothesis deadline, to a finite factor or a UnitError; the power of each unit stays within
# the documented range (-12..12) whatever the nesting.

UNIT_NAMES = ["m", "mm", "km", "um", "in", "ft", "mi", "kg", "g", "lb", "s", "ms", "h", "rad", "deg",
              "rpm", "Hz", "N", "J", "g0", "nope", "°", "µm"]


@st.composite
def unit_expr(draw, depth: int = 0) -> str:
    if depth > 4 or draw(st.integers(0, 3)) == 0:
        text = draw(st.sampled_from(UNIT_NAMES))
    else:
        op = draw(st.sampled_from(["*", "/", "·", " * ", "**"]))
        left = draw(unit_expr(depth + 1))
        right = draw(unit_expr(depth + 1))
        text = f"({left}{op}{right})" if op != "**" else f"({left})"
    if draw(st.booleans()):
        n = draw(st.integers(-30, 30))
        text += draw(st.sampled_from([f"^{n}", f"**{n}", f"^({n})", "²", "⁻¹", f"^{n}^{n}"]))
    return text


@pytest.mark.sampled
@settings(max_examples=sample(60, 300), deadline=2000, suppress_health_check=[HealthCheck.too_slow])
@given(expr=unit_expr(), number=st.sampled_from(["1", "-2.5", "1e300", "3e-300", "0"]))
def test_nested_unit_expressions_read_quickly_or_give_a_unit_error(expr, number):
    import math

    from rbcli.io import units

    try:
        factor, dim = units.parse_unit(expr)
    except units.UnitError:
        pass
    else:
        assert math.isfinite(factor) and factor > 0
        assert all(abs(e) <= 12 * 2 * len(UNIT_NAMES) for e in dim)  # each unit within -12..12
    try:
        value, _ = units.parse_quantity(f"{number} {expr}")
    except units.UnitError:
        pass
    else:
        assert math.isfinite(value)


def test_seven_nested_powers_of_twelve_are_refused_at_once():
    from rbcli.io import units

    nested = "(((((((mm^12)^12)^12)^12)^12)^12)^12)"
    for text in (nested, f"1,1,1 {nested}"[6:], f"kg*{nested}/s"):
        try:
            units.parse_unit(text)
        except units.UnitError as exc:
            assert "reaches" in str(exc)
        else:  # pragma: no cover
            raise AssertionError(text)


OPTION_KINDS = ["length", "angular_speed", "mass", "inertia", "acceleration"]


@pytest.mark.sampled
@settings(max_examples=sample(60, 300), deadline=2000, suppress_health_check=[HealthCheck.too_slow])
@given(values=st.lists(st.sampled_from(["1", "-2", "0.5", "1e308", "1e-320", "nan", "", " ", "1e999"]),
                       min_size=0, max_size=4),
       unit=st.one_of(st.just(""), unit_expr()), sep=st.sampled_from([",", ", ", " ", ";"]),
       kind=st.sampled_from(OPTION_KINDS))
def test_option_values_with_nested_units_read_or_give_an_input_error(values, unit, sep, kind):
    from rbcli.api import options

    text = sep.join(values) + (" " + unit if unit else "")
    for read in (lambda: options.vector(text, kind, "x"), lambda: options.quantity(text, kind, "x")):
        try:
            out = read()
        except InputError as exc:
            assert str(exc).startswith("x: "), str(exc)
        else:
            import math

            assert all(math.isfinite(v) for v in (out if isinstance(out, list) else [out]))
