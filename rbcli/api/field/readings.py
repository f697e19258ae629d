"""Readings ``amplitude [unit] [measure]@phase`` — bare (one relative scale) or converted
exactly to SI: displacement (µm, mm, mil, m), velocity (mm/s, in/s, m/s), acceleration (g =
standard gravity, m/s²); measure pk, pk-pk, rms (or peak, 0-pk, p-p, pp) — and trial masses
``mass@angle`` (bare: grams; there g is the gram). Messages name parameters as ``{param}``.
"""

from __future__ import annotations

import cmath
import math
import re
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from rbcli.api import options as op
from rbcli.core.field.severity import convert_measure
from rbcli.errors import InputError, Location, ParamError, literal, spell
from rbcli.io import units as un
from rbcli.io.reader import limit_from_env

__all__ = ["Reading", "reading", "split_measure", "amplitude", "trial_mass", "readings", "one_kind", "at", "read_at", "Measures",
    "common_measure", "budget", "READING_KINDS", "READING_UNITS", "MEASURE_WORDS", "JOB_WORDS"]

#: what a reading's unit may measure -> its kind; readings are converted to SI
READING_KINDS = {"displacement": (1, 0), "velocity": (1, -1), "acceleration": (1, -2)}
#: the units a reading may carry, for messages and help
READING_UNITS = "displacement µm, mm, mil; velocity mm/s, in/s; acceleration g, m/s²"
#: how a reading may say its measure -> the measure
MEASURE_WORDS = {"pk": "pk", "peak": "pk", "0-pk": "pk", "0-p": "pk", "pk-pk": "pk-pk", "p-p": "pk-pk",
                 "pp": "pk-pk", "peak-peak": "pk-pk", "peak-to-peak": "pk-pk", "rms": "rms"}

_READING = re.compile(r"\s*(?P<num>[^@]+?)\s*@\s*(?P<ang>.+?)\s*")


@dataclass(frozen=True)
class Reading:
    """One reading as read: ``value`` amplitude e^{i phase} (SI of ``kind``, or the bare
    number when ``kind`` is None) in its own ``measure`` (or None); ``gravity``: its unit was
    ``g``; the parameter it was given for, its text, its place in a job file."""

    value: complex
    kind: str | None
    measure: str | None
    gravity: bool
    param: str
    text: str
    where: Location | None = None


def split_measure(amp: str) -> tuple[str, str | None]:
    """``"6 mm/s rms"`` -> ``("6 mm/s", "rms")``; no measure word -> ``(amp, None)``."""
    parts = amp.rsplit(None, 1)
    if len(parts) == 2 and parts[1].lower() in MEASURE_WORDS:
        return parts[0], MEASURE_WORDS[parts[1].lower()]
    if len(parts) == 1:  # "6rms": a number glued to the word
        m = op.NUMBER.match(amp)
        if m and amp[m.end():].strip().lower() in MEASURE_WORDS:
            return amp[: m.end()], MEASURE_WORDS[amp[m.end():].strip().lower()]
    return amp, None


def amplitude(text: str, param: str, whole: str) -> tuple[float, str | None, bool]:
    """A reading's amplitude: (value, kind, read g as gravity) - SI for a unit of
    vibration, the number for a bare one (kind None)."""
    num = op.NUMBER.match(text)
    lit = literal(whole)
    if not num:
        raise ParamError(param, f"'{lit}': the amplitude must be a number, optionally with a unit "
                                f"({READING_UNITS})")
    number = text[: num.end()].strip().replace("\u2212", "-")
    unit = text[num.end():].strip()
    try:
        if not unit:
            return op.quantity(number, "dimensionless", param), None, False
        if unit in ("mil", "mils"):
            op.quantity(number, "dimensionless", param)  # its checks (range, digits)
            return float(Fraction(number) * Fraction(254, 10**7)), "displacement", False
        if unit == "g":
            return un.to_si(f"{number} g0", "acceleration"), "acceleration", True
        value, dim = un.parse_quantity(f"{number} {unit}")
    except un.UnitError as exc:
        raise ParamError(param, f"'{lit}': {literal(exc)}") from None
    for kind, (L, T) in READING_KINDS.items():
        if dim == un.Dim(L=L, T=T):
            return value, kind, False
    raise ParamError(param, f"'{lit}': '{literal(unit)}' is {dim.describe()}, not a vibration reading; "
                            f"give {READING_UNITS}, or bare numbers for all readings (a relative scale)")


def reading(text: str, param: str, where: Location | None = None) -> Reading:
    """``'6.0@30'``, ``'6 mm@30'``, ``'4.0 in/s pk@110'`` -> a :class:`Reading`; a
    :class:`rbcli.ParamError` naming ``param``."""
    m = _READING.fullmatch(text)
    lit = literal(text)
    if not m:
        raise ParamError(param, f"'{lit}' is not amplitude@phase, e.g. '6.0@30' or '6 mm/s@30'")
    amp_text, measure = split_measure(m["num"])
    amp, kind, gravity = amplitude(amp_text, param, text)
    ang = math.degrees(op.quantity(m["ang"], "angle", param, bare="deg"))
    _check(amp, ang, param, lit, "amplitude")
    return Reading(complex(cmath.rect(amp, math.radians(ang))), kind, measure, gravity, param, text, where)


def _check(amp: float, ang: float, param: str, lit: str, what: str) -> None:
    """An amplitude 0 or from 1e-100 to 1e100 (SI; bare readings alike) and a finite angle:
    nothing a balancing job measures lies beyond, and the solve stays within floats."""
    if not (math.isfinite(ang) and (amp == 0.0 or 1e-100 <= amp <= 1e100)):
        raise ParamError(param, f"'{lit}': the {what} must be {'0 or ' * (what == 'amplitude')}from 1e-100 to "
                                "1e100 (SI) and the angle finite")


def trial_mass(text: str, param: str = "trial", bare: str = "g") -> complex:
    """``'10 g@0'`` or ``'10@0'`` (a bare mass in ``bare``) -> kg e^{i angle}."""
    m = _READING.fullmatch(text)
    lit = literal(text)
    if not m:
        raise ParamError(param, f"'{lit}' is not mass@angle, e.g. '10 g@0' (a bare mass is grams)")
    with op.naming(param):
        amp = op.quantity(m["num"], "mass", param, bare=bare)
        ang = math.degrees(op.quantity(m["ang"], "angle", param, bare="deg"))
    _check(amp, ang, param, lit, "mass")
    value = complex(cmath.rect(amp, math.radians(ang)))
    if value == 0:
        raise ParamError(param, "the trial mass must not be zero")
    return value


def readings(text: str, param: str, n: int | None, *, what: str = "") -> list[Reading]:
    """Comma-separated readings, ``n`` of them (None: any number)."""
    parts = text.split(",")
    if n is not None and len(parts) != n:
        raise ParamError(param, f"expected {n} reading{'s' if n > 1 else ''} ({what}), got "
                                f"{len(parts)} in '{literal(text)}'")
    with op.naming(param):
        return [reading(p, param) for p in parts]


def one_kind(rs: list[Reading]) -> str | None:
    """The one kind every reading has (None: all bare); else refused, saying what was found."""
    first = rs[0]
    for r in rs[1:]:
        if (r.kind is None) != (first.kind is None):
            b, u = (r, first) if r.kind is None else (first, r)
            raise at(r.where, ParamError(r.param, (
                f"'{literal(b.text)}' ({{{b.param}}}) is a bare number but '{literal(u.text)}' "
                f"({{{u.param}}}) has a unit ({u.kind}): give every reading a unit of one kind "
                f"({READING_UNITS}) or none (all bare: a relative scale)")))
        if r.kind != first.kind:
            raise at(r.where, ParamError(r.param, (
                f"'{literal(r.text)}' ({{{r.param}}}) is a {r.kind} but '{literal(first.text)}' "
                f"({{{first.param}}}) is a {first.kind}: every reading must be of one kind "
                f"({READING_UNITS})")))
    return first.kind


#: how a message about a job file's reading names what the command line calls a parameter
JOB_WORDS = {"initial": "initial", "run": "a trial run", "measure": "readings: measure",
             "trial": "a trial mass"}


def read_at(item: Any, fn: Any) -> Any:
    """``fn(text)`` of a parameter's item, or of a job file's located Text (errors located
    there)."""
    try:
        return fn(getattr(item, "text", item))
    except InputError as exc:
        raise at(getattr(item, "where", None), exc) from None


def at(where: Location | None, exc: InputError) -> InputError:
    """``exc`` about a value of a job file: its reason, located at ``where`` (parameters
    spelled as the job file's words); ``exc`` itself when ``where`` is None."""
    if where is None:
        return exc
    words = lambda p: JOB_WORDS.get(p, p)  # noqa: E731
    if isinstance(exc, ParamError):
        text = f"{words(exc.param)}: {spell(exc.reason, words)}"
    else:
        text = spell(exc.template, words)
    return InputError(literal(text), where)


#: the most influence coefficients (readings per run x planes) a job may have unless
#: RBCLI_MAX_FIELD_COEFFICIENTS says otherwise: the solve grows as readings x planes²
MAX_COEFFICIENTS = 20_000


def budget(n: int, p: int, where: Location | None) -> None:
    """Refuse a job beyond :data:`MAX_COEFFICIENTS` (README, "Budgets"), before reading it."""
    limit = limit_from_env("RBCLI_MAX_FIELD_COEFFICIENTS", MAX_COEFFICIENTS)
    if n * p > limit:
        raise InputError(f"the job has {n} readings per run x {p} planes = {n * p} influence coefficients, "
                         f"above the limit of {limit}; set RBCLI_MAX_FIELD_COEFFICIENTS to raise it (the "
                         "solve's time grows as readings x planes²)", where)


@dataclass(frozen=True)
class Measures:
    """The measure every amplitude is now in (None: unsaid) and the conversions made
    ((from, to, how many readings))."""

    measure: str | None
    converted: tuple[tuple[str, str, int], ...]


def common_measure(rs: list[Reading], default: str | None, want: str | None) -> tuple[list[complex], Measures]:
    """Every reading in one measure (a sinusoid: pk-pk = 2 pk, rms = pk/sqrt 2): ``want``
    (severity: "rms"), else the first reading's; ``default`` the measure of those that say
    none. A mix of readings with and without a measure and no default is refused."""
    stated = [r for r in rs if r.measure is not None]
    bare = [r for r in rs if r.measure is None]
    if stated and bare and default is None:
        s, b = stated[0], bare[0]
        raise at(b.where, ParamError("measure", (
            f"'{literal(s.text)}' ({{{s.param}}}) says {s.measure} but '{literal(b.text)}' "
            f"({{{b.param}}}) says no measure: say the measure (pk, pk-pk or rms) of every "
            "reading or of none, or give the measure of those that say none ({measure})")))
    each = [r.measure or default for r in rs]
    if all(m is None for m in each):
        return [r.value for r in rs], Measures(None, ())
    target = want or each[0]
    moved = [m for m in each if m != target]
    out = [r.value * convert_measure(1.0, m, target) if m != target else r.value for r, m in zip(rs, each)]
    return out, Measures(target, tuple((a, target, moved.count(a)) for a in dict.fromkeys(moved)))
