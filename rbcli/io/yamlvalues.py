"""Typed, located values of a YAML tree (:mod:`rbcli.io.yamlsafe`'s nodes): numbers with
units, vectors, matrices, texts, flags, mappings with known keys. Every problem is an
:class:`rbcli.errors.InputError` at the node at fault, made by the reader's ``ctx``
(:class:`FileContext`: ``error(node, message)``, ``factor(kind, node)``, the file's unit
of a kind). The body file's readers (:mod:`rbcli.body`) and the field-balancing job's
(:mod:`rbcli.io.fieldjob`) read through these.
"""

from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from rbcli.errors import InputError, Location
from rbcli.io import units as un
from rbcli.io import yamlsafe as ys

#: largest magnitude accepted for any number in a body file (SI); the Earth's mass
#: (6e24 kg) and moment of inertia (8e37 kg m^2) are well inside.
HUGE = 1e60


@dataclass
class FileContext:
    """One file being read: its name in messages and its bare units (``units:``)."""

    file: str  # as shown in messages
    base_units: dict[str, str] = field(default_factory=dict)
    #: the file's unit of each kind read so far: kind -> (SI factor, unit text)
    factors: dict[str, tuple[float, str]] = field(default_factory=dict)

    def where(self, node_or_mark: ys.Node | ys.Mark | None) -> Location:
        """Where a node (or a mark) is: ``file:line:col``."""
        if node_or_mark is None:
            return Location(self.file)
        mark = node_or_mark.mark if isinstance(node_or_mark, ys.Node) else node_or_mark
        return Location(self.file, mark.line, mark.col)

    def error(self, node_or_mark: ys.Node | ys.Mark | None, message: str) -> InputError:
        return InputError(message, self.where(node_or_mark))

    def factor(self, kind: str, node: ys.Node | None = None) -> tuple[float, str]:
        """SI per bare number of ``kind`` in this file, and the unit's text."""
        if kind not in self.factors:
            try:
                self.factors[kind] = un.unit_for_kind(self.base_units, kind)
            except un.UnitError as exc:
                raise self.error(node, str(exc)) from None
        return self.factors[kind]


def suggest(word: str, allowed: tuple[str, ...] | list[str]) -> str:
    close = difflib.get_close_matches(word, list(allowed), n=1, cutoff=0.6)
    return f"; did you mean '{close[0]}'?" if close else ""


def check_keys(
    ctx: Any,
    node: ys.MapNode,
    allowed: tuple[str, ...] | list[str],
    what: str,
    required: tuple[str, ...] = (),
) -> None:
    for key, (kmark, _v) in node.items.items():
        if key not in allowed:
            raise ctx.error(
                kmark,
                f"unknown key '{key}' in {what}{suggest(key, allowed)} "
                f"(allowed: {', '.join(allowed)})",
            )
    for key in required:
        if key not in node.items:
            raise ctx.error(node, f"{what} needs '{key}'")


def describe(node: ys.Node) -> str:
    if isinstance(node, ys.MapNode):
        return "a mapping"
    if isinstance(node, ys.SeqNode):
        return "a list"
    assert isinstance(node, ys.ScalarNode)
    if node.value is None:
        return "nothing (null)"
    if isinstance(node.value, bool):
        return f"'{node.raw}' (a boolean)"
    return f"'{node.raw}'"


def mapping(ctx: Any, node: ys.Node, what: str) -> ys.MapNode:
    if not isinstance(node, ys.MapNode):
        raise ctx.error(node, f"{what} must be a mapping (key: value), not {describe(node)}")
    return node


def number(ctx: Any, node: ys.Node, kind: str, what: str) -> float:
    """A scalar quantity in SI: a bare number (in the file's units) or a text with a unit."""
    value = node.value if isinstance(node, ys.ScalarNode) else None
    if value is None or isinstance(value, bool):
        raise ctx.error(node, f"{what} must be a number or a quantity like '30 cm', not {describe(node)}")
    if isinstance(value, str):
        try:
            x = un.to_si(value, kind)
        except un.UnitError as exc:
            raise ctx.error(node, f"{what}: {exc}") from None
    else:
        x = un.bare_to_si(float(value), ctx.factor(kind, node)[1])
    if not math.isfinite(x):
        raise ctx.error(node, f"{what} must be finite, not {node.raw}")
    if abs(x) > HUGE:
        raise ctx.error(node, f"{what} is too large ({node.raw}); numbers are limited to 1e60 in SI units")
    return x


def floats(ctx: Any, node: ys.Node, kind: str, what: str, n: int | tuple[int, ...] = 3) -> list[float]:
    """A vector of ``n`` (or one of the sizes ``n``) quantities in SI, as a list of floats."""
    sizes = (n,) if isinstance(n, int) else n
    want = " or ".join(str(s) for s in sizes)
    if not isinstance(node, ys.SeqNode):
        raise ctx.error(node, f"{what} must be a list of {want} numbers like [1, 0, 0], not {describe(node)}")
    if len(node.items) not in sizes:
        raise ctx.error(node, f"{what} must have {want} components, not {len(node.items)}")
    return [number(ctx, item, kind, what) for item in node.items]


def vector(ctx: Any, node: ys.Node, kind: str, what: str, n: int | tuple[int, ...] = 3) -> np.ndarray:
    return np.array(floats(ctx, node, kind, what, n))


def rows(ctx: Any, node: ys.Node, kind: str, what: str) -> list[list[float]]:
    """A 3x3 matrix of quantities in SI, as three lists of floats."""
    if not isinstance(node, ys.SeqNode) or len(node.items) != 3:
        raise ctx.error(node, f"{what} must be a 3x3 matrix: a list of three rows of three numbers")
    return [floats(ctx, row, kind, f"a row of {what}") for row in node.items]


def matrix(ctx: Any, node: ys.Node, kind: str, what: str) -> np.ndarray:
    return np.array(rows(ctx, node, kind, what))


def string(ctx: Any, node: ys.Node, what: str) -> str:
    if not isinstance(node, ys.ScalarNode) or not isinstance(node.value, str):
        raise ctx.error(node, f"{what} must be a text, not {describe(node)}")
    return node.value


def flag(ctx: Any, node: ys.Node, what: str) -> bool:
    if not isinstance(node, ys.ScalarNode) or not isinstance(node.value, bool):
        raise ctx.error(node, f"{what} must be true or false, not {describe(node)}")
    return node.value


def positive(ctx: Any, node: ys.Node, kind: str, what: str, allow_zero: bool = False) -> float:
    x = number(ctx, node, kind, what)
    if x < 0 or (x == 0 and not allow_zero):
        raise ctx.error(node, f"{what} must be {'zero or ' if allow_zero else ''}positive, not {node.raw}")
    return x
