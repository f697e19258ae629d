"""Units: parse ``"30 cm"``, ``"7850 kg/m^3"``, ``"1200 rpm"`` into SI floats.

Standard library only (this module sits on every command's start-up path).

Model
-----
Four base dimensions: length ``L``, mass ``M``, time ``T`` and angle ``A``. The angle
is a dimension of its own, not "dimensionless": ``"12 deg"`` is an angle, ``"rpm"`` and
``"rad/s"`` are angle/time, and ``"Hz"`` is 1/time, so a frequency is never silently
taken for an angular speed (pint, which treats the radian as dimensionless, converts
``1 Hz`` to ``1 rad/s`` without a word).

Every unit's factor to SI (m, kg, s, rad) is held exactly, as a rational number
(:class:`_Q`, what this module needs of :class:`fractions.Fraction`) times an integer
power of pi (``deg = pi/180``, ``rpm = 2 pi / 60``), and the number of a quantity is
read exactly too (``7.85`` is 157/20). The product is rounded to a float once, at the very end, with
pi taken to 60 digits, so ``"7.85 g/cm^3"`` gives exactly 7850.0, ``"1 in"`` exactly
0.0254 and ``"12 deg"`` the float nearest to 12 pi / 180.

Grammar
-------
A quantity is a number (Python float syntax without underscores: sign, decimals,
exponent; ``inf`` and ``nan`` refused), optional white space, then an optional unit
expression. A unit expression is unit names joined by ``*`` (or ``·``) and ``/``,
read left to right (``kg/m/s`` = kg m^-1 s^-1); each name or parenthesised group may
carry an integer power ``^n``, ``**n`` or a superscript (``m²``, ``s⁻¹``), from -12 to
12; the power of any one unit in the whole expression (``(mm^2)^3`` is mm^6) stays in
the same range, checked at every step while reading, so nested powers cost nothing.
``1/s`` is allowed at the start. A digit string directly after a name is its power
(``kg/m3``, ``mm4``; a name in the table that ends in a digit, ``g0``, is that unit).
Names are matched exactly first; a name that is not in the table is matched ignoring
case only when exactly one unit matches that way and the change of case cannot turn an
SI prefix or a unit symbol into another (``RPM``, ``Kg``, ``KG``, ``hz`` are read; ``Mm``,
``MM``, ``G``, ``Nm``, ``MS`` are refused: mega, giga and newton are not milli, gram and
nano). There is no general SI-prefix machinery, only the explicit entries of the table
(:func:`format_unit_table`).
"""

from __future__ import annotations

import math
import re
from functools import lru_cache
from typing import NamedTuple

from rbcli._startup import LazyRe

__all__ = [
    "Dim",
    "UnitError",
    "KINDS",
    "parse_unit",
    "parse_quantity",
    "to_si",
    "unit_for_kind",
    "known_units",
    "format_unit_table",
]


# --------------------------------------------------------------------------- exact numbers


class _Q:
    """An exact rational number ``numerator/denominator`` in lowest terms, denominator > 0.

    What this module needs of :class:`fractions.Fraction` (``*``, ``/``, ``**`` an int,
    ``float()``, ``numerator``/``denominator``, ``==``), with the same values: ``float()``
    is ``numerator / denominator``, Python's correctly rounded integer division, as
    ``Fraction.__float__``. It exists because ``import fractions`` (which imports
    ``decimal``) cost ~1.5 ms of every command's start-up (issue 16).
    """

    __slots__ = ("numerator", "denominator")

    def __init__(self, numerator: int, denominator: int = 1) -> None:
        if denominator == 0:
            raise ZeroDivisionError(f"_Q({numerator}, 0)")
        if denominator < 0:
            numerator, denominator = -numerator, -denominator
        g = math.gcd(numerator, denominator)
        if g != 1:
            numerator //= g
            denominator //= g
        self.numerator = numerator
        self.denominator = denominator

    def __mul__(self, other: _Q | int) -> _Q:
        if isinstance(other, int):
            return _Q(self.numerator * other, self.denominator)
        return _Q(self.numerator * other.numerator, self.denominator * other.denominator)

    __rmul__ = __mul__

    def __truediv__(self, other: _Q | int) -> _Q:
        if isinstance(other, int):
            return _Q(self.numerator, self.denominator * other)
        return _Q(self.numerator * other.denominator, self.denominator * other.numerator)

    def __pow__(self, n: int) -> _Q:
        if n >= 0:
            return _Q(self.numerator**n, self.denominator**n)
        return _Q(self.denominator ** (-n), self.numerator ** (-n))

    def __float__(self) -> float:
        return self.numerator / self.denominator

    def __eq__(self, other: object) -> bool:
        if isinstance(other, int):
            return self.denominator == 1 and self.numerator == other
        if isinstance(other, _Q):
            return self.numerator == other.numerator and self.denominator == other.denominator
        return NotImplemented

    def __hash__(self) -> int:
        return hash((self.numerator, self.denominator))

    def __repr__(self) -> str:
        return f"_Q({self.numerator}, {self.denominator})"


def _decimal(text: str) -> _Q:
    """The exact value of a decimal literal (``"-7.85"``, ``".5"``, ``"1e-3"``; digits and an
    optional sign, point and exponent, as :data:`_NUMBER_RE` matches them), as
    ``Fraction(text)`` reads it."""
    mantissa, _, exp = text.replace("E", "e").partition("e")
    sign = -1 if mantissa.startswith("-") else 1
    whole, _, frac = mantissa.lstrip("+-").partition(".")
    n = sign * int((whole + frac) or "0")
    e = (int(exp) if exp else 0) - len(frac)
    return _Q(n * 10**e) if e >= 0 else _Q(n, 10 ** (-e))


def _F(value: int | str, denominator: int = 1) -> _Q:
    """A table constant: ``_F(1, 1000)``, ``_F("0.0254")``."""
    return _decimal(value) if isinstance(value, str) else _Q(value, denominator)


# --------------------------------------------------------------------------- dimensions

_DIM_ORDER = (("M", "mass"), ("L", "length"), ("T", "time"), ("A", "angle"))


class Dim(NamedTuple):
    """Exponents of the four base dimensions: length, mass, time, angle.

    ``Dim(M=1, L=-3)`` is a density. ``*``, ``/`` with another :class:`Dim` and ``**``
    with an integer combine dimensions (``+`` stays tuple concatenation: do not use it).
    """

    L: int = 0
    M: int = 0
    T: int = 0
    A: int = 0

    def __mul__(self, other: object) -> Dim:  # type: ignore[override]
        if not isinstance(other, Dim):
            return NotImplemented
        return Dim(*(a + b for a, b in zip(self, other)))

    def __truediv__(self, other: object) -> Dim:
        if not isinstance(other, Dim):
            return NotImplemented
        return Dim(*(a - b for a, b in zip(self, other)))

    def __pow__(self, n: int) -> Dim:
        if not isinstance(n, int) or isinstance(n, bool):
            return NotImplemented
        return Dim(*(a * n for a in self))

    @property
    def is_dimensionless(self) -> bool:
        return not any(self)

    def describe(self) -> str:
        """E.g. ``"length"``, ``"mass/length^3"``, ``"angle/time"``, ``"1/time"``."""
        num: list[str] = []
        den: list[str] = []
        for attr, word in _DIM_ORDER:
            e = getattr(self, attr)
            if e:
                text = word if abs(e) == 1 else f"{word}^{abs(e)}"
                (num if e > 0 else den).append(text)
        if not num and not den:
            return "dimensionless"
        top = "*".join(num) if num else "1"
        if not den:
            return top
        bottom = den[0] if len(den) == 1 else "(" + "*".join(den) + ")"
        return f"{top}/{bottom}"


class UnitError(ValueError):
    """A quantity or unit that cannot be read, or has the wrong dimension."""


# Named kinds used by the rest of rbcli, with the dimension each must have.
KINDS: dict[str, Dim] = {
    "dimensionless": Dim(),
    "length": Dim(L=1),
    "mass": Dim(M=1),
    "time": Dim(T=1),
    "angle": Dim(A=1),
    "area": Dim(L=2),
    "volume": Dim(L=3),
    "density": Dim(M=1, L=-3),
    "areal_density": Dim(M=1, L=-2),
    "linear_density": Dim(M=1, L=-1),
    "inertia": Dim(M=1, L=2),
    "unbalance": Dim(M=1, L=1),
    "couple_unbalance": Dim(M=1, L=2),
    "speed": Dim(L=1, T=-1),
    "acceleration": Dim(L=1, T=-2),
    "angular_speed": Dim(A=1, T=-1),
    "force": Dim(M=1, L=1, T=-2),
    "torque": Dim(M=1, L=2, T=-2),
    "angular_momentum": Dim(M=1, L=2, T=-1),
    "energy": Dim(M=1, L=2, T=-2),
    "stiffness": Dim(M=1, T=-2),
    "damping": Dim(M=1, T=-1),
}

# How a kind is named in messages, and units to suggest for it.
_KIND_NOUN: dict[str, str] = {
    "dimensionless": "a dimensionless number (no unit)",
    "length": "a length",
    "mass": "a mass",
    "time": "a time",
    "angle": "an angle",
    "area": "an area",
    "volume": "a volume",
    "density": "a density",
    "areal_density": "an areal density",
    "linear_density": "a linear density",
    "inertia": "a moment of inertia",
    "unbalance": "an unbalance",
    "couple_unbalance": "a couple unbalance",
    "speed": "a speed",
    "acceleration": "an acceleration",
    "angular_speed": "an angular speed",
    "force": "a force",
    "torque": "a torque",
    "angular_momentum": "an angular momentum",
    "energy": "an energy",
    "stiffness": "a stiffness",
    "damping": "a damping coefficient",
}
_KIND_EXAMPLES: dict[str, str] = {
    "dimensionless": "2.5",
    "length": "m, mm, in",
    "mass": "kg, g, lb",
    "time": "s, ms, min",
    "angle": "deg, rad, rev",
    "area": "m^2, mm^2, in^2",
    "volume": "m^3, cm^3, in^3",
    "density": "kg/m^3, g/cm^3",
    "areal_density": "kg/m^2, g/cm^2",
    "linear_density": "kg/m, g/mm",
    "inertia": "kg*m^2, g*cm^2, lb*in^2",
    "unbalance": "kg*m, g*mm",
    "couple_unbalance": "kg*m^2, g*mm^2",
    "speed": "m/s, km/h",
    "acceleration": "m/s^2, g0",
    "angular_speed": "rad/s, rpm, rev/s, deg/s",
    "force": "N, kN, lbf",
    "torque": "N*m, lbf*in",
    "angular_momentum": "kg*m^2/s, N*m*s",
    "energy": "J, N*m",
    "stiffness": "N/m, N/mm, lbf/in",
    "damping": "N*s/m, N*s/mm, lbf*s/in",
}
# The noun for a dimension found in the input (first match wins; torque = energy).
_DIM_NOUN: dict[Dim, str] = {
    Dim(): "a dimensionless number",
    Dim(T=-1): "a frequency",
    Dim(M=1, L=2, T=-2): "a torque or energy",
    Dim(M=1, L=2): "a moment of inertia",
}
for _kind, _dim in KINDS.items():
    _DIM_NOUN.setdefault(_dim, _KIND_NOUN[_kind])


def _noun_for_dim(dim: Dim) -> str:
    noun = _DIM_NOUN.get(dim)
    if noun is None:
        return f"a quantity of dimension {dim.describe()}"
    if dim in (Dim(), Dim(L=1), Dim(M=1), Dim(T=1), Dim(A=1)):
        return noun
    return f"{noun} ({dim.describe()})"


def _noun_for_kind(kind: str) -> str:
    dim = KINDS[kind]
    noun = _KIND_NOUN[kind]
    if dim in (Dim(), Dim(L=1), Dim(M=1), Dim(T=1), Dim(A=1)):
        return noun
    return f"{noun} ({dim.describe()})"


# --------------------------------------------------------------------------- the table

# pi to 60 decimals: enough that rounding q * pi^k to a float is the correctly rounded
# value (the error, ~1e-60 relative, is far below half an ulp, 1.1e-16).
_PI = _F("3.141592653589793238462643383279502884197169399375105820974944")

class _Unit:
    """A row of the unit table (a plain class: a NamedTuple costs start-up to create)."""

    __slots__ = ("names", "q", "pi", "dim", "note")

    def __init__(self, names: tuple[str, ...], q: _Q, pi: int, dim: Dim, note: str) -> None:
        self.names = names  # canonical name first, then aliases
        self.q = q  # rational part of the factor to SI
        self.pi = pi  # power of pi in the factor to SI
        self.dim = dim
        self.note = note  # what it is, for the table


_IN = _F("0.0254")
_LB = _F("0.45359237")
_GN = _F("9.80665")

_UNITS: tuple[_Unit, ...] = (
    # length
    _Unit(("m",), _F(1), 0, Dim(L=1), "metre"),
    _Unit(("mm",), _F(1, 1000), 0, Dim(L=1), "millimetre"),
    _Unit(("cm",), _F(1, 100), 0, Dim(L=1), "centimetre"),
    _Unit(("dm",), _F(1, 10), 0, Dim(L=1), "decimetre"),
    _Unit(("km",), _F(1000), 0, Dim(L=1), "kilometre"),
    _Unit(("um", "µm", "μm"), _F(1, 10**6), 0, Dim(L=1), "micrometre"),
    _Unit(("nm",), _F(1, 10**9), 0, Dim(L=1), "nanometre"),
    _Unit(("in", "inch"), _IN, 0, Dim(L=1), "inch, exactly 0.0254 m"),
    _Unit(("ft",), 12 * _IN, 0, Dim(L=1), "foot, 12 in"),
    _Unit(("yd",), 36 * _IN, 0, Dim(L=1), "yard, 3 ft"),
    _Unit(("mi",), 5280 * 12 * _IN, 0, Dim(L=1), "statute mile, 5280 ft"),
    _Unit(("mil", "thou"), _IN / 1000, 0, Dim(L=1), "thousandth of an inch, 25.4 um"),
    # mass
    _Unit(("kg",), _F(1), 0, Dim(M=1), "kilogram"),
    _Unit(("g",), _F(1, 1000), 0, Dim(M=1), "gram"),
    _Unit(("mg",), _F(1, 10**6), 0, Dim(M=1), "milligram"),
    _Unit(("t", "tonne"), _F(1000), 0, Dim(M=1), "tonne (metric ton)"),
    _Unit(("lb", "lbm"), _LB, 0, Dim(M=1), "avoirdupois pound, exactly 0.45359237 kg"),
    _Unit(("slug",), _LB * _GN / (12 * _IN), 0, Dim(M=1), "slug, lbf*s^2/ft"),
    _Unit(("oz",), _LB / 16, 0, Dim(M=1), "avoirdupois ounce, lb/16"),
    # volume
    _Unit(("cc",), _F(1, 10**6), 0, Dim(L=3), "cubic centimetre, cm^3"),
    # time
    _Unit(("s",), _F(1), 0, Dim(T=1), "second"),
    _Unit(("ms",), _F(1, 1000), 0, Dim(T=1), "millisecond"),
    _Unit(("min",), _F(60), 0, Dim(T=1), "minute"),
    _Unit(("h",), _F(3600), 0, Dim(T=1), "hour"),
    _Unit(("d", "day"), _F(86400), 0, Dim(T=1), "day (86 400 s)"),
    # angle
    _Unit(("rad",), _F(1), 0, Dim(A=1), "radian"),
    _Unit(("mrad",), _F(1, 1000), 0, Dim(A=1), "milliradian"),
    _Unit(("deg", "°"), _F(1, 180), 1, Dim(A=1), "degree, pi/180 rad"),
    _Unit(("arcmin",), _F(1, 180 * 60), 1, Dim(A=1), "minute of arc, deg/60"),
    _Unit(("arcsec",), _F(1, 180 * 3600), 1, Dim(A=1), "second of arc, deg/3600"),
    _Unit(("rev", "turn"), _F(2), 1, Dim(A=1), "revolution, 2 pi rad"),
    # angular speed
    _Unit(("rpm", "r/min"), _F(2, 60), 1, Dim(A=1, T=-1), "revolution per minute, rev/min"),
    # frequency (1/time: NOT an angular speed)
    _Unit(("Hz",), _F(1), 0, Dim(T=-1), "hertz, 1/s (a frequency, not an angular speed)"),
    _Unit(("kHz",), _F(1000), 0, Dim(T=-1), "kilohertz, 1000/s"),
    # acceleration
    _Unit(("g0",), _GN, 0, Dim(L=1, T=-2), "standard gravity, exactly 9.80665 m/s^2"),
    # force
    _Unit(("N",), _F(1), 0, Dim(M=1, L=1, T=-2), "newton, kg*m/s^2"),
    _Unit(("kN",), _F(1000), 0, Dim(M=1, L=1, T=-2), "kilonewton"),
    _Unit(("lbf",), _LB * _GN, 0, Dim(M=1, L=1, T=-2), "pound-force, lb*g0"),
    _Unit(("kgf",), _GN, 0, Dim(M=1, L=1, T=-2), "kilogram-force, kg*g0"),
    # energy
    _Unit(("J",), _F(1), 0, Dim(M=1, L=2, T=-2), "joule, N*m"),
)

_BY_NAME: dict[str, _Unit] = {name: u for u in _UNITS for name in u.names}

#: first letters whose case changes meaning (SI prefixes mega/milli, giga, tera, peta, exa,
#: zetta/zepto, yotta/yocto, pico, nano/newton, femto, atto; joule): a name typed with
#: such a letter in the other case is never read as the table's unit
_CASE_SENSITIVE_FIRST = set("MmGTPEZzYyNnpfaJ")
_POWER_SUFFIX_RE = LazyRe(r"(.*?[^\d])([1-9]\d*)")


def _folded(name: str) -> _Unit | None:
    """The one unit ``name`` means when read ignoring case, if that is unambiguous."""
    if len(name) < 2:
        return None
    matches = {u.names[0]: (u, n) for u in _UNITS for n in u.names if n.lower() == name.lower()}
    if len(matches) != 1:
        return None
    unit, written = next(iter(matches.values()))
    if name[0] != written[0] and (name[0] in _CASE_SENSITIVE_FIRST or written[0] in _CASE_SENSITIVE_FIRST):
        return None
    if any(a != b and (a in "NJ" or b in "NJ") for a, b in zip(name, written)):
        return None  # 'kn' is not kN
    return unit


def _lookup(name: str) -> tuple[_Unit, int] | None:
    """A written name as (unit, power): exact, ignoring case when unambiguous, or a
    name followed by digits as that unit to the power of the digits (``m3``)."""
    unit = _BY_NAME.get(name) or _folded(name)
    if unit is not None:
        return unit, 1
    m = _POWER_SUFFIX_RE.fullmatch(name)
    if m:
        unit = _BY_NAME.get(m.group(1)) or _folded(m.group(1))
        if unit is not None:
            return unit, int(m.group(2))
    return None

_SI_TEXT = {"M": "kg", "L": "m", "T": "s", "A": "rad"}


def known_units() -> list[str]:
    """Every unit name (aliases included) the parser accepts, in table order."""
    return [name for u in _UNITS for name in u.names]


def _si_unit_text(dim: Dim) -> str:
    """The SI unit of a dimension, e.g. ``kg/m^3``; ``1`` when dimensionless."""
    text = _compose(_SI_TEXT, dim) or "1"
    return text.replace("1/s", "s^-1") if text.startswith("1/") else text


def _exact_text(q: _Q, pi: int) -> str:
    parts = []
    if q.numerator != 1 or pi == 0:
        parts.append(str(q.numerator))
    if pi:
        parts.append("pi" if pi == 1 else f"pi^{pi}")
    text = "*".join(parts)
    if q.denominator != 1:
        text += f"/{q.denominator}"
    return text


def format_unit_table() -> str:
    """A plain-text table of every unit, its dimension and its exact factor to SI."""
    rows = [("unit", "aliases", "dimension", "in SI (exact)", "in SI (float)", "what")]
    for u in _UNITS:
        si = _si_unit_text(u.dim)
        rows.append(
            (
                u.names[0],
                ", ".join(u.names[1:]),
                u.dim.describe(),
                f"{_exact_text(u.q, u.pi)} {si}",
                f"{_to_float(u.q, u.pi)!r} {si}",
                u.note,
            )
        )
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]) - 1)]
    lines = []
    for r in rows:
        cells = [c.ljust(w) for c, w in zip(r, widths)]
        lines.append("  ".join(cells + [r[-1]]).rstrip())
    lines.insert(1, "  ".join("-" * w for w in widths) + "  " + "-" * 4)
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------- parsing

_MAX_TEXT = 200  # characters; keeps exact arithmetic on hostile input cheap
_MAX_EXPONENT = 12  # largest |n| in a written unit power
#: largest |n| of the power of any one unit in an expression once products and nested powers
#: are taken ('(mm^2)^3' is mm^6): checked at every step, before any factor is expanded
_MAX_UNIT_POWER = 12
_MAX_DECIMAL_EXPONENT = 400  # largest |e| in a number's exponent (floats stop at ~308)

_NUMBER_RE = LazyRe(r"[+\-\u2212]?(?:\d+\.?\d*|\.\d+)(?:[eE][+\-\u2212]?\d+)?")
_NONFINITE_RE = LazyRe(r"[+\-\u2212]?(?:inf(?:inity)?|nan)(?![A-Za-z0-9_])", re.IGNORECASE)
_NAME_RE = LazyRe(r"[A-Za-zµμ][A-Za-z0-9_µμ]*|°")
# 'r/min' is rpm, unless a power follows ('r/min^2' would be ambiguous)
_RMIN_RE = LazyRe(
    r"(?<![A-Za-z0-9_µμ])r/min(?![A-Za-z0-9_µμ])(?!\s*(?:\^|\*\*|[⁻⁰¹²³⁴-⁹]))"
)
_SUPER = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺", "0123456789-+")
_SUPER_CHARS = "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺"
_INT_RE = LazyRe(r"\s*(?:\(\s*([+\-\u2212]?\d+)\s*\)|([+\-\u2212]?\d+))")


def _to_float(q: _Q, pi: int, text: str = "") -> float:
    """Round ``q * pi**pi`` to the nearest float, once."""
    exact = q * _PI**pi if pi else q
    try:
        return float(exact)
    except OverflowError:
        where = f"'{text}' is" if text else "the value is"
        raise UnitError(
            f"{where} too large in SI units; floating-point numbers stop at about 1.8e308"
        ) from None


def _suggest(name: str) -> list[str]:
    known = known_units()
    same_case = [u for u in known if u.lower() == name.lower()]
    if same_case:
        return same_case[:3]
    import difflib  # only on the error path

    lowered: dict[str, str] = {}
    for u in known:
        lowered.setdefault(u.lower(), u)
    close = difflib.get_close_matches(name.lower(), list(lowered), n=3, cutoff=0.6)
    return [lowered[c] for c in close]


def _unknown_unit(name: str, whole: str) -> UnitError:
    where = "" if whole.strip() == name else f" in '{whole}'"
    hints = _suggest(name)
    if hints:
        alts = " or ".join(f"'{h}'" for h in hints)
        return UnitError(f"unknown unit '{name}'{where}; did you mean {alts}?")
    return UnitError(
        f"unknown unit '{name}'{where}; known units: {', '.join(known_units())}"
    )


class _UnitParser:
    """Recursive descent over a unit expression; exact factors."""

    def __init__(self, text: str, whole: str) -> None:
        self.s = _RMIN_RE.sub("rpm", text)
        self.whole = whole
        self.i = 0

    def error(self, what: str) -> UnitError:
        return UnitError(f"cannot read '{self.whole}': {what}")

    def skip_ws(self) -> None:
        while self.i < len(self.s) and self.s[self.i].isspace():
            self.i += 1

    def peek(self) -> str:
        self.skip_ws()
        return self.s[self.i] if self.i < len(self.s) else ""

    def parse(self) -> tuple[_Q, int, Dim]:
        self.skip_ws()
        if self.i >= len(self.s):
            raise UnitError(f"no unit in '{self.whole}'; write a unit such as m, kg, s, deg")
        # '1/s': a leading 1 is allowed only before '/'
        if self.s.startswith("1", self.i):
            j = self.i + 1
            while j < len(self.s) and self.s[j].isspace():
                j += 1
            if j < len(self.s) and self.s[j] == "/":
                self.i = j
                return self.expand(self.finish(self.product({})))
        return self.expand(self.finish(self.expression()))

    # A unit expression is read as the exponent of each named unit ({"mm": 2, "g": 1}),
    # bounded after every step (:data:`_MAX_UNIT_POWER`); the exact factor is expanded
    # only at the end, from exponents that are known to be small. So nested powers such
    # as '((mm^12)^12)^12' are refused at once instead of building huge fractions.

    def expand(self, powers: dict[str, int]) -> tuple[_Q, int, Dim]:
        q, p, d = _Q(1), 0, Dim()
        for name, n in powers.items():
            if n:
                unit = _BY_NAME[name]
                q, p, d = q * unit.q**n, p + unit.pi * n, d * unit.dim**n
        return q, p, d

    def bounded(self, powers: dict[str, int]) -> dict[str, int]:
        for name, n in powers.items():
            if abs(n) > _MAX_UNIT_POWER:
                raise self.error(
                    f"the power of '{name}' reaches {n}; the power of each unit in an "
                    f"expression goes from -{_MAX_UNIT_POWER} to {_MAX_UNIT_POWER}"
                )
        return powers

    def finish(self, result: dict[str, int]) -> dict[str, int]:
        self.skip_ws()
        if self.i < len(self.s):
            rest = self.s[self.i :]
            if _NAME_RE.match(rest):
                raise self.error(
                    f"unexpected '{rest}' after a unit; join units with '*' or '/' "
                    "(e.g. 'kg*m^2', 'kg/m^3')"
                )
            if rest[0] == ")":
                raise self.error("unbalanced ')'")
            raise self.error(f"unexpected '{rest}'; a unit is names joined by '*' and '/'")
        return result

    def expression(self) -> dict[str, int]:
        return self.product(self.power())

    def product(self, acc: dict[str, int]) -> dict[str, int]:
        while True:
            c = self.peek()
            if c in ("*", "·", "⋅") and not self.s.startswith("**", self.i):
                sign = 1
            elif c == "/":
                sign = -1
            else:
                return acc
            self.i += 1
            acc = dict(acc)
            for name, n in self.power().items():
                acc[name] = acc.get(name, 0) + sign * n
            self.bounded(acc)

    def power(self) -> dict[str, int]:
        powers = self.atom()
        n = self.exponent()
        if n is None:
            return powers
        return self.bounded({name: e * n for name, e in powers.items()})

    def exponent(self) -> int | None:
        self.skip_ws()
        s = self.s
        if s.startswith("**", self.i):
            self.i += 2
        elif s.startswith("^", self.i):
            self.i += 1
        elif self.i < len(s) and s[self.i] in _SUPER_CHARS:
            j = self.i
            while j < len(s) and s[j] in _SUPER_CHARS:
                j += 1
            raw = s[self.i : j].translate(_SUPER)
            self.i = j
            return self.check_exponent(raw)
        else:
            return None
        m = _INT_RE.match(s, self.i)
        if not m:
            raise self.error("a power must be a whole number, e.g. 'm^2' or 's^-1'")
        self.i = m.end()
        if re.match(r"\.\d", s[self.i : self.i + 2]):
            raise self.error("a power must be a whole number, e.g. 'm^2' or 's^-1'")
        return self.check_exponent(m.group(1) or m.group(2))

    def check_exponent(self, raw: str) -> int:
        raw = raw.replace("\u2212", "-")
        try:
            n = int(raw)
        except ValueError:
            raise self.error(f"bad power '{raw}'; a power must be a whole number") from None
        if abs(n) > _MAX_EXPONENT:
            raise self.error(f"power {n} is too large; powers go from -12 to 12")
        return n

    def atom(self) -> dict[str, int]:
        c = self.peek()
        if c == "(":
            self.i += 1
            result = self.expression()
            if self.peek() != ")":
                raise self.error("missing ')'")
            self.i += 1
            return result
        m = _NAME_RE.match(self.s, self.i)
        if not m:
            found = f"'{c}'" if c else "the end"
            raise self.error(f"expected a unit name, found {found}")
        self.i = m.end()
        found = _lookup(m.group())
        if found is None:
            raise _unknown_unit(m.group(), self.whole)
        unit, n = found
        if n != 1:
            self.check_exponent(str(n))
        return {unit.names[0]: n}


def _check_text(text: object, what: str) -> str:
    if not isinstance(text, str):
        raise TypeError(f"{what} must be a string, not {type(text).__name__}")
    if len(text) > _MAX_TEXT:
        raise UnitError(f"{what} is too long ({len(text)} characters; at most {_MAX_TEXT})")
    return text


def _parse_unit_exact(text: str, whole: str | None = None) -> tuple[_Q, int, Dim]:
    unit = _BY_NAME.get(text)
    if unit is not None and "/" not in text:
        # a bare name of the table ('mm', 'kg', '°'): what the parser returns for it (one
        # name to the power 1, no 'r/min' to rewrite), without reading it character by
        # character (the loader's units: block is mostly such names)
        return unit.q, unit.pi, unit.dim
    return _UnitParser(text, text if whole is None else whole).parse()


def parse_unit(text: str) -> tuple[float, Dim]:
    """Read a unit expression: its factor to SI and its dimension.

    Parameters
    ----------
    text : str
        E.g. ``"g/cm^3"``, ``"kg*m^2"``, ``"rev/min"``.

    Returns
    -------
    factor : float
        What one of this unit is in SI (m, kg, s, rad), computed exactly and rounded
        once: ``parse_unit("g/cm^3") == (1000.0, Dim(M=1, L=-3))``.
    dim : Dim

    Raises
    ------
    UnitError
        Unknown names (with a "did you mean"), bad syntax, powers beyond +-12.
    """
    text = _check_text(text, "a unit")
    q, p, d = _parse_unit_exact(text)
    return _to_float(q, p, text.strip()), d


def plain_decimal(s: str) -> bool:
    """``s`` is a plain decimal number and nothing else: an optional ``+``/``-``, ASCII
    digits with at most one ``.``, at least one digit (``"150"``, ``"-9.81"``, ``".5"``).

    Every such text is a whole number for :data:`_NUMBER_RE` here and for
    ``rbcli.api.options.NUMBER`` (which this lets a command skip compiling); any other text
    (an exponent, a unit, ``−``, other digits) goes to those patterns as before."""
    body = s[1:] if s[:1] in ("+", "-") else s
    digits = body.replace(".", "", 1)
    return digits.isascii() and digits.isdigit()


def _parse_quantity_exact(text: str) -> tuple[_Q, _Q, int, Dim, bool]:
    """(number, unit rational, unit pi power, dim, has_unit)."""
    text = _check_text(text, "a quantity")
    s = text.strip()
    if len(s) <= 100 and plain_decimal(s):  # what the general path returns for it
        return _decimal(s), _Q(1), 0, Dim(), False
    if not s:
        raise UnitError("empty quantity; write a number, with a unit where one is needed, "
                        "e.g. '30 cm'")
    if _NONFINITE_RE.match(s):
        raise UnitError(f"'{text}' is not a finite number; only finite numbers are allowed")
    m = _NUMBER_RE.match(s)
    if not m:
        raise UnitError(
            f"'{text}' does not start with a number; write a number, then a unit, e.g. '30 cm'"
        )
    num_text = m.group().replace("\u2212", "-")
    mantissa, _, exp = num_text.replace("E", "e").partition("e")
    if exp and abs(int(exp)) > _MAX_DECIMAL_EXPONENT:
        raise UnitError(
            f"the number in '{text}' is out of range; floating-point numbers go from about "
            "1e-308 to 1e308"
        )
    if len(mantissa) > 100:
        raise UnitError(f"the number in '{text}' has too many digits (at most 100)")
    number = _decimal(num_text)
    rest = s[m.end() :]
    if rest.startswith((",", "_")):
        raise UnitError(
            f"cannot read the number in '{text}': use '.' as the decimal point and no "
            "thousands separators"
        )
    if not rest.strip():
        return number, _Q(1), 0, Dim(), False
    q, p, d = _parse_unit_exact(rest, whole=text)
    return number, q, p, d, True


#: parsed quantity texts are cached (issue 16): a body file repeats its few unit strings
#: ("7850 kg/m^3") thousands of times, and the exact parse costs 10-20 µs each
@lru_cache(maxsize=4096)
def parse_quantity(text: str) -> tuple[float, Dim]:
    """Read a quantity: its value in SI units and its dimension.

    Parameters
    ----------
    text : str
        A number, optional white space, an optional unit expression: ``"30 cm"``,
        ``"7850 kg/m^3"``, ``"1200 rpm"``, ``"12 deg"``, ``"4e-4 kg*m^2"``, ``"-3.5 mm"``.
        A bare number (``"2.5"``) is dimensionless.

    Returns
    -------
    value : float
        In m, kg, s, rad and their products (``"30 cm"`` -> 0.3), rounded once from the
        exact product of the number and the unit's factor.
    dim : Dim

    Raises
    ------
    UnitError
        Anything that is not such a quantity, including ``inf``, ``nan`` and numbers
        whose SI value overflows a float.
    """
    number, q, p, d, _ = _parse_quantity_exact(text)
    return _to_float(number * q, p, text.strip()), d


def _format_float(x: float) -> str:
    return f"{x:.6g}"


@lru_cache(maxsize=4096)  # see parse_quantity
def to_si(text: str, kind: str) -> float:
    """Read a quantity that must be of a given kind; return its value in SI.

    Parameters
    ----------
    text : str
        A quantity with a unit (``"30 cm"``). A bare number is allowed only for
        ``kind="dimensionless"``; bare numbers in body files go through
        :func:`unit_for_kind` instead.
    kind : str
        A key of :data:`KINDS`.

    Returns
    -------
    float
        The value in SI units of that kind (an angle in rad, an angular speed in rad/s).

    Raises
    ------
    UnitError
        Unreadable text, a missing unit, or a unit of the wrong dimension; the message
        names both dimensions and suggests units of the right one. A frequency (Hz)
        given for an angular speed gets its own hint: it is never taken as rad/s.
    ValueError
        ``kind`` is not a known kind (a programming error).
    """
    if kind not in KINDS:
        raise ValueError(f"unknown kind {kind!r}; kinds are: {', '.join(KINDS)}")
    want = KINDS[kind]
    number, q, p, d, has_unit = _parse_quantity_exact(text)
    shown = text.strip()
    if not has_unit and want != Dim():
        first = _KIND_EXAMPLES[kind].split(",")[0].strip()
        raise UnitError(
            f"'{shown}' has no unit, but {_noun_for_kind(kind)} is needed here; "
            f"write e.g. '{shown} {first}' (units: {_KIND_EXAMPLES[kind]})"
        )
    if d != want:
        if kind == "angular_speed" and d == Dim(T=-1):
            per_s = _to_float(number * q, p)
            raise UnitError(
                f"'{shown}' is a frequency (1/s), not an angular speed; "
                f"write '{_format_float(per_s)} rev/s' "
                f"(= {_format_float(per_s)} Hz of rotation), "
                f"'{_format_float(60 * per_s)} rpm' or "
                f"'{_format_float(2 * math.pi * per_s)} rad/s'"
            )
        if want == Dim():
            raise UnitError(
                f"'{shown}' is {_noun_for_dim(d)}, but a dimensionless number (no unit) "
                "is needed here"
            )
        raise UnitError(
            f"'{shown}' is {_noun_for_dim(d)}, but {_noun_for_kind(kind)} is needed here "
            f"(e.g. {_KIND_EXAMPLES[kind]})"
        )
    return _to_float(number * q, p, shown)


# --------------------------------------------------------------------------- base units

_BASE_KEYS = {"length": "L", "mass": "M", "time": "T", "angle": "A"}
_BASE_DEFAULTS = {"length": "m", "mass": "kg", "time": "s", "angle": "deg"}


def _is_name(text: str) -> bool:
    """``text`` is one unit name (no parentheses needed around it); a name of the table is
    known to be one without compiling :data:`_NAME_RE` (tests/test_io_units.py checks)."""
    return (text in _BY_NAME and "/" not in text) or _NAME_RE.fullmatch(text) is not None


def _compose(texts: dict[str, str], dim: Dim) -> str:
    """Unit text for ``dim`` from base unit texts keyed by 'M', 'L', 'T', 'A'."""
    num: list[str] = []
    den: list[str] = []
    for attr, _word in _DIM_ORDER:
        e = getattr(dim, attr)
        if not e:
            continue
        base = texts[attr]
        alone = e == 1 and sum(1 for x in dim if x) == 1
        if not alone and not _is_name(base):
            base = f"({base})"
        piece = base if abs(e) == 1 else f"{base}^{abs(e)}"
        (num if e > 0 else den).append(piece)
    if not num and not den:
        return ""
    top = "*".join(num) if num else "1"
    return top + "".join(f"/{x}" for x in den)


def unit_for_kind(base_units: dict[str, str], kind: str) -> tuple[float, str]:
    """What a bare number of a given kind means in a body file.

    Parameters
    ----------
    base_units : dict
        The file's ``units:`` block: keys among ``length``, ``mass``, ``time``,
        ``angle``, ``angular_speed``, values unit texts; missing keys default to m, kg,
        s, deg and rad/s.
    kind : str
        A key of :data:`KINDS`.

    Returns
    -------
    factor : float
        Multiply a bare number by this to get SI.
    unit : str
        The unit the bare number is in, e.g. ``"g/mm^3"``; ``""`` for dimensionless.

    Notes
    -----
    The kind's dimension is built from the base units (density with
    ``{length: mm, mass: g}`` is g/mm^3, factor 1e6; force is mass*length/time^2 in
    those units); an angle is in the angle unit (default deg). Angular speeds are the
    exception: a bare angular speed is in the file's ``angular_speed`` unit when it names
    one (``angular_speed: rpm``), else rad/s (SPEC §1: "bare angles are degrees, bare
    angular speeds rad/s"), whatever the angle and time units.

    Raises
    ------
    UnitError
        An unknown key, an unknown unit, or a unit of the wrong dimension
        (``{length: kg}``).
    ValueError
        ``kind`` is not a known kind (a programming error).
    """
    try:  # cached (issue 16): a batch of files repeats one `units:` block
        items = tuple(base_units.items())
        hash(items)
    except TypeError:  # a value that is not a unit text: the uncached path says what is wrong
        return _unit_for_kind(base_units, kind)
    return _unit_for_kind_cached(items, kind)


@lru_cache(maxsize=256)
def _unit_for_kind_cached(items: tuple[tuple[str, str], ...], kind: str) -> tuple[float, str]:
    return _unit_for_kind(dict(items), kind)


def _unit_for_kind(base_units: dict[str, str], kind: str) -> tuple[float, str]:
    if kind not in KINDS:
        raise ValueError(f"unknown kind {kind!r}; kinds are: {', '.join(KINDS)}")
    speed = base_units.get("angular_speed")
    if speed is not None:
        if not isinstance(speed, str):
            raise UnitError(f"units: angular_speed must be a unit name such as 'rpm', not {speed!r}")
        try:
            _check_text(speed, "a unit")
            q, p, d = _parse_unit_exact(speed.strip(), whole=speed)
        except UnitError as exc:
            raise UnitError(f"units: angular_speed: {exc}") from None
        if d != KINDS["angular_speed"]:
            raise UnitError(
                f"units: angular_speed is '{speed}', which is {_noun_for_dim(d)}, "
                f"not {_noun_for_kind('angular_speed')} (e.g. {_KIND_EXAMPLES['angular_speed']})"
            )
        if kind == "angular_speed":
            return _to_float(q, p), speed.strip()
        base_units = {k: v for k, v in base_units.items() if k != "angular_speed"}
    if kind == "angular_speed":
        return 1.0, "rad/s"
    exact: dict[str, tuple[_Q, int]] = {}
    texts: dict[str, str] = {}
    for key, default in _BASE_DEFAULTS.items():
        exact[_BASE_KEYS[key]] = (_Q(1), 0)
        texts[_BASE_KEYS[key]] = default
    for key, value in base_units.items():
        if key not in _BASE_KEYS:
            raise UnitError(
                f"unknown key '{key}' in units; allowed: {', '.join(_BASE_KEYS)}, angular_speed"
            )
        if not isinstance(value, str):
            raise UnitError(
                f"units: {key} must be a unit name such as '{_BASE_DEFAULTS[key]}', "
                f"not {value!r}"
            )
    for key, default in _BASE_DEFAULTS.items():
        text = base_units.get(key, default)
        want = KINDS[key]
        try:
            _check_text(text, "a unit")
            q, p, d = _parse_unit_exact(text.strip(), whole=text)
        except UnitError as exc:
            raise UnitError(f"units: {key}: {exc}") from None
        if d != want:
            raise UnitError(
                f"units: {key} is '{text}', which is {_noun_for_dim(d)}, "
                f"not {_noun_for_kind(key)} (e.g. {_KIND_EXAMPLES[key]})"
            )
        exact[_BASE_KEYS[key]] = (q, p)
        texts[_BASE_KEYS[key]] = text.strip()
    dim = KINDS[kind]
    q, p = _Q(1), 0
    for attr, _word in _DIM_ORDER:
        e = getattr(dim, attr)
        if e:
            bq, bp = exact[attr]
            q *= bq**e
            p += bp * e
    return _to_float(q, p), _compose(texts, dim)
