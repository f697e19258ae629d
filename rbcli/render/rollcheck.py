"""Tables and the figure of ``rbcli rollcheck`` (the JSON is the result's ``to_json()``).

Everything here is formatting: the numbers and the figure's arrays come finished from
:class:`rbcli.api.rollcheck.RollcheckResult` (``curves()``)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.render import echo
from rbcli.render.fmt import num, said
from rbcli.render.plots import figure, style
from rbcli.render.text import Doc
from rbcli.render.top import asymmetry_note
from rbcli.render.units import RPM, DisplayUnits

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.rollcheck import RollcheckResult
    from rbcli.core.rolling import Curves


def echo_rows(res: RollcheckResult) -> list[tuple[str, str, str]]:
    """The options as understood (:func:`rbcli.render.echo.echo_rows`)."""
    return echo.echo_rows(res.options, res.units)


# --- tables


def _rate(du: DisplayUnits, x: float | None, digits: int) -> tuple[str, str]:
    """A rate in 1/s (or per the display time unit)."""
    f, t = du.factor("time")
    if x is None:
        return "—", f"1/{t}"
    return num(x / f, digits), f"1/{t}"


def document(doc: Doc, res: RollcheckResult, du: DisplayUnits, digits: int) -> None:
    """The tables of a rolling check, into ``doc``."""
    st = res.straight
    w = st.wheel
    o, du = res.options, du.of(res.units)
    L, M, I = du.unit("length"), du.unit("mass"), du.unit("inertia")
    doc.heading(f"{res.name}  ({res.source})")
    rim_label = {"edge": " (knife edge)", "torus": " (rounded rim)", "sphere": " (a sphere)",
                 "band": " (flat band)"}[st.rim]
    rows = [
        ("rim radius a", du.show(st.radius, "length", digits), L),
        ("tyre radius r" + rim_label, du.show(st.tyre_radius, "length", digits), L),
        ("mass m", du.show(w.mass, "mass", digits), M),
        ("I = A, across the axle, about the com", du.show(w.A, "inertia", digits), I),
        ("Is = C, about the axle", du.show(w.C, "inertia", digits), I),
        ("Is + m a², axial, about the contact point", du.show(st.C_contact, "inertia", digits), I),
        ("I + m a², fore-aft, about the contact point", du.show(st.A_contact, "inertia", digits), I),
        ("g", du.show(st.g, "acceleration", digits), du.unit("acceleration")),
    ]
    if st.band is not None:
        rows[2:2] = [("band width (along the axle)", du.show(st.band[0] + st.band[1], "length", digits), L)]
    doc.kv("wheel", rows)
    doc.note(f"rim radius from {said(res.setup.radius_source)}{_tyre_source(res)}; axle along "
             f"[{', '.join(num(x, digits) for x in w.axle)}] ({said(res.setup.axle_source)}).")
    if res.asymmetry is not None:
        asymmetry_note(doc, res.asymmetry, o.symmetry_tol, res.asymmetry_effect, du, digits, "wheel", "I")
    doc.note("model: " + res.model + ".")
    rows = [
        ("critical spin s_c", du.show(st.critical_spin, "angular_speed", digits), "rad/s"),
        ("critical spin s_c", num(st.critical_spin * RPM, digits), "rpm"),
        ("critical speed v_c = a s_c", du.show(st.critical_speed, "speed", digits), du.unit("speed")),
        ("critical speed v_c", num(st.critical_speed * 3.6, digits), "km/h"),
    ]
    if st.band is not None:
        assert st.static_lean_limit is not None and st.knife_edge_critical_spin is not None
        rows.insert(0, ("static lean limit atan(c/a) (weight within the band)",
                        num(math.degrees(st.static_lean_limit), digits), "°"))
        rows.append(("knife edge at the com's plane (for comparison)",
                     du.show(st.radius * st.knife_edge_critical_spin, "speed", digits), du.unit("speed")))
    title = {"band": "straight rolling on a flat band: threshold (balanced on an edge)",
             "sphere": "straight rolling on a sphere: threshold"}.get(st.rim, "straight upright rolling: threshold")
    doc.kv(title, rows)
    doc.note(_threshold_note(st, digits))
    v = res.verdict
    if v is not None:
        given = "--speed" if o.rolling_speed is not None else "--spin"
        speed_arg = (_speed_text(v.speed, du, digits) if o.rolling_speed is not None
                     else f"{du.show(v.spin, 'angular_speed', digits)} rad/s")
        rows = [
            ("speed v" + (" (backwards)" if v.backwards else ""), du.show(v.speed, "speed", digits), du.unit("speed")),
            ("spin s = v / a", du.show(v.spin, "angular_speed", digits), "rad/s"),
            ("margin |v| / v_c", "—" if v.margin is None else num(v.margin, digits), ""),
            ("verdict", "STABLE" if v.stable else ("UNSTABLE on an edge" if st.rim == "band" else "UNSTABLE"), ""),
        ]
        if v.stable:
            rows.append(("lean oscillation frequency ν", du.show(v.lean_frequency, "angular_speed", digits), "rad/s"))
            rows.append(("lean oscillation frequency ν/2π", num(v.lean_frequency_hz, digits), "Hz"))
            rows.append(("period 2π/ν", num(1.0 / v.lean_frequency_hz, digits) if v.lean_frequency_hz else "—", "s"))
        else:
            val, unit = _rate(du, v.growth_rate, digits)
            rows.append(("lean growth rate √(−ν²)", val, unit))
            if v.growth_rate:
                rows.append(("e-folding time", num(1.0 / v.growth_rate, digits), "s"))
        doc.kv(f"straight rolling at {given} {speed_arg}", rows)
        if res.straight_asked:
            doc.note(_straight_verdict(res, du, digits))
        else:
            doc.note("(straight rolling at this speed, for comparison; the steady circle below is "
                     "the motion asked about and sets the exit status)")
    circ = res.circle
    if circ is not None:
        how = _circle_how(res)
        rows = [
            ("lean β from the vertical (inwards)", num(circ.lean_deg, digits), "°"),
            ("radius of the centre's circle R_G", du.show(circ.radius, "length", digits), L),
            ("radius of the contact point's circle R_P", du.show(circ.contact_radius, "length", digits), L),
            ("turn rate Ω", du.show(circ.turn_rate, "angular_speed", digits), "rad/s"),
            ("spin about the axle ω3", du.show(circ.spin, "angular_speed", digits), "rad/s"),
            ("speed of the centre v = Ω R_G", du.show(circ.speed, "speed", digits), du.unit("speed")),
            ("lean stiffness κ", du.show(circ.kappa, "torque", digits), du.unit("torque")),
            ("verdict", "STABLE" if circ.stable else "UNSTABLE", ""),
        ]
        if circ.stable:
            rows.append(("lean oscillation frequency √(κ/(I + m a²))", du.show(circ.lean_frequency, "angular_speed", digits), "rad/s"))
            rows.append(("lean oscillation frequency /2π", num(circ.lean_frequency / (2 * math.pi), digits), "Hz"))
        else:
            val, unit = _rate(du, circ.growth_rate, digits)
            rows.append(("lean growth rate √(−κ/(I + m a²))", val, unit))
        title = "steady circular rolling" + (" (spinning in place)" if circ.radius == 0.0 else "")
        doc.kv(title, rows)
        doc.note(f"({how})")
        if circ.stable:
            doc.note(f"verdict: the steady circle is STABLE (κ > 0): a small lean disturbance "
                     f"oscillates at {num(circ.lean_frequency, digits)} rad/s (undamped).")
        else:
            extra = " (the wheel is upright and at rest: it falls over)" if circ.turn_rate == 0.0 else ""
            doc.note(f"verdict: the steady circle is UNSTABLE (κ ≤ 0): a small lean disturbance "
                     f"grows at {num(circ.growth_rate, digits)} 1/s{extra}.")


def _speed_text(v: float, du: DisplayUnits, digits: int) -> str:
    return f"{du.show(v, 'speed', digits)} {du.unit('speed')}"


def _tyre_source(res: RollcheckResult) -> str:
    o, st = res.setup, res.straight
    if o.tyre_radius_kind == "tyre_radius":  # given (a Note: "{tyre_radius}")
        return f"; tyre radius from {said(o.tyre_radius_kind)}"
    if o.rim is None:
        return ""
    parts = ", ".join(f"'{n}' ({s})" for n, s in o.rim.parts)
    what = {"edge": "a knife edge", "torus": "a torus: its tube radius", "sphere": "a sphere: its radius",
            "band": "a flat band: its width along the axle"}[st.rim]
    return f"; the rim is {what}, from part {parts}"


def _threshold_note(st: Any, digits: int) -> str:
    if st.rim == "sphere":
        return ("critical speed 0: a rolling sphere has no lean instability: it stays up at any "
                "speed (its weight acts through the contact point at every lean; ν² = "
                "Is (Is + m a²) s² / (I (I + m a²)) ≥ 0).")
    if st.rim == "band":
        lim = num(math.degrees(st.static_lean_limit), digits)
        return (f"on its flat band the weight holds it up against leans below {lim}° at any speed "
                "(a disturbance within that rocks it back, or rolls it on along a curve on one "
                f"edge); tipped past {lim}° it balances on an edge circle, c from the com's plane, "
                "and is stable (neutrally) there when s² > s_e² = m g l Δ / (Is (Is + m a²) "
                "(Is + m l²)), l² = a² + c², Δ = (Is + m a²)(I + m c²) − m² a² c²: s_c is the larger "
                "of the two edges'.")
    return ("stable (neutrally) when the spin s about the axle has s² > s_c² = "
            "m g (a − r) I / (Is (Is + m a²)).")


def _straight_verdict(res: RollcheckResult, du: DisplayUnits, digits: int) -> str:
    v = res.verdict
    st = res.straight
    assert v is not None
    if st.rim == "sphere":
        return (f"verdict: STABLE at {_speed_text(abs(v.speed), du, digits)}: a rolling sphere "
                "stays up at any speed.")
    at = f"{_speed_text(abs(v.speed), du, digits)} ({num(v.margin, digits)} × the critical speed " \
         f"{_speed_text(st.critical_speed, du, digits)})"
    if st.rim == "band" and not v.stable:
        lim = num(math.degrees(st.static_lean_limit), digits)
        return (f"verdict: UNSTABLE at {at} when balanced on an edge: the band holds it up against "
                f"leans below {lim}°, but tipped past {lim}° onto an edge the lean grows as "
                f"exp({num(v.growth_rate, digits)} t/s); roll faster than "
                f"{_speed_text(st.critical_speed, du, digits)} to stay up however it is tipped.")
    if v.stable:
        return (f"verdict: STABLE at {at}: a small lean oscillates at "
                f"{num(v.lean_frequency_hz, digits)} Hz and stays bounded (undamped).")
    if v.growth_rate == 0.0:
        return (f"verdict: UNSTABLE at {at}: exactly at the threshold the lean drifts "
                "(grows linearly).")
    return (f"verdict: UNSTABLE at {at}: a small lean grows as exp({num(v.growth_rate, digits)} t/s); "
            f"roll faster than {_speed_text(st.critical_speed, du, digits)}.")


def _circle_how(res: RollcheckResult) -> str:
    o = res.options
    sp = "--speed" if o.rolling_speed is not None else "--spin"
    if o.lean is not None and o.circle is not None:
        return "from --lean and --circle"
    if o.circle is not None:
        return f"lean solved from {sp} and --circle"
    return f"circle radius solved from {sp} and --lean"


# --- plot


def plot(res: RollcheckResult, cv: Curves):
    """nu^2 and the lean frequency / growth rate against speed (critical speed marked);
    with a circle, the stable region in the (lean, circle radius) plane instead of the
    second panel. ``cv`` is ``res.curves()``. Returns the matplotlib Figure."""
    vc = cv.critical_speed
    speeds, nu2 = cv.speeds, cv.nu2
    vmax = float(speeds[-1])
    fig, axes = figure(f"rollcheck: {res.name}", nrows=1, ncols=2, size=(9.0, 4.0))
    ax = axes[0][0]
    ax.axhline(0.0, color="0.6", linewidth=0.8)
    ax.plot(speeds, nu2, label="ν² (> 0 stable: oscillation; < 0 unstable: growth)", **style(0))
    ax.axvline(vc, label=f"critical speed {vc:.4g} m/s", **style(1))
    ax.axvspan(0.0, vc, color="0.92", zorder=0)
    if res.verdict is not None:
        v = abs(res.verdict.speed)
        ax.plot([v], [res.verdict.nu2], marker="o", color="black", linestyle="none",
                label=f"{v:.4g} m/s: {'stable' if res.verdict.stable else 'unstable'}")
    ax.set_xlabel("speed of the centre v [m/s]")
    ax.set_ylabel("squared lean frequency ν² [rad²/s²]")
    ax.set_title({"band": "straight rolling balanced on an edge (shaded: unstable)",
                  "sphere": "straight rolling on a sphere (never unstable)"}.get(
        res.straight.rim, "straight upright rolling (shaded: unstable)"))
    ax.set_xlim(0.0, vmax)
    ax.legend(loc="upper left")

    ax = axes[0][1]
    if res.circle is None or cv.circle_kappa is None:
        above = speeds >= vc
        ax.plot(speeds[above], cv.lean_frequency[above], label="lean frequency ν [rad/s]", **style(0))
        ax.plot(speeds[~above], cv.growth_rate[~above], label="growth rate √(−ν²) [1/s]", **style(1))
        ax.axvline(vc, **style(2))
        ax.axvspan(0.0, vc, color="0.92", zorder=0)
        if res.verdict is not None:
            y = res.verdict.lean_frequency if res.verdict.stable else res.verdict.growth_rate
            ax.plot([abs(res.verdict.speed)], [y], marker="o", color="black", linestyle="none")
        ax.set_xlabel("speed of the centre v [m/s]")
        ax.set_ylabel("rate [rad/s or 1/s]")
        ax.set_title("lean oscillation (v > v_c) or growth (v < v_c)")
        ax.set_xlim(0.0, vmax)
        ax.legend(loc="upper right")
    else:
        c = res.circle
        X, Y = np.meshgrid(cv.circle_radii, cv.circle_leans_deg)
        kappa, V = cv.circle_kappa, cv.circle_speed
        ax.contourf(X, Y, (kappa > 0.0).astype(float), levels=[-0.5, 0.5, 1.5], colors=["0.92", "white"])
        ax.contour(X, Y, kappa, levels=[0.0], colors="black", linewidths=1.2)
        # dotted: the speed of the centre along the steady circles, v = Omega R_G
        cs = ax.contour(X, Y, V, levels=_speed_levels(V), colors="0.5", linewidths=0.7,
                        linestyles=":")
        ax.clabel(cs, fmt=lambda x: f"{x:g} m/s", fontsize=7)
        ax.plot([c.radius], [c.lean_deg], marker="o", color="black", linestyle="none")
        ax.annotate(f"asked: {'stable' if c.stable else 'unstable'}", (c.radius, c.lean_deg),
                    xytext=(6, 6), textcoords="offset points", fontsize=8)
        ax.set_xlabel("radius of the centre's circle R_G [m]")
        ax.set_ylabel("inward lean β [°] (dotted: speed of the centre)")
        ax.set_title("steady circles (shaded: unstable, κ ≤ 0)")
    return fig


def _speed_levels(V) -> list[float]:
    """A handful of round speeds spread over the map (for dotted, labelled contours)."""
    vals = np.asarray(V, dtype=float)
    vals = vals[np.isfinite(vals) & (vals > 0.0)]
    if vals.size == 0:
        return [1.0]
    out: list[float] = []
    for q in np.quantile(vals, [0.15, 0.35, 0.55, 0.75, 0.9]):
        e = math.floor(math.log10(q))
        x = float(f"{round(q / 10.0 ** e) * 10.0 ** e:.1g}")
        if x > 0.0 and x not in out:
            out.append(x)
    return sorted(out)
