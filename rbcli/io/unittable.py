"""The unit table: exact numbers, dimensions, the kinds rbcli reads, and every unit's
exact factor to SI. Standard library only (on every command's start-up path).

Four base dimensions: length, mass, time and angle (an angle is not dimensionless, so
``Hz`` is never silently taken for rad/s, as pint does). Factors are exact, a
:class:`fractions.Fraction` times a power of pi, rounded once by :func:`to_float`. Names
match exactly, else ignoring case when exactly one unit matches and no prefix or symbol
changes meaning (``RPM``, ``Kg`` are read; ``Mm``, ``G``, ``MS`` refused). No general
SI-prefix machinery: the table's entries only (:func:`format_unit_table`). The grammar is
:mod:`rbcli.io.unitparse`; the public functions :mod:`rbcli.io.units`."""

from __future__ import annotations

import re
from fractions import Fraction
from typing import NamedTuple

# --- dimensions

DIM_ORDER = (("M", "mass"), ("L", "length"), ("T", "time"), ("A", "angle"))


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

    def describe(self) -> str:
        """E.g. ``"length"``, ``"mass/length^3"``, ``"angle/time"``, ``"1/time"``."""
        num: list[str] = []
        den: list[str] = []
        for attr, word in DIM_ORDER:
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
KIND_EXAMPLES: dict[str, str] = {
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


def noun_for_dim(dim: Dim) -> str:
    noun = _DIM_NOUN.get(dim)
    if noun is None:
        return f"a quantity of dimension {dim.describe()}"
    if dim in (Dim(), Dim(L=1), Dim(M=1), Dim(T=1), Dim(A=1)):
        return noun
    return f"{noun} ({dim.describe()})"


def noun_for_kind(kind: str) -> str:
    dim = KINDS[kind]
    noun = _KIND_NOUN[kind]
    if dim in (Dim(), Dim(L=1), Dim(M=1), Dim(T=1), Dim(A=1)):
        return noun
    return f"{noun} ({dim.describe()})"


# --- the table

# pi to 60 decimals: enough that rounding q * pi^k to a float is the correctly rounded
# value (the error, ~1e-60 relative, is far below half an ulp, 1.1e-16).
_PI = Fraction("3.141592653589793238462643383279502884197169399375105820974944")

class _Unit:
    """A row of the unit table (a plain class: a NamedTuple costs start-up to create)."""

    __slots__ = ("names", "q", "pi", "dim", "note")

    def __init__(self, names: tuple[str, ...], q: Fraction, pi: int, dim: Dim, note: str) -> None:
        self.names = names  # canonical name first, then aliases
        self.q = q  # rational part of the factor to SI
        self.pi = pi  # power of pi in the factor to SI
        self.dim = dim
        self.note = note  # what it is, for the table


_IN = Fraction("0.0254")
_LB = Fraction("0.45359237")
_GN = Fraction("9.80665")

_UNITS: tuple[_Unit, ...] = (
    # length
    _Unit(("m",), Fraction(1), 0, Dim(L=1), "metre"),
    _Unit(("mm",), Fraction(1, 1000), 0, Dim(L=1), "millimetre"),
    _Unit(("cm",), Fraction(1, 100), 0, Dim(L=1), "centimetre"),
    _Unit(("dm",), Fraction(1, 10), 0, Dim(L=1), "decimetre"),
    _Unit(("km",), Fraction(1000), 0, Dim(L=1), "kilometre"),
    _Unit(("um", "µm", "μm"), Fraction(1, 10**6), 0, Dim(L=1), "micrometre"),
    _Unit(("nm",), Fraction(1, 10**9), 0, Dim(L=1), "nanometre"),
    _Unit(("in", "inch", "inches", "in."), _IN, 0, Dim(L=1), "inch, exactly 0.0254 m"),
    _Unit(("ft", "foot", "feet"), 12 * _IN, 0, Dim(L=1), "foot, 12 in"),
    _Unit(("yd",), 36 * _IN, 0, Dim(L=1), "yard, 3 ft"),
    _Unit(("mi",), 5280 * 12 * _IN, 0, Dim(L=1), "statute mile, 5280 ft"),
    _Unit(("mil", "thou"), _IN / 1000, 0, Dim(L=1), "thousandth of an inch, 25.4 um"),
    # mass
    _Unit(("kg",), Fraction(1), 0, Dim(M=1), "kilogram"),
    _Unit(("g",), Fraction(1, 1000), 0, Dim(M=1), "gram"),
    _Unit(("mg",), Fraction(1, 10**6), 0, Dim(M=1), "milligram"),
    _Unit(("ug", "µg", "μg"), Fraction(1, 10**9), 0, Dim(M=1), "microgram"),
    _Unit(("t", "tonne"), Fraction(1000), 0, Dim(M=1), "tonne (metric ton)"),
    _Unit(("lb", "lbm", "lbs", "pound", "pounds"), _LB, 0, Dim(M=1),
          "avoirdupois pound, exactly 0.45359237 kg"),
    _Unit(("slug",), _LB * _GN / (12 * _IN), 0, Dim(M=1), "slug, lbf*s^2/ft"),
    _Unit(("oz",), _LB / 16, 0, Dim(M=1), "avoirdupois ounce, lb/16"),
    # volume
    _Unit(("cc",), Fraction(1, 10**6), 0, Dim(L=3), "cubic centimetre, cm^3"),
    # time
    _Unit(("s",), Fraction(1), 0, Dim(T=1), "second"),
    _Unit(("ms",), Fraction(1, 1000), 0, Dim(T=1), "millisecond"),
    _Unit(("min",), Fraction(60), 0, Dim(T=1), "minute"),
    _Unit(("h",), Fraction(3600), 0, Dim(T=1), "hour"),
    _Unit(("d", "day"), Fraction(86400), 0, Dim(T=1), "day (86 400 s)"),
    # angle
    _Unit(("rad",), Fraction(1), 0, Dim(A=1), "radian"),
    _Unit(("mrad",), Fraction(1, 1000), 0, Dim(A=1), "milliradian"),
    _Unit(("deg", "°"), Fraction(1, 180), 1, Dim(A=1), "degree, pi/180 rad"),
    _Unit(("arcmin",), Fraction(1, 180 * 60), 1, Dim(A=1), "minute of arc, deg/60"),
    _Unit(("arcsec",), Fraction(1, 180 * 3600), 1, Dim(A=1), "second of arc, deg/3600"),
    _Unit(("rev", "turn"), Fraction(2), 1, Dim(A=1), "revolution, 2 pi rad"),
    # speed
    _Unit(("mph",), 5280 * 12 * _IN / 3600, 0, Dim(L=1, T=-1), "mile per hour, 0.44704 m/s"),
    # angular speed
    _Unit(("rpm", "r/min"), Fraction(2, 60), 1, Dim(A=1, T=-1), "revolution per minute, rev/min"),
    # frequency (1/time: NOT an angular speed)
    _Unit(("Hz",), Fraction(1), 0, Dim(T=-1), "hertz, 1/s (a frequency, not an angular speed)"),
    _Unit(("kHz",), Fraction(1000), 0, Dim(T=-1), "kilohertz, 1000/s"),
    # acceleration
    _Unit(("g0",), _GN, 0, Dim(L=1, T=-2), "standard gravity, exactly 9.80665 m/s^2"),
    # force
    _Unit(("N",), Fraction(1), 0, Dim(M=1, L=1, T=-2), "newton, kg*m/s^2"),
    _Unit(("kN",), Fraction(1000), 0, Dim(M=1, L=1, T=-2), "kilonewton"),
    _Unit(("lbf",), _LB * _GN, 0, Dim(M=1, L=1, T=-2), "pound-force, lb*g0"),
    _Unit(("kgf",), _GN, 0, Dim(M=1, L=1, T=-2), "kilogram-force, kg*g0"),
    # energy
    _Unit(("J",), Fraction(1), 0, Dim(M=1, L=2, T=-2), "joule, N*m"),
)

BY_NAME: dict[str, _Unit] = {name: u for u in _UNITS for name in u.names}

#: first letters whose case changes meaning (SI prefixes mega/milli, giga, tera, peta, exa,
#: zetta/zepto, yotta/yocto, pico, nano/newton, femto, atto; joule): a name typed with
#: such a letter in the other case is never read as the table's unit
_CASE_SENSITIVE_FIRST = set("MmGTPEZzYyNnpfaJ")
_POWER_SUFFIX_RE = re.compile(r"(.*?[^\d])([1-9]\d*)")


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


def lookup(name: str) -> tuple[_Unit, int] | None:
    """A written name as (unit, power): exact, ignoring case when unambiguous, or a
    name followed by digits as that unit to the power of the digits (``m3``)."""
    unit = BY_NAME.get(name) or _folded(name)
    if unit is not None:
        return unit, 1
    m = _POWER_SUFFIX_RE.fullmatch(name)
    if m:
        unit = BY_NAME.get(m.group(1)) or _folded(m.group(1))
        if unit is not None:
            return unit, int(m.group(2))
    return None

#: a unit name: a letter, then letters, digits or underscores (or the degree sign)
NAME_RE = re.compile(r"[A-Za-zµμ][A-Za-z0-9_µμ]*|°")

def to_float(q: Fraction, pi: int, text: str = "") -> float:
    """Round ``q * pi**pi`` to the nearest float, once."""
    exact = q * _PI**pi if pi else q
    try:
        return float(exact)
    except OverflowError:
        where = f"'{text}' is" if text else "the value is"
        raise UnitError(
            f"{where} too large in SI units; floating-point numbers stop at about 1.8e308"
        ) from None


_SI_TEXT = {"M": "kg", "L": "m", "T": "s", "A": "rad"}


def known_units() -> list[str]:
    """Every unit name (aliases included) the parser accepts, in table order."""
    return [name for u in _UNITS for name in u.names]


def _si_unit_text(dim: Dim) -> str:
    """The SI unit of a dimension, e.g. ``kg/m^3``; ``1`` when dimensionless."""
    text = compose(_SI_TEXT, dim) or "1"
    return text.replace("1/s", "s^-1") if text.startswith("1/") else text


def _exact_text(q: Fraction, pi: int) -> str:
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
                f"{to_float(u.q, u.pi)!r} {si}",
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


# --- base units

BASE_KEYS = {"length": "L", "mass": "M", "time": "T", "angle": "A"}
BASE_DEFAULTS = {"length": "m", "mass": "kg", "time": "s", "angle": "deg"}


def _is_name(text: str) -> bool:
    """``text`` is one unit name (no parentheses needed around it): a name of the table
    (``in.`` too) or what :data:`NAME_RE` reads as one."""
    return (text in BY_NAME and "/" not in text) or NAME_RE.fullmatch(text) is not None


def compose(texts: dict[str, str], dim: Dim) -> str:
    """Unit text for ``dim`` from base unit texts keyed by 'M', 'L', 'T', 'A'."""
    num: list[str] = []
    den: list[str] = []
    for attr, _word in DIM_ORDER:
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


