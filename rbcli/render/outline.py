"""Outlines of the parts for drawings: each shape as surface triangles in the body frame,
and its shadow (filled triangles and outline segments) on a coordinate plane.

Geometry only: a part's :class:`rbcli.body.partmodel.Outline` becomes a :class:`Sketch`
(vertices on the shape's true surface, triangles, always-drawn lines); :func:`shadow`
projects it orthographically on a body-frame plane (:class:`Shadow`: fill, silhouette,
creases over :data:`CREASE_DEG`, dashed hidden inner surfaces).

Circles have :data:`SEGMENTS` points (outlines within ``R (1 − cos(π/n))``). Meshes are drawn
decimated by vertex clustering (:func:`decimate`; Rossignac & Borrel 1993); a given part
as its equivalent uniform ellipsoid.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from rbcli.body.partmodel import equivalent_ellipsoid  # the given parts' shape (re-exported here)

__all__ = [
    "CREASE_DEG", "MESH_MAX_TRIANGLES", "SEGMENTS", "Shadow", "Sketch", "decimate",
    "ellipse_shadow", "equivalent_ellipsoid", "facing", "features", "fill_loops", "hull",
    "local_sketch", "normals", "polylines", "shadow", "sketch",
]

#: points around a full circle
SEGMENTS = 48
#: the most triangles a mesh part keeps for drawing (decimated beyond)
MESH_MAX_TRIANGLES = 2000
#: an edge is a crease when its two faces' normals differ by more than this, degrees
CREASE_DEG = 35.0
_EDGE_ON = 1e-9  # |n · view| below this: the triangle is seen edge-on


@dataclass(frozen=True)
class Sketch:
    """A part's surface for drawing, in one frame (m).

    Attributes
    ----------
    vertices : (n, 3) ndarray — m, on the shape's surface
    faces : (m, 3) int ndarray — triangles, oriented alike (outward for a closed surface)
    inner : (m,) bool ndarray — the triangle is of an inner surface (bore, cavity)
    lines : (k, 2) int ndarray — vertex pairs always drawn (rod, ring, thin triangle edges)
    points : (p, 3) ndarray — m, marked points (a point mass, a given part's centre)
    closed : bool — the triangles bound a solid
    fill : str — a shadow's fill: ``"hull"`` (convex), ``"front"`` (the triangles facing the
        viewer, of a closed surface) or ``"all"`` (every triangle not seen edge-on)
    rough : bool — a decimated mesh: a shadow keeps only the outline, no creases
    """

    vertices: np.ndarray
    faces: np.ndarray
    inner: np.ndarray
    lines: np.ndarray
    points: np.ndarray
    closed: bool
    fill: str = "all"
    rough: bool = False

    def placed(self, at, R) -> Sketch:
        """The sketch moved by ``x -> at + R x`` (m; R a rotation)."""
        R = np.asarray(R, dtype=float)
        at = np.asarray(at, dtype=float)
        return replace(self, vertices=self.vertices @ R.T + at, points=self.points @ R.T + at)

    @property
    def edges(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Unique edges ``(e, 2)``, and for each edge-face incidence its edge index and face index."""
        f = self.faces
        pairs = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
        face_of = np.tile(np.arange(len(f)), 3)
        pairs = np.sort(pairs, axis=1)
        n = max(len(self.vertices), 1)
        keys, which = np.unique(pairs[:, 0] * n + pairs[:, 1], return_inverse=True)
        return np.column_stack([keys // n, keys % n]), which.ravel(), face_of


@dataclass(frozen=True)
class Shadow:
    """A sketch projected on a coordinate plane (m): ``fill`` closed (n, 2) polygons whose
    nonzero-rule union is the shadow; (k, 2, 2) segments ``outline`` (silhouette, border,
    always-drawn lines), ``hidden`` (inner surfaces'), ``creases``; (p, 2) ``points``."""

    fill: list
    outline: np.ndarray
    hidden: np.ndarray
    creases: np.ndarray
    points: np.ndarray


# --- building blocks

_NO_LINES = np.zeros((0, 2), dtype=np.int64)
_NO_POINTS = np.zeros((0, 3))


def _make(vertices, faces, *, inner=None, lines=None, points=None, closed=True) -> Sketch:
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    return Sketch(
        np.asarray(vertices, dtype=float).reshape(-1, 3), faces,
        np.zeros(len(faces), dtype=bool) if inner is None else np.asarray(inner, dtype=bool),
        _NO_LINES if lines is None else np.asarray(lines, dtype=np.int64).reshape(-1, 2),
        _NO_POINTS if points is None else np.asarray(points, dtype=float).reshape(-1, 3),
        closed,
    )


def _join(*parts: Sketch, closed: bool = True) -> Sketch:
    vs, fs, ins, ls, ps = [], [], [], [], []
    k = 0
    for s in parts:
        vs.append(s.vertices)
        fs.append(s.faces + k)
        ins.append(s.inner)
        ls.append(s.lines + k)
        ps.append(s.points)
        k += len(s.vertices)
    return Sketch(np.concatenate(vs), np.concatenate(fs), np.concatenate(ins), np.concatenate(ls),
                  np.concatenate(ps), closed)


def _circle(n: int = SEGMENTS) -> np.ndarray:
    t = 2.0 * math.pi * np.arange(n) / n
    return np.column_stack([np.cos(t), np.sin(t)])


def _revolve(profile, *, loop: bool, inner=(), n: int = SEGMENTS) -> Sketch:
    """The surface swept by the (r, z) ``profile`` turning about local z, consistently
    oriented; points on the axis become one vertex; ``loop`` closes the profile; ``inner``:
    the profile segments (k: point k to k + 1) that sweep an inner surface, or True for all.
    """
    prof = np.asarray(profile, dtype=float)
    cs = _circle(n)
    verts = []
    index = np.empty((len(prof), n), dtype=np.int64)
    for k, (r, z) in enumerate(prof):
        if r == 0.0:
            index[k] = len(verts)
            verts.append((0.0, 0.0, z))
        else:
            index[k] = np.arange(len(verts), len(verts) + n)
            verts.extend((r * c, r * s, z) for c, s in cs)
    m = len(prof) if loop else len(prof) - 1
    k0 = np.arange(m)[:, None]
    k1 = (k0 + 1) % len(prof)
    j0 = np.arange(n)[None, :]
    j1 = (j0 + 1) % n
    a, b, c, d = index[k0, j0], index[k0, j1], index[k1, j1], index[k1, j0]
    faces = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    segment = np.tile(np.repeat(np.arange(m), n), 2)
    is_inner = np.full(len(faces), True) if inner is True else np.isin(segment, list(inner))
    keep = (faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 0] != faces[:, 2])
    return _make(verts, faces[keep], inner=is_inner[keep], closed=True)


def _arc(radius: float, t0: float, t1: float, n: int, cz: float = 0.0, cr: float = 0.0) -> np.ndarray:
    """(n + 1, 2) points (r, z) on a circle of ``radius`` about (cr, cz), angles t0..t1 from +r."""
    t = np.linspace(t0, t1, n + 1)
    pts = np.column_stack([cr + radius * np.cos(t), cz + radius * np.sin(t)])
    if cr == 0.0:  # exactly on the axis at the poles
        pts[np.isclose(t, math.pi / 2) | np.isclose(t, -math.pi / 2), 0] = 0.0
    return pts


def _box(a: float, b: float, c: float) -> Sketch:
    s = np.array([a, b, c]) / 2.0
    v = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float) * s
    # vertex index = 4 ix + 2 iy + iz; each face as two outward triangles
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    faces = [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
    return _make(v, faces)


def _rect(a: float, b: float) -> Sketch:
    v = [(-a / 2, -b / 2, 0), (a / 2, -b / 2, 0), (a / 2, b / 2, 0), (-a / 2, b / 2, 0)]
    return _make(v, [(0, 1, 2), (0, 2, 3)], closed=False)


def _ellipsoid(a: float, b: float, c: float, n: int) -> Sketch:
    s = _revolve(_arc(1.0, -math.pi / 2, math.pi / 2, n // 2), loop=False, n=n)
    return _make(s.vertices * np.array([a, b, c]), s.faces)


# --- shapes


#: shapes whose solid is convex: their shadow is the convex hull of their vertices' shadows
_CONVEX = {"box", "plate", "triangle", "ellipsoid", "given", "hemisphere", "cone", "sphere"}


def local_sketch(kind: str, dims: dict, vertices=None, faces=None, n: int = SEGMENTS) -> Sketch:
    """The sketch (m) of a shape in its local frame (:mod:`rbcli.core.shapes`'): ``kind`` a
    primitive, ``"given"`` (an ellipsoid of ``semi_axes``, centre marked) or ``"mesh"``
    (``vertices``, ``faces``); ``dims`` its parameters in m; ``n`` points a circle (>= 8)."""
    s = _local(kind, dims, vertices, faces, max(8, int(n)))
    r_in = float(dims.get("inner_radius") or 0.0)
    solid_round = (kind == "cylinder" and not dims.get("shell")) or kind == "disk"
    if kind in _CONVEX or (solid_round and r_in == 0.0):
        return replace(s, fill="hull")
    if kind in ("cylinder", "torus") and s.closed:
        return replace(s, fill="front")
    return s


def _local(kind: str, dims: dict, vertices, faces, n: int) -> Sketch:
    d = dims
    if kind == "point":
        return _make(np.zeros((0, 3)), [], points=[(0.0, 0.0, 0.0)], closed=False)
    if kind == "rod":
        h = float(d["length"]) / 2.0
        return _make([(0, 0, -h), (0, 0, h)], [], lines=[(0, 1)], closed=False)
    if kind == "ring":
        r = float(d["radius"])
        v = np.column_stack([r * _circle(n), np.zeros(n)])
        return _make(v, [], lines=np.column_stack([np.arange(n), (np.arange(n) + 1) % n]), closed=False)
    if kind == "disk":
        r_in = float(d.get("inner_radius") or 0.0)
        s = _revolve([(r_in, 0.0), (float(d["radius"]), 0.0)], loop=False, n=n)
        return _make(s.vertices, s.faces, closed=False)
    if kind == "plate":
        a, b = (float(x) for x in d["size"])
        t = float(d.get("thickness") or 0.0)
        return _box(a, b, t) if t > 0 else _rect(a, b)
    if kind == "triangle":
        v = np.asarray(d["vertices"], dtype=float)
        return _make(v, [(0, 1, 2)], lines=[(0, 1), (1, 2), (2, 0)], closed=False)
    if kind == "box":
        return _box(*(float(x) for x in d["size"]))
    if kind == "cylinder":
        R, h = float(d["radius"]), float(d["length"]) / 2.0
        if d.get("shell"):
            s = _revolve([(R, -h), (R, h)], loop=False, n=n)
            return _make(s.vertices, s.faces, closed=False)
        r = float(d.get("inner_radius") or 0.0)
        if r > 0.0:  # a tube: end faces, outer wall, end faces, bore
            return _revolve([(r, -h), (R, -h), (R, h), (r, h)], loop=True, inner=(3,), n=n)
        return _revolve([(0.0, -h), (R, -h), (R, h), (0.0, h)], loop=False, n=n)
    if kind == "sphere":
        R = float(d["radius"])
        outer = _revolve(_arc(R, -math.pi / 2, math.pi / 2, n // 2), loop=False, n=n)
        r = 0.0 if d.get("shell") else float(d.get("inner_radius") or 0.0)
        if r > 0.0:  # the cavity: the same sphere smaller, turned inside out
            cavity = _revolve(_arc(r, math.pi / 2, -math.pi / 2, n // 2), loop=False, inner=True, n=n)
            return _join(outer, cavity)
        return outer
    if kind == "hemisphere":
        R = float(d["radius"])
        return _revolve([(0.0, 0.0), *_arc(R, 0.0, math.pi / 2, n // 4)], loop=False, n=n)
    if kind == "cone":
        R, h = float(d["radius"]), float(d["height"])
        return _revolve([(0.0, 0.0), (R, 0.0), (0.0, h)], loop=False, n=n)
    if kind == "ellipsoid":
        return _ellipsoid(*(float(x) for x in d["semi_axes"]), n)
    if kind == "given":
        s = _ellipsoid(*(float(x) for x in d["semi_axes"]), n)
        return _make(s.vertices, s.faces, points=[(0.0, 0.0, 0.0)])
    if kind == "torus":
        R, r = float(d["major_radius"]), float(d["minor_radius"])
        prof = _arc(r, 0.0, 2.0 * math.pi, n // 3, cr=R)[:-1]
        return _revolve(prof, loop=True, n=n)
    if kind == "mesh":
        return _make(vertices, faces)
    raise ValueError(f"no outline for shape {kind!r}")


def sketch(outline, n: int = SEGMENTS, max_triangles: int | None = None) -> Sketch:
    """The sketch of a part's :class:`rbcli.body.partmodel.Outline`, in the body frame (m), with
    ``n`` points around a full circle; a mesh decimated to :data:`MESH_MAX_TRIANGLES`, then
    to ``max_triangles`` if given and fewer."""
    V, F = outline.vertices, outline.faces
    if outline.kind == "mesh":
        V, F = decimate(V, F)  # the drawing's copy (its unused vertices dropped)
        if max_triangles is not None and len(F) > max_triangles:
            V, F = decimate(V, F, max_triangles)
    s = local_sketch(outline.kind, dict(outline.dims), V, F, n)
    if outline.kind == "mesh" and len(F) < int(dict(outline.dims).get("triangles", len(F))):
        s = replace(s, rough=True)
    return s.placed(outline.at, outline.R)


def decimate(vertices, faces, max_triangles: int = MESH_MAX_TRIANGLES) -> tuple[np.ndarray, np.ndarray]:
    """A mesh of at most ``max_triangles`` triangles that looks like ``(vertices, faces)``:
    vertex clustering on a g³ grid (cell means; collapsed triangles dropped, duplicates once),
    g from √max_triangles shrinking as the square root of the excess (two or three passes)."""
    V = np.asarray(vertices, dtype=float)
    F = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    if len(F) <= max_triangles:
        used, F2 = np.unique(F, return_inverse=True)
        return V[used].copy(), F2.reshape(-1, 3)
    lo = V.min(axis=0)
    size = float((V.max(axis=0) - lo).max()) or 1.0
    U = (V - lo) / size  # in the unit cube
    g = max(1, int(math.sqrt(max_triangles)))
    while True:
        cell = np.minimum((U * g).astype(np.int64), g - 1)
        key = (cell[:, 0] * g + cell[:, 1]) * g + cell[:, 2]
        used = np.zeros(g**3, dtype=bool)
        used[key] = True
        ids = np.cumsum(used) - 1
        cluster = ids[key]
        n = int(ids[-1]) + 1
        F2 = cluster[F]
        F2 = F2[(F2[:, 0] != F2[:, 1]) & (F2[:, 1] != F2[:, 2]) & (F2[:, 0] != F2[:, 2])]
        if len(F2):  # one copy of each triangle (whatever its orientation)
            srt = np.sort(F2, axis=1)
            _, first = np.unique((srt[:, 0] * n + srt[:, 1]) * n + srt[:, 2], return_index=True)
            F2 = F2[np.sort(first)]
        if len(F2) <= max_triangles or g == 1:
            break
        g = max(1, min(g - 1, int(g * math.sqrt(max_triangles / len(F2)) * 0.97)))
    count = np.bincount(cluster, minlength=n).astype(float)
    V2 = np.column_stack([np.bincount(cluster, weights=V[:, k], minlength=n) for k in range(3)]) / count[:, None]
    used_v, F3 = np.unique(F2, return_inverse=True)
    return V2[used_v], F3.reshape(-1, 3)


# --- projection


def normals(s: Sketch) -> np.ndarray:
    """(m, 3) unit normals of the triangles (zero for a degenerate triangle)."""
    v = s.vertices[s.faces]
    n = np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    length = np.linalg.norm(n, axis=1)
    out = np.zeros_like(n)
    ok = length > 0
    out[ok] = n[ok] / length[ok, None]
    return out


def shadow(s: Sketch, i: int, j: int, toward: float = 1.0) -> Shadow:
    """Sketch ``s`` (body frame) seen along the third body axis, body axes ``i`` across and
    ``j`` up; ``toward`` (±1) the sign of the third axis at the viewer (top view from +z: +1,
    front view from −y: −1), which decides the near creases."""
    k = 3 - i - j
    p2 = s.vertices[:, [i, j]]
    nz = normals(s)[:, k] * toward
    side = np.where(nz > _EDGE_ON, 1, np.where(nz < -_EDGE_ON, -1, 0))
    if s.fill == "hull" and len(s.faces):
        fill = [hull(p2)]
    else:
        fill = fill_loops(s.faces[side > 0] if s.fill == "front" else s.faces[side != 0], p2)
    segs = [p2[s.lines]]
    hidden = np.zeros((0, 2, 2))
    creases = np.zeros((0, 2, 2))
    if len(s.faces):
        uniq, which, face_of = s.edges
        e = len(uniq)
        lo = np.full(e, 2)
        hi = np.full(e, -2)
        np.minimum.at(lo, which, side[face_of])
        np.maximum.at(hi, which, side[face_of])
        count = np.bincount(which, minlength=e)
        all_inner = np.ones(e, dtype=bool)
        np.logical_and.at(all_inner, which, s.inner[face_of])
        # edges between two edge-on triangles lie inside the line they make (a cylinder's
        # end face seen from the side): drawn only when the whole surface is edge-on
        sil = (count == 1) | (lo != hi) | ((lo == 0) & (not np.any(side)))
        segs.append(p2[uniq[sil & ~all_inner]])
        hidden = p2[uniq[sil & all_inner]]
        # creases: two faces whose normals part by more than CREASE_DEG, one of them facing us
        n = normals(s)
        nmin = np.full((e, 3), np.inf)
        nmax = np.full((e, 3), -np.inf)
        np.minimum.at(nmin, which, n[face_of])
        np.maximum.at(nmax, which, n[face_of])
        near = hi > 0 if s.closed else (hi != 0) | (lo != 0)
        spread = np.linalg.norm(nmax - nmin, axis=1)  # two unit normals at angle a: 2 sin(a/2)
        sharp = (count >= 2) & (spread > 2.0 * math.sin(math.radians(CREASE_DEG) / 2.0))
        creases = p2[uniq[sharp & near & ~sil & ~all_inner]]
        if s.rough:
            tris = p2[s.faces[side != 0]]
            span = float(np.ptp(p2, axis=0).max()) if len(p2) else 0.0
            segs[-1] = segs[-1][~_covered_both_sides(segs[-1], tris, 1e-3 * span)]
            creases = creases[:0]
    return Shadow(fill, np.concatenate(segs), hidden, creases, s.points[:, [i, j]])


def features(s: Sketch) -> np.ndarray:
    """(f, 2, 3) segments a wireframe draws whatever the view: sharp edges (over
    :data:`CREASE_DEG`), the border of an open surface, and the always-drawn lines (m);
    a rough (decimated) mesh only its lines (its sharp edges are artefacts)."""
    segs = [s.vertices[s.lines]]
    if len(s.faces) and not s.rough:
        uniq, which, face_of = s.edges
        e = len(uniq)
        n = normals(s)
        nmin = np.full((e, 3), np.inf)
        nmax = np.full((e, 3), -np.inf)
        np.minimum.at(nmin, which, n[face_of])
        np.maximum.at(nmax, which, n[face_of])
        count = np.bincount(which, minlength=e)
        sharp = (count >= 2) & (np.linalg.norm(nmax - nmin, axis=1) > 2.0 * math.sin(math.radians(CREASE_DEG) / 2.0))
        segs.append(s.vertices[uniq[sharp | (count == 1)]])
    return np.concatenate(segs)


def facing(s: Sketch, direction) -> np.ndarray:
    """(m,) bool: the triangles a viewer looking from ``direction`` (towards the body) can
    see: those turned towards it on a closed surface, every non-degenerate one on an open
    surface (back-face culling)."""
    n = normals(s)
    d = n @ np.asarray(direction, dtype=float)
    return d > _EDGE_ON if s.closed else np.abs(d) > _EDGE_ON


def ellipse_shadow(semi_axes, axes, i: int, j: int, n: int = 181) -> np.ndarray:
    """(n, 2) outline of the shadow on the (i, j) plane of the ellipsoid ``{x : xᵀ M⁻¹ x ≤ 1}``,
    ``M = Σ a_k² n_k n_kᵀ`` (semi-axes ``a_k`` along rows ``axes[k]``): ``S [cos t, sin t]``,
    ``S`` the symmetric square root of M's (i, j) block (a flat ellipsoid gives a segment).
    """
    a = np.asarray(semi_axes, dtype=float)
    N = np.asarray(axes, dtype=float)
    M = (N.T * a**2) @ N
    M2 = M[np.ix_((i, j), (i, j))]
    w, V = np.linalg.eigh(M2)
    S = V @ np.diag(np.sqrt(np.clip(w, 0.0, None))) @ V.T
    t = np.linspace(0.0, 2.0 * np.pi, n)
    return (S @ np.vstack([np.cos(t), np.sin(t)])).T


def _covered_both_sides(segs: np.ndarray, tris: np.ndarray, eps: float) -> np.ndarray:
    """For each (2, 2) segment: are the points ``eps`` either side of its middle both
    inside some triangle (an edge inside the shadow, not on its border)?"""
    if not len(segs) or not len(tris) or eps <= 0:
        return np.zeros(len(segs), dtype=bool)
    mid = segs.mean(axis=1)
    d = segs[:, 1] - segs[:, 0]
    length = np.hypot(d[:, 0], d[:, 1])
    length[length == 0] = 1.0
    nrm = np.column_stack([-d[:, 1], d[:, 0]]) / length[:, None]
    probes = np.concatenate([mid + eps * nrm, mid - eps * nrm])
    a, b, c = tris[:, 0], tris[:, 1], tris[:, 2]

    def side(p, q, r):  # (P, T): sign of the turn p -> q -> r for every probe r
        return (q[None, :, 0] - p[None, :, 0]) * (r[:, None, 1] - p[None, :, 1]) - (
            q[None, :, 1] - p[None, :, 1]) * (r[:, None, 0] - p[None, :, 0])

    inside = np.zeros(len(probes), dtype=bool)
    for k in range(0, len(probes), 256):
        r = probes[k:k + 256]
        s1, s2, s3 = side(a, b, r), side(b, c, r), side(c, a, r)
        pos = (s1 >= 0) & (s2 >= 0) & (s3 >= 0)
        neg = (s1 <= 0) & (s2 <= 0) & (s3 <= 0)
        inside[k:k + 256] = np.any(pos | neg, axis=1)
    n = len(segs)
    return inside[:n] & inside[n:]


def fill_loops(faces, points2) -> list[np.ndarray]:
    """Closed (k, 2) loops whose nonzero-rule fill is the union of the projected triangles
    ``faces`` ((m, 3) indices into the (n, 2) ``points2``): the counter-clockwise triangles'
    directed edges summed (an edge cancels its reverse) and chained; the loops' winding number
    about a point is the number of triangles covering it."""
    P = np.asarray(points2, dtype=float)
    F = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    if not len(F):
        return []
    t = P[F]
    area = (t[:, 1, 0] - t[:, 0, 0]) * (t[:, 2, 1] - t[:, 0, 1]) - (t[:, 1, 1] - t[:, 0, 1]) * (t[:, 2, 0] - t[:, 0, 0])
    F = F[area != 0.0].copy()
    neg = area[area != 0.0] < 0
    F[neg] = F[neg][:, ::-1]
    e = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    n = len(P)
    keys, counts = np.unique(e[:, 0] * n + e[:, 1], return_counts=True)
    back = dict(zip(keys.tolist(), counts.tolist()))
    out: dict[int, list[int]] = {}
    for k, c in zip(keys.tolist(), counts.tolist()):
        u, v = divmod(k, n)
        for _ in range(c - back.get(v * n + u, 0)):
            out.setdefault(u, []).append(v)
    loops = []
    for start in list(out):
        while out[start]:
            ring = [start]
            cur = start
            while True:  # in-degree = out-degree everywhere: the walk comes back to start
                cur = out[cur].pop()
                ring.append(cur)
                if cur == start:
                    break
            loops.append(P[ring])
    return loops


def hull(points) -> np.ndarray:
    """Convex hull of 2-D points (Andrew's monotone chain), counter-clockwise and closed
    (first point repeated); fewer than three distinct points give them as they are."""
    pts = sorted(set(map(tuple, np.asarray(points, dtype=float).tolist())))
    if len(pts) <= 2:
        return np.array(pts + pts[:1]).reshape(-1, 2)

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


def polylines(segments: np.ndarray) -> list[np.ndarray]:
    """The (s, 2, d) segments joined at equal endpoints into polylines (a list of (n, d)
    arrays), so that dashes flow along a curve; each segment used once, either way round.
    """
    segs = np.asarray(segments, dtype=float)
    if not len(segs):
        return []
    ends: dict[tuple, list[tuple[int, int]]] = {}
    keys = [(tuple(a), tuple(b)) for a, b in segs.tolist()]
    for k, (a, b) in enumerate(keys):
        ends.setdefault(a, []).append((k, 1))  # from a, go to the segment's end 1
        ends.setdefault(b, []).append((k, 0))
    used = [False] * len(segs)
    # the first unused segment at a point: every entry before ``seen[point]`` is used (a
    # segment once used stays used), so the scans cost O(segments) in all even where
    # thousands of segments meet at one point (many equal parts seen end-on)
    seen: dict[tuple, int] = {}

    def walk(point: tuple, out: list) -> None:
        while True:
            at = ends.get(point, ())
            i = seen.get(point, 0)
            while i < len(at) and used[at[i][0]]:
                i += 1
            seen[point] = i
            if i == len(at):
                return
            k, e = at[i]
            used[k] = True
            point = keys[k][e]
            out.append(point)

    lines = []
    # start at free ends first (open chains stay whole), then the closed loops
    order = [k for k, (a, b) in enumerate(keys) if len(ends[a]) != 2 or len(ends[b]) != 2]
    order += range(len(keys))
    for k in order:
        if used[k]:
            continue
        used[k] = True
        a, b = keys[k]
        if len(ends[a]) != 2 and len(ends[b]) == 2:
            a, b = b, a  # walk away from the free end... both ways below
        fwd: list = [b]
        walk(b, fwd)
        back: list = []
        walk(a, back)
        lines.append(np.array([*reversed(back), a, *fwd]))
    return lines
