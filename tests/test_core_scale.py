"""Tests of rbcli.core.scale: how far a body's material reaches from a spin axis (issue 24,
item 3: the rim-speed warnings measured a bounding-box half-diagonal, not the distance from
the axis).

The oracle is written here from the shape definitions (``rbcli shapes``): points sampled on
each shape's surface in its local frame (local origin and axes as the catalogue states
them), placed with scipy's ``Rotation`` from the ``rotate: {axis, angle}`` and the ``at`` of
the body text, and their largest distance from the line. The reach must not be below the
sampled maximum (it is exact or an upper bound) and must be within the sampling's own error
above it (the sagitta of the sampling angle).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

import rbcli
from rbcli.core.scale import axis_reach

N = 721  # samples on a circle: a sagitta of r (1 - cos(pi/720)) < 1e-5 r
SAG = 1.0 - math.cos(math.pi / (N - 1))


def _circle(r: float, z: float = 0.0, n: int = N) -> np.ndarray:
    t = np.linspace(0.0, 2.0 * np.pi, n)
    return np.column_stack([r * np.cos(t), r * np.sin(t), np.full(n, z)])


def _sphere(r: float, n: int = 181, upper: bool = False) -> np.ndarray:
    lat = np.linspace(0.0 if upper else -np.pi / 2, np.pi / 2, n)
    lon = np.linspace(0.0, 2.0 * np.pi, 2 * n)
    la, lo = np.meshgrid(lat, lon)
    return r * np.column_stack([(np.cos(la) * np.cos(lo)).ravel(), (np.cos(la) * np.sin(lo)).ravel(),
                                np.sin(la).ravel()])


def _local_points(shape: str, p: dict) -> np.ndarray:
    """Points of the shape's boundary (a superset of its farthest points) in its local frame,
    from the shapes' definitions: the catalogue's local origins and axes."""
    if shape == "point":
        return np.zeros((1, 3))
    if shape == "rod":
        h = p["length"] / 2
        return np.array([[0, 0, -h], [0, 0, h]], dtype=float)
    if shape in ("ring", "disk"):
        return _circle(p["radius"])
    if shape == "plate":
        a, b = p["size"]
        t = p.get("thickness", 0.0)
        return np.array([[sx * a / 2, sy * b / 2, sz * t / 2] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
    if shape == "box":
        a, b, c = p["size"]
        return np.array([[sx * a / 2, sy * b / 2, sz * c / 2] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
    if shape == "triangle":
        return np.asarray(p["vertices"], dtype=float)
    if shape == "cylinder":
        h = p["length"] / 2
        return np.vstack([_circle(p["radius"], -h), _circle(p["radius"], h)])
    if shape == "sphere":
        return _sphere(p["radius"])
    if shape == "hemisphere":  # dome towards +z, flat face at z = 0
        return np.vstack([_sphere(p["radius"], upper=True), _circle(p["radius"])])
    if shape == "cone":  # base at z = 0, apex at z = height
        return np.vstack([_circle(p["radius"]), [[0.0, 0.0, p["height"]]]])
    if shape == "ellipsoid":
        return _sphere(1.0) * np.asarray(p["semi_axes"], dtype=float)
    if shape == "torus":
        R, r = p["major_radius"], p["minor_radius"]
        u = np.linspace(0, 2 * np.pi, N)
        v = np.linspace(0, 2 * np.pi, 361)
        U, V = np.meshgrid(u, v)
        return np.column_stack([((R + r * np.cos(V)) * np.cos(U)).ravel(),
                                ((R + r * np.cos(V)) * np.sin(U)).ravel(), (r * np.sin(V)).ravel()])
    raise AssertionError(shape)


SHAPES = {
    "point": {},
    "rod": {"length": 0.8},
    "ring": {"radius": 0.3},
    "disk": {"radius": 0.25, "inner_radius": 0.1},
    "plate": {"size": [0.4, 0.2], "thickness": 0.03},
    "box": {"size": [0.1, 0.2, 0.5]},
    "triangle": {"vertices": [[0.0, 0.0, 0.0], [0.3, 0.05, 0.0], [0.1, 0.4, 0.02]]},
    "cylinder": {"radius": 0.025, "length": 1.5},
    "sphere": {"radius": 0.2, "inner_radius": 0.15},
    "hemisphere": {"radius": 0.2},
    "cone": {"radius": 0.1, "height": 0.3},
    "ellipsoid": {"semi_axes": [0.3, 0.1, 0.05]},
    "torus": {"major_radius": 0.3, "minor_radius": 0.04},
}


def _body(shape: str, params: dict, at, axis, angle) -> rbcli.Body:
    import json

    part = {"shape": shape, "mass": 1.0, **params, "at": list(at),
            "rotate": {"axis": list(axis), "angle": angle}}
    return rbcli.load_text(json.dumps(part))


def _line_distance(points: np.ndarray, n: np.ndarray, P: np.ndarray) -> np.ndarray:
    n = n / np.linalg.norm(n)
    d = points - P
    return np.linalg.norm(d - np.outer(d @ n, n), axis=1)


vec = st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3).filter(lambda v: np.linalg.norm(v) > 0.1)


@pytest.mark.parametrize("shape", sorted(SHAPES))
@settings(max_examples=25, deadline=None)
@given(at=vec, axis=vec, angle=st.floats(-180, 180), n=vec, P=vec)
def test_reach_bounds_the_sampled_shape_tightly(shape, at, axis, angle, n, P):
    params = SHAPES[shape]
    body = _body(shape, params, at, axis, angle)
    pts = Rotation.from_rotvec(np.radians(angle) * np.asarray(axis) / np.linalg.norm(axis)).apply(
        _local_points(shape, params)) + np.asarray(at)
    sampled = float(_line_distance(pts, np.asarray(n), np.asarray(P)).max())
    reach = axis_reach(body.parts, n, P)
    size = 4.0  # |at| + |P| + the shape: the scale of round-off (1e-13 of it)
    assert reach >= sampled - 1e-13 * size
    # the samples miss the true maximum by at most a sagitta of the sampled circles (or,
    # for the sphere grids, of their 1° steps): relative SAG, 1.2e-4 for the spheres
    slack = 1.2e-4 if shape in ("sphere", "hemisphere", "ellipsoid", "torus") else 2 * SAG
    assert reach <= sampled * (1 + slack) + 1e-13 * size


def test_the_issues_shaft_and_disk():
    """The audit's cases: a 50 mm shaft 1.5 m long spun about its own axis reaches 25 mm
    (at 6000 rpm its surface moves at 15.7 m/s; the box half-diagonal said 1.3 m); a disk of
    radius 0.5 m about its axis reaches 0.5 m (at 400 rad/s its rim moves at 200 m/s; the
    box said 424)."""
    shaft = rbcli.load_text("{units: {length: mm}, shape: cylinder, diameter: 50, length: 1500, mass: 23}")
    r = axis_reach(shaft.parts, (0, 0, 1), (0, 0, 0))
    assert r == pytest.approx(0.025, rel=1e-15)
    assert r * 6000 * 2 * math.pi / 60 == pytest.approx(15.70796, rel=1e-6)
    disk = rbcli.load_text("{shape: disk, radius: 0.5, mass: 2}")
    assert axis_reach(disk.parts, (0, 0, 1), (0, 0, 0)) * 400 == pytest.approx(200.0, rel=1e-15)


def test_holes_do_not_reach_and_parts_combine():
    # a plate with a hole at its far corner: the hole is inside the material; the reach is
    # the plate's corner. Two parts: the farther one counts.
    body = rbcli.load_text(
        "{parts: [{shape: box, size: [0.4, 0.2, 0.01], mass: 1},"
        " {shape: cylinder, radius: 0.02, length: 0.01, at: [0.15, 0.05, 0], subtract: true, mass: 0.01},"
        " {shape: point, mass: 0.1, at: [0, 0, 0.7]}]}")
    # about the z axis: the box corner sqrt(0.2² + 0.1²); about x: the point at 0.7
    assert axis_reach(body.parts, (0, 0, 1), (0, 0, 0)) == pytest.approx(math.hypot(0.2, 0.1), rel=1e-15)
    assert axis_reach(body.parts, (1, 0, 0), (0, 0, 0)) == pytest.approx(0.7, rel=1e-15)


def test_a_line_through_a_circle_centre_along_its_plane():
    # the degenerate ellipse (a circle seen edge-on) and the face-on circle (constant)
    ring = rbcli.load_text("{shape: ring, radius: 0.3, mass: 1}")
    assert axis_reach(ring.parts, (1, 0, 0), (0, 0, 0)) == pytest.approx(0.3, rel=1e-15)
    assert axis_reach(ring.parts, (0, 0, 1), (0, 0, 0)) == pytest.approx(0.3, rel=1e-15)
    assert axis_reach(ring.parts, (0, 0, 1), (0.1, 0, 0)) == pytest.approx(0.4, rel=1e-15)


def test_a_mesh_reaches_its_farthest_vertex(tmp_path):
    """A mesh part (an OBJ tetrahedron, placed and turned): its farthest vertex from the line,
    read from the file here and placed with scipy's Rotation (exact: below the drawing's
    decimation threshold the outline keeps the file's vertices)."""
    V = np.array([[0.0, 0.0, 0.0], [0.3, 0.0, 0.0], [0.0, 0.2, 0.0], [0.0, 0.0, 0.5]])
    (tmp_path / "tet.obj").write_text("".join(f"v {x} {y} {z}\n" for x, y, z in V)
                                      + "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n", encoding="utf-8")
    body_file = tmp_path / "b.yaml"
    body_file.write_text("parts:\n  - {shape: mesh, file: tet.obj, density: 1000, at: [0.1, -0.2, 0.3],"
                         " rotate: {axis: [1, 1, 0], angle: 40}}\n", encoding="utf-8")
    body = rbcli.load(body_file)
    pts = Rotation.from_rotvec(np.radians(40) * np.array([1, 1, 0]) / math.sqrt(2)).apply(V) + [0.1, -0.2, 0.3]
    n, P = np.array([0.2, -1.0, 0.4]), np.array([0.05, 0.0, -0.1])
    assert axis_reach(body.parts, n, P) == pytest.approx(_line_distance(pts, n, P).max(), rel=1e-14)


def test_a_given_part_is_measured_as_its_equivalent_ellipsoid():
    """A given part (mass, com, inertia only) has no shape: the reach is that of its
    equivalent uniform ellipsoid (semi-axes sqrt(5 (I2 + I3 - I1) / (2 m)), ...), the same a
    uniform ellipsoid of those moments gives."""
    g = rbcli.load_text("{shape: given, mass: 2, com: [0.1, 0, 0], inertia: [[0.02, 0, 0], [0, 0.05, 0], "
                        "[0, 0, 0.06]], convention: tensor}")
    I1, I2, I3 = 0.02, 0.05, 0.06
    semi = [math.sqrt(5 * (I2 + I3 - I1) / 4), math.sqrt(5 * (I1 + I3 - I2) / 4), math.sqrt(5 * (I1 + I2 - I3) / 4)]
    e = rbcli.load_text("{shape: ellipsoid, mass: 2, semi_axes: [%r, %r, %r], at: [0.1, 0, 0]}" % tuple(semi))
    for n in ((0, 0, 1), (1, 0, 0), (0.3, 0.4, 0.5)):
        assert axis_reach(g.parts, n, (0, 0, 0)) == pytest.approx(axis_reach(e.parts, n, (0, 0, 0)), rel=1e-12)
