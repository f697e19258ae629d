"""Tables and figures of ``rbcli whirl`` (the JSON is the result's ``to_json()``; the
report's section is :mod:`rbcli.render.reportdoc`'s): formatting only, from
:class:`rbcli.api.whirlresult.WhirlResult`. Speeds in rpm and rad/s, whirl frequencies in
rad/s and cpm, positions in the display length unit, displacements in µm, forces in N."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from rbcli.core.whirl.response import phase_deg
from rbcli.render import echo
from rbcli.render.fmt import num, said
from rbcli.render.plots import figure, figure_bytes, style
from rbcli.render.text import Doc
from rbcli.render.units import RPM, DisplayUnits

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.whirlresult import WhirlResult

__all__ = ["document", "echo_rows", "campbell_figure", "response_figure", "map_figure",
           "conventions_note"]

UM = 1e6  # m -> µm

#: how each whirl direction is drawn: (label, colour, line style)
WHIRL_STYLE = {
    "forward": ("forward whirl", "black", "-"),
    "backward": ("backward whirl", "0.45", "--"),
    "linear": ("straight-line orbit", "0.25", "-."),
    "none": ("not oscillating", "0.6", ":"),
}


# --- tables


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
    du = du.of(res.units, (res.rotor.mass, max(abs(b.plane) for b in res.bearings)))
    if heading:
        doc.heading(f"{res.name}  ({res.source})" if res.source else res.name)
    if echo:
        doc.table("options (as understood)", ("option", "value", "unit"), echo_rows(res), right=(1,))
    doc.kv("rotor (rigid; about its centre of mass, shaft axes)", _rotor_rows(res, du, digits))
    _bearings(doc, res, du, digits)
    _modes(doc, res, du, digits)
    _criticals(doc, res, du, digits)
    _stability(doc, res, digits)
    _response(doc, res, du, digits)
    _margins(doc, res, digits)
    _map(doc, res, digits)
    doc.note(conventions_note(res))


def _rotor_rows(res: WhirlResult, du: DisplayUnits, digits: int) -> list[tuple[str, str, str]]:
    r, L, J = res.rotor, du.unit("length"), du.unit("inertia")
    rows = [
        ("mass m", du.show(r.mass, "mass", digits), du.unit("mass")),
        ("centre of mass z_G (along the shaft)", du.show(r.com, "length", digits), L),
        ("polar moment Ip (about the shaft)", du.show(r.polar_moment, "inertia", digits), J),
        ("transverse moment It (across, about the com)", du.show(r.transverse_moment, "inertia", digits), J),
    ]
    if r.asymmetry > 1e-6:
        rows.append(("moments across: I1, I2", ", ".join(du.show(x, "inertia", digits) for x in r.transverse_moments), J))
    return rows + [
        ("Ip / It", num(r.polar_moment / r.transverse_moment, digits),
         "disk-like" if r.polar_moment >= r.transverse_moment else "long"),
        ("tilt of the nearest principal axis", num(r.tilt_deg, digits), "°"),
        ("static unbalance U", num(r.static_unbalance * 1e6, digits), "g·mm"),
        ("  its angle", num(r.static_unbalance_angle_deg, digits) if r.static_unbalance > 0 else "—", "°"),
        ("couple unbalance P_G (about the com)", num(r.couple_unbalance * 1e9, digits), "g·mm²"),
        ("  its angle", num(r.couple_unbalance_angle_deg, digits) if r.couple_unbalance > 0 else "—", "°"),
    ]


def _k(b) -> tuple[float, float, float, float]:
    """A bearing's kxx, kxy, kyx, kyy."""
    return (b.stiffness[0], *b.cross_stiffness, b.stiffness[1])


def _conservative(b) -> bool:
    """No damping and a symmetric stiffness (kxy = kyx), constant."""
    _, kxy, kyx, _ = _k(b)
    return b.table is None and kxy == kyx and not any(b.damping) and not any(b.cross_damping)


def _bearings(doc: Doc, res: WhirlResult, du: DisplayUnits, digits: int) -> None:
    """The bearings: one table of springs and dampers (a column kxy = -kyx for a follower
    stiffness); with names, tables or full 2x2 coefficients, a stiffness and a damping table
    (the tables' values at the modes' speed)."""
    B, L = res.bearings, du.unit("length")
    tabled = [(i, b) for i, b in enumerate(B) if b.table is not None]
    ks = [_k(b) for b in B]
    plain = all(k[1] == -k[2] for k in ks) and not tabled and not any(any(b.cross_damping) for b in B) \
        and all(b.name == f"bearing {i + 1}" for i, b in enumerate(B))
    if plain:
        cross = any(k[1] for k in ks)
        cols = ["bearing", f"z [{L}]", "kxx [N/m]", "kyy [N/m]", *(["kxy = -kyx [N/m]"] if cross else []),
                "cxx [N s/m]", "cyy [N s/m]"]
        rows = [[str(i + 1), du.show(b.plane, "length", digits)] + [num(v, digits) for v in (
            k[0], k[3], *([k[1]] if cross else []), *b.damping)] for i, (b, k) in enumerate(zip(B, ks))]
        doc.table("bearings (linear springs and dampers, fixed)", cols, rows, right=tuple(range(1, len(cols))))
        return
    at = f" at {num(res.modes_speed * RPM, digits)} rpm" if tabled else ""
    doc.table(f"bearings: stiffness{at} (fixed springs)", ("bearing", "name", f"z [{L}]", "kxx [N/m]", "kxy [N/m]",
                                                          "kyx [N/m]", "kyy [N/m]"),
              [(str(i + 1), b.name, du.show(b.plane, "length", digits), *(num(x, digits) for x in k))
               for i, (b, k) in enumerate(zip(B, ks))], right=(2, 3, 4, 5, 6))
    doc.table(f"bearings: damping{at}", ("bearing", "cxx [N s/m]", "cxy [N s/m]", "cyx [N s/m]", "cyy [N s/m]"),
              [(str(i + 1), num(b.damping[0], digits), num(b.cross_damping[0], digits),
                num(b.cross_damping[1], digits), num(b.damping[1], digits)) for i, b in enumerate(B)],
              right=(1, 2, 3, 4))
    for i, b in tabled:
        sp = b.table.speeds
        doc.note(f"bearing {i + 1}: coefficients against speed from {b.table.source or 'the body file'}, "
                 f"{len(sp)} speeds {num(sp[0] * RPM, digits)}-{num(sp[-1] * RPM, digits)} rpm, "
                 "interpolated linearly in the speed; speeds beyond the table are refused.")


def _share(m) -> str:
    """The forward share, and each bearing's when they differ from it."""
    text = num(m.forward_share, 3)
    if any(abs(x - m.forward_share) > 1e-3 for x in m.bearing_forward_share):
        text += " (" + ", ".join(num(x, 3) for x in m.bearing_forward_share) + ")"
    return text


def _modes(doc: Doc, res: WhirlResult, du: DisplayUnits, digits: int) -> None:
    title = "whirl modes at rest" if res.modes_speed == 0.0 else \
        f"whirl modes at {num(res.modes_speed * RPM, digits)} rpm"
    d4 = min(digits, 4)
    share = any(m.forward_share not in (0.0, 1.0) for m in res.modes)  # elliptic orbits: say how much
    rows = [(str(i + 1), num(m.frequency, digits), num(m.frequency * RPM, digits), m.whirl,
             *((_share(m),) if share else ()), m.kind,
             "—" if m.node is None else du.show(m.node, "length", digits), num(m.damping_ratio, d4),
             "—" if m.log_decrement is None else num(m.log_decrement, d4), "yes" if m.stable else "NO, GROWS")
            for i, m in enumerate(res.modes)]
    cols = ("mode", "frequency [rad/s]", "[cpm]", "whirl", *(("forward share",) if share else ()), "kind",
            f"node z [{du.unit('length')}]", "damping ratio", "log dec", "stable")
    doc.table(title, cols, rows, right=(1, 2, 4, 6, 7, 8) if share else (1, 2, 5, 6, 7))


def _exact(res: WhirlResult) -> bool:
    """The undamped critical speeds came from the eigenproblem in the speed."""
    return all(b.table is None for b in res.bearings)


def _criticals(doc: Doc, res: WhirlResult, du: DisplayUnits, digits: int) -> None:
    d4 = min(digits, 4)
    rows = [(f"{c.order}×", num(c.speed * RPM, digits) + ("" if c.in_range else " *"), num(c.speed, digits),
             c.mode, c.whirl, "—" if c.node is None else du.show(c.node, "length", digits),
             "—" if c.damped_speed is None else num(c.damped_speed * RPM, digits),
             "—" if c.damping_ratio is None else num(c.damping_ratio, d4),
             "—" if c.excited is None else ("yes" if c.excited else "no")) for c in res.critical_speeds]
    how = "an eigenproblem in the speed" if _exact(res) else "a root solve on the modes followed by their shapes"
    doc.table(f"critical speeds (undamped: {how}; damped: a root solve)",
              ("order", "speed [rpm]", "[rad/s]", "mode", "whirl", f"node z [{du.unit('length')}]",
               "damped [rpm]", "ζ", "driven"), rows, right=(1, 2, 5, 6, 7))
    if res.critical_speeds:
        doc.note("ζ: the damping ratio at the damped critical speed; driven: the unbalance excites the "
                 "mode (order 1 only)" + ("; *: outside the speed range" if not all(
                     c.in_range for c in res.critical_speeds) else "") + ".")
    else:
        doc.note("no critical speed: no whirl frequency meets an n× line.")
    for m in res.no_crossings:
        doc.note(f"no crossing: {m.explanation}.")
    doc.note(_rigid_note(res, digits))


def _stability(doc: Doc, res: WhirlResult, digits: int) -> None:
    st = res.stability
    if st.thresholds:
        doc.table("stability thresholds (Re λ = 0 by a root solve, each mode followed by its shape)",
                  ("speed [rpm]", "[rad/s]", "change", "mode", "whirl", "kind", "frequency [rad/s]"),
                  [(num(t.speed * RPM, digits), num(t.speed, digits), t.change, str(t.mode), t.whirl, t.kind,
                    num(t.frequency, digits)) for t in st.thresholds], right=(0, 1, 6))
    doc.note(_stability_note(res, digits))


def _af(p, digits: int) -> str:
    """An amplification factor as the tables show it, with its basis."""
    if p.basis == "undamped":
        return "∞ (undamped)"
    if p.basis == "undefined" or p.amplification_factor is None:
        return "∞ (undefined)"
    return num(p.amplification_factor, digits) + (" (1/2ζ)" if p.basis == "damping ratio" else "")


def _response(doc: Doc, res: WhirlResult, du: DisplayUnits, digits: int) -> None:
    resp, r, L = res.response, res.rotor, du.unit("length")
    if resp.source == "body":
        src = (f"unbalance response to the body's own unbalance: U = {num(r.static_unbalance * 1e6, digits)} "
               f"g·mm, P_G = {num(r.couple_unbalance * 1e9, digits)} g·mm² (as rbcli balance gives them)")
    else:
        src = "unbalance response to " + ", ".join(
            f"{num(u.amount * 1e6, digits)} g·mm at {num(u.angle_deg, digits)}° in z = "
            f"{du.show(u.plane, 'length', digits)} {L}" for u in resp.unbalance)
    doc.note(src + ".")
    if resp.peaks:
        rows = [(str(p.bearing), num(p.speed * RPM, digits),
                 "∞ (undamped)" if p.undamped else num(p.amplitude * UM, digits), _af(p, digits),
                 "—" if p.half_power is None else
                 f"{num(p.half_power[0] * RPM, digits)}-{num(p.half_power[1] * RPM, digits)}",
                 p.mode or "—", p.whirl or "—") for p in resp.peaks]
        doc.table("response peaks (amplification factor AF = Nc/(N2 - N1), half-power points)",
                  ("bearing", "Nc [rpm]", "amplitude [µm]", "AF", "N1-N2 [rpm]", "mode", "whirl"), rows,
                  right=(1, 2, 3, 4))
        if any(p.basis == "damping ratio" for p in resp.peaks):
            doc.note("AF (1/2ζ): the response does not fall to 1/√2 of the peak before it rises into "
                     "the next one (the half-power bands overlap), so AF is 1/(2ζ) of the mode's "
                     "damping ratio at its damped critical speed (API 684).")
    if resp.at_speed:
        rows = [(str(i + 1), num(a.displacement * UM, digits), num(a.displacement_phase_deg, digits),
                 num(a.force, digits), num(a.force_phase_deg, digits),
                 "—" if a.rigid_force is None else num(a.rigid_force, digits)) for i, a in enumerate(resp.at_speed)]
        doc.table(f"at {num(res.speed[1] * RPM, digits)} rpm (the operating speed)",
                  ("bearing", "displacement [µm]", "phase [°]", "force [N]", "phase [°]", "on rigid bearings [N]"),
                  rows, right=(1, 2, 3, 4, 5))


def _margins(doc: Doc, res: WhirlResult, digits: int) -> None:
    mg = res.margins
    if mg is None:
        return
    lo, hi = mg.operating_speed
    op = f"{num(lo * RPM, digits)} rpm" if lo == hi else f"{num(lo * RPM, digits)}-{num(hi * RPM, digits)} rpm"
    rows = [("—" if ch.bearing is None else str(ch.bearing), num(ch.speed * RPM, digits), ch.mode or "—",
             _af(ch, digits), ch.position, num(ch.margin_percent, digits), num(ch.required_margin_percent, digits),
             "PASS" if ch.passed else "FAIL") for ch in mg.checks]
    doc.table(f"separation margins from the operating speed {op} (API 617 / API 684 rule)",
              ("bearing", "critical [rpm]", "mode", "AF", "position", "margin [%]", "required [%]", "verdict"),
              rows, right=(1, 3, 5, 6))
    doc.note("rule: " + mg.rule + ". (Taken from public implementations of the standard; check a "
             "licensed copy before claiming conformity.)")
    if mg.passed is None:
        doc.note("separation margins: nothing to judge (no response peak in the speed range).")
    else:
        doc.note("separation margins: " + ("PASS" if mg.passed else "FAIL: a critical speed is too close "
                                            "to the operating speed for its amplification factor") + ".")


def _map(doc: Doc, res: WhirlResult, digits: int) -> None:
    """The critical speed map at each decade of stiffness."""
    cm = res.critical_speed_map
    k = np.asarray(cm.stiffness)
    decades = [j for j, x in enumerate(k) if abs(math.log10(x) - round(math.log10(x))) < 1e-9]
    rows = [(num(k[j], digits), *(num(cm.speeds[b][j] * RPM, digits) for b in range(len(cm.whirl))))
            for j in decades or range(len(k))]
    doc.table("undamped critical speed map (every bearing the stiffness k, isotropic; no damping)",
              ("k [N/m]", *(f"{w} {m} [rpm]" for w, m in zip(cm.whirl, cm.mode))), rows,
              right=tuple(range(len(cm.whirl) + 1)))
    doc.note("map: each critical speed grows as the square root of the stiffness (a rigid rotor); "
             "where a bearing's stiffness against speed (drawn on the map's figure) meets a branch "
             "is that critical speed on that bearing.")


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
    if all(_conservative(b) for b in res.bearings):
        return ("stability: no damping and no cross-coupling: every mode is neutrally stable "
                "(it neither grows nor decays).")
    if st.stable_in_range and st.stable_at_speed is not False:
        return (f"stability: STABLE over the speed range (least damping ratio {num(st.least_damping_ratio, digits)} "
                f"at {num(st.least_damping_speed * RPM, digits)} rpm).")
    parts = ["stability: UNSTABLE — a whirl mode GROWS"]
    if st.unstable_from_start:
        parts.append(" from the start of the speed range")
    elif st.threshold_speed is not None:
        parts.append(f" from the threshold speed of instability {num(st.threshold_speed * RPM, digits)} rpm")
    parts.append(f"; least damping ratio {num(st.least_damping_ratio, digits)} at "
                 f"{num(st.least_damping_speed * RPM, digits)} rpm")
    if st.stable_at_speed is False:
        parts.append("; UNSTABLE AT THE OPERATING SPEED")
    return "".join(parts) + "."


# --- figures


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


def _by_branch(cb, values: np.ndarray) -> np.ndarray:
    """(4, N) ``values`` (by frequency at each speed) reordered by branch: row k is the mode
    followed by its shape from mode k at the first speed."""
    br = np.asarray(cb.branch) - 1
    out = np.empty_like(values)
    np.put_along_axis(out, br, values, 0)
    return out


def _critical_marks(res: WhirlResult, lo: float, hi: float) -> list[tuple[float, int, str, int]]:
    """(speed, order, how, count) of the critical speeds in [lo, hi] rad/s: at the damped
    crossing, else the undamped speed ("undamped": no damped crossing); how "driven" when
    the unbalance drives one; those that coincide (to 1e-6 of the speed, one order) one mark."""
    marks: list[list] = []
    for c in sorted(res.critical_speeds, key=lambda c: (c.order, c.damped_speed or c.speed)):
        s = c.damped_speed if c.damped_speed is not None else c.speed
        if not lo <= s <= hi:
            continue
        how = "driven" if c.excited else "undamped" if c.damped_speed is None and not _exact_only(res) else "not driven"
        if marks and marks[-1][1] == c.order and abs(marks[-1][0] - s) <= 1e-6 * s:
            marks[-1][2] = "driven" if "driven" in (how, marks[-1][2]) else marks[-1][2]
            marks[-1][3] += 1
        else:
            marks.append([s, c.order, how, 1])
    return [tuple(m) for m in marks]


def _exact_only(res: WhirlResult) -> bool:
    """Undamped and conservative: the critical speeds are the crossings themselves."""
    return all(_conservative(b) for b in res.bearings)


#: how a critical speed is marked: (marker, face colour, legend, z-order: driven on top)
MARKS = {"driven": ("o", "black", "critical speed (driven by the unbalance)", 6),
         "not driven": ("o", "white", "critical speed (not driven)", 5),
         "undamped": ("s", "white", "undamped critical speed (no damped crossing)", 5)}


def campbell_figure(res: WhirlResult):
    """The Campbell diagram of ``--plot`` (what it draws: the man page's notes,
    :mod:`rbcli.cli.whirl`). A matplotlib Figure."""
    cb = res.campbell
    sp = np.asarray(cb.speeds) * RPM
    fr = np.asarray(cb.frequencies) * RPM
    fig, axes = figure(f"whirl: {res.name} — Campbell diagram", size=(7.5, 5.0))
    ax = axes[0][0]
    seen = set()
    whirl = _by_branch(cb, np.array(cb.whirl, dtype=object))
    fb = _by_branch(cb, fr)
    for i in range(fb.shape[0]):
        for lab, xs, ys in _segments(sp, fb[i], tuple(whirl[i])):
            name, colour, ls = WHIRL_STYLE.get(lab, WHIRL_STYLE["none"])
            ax.plot(xs, ys, color=colour, linestyle=ls, linewidth=1.5, label=name if lab not in seen else None)
            seen.add(lab)
    grow = np.asarray(cb.damping_ratio) < -1e-9
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
    marks = _critical_marks(res, sp[0] / RPM, top / RPM)
    for k, (s, n, how, count) in enumerate(marks):
        marker, face, name, z = MARKS[how]
        ax.plot([s * RPM], [n * s * RPM], marker=marker, markersize=6, linestyle="none", zorder=z,
                markerfacecolor=face, markeredgecolor="black", label=None if how in seen else name)
        seen.add(how)
        near = k > 0 and abs(s - marks[k - 1][0]) < 0.06 * top / RPM and k % 2  # a close neighbour: below
        ax.annotate(f"{s * RPM:.4g}" + (f" (×{count})" if count > 1 else ""), (s * RPM, n * s * RPM),
                    textcoords="offset points", xytext=(8, -12) if near else (-8, 6),
                    ha="left" if near else "right", fontsize=7, zorder=7)
    ymax = max([ymax] + [n * s * RPM for s, n, _, _ in marks])
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


def map_figure(res: WhirlResult):
    """The undamped critical speed map of ``--plot-map`` (the man page's notes). A matplotlib
    Figure."""
    cm = res.critical_speed_map
    k = np.asarray(cm.stiffness)
    fig, axes = figure(f"whirl: {res.name} — undamped critical speed map", size=(7.5, 5.0))
    ax = axes[0][0]
    from matplotlib.ticker import FuncFormatter, NullFormatter

    for b in range(len(cm.whirl)):
        ax.plot(k, np.asarray(cm.speeds[b]) * RPM, linewidth=1.2, markevery=8, markersize=4,
                label=f"{cm.whirl[b]} {cm.mode[b]}", **style(b))
    for i, c in enumerate(cm.bearings):
        sp = np.asarray(c["speeds"]) * RPM
        colour = ("tab:blue", "tab:orange", "tab:green", "tab:red")[i % 4]
        ax.plot(c["kxx"], sp, color=colour, linewidth=2.6, alpha=0.55, label=f"bearing {i + 1} kxx")
        if c["kyy"] != c["kxx"]:
            ax.plot(c["kyy"], sp, color=colour, linewidth=2.6, alpha=0.55, linestyle="--",
                    label=f"bearing {i + 1} kyy")
    if res.speed is not None:
        for x in sorted(set(res.speed)):
            ax.axhline(x * RPM, color="0.3", linewidth=0.9, linestyle="-.")
    ax.set_xscale("log")
    ax.set_yscale("log")
    for axis in (ax.xaxis, ax.yaxis):  # plain text, not mathtext
        axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
        axis.set_minor_formatter(NullFormatter())
    ax.set_xlim(float(k[0]), float(k[-1]))
    ax.set_xlabel("bearing stiffness [N/m]")
    ax.set_ylabel("critical speed [rpm]")
    ax.set_title("every bearing the stiffness on the axis, no damping; the bearings' own stiffness "
                 "against speed drawn over it", fontsize=8)
    fig.legend(loc="outside lower center", ncols=3, fontsize=7)
    return fig


def response_figure(res: WhirlResult):
    """The unbalance response of ``--plot-response`` (the man page's notes). A matplotlib Figure."""
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
    said: list[tuple[float, str]] = []  # AF labels placed: a twin peak's goes below, the same one once
    for p in resp.peaks:
        if p.undamped:
            ax.axvline(p.speed * RPM, color="0.5", linewidth=0.7, linestyle=":")
            continue
        ax.plot([p.speed * RPM], [p.amplitude * UM], marker="o", color="black", markersize=4, linestyle="none")
        if p.half_power is not None:
            lvl = p.amplitude * UM / math.sqrt(2.0)
            ax.plot([p.half_power[0] * RPM, p.half_power[1] * RPM], [lvl, lvl], color="0.4", linewidth=0.8)
        if p.amplification_factor is None:  # no AF defined (e.g. a peak without half-power points)
            continue
        text = f"AF {p.amplification_factor:.3g}" + (" (1/2ζ)" if p.basis == "damping ratio" else "")
        near = [t for s, t in said if abs(s - p.speed) < 0.05 * (sp[-1] - sp[0]) / RPM]
        if text not in near:
            ax.annotate(text, (p.speed * RPM, p.amplitude * UM), textcoords="offset points",
                        xytext=(5, 3 - 12 * len(near)), fontsize=7)
            said.append((p.speed, text))
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
    ax.set_ylabel("displacement [µm]\n(orbit semi-major axis)")
    src = "the body's own unbalance" if resp.source == "body" else "the unbalances given"
    ax.set_title(f"response to {src}; half-power points marked", fontsize=9)
    fig.legend(loc="outside lower center", ncols=3, fontsize=7)
    from matplotlib.ticker import MultipleLocator

    axp.yaxis.set_major_locator(MultipleLocator(90.0))
    axp.set_xlabel("rotor speed [rpm]")
    axp.set_ylabel("high-spot phase [°]\n(rotor frame)")
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

