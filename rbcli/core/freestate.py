"""Sampling an exact torque-free motion: the state at any times, the time series, notes.

The formulas of the motion are in :mod:`rbcli.core.freemotion` and :mod:`rbcli.core.freepath`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.core import freepath
from rbcli.core.freepath import CASE_SEPARATRIX, CASE_STEADY
from rbcli.core.rotation import quat_to_axis_angle, quat_to_matrix
from rbcli.errors import ParamError

if TYPE_CHECKING:
    from rbcli.core.freemotion import FreeMotion

__all__ = [
    "FreeState",
    "SERIES_COLUMNS",
    "MAX_PHASE",
    "NEAR_SEPARATRIX",
    "EARTH_LIKE",
    "evaluate",
    "fastest_rate",
    "check_phase",
    "state_json",
    "series",
    "notes",
    "plot_span",
    "polhode_family",
]

#: the columns of :func:`series`: t (s), ω (rad/s, body), L (kg m²/s, body), q (body → space)
SERIES_COLUMNS = ("t", "wx", "wy", "wz", "Lx", "Ly", "Lz", "qw", "qx", "qy", "qz")
#: the phase of the motion at time t is known to about eps * rate * |t| rad (t itself is a
#: double); beyond this rate * |t| it would be known to worse than 0.1 rad
MAX_PHASE = 1e15
#: 1 - m below this: "close to the separatrix", the flips are the story (as in core's description)
NEAR_SEPARATRIX = 0.01
#: an oblate symmetric body with Is/I - 1 below this is "Earth-like" (nearly spherical)
EARTH_LIKE = 0.01
#: rows evaluated at a time by :func:`series`
CHUNK = 100_000
_DAY = 86400.0


@dataclass(frozen=True, eq=False)
class FreeState:
    """The state of a torque-free motion at one time or an array of times.

    Attributes
    ----------
    t : float or (N,) ndarray — s
    omega : (3,) or (N, 3) ndarray — rad/s, angular velocity in the body frame
    angular_momentum : (3,) or (N, 3) ndarray — kg m²/s, L = J ω in the body frame at t
        (in space L is constant: ``motion.angular_momentum``)
    quaternion : (4,) or (N, 4) ndarray — ``[w, x, y, z]``, the rotation body → space
        (space = body frame at t = 0), unit, ``w >= 0``
    """

    t: Any
    omega: np.ndarray
    angular_momentum: np.ndarray
    quaternion: np.ndarray

    @property
    def rotation_matrix(self) -> np.ndarray:
        """(3, 3) or (N, 3, 3): R(t), body coordinates at t → space coordinates."""
        return quat_to_matrix(self.quaternion)

    def axis_angle(self) -> tuple[np.ndarray | None, float]:
        """(unit axis or None, angle in rad in [0, π]) of R(t), for a single time."""
        if np.ndim(self.t) != 0:
            raise ValueError("axis_angle is for the state at one time")
        return quat_to_axis_angle(self.quaternion)


def evaluate(motion: FreeMotion, t: Any) -> FreeState:
    """ω, L (body frame) and q (body → space) at the times ``t`` (s; a number or an array).

    At t = 0 the values are exactly the initial conditions (ω0 and the identity), not their
    round-off through the closed forms.
    """
    scalar = np.ndim(t) == 0
    tt = np.atleast_1d(np.asarray(t, dtype=float))
    w = freepath.omega_at(motion, tt)
    q = freepath.attitude_at(motion, tt)
    zero = tt == 0.0
    if np.any(zero):
        w[zero] = motion.omega0
        q[zero] = (1.0, 0.0, 0.0, 0.0)
    L = w @ motion.inertia  # the model tensor is symmetric: rows are J w
    if scalar:
        return FreeState(float(tt[0]), w[0], L[0], q[0])
    return FreeState(tt, w, L, q)


def fastest_rate(motion: FreeMotion) -> float:
    """rad/s: the fastest rate anything turns at (|ω|, or 2π/period or λ if faster)."""
    r = float(np.linalg.norm(motion.omega0))
    if motion.period:
        r = max(r, 2 * math.pi / motion.period)
    if motion.elliptic is not None:
        r = max(r, motion.elliptic.lam)
    return r


def check_phase(motion: FreeMotion, t: float, param: str) -> None:
    """Refuse a time so far away that a double-precision t does not fix the phase there.

    Raises
    ------
    rbcli.errors.ParamError
        naming ``param`` (``"at"`` or ``"duration"``) when rate × |t| > :data:`MAX_PHASE`.
    """
    rate = fastest_rate(motion)
    if rate * abs(t) > MAX_PHASE:
        raise ParamError(
            param,
            f"{t:.6g} s is about {rate * abs(t) / (2 * 3.141592653589793):.3g} turns away; the "
            "phase of the motion there is not determined by a double-precision time (keep "
            f"rate x |t| below {MAX_PHASE:.0e} rad)",
        )


def _snap(a: np.ndarray, rtol: float) -> np.ndarray:
    """Entries below ``rtol`` (of a unit scale) become exactly 0, no negative zeros."""
    a = np.array(a, dtype=float)
    a[np.abs(a) <= rtol] = 0.0
    a[a == 0.0] = 0.0
    return a


def state_json(motion: FreeMotion, t: float) -> dict[str, Any]:
    """The ``--at`` object: t, ω, L (body frame at t), quaternion, axis-angle, matrix, periods."""
    st = evaluate(motion, float(t))
    axis, angle = st.axis_angle()
    return {
        "t": float(t),
        "omega": st.omega.tolist(),
        "angular_momentum": st.angular_momentum.tolist(),
        "quaternion": st.quaternion.tolist(),
        "rotation_axis": None if axis is None else [float(x) for x in axis],
        "rotation_angle_deg": math.degrees(angle),
        "rotation_matrix": _snap(st.rotation_matrix, 1e-16).tolist(),
        "periods": None if motion.period is None else float(t) / motion.period,
    }


def series(motion: FreeMotion, duration: float, samples: int,
           chunk: int = CHUNK) -> Iterator[np.ndarray]:
    """Rows :data:`SERIES_COLUMNS` at ``samples`` times evenly spaced from 0 to ``duration``
    inclusive, in blocks of at most ``chunk`` rows (arrays (rows, 11)).

    The quaternion's sign is continuous along the series (w = +1 at t = 0; each q whose dot
    product with the one before is negative is negated: q and −q are one orientation).
    """
    t_all = np.linspace(0.0, float(duration), int(samples))
    prev = None
    for i in range(0, t_all.size, chunk):
        t = t_all[i:i + chunk]
        st = evaluate(motion, t)
        q = st.quaternion
        ref = np.vstack([q[:1] if prev is None else prev[None, :], q[:-1]])
        flips = np.einsum("ij,ij->i", q, ref) < 0.0
        sign = np.where(np.cumsum(flips) % 2 == 1, -1.0, 1.0)
        q = q * sign[:, None]
        prev = q[-1].copy()
        yield np.column_stack([t, st.omega, st.angular_momentum, q])


def _num6(x: float) -> str:
    """6 significant figures, no "-0" (the SI form of the notes)."""
    s = f"{float(x):.6g}"
    return s[1:] if s.startswith("-") and float(s) == 0.0 else s


def notes(motion: FreeMotion, *, time: Callable[[float], str] | None = None,
          number: Callable[[float], str] | None = None) -> list[str]:
    """What the numbers mean, in words (the JSON ``notes`` and the table notes).

    Parameters
    ----------
    motion : FreeMotion
    time : callable, optional — formats a time in s with its unit (default ``"19.5529 s"``)
    number : callable, optional — formats a plain number (default 6 significant figures)
    """
    number = number or _num6
    time = time or (lambda x: f"{_num6(x)} s")
    out: list[str] = []
    el = motion.elliptic
    if motion.case == CASE_SEPARATRIX:
        out.append(
            "separatrix: G^2 = 2 T I2 exactly (to round-off), the boundary between circling the "
            "largest and the smallest axis. There is no period: ω creeps towards the intermediate "
            "axis (axis 2) as t -> ±infinity, and the body turns over once"
            + (f", at t = {time(motion.first_flip)}." if motion.first_flip is not None
               else " (before t = 0).")
        )
    elif el is not None and el.mc < NEAR_SEPARATRIX and motion.flip_interval is not None:
        out.append(
            f"close to the intermediate axis: the body flips over every "
            f"{time(motion.flip_interval)}, first at {time(motion.first_flip)} (the "
            "tennis-racket or Dzhanibekov effect: rotation about the intermediate axis is "
            "unstable)."
        )
    if motion.case == CASE_STEADY and motion.circles_axis is None and motion.symmetry == "asymmetric":
        out.append(
            "steady rotation about the intermediate axis is unstable: a small disturbance grows as "
            f"exp(σt), σ = {number(motion.linear_rates[1])} 1/s, and turns into flips."
        )
    if motion.circles_axis == 1 and motion.stable:
        out.append(
            "rotation about the smallest moment is stable for a rigid body; a body that loses "
            "energy inside (flexing, sloshing) drifts to rotation about the largest moment "
            "(the major-axis rule, Explorer 1)."
        )
    if (motion.symmetry == "symmetric" and motion.oblate and motion.wobble_period is not None
            and float(motion.moments[2]) / float(motion.moments[0]) - 1.0 < EARTH_LIKE):
        out.append(
            f"rigid-body (Euler) wobble period {number(motion.wobble_period / _DAY)} d. For "
            "the Earth the observed Chandler wobble takes about 433 d: that is not a rigid-body "
            "result (the elastic mantle, the oceans and the fluid core lengthen it)."
        )
    return out


def plot_span(motion: FreeMotion, duration: float | None) -> tuple[float, float]:
    """(t0, t1), s: ``duration`` from 0, else 3 periods (or 3 characteristic times; on the
    separatrix a span that shows the flip, even if it was before t = 0)."""
    if duration is not None:
        return 0.0, float(duration)
    if motion.period is not None:
        return 0.0, 3.0 * motion.period
    el = motion.elliptic
    if el is not None:
        char = 2 * math.pi / el.lam
        tf = -el.tau0 / el.lam
        return min(0.0, tf - char), max(3.0 * char, tf + char)
    wn = float(np.linalg.norm(motion.omega0))
    return 0.0, 3.0 * (2 * math.pi / wn if wn > 0 else 1.0)


@dataclass(frozen=True)
class PlotSamples:
    """What the precess figure draws: ``t0``, ``t1``, ``t`` (s), ``omega`` (n, 3) rad/s (body
    frame), ``polhode`` (L/|L|, principal frame), ``start``, ``family`` (polhodes at a few
    energies and the separatrix) and ``flips`` (s, the flip times drawn)."""

    t0: float
    t1: float
    t: np.ndarray
    omega: np.ndarray
    polhode: np.ndarray
    start: np.ndarray
    family: list
    flips: np.ndarray


def plot_samples(motion: FreeMotion, duration: float | None) -> PlotSamples:
    """Sample the motion for the figure: 400 points a period, 1 500 to 20 000 in all."""
    t0, t1 = plot_span(motion, duration)
    per = motion.period or (t1 - t0)
    n = int(min(20000, max(1500, 400 * (t1 - t0) / per)))
    t = np.linspace(t0, t1, n)
    w = freepath.omega_at(motion, t)
    G = motion.angular_momentum_norm
    m = (freepath.omega_at(motion, t, frame="principal") * motion.moments) / G if G > 0 else np.zeros((0, 3))
    m0 = motion.omega0_principal * motion.moments / G if G > 0 else np.zeros(3)
    flips = np.zeros(0)
    if motion.flip_interval is not None and motion.first_flip is not None:
        all_flips = motion.first_flip + np.arange(0, 50) * motion.flip_interval
        flips = all_flips[(all_flips >= t0) & (all_flips <= t1)]
    return PlotSamples(t0, t1, t, w, m, m0, polhode_family(motion.moments), flips)


def polhode_family(moments: np.ndarray, levels: int = 5) -> list[np.ndarray]:
    """Polhodes on the unit L-sphere (principal frame) at a few energies, and the separatrix.

    Each curve (361, 3) is the sphere |m| = 1 cut by the energy ellipsoid
    sum m_i²/I_i = e, in closed form: around axis 3, m1 = a cos s, m2 = b sin s; around
    axis 1, m3 = c cos s, m2 = b' sin s; the third component from |m| = 1, both signs.
    Levels are picked by the point (sin β, 0, cos β) they pass through.
    """
    I1, I2, I3 = (float(x) for x in moments)
    u1, u2, u3 = 1 / I1, 1 / I2, 1 / I3
    s = np.linspace(0.0, 2 * math.pi, 361)
    curves: list[np.ndarray] = []
    if not I3 > I1:
        return curves
    sep_a2 = (u2 - u3) / (u1 - u3)  # sin² of the separatrix's β
    beta_s = math.asin(math.sqrt(min(max(sep_a2, 0.0), 1.0)))

    def close(m1, m2):
        r = np.clip(1.0 - m1 * m1 - m2 * m2, 0.0, None)
        return np.sqrt(r)

    if I3 > I2:
        for fr in np.linspace(0.0, 1.0, levels + 2)[1:-1]:
            beta = fr * beta_s
            a = math.sin(beta)
            b = math.sqrt(a * a * (u1 - u3) / (u2 - u3))
            m1, m2 = a * np.cos(s), b * np.sin(s)
            for sg in (1.0, -1.0):
                curves.append(np.column_stack([m1, m2, sg * close(m1, m2)]))
    if I2 > I1:
        for fr in np.linspace(0.0, 1.0, levels + 2)[1:-1]:
            beta = beta_s + fr * (math.pi / 2 - beta_s)
            cc = math.cos(beta)
            bb = math.sqrt(cc * cc * (u1 - u3) / (u1 - u2))
            m3, m2 = cc * np.cos(s), bb * np.sin(s)
            for sg in (1.0, -1.0):
                curves.append(np.column_stack([sg * close(m2, m3), m2, m3]))
    if I3 > I2 > I1:  # the separatrix: b = 1 around axis 3
        a = math.sqrt(sep_a2)
        m1, m2 = a * np.cos(s), np.sin(s)
        for sg in (1.0, -1.0):
            curves.append(np.column_stack([m1, m2, sg * close(m1, m2)]))
    return curves
