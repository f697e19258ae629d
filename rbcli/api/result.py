"""What every service result shares: a frozen dataclass (the :class:`Result` mixin) that
knows its JSON (``to_json()``: ``rbcli <command> --json`` less ``file``), passed through the
one finiteness check, and its exit status (``return_code``, as black's ``Report``)."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterable, Iterator, Mapping
from typing import Any

import numpy as np

from rbcli.body.partmodel import same_fields, unhashable
from rbcli.body.partspec import ReadOnly
from rbcli.errors import ExitStatus, NonFiniteResult

__all__ = ["Result", "Record", "record", "frozen", "freeze_fields", "jsonable"]


class Result:
    """Mixin of every service result (use with ``@dataclass(frozen=True)``).

    A result is a value: after it is made, every field is :func:`frozen` (arrays read-only,
    mappings read-only, lists as tuples, nested dataclasses likewise), so nothing a caller
    does to it changes what it says. ``==`` is :func:`rbcli.body.partmodel.same`; unhashable.
    """

    #: located one-line warnings the command prints on standard error (``rbcli: warning: ...``)
    warnings: tuple[str, ...] = ()

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        cls.__repr__ = Result.__repr__  # type: ignore[method-assign]  # set before @dataclass, which keeps it
        cls.__eq__, cls.__hash__ = same_fields, unhashable  # type: ignore[method-assign,assignment]

    def __post_init__(self) -> None:
        freeze_fields(self)

    def __setstate__(self, state: dict[str, Any]) -> None:
        """Unpickled: the fields frozen again (pickle makes arrays writable)."""
        self.__dict__.update(state)
        freeze_fields(self)

    def __repr__(self) -> str:
        """One line: the class and the first numbers and words of the JSON."""
        data = self.to_json()
        shown = [f"{k}={v:.6g}" if isinstance(v, float) else f"{k}={v!r}" for k, v in data.items()
                 if isinstance(v, (str, int, float)) and k != "warnings"][:4]
        return f"<{type(self).__name__} {' '.join(shown)}{' …' if len(data) > len(shown) else ''}>"

    def _repr_html_(self) -> str:
        """The command's tables as HTML (units in the headers) and its figure as SVG, for
        notebooks. The one import of render from api (tests/test_architecture.py)."""
        from rbcli.render import notebook

        return notebook.html(self)

    def to_json(self) -> dict[str, Any]:  # pragma: no cover - every result defines it
        raise NotImplementedError

    def __getattr__(self, name: str) -> Any:
        """Every key of :meth:`to_json` is an attribute with that value (one vocabulary:
        ``r.static_unbalance`` is ``r.to_json()["static_unbalance"]``); a mapping in it is a
        :class:`Record` (``r.corrections[0].angle_deg``), a list a tuple. Fields and
        properties of the result class come first."""
        if name.startswith("_"):
            raise AttributeError(name)
        data = self.__dict__.get("_json_data")
        if data is None:
            data = self.to_json()
            object.__setattr__(self, "_json_data", data)
        if name in data:
            return record(data[name])
        raise AttributeError(f"{type(self).__name__!r} has no attribute {name!r} (its JSON keys: "
                             f"{', '.join(data)})")

    @property
    def return_code(self) -> int:
        """0, or 1 (:attr:`ExitStatus.CHECK_FAILED`) when a check asked for failed."""
        return int(ExitStatus.OK)


class Record(ReadOnly):
    """A read-only JSON object whose keys are also attributes: ``rec.angle_deg`` is
    ``rec["angle_deg"]``. What a mapping inside a result's JSON is, seen as an attribute."""

    __slots__ = ()

    def __getitem__(self, key: str) -> Any:
        return record(self._data[key])

    def __getattr__(self, name: str) -> Any:
        try:
            return record(self._data[name])
        except KeyError:
            raise AttributeError(f"no key {name!r} (keys: {', '.join(self._data)})") from None

    def to_json(self) -> dict[str, Any]:
        return self._data


def record(value: Any) -> Any:
    """JSON data as attributes see it: mappings as :class:`Record`, lists as tuples."""
    if isinstance(value, dict):
        return Record(value)
    if isinstance(value, list):
        return tuple(record(v) for v in value)
    return value


def frozen(value: Any, _depth: int = 0) -> Any:
    """``value`` made immutable, deeply: numpy arrays read-only (a read-only copy when the
    array is writable), dicts as read-only mappings, lists as tuples, the fields of
    dataclass instances likewise (in place: :func:`freeze_fields`). Other objects are
    returned as they are (a :class:`rbcli.body.model.Body` is frozen where it is made)."""
    if value is None or isinstance(value, (str, int, float)) or _depth > 20:
        return value
    if isinstance(value, np.ndarray):
        if value.flags.writeable:
            value = value.copy()
            value.setflags(write=False)
        return value
    if type(value) is dict or isinstance(value, ReadOnly):
        items = {k: frozen(v, _depth + 1) for k, v in value.items()}
        same = isinstance(value, ReadOnly) and all(items[k] is v for k, v in value.items())
        return value if same else ReadOnly(items)
    if type(value) in (list, tuple):
        items = tuple(frozen(v, _depth + 1) for v in value)
        return value if type(value) is tuple and all(a is b for a, b in zip(items, value)) else items
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        freeze_fields(value, _depth + 1)
    return value


def freeze_fields(obj: Any, _depth: int = 0) -> None:
    """Replace each field of the dataclass instance ``obj`` by :func:`frozen` of it."""
    for f in dataclasses.fields(obj):
        v = getattr(obj, f.name)
        fv = frozen(v, _depth)
        if fv is not v:
            object.__setattr__(obj, f.name, fv)


def jsonable(obj: Any) -> Any:
    """Plain JSON data from results (arrays and tuples to lists, -0.0 to 0.0): the one
    finiteness check of every JSON document and API result. NonFiniteResult (exit 2) naming the
    key of an inf or NaN; TypeError for a value with no JSON form."""
    if obj is None or isinstance(obj, (str, bool, int)):  # a Note (a str) is kept as it is
        return obj
    if isinstance(obj, float):  # numpy's float64 too
        if not math.isfinite(obj):
            raise _NonFinite(float(obj))
        return 0.0 if obj == 0.0 else float(obj)
    if isinstance(obj, np.ndarray) and obj.dtype.kind in "biuU":  # whole arrays at once
        return obj.tolist()
    if isinstance(obj, np.ndarray) and obj.dtype.kind == "f":
        if not np.isfinite(obj).all():
            bad = np.argwhere(~np.isfinite(obj))[0]
            raise _NonFinite(float(obj[tuple(bad)]), bad.tolist())
        return (obj + 0.0).tolist()  # -0.0 + 0.0 is 0.0
    if hasattr(obj, "tolist"):  # other numpy arrays and scalars
        return jsonable(obj.tolist())
    if hasattr(obj, "to_json"):
        return jsonable(obj.to_json())
    if isinstance(obj, Mapping):
        return dict(_items((str(k), v) for k, v in obj.items()))
    if isinstance(obj, (list, tuple)):
        return [v for _, v in _items(enumerate(obj))]
    raise TypeError(f"cannot write {type(obj).__name__} as JSON")


def _items(pairs: Iterable[tuple[Any, Any]]) -> Iterator[tuple[Any, Any]]:
    """(key, :func:`jsonable` of the value) of a mapping's or a list's items, naming the key
    or index of a number that is not finite."""
    for key, v in pairs:
        try:
            yield key, jsonable(v)
        except _NonFinite as exc:
            exc.path.insert(0, key)
            raise


class _NonFinite(NonFiniteResult):
    """NonFiniteResult that collects the key path on its way up through :func:`jsonable`."""

    def __init__(self, value: float, path: list[str | int] | None = None) -> None:
        self.value = value
        self.path = path or []
        super().__init__("")

    @property
    def message(self) -> str:  # the path is known only once the error has left jsonable
        return str(self)

    @message.setter
    def message(self, _text: str) -> None:
        pass

    def spelled(self, name=None) -> str:  # names no parameter
        return str(self)

    def __str__(self) -> str:
        where = "".join(f"[{p}]" if isinstance(p, int) else (f".{p}" if i else p)
                        for i, p in enumerate(self.path))
        what = f"the result '{where}'" if where else "a result"
        return (f"{what} is not a finite number ({self.value}): a value is too large or too "
                "small to compute with; check the options and the body's numbers")
