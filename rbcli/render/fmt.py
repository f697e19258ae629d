"""Numbers and units as people read them: significant figures and display units."""

from __future__ import annotations

import math
from rbcli.errors import InputError
from rbcli.io import units as un

SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
#: named SI units for some kinds, used when the display units are SI
NAMED = {"force": "N", "energy": "J", "torque": "N·m"}


def num(x: float | None, digits: int = 6) -> str:
    """``x`` to ``digits`` significant figures; "—" for None; no "-0"."""
    if x is None:
        return "—"
    x = float(x)
    if not math.isfinite(x):
        return str(x)
    s = f"{x:.{digits}g}"
    if s.startswith("-") and float(s) == 0.0:
        s = s[1:]
    return s


def vec(v, digits: int = 6) -> str:
    return "[" + ", ".join(num(x, digits) for x in v) + "]"


def snap(values, scale: float | None = None, rtol: float = 1e-14):
    """Entries below ``rtol`` times the largest magnitude (round-off) become exactly 0."""
    import numpy as np

    a = np.array(values, dtype=float)
    s = float(np.max(np.abs(a))) if scale is None else scale
    a[np.abs(a) <= rtol * s] = 0.0
    a[a == 0.0] = 0.0  # no negative zeros
    return a


class DisplayUnits:
    """Units that tables show (``--units mm,g``); JSON is always SI.

    Each base dimension (length, mass, time) may be given one unit, as (factor from SI, name);
    the unit of any quantity kind is composed from them (inertia in ``g·mm²`` for ``mm,g``).
    (A plain class, not a dataclass: it sits on every command's start-up path.)
    """

    __slots__ = ("length", "mass", "time", "si", "_cache")

    def __init__(self, length: tuple[float, str] = (1.0, "m"), mass: tuple[float, str] = (1.0, "kg"),
                 time: tuple[float, str] = (1.0, "s"), si: bool = True) -> None:
        self.length = length
        self.mass = mass
        self.time = time
        self.si = si
        self._cache: dict = {}

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
                raise InputError(f"--units: {exc}") from None
            for base, d in (("length", un.Dim(L=1)), ("mass", un.Dim(M=1)), ("time", un.Dim(T=1))):
                if dim == d:
                    setattr(out, base, (factor, name))
                    break
            else:
                raise InputError(
                    f"--units: '{name}' is not a length, mass or time unit "
                    "(give e.g. --units mm,g or --units in,lb)"
                )
        out.si = out.length[1] == "m" and out.mass[1] == "kg" and out.time[1] == "s"
        return out

    def factor(self, kind: str) -> tuple[float, str]:
        """(multiplier from SI to the display unit, the unit's label) for a kind."""
        if kind in self._cache:
            return self._cache[kind]
        if kind in ("angle_deg",):
            res = (1.0, "°")
        elif kind == "angular_speed":
            res = (1.0, "rad/s")
        elif kind == "dimensionless":
            res = (1.0, "")
        else:
            dim = un.KINDS[kind]
            if self.si and kind in NAMED:
                res = (1.0, NAMED[kind])
            else:
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
                res = (f, label)
        self._cache[kind] = res
        return res

    def show(self, x: float | None, kind: str, digits: int) -> str:
        if x is None:
            return "—"
        f, _ = self.factor(kind)
        return num(x * f, digits)

    def unit(self, kind: str) -> str:
        return self.factor(kind)[1]
