"""rbcli._startup.frozen behaves as dataclass(frozen=True) for what rbcli's results use."""

from __future__ import annotations

import dataclasses
import copy
from dataclasses import dataclass, field

import numpy as np
import pytest

from rbcli._startup import frozen


def _pair(eq: bool = True):
    """The same class made both ways."""

    def body():
        class Base:
            warnings: tuple[str, ...] = ()  # a plain mixin's annotation: not a field

            def total(self) -> float:
                return self.a + self.b

        class C(Base):
            """A result."""

            a: float
            b: float = 2.0
            c: list = field(default_factory=list)
            hidden: object = field(default=None, repr=False)
            loose: float = field(default=0.0, compare=False)

        return C

    return dataclass(frozen=True, eq=eq)(body()), frozen(eq=eq)(body())


def test_fields_and_defaults_match_dataclass():
    D, F = _pair()
    assert [(f.name, f.type, f.repr, f.compare) for f in dataclasses.fields(D)] == \
        [(f.name, f.type, f.repr, f.compare) for f in dataclasses.fields(F)]
    assert dataclasses.is_dataclass(F) and dataclasses.is_dataclass(F(1.0))
    assert F.__match_args__ == D.__match_args__
    for args, kw in (((1.0,), {}), ((1.0, 3.0), {"hidden": 5}), ((), {"a": 1.0, "c": [1]})):
        d, f = D(*args, **kw), F(*args, **kw)
        assert repr(d).replace("C(", "X(") == repr(f).replace("C(", "X(")
        assert dataclasses.astuple(d) == dataclasses.astuple(f)
        assert dataclasses.asdict(d) == dataclasses.asdict(f)
        assert f.total() == d.total()
    assert F(1.0).c is not F(1.0).c  # a fresh default per instance


def test_constructor_errors_match_dataclass():
    D, F = _pair()
    for args, kw in (((), {}), ((1, 2, 3, 4, 5, 6), {}), ((1,), {"a": 2}), ((1,), {"zz": 1}),
                     ((), {"b": 1, "c": 2, "hidden": 3, "loose": 4, "zz": 5}),  # as many as fields
                     ((), {"b": 1}), ((1, 2), {"c": [], "zz": 1})):
        with pytest.raises(TypeError) as ed:
            D(*args, **kw)
        with pytest.raises(TypeError) as ef:
            F(*args, **kw)
        # the same words after the class's qualified name (dataclass names __init__ only)
        assert str(ed.value).split("__init__() ")[1] == str(ef.value).split("__init__() ")[1]


def test_frozen_equality_hash_replace():
    D, F = _pair()
    f = F(1.0, 2.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        f.a = 3.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        del f.a
    with pytest.raises(dataclasses.FrozenInstanceError):
        f.other = 1
    assert f == F(1.0, 2.0) and f != F(1.0, 3.0) and f == F(1.0, 2.0, loose=9.0)
    assert f != D(1.0, 2.0)  # another class: not equal, as dataclass
    g = F(1.0, 2.0, c=(1, 2))
    assert hash(g) == hash(F(1.0, 2.0, c=(1, 2)))
    r = dataclasses.replace(f, b=5.0)
    assert type(r) is F and r.b == 5.0 and r.a == 1.0
    assert copy.deepcopy(g) == g and copy.copy(g) == g  # the reduce path pickle takes too


def test_eq_false_and_own_methods_kept():
    D, F = _pair(eq=False)
    f = F(np.zeros(3))
    assert f != F(np.zeros(3)) and f == f  # identity, as dataclass(eq=False)
    assert hash(f) == object.__hash__(f)

    @frozen
    class Own:
        x: int

        def __repr__(self) -> str:
            return "own"

    assert repr(Own(1)) == "own" and Own(1) == Own(1)


def test_post_init_runs_and_may_set_fields():
    @frozen
    class P:
        x: float
        y: float = 0.0

        def __post_init__(self) -> None:
            if self.x < 0:
                raise ValueError("negative")
            object.__setattr__(self, "y", 2 * self.x)

    assert P(2.0).y == 4.0
    with pytest.raises(ValueError):
        P(-1.0)


def test_subclass_of_a_frozen_class():
    @frozen
    class A:
        x: int

    @frozen
    class B(A):
        y: int = 0

    assert [f.name for f in dataclasses.fields(B)] == ["x", "y"]
    assert B(1, 2) == B(x=1, y=2) and repr(B(1)) == "test_subclass_of_a_frozen_class.<locals>.B(x=1, y=0)"


def test_every_way_of_calling_matches_dataclass():
    """Positional prefixes times keyword subsets (with an unknown key): same fields or the
    same TypeError."""
    import itertools

    D, F = _pair()
    names = ["a", "b", "c", "hidden", "loose", "zz"]
    for npos in range(7):
        for r in range(4):
            for keys in itertools.combinations(names, r):
                args = tuple(range(npos))
                kw = {k: i + 10 for i, k in enumerate(keys)}
                out = []
                for C in (D, F):
                    try:
                        x = C(*args, **kw)
                        out.append(("ok", dataclasses.astuple(x)))
                    except TypeError as exc:
                        out.append(("error", str(exc).split("__init__() ")[1]))
                assert out[0] == out[1], (args, kw, out)
