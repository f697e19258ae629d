"""A part as the body file writes it (:class:`PartSpec`, what :mod:`rbcli.parts` makes),
and Python data made plain and immutable (:func:`freeze`), as a body file could hold it.

Freezing makes plain, immutable values: str, int, float, bool, None, tuples, read-only
mappings with text keys; numpy scalars and arrays become Python numbers and tuples. It
refuses a value of a type no body file holds (a complex number, a set, an object) or a
mapping key that is not a text with a ``TypeError`` naming where it is; a cycle, nesting
deeper than a body file may nest, an integer of more than 300 digits or a text that is not
Unicode (a lone surrogate) with an :class:`rbcli.errors.InputError` located there.

Light on purpose: ``import rbcli.parts`` loads this module and no numpy.
"""

from __future__ import annotations

import numbers
import sys
from collections.abc import Mapping, Sequence
from typing import Any

from rbcli.errors import InputError, Location
from rbcli.io.yamlsafe import MAX_DEPTH

__all__ = ["ReadOnly", "PartSpec", "freeze", "thaw"]

_MAX_DIGITS = 300  # as a body file's integers (rbcli.io.yamlsafe)
_TOO_DEEP = (f"nesting is too deep: more than {MAX_DEPTH} levels of lists and mappings; "
             f"body files allow at most {MAX_DEPTH}")
_KINDS = "numbers, texts, booleans, None, lists and mappings with text keys"


class ReadOnly(Mapping):
    """A read-only mapping of its own that pickles (``MappingProxyType`` does not)."""

    __slots__ = ("_data",)

    def __init__(self, data=()) -> None:
        object.__setattr__(self, "_data", dict(data))

    def __getitem__(self, key):
        return self._data[key]

    def __iter__(self):
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)

    def __setattr__(self, name, value) -> None:
        raise AttributeError(f"a {type(self).__name__} is read-only")

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self._data!r})"

    def __reduce__(self):
        return type(self), (self._data,)


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
    if isinstance(key, int):
        return f"{where}[{key}]"
    text = key if key.isidentifier() else repr(key)
    return f"{where}.{text}" if where else text


def _at(where: str) -> Location:
    return Location(where or "<data>")


def _freeze(v: Any, where: str, depth: int, open_ids: set[int]) -> object:
    if v is None or isinstance(v, bool):
        return v
    if isinstance(v, str):  # numpy.str_ and other subclasses too
        return _text(str(v), where)
    if isinstance(v, int):
        return _integer(int(v), where)
    if isinstance(v, float):  # numpy.float64 too
        return float(v)
    if isinstance(v, (Mapping, tuple, list)):
        return _container(v, where, depth, open_ids, isinstance(v, Mapping))
    np = sys.modules.get("numpy")  # numpy values exist only once numpy is imported
    if np is not None:
        if isinstance(v, np.ndarray):
            if v.dtype.kind not in "biuf":
                raise TypeError(f"{where or 'value'}: an array of {v.dtype} is not a value a "
                                f"body file holds ({_KINDS})")
            return _freeze(v.tolist(), where, depth, open_ids)
        if isinstance(v, np.bool_):
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
    if depth >= MAX_DEPTH:
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
                if not isinstance(key, str):
                    raise TypeError(f"{where or 'mapping'}: keys must be texts, not "
                                    f"{type(key).__name__} ({_short(key)})")
                key = str(key)
                out[_text(key, where)] = _freeze(v[key], _path(where, key), depth + 1, open_ids)
            return ReadOnly(out)
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
    if isinstance(v, Mapping):
        return {k: thaw(x) for k, x in v.items()}
    if isinstance(v, tuple):
        return [thaw(x) for x in v]  # type: ignore[union-attr]
    return v


class PartSpec(ReadOnly):
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

    __slots__ = ("_hash",)

    def __init__(self, mapping: Mapping[str, object], /) -> None:
        if not isinstance(mapping, Mapping):
            raise TypeError(f"PartSpec takes a mapping of a part's keys, not {type(mapping).__name__}")
        data = freeze(mapping)
        shape = data.get("shape")  # type: ignore[attr-defined]
        if not isinstance(shape, str):
            raise TypeError(f"shape: a part's shape is a text, not {type(shape).__name__}")
        object.__setattr__(self, "_data", data)
        object.__setattr__(self, "_hash", None)

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"a part spec is frozen; use .replace({name}=...) for a new one")

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
        return PartSpec(data)

    def __repr__(self) -> str:
        args = ", ".join(f"{'from_' if k == 'from' else k}={thaw(v)!r}"
                         for k, v in self._data.items() if k != "shape")
        return f"rbcli.parts.{self.shape}({args})"

    def __reduce__(self) -> tuple:
        return (PartSpec, (thaw(self._data),))


def _key(v: object) -> object:
    """A hashable form of frozen data (equal data, equal keys; ``1 == 1.0`` as Python says)."""
    if isinstance(v, Mapping):
        return ("map", tuple((k, _key(x)) for k, x in v.items()))
    if isinstance(v, tuple):
        return ("seq", tuple(_key(x) for x in v))
    return v
