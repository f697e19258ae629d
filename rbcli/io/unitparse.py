"""The grammar of units and quantities, read into exact factors (:mod:`rbcli.io.unittable`'s
rationals and powers of pi). Standard library only.

A quantity is a number (Python float syntax; ``inf``, ``nan`` refused; read exactly:
``7.85`` is 157/20), optional space and an optional unit expression: names joined by ``*``
(``·``) and ``/``, left to right, each name or group with an integer power (``^n``, ``**n``,
``m²``, or digits after a name: ``kg/m3``) from -12 to 12, checked for each unit at every
step; ``1/s`` may start it."""

from __future__ import annotations

import difflib
import re
from fractions import Fraction

from rbcli.io.unittable import BY_NAME, NAME_RE, Dim, UnitError, known_units, lookup

# --- parsing

_MAX_TEXT = 200  # characters; keeps exact arithmetic on hostile input cheap
_MAX_EXPONENT = 12  # largest |n| in a written unit power
#: largest |n| of the power of any one unit in an expression once products and nested powers
#: are taken ('(mm^2)^3' is mm^6): checked at every step, before any factor is expanded
_MAX_UNIT_POWER = 12
_MAX_DECIMAL_EXPONENT = 400  # largest |e| in a number's exponent (floats stop at ~308)

_NUMBER_RE = re.compile(r"[+\-\u2212]?(?:\d+\.?\d*|\.\d+)(?:[eE][+\-\u2212]?\d+)?")
_NONFINITE_RE = re.compile(r"[+\-\u2212]?(?:inf(?:inity)?|nan)(?![A-Za-z0-9_])", re.IGNORECASE)
# 'r/min' is rpm, unless a power follows ('r/min^2' would be ambiguous)
_RMIN_RE = re.compile(
    r"(?<![A-Za-z0-9_µμ])r/min(?![A-Za-z0-9_µμ])(?!\s*(?:\^|\*\*|[⁻⁰¹²³⁴-⁹]))"
)
_SUPER = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺", "0123456789-+")
_SUPER_CHARS = "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺"
#: what may not follow an abbreviation's point for the point to be part of the name
_NAME_ON = re.compile(r"[A-Za-z0-9_µμ.]")
_INT_RE = re.compile(r"\s*(?:\(\s*([+\-\u2212]?\d+)\s*\)|([+\-\u2212]?\d+))")


def _suggest(name: str) -> list[str]:
    known = known_units()
    same_case = [u for u in known if u.lower() == name.lower()]
    if same_case:
        return same_case[:3]
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

    def parse(self) -> tuple[Fraction, int, Dim]:
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

    def expand(self, powers: dict[str, int]) -> tuple[Fraction, int, Dim]:
        q, p, d = Fraction(1), 0, Dim()
        for name, n in powers.items():
            if n:
                unit = BY_NAME[name]
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
            if NAME_RE.match(rest):
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
        m = NAME_RE.match(self.s, self.i)
        if not m:
            found = f"'{c}'" if c else "the end"
            raise self.error(f"expected a unit name, found {found}")
        self.i = m.end()
        name = m.group()
        if self.s.startswith(".", self.i) and lookup(name + ".") is not None and not _NAME_ON.match(self.s, self.i + 1):
            self.i += 1  # an abbreviation's point ('in.'), not a point before a name or digit
            name += "."
        found = lookup(name)
        if found is None:
            raise _unknown_unit(name, self.whole)
        unit, n = found
        if n != 1:
            self.check_exponent(str(n))
        return {unit.names[0]: n}


def check_text(text: object, what: str) -> str:
    if not isinstance(text, str):
        raise TypeError(f"{what} must be a string, not {type(text).__name__}")
    if len(text) > _MAX_TEXT:
        raise UnitError(f"{what} is too long ({len(text)} characters; at most {_MAX_TEXT})")
    return text


def parse_unit_exact(text: str, whole: str | None = None) -> tuple[Fraction, int, Dim]:
    return _UnitParser(text, text if whole is None else whole).parse()


def plain_decimal(s: str) -> bool:
    """``s`` is a plain decimal number and nothing else: an optional ``+``/``-``, ASCII
    digits with at most one ``.``, at least one digit (``"150"``, ``"-9.81"``, ``".5"``)."""
    body = s[1:] if s[:1] in ("+", "-") else s
    digits = body.replace(".", "", 1)
    return digits.isascii() and digits.isdigit()


def parse_quantity_exact(text: str) -> tuple[Fraction, Fraction, int, Dim, bool]:
    """(number, unit rational, unit pi power, dim, has_unit)."""
    text = check_text(text, "a quantity")
    s = text.strip()
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
    number = Fraction(num_text)
    rest = s[m.end() :]
    if rest.startswith((",", "_")):
        raise UnitError(
            f"cannot read the number in '{text}': use '.' as the decimal point and no "
            "thousands separators"
        )
    if not rest.strip():
        return number, Fraction(1), 0, Dim(), False
    q, p, d = parse_unit_exact(rest, whole=text)
    return number, q, p, d, True
