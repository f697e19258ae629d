"""Heavy symmetric top on a fixed pivot: the exact closed form of its motion.

Goldstein, Poole and Safko, *Classical Mechanics*, 3rd ed., §5.7; "sheet §n" names the
sections of rbcli's physics notes; elliptic integrals in Carlson's form (DLMF §19.25).
:func:`analyse` computes the constants; :mod:`rbcli.core.topbody` reduces a body to a top,
:mod:`rbcli.core.toppath` evaluates the motion, :mod:`rbcli.core.topverify` checks it.

Conventions
-----------
- ``theta`` is the tilt of the axis from the upward vertical, ``phi`` its azimuth (from
  space x towards y), ``psi`` the spin angle: ``R = Rz(phi) Ry(theta) Rz(psi)``.
- ``spin`` S is ω3 = ψ' + φ' cos θ, never ψ'.
- ``u = cos θ``; the roots of the cubic are ``u1 <= u2 <= 1 < u3``; the axis moves between
  ``θ1 = arccos u2`` and ``θ2 = arccos u1``.

The cubic is solved in ``x = u - u0`` (coefficients straight from the initial data), so
near steady precession the lower roots are as well conditioned as the data and the
elliptic formulas tend smoothly to m = 0; complementary quantities (1 - m, 1 - n, 1 - u)
are carried separately."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from rbcli.core.checks import finite, json_float
from rbcli.core.roots import brentq
from rbcli.core.topbody import TopParams
from rbcli.core.toppath import TopState, carlson_F, complete_Pi, state_at
from rbcli.errors import ParamError

#: Standard gravity, m/s^2 (SPEC §2 default of ``--g``).
STANDARD_GRAVITY = 9.80665
#: A motion whose nutation band u2 - u1 is within this many round-off units of the
#: cubic's coefficients (see ``analyse``) is reported as steady precession.
STEADY_ULPS = 1e3
#: The apex point u' = b/a within this fraction of the band of a turning point: cusps.
CUSP_RTOL = 1e-9
#: |cos θ0| below this: the axis is horizontal and the fast steady root is infinite.
HORIZONTAL_COS = 4.0 * np.finfo(float).eps


class TopInputError(ParamError, ValueError):
    """A start value of :func:`analyse` out of range; ``param`` names it (``"spin"``,
    ``"theta"``, ``"theta_dot"``, ``"phi_dot"`` or ``"g"``)."""



@dataclass(frozen=True)
class FastTop:
    """Fast-top (a² ≫ β) estimates beside the exact values (sheet §2 "Fast top"):
    ``nutation_frequency`` |a| (rad/s), ``nutation_amplitude`` (2 I m g l/(Is S)²) sin θ0 (rad,
    released from rest only), ``mean_precession_rate`` β/(2a) (rad/s), and each one's
    ``..._rel_error`` (estimate - exact)/exact (None where the exact value is 0 or undefined)."""

    nutation_frequency: float
    nutation_amplitude: float | None
    mean_precession_rate: float
    nutation_frequency_rel_error: float | None
    nutation_amplitude_rel_error: float | None
    mean_precession_rate_rel_error: float | None

    def to_json(self) -> dict:
        amp = self.nutation_amplitude
        return {
            "nutation_frequency": json_float(self.nutation_frequency),
            "nutation_amplitude_deg": None if amp is None else json_float(math.degrees(amp)),
            "mean_precession_rate": json_float(self.mean_precession_rate),
            "nutation_frequency_rel_error": json_float(self.nutation_frequency_rel_error),
            "nutation_amplitude_rel_error": json_float(self.nutation_amplitude_rel_error),
            "mean_precession_rate_rel_error": json_float(self.mean_precession_rate_rel_error),
        }


@dataclass(frozen=True)
class EllipticSolution:
    """The constants of u(t) = u1 + (u2 - u1) sn²(λ t + τ0 | m) and of φ(t), ψ(t): ``m``, ``m1``
    ((u2-u1)/(u3-u1), 1 - m), ``lam`` (1/s, ½ sqrt(β (u3 - u1))), ``tau0`` (in [-K, K]; τ = 0
    at the greatest tilt), ``am0``, ``K``, ``band`` (u2 - u1), ``one_plus_u1``,
    ``one_minus_u2``, ``cp``, ``cm`` (1/s), ``n_plus``, ``n_minus`` and their complements,
    ``Pi_plus``, ``Pi_minus`` (Π(n±|m)), and ``top_jump``, ``bottom_jump`` (±1 when the axis
    passes exactly through a pole: φ jumps by ±π there)."""

    m: float
    m1: float
    lam: float
    tau0: float
    am0: float
    K: float
    band: float
    one_plus_u1: float
    one_minus_u2: float
    cp: float
    cm: float
    n_plus: float
    n_plus1: float
    n_minus: float
    n_minus1: float
    Pi_plus: float
    Pi_minus: float
    top_jump: float = 0.0
    bottom_jump: float = 0.0


@dataclass(frozen=True)
class TopMotion:
    """The exact motion of a heavy symmetric top from a given start.

    Attributes
    ----------
    params : TopParams — mass (kg), length l (m), I and Is (kg m², about the pivot)
    spin : float — rad/s, S = ω3
    theta0, theta_dot0, phi_dot0, g — the start (rad, rad/s) and gravity (m/s²)
    a, b, alpha, beta : float — Goldstein's a = Is S/I, b = p_φ/I (1/s), α = 2E'/I,
        β = 2mgl/I (1/s²)
    u1, u2, u3 : float — roots of f(u) (u = cos θ); theta1, theta2 : rad, least and greatest tilt
    nutation_period, nutation_frequency : float or None — T_n = 2 K(m)/λ (s), 2π/T_n (rad/s)
    precession_per_nutation, spin_per_nutation : float or None — rad, Δφ and Δψ per T_n
    mean_precession_rate, mean_spin_rate : float or None — rad/s, <φ'> and <ψ'>
    steady_precession_rates, steady_nutation_frequencies : tuple of float — rad/s, (slow, fast)
        at θ0 and the small-nutation frequency about each (() below the minimum spin)
    minimum_spin_for_steady : float — rad/s, sqrt(4 I m g l cos θ0)/Is (0 for θ0 >= 90°)
    horizontal_precession_rate, critical_spin : float — rad/s, m g l/(Is S); sqrt(4 I m g l)/Is
    sleeps : bool — |S| > S_c
    apex_u : float — b/a, where φ' = 0
    path : str — "waves", "loops", "cusps" or "steady"
    steady : bool — θ1 = θ2 to round-off (the band round-off of c1 alone would open)
    fast_top : FastTop — the a² ≫ β estimates and their relative errors
    elliptic : EllipticSolution — constants used by :func:`path_at`"""

    params: TopParams
    spin: float
    theta0: float
    theta_dot0: float
    phi_dot0: float
    g: float
    a: float
    b: float
    alpha: float
    beta: float
    u1: float
    u2: float
    u3: float
    theta1: float
    theta2: float
    nutation_period: float | None
    nutation_frequency: float | None
    precession_per_nutation: float | None
    spin_per_nutation: float | None
    mean_precession_rate: float | None
    mean_spin_rate: float | None
    steady_precession_rates: tuple[float, ...]
    steady_nutation_frequencies: tuple[float, ...]
    minimum_spin_for_steady: float
    horizontal_precession_rate: float
    critical_spin: float
    sleeps: bool
    apex_u: float
    path: str
    steady: bool
    fast_top: FastTop
    elliptic: EllipticSolution = field(repr=False)

    def at(self, t) -> TopState:
        """The Euler angles and their rates at times ``t`` (s): :func:`state_at`."""
        return state_at(self, t)

    @property
    def fast_top_ratio(self) -> float:
        """a²/β = (Is S)²/(2 I m g l): the fast-top estimates hold for a²/β ≫ 1."""
        return self.a**2 / self.beta

    @property
    def steady_estimate_errors(self) -> list[float | None]:
        """(estimate - exact)/exact of each steady rate's fast-top estimate (None where the
        exact rate is 0), in the order of ``steady_precession_rates``."""
        out: list[float | None] = []
        for est, exact in zip(self.steady_estimates, self.steady_precession_rates):
            out.append(None if exact == 0.0 else (est - exact) / exact)
        return out

    @property
    def steady_estimates(self) -> list[float]:
        """Fast-top estimates of the steady rates (a² ≫ β), rad/s: slow ≈ m g l/(Is S),
        fast ≈ Is S/(I cos θ0); only the slow one for a horizontal axis. Goldstein §5.7."""
        p = self.params
        out = [self.horizontal_precession_rate]
        if len(self.steady_precession_rates) == 2:
            out.append(p.Is * self.spin / (p.I * math.cos(self.theta0)))
        return out

    def to_json(self) -> dict:
        """SPEC §3 ``top`` keys (SI, angles in degrees under ``*_deg``), plus extras."""
        p = self.params
        return {
            "mass": float(p.mass),
            "length": float(p.length),
            "I": float(p.I),
            "Is": float(p.Is),
            "spin": float(self.spin),
            "steady_precession_rates": [float(r) for r in self.steady_precession_rates],
            "horizontal_precession_rate": json_float(self.horizontal_precession_rate),
            "critical_spin": json_float(self.critical_spin),
            "theta1_deg": json_float(math.degrees(self.theta1)),
            "theta2_deg": json_float(math.degrees(self.theta2)),
            "nutation_period": json_float(self.nutation_period),
            "mean_precession_rate": json_float(self.mean_precession_rate),
            "path": self.path,
            # extras
            "g": float(self.g),
            "theta0_deg": math.degrees(self.theta0),
            "theta_dot0": float(self.theta_dot0),
            "phi_dot0": float(self.phi_dot0),
            "steady": bool(self.steady),
            "sleeps": bool(self.sleeps),
            "minimum_spin_for_steady": json_float(self.minimum_spin_for_steady),
            "steady_nutation_frequencies": [float(r) for r in self.steady_nutation_frequencies],
            "nutation_amplitude_deg": json_float(math.degrees(self.theta2 - self.theta1)),
            "nutation_frequency": json_float(self.nutation_frequency),
            "mean_spin_rate": json_float(self.mean_spin_rate),
            "precession_per_nutation": json_float(self.precession_per_nutation),
            "spin_per_nutation": json_float(self.spin_per_nutation),
            "goldstein": {
                "a": float(self.a),
                "b": float(self.b),
                "alpha": float(self.alpha),
                "beta": float(self.beta),
            },
            "turning_points": [float(self.u1), float(self.u2), float(self.u3)],
            "elliptic_parameter": float(self.elliptic.m),
            "apex_u": json_float(self.apex_u),
            "fast_top": self.fast_top.to_json(),
        }


def _cubic_roots_shifted(
    c0: float, c1: float, c2: float, beta: float, lo: float, hi: float, f_lo: float, f_hi: float
) -> tuple[float, float, float]:
    """Roots x1 <= 0 <= x2 < x3 of P(x) = β x³ + c2 x² + c1 x + c0, c0 >= 0.

    ``lo = -(1 + u0)`` and ``hi = 1 - u0`` bracket x1 and x2 (u = ±1); ``f_lo`` and ``f_hi``
    are the exact values -(b + a)² and -(b - a)² there.
    """

    def P(x: float) -> float:
        return ((beta * x + c2) * x + c1) * x + c0

    def dP(x: float) -> float:
        return (3.0 * beta * x + 2.0 * c2) * x + c1

    if c0 == 0.0:
        # x = 0 is a root (released with θ0' = 0, sheet §2 "Released from rest"): deflate.
        disc = c2 * c2 - 4.0 * beta * c1
        if math.isfinite(disc):
            root = math.sqrt(max(disc, 0.0))
        else:  # c2² overflows (rates ~1e152 and up): |c2| sqrt(1 - 4 β c1/c2²)
            root = abs(c2) * math.sqrt(max(1.0 - 4.0 * beta * (c1 / c2) / c2, 0.0))
        q = -0.5 * (c2 + math.copysign(root, c2))
        ra = q / beta
        rb = c1 / q if q != 0.0 else 0.0
        x1, x2, x3 = sorted((0.0, ra, rb))
        return x1, x2, x3

    def bracketed(a_: float, fa: float, b_: float, fb: float) -> float:
        if fa == 0.0:
            return a_
        if fb == 0.0:
            return b_

        def g(x: float) -> float:
            if x == a_:
                return fa
            if x == b_:
                return fb
            return P(x)

        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # extreme starts
            return float(brentq(g, a_, b_, xtol=1e-300, rtol=4.0 * np.finfo(float).eps, maxiter=500))

    def next_to_zero(lo_: float, hi_: float) -> float | None:
        # The root beside x = 0 when P is linear there to round-off: x0 = -c0/c1 with
        # |c2 x0| + |β x0²| <= eps/2 |c1| is the root to within rounding (P(x0)/c1 is below
        # half an ulp of x0): with θ0' tiny beside the other rates (c0 ~ 1e-300) P is
        # subnormal there and Brent's method would creep in steps of xtol/2.
        if c1 == 0.0:
            return None
        x0 = -c0 / c1
        if lo_ <= x0 <= hi_ and abs(c2 * x0) + abs(beta * x0 * x0) <= 0.5 * np.finfo(float).eps * abs(c1):
            return x0
        return None

    x1 = next_to_zero(lo, 0.0)
    if x1 is None:
        x1 = bracketed(lo, f_lo, 0.0, c0)
    x2 = next_to_zero(0.0, hi)
    if x2 is None:
        x2 = bracketed(0.0, c0, hi, f_hi)

    x3 = -c2 / beta - x1 - x2  # Vieta
    for _ in range(3):  # Newton polish of the isolated large root
        d = dP(x3)
        p = P(x3)
        if not (math.isfinite(d) and math.isfinite(p)):
            # β x3³ overflows (a large root, ~1e103 and up): the same step from
            # P(x)/x³ = β + c2 t + c1 t² + c0 t³ and P'(x)/x² = 3β + 2 c2 t + c1 t², t = 1/x
            t = 1.0 / x3
            d = (c1 * t + 2.0 * c2) * t + 3.0 * beta
            if d == 0.0:
                break
            step = x3 * ((((c0 * t + c1) * t + c2) * t + beta) / d)
        elif d == 0.0:
            break
        else:
            step = p / d
        x3 -= step
        if abs(step) <= 1e-16 * abs(x3):
            break
    return x1, x2, x3


def _require_representable(
    thd: float, w_s0: float, a: float, beta: float, g: float, given: tuple[float, float, float],
    c0: float, c1: float, c2: float, bpa: float, bma: float,
) -> None:
    """Refuse, naming the parameter, a start whose turning-point cubic is beyond doubles:
    |c0| + 2|c1| + 4|c2| + 8β, (b ± a)² and u3 ≈ -c2/β must be finite (the cubic is evaluated
    on |x| <= 2). Blamed: the dominant rate (θ0', φ0' sin θ0, a, sqrt(β)), or g when β
    underflows.
    """
    size = abs(c0) + 2.0 * abs(c1) + 4.0 * abs(c2) + 8.0 * beta + bpa * bpa + bma * bma
    tiny = not beta >= np.finfo(float).tiny
    if math.isfinite(size) and not tiny and math.isfinite(c2 / beta):
        return
    S, thd_given, w_given = given
    if tiny:
        raise TopInputError(
            "g", f"gravity {g:.6g} m/s² is too small for the top's equations: "
            "β = 2 m g l/I underflows double precision; give a value of a physical size")
    rates = {"theta_dot": abs(thd), "phi_dot": abs(w_s0), "spin": abs(a), "g": math.sqrt(beta)}
    param = max(rates, key=lambda k: rates[k])
    what = {"theta_dot": f"the initial tilt rate {thd_given:.6g} rad/s",
            "phi_dot": f"the initial precession rate {w_given:.6g} rad/s",
            "spin": f"the spin {S:.6g} rad/s",
            "g": f"gravity {g:.6g} m/s²"}[param]
    if math.isfinite(size):
        why = ("the top's energy is more than 1e308 times the range of its potential energy, so "
               "the third turning point u3 of its motion overflows double precision")
    else:
        why = ("the squares of the rates (the energy per unit moment) overflow double "
               "precision in the top's equations")
    raise TopInputError(param, f"{what} is too large: {why}; give a value of a physical size")


def _pole_root(e0: float, e1: float, e2: float, e3: float, d: float) -> float:
    """Polish the small root d >= 0 of e0 + e1 d + e2 d² + e3 d³ (f about a pole) by Newton."""
    for _ in range(60):
        g = ((e3 * d + e2) * d + e1) * d + e0
        dg = (3.0 * e3 * d + 2.0 * e2) * d + e1
        if dg == 0.0:
            break
        new = max(d - g / dg, 0.0)
        if new == d or abs(new - d) <= 1e-15 * max(d, new):
            d = new
            break
        d = new
    return d


def _checked_start(spin: float, theta0: float, theta_dot0: float, phi_dot0: float,
                   g: float) -> tuple[float, float, float, float, float]:
    """The start of :func:`analyse` as finite floats, refused (naming the parameter) when it
    is not a top's: θ0 not in (0, π), g <= 0, no spin."""
    def start(param: str, name: str, x: float) -> float:
        try:
            return finite(name, x)
        except ValueError as exc:
            raise TopInputError(param, str(exc)) from None

    S = start("spin", "spin", spin)
    th0 = start("theta", "theta0", theta0)
    thd = start("theta_dot", "theta_dot0", theta_dot0)
    w = start("phi_dot", "phi_dot0", phi_dot0)
    gg = start("g", "g", g)
    if not (0.0 < th0 < math.pi):
        raise TopInputError(
            "theta",
            f"the initial tilt theta0 must be strictly between 0 and 180 degrees, not "
            f"{math.degrees(th0):.6g} deg (at 0 or 180 the axis is vertical and the "
            "precession angle is undefined; start it slightly tilted)"
        )
    if gg <= 0.0:
        raise TopInputError("g", f"gravity g must be positive, not {gg}")
    if S == 0.0:
        raise TopInputError(
            "spin",
            "the spin is 0: a top without spin is a spherical pendulum, not a top; "
            "give a nonzero spin"
        )
    return S, th0, thd, w, gg


def analyse(
    params: TopParams,
    spin: float,
    theta0: float,
    theta_dot0: float = 0.0,
    phi_dot0: float = 0.0,
    g: float = STANDARD_GRAVITY,
) -> TopMotion:
    """The exact motion of a heavy symmetric top: turning points, periods, rates, path.

    Parameters
    ----------
    params : TopParams — mass (kg), l (m), I and Is about the pivot (kg m²)
    spin : float — rad/s, S = ω3, nonzero
    theta0 : float — rad, initial tilt from the upward vertical, in (0, π)
    theta_dot0, phi_dot0 : float — rad/s, initial θ' and φ' (default 0)
    g : float — m/s², > 0

    Raises
    ------
    TopInputError
        (a ParamError) θ0 outside (0, π), g <= 0, spin 0 or a non-finite input.

    Notes
    -----
    Sheet §2. a = Is S/I, β = 2 m g l/I, b = φ0' sin²θ0 + a u0, α = θ0'² + φ0'² sin²θ0 + β u0;
    f(u) = (1-u²)(α-βu) - (b-au)², solved in x = u - u0 (P(x) = βx³ + c2 x² + c1 x + c0,
    c0 = sin²θ0 θ0'²): x = 0 is exact for θ0' = 0, else x1, x2 by Brent to 4 ulp, x3 by Vieta
    and Newton. m = (u2-u1)/(u3-u1), λ = ½ sqrt(β(u3-u1)), T_n = 2K(m)/λ,
    <φ'> = [cp Π(n+|m) + cm Π(-n-|m)]/K, <ψ'> = S - a - [cp Π(n+|m) - cm Π(-n-|m)]/K with
    cp = (b-a)/(2(1-u1)), cm = (b+a)/(2(1+u1)), n± = (u2-u1)/(1∓u1). Steady rates:
    q = ½(Is S + sign(Is S) sqrt(Is²S² - 4 I m g l cos θ0)), φ'_slow = m g l/q,
    φ'_fast = q/(I cos θ0); small nutation ω² = (a - 2φ' cos θ)² + φ'² sin²θ. The path
    compares b/a with [u1, u2] (within CUSP_RTOL: cusps; inside: loops; else waves). Near a
    pole 1 - u2 is re-solved from f expanded about u = ±1; an axis through the pole (b = ±a)
    adds the azimuth's jump of π to φ."""
    S, th0, thd, w, gg = _checked_start(spin, theta0, theta_dot0, phi_dot0, g)
    m_, l_, I, Is = params.mass, params.length, params.I, params.Is
    mgl = m_ * gg * l_
    slow = mgl / (Is * S)  # m g l/(Is S): the horizontal (and fast-top) precession rate
    if not (math.isfinite(slow * slow) and math.isfinite(2.0 * I * slow / (Is * S))):
        raise TopInputError(
            "spin",
            f"the spin {S:.6g} rad/s is too small against gravity for the top's equations: "
            f"its precession rate m g l/(Is S) overflows double precision; give a spin of a "
            "physical size (without spin the body is a spherical pendulum, not a top)"
        )

    u0 = math.cos(th0)
    s0 = math.sin(th0)
    s0sq = s0 * s0
    omu0 = 2.0 * math.sin(0.5 * th0) ** 2  # 1 - u0 without cancellation
    opu0 = 2.0 * math.cos(0.5 * th0) ** 2  # 1 + u0

    a = Is * S / I
    beta = 2.0 * mgl / I
    A0 = thd * thd + w * w * s0sq  # α - β u0
    B0 = w * s0sq  # b - a u0
    b = B0 + a * u0
    alpha = A0 + beta * u0

    c0 = s0sq * thd * thd
    c1 = -beta * s0sq - 2.0 * u0 * A0 + 2.0 * a * B0
    c2 = 2.0 * u0 * beta - A0 - a * a
    bpa = B0 + a * opu0  # b + a
    bma = B0 - a * omu0  # b - a
    _require_representable(thd, w * s0, a, beta, gg, (S, thd, w), c0, c1, c2, bpa, bma)
    x1, x2, x3 = _cubic_roots_shifted(c0, c1, c2, beta, -opu0, omu0, -(bpa**2), -(bma**2))
    # a root exactly at u = ±1 (the axis passes through a pole): snap it there
    x1 = -opu0 if bpa == 0.0 else max(x1, -opu0)
    x2 = omu0 if bma == 0.0 else min(x2, omu0)
    band = x2 - x1
    span = x3 - x1
    m = band / span
    m1 = (x3 - x2) / span
    lam = 0.5 * math.sqrt(beta * span)
    omu1, opu1 = omu0 - x1, opu0 + x1
    omu2, opu2 = omu0 - x2, opu0 + x2
    # Near a pole, 1 - u2 (or 1 + u1) can be far below the ulp of u: it is ~(b ∓ a)²/|f'|.
    # Re-solve for it with f expanded about u = ±1, whose coefficients are exact.
    near = 1e-3 * band
    if 0.0 < omu2 < near and not (c0 == 0.0 and x2 == 0.0):
        A1 = A0 - beta * omu0  # α - β
        omu2 = _pole_root(
            -(bma**2), 2.0 * (A1 - a * bma), 2.0 * beta - A1 - a * a, -beta, omu2
        )
    if 0.0 < opu1 < near and not (c0 == 0.0 and x1 == 0.0):
        A2 = A0 + beta * opu0  # α + β
        opu1 = _pole_root(
            -(bpa**2), 2.0 * (A2 + a * bpa), -2.0 * beta - A2 - a * a, beta, opu1
        )
    u1, u2, u3 = u0 + x1, u0 + x2, u0 + x3

    def tilt(one_minus: float, one_plus: float) -> float:
        return 2.0 * math.atan2(math.sqrt(max(one_minus, 0.0)), math.sqrt(max(one_plus, 0.0)))

    theta1 = tilt(omu2, opu2)
    theta2 = tilt(omu1, opu1)

    # The axis through the upward (u2 = 1, b = a) or downward (u1 = -1, b = -a) vertical:
    # φ jumps by π once per nutation period (ψ by ∓π) and that pole's Π term (0 × ∞) is
    # dropped. The jump's sign is that of b - a (resp. b + a); + when it is exactly zero.
    top_pass = omu2 <= 0.0
    bottom_pass = opu1 <= 0.0
    top_sign = -1.0 if bma < 0.0 else 1.0
    bottom_sign = -1.0 if bpa < 0.0 else 1.0

    # elliptic constants
    cp = bma / (2.0 * omu1) if not top_pass else 0.0
    cm = bpa / (2.0 * opu1) if not bottom_pass else 0.0
    n_plus, n_plus1 = band / omu1, omu2 / omu1
    if opu1 > 0.0:
        n_minus, n_minus1 = -band / opu1, opu2 / opu1
    else:
        n_minus, n_minus1 = 0.0, 1.0  # u1 = -1 exactly: cm = 0, the term drops out
    K = complete_Pi(0.0, 1.0, m1)
    Pi_p = complete_Pi(n_plus, n_plus1, m1) if cp != 0.0 else K
    Pi_m = complete_Pi(n_minus, n_minus1, m1) if cm != 0.0 else K
    jt = top_sign if top_pass else 0.0
    jb = bottom_sign if bottom_pass else 0.0
    T_n, nut_freq, mean_phi, mean_psi = _mean_rates(K, lam, cp * Pi_p if cp != 0.0 else 0.0,
                                                    cm * Pi_m if cm != 0.0 else 0.0, jt, jb, S - a)
    dphi = None if T_n is None else mean_phi * T_n  # type: ignore[operator]
    dpsi = None if T_n is None else mean_psi * T_n  # type: ignore[operator]

    am0, F0 = _phase(x1, x2, m1, thd)
    ell = EllipticSolution(
        m=m, m1=m1, lam=lam, tau0=F0, am0=am0, K=K, band=band, one_plus_u1=opu1,
        one_minus_u2=omu2, cp=cp, cm=cm, n_plus=n_plus, n_plus1=n_plus1, n_minus=n_minus,
        n_minus1=n_minus1, Pi_plus=Pi_p, Pi_minus=Pi_m, top_jump=jt, bottom_jump=jb,
    )  # fmt: skip

    IsS = Is * S
    rates, nut_steady, min_spin, S_c = _steady(I, Is, S, a, mgl, u0, s0)
    xstar = B0 / a  # u' - u0, where φ' = 0
    c1_scale = beta * s0sq + 2.0 * abs(u0) * A0 + 2.0 * abs(a * B0)
    band_noise = np.finfo(float).eps * c1_scale / (abs(c2) + beta * omu0)
    steady = band <= STEADY_ULPS * band_noise
    path = _path(steady, top_pass or bottom_pass, xstar, x1, x2, (bma / a, bpa / a))
    released = thd == 0.0 and w == 0.0
    fast = _fast_top(a, mgl / IsS, (2.0 * I * mgl / IsS**2) * s0 if released else None,
                     nut_freq, theta2 - theta1, mean_phi)

    return TopMotion(
        params=params, spin=S, theta0=th0, theta_dot0=thd, phi_dot0=w, g=gg,
        a=a, b=b, alpha=alpha, beta=beta, u1=u1, u2=u2, u3=u3,
        theta1=theta1, theta2=theta2, nutation_period=T_n, nutation_frequency=nut_freq,
        precession_per_nutation=dphi, spin_per_nutation=dpsi,
        mean_precession_rate=mean_phi, mean_spin_rate=mean_psi,
        steady_precession_rates=rates, steady_nutation_frequencies=nut_steady,
        minimum_spin_for_steady=min_spin, horizontal_precession_rate=mgl / IsS,
        critical_spin=S_c, sleeps=abs(S) > S_c, apex_u=u0 + xstar, path=path,
        steady=steady, fast_top=fast, elliptic=ell,
    )  # fmt: skip


def _steady(I: float, Is: float, S: float, a: float, mgl: float, cos0: float,
            s0: float) -> tuple[tuple[float, ...], tuple[float, ...], float, float]:
    """Steady precession at θ0 (sheet §2 "Steady precession"): its rates (slow, fast), the
    frequencies of a small nutation about each, the least spin for it and the critical
    spin of a sleeping top."""
    IsS = Is * S
    if abs(cos0) <= HORIZONTAL_COS:
        rates: tuple[float, ...] = (mgl / IsS,)
    else:
        D = IsS * IsS - 4.0 * I * mgl * cos0
        if D >= 0.0:
            q = 0.5 * (IsS + math.copysign(math.sqrt(D), IsS))
            rates = (mgl / q, q / (I * cos0))
        else:
            rates = ()
    nut_steady = tuple(
        math.sqrt((a - 2.0 * r_ * cos0) ** 2 + (r_ * s0) ** 2) for r_ in rates
    )
    min_spin = math.sqrt(4.0 * I * mgl * cos0) / Is if cos0 > HORIZONTAL_COS else 0.0
    return rates, nut_steady, min_spin, math.sqrt(4.0 * I * mgl) / Is


def _path(steady: bool, passes_pole: bool, xstar: float, x1: float, x2: float,
          pole_apex: tuple[float, float]) -> str:
    """The kind of path (sheet §2 "Locus of the symmetry-axis apex"): where the apex point
    u' = b/a (``xstar`` = u' - u0) lies against the band [x1, x2]; ``pole_apex``:
    ((b - a)/a, (b + a)/a)."""
    tol = CUSP_RTOL * (x2 - x1)
    if steady:
        return "steady"  # θ stays at θ0 (JSON and tables say the same)
    if passes_pole or abs(pole_apex[0]) <= tol or abs(pole_apex[1]) <= tol:
        # the apex u' = b/a at a pole: φ' = (b - au)/(1 - u²) = ±a/(1 ± u) does not vanish
        # (or only on a loop too small to see); the axis passes through the vertical
        return "waves"
    if abs(xstar - x2) <= tol or abs(xstar - x1) <= tol:
        return "cusps"
    return "loops" if x1 < xstar < x2 else "waves"


def _fast_top(a: float, precession: float, amplitude: float | None, nut_freq: float | None,
              exact_amp: float, mean_phi: float | None) -> FastTop:
    """The fast-top estimates (sheet §2 "Fast top") and their errors against the exact
    motion's nutation frequency and amplitude and mean precession rate."""

    def rel(est: float | None, exact: float | None) -> float | None:
        if est is None or exact is None or exact == 0.0:
            return None
        return (est - exact) / exact

    return FastTop(
        nutation_frequency=abs(a),
        nutation_amplitude=amplitude,
        mean_precession_rate=precession,
        nutation_frequency_rel_error=rel(abs(a), nut_freq),
        nutation_amplitude_rel_error=rel(amplitude, exact_amp),
        mean_precession_rate_rel_error=rel(precession, mean_phi),
    )


def _mean_rates(K: float, lam: float, term_p: float, term_m: float, jt: float, jb: float,
                spin_less_a: float) -> tuple[float | None, float | None, float | None, float | None]:
    """T_n, 2π/T_n, <φ'> and <ψ'> as in :func:`analyse` (``term_p``, ``term_m``: cp Π(n+|m)
    and cm Π(-n-|m)), with the pole jumps ``jt``, ``jb``; all None on the separatrix (K = ∞)."""
    if not math.isfinite(K):
        return None, None, None, None
    T_n = 2.0 * K / lam
    jump = 0.5 * math.pi * lam  # π per nutation period, in the units of term/K * K
    mean_phi = (term_p + term_m + jump * (jt + jb)) / K
    mean_psi = spin_less_a - (term_p - term_m + jump * (jt - jb)) / K
    return T_n, 2.0 * math.pi / T_n, mean_phi, mean_psi


def _phase(x1: float, x2: float, m1: float, theta_dot: float) -> tuple[float, float]:
    """The phase at t = 0: the amplitude am(τ0) and τ0 = F(am | m) from sn²(τ0) = -x1/band
    and cn²(τ0) = x2/band; τ0 in [-K, 0] while θ increases (u decreasing)."""
    band = x2 - x1
    if not band > 0.0:
        return 0.0, 0.0
    r, r1 = -x1 / band, x2 / band  # sn²(τ0) and cn²(τ0)
    am0 = math.atan2(math.sqrt(max(r, 0.0)), math.sqrt(max(r1, 0.0)))
    F0 = float(carlson_F(np.asarray(am0), m1))
    return (-am0, -F0) if theta_dot > 0.0 else (am0, F0)
