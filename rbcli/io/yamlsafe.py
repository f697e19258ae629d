"""The safe YAML loader that every body file goes through.

:func:`load` turns a body file into a tree of :class:`Node` objects, each with its 1-based
line and column (for ``file:line:col: message``). It refuses with a located
:class:`~rbcli.errors.InputError`, never another exception: files over :data:`MAX_BYTES`,
text not UTF-8, control characters; nesting deeper than :data:`MAX_DEPTH` (on libyaml's
iterative event stream: PyYAML's recursive composer, which crashes at ~30 000 levels, is
never used); anchors, aliases, explicit tags, several or empty documents; keys that are not
names, duplicate and merge keys; integers over 300 digits. Plain scalars follow the YAML
1.2 *core* schema (``1e3`` a float, ``no`` and ``1:30`` strings, ``017`` the integer 17)."""

from __future__ import annotations

import re
from dataclasses import FrozenInstanceError
from typing import Any, NamedTuple

import yaml
from yaml.reader import ReaderError

from rbcli.errors import InputError, Location
from rbcli.io.reader import limit_from_env, size_text

__all__ = [
    "MAX_BYTES",
    "MAX_DEPTH",
    "MapNode",
    "Mark",
    "Node",
    "ScalarNode",
    "SeqNode",
    "load",
    "max_bytes",
    "plain_value",
    "to_python",
    "where",
]

MAX_BYTES = 32 * 1024 * 1024
"""Body files larger than this (in bytes of UTF-8) are refused before parsing: 32 MiB
holds a body of ~170 000 generated parts (``bench/large_bodies.py``, ~190 bytes a part),
which loads in a few seconds; ``RBCLI_MAX_BODY_BYTES`` changes it (:func:`max_bytes`)."""

MAX_DEPTH = 64
"""Nesting of mappings and sequences deeper than this is refused before composing."""

_MAX_DIGITS = 300  # integers longer than this are refused ("number too long")

# libyaml's parser when PyYAML was built with it (only its events are read: no constructor
# or resolver is made); the pure-Python loader otherwise.
_LOADER: type = (
    yaml.cyaml.CParser if getattr(yaml, "__with_libyaml__", False) else yaml.SafeLoader
)

_EMPTY = "the file is empty; a body needs `parts:` or a single part"


# --- nodes


class Mark(NamedTuple):
    """Where a node starts: 1-based line and column (columns count characters). It equals
    only another :class:`Mark` (never a plain tuple), as a dataclass would."""

    line: int
    col: int

    def __str__(self) -> str:
        return f"{self.line}:{self.col}"

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Mark):
            return tuple(self) == tuple(other)
        return False if isinstance(other, tuple) else NotImplemented

    def __ne__(self, other: object) -> bool:
        return not self == other

    __hash__ = tuple.__hash__


class Node:
    """Base of the loaded tree (frozen): ``.tag`` (``"map"``, ``"seq"``, ``"str"``, ``"int"``,
    ``"float"``, ``"bool"``, ``"null"``) and ``.mark``, the 1-based :class:`Mark` of where it
    starts, kept as given or as the loader's 0-based ``line << 32 | column`` int (untracked by
    the garbage collector: a large body's tree holds millions of nodes)."""

    __slots__ = ("_mark",)
    __match_args__: tuple[str, ...] = ("mark",)

    def __init__(self, mark: Mark | int) -> None:
        object.__setattr__(self, "_mark", mark)

    @property
    def mark(self) -> Mark:
        """Where the node starts (1-based line and column)."""
        m = self._mark
        return Mark((m >> 32) + 1, (m & 0xFFFFFFFF) + 1) if isinstance(m, int) else m

    @property
    def tag(self) -> str:  # pragma: no cover - every subclass overrides it
        raise NotImplementedError

    def _fields(self) -> tuple:  # what equality and the hash compare
        return tuple(getattr(self, name) for name in self.__match_args__)

    def __setattr__(self, name: str, value: object) -> None:
        raise FrozenInstanceError(f"cannot assign to field {name!r}")

    def __delattr__(self, name: str) -> None:
        raise FrozenInstanceError(f"cannot delete field {name!r}")

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        return self._fields() == other._fields()  # type: ignore[attr-defined]

    def __hash__(self) -> int:
        return hash(self._fields())


class ScalarNode(Node):
    """A scalar, ``ScalarNode(mark, value, raw, quoted)``: ``value`` resolved (core schema
    for plain scalars, else str), ``raw`` its text before resolution (``"1e3"``), ``quoted``
    True for quoted and block scalars (always strings)."""

    __slots__ = ("value", "raw", "quoted")
    __match_args__ = ("mark", "value", "raw", "quoted")
    value: str | int | float | bool | None
    raw: str
    quoted: bool

    def __init__(
        self, mark: Mark | int, value: str | int | float | bool | None, raw: str, quoted: bool
    ) -> None:
        object.__setattr__(self, "_mark", mark)
        object.__setattr__(self, "value", value)
        object.__setattr__(self, "raw", raw)
        object.__setattr__(self, "quoted", quoted)

    @property
    def tag(self) -> str:
        v = self.value
        if v is None:
            return "null"
        if isinstance(v, bool):
            return "bool"
        if isinstance(v, int):
            return "int"
        if isinstance(v, float):
            return "float"
        return "str"

    def __repr__(self) -> str:
        q = " quoted" if self.quoted else ""
        return f"ScalarNode({self.tag}{q} {self.value!r} at {self.mark})"


class _Items(Node):
    """A collection: its ``items``, filled as the parser goes."""

    __slots__ = ("items",)

    def __init__(self, mark: Mark | int, items: dict | list) -> None:
        object.__setattr__(self, "_mark", mark)
        object.__setattr__(self, "items", items)


class MapNode(_Items):
    """A mapping, ``MapNode(mark, items)``: ``items`` maps each key to (the key's
    :class:`Mark`, the value node), in source order."""

    __slots__ = ()
    __match_args__ = ("mark", "items")
    items: dict[str, tuple[Mark, Node]]

    @property
    def tag(self) -> str:
        return "map"

    def __repr__(self) -> str:
        return f"MapNode(keys={list(self.items)!r} at {self.mark})"


class SeqNode(_Items):
    """A sequence of nodes: ``SeqNode(mark, items)``."""

    __slots__ = ()
    __match_args__ = ("mark", "items")
    items: list[Node]

    @property
    def tag(self) -> str:
        return "seq"

    def __repr__(self) -> str:
        return f"SeqNode({len(self.items)} items at {self.mark})"


def where(filename: str, mark: Mark) -> Location:
    """The :class:`~rbcli.errors.Location` of ``mark`` in ``filename``."""
    return Location(filename, mark.line, mark.col)


def to_python(node: Node) -> object:
    """Plain Python data (dict / list / str / int / float / bool / None) of a tree."""
    if isinstance(node, ScalarNode):
        return node.value
    if isinstance(node, MapNode):
        return {key: to_python(value) for key, (_, value) in node.items.items()}
    if isinstance(node, SeqNode):
        return [to_python(item) for item in node.items]
    raise TypeError(f"not a yamlsafe node: {node!r}")


# --- positions and errors

_BREAK = re.compile("\r\n|[\r\n\x85\u2028\u2029]")  # the line breaks libyaml counts


def _mark_of_prefix(prefix: str) -> Mark:
    """The 1-based mark of the character that follows ``prefix``."""
    line = 1
    last_end = 0
    for m in _BREAK.finditer(prefix):
        line += 1
        last_end = m.end()
    return Mark(line, len(prefix) - last_end + 1)


def _yaml_mark(mark: Any) -> Mark:
    """A yaml Mark (0-based line/column; PyYAML's or libyaml's) or None as a 1-based :class:`Mark`."""
    if mark is None:
        return Mark(1, 1)
    return Mark(mark.line + 1, mark.column + 1)


def _error(message: str, filename: str, mark: Mark) -> InputError:
    return InputError(message, where=where(filename, mark))


def _one_line(text: object) -> str:
    return " ".join(str(text).split())


def _marked_error(exc: yaml.MarkedYAMLError, filename: str) -> InputError:
    problem = _one_line(exc.problem) if exc.problem else ""
    mark = exc.problem_mark if exc.problem_mark is not None else exc.context_mark
    if "maximum nesting depth" in problem:
        # libyaml >= 0.2.5 stops at 1000 levels while scanning ahead, before the event
        # that would meet rbcli's own, lower, limit: one message either way
        return _error(
            f"nesting is too deep: more than {MAX_DEPTH} levels of lists and mappings; body "
            f"files allow at most {MAX_DEPTH}",
            filename,
            _yaml_mark(mark),
        )
    message = f"invalid YAML: {problem}" if problem else "invalid YAML"
    if exc.context:
        context = _one_line(exc.context)
        if exc.context_mark is not None and exc.problem_mark is not None:
            cm = _yaml_mark(exc.context_mark)
            context += f" that starts at line {cm.line}, column {cm.col}"
        message += f" ({context})" if problem else f": {context}"
    return _error(message, filename, _yaml_mark(mark))


def _reader_error(exc: ReaderError, text: str, filename: str) -> InputError:
    position = exc.position if isinstance(exc.position, int) else 0
    if _LOADER is not yaml.SafeLoader:
        # libyaml reads the UTF-8 encoding of the text: the position is a byte offset.
        prefix = text.encode("utf-8", "surrogatepass")[:position].decode("utf-8", "replace")
    else:
        prefix = text[:position]
    char = exc.character
    if isinstance(char, int):
        what = f"character U+{char:04X}"
    elif isinstance(char, str) and len(char) == 1:
        what = f"character U+{ord(char):04X}"
    else:
        what = "character"
    message = (
        f"invalid {what}: {_one_line(exc.reason)}; body files must be printable text "
        "(tabs and line breaks are fine)"
    )
    return _error(message, filename, _mark_of_prefix(prefix))


# --- decoding


def max_bytes() -> int:
    """The size limit of a body file: :data:`MAX_BYTES`, or ``RBCLI_MAX_BODY_BYTES``."""
    return limit_from_env("RBCLI_MAX_BODY_BYTES", MAX_BYTES)


def _decode(text: str | bytes, filename: str) -> str:
    """Check the size, decode UTF-8, drop a leading BOM; refuse lone surrogates."""
    MAX_BYTES = max_bytes()  # noqa: N806  (the module's, or the environment's)
    if isinstance(text, (bytes, bytearray, memoryview)):
        data = bytes(text)
        if len(data) > MAX_BYTES:
            raise _error(
                f"file is {len(data)} bytes; body files are limited to {size_text(MAX_BYTES)}",
                filename,
                Mark(1, 1),
            )
        try:
            decoded = data.decode("utf-8")
        except UnicodeDecodeError as exc:
            prefix = data[: exc.start].decode("utf-8", "replace").removeprefix("\ufeff")
            raise _error(
                f"the file is not valid UTF-8 (byte 0x{data[exc.start]:02x} cannot be "
                "decoded here); body files must be UTF-8 text",
                filename,
                _mark_of_prefix(prefix),
            ) from exc
        return decoded.removeprefix("\ufeff")
    if not isinstance(text, str):
        raise TypeError(f"load() needs str or bytes, not {type(text).__name__}")
    size = len(text.encode("utf-8", "surrogatepass"))
    if size > MAX_BYTES:
        raise _error(
            f"file is {size} bytes; body files are limited to {size_text(MAX_BYTES)}",
            filename,
            Mark(1, 1),
        )
    text = text.removeprefix("\ufeff")
    try:
        text.encode("utf-8")
    except UnicodeEncodeError as exc:
        raise _error(
            f"invalid character U+{ord(text[exc.start]):04X} (a lone surrogate); "
            "body files must be UTF-8 text",
            filename,
            _mark_of_prefix(text[: exc.start]),
        ) from exc
    return text



# --- YAML 1.2 core schema

# The null and bool words (the empty scalar is null too); each starts with _WORD_START.
_WORDS: dict[str, bool | None] = {
    "~": None, "null": None, "Null": None, "NULL": None,
    "true": True, "True": True, "TRUE": True,
    "false": False, "False": False, "FALSE": False,
}  # fmt: skip
_WORD_START = frozenset("~nNtTfF")
# int [-+]?[0-9]+ (no group takes part) or float (a fraction or an exponent group does)
_DECIMAL = re.compile(r"[-+]?(?:(\.[0-9]+)|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?")
_INT8 = re.compile(r"0o[0-7]+")
_INT16 = re.compile(r"0x[0-9a-fA-F]+")
_INF = re.compile(r"[-+]?(\.inf|\.Inf|\.INF)")
_NAN = re.compile(r"\.nan|\.NaN|\.NAN")
# Every non-string of the core schema starts with one of these (or is empty).
_NUM_START = frozenset("+-.0123456789")
_MAYBE_NOT_STR = _WORD_START | _NUM_START


def _int(digits: str, base: int, filename: str, mark: object) -> int:
    """``int(digits, base)``, refused when it has too many digits; ``mark``: where the
    scalar starts (a :class:`Mark`, or libyaml's own)."""
    count = len(digits.lstrip("+-"))
    if count <= _MAX_DIGITS:
        try:
            return int(digits, base)
        except ValueError:  # defensive: the patterns only admit valid, short digits
            pass
    raise _error(
        f"number too long: {count} digits; numbers may have at most {_MAX_DIGITS} digits",
        filename,
        mark if isinstance(mark, Mark) else _yaml_mark(mark),
    )


def _resolve_plain(raw: str, filename: str, mark: object) -> str | int | float | bool | None:
    """The value of a plain scalar by the YAML 1.2 core schema (spec §10.3.2); ``mark``
    (a :class:`Mark` or libyaml's) locates a number that is too long."""
    if not raw:
        return None
    first = raw[0]
    if first not in _MAYBE_NOT_STR:
        return raw
    if first in _WORD_START:  # only null and bool words start so; nothing numeric does
        return _WORDS.get(raw, raw)
    # [-+.0-9]: a decimal int or float (the common case), then the rarer forms
    m = _DECIMAL.fullmatch(raw)
    if m is not None:
        if m.lastindex is None:  # no fraction, no exponent: [-+]?[0-9]+
            return _int(raw, 10, filename, mark)
        return float(raw)  # overflow (1e999) gives inf; validation refuses it, located
    if _INT8.fullmatch(raw):
        return _int(raw[2:], 8, filename, mark)
    if _INT16.fullmatch(raw):
        return _int(raw[2:], 16, filename, mark)
    if _INF.fullmatch(raw):
        return float("-inf") if first == "-" else float("inf")
    if _NAN.fullmatch(raw):
        return float("nan")
    return raw


def plain_value(raw: str) -> str | int | float | bool | None:
    """The value of the plain scalar ``raw`` as :func:`load` gives it (an integer of more than
    300 digits: an InputError at 1:1)."""
    return _resolve_plain(raw, "", Mark(1, 1))


_KIND = {type(None): "null", bool: "a boolean", int: "a number", float: "a number"}


# --- event-driven build


def _show_tag(tag: str) -> str:
    prefix = "tag:yaml.org,2002:"
    return "!!" + tag[len(prefix) :] if tag.startswith(prefix) else tag


def _check_node_event(event: yaml.NodeEvent, filename: str) -> None:
    """Refuse anchors, aliases and explicit tags."""
    if isinstance(event, yaml.AliasEvent) or event.anchor is not None:
        raise _error(
            "anchors and aliases (&, *) are not allowed in body files; "
            "write each value out in full",
            filename,
            _yaml_mark(event.start_mark),
        )
    tag = getattr(event, "tag", None)
    if tag is not None:
        raise _error(
            f"tags such as !!python/object are not allowed in body files (found "
            f"{_show_tag(tag)!r}); write plain values, and quote a value to make it a string",
            filename,
            _yaml_mark(event.start_mark),
        )


def _check_plain_key(raw: str, filename: str, mark: Mark) -> None:
    """Refuse a plain key that is not a name: ``<<``, or one that resolves to a non-string."""
    if raw == "<<":
        raise _error(
            "merge keys (<<) are not allowed in body files; write the keys out in full",
            filename,
            mark,
        )
    value = _resolve_plain(raw, filename, mark)
    if not isinstance(value, str):
        shown = raw if raw else "an empty key"
        raise _error(
            f"keys must be names, not {_KIND[type(value)]} ({shown}); "
            f'quote it ("{raw}") if it is meant as a name',
            filename,
            mark,
        )


def _duplicate_key(raw: str, first: Mark, filename: str, mark: Mark) -> InputError:
    return _error(
        f"duplicate key {raw!r} (first at line {first.line}, column {first.col}); "
        "each key may appear only once in a mapping",
        filename,
        mark,
    )


def _start(event: yaml.Event) -> int:
    """Where ``event`` starts, as a node keeps it (see :class:`Node`)."""
    return event.start_mark.line << 32 | event.start_mark.column


class _Tree:
    """The tree being built from libyaml's events: the open collection's ``items`` (a
    mapping's dict or a list's list; at first ``top``, which receives the document's root)
    and whether it is a mapping's; the enclosing ones wait on ``stack``. A mapping's key
    waits in ``key`` for its value. ``cap`` is :func:`load`'s ``list_cap``."""

    def __init__(self, filename: str, cap: tuple | None) -> None:
        self.filename = filename
        self.top: list[Node] = []
        self.stack: list[tuple[dict | list, bool]] = []
        self.items: dict[str, tuple[Mark, Node]] | list[Node] = self.top
        self.in_map = False
        self.key: str | None = None
        self.key_mark: Mark | None = None
        self.documents = 0
        self.cap_key, self.cap_items, self.cap_error = cap if cap is not None else (None, 0, None)
        self.capped: list | None = None  # the root mapping's list under cap_key, once open

    def error(self, message: str, event: yaml.Event) -> InputError:
        return _error(message, self.filename, _yaml_mark(event.start_mark))

    def scalar(self, event: yaml.ScalarEvent) -> None:
        if event.anchor is not None or event.tag is not None:
            _check_node_event(event, self.filename)  # raises
        raw = event.value
        if self.in_map and self.key is None:
            self.take_key(raw, bool(event.style), _yaml_mark(event.start_mark))
        elif event.style:  # quoted or block: a string
            self.add(ScalarNode(_start(event), raw, raw, True), event)
        else:
            value = _resolve_plain(raw, self.filename, event.start_mark)
            self.add(ScalarNode(_start(event), value, raw, False), event)

    def take_key(self, raw: str, quoted: bool, mark: Mark) -> None:
        if not quoted:
            _check_plain_key(raw, self.filename, mark)
        if raw in self.items:
            raise _duplicate_key(raw, self.items[raw][0], self.filename, mark)  # type: ignore[call-overload]
        self.key, self.key_mark = raw, mark

    def add(self, node: Node, event: yaml.Event) -> None:
        """Put ``node`` in the open collection (under the waiting key of a mapping)."""
        if self.in_map:
            self.items[self.key] = (self.key_mark, node)  # type: ignore[index, call-overload]
            self.key = None
            return
        if self.items is self.capped and len(self.items) >= self.cap_items:
            self.top.clear()  # the tree goes now, not with the traceback
            self.stack.clear()
            self.items = self.capped = None  # type: ignore[assignment]
            raise self.cap_error(_yaml_mark(event.start_mark))  # type: ignore[misc]
        self.items.append(node)  # type: ignore[union-attr]

    def open(self, event: yaml.CollectionStartEvent) -> None:
        if event.anchor is not None or event.tag is not None:
            _check_node_event(event, self.filename)  # raises
        is_map = isinstance(event, yaml.MappingStartEvent)
        if self.in_map and self.key is None:
            what = "a mapping" if is_map else "a list"
            raise self.error(f"keys must be names, not {what}; write `name: value`", event)
        if len(self.stack) >= MAX_DEPTH:
            raise self.error(f"nesting is too deep: more than {MAX_DEPTH} levels of lists and "
                             f"mappings; body files allow at most {MAX_DEPTH}", event)
        items: dict | list = {} if is_map else []
        if self.in_map and self.key == self.cap_key and len(self.stack) == 1 and not is_map:
            self.capped = items  # type: ignore[assignment]
        self.add(MapNode(_start(event), items) if is_map else SeqNode(_start(event), items), event)
        self.stack.append((self.items, self.in_map))
        self.items, self.in_map = items, is_map

    def close(self, event: yaml.CollectionEndEvent) -> None:  # noqa: ARG002
        self.items, self.in_map = self.stack.pop()

    def document(self, event: yaml.DocumentStartEvent) -> None:
        self.documents += 1
        if self.documents > 1:
            raise self.error("more than one YAML document in the file (a second one starts "
                             "here); a body file holds exactly one document", event)


def _parse(text: str, filename: str, cap: tuple | None = None) -> Node | None:
    """Build the node tree from libyaml's event stream in one pass (None for no document),
    refusing what is refused as soon as its event arrives: a hostile file costs milliseconds.
    """
    if cap is not None and text.count("-") + text.count(",") >= cap[1]:
        _count_first(text, cap)
    loader = _LOADER(text)
    tree = _Tree(filename, cap)
    refuse = lambda event: _check_node_event(event, filename)  # noqa: E731 - an alias: raises
    handle = {yaml.ScalarEvent: tree.scalar, yaml.MappingStartEvent: tree.open,
              yaml.SequenceStartEvent: tree.open, yaml.MappingEndEvent: tree.close,
              yaml.SequenceEndEvent: tree.close, yaml.AliasEvent: refuse,
              yaml.DocumentStartEvent: tree.document}  # the others: stream and document ends
    try:
        while (event := loader.get_event()) is not None:
            action = handle.get(type(event))
            if action is not None:
                action(event)
    finally:
        loader.dispose()
    return tree.top[-1] if tree.top else None


def _count_first(text: str, cap: tuple) -> None:
    """``cap``'s list counted over the events alone, no node made (each list item takes a '-'
    or a ',': called when a file may exceed it): its error at the first item beyond, with no
    tree in memory (400 000 parts: ~100 MiB, not ~450). Anchors, tags, YAML errors: the tree's."""
    key, most, make_error = cap
    loader = _LOADER(text)
    depth, want_key, last, capped, n = 0, True, None, False, 0
    try:
        while (event := loader.get_event()) is not None:
            if isinstance(event, yaml.CollectionEndEvent):
                depth -= 1
                capped = capped and depth > 1
            elif isinstance(event, yaml.NodeEvent):
                if event.anchor is not None or getattr(event, "tag", None) is not None:
                    return  # (an alias has an anchor)
                if depth == 1:  # the root's keys and values
                    last = event.value if want_key and isinstance(event, yaml.ScalarEvent) else last
                    capped = not want_key and last == key and isinstance(event, yaml.SequenceStartEvent)
                    want_key = not want_key
                elif depth == 2 and capped and (n := n + 1) > most:
                    raise make_error(_yaml_mark(event.start_mark))
                depth += isinstance(event, yaml.CollectionStartEvent)
    except yaml.YAMLError:
        return
    finally:
        loader.dispose()


# --- load


def load(text: str | bytes, filename: str, *, list_cap: tuple | None = None) -> Node:
    """Parse a body file safely: the root :class:`Node`, or an InputError located at
    ``filename:line:col``. ``text`` is str or bytes (UTF-8, a BOM dropped); ``list_cap``
    ``(key, n, make_error)``: the list under the root's ``key`` holds at most ``n`` items,
    the next one raising ``make_error(mark)`` before the rest of the file is read."""
    text = _decode(text, filename)
    try:
        root = _parse(text, filename, list_cap)
    except yaml.MarkedYAMLError as exc:
        raise _marked_error(exc, filename) from exc
    except ReaderError as exc:
        raise _reader_error(exc, text, filename) from exc
    except yaml.YAMLError as exc:  # defensive: PyYAML's other errors carry no mark
        raise _error(f"invalid YAML: {_one_line(exc)}", filename, Mark(1, 1)) from exc
    except RecursionError as exc:  # defensive: nothing here recurses
        raise _error(
            f"nesting is too deep; body files allow at most {MAX_DEPTH} levels",
            filename,
            Mark(1, 1),
        ) from exc
    except InputError:  # located already (an InputError is a ValueError)
        raise
    except ValueError as exc:  # defensive: e.g. an encoding problem inside PyYAML
        raise _error(
            f"cannot read the file as YAML: {_one_line(exc)}", filename, Mark(1, 1)
        ) from exc
    if root is None or (isinstance(root, ScalarNode) and not root.quoted and root.raw == ""):
        raise _error(_EMPTY, filename, Mark(1, 1))
    return root
