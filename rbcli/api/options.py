"""How option values are read: the one place a number typed by a user gets its meaning.

The Python API and the command line read every value here, so ``radius="100 mm"`` and
``--radius '100 mm'`` mean the same. A value is a Python number (SI; angles in degrees), a
sequence, or a string as typed (``"30 cm"``, ``"1,1,1 mm"``); in a list a unit after the
last number applies to every bare number before it (:data:`UNIT_RULE`). Errors are
:class:`rbcli.errors.ParamError` naming the parameter (``radius: ...``; the command line
spells ``--radius: ...``)."""

from __future__ import annotations

import math
import re
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any

from rbcli.errors import InputError, Note, ParamError, literal
from rbcli.io import bare as _bare_units
from rbcli.io import units as un

__all__ = ["Value", "UNIT_RULE", "NUMBER", "Units", "param", "naming", "is_bare", "quantity",
    "degrees", "numbers", "finite", "positive", "grade", "vector", "point",
    "direction", "choice", "fraction", "symmetry_tolerance"]

#: a number at the start of a value: what is left after it is the value's unit
NUMBER = re.compile(r"\s*[-+\u2212]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?")

#: how the unit rule reads, for help texts
UNIT_RULE = "a unit after the last number applies to every bare number before it"

#: a value as the API accepts it: a number (SI), a string with or without a unit, a sequence
Value = Any


def param(name: str) -> str:
    """The Python parameter a reader is asked about: ``"radius"``; an option spelling
    (two dashes, then zero-mark-deg) is taken as its parameter (``"zero_mark_deg"``)."""
    if name.startswith("-"):
        return name.split("/")[-1].strip().lstrip("-").replace("-", "_")
    return name


@contextmanager
def naming(name: str) -> Iterator[None]:
    """An InputError raised inside that names no parameter is given ``name``'s (a reader
    that could not tell). Most readers name their parameter themselves."""
    try:
        yield
    except InputError as exc:
        if exc.param is None:
            exc.param = param(name)
        raise


def _error(name: str, reason: str) -> ParamError:
    """The error of parameter ``name``: ``{name}: reason``."""
    return ParamError(param(name), reason)


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) or (
        hasattr(v, "dtype") and getattr(v, "shape", None) == ())


def _text(v: Value, option: str) -> str:
    """A value as the text a user would have typed (numbers exactly, via repr)."""
    if isinstance(v, str):
        return v
    if _is_number(v):
        return repr(float(v))
    if isinstance(v, Sequence) or hasattr(v, "tolist"):
        items = v.tolist() if hasattr(v, "tolist") else list(v)
        return ",".join(_text(x, option) for x in items)
    raise _error(option, f"expected a number, a quantity string or a list, got "
                     f"{type(v).__name__}")


def _bare(s: str) -> bool:
    """A number with no unit after it."""
    return un.plain_decimal(s) or NUMBER.fullmatch(s) is not None


def is_bare(text: str) -> bool:
    """Every comma-separated item of ``text`` is a number with no unit (``"0.5,0.5,0"``)."""
    return all(_bare(x.strip()) for x in text.split(","))


def quantity(text: Value, kind: str, option: str, *, bare: str | None = None) -> float:
    """A scalar quantity in SI. A bare number is in ``bare`` (default: SI)."""
    if _is_number(text) and bare is None:
        return finite(float(text), option)
    s = _text(text, option).strip()
    try:
        value, dim = un.parse_quantity(s)
    except un.UnitError as exc:
        raise _error(option, literal(exc)) from None
    plain = dim == un.Dim() and _bare(s)
    if plain and bare is None:
        return value
    try:  # a bare number in ``bare`` as if typed with it: one route, one rounding
        return un.to_si(f"{s} {bare}" if plain else s, kind)
    except un.UnitError as exc:
        raise _error(option, literal(exc)) from None


def degrees(text: Value, option: str) -> float:
    """An angle in degrees: a bare number is degrees (kept exactly), else any angle unit
    (``'0.5 rad'``, ``'30 arcmin'``)."""
    s = _text(text, option).strip()
    if _bare(s):
        quantity(s, "angle", option, bare="deg")  # its errors (inf, 1e999, ...)
        return float(s.replace("\u2212", "-"))
    return math.degrees(quantity(s, "angle", option, bare="deg"))


def numbers(text: Value, kind: str, option: str, *, counts: tuple[int, ...] = (3,),
            bare: str | None = None) -> list[float]:
    """Comma-separated finite quantities of one kind, in SI: the one rule for list options.

    A unit after the LAST number applies to every bare number before it (``1,1,1 mm``); a
    number with its own unit keeps it (``10 mm,0,2 cm``); no unit at all: ``bare``, else SI.
    A bare last number with a unit elsewhere is refused unless the bare numbers are 0 (the
    unit of 5 in ``10 mm,5,0`` is a guess). A Python sequence is SI; a number, a list of one.
    """
    text = _text(text, option)
    parts = [p.strip() for p in text.split(",")]
    if len(parts) not in counts or not all(parts):
        want = " or ".join(str(n) for n in counts)
        raise _error(option, f"expected {want} comma-separated value{'s' if counts != (1,) else ''}, "
                         f"got '{literal(text)}'")
    last = quantity(parts[-1], kind, option, bare=bare)  # its own errors first
    for p in parts[:-1]:
        if not _bare(p):  # ('inf', '1e999', 'x mm': said as such, not as a unit left unclear)
            quantity(p, kind, option, bare=bare)
    m = NUMBER.match(parts[-1])
    unit = parts[-1][m.end():].strip() if m else ""
    if unit:
        parts = [f"{p} {unit}" if _bare(p) else p for p in parts]
    elif not all(_bare(p) for p in parts):
        stray = [p for p in parts if _bare(p) and float(p.replace("\u2212", "-")) != 0.0]
        if stray:
            raise _error(option, 
                f"'{literal(text)}' has a unit on some numbers but none after the last, so the "
                f"unit of {stray[0]} is unclear; put the unit after the last number (it then "
                "applies to every bare number before it) or after each number"
            )
    vals = [quantity(p, kind, option, bare=bare) for p in parts[:-1]] + [last]
    if not all(math.isfinite(v) for v in vals):
        raise _error(option, f"values must be finite numbers, got '{literal(text)}'")
    return vals


def finite(x: float, option: str) -> float:
    """``x`` if it is a finite number, else an InputError naming ``option``."""
    if not math.isfinite(x):
        raise _error(option, "must be a finite number")
    return x


def positive(x: float, option: str, what: str, unit: str = "") -> float:
    """``x`` if it is a positive finite number, else an InputError saying ``what`` it is
    and the value with its ``unit`` (``x`` is in it: SI for a value read in SI)."""
    if not (x > 0.0 and math.isfinite(x)):
        raise _error(option, f"{what} must be a positive number, got {x:.6g}{' ' + unit if unit else ''}")
    return x


#: an ISO 21940-11 balance quality grade: 'G6.3', 'g 2.5', '6.3' or '6.3 mm/s'
_GRADE = re.compile(r"[Gg]?\s*([-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?)\s*(mm/s)?")


def grade(text: Value, option: str = "grade") -> float:
    """A balance quality grade: 'G6.3', 'g 2.5', '6.3' or '6.3 mm/s' -> 6.3 (mm/s), within the
    grades ISO 21940-11 defines (G0.4 to G4000)."""
    from rbcli.core.balance import ISO_GRADE_MAX, ISO_GRADE_MIN  # (numpy: off the start-up path)

    text = _text(text, option)
    m = _GRADE.fullmatch(text.strip())
    if not m:
        raise _error(option, 
            f"'{literal(text)}' is not a balance quality grade; write e.g. G6.3, 6.3 or g2.5 "
            "(G in mm/s, from G0.4 to G4000)"
        )
    G = float(m.group(1))
    if not (math.isfinite(G) and ISO_GRADE_MIN <= G <= ISO_GRADE_MAX):
        raise _error(option, 
            f"ISO 21940-11 grades run from G{ISO_GRADE_MIN:g} to G{ISO_GRADE_MAX:g} "
            f"(mm/s), got {text}"
        )
    return G


def vector(text: Value, kind: str, option: str, n: int = 3, *, bare: str | None = None) -> list[float]:
    """A vector like ``1,0,0``, ``0,0,300 rpm``, ``10,0,5 mm`` or ``[1, 0, 0]`` (see
    :func:`numbers`)."""
    t = _text(text, option)
    if len(t.split(",")) != n:
        raise _error(option, f"expected {n} comma-separated numbers like 1,0,0, got '{literal(t)}'")
    return numbers(t, kind, option, counts=(n,), bare=bare)


def point(text: Value, option: str) -> str | list[float]:
    """``com``, ``origin`` or ``x,y,z`` (metres, unless a unit follows the last number)."""
    t = _text(text, option).strip()
    if t in ("com", "origin"):
        return t
    return vector(t, "length", option)


def direction(text: Value, option: str) -> list[float]:
    """A non-zero direction ``x,y,z`` (or a sequence); also ``x``, ``y``, ``z`` for the body
    axes. Scaled so its largest component is ±1."""
    t = _text(text, option).strip().lower()
    named = {"x": [1.0, 0.0, 0.0], "y": [0.0, 1.0, 0.0], "z": [0.0, 0.0, 1.0]}
    if t in named:
        return named[t]
    v = vector(t, "dimensionless", option)
    big = max(abs(x) for x in v)
    if not big > 0:
        raise _error(option, "the direction must be a non-zero vector")
    return [x / big for x in v]  # largest component ±1: no under/overflow when normalised


def choice(text: Value, option: str, allowed: Sequence[str]) -> str:
    """One of ``allowed`` (e.g. ``--products tensor|positive``)."""
    if text not in allowed:
        ways = " or ".join(f"'{a}'" for a in allowed)
        raise InputError(f"{{{param(option)}}} must be {ways}, not '{literal(text)}'",
                         param=param(option))
    return str(text)


def fraction(value: Value, option: str) -> float:
    """A fraction: a number (``0.05``) or a percentage (``"5 %"``, ``"5%"``)."""
    text = value.strip() if isinstance(value, str) else value
    if isinstance(text, str) and text.endswith("%"):
        return quantity(text[:-1].strip(), "dimensionless", option) / 100.0
    return quantity(text, "dimensionless", option)


def symmetry_tolerance(value: Any, option: str = "symmetry_tol") -> float:
    """The tolerance of a nearly symmetric body (``top``, ``gyrocompass``, ``rollcheck``):
    a fraction (``0.01``) or a percentage (``"1 %"``, ``"0.5%"``), from 0 to 10 %; None
    gives the default, 1 % (:data:`rbcli.core.symmetry.DEFAULT_TOLERANCE`)."""
    from rbcli.core.symmetry import DEFAULT_TOLERANCE, MAX_TOLERANCE  # (numpy, as above)

    if value is None:
        return DEFAULT_TOLERANCE
    x = fraction(value, option)
    if not (0.0 <= x <= MAX_TOLERANCE):
        raise _error(option, f"must be from 0 to {MAX_TOLERANCE * 100:g} % (a fraction such as "
                     f"0.01 or a percentage such as '1 %'), got {literal(value)}")
    return x


# --- the bare-number rule


class Units:
    """The bare-number rule for one body (:mod:`rbcli.io.bare`) as the readers apply it: a Python
    number is SI (an angle degrees), a string without a unit is in the body's bare unit of its
    kind (``base``: its ``units`` block; SI without a body)."""

    __slots__ = ("base", "_cache", "typed")

    def __init__(self, base: Any = None) -> None:
        self.base = dict(base or {})
        self._cache: dict[str, str | None] = {}
        #: parameter -> the unit the caller typed after its (last) number, for the options
        #: table to echo the value in it (``"0.5 g"`` shown as 0.5 g, not 0.0005 kg)
        self.typed: dict[str, str] = {}

    def _typed(self, value: Value, option: str) -> None:
        unit = typed_unit(value)
        if unit:
            self.typed[param(option)] = unit

    @classmethod
    def of(cls, body: Any) -> "Units":
        """The rule for ``body`` (None: SI)."""
        return cls(getattr(body, "units", None) if body is not None else None)

    def bare(self, kind: str) -> str | None:
        """The unit a bare number of ``kind`` is in (None: SI)."""
        if kind not in self._cache:
            self._cache[kind] = _bare_units.bare_unit(self.base, kind)
        return self._cache[kind]

    def label(self, kind: str) -> str:
        """How messages name the bare unit of ``kind`` (``"mm"``, ``"m"``, ``"SI"``...)."""
        return self.bare(kind) or _bare_units.SI_LABELS.get(kind, "SI")

    def factor(self, kind: str) -> float:
        """SI per bare unit of ``kind`` (1.0 for SI; an angle's is pi/180)."""
        return _bare_units.factor(self.base, kind)

    def show(self, si: Any, kind: str) -> str:
        """An SI value (or a sequence) in the bare unit of ``kind``, 6 digits, for messages."""
        f = self.factor(kind)
        if _is_number(si):
            return _g(float(si) / f)
        return ", ".join(_g(float(x) / f) for x in (si.tolist() if hasattr(si, "tolist") else si))

    def far(self, option: str, what: str, distance: float, size: float) -> str:
        """The one-line plausibility warning for a point or radius ``distance`` m away
        while the body is ``size`` m across (lengths quoted in the bare unit)."""
        unit = self.label("length")
        return Note(f"{{{param(option)}}}: {what} is {self.show(distance, 'length')} {unit}, more "
                    f"than 10× the body's size ({self.show(size, 'length')} {unit}); bare lengths are "
                    f"in {unit} (the body's units): is a unit missing?")

    def quantity(self, value: Value, kind: str, option: str) -> float:
        """:func:`quantity` with this body's bare unit (a Python number is SI, except an
        angle: degrees)."""
        if _is_number(value) and kind != "angle":
            return finite(float(value), option)
        x = quantity(value, kind, option, bare=self.bare(kind))
        self._typed(value, option)
        return x

    def positive(self, value: Value, kind: str, option: str, what: str) -> float:
        """:meth:`quantity`, which must be positive; the message quotes the value read in
        the bare unit of ``kind`` (``got -180 mm``)."""
        return self.check_positive(self.quantity(value, kind, option), kind, option, what)

    def check_positive(self, x: float, kind: str, option: str, what: str) -> float:
        """``x`` (SI) if positive and finite, else the error quoting it in the bare unit."""
        if not (x > 0.0 and math.isfinite(x)):
            raise _error(option, f"{what} must be a positive number, got {self.show(x, kind)} "
                                 f"{self.label(kind)}")
        return x

    def numbers(self, value: Value, kind: str, option: str, *,
                counts: tuple[int, ...] = (3,)) -> list[float]:
        """:func:`numbers` with this body's bare unit (a Python sequence of numbers is SI)."""
        if _is_number(value) or _is_sequence_of_numbers(value):
            return numbers(value, kind, option, counts=counts)
        vals = numbers(value, kind, option, counts=counts, bare=self.bare(kind))
        self._typed(value, option)
        return vals

    def vector(self, value: Value, kind: str, option: str, n: int = 3) -> list[float]:
        """:func:`vector` with this body's bare unit."""
        if _is_sequence_of_numbers(value):
            return vector(value, kind, option, n)
        vals = vector(value, kind, option, n, bare=self.bare(kind))
        self._typed(value, option)
        return vals

    def point(self, value: Value, option: str) -> str | list[float]:
        """:func:`point` (``com``, ``origin`` or x,y,z) with this body's bare length unit."""
        if isinstance(value, str) and value.strip() in ("com", "origin"):
            return value.strip()
        return self.vector(value, "length", option)


def typed_unit(value: Any) -> str | None:
    """The unit typed after the last number of a quantity string (``"0.5 g"`` -> ``"g"``,
    ``"-50,50 mm"`` -> ``"mm"``, ``"3000rpm"`` -> ``"rpm"``); None for a bare number, a
    Python number or anything else."""
    if not isinstance(value, str):
        return None
    last = value.rsplit(",", 1)[-1].strip()
    m = NUMBER.match(last)
    unit = last[m.end():].strip() if m else ""
    return unit or None


def _g(x: float) -> str:
    text = f"{x:.6g}"
    return "0" if text == "-0" else text


def _is_sequence_of_numbers(v: Any) -> bool:
    if isinstance(v, str):
        return False
    if hasattr(v, "tolist"):
        v = v.tolist()
    return isinstance(v, (list, tuple)) and all(_is_number(x) for x in v)
