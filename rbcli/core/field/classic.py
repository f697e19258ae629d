"""Field (trial-weight) balancing by influence coefficients, one or two planes (sheet §5).

The one- and two-plane solves of ``rbcli field-balance`` as it always was (their outputs
are golden); any number of planes and readings is :mod:`rbcli.core.field.solve`,
which does the same arithmetic for these two cases.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from rbcli.core.balance.common import (
    FIELD_COND_WARN, SMALL_RESPONSE_AMPLITUDE, SMALL_RESPONSE_PHASE_DEG, BalanceValueError,
    angle_of,
)


def small_response(v0: complex, v1: complex) -> bool:
    """Whether a trial changed a reading too little to trust its influence coefficient.

    Rule of thumb (sheet §5.1; ACOEM, "Balancing How To #2 - Selecting a Proper Trial
    Weight", asks for 30 %): small unless the amplitude changed by >= 25 % or the phase by
    >= 25 deg."""
    a0, a1 = abs(v0), abs(v1)
    if a0 == 0.0:
        return a1 == 0.0
    amp = abs(a1 - a0) / a0
    if a1 == 0.0:
        return amp < SMALL_RESPONSE_AMPLITUDE
    dphi = abs(math.degrees(cmath.phase(v1 / v0)))
    return amp < SMALL_RESPONSE_AMPLITUDE and dphi < SMALL_RESPONSE_PHASE_DEG


@dataclass(frozen=True)
class FieldSinglePlane:
    """Single-plane influence-coefficient result (sheet §5.1).

    Attributes
    ----------
    influence : complex — H = (V1 - V0)/T, vibration unit per mass unit
    correction : complex — W = -V0/H, with the trial removed (mass unit of the trial)
    mass : float — |W|
    angle_deg : float — deg, arg W in [0, 360) (same sense as the trial angle and phases)
    correction_trial_on : complex — W - T, to add if the trial stays on
    mass_trial_on : float
    angle_trial_on_deg : float
    predicted_residual : complex — V0 + H W (0 for the linear model)
    small_response : bool
    warnings : tuple[str, ...]
    """

    influence: complex
    correction: complex
    mass: float
    angle_deg: float
    correction_trial_on: complex
    mass_trial_on: float
    angle_trial_on_deg: float
    predicted_residual: complex
    small_response: bool
    warnings: tuple[str, ...]

def _complex(v: object, name: str) -> complex:
    try:
        z = complex(v)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise BalanceValueError(name, f"{name} must be a complex number (amplitude and phase)") from None
    if not (math.isfinite(z.real) and math.isfinite(z.imag)):
        raise BalanceValueError(name, f"{name} must be finite")
    return z


def field_single_plane(v0: complex, v1: complex, trial: complex) -> FieldSinglePlane:
    """Single-plane field balancing from two runs (sheet §5.1).

    Parameters
    ----------
    v0 : complex — reading without trial, amplitude * exp(i phase) (any vibration unit)
    v1 : complex — reading with the trial on
    trial : complex — trial mass * exp(i angle) (any mass unit; the same angle sense as the phase)

    Returns
    -------
    FieldSinglePlane

    Raises
    ------
    ValueError
        zero trial; the trial changed nothing (V1 == V0).

    Notes
    -----
    ``H = (V1 - V0)/T``, ``W = -V0/H``; trial left on: ``W - T``.
    """
    V0, V1, T = _complex(v0, "v0"), _complex(v1, "v1"), _complex(trial, "trial")
    if T == 0:
        raise BalanceValueError("trial", "the trial mass must not be zero")
    if V1 == V0:
        raise BalanceValueError(
            "v1",
            "the trial run gave the same reading as the initial run; no influence coefficient"
        )
    H = (V1 - V0) / T
    W = -V0 / H
    Won = W - T
    small = small_response(V0, V1)
    warns = []
    if small:
        warns.append(
            "the trial changed the reading by less than 25 % in amplitude and 25 deg in phase: "
            "use a larger trial mass"
        )
    return FieldSinglePlane(
        influence=H,
        correction=W,
        mass=abs(W),
        angle_deg=angle_of(W, 0.0)[0],
        correction_trial_on=Won,
        mass_trial_on=abs(Won),
        angle_trial_on_deg=angle_of(Won, 0.0)[0],
        predicted_residual=V0 + H * W,
        small_response=small,
        warnings=tuple(warns),
    )


@dataclass(frozen=True, eq=False)
class FieldTwoPlane:
    """Two-plane influence-coefficient result (sheet §5.1).

    Attributes
    ----------
    influence : (2, 2) complex ndarray — alpha[i, j], response of sensor i per unit trial
        in plane j
    corrections : (2,) complex ndarray — W_A, W_B (trials removed), mass unit of the trials
    masses : (float, float)
    angles_deg : (float, float) — [0, 360), same sense as the trial angles and phases
    corrections_trials_on : (2,) complex ndarray — W - T per plane, if that plane's trial stays on
    cond : float — 2-norm condition number of alpha
    det : complex
    ill_conditioned : bool — cond > FIELD_COND_WARN
    small_response : (bool, bool) — per trial run, no sensor changed by >= 25 % / 25 deg
    predicted_residual : (2,) complex ndarray — V0 + alpha W (0 in the linear model)
    cumulative : bool
    warnings : tuple[str, ...]
    """

    influence: np.ndarray
    corrections: np.ndarray
    masses: tuple[float, float]
    angles_deg: tuple[float, float]
    corrections_trials_on: np.ndarray
    cond: float
    det: complex
    ill_conditioned: bool
    small_response: tuple[bool, bool]
    predicted_residual: np.ndarray
    cumulative: bool
    warnings: tuple[str, ...]

def field_two_plane(
    v0: Sequence[complex],
    va: Sequence[complex],
    vb: Sequence[complex],
    trial_a: complex,
    trial_b: complex,
    *,
    cumulative: bool = False,
) -> FieldTwoPlane:
    """Two-plane field balancing from three runs (2 sensors, sheet §5.1).

    Parameters
    ----------
    v0 : (2,) complex — sensor readings without trials
    va : (2,) complex — with trial A
    vb : (2,) complex — with trial B (trial A removed, unless ``cumulative``)
    trial_a, trial_b : complex — trial mass * exp(i angle), planes A and B
    cumulative : bool — trial A was left on during run B: the B column uses VB - VA

    Returns
    -------
    FieldTwoPlane

    Raises
    ------
    ValueError
        a zero trial; a singular influence matrix.

    Notes
    -----
    ``alpha_iA = (V_iA - V_i0)/T_A``, ``alpha_iB = (V_iB - V_i0)/T_B`` (or ``V_iB - V_iA``),
    ``W = -alpha^{-1} V0``. Warns when cond(alpha) > 50 (sheet §7.10).
    """
    V0 = np.array([_complex(v, "v0") for v in v0], dtype=complex)
    VA = np.array([_complex(v, "va") for v in va], dtype=complex)
    VB = np.array([_complex(v, "vb") for v in vb], dtype=complex)
    for arr, nm in ((V0, "v0"), (VA, "va"), (VB, "vb")):
        if arr.shape != (2,):
            raise BalanceValueError(nm, f"{nm} must hold two sensor readings")
    TA, TB = _complex(trial_a, "trial_a"), _complex(trial_b, "trial_b")
    if TA == 0 or TB == 0:
        raise BalanceValueError("trial_a" if TA == 0 else "trial_b", "trial masses must not be zero")
    refB = VA if cumulative else V0
    alpha = np.column_stack([(VA - V0) / TA, (VB - refB) / TB])
    det = complex(alpha[0, 0] * alpha[1, 1] - alpha[0, 1] * alpha[1, 0])
    scale = float(np.max(np.abs(alpha)))
    if not scale > 0.0 or abs(det) <= 1e-14 * scale * scale:
        raise BalanceValueError(
            "vb",
            "the influence matrix is singular: the trial runs do not separate the two planes"
        )
    W = np.linalg.solve(alpha, -V0)
    cond = float(np.linalg.cond(alpha))
    small = (
        all(small_response(V0[i], VA[i]) for i in range(2)),
        all(small_response(refB[i], VB[i]) for i in range(2)),
    )
    warns = []
    if cond > FIELD_COND_WARN:
        warns.append(
            f"the influence matrix is ill-conditioned (cond = {cond:.3g} > "
            f"{FIELD_COND_WARN:g}): the planes are not well separated"
        )
    for name, sm in zip("AB", small):
        if sm:
            warns.append(
                f"trial {name} changed no reading by 25 % in amplitude or 25 deg in phase: "
                "use a larger trial mass"
            )
    Won = W - np.array([TA, TB])
    return FieldTwoPlane(
        influence=alpha,
        corrections=W,
        masses=(float(abs(W[0])), float(abs(W[1]))),
        angles_deg=(angle_of(complex(W[0]), 0.0)[0], angle_of(complex(W[1]), 0.0)[0]),
        corrections_trials_on=Won,
        cond=cond,
        det=det,
        ill_conditioned=cond > FIELD_COND_WARN,
        small_response=small,
        predicted_residual=V0 + alpha @ W,
        cumulative=bool(cumulative),
        warnings=tuple(warns),
    )
