"""The picture of a body for ``rbcli report``: its equivalent ellipsoid and box and its
principal axes, in a 3-D view and three orthographic views (top, front, side).

The equivalent uniform ellipsoid and box have the body's mass and principal moments
about the centre of mass (``rbcli principal``); they are drawn centred on the com with
their axes along the principal axes, in the body frame, in the report's length unit.
The same scale is used in the three flat views, so lengths can be compared between
them. Grey scale only: a filled light-grey ellipsoid, a dashed box, black axes
labelled 1, 2, 3 (ascending moments), the com as a cross and each part's centre as a
small dot. matplotlib is imported only inside :func:`body_figure` (through
:mod:`rbcli.render.plots`).
"""

from __future__ import annotations

import numpy as np

from rbcli.render.fmt import DisplayUnits

#: (title, index of the horizontal body axis, index of the vertical one, viewing direction)
VIEWS = (
    ("top view (from +z)", 0, 1),
    ("front view (from −y)", 0, 2),
    ("side view (from +x)", 1, 2),
)
NAMES = ("x", "y", "z")
#: axis labels stay readable over lines and fills
LABEL_BOX = {"boxstyle": "round,pad=0.12", "facecolor": "white", "edgecolor": "none", "alpha": 0.85}


def shadow_ellipse(semi_axes, axes, i: int, j: int, n: int = 181) -> np.ndarray:
    """(n, 2) outline of the shadow of an ellipsoid on the (i, j) coordinate plane.

    The ellipsoid centred at 0 with semi-axes ``a_k`` along the unit rows ``axes[k]`` is
    ``{x : xᵀ M⁻¹ x ≤ 1}`` with ``M = Σ a_k² n_k n_kᵀ``; its orthographic shadow on the
    (i, j) plane is the ellipse of the 2×2 block of M, traced as ``S [cos t, sin t]``
    with ``S = M₂^{1/2}`` (symmetric square root, so a flat ellipsoid gives a segment).
    """
    a = np.asarray(semi_axes, dtype=float)
    N = np.asarray(axes, dtype=float)
    M = (N.T * a**2) @ N
    M2 = M[np.ix_((i, j), (i, j))]
    w, V = np.linalg.eigh(M2)
    S = V @ np.diag(np.sqrt(np.clip(w, 0.0, None))) @ V.T
    t = np.linspace(0.0, 2.0 * np.pi, n)
    return (S @ np.vstack([np.cos(t), np.sin(t)])).T


def box_corners(sides, axes) -> np.ndarray:
    """(8, 3) corners of the box of full ``sides`` along the unit rows ``axes``, centred at 0."""
    s = 0.5 * np.asarray(sides, dtype=float)
    N = np.asarray(axes, dtype=float)
    signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], dtype=float)
    return (signs * s) @ N


def hull(points: np.ndarray) -> np.ndarray:
    """Convex hull of 2-D points (Andrew's monotone chain), closed (first point repeated)."""
    pts = sorted({(round(float(x), 15), round(float(y), 15)) for x, y in points})
    if len(pts) <= 2:
        return np.array(pts + pts[:1])

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower: list = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    upper: list = []
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    ring = lower[:-1] + upper[:-1]
    return np.array(ring + ring[:1])


def extent(body, com, semi_axes, sides) -> float:
    """Half the width (m) of the region the views show around the com."""
    r = max(float(np.max(semi_axes)), 0.5 * float(np.linalg.norm(sides)))  # box corners
    for p in body.parts:
        r = max(r, float(np.linalg.norm(np.asarray(p.com, dtype=float) - com)))
    return r if r > 0.0 else 1.0


def body_figure(body, com, principal, du: DisplayUnits, title: str):
    """The figure (matplotlib Figure) of the body's equivalent ellipsoid, box and principal axes.

    Parameters
    ----------
    body : Body — for the part centres
    com : (3,) ndarray — m, the centre of mass
    principal : PrincipalResult — about the com
    du : DisplayUnits — the length unit of the axes
    title : str — the figure title (with the body name)
    """
    from rbcli.render.plots import figure, style

    f, L = du.factor("length")
    ell = np.asarray(principal.equivalent_ellipsoid, dtype=float)
    box = np.asarray(principal.equivalent_box, dtype=float)
    N = np.asarray(principal.axes, dtype=float)
    c = np.asarray(com, dtype=float)
    R = extent(body, c, ell, box)
    arrow = 1.15 * max(float(np.max(ell)), 0.5 * float(np.max(box)), 0.35 * R)
    half = 1.2 * max(R, arrow)
    parts = np.array([np.asarray(p.com, dtype=float) for p in body.parts])
    solid = np.array([not p.subtract for p in body.parts])

    fig, axes = figure(title, nrows=2, ncols=2, size=(7.0, 7.4))
    spec = axes[0][0].get_subplotspec()
    axes[0][0].remove()
    ax3 = fig.add_subplot(spec, projection="3d")
    flat = [axes[0][1], axes[1][0], axes[1][1]]

    # --- 3-D view: wireframe ellipsoid, box edges, principal axes
    u = np.linspace(0.0, 2.0 * np.pi, 25)
    v = np.linspace(0.0, np.pi, 13)
    X = np.outer(np.cos(u), np.sin(v))
    Y = np.outer(np.sin(u), np.sin(v))
    Z = np.outer(np.ones_like(u), np.cos(v))
    P = np.stack([X * ell[0], Y * ell[1], Z * ell[2]], axis=-1) @ N + c
    ax3.plot_wireframe(P[..., 0] * f, P[..., 1] * f, P[..., 2] * f, color="0.6", linewidth=0.5)
    corners = box_corners(box, N) + c
    for a in range(8):
        for b in range(a + 1, 8):
            if bin(a ^ b).count("1") == 1:  # corners differing in one sign share an edge
                seg = corners[[a, b]] * f
                ax3.plot(seg[:, 0], seg[:, 1], seg[:, 2], color="0.35", linestyle="--", linewidth=0.8)
    for k in range(3):
        tip = c + arrow * N[k]
        seg = np.array([c, tip]) * f
        ax3.plot(seg[:, 0], seg[:, 1], seg[:, 2], color="black", linewidth=1.6)
        ax3.text(*(c + 1.12 * arrow * N[k]) * f, str(k + 1), fontsize=10, fontweight="bold",
                 ha="center", va="center")
    ax3.scatter(*(parts[solid].T * f), s=6, color="0.4", depthshade=False)
    lim = [(x - half) * f for x in c], [(x + half) * f for x in c]
    ax3.set_xlim(lim[0][0], lim[1][0])
    ax3.set_ylim(lim[0][1], lim[1][1])
    ax3.set_zlim(lim[0][2], lim[1][2])
    ax3.set_box_aspect((1, 1, 1), zoom=0.82)
    ax3.set_xlabel(f"x [{L}]")
    ax3.set_ylabel(f"y [{L}]")
    ax3.set_zlabel(f"z [{L}]")
    ax3.set_title("3-D view")
    ax3.tick_params(labelsize=7)
    from matplotlib.ticker import MaxNLocator

    for a in (ax3.xaxis, ax3.yaxis, ax3.zaxis):
        a.set_major_locator(MaxNLocator(4))
    for pane in (ax3.xaxis, ax3.yaxis, ax3.zaxis):
        pane.set_pane_color((1.0, 1.0, 1.0, 0.0))

    # --- flat views
    handles = {}
    for ax, (name, i, j) in zip(flat, VIEWS):
        ci = np.array([c[i], c[j]])
        e2 = shadow_ellipse(ell, N, i, j) + ci
        handles["ellipse"] = ax.fill(e2[:, 0] * f, e2[:, 1] * f, facecolor="0.88", edgecolor="black",
                                     linewidth=1.0, label="equivalent uniform ellipsoid")[0]
        b2 = hull(box_corners(box, N)[:, (i, j)]) + ci
        handles["box"] = ax.plot(b2[:, 0] * f, b2[:, 1] * f, label="equivalent uniform box",
                                 **{**style(1), "linewidth": 1.0})[0]
        tips: list[tuple[np.ndarray, list[str]]] = []  # label coincident tips once: "1, 2"
        for k in range(3):
            d = arrow * N[k][[i, j]]
            if np.hypot(*d) < 0.08 * arrow:  # along the line of sight: a ring at the com
                ax.plot(*(ci * f), marker="o", markersize=9, markerfacecolor="none", color="black")
                ax.annotate(str(k + 1), xy=tuple(ci * f), xytext=(-9, -9), textcoords="offset points",
                            fontsize=10, fontweight="bold", ha="right", va="top", bbox=LABEL_BOX)
                continue
            ax.annotate("", xy=tuple((ci + d) * f), xytext=tuple(ci * f),
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
                        ha="center", va="center", bbox=LABEL_BOX)
        handles["parts"] = ax.plot(parts[solid][:, i] * f, parts[solid][:, j] * f, linestyle="none",
                                   marker="o", markersize=2.5, color="0.4", label="part centres")[0]
        if np.any(~solid):
            handles["holes"] = ax.plot(parts[~solid][:, i] * f, parts[~solid][:, j] * f, linestyle="none",
                                       marker="o", markersize=4, markerfacecolor="white", color="0.3",
                                       label="hole centres")[0]
        handles["com"] = ax.plot(c[i] * f, c[j] * f, linestyle="none", marker="+", markersize=10,
                                 markeredgewidth=1.4, color="black", label="centre of mass")[0]
        ax.set_xlim((c[i] - half) * f, (c[i] + half) * f)
        ax.set_ylim((c[j] - half) * f, (c[j] + half) * f)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel(f"{NAMES[i]} [{L}]")
        ax.set_ylabel(f"{NAMES[j]} [{L}]")
        ax.set_title(name)
        ax.tick_params(labelsize=7)
    keys = [k for k in ("ellipse", "box", "com", "parts", "holes") if k in handles]
    fig.legend([handles[k] for k in keys], [handles[k].get_label() for k in keys],
               loc="outside lower center", ncols=len(keys) if len(keys) <= 4 else 3)
    return fig
