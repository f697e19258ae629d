"""Constants, checks and angle helpers shared by the balancing modules (sheet §2.1).

Angles: the internal ('with rotation') angle of a complex quantity ``x + i y`` in the
shaft frame is ``arg``; ``angle_sense="against"`` reports ``360 - angle``. Every reported
angle is in [0, 360), never -0.0, and 0.0 with a false flag when the quantity is zero to
its tolerance (:func:`angle_of`).
"""

from __future__ import annotations

import cmath
import math

import numpy as np

STANDARD_GRAVITY = 9.80665
"""m/s^2, the default g (SPEC §2)."""

BALANCE_RTOL = 1e-9
"""Relative tolerance of the ideal (geometric) balanced verdicts; see :func:`unbalance`."""

TILT_GAP_RTOL = 1e-6
"""Principal moments closer than this (relative to the largest) make the tilt ill-defined."""

FRAME_SWITCH_COS = 0.9
"""Body x is the reference mark unless |cos(shaft, body x)| exceeds this; then body y."""

NARROW_PLANE_FRACTION = 0.2
"""Correction planes closer than this fraction of the reference length are 'narrow' (sheet §7.9)."""

LARGE_CORRECTION_FRACTION = 0.1
"""Warn when the two-plane correction masses add up to more than this fraction of the rotor mass."""

ISO_GRADE_MIN = 0.4
ISO_GRADE_MAX = 4000.0
"""mm/s, the range of ISO 21940-11 balance quality grades (sheet §1.3)."""

ISO_CLAMP = (0.3, 0.7)
"""Inboard allocation limits, fractions of U_per (sheet §1.4a)."""

ISO_OUTBOARD_FLOOR = 0.3
"""Floor of the far share for outboard rotors, fraction of U_per (sheet §1.4c; rbcli's rule)."""

FIELD_COND_WARN = 50.0
"""Warn when the 2-norm condition number of the influence matrix exceeds this (sheet §7.10)."""

SMALL_RESPONSE_AMPLITUDE = 0.25
SMALL_RESPONSE_PHASE_DEG = 25.0
"""A trial run is 'small' unless the amplitude changed by >= 25 % or the phase by >= 25 deg."""

ANGLE_SENSES = ("with", "against")


class BalanceValueError(ValueError):
    """A value a balancing function cannot use, naming the parameter at fault.

    Attributes
    ----------
    param : str — the name of the function's parameter (``"planes"``, ``"reference"``,
        ``"n_positions"``, ...) or of the rotor's own data (``"mass"``, ``"com"``), so a
        caller maps it to its own option without reading the message
    """

    def __init__(self, param: str, message: str) -> None:
        super().__init__(message)
        self.param = param


# --- small helpers


def vec3(v: object, name: str, param: str | None = None) -> np.ndarray:
    """A finite 3-vector; else BalanceValueError naming ``param`` (default ``name``)."""
    a = np.asarray(v, dtype=float)
    if a.shape != (3,):
        raise BalanceValueError(param or name, f"{name} must be a 3-vector, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise BalanceValueError(param or name, f"{name} must be finite")
    return a


def finite(x: object, name: str, param: str | None = None) -> float:
    """A finite float; else BalanceValueError naming ``param`` (default ``name``)."""
    try:
        v = float(x)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise BalanceValueError(param or name, f"{name} must be a number") from None
    if not math.isfinite(v):
        raise BalanceValueError(param or name, f"{name} must be finite")
    return v


def positive(x: object, name: str, param: str | None = None) -> float:
    """A positive finite float; else BalanceValueError naming ``param`` (default ``name``)."""
    v = finite(x, name, param)
    if v <= 0.0:
        raise BalanceValueError(param or name, f"{name} must be positive, got {v:g}")
    return v


def pair(v: object, name: str, param: str | None = None) -> tuple[float, float]:
    """Two finite floats; else BalanceValueError naming ``param`` (default ``name``)."""
    if np.ndim(v) == 0:  # type: ignore[arg-type]
        raise BalanceValueError(param or name, f"{name} must be two numbers")
    seq = list(v)  # type: ignore[call-overload]
    if len(seq) != 2:
        raise BalanceValueError(param or name, f"{name} must be two numbers, got {len(seq)}")
    return finite(seq[0], name, param), finite(seq[1], name, param)


def check_sense(angle_sense: str) -> str:
    """``angle_sense`` if it is "with" or "against"."""
    if angle_sense not in ANGLE_SENSES:
        raise BalanceValueError("angle_sense", f"angle_sense must be 'with' or 'against', got {angle_sense!r}")
    return angle_sense


def wrap_deg(a: float) -> float:
    """Angle in [0, 360); within 1e-9 deg below 360 counts as 0."""
    a = math.fmod(a, 360.0)
    if a < 0.0:
        a += 360.0
    if a >= 360.0 - 1e-9:  # -1e-17 + 360 rounds to 360; 359.9999999999999 would print as 360
        a = 0.0
    return a + 0.0  # no -0.0


def report_deg(phi_deg: float, sense: str) -> float:
    """Internal ('with' rotation) angle -> reported angle in [0, 360)."""
    return wrap_deg(-phi_deg if sense == "against" else phi_deg)


def internal_deg(reported_deg: float, sense: str) -> float:
    """Reported angle -> internal ('with' rotation) angle in [0, 360)."""
    return report_deg(reported_deg, sense)  # the map is its own inverse


def angle_of(z: complex, tol: float, sense: str = "with") -> tuple[float, bool]:
    """Reported angle (deg, [0, 360)) of a complex number and whether it is defined.

    ``|z| <= tol`` -> ``(0.0, False)``: the angle of a zero (to tolerance) quantity is
    undefined and reported as 0.0 with a false flag (never NaN).
    """
    if not abs(z) > tol:
        return 0.0, False
    return report_deg(math.degrees(cmath.phase(z)), sense), True


def readonly(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


def phasor(amplitude: float, phase_deg: float) -> complex:
    """Complex number ``amplitude * exp(i * phase)``.

    Parameters
    ----------
    amplitude : float — any unit (g, µm, mm/s, ...)
    phase_deg : float — degrees

    Returns
    -------
    complex
    """
    return complex(cmath.rect(float(amplitude), math.radians(float(phase_deg))))
