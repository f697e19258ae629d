"""rbcli.core.shapes: textbook values, mesh and quadrature oracles, limits and invariants.

Expected values come from (a) textbook tables (Meriam & Kraige, Dynamics, App. B;
Beer & Johnston, inside covers), evaluated by hand for the dimensions used and written
out as decimals; (b) trimesh's mass properties of meshes whose discretisation error is
either known in closed form (regular-polygon prisms and pyramids) or bracketed
rigorously (an inscribed convex polyhedron) or extrapolated (Richardson); (c) numerical
quadrature with scipy.integrate; (d) limits and exact additivity.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import trimesh
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from rbcli.core.shapes import SHAPES, ShapeError, ShapeGeometry, geometry

# Closed forms with O(10) floating-point operations on O(1) numbers: relative error
# ~10 * 1.1e-16; the hand-computed decimals below carry >= 15 significant figures.
RT = 1e-12


def parallel(unit_inertia: np.ndarray, com: np.ndarray, point) -> np.ndarray:
    """Textbook parallel-axis theorem, written out independently of the code under test."""
    d = np.asarray(com, float) - np.asarray(point, float)
    return unit_inertia + (d @ d) * np.eye(3) - np.outer(d, d)


def total(g: ShapeGeometry) -> np.ndarray:
    """Inertia about the com for unit density: measure * unit inertia."""
    return g.measure * g.unit_inertia


# ----------------------------------------------------------------- textbook values

# (shape, params, measure_kind, measure, com, unit inertia about the com,
#  unit inertia about the local origin) — each number worked by hand from the cited formula.
TEXTBOOK = [
    # point mass: nothing but the point
    ("point", {}, "point", 1.0, [0, 0, 0], np.zeros((3, 3)), np.zeros((3, 3))),
    # slender rod L = 0.6: Ixx = Iyy = L²/12 = 0.36/12 = 0.03, Izz = 0
    ("rod", {"length": 0.6}, "length", 0.6, [0, 0, 0],
     np.diag([0.03, 0.03, 0.0]), np.diag([0.03, 0.03, 0.0])),
    # thin hoop R = 0.2: length 2πR = 1.2566370614359172; Izz = R² = 0.04; Ixx = R²/2 = 0.02
    ("ring", {"radius": 0.2}, "length", 1.2566370614359172, [0, 0, 0],
     np.diag([0.02, 0.02, 0.04]), np.diag([0.02, 0.02, 0.04])),
    # annulus R = 0.3, r = 0.1: area π(0.09 − 0.01) = 0.25132741228718347;
    # Izz = (R² + r²)/2 = 0.05; Ixx = Iyy = (R² + r²)/4 = 0.025
    ("disk", {"radius": 0.3, "inner_radius": 0.1}, "area", 0.25132741228718347, [0, 0, 0],
     np.diag([0.025, 0.025, 0.05]), np.diag([0.025, 0.025, 0.05])),
    # solid disk R = 0.3: area 0.09π = 0.2827433388230814; Izz = R²/2 = 0.045; Ixx = R²/4
    ("disk", {"radius": 0.3}, "area", 0.2827433388230814, [0, 0, 0],
     np.diag([0.0225, 0.0225, 0.045]), np.diag([0.0225, 0.0225, 0.045])),
    # thin plate 0.4 x 0.3: area 0.12; Ixx = b²/12 = 0.0075; Iyy = a²/12 = 0.013333...;
    # Izz = (a² + b²)/12 = 0.25/12 = 0.0208333...
    ("plate", {"size": [0.4, 0.3]}, "area", 0.12, [0, 0, 0],
     np.diag([0.0075, 0.013333333333333334, 0.020833333333333332]),
     np.diag([0.0075, 0.013333333333333334, 0.020833333333333332])),
    # thick plate = box 0.4 x 0.3 x 0.02: volume 0.0024; Ixx = (0.09 + 0.0004)/12 =
    # 0.0075333..., Iyy = (0.16 + 0.0004)/12 = 0.0133666..., Izz = 0.25/12
    ("plate", {"size": [0.4, 0.3], "thickness": 0.02}, "volume", 0.0024, [0, 0, 0],
     np.diag([0.007533333333333333, 0.013366666666666667, 0.020833333333333332]),
     np.diag([0.007533333333333333, 0.013366666666666667, 0.020833333333333332])),
    # right triangle, legs b = 0.3 along x, h = 0.6 along y, right angle at the origin
    # (Beer & Johnston): area bh/2 = 0.09, centroid (b/3, h/3) = (0.1, 0.2, 0);
    # about the centroid ∫y²dA = bh³/36, ∫x²dA = hb³/36, ∫xy dA = −b²h²/72, so per unit
    # area Ixx = h²/18 = 0.02, Iyy = b²/18 = 0.005, Izz = 0.025, Ixy = +bh/36 = 0.005;
    # about the right-angle vertex ∫y²dA = bh³/12, ∫xy dA = b²h²/24: Ixx = h²/6 = 0.06,
    # Iyy = b²/6 = 0.015, Izz = 0.075, Ixy = −bh/12 = −0.015
    ("triangle", {"vertices": [[0, 0, 0], [0.3, 0, 0], [0, 0.6, 0]]}, "area", 0.09,
     [0.1, 0.2, 0.0],
     np.array([[0.02, 0.005, 0], [0.005, 0.005, 0], [0, 0, 0.025]]),
     np.array([[0.06, -0.015, 0], [-0.015, 0.015, 0], [0, 0, 0.075]])),
    # box 1 x 2 x 3: volume 6; Ixx = (4 + 9)/12, Iyy = (1 + 9)/12, Izz = (1 + 4)/12
    ("box", {"size": [1, 2, 3]}, "volume", 6.0, [0, 0, 0],
     np.diag([13 / 12, 10 / 12, 5 / 12]), np.diag([13 / 12, 10 / 12, 5 / 12])),
    # solid cylinder R = 0.1, L = 0.4: volume 0.004π = 0.012566370614359173;
    # Izz = R²/2 = 0.005; Ixx = (3R² + L²)/12 = 0.19/12 = 0.015833...
    ("cylinder", {"radius": 0.1, "length": 0.4}, "volume", 0.012566370614359173, [0, 0, 0],
     np.diag([0.015833333333333333, 0.015833333333333333, 0.005]),
     np.diag([0.015833333333333333, 0.015833333333333333, 0.005])),
    # thick tube R = 0.1, r = 0.05, L = 0.4: volume π(0.01 − 0.0025)0.4 = 0.003π =
    # 0.009424777960769379; Izz = (R² + r²)/2 = 0.00625; Ixx = (3·0.0125 + 0.16)/12 = 0.0164583...
    ("cylinder", {"radius": 0.1, "length": 0.4, "inner_radius": 0.05}, "volume",
     0.009424777960769379, [0, 0, 0],
     np.diag([0.016458333333333333, 0.016458333333333333, 0.00625]),
     np.diag([0.016458333333333333, 0.016458333333333333, 0.00625])),
    # thin open tube R = 0.1, L = 0.4: area 2πRL = 0.08π = 0.25132741228718347;
    # Izz = R² = 0.01; Ixx = R²/2 + L²/12 = 0.005 + 0.0133333... = 0.0183333...
    ("cylinder", {"radius": 0.1, "length": 0.4, "shell": True}, "area",
     0.25132741228718347, [0, 0, 0],
     np.diag([0.018333333333333333, 0.018333333333333333, 0.01]),
     np.diag([0.018333333333333333, 0.018333333333333333, 0.01])),
    # solid sphere R = 0.5: volume 4πR³/3 = π/6 = 0.5235987755982988; I = 2R²/5 = 0.1
    ("sphere", {"radius": 0.5}, "volume", 0.5235987755982988, [0, 0, 0],
     np.diag([0.1, 0.1, 0.1]), np.diag([0.1, 0.1, 0.1])),
    # hollow sphere R = 0.5, r = 0.25: volume 4π(0.125 − 0.015625)/3 = 0.4581489286485115;
    # I = (2/5)(R⁵ − r⁵)/(R³ − r³) = 0.4·0.25·(31/32)/(7/8) = 3.1/28 = 0.11071428571428571
    ("sphere", {"radius": 0.5, "inner_radius": 0.25}, "volume", 0.4581489286485115, [0, 0, 0],
     np.eye(3) * 0.11071428571428571, np.eye(3) * 0.11071428571428571),
    # thin spherical shell R = 0.5: area 4πR² = π; I = 2R²/3 = 1/6
    ("sphere", {"radius": 0.5, "shell": True}, "area", math.pi, [0, 0, 0],
     np.eye(3) / 6, np.eye(3) / 6),
    # hemisphere R = 0.2: volume 2πR³/3 = 0.016755160819145562; com z = 3R/8 = 0.075;
    # about the flat-face centre I = 2R²/5 = 0.016 for every axis; about the com
    # Ixx = 0.016 − 0.075² = 0.010375 (= 83R²/320), Izz = 0.016
    ("hemisphere", {"radius": 0.2}, "volume", 0.016755160819145562, [0, 0, 0.075],
     np.diag([0.010375, 0.010375, 0.016]), np.diag([0.016, 0.016, 0.016])),
    # cone R = 0.3, h = 0.8: volume πR²h/3 = 0.024π = 0.07539822368615504; com z = h/4 = 0.2;
    # about the com Izz = 3R²/10 = 0.027, Ixx = 3R²/20 + 3h²/80 = 0.0135 + 0.024 = 0.0375;
    # about the base centre Ixx = 3R²/20 + h²/10 = 0.0135 + 0.064 = 0.0775
    ("cone", {"radius": 0.3, "height": 0.8}, "volume", 0.07539822368615504, [0, 0, 0.2],
     np.diag([0.0375, 0.0375, 0.027]), np.diag([0.0775, 0.0775, 0.027])),
    # ellipsoid 1, 2, 3: volume 4π·6/3 = 8π = 25.132741228718345;
    # Ixx = (b² + c²)/5 = 2.6, Iyy = (a² + c²)/5 = 2, Izz = (a² + b²)/5 = 1
    ("ellipsoid", {"semi_axes": [1, 2, 3]}, "volume", 25.132741228718345, [0, 0, 0],
     np.diag([2.6, 2.0, 1.0]), np.diag([2.6, 2.0, 1.0])),
    # torus R = 2, r = 0.5: volume 2π²Rr² = π² = 9.869604401089358;
    # Izz = R² + 3r²/4 = 4.1875; Ixx = R²/2 + 5r²/8 = 2.15625
    ("torus", {"major_radius": 2, "minor_radius": 0.5}, "volume", 9.869604401089358, [0, 0, 0],
     np.diag([2.15625, 2.15625, 4.1875]), np.diag([2.15625, 2.15625, 4.1875])),
]


@pytest.mark.parametrize(
    "shape, params, kind, measure, com, i_com, i_origin",
    TEXTBOOK,
    ids=[f"{t[0]}-{'-'.join(t[1])}" for t in TEXTBOOK],
)
def test_textbook_values(shape, params, kind, measure, com, i_com, i_origin) -> None:
    g = geometry(shape, **params)
    assert g.measure_kind == kind
    assert g.measure == pytest.approx(measure, rel=RT)  # RT: module constant
    np.testing.assert_allclose(g.com, com, rtol=0, atol=1e-15)  # coms are exact fractions of R, h
    scale = max(float(np.max(np.abs(i_origin))), 1e-300)
    np.testing.assert_allclose(g.unit_inertia, i_com, rtol=0, atol=RT * scale)
    np.testing.assert_allclose(parallel(g.unit_inertia, g.com, [0, 0, 0]), i_origin,
                               rtol=0, atol=RT * scale)
    assert np.array_equal(g.unit_inertia, g.unit_inertia.T)


def test_every_shape_has_a_textbook_case() -> None:
    assert {t[0] for t in TEXTBOOK} == set(SHAPES)


# ----------------------------------------------------------------- the catalogue


def test_catalogue_lists_the_primitives() -> None:
    assert set(SHAPES) == {
        "point", "rod", "ring", "disk", "plate", "triangle", "box", "cylinder",
        "sphere", "hemisphere", "cone", "ellipsoid", "torus",
    }
    for name, info in SHAPES.items():
        assert info.name == name
        assert info.measure_kind in {"volume", "area", "length", "point"}
        assert info.summary and info.density_keys and info.origin and info.formulas


@pytest.mark.parametrize("case", TEXTBOOK, ids=[t[0] for t in TEXTBOOK])
def test_catalogue_agrees_with_geometry(case) -> None:
    shape, params = case[0], case[1]
    info = SHAPES[shape]
    assert set(params) <= set(info.required) | set(info.optional)
    assert set(info.required) <= set(params)
    # the default measure kind is what the required parameters alone give
    required_only = {k: v for k, v in params.items() if k in info.required}
    assert geometry(shape, **required_only).measure_kind == info.measure_kind
    for key in info.required:
        with pytest.raises(ShapeError) as err:
            geometry(shape, **{k: v for k, v in params.items() if k != key})
        assert err.value.param == key


# ----------------------------------------------------------------- validation


BAD = [
    ("rod", {"length": 0}, "length", "greater than 0"),
    ("rod", {"length": -1.0}, "length", "greater than 0"),
    ("rod", {"length": float("inf")}, "length", "finite"),
    ("rod", {"length": float("nan")}, "length", "finite"),
    ("rod", {"length": "1 m"}, "length", "number"),
    ("rod", {"length": True}, "length", "number"),
    ("rod", {"from": [0, 0, 0]}, "from", "unknown parameter"),
    ("ring", {}, "radius", "needs 'radius'"),
    ("disk", {"radius": 0.1, "inner_radius": 0.1}, "inner_radius", "less than radius"),
    ("disk", {"radius": 0.1, "inner_radius": 0.2}, "inner_radius", "less than radius"),
    ("disk", {"radius": 0.1, "inner_radius": -0.01}, "inner_radius", "negative"),
    ("plate", {"size": [1, 2, 3]}, "size", "2 components"),
    ("plate", {"size": [1, 0]}, "size", "size[1] must be greater than 0"),
    ("plate", {"size": [1, 2], "thickness": -0.1}, "thickness", "negative"),
    ("plate", {"size": 1.0}, "size", "list of 2"),
    ("box", {"size": [1, 2]}, "size", "3 components"),
    ("box", {"size": "1 2 3"}, "size", "list of 3"),
    ("box", {"size": [1, 2, float("nan")]}, "size", "size[2] must be finite"),
    ("triangle", {"vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]]}, "vertices", "collinear"),
    ("triangle", {"vertices": [[0, 0, 0], [1, 0, 0], [1, 0, 0]]}, "vertices", "collinear"),
    ("triangle", {"vertices": [[0, 0, 0], [1, 0, 0]]}, "vertices", "3 components"),
    ("triangle", {"vertices": [[0, 0, 0], [1, 0], [0, 1, 0]]}, "vertices", "vertices[1]"),
    ("triangle", {"vertices": [[0, 0, 0], [1, 0, "x"], [0, 1, 0]]}, "vertices", "vertices[1][2]"),
    ("cylinder", {"radius": 0.1}, "length", "needs 'length'"),
    ("cylinder", {"radius": 0.1, "length": 1, "inner_radius": 0.05, "shell": True},
     "inner_radius", "shell"),
    ("cylinder", {"radius": 0.1, "length": 1, "shell": "yes"}, "shell", "true or false"),
    ("sphere", {"radius": 0.1, "inner_radius": 0.05, "shell": True}, "inner_radius", "shell"),
    ("sphere", {"radius": 0.1, "inner_radius": 0.1}, "inner_radius", "less than radius"),
    ("cone", {"radius": 0.1, "height": 0}, "height", "greater than 0"),
    ("ellipsoid", {"semi_axes": [1, 2]}, "semi_axes", "3 components"),
    ("ellipsoid", {"semi_axes": [1, -2, 3]}, "semi_axes", "semi_axes[1]"),
    ("torus", {"major_radius": 1, "minor_radius": 1.5}, "minor_radius", "must not exceed"),
    ("torus", {"major_radius": 1, "minor_radius": 0}, "minor_radius", "greater than 0"),
    ("point", {"radius": 1}, "radius", "unknown parameter"),
    ("hemisphere", {"radius": 1, "height": 1}, "height", "allowed: radius"),
]


@pytest.mark.parametrize(
    "shape, params, param, text", BAD, ids=[f"{b[0]}-{b[2]}-{b[3]}" for b in BAD]
)
def test_bad_parameters_name_the_parameter(shape, params, param, text) -> None:
    with pytest.raises(ShapeError) as err:
        geometry(shape, **params)
    assert isinstance(err.value, ValueError)
    assert err.value.param == param
    assert text in str(err.value)
    assert str(err.value)[0].islower()  # messages are lower case


def test_unknown_shape_lists_the_shapes() -> None:
    with pytest.raises(ValueError) as err:
        geometry("cuboid", size=[1, 2, 3])
    for name in SHAPES:
        assert name in str(err.value)
    assert err.value.param == "shape"


@pytest.mark.parametrize("shape", ["mesh", "given", "include"])
def test_io_shapes_are_refused_with_a_reason(shape) -> None:
    with pytest.raises(ValueError, match="handled by the body loader"):
        geometry(shape, file="x.stl")


def test_horn_torus_is_allowed_and_optional_none_is_absent() -> None:
    # minor == major is the (self-touching) horn torus: allowed by the spec (r <= R)
    assert geometry("torus", major_radius=1, minor_radius=1).measure > 0
    a = geometry("cylinder", radius=0.1, length=0.2, inner_radius=None, shell=None)
    b = geometry("cylinder", radius=0.1, length=0.2)
    assert a.measure == b.measure and np.array_equal(a.unit_inertia, b.unit_inertia)
    # inner_radius: 0 with shell is harmless (no inner wall asked for)
    assert geometry("sphere", radius=1, inner_radius=0, shell=True).measure_kind == "area"


def test_geometry_is_frozen() -> None:
    g = geometry("cone", radius=0.3, height=0.8)
    with pytest.raises(ValueError):
        g.com[2] = 1.0  # read-only arrays
    with pytest.raises(AttributeError):
        g.measure = 2.0  # type: ignore[misc]
    assert type(g.measure) is float


# ----------------------------------------------------------------- trimesh oracles


def tm_props(mesh: trimesh.Trimesh) -> tuple[float, np.ndarray, np.ndarray]:
    """trimesh's volume, com and inertia about the com at unit density."""
    assert mesh.is_watertight and mesh.is_winding_consistent
    mesh.density = 1.0
    return float(mesh.volume), np.asarray(mesh.center_mass), np.asarray(mesh.moment_inertia)


def test_box_agrees_with_trimesh_to_round_off() -> None:
    size = (0.7, 1.3, 2.9)
    v, com, inertia = tm_props(trimesh.creation.box(extents=size))
    g = geometry("box", size=size)
    # 12 triangles, a few dozen operations each on O(1) numbers: round-off ~1e-15
    assert v == pytest.approx(g.measure, rel=1e-13)
    np.testing.assert_allclose(com, g.com, rtol=0, atol=1e-14)
    np.testing.assert_allclose(inertia, total(g), rtol=0, atol=1e-13 * np.max(total(g)))


# A prism or pyramid over the regular N-gon inscribed in the circle of radius R
# (trimesh.creation.cylinder / cone) differs from the round solid in closed form. With
# α = 2π/N, split the N-gon into N triangles (centre, Pᵢ, Pᵢ₊₁):
#   area  A_N = N (R²/2) sin α             = πR² · [N sin α / (2π)]
#   ∫ρ² dA / A = (|P₁|² + |P₂|² + P₁·P₂)/6 = R² (2 + cos α)/6  (triangle second moment)
#              = (R²/2) · [(2 + cos α)/3]
# and by N-fold symmetry (N >= 3) ∫x² dA = ∫y² dA, ∫xy dA = 0. Every cross-section of a
# prism or pyramid is that N-gon scaled, so the polygonal solid has exactly the volume of
# the round one times N sin α/(2π), and exactly the inertia per unit mass of the round
# one with R² replaced by R²(2 + cos α)/3 (the axial terms are unchanged, the com too).


def _polygon_factors(n: int) -> tuple[float, float]:
    a = 2 * math.pi / n
    return n * math.sin(a) / (2 * math.pi), (2 + math.cos(a)) / 3


@pytest.mark.parametrize("n", [5, 16, 64])
def test_cylinder_against_trimesh_prism(n) -> None:
    r, length = 0.15, 0.5
    v, com, inertia = tm_props(trimesh.creation.cylinder(radius=r, height=length, sections=n))
    f_area, f_r2 = _polygon_factors(n)
    round_ = geometry("cylinder", radius=r, length=length)
    poly = geometry("cylinder", radius=r * math.sqrt(f_r2), length=length)
    # ~4N triangles summed: round-off ~N * 1e-16 relative -> 1e-12 is ample
    assert v == pytest.approx(round_.measure * f_area, rel=1e-12)
    np.testing.assert_allclose(com, [0, 0, 0], rtol=0, atol=1e-14)
    np.testing.assert_allclose(inertia / v, poly.unit_inertia, rtol=0,
                               atol=1e-12 * np.max(poly.unit_inertia))
    # and the round formula is the N -> oo limit: the relative defect is the closed form
    assert 1 - v / round_.measure == pytest.approx(1 - f_area, rel=1e-6)


@pytest.mark.parametrize("n", [5, 16, 64])
def test_cone_against_trimesh_pyramid(n) -> None:
    r, h = 0.3, 0.8
    v, com, inertia = tm_props(trimesh.creation.cone(radius=r, height=h, sections=n))
    f_area, f_r2 = _polygon_factors(n)
    round_ = geometry("cone", radius=r, height=h)
    poly = geometry("cone", radius=r * math.sqrt(f_r2), height=h)
    # trimesh puts the base on z = 0 with the apex at +z, like our local frame; any
    # pyramid has its com at h/4 above the base. Round-off as for the prism.
    assert v == pytest.approx(round_.measure * f_area, rel=1e-12)
    np.testing.assert_allclose(com, round_.com, rtol=0, atol=1e-14)
    np.testing.assert_allclose(inertia / v, poly.unit_inertia, rtol=0,
                               atol=1e-12 * np.max(poly.unit_inertia))


def _inscribed_polyhedron(subdivisions: int) -> tuple[trimesh.Trimesh, float]:
    """A unit icosphere (convex, vertices on the sphere) and the radius of the largest
    ball it contains.

    A convex polyhedron with its vertices on the unit sphere is the intersection of the
    half-spaces of its faces; the plane of a face with circumradius ρ lies at distance
    sqrt(1 − ρ²) from the centre. So B(r_in) ⊂ P ⊂ B(1) with r_in = sqrt(1 − max ρ²).
    """
    mesh = trimesh.creation.icosphere(subdivisions=subdivisions, radius=1.0)
    assert mesh.is_convex
    tri = mesh.vertices[mesh.faces]
    a = np.linalg.norm(tri[:, 1] - tri[:, 2], axis=1)
    b = np.linalg.norm(tri[:, 0] - tri[:, 2], axis=1)
    c = np.linalg.norm(tri[:, 0] - tri[:, 1], axis=1)
    area2 = np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    rho = a * b * c / (2 * area2)  # circumradius abc / (4 · area)
    return mesh, math.sqrt(1 - float(rho.max()) ** 2)


def test_sphere_bracketed_by_inscribed_icosphere() -> None:
    # B(r_in) ⊂ P ⊂ B(R), and volume and every moment of inertia about the centre grow
    # with the set (positive density). So r_in³ V ≤ V_P ≤ V and r_in⁵ I ≤ I_P ≤ I for the
    # unit-density totals of the ball of radius 1. Here 1 − r_in = 1.1e-3, so a formula
    # off by more than ~0.6 % fails.
    mesh, r_in = _inscribed_polyhedron(4)
    v, com, inertia = tm_props(mesh)
    g = geometry("sphere", radius=1.0)
    slack = 1e-12  # round-off in trimesh's sum over 5120 faces
    assert g.measure * r_in**3 * (1 - slack) <= v <= g.measure * (1 + slack)
    np.testing.assert_allclose(com, 0, atol=1e-14)
    for k in range(3):
        upper = total(g)[k, k]
        assert upper * r_in**5 * (1 - slack) <= inertia[k, k] <= upper * (1 + slack)
    assert 1 - r_in**5 < 6e-3  # the bracket is tight enough to mean something


def test_ellipsoid_bracketed_by_scaled_icosphere() -> None:
    # The linear map S = diag(a, b, c) takes B(r_in) ⊂ P ⊂ B(1) to
    # E(r_in·abc) ⊂ S P ⊂ E(a, b, c); the second-moment matrix ∫x xᵀ dV grows with the set
    # and so do the diagonal inertias (sums of its diagonal entries). Scaling by r_in
    # multiplies volume by r_in³ and second moments by r_in⁵.
    semi = np.array([0.5, 1.2, 2.0])
    mesh, r_in = _inscribed_polyhedron(4)
    mesh.apply_transform(np.diag([*semi, 1.0]))
    v, com, inertia = tm_props(mesh)
    g = geometry("ellipsoid", semi_axes=semi)
    slack = 1e-12  # round-off in the sum over 5120 faces
    assert g.measure * r_in**3 * (1 - slack) <= v <= g.measure * (1 + slack)
    np.testing.assert_allclose(com, 0, atol=1e-13)
    for k in range(3):
        upper = total(g)[k, k]
        assert upper * r_in**5 * (1 - slack) <= inertia[k, k] <= upper * (1 + slack)
    # symmetric under x -> -x etc.: products of inertia vanish to round-off
    off = inertia - np.diag(np.diag(inertia))
    assert np.max(np.abs(off)) < 1e-12 * np.max(inertia)


def test_torus_against_trimesh_with_richardson_extrapolation() -> None:
    # trimesh.creation.torus(R, r, N, N) samples the surface on an N x N grid; the error
    # of volume and inertia is c/N² + O(N⁻⁴) (second-order faceting in both angles).
    # Check the N⁻² model (error ratio 4 when N doubles) and that the extrapolation
    # (4 X(2N) − X(N))/3, which removes the N⁻² term, meets the closed form. Measured
    # with N = 32/64 the extrapolated residual is 4e-5 and it shrinks 16-fold per
    # doubling, so with N = 64/128 it is ~3e-6: allow 1e-5.
    big, small = 2.0, 0.5
    g = geometry("torus", major_radius=big, minor_radius=small)
    exact = np.array([g.measure, total(g)[0, 0], total(g)[2, 2]])
    values = []
    for n in (64, 128):
        v, com, inertia = tm_props(trimesh.creation.torus(big, small, n, n))
        np.testing.assert_allclose(com, 0, atol=1e-13)
        values.append(np.array([v, inertia[0, 0], inertia[2, 2]]))
    err64, err128 = values[0] / exact - 1, values[1] / exact - 1
    np.testing.assert_allclose(err64 / err128, 4.0, rtol=0.01)  # N⁻² with a 1 % O(N⁻²) wobble
    extrapolated = (4 * values[1] - values[0]) / 3
    np.testing.assert_allclose(extrapolated, exact, rtol=1e-5)


# ----------------------------------------------------------------- quadrature oracles


def _moments_by_quadrature(top, z_max: float) -> np.ndarray:
    """∫ over the solid of revolution {0 ≤ z ≤ z_max, ρ ≤ top(z)} of
    [1, x, y, z, x², y², z², xy, yz, zx] dV, in cylindrical coordinates (dV = ρ dρ dφ dz).

    scipy.integrate.tplquad with epsrel 1e-11; the integrands are polynomials in ρ, z and
    trigonometric in φ, so Gauss–Kronrod converges to ~1e-13 with few subdivisions.
    """
    from scipy.integrate import tplquad

    funcs = [
        lambda x, y, z: 1.0,
        lambda x, y, z: x,
        lambda x, y, z: y,
        lambda x, y, z: z,
        lambda x, y, z: x * x,
        lambda x, y, z: y * y,
        lambda x, y, z: z * z,
        lambda x, y, z: x * y,
        lambda x, y, z: y * z,
        lambda x, y, z: z * x,
    ]
    out = []
    for f in funcs:
        # tplquad integrates func(phi, rho, z): z outer, rho middle, phi inner
        val, _ = tplquad(
            lambda phi, rho, z, f=f: f(rho * math.cos(phi), rho * math.sin(phi), z) * rho,
            0.0, z_max, 0.0, lambda z: top(z), 0.0, 2 * math.pi,
            epsabs=1e-14, epsrel=1e-11,
        )
        out.append(val)
    return np.array(out)


def _check_against_moments(g: ShapeGeometry, m: np.ndarray, rtol: float) -> None:
    vol, mx, my, mz, xx, yy, zz, xy, yz, zx = m
    # inertia about the local ORIGIN from the raw moments (tensor convention)
    i_origin = np.array([
        [yy + zz, -xy, -zx],
        [-xy, xx + zz, -yz],
        [-zx, -yz, xx + yy],
    ]) / vol
    scale = float(np.max(np.abs(i_origin)))
    assert g.measure == pytest.approx(vol, rel=rtol)
    np.testing.assert_allclose(g.com, np.array([mx, my, mz]) / vol, rtol=0,
                               atol=rtol * math.sqrt(scale))
    np.testing.assert_allclose(parallel(g.unit_inertia, g.com, [0, 0, 0]), i_origin,
                               rtol=0, atol=rtol * scale)


def test_hemisphere_against_quadrature() -> None:
    r = 0.37
    m = _moments_by_quadrature(lambda z: math.sqrt(max(r * r - z * z, 0.0)), r)
    # 1e-9: quadrature asked for 1e-11 relative, the integrand along z has a sqrt-type
    # endpoint only in the upper limit of rho (smooth in z after the rho integral)
    _check_against_moments(geometry("hemisphere", radius=r), m, rtol=1e-9)


def test_cone_against_quadrature() -> None:
    r, h = 0.3, 0.8
    m = _moments_by_quadrature(lambda z: r * (1 - z / h), h)
    # polynomial integrands: the quadrature is accurate to ~1e-13; 1e-9 as above
    _check_against_moments(geometry("cone", radius=r, height=h), m, rtol=1e-9)


def test_two_hemispheres_make_a_sphere() -> None:
    # the upper hemisphere and its mirror image (com at −3R/8) together are the sphere:
    # equal halves, so the sphere's unit inertia about the centre is the mean of the
    # halves' unit inertias about their flat-face centre (= the sphere's centre).
    r = 0.9
    h = geometry("hemisphere", radius=r)
    s = geometry("sphere", radius=r)
    mirror = np.diag([1.0, 1.0, -1.0])
    up = parallel(h.unit_inertia, h.com, [0, 0, 0])
    down = parallel(mirror @ h.unit_inertia @ mirror, mirror @ h.com, [0, 0, 0])
    np.testing.assert_allclose((up + down) / 2, s.unit_inertia, rtol=0, atol=1e-15)  # 3 ops
    assert 2 * h.measure == pytest.approx(s.measure, rel=1e-15)  # (2/3)·2 = 4/3, one rounding


# ----------------------------------------------------------------- limits


def test_annulus_with_inner_to_zero_is_the_disk() -> None:
    disk = geometry("disk", radius=0.4)
    same = geometry("disk", radius=0.4, inner_radius=0.0)
    assert same.measure == disk.measure and np.array_equal(same.unit_inertia, disk.unit_inertia)
    tiny = geometry("disk", radius=0.4, inner_radius=1e-6)
    # r = 1e-6: relative changes are (r/R)² = 6e-12 in area and inertia
    assert tiny.measure == pytest.approx(disk.measure, rel=1e-11)
    np.testing.assert_allclose(tiny.unit_inertia, disk.unit_inertia, rtol=1e-11)


@pytest.mark.parametrize("t", [1e-2, 1e-4, 1e-6])
def test_thick_plate_tends_to_the_thin_plate(t) -> None:
    a, b = 0.4, 0.3
    thin = geometry("plate", size=[a, b])
    thick = geometry("plate", size=[a, b], thickness=t)
    assert thick.measure / t == pytest.approx(thin.measure, rel=1e-15)  # one rounding
    # about z the thickness does not enter at all (exact); about x and y it adds t²/12
    assert thick.unit_inertia[2, 2] == thin.unit_inertia[2, 2]
    np.testing.assert_allclose(
        np.diag(thick.unit_inertia)[:2] - np.diag(thin.unit_inertia)[:2], t * t / 12,
        rtol=0, atol=1e-17)
    # atol 1e-17: each entry is ~0.013 and carries a rounding of <= 2 · 1.1e-16 · 0.013
    # = 3e-18; the difference of two such entries is good to ~6e-18 absolute


def test_ellipsoid_with_equal_axes_is_the_sphere() -> None:
    e = geometry("ellipsoid", semi_axes=[0.7, 0.7, 0.7])
    s = geometry("sphere", radius=0.7)
    assert e.measure == pytest.approx(s.measure, rel=1e-15)  # 4π/3 · a³ by two routes
    np.testing.assert_allclose(e.unit_inertia, s.unit_inertia, rtol=1e-15)


@pytest.mark.parametrize("eps", [1e-2, 1e-3, 1e-5])
def test_hollow_sphere_tends_to_the_shell_at_rate_eps(eps) -> None:
    # With r = R(1 − ε): (R⁵ − r⁵)/(R³ − r³) = R² f(q), f(q) = q² + (1 + q)/(1 + q + q²)
    # (polynomial division), and expanding at q = 1 − ε gives f = 5/3 − (5/3)ε + (10/9)ε²,
    # so I_hollow / I_shell = (3/5) f = 1 − ε + (2/3)ε² + O(ε³): the approach is O(ε).
    # The volume is (4π/3)R³(3ε − 3ε² + ε³) = shell area · Rε · (1 − ε + ε²/3) exactly.
    radius = 0.8
    shell = geometry("sphere", radius=radius, shell=True)
    hollow = geometry("sphere", radius=radius, inner_radius=radius * (1 - eps))
    ratio = hollow.unit_inertia[0, 0] / shell.unit_inertia[0, 0]
    assert 1 - ratio == pytest.approx(eps - 2 / 3 * eps**2, rel=2 * eps**2 + 1e-9)
    # rel: the neglected O(ε³) term relative to ε is O(ε²); 1e-9 covers the round-off of
    # 1 − ratio (~1e-16 / ε = 1e-11 at ε = 1e-5)
    assert hollow.measure / (shell.measure * radius * eps) == pytest.approx(
        1 - eps + eps**2 / 3, rel=1e-9)  # exact identity; 1e-9: round-off in r = R(1 − ε)


def test_thick_tube_tends_to_the_thin_tube() -> None:
    # r = R(1 − ε): Izz = R²(1 + (1 − ε)²)/2 = R²(1 − ε + ε²/2); Ixx -> R²/2 + L²/12
    big, length, eps = 0.1, 0.4, 1e-4
    shell = geometry("cylinder", radius=big, length=length, shell=True)
    tube = geometry("cylinder", radius=big, length=length, inner_radius=big * (1 - eps))
    assert tube.unit_inertia[2, 2] / shell.unit_inertia[2, 2] == pytest.approx(
        1 - eps + eps**2 / 2, rel=1e-12)  # exact identity, round-off only
    np.testing.assert_allclose(np.diag(tube.unit_inertia)[:2], np.diag(shell.unit_inertia)[:2],
                               rtol=eps)  # differs by ~(3/12)·2εR² relative to O(R²)


# ----------------------------------------------------------------- the triangle


def _second_moment_about_origin(g: ShapeGeometry) -> np.ndarray:
    """Area · inertia about the local origin (unit areal density): additive over pieces."""
    return g.measure * parallel(g.unit_inertia, g.com, [0, 0, 0])


def test_plate_is_two_triangles() -> None:
    # the rectangle a x b centred at the origin, cut along a diagonal: the two triangles'
    # second moments about the origin add up to the plate's (exact additivity of ∫ dA)
    a, b = 0.4, 0.3
    p = [[-a / 2, -b / 2, 0], [a / 2, -b / 2, 0], [a / 2, b / 2, 0], [-a / 2, b / 2, 0]]
    t1 = geometry("triangle", vertices=[p[0], p[1], p[2]])
    t2 = geometry("triangle", vertices=[p[0], p[2], p[3]])
    plate = geometry("plate", size=[a, b])
    assert t1.measure + t2.measure == pytest.approx(plate.measure, rel=1e-15)
    summed = _second_moment_about_origin(t1) + _second_moment_about_origin(t2)
    # a few dozen roundings on O(0.1) numbers: 1e-15 relative to the largest entry
    np.testing.assert_allclose(summed, total(plate), rtol=0, atol=1e-15 * np.max(total(plate)) * 10)


def test_triangle_in_a_tilted_plane() -> None:
    # the same right triangle turned into the xz plane: Ixx and Izz swap roles, and the
    # product moves to Ixz (tensor convention) — a rigid relabelling y -> z
    b, h = 0.3, 0.6
    g = geometry("triangle", vertices=[[0, 0, 0], [b, 0, 0], [0, 0, h]])
    expected = np.array([[h * h / 18, 0, b * h / 36], [0, (b * b + h * h) / 18, 0],
                         [b * h / 36, 0, b * b / 18]])  # Beer & Johnston, see TEXTBOOK
    np.testing.assert_allclose(g.unit_inertia, expected, rtol=0, atol=1e-15)


coords = st.floats(min_value=-5.0, max_value=5.0, allow_nan=False)
points = st.lists(coords, min_size=3, max_size=3)


def _well_shaped(v) -> bool:
    v = np.asarray(v, float)
    twice_area = np.linalg.norm(np.cross(v[1] - v[0], v[2] - v[0]))
    longest = max(np.linalg.norm(v[i] - v[j]) for i, j in ((0, 1), (1, 2), (0, 2)))
    return bool(longest > 1e-2 and twice_area > 1e-2 * longest**2)


@settings(max_examples=50, deadline=None)
@given(v=st.lists(points, min_size=3, max_size=3))
def test_triangle_invariant_under_vertex_permutation(v) -> None:
    assume(_well_shaped(v))
    ref = geometry("triangle", vertices=v)
    scale = float(np.max(np.abs(ref.unit_inertia)))
    for perm in itertools.permutations(range(3)):
        g = geometry("triangle", vertices=[v[i] for i in perm])
        assert g.measure == pytest.approx(ref.measure, rel=1e-12)
        # different summation order only: ~10 roundings of numbers up to |v|² ~ 75
        np.testing.assert_allclose(g.com, ref.com, rtol=0, atol=1e-14 * 10)
        np.testing.assert_allclose(g.unit_inertia, ref.unit_inertia, rtol=0, atol=1e-13 * scale)


@settings(max_examples=50, deadline=None)
@given(v=st.lists(points, min_size=3, max_size=3), k=st.integers(0, 2))
def test_triangle_second_moment_is_additive_over_a_midpoint_split(v, k) -> None:
    assume(_well_shaped(v))
    a, b, c = (np.asarray(v[(k + i) % 3], float) for i in range(3))
    m = (b + c) / 2  # split from vertex a to the midpoint of the opposite side
    whole = geometry("triangle", vertices=[a, b, c])
    left = geometry("triangle", vertices=[a, b, m])
    right = geometry("triangle", vertices=[a, m, c])
    assert left.measure == pytest.approx(whole.measure / 2, rel=1e-9)
    # 1e-9: the halves' areas come from cross products of differences; with the
    # well-shaped filter (area >= 1e-2 · longest²) the cancellation costs <= ~100x eps·|v|²
    summed = _second_moment_about_origin(left) + _second_moment_about_origin(right)
    ref = _second_moment_about_origin(whole)
    np.testing.assert_allclose(summed, ref, rtol=0, atol=1e-10 * float(np.max(np.abs(ref))))
    # 1e-10: parallel-axis terms up to |com|²·A ~ 25·A add back in, cancelling by at most
    # the ratio of the origin moment to the centroidal one (a few hundred here)


# ---------------------------------------------------------------------------------------
# the registry: every shape fact lives in SHAPES, and the other lists follow it


def test_the_registry_is_what_the_loader_schema_and_catalogue_read() -> None:
    from rbcli.cli.app import MANUAL
    from rbcli.cli.catalog import SPECIAL
    from rbcli.core.shapes import IO_SHAPES, SHAPES
    from rbcli.body.partlist import SPECIAL_SHAPES
    from rbcli.body.schema import body_schema

    assert SPECIAL_SHAPES == tuple(IO_SHAPES) and set(SPECIAL) == set(IO_SHAPES)
    assert body_schema()["definitions"]["part"]["properties"]["shape"]["enum"] == [*SHAPES, *IO_SHAPES]
    listed = MANUAL[""]["notes"][0]
    assert all(name in listed for name in [*SHAPES, *IO_SHAPES]), "rbcli(1) lists every shape"
    for info in SHAPES.values():
        for param in (*info.required, *info.optional):
            assert info.kind(param).name in ("length", "lengths", "points", "bool")


@pytest.mark.parametrize("shape, params, radius", [
    ("disk", {"radius": 0.3, "inner_radius": 0.1}, 0.3),
    ("ring", {"radius": 0.2}, 0.2),
    ("cylinder", {"radius": 0.1, "length": 2.0}, 0.1),
    ("sphere", {"radius": 0.4}, 0.4),
    ("hemisphere", {"radius": 0.4}, 0.4),
    ("cone", {"radius": 0.5, "height": 1.0}, 0.5),
    ("torus", {"major_radius": 0.3, "minor_radius": 0.05}, 0.35),
    ("box", {"size": [1, 2, 3]}, None),
    ("rod", {"length": 1.0}, None),
])
def test_round_shapes_know_their_outer_radius(shape, params, radius) -> None:
    from rbcli.core.shapes import SHAPES

    info = SHAPES[shape]
    assert info.radius(params) == radius and (info.round is None) == (radius is None)
    assert SHAPES["sphere"].round == "any" and SHAPES["disk"].round == "z"


def test_a_loaded_round_part_carries_the_registry_radius() -> None:
    from rbcli.api.load import load_text

    body = load_text("parts:\n  - {shape: torus, major_radius: 0.3, minor_radius: 0.05, mass: 1}\n"
                     "  - {shape: plate, size: [0.1, 0.2], mass: 1}\n")
    assert body.parts[0].radius == pytest.approx(0.35) and body.parts[1].radius is None
