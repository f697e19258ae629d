"""Units: read ``"30 cm"``, ``"7850 kg/m^3"``, ``"1200 rpm"`` into SI floats (standard
library only). The table is :mod:`rbcli.io.unittable`, the grammar :mod:`rbcli.io.unitparse`;
factors are exact and a quantity is rounded to a float once, so ``"7.85 g/cm^3"`` is exactly
7850.0 and ``"1 in"`` exactly 0.0254."""

from __future__ import annotations

import math
from fractions import Fraction
from functools import lru_cache

from rbcli.io.unitparse import check_text, parse_quantity_exact, parse_unit_exact, plain_decimal
from rbcli.io.unittable import (
    BASE_DEFAULTS,
    BASE_KEYS,
    BY_NAME,
    DIM_ORDER,
    KIND_EXAMPLES,
    KINDS,
    NAME_RE,
    Dim,
    UnitError,
    compose,
    format_unit_table,
    known_units,
    lookup,
    noun_for_dim,
    noun_for_kind,
    to_float,
)

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
    "plain_decimal",
    "canonical_unit",
    "bare_to_si",
]


def canonical_unit(text: str) -> str:
    """A unit text as rbcli shows it: one name of the table, whatever alias or case was
    typed (``RPM``, ``r/min`` -> ``rpm``; ``inches``, ``in.`` -> ``in``; ``lbs``,
    ``pounds`` -> ``lb``; ``feet`` -> ``ft``), as the table's first name; anything else (an
    expression such as ``g/cm^3``, a name with a power ``m3``, or no unit) as written,
    stripped."""
    t = text.strip()
    found = BY_NAME.get(t)
    if found is None and NAME_RE.fullmatch(t.rstrip(".")):
        got = lookup(t)
        found = got[0] if got is not None and got[1] == 1 else None
    return found.names[0] if found is not None else t


def parse_unit(text: str) -> tuple[float, Dim]:
    """Read a unit expression (``"g/cm^3"``, ``"kg*m^2"``, ``"rev/min"``): (its factor to SI,
    exact and rounded once, its Dim); ``parse_unit("g/cm^3") == (1000.0, Dim(M=1, L=-3))``.
    UnitError for unknown names (with a "did you mean"), bad syntax, powers beyond +-12."""
    text = check_text(text, "a unit")
    q, p, d = parse_unit_exact(text)
    return to_float(q, p, text.strip()), d


@lru_cache(maxsize=4096)
def parse_quantity(text: str) -> tuple[float, Dim]:
    """Read a quantity (``"30 cm"``, ``"7850 kg/m^3"``, ``"1200 rpm"``; a bare number is
    dimensionless): (its value in SI, rounded once from the exact product, its Dim).
    UnitError for anything else, ``inf``, ``nan`` and values that overflow."""
    number, q, p, d, _ = parse_quantity_exact(text)
    return to_float(number * q, p, text.strip()), d


def _format_float(x: float) -> str:
    return f"{x:.6g}"


@lru_cache(maxsize=4096)  # see parse_quantity
def to_si(text: str, kind: str) -> float:
    """Read a quantity of kind ``kind`` (a key of :data:`KINDS`) in SI (an angle in rad).

    A bare number only for ``"dimensionless"`` (a body file's bare numbers:
    :func:`unit_for_kind`). UnitError for unreadable text, a missing unit or one of the wrong
    dimension (naming both and suggesting units; a frequency in Hz is never taken as rad/s);
    ValueError for an unknown kind."""
    if kind not in KINDS:
        raise ValueError(f"unknown kind {kind!r}; kinds are: {', '.join(KINDS)}")
    want = KINDS[kind]
    number, q, p, d, has_unit = parse_quantity_exact(text)
    shown = text.strip()
    if not has_unit and want != Dim():
        first = KIND_EXAMPLES[kind].split(",")[0].strip()
        raise UnitError(
            f"'{shown}' has no unit, but {noun_for_kind(kind)} is needed here; "
            f"write e.g. '{shown} {first}' (units: {KIND_EXAMPLES[kind]})"
        )
    if d != want:
        if kind == "angular_speed" and d == Dim(T=-1):
            per_s = to_float(number * q, p)
            raise UnitError(
                f"'{shown}' is a frequency (1/s), not an angular speed; "
                f"write '{_format_float(per_s)} rev/s' "
                f"(= {_format_float(per_s)} Hz of rotation), "
                f"'{_format_float(60 * per_s)} rpm' or "
                f"'{_format_float(2 * math.pi * per_s)} rad/s'"
            )
        if want == Dim():
            raise UnitError(
                f"'{shown}' is {noun_for_dim(d)}, but a dimensionless number (no unit) "
                "is needed here"
            )
        raise UnitError(
            f"'{shown}' is {noun_for_dim(d)}, but {noun_for_kind(kind)} is needed here "
            f"(e.g. {KIND_EXAMPLES[kind]})"
        )
    return to_float(number * q, p, shown)


@lru_cache(maxsize=256)
def _exact_unit(unit: str) -> tuple[Fraction, int, int | None]:
    """(q, p) of ``unit`` (:func:`parse_unit_exact`), and k when it is exactly 10^k."""
    q, p, _ = parse_unit_exact(unit)
    k = len(str(q.numerator)) - 1 if q.denominator == 1 else 1 - len(str(q.denominator))
    return q, p, k if p == 0 and q == Fraction(10) ** k else None


def bare_to_si(x: float, unit: str) -> float:
    """A bare number ``x`` in ``unit`` (a body's, :func:`unit_for_kind`) in SI: the same bits
    as the text ``f"{x!r} {unit}"`` read by :func:`to_si` (the one route: the decimal that
    prints ``x``, times the unit's exact factor, rounded once). A unit of 10^k (mm, g, km)
    moves the decimal point of that text, which float() rounds once: the same bits, without
    Fractions (bench/batch.py's goal; tests/test_units_route.py checks the two agree)."""
    if not unit or not math.isfinite(x):
        return x * (parse_unit(unit)[0] if unit else 1.0)
    q, p, k = _exact_unit(unit)
    if k == 0:
        return x
    if k is not None:  # (+ 0.0: the text route's -0.0 is 0.0)
        digits, _, exponent = repr(float(x)).partition("e")
        return float(f"{digits}e{int(exponent or 0) + k}") + 0.0
    try:
        return to_float(Fraction(repr(float(x))) * q, p)
    except UnitError:  # beyond a float: the caller's range check says so
        return math.copysign(math.inf, x)


def unit_for_kind(base_units: dict[str, str], kind: str) -> tuple[float, str]:
    """:func:`_unit_for_kind`, remembered for units blocks of text (a batch of body files
    parses the same block over and over: bench/batch.py's goal needs it)."""
    if all(isinstance(v, str) for v in base_units.values()):
        return _remembered(tuple(base_units.items()), kind)
    return _unit_for_kind(base_units, kind)


@lru_cache(maxsize=256)
def _remembered(items: tuple[tuple[str, str], ...], kind: str) -> tuple[float, str]:
    return _unit_for_kind(dict(items), kind)


def _unit_for_kind(base_units: dict[str, str], kind: str) -> tuple[float, str]:
    """What a bare number of ``kind`` means in a body file with ``units:`` block ``base_units``
    (length, mass, time, angle, angular_speed; default m, kg, s, deg, rad/s): (the factor to
    SI, the unit's text, ``""`` for dimensionless).

    The kind's dimension is built from the base units (density with ``{length: mm, mass: g}`` is
    g/mm^3); a bare angular speed is in ``angular_speed`` when given, else rad/s, whatever the
    angle and time units (SPEC §1). UnitError for an unknown key or unit, or one of the wrong
    dimension; ValueError for an unknown kind."""
    if kind not in KINDS:
        raise ValueError(f"unknown kind {kind!r}; kinds are: {', '.join(KINDS)}")
    speed = base_units.get("angular_speed")
    if speed is not None:
        if not isinstance(speed, str):
            raise UnitError(f"units: angular_speed must be a unit name such as 'rpm', not {speed!r}")
        try:
            check_text(speed, "a unit")
            q, p, d = parse_unit_exact(speed.strip(), whole=speed)
        except UnitError as exc:
            raise UnitError(f"units: angular_speed: {exc}") from None
        if d != KINDS["angular_speed"]:
            raise UnitError(
                f"units: angular_speed is '{speed}', which is {noun_for_dim(d)}, "
                f"not {noun_for_kind('angular_speed')} (e.g. {KIND_EXAMPLES['angular_speed']})"
            )
        if kind == "angular_speed":
            return to_float(q, p), canonical_unit(speed)
        base_units = {k: v for k, v in base_units.items() if k != "angular_speed"}
    if kind == "angular_speed":
        return 1.0, "rad/s"
    exact: dict[str, tuple[Fraction, int]] = {}
    texts: dict[str, str] = {}
    for key, default in BASE_DEFAULTS.items():
        exact[BASE_KEYS[key]] = (Fraction(1), 0)
        texts[BASE_KEYS[key]] = default
    for key, value in base_units.items():
        if key not in BASE_KEYS:
            raise UnitError(
                f"unknown key '{key}' in units; allowed: {', '.join(BASE_KEYS)}, angular_speed"
            )
        if not isinstance(value, str):
            raise UnitError(
                f"units: {key} must be a unit name such as '{BASE_DEFAULTS[key]}', "
                f"not {value!r}"
            )
    for key, default in BASE_DEFAULTS.items():
        text = base_units.get(key, default)
        want = KINDS[key]
        try:
            check_text(text, "a unit")
            q, p, d = parse_unit_exact(text.strip(), whole=text)
        except UnitError as exc:
            raise UnitError(f"units: {key}: {exc}") from None
        if d != want:
            raise UnitError(
                f"units: {key} is '{text}', which is {noun_for_dim(d)}, "
                f"not {noun_for_kind(key)} (e.g. {KIND_EXAMPLES[key]})"
            )
        exact[BASE_KEYS[key]] = (q, p)
        texts[BASE_KEYS[key]] = canonical_unit(text)
    dim = KINDS[kind]
    q, p = Fraction(1), 0
    for attr, _word in DIM_ORDER:
        e = getattr(dim, attr)
        if e:
            bq, bp = exact[attr]
            q *= bq**e
            p += bp * e
    return to_float(q, p), compose(texts, dim)
