"""What one load shares (:class:`Session`: the parts budget, the files parsed) and each file's
:class:`Ctx` (where its messages point, its units, what it read); the readers raise
``ctx.error(node, message)``. A node is located by a :class:`rbcli.io.yamlsafe.Mark` (YAML
text) or a :class:`DataMark` (Python data: ``parts[2].radius``, or the call that made it,
``parts[2] (cylinder 'bore')``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from rbcli.errors import InputError, Location
from rbcli.io import yamlsafe as ys
from rbcli.io.reader import limit_from_env
from rbcli.io.yamlvalues import FileContext

__all__ = ["MAX_PARTS", "Session", "Ctx", "DataMark", "Label", "new_session"]

#: the default budget of a body: its parts, counting every use of an included file's parts
#: and each include once; RBCLI_MAX_PARTS raises it (README, "Budgets")
MAX_PARTS = 200_000


@dataclass
class Session:
    """What a load's files share: the parts budget, the files parsed; ``load`` reads an
    included file (:func:`rbcli.body.bodyfile._load`: the include reader need not import it)."""

    max_parts: int
    load: Callable | None = None
    used: int = 0  # parts and includes so far, every use counted
    parsed: dict = field(default_factory=dict)  # (real path, real folder) -> its loaded file
    parses: int = 0  # files parsed (the work count the tests check)
    #: densities no matter has, as located warnings (rbcli.body.plausible): the first is said
    densities: list = field(default_factory=list)

    def spend(self, ctx: Ctx, node: ys.Node | None, n: int) -> None:
        self.used += n
        if self.used > self.max_parts:
            raise ctx.error(node, self.over_message())

    def over_message(self) -> str:
        return (f"the body has more than {self.max_parts} parts (counting every use of an "
                f"included file's parts, and each include); set RBCLI_MAX_PARTS to raise the "
                "limit")

    def list_cap(self, filename: str) -> tuple:
        """:func:`rbcli.io.yamlsafe.load`'s ``list_cap``: a ``parts`` list may hold what is
        left of the budget (refused while its tree is built, at the first part beyond)."""
        return ("parts", self.max_parts - self.used,
                lambda mark: InputError(self.over_message(), Location(filename, mark.line, mark.col)))


def new_session(load: Callable | None = None) -> Session:
    """A session with the parts budget of ``RBCLI_MAX_PARTS`` (else :data:`MAX_PARTS`)."""
    return Session(limit_from_env("RBCLI_MAX_PARTS", MAX_PARTS), load)


class DataMark:
    """Where a value is in Python data: its key path (``parts[2].radius``). ``key`` is a
    mapping key, a list index or a :class:`Label` (it names the value and all it holds:
    ``parts[2] (cylinder 'bore')``); the root's path is ``root`` (``mapping``); no line."""

    __slots__ = ("parent", "key", "root")
    line = 0
    col = 0

    def __init__(self, parent: DataMark | None, key: str | int | Label, root: str = "") -> None:
        self.parent, self.key = parent, key
        self.root = root if parent is None else parent.root

    def child(self, key: str | int | Label) -> DataMark:
        return DataMark(self, key)

    def path(self) -> str:
        """``parts[2].radius``; the nearest :class:`Label` on the way up, as it is; the
        root's name for the root itself."""
        keys: list = []
        m: DataMark | None = self
        while m is not None:
            if isinstance(m.key, Label):
                return str(m.key)
            if m.parent is not None:
                keys.append(m.key)
            m = m.parent
        out = ""
        for k in reversed(keys):
            if isinstance(k, int):
                out += f"[{k}]"
            elif not k.isidentifier():
                out += f"[{k!r}]"
            else:
                out += f".{k}" if out else str(k)
        return out or self.root

    def __repr__(self) -> str:
        return f"DataMark({self.path()!r})"


class Label(str):
    """A :class:`DataMark` key that names a value and all it holds as a whole."""

    __slots__ = ()


@dataclass(kw_only=True)
class Ctx(FileContext):
    """One file of a body being read: its name in messages, its folder, its units, what it
    found."""

    base_dir: Path  # where relative paths start
    stack: tuple[str, ...] = ()  # real paths of the files being included (cycle check)
    warnings: list[str] = field(default_factory=list)
    #: real paths of the files read below this one (includes at any depth, meshes)
    inputs: list[str] = field(default_factory=list)
    session: Session = field(default_factory=lambda: Session(MAX_PARTS))
    #: how deep includes go below this file (0: it includes nothing)
    height: int = 0
    #: the file's own materials (its ``materials:`` section): matching key -> kg/m³
    materials: dict[str, float] = field(default_factory=dict)

    def where(self, node_or_mark: ys.Node | ys.Mark | DataMark | None) -> Location:
        """Where a node (or a mark) is: ``file:line:col`` in a file, or the key path of
        Python data (:class:`DataMark`)."""
        mark = node_or_mark.mark if isinstance(node_or_mark, ys.Node) else node_or_mark
        if isinstance(mark, DataMark):
            return Location(mark.path())
        return super().where(mark)
