"""Figures that fit (issue 32 item 5): every figure of every example is drawn, and with
matplotlib's renderer extents no text leaves the canvas, no two texts overlap, no text is
drawn over a legend it is not part of, and no tick label carries an offset (``1e-5+3.14``).
Sampled: a few examples by default, every one under ``-m slow``."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import rbcli
from conftest import sampled_params
from rbcli.render import balanceplot, precess, rollcheck, top, whirl
from rbcli.render.bodyplot import body_figure
from rbcli.render.units import DisplayUnits, ShopUnits

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted(p.stem for p in (ROOT / "examples").glob("*.yaml"))
ROUND = {"bicycle_wheel", "car_wheel", "frisbee", "gyroscope", "hoop", "penny", "spoked_wheel",
         "thick_coin", "top", "toy_top"}
#: a rotor on two bearings for whirl: (bearings, stiffness)
ROTORS = {"fan_rotor": "-150,150", "two_disk_rotor": "-50,450", "journal_rotor": "0,300", "rotor_mm": "-80,80"}
#: how far a text may stick out or into another, in pixels (anti-aliasing of glyph edges)
SLACK = 1.0


def _figures(name: str):
    body = rbcli.load(ROOT / "examples" / f"{name}.yaml")
    du = DisplayUnits()
    at_com = rbcli.principal(body, about="com")
    yield "principal", body_figure(body, at_com.reference, at_com, du, f"principal: {body.name} — principal axes about the com")
    p = rbcli.precess(body, omega="0.3,1,0.2")
    yield "precess", precess.plot(body, p.motion, None, du)
    b = rbcli.balance(body, planes="-0.05,0.05 m", radius="0.05 m", speed="1500 rpm")
    yield "balance", balanceplot.plot(b.diagram(), ShopUnits(None).of(body))
    if name in ROUND:
        if name in ("gyroscope", "top", "toy_top"):  # a top on a pivot (the wheels have none)
            t = rbcli.top(body, spin=150, theta=30)
            yield "top", top.plot(t, t.sample(t.default_duration()), t.default_duration())
        if name not in ("top", "toy_top"):  # rolling: wheels only (a top's rim is off its com)
            r = rbcli.rollcheck(body, rolling_speed="3 m/s")
            yield "rollcheck", rollcheck.plot(r, r.curves())
    if name in ROTORS:
        w = rbcli.whirl(body, bearings=ROTORS[name], stiffness=5e6, damping=500, speed="1480 rpm")
        for draw in (whirl.campbell_figure, whirl.response_figure, whirl.map_figure):
            yield draw.__name__, draw(w)


def _problems(fig) -> list[str]:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.legend import Legend
    from matplotlib.text import Text

    FigureCanvasAgg(fig).draw()
    r = fig.canvas.get_renderer()
    canvas = fig.bbox
    ticks, drawn, in_3d = set(), set(), set()  # tick labels: only those of ticks within the view are drawn
    for ax in fig.axes + [c for a in fig.axes for c in a.child_axes]:  # child: a secondary axis
        for axis in (ax.xaxis, ax.yaxis, getattr(ax, "zaxis", None)):
            if axis is None:
                continue
            lo, hi = sorted(axis.get_view_interval())
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                labels = {id(tick.label1), id(tick.label2)}
                ticks |= labels
                in_3d |= labels | {id(axis.label)} if ax.name == "3d" else set()
                if lo - 1e-9 * (hi - lo) <= tick.get_loc() <= hi + 1e-9 * (hi - lo) and axis.get_visible():
                    drawn |= labels
    # a Text3D (the 3-D view's axis numbers) is placed at draw time and put back after, so its
    # extent is not known here: those sit inside the view's limits box (bodyplot._frame)
    texts = [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()
             and (id(t) not in ticks or id(t) in drawn) and type(t).__name__ != "Text3D"]
    boxes = [(t, t.get_window_extent(r)) for t in texts]
    out = []
    for t, b in boxes:
        if b.x0 < canvas.x0 - SLACK or b.y0 < canvas.y0 - SLACK or b.x1 > canvas.x1 + SLACK or b.y1 > canvas.y1 + SLACK:
            out.append(f"off the canvas: {t.get_text()!r}")
    for i, (t, b) in enumerate(boxes):
        for u, c in boxes[i + 1:]:
            # a 3-D view lays out its own rotated labels; their upright boxes meet where the glyphs do not
            one_3d = id(t) in in_3d and id(u) in in_3d
            if b.width and c.width and not one_3d and b.padded(-SLACK).overlaps(c.padded(-SLACK)):
                out.append(f"overlap: {t.get_text()!r} and {u.get_text()!r}")
    for leg in fig.findobj(Legend):
        lb = leg.get_window_extent(r)
        mine = set(map(id, leg.get_texts())) | {id(leg.get_title())}
        out += [f"over a legend: {t.get_text()!r}" for t, b in boxes
                if id(t) not in mine and b.padded(-SLACK).overlaps(lb)]
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            if re.search(r"\d[+−-]\d|^[+−]", axis.get_offset_text().get_text()):  # a multiplier alone (1e6) is fine
                out.append(f"offset tick label {axis.get_offset_text().get_text()!r}")
    return out


@pytest.mark.parametrize("name", sampled_params(EXAMPLES, lambda n: n in ("fan_rotor", "penny", "bracket")))
def test_every_figure_fits_its_canvas_and_no_text_overlaps(name):
    bad = {kind: p for kind, fig in _figures(name) if (p := _problems(fig))}
    assert not bad, bad
