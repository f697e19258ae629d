"""Tables, the figure and the CSV rows of ``rbcli top`` (a TopResult and its sampled
:class:`rbcli.core.toppath.TopState`); tables of ``rbcli gyrocompass``."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from rbcli.render.fmt import num, said
from rbcli.render.plots import figure, style
from rbcli.render.units import RPM, DisplayUnits

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.render.text import Doc  # hints only: --json never loads render.text
    from rbcli.api.gyrocompass import GyrocompassResult
    from rbcli.api.top import TopResult
    from rbcli.core.toppath import TopState

EPS = float(np.finfo(float).eps)

PATHS = {
    "cusps": "cusps: the axis stops (φ' = 0) at each least tilt θ1 and falls again — a top "
             "released from rest",
    "loops": "loops: φ' reverses inside the band, so the tip of the axis draws loops",
    "waves": "waves: φ' keeps its sign, the tip of the axis undulates between θ1 and θ2",
    "steady": "steady precession: θ stays at θ0 and the axis turns at a constant rate",
}


# --- tables


def _deg(x: float | None, digits: int) -> str:
    return "—" if x is None else num(math.degrees(x), digits)


def _pct(rel: float | None) -> str:
    return "—" if rel is None else f"{num(100.0 * rel, 3)} %"


def document(doc: Doc, result: TopResult, du: DisplayUnits, digits: int, *, plot: str | None = None,
             csv: str | None = None, rows: int | None = None, duration: float | None = None) -> None:
    """The tables of ``rbcli top``; ``plot``, ``csv`` (with its ``rows`` and ``duration``, s)
    name the files written, for the closing notes."""
    motion = result.motion
    check = result.verify
    p = motion.params
    b, du = result.body, du.of(result.body)
    M, L, J = du.unit("mass"), du.unit("length"), du.unit("inertia")
    d = digits
    doc.heading(f"{b.name}  ({b.source})")
    rows = [
        ("mass m", du.show(p.mass, "mass", d), M),
        ("pivot to com l", du.show(p.length, "length", d), L),
        ("I, about the pivot, across the axis", du.show(p.I, "inertia", d), J),
        ("I − m l², about the com, across the axis", du.show(result.I_com, "inertia", d), J),
        ("Is, about the axis", du.show(p.Is, "inertia", d), J),
        ("g", du.show(motion.g, "acceleration", d), du.unit("acceleration")),
    ]
    doc.kv("top", rows)
    piv = ", ".join(du.show(x, "length", d) for x in (p.pivot or (0.0, 0.0, 0.0)))
    ax = ", ".join(num(x, d) for x in (p.axis or (0.0, 0.0, 1.0)))
    doc.note(f"pivot [{piv}] {L} ({said(result.pivot_source)}); symmetry axis, pivot to com, along [{ax}] "
             "(body frame).")
    if result.asymmetry is not None:
        asymmetry_note(doc, result.asymmetry, result.options.symmetry_tol, result.asymmetry_effect,
                        du, d, "body", "I")

    S = motion.spin
    start = [
        ("spin S = ω3 (along the axis)", num(S, d), "rad/s"),
        ("spin S", num(S * RPM, d), "rpm"),
        ("tilt θ0 from the upward vertical", _deg(motion.theta0, d), "°"),
        ("θ0'", num(motion.theta_dot0, d), "rad/s"),
        ("φ0'", num(motion.phi_dot0, d), "rad/s"),
    ]
    released = motion.theta_dot0 == 0.0 and motion.phi_dot0 == 0.0
    doc.kv("start" + (" (released from rest)" if released else ""), start)

    th0 = _deg(motion.theta0, d)
    rates = motion.steady_precession_rates
    rows = []
    if len(rates) == 2:
        rows += [
            ("slow rate φ'", num(rates[0], d), "rad/s"),
            ("fast rate φ'", num(rates[1], d), "rad/s"),
            ("small-nutation frequency about the slow rate", num(motion.steady_nutation_frequencies[0], d), "rad/s"),
            ("small-nutation frequency about the fast rate", num(motion.steady_nutation_frequencies[1], d), "rad/s"),
        ]
    elif len(rates) == 1:
        rows += [
            ("rate φ' (axis horizontal: one rate)", num(rates[0], d), "rad/s"),
            ("small-nutation frequency about it", num(motion.steady_nutation_frequencies[0], d), "rad/s"),
        ]
    else:
        rows.append(("rates φ'", "none", ""))
    if motion.minimum_spin_for_steady > 0.0:
        rows.append(("least |S| for steady precession at θ0", num(motion.minimum_spin_for_steady, d), "rad/s"))
    rows.append(("horizontal-axis rate m g l/(Is S)", num(motion.horizontal_precession_rate, d), "rad/s"))
    doc.kv(f"steady precession at θ0 = {th0}°", rows)
    if not rates:
        doc.note(f"no steady precession at {th0}°: |S| = {num(abs(S), d)} rad/s is below "
                 f"{num(motion.minimum_spin_for_steady, d)} rad/s = √(4 I m g l cos θ0)/Is.")

    sc = motion.critical_spin
    doc.kv("sleeping top (spinning upright)", [
        ("critical spin S_c = √(4 I m g l)/Is", num(sc, d), "rad/s"),
        ("critical spin S_c", num(sc * RPM, d), "rpm"),
        ("|S| / S_c", num(abs(S) / sc, d), ""),
        ("sleeps", "yes" if motion.sleeps else "no", ""),
    ])
    doc.note(("an upright start at this spin stays upright (|S| > S_c)." if motion.sleeps else
              "an upright start at this spin falls away from the vertical (|S| <= S_c)."))

    kind = "steady" if motion.steady else motion.path
    tn = motion.nutation_period
    rows = [
        ("least tilt θ1", _deg(motion.theta1, d), "°"),
        ("greatest tilt θ2", _deg(motion.theta2, d), "°"),
        ("nutation amplitude θ2 − θ1", _deg(motion.theta2 - motion.theta1, d), "°"),
        ("nutation period T_n", du.show(tn, "time", d), du.unit("time")),
        ("nutation frequency 2π/T_n", num(motion.nutation_frequency, d), "rad/s"),
        ("mean precession rate <φ'>", num(motion.mean_precession_rate, d), "rad/s"),
        ("precession per nutation Δφ", _deg(motion.precession_per_nutation, d), "°"),
        ("mean spin rate <ψ'>", num(motion.mean_spin_rate, d), "rad/s"),
        ("path of the axis tip", "steady precession" if motion.steady else motion.path, ""),
    ]
    doc.kv("motion from this start (exact)", rows)
    doc.note(PATHS[kind] + ".")
    if tn is None:
        doc.note("the motion is on the separatrix: the axis creeps towards the vertical in "
                 "infinite time (no nutation period).")

    ratio = motion.fast_top_ratio
    ft = motion.fast_top
    trows = [
        ("nutation frequency", num(motion.nutation_frequency, d), num(ft.nutation_frequency, d),
         _pct(ft.nutation_frequency_rel_error), "rad/s"),
    ]
    if ft.nutation_amplitude is not None:
        trows.append(("nutation amplitude θ2 − θ1", _deg(motion.theta2 - motion.theta1, d),
                      _deg(ft.nutation_amplitude, d), _pct(ft.nutation_amplitude_rel_error), "°"))
    trows.append(("mean precession rate", num(motion.mean_precession_rate, d),
                  num(ft.mean_precession_rate, d), _pct(ft.mean_precession_rate_rel_error), "rad/s"))
    if rates:
        names = ("steady slow rate", "steady fast rate") if len(rates) == 2 else ("steady rate",)
        for name, exact, e_, err in zip(names, rates, motion.steady_estimates, motion.steady_estimate_errors):
            trows.append((name, num(exact, d), num(e_, d), _pct(err), "rad/s"))
    doc.table(f"fast-top estimates beside the exact values (a²/β = {num(ratio, 3)}; they hold for a²/β ≫ 1)",
              ("quantity", "exact", "estimate", "error", "unit"), trows, right=(1, 2, 3))
    doc.note("estimates: nutation frequency a = Is S/I; amplitude (2 I m g l/(Is S)²) sin θ0 "
             "(released from rest only); mean precession m g l/(Is S); steady rates m g l/(Is S) "
             "and Is S/(I cos θ0). error = (estimate − exact)/exact.")
    loss = EPS * ratio
    if loss > 1e-9 and motion.mean_precession_rate is not None:
        doc.note(f"precision: at a²/β = {num(ratio, 3)} the exact mean precession is a small "
                 f"difference of large terms, good to about {loss:.0e} relative; the fast-top "
                 f"estimate is good to about β/a² = {1.0 / ratio:.0e} here.")

    doc.kv("closed form (Goldstein §5.7; u = cos θ)", [
        ("a = Is S/I", num(motion.a, d), "1/s"),
        ("b = p_φ/I", num(motion.b, d, abs(motion.a)), "1/s"),  # round-off: of a, and of a² + β
        ("α = 2E'/I", num(motion.alpha, d, motion.a ** 2 + abs(motion.beta)), "1/s²"),
        ("β = 2 m g l/I", num(motion.beta, d), "1/s²"),
        ("turning points u1, u2, u3", ", ".join(num(x, d, 1.0) for x in (motion.u1, motion.u2, motion.u3)), ""),
        ("elliptic parameter m", num(motion.elliptic.m, d), ""),
    ])

    if check is not None:
        _verify(doc, result, d)
    if plot is not None:
        doc.note(f"plot written to {plot}")
    if csv is not None:
        doc.note(f"CSV written to {csv} ({rows} rows over {num(duration, d)} s)")


def _verify(doc: Doc, result: TopResult, d: int) -> None:
    """The tables of ``--verify``: the closed form against the integration (and the real
    body's, for a nearly symmetric one)."""
    check = result.verify
    ok = check.passed
    doc.kv(
        f"--verify: numerical integration (DOP853, rtol {check.rtol:g}, "
        f"{num(check.t_end, 4)} s, {check.samples} samples)",
        [
            ("largest difference of the axis (chord)", f"{check.max_axis_error:.2e}", "rad"),
            ("largest difference of θ", f"{check.max_theta_error * 180 / math.pi:.2e}", "°"),
            ("largest difference of φ", f"{check.max_phi_error * 180 / math.pi:.2e}", "°"),
            ("largest difference of ψ", f"{check.max_psi_error * 180 / math.pi:.2e}", "°"),
            ("energy drift", f"{check.energy_drift:.2e}", "relative"),
            ("drift of p_φ = L·z", f"{check.p_phi_drift:.2e}", "relative"),
            ("drift of p_ψ = L·e3", f"{check.p_psi_drift:.2e}", "relative"),
            ("θ range integrated", f"{_deg(check.theta_min, d)} to {_deg(check.theta_max, d)}", "°"),
            ("mean precession integrated", num(check.mean_precession_rate, d), "rad/s"),
            ("verdict", "PASS" if ok else "FAIL", ""),
        ],
    )
    rb = result.real_body
    if rb is not None:
        doc.kv("--verify: the real (unsymmetrised) body against the symmetrised closed form", [
            ("largest difference of the axis (chord)", f"{rb.max_axis_error:.2e}", "rad"),
            ("largest difference of θ", f"{rb.max_theta_error * 180 / math.pi:.2e}", "°"),
            ("largest difference of φ", f"{rb.max_phi_error * 180 / math.pi:.2e}", "°"),
            ("energy drift of that integration", f"{rb.energy_drift:.2e}", "relative"),
        ])
        doc.note("the effect of the asymmetry on the motion over the same span (quaternion and "
                 "ω in body axes with the full inertia tensor about the pivot, DOP853); it "
                 "does not enter the verdict.")
    doc.note(f"the check passes when the axis agrees within {check.axis_tolerance:g} rad and "
             f"the energy drifts by at most {check.energy_tolerance:g} (relative to T0 + m g l); "
             "integrated in space axes (axis, a body vector and L), no Euler angles.")


def asymmetry_note(doc: Doc, sym, tol: float, effect: float, du: DisplayUnits, d: int, what: str,
                    name: str) -> None:
    """The line of a nearly symmetric body (top's, gyrocompass's and rollcheck's): its two
    moments across, how far apart, the tilt of the nearest principal axis, and how far the
    answer may be off (``effect``, relative)."""
    J = du.unit("inertia")
    i1, i2 = (du.show(x, "inertia", d) for x in sym.transverse)
    tilt = f"; the nearest principal axis is {sym.principal_tilt:.3g} rad off it" if sym.coupling else ""
    doc.note(f"nearly symmetric {what}: the moments across the axis are {i1} and {i2} {J} (differ by "
             f"{num(100.0 * sym.relative, 3)} %{tilt}; --symmetry-tol {num(100.0 * tol, 3)} %): the "
             f"answer is for the symmetrised {what} ({name} = their mean) and may be off by a relative "
             f"amount of the order of {num(100.0 * effect, 2)} %"
             + _TAILS.get(what, "."))


#: what :func:`asymmetry_note` adds after "may be off by ..." for each command's body
_TAILS = {
    "body": " (the path of the axis by a few times that tilt; --verify measures it).",
    "wheel": " (the critical spin and speed; the centre of mass is taken on the axle).",
}


# --- CSV


#: the columns of ``top --csv``
CSV_HEADER = ("t", "theta_deg", "phi_deg", "psi_deg")


def csv_block(state: TopState) -> np.ndarray:
    """The CSV rows t, theta, phi, psi (s, degrees) of the motion sampled at some times."""
    return np.column_stack([state.t, np.degrees(state.theta), np.degrees(state.phi), np.degrees(state.psi)])


# --- plot


def plot(result: TopResult, state: TopState, duration: float):
    """The path of the axis tip: θ against φ (up is up) and the view from above, θ1 and
    θ2 marked; ``state`` is the motion sampled over ``duration`` seconds from the start
    (:meth:`rbcli.api.top.TopResult.sample`)."""
    motion = result.motion
    theta, phi = state.theta, state.phi
    th_d, ph_d = np.degrees(theta), np.degrees(phi)
    t1, t2 = math.degrees(motion.theta1), math.degrees(motion.theta2)
    kind = "steady precession" if motion.steady else motion.path
    title = (f"top: {result.body.name} — S = {motion.spin:.4g} rad/s, θ0 = {math.degrees(motion.theta0):.4g}°: "
             f"{kind}")
    fig, axes = figure(title, nrows=1, ncols=2, size=(10.0, 5.0))
    ax = axes[0][0]
    ax.plot(ph_d, th_d, label="axis tip", **style(0))
    ax.axhline(t1, label=f"θ1 = {t1:.5g}° (least tilt)", **style(1))
    ax.axhline(t2, label=f"θ2 = {t2:.5g}° (greatest tilt)", **style(2))
    ax.plot([ph_d[0]], [th_d[0]], marker="o", color="black", linestyle="none", label="start")
    pad = max(0.15 * (t2 - t1), 1e-3)
    ax.set_ylim(t2 + pad, t1 - pad)  # inverted: up is up
    ax.set_xlabel("precession angle φ [°]")
    ax.set_ylabel("tilt θ from the upward vertical [°]")
    ax.set_title(f"θ against φ over {duration:.4g} s")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2)

    ax = axes[0][1]
    st = np.sin(theta)
    x, y = st * np.cos(phi), st * np.sin(phi)
    ring = np.linspace(0.0, 2.0 * np.pi, 721)
    for i, (tt, name) in enumerate(((t1, "θ1"), (t2, "θ2"))):
        r = math.sin(math.radians(tt))
        ax.plot(r * np.cos(ring), r * np.sin(ring), label=f"{name} = {tt:.5g}°", **style(i + 1))
    ax.plot(x, y, label="axis tip", **style(0))
    ax.plot([x[0]], [y[0]], marker="o", color="black", linestyle="none")
    ax.plot([0.0], [0.0], marker="+", color="black", linestyle="none", markersize=10, label="pivot")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (unit axis, from the pivot)")
    ax.set_ylabel("y")
    ax.set_title("seen from above")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2)
    return fig


# --- gyrocompass


def gyro_document(doc: Doc, result: GyrocompassResult, du: DisplayUnits, digits: int) -> None:
    """The tables of ``rbcli gyrocompass``."""
    d, res, du = digits, result.swing, du.of(result.body)
    if result.body is not None:
        b = result.body
        J = du.unit("inertia")
        doc.heading(f"{b.name}  ({b.source})")
        doc.kv("rotor (about its centre of mass)", [
            ("mass", du.show(result.mass, "mass", d), du.unit("mass")),
            ("C, about the spin axis", du.show(result.C, "inertia", d), J),
            ("A, across the spin axis", du.show(result.A, "inertia", d), J),
            ("C/A", num(res.C_over_A, d), ""),
        ])
        doc.note(f"spin axis [{', '.join(num(x, d) for x in result.axis)}] ({said(result.axis_source)}).")
        if result.asymmetry is not None:
            asymmetry_note(doc, result.asymmetry, result.options.symmetry_tol, result.asymmetry_effect,
                            du, d, "rotor", "A")
    else:
        doc.heading("gyrocompass")
    lat = math.degrees(res.latitude)
    rows = [
        ("C/A", num(res.C_over_A, d), ""),
        ("spin S", num(res.spin, d), "rad/s"),
        ("spin S", num(res.spin * RPM, d), "rpm"),
        ("latitude", num(lat, d), "°"),
        ("Earth's rate Ω_E", num(res.earth_rate, d), "rad/s"),
        ("horizontal component Ω_E cos λ", num(res.horizontal_earth_rate, d), "rad/s"),
        ("directive (C/A) S Ω_E cos λ", num(res.directive, d), "1/s²"),
    ]
    if res.period is not None:
        rows += [
            ("swing frequency ω0", num(res.omega0, d), "rad/s"),
            ("period T = 2π/ω0", du.show(res.period, "time", d), du.unit("time")),
            ("estimate √((C/A) S Ω_E cos λ)", num(res.omega0_approx, d), "rad/s"),
            ("period from the estimate", du.show(res.period_approx, "time", d), du.unit("time")),
            ("settles to", str(res.settles_to), ""),
        ]
    else:
        rows.append(("period", "none", ""))
    doc.kv(f"gyrocompass at latitude {num(lat, d)}°", rows)
    if res.period is not None:
        doc.note(f"the spin axis swings about {res.settles_to} with period {num(res.period, d)} s "
                 "(undamped; a real gyrocompass damps the swing to settle). "
                 + ("The spin vector points north, along the Earth's rotation." if res.settles_to == "north"
                    else "With a negative spin the rotor's +axis points south."))
    else:
        why = "at a pole the Earth's rotation has no horizontal component" if abs(lat) >= 90.0 - 1e-9 \
            else "the spin is too slow to beat the Ω_E² cos² λ term"
        doc.note(f"no directive torque: {why}; the rotor does not seek north.")
