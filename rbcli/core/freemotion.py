"""Exact torque-free motion of a rigid body (Euler–Poinsot) — the physics of ``rbcli precess``.

Input: the inertia tensor about the com (body frame, tensor convention) and the initial
angular velocity (body frame). :func:`analyse` classifies the motion (:class:`FreeMotion`);
:mod:`rbcli.core.freepath` evaluates it at any times (no integration);
:func:`rbcli.core.freeverify.verify` checks it against ``solve_ivp``.

Conventions: principal moments ascending (axis 1 the smallest), ``axes`` rows the unit
axes in the body frame (``w_p = axes @ w_b``); ``R(t)`` maps body to space coordinates and
``R(0) = 1``; quaternions ``[w, x, y, z]``, ``w >= 0``; radians (``to_json``: ``_deg``
keys). Sources: physics sheet ``dynamics.md`` §1; Landau & Lifshitz §37; Celledoni, Fassò,
Säfström & Zanna (2008) with Leroy's corrections."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from rbcli.core.elliptic import ellipk, ellippi, ellippi_sc
from rbcli.core.elliptic import jacobi_reduced as _jacobi
from rbcli.core.freepath import (  # noqa: F401 - the cases are freemotion's vocabulary too
    CASE_MAX,
    CASE_MIN,
    CASE_REST,
    CASE_SEPARATRIX,
    CASE_SPHERICAL,
    CASE_STEADY,
    ll_quat,
)
from rbcli.core.freestate import FreeState, evaluate
from rbcli.core.inertia import InputOverflow
from rbcli.core.principal import principal_axes
from rbcli.core.rotation import quat_conjugate as _qconj
from rbcli.core.rotation import quat_from_matrix as _quat_from_matrix
from rbcli.core.rotation import quat_multiply as _qmul

__all__ = [
    "CASE_REST",
    "CASE_SPHERICAL",
    "CASE_STEADY",
    "CASE_MAX",
    "CASE_MIN",
    "CASE_SEPARATRIX",
    "SNAP_RTOL",
    "SEPARATRIX_RTOL",
    "EllipticSolution",
    "FreeMotion",
    "analyse",
    "frame_quaternions",
    "ll_quat",
]

#: Principal components of omega0 smaller than this times |omega0| are round-off of the
#: projection on the principal axes (a few ulp) and are set to zero.
SNAP_RTOL = 8 * np.finfo(float).eps

#: |Delta2| <= SEPARATRIX_RTOL * (|M1^2 (I2-I1)/I1| + |M3^2 (I3-I2)/I3|) is a separatrix:
#: the sign of Delta2 = G^2 - 2 T I2 is then not determined by the data (round-off of the two
#: terms is ~4 eps of their sum). See the Notes of :func:`analyse`.
SEPARATRIX_RTOL = 1e-14

_TWO_PI = 2.0 * math.pi
#: smallest |L|^2 (kg^2 m^4/s^2) kept at full relative precision (a normal double / eps)
_TINY = float(np.finfo(float).tiny / np.finfo(float).eps)


# --- results


@dataclass(frozen=True, eq=False)
class EllipticSolution:
    """Constants of the exact asymmetric solution (principal frame, I1 < I2 < I3).

    Attributes
    ----------
    kind : str — "3" (w = (A1 cn, s A2 sn, s A3 dn)), "1" (w = (s A1 dn, s A2 sn, A3 cn)) or
        "separatrix" (w = (s1 A1 sech, s1 s3 Omega0 tanh, s3 A3 sech))
    m, mc : float — m = k^2 and 1 - m, each from its own Delta form
    lam, tau0 : float — tau = lambda t + tau0 (1/s, -)
    K : float or None — K(m) (None on the separatrix)
    signs, amplitudes — (s, s) or (s1, s3); (A1, A2, A3) rad/s (separatrix: A2 = Omega0)
    pole : int — principal index of the Landau–Lifshitz pole (the dn axis)
    n, coeff, pi_complete — Pi's characteristic, its coefficient in phi(t) (rad), Pi(n | m)
    precession_per_period : float or None — rad, Delta phi over one period"""

    kind: str
    m: float
    mc: float
    lam: float
    K: float | None
    tau0: float
    signs: tuple[float, float]
    amplitudes: np.ndarray
    pole: int
    n: float
    coeff: float
    pi_complete: float | None
    precession_per_period: float | None
    # evaluation constants
    _pi_tau0: float = field(repr=False)
    _q_left: np.ndarray = field(repr=False)
    _q_right: np.ndarray = field(repr=False)
    _perm: tuple[int, int, int] = field(repr=False)
    _G: float = field(repr=False)
    _Ic: float = field(repr=False)


@dataclass(frozen=True, eq=False)
class FreeMotion:
    """Classification and constants of a torque-free motion (SI units, radians); the JSON
    keys of ``precess`` (their meaning: the man page's JSON section).

    Attributes
    ----------
    inertia : (3, 3) ndarray — kg m^2, the tensor used (body frame, rebuilt from the principal
        moments and axes, so a symmetric average shows)
    omega0 : (3,) ndarray — rad/s, initial angular velocity, body frame
    moments : (3,) ndarray — kg m^2, principal moments, ascending (equal pairs averaged)
    axes : (3, 3) ndarray — rows: unit principal axes, body frame (a proper rotation)
    symmetry : str — "asymmetric", "symmetric" or "spherical"
    omega0_principal : (3,) ndarray — rad/s, omega0 in the principal frame
    angular_momentum : (3,) ndarray — kg m^2/s, L = I omega0 (constant in space)
    angular_momentum_norm, kinetic_energy : float — G = |L| (kg m^2/s), T (J)
    case, description : str — a ``CASE_*`` constant; the case in one sentence
    circles_axis, period, stable — as the JSON keys (s for ``period``)
    linear_coefficients, linear_kinds, linear_rates — sqrt|k_j|, k_j = (Ij-Ik)(Ij-Il)/(Ik Il):
        oscillation (k_j > 0) or growth about steady rotation about axis j; rates at W = G/I_j
    elliptic : EllipticSolution or None — asymmetric non-steady motions
    flip_interval, first_flip, flip_interval_estimate : float or None — s: 2K/lambda, the
        first sign change of w2, and (2/sigma) ln(4/k')
    precession_per_period, mean_precession_rate : float or None — rad and rad/s about L
    symmetry_axis, symmetry_index, oblate — a symmetric body's axis (body frame), its principal
        index, Is > I
    spin, transverse_rate, precession_rate, space_precession_rate, spin_rate : float or None —
        rad/s: omega3, |omega across|, W = omega3 (Is/I - 1), phi' = G/I, psi' = -W
    body_cone, nutation, space_cone : float or None — rad: angle(omega, axis),
        tan theta = (I/Is) tan alpha, |theta - alpha|
    wobble_to_spin, wobble_period, space_precession_period : float or None — |phi'/psi'|,
        2 pi/|W| (s), 2 pi/phi' (s)"""

    inertia: np.ndarray
    omega0: np.ndarray
    moments: np.ndarray
    axes: np.ndarray
    symmetry: str
    omega0_principal: np.ndarray
    angular_momentum: np.ndarray
    angular_momentum_norm: float
    kinetic_energy: float
    case: str
    description: str
    circles_axis: int | None
    period: float | None
    stable: bool | None
    linear_coefficients: np.ndarray
    linear_kinds: tuple[str, str, str]
    linear_rates: np.ndarray
    elliptic: EllipticSolution | None = None
    flip_interval: float | None = None
    first_flip: float | None = None
    flip_interval_estimate: float | None = None
    precession_per_period: float | None = None
    mean_precession_rate: float | None = None
    symmetry_axis: np.ndarray | None = None
    symmetry_index: int | None = None
    oblate: bool | None = None
    spin: float | None = None
    transverse_rate: float | None = None
    precession_rate: float | None = None
    space_precession_rate: float | None = None
    spin_rate: float | None = None
    body_cone: float | None = None
    nutation: float | None = None
    space_cone: float | None = None
    wobble_to_spin: float | None = None
    wobble_period: float | None = None
    space_precession_period: float | None = None

    @property
    def symmetric(self) -> bool:
        """True for a symmetric or spherical body (two or three equal principal moments)."""
        return self.symmetry != "asymmetric"

    def at(self, t: Any) -> FreeState:
        """The exact state at ``t`` (s; a number or an array): a
        :class:`rbcli.core.freestate.FreeState` with ``omega``, ``angular_momentum`` (body
        frame, at t), ``quaternion`` (body -> space) and ``rotation_matrix``."""
        return evaluate(self, t)

    def to_json(self) -> dict[str, Any]:
        """Plain-JSON form (SI, degrees under ``*_deg``); every key always present, null = n/a
        (which are SPEC §3's and which additions: SPEC)."""

        def f(x: float | None) -> float | None:
            return None if x is None else float(x)

        def deg(x: float | None) -> float | None:
            return None if x is None else math.degrees(float(x))

        def vec(v: np.ndarray | None) -> list[Any] | None:
            return None if v is None else np.asarray(v, dtype=float).tolist()

        el = self.elliptic
        return {
            "omega": vec(self.omega0),
            "angular_momentum": vec(self.angular_momentum),
            "angular_momentum_norm": f(self.angular_momentum_norm),
            "kinetic_energy": f(self.kinetic_energy),
            "symmetric": self.symmetric,
            "symmetry": self.symmetry,
            "principal_moments": vec(self.moments),
            "principal_axes": vec(self.axes),
            "case": self.case,
            "description": self.description,
            "period": f(self.period),
            "circles_axis": self.circles_axis,
            "stable": self.stable,
            "precession_rate": f(self.precession_rate),
            "space_precession_rate": f(self.space_precession_rate),
            "body_cone_deg": deg(self.body_cone),
            "space_cone_deg": deg(self.space_cone),
            "nutation_deg": deg(self.nutation),
            "symmetry_axis": vec(self.symmetry_axis),
            "oblate": self.oblate,
            "spin_rate": f(self.spin_rate),
            "wobble_to_spin": f(self.wobble_to_spin),
            "wobble_period": f(self.wobble_period),
            "space_precession_period": f(self.space_precession_period),
            "flip_interval": f(self.flip_interval),
            "first_flip": f(self.first_flip),
            "flip_interval_estimate": f(self.flip_interval_estimate),
            "precession_per_period": f(self.precession_per_period),
            "mean_precession_rate": f(self.mean_precession_rate),
            "elliptic_parameter": None if el is None else float(el.m),
            "elliptic_complement": None if el is None else float(el.mc),
            "elliptic_rate": None if el is None else float(el.lam),
            "linear_rates": vec(self.linear_rates),
            "linear_kinds": list(self.linear_kinds),
        }


# --- analysis

_AXIS_NAMES = ("smallest", "intermediate", "largest")


def _linear(moments: np.ndarray, G: float) -> tuple[np.ndarray, tuple[str, str, str], np.ndarray]:
    coefs = np.zeros(3)
    kinds: list[str] = []
    rates = np.zeros(3)
    for j in range(3):
        k, m = [i for i in range(3) if i != j]
        kap = (moments[j] - moments[k]) * (moments[j] - moments[m]) / (moments[k] * moments[m])
        coefs[j] = math.sqrt(abs(kap))
        kinds.append("oscillation" if kap > 0 else ("growth" if kap < 0 else "neutral"))
        rates[j] = coefs[j] * G / moments[j]
    return coefs, (kinds[0], kinds[1], kinds[2]), rates


def analyse(
    inertia: np.ndarray, omega0: np.ndarray, *, symmetric_rtol: float = 1e-9
) -> FreeMotion:
    """Classify the torque-free motion of a rigid body and compute its constants.

    Parameters
    ----------
    inertia : (3, 3) array_like — kg m^2, about the centre of mass, body frame; positive definite
    omega0 : (3,) array_like — rad/s, angular velocity at t = 0, body frame
    symmetric_rtol : float — principal moments closer than this times the largest are equal

    Raises
    ------
    ValueError
        wrong shapes; :class:`rbcli.core.inertia.InputOverflow` (``param`` ``"inertia"`` or
        ``"omega"``) for non-finite numbers, a moment <= 0, or |L|^2 or T out of range.

    Notes
    -----
    Physics sheet §1. With M = (I1 w1, I2 w2, I3 w3) (principal frame), G^2 = |M|^2, 2T = w.M
    and the cancellation-free ``Delta2 = M3^2 (I3-I2)/I3 - M1^2 (I2-I1)/I1`` (Delta1, Delta3
    alike): Delta2 > 0, omega circles axis 3; < 0, axis 1 (period 4K/lambda, §1.2); the body
    flips only when I2 A2 > Ic Ac k'. Separatrix when |Delta2| <= SEPARATRIX_RTOL times the sum
    of its terms (round-off decides its sign): sn, cn, dn from our own AGM started from
    sqrt(1 - m) stay accurate to 1 - m = 1e-15, where scipy's ellipj fails. Symmetric bodies
    §1.1: W = w3 (Is/I - 1), phi' = G/I, tan theta = (I/Is) tan alpha. Steady rotation (after
    snapping components below SNAP_RTOL |omega0|): ``e'' = -k_j W^2 e``."""
    J = np.asarray(inertia, dtype=float)
    w0 = np.asarray(omega0, dtype=float)
    if J.shape != (3, 3):
        raise ValueError(f"inertia must be a 3x3 tensor, got shape {J.shape}")
    if w0.shape != (3,):
        raise ValueError(f"omega must have 3 components, got shape {w0.shape}")
    if not np.all(np.isfinite(J)):
        raise InputOverflow("inertia", "inertia and omega must be finite")
    if not np.all(np.isfinite(w0)):
        raise InputOverflow("omega", "inertia and omega must be finite")
    moments, axes, symmetry, unique = _principal(0.5 * (J + J.T), symmetric_rtol)
    wp, wn, Mp, G, T = _momentum(moments, axes, w0)
    coefs, kinds, rates = _linear(moments, G)
    common: dict[str, Any] = dict(
        inertia=axes.T @ np.diag(moments) @ axes,
        omega0=w0.copy(),
        moments=moments,
        axes=axes,
        symmetry=symmetry,
        omega0_principal=wp,
        angular_momentum=axes.T @ Mp,
        angular_momentum_norm=G,
        kinetic_energy=T,
        linear_coefficients=coefs,
        linear_kinds=kinds,
        linear_rates=rates,
    )
    nz = [i for i in range(3) if wp[i] != 0.0]
    if symmetry != "asymmetric":
        return _analyse_symmetric(common, unique, nz, w0, wn)
    if not nz:
        return FreeMotion(
            case=CASE_REST, description="at rest: omega = 0, nothing moves",
            circles_axis=None, period=None, stable=None, mean_precession_rate=0.0, **common,
        )
    if len(nz) == 1:
        j = nz[0]
        stable = j != 1
        return FreeMotion(
            case=CASE_STEADY,
            description=(
                f"steady rotation about principal axis {j + 1} ({_AXIS_NAMES[j]} moment), "
                + ("stable" if stable else "unstable: any disturbance grows into flips")
            ),
            circles_axis={0: 1, 2: 3}.get(j),
            period=None,
            stable=stable,
            mean_precession_rate=wn,
            **common,
        )
    return _analyse_asymmetric(common, wp, Mp, G, T)


def _principal(J: np.ndarray, symmetric_rtol: float) -> tuple[np.ndarray, np.ndarray, str, int | None]:
    """Principal moments (pairs closer than ``symmetric_rtol`` times the largest averaged),
    axes, symmetry and the unique axis of the symmetric tensor ``J``; refused when not
    positive definite."""
    pa = principal_axes(J)
    moments = np.array(pa.moments, dtype=float)
    axes = np.array(pa.axes, dtype=float)
    symmetry = pa.symmetry
    unique = pa.unique_axis
    if not moments[0] > 0.0:
        raise InputOverflow(
            "inertia",
            "inertia must be positive definite: the smallest principal moment is "
            f"{moments[0]:.6g} kg m^2 (a point mass or a thin rod has no free rotation about "
            "its own axis)"
        )
    if symmetry == "asymmetric":
        scale = moments[2]
        eq01 = moments[1] - moments[0] <= symmetric_rtol * scale
        eq12 = moments[2] - moments[1] <= symmetric_rtol * scale
        if eq01 and eq12:
            symmetry, unique = "spherical", None
            moments = np.full(3, moments.mean())
        elif eq01 or eq12:
            symmetry = "symmetric"
            unique = 2 if eq01 else 0
            pair = [0, 1] if eq01 else [1, 2]
            moments[pair] = moments[pair].mean()
    return moments, axes, symmetry, unique


def _momentum(moments: np.ndarray, axes: np.ndarray,
              w0: np.ndarray) -> tuple[np.ndarray, float, np.ndarray, float, float]:
    """omega0 in the principal frame (round-off snapped to 0), |omega0|, the angular
    momentum M there, G = |M| and the kinetic energy T; refused when |L|^2 or T is not a
    normal double."""
    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        wp = axes @ w0
        wn = float(np.linalg.norm(w0))
        wp = np.where(np.abs(wp) <= SNAP_RTOL * wn, 0.0, wp)
        Mp = moments * wp
        G = float(np.linalg.norm(Mp))
        T = 0.5 * float(wp @ Mp)
        G2 = G * G
    # The closed forms square L and multiply 2T by a moment: those must be normal doubles.
    # (Found through the CLI: |omega| = 1e200 rad/s overflowed |omega| and was classified
    # "rest"; 1e-300 underflowed G^2 and divided by zero.)
    if not (math.isfinite(wn) and math.isfinite(G2) and math.isfinite(2.0 * T * float(moments[2]))):
        raise InputOverflow(
            "omega",
            "omega is too large for this body: |L|^2 or the kinetic energy overflows double "
            "precision"
        )
    if bool(np.any(w0 != 0.0)) and not (G2 >= _TINY and T > 0.0):
        raise InputOverflow(
            "omega",
            "omega is too small for this body: |L|^2 or the kinetic energy underflows double "
            "precision"
        )
    return wp, wn, Mp, G, T


def _analyse_asymmetric(common: dict[str, Any], wp: np.ndarray, Mp: np.ndarray, G: float,
                        T: float) -> FreeMotion:
    """The motion of an asymmetric body that turns about no principal axis: the elliptic
    solution (or the separatrix), its period, flips and precession."""
    axes = common["axes"]
    moments = common["moments"]
    I1, I2, I3 = (float(x) for x in moments)
    M1, M2, M3 = (float(x) for x in Mp)
    d1 = M2 * M2 * (I2 - I1) / I2 + M3 * M3 * (I3 - I1) / I3
    d3 = -(M1 * M1 * (I3 - I1) / I1 + M2 * M2 * (I3 - I2) / I2)
    ta = M1 * M1 * (I2 - I1) / I1
    tb = M3 * M3 * (I3 - I2) / I3
    d2 = tb - ta
    sigma_G = (G / I2) * math.sqrt((I2 - I1) * (I3 - I2) / (I1 * I3))

    if abs(d2) <= SEPARATRIX_RTOL * (ta + tb):
        return _analyse_separatrix(common, wp, G, T)

    if d2 > 0:
        kind, pole = "3", 2
        s = 1.0 if wp[2] >= 0 else -1.0
        A1 = math.sqrt(-d3 / (I1 * (I3 - I1)))
        A2 = math.sqrt(-d3 / (I2 * (I3 - I2)))
        A3 = math.sqrt(d1 / (I3 * (I3 - I1)))
        lam = math.sqrt((I3 - I2) * d1 / (I1 * I2 * I3))
        m = (I2 - I1) * (-d3) / ((I3 - I2) * d1)
        mc = (I3 - I1) * d2 / ((I3 - I2) * d1)
        y, x = s * wp[1] / A2, wp[0] / A1
        n = -I3 * (I2 - I1) / (I1 * (I3 - I2))
        sig, Ic, perm = 1.0, I3, (0, 1, 2)
        circles, case = 3, CASE_MAX
    else:
        kind, pole = "1", 0
        s = 1.0 if wp[0] >= 0 else -1.0
        A1 = math.sqrt(-d3 / (I1 * (I3 - I1)))
        A2 = math.sqrt(d1 / (I2 * (I2 - I1)))
        A3 = math.sqrt(d1 / (I3 * (I3 - I1)))
        lam = math.sqrt((I2 - I1) * (-d3) / (I1 * I2 * I3))
        m = (I3 - I2) * d1 / ((I2 - I1) * (-d3))
        mc = (I3 - I1) * (-d2) / ((I2 - I1) * (-d3))
        y, x = s * wp[1] / A2, wp[2] / A3
        n = -I1 * (I3 - I2) / (I3 * (I2 - I1))
        sig, Ic, perm = -1.0, I1, (1, 2, 0)
        circles, case = 1, CASE_MIN
    m = min(max(m, 0.0), 1.0)
    mc = min(max(mc, 0.0), 1.0)

    K = ellipk(m, mc)
    # tau0 = F(phi0 | m), phi0 = atan2(y, x), with the half-turn reduction; from sin and cos
    # of phi0 (= Pi(0; phi0 | m)) so that a small cos keeps its digits near the separatrix
    r = math.hypot(x, y)
    sr, cr = y / r, x / r
    jf = 0.0
    if cr < 0.0:
        jf = 1.0 if sr >= 0.0 else -1.0
        sr, cr = -sr, -cr
    tau0 = float(ellippi_sc(0.0, sr, cr, m, mc)) + 2.0 * K * jf
    period = 4.0 * K / lam
    pi_c = ellippi(n, m, mc)
    coeff = sig * G * (I3 - I1) / (lam * I1 * I3)
    dphi = (G / Ic) * period + 4.0 * coeff * pi_c

    _, _, _, j0, snu0, cnu0 = _jacobi(np.array([tau0]), K, m, mc)
    pi_tau0 = float(ellippi_sc(n, snu0, cnu0, m, mc)[0] + 2.0 * j0[0] * pi_c)

    q_left, q_right = frame_quaternions(Mp, G, perm, axes)
    ell = EllipticSolution(
        kind=kind, m=m, mc=mc, lam=lam, K=K, tau0=tau0, signs=(s, s),
        amplitudes=np.array([A1, A2, A3]), pole=pole, n=n, coeff=coeff, pi_complete=pi_c,
        precession_per_period=dphi, _pi_tau0=pi_tau0, _q_left=q_left, _q_right=q_right,
        _perm=perm, _G=G, _Ic=Ic,
    )
    # The body flips (the intermediate axis turns over relative to L) when L, seen in the
    # body, passes nearer to the intermediate axis than to any other principal axis: at
    # sn = +-1 (w2 extreme) |M2| = I2 A2 while the other components are 0 and Ic Ac k'
    # (Ic, Ac: the dn axis). Otherwise w2 still changes sign every 2K/lambda, but that is
    # the wobble of a body circling its largest (smallest) axis, not a flip.
    Ac = A3 if kind == "3" else A1
    flips = I2 * A2 > Ic * Ac * math.sqrt(mc)
    half = 2.0 * K / lam
    flip = first = est = None
    if flips:
        flip = half
        first = (2.0 * K * math.floor(tau0 / (2.0 * K) + 1.0) - tau0) / lam
        est = (2.0 / sigma_G) * math.log(4.0 / math.sqrt(mc)) if mc > 0 else None
    big = "largest" if circles == 3 else "smallest"
    if flips:
        desc = (
            f"omega circles principal axis {circles} ({big} moment), period {period:.6g} s; "
            f"the body flips over (the intermediate axis turns over relative to L) every "
            f"{half:.6g} s"
        )
    else:
        desc = (
            f"omega circles principal axis {circles} ({big} moment), period {period:.6g} s; "
            f"no flip: stable about axis {circles}"
        )
    return FreeMotion(
        case=case, description=desc, circles_axis=circles, period=period, stable=not flips,
        elliptic=ell, flip_interval=flip, first_flip=first, flip_interval_estimate=est,
        precession_per_period=dphi, mean_precession_rate=dphi / period, **common,
    )


def frame_quaternions(
    Mp: np.ndarray, G: float, perm: tuple[int, int, int], axes: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Constant factors of q(t) = q_left qz(phi) qx(theta) qz(psi) q_right (see :func:`ll_quat`):
    ``Mp`` (3,) the angular momentum in the principal frame, ``perm`` the cyclic relabel
    putting the pole axis last, ``axes`` the principal axes (rows, body frame)."""
    Pm = np.eye(3)[list(perm)]
    q_pm = _quat_from_matrix(Pm)
    q_P = _quat_from_matrix(axes)
    q_zl0 = _qmul(ll_quat(np.zeros(1), Mp[list(perm)][None, :], G), q_pm)[0]
    q_left = _qmul(_qconj(q_P), _qconj(q_zl0))
    q_right = _qmul(q_pm, q_P)
    return q_left, q_right


def _analyse_separatrix(common: dict[str, Any], wp: np.ndarray, G: float, T: float) -> FreeMotion:
    I1, I2, I3 = (float(x) for x in common["moments"])
    s1 = 1.0 if wp[0] >= 0 else -1.0
    s3 = 1.0 if wp[2] >= 0 else -1.0
    Om0 = G / I2
    A1 = Om0 * math.sqrt(I2 * (I3 - I2) / (I1 * (I3 - I1)))
    A3 = Om0 * math.sqrt(I2 * (I2 - I1) / (I3 * (I3 - I1)))
    lam = Om0 * math.sqrt((I3 - I2) * (I2 - I1) / (I1 * I3))
    sech0 = math.sqrt(0.5 * ((wp[0] / A1) ** 2 + (wp[2] / A3) ** 2))
    tanh0 = s1 * s3 * wp[1] / Om0
    tau0 = math.asinh(tanh0 / sech0)
    r2 = I3 * (I2 - I1) / (I1 * (I3 - I2))
    r = math.sqrt(r2)
    coeff = G * (I3 - I2) / (I2 * I3 * lam) * r
    perm = (0, 1, 2)
    q_left, q_right = frame_quaternions(common["moments"] * wp, G, perm, common["axes"])
    ell = EllipticSolution(
        kind="separatrix", m=1.0, mc=0.0, lam=lam, K=None, tau0=tau0, signs=(s1, s3),
        amplitudes=np.array([A1, Om0, A3]), pole=2, n=-r2, coeff=coeff, pi_complete=None,
        precession_per_period=None, _pi_tau0=math.atan(r * math.tanh(tau0)),
        _q_left=q_left, _q_right=q_right, _perm=perm, _G=G, _Ic=I3,
    )
    first = -tau0 / lam if tau0 < 0 else None
    desc = (
        "separatrix (G^2 = 2 T I2): the motion is on the boundary between circling the largest "
        "and the smallest axis; not periodic - omega tends to the intermediate axis as "
        "t -> +-infinity and w2 changes sign once"
    )
    return FreeMotion(
        case=CASE_SEPARATRIX, description=desc, circles_axis=None, period=None, stable=False,
        elliptic=ell, first_flip=first, **common,
    )


def _analyse_symmetric(
    common: dict[str, Any], unique: int | None, nz: list[int], w0: np.ndarray, wn: float
) -> FreeMotion:
    moments = common["moments"]
    axes = common["axes"]
    wp = common["omega0_principal"]
    G = common["angular_momentum_norm"]
    if common["symmetry"] == "spherical":
        Iq = float(moments[0])
        e = w0 / wn if wn > 0 else axes[2].copy()
        if wn == 0:
            case, desc, stable, circ = CASE_REST, "at rest: omega = 0, nothing moves", None, None
        else:
            case, stable, circ = CASE_SPHERICAL, None, None
            desc = "spherical body: steady rotation about omega0 (every axis is principal)"
        return FreeMotion(
            case=case, description=desc, circles_axis=circ, period=None, stable=stable,
            mean_precession_rate=wn, symmetry_axis=e, symmetry_index=None, oblate=None,
            spin=wn, transverse_rate=0.0, precession_rate=0.0, space_precession_rate=G / Iq,
            spin_rate=0.0, body_cone=0.0, nutation=0.0, space_cone=0.0, wobble_to_spin=None,
            wobble_period=None,
            space_precession_period=_TWO_PI * Iq / G if G > 0 else None,
            **common,
        )
    assert unique is not None
    pair = [i for i in range(3) if i != unique]
    Is = float(moments[unique])
    Iq = float(moments[pair[0]])
    oblate = Is > Iq
    e = axes[unique].copy()
    w3 = float(wp[unique])
    wperp = math.hypot(float(wp[pair[0]]), float(wp[pair[1]]))
    W = w3 * (Is - Iq) / Iq
    alpha = math.atan2(wperp, abs(w3))
    theta = math.atan2(Iq * wperp, Is * abs(w3))
    phid = G / Iq
    circ_label = 3 if oblate else 1
    if not nz:
        case, circ, stable, period = CASE_REST, None, None, None
        desc = "at rest: omega = 0, nothing moves"
        mean = 0.0
    elif wperp == 0.0:
        case, circ, stable, period = CASE_STEADY, circ_label, True, None
        desc = (
            f"steady rotation about the symmetry axis (axis {circ_label}, "
            f"{'largest' if oblate else 'smallest'} moment), stable"
        )
        mean = wn
    elif w3 == 0.0:
        case, circ, stable, period = CASE_STEADY, None, None, None
        desc = (
            "steady rotation about a transverse principal axis of a symmetric body "
            "(neutral: a small tilt towards the symmetry axis makes omega wander round it)"
        )
        mean = wn
    else:
        case = CASE_MAX if oblate else CASE_MIN
        circ, stable = circ_label, True
        period = _TWO_PI / abs(W)
        mean = phid
        desc = (
            f"symmetric {'oblate' if oblate else 'prolate'} body: omega and the symmetry axis "
            f"precess about L at {phid:.6g} rad/s; in the body omega circles the axis at "
            f"{W:.6g} rad/s (period {period:.6g} s)"
        )
    return FreeMotion(
        case=case, description=desc, circles_axis=circ, period=period, stable=stable,
        precession_per_period=None if period is None else phid * period,
        mean_precession_rate=mean, symmetry_axis=e, symmetry_index=unique, oblate=oblate,
        spin=w3, transverse_rate=wperp, precession_rate=W, space_precession_rate=phid,
        spin_rate=-W, body_cone=alpha, nutation=theta, space_cone=abs(theta - alpha),
        wobble_to_spin=abs(phid / W) if W != 0 else None,
        wobble_period=_TWO_PI / abs(W) if W != 0 else None,
        space_precession_period=_TWO_PI / phid if phid > 0 else None,
        **common,
    )
