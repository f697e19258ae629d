"""Cheaper equivalents, for modules on every command's start-up path, of two things that
cost time at import: ``@dataclass(frozen=True)`` (:func:`frozen`) and ``re.compile``
(:class:`LazyRe`).

``@frozen``: a frozen dataclass whose methods are shared, not compiled per class.

``dataclasses.dataclass(frozen=True)`` writes the source of ``__init__``, ``__repr__``,
``__eq__``, ``__hash__``, ``__setattr__`` and ``__delattr__`` for each class and compiles
each with ``exec``: 0.5-1.5 ms of start-up per class in Python 3.11, and the start-up of
``rbcli top`` went through nine of them (bench/README.md, "Start-up"). :func:`frozen`
gives a class the same behaviour with generic methods that read the class's field list:

- the same fields: ``dataclasses.fields``, ``replace``, ``astuple``, ``asdict`` and
  ``is_dataclass`` work on the class and its instances (``__dataclass_fields__`` holds
  ordinary :class:`dataclasses.Field` objects; ``field(default=..., default_factory=...,
  repr=False, compare=False)`` are honoured);
- the same constructor: positional or keyword arguments in field order, defaults,
  ``__post_init__``; the same ``TypeError`` for a missing or an unexpected argument;
- immutable: assigning or deleting an attribute raises
  :class:`dataclasses.FrozenInstanceError`;
- the same ``repr`` (``Name(a=1, b=2)``, fields with ``repr=False`` left out), ``==`` (same
  class, equal field tuples; not with ``eq=False``), ``hash`` (of the field tuple, with
  ``eq``), and ``__match_args__``.

A method the class defines itself (``__repr__``, ``__eq__``, ``__hash__``) is kept, as
dataclass keeps it. Not supported (a ``TypeError`` at class creation): ``InitVar``,
``ClassVar`` fields are skipped as dataclass skips them; ``kw_only``, ``slots``,
``order`` do not exist here. Standard library only; importing it costs what
``import dataclasses`` costs.

Instances are built a little more slowly than a compiled ``__init__`` builds them (a
loop over the fields): use it for results and options, made a few times per command, not
for per-element records in hot loops.
"""

from __future__ import annotations

import dataclasses
from dataclasses import MISSING, Field, FrozenInstanceError
from typing import Any

__all__ = ["LazyRe", "frozen"]

#: dataclasses' marker of an ordinary field (``Field._field_type``); what ``fields()``,
#: ``replace()`` and ``asdict()`` look for
_FIELD = getattr(dataclasses, "_FIELD")
_PARAMS = getattr(dataclasses, "_PARAMS", "__dataclass_params__")


def _params(eq: bool) -> Any:
    make = getattr(dataclasses, "_DataclassParams")
    try:  # Python 3.11: (init, repr, eq, order, unsafe_hash, frozen)
        return make(True, True, eq, False, False, True)
    except TypeError:  # 3.12+: more flags, with keywords
        return make(init=True, repr=True, eq=eq, order=False, unsafe_hash=False, frozen=True,
                    match_args=True, kw_only=False, slots=False, weakref_slot=False)


def _is_classvar(annotation: Any) -> bool:
    text = annotation if isinstance(annotation, str) else repr(annotation)
    return text.startswith(("ClassVar", "typing.ClassVar", "t.ClassVar"))


def frozen(cls: type | None = None, *, eq: bool = True) -> Any:
    """Class decorator: ``@frozen`` or ``@frozen(eq=False)``, as
    ``@dataclass(frozen=True)`` / ``@dataclass(frozen=True, eq=False)``."""

    def wrap(c: type) -> type:
        return _process(c, eq)

    return wrap if cls is None else wrap(cls)


def _process(cls: type, eq: bool) -> type:
    fields: dict[str, Field] = {}
    for base in cls.__mro__[-1:0:-1]:  # inherited dataclass fields first, as dataclass
        base_fields = base.__dict__.get("__dataclass_fields__")
        if base_fields:
            for f in base_fields.values():
                if f._field_type is _FIELD:
                    fields[f.name] = f
    for name, annotation in cls.__dict__.get("__annotations__", {}).items():
        if _is_classvar(annotation):
            continue
        if "InitVar" in str(annotation):
            raise TypeError(f"{cls.__qualname__}.{name}: @frozen does not support InitVar")
        default = cls.__dict__.get(name, MISSING)
        f = default if isinstance(default, Field) else dataclasses.field(default=default)
        f.name = name
        f.type = annotation
        f._field_type = _FIELD
        if isinstance(default, Field):  # the class attribute is the plain default, or none
            if f.default is MISSING:
                delattr(cls, name)
            else:
                setattr(cls, name, f.default)
        fields[name] = f
    seen_default = False
    for f in fields.values():
        has_default = f.default is not MISSING or f.default_factory is not MISSING
        if seen_default and not has_default and f.init:
            raise TypeError(f"non-default argument '{f.name}' follows default argument")
        seen_default = seen_default or has_default

    names = tuple(f.name for f in fields.values() if f.init)
    plan = tuple((f.name, f.default, f.default_factory) for f in fields.values() if f.init)
    repr_names = tuple(f.name for f in fields.values() if f.repr)
    cmp_names = tuple(f.name for f in fields.values() if f.compare)
    hash_names = tuple(f.name for f in fields.values()
                       if (f.compare if f.hash is None else f.hash))
    all_names = frozenset(fields)
    name_set = frozenset(names)
    post_init = getattr(cls, "__post_init__", None)
    qualname = cls.__qualname__
    nparams = len(names)
    nrequired = sum(1 for _, d, fa in plan if d is MISSING and fa is MISSING)

    def _bad_call(args: tuple, kwargs: dict) -> TypeError:
        """The TypeError a compiled __init__ raises for this call (the slow path), in
        CPython's order: keywords, then too many positional arguments, then missing ones."""
        for k in kwargs:
            if k not in name_set:
                return TypeError(f"{qualname}.__init__() got an unexpected keyword argument '{k}'")
            if k in names[: len(args)]:
                return TypeError(f"{qualname}.__init__() got multiple values for argument '{k}'")
        if len(args) > nparams:
            takes = (f"{nparams + 1}" if nrequired == nparams else
                     f"from {nrequired + 1} to {nparams + 1}")
            return TypeError(f"{qualname}.__init__() takes {takes} positional arguments "
                             f"but {len(args) + 1} were given")
        missing = [n for n, d, f in plan[len(args):] if n not in kwargs and d is MISSING and f is MISSING]
        listed = (f"'{missing[0]}'" if len(missing) == 1 else
                  ", ".join(f"'{m}'" for m in missing[:-1]) + f" and '{missing[-1]}'")
        return TypeError(f"{qualname}.__init__() missing {len(missing)} required "
                         f"positional argument{'s' if len(missing) > 1 else ''}: {listed}")

    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
        d = self.__dict__  # assigned in field order, as a compiled __init__ does
        if not kwargs and len(args) == nparams:  # every field, by position
            for name, value in zip(names, args):
                d[name] = value
        else:
            if args:
                if len(args) > nparams or any(n in kwargs for n in names[: len(args)]):
                    raise _bad_call(args, kwargs)
                kwargs.update(zip(names, args))  # kwargs: this call's own dict
            if len(kwargs) == nparams:  # every field given
                try:
                    for name in names:
                        d[name] = kwargs[name]
                except KeyError:
                    d.clear()
                    raise _bad_call(args, {k: v for k, v in kwargs.items() if k not in names[: len(args)]}) from None
            else:
                if not name_set.issuperset(kwargs):
                    raise _bad_call(args, {k: v for k, v in kwargs.items() if k not in names[: len(args)]})
                for name, default, factory in plan:
                    value = kwargs.get(name, MISSING)
                    if value is MISSING:
                        if default is not MISSING:
                            value = default
                        elif factory is not MISSING:
                            value = factory()
                        else:
                            d.clear()
                            raise _bad_call(args, {k: v for k, v in kwargs.items() if k not in names[: len(args)]})
                    d[name] = value
        if post_init is not None:
            self.__post_init__()

    def __repr__(self) -> str:
        return f"{type(self).__qualname__}(" + ", ".join(
            f"{n}={getattr(self, n)!r}" for n in repr_names) + ")"

    def __eq__(self, other: object) -> Any:
        if other.__class__ is self.__class__:
            return tuple(getattr(self, n) for n in cmp_names) == tuple(
                getattr(other, n) for n in cmp_names)
        return NotImplemented

    def __hash__(self) -> int:
        return hash(tuple(getattr(self, n) for n in hash_names))

    def __setattr__(self, name: str, value: Any) -> None:
        if type(self) is cls or name in all_names:
            raise FrozenInstanceError(f"cannot assign to field {name!r}")
        super(cls, self).__setattr__(name, value)

    def __delattr__(self, name: str) -> None:
        if type(self) is cls or name in all_names:
            raise FrozenInstanceError(f"cannot delete field {name!r}")
        super(cls, self).__delattr__(name)

    own = cls.__dict__
    explicit_hash = "__hash__" in own and not (own["__hash__"] is None and "__eq__" in own)
    methods = {"__init__": __init__, "__repr__": __repr__, "__setattr__": __setattr__,
               "__delattr__": __delattr__}
    if eq:
        methods["__eq__"] = __eq__
    for name, fn in methods.items():
        if name in ("__setattr__", "__delattr__") and name in own:
            raise TypeError(f"cannot overwrite attribute {name} in class {qualname}")
        if name not in own:
            fn.__qualname__ = f"{qualname}.{name}"
            setattr(cls, name, fn)
    if eq and not explicit_hash:  # as dataclass(eq=True, frozen=True): unless the class wrote one
        __hash__.__qualname__ = f"{qualname}.__hash__"
        cls.__hash__ = __hash__  # type: ignore[method-assign]
    cls.__dataclass_fields__ = fields  # type: ignore[attr-defined]
    setattr(cls, _PARAMS, _params(eq))
    if "__match_args__" not in own:
        cls.__match_args__ = names  # type: ignore[attr-defined]
    return cls


class LazyRe:
    """A regular expression compiled on its first use: ``NAME = LazyRe(r"...")`` at module
    level instead of ``re.compile`` (which costs 0.1-0.4 ms of start-up per pattern, paid by
    every run although most use few of them). ``match``, ``fullmatch``, ``search``, ``sub``
    and any other attribute are the compiled pattern's own; after the first use they are
    plain instance attributes, as fast as the compiled pattern's."""

    def __init__(self, pattern: str, flags: int = 0) -> None:
        self._args = (pattern, flags)

    def __getattr__(self, name: str) -> Any:  # only until the pattern is compiled
        if name.startswith("__"):
            raise AttributeError(name)
        import re

        compiled = re.compile(*self._args)
        for method in ("match", "fullmatch", "search", "sub", "finditer", "findall", "split",
                       "pattern", "flags"):
            setattr(self, method, getattr(compiled, method))
        return getattr(compiled, name)

    def __repr__(self) -> str:
        return f"LazyRe({self._args[0]!r})"
