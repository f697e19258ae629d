"""Tests of rbcli.core.mesh: validation and exact mass properties of triangle meshes.

Oracles: closed forms of the polyhedra (box, corner tetrahedron, regular icosahedron,
regular n-gon prism), closed forms of the smooth solids they approximate (sphere,
torus) with the discretisation error bounded, trimesh's ``mass_properties`` on the same
arrays (test-only dependency), scipy's Rotation, and the parallel-axis theorem.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from rbcli.core.mesh import VOLUME_RTOL, MeshError, MeshProps, mass_properties

EPS = np.finfo(float).eps


# ------------------------------------------------------------------ meshes for the tests


def box_mesh(a: float, b: float, c: float, corner=(0.0, 0.0, 0.0)):
    """A box [0,a]x[0,b]x[0,c] (+ corner) as 8 vertices and 12 outward triangles."""
    x = np.array(
        [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
        dtype=float,
    )
    v = x * [a, b, c] + np.asarray(corner, dtype=float)
    f = np.array(
        [
            [0, 2, 1], [0, 3, 2],  # z = 0, normal -z
            [4, 5, 6], [4, 6, 7],  # z = c, normal +z
            [0, 1, 5], [0, 5, 4],  # y = 0, normal -y
            [3, 7, 6], [3, 6, 2],  # y = b, normal +y
            [0, 4, 7], [0, 7, 3],  # x = 0, normal -x
            [1, 2, 6], [1, 6, 5],  # x = a, normal +x
        ]
    )  # fmt: skip
    return v, f


def tetra_mesh(a: float, b: float, c: float):
    """Corner tetrahedron O, (a,0,0), (0,b,0), (0,0,c), outward triangles."""
    v = np.array([[0, 0, 0], [a, 0, 0], [0, b, 0], [0, 0, c]], dtype=float)
    f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    return v, f


def lumpy_mesh():
    """A closed, non-symmetric, non-convex mesh: a stretched, sheared, dented icosphere."""
    s = trimesh.creation.icosphere(subdivisions=2)
    v = s.vertices * [1.0, 1.7, 2.6]
    v[:, 0] += 0.3 * v[:, 1] + 0.2 * np.sin(3 * v[:, 2])
    v *= 1.0 - 0.2 * np.exp(-((v[:, 2] - 1.5) ** 2))[:, None]
    return v, np.asarray(s.faces)


def trimesh_props(v, f):
    """trimesh's answer on the same arrays: volume, centroid, inertia per unit mass."""
    m = trimesh.Trimesh(vertices=v, faces=f, process=False)
    mp = m.mass_properties
    return mp["volume"], np.asarray(mp["center_mass"]), np.asarray(mp["inertia"]) / mp["volume"]


def rel(a, b) -> float:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.abs(a - b).max() / np.abs(b).max())


# ------------------------------------------------------------------ closed forms (exact)


def test_box_closed_form():
    a, b, c = 0.3, 0.5, 1.1
    v, f = box_mesh(a, b, c, corner=(1.0, -2.0, 0.5))
    p = mass_properties(v, f)
    assert isinstance(p, MeshProps)
    # 12 triangles, each a few dozen floating-point operations on numbers of size ~1:
    # the result is exact to a few ulps; 1e-13 leaves a factor ~100 of margin.
    assert p.volume == pytest.approx(a * b * c, rel=1e-13)
    assert p.area == pytest.approx(2 * (a * b + b * c + c * a), rel=1e-13)
    np.testing.assert_allclose(p.centroid, [1 + a / 2, -2 + b / 2, 0.5 + c / 2], rtol=1e-13)
    expected = np.diag([b * b + c * c, a * a + c * c, a * a + b * b]) / 12  # per unit mass
    np.testing.assert_allclose(p.unit_inertia, expected, rtol=0, atol=1e-13 * expected.max())
    assert p.n_triangles == 12 and not p.flipped and p.warnings == ()


def test_corner_tetrahedron_closed_form():
    a, b, c = 1.0, 2.0, 3.0
    v, f = tetra_mesh(a, b, c)
    p = mass_properties(v, f)
    vol = a * b * c / 6
    # Dirichlet integrals over the unit simplex (∫u² = 2!/5! = 1/60, ∫uv = 1/5! = 1/120),
    # scaled by the Jacobian abc: ∫x² dV = a² V / 10, ∫xy dV = a b V / 20.
    m2 = vol * np.array(
        [[a * a / 10, a * b / 20, a * c / 20],
         [a * b / 20, b * b / 10, b * c / 20],
         [a * c / 20, b * c / 20, c * c / 10]]
    )  # fmt: skip
    g = np.array([a, b, c]) / 4
    cc = m2 - vol * np.outer(g, g)  # second moments about the centroid
    expected = (np.trace(cc) * np.eye(3) - cc) / vol
    # 4 triangles, exact small rationals: rounding only, a few ulps.
    assert p.volume == pytest.approx(vol, rel=1e-14)
    np.testing.assert_allclose(p.centroid, g, rtol=1e-14)
    scale = np.abs(expected).max()
    np.testing.assert_allclose(p.unit_inertia, expected, rtol=0, atol=1e-14 * scale)
    hyp = 0.5 * np.linalg.norm(np.cross([-a, b, 0], [-a, 0, c]))
    assert p.area == pytest.approx(a * b / 2 + b * c / 2 + a * c / 2 + hyp, rel=1e-14)


def test_regular_icosahedron_closed_form():
    s = trimesh.creation.icosphere(subdivisions=0, radius=1.0)
    p = mass_properties(s.vertices, s.faces)
    edge = 4 / math.sqrt(10 + 2 * math.sqrt(5))  # edge of the icosahedron with circumradius 1
    phi = (1 + math.sqrt(5)) / 2
    # Regular icosahedron of edge e: V = 5(3 + √5) e³ / 12, area 5√3 e², and an isotropic
    # inertia I = φ² m e² / 10 about every axis through the centre.
    # 20 triangles and trimesh's vertices are themselves rounded: 1e-13 relative.
    assert p.volume == pytest.approx(5 * (3 + math.sqrt(5)) / 12 * edge**3, rel=1e-13)
    assert p.area == pytest.approx(5 * math.sqrt(3) * edge**2, rel=1e-13)
    np.testing.assert_allclose(p.centroid, 0, atol=1e-15)
    expected = phi**2 * edge**2 / 10 * np.eye(3)
    np.testing.assert_allclose(p.unit_inertia, expected, rtol=0, atol=1e-13)


@pytest.mark.parametrize("n", [3, 6, 17, 64])
def test_regular_prism_closed_form(n):
    r, h = 0.4, 1.3
    cyl = trimesh.creation.cylinder(radius=r, height=h, sections=n)
    p = mass_properties(cyl.vertices, cyl.faces)
    t = 2 * math.pi / n
    # Regular n-gon of circumradius r: area A = n r² sin(t) / 2, polar second moment
    # J = n r⁴ sin(t) (2 + cos t) / 12 (→ π r⁴/2 as n → ∞), isotropic in the plane.
    # Prism: I_z/m = J/A; I_x/m = I_y/m = J/(2A) + h²/12.
    area = n * r * r * math.sin(t) / 2
    j_over_a = r * r * (2 + math.cos(t)) / 6
    # The vertices come from cos/sin (rounded), ~4n triangles: 1e-12 relative.
    assert p.volume == pytest.approx(area * h, rel=1e-12)
    expected = np.diag([j_over_a / 2 + h * h / 12, j_over_a / 2 + h * h / 12, j_over_a])
    np.testing.assert_allclose(p.unit_inertia, expected, rtol=0, atol=1e-12 * expected.max())
    np.testing.assert_allclose(p.centroid, 0, atol=1e-15)


# ------------------------------------------------- smooth solids (discretisation error)


def test_fine_icosphere_approaches_the_sphere():
    r = 1.0
    errors = []
    for k in (4, 5):
        s = trimesh.creation.icosphere(subdivisions=k, radius=r)
        p = mass_properties(s.vertices, s.faces)
        h = float(s.edges_unique_length.max())
        # Inscribed polyhedron: every flat triangle lies inside the sphere, at most the
        # sagitta ρ²/(2r) ≈ h²/(6r) below it (ρ ≈ h/√3 the triangle's circumradius), so
        # 0 < 1 - V/V_sphere < 3 h²/(6 r²) = h²/(2 r²).
        v_sphere = 4 / 3 * math.pi * r**3
        deficit = 1 - p.volume / v_sphere
        assert 0 < deficit < h * h / (2 * r * r)
        # Per unit mass the sphere has I = 2 r²/5; the polyhedron's mass sits slightly
        # closer to the centre, by the same O(h²) relative amount.
        i_err = 1 - p.unit_inertia.diagonal() / (0.4 * r * r)
        assert np.all(i_err > 0) and np.all(i_err < h * h / (r * r))
        offdiag = p.unit_inertia - np.diag(p.unit_inertia.diagonal())
        assert np.abs(offdiag).max() < 1e-12  # cubic symmetry of the icosphere
        errors.append(deficit)
    # Second-order convergence: halving the edge divides the error by ~4.
    assert 3.5 < errors[0] / errors[1] < 4.5


def test_polyhedron_volume_by_an_independent_formula():
    # Independent check of the icosphere's exact polyhedral volume: the sum of the
    # pyramids (1/3) base-area x height from the centre (the surface is star-shaped
    # about the origin), with area from Heron's formula.
    s = trimesh.creation.icosphere(subdivisions=3, radius=2.0)
    tri = s.vertices[s.faces]
    la, lb, lc = (np.linalg.norm(tri[:, i] - tri[:, (i + 1) % 3], axis=1) for i in range(3))
    sp = (la + lb + lc) / 2
    heron = np.sqrt(sp * (sp - la) * (sp - lb) * (sp - lc))
    normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    height = np.einsum("ij,ij->i", tri[:, 0], normal / np.linalg.norm(normal, axis=1)[:, None])
    p = mass_properties(s.vertices, s.faces)
    # Heron loses a few digits on thin triangles; 1280 triangles: 1e-12 relative.
    assert p.volume == pytest.approx(float((heron * height).sum() / 3), rel=1e-12)
    assert p.area == pytest.approx(float(heron.sum()), rel=1e-12)


def test_torus_approaches_the_smooth_torus():
    big, small = 1.0, 0.25
    t = trimesh.creation.torus(big, small, major_sections=256, minor_sections=128)
    p = mass_properties(t.vertices, t.faces)
    # Smooth solid torus: V = 2π² R r², I_z/m = R² + 3r²/4, I_x/m = I_y/m = R²/2 + 5r²/8.
    v_exact = 2 * math.pi**2 * big * small**2
    i_exact = np.diag([big**2 / 2 + 5 * small**2 / 8] * 2 + [big**2 + 3 * small**2 / 4])
    # Inscribed polygons with n sides lose ~ (2π/n)²/6 of their area: the cross-section
    # (n = 128) and the sweep (n = 256) add up to ~5e-4; allow twice that.
    tol = 2 * ((2 * math.pi / 128) ** 2 + (2 * math.pi / 256) ** 2) / 6
    assert 0 < 1 - p.volume / v_exact < tol
    np.testing.assert_allclose(p.unit_inertia, i_exact, rtol=0, atol=tol * i_exact.max())
    np.testing.assert_allclose(p.centroid, 0, atol=1e-12)


# ------------------------------------------------------------- against trimesh (oracle)


@pytest.mark.parametrize(
    "make",
    [
        lambda: box_mesh(0.3, 0.5, 1.1, corner=(-0.15, -0.25, -0.55)),
        lambda: tetra_mesh(1.0, 2.0, 3.0),
        lambda: lumpy_mesh(),
        lambda: (lambda s: (s.vertices, s.faces))(trimesh.creation.icosphere(4)),
        lambda: (lambda s: (s.vertices, s.faces))(trimesh.creation.torus(1.0, 0.3)),
        lambda: (lambda s: (s.vertices, s.faces))(trimesh.creation.cylinder(0.2, 2.0)),
        lambda: (lambda s: (s.vertices, s.faces))(trimesh.creation.capsule(1.0, 0.3)),
    ],
    ids=["box", "tetra", "lumpy", "icosphere", "torus", "cylinder", "capsule"],
)
def test_agrees_with_trimesh(make):
    v, f = make()
    p = mass_properties(v, f)
    vol, com, inertia = trimesh_props(v, f)
    # Same exact polynomial integrals in float64; only the reference point (ours the
    # bounding-box centre, trimesh's the origin, both within ~1 mesh size here) and the
    # order of summation differ, so the answers differ by rounding: ~eps x log2(F) for
    # pairwise/BLAS sums, well under 1e-12 for F <= 5120 triangles.
    assert p.volume == pytest.approx(vol, rel=1e-12)
    assert np.abs(p.centroid - com).max() <= 1e-12 * np.abs(v).max()
    assert rel(p.unit_inertia, inertia) < 1e-12


def test_far_from_the_origin_keeps_its_digits():
    rng = np.random.default_rng(7)
    v, f = lumpy_mesh()
    v = v * 0.1  # a part ~0.5 m across
    rot = Rotation.random(random_state=rng).as_matrix()
    shift = np.array([1.0e4, -0.7e4, 0.3e4])  # ~10 km away
    v2 = v @ rot.T + shift
    p1 = mass_properties(v, f)
    p2 = mass_properties(v2, f)
    # Coordinates 1e4 carry an absolute rounding of 1e4 * eps ~ 2e-12 m; about the
    # bounding-box centre that is ~1e-11 relative to a 0.5 m part, whatever the distance.
    back = rot.T @ p2.unit_inertia @ rot
    assert rel(back, p1.unit_inertia) < 1e-9
    assert np.abs(p2.centroid - (rot @ p1.centroid + shift)).max() < 1e-9
    assert p2.volume == pytest.approx(p1.volume, rel=1e-9)
    # Documentation, not a requirement: trimesh integrates about the origin, so its
    # second moments (~V x 1e8) cancel down to ~V x 0.01 and most digits are lost.
    _, _, inertia_t = trimesh_props(v2, f)
    assert rel(rot.T @ inertia_t @ rot, p1.unit_inertia) > 1e-4


# --------------------------------------------------------------------------- invariants


def _quaternion(q):
    q = np.asarray(q, dtype=float)
    n = np.linalg.norm(q)
    return Rotation.from_quat(q / n) if n > 0.1 else Rotation.identity()


@settings(max_examples=40, deadline=None)
@given(
    q=st.lists(st.floats(-1, 1), min_size=4, max_size=4),
    t=st.lists(st.floats(-1e3, 1e3), min_size=3, max_size=3),
)
def test_rigid_motion_leaves_principal_moments_unchanged(q, t):
    v, f = _LUMPY
    r = _quaternion(q)
    p = mass_properties(r.apply(v) + t, f)
    # Coordinates up to ~1e3 carry rounding ~1e3 * eps ~ 2e-13 on a mesh ~3 across: the
    # moments (eigvalsh of a rounded tensor) agree to ~1e-12 relative; 1e-10 is safe.
    np.testing.assert_allclose(
        np.linalg.eigvalsh(p.unit_inertia), _LUMPY_MOMENTS, rtol=1e-10, atol=0
    )
    assert p.volume == pytest.approx(_LUMPY_PROPS.volume, rel=1e-12)
    np.testing.assert_allclose(p.centroid, r.apply(_LUMPY_PROPS.centroid) + t, atol=1e-10)


_LUMPY = lumpy_mesh()
_LUMPY_PROPS = mass_properties(*_LUMPY)
_LUMPY_MOMENTS = np.linalg.eigvalsh(_LUMPY_PROPS.unit_inertia)


def test_additive_over_disjoint_parts():
    v1, f1 = box_mesh(0.3, 0.5, 1.1, corner=(2.0, 0.0, 0.0))
    v2, f2 = lumpy_mesh()
    v = np.vstack([v1, v2])
    f = np.vstack([f1, f2 + len(v1)])
    p1, p2, p = mass_properties(v1, f1), mass_properties(v2, f2), mass_properties(v, f)
    vol = p1.volume + p2.volume
    com = (p1.volume * p1.centroid + p2.volume * p2.centroid) / vol

    def shifted(props):  # parallel-axis theorem to the common centroid, times volume
        d = props.centroid - com
        return props.volume * (props.unit_inertia + (d @ d) * np.eye(3) - np.outer(d, d))

    # Sums of the same terms in another order: rounding only, 1e-12 relative.
    assert p.volume == pytest.approx(vol, rel=1e-12)
    np.testing.assert_allclose(p.centroid, com, atol=1e-12)
    assert rel(p.unit_inertia * p.volume, shifted(p1) + shifted(p2)) < 1e-12
    assert p.area == pytest.approx(p1.area + p2.area, rel=1e-12)


def test_hollow_box_inner_surface_facing_inwards():
    # A box with a box-shaped cavity: the inner surface is wound the other way, so the
    # mesh is closed, consistently oriented, and its volume is the difference.
    vo, fo = box_mesh(2.0, 2.0, 2.0, corner=(-1, -1, -1))
    vi, fi = box_mesh(1.0, 1.0, 1.0, corner=(-0.5, -0.5, -0.5))
    v = np.vstack([vo, vi])
    f = np.vstack([fo, fi[:, ::-1] + len(vo)])
    p = mass_properties(v, f)
    assert p.volume == pytest.approx(8 - 1, rel=1e-14)  # exact small numbers
    # Per volume: (8 x (2²+2²)/12 - 1 x (1²+1²)/12) / 7 about every axis.
    expected = (8 * 8 / 12 - 1 * 2 / 12) / 7
    np.testing.assert_allclose(p.unit_inertia, expected * np.eye(3), rtol=0, atol=1e-14)
    assert not p.flipped


# ------------------------------------------------------------------------- validation


def test_open_box_is_an_error_naming_the_boundary_edges():
    v, f = box_mesh(1.0, 2.0, 3.0)
    open_f = f[:10]  # drop the x = a face: two triangles, a square hole with 4 sides
    with pytest.raises(MeshError, match=r"not closed: 4 boundary edges"):
        mass_properties(v, open_f)
    with pytest.raises(MeshError, match=r"not closed: 3 boundary edges"):
        mass_properties(v, f[:11])  # one triangle missing: a triangular hole


def test_allow_open_gives_the_cone_closed_volume_and_a_warning():
    a, b, c = 1.0, 2.0, 3.0
    v, f = box_mesh(a, b, c)
    p = mass_properties(v, f[:10], allow_open=True)
    # The hole (the face x = a, area b c) is closed by a pyramid to the bounding-box
    # centre, height a/2, volume b c a / 6, which is left out: V = 5 a b c / 6.
    assert p.volume == pytest.approx(5 * a * b * c / 6, rel=1e-14)
    assert any("open (4 boundary edges)" in w for w in p.warnings)


def test_inverted_mesh_is_flipped_with_a_warning():
    v, f = lumpy_mesh()
    good = mass_properties(v, f)
    p = mass_properties(v, f[:, ::-1])
    assert p.flipped and p.volume > 0
    assert any("faces inwards" in w for w in p.warnings)
    # Reversing the corners negates every integral; only the rounding differs (another
    # first corner per triangle): 1280 triangles, 1e-13 relative.
    assert p.volume == pytest.approx(good.volume, rel=1e-13)
    assert rel(p.unit_inertia, good.unit_inertia) < 1e-13
    np.testing.assert_allclose(p.centroid, good.centroid, rtol=0, atol=1e-13)
    assert any("faces inwards" in w for w in p.warnings)


def test_one_flipped_triangle_is_an_orientation_error():
    v, f = box_mesh(1.0, 2.0, 3.0)
    f = f.copy()
    f[5] = f[5, ::-1]
    # Its 3 edges are each traversed the same way by it and by its neighbour.
    with pytest.raises(MeshError, match=r"inconsistent orientation: 3 edges are traversed"):
        mass_properties(v, f)
    with pytest.raises(MeshError, match="inconsistent orientation"):
        mass_properties(v, f, allow_open=True)  # allow_open does not excuse it


def test_fin_is_a_non_manifold_error():
    v, f = box_mesh(1.0, 1.0, 1.0)
    v = np.vstack([v, [[0.5, -1.0, -1.0]]])
    f = np.vstack([f, [[0, 1, 8]]])  # a fin hanging on the edge 0-1
    with pytest.raises(MeshError, match=r"not manifold: 1 edge is shared by more than two"):
        mass_properties(v, f)
    with pytest.raises(MeshError, match="not manifold"):
        mass_properties(v, f, allow_open=True)


def test_flat_closed_mesh_has_no_volume():
    v, f = tetra_mesh(1.0, 2.0, 3.0)
    v = v.copy()
    v[3] = [0.4, 0.7, 0.0]  # all four points in the plane z = 0: closed but flat
    with pytest.raises(MeshError, match="encloses no volume"):
        mass_properties(v, f)
    assert VOLUME_RTOL < 1e-6  # a real 1 m x 1 m x 1 um foil is still accepted
    thin_v, thin_f = box_mesh(1.0, 1.0, 1e-6)
    assert mass_properties(thin_v, thin_f).volume == pytest.approx(1e-6, rel=1e-9)


def test_all_degenerate_triangles_are_an_error():
    v = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]], dtype=float)  # collinear
    _, f = tetra_mesh(1, 1, 1)
    with pytest.raises(MeshError, match="all 4 triangles are degenerate"):
        mass_properties(v, f)
    with pytest.raises(MeshError, match="all 2 triangles are degenerate"):
        mass_properties(v, np.array([[0, 0, 1], [2, 2, 2]]))


def test_repeated_vertex_triangles_are_dropped_with_a_warning():
    v, f = box_mesh(1.0, 2.0, 3.0)
    f2 = np.vstack([f, [[1, 1, 5], [3, 3, 3]]])
    p = mass_properties(v, f2)
    assert p.volume == pytest.approx(6.0, rel=1e-14)
    assert p.n_triangles == 14
    assert any("dropped 2 degenerate triangles" in w for w in p.warnings)


def test_zero_area_triangles_are_counted():
    # Put a vertex (8) in the middle of the edge 4-5 on the top side only: the top
    # triangle 4-5-6 becomes 4-8-6 and 8-5-6, leaving a T-junction that the zero-area
    # sliver 4-5-8 closes (a common CAD artefact). The mesh stays closed.
    v, f = box_mesh(1.0, 1.0, 1.0)
    v = np.vstack([v, [[0.5, 0.0, 1.0]]])
    f = [list(t) for t in f if sorted(t) not in ([4, 5, 6],)]
    f += [[4, 8, 6], [8, 5, 6], [4, 5, 8]]
    p = mass_properties(v, np.array(f))
    assert p.volume == pytest.approx(1.0, rel=1e-14)
    assert any("1 triangle has zero area" in w for w in p.warnings)


@pytest.mark.parametrize(
    ("vertices", "faces", "message"),
    [
        (np.zeros((4, 2)), [[0, 1, 2]], r"vertices must be an \(n, 3\) array"),
        (np.eye(3), [[0, 1]], r"faces must be an \(n, 3\) array"),
        (np.eye(3), np.zeros((0, 3), dtype=int), "no triangles"),
        (np.eye(3), [[0.0, 1.0, 2.0]], "face indices must be integers"),
        (np.eye(3), [[0, 1, 3]], "face index 3 is out of range"),
        (np.eye(3), [[0, -1, 2]], "face index -1 is out of range"),
        ([[0, 0, 0], [1, 0, np.nan], [0, 1, 0]], [[0, 1, 2]], "nan or infinite"),
        ([[0, 0, 0], [1, 0, np.inf], [0, 1, 0]], [[0, 1, 2]], "nan or infinite"),
    ],
)
def test_bad_arrays(vertices, faces, message):
    with pytest.raises(MeshError, match=message):
        mass_properties(vertices, faces)


def test_mesh_error_is_a_value_error():
    assert issubclass(MeshError, ValueError)


def test_to_json_is_plain_python():
    v, f = box_mesh(1.0, 2.0, 3.0)
    js = mass_properties(v, f[:, ::-1]).to_json()
    assert set(js) == {
        "volume", "area", "centroid", "unit_inertia", "n_triangles", "flipped", "warnings",
        "welded", "gap",
    }  # fmt: skip
    assert type(js["volume"]) is float and type(js["area"]) is float
    assert all(type(x) is float for x in js["centroid"])
    assert all(type(x) is float for row in js["unit_inertia"] for x in row)
    assert type(js["n_triangles"]) is int and js["flipped"] is True
    assert all(type(w) is str for w in js["warnings"]) and js["warnings"]


def test_large_mesh_is_vectorised_and_chunked():
    # More triangles than one integration block (65536): the blocks must add up.
    s = trimesh.creation.icosphere(subdivisions=6)  # 81920 triangles
    p = mass_properties(s.vertices, s.faces)
    vol, com, inertia = trimesh_props(s.vertices, s.faces)
    # Rounding only (see test_agrees_with_trimesh), ~eps x log2(F): 1e-12.
    assert p.volume == pytest.approx(vol, rel=1e-12)
    assert rel(p.unit_inertia, inertia) < 1e-12


# ----------------------------------------------------------- welding with a tolerance
# CAD exports write each triangle's corners on their own, with noise: a shared corner may
# read 0.0 in one triangle and -3.79e-33 in the next, or differ in the last float32 bit.
# The core welds (for closedness only) the ends of boundary edges closer than `weld`.


def soup(v, f):
    """Each triangle with corners of its own: (corners (3F, 3), faces (F, 3))."""
    c = np.asarray(v, dtype=float)[np.asarray(f)].reshape(-1, 3).copy()
    return c, np.arange(len(c)).reshape(-1, 3)


def exact_weld(c, faces):
    """Merge bit-identical corners (what the file readers do): an indexed mesh."""
    from rbcli.io.meshfile import weld

    u, inv = weld(c)
    return u, inv[faces]


def noisy_box(delta, every=2, size=(1.0, 2.0, 3.0)):
    """A box with a corner at the origin whose corner copies are moved by ``delta`` (x)."""
    v, f = box_mesh(*size)
    c, faces = soup(v, f)
    c[::every, 0] += delta
    return exact_weld(c, faces)


F32_ULP_AT_3 = float(np.spacing(np.float32(3.0)))  # the float32 spacing at the box's size
TOL32 = 4 * F32_ULP_AT_3  # what rbcli.io.meshfile.default_weld gives a binary STL of it
TOLTEXT = 1e-9 * math.sqrt(14.0)  # ... and a text file: 1e-9 of the diagonal


@pytest.mark.parametrize("tol", [TOL32, TOLTEXT])
def test_a_box_off_by_1e_33_is_closed(tol):
    v, f = noisy_box(-3.79e-33)  # 0.0 next to -3.79e-33, as in the CAD files of issue 14
    assert len(v) > 8  # the exact weld leaves it open ...
    with pytest.raises(MeshError, match="not closed"):
        mass_properties(v, f)
    p = mass_properties(v, f, weld=tol, unit="m")  # ... the tolerance closes it
    assert p.volume == pytest.approx(6.0, rel=1e-15) and p.welded > 0
    assert p.gap == pytest.approx(3.79e-33, rel=1e-12)
    (w,) = p.warnings
    assert w.startswith("welded ") and "largest gap closed 3.79e-33 m" in w


def test_a_box_off_by_one_float32_ulp_is_closed_at_the_binary_stl_tolerance():
    v, f = noisy_box(F32_ULP_AT_3, size=(1.0, 2.0, 3.0))
    with pytest.raises(MeshError, match="not closed"):
        mass_properties(v, f, weld=TOLTEXT)  # a text file's tolerance is far finer
    p = mass_properties(v, f, weld=TOL32)
    assert p.gap == F32_ULP_AT_3 and p.volume == pytest.approx(6.0, rel=1e-6)


@pytest.mark.parametrize("tol", [TOL32, TOLTEXT])
def test_a_box_off_by_1e_4_of_its_size_stays_open(tol):
    v, f = noisy_box(3e-4)
    with pytest.raises(MeshError, match=r"not closed: \d+ boundary edges .*after welding") as info:
        mass_properties(v, f, weld=tol, unit="m")
    assert info.value.boundary > 0
    p = mass_properties(v, f, weld=tol, allow_open=True)  # allow_open still lets it through
    assert any("open" in w for w in p.warnings)


def test_welding_never_changes_the_integrals():
    v, f = lumpy_mesh()
    c, faces = soup(v, f)
    rng = np.random.default_rng(5)
    c *= 1 + 1e-12 * rng.standard_normal(c.shape)  # every corner copy jittered
    u, g = exact_weld(c, faces)
    welded = mass_properties(u, g, weld=1e-9)
    as_given = mass_properties(u, g, allow_open=True)  # the same triangles, not welded
    assert welded.volume == as_given.volume and welded.area == as_given.area
    assert np.array_equal(welded.centroid, as_given.centroid)
    assert np.array_equal(welded.unit_inertia, as_given.unit_inertia)
    assert welded.welded == len(u) - len(v)  # every copy merged back onto one vertex


@pytest.mark.parametrize(
    ("noise", "agree"),
    # A soup whose copies of a corner differ is closed only up to those gaps: its volume
    # depends on the reference point (trimesh integrates about the origin, rbcli about
    # the box centre) by about gap x size x perimeter, so the agreement follows the noise.
    [("negative zero", 1e-13), ("denormal", 1e-13), ("tiny", 1e-13),
     ("jitter 1e-12", 1e-10), ("float32 round", 1e-5)],
)
def test_cad_style_noise_gives_trimesh_mass_properties(noise, agree):
    v, f = lumpy_mesh()
    v = v - v.min(axis=0)  # coordinates that are exactly 0.0 on three faces of the box
    v[np.abs(v) < 0.2] = 0.0  # ... and many of them
    c, faces = soup(v, f)
    rng = np.random.default_rng(11)
    pick = rng.random(len(c)) < 0.5
    zero = (c == 0.0) & pick[:, None]
    if noise == "negative zero":
        c[zero] = -0.0
    elif noise == "denormal":
        c[zero] = 5e-324 * rng.integers(1, 1000, zero.sum())
    elif noise == "tiny":
        c[zero] = rng.choice([-3.79e-33, 2.1e-40, -1e-300], zero.sum())
    elif noise == "jitter 1e-12":
        c[pick] *= 1 + 1e-12 * rng.uniform(-1, 1, (pick.sum(), 3))
    else:  # float32 rounding one way or the other, as two exporters would
        c[pick] = np.nextafter(c[pick].astype(np.float32), np.float32(np.inf)).astype(float)
    u, g = exact_weld(c, faces)
    tol = 4 * float(np.spacing(np.float32(np.abs(c).max())))
    p = mass_properties(u, g, weld=tol)
    vol, com, unit = trimesh_props(c, faces)  # trimesh integrates the soup as it is
    assert (p.welded > 0) == (noise != "negative zero")  # -0.0 == 0.0: the exact weld
    assert p.volume == pytest.approx(vol, rel=agree)
    assert rel(p.centroid, com) < 10 * agree
    assert rel(p.unit_inertia, unit) < 10 * agree


def test_weld_groups_are_order_independent_and_chains_stay_apart():
    from rbcli.core.mesh import weld_gaps

    t = 1e-6
    pts = np.array(
        [
            [0, 0, 0], [0.5e-6, 0, 0],  # a pair within t: merged
            [5, 5, 5], [5 + 0.6e-6, 5, 5], [5 + 1.2e-6, 5, 5],  # a chain over 1.2 t: apart
            [9, 9, 9], [9, 9, 9 + 2e-6],  # too far: apart
        ],
        dtype=float,
    )  # fmt: skip
    label, gap, chained = weld_gaps(pts, t)
    assert list(label) == [0, 0, 2, 3, 4, 5, 6] and gap == 0.5e-6 and chained == 1
    rng = np.random.default_rng(2)
    for _ in range(5):
        perm = rng.permutation(len(pts))
        lab, g, ch = weld_gaps(pts[perm], t)
        groups = {frozenset(perm[lab == k]) for k in np.unique(lab)}
        assert groups == {frozenset(x) for x in ({0, 1}, {2}, {3}, {4}, {5}, {6})}
        assert (g, ch) == (gap, chained)


def test_pairs_across_cell_borders_are_found():
    from rbcli.core.mesh import weld_gaps

    t = 1e-3
    rng = np.random.default_rng(4)
    a = rng.uniform(-1, 1, (300, 3))
    b = a + rng.uniform(-t, t, a.shape) * 0.999  # each within t of its partner
    label, gap, chained = weld_gaps(np.vstack([a, b]), t)
    assert chained == 0 and np.array_equal(label[:300], label[300:])
    assert gap <= t


def test_a_sliver_thinner_than_the_tolerance_is_left_out_of_the_edge_check():
    v, f = box_mesh(1.0, 1.0, 1.0)
    # The top triangle (4, 5, 6) is cut along 8-6, with 8 a hair from corner 4: a needle
    # (4, 8, 6) and (8, 5, 6). Exactly, edges 4-5, 5-8 and 8-4 are open; welded, 8 is 4,
    # the needle has no edges of its own and (8, 5, 6) is (4, 5, 6) again.
    v = np.vstack([v, v[4] + [1e-12, 0, 0]])
    f = [list(t) for t in f if list(t) != [4, 5, 6]] + [[8, 5, 6], [4, 8, 6]]
    with pytest.raises(MeshError, match="not closed: 3 boundary edges"):
        mass_properties(v, np.array(f))
    p = mass_properties(v, np.array(f), weld=1e-9, unit="m")
    assert p.volume == pytest.approx(1.0, rel=1e-11) and p.welded == 1
    (w,) = p.warnings
    assert "1 triangle narrower than the tolerance left out of the closedness check" in w


def test_a_tolerance_far_too_large_is_refused():
    v, f = noisy_box(1e-3)
    with pytest.raises(MeshError, match=r"weld tolerance 10 m is too large for a mesh of size 3 m"):
        mass_properties(v, f, weld=10.0, unit="m")  # it would fold the box into a point
    from rbcli.core.mesh import weld_gaps

    crowd = np.random.default_rng(1).uniform(0, 1e-6, (100, 3))
    with pytest.raises(MeshError, match="far too large for this mesh: more than 64"):
        weld_gaps(crowd, 1e-6)
