"""Units in tables: the one place that turns SI numbers into the units people read.

JSON is always SI; tables show

- :class:`DisplayUnits` — ``--units mm,g`` (each base dimension one unit; any kind's unit
  composed from them, inertia in g·mm² for ``mm,g``); SI by default;
- :class:`ShopUnits` — the balance tables' shop units (g, mm, g·mm, µm) unless ``--units``;
- :class:`BodyUnits` — a body's bare units (its file's ``units``, :mod:`rbcli.io.bare`), in
  which the "options" table echoes the options as understood
  (:func:`rbcli.render.echo.echo_rows`).

:data:`RPM` is the one rad/s → rev/min factor.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from rbcli.errors import ParamError, literal, option_name
from rbcli.io import bare
from rbcli.io import units as un
from rbcli.render.fmt import num

__all__ = ["RPM", "DisplayUnits", "ShopUnits", "BodyUnits"]

#: rad/s -> rev/min
RPM = 30.0 / math.pi
SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
#: named SI units for some kinds, used when the display units are SI
NAMED = {"force": "N", "energy": "J", "torque": "N·m"}


class DisplayUnits:
    """Units that tables show (``--units mm,g``); JSON is always SI.

    Each base dimension (length, mass, time) may be given one unit, as (factor from SI, name);
    the unit of any quantity kind is composed from them (inertia in ``g·mm²`` for ``mm,g``).
    (A plain class, not a dataclass: it sits on every command's start-up path.)
    """

    __slots__ = ("length", "mass", "time", "si")

    def __init__(self, length: tuple[float, str] = (1.0, "m"), mass: tuple[float, str] = (1.0, "kg"),
                 time: tuple[float, str] = (1.0, "s"), si: bool = True) -> None:
        self.length = length
        self.mass = mass
        self.time = time
        self.si = si

    def __repr__(self) -> str:
        return f"DisplayUnits(length={self.length!r}, mass={self.mass!r}, time={self.time!r}, si={self.si!r})"

    @classmethod
    def parse(cls, spec: str | None) -> "DisplayUnits":
        out = cls()
        if not spec:
            return out
        for raw in spec.split(","):
            name = raw.strip()
            if not name:
                continue
            try:
                factor, dim = un.parse_unit(name)
            except un.UnitError as exc:
                raise ParamError("units", literal(exc)) from None
            for base, d in (("length", un.Dim(L=1)), ("mass", un.Dim(M=1)), ("time", un.Dim(T=1))):
                if dim == d:
                    setattr(out, base, (factor, name))
                    break
            else:
                raise ParamError(
                    "units", f"'{literal(name)}' is not a length, mass or time unit "
                    "(give e.g. {units} mm,g or {units} in,lb)")
        out.si = out.length[1] == "m" and out.mass[1] == "kg" and out.time[1] == "s"
        return out

    def factor(self, kind: str) -> tuple[float, str]:
        """(multiplier from SI to the display unit, the unit's label) for a kind."""
        if kind == "angle_deg":
            return (1.0, "°")
        if kind == "angular_speed":
            return (1.0, "rad/s")
        if kind == "dimensionless":
            return (1.0, "")
        if self.si and kind in NAMED:
            return (1.0, NAMED[kind])
        dim = un.KINDS[kind]
        f = 1.0
        top, bottom = [], []
        for (factor, name), e in ((self.mass, dim.M), (self.length, dim.L), (self.time, dim.T)):
            if e == 0:
                continue
            f /= factor**e
            label = name + (str(abs(e)).translate(SUPERSCRIPT) if abs(e) != 1 else "")
            (top if e > 0 else bottom).append(label)
        label = "·".join(top) or "1"
        if bottom:
            label += "/" + "/".join(bottom) if len(bottom) == 1 else "/(" + "·".join(bottom) + ")"
        return (f, label)

    def show(self, x: float | None, kind: str, digits: int) -> str:
        if x is None:
            return "—"
        f, _ = self.factor(kind)
        return num(x * f, digits)

    def unit(self, kind: str) -> str:
        return self.factor(kind)[1]


class ShopUnits:
    """Display units of the balance tables (JSON is always SI)."""

    def __init__(self, spec: str | None) -> None:
        if not spec:
            self.length = (1e-3, "mm")
            self.mass = (1e-3, "g")
            self.rotor = (1.0, "kg")
            self.ecc = (1e-6, "µm")
        else:
            du = DisplayUnits.parse(spec)
            self.length = du.length
            self.mass = du.mass
            self.rotor = du.mass
            self.ecc = du.length
        m, L = self.mass[1], self.length[1]
        self._kinds: dict[str, tuple[float, str]] = {
            "length": self.length,
            "mass": self.mass,
            "rotor_mass": self.rotor,
            "eccentricity": self.ecc,
            "unbalance": (self.mass[0] * self.length[0], f"{m}·{L}"),
            "couple": (self.mass[0] * self.length[0] ** 2, f"{m}·{L}²"),
            "force": (1.0, "N"),
            "torque": (1.0, "N·m"),
            "angular_momentum": (1.0, "kg·m²/s"),
            "grade": (1e-3, "mm/s"),
            "acceleration": (1.0, "m/s²"),
        }

    def unit(self, kind: str) -> str:
        return self._kinds[kind][1]

    def factor(self, kind: str) -> float:
        """SI per display unit of ``kind``."""
        return self._kinds[kind][0]

    def show(self, x: float | None, kind: str, digits: int) -> str:
        if x is None:
            return "—"
        return num(float(x) / self._kinds[kind][0], digits)


def _g(x: float) -> str:
    text = f"{x:.6g}"
    return "0" if text == "-0" else text


class BodyUnits:
    """A body's bare units (:mod:`rbcli.io.bare`): how the "options" table shows a value
    given for it — the number as understood, in the unit a bare number would have meant."""

    __slots__ = ("base",)

    def __init__(self, base: Mapping[str, str] | None = None) -> None:
        self.base = dict(base or {})

    @classmethod
    def of(cls, body: Any) -> "BodyUnits":
        return cls(getattr(body, "units", None) if body is not None else None)

    def label(self, kind: str) -> str:
        return bare.label(self.base, kind)

    def show(self, si: Any, kind: str, unit: tuple[float, str] | None = None) -> str:
        """An SI value (or a sequence) as numbers in the bare unit of ``kind`` (or in
        ``unit``, (SI per unit, name)), 6 digits."""
        f = unit[0] if unit else bare.factor(self.base, kind)
        vals = si.tolist() if hasattr(si, "tolist") else si
        if isinstance(vals, (list, tuple)):
            return ", ".join(_g(float(x) / f) for x in vals)
        return _g(float(vals) / f)

    def echo(self, param: str, si: Any, kind: str, typed: str | None = None) -> tuple[str, str, str]:
        """One row (option, value, unit) of the "options" table: the value in the unit the
        caller typed (``typed``, e.g. ``"g"`` for ``--mass-step "0.5 g"``), else in the bare
        unit of ``kind``; an angular speed also in rpm (or in rad/s when shown in rpm)."""
        shown = _typed(typed, kind)
        value, unit = self.show(si, kind, shown), shown[1] if shown else self.label(kind)
        if kind == "angular_speed":
            vals = si.tolist() if hasattr(si, "tolist") else si
            vals = [float(x) for x in vals] if isinstance(vals, (list, tuple)) else [float(vals)]
            other = "rad/s" if unit == "rpm" else "rpm"
            per = 1.0 if other == "rad/s" else 1.0 / RPM
            value += f" ({', '.join(_g(v / per) for v in vals)} {other})"
        return option_name(param), value, unit


def _typed(typed: str | None, kind: str) -> tuple[float, str] | None:
    """(SI per unit, its name) of the unit a caller typed for a value of ``kind``; None when
    nothing was typed or it is not a unit of ``kind`` (the value then shows in the bare unit)."""
    if not typed:
        return None
    try:
        return un.to_si(f"1 {typed}", kind), un.canonical_unit(typed)
    except un.UnitError:
        return None
