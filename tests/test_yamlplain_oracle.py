"""The plain-YAML reader (:mod:`rbcli.io.yamlplain`, a fast path that serves the batch goal
of bench/README.md, issue 23) against the loader it stands in for
(:func:`rbcli.io.yamlsafe.load`, libyaml's events): where it answers, the very same tree —
each node's class and mark, each scalar's value *and its type*, raw text and quoting, each
mapping's keys in order with their marks —; where the loader refuses a text (one located
InputError), it does not answer, so every error and its location stay the loader's.

The texts: every YAML file of the repository, bodies written as bench/batch.py writes them
(the plain reader must answer those: the test fails if it stops), and generated texts
around the edge of the subset (keys that are not names, numbers in every spelling, quoted,
flow and empty values, compact and odd indentation, blank lines and trailing spaces), each
also mutated by one character inserted, deleted or replaced.
"""

from __future__ import annotations

import functools
import random
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rbcli.errors import InputError
from rbcli.io import yamlplain
from rbcli.io import yamlsafe as ys

from conftest import sample

ROOT = Path(__file__).resolve().parent.parent


def same(a: ys.Node, b: ys.Node) -> bool:
    """Whether two trees are the same node for node (stricter than ``==``, for which
    ``1 == 1.0 == True`` and a mapping's key order does not count)."""
    if a.__class__ is not b.__class__ or a.mark != b.mark:
        return False
    if a.__class__ is ys.ScalarNode:
        nan = a.value != a.value and b.value != b.value  # noqa: PLR0124 - NaN is NaN
        return (type(a.value) is type(b.value) and (a.value == b.value or nan)
                and a.raw == b.raw and a.quoted is b.quoted)
    if a.__class__ is ys.SeqNode:
        return len(a.items) == len(b.items) and all(map(same, a.items, b.items))
    return (list(a.items) == list(b.items)
            and all(a.items[k][0] == b.items[k][0] and same(a.items[k][1], b.items[k][1])
                    for k in a.items))


def outcome(text: str | bytes, cap: tuple | None = None) -> str:
    """"same", "declined" (the plain reader left the text to the loader) or "refused" (the
    loader refused it, and so did the plain reader); any disagreement fails."""
    fast = yamlplain.tree(text, cap)
    try:
        slow = ys.load(text, "body.yaml", list_cap=cap)
    except InputError:
        assert fast is None, f"the loader refuses this text, the plain reader answered:\n{text!r}"
        return "refused"
    if fast is None:
        return "declined"
    assert same(fast, slow), f"different trees for:\n{text!r}"
    return "same"


# ----------------------------------------------------------------------------- corpus


def _yaml_files() -> list[Path]:
    skip = {".venv", ".git", "data"}
    return sorted(p for p in ROOT.rglob("*.y*ml") if not skip & set(p.relative_to(ROOT).parts))


def test_every_yaml_file_of_the_repository():
    """Bodies, golden cases, examples: the same tree, or left to the loader."""
    files = _yaml_files()
    assert len(files) > 100  # the corpus is there
    seen = {outcome(p.read_bytes()) for p in files}
    assert "same" in seen


@functools.cache
def _bench_batch():
    """bench/batch.py, whose body files the batch goal is measured on (a script, not a
    package: loaded from its path)."""
    import importlib.util

    path = Path(__file__).resolve().parent.parent / "bench" / "batch.py"
    spec = importlib.util.spec_from_file_location("rbcli_bench_batch", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)  # type: ignore[union-attr]
    return module


def batch_body(rng: random.Random, i: int) -> str:
    """A body as bench/batch.py writes them (its own generator)."""
    return _bench_batch().body_text(rng, i)


def test_batch_bodies_are_read_by_the_plain_reader():
    """The files the batch goal is measured on: answered (the fast path is taken), and
    the same trees; as text and as bytes."""
    rng = random.Random(7)
    for i in range(sample(60, 600)):
        text = batch_body(rng, i)
        assert outcome(text) == "same"
        assert outcome(text.encode()) == "same"


def test_the_parts_cap_is_left_to_the_loader():
    """A ``parts`` list over the loader's cap: the loader refuses it at the first part
    beyond (located), so the plain reader must not answer."""
    text = "parts:\n" + "".join(f"  - {{shape: point, mass: {i + 1}}}\n" for i in range(5))

    def cap(n):
        return ("parts", n, lambda mark: InputError("too many parts", ys.where("body.yaml", mark)))

    assert outcome(text, cap(5)) == "same"
    assert outcome(text, cap(4)) == "refused"


@pytest.mark.parametrize("levels", [3, 20, 40, 70, 200])
def test_deep_nesting_is_left_to_the_loader(levels):
    """Block mappings nested by indentation alone: the loader refuses more than MAX_DEPTH (64)
    levels, located; the plain reader answers only well inside that (a tree it answered
    would reach code that counts on the loader's limit)."""
    text = "".join("  " * i + f"k{i}:\n" for i in range(levels)) + "  " * levels + "x: 1\n"
    assert outcome(text) == ("same" if levels <= 20 else "declined" if levels < ys.MAX_DEPTH else "refused")


@pytest.mark.parametrize("length", [1, 250, 1024, 1025, 1100])
@pytest.mark.parametrize("form", ["{k}: 1\n", "x:\n  {k}: 1\n", "p:\n- {k}: 1\n",
                                  "p:\n  - b: 1\n    {k}: 1\n", "a: {{{k}: 1}}\n"])
def test_long_keys_are_left_to_the_loader(form, length):
    """libyaml finds a key's ':' only within 1024 characters of the key's start (a "simple
    key"; yaml_parser_stale_simple_keys): a longer key is refused, in block and flow
    mappings alike, so the plain reader must not answer it."""
    text = form.format(k="k" * length)
    expected = {"same"} if length <= 250 else {"refused"} if length > 1024 else {"same", "declined"}
    assert outcome(text) in expected


def test_the_size_limit_is_left_to_the_loader(monkeypatch):
    text = "name: a body of more than forty bytes of text\nparts: []\n"
    assert outcome(text) == "same"
    monkeypatch.setenv("RBCLI_MAX_BODY_BYTES", "40")
    assert outcome(text) == "refused"


@pytest.mark.parametrize("limit", ["abc", "0", "-1", "1" * 21])
def test_a_bad_size_limit_is_left_to_the_loader(monkeypatch, limit):
    """A limit in the environment that is not a positive whole number: the loader refuses it
    (an InputError naming the variable); the plain reader does not raise, it declines."""
    monkeypatch.setenv("RBCLI_MAX_BODY_BYTES", limit)
    assert outcome("a: 1\n") == "refused"
    assert outcome(b"a: 1\n") == "refused"


def test_other_inputs_are_declined():
    """What is not str or bytes, and texts outside the subset, are not answered."""
    assert yamlplain.tree(bytearray(b"a: 1\n")) is None
    for text in ("", "\n", "a: 1 # c\n", "\ufeffa: 1\n", "a: 1\r\n", "a:\n", "- 1\n",
                 "a: &x 1\n", "a: 'x'\n", "a: [[1]]\n", "--- \na: 1\n", "  a: 1\n"):
        assert yamlplain.tree(text) is None, repr(text)


# ----------------------------------------------------------------------------- generated

_KEYS = ["name", "shape", "at", "a", "b_2", "parts", "x", "true", "null", "Null", "on", "no",
         "1a", "a b", "a-b", "~", "<<", "A"]
_SCALARS = st.one_of(
    st.sampled_from([
        "1", "-1", "+1", "0", "-0", "007", "1.5", "-.5", "+.5", ".5", "5.", "1e3", "1E-3",
        "1e", "e5", "1.2.3", "--1", "-", "-a", "0x1F", "0o17", "0b1", ".inf", "-.inf",
        ".nan", ".NaN", "1_000", "1" * 301, "mm", "kg", "7850 kg/m^3", "2.7 g/cm^3",
        "a  b", "a:b", "a: b", "a #b", "a,b", "~", "null", "NULL", "true", "False", "no",
        "yes", "(x)", "x^2", "a/b", "_a", "a-", "a.", ".", "..", "...", "[", "]", "{", "}",
        '"x"', '"a, b"', '"a: b"', '""', '"a\\"b"', "'a'", '"x', "x\"",
    ]),
    st.from_regex(r"[-+]?[0-9]{1,4}(\.[0-9]{0,3})?([eE][-+]?[0-9]{1,3})?", fullmatch=True),
    st.text(alphabet="ab1.-+ e_:,#'\"", min_size=1, max_size=6),
)
_FLOWS = st.one_of(
    st.lists(_SCALARS, max_size=4).map(lambda xs: "[" + ", ".join(xs) + "]"),
    st.lists(st.tuples(st.sampled_from(_KEYS), _SCALARS), max_size=3).map(
        lambda kv: "{" + ", ".join(f"{k}: {v}" for k, v in kv) + "}"),
    st.sampled_from(["[]", "[ ]", "{}", "[1,,2]", "[1, 2,]", "[1,2]", "[ 1 , 2 ]", "[[1], 2]",
                     "{a:1}", "{a: 1, a: 2}", "{a: [1]}", "[1, 2", "{a: 1"]),
)
_VALUES = st.one_of(_SCALARS, _FLOWS)


def _node():
    return st.recursive(
        _VALUES,
        lambda children: st.one_of(
            st.lists(children, min_size=1, max_size=4).map(lambda xs: ("seq", xs)),
            st.lists(st.tuples(st.sampled_from(_KEYS), children), min_size=1, max_size=4).map(
                lambda kv: ("map", kv)),
        ),
        max_leaves=16,
    )


def _render(node, indent: int, steps: list[int], compact: bool) -> list[str]:
    """Block lines of a collection at ``indent``; ``steps`` chooses each nested collection's
    indentation (0 to 4 spaces more: 0 is a list at its key's indentation, or a text the
    loader refuses); ``compact`` writes a mapping in a list as ``- key: value``."""
    pad = " " * indent
    lines: list[str] = []
    kind, entries = node
    for entry in entries:
        lead, child = ("- ", entry) if kind == "seq" else (f"{entry[0]}: ", entry[1])
        if not isinstance(child, tuple):
            lines.append(pad + lead + child)
        elif kind == "seq" and child[0] == "map" and compact:
            sub = _render(child, indent + 2, steps, compact)
            lines.append(pad + "- " + sub[0][indent + 2:])
            lines.extend(sub[1:])
        else:
            lines.append(pad + lead.rstrip())
            lines.extend(_render(child, indent + steps[len(lines) % len(steps)], steps, compact))
    return lines


@st.composite
def documents(draw) -> str:
    root = draw(_node())
    if not isinstance(root, tuple) or root[0] != "map":
        root = ("map", [("parts", root)])
    steps = draw(st.lists(st.integers(0, 4), min_size=1, max_size=3))
    lines = _render(root, 0, steps, draw(st.booleans()))
    blank = draw(st.sets(st.integers(0, len(lines)), max_size=2))
    trailing = draw(st.sets(st.integers(0, len(lines)), max_size=2))
    out = []
    for i, line in enumerate(lines):
        if i in blank:
            out.append(draw(st.sampled_from(["", "  "])))
        out.append(line + ("  " if i in trailing else ""))
    return "\n".join(out) + draw(st.sampled_from(["\n", "", "\n\n"]))


_SETTINGS = settings(max_examples=sample(300, 3000), deadline=None,
                     suppress_health_check=[HealthCheck.too_slow])


@pytest.mark.sampled
@_SETTINGS
@given(documents())
def test_generated_documents(text):
    outcome(text)


@pytest.mark.sampled
@_SETTINGS
@given(documents(), st.integers(0, 10**6), st.sampled_from(["insert", "delete", "replace"]),
       st.sampled_from(list(" -:,[]{}\"#\n\t.0aeE+~'&!") + ["\r", "\x7f", "é"]))
def test_generated_documents_mutated(text, where, how, char):
    """One character inserted, deleted or replaced anywhere: at the edge of the subset."""
    i = where % (len(text) + 1)
    if how == "insert":
        text = text[:i] + char + text[i:]
    elif how == "delete":
        text = text[:i] + text[i + 1:]
    else:
        text = text[:i] + char + text[i + 1:]
    outcome(text)


@pytest.mark.sampled
def test_generated_documents_reach_every_outcome():
    """The generator reaches trees the plain reader answers, texts it declines and texts
    the loader refuses (a check of the generator, not of the readers)."""
    seen: set[str] = set()

    # derandomized: a check of the generator must not depend on the draw
    @settings(max_examples=sample(200, 600), deadline=None, database=None, derandomize=True)
    @given(documents())
    def collect(text):
        seen.add(outcome(text))

    collect()
    assert seen == {"same", "declined", "refused"}, seen


# ------------------------------------------------------------------- walked, line by line

#: keys that are names, and (with the odd-case pool) keys that are not, or are too long
_NAMES = ["a", "b", "c", "name", "parts", "y", "n", "on", "off", "e", "_", "nan", "inf", "k1"]
_ODD_KEYS = _KEYS + ["k" * 250, "k" * 1024, "k" * 1025, "a ", "a\t", "nULL", "tRUE", "-a", ".a"]
#: values the subset reads, and values at or beyond its edge
_PLAIN_VALUES = ["1", "-1", "+1", "007", "1.5", "-.5", "+.5", "5.", "1e3", "1.e5", "-0", ".",
                 "-.", "+", "0x1F", "0o17", ".inf", "-.Inf", ".nan", "1_0", ".5.", "~", "~/x",
                 "null", "TRUE", "tRUE", "yes", "mm", "7850 kg/m^3", "(x)", "a - b", "1 -",
                 "x" * 250, "1" * 250, '"x"', '""', '" a "', '"a: b"', '"] ["', '"}"']
_EDGE_VALUES = ["-", "-x", "- 1", "--1", "a  b", "a:b", "a: b", "a #b", "#", "a,b", "x\"",
                '"x', "'a'", "x" * 251, "1" * 301, "0" * 251, "&a x", "*a", "!x", "|", ">",
                "?", "? x", "%", "@", "`", "=", "[1,,2]", "[1, 2,]", "{a:1}", "{a: }", "[[1]]",
                '["a, b"]', "{a: 1, a: 2}", "{null: 1}", "[1] x", "\x7f", "\x0c", "é", "\t1"]


def walked(rng: random.Random, odd: float) -> str:
    """A text written line by line as an author would, keeping a stack of open block
    collections (a key's child one to four columns deeper, or a list at its key's own
    indentation; compact ``- key: value`` items at their odd columns), with the probability
    ``odd`` of each kind of slip: a bad key or value, a line off by a column, a stray
    blank, trailing characters, one character or line break inserted or replaced."""
    def value():
        if rng.random() < odd:
            return rng.choice(_EDGE_VALUES)
        r = rng.random()
        if r < 0.2:
            return "[" + rng.choice([", ", ",", " , "]).join(
                rng.choice(_PLAIN_VALUES) for _ in range(rng.randint(0, 3))) + "]"
        if r < 0.3:
            keys = rng.sample(_NAMES, rng.randint(0, 3))
            return "{" + ", ".join(f"{k}: {rng.choice(_PLAIN_VALUES)}" for k in keys) + "}"
        return rng.choice(_PLAIN_VALUES)

    lines: list[str] = []
    stack: list[tuple[str, int, set]] = [("map", 0, set())]  # open collections
    pending = False  # the last line was `key:` whose value is still to come
    for _ in range(rng.randint(1, 14)):
        if rng.random() < odd * 0.3:
            lines.append(rng.choice(["", " ", "   "]))
        if not pending and len(stack) > 1 and rng.random() < 0.3:
            stack.pop()
        if pending:
            step = rng.choice([1, 2, 2, 3, 4]) if rng.random() >= odd else rng.choice([-1, 0, 5])
            kind, indent, _ = stack[-1]
            seq = rng.random() < 0.5
            stack.append(("seq" if seq else "map", indent + (rng.choice([0, step]) if seq else step), set()))
            pending = False
        kind, indent, used = stack[-1]
        pad = " " * max(0, indent + (rng.choice([-1, 1, 2]) if rng.random() < odd else 0))
        key = rng.choice(_NAMES) if rng.random() >= odd else rng.choice(_ODD_KEYS)
        if kind == "map":
            if key in used and rng.random() >= odd:
                key += str(len(used))
            used.add(key)
            if rng.random() < 0.3:
                lines.append(pad + key + ":" + rng.choice(["", " "]))
                pending = True
            else:
                lines.append(pad + key + rng.choice([": ", ":  "]) + value())
        else:
            dash = rng.choice(["- ", "- ", "-  ", "-   "])
            if rng.random() < 0.4:
                lines.append(pad + dash + value())
            else:
                stack.append(("map", len(pad) + len(dash), {key}))
                pending = rng.random() < 0.3
                lines.append(pad + dash + key + (":" if pending else ": " + value()))
        if rng.random() < odd * 0.2:
            lines[-1] += rng.choice([" ", "  ", " #c", ":", " -", ",", "\r", "\t"])
    text = "\n".join(lines) + rng.choice(["\n", "", "\n\n", "\n  "])
    if rng.random() < odd:
        i = rng.randint(0, len(text))
        piece = rng.choice(list(" -:,[]{}\"#\n.0aeE+~'&!?|>\r\x7fé") + ["\n  ", "\n- ", ": ", "- "])
        text = text[:i] + piece + text[i + rng.randint(0, 1):]
    return text


@pytest.mark.sampled
@settings(max_examples=sample(300, 5000), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.randoms(use_true_random=False), st.sampled_from([0.0, 0.02, 0.08, 0.25]))
def test_walked_documents(rng, odd):
    """Texts written line by line (:func:`walked`), mostly inside the subset with a few
    slips: the same tree, declined or refused; as text and as bytes."""
    text = walked(rng, odd)
    outcome(text)
    outcome(text.encode("utf-8"))


def test_walked_documents_reach_every_outcome():
    """:func:`walked` writes texts the plain reader answers (most at ``odd=0``), texts it
    declines and texts the loader refuses (a check of the generator)."""
    rng = random.Random(3)
    seen = [outcome(walked(rng, odd)) for odd in (0.0, 0.25) for _ in range(300)]
    assert seen[:300].count("same") > 60, seen[:300].count("same")
    assert {"same", "declined", "refused"} <= set(seen)
