"""Tables, JSON, CSV time series and the figure of ``rbcli precess``."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.core import freemotion as fm
from rbcli.core import freestate as fs
from rbcli.render.fmt import num, snap
from rbcli.render.massprops import AXES, vec_rows
from rbcli.render.plots import figure, style
from rbcli.render.units import DisplayUnits

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body
    from rbcli.render.text import Doc  # hints only: --json never loads render.text

#: the CSV header of ``--csv`` (the columns of :func:`rbcli.core.freestate.series`)
CSV_HEADER = fs.SERIES_COLUMNS
_DAY = 86400.0


def notes(motion: fm.FreeMotion, du: DisplayUnits | None = None, digits: int = 6) -> list[str]:
    """The notes of :func:`rbcli.core.freestate.notes` with times and numbers as displayed."""
    du = du or DisplayUnits()
    tu = du.unit("time")
    return fs.notes(motion, time=lambda x: f"{du.show(x, 'time', digits)} {tu}",
                    number=lambda x: num(x, digits))


# --- tables


def _time(x: float | None, du: DisplayUnits, digits: int) -> tuple[str, str]:
    """(value, unit) for a time; long SI times also in days."""
    if x is None:
        return "—", ""
    unit = du.unit("time")
    if unit == "s" and abs(x) >= 2 * _DAY:
        unit = f"s  (= {num(x / _DAY, digits)} d)"
    return du.show(x, "time", digits), unit


def _axis_label(motion: fm.FreeMotion, i: int) -> str:
    """'axis 3 (largest moment)' and, when it is a body axis, '= body +z'."""
    base = f"axis {i + 1} ({('smallest', 'intermediate', 'largest')[i]} moment)"
    ax = motion.axes[i]
    j = int(np.argmax(np.abs(ax)))
    if abs(abs(ax[j]) - 1.0) < 1e-12:
        base += f" = body {'+' if ax[j] > 0 else '-'}{AXES[j]}"
    return base


def document(doc: Doc, body: Body, result: Any, du: DisplayUnits, digits: int, *,
             csv: dict | None = None, plot: str | None = None) -> None:
    """The tables a person reads, from a :class:`rbcli.api.precess.PrecessResult`; ``csv``
    ({file, samples, duration}) and ``plot`` (a file name) say what was written."""
    motion, du = result.motion, du.of(body)
    doc.heading(f"{body.name}  ({body.source})")
    f, iu = du.factor("inertia")
    rows = [(str(i + 1), num(motion.moments[i] * f, digits),
             ", ".join(num(x, digits) for x in snap(motion.axes[i], scale=1.0, rtol=1e-15)))
            for i in range(3)]
    doc.table(f"principal moments about the com [{iu}] ({motion.symmetry})",
              ("axis", "moment", "direction (body x, y, z)"), rows, right=(1,))
    doc.kv("at t = 0 (body frame; L is also the constant L in space)", _start(motion, du, digits))
    doc.note(motion.description)
    doc.kv("motion", _motion(motion, du, digits))
    if motion.symmetry == "symmetric" and motion.case != fm.CASE_REST:
        doc.kv("symmetric body", _symmetric(motion, du, digits))
    for text in notes(motion, du, digits):
        doc.note(text)
    st = result.at_json
    if st is not None:
        doc.kv(f"at t = {du.show(st['t'], 'time', digits)} {du.unit('time')} (body frame; "
               "orientation body → space)", _at(st, du, digits))
    if result.check is not None:
        _verify(doc, motion, result.check, du, digits)
    if csv is not None:
        doc.note(f"time series ({csv['samples']} rows over {du.show(csv['duration'], 'time', digits)} "
                 f"{du.unit('time')}) written to {csv['file']}")
    if plot is not None:
        doc.note(f"plot written to {plot}")


Rows = list[tuple[str, str, str]]


def _start(motion: fm.FreeMotion, du: DisplayUnits, digits: int) -> Rows:
    """ω, L and T at t = 0 (body frame), and the angle between L and ω."""
    w = motion.omega0
    G = motion.angular_momentum_norm
    rows = vec_rows("ω", w, du, "angular_speed", digits)
    rows.append(("|ω|", du.show(float(np.linalg.norm(w)), "angular_speed", digits), du.unit("angular_speed")))
    rows += vec_rows("L = J·ω", snap(motion.angular_momentum), du, "angular_momentum", digits)
    rows.append(("|L|", du.show(G, "angular_momentum", digits), du.unit("angular_momentum")))
    rows.append(("T = ω·J·ω/2", du.show(motion.kinetic_energy, "energy", digits), du.unit("energy")))
    if G > 0:
        cosang = float(np.dot(w, motion.angular_momentum)) / (float(np.linalg.norm(w)) * G)
        rows.append(("angle between L and ω", num(math.degrees(math.acos(min(1.0, max(-1.0, cosang)))), digits), "°"))
    return rows


def _stable(motion: fm.FreeMotion) -> str:
    if motion.stable is False and motion.flip_interval is not None:
        return "no: it flips over"
    if motion.stable is None and motion.case == fm.CASE_STEADY and motion.symmetry == "symmetric":
        return "neutral"
    return {True: "yes", False: "no", None: "—"}[motion.stable]


def _motion(motion: fm.FreeMotion, du: DisplayUnits, digits: int) -> Rows:
    """What ω circles, its period, the flips (the elliptic constants), the turn about L."""
    circ = motion.circles_axis
    rows = [("ω circles", "—" if circ is None else _axis_label(motion, circ - 1), ""),
            ("stable", _stable(motion), ""),
            ("period of ω (body frame)", *_time(motion.period, du, digits))]
    if motion.elliptic is not None:
        rows += _flips(motion, du, digits)
    if motion.precession_per_period is not None:
        rows.append(("turn about L per period of ω", num(motion.precession_per_period, digits), "rad"))
    if motion.mean_precession_rate is not None and motion.case != fm.CASE_REST:
        rows.append(("mean rate of turning about L", du.show(motion.mean_precession_rate, "angular_speed", digits), du.unit("angular_speed")))
    if motion.case == fm.CASE_STEADY:
        for j, (kind, r) in enumerate(zip(motion.linear_kinds, motion.linear_rates)):
            if abs(float(np.dot(motion.omega0_principal, np.eye(3)[j]))) > 0 and kind != "neutral":
                what = "small wobble frequency" if kind == "oscillation" else "growth rate of a disturbance"
                rows.append((what, num(r, digits), "rad/s" if kind == "oscillation" else "1/s"))
    return rows


def _flips(motion: fm.FreeMotion, du: DisplayUnits, digits: int) -> Rows:
    """The rows of an asymmetric motion: flips, the separatrix, the elliptic constants."""
    el = motion.elliptic
    rows = []
    if motion.flip_interval is not None:
        rows.append(("flip interval (ω2 changes sign)", *_time(motion.flip_interval, du, digits)))
    elif el.kind != "separatrix":
        rows.append(("flips", f"no flip: stable about axis {motion.circles_axis}", ""))
    if el.kind == "separatrix":
        rows.append(("the one flip (ω2 changes sign) at", *_time(-el.tau0 / el.lam, du, digits)))
        rows.append(("Ω0 = |L|/I2 (ω → ±Ω0 along axis 2)", du.show(el.amplitudes[1], "angular_speed", digits), du.unit("angular_speed")))
    elif motion.first_flip is not None:
        rows.append(("first flip", *_time(motion.first_flip, du, digits)))
    if motion.flip_interval_estimate is not None and el.mc < fs.NEAR_SEPARATRIX:
        rows.append(("near-separatrix estimate (2/σ) ln(4/k')", *_time(motion.flip_interval_estimate, du, digits)))
    if el.kind != "separatrix":
        rows.append(("elliptic parameter m, 1 − m", f"{num(el.m, digits)}, {num(el.mc, digits)}", ""))
    rows.append(("rate λ", num(el.lam, digits), "1/s"))
    return rows


def _symmetric(motion: fm.FreeMotion, du: DisplayUnits, digits: int) -> Rows:
    """The symmetric body's precession: rates, cones, nutation, periods."""
    f, iu = du.factor("inertia")
    au = du.unit("angular_speed")
    return [
        ("symmetry axis (body frame)", ", ".join(num(x, digits) for x in snap(motion.symmetry_axis, scale=1.0, rtol=1e-15)), ""),
        ("shape", "oblate (Is > I, like a disk)" if motion.oblate else "prolate (Is < I, like a rod)", ""),
        ("I (across), Is (about the axis)", f"{num(motion.moments[0 if motion.oblate else 1] * f, digits)}, "
         f"{num(motion.moments[motion.symmetry_index] * f, digits)}", iu),
        ("spin ω3", du.show(motion.spin, "angular_speed", digits), au),
        ("body-frame precession W = ω3 (Is/I − 1)", du.show(motion.precession_rate, "angular_speed", digits), au),
        ("space precession |L|/I", du.show(motion.space_precession_rate, "angular_speed", digits), au),
        ("spin relative to the precessing plane ψ' = −W", du.show(motion.spin_rate, "angular_speed", digits), au),
        ("body cone semi-angle (ω to axis)", num(math.degrees(motion.body_cone), digits), "°"),
        ("space cone semi-angle (ω to L)", num(math.degrees(motion.space_cone), digits), "°"),
        ("nutation (L to axis)", num(math.degrees(motion.nutation), digits), "°"),
        ("wobble-to-spin |φ'/ψ'|", num(motion.wobble_to_spin, digits), ""),
        ("wobble period 2π/|W| (body frame)", *_time(motion.wobble_period, du, digits)),
        ("space precession period 2π I/|L|", *_time(motion.space_precession_period, du, digits)),
    ]


def _at(st: dict, du: DisplayUnits, digits: int) -> Rows:
    """The state at ``t`` (the JSON's ``at`` object)."""
    rows = [("t", *_time(st["t"], du, digits))]
    if st["periods"] is not None:
        rows.append(("periods of ω since t = 0", num(st["periods"], digits), ""))
    rows += vec_rows("ω", st["omega"], du, "angular_speed", digits)
    rows += vec_rows("L", snap(st["angular_momentum"]), du, "angular_momentum", digits)
    rows.append(("quaternion w, x, y, z", ", ".join(num(x, digits) for x in st["quaternion"]), ""))
    rows.append(("rotation axis (space = body at t = 0)",
                 "—" if st["rotation_axis"] is None else ", ".join(num(x, digits) for x in st["rotation_axis"]), ""))
    rows.append(("rotation angle", num(st["rotation_angle_deg"], digits), "°"))
    return rows


def _verify(doc: Doc, motion: fm.FreeMotion, v: Any, du: DisplayUnits, digits: int) -> None:
    """The check against the numerical integration (``verify``)."""
    rows = [
        ("span", *_time(v.t_end, du, digits)),
        ("comparison times", str(v.samples), ""),
        ("largest |Δω|/|ω|", num(v.omega_error, 3), ""),
        ("largest attitude difference", num(v.attitude_error, 3), "rad"),
        ("drift of T: exact, numerical", f"{num(v.exact_energy_drift, 3)}, {num(v.numeric_energy_drift, 3)}", ""),
        ("drift of |L|: exact, numerical", f"{num(v.exact_momentum_drift, 3)}, {num(v.numeric_momentum_drift, 3)}", ""),
        ("drift of L in space: exact, numerical", f"{num(v.exact_L_drift, 3)}, {num(v.numeric_L_drift, 3)}", ""),
        ("verdict", f"agree (all ≤ {num(v.tol, 3)})" if v.ok else f"DISAGREE (tolerance {num(v.tol, 3)})", ""),
    ]
    doc.kv(f"check against numerical integration (DOP853, rtol {num(v.rtol, 3)}, {v.nfev} evaluations)", rows)
    if not v.ok and motion.elliptic is not None and motion.elliptic.mc < fs.NEAR_SEPARATRIX:
        doc.note("near the separatrix the integrator's own error grows at every pass near the "
                 "intermediate axis; the drifts along the exact solution show whether it is exact.")


# --- figure


def plot(body: Body, motion: fm.FreeMotion, duration: float | None, du: DisplayUnits):
    """w(t) in the body frame (three panels) and the polhode seen along axes 3 and 1; the
    samples come from the exact motion (:func:`rbcli.core.freestate.plot_samples`)."""
    ps, du = fs.plot_samples(motion, duration), du.of(body)
    t0, t1, t, w = ps.t0, ps.t1, ps.t, ps.omega
    ft, tu = du.factor("time")

    fig, axes = figure(f"precess: {body.name}", nrows=3, ncols=3, size=(11.0, 4.6))
    gs = axes[0][1].get_gridspec()
    for ax in list(axes[0][1:]) + list(axes[1][1:]) + list(axes[2][1:]):
        ax.remove()
    for i in range(3):
        ax = axes[i][0]
        ax.plot(t * ft, w[:, i], **style(i))
        ax.set_ylabel(f"ω{AXES[i]} [rad/s]")
        for tf in ps.flips:
            ax.axvline(tf * ft, color="0.7", linewidth=0.7, linestyle=":")
        if t0 < 0.0:
            ax.axvline(0.0, color="0.5", linewidth=0.8)
        ax.set_xlim(t0 * ft, t1 * ft)
        if i < 2:
            ax.tick_params(labelbottom=False)
    axes[0][0].set_title("ω in the body frame" + (" (dotted: flips)" if motion.flip_interval else ""))
    axes[2][0].set_xlabel(f"t [{tu}]")

    m, m0, family = ps.polhode, ps.start, ps.family
    names = [_axis_label(motion, i).replace(" moment", "") for i in range(3)]
    first = (0, 1, 2) if motion.circles_axis == 1 else (2, 0, 1)  # along the circled axis
    extent = float(np.max(np.ptp(m, axis=0))) if m.size else 0.0
    for col, (view, hx, hy) in ((1, first), (2, (1, 0, 2))):  # then along axis 2: the separatrix X
        ax = fig.add_subplot(gs[:, col])
        front = 1.0
        if m.size and abs(float(np.mean(m[:, view]))) > 1e-12:
            front = float(np.sign(np.mean(m[:, view])))
        circ = np.linspace(0.0, 2 * math.pi, 361)
        ax.plot(np.cos(circ), np.sin(circ), color="0.6", linewidth=0.8)
        for curve in family:
            vis = np.where(front * curve[:, view] >= -1e-12, 1.0, np.nan)
            ax.plot(curve[:, hx] * vis, curve[:, hy] * vis, color="0.78", linewidth=0.7)
        if m.size:
            fr = front * m[:, view] >= 0
            ax.plot(np.where(fr, m[:, hx], np.nan), np.where(fr, m[:, hy], np.nan), color="black", linewidth=1.8,
                    label="this motion")
            if not np.all(fr):
                ax.plot(np.where(~fr, m[:, hx], np.nan), np.where(~fr, m[:, hy], np.nan), color="black",
                        linewidth=1.0, linestyle=":", label="(far side)")
            ax.plot([m0[hx]], [m0[hy]], marker="o", color="black", linestyle="none", label="t = 0")
            ax.legend(loc="lower right")
            if 0.0 < extent < 0.02 and col == 1:
                ax.text(0.03, 0.03, f"the polhode spans {extent:.2g}: too small to draw",
                        transform=ax.transAxes, fontsize=8)
        ax.set_aspect("equal")
        ax.set_xlim(-1.1, 1.1)
        ax.set_ylim(-1.1, 1.1)
        ax.set_xlabel(f"L{hx + 1}/|L|, {names[hx]}")
        ax.set_ylabel(f"L{hy + 1}/|L|, {names[hy]}")
        side = ">" if front > 0 else "<"
        ax.set_title(f"polhode seen along axis {view + 1} (L{view + 1} {side} 0 side)")
    return fig
