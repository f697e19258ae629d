"""Units in tables: the one place that turns SI numbers into the units people read (JSON
is SI):

- :class:`DisplayUnits` — the body file's ``units``, or ``--units mm,g`` (each base dimension
  one unit; any kind's unit composed from them, inertia in g·mm² for ``mm,g``), round-off as 0;
- :class:`ShopUnits` — the balance tables' shop units (g, mm, g·mm, µm) unless ``--units``;
- :class:`BodyUnits` — a body's bare units (its file's ``units``, :mod:`rbcli.io.bare`), in
  which the "options" table echoes the options as understood (:mod:`rbcli.render.echo`).

:data:`RPM` is the one rad/s → rev/min factor.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from rbcli.core.inertia import body_mass_props
from rbcli.core.scale import body_scale
from rbcli.errors import ParamError, literal, option_name
from rbcli.io import bare
from rbcli.io import units as un
from rbcli.render.fmt import ROUNDOFF, num

__all__ = ["RPM", "DisplayUnits", "ShopUnits", "BodyUnits"]

#: rad/s -> rev/min
RPM = 30.0 / math.pi
SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
#: named SI units for some kinds, used when the display units are SI
NAMED = {"force": "N", "energy": "J", "torque": "N·m"}
#: kinds shown in one unit whatever the display units
FIXED = {"angle_deg": (1.0, "°"), "angular_speed": (1.0, "rad/s"), "dimensionless": (1.0, "")}


class DisplayUnits:
    """Units that tables show; JSON is always SI.

    Each base dimension (length, mass, time) has one unit, as (factor from SI, name): the
    body file's ``units`` unless ``--units`` chose (``mm,g``; ``si``). ``scale`` (kg, m) is
    the body's mass and reach from the origin: a value of a kind made of mass and length that
    is at most :data:`ROUNDOFF` of that kind's scale shows as 0 (angles: of a turn)."""

    __slots__ = ("length", "mass", "time", "si", "chosen", "scale")

    def __init__(self, length: tuple[float, str] = (1.0, "m"), mass: tuple[float, str] = (1.0, "kg"),
                 time: tuple[float, str] = (1.0, "s"), chosen: bool = False,
                 scale: tuple[float, float] = (0.0, 0.0)) -> None:
        self.length, self.mass, self.time, self.chosen, self.scale = length, mass, time, chosen, scale
        self.si = (length[1], mass[1], time[1]) == ("m", "kg", "s")

    @classmethod
    def parse(cls, spec: str | None) -> "DisplayUnits":
        """``--units``: None (the body's), ``si``, or one unit per base dimension (``mm,g``)."""
        if spec is None:
            return cls()
        names = [name.strip() for name in spec.split(",")]
        if [name.lower() for name in names] == ["si"]:
            return cls(chosen=True)
        bases: dict[str, tuple[float, str]] = {}
        for name in names:
            if name.lower() in ("", "si"):
                why = "si stands alone" if name else f"an empty item in '{literal(spec)}'" \
                    if spec.strip() else "an empty value"
                raise ParamError("units", f"{why}: give e.g. {{units}} mm,g or {{units}} si")
            try:
                factor, dim = un.parse_unit(name)
            except un.UnitError as exc:
                raise ParamError("units", literal(exc)) from None
            base = {un.Dim(L=1): "length", un.Dim(M=1): "mass", un.Dim(T=1): "time"}.get(dim)
            if base is None:
                raise ParamError("units", f"'{literal(name)}' is not a length, mass or time unit "
                                 "(give e.g. {units} mm,g or {units} in,lb, or {units} si)")
            if base in bases:
                raise ParamError("units", f"two {base} units, '{literal(bases[base][1])}' and "
                                 f"'{literal(name)}': give one of each kind")
            bases[base] = (factor, name)
        return cls(**bases, chosen=True)

    def of(self, body: Any, scale: tuple[float, float] | None = None) -> "DisplayUnits":
        """These units for ``body`` (a Body, or a body's ``units`` mapping): its file's units
        unless chosen, and ``scale`` (kg, m; a Body's by default) for round-off."""
        units = getattr(body, "units", body) or {}
        bases = {} if self.chosen else {
            b: (un.parse_unit(units[b])[0], un.canonical_unit(units[b])) for b in ("length", "mass", "time") if b in units}
        if scale is None and getattr(body, "parts", None):
            box = body_scale(body.parts)
            scale = (body_mass_props(body).mass, float(np.max(np.abs([box.low, box.high]))))
        kept = {"length": self.length, "mass": self.mass, "time": self.time}
        return DisplayUnits(**(kept if self.chosen else bases), chosen=self.chosen, scale=scale or self.scale)

    def zero(self, x: float, kind: str) -> bool:
        """Whether ``x`` (SI) is round-off: at most :data:`ROUNDOFF` of its kind's scale."""
        if kind in ("angle_deg", "angle"):
            return abs(x) <= ROUNDOFF * (360.0 if kind == "angle_deg" else 2 * math.pi)
        dim = un.KINDS.get(kind)
        if dim is None or dim.T or dim.A or not (dim.M or dim.L) or not all(self.scale):
            return False
        return abs(x) <= ROUNDOFF * self.scale[0] ** dim.M * self.scale[1] ** dim.L

    def factor(self, kind: str) -> tuple[float, str]:
        """(multiplier from SI to the display unit, the unit's label) for a kind."""
        if kind in FIXED:
            return FIXED[kind]
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
        """``x`` (SI) in this unit of ``kind``: "—" for None, "0" for round-off."""
        if x is None:
            return "—"
        return "0" if self.zero(float(x), kind) else num(x * self.factor(kind)[0], digits)

    def unit(self, kind: str) -> str:
        return self.factor(kind)[1]


class ShopUnits:
    """Display units of the balance tables (JSON is always SI): ``--units``' length and
    mass, else the body file's where they are not metric (in, lb, oz), else mm and g;
    eccentricity in that length, else µm; the rotor's mass in that mass, else kg."""

    def __init__(self, spec: str | None, body: Any = None) -> None:
        du = DisplayUnits.parse(spec)
        units = getattr(body, "units", None) or {}
        given = {b: (f, un.canonical_unit(units[b])) for b in ("length", "mass") if b in units
                 and not math.log10(f := un.parse_unit(units[b])[0]).is_integer()}
        if du.chosen:
            given = {"length": du.length, "mass": du.mass}
        self.spec, self.length, self.mass = spec, given.get("length", (1e-3, "mm")), given.get("mass", (1e-3, "g"))
        self.rotor, self.ecc = given.get("mass", (1.0, "kg")), given.get("length", (1e-6, "µm"))
        m, L = self.mass[1], self.length[1]
        self._kinds: dict[str, tuple[float, str]] = {
            "length": self.length, "mass": self.mass, "rotor_mass": self.rotor, "eccentricity": self.ecc,
            "unbalance": (self.mass[0] * self.length[0], f"{m}·{L}"),
            "couple": (self.mass[0] * self.length[0] ** 2, f"{m}·{L}²"),
            "force": (1.0, "N"), "torque": (1.0, "N·m"), "angular_momentum": (1.0, "kg·m²/s"),
            "grade": (1e-3, "mm/s"), "acceleration": (1.0, "m/s²"),
        }

    def of(self, body: Any) -> "ShopUnits":
        """These shop units for ``body`` (its file's units where they are not metric)."""
        return ShopUnits(self.spec, body)

    def unit(self, kind: str) -> str:
        return self._kinds[kind][1]

    def factor(self, kind: str) -> float:
        """SI per display unit of ``kind``."""
        return self._kinds[kind][0]

    def show(self, x: float | None, kind: str, digits: int) -> str:
        return "—" if x is None else num(float(x) / self._kinds[kind][0], digits)


class BodyUnits:
    """A body's bare units (:mod:`rbcli.io.bare`): how the "options" table shows a value
    given for it — the number as understood, in the unit a bare number would have meant."""

    __slots__ = ("base",)

    def __init__(self, base: Mapping[str, str] | None = None) -> None:
        self.base = dict(base or {})

    def label(self, kind: str) -> str:
        return bare.label(self.base, kind)

    def show(self, si: Any, kind: str, unit: tuple[float, str] | None = None) -> str:
        """An SI value (or a sequence) as numbers in the bare unit of ``kind`` (or in
        ``unit``, (SI per unit, name)), 6 digits."""
        f = unit[0] if unit else bare.factor(self.base, kind)
        vals = si.tolist() if hasattr(si, "tolist") else si
        if isinstance(vals, (list, tuple)):
            return ", ".join(num(float(x) / f) for x in vals)
        return num(float(vals) / f)

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
            value += f" ({', '.join(num(v / per) for v in vals)} {other})"
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
