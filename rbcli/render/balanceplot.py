"""Polar balancing diagrams: the rotor's clock face with the vectors of a balancing job.

A :class:`rbcli.api.diagram.Diagram` (magnitudes in SI, angles as printed) as a Figure of
polar panels, 0° (the mark) on the right, angles with the rotation counterclockwise (against
it, ``--angle-sense against``, clockwise): each vector where it is on the rotor. Roles
differ by line style as well as shade.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

from rbcli.render.fmt import ROUNDOFF, num
from rbcli.render.plots import figure

#: how each role is drawn: (colour, line style, legend order)
ROLE_STYLE = {
    "initial": ("black", "-"),
    "run": ("0.45", "-"),
    "effect": ("0.3", ":"),
    "trial": ("0.45", "-."),
    "correction": ("0.25", "--"),
    "residual": ("0.6", ":"),
}


#: dash patterns of the second, third, ... arrow of one role in a panel
REPEAT_DASHES = [(0, (6, 2, 1, 2)), (0, (2, 1)), (0, (8, 3))]


def _units(panel: Any, su: Any, reading: tuple[float, str]) -> tuple[float, str]:
    """(SI per display unit, display unit) of a panel's quantity."""
    if panel.quantity == "reading":
        return reading
    kind = {"unbalance": "unbalance", "couple": "couple", "mass": "mass"}[panel.quantity]
    return su.factor(kind), su.unit(kind)


def plot(diagram: Any, su: Any, reading: tuple[float, str] = (1.0, "")):
    """The Figure of ``diagram`` (a polar panel each) in the tables' units ``su``
    (:class:`rbcli.render.units.ShopUnits`), readings in ``reading`` = (SI per unit, unit)."""
    from matplotlib.lines import Line2D
    from matplotlib.ticker import MaxNLocator

    n = len(diagram.panels)
    cols = n if n <= 4 else 4  # a field job's many readings: rows of four dials
    rows = -(-n // cols)
    fig, axes = figure(diagram.title.replace("$", r"\$"), nrows=rows, ncols=cols, size=(3.8 * cols, 5.4 * rows))
    for ax in axes.flat:
        fig.delaxes(ax)
    m_unit = su.unit("mass")
    m_scale = su.factor("mass")
    for k, panel in enumerate(diagram.panels):
        ax = fig.add_subplot(rows, cols, k + 1, projection="polar")
        ax.set_theta_zero_location("E")
        ax.set_theta_direction(-1 if diagram.angle_sense == "against" else 1)
        scale, unit = _units(panel, su, reading)
        big = max([a.magnitude / scale for a in panel.arrows if a.defined]
                  + [a.tail[0] / scale for a in panel.arrows if a.defined and a.tail] + [0.0])
        rmax = big * 1.12 if big > 0 else 1.0
        ax.set_ylim(0.0, rmax)
        ax.set_rlabel_position(22.5)
        ax.yaxis.set_major_locator(MaxNLocator(3))  # few radial labels: they share one ray
        ax.tick_params(axis="y", labelsize=7)
        handles = []
        seen: dict[str, int] = {}
        tiny = ROUNDOFF * max([a.magnitude for a in panel.arrows] + [0.0])  # round-off: no length, no angle
        for a in panel.arrows:
            if a.mass == 0.0 and a.role in ("correction", "residual"):
                continue  # no weight of nothing at a position
            a = replace(a, defined=a.defined and a.magnitude > tiny)
            colour, ls = ROLE_STYLE.get(a.role, ("black", "-"))
            repeat = seen[a.role] = seen.get(a.role, -1) + 1
            if repeat:  # a second run or correction in one panel: another dash pattern
                ls = REPEAT_DASHES[(repeat - 1) % len(REPEAT_DASHES)]
            # a quantity zero to its tolerance shows as 0, as in the tables
            value = num(a.magnitude / scale if a.defined else 0.0, 4) + (f" {unit}" if unit else "")
            if a.mass is not None and panel.quantity != "mass":
                value = f"{num(a.mass / m_scale, 4)} {m_unit} ({value})"
            text = f"{a.label}: {value}" + (f" at {num(a.angle_deg, 4)}°" if a.defined else "")
            handles.append(Line2D([], [], color=colour, linestyle=ls, linewidth=1.6, label=text))
            if not a.defined or a.magnitude <= 0.0:
                continue
            tip = (math.radians(a.angle_deg), a.magnitude / scale)
            tail = (0.0, 0.0)
            if a.tail is not None:  # drawn from the tail point: the head is tail + the vector
                tail = (math.radians(a.tail[1]), a.tail[0] / scale)
                x = tail[1] * math.cos(tail[0]) + tip[1] * math.cos(tip[0])
                y = tail[1] * math.sin(tail[0]) + tip[1] * math.sin(tip[0])
                tip = (math.atan2(y, x), math.hypot(x, y))
            ax.annotate("", xy=tip, xytext=tail, annotation_clip=False,
                        arrowprops=dict(arrowstyle="-|>", color=colour, linestyle=ls, linewidth=1.6,
                                        shrinkA=0, shrinkB=0, mutation_scale=12))
        ax.set_title(panel.title + (f" [{unit}]" if unit else ""), fontsize=9, pad=14)
        ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.08), fontsize=7,
                  handlelength=2.6)
    fig.supxlabel(diagram.note, fontsize=7, color="0.3")
    return fig
