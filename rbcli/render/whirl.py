"""Tables, figures and the report section of ``rbcli whirl`` (the JSON is the result's
own ``to_json()``).

Everything here is formatting: every number comes finished from
:class:`rbcli.api.whirlresult.WhirlResult`, and every display row (the echo of the
options as understood included) is built here from it. Tables show speeds and critical
speeds in rpm and rad/s, whirl frequencies in rad/s and cpm (cycles per minute: on the
Campbell diagram the 1× line is the diagonal), positions in the display length unit (m
unless ``--units``), displacements in µm, forces in N, stiffness in N/m and damping in
N s/m.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from rbcli.core.whirl.response import phase_deg
from rbcli.render import echo
from rbcli.render.fmt import num
from rbcli.render.text import Doc
from rbcli.render.units import RPM, BodyUnits, DisplayUnits

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.whirlresult import WhirlResult
    from rbcli.render.report import Section

__all__ = ["document", "echo_rows", "campbell_figure", "response_figure", "report_section",
           "conventions_note"]

UM = 1e6  # m -> µm

#: how each whirl direction is drawn: (label, colour, line style)
WHIRL_STYLE = {
    "forward": ("forward whirl", "black", "-"),
    "backward": ("backward whirl", "0.45", "--"),
    "linear": ("straight-line orbit", "0.25", "-."),
    "none": ("not oscillating", "0.6", ":"),
}


def _speed(x: float | None, digits: int) -> str:
    """A speed as 'rpm (rad/s)'."""
    if x is None:
        return "—"
    return f"{num(x * RPM, digits)} rpm ({num(x, digits)} rad/s)"


# ----------------------------------------------------------------------------- tables


def echo_rows(res: WhirlResult) -> list[tuple[str, str, str]]:
    """The options as understood (:func:`rbcli.render.echo.echo_rows`)."""
    return echo.echo_rows(res.options, res.units, {"unbalance": lambda v: (", ".join(
        f"{num(abs(u) * 1e6)}@{num(phase_deg(u))}" for _, u in v), "g·mm@deg")})


def conventions_note(res: WhirlResult) -> str:
    """One paragraph: the conventions every output states."""
    return ("Conventions: speeds in rpm (rad/s); whirl frequencies in the fixed frame of the "
            "bearings (cpm = cycles per minute, rad/s); forward whirl turns the same way as the "
            "spin, backward the opposite way; stiffness N/m, damping N s/m, x and y of the "
            "bearings along the shaft frame's axes with the rotor at angle 0; positions along "
            "the shaft from the shaft point; angles and phases in the rotor frame from the 0° "
            "mark in the direction of rotation (a phase is the high spot's angle); amplitudes "
            "are the semi-major axes of the orbits. Gravity is left out of the linear modes.")


def document(doc: Doc, res: WhirlResult, du: DisplayUnits, digits: int, *, echo: bool = True,
             heading: bool = True) -> None:
    """The tables of a whirl analysis, into ``doc``."""
    L = du.unit("length")
    if heading:
        doc.heading(f"{res.name}  ({res.source})" if res.source else res.name)
    if echo:
        doc.table("options (as understood)", ("option", "value", "unit"), echo_rows(res), right=(1,))
    r = res.rotor
    rows = [
        ("mass m", du.show(r.mass, "mass", digits), du.unit("mass")),
        ("centre of mass z_G (along the shaft)", du.show(r.com, "length", digits), L),
        ("polar moment Ip (about the shaft)", du.show(r.polar_moment, "inertia", digits), du.unit("inertia")),
        ("transverse moment It (across, about the com)", du.show(r.transverse_moment, "inertia", digits),
         du.unit("inertia")),
    ]
    if r.asymmetry > 1e-6:
        rows.append(("moments across: I1, I2", ", ".join(du.show(x, "inertia", digits) for x in r.transverse_moments),
                     du.unit("inertia")))
    rows += [
        ("Ip / It", num(r.polar_moment / r.transverse_moment, digits),
         "disk-like" if r.polar_moment >= r.transverse_moment else "long"),
        ("tilt of the nearest principal axis", num(r.tilt_deg, digits), "°"),
        ("static unbalance U", num(r.static_unbalance * 1e6, digits), "g·mm"),
        ("  its angle", num(r.static_unbalance_angle_deg, digits) if r.static_unbalance > 0 else "—", "°"),
        ("couple unbalance P_G (about the com)", num(r.couple_unbalance * 1e9, digits), "g·mm²"),
        ("  its angle", num(r.couple_unbalance_angle_deg, digits) if r.couple_unbalance > 0 else "—", "°"),
    ]
    doc.kv("rotor (rigid; about its centre of mass, shaft axes)", rows)
    brow = []
    cross = any(b.cross_stiffness[0] for b in res.bearings)
    for i, b in enumerate(res.bearings):
        row = [str(i + 1), du.show(b.plane, "length", digits), num(b.stiffness[0], digits), num(b.stiffness[1], digits)]
        if cross:
            row.append(num(b.cross_stiffness[0], digits))
        row += [num(b.damping[0], digits), num(b.damping[1], digits)]
        brow.append(row)
    cols = ["bearing", f"z [{L}]", "kxx [N/m]", "kyy [N/m]"] + (["kxy = -kyx [N/m]"] if cross else []) + \
        ["cxx [N s/m]", "cyy [N s/m]"]
    doc.table("bearings (linear springs and dampers, fixed)", cols, brow, right=tuple(range(1, len(cols))))

    # modes at the operating speed (or at rest)
    title = "whirl modes at rest" if res.modes_speed == 0.0 else \
        f"whirl modes at {num(res.modes_speed * RPM, digits)} rpm"
    d4 = min(digits, 4)
    mrows = []
    for i, m in enumerate(res.modes):
        mrows.append((str(i + 1), num(m.frequency, digits), num(m.frequency * RPM, digits), m.whirl, m.kind,
                      "—" if m.node is None else du.show(m.node, "length", digits),
                      num(m.damping_ratio, d4), "—" if m.log_decrement is None else num(m.log_decrement, d4),
                      "yes" if m.stable else "NO, GROWS"))
    doc.table(title, ("mode", "frequency [rad/s]", "[cpm]", "whirl", "kind", f"node z [{L}]",
                      "damping ratio", "log dec", "stable"), mrows, right=(1, 2, 5, 6, 7))

    # critical speeds
    crows = []
    for c in res.critical_speeds:
        crows.append((f"{c.order}×", num(c.speed * RPM, digits) + ("" if c.in_range else " *"), num(c.speed, digits),
                      c.mode, c.whirl, "—" if c.node is None else du.show(c.node, "length", digits),
                      "—" if c.damped_speed is None else num(c.damped_speed * RPM, digits),
                      "—" if c.damping_ratio is None else num(c.damping_ratio, d4),
                      "—" if c.excited is None else ("yes" if c.excited else "no")))
    doc.table("critical speeds (undamped: an eigenproblem in the speed; damped: a root solve)",
              ("order", "speed [rpm]", "[rad/s]", "mode", "whirl", f"node z [{L}]", "damped [rpm]",
               "ζ", "driven"), crows, right=(1, 2, 5, 6, 7))
    if res.critical_speeds:
        doc.note("ζ: the damping ratio at the damped critical speed; driven: the unbalance excites the "
                 "mode (order 1 only)" + ("; *: outside the speed range" if not all(
                     c.in_range for c in res.critical_speeds) else "") + ".")
    if not res.critical_speeds:
        doc.note("no critical speed: no whirl frequency meets an n× line.")
    for m in res.no_crossings:
        doc.note(f"no crossing: {m.explanation}.")
    doc.note(_rigid_note(res, digits))
    doc.note(_stability_note(res, digits))

    # response
    resp = res.response
    if resp.source == "body":
        src = (f"unbalance response to the body's own unbalance: U = {num(r.static_unbalance * 1e6, digits)} "
               f"g·mm, P_G = {num(r.couple_unbalance * 1e9, digits)} g·mm² (as rbcli balance gives them)")
    else:
        src = "unbalance response to " + ", ".join(
            f"{num(u.amount * 1e6, digits)} g·mm at {num(u.angle_deg, digits)}° in z = "
            f"{du.show(u.plane, 'length', digits)} {L}" for u in resp.unbalance)
    doc.note(src + ".")
    if resp.peaks:
        prow = []
        for p in resp.peaks:
            prow.append((str(p.bearing), num(p.speed * RPM, digits),
                         "∞ (undamped)" if p.undamped else num(p.amplitude * UM, digits),
                         "∞" if p.undamped else ("—" if p.amplification_factor is None else num(p.amplification_factor, digits)),
                         "—" if p.half_power is None else
                         f"{num(p.half_power[0] * RPM, digits)}-{num(p.half_power[1] * RPM, digits)}",
                         p.mode or "—", p.whirl or "—"))
        doc.table("response peaks (amplification factor AF = Nc/(N2 - N1), half-power points)",
                  ("bearing", "Nc [rpm]", "amplitude [µm]", "AF", "N1-N2 [rpm]", "mode", "whirl"), prow,
                  right=(1, 2, 3, 4))
    if resp.at_speed:
        arow = []
        for i, a in enumerate(resp.at_speed):
            arow.append((str(i + 1), num(a.displacement * UM, digits), num(a.displacement_phase_deg, digits),
                         num(a.force, digits), num(a.force_phase_deg, digits),
                         "—" if a.rigid_force is None else num(a.rigid_force, digits)))
        doc.table(f"at {num(res.speed[1] * RPM, digits)} rpm (the operating speed)",
                  ("bearing", "displacement [µm]", "phase [°]", "force [N]", "phase [°]", "on rigid bearings [N]"),
                  arow, right=(1, 2, 3, 4, 5))
    mg = res.margins
    if mg is not None:
        lo, hi = mg.operating_speed
        op = f"{num(lo * RPM, digits)} rpm" if lo == hi else f"{num(lo * RPM, digits)}-{num(hi * RPM, digits)} rpm"
        mrow = []
        for ch in mg.checks:
            af = {"undamped": "∞ (undamped)", "undefined": "∞ (no half-power points)"}.get(
                ch.basis, num(ch.amplification_factor, digits) if ch.amplification_factor is not None else "—")
            mrow.append(("—" if ch.bearing is None else str(ch.bearing), num(ch.speed * RPM, digits), ch.mode or "—",
                         af, ch.position, num(ch.margin_percent, digits), num(ch.required_margin_percent, digits),
                         "PASS" if ch.passed else "FAIL"))
        doc.table(f"separation margins from the operating speed {op} (API 617 / API 684 rule)",
                  ("bearing", "critical [rpm]", "mode", "AF", "position", "margin [%]", "required [%]", "verdict"),
                  mrow, right=(1, 3, 5, 6))
        doc.note("rule: " + mg.rule + ". (Taken from public implementations of the standard; check a "
                 "licensed copy before claiming conformity.)")
        if mg.passed is None:
            doc.note("separation margins: nothing to judge (no response peak in the speed range).")
        else:
            doc.note("separation margins: " + ("PASS" if mg.passed else "FAIL: a critical speed is too close "
                                                "to the operating speed for its amplification factor") + ".")
    doc.note(conventions_note(res))


def _rigid_note(res: WhirlResult, digits: int) -> str:
    text = ("rigid-support limit: these critical speeds exist because the bearings give; they "
            "grow as the square root of the stiffness, and on rigid supports a rigid rotor has none "
            "(its bearing forces are then rbcli balance's, F = Ω² (z2 U - P)/(z2 - z1))")
    at = res.response.at_speed
    if at and all(a.rigid_force for a in at):
        ratios = [a.force / a.rigid_force for a in at]
        text += (f"; at the operating speed the bearing forces are {', '.join(num(x, 4) for x in ratios)} "
                 "times the rigid-support forces")
    return text + "."


def _stability_note(res: WhirlResult, digits: int) -> str:
    st = res.stability
    undamped = all(not any(b.damping) and not any(b.cross_stiffness) for b in res.bearings)
    if undamped:
        return ("stability: no damping and no cross-coupling: every mode is neutrally stable "
                "(it neither grows nor decays).")
    if st.stable_in_range and st.stable_at_speed is not False:
        return (f"stability: STABLE over the speed range (least damping ratio {num(st.least_damping_ratio, digits)} "
                f"at {num(st.least_damping_speed * RPM, digits)} rpm).")
    parts = ["stability: UNSTABLE — a whirl mode GROWS"]
    if st.onset_speeds:
        parts.append(" (onset of instability at " + ", ".join(f"{num(x * RPM, digits)} rpm" for x in st.onset_speeds) + ")")
    parts.append(f"; least damping ratio {num(st.least_damping_ratio, digits)} at "
                 f"{num(st.least_damping_speed * RPM, digits)} rpm")
    if st.stable_at_speed is False:
        parts.append("; UNSTABLE AT THE OPERATING SPEED")
    return "".join(parts) + "."


# ----------------------------------------------------------------------------- figures


def _segments(x: np.ndarray, y: np.ndarray, labels: tuple[str, ...]):
    """Runs of equal label: (label, x, y), each run joined to the next point."""
    out = []
    start = 0
    for j in range(1, len(x) + 1):
        if j == len(x) or labels[j] != labels[start]:
            end = min(j + 1, len(x))
            out.append((labels[start], x[start:end], y[start:end]))
            start = j
    return out


def campbell_figure(res: WhirlResult):
    """The Campbell diagram: whirl frequencies (cpm, Hz on the right) against speed (rpm),
    forward solid, backward dashed; the n× lines; the critical speeds marked (filled: the
    unbalance drives it); the operating speed; growing modes crossed. A matplotlib Figure."""
    from rbcli.render.plots import figure

    cb = res.campbell
    sp = np.asarray(cb.speeds) * RPM
    fr = np.asarray(cb.frequencies) * RPM
    fig, axes = figure(f"whirl: {res.name} — Campbell diagram", size=(7.5, 5.0))
    ax = axes[0][0]
    seen = set()
    for i in range(fr.shape[0]):
        for lab, xs, ys in _segments(sp, fr[i], cb.whirl[i]):
            name, colour, ls = WHIRL_STYLE.get(lab, WHIRL_STYLE["none"])
            ax.plot(xs, ys, color=colour, linestyle=ls, linewidth=1.5,
                    label=name if lab not in seen else None)
            seen.add(lab)
    zeta = np.asarray(cb.damping_ratio)
    grow = zeta < -1e-9
    if grow.any():
        ii, jj = np.nonzero(grow)
        ax.plot(sp[jj], fr[ii, jj], linestyle="none", marker="x", color="black", markersize=4,
                label="growing (unstable)")
    top = float(sp[-1])
    ymax = max(float(np.max(fr)) if fr.size else 0.0, 1.0)
    for n in res.orders:
        ax.plot([0.0, top], [0.0, n * top], color="0.6", linewidth=0.9, linestyle=(0, (1, 2)))
        xt = min(top, ymax / n) * 0.92
        ax.annotate(f"{n}×", (xt, n * xt), textcoords="offset points", xytext=(4, -10), fontsize=8, color="0.4")
    for k, c in enumerate(res.critical_speeds):
        s = c.damped_speed if c.damped_speed is not None else c.speed
        if not (sp[0] <= s * RPM <= top):
            continue
        filled = bool(c.excited)
        ax.plot([s * RPM], [c.order * s * RPM], marker="o", markersize=6, linestyle="none",
                markerfacecolor="black" if filled else "white", markeredgecolor="black",
                label=("critical speed (driven by the unbalance)" if filled else "critical speed (not driven)")
                if (filled, "crit") not in seen else None)
        seen.add((filled, "crit"))
        ax.annotate(f"{s * RPM:.4g}", (s * RPM, c.order * s * RPM), textcoords="offset points",
                    xytext=(6, -12) if c.whirl == "backward" else (-8, 6),
                    ha="left" if c.whirl == "backward" else "right", fontsize=7)
    if res.speed is not None:
        lo, hi = res.speed
        if lo == hi:
            ax.axvline(lo * RPM, color="0.3", linewidth=1.0, linestyle="-.", label="operating speed")
        else:
            ax.axvspan(lo * RPM, hi * RPM, color="0.9", zorder=0, label="operating range")
    ax.set_xlim(float(sp[0]), top)
    ax.set_ylim(0.0, 1.08 * ymax)
    ax.set_xlabel("rotor speed [rpm]")
    ax.set_ylabel("whirl frequency, fixed frame [cpm]")
    sec = ax.secondary_yaxis("right", functions=(lambda y: y / 60.0, lambda h: h * 60.0))
    sec.set_ylabel("[Hz]")
    ax.set_title("forward: with the spin; backward: against it", fontsize=9)
    fig.legend(loc="outside lower center", ncols=3, fontsize=7)
    return fig


def response_figure(res: WhirlResult):
    """The unbalance response: per bearing the displacement amplitude (µm; log scale
    without damping) and its phase (high spot, rotor frame) against speed (rpm), peaks
    and half-power points marked, the operating speed. A matplotlib Figure."""
    from rbcli.render.plots import figure, style

    resp = res.response
    sp = np.asarray(resp.speeds) * RPM
    fig, axes = figure(f"whirl: {res.name} — unbalance response", nrows=2, ncols=1, size=(7.5, 6.0))
    ax, axp = axes[0][0], axes[1][0]
    undamped = any(p.undamped for p in resp.peaks)
    for i, b in enumerate(resp.bearings):
        amp = np.asarray(b.displacement) * UM
        kw = style(i)
        ax.plot(sp, amp, label=f"bearing {i + 1} (z = {b.plane:.4g} m)", **kw)
        axp.plot(sp, _continuous_phase(np.asarray(b.displacement_phase_deg), amp), **kw)
    for p in resp.peaks:
        if p.undamped:
            ax.axvline(p.speed * RPM, color="0.5", linewidth=0.7, linestyle=":")
            continue
        ax.plot([p.speed * RPM], [p.amplitude * UM], marker="o", color="black", markersize=4, linestyle="none")
        if p.half_power is not None:
            lvl = p.amplitude * UM / math.sqrt(2.0)
            ax.plot([p.half_power[0] * RPM, p.half_power[1] * RPM], [lvl, lvl], color="0.4", linewidth=0.8)
            if p.amplification_factor is not None:
                ax.annotate(f"AF {p.amplification_factor:.3g}", (p.speed * RPM, p.amplitude * UM),
                            textcoords="offset points", xytext=(5, 3), fontsize=7)
    if res.speed is not None:
        lo, hi = res.speed
        for a in (ax, axp):
            if lo == hi:
                a.axvline(lo * RPM, color="0.3", linewidth=1.0, linestyle="-.")
            else:
                a.axvspan(lo * RPM, hi * RPM, color="0.9", zorder=0)
    if undamped and np.any(np.asarray([b.displacement for b in resp.bearings]) > 0):
        ax.set_yscale("log")
    ax.set_xlim(float(sp[0]), float(sp[-1]))
    axp.set_xlim(float(sp[0]), float(sp[-1]))
    ax.set_ylabel("displacement, orbit semi-major axis [µm]")
    src = "the body's own unbalance" if resp.source == "body" else "the unbalances given"
    ax.set_title(f"response to {src}; half-power points marked", fontsize=9)
    ax.legend(loc="upper left", fontsize=7)
    from matplotlib.ticker import MultipleLocator

    axp.yaxis.set_major_locator(MultipleLocator(90.0))
    axp.set_xlabel("rotor speed [rpm]")
    axp.set_ylabel("phase of the high spot [°] (rotor frame)")
    return fig


def _continuous_phase(deg: np.ndarray, amp: np.ndarray) -> np.ndarray:
    """Phases (deg) drawn without jumps at 0/360: unwrapped along the speed, the first
    defined one in [-180, 180); NaN (not drawn) where the amplitude is zero."""
    out = np.full(deg.shape, np.nan)
    ok = amp > 0.0
    if not ok.any():
        return out
    un = np.degrees(np.unwrap(np.radians(deg[ok])))
    shift = 360.0 * np.floor((un[0] + 180.0) / 360.0)
    out[ok] = un - shift
    return out


# ----------------------------------------------------------------------------- report


def report_section(res: WhirlResult, du: DisplayUnits, digits: int, *, figures: bool = True,
                   key: str = "whirl", title: str = "Whirl: critical speeds and unbalance response") -> Section:
    """The report's whirl section: the tables of :func:`document` (the options as
    understood first, no heading), the result's warnings as notes (options spelled as the
    command line spells them) and, with ``figures``, the Campbell diagram and the response as
    SVG :class:`rbcli.render.report.Figure` items.

    ``rbcli.render.reportdoc`` would build it from a computed section ``c`` (``c.result`` a
    :class:`rbcli.api.whirlresult.WhirlResult`) as
    ``report_section(c.result, du, digits, key=c.key, title=c.title)``."""
    from rbcli.render.fmt import said
    from rbcli.render.plots import figure_bytes
    from rbcli.render.report import Figure, Section
    from rbcli.render.text import Note

    doc = Doc()
    document(doc, res, du, digits, heading=False)
    s = Section(key, title)
    s.add_doc(doc)
    for w in res.warnings:
        s.items.append(Note("warning: " + said(w)))
    if figures:
        s.items.append(Figure("whirl-campbell", "Campbell diagram: whirl frequencies against speed, "
                              "the n× lines and the critical speeds.",
                              figure_bytes(campbell_figure(res), "svg").decode("utf-8")))
        s.items.append(Figure("whirl-response", "Unbalance response at each bearing: amplitude and "
                              "phase against speed.",
                              figure_bytes(response_figure(res), "svg").decode("utf-8")))
    return s
