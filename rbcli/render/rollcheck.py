"""Tables, JSON and the figure of ``rbcli rollcheck``."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from rbcli.core.rolling import RollCheck
from rbcli.model import Body
from rbcli.render.fmt import DisplayUnits, num
from rbcli.render.text import Doc

RPM = 60.0 / (2.0 * math.pi)  # rad/s -> rev/min


@dataclass(frozen=True)
class Info:
    """What the command knows besides the physics: where the inputs came from."""

    body: Body
    radius_source: str
    axle_source: str
    axle_through: Any
    radius_kind: str = "--radius"
    radius_part: str | None = None
    speed_given: bool = False
    spin_given: bool = False
    lean_given: bool = False
    circle_given: bool = False
    straight_asked: bool = False
    circle_asked: bool = False


# ----------------------------------------------------------------------------- JSON

SPEC_TOP = ("radius", "mass", "I", "Is", "critical_spin", "critical_speed")
SPEC_SPEED = ("speed", "stable", "margin")


def to_json(res: RollCheck, info: Info) -> dict:
    """SPEC §3 keys first (radius, mass, I, Is, critical_spin, critical_speed; speed,
    stable, margin with a speed; circle {...} when asked), then the extras."""
    core = res.to_json()
    out: dict[str, Any] = {k: core[k] for k in SPEC_TOP}
    if res.verdict is not None:
        out.update({k: core[k] for k in SPEC_SPEED})
    if res.circle is not None:
        out["circle"] = core["circle"]
    out["radius_source"] = info.radius_kind
    if info.radius_part is not None:
        out["radius_part"] = info.radius_part
    for k, v in core.items():
        if k not in out and k != "model":
            out[k] = v
    w = res.straight.wheel
    out["axle"] = list(w.axle)
    out["axle_through"] = [float(x) for x in info.axle_through]
    out["com"] = list(w.com)
    out["model"] = model_sentence(res)
    out["name"] = info.body.name
    out["file"] = info.body.source
    return out


def model_sentence(res: RollCheck) -> str:
    r = res.straight.tyre_radius
    rim = "knife-edge rim (tyre radius 0)" if r == 0.0 else f"rounded rim of tube radius r = {r:.6g} m (gravity term a - r)"
    return (
        f"{rim} rolling without slip on a rough level floor; I and Is about the centre of "
        "mass, Is + m a^2 about the contact point; stable means neutral stability (undamped): "
        "a small lean oscillates, it does not decay"
    )


# ----------------------------------------------------------------------------- tables


def _rate(du: DisplayUnits, x: float | None, digits: int) -> tuple[str, str]:
    """A rate in 1/s (or per the display time unit)."""
    f, t = du.factor("time")
    if x is None:
        return "—", f"1/{t}"
    return num(x / f, digits), f"1/{t}"


def document(doc: Doc, res: RollCheck, info: Info, du: DisplayUnits, digits: int) -> None:
    st = res.straight
    w = st.wheel
    b = info.body
    L, M, I = du.unit("length"), du.unit("mass"), du.unit("inertia")
    doc.heading(f"{b.name}  ({b.source})")
    rows = [
        ("rim radius a", du.show(st.radius, "length", digits), L),
        ("tyre radius r" + (" (knife edge)" if st.tyre_radius == 0.0 else " (rounded rim)"),
         du.show(st.tyre_radius, "length", digits), L),
        ("mass m", du.show(w.mass, "mass", digits), M),
        ("I = A, across the axle, about the com", du.show(w.A, "inertia", digits), I),
        ("Is = C, about the axle", du.show(w.C, "inertia", digits), I),
        ("Is + m a², axial, about the contact point", du.show(st.C_contact, "inertia", digits), I),
        ("I + m a², fore-aft, about the contact point", du.show(st.A_contact, "inertia", digits), I),
        ("g", du.show(st.g, "acceleration", digits), du.unit("acceleration")),
    ]
    doc.kv("wheel", rows)
    doc.note(f"rim radius from {info.radius_source}; axle along "
             f"[{', '.join(num(x, digits) for x in w.axle)}] ({info.axle_source}).")
    doc.note("model: " + model_sentence(res) + ".")
    doc.kv(
        "straight upright rolling: threshold",
        [
            ("critical spin s_c", du.show(st.critical_spin, "angular_speed", digits), "rad/s"),
            ("critical spin s_c", num(st.critical_spin * RPM, digits), "rpm"),
            ("critical speed v_c = a s_c", du.show(st.critical_speed, "speed", digits), du.unit("speed")),
            ("critical speed v_c", num(st.critical_speed * 3.6, digits), "km/h"),
        ],
    )
    doc.note("stable (neutrally) when the spin s about the axle has s² > s_c² = "
             "m g (a − r) I / (Is (Is + m a²)).")
    v = res.verdict
    if v is not None:
        given = "--speed" if info.speed_given else "--spin"
        speed_arg = (_speed_text(v.speed, du, digits) if info.speed_given
                     else f"{du.show(v.spin, 'angular_speed', digits)} rad/s")
        rows = [
            ("speed v" + (" (backwards)" if v.backwards else ""), du.show(v.speed, "speed", digits), du.unit("speed")),
            ("spin s = v / a", du.show(v.spin, "angular_speed", digits), "rad/s"),
            ("margin |v| / v_c", num(v.margin, digits), ""),
            ("verdict", "STABLE" if v.stable else "UNSTABLE", ""),
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
        if info.straight_asked:
            doc.note(_straight_verdict(res, du, digits))
        else:
            doc.note("(straight rolling at this speed, for comparison; the steady circle below is "
                     "the motion asked about and sets the exit status)")
    circ = res.circle
    if circ is not None:
        how = _circle_how(info)
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


def _straight_verdict(res: RollCheck, du: DisplayUnits, digits: int) -> str:
    v = res.verdict
    st = res.straight
    assert v is not None
    at = f"{_speed_text(abs(v.speed), du, digits)} ({num(v.margin, digits)} × the critical speed " \
         f"{_speed_text(st.critical_speed, du, digits)})"
    if v.stable:
        return (f"verdict: STABLE at {at}: a small lean oscillates at "
                f"{num(v.lean_frequency_hz, digits)} Hz and stays bounded (undamped).")
    if v.growth_rate == 0.0:
        return (f"verdict: UNSTABLE at {at}: exactly at the threshold the lean drifts "
                "(grows linearly).")
    return (f"verdict: UNSTABLE at {at}: a small lean grows as exp({num(v.growth_rate, digits)} t/s); "
            f"roll faster than {_speed_text(st.critical_speed, du, digits)}.")


def _circle_how(info: Info) -> str:
    sp = "--speed" if info.speed_given else "--spin"
    if info.lean_given and info.circle_given:
        return "from --lean and --circle"
    if info.circle_given:
        return f"lean solved from {sp} and --circle"
    return f"circle radius solved from {sp} and --lean"


# ----------------------------------------------------------------------------- plot


def plot(res: RollCheck, info: Info):
    """nu^2 and the lean frequency / growth rate against speed (critical speed marked);
    with a circle, the stable region in the (lean, circle radius) plane instead of the
    second panel."""
    from rbcli.core.rolling import margin_curve, stability_map
    from rbcli.render.plots import figure, style

    st = res.straight
    w = st.wheel
    vc = st.critical_speed
    vmax = 2.5 * vc
    if res.verdict is not None:
        vmax = max(vmax, 1.25 * abs(res.verdict.speed))
    speeds = np.linspace(0.0, vmax, 501)
    nu2 = margin_curve(w, st.radius, st.tyre_radius, st.g, speeds)
    fig, axes = figure(f"rollcheck: {info.body.name}", nrows=1, ncols=2, size=(9.0, 4.0))
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
    ax.set_title("straight upright rolling (shaded: unstable)")
    ax.set_xlim(0.0, vmax)
    ax.legend(loc="upper left")

    ax = axes[0][1]
    if res.circle is None:
        freq = np.sqrt(np.clip(nu2, 0.0, None))
        grow = np.sqrt(np.clip(-nu2, 0.0, None))
        above = speeds >= vc
        ax.plot(speeds[above], freq[above], label="lean frequency ν [rad/s]", **style(0))
        ax.plot(speeds[~above], grow[~above], label="growth rate √(−ν²) [1/s]", **style(1))
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
        a = st.radius
        rmax = max(10.0 * a, 2.0 * c.radius)
        leans_deg = np.linspace(0.25, 85.0, 200)
        radii = np.linspace(0.0, rmax, 220)
        kappa = stability_map(w, a, st.g, np.radians(leans_deg), radii)
        X, Y = np.meshgrid(radii, leans_deg)
        ax.contourf(X, Y, (kappa > 0.0).astype(float), levels=[-0.5, 0.5, 1.5], colors=["0.92", "white"])
        ax.contour(X, Y, kappa, levels=[0.0], colors="black", linewidths=1.2)
        # speed of the centre along the steady circles: v = Omega R_G
        Cc = w.C + w.mass * a * a
        b = np.radians(Y)
        W = np.sqrt(w.mass * st.g * a * a * np.tan(b) / (w.A * a * np.sin(b) + Cc * X))
        V = W * X
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
