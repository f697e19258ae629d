"""The arguments of the public API, checked at the door (issue 27 item 1).

Only two errors come out: a :class:`TypeError` naming the parameter and the type expected,
and an :class:`rbcli.InputError` naming it for a value that cannot be used (too large, too
long: refused by length before it is read, NaN). A checker returns plain Python types, so
:mod:`rbcli.api.options` never sees a numpy subclass, a cyclic list or a failing
``__float__``; a user's object is asked as little as possible (``len()`` first).
:data:`Quantity`, :data:`Vector`, :data:`Point` and :data:`Values` type the signatures."""

from __future__ import annotations

import math
import numbers
import os
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any, TypeAlias, Union

from rbcli.api import options as op
from rbcli.env import clean
from rbcli.errors import NonFiniteResult, ParamError, literal

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body

__all__ = [
    "Quantity", "Vector", "Point", "Values", "MAX_TEXT", "MAX_TEXT_TOTAL", "MAX_ITEMS", "MAX_TIMES",
    "body", "flag", "count", "quantity", "values", "vector", "text", "texts", "integers",
    "path", "function", "times", "arguments", "arithmetic",
]

#: a number in SI units (angles in degrees) or a quantity string as typed on the command
#: line: ``0.3``, ``"30 cm"``, ``"3000 rpm"``, ``"G6.3"``
Quantity: TypeAlias = Union[float, str]
#: x, y, z: ``"1,0,0"``, ``"0,0,300 rpm"``, ``[0, 0, 0.3]``, ``["10 mm", 0, 0]``, a 1-D array
Vector: TypeAlias = Union[str, Sequence[Quantity]]
#: a point: ``"com"``, ``"origin"`` or a :data:`Vector` (m)
Point: TypeAlias = Union[str, Sequence[Quantity]]
#: one value or several of one kind: ``"0,400 mm"``, ``[0, 0.4]``, ``2e7``
Values: TypeAlias = Union[Quantity, Sequence[Quantity]]

#: the longest string argument, characters (a quantity, a list typed as text, a reading)
MAX_TEXT = 10_000
#: the most characters of all the strings of one argument (a sequence of readings)
MAX_TEXT_TOTAL = 100_000
#: the most items of a sequence argument whose parameter names no size of its own
MAX_ITEMS = 10_000
#: the most times ``at(t)`` takes at once (the rows of the longest time series)
MAX_TIMES = 1_000_000

_NUMBER = "a number or a quantity string"


def _type(value: object) -> str:
    """How a message names the type of ``value`` (never its text; a class's name made safe
    to show, as the command line shows names: :func:`rbcli.env.clean`)."""
    t = type(value)
    name = t.__name__ if t.__module__ in ("builtins", None) else f"{t.__module__}.{t.__qualname__}"
    return clean(name, max_line=120)


def _wrong(param: str, expected: str, value: object) -> TypeError:
    return TypeError(f"{param}: expected {expected}, got {_type(value)}")


def _failed(param: str, expected: str, value: object, what: str, exc: BaseException) -> TypeError:
    return TypeError(f"{param}: expected {expected}; {what} of the {_type(value)} given failed "
                     f"({type(exc).__name__})")


def _is_bool(value: object) -> bool:
    t = type(value)
    return isinstance(value, bool) or (t.__name__ in ("bool_", "bool") and t.__module__ == "numpy")


def _shape(value: object) -> tuple | None:
    """The shape of a numpy array (or an array-like that has one), else None."""
    if isinstance(value, (str, bytes, list, tuple)):
        return None
    try:
        shape = getattr(value, "shape", None)
    except Exception:  # noqa: BLE001 - a property that raises: no shape
        return None
    return shape if isinstance(shape, tuple) else None


def _item(value: Any, param: str, expected: str) -> Any:
    """The Python scalar of a 0-d array."""
    try:
        return value.item()
    except Exception as exc:  # noqa: BLE001 - a user's array: any failure is its type's
        raise _failed(param, expected, value, "item()", exc) from None


def _text(value: str, param: str) -> str:
    """A string argument, refused when it is longer than any value of a parameter."""
    if len(value) > MAX_TEXT:
        raise ParamError(param, f"the text given is {len(value)} characters long; a value has at "
                         f"most {MAX_TEXT}")
    return str(value)  # a str subclass (numpy.str_) as a str


def _real(value: Any, param: str, expected: str = _NUMBER) -> float:
    """A real number as a float — a Python int stays an int, once it is known to fit a float
    (one beyond the floats is an InputError)."""
    try:
        x = float(value)
    except OverflowError:
        size = (f"an integer of about {int(value.bit_length() * math.log10(2)) + 1} digits"
                if isinstance(value, int) else "a number")
        raise ParamError(param, f"{size} is too large for a floating-point number (at most "
                         "about 1.8e308)") from None
    except Exception as exc:  # noqa: BLE001 - a user's number type: any failure is its type's
        raise _failed(param, expected, value, "float()", exc) from None
    if type(x) is not float:  # pragma: no cover - float() returns a float
        raise _wrong(param, expected, value)
    if type(value) is int:
        return value  # an int as it is (messages quote it as the caller wrote it)
    return x


def _scalar(value: Any, param: str, expected: str, *, strings: bool = True) -> float | str:
    """A number (as a float) or, when ``strings``, a quantity string."""
    if isinstance(value, str):
        if not strings:
            raise _wrong(param, expected, value)
        return _text(value, param)
    if _is_bool(value):
        raise _wrong(param, expected, value)
    if isinstance(value, numbers.Real):
        return _real(value, param, expected)
    shape = _shape(value)
    if shape == ():
        return _scalar(_item(value, param, expected), param, expected, strings=strings)
    raise _wrong(param, expected, value)


def _length(value: Any, param: str, expected: str) -> int:
    try:
        n = len(value)
    except Exception as exc:  # noqa: BLE001 - a user's sequence: any failure is its type's
        raise _failed(param, expected, value, "len()", exc) from None
    if not isinstance(n, int) or n < 0:  # pragma: no cover - len() checks this itself
        raise _wrong(param, expected, value)
    return n


def _sequence(value: Any, param: str, most: int, expected: str) -> list:
    """The items of a sequence argument (a list, a tuple, a 1-D array, another Sequence),
    its length checked before anything is read."""
    shape = _shape(value)
    if shape is not None:
        if len(shape) != 1:
            dims = "×".join(str(s) if isinstance(s, int) else "?" for s in shape)
            raise ParamError(param, f"expected {expected}, got an array of shape {dims}")
        n = shape[0]
    elif isinstance(value, (list, tuple)) or (isinstance(value, Sequence)
                                              and not isinstance(value, (str, bytes, bytearray))):
        n = _length(value, param, expected)
    else:
        raise _wrong(param, expected, value)
    if not isinstance(n, int):
        raise _wrong(param, expected, value)
    if n > most:
        raise ParamError(param, f"expected {expected}, got {n} values")
    try:
        items = value.tolist() if shape is not None else list(value)
    except Exception as exc:  # noqa: BLE001 - a user's sequence: any failure is its type's
        raise _failed(param, expected, value, "reading the items", exc) from None
    if not isinstance(items, list) or len(items) != n:
        raise _wrong(param, expected, value)
    return items


def _total(value: Any, param: str) -> Any:
    """``value`` (a tuple of strings and numbers, nested at most twice), refused when its
    strings hold more than :data:`MAX_TEXT_TOTAL` characters in all."""
    n = 0
    for x in value if isinstance(value, tuple) else (value,):
        if isinstance(x, str):
            n += len(x)
        elif isinstance(x, tuple):
            n += sum(len(y) for y in x if isinstance(y, str))
    if n > MAX_TEXT_TOTAL:
        raise ParamError(param, f"the strings given hold {n} characters; a value has at most "
                         f"{MAX_TEXT_TOTAL} in all")
    return value


# --- the checkers


def body(value: Any, param: str = "body", *, optional: bool = False) -> Body | None:
    """``value`` if it is an :class:`rbcli.Body` (None too when ``optional``), else a
    TypeError saying how to get one (a path is not a body: ``rbcli.load(path)`` reads it)."""
    from rbcli.body.model import Body  # (numpy: this module is on the command line's import path)

    if isinstance(value, Body):
        return value.checked(param)
    if optional and value is None:
        return value
    hint = ""
    if isinstance(value, (str, os.PathLike)):
        hint = " (a path: read the file with rbcli.load(path))"
    elif isinstance(value, Mapping):
        hint = " (a mapping is not a body: rbcli.load_text builds one from text)"
    raise TypeError(f"{param}: expected an rbcli.Body{' or None' if optional else ''} (from "
                    f"rbcli.load or rbcli.load_text), got {_type(value)}{hint}")


def flag(value: Any, param: str) -> bool:
    """A flag: ``True`` or ``False`` (a numpy bool too); anything else — ``"false"``, ``0``,
    ``None`` — is a TypeError, never read as true or false."""
    if _is_bool(value):
        return bool(value)
    raise _wrong(param, "True or False", value)


#: the largest count any parameter takes is far below this (a 64-bit integer's range)
_MAX_COUNT = 2**63 - 1


def count(value: Any, param: str) -> int | None:
    """A whole number (an ``int`` or a numpy integer; not a bool, a float or a string), or
    None. Its range is the reader's to check (an InputError naming ``param``); one beyond a
    64-bit integer is refused here (no count is that large, and its digits are not printed)."""
    if value is None:
        return None
    if _is_bool(value) or isinstance(value, (str, bytes, float)):
        raise _wrong(param, "an int", value)
    if not isinstance(value, int):
        if not (isinstance(value, numbers.Integral) or _shape(value) == ()):
            raise _wrong(param, "an int", value)
        if _shape(value) == ():
            value = _item(value, param, "an int")
            if _is_bool(value) or not isinstance(value, numbers.Integral):
                raise _wrong(param, "an int", value)
        try:
            import operator

            value = operator.index(value)
        except Exception as exc:  # noqa: BLE001 - a user's integer type
            raise _failed(param, "an int", value, "__index__", exc) from None
    n = int(value)
    if abs(n) > _MAX_COUNT:
        raise ParamError(param, f"an integer of about {int(n.bit_length() * math.log10(2)) + 1} "
                         "digits is far beyond any count")
    return n


def quantity(value: Any, param: str) -> float | str | None:
    """One :data:`Quantity` — a number (SI) or a quantity string — or None."""
    if value is None:
        return None
    return _scalar(value, param, _NUMBER)


def values(most: int, *, expected: str | None = None) -> Callable[[Any, str], Any]:
    """The checker of a parameter taking one value or up to ``most`` of them (:data:`Values`):
    a string, a number, or a sequence of numbers and quantity strings (returned as a tuple)."""
    what = expected or (f"{_NUMBER}, or a sequence of up to {most}" if most > 1 else _NUMBER)

    def check(value: Any, param: str) -> float | str | tuple | None:
        if value is None:
            return None
        if isinstance(value, str) or _is_bool(value) or isinstance(value, numbers.Real) \
                or _shape(value) == ():
            return _scalar(value, param, what)
        items = _sequence(value, param, most, what)
        return _total(tuple(_scalar(x, f"{param}[{i}]", _NUMBER) for i, x in enumerate(items)), param)

    return check


#: x, y, z (:data:`Vector`, :data:`Point`): a string or three values
vector = values(3, expected="x, y, z: a string such as '1,0,0' or a sequence of 3 numbers")


def text(value: Any, param: str) -> str | None:
    """A string (a choice such as ``"with"``, a units list such as ``"mm,g"``), or None."""
    if value is None:
        return None
    if not isinstance(value, str):
        raise _wrong(param, "a str", value)
    return _text(value, param)


def texts(depth: int = 1, most: int = MAX_ITEMS) -> Callable[[Any, str], Any]:
    """The checker of a parameter taking a string or a sequence of strings (``depth`` 2: each
    item a string or itself a sequence of strings, as a run of readings)."""
    what = "a str or a sequence of str" if depth == 1 else \
        "a str or a sequence of str (or of sequences of str)"

    def one(value: Any, param: str, level: int) -> Any:
        if isinstance(value, str):
            return _text(value, param)
        if level == 0:
            raise _wrong(param, "a str", value)
        items = _sequence(value, param, most, what)
        return tuple(one(x, f"{param}[{i}]", level - 1) for i, x in enumerate(items))

    def check(value: Any, param: str) -> Any:
        if value is None:
            return None
        return _total(one(value, param, depth), param)

    return check


def integers(most: int) -> Callable[[Any, str], Any]:
    """The checker of a parameter taking whole numbers: an int, a string (``"1,2"``) or a
    sequence of ints (returned as a tuple)."""
    expected = f"an int, a str or a sequence of up to {most} ints"

    def check(value: Any, param: str) -> Any:
        if value is None or isinstance(value, str):
            return text(value, param)
        shape = _shape(value)
        if shape == () or (shape is None and not isinstance(value, Sequence)):
            return count(value, param)
        items = _sequence(value, param, most, expected)
        return tuple(count(x, f"{param}[{i}]") for i, x in enumerate(items))

    return check


def path(value: Any, param: str) -> str | None:
    """A file name: a ``str`` or an :class:`os.PathLike` giving one (not bytes), or None."""
    if value is None:
        return None
    if isinstance(value, str):
        return _text(value, param)
    if isinstance(value, os.PathLike):
        try:
            p = os.fspath(value)
        except Exception as exc:  # noqa: BLE001 - a user's path type
            raise _failed(param, "a str or a path", value, "os.fspath", exc) from None
        if isinstance(p, str):
            return _text(p, param)
    raise _wrong(param, "a str or an os.PathLike (a pathlib.Path)", value)


def function(value: Any, param: str) -> Callable | None:
    """A callable, or None."""
    if value is None or callable(value):
        return value
    raise _wrong(param, "a callable", value)


def times(value: Any, param: str = "t", *, most: int = MAX_TIMES, ndim: int | None = None) -> Any:
    """Times in seconds: a number or a quantity string (``"7320 h"``) as a float, or numbers
    (a sequence, an array: of at most ``ndim`` dimensions when given) as a float ndarray of
    at most ``most`` entries; each finite (an InputError naming ``param`` otherwise)."""
    if isinstance(value, str) or isinstance(value, numbers.Real) or _is_bool(value) \
            or _shape(value) == ():
        x = _scalar(value, param, "a time: a number (s), a quantity string or an array of numbers")
        if isinstance(x, str):
            return op.quantity(x, "time", param)
        if not math.isfinite(x):
            raise ParamError(param, f"a time must be a finite number (s), got {x}")
        return x
    import numpy as np

    expected = "a time: a number (s), a quantity string or an array of numbers"
    shape = _shape(value)
    if shape is None:
        if not isinstance(value, (list, tuple)):
            raise _wrong(param, expected, value)
        n = _length(value, param, expected)
    else:
        try:
            n = math.prod(int(s) for s in shape)
        except Exception as exc:  # noqa: BLE001 - a user's array
            raise _failed(param, expected, value, "its shape", exc) from None
    if n > most:
        raise ParamError(param, f"at most {most} times at once, got {n}")
    if shape is not None:
        kind = getattr(getattr(value, "dtype", None), "kind", None)
        if kind not in ("i", "u", "f"):
            raise _wrong(param, f"{expected} (real numbers)", value)
    else:
        for x in value:  # one level: a nested list is numpy's to refuse below
            if _is_bool(x) or isinstance(x, (str, bytes)):
                raise _wrong(param, expected, value)
    try:
        with np.errstate(all="ignore"):
            a = np.array(value, dtype=float)
    except Exception as exc:  # noqa: BLE001 - ragged lists, a user's array type
        raise _failed(param, expected, value, "reading it as numbers", exc) from None
    if a.size > most:
        raise ParamError(param, f"at most {most} times at once, got {a.size}")
    if ndim is not None and a.ndim > ndim:
        raise ParamError(param, f"expected a number or a {ndim}-D array of times, got an array of "
                         f"{a.ndim} dimensions")
    if not np.all(np.isfinite(a)):
        raise ParamError(param, "times must be finite numbers (s)")
    return a


def arguments(kinds: Mapping[str, Callable[[Any, str], Any]], **given: Any) -> dict[str, Any]:
    """Each keyword argument in ``given`` checked by its checker in ``kinds``, in order (a
    name ``kinds`` does not have is a TypeError, as Python says it for a signature)."""
    out = {}
    for name, value in given.items():
        kind = kinds.get(name)
        if kind is None:
            raise TypeError(f"unexpected keyword argument {name!r}")
        out[name] = kind(value, name)
    return out


@contextmanager
def arithmetic(given: Mapping[str, Any]) -> Iterator[None]:
    """The other half of the door: an arithmetic error deep in a computation (a float that
    overflows, a division by zero) with values that passed every check comes out as a
    :class:`rbcli.NonFiniteResult` (an InputError, exit 2) naming the parameters ``given``
    (those not None or False). numpy's warnings of such values are not shown (the result's
    finiteness check refuses what they warn of); its error state is restored afterwards."""
    import numpy as np

    try:
        with np.errstate(all="ignore"):  # NaN and inf are refused on the way out, as one error
            yield
    except (OverflowError, ZeroDivisionError, FloatingPointError) as exc:
        names = [n for n, v in given.items() if v is not None and v is not False]
        who = ", ".join("{%s}" % n for n in names)
        raise NonFiniteResult(
            f"{who + ': ' if who else ''}a value is too large or too small to compute with "
            f"({literal(exc) or type(exc).__name__}); check the values and the body's numbers"
        ) from None
