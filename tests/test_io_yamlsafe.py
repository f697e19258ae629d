"""Tests of rbcli.io.yamlsafe, the safe YAML loader of body files.

Expected scalar values come from the YAML 1.2.2 spec, §10.3.2 (core schema tag
resolution); expected line/column numbers are counted by hand from the test texts.
Every test runs twice: with libyaml's parser (CParser) and with the pure-Python
SafeLoader the module falls back to when PyYAML lacks libyaml.
"""

from __future__ import annotations

import json
import math

import pytest

from conftest import sample
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from rbcli.errors import InputError, Location
from rbcli.io import yamlsafe
from rbcli.io.yamlsafe import (
    MAX_BYTES,
    MAX_DEPTH,
    MapNode,
    Mark,
    ScalarNode,
    SeqNode,
    load,
    to_python,
    where,
)

LOADERS = [yaml.SafeLoader]
if yaml.__with_libyaml__:
    LOADERS.insert(0, yaml.cyaml.CParser)  # what yamlsafe uses: libyaml's parser alone


@pytest.fixture(autouse=True, params=LOADERS, ids=lambda c: c.__name__)
def loader(request, monkeypatch):
    """Run every test with libyaml and with the pure-Python fallback."""
    monkeypatch.setattr(yamlsafe, "_LOADER", request.param)
    return request.param


def refused(text: str | bytes, filename: str = "body.yaml") -> InputError:
    """Load text that must be refused; check the error is located and lower case."""
    with pytest.raises(InputError) as info:
        load(text, filename)
    err = info.value
    assert isinstance(err.where, Location)
    assert err.where.file == filename
    assert err.where.line >= 1 and err.where.col >= 1
    assert err.message[:1].islower(), err.message
    assert "\n" not in err.message
    return err


def value_of(yaml_value: str) -> ScalarNode:
    root = load(f"v: {yaml_value}\n", "t.yaml")
    assert isinstance(root, MapNode)
    node = root.items["v"][1]
    assert isinstance(node, ScalarNode)
    return node


# --------------------------------------------------------------- YAML 1.2 core schema

CORE_SCHEMA = [
    # null (spec 10.3.2: null | Null | NULL | ~ | empty)
    ("~", None), ("null", None), ("Null", None), ("NULL", None), ("", None),
    ("nULL", "nULL"),
    # bool (true | True | TRUE | false | False | FALSE)
    ("true", True), ("True", True), ("TRUE", True),
    ("false", False), ("False", False), ("FALSE", False),
    # YAML 1.1 booleans are plain strings in 1.2
    ("yes", "yes"), ("no", "no"), ("on", "on"), ("off", "off"), ("y", "y"), ("n", "n"),
    ("NO", "NO"), ("tRUE", "tRUE"),
    # int: [-+]?[0-9]+ | 0o[0-7]+ | 0x[0-9a-fA-F]+
    ("0", 0), ("17", 17), ("017", 17), ("-19", -19), ("+12", 12), ("-0", 0),
    ("0o14", 12), ("0x1A", 26), ("0xc", 12), ("0xFF", 255),
    ("0o8", "0o8"), ("0b101", "0b101"), ("0x", "0x"), ("0X1A", "0X1A"), ("0O14", "0O14"),
    ("1_000", "1_000"), ("1:30", "1:30"), ("1,000", "1,000"), ("+-1", "+-1"),
    # float: [-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?
    ("1e3", 1000.0), ("1E3", 1000.0), ("1.5", 1.5), (".5", 0.5), ("1.", 1.0),
    ("-1.5e-3", -0.0015), ("+12e03", 12000.0), ("6.8523015e+5", 685230.15),
    ("0.", 0.0), ("-.5", -0.5), ("2.5E-1", 0.25),
    ("1.2.3", "1.2.3"), ("e3", "e3"), ("1e", "1e"), ("1e+", "1e+"), (".", "."),
    ("1.5m", "1.5m"), ("1 e3", "1 e3"),
    # infinities and not-a-number
    (".inf", math.inf), (".Inf", math.inf), (".INF", math.inf), ("+.inf", math.inf),
    ("-.inf", -math.inf), ("-.Inf", -math.inf), ("-.INF", -math.inf),
    ("inf", "inf"), (".iNf", ".iNf"), ("infinity", "infinity"), ("-inf", "-inf"),
    (".nan", "nan"), (".NaN", "nan"), (".NAN", "nan"),
    ("nan", "nan-string"), ("NaN", "NaN"), ("-.nan", "-.nan"),
    # anything else is a string
    ("box", "box"), ("kg/m^3", "kg/m^3"), ("7.85 g/cm^3", "7.85 g/cm^3"),
]  # fmt: skip


@pytest.mark.parametrize("text,expected", CORE_SCHEMA, ids=[repr(t) for t, _ in CORE_SCHEMA])
def test_core_schema_resolution_of_plain_scalars(text, expected):
    node = value_of(text)
    assert node.quoted is False
    assert node.raw == text
    if expected == "nan":
        assert isinstance(node.value, float) and math.isnan(node.value)
        assert node.tag == "float"
        return
    if expected == "nan-string":
        expected = text
    assert node.value == expected
    # type, not just value: True == 1 and 17 == 17.0 in Python
    assert type(node.value) is type(expected)
    assert node.tag == {
        type(None): "null", bool: "bool", int: "int", float: "float", str: "str"
    }[type(expected)]


@pytest.mark.parametrize(
    "text,expected",
    [
        ("'1'", "1"), ('"1e3"', "1e3"), ("'true'", "true"), ('"null"', "null"),
        ("''", ""), ('"~"', "~"), ("'.inf'", ".inf"), ('"a\\tb"', "a\tb"),
        ("'it''s'", "it's"),
    ],
)  # fmt: skip
def test_quoted_scalars_are_always_strings(text, expected):
    node = value_of(text)
    assert node.quoted is True
    assert node.value == expected and type(node.value) is str
    assert node.raw == expected
    assert node.tag == "str"


def test_block_scalars_are_strings_and_plain_multiline_folds():
    root = load("a: |\n  1\nb: >\n  true\n  x\nc: 1\n  2\n", "t.yaml")
    assert to_python(root) == {"a": "1\n", "b": "true x\n", "c": "1 2"}
    assert root.items["a"][1].quoted is True  # block scalar: never resolved
    assert root.items["c"][1].quoted is False


def test_float_overflow_is_kept_as_inf():
    assert value_of("1e999").value == math.inf
    assert value_of("-1e999").value == -math.inf
    assert value_of("1e999").tag == "float"


def test_integer_digit_limit():
    # 300 digits is the documented limit; Python's own int() limit is 4300 digits.
    assert value_of("9" * 300).value == 10**300 - 1
    assert value_of("-" + "9" * 300).value == -(10**300 - 1)
    for text in ["9" * 301, "-" + "1" * 301, "1" * 5000, "0x" + "f" * 301, "0o" + "7" * 301]:
        err = refused(f"v: {text}\n")
        assert "number too long" in err.message
        assert (err.where.line, err.where.col) == (1, 4)
    # a 400-digit float literal (about 1.1e399) is a float and overflows to inf
    assert value_of("1" * 400 + ".0").value == math.inf


# ------------------------------------------------------------------------------ marks

MARKED = """\
body:
  mass: 2.5
  size: [0.1, 0.2,
         0.3]
  parts:
    - shape: box
      name: "a"
"""


def test_marks_of_nested_nodes():
    root = load(MARKED, "m.yaml")
    assert isinstance(root, MapNode) and root.mark == Mark(1, 1)
    key_mark, body = root.items["body"]
    assert key_mark == Mark(1, 1)
    assert isinstance(body, MapNode) and body.mark == Mark(2, 3)
    assert body.items["mass"][0] == Mark(2, 3)
    assert body.items["mass"][1].mark == Mark(2, 9)
    assert body.items["size"][0] == Mark(3, 3)
    size = body.items["size"][1]
    assert isinstance(size, SeqNode) and size.mark == Mark(3, 9)
    assert [n.mark for n in size.items] == [Mark(3, 10), Mark(3, 15), Mark(4, 10)]
    assert body.items["parts"][0] == Mark(5, 3)
    parts = body.items["parts"][1]
    assert isinstance(parts, SeqNode) and parts.mark == Mark(6, 5)
    part = parts.items[0]
    assert isinstance(part, MapNode) and part.mark == Mark(6, 7)
    assert part.items["shape"][0] == Mark(6, 7)
    assert part.items["shape"][1].mark == Mark(6, 14)
    assert part.items["name"][0] == Mark(7, 7)
    name = part.items["name"][1]
    assert name.mark == Mark(7, 13) and name.quoted and name.value == "a"
    assert list(body.items) == ["mass", "size", "parts"]  # source order kept


def test_marks_count_characters_not_bytes_and_skip_a_bom():
    root = load("\ufeffé: ü\nx: [ää, b]\n".encode(), "u.yaml")
    assert root.items["é"][0] == Mark(1, 1)
    assert root.items["é"][1].mark == Mark(1, 4)
    assert [n.mark for n in root.items["x"][1].items] == [Mark(2, 5), Mark(2, 9)]


def test_tags_repr_and_where():
    root = load("a: [1, 2.0, x, true, ~]\nb: {c: d}\n", "w.yaml")
    assert root.tag == "map"
    seq = root.items["a"][1]
    assert seq.tag == "seq"
    assert [n.tag for n in seq.items] == ["int", "float", "str", "bool", "null"]
    assert "1" in repr(seq.items[0]) and "1:5" in repr(seq.items[0])
    assert "'c'" in repr(root.items["b"][1])
    assert "5 items" in repr(seq)
    assert where("w.yaml", Mark(3, 7)) == Location("w.yaml", 3, 7)
    assert str(where("w.yaml", seq.mark)) == "w.yaml:1:4"


def test_nodes_are_frozen_values_with_their_marks():
    """A loaded node (its mark kept as libyaml's 0-based position) equals, hashes and reads like
    one made by the public constructors; no attribute can be set or deleted."""
    root = load("a: [1, x]\nb: {c: 'd'}\n", "f.yaml")
    seq = root.items["a"][1]
    one = seq.items[0]
    made = ScalarNode(Mark(1, 5), 1, "1", False)
    assert one == made and hash(one) == hash(made) and one != ScalarNode(Mark(1, 6), 1, "1", False)
    assert type(one.mark) is Mark and one.mark == Mark(1, 5)
    assert seq == SeqNode(Mark(1, 4), [made, ScalarNode(Mark(1, 8), "x", "x", False)])
    assert root.items["b"][1] == MapNode(
        Mark(2, 4), {"c": (Mark(2, 5), ScalarNode(Mark(2, 8), "d", "d", True))}
    )
    assert one != (Mark(1, 5), 1, "1", False) and seq != one
    match one:
        case ScalarNode(mark, value, raw, quoted):
            assert (mark, value, raw, quoted) == (Mark(1, 5), 1, "1", False)
    for node, name in [(one, "value"), (one, "mark"), (seq, "items"), (root, "items")]:
        with pytest.raises(AttributeError):
            setattr(node, name, None)
        with pytest.raises(AttributeError):
            delattr(node, name)
    with pytest.raises(AttributeError):
        one.other = 1  # type: ignore[attr-defined]


def test_root_may_be_any_node():
    assert to_python(load("[1, 2]", "r.yaml")) == [1, 2]
    assert to_python(load("'x'", "r.yaml")) == "x"


# -------------------------------------------------------------------- refused content


def test_duplicate_keys_name_both_places():
    text = "part:\n  name: x\n  mass: 1\n  size: [1, 2, 3]\n  mass: 2\n"
    err = refused(text)
    assert "duplicate key 'mass'" in err.message
    assert "first at line 3, column 3" in err.message
    assert (err.where.line, err.where.col) == (5, 3)


def test_duplicate_keys_in_flow_mappings_and_quoted_forms():
    err = refused("{a: 1, a: 2}")
    assert (err.where.line, err.where.col) == (1, 8)
    assert "first at line 1, column 2" in err.message
    err = refused("a: 1\n'a': 2\n")  # the same name, quoted or not
    assert (err.where.line, err.where.col) == (2, 1)


def test_same_key_in_different_mappings_is_fine():
    assert to_python(load("a: {x: 1}\nb: {x: 2}\n", "t.yaml")) == {"a": {"x": 1}, "b": {"x": 2}}


@pytest.mark.parametrize(
    "text,line,col",
    [("1: x", 1, 1), ("a: 1\n1.5: x", 2, 1), ("true: x", 1, 1), ("null: x", 1, 1),
     ("~: x", 1, 1), ("a:\n  0x1F: x", 2, 3), ("? [a]\n: x", 1, 3), ("{a: 1}: x", 1, 1),
     ("- [a, b]: 1", 1, 3)],
)  # fmt: skip
def test_non_string_keys_refused(text, line, col):
    err = refused(text)
    assert "keys must be names" in err.message
    assert (err.where.line, err.where.col) == (line, col)


def test_quoted_and_yaml11_keys_are_names():
    root = load("'1': a\n\"true\": b\nyes: c\nno: d\n1_000: e\n'<<': f\n", "t.yaml")
    assert list(root.items) == ["1", "true", "yes", "no", "1_000", "<<"]


def test_merge_key_refused():
    err = refused("a: 1\n<<: {b: 2}\n")
    assert "merge keys" in err.message
    assert (err.where.line, err.where.col) == (2, 1)


@pytest.mark.parametrize(
    "text,line,col",
    [("a: &x 1\nb: 2\n", 1, 4), ("a: 1\nb: *x\n", 2, 4), ("&a [*a]", 1, 1),
     ("base: &b {m: 1}\nother:\n  <<: *b\n", 1, 7)],
)  # fmt: skip
def test_anchors_and_aliases_refused(text, line, col):
    err = refused(text)
    assert "anchors and aliases" in err.message
    assert (err.where.line, err.where.col) == (line, col)


def test_billion_laughs_refused():
    lines = ['a: &a ["lol","lol","lol","lol","lol","lol","lol","lol","lol"]']
    for prev, name in zip("abcdefgh", "bcdefghi"):
        lines.append(f"{name}: &{name} [" + ",".join([f"*{prev}"] * 9) + "]")
    err = refused("\n".join(lines) + "\n")
    assert "anchors and aliases" in err.message
    assert (err.where.line, err.where.col) == (1, 4)


@pytest.mark.parametrize(
    "text,line,col",
    [("a: !!python/object:os.system {}", 1, 4),
     ("a: !!python/object/apply:os.system ['echo hi']", 1, 4),
     ("a: !!python/name:os.system ''", 1, 4),
     ("- !custom 3", 1, 3), ("a: !!str 3", 1, 4), ("a: ! x", 1, 4),
     ("a: !<tag:yaml.org,2002:str> x", 1, 4), ("a: !!map {b: 1}", 1, 4),
     ("%TAG !e! tag:example.com,2000:\n---\na: !e!foo x\n", 3, 4),
     ("!!map\na: 1\n", 1, 1)],
)  # fmt: skip
def test_tags_refused(text, line, col):
    err = refused(text)
    assert "tags such as !!python/object are not allowed" in err.message
    assert (err.where.line, err.where.col) == (line, col)


# ---------------------------------------------------------------------------- nesting


def nested_flow(depth: int) -> str:
    return "[" * depth + "]" * depth


def test_depth_limit_exact():
    assert MAX_DEPTH == 64
    root = load(nested_flow(MAX_DEPTH), "d.yaml")
    depth = 0
    while isinstance(root, SeqNode):
        depth += 1
        root = root.items[0] if root.items else None
    assert depth == MAX_DEPTH
    err = refused(nested_flow(MAX_DEPTH + 1))
    assert "nesting is too deep" in err.message and "64" in err.message
    assert (err.where.line, err.where.col) == (1, MAX_DEPTH + 1)  # the 65th '['


def test_depth_limit_block_style():
    # line L holds 2*(L-1) spaces and "a:"; the root mapping (level 1) starts on
    # line 1 and the mapping of level L on line L, so level 65 starts at 65:129.
    text = "".join("  " * i + "a:\n" for i in range(70))
    err = refused(text)
    assert (err.where.line, err.where.col) == (65, 2 * 64 + 1)


def test_depth_limit_follows_the_module_constant(monkeypatch):
    monkeypatch.setattr(yamlsafe, "MAX_DEPTH", 3)
    assert to_python(load("a: {b: [1]}", "t.yaml")) == {"a": {"b": [1]}}
    err = refused("a: {b: [[1]]}")
    assert (err.where.line, err.where.col) == (1, 9)


@pytest.mark.parametrize(
    "text",
    [nested_flow(30_000), "[" * 30_000, "{a: " * 30_000, "- " * 30_000 + "x",
     "a: " + "[{b: " * 15_000],
    ids=["flow-seq", "unclosed", "flow-map", "block-seq", "mixed"],
)
def test_very_deep_nesting_refused_in_process(text):
    # PyYAML's composer segfaults at about this depth; refusal must come first.
    err = refused(text)
    assert "nesting is too deep" in err.message


# ----------------------------------------------------------------- documents, empty


@pytest.mark.parametrize(
    "text,line",
    [("a: 1\n---\nb: 2\n", 2), ("---\na: 1\n---\na: 2\n", 3), ("a: 1\n--- \n", 2),
     ("---\n---\n", 2)],
)
def test_more_than_one_document_refused(text, line):
    err = refused(text)
    assert "more than one YAML document" in err.message
    assert (err.where.line, err.where.col) == (line, 1)


@pytest.mark.parametrize(
    "text",
    ["", "\n\n", "   \n", "# only a comment\n", "---\n", "---\n...\n", "--- # c\n",
     b"", b"\xef\xbb\xbf", "\ufeff# c\n"],
)  # fmt: skip
def test_empty_file(text):
    err = refused(text)
    assert err.message == "the file is empty; a body needs `parts:` or a single part"
    assert (err.where.line, err.where.col) == (1, 1)


# -------------------------------------------------------------- bytes, text, syntax


@pytest.mark.parametrize(
    "data,line,col",
    [(b"a: \xff\n", 1, 4), (b"a: 1\nbb: \xc3\x28\n", 2, 5), ("é: ".encode() + b"\x80", 1, 4),
     (b"\xef\xbb\xbfab\xfe", 1, 3), (b"\xff\xfea\x00:\x00", 1, 1)],
)  # fmt: skip
def test_invalid_utf8_located(data, line, col):
    err = refused(data)
    assert "not valid UTF-8" in err.message
    assert (err.where.line, err.where.col) == (line, col)


def test_lone_surrogate_in_str_located():
    err = refused("a: 1\nb: x\ud800\n")
    assert (err.where.line, err.where.col) == (2, 5)


@pytest.mark.parametrize(
    "text,line,col,char",
    [("a: 1\nb: x\x07y\n", 2, 5, "U+0007"), ("é: ü\x07", 1, 5, "U+0007"),
     ("a: 1\r\nb: \x00\n", 2, 4, "U+0000"), ("a:\n  - 'ö'\n  - \x1b[0m\n", 3, 5, "U+001B")],
)  # fmt: skip
def test_control_character_located(text, line, col, char):
    err = refused(text)
    assert char in err.message and "printable" in err.message
    assert (err.where.line, err.where.col) == (line, col)
    # the same file as bytes is located identically
    err = refused(text.encode())
    assert (err.where.line, err.where.col) == (line, col)


@pytest.mark.parametrize(
    "text,line,col",
    [("a: b: c", 1, 5), ("a:\n  b: 1\n c: 2\n", 3, 2), ("a: [1, 2\n", 2, 1),
     ("a:\n  - x\n\tb: 1\n", 3, 1), ("a: 'x\n", 2, 1), ("key: value\n- item\n", 2, 1)],
)  # fmt: skip
def test_malformed_yaml_located(text, line, col):
    err = refused(text)
    assert err.message.startswith("invalid YAML: ")
    assert (err.where.line, err.where.col) == (line, col)


def test_mapping_values_message():
    err = refused("a: b: c")
    assert err.message.startswith("invalid YAML: mapping values are not allowed")


def test_max_bytes_enforced(monkeypatch):
    assert MAX_BYTES == 32 * 1024 * 1024
    monkeypatch.setattr(yamlsafe, "MAX_BYTES", 100)
    ok = "a: " + "x" * 97  # 100 bytes
    assert load(ok, "s.yaml").items["a"][1].value == "x" * 97
    assert load(ok.encode(), "s.yaml").items["a"][1].value == "x" * 97
    for big in ["a: " + "x" * 98, ("a: " + "x" * 98).encode(), "a: " + "é" * 49]:
        err = refused(big)  # the last is 52 characters but 101 bytes
        assert err.message == "file is 101 bytes; body files are limited to 100 bytes"


def test_max_bytes_message_in_mib(monkeypatch):
    monkeypatch.setattr(yamlsafe, "MAX_BYTES", 2 * 1024 * 1024)
    err = refused(b"#" * (2 * 1024 * 1024 + 1))
    assert err.message == f"file is {2 * 1024 * 1024 + 1} bytes; body files are limited to 2 MiB"


# --------------------------------------------------------------------------- to_python


def test_to_python_round_trip():
    text = (
        "name: wheel\nmass: 1.5e+0\ncount: 0x10\nflags: [true, no, ~]\n"
        "parts:\n  - {shape: box, size: [.1, 2., 3]}\n  - shape: 'ring'\n"
    )
    data = to_python(load(text, "t.yaml"))
    assert data == {
        "name": "wheel", "mass": 1.5, "count": 16, "flags": [True, "no", None],
        "parts": [{"shape": "box", "size": [0.1, 2.0, 3]}, {"shape": "ring"}],
    }  # fmt: skip
    # JSON is YAML 1.2: re-writing the plain data as JSON and loading it gives it back
    assert to_python(load(json.dumps(data), "t.json")) == data
    assert type(data["parts"][0]["size"][2]) is int


# libyaml refuses non-printable characters even when escaped JSON would allow them.
_PRINTABLE = st.characters(blacklist_categories=("Cs", "Cc", "Cf", "Co", "Cn", "Zl", "Zp"))
_JSON = st.recursive(
    st.none()
    | st.booleans()
    | st.integers(min_value=-(10**100), max_value=10**100)
    | st.floats(allow_nan=False, allow_infinity=False)
    | st.text(_PRINTABLE, max_size=20),
    lambda children: st.lists(children, max_size=4)
    | st.dictionaries(st.text(_PRINTABLE, max_size=8), children, max_size=4),
    max_leaves=20,
)


@settings(max_examples=50, deadline=None)
@given(_JSON)
def test_json_documents_load_as_themselves(data):
    assert to_python(load(json.dumps(data, ensure_ascii=False), "h.json")) == data


# ---------------------------------------------------------------------------- fuzzing


def _load_or_input_error(text):
    try:
        node = load(text, "fuzz.yaml")
    except InputError as err:
        assert err.where is not None and err.where.line >= 1 and err.where.col >= 1
        return
    assert isinstance(node, (MapNode, SeqNode, ScalarNode))
    to_python(node)


@pytest.mark.sampled
@settings(max_examples=sample(60, 300), deadline=None)
@given(st.text())
def test_random_text_only_ever_gives_a_node_or_input_error(text):
    _load_or_input_error(text)


@pytest.mark.sampled
@settings(max_examples=sample(60, 300), deadline=None)
@given(st.binary())
def test_random_bytes_only_ever_give_a_node_or_input_error(data):
    _load_or_input_error(data)


@pytest.mark.sampled
@settings(max_examples=sample(60, 300), deadline=None)
@given(st.text(alphabet="[]{}:,-?&*!|>'\"#%@` \n\t\rab01.eE+~\x07\x85\u2028\ufeff<", max_size=60))
def test_random_yamlish_text_only_ever_gives_a_node_or_input_error(text):
    _load_or_input_error(text)
