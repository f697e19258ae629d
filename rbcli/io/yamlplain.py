"""A second reader for the plainest body files, tried before libyaml: the same tree or none.

serves bench goal: batch of 1000 small files ≤ 1.5× naive (issue 23). A small body file
costs ~60 µs in :func:`rbcli.io.yamlsafe.load` (libyaml's events, each a Python object,
then the located tree); this reader builds the same tree from the lines of a file written
in the plainest block style in about half of that. It reads only:

- printable ASCII text and line breaks (``\\n``), without the characters that start
  anything else (``# & * ! | > ' % @ ` \\ ? <``, tabs, ``\\r``);
- block mappings whose keys are names (``[A-Za-z_][A-Za-z0-9_]*``, at most 250
  characters, not a null or bool word) followed by ``:`` and a space or the line's end; block lists (``- ``), also at
  their key's indentation; a list item that is a scalar, a one-line flow value or a
  mapping that starts on the item's line;
- values on their key's line: plain scalars of ``[A-Za-z0-9_.+~/^()]`` and inner spaces
  (a leading ``-`` only before a digit or ``.``), double-quoted strings without escapes,
  and one-line flow lists ``[...]`` and mappings ``{key: value, ...}`` of such scalars.

Anything else — a comment, a key without a value, a duplicate key, nested flow values,
nesting deeper than half the loader's limit, a document marker, a scalar that could go on to the next line, a list longer than the
loader's cap, a file over the size limit — and this reader answers None: the caller then
reads the file with :func:`rbcli.io.yamlsafe.load`, which gives every error and its
location. It never raises for a text. Where it answers, its tree equals the loader's,
node for node (values, raw text, quoting, marks): ``tests/test_yamlplain_oracle.py``
keeps it so, with generated files and every body file of the repository.
"""

from __future__ import annotations

import re

from rbcli.errors import InputError
from rbcli.io.yamlsafe import MAX_DEPTH, MapNode, Mark, Node, ScalarNode, SeqNode, max_bytes, plain_value

__all__ = ["tree"]

#: a character outside the subset, anywhere in the text
_OUTSIDE = re.compile("[^\\n" + re.escape(
    "".join(chr(c) for c in range(0x20, 0x7F) if chr(c) not in "#&*!|>'%@`\\?<")) + "]")
#: a key and what follows its colon (group 2: the value, possibly empty); at most 250
#: characters: libyaml refuses a key whose ':' is more than 1024 characters past its start
#: (a "simple key", yaml_parser_stale_simple_keys), in block and flow mappings alike
_KEY = re.compile(r"([A-Za-z_][A-Za-z0-9_]{0,249}):(?: +(.*)|$)")
#: a plain scalar on its key's line or in a flow value (no ',', no brackets)
_PLAIN = re.compile(r"(?:[A-Za-z0-9_.+~/^(]|-[0-9.])[A-Za-z0-9_.+~/^()\- ]*")
#: a double-quoted string without escapes
_QUOTED = re.compile(r'"[^"]*"')
#: the null and bool words: keys that are not names
_WORDS = frozenset(("null", "Null", "NULL", "true", "True", "TRUE", "false", "False", "FALSE"))
#: plain scalars longer than this are left to the loader (its digit limit is 300)
_LONGEST = 250
#: the first characters of every plain scalar that may not be a string (YAML 1.2 core
#: schema: numbers, null and bool words), and the characters of its decimal numbers
_MAYBE_NOT_STR = frozenset("~nNtTfF+-.0123456789")
_DECIMAL_CHARS = "0123456789.eE+-"
_DIGIT_OR_POINT = frozenset("0123456789.")

_new_tuple = tuple.__new__

#: the deepest nesting this reader takes: well inside the loader's MAX_DEPTH (a line adds at
#: most two block levels and a flow value one), so a text the loader refuses as too deep is
#: never answered here (body files nest at most 6 levels)
_DEEPEST = MAX_DEPTH // 2


class _Frame:
    """An open block collection: its indentation (0-based column), its items, and for a
    mapping the key whose value is a block still to come."""

    __slots__ = ("indent", "items", "is_map", "pending", "pending_mark")

    def __init__(self, indent: int, items: dict | list, is_map: bool) -> None:
        self.indent, self.items, self.is_map = indent, items, is_map
        self.pending: str | None = None
        self.pending_mark: Mark | None = None


def tree(data: bytes | str, list_cap: tuple | None = None) -> Node | None:
    """The tree :func:`rbcli.io.yamlsafe.load` makes of ``data``, for a text in this
    module's subset; None for any other text (and for one the loader would refuse).

    ``list_cap`` is the loader's ``(key, n, make_error)``: a root list under ``key`` of
    more than ``n`` items is left to the loader (which refuses it, located).
    """
    if data.__class__ is bytes:
        text = data.decode("ascii") if data.isascii() else ""
    elif data.__class__ is str:
        text = data if data.isascii() else ""
    else:
        return None
    try:
        limit = max_bytes()
    except InputError:  # RBCLI_MAX_BODY_BYTES is not a whole number: the loader says so
        return None
    if not text or len(text) > limit or _OUTSIDE.search(text) is not None:
        return None
    key_match = _KEY.fullmatch
    stack: list[_Frame] = []
    root: MapNode | None = None
    for number, line in enumerate(text.split("\n")):
        if len(stack) > _DEEPEST:
            return None
        content = line.lstrip(" ")
        if not content:
            continue
        indent = len(line) - len(content)
        content = content.rstrip(" ")
        while stack and stack[-1].indent > indent:
            if stack.pop().pending is not None:  # a key without a value
                return None
        if content[0] == "-" and (len(content) == 1 or content[1] == " "):
            top = stack[-1] if stack else None
            if top is None:
                return None
            if top.is_map:  # a block list as the value of the pending key
                if top.pending is None:
                    return None
                items: list = []
                top.items[top.pending] = (top.pending_mark, SeqNode(number << 32 | indent, items))
                top.pending = None
                stack.append(_Frame(indent, items, False))
            elif top.indent != indent:
                return None
            seq = stack[-1].items
            rest = content[1:].lstrip(" ")
            col = indent + len(content) - len(rest)
            if not rest or rest[0] == "-":
                return None
            m = key_match(rest)
            if m is None:
                node = _scalar(rest, number, col) if rest[0] not in "[{" else _value(rest, number, col)
                if node is None:
                    return None
                seq.append(node)
                continue
            entries: dict = {}
            seq.append(MapNode(number << 32 | col, entries))
            frame = _Frame(col, entries, True)
            stack.append(frame)
        else:
            m = key_match(content)
            if m is None:
                return None
            while stack and not stack[-1].is_map and stack[-1].indent == indent:
                stack.pop()  # a list at its key's indentation ends at the next key
            if not stack:
                if root is not None or indent != 0:
                    return None
                root = MapNode(number << 32, {})
                frame = _Frame(0, root.items, True)
                stack.append(frame)
            else:
                frame = stack[-1]
                if frame.is_map and frame.pending is not None and indent > frame.indent:
                    entries = {}
                    frame.items[frame.pending] = (frame.pending_mark,
                                                  MapNode(number << 32 | indent, entries))
                    frame.pending = None
                    frame = _Frame(indent, entries, True)
                    stack.append(frame)
                elif not (frame.is_map and frame.pending is None and frame.indent == indent):
                    return None
            col = indent
        key, value = m.groups()
        if key in frame.items or key in _WORDS:
            return None
        key_mark = _new_tuple(Mark, (number + 1, col + 1))
        if not value:
            frame.pending, frame.pending_mark = key, key_mark
            continue
        at = col + m.start(2)
        node = _scalar(value, number, at) if value[0] not in "[{" else _value(value, number, at)
        if node is None:
            return None
        frame.items[key] = (key_mark, node)
    for frame in stack:
        if frame.pending is not None:
            return None
    if root is None:
        return None
    if list_cap is not None:
        cap_key, cap_items, _ = list_cap
        capped = root.items.get(cap_key)
        if capped is not None and capped[1].__class__ is SeqNode and len(capped[1].items) > cap_items:
            return None
    return root


def _value(s: str, number: int, col: int) -> Node | None:
    """The node of the value ``s`` that starts at 0-based ``col`` of line ``number``."""
    first = s[0]
    if first == "[":
        if s[-1] != "]":
            return None
        items = []
        inner = s[1:-1]
        if inner.strip(" "):
            start = col + 1
            for piece in inner.split(","):
                text = piece.lstrip(" ")
                node = _scalar(text.rstrip(" "), number, start + len(piece) - len(text))
                if node is None:
                    return None
                items.append(node)
                start += len(piece) + 1
        return SeqNode(number << 32 | col, items)
    if first == "{":
        if s[-1] != "}":
            return None
        entries: dict = {}
        inner = s[1:-1]
        if inner.strip(" "):
            start = col + 1
            for piece in inner.split(","):
                text = piece.lstrip(" ")
                kcol = start + len(piece) - len(text)
                m = _KEY.fullmatch(text.rstrip(" "))
                if m is None or not m.group(2) or m.group(1) in entries or m.group(1) in _WORDS:
                    return None
                node = _scalar(m.group(2), number, kcol + m.start(2))
                if node is None:
                    return None
                entries[m.group(1)] = (_new_tuple(Mark, (number + 1, kcol + 1)), node)
                start += len(piece) + 1
        return MapNode(number << 32 | col, entries)
    return _scalar(s, number, col)


def _scalar(s: str, number: int, col: int) -> ScalarNode | None:
    """A plain or double-quoted scalar ``s`` (its whole text), or None."""
    if not s or len(s) > _LONGEST:
        return None
    mark = number << 32 | col  # the loader's form of a node's mark (yamlsafe.Node.mark)
    first = s[0]
    if not s.strip(_DECIMAL_CHARS):  # the usual numbers, read as the loader reads them
        if first == "-" and (len(s) == 1 or s[1] not in _DIGIT_OR_POINT):
            return None
        try:
            value = float(s) if "." in s or "e" in s or "E" in s else int(s)
        except ValueError:
            value = plain_value(s)
        return ScalarNode(mark, value, s, False)
    if first == '"':
        if _QUOTED.fullmatch(s) is None:
            return None
        raw = s[1:-1]
        return ScalarNode(mark, raw, raw, True)
    if _PLAIN.fullmatch(s) is None or "  " in s:
        return None
    return ScalarNode(mark, s if first not in _MAYBE_NOT_STR else plain_value(s), s, False)
