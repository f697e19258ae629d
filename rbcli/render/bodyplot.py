"""The picture of a body as built, for ``rbcli report`` (and ``principal --plot``): its
parts, its holes, its centre of mass and principal axes, in a 3-D view and three
orthographic views (top, front, side) of the body frame.

Each part is drawn from its :class:`rbcli.body.partmodel.Outline` through
:mod:`rbcli.render.outline` (the geometry): solids grey, holes white and dashed after every
solid, point masses as dots, a given part as its equivalent ellipsoid; over them the com (+),
the principal axes as arrows and the body's equivalent ellipsoid dotted. One scale for the
flat views; grey scale only.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass

import numpy as np

from rbcli.render import outline as ol
from rbcli.render.plots import figure
from rbcli.render.units import DisplayUnits

#: (title, index of the horizontal body axis, index of the vertical one, sign of the third
#: axis toward the viewer)
VIEWS = (
    ("top view (from +z)", 0, 1, 1.0),
    ("front view (from −y)", 0, 2, -1.0),
    ("side view (from +x)", 1, 2, 1.0),
)
NAMES = ("x", "y", "z")
#: axis labels stay readable over lines and fills
LABEL_BOX = {"boxstyle": "round,pad=0.12", "facecolor": "white", "edgecolor": "none", "alpha": 0.85}
#: the figure's caption, for the report
CAPTION = (
    "The body as built, in the body frame: solid parts grey with black outlines, holes "
    "(subtracted parts) white with dashed outlines, the centre of mass (+) and the principal "
    "axes 1, 2, 3 (ascending moments), with the equivalent uniform ellipsoid (same mass and "
    "principal moments, dotted): a 3-D view and three views along the body axes at one scale."
)
SOLID = "0.88"
#: the 3-D view's camera (degrees) and the coarseness of its surfaces (all vector, no bitmap)
ELEV, AZIM = 30.0, -60.0
SEGMENTS_3D = 20
TRIANGLES_3D = 400
#: above this many triangles in all (about twice what is drawn) the 3-D view goes coarser,
#: and then shows only the heaviest parts that fit (the others as dots at their centres)
BUDGET_3D = 2000
#: the most parts drawn by their outline: the heaviest. Each costs ~1 ms and ~1 KB of SVG
#: per view, and in a figure of more no one part can be told from its neighbours; 10 000
#: drawn parts took 15 s and 10 MB of SVG
FIGURE_MAX_PARTS = 500
#: the most further parts drawn as a dot at their centre (the next heaviest), ~100 bytes of
#: SVG a dot in each of the four views; the lighter parts beyond are not drawn, and the
#: caption (:func:`caption`) and the figure's legend say how many and what share of the mass
FIGURE_MAX_DOTS = 2000


@dataclass(frozen=True)
class Drawn:
    """Which parts the body figure draws (indices into ``body.parts``, in file order):
    ``outlined`` the heaviest with an outline (:data:`FIGURE_MAX_PARTS`), ``dotted`` those
    without and the next heaviest (:data:`FIGURE_MAX_DOTS`); ``left_out`` the lightest, of
    ``left_out_mass`` kg; ``total`` parts of ``mass`` kg (holes by their mass too)."""

    outlined: tuple[int, ...]
    dotted: tuple[int, ...]
    left_out: int
    left_out_mass: float
    total: int
    mass: float

    @property
    def note(self) -> str:
        """What was left out, in one sentence ("" when every part is drawn)."""
        if self.total <= FIGURE_MAX_PARTS:
            return ""
        text = f"Of the {self.total} parts, the {FIGURE_MAX_PARTS} heaviest are drawn"
        more = self.total - FIGURE_MAX_PARTS - self.left_out
        if more:
            text += f", the next {more} as dots at their centres"
        if self.left_out:
            share = 100.0 * self.left_out_mass / self.mass if self.mass > 0 else 0.0
            text += (f"; the other {self.left_out}, the lightest ({share:.2g} % of the parts' mass), "
                     "are not drawn")
        return text + "."


def drawn_parts(body) -> Drawn:
    """The parts the figure draws: the :data:`FIGURE_MAX_PARTS` heaviest (by their outline,
    or a dot without one), then dots at the centres of the next :data:`FIGURE_MAX_DOTS`;
    ties go to the earlier part."""
    parts = body.parts
    n = len(parts)
    mass = np.fromiter((p.mass for p in parts), dtype=float, count=n)
    order = np.lexsort((np.arange(n), -mass))
    top = np.sort(order[:FIGURE_MAX_PARTS])
    outlined = tuple(int(i) for i in top if parts[i].outline is not None)
    dotted = [int(i) for i in top if parts[i].outline is None]
    dotted = tuple(sorted(dotted + order[FIGURE_MAX_PARTS:FIGURE_MAX_PARTS + FIGURE_MAX_DOTS].tolist()))
    rest = order[FIGURE_MAX_PARTS + FIGURE_MAX_DOTS:]
    return Drawn(outlined, dotted, len(rest), float(mass[rest].sum()), n, float(mass.sum()))


def caption(body) -> str:
    """The report's caption of the body figure: :data:`CAPTION` and what was left out."""
    note = drawn_parts(body).note
    return f"{CAPTION} {note}" if note else CAPTION


def _segments_path(segs: np.ndarray):
    """One matplotlib Path of many (s, 2, 2) segments, joined into polylines (one SVG
    element, dashes flowing along curves)."""
    from matplotlib.path import Path

    lines = ol.polylines(segs)
    codes = np.concatenate([np.r_[Path.MOVETO, np.full(len(p) - 1, Path.LINETO)] for p in lines]).astype(np.uint8)
    return Path(np.concatenate(lines), codes)


def _polygons_path(rings: list):
    """One matplotlib Path of closed polygons (filled by the nonzero rule: their union,
    holes that turn the other way left empty; one SVG element)."""
    from matplotlib.path import Path

    codes = np.concatenate([np.r_[Path.MOVETO, np.full(len(r) - 2, Path.LINETO), Path.CLOSEPOLY] for r in rings])
    return Path(np.concatenate(rings), codes.astype(np.uint8))


def _add_lines(ax, segs, f, z, **kw):
    from matplotlib.patches import PathPatch

    if len(segs):  # add_artist: the limits are set, not computed from every path
        ax.add_artist(PathPatch(_segments_path(segs * f), fill=False, zorder=z, capstyle="round", **kw))


def _add_fill(ax, rings, f, z, colour):
    from matplotlib.patches import PathPatch

    rings = [r for r in rings if len(r) >= 4]
    if rings:
        ax.add_artist(PathPatch(_polygons_path([r * f for r in rings]), facecolor=colour, edgecolor="none",
                                zorder=z))


def segments(n_parts: int) -> int:
    """Points around a circle in the flat views: :data:`rbcli.render.outline.SEGMENTS` for up
    to 24 parts, fewer (down to 12) for more, so a figure of many parts stays a few MB at most."""
    return ol.SEGMENTS if n_parts <= 24 else max(12, int(ol.SEGMENTS * (24 / n_parts) ** 0.5))


def body_figure(body, com, principal, du: DisplayUnits, title: str):
    """The Figure (3-D view, top, front and side views) of ``body``'s parts (a part without
    ``outline`` as a dot), its ``com`` ((3,) m) and ``principal`` axes about the com (a
    PrincipalResult), lengths in ``du``'s unit of the body."""
    f, L = du.of(body).factor("length")
    if L == "m" and np.max(np.abs(np.asarray(com))) + max(principal.equivalent_ellipsoid) > 1e4:
        f, L = 1e-3, "km"  # a planet in km: tick labels without a 1e6 multiplier
    ell = np.asarray(principal.equivalent_ellipsoid, dtype=float)
    N = np.asarray(principal.axes, dtype=float)
    c = np.asarray(com, dtype=float)

    drawn = drawn_parts(body)
    parts = body.parts
    solids, holes = [], []
    n_seg = segments(len(drawn.outlined))
    for i in drawn.outlined:
        p = parts[i]
        (holes if p.subtract else solids).append((p, ol.sketch(p.outline, n=n_seg)))
    dots = [(parts[i], np.asarray(parts[i].com, dtype=float)) for i in drawn.dotted]
    arrow, mid, half = _frame(solids + holes, dots, c, N, ell)

    fig, axes = figure(title, nrows=2, ncols=2, size=(7.0, 7.6))
    spec = axes[0][0].get_subplotspec()
    axes[0][0].remove()
    ax3 = fig.add_subplot(spec, projection="3d")
    flat = [axes[0][1], axes[1][0], axes[1][1]]
    _three_d(ax3, solids, holes, dots, c, N, arrow, f, mid, half, L)

    shown: set[str] = set()  # what the legend explains
    for ax, view in zip(flat, VIEWS):
        shown |= _flat_view(ax, view, solids, holes, dots, f)
        _frame_view(ax, view, c, N, ell, arrow, f, mid, half, L)
    _legend(fig, shown | {"com", "ellipse"}, drawn.note)
    return fig


def _frame(sketches: list, dots: list, c: np.ndarray, N: np.ndarray,
           ell: np.ndarray) -> tuple[float, np.ndarray, float]:
    """The length of the principal axes' arrows, and the centre and half-width of the
    views: all the drawn points, the arrows and the equivalent ellipsoid's box."""
    pts = [s.vertices for _, s in sketches] + [s.points for _, s in sketches]
    pts += [np.array([d for _, d in dots]).reshape(-1, 3), c.reshape(1, 3)]
    allp = np.concatenate(pts)
    size = float(np.max(allp.max(axis=0) - allp.min(axis=0)))
    arrow = 0.6 * size if size > 0 else 1.15 * float(np.max(ell)) or 1.0
    box = ell.max() * np.eye(3)  # the equivalent ellipsoid's bounding box, and the arrows
    allp = np.concatenate([allp, c + arrow * 1.15 * N, c - 0.05 * arrow * N, c + box, c - box])
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    return arrow, 0.5 * (lo + hi), 0.54 * float(np.max(hi - lo)) or 1.0


def _segments_of(shadows: list, what: str) -> np.ndarray:
    """The (s, 2, 2) segments of one kind (``creases``, ``hidden``, ``outline``) of shadows."""
    return np.concatenate([getattr(x, what) for _, x in shadows] or [np.zeros((0, 2, 2))])


def _flat_view(ax, view: tuple, solids: list, holes: list, dots: list, f: float) -> set[str]:
    """The parts in one flat view: solid shadows, holes, marked points and dots; what it
    showed, for the legend."""
    _, i, j, toward = view
    shown = set()
    sh = [(p, ol.shadow(s, i, j, toward)) for p, s in solids]
    hs = [(p, ol.shadow(s, i, j, toward)) for p, s in holes]
    _add_fill(ax, [r for _, x in sh for r in x.fill], f, 1, SOLID)
    _add_lines(ax, _segments_of(sh, "creases"), f, 2, edgecolor="0.45", linewidth=0.5)
    _add_lines(ax, _segments_of(sh, "hidden"), f, 2, edgecolor="0.3", linewidth=0.6, linestyle=(0, (3, 2)))
    _add_lines(ax, _segments_of(sh, "outline"), f, 3, edgecolor="black", linewidth=0.8)
    if sh:
        shown.add("solid")
    if hs:
        _add_fill(ax, [r for _, x in hs for r in x.fill], f, 4, "white")
        _add_lines(ax, _segments_of(hs, "outline"), f, 5, edgecolor="0.15", linewidth=0.9,
                   linestyle=(0, (4, 2)))
        shown.add("hole")
    # marked points: point masses (dots), a given part's centre (×), parts without outline
    for plist, face in ((sh, "black"), (hs, "white")):
        for p, x in plist:
            if len(x.points):
                given = p.outline.kind == "given"
                ax.plot(x.points[:, 0] * f, x.points[:, 1] * f, linestyle="none", zorder=6,
                        **(MARKS["given"] if given else {**MARKS["point"], "markerfacecolor": face}))
                shown.add("given" if given else "point" if face == "black" else "removed")
    for removed in (False, True):  # one artist for each kind of dot, however many
        ds = np.array([d for p, d in dots if p.subtract == removed]).reshape(-1, 3)
        if len(ds):
            ax.plot(ds[:, i] * f, ds[:, j] * f, linestyle="none", zorder=6,
                    **{**MARKS["centre"], "markerfacecolor": "white" if removed else "0.4"})
            shown.add("centre")
    return shown


def _frame_view(ax, view: tuple, c: np.ndarray, N: np.ndarray, ell: np.ndarray, arrow: float,
                f: float, mid: np.ndarray, half: float, L: str) -> None:
    """Over one flat view's parts: the equivalent ellipsoid, the principal axes and the
    centre of mass; then its limits, labels and ticks."""
    from matplotlib.ticker import MaxNLocator

    name, i, j, _ = view
    ci = np.array([c[i], c[j]])
    e2 = ol.ellipse_shadow(ell, N, i, j) + ci
    ax.plot(e2[:, 0] * f, e2[:, 1] * f, zorder=7, **LINES["ellipse"])
    _arrows(ax, ci, N, arrow, i, j, f)
    ax.plot(c[i] * f, c[j] * f, linestyle="none", zorder=9, **MARKS["com"])
    ax.set_xlim((mid[i] - half) * f, (mid[i] + half) * f)
    ax.set_ylim((mid[j] - half) * f, (mid[j] + half) * f)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel(f"{NAMES[i]} [{L}]")
    ax.set_ylabel(f"{NAMES[j]} [{L}]")
    ax.set_title(name)
    ax.tick_params(labelsize=7)
    ax.set_axisbelow(True)
    for a in (ax.xaxis, ax.yaxis):
        a.set_major_locator(MaxNLocator(5))


#: marker styles of the flat views (and their legend)
MARKS = {
    "point": {"marker": "o", "markersize": 4, "markerfacecolor": "black", "markeredgecolor": "black",
              "markeredgewidth": 1.0},
    "given": {"marker": "x", "markersize": 5, "markeredgecolor": "black", "markeredgewidth": 1.0},
    "centre": {"marker": "o", "markersize": 3, "markerfacecolor": "0.4", "markeredgecolor": "0.2"},
    "com": {"marker": "+", "markersize": 11, "markeredgewidth": 1.5, "color": "black"},
}
LINES = {"ellipse": {"color": "0.25", "linestyle": ":", "linewidth": 1.0}}
LEGEND = (
    ("solid", "parts"),
    ("hole", "holes (subtracted)"),
    ("point", "point masses"),
    ("removed", "removed point masses"),
    ("given", "given part (its equivalent ellipsoid)"),
    ("centre", "part centres"),
    ("com", "centre of mass"),
    ("ellipse", "equivalent uniform ellipsoid"),
)


def _legend(fig, shown: set, note: str = "") -> None:
    """One legend under the views for what they show (proxy artists: nothing extra drawn),
    titled with ``note`` (what was left out) when there is one."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    proxy = {
        "solid": lambda: Patch(facecolor=SOLID, edgecolor="black", linewidth=0.8),
        "hole": lambda: Patch(facecolor="white", edgecolor="0.15", linewidth=0.9, linestyle=(0, (4, 2))),
        "point": lambda: Line2D([], [], linestyle="none", **MARKS["point"]),
        "removed": lambda: Line2D([], [], linestyle="none", **{**MARKS["point"], "markerfacecolor": "white"}),
        "given": lambda: Line2D([], [], linestyle="none", **MARKS["given"]),
        "centre": lambda: Line2D([], [], linestyle="none", **MARKS["centre"]),
        "com": lambda: Line2D([], [], linestyle="none", **MARKS["com"]),
        "ellipse": lambda: Line2D([], [], **LINES["ellipse"]),
    }
    keys = [(k, text) for k, text in LEGEND if k in shown]
    extra = {"title": _wrap(note), "title_fontsize": 8} if note else {}
    fig.legend([proxy[k]() for k, _ in keys], [t for _, t in keys], loc="outside lower center",
               ncols=min(len(keys), 3), **extra)


def _wrap(text: str, width: int = 90) -> str:
    return "\n".join(textwrap.wrap(text, width))


def _arrows(ax, ci, N, arrow, i, j, f):
    """The principal axes 1, 2, 3 as arrows from the com, labelled beyond their tips."""
    tips: list[tuple[np.ndarray, list[str]]] = []  # label coincident tips once: "1, 2"
    for k in range(3):
        d = arrow * N[k][[i, j]]
        if np.hypot(*d) < 0.08 * arrow:  # along the line of sight: a ring at the com
            ax.plot(*(ci * f), marker="o", markersize=9, markerfacecolor="none", color="black", zorder=8)
            ax.annotate(str(k + 1), xy=tuple(ci * f), xytext=(-9, -9), textcoords="offset points",
                        fontsize=10, fontweight="bold", ha="right", va="top", bbox=LABEL_BOX, zorder=10)
            continue
        ax.annotate("", xy=tuple((ci + d) * f), xytext=tuple(ci * f), zorder=8,
                    arrowprops={"arrowstyle": "-|>", "color": "black", "linewidth": 1.4,
                                "shrinkA": 0, "shrinkB": 0})
        for tip, names in tips:
            if np.hypot(*(tip - d)) < 0.05 * arrow:
                names.append(str(k + 1))
                break
        else:
            tips.append((d, [str(k + 1)]))
    for d, names in tips:  # the label 11 points beyond the tip, along the arrow
        u = d / np.hypot(*d)
        ax.annotate(", ".join(names), xy=tuple((ci + d) * f), xytext=tuple(11 * u),
                    textcoords="offset points", fontsize=10, fontweight="bold",
                    ha="center", va="center", bbox=LABEL_BOX, zorder=10)


def _three_d(ax3, solids, holes, dots, c, N, arrow, f, mid, half, L):
    """The 3-D view: shaded solid surfaces with their sharp edges, holes as dashed edges,
    point masses, the principal axes (within :data:`BUDGET_3D`: see there)."""
    from matplotlib.ticker import MaxNLocator

    solids, holes, dots = _coarse(solids, holes, dots)
    _surfaces_3d(ax3, solids, holes, f)
    marks = [s.points for _, s in solids + holes if len(s.points)]
    if marks:  # point masses, given parts' centres
        M = np.concatenate(marks) * f
        ax3.scatter(M[:, 0], M[:, 1], M[:, 2], s=10, color="black", depthshade=False)
    if dots:  # parts drawn only by their centre
        M = np.array([d for _, d in dots]) * f
        ax3.scatter(M[:, 0], M[:, 1], M[:, 2], s=3, color="0.45", depthshade=False)
    for k in range(3):
        seg = np.array([c, c + arrow * N[k]]) * f
        ax3.plot(seg[:, 0], seg[:, 1], seg[:, 2], color="black", linewidth=1.6)
        ax3.text(*(c + 1.12 * arrow * N[k]) * f, str(k + 1), fontsize=10, fontweight="bold",
                 ha="center", va="center")
    ax3.set_xlim((mid[0] - half) * f, (mid[0] + half) * f)
    ax3.set_ylim((mid[1] - half) * f, (mid[1] + half) * f)
    ax3.set_zlim((mid[2] - half) * f, (mid[2] + half) * f)
    ax3.set_box_aspect((1, 1, 1), zoom=0.76)  # its labels inside its cell (the layout sees a 3-D cell's box only)
    ax3.view_init(elev=ELEV, azim=AZIM)
    ax3.set_xlabel(f"x [{L}]", labelpad=8)  # clear of the tick labels
    ax3.set_ylabel(f"y [{L}]", labelpad=8)
    ax3.set_zlabel(f"z [{L}]", labelpad=2)
    ax3.set_title("3-D view")
    ax3.tick_params(labelsize=7)
    for a in (ax3.xaxis, ax3.yaxis, ax3.zaxis):
        a.set_major_locator(MaxNLocator(4))
        a.set_pane_color((1.0, 1.0, 1.0, 0.0))


def _coarse(solids: list, holes: list, dots: list) -> tuple[list, list, list]:
    """The 3-D view's parts with coarse surfaces (a few hundred polygons), coarser when there
    are many parts, and then only the heaviest within :data:`BUDGET_3D` (the others become
    dots at their centres)."""
    parts = [p for p, _ in solids + holes]
    for n, most in ((SEGMENTS_3D, TRIANGLES_3D), (10, 100)):  # coarser when there are many parts
        coarse = {id(p): ol.sketch(p.outline, n=n, max_triangles=most) for p in parts}
        if sum(len(s.faces) for s in coarse.values()) <= BUDGET_3D:
            break
    else:  # still too many: the heaviest parts within the budget, the others as dots
        used, kept = 0, set()
        for p in sorted(parts, key=lambda p: -p.mass):
            used += len(coarse[id(p)].faces) + len(coarse[id(p)].lines)
            if used > BUDGET_3D:
                break
            kept.add(id(p))
        dots = dots + [(p, np.asarray(p.com, dtype=float)) for p in parts if id(p) not in kept]
        solids = [(p, s) for p, s in solids if id(p) in kept]
        holes = [(p, s) for p, s in holes if id(p) in kept]
    return [(p, coarse[id(p)]) for p, _ in solids], [(p, coarse[id(p)]) for p, _ in holes], dots


def _surfaces_3d(ax3, solids: list, holes: list, f: float) -> None:
    """The solids' faces turned to the camera, shaded by a fixed light, their sharp edges,
    and the holes' edges dashed."""
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

    elev, azim = np.radians(ELEV), np.radians(AZIM)
    eye = np.array([np.cos(elev) * np.cos(azim), np.cos(elev) * np.sin(azim), np.sin(elev)])
    light = np.array([-0.4, -0.6, 0.7])
    light /= np.linalg.norm(light)
    polys, shades = [], []
    for p, s in solids:
        keep = ol.facing(s, eye)
        if np.any(keep):
            polys.append(s.vertices[s.faces[keep]] * f)
            shades.append(0.62 + 0.33 * np.abs(ol.normals(s)[keep] @ light))
    if polys:
        P = np.concatenate(polys)
        g = np.concatenate(shades)
        ax3.add_collection3d(Poly3DCollection(P, facecolors=np.column_stack([g, g, g, np.ones_like(g)]),
                                              edgecolors=np.column_stack([g, g, g, np.ones_like(g)]),
                                              linewidths=0.3))
    edges = [ol.features(s) for _, s in solids]
    if edges:
        E = np.concatenate(edges)
        if len(E):
            ax3.add_collection3d(Line3DCollection(E * f, colors="0.1", linewidths=0.6))
    hedges = [ol.features(s) for _, s in holes]
    if hedges and len(np.concatenate(hedges)):
        ax3.add_collection3d(Line3DCollection(np.concatenate(hedges) * f, colors="0.2", linewidths=0.7,
                                              linestyles=(0, (4, 2))))
