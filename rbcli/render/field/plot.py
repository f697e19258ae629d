"""The polar diagrams of ``field-balance --plot`` and the job sheet: a dial per reading (O
black, each run O+T and its change in the run's colour, the prediction grey) and per plane
(trial, correction, masses fitted; a drawer's holes numbered on the rim), each with a legend,
angles running as the rotor is seen. At most :data:`MAX_DIALS` readings (the largest) with
the :data:`MAX_RUNS` runs that moved each most, and :data:`MAX_PLANES` planes; said.
"""

from __future__ import annotations

import cmath
import math
from typing import TYPE_CHECKING

from rbcli.core.field.solve import deg
from rbcli.render.fmt import num
from rbcli.render.plots import figure

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.field.result import FieldBalanceResult
    from rbcli.render.units import ShopUnits

#: the most reading dials and plane dials one figure draws, and runs one dial shows
MAX_DIALS, MAX_PLANES, MAX_RUNS = 12, 6, 6
#: a run's colour (Okabe and Ito's palette, distinct for colour-blind readers)
RUN_COLOURS = ("#E69F00", "#0072B2", "#009E73", "#CC79A7", "#D55E00", "#56B4E9", "#F0E442")


def _sense(res: FieldBalanceResult) -> int:
    """+1: angles drawn counterclockwise; -1: clockwise (against a ccw rotation, with a cw one)."""
    c = res.conventions
    if c is None or c.rotation is None:
        return 1
    return 1 if (c.rotation == "ccw") == (c.angle_sense != "against") else -1


def _arrow(ax, z: complex, colour: str, ls: str, tail: complex = 0j) -> None:
    if abs(z) > 0.0:
        tip = tail + z
        ax.annotate("", xy=(cmath.phase(tip), abs(tip)), xytext=(cmath.phase(tail), abs(tail)),
                    annotation_clip=False, arrowprops=dict(arrowstyle="-|>", color=colour, linestyle=ls,
                                                           linewidth=1.6, shrinkA=0, shrinkB=0, mutation_scale=12))


def _dial(ax, title: str, items: list, sense: int, big: float) -> None:
    """One dial: ``items`` (label, vector, colour, line style, tail) in display units."""
    from matplotlib.lines import Line2D

    ax.set_theta_zero_location("E")
    ax.set_theta_direction(sense)
    ax.set_ylim(0.0, big * 1.15 if big > 0 else 1.0)
    ax.set_rlabel_position(22.5)
    ax.tick_params(axis="both", labelsize=7)
    for _, z, colour, ls, tail in items:
        _arrow(ax, z, colour, ls, tail)
    ax.set_title(title, fontsize=9, pad=12)
    ax.legend(handles=[Line2D([], [], color=c, linestyle=ls, linewidth=1.6, label=lab) for lab, _, c, ls, _ in items],
              loc="upper center", bbox_to_anchor=(0.5, -0.1), fontsize=7, handlelength=2.4)


def _text(z: complex, unit: str) -> str:
    return f"{num(abs(z), 4)}{' ' + unit if unit else ''} at {num(deg(z), 4)}°" if z != 0 else "0"


def plot(res: FieldBalanceResult, su: ShopUnits, reading: tuple[float, str]):
    """The figure of an extended or classic result ``res`` (a matplotlib Figure)."""
    scale, ru = reading
    ms, mu = su.factor("mass"), su.unit("mass")
    n, p = len(res.initial), res.planes
    names = res.plane_names or ("A", "B")[:p]
    rows = res.row_names() if res.sensors else [(str(k + 1), "") for k in range(n)]
    keep = sorted(sorted(range(n), key=lambda k: -abs(res.initial[k]))[:MAX_DIALS])
    shown = list(range(min(p, MAX_PLANES)))
    dials = len(keep) + len(shown)
    cols = min(dials, 4)
    fig, axes = figure("field balancing" + (f": {res.name}" if res.name else ""), nrows=-(-dials // cols),
                       ncols=cols, size=(4.0 * cols, (4.8 + 0.2 * (2 + 2 * min(len(res.runs), MAX_RUNS)))
                                         * -(-dials // cols)))
    for ax in axes.flat:
        fig.delaxes(ax)
    sense = _sense(res)
    for i, k in enumerate(keep):
        o = res.initial[k] / scale
        items = [(f"O: {_text(o, ru)}", o, "black", "-", 0j)]
        refs = [(res.runs[j - 1][k] if j and res.cumulative else res.initial[k]) / scale for j in range(len(res.runs))]
        runs = sorted(sorted(range(len(res.runs)), key=lambda j: -abs(res.runs[j][k] / scale - refs[j]))[:MAX_RUNS])
        for j in runs:
            run, ref = res.runs[j][k] / scale, refs[j]
            colour = RUN_COLOURS[j % len(RUN_COLOURS)]
            items += [(f"O+T{names[j]}: {_text(run, ru)}", run, colour, "-", 0j),
                      (f"T{names[j]} (its change): {_text(run - ref, ru)}", run - ref, colour, ":", ref)]
        if res.residual_values:
            r = res.residual_values[k] / scale
            items.append((f"predicted: {_text(r, ru)}", r, "0.5", "--", 0j))
        big = max([abs(z) for _, z, _, _, _ in items] + [abs(t + z) for _, z, _, _, t in items])
        ax = fig.add_subplot(axes.shape[0], cols, i + 1, projection="polar")
        s, v = rows[k]
        _dial(ax, f"reading {s}" + (f" at {v}" if v else "") + (f" [{ru}]" if ru else ""), items, sense, big)
    for i, j in enumerate(shown):
        ax = fig.add_subplot(axes.shape[0], cols, len(keep) + i + 1, projection="polar")
        _plane(ax, res, j, names[j], sense, ms, mu)
    notes = [res.angle_convention]
    if len(keep) < n or len(shown) < p or len(res.runs) > MAX_RUNS:
        notes.append(f"{len(keep)} of {n} readings (the largest) and {len(shown)} of {p} planes drawn, each "
                     f"reading with the {min(MAX_RUNS, len(res.runs))} runs that changed it most")
    fig.supxlabel("; ".join(notes), fontsize=7, color="0.3", wrap=True)
    return fig


def _plane(ax, res: FieldBalanceResult, j: int, name: str, sense: int, ms: float, mu: str) -> None:
    """Plane ``j``'s dial (a drawer's holes numbered on the rim, the weights in them)."""
    items = []
    if j < len(res.trial_masses):
        t = res.trial_masses[j] / ms
        items.append((f"trial: {_text(t, mu)}", t, RUN_COLOURS[j % len(RUN_COLOURS)], "-.", 0j))
    c = res.corrections[j].correction / ms
    items.append((f"add (trial removed): {_text(c, mu)}", c, "black", "--", 0j))
    fitted = res.fitted.planes[j] if res.fitted is not None else None
    drawer = res.fitted.drawer.planes[j] if res.fitted is not None and res.fitted.drawer is not None else None
    for m in fitted.masses if fitted is not None else ():
        z = cmath.rect(m.mass / ms, math.radians(m.angle_deg))
        where = f"hole {m.position}" if drawer is not None else f"position {m.position}" if m.position else "fit"
        items.append((f"{where}: {num(m.mass / ms, 4)} {mu} at {num(m.angle_deg, 4)}°", z, "#009E73", "-", 0j))
    big = max(abs(z) for _, z, _, _, _ in items)
    if drawer is not None:
        rim = big * 1.08
        for h, a in enumerate(drawer.holes_deg):
            ax.plot([math.radians(a)], [rim], "o", mfc="white", mec="0.4", ms=6, clip_on=False)
            ax.annotate(str(h + 1), (math.radians(a), rim), textcoords="offset points", xytext=(0, 6),
                        ha="center", fontsize=6, color="0.3", annotation_clip=False)
        for m in fitted.masses:
            ax.plot([math.radians(m.angle_deg)], [rim], "o", color="#009E73", ms=9, clip_on=False)
    _dial(ax, f"plane {name}: masses [{mu}]", items, sense, big * (1.08 if drawer is not None else 1.0))
