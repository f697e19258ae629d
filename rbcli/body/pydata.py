"""Bodies from Python data: :func:`load_data` (a mapping like a body file's),
:func:`from_parts` (parts made by :mod:`rbcli.parts`), and the bodies made from another
(:func:`replace_part`, :func:`with_points`).

There is one validator, the body loader (:mod:`rbcli.body.bodyfile` and its readers): Python data
is first *frozen* (:func:`freeze`: plain, immutable values — str, int, float, bool, None,
tuples, read-only mappings with text keys; numpy scalars and arrays become Python numbers
and tuples), then made into the loader's tree (:func:`tree`), each node located by a
:class:`rbcli.body.loadctx.DataMark` (its key path, ``parts[2].radius``) instead of a line
and column. The loader then makes every check and says every message it says of a file.

What freezing refuses: a value of a type no body file holds (a complex number, a set, an
object) or a mapping key that is not a text is a ``TypeError`` naming where it is; a cycle,
nesting deeper than a body file may nest, an integer of more than 300 digits or a text that
is not Unicode (a lone surrogate) is an :class:`rbcli.errors.InputError` located there.

A body built here keeps its document as YAML text (``Body.text``, what
:func:`rbcli.body.document.dump` writes of the frozen data), so that it can be written
(``Body.to_yaml``), changed (``Body.replace``) and reported like a body read from a file.
"""

from __future__ import annotations

import numbers
import os
import sys
from collections.abc import Iterable, Iterator, Mapping, Sequence, Sized
from pathlib import Path
from types import MappingProxyType
from typing import Any

from rbcli.errors import InputError, Location
from rbcli.io import yamlsafe as ys
from rbcli.body.loadctx import DataMark, Label

__all__ = ["PartSpec", "freeze", "thaw", "tree", "load_data", "from_parts", "rebuilt", "replace_part", "move_part", "with_points", "SOURCE"]

#: ``Body.source`` of a body built from Python data
SOURCE = "<data>"
_MAX_DIGITS = 300  # as a body file's integers (rbcli.io.yamlsafe)
_TOO_DEEP = (f"nesting is too deep: more than {ys.MAX_DEPTH} levels of lists and mappings; "
             f"body files allow at most {ys.MAX_DEPTH}")
_KINDS = "numbers, texts, booleans, None, lists and mappings with text keys"


# --------------------------------------------------------------------------- freezing


def freeze(value: object, where: str = "") -> object:
    """``value`` as immutable plain data a body file could hold (see the module's notes).

    Parameters
    ----------
    value : object — a mapping, a list, a number, ...
    where : str — its key path or parameter name, for messages (``parts[2].at``)

    Raises
    ------
    TypeError
        A value of a type no body file holds, or a mapping key that is not a text.
    rbcli.InputError
        A cycle, nesting too deep, an integer too long, a lone surrogate.
    """
    return _freeze(value, where, 0, set())


def _path(where: str, key: str | int) -> str:
    if key.__class__ is int:
        return f"{where}[{key}]"
    text = key if key.isidentifier() else repr(key)
    return f"{where}.{text}" if where else text


def _at(where: str) -> Location:
    return Location(where or "<data>")


def _freeze(v: Any, where: str, depth: int, open_ids: set[int]) -> object:
    c = v.__class__
    if c is str:
        return _text(v, where)
    if c is float or c is bool or v is None:
        return v
    if c is int:
        return _integer(v, where)
    if c is MappingProxyType or isinstance(v, Mapping):
        return _container(v, where, depth, open_ids, True)
    if c is tuple or c is list:
        return _container(v, where, depth, open_ids, False)
    if isinstance(v, str):  # numpy.str_, other subclasses
        return _text(str(v), where)
    np = sys.modules.get("numpy")  # numpy values exist only once numpy is imported
    if np is not None:
        if isinstance(v, np.ndarray):
            if v.dtype.kind not in "biuf":
                raise TypeError(f"{where or 'value'}: an array of {v.dtype} is not a value a "
                                f"body file holds ({_KINDS})")
            return _freeze(v.tolist(), where, depth, open_ids)
        if isinstance(v, np.bool_):
            return bool(v)
        if isinstance(v, np.integer):
            return _integer(int(v), where)
        if isinstance(v, np.floating):
            return float(v)
    if isinstance(v, bool):  # never reached: bool cannot be subclassed
        return bool(v)
    if isinstance(v, numbers.Integral):
        return _integer(int(v), where)
    if isinstance(v, numbers.Real):
        return float(v)
    if isinstance(v, Sequence) and not isinstance(v, (bytes, bytearray)):
        return _container(v, where, depth, open_ids, False)
    raise TypeError(f"{where or 'value'}: {type(v).__name__} is not a value a body file holds "
                    f"({_KINDS})")


def _text(s: str, where: str) -> str:
    if not s.isascii():
        try:
            s.encode("utf-8")
        except UnicodeEncodeError as exc:
            raise InputError(f"invalid character U+{ord(s[exc.start]):04X} (a lone surrogate); "
                             "texts must be Unicode", _at(where)) from None
    return s


def _integer(n: int, where: str) -> int:
    if -(10**_MAX_DIGITS) < n < 10**_MAX_DIGITS:
        return n
    raise InputError(f"number too long: more than {_MAX_DIGITS} digits; numbers may have at "
                     f"most {_MAX_DIGITS} digits", _at(where))


def _container(v: Any, where: str, depth: int, open_ids: set[int], is_map: bool) -> object:
    if depth >= ys.MAX_DEPTH:
        raise InputError(_TOO_DEEP, _at(where))
    me = id(v)
    if me in open_ids:
        raise InputError(f"{'this mapping' if is_map else 'this list'} contains itself (a "
                         "cycle); body data is a tree of values", _at(where))
    open_ids.add(me)
    try:
        if is_map:
            out = {}
            for key in v:
                if key.__class__ is not str:
                    if not isinstance(key, str):
                        raise TypeError(f"{where or 'mapping'}: keys must be texts, not "
                                        f"{type(key).__name__} ({_short(key)})")
                    key = str(key)
                out[_text(key, where)] = _freeze(v[key], _path(where, key), depth + 1, open_ids)
            return MappingProxyType(out)
        return tuple(_freeze(x, _path(where, i), depth + 1, open_ids) for i, x in enumerate(v))
    finally:
        open_ids.discard(me)


def _short(x: object) -> str:
    try:
        text = repr(x)
    except Exception:  # noqa: BLE001 - a hostile __repr__: the type says enough
        return type(x).__name__
    return text if len(text) <= 40 else text[:37] + "..."


def thaw(v: object) -> object:
    """Frozen data as plain, mutable data (dicts and lists), e.g. for YAML."""
    if v.__class__ is MappingProxyType or isinstance(v, PartSpec):
        return {k: thaw(x) for k, x in v.items()}  # type: ignore[union-attr]
    if v.__class__ is tuple:
        return [thaw(x) for x in v]  # type: ignore[union-attr]
    return v


# --------------------------------------------------------------------------- a part


class PartSpec(Mapping):
    """One part of a body as the body file writes it: a read-only mapping of its keys
    (``shape``, ``name``, sizes, mass, placement), made by the constructors of
    :mod:`rbcli.parts`.

    A small frozen value: its values are plain and immutable (numbers, texts, tuples,
    read-only mappings), so it can be kept, compared, hashed and reused in many bodies. What
    it says is checked when a body is built from it (:meth:`rbcli.Body.from_parts`), with
    the messages a body file gets.

    Attributes
    ----------
    shape : str — the ``shape:`` key
    name : str | None — the ``name:`` key, if given
    """

    __slots__ = ("_data", "_hash")

    def __init__(self, mapping: Mapping[str, object], /) -> None:
        if not isinstance(mapping, Mapping):
            raise TypeError(f"PartSpec takes a mapping of a part's keys, not {type(mapping).__name__}")
        data = freeze(mapping)
        shape = data.get("shape")  # type: ignore[attr-defined]
        if not isinstance(shape, str):
            raise TypeError(f"shape: a part's shape is a text, not {type(shape).__name__}")
        object.__setattr__(self, "_data", data)
        object.__setattr__(self, "_hash", None)

    @classmethod
    def _of(cls, data: MappingProxyType) -> PartSpec:
        """A spec of data frozen already."""
        self = cls.__new__(cls)
        object.__setattr__(self, "_data", data)
        object.__setattr__(self, "_hash", None)
        return self

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"a part spec is frozen; use .replace({name}=...) for a new one")

    def __getitem__(self, key: str) -> object:
        return self._data[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, PartSpec):
            return _key(self._data) == _key(other._data)
        return super().__eq__(other)

    def __hash__(self) -> int:
        if self._hash is None:
            object.__setattr__(self, "_hash", hash(_key(self._data)))
        return self._hash  # type: ignore[return-value]

    @property
    def shape(self) -> str:
        return self._data["shape"]  # type: ignore[return-value]

    @property
    def name(self) -> str | None:
        n = self._data.get("name")
        return n if isinstance(n, str) else None

    def replace(self, **keys: object) -> PartSpec:
        """The same part with ``keys`` changed (``None`` removes a key; ``from_`` is the
        rod's ``from``).

        Examples
        --------
        >>> import rbcli
        >>> disk = rbcli.parts.disk(name="wheel", radius="300 mm", mass=12)
        >>> disk.replace(radius="320 mm", at=[0, 0, 0.1])
        rbcli.parts.disk(name='wheel', radius='320 mm', mass=12, at=[0, 0, 0.1])
        """
        data = dict(self._data)
        for k, v in keys.items():
            k = "from" if k == "from_" else k
            if v is None:
                data.pop(k, None)
            else:
                data[k] = freeze(v, k)
        if not isinstance(data.get("shape"), str):
            raise TypeError(f"shape: a part's shape is a text, not {type(data.get('shape')).__name__}")
        return PartSpec._of(MappingProxyType(data))

    def __repr__(self) -> str:
        args = ", ".join(f"{'from_' if k == 'from' else k}={thaw(v)!r}"
                         for k, v in self._data.items() if k != "shape")
        return f"rbcli.parts.{self.shape}({args})"

    def __reduce__(self) -> tuple:
        return (PartSpec, (thaw(self._data),))


def _key(v: object) -> object:
    """A hashable form of frozen data (equal data, equal keys; ``1 == 1.0`` as Python says)."""
    if v.__class__ is MappingProxyType:
        return ("map", tuple((k, _key(x)) for k, x in v.items()))  # type: ignore[union-attr]
    if v.__class__ is tuple:
        return ("seq", tuple(_key(x) for x in v))  # type: ignore[union-attr]
    return v


# --------------------------------------------------------------------------- the tree


def tree(data: object, mark: DataMark) -> ys.Node:
    """The loader's tree of frozen ``data``, each node located by its :class:`DataMark`."""
    if data.__class__ is MappingProxyType or isinstance(data, PartSpec):
        items = {}
        for k, v in data.items():  # type: ignore[union-attr]
            m = mark.child(k)
            items[k] = (m, tree(v, m))
        return ys.MapNode(mark, items)  # type: ignore[arg-type]
    if data.__class__ is tuple:
        return ys.SeqNode(mark, [tree(v, mark.child(i)) for i, v in enumerate(data)])  # type: ignore[arg-type]
    raw = data if data.__class__ is str else repr(data)
    return ys.ScalarNode(mark, data, raw, data.__class__ is str)  # type: ignore[arg-type]


# --------------------------------------------------------------------------- bodies


def _base(base_dir: object, param: str = "base_dir") -> Path:
    if base_dir is None:
        return Path.cwd()
    if not isinstance(base_dir, (str, os.PathLike)):
        raise TypeError(f"{param}: expected a folder (str or path-like), not {type(base_dir).__name__}")
    return Path(base_dir)


def _check_budget(parts: object, where: str) -> None:
    """Refuse a list of parts over the parts budget before it is frozen (a part costs at
    least one of it), as a body file's is refused while it is parsed."""
    from rbcli.body.loadctx import new_session

    if isinstance(parts, Sized) and not isinstance(parts, (str, Mapping)):
        session = new_session()
        if len(parts) > session.max_parts:
            raise InputError(session.over_message(), _at(where))


def _load(data: MappingProxyType, root: str, base_dir: Path, *, name: str = "body",
          units: Mapping[str, str] | None = None, labels: Sequence[str] | None = None):
    """The body of frozen ``data`` (a body file's mapping), through the loader; ``labels``
    name each of its parts as a whole (``Body.from_parts``'s ``parts[2] (cylinder 'bore')``)."""
    from rbcli.body.bodyfile import load_node
    from rbcli.body.document import dump

    top = DataMark(None, "", root)
    if labels is None:
        node = tree(data, top)
    else:
        items = {}
        for k, v in data.items():
            m = top.child(k)
            if k == "parts":
                pm = [DataMark(m, Label(label)) for label in labels]
                items[k] = (m, ys.SeqNode(m, [tree(p, pmark) for p, pmark in zip(v, pm)]))  # type: ignore[arg-type]
            else:
                items[k] = (m, tree(v, m))
        node = ys.MapNode(top, items)  # type: ignore[arg-type]
    text = dump(thaw(data))
    return load_node(node, SOURCE, base_dir, text=text, name_default=name,
                     units=dict(units) if units else None)


def load_data(mapping: Mapping[str, object], *, units: Mapping[str, str] | None = None,
              name: str = "body", base_dir: object = None):
    """The body of ``mapping``, a body file's mapping as Python data (see the module's
    notes); every problem located by its key path (``parts[2].radius``)."""
    if not isinstance(mapping, Mapping):
        raise TypeError(f"mapping: expected a mapping like a body file's (a dict), not "
                        f"{type(mapping).__name__}")
    base = _base(base_dir)
    if "parts" in mapping:
        _check_budget(mapping["parts"], "parts")
    data = freeze(mapping)
    return _load(data, "mapping", base, name=name, units=units)  # type: ignore[arg-type]


def _label(i: int, part: Mapping[str, object]) -> str:
    shape, name = part.get("shape"), part.get("name")
    shown = shape if isinstance(shape, str) else "part"
    if isinstance(name, str):
        return f"parts[{i}] ({shown} {name!r})"
    return f"parts[{i}] ({shown})"


#: Body.from_parts's keyword arguments that are body keys, in the order a file writes them
BODY_ARGS = ("name", "description", "units", "reference", "shaft", "pivot", "rim_radius")


def from_parts(parts: Sequence[Mapping[str, object]], *, base_dir: object = None,
               **body: object):
    """The body of ``parts`` (:class:`PartSpec` s or mappings) with the body keys ``body``
    (``name``, ``units``, ``shaft``, ...; None: not given); each problem in a part located
    by the call, ``parts[2] (cylinder 'bore')``."""
    if isinstance(parts, (str, bytes, Mapping)) or not isinstance(parts, Iterable):
        raise TypeError(f"parts: expected a list of parts (rbcli.parts.*), not {type(parts).__name__}")
    _check_budget(parts, "parts")
    parts = list(parts)
    _check_budget(parts, "parts")
    specs = []
    for i, p in enumerate(parts):
        if isinstance(p, PartSpec):
            specs.append(p._data)
        elif isinstance(p, Mapping):
            specs.append(freeze(p, f"parts[{i}]"))
        else:
            raise TypeError(f"parts[{i}]: expected a part (rbcli.parts.*) or a mapping of its "
                            f"keys, not {type(p).__name__}")
    name = body.get("name", "body")
    if not isinstance(name, str):
        raise TypeError(f"name: expected a text, not {type(name).__name__}")
    base = _base(base_dir)
    data: dict[str, object] = {}
    for key in BODY_ARGS:
        value = body.get(key)
        if value is not None:
            data[key] = freeze(value, key)
        if key == "units":
            data["parts"] = tuple(specs)
    labels = [_label(i, p) for i, p in enumerate(specs)]
    return _load(MappingProxyType(data), "Body.from_parts", base, name=name, labels=labels)


# --------------------------------------------------------------------------- from a body


def rebuilt(body, data: dict):
    """The body of ``data`` (:func:`document` of ``body``, changed), read from ``body``'s
    folder, its problems located by key path."""
    from rbcli.body.bodyfile import origin

    return load_data(data, base_dir=origin(body))


def _document(body) -> dict:
    from rbcli.body.document import document

    return document(body)


def _index(body, data: dict, which: object) -> int:
    parts = data["parts"]
    if isinstance(which, bool) or not isinstance(which, (int, str)):
        raise TypeError(f"which: expected a part's name or its index in the body's parts, not "
                        f"{type(which).__name__}")
    if isinstance(which, int):
        if not -len(parts) <= which < len(parts):
            raise InputError(f"which: the body has {len(parts)} parts; no part {which}")
        return which % len(parts)
    names = []
    for i, p in enumerate(parts):
        n = p.get("name") if isinstance(p, dict) else None
        n = n if isinstance(n, str) else f"{p.get('shape')}{i + 1}"
        if n == which:
            return i
        names.append(n)
    from rbcli.io.yamlvalues import suggest

    raise InputError(f"which: the body has no part named {which!r}{suggest(which, names)} "
                     f"(parts: {', '.join(names)})")


def replace_part(body, which: object, part: object, keys: Mapping[str, object]):
    """``body`` with its part ``which`` (a name, or an index in its ``parts:`` list) replaced
    by ``part`` (a spec or mapping, or None: the part as it is) with ``keys`` changed
    (None removes a key)."""
    data = _document(body)
    i = _index(body, data, which)
    if part is None:
        new = dict(data["parts"][i])
    elif isinstance(part, Mapping):
        new = thaw(part if isinstance(part, PartSpec) else freeze(part, "part"))  # type: ignore[assignment]
    else:
        raise TypeError(f"part: expected a part (rbcli.parts.*) or a mapping of its keys, not "
                        f"{type(part).__name__}")
    for k, v in keys.items():
        k = "from" if k == "from_" else k
        if v is None:
            new.pop(k, None)
        else:
            new[k] = thaw(freeze(v, k))
    data["parts"][i] = new
    return rebuilt(body, data)


def move_part(body, which: object, at: object = None, axis: object = None,
              rotate: object = None):
    """``body`` with part ``which`` placed anew: ``at`` replaces its position, ``axis`` or
    ``rotate`` its orientation (the other one removed)."""
    keys: dict[str, object] = {}
    if axis is not None and rotate is not None:
        raise InputError("give either 'axis' or 'rotate', not both", Location("moved"))
    if at is not None:
        keys["at"] = at
    if axis is not None:
        keys.update(axis=axis, rotate=None)
    if rotate is not None:
        keys.update(rotate=rotate, axis=None)
    return replace_part(body, which, None, keys)


def with_points(body, points: Sequence[tuple[str, float, Sequence[float]]]):
    """``body`` with point masses added: ``(name, mass kg, at (3,) m)`` each, written as
    ``point`` parts with numbers in explicit units (``"43.631 g"``, ``"200 mm"``: 15
    significant figures, whatever the body's ``units``); a name already used gets `` (2)``,
    `` (3)``... (what ``rbcli balance --apply`` writes)."""
    data = _document(body)
    parts = data["parts"]
    names = {p["name"] for p in parts if isinstance(p, dict) and isinstance(p.get("name"), str)}
    names |= {p.name for p in body.parts}
    for name, mass, at in points:
        xyz = [float(x) for x in at]
        big = max(abs(x) for x in xyz)
        xyz = [0.0 if abs(x) <= 1e-13 * big else x for x in xyz]  # round-off of cos/sin
        shown, k = name, 2
        while shown in names:
            shown = f"{name} ({k})"
            k += 1
        names.add(shown)
        parts.append({"name": shown, "shape": "point", "mass": f"{_num(mass * 1e3)} g",
                      "at": [f"{_num(x * 1e3)} mm" for x in xyz]})
    return rebuilt(body, data)


def _num(x: float) -> str:
    """A float in at most 15 significant figures (round trip to ~5e-16 relative)."""
    s = f"{x:.15g}"
    return "0" if float(s) == 0.0 else s
