"""Numbers as people read them: significant figures, no "-0" (units: :mod:`rbcli.render.units`)."""

from __future__ import annotations

import math

import numpy as np

from rbcli.errors import option_name, spelled


#: a value at most this fraction of its scale is round-off, printed 0 (README, "Round-off")
ROUNDOFF = 1e-12


def num(x: float | None, digits: int = 6, scale: float = 0.0) -> str:
    """``x`` to ``digits`` significant figures; "—" for None; "0" for round-off (``|x| <=
    ROUNDOFF * scale``); no "-0"."""
    if x is None:
        return "—"
    x = float(x)
    if not math.isfinite(x) or abs(x) <= ROUNDOFF * scale:
        return str(x) if not math.isfinite(x) else "0"
    s = f"{x:.{digits}g}"
    if s.startswith("-") and float(s) == 0.0:
        s = s[1:]
    return s


def polar(amplitude: float, angle_deg: float, digits: int = 6, scale: float = 0.0) -> tuple[str, str]:
    """A vector's amplitude and angle as printed: round-off is 0, with no angle ("—")."""
    shown = num(amplitude, digits, scale)
    return shown, "—" if shown == "0" else num(angle_deg, digits)


def vec(v, digits: int = 6) -> str:
    return "[" + ", ".join(num(x, digits) for x in v) + "]"


def snap(values, scale: float | None = None, rtol: float = 1e-14):
    """Entries below ``rtol`` times the largest magnitude (round-off) become exactly 0."""
    a = np.array(values, dtype=float)
    s = float(np.max(np.abs(a))) if scale is None else scale
    a[np.abs(a) <= rtol * s] = 0.0
    a[a == 0.0] = 0.0  # no negative zeros
    return a


def said(text: str) -> str:
    """A result's text (a :class:`rbcli.errors.Note`) as documents say it: parameters
    spelled as the command line's options (``--radius``); other text as it is."""
    return spelled(text, option_name)
