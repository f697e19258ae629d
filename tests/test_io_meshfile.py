"""Tests of rbcli.io.meshfile: STL (binary, ASCII) and OBJ readers, welding, errors.

Files are written by small writers here (and by trimesh's exporters, an independent
oracle) to tmp_path and read back; volumes come from the source arrays.
"""

from __future__ import annotations

import os
import pathlib

import numpy as np
import pytest
import trimesh

from rbcli.core.mesh import mass_properties
from rbcli.io.meshfile import SUFFIXES, MeshFileError, read_mesh, weld
from rbcli.io.reader import ReadError

# ---------------------------------------------------------------------------- writers


def write_binary_stl(path, vertices, faces, header=b"rbcli test", count=None, cut=0):
    tri = np.asarray(vertices, dtype=np.float64)[np.asarray(faces)]
    rec = np.zeros(
        len(tri), dtype=[("n", "<f4", (3,)), ("v", "<f4", (3, 3)), ("a", "<u2")]
    )
    rec["v"] = tri
    data = header.ljust(80, b" ")[:80]
    data += np.uint32(len(tri) if count is None else count).tobytes()
    data += rec.tobytes()
    pathlib.Path(path).write_bytes(data[: len(data) - cut] if cut else data)
    return path


def num(x) -> str:
    return repr(float(x))  # shortest string that round-trips the float64


def write_ascii_stl(path, vertices, faces, name="part", upper=False):
    tri = np.asarray(vertices, dtype=np.float64)[np.asarray(faces)]
    lines = [f"solid {name}"]
    for t in tri:
        with np.errstate(invalid="ignore"):
            n = np.cross(t[1] - t[0], t[2] - t[0])
        lines.append(f"  facet normal {num(n[0])} {num(n[1])} {num(n[2])}")
        lines.append("    outer loop")
        for p in t:
            lines.append(f"      vertex {num(p[0])} {num(p[1])} {num(p[2])}")
        lines.append("    endloop")
        lines.append("  endfacet")
    lines.append(f"endsolid {name}")
    text = "\n".join(lines) + "\n"
    pathlib.Path(path).write_text(text.upper() if upper else text)
    return path


def box_arrays(a=1.0, b=2.0, c=3.0):
    m = trimesh.creation.box(extents=[a, b, c])
    return np.asarray(m.vertices), np.asarray(m.faces)


def sphere_arrays():
    m = trimesh.creation.icosphere(subdivisions=3, radius=0.7)
    return np.asarray(m.vertices) + [0.1, -0.2, 0.3], np.asarray(m.faces)


def volume(v, f):
    return mass_properties(v, f).volume


def same_triangles(v1, f1, v2, f2):
    """Same triangles (same corner order) regardless of the vertex numbering."""
    return np.array_equal(np.asarray(v1)[f1], np.asarray(v2)[f2])


# --------------------------------------------------------------------------------- STL


def test_binary_stl_round_trip(tmp_path):
    v, f = sphere_arrays()
    path = write_binary_stl(tmp_path / "s.stl", v, f)
    rv, rf, *_ = read_mesh(path)
    assert rv.dtype == np.float64 and rf.dtype == np.int64
    assert rv.shape == v.shape and rf.shape == f.shape  # welded back to 642 vertices
    v32 = v.astype(np.float32).astype(np.float64)  # what the file holds
    assert same_triangles(v32, f, rv, rf)
    # Exactly the source triangles (float32-rounded), in the same order: the same sums,
    # so the volume agrees to rounding (1e-13); the rounding to float32 itself moves the
    # volume by ~1e-7 relative.
    assert volume(rv, rf) == pytest.approx(volume(v32, f), rel=1e-13)
    assert volume(rv, rf) == pytest.approx(volume(v, f), rel=1e-6)


def test_binary_stl_whose_header_starts_with_solid(tmp_path):
    v, f = box_arrays()
    path = write_binary_stl(tmp_path / "b.stl", v, f, header=b"solid exported by some CAD")
    rv, rf, *_ = read_mesh(path)
    assert len(rv) == 8 and len(rf) == 12
    assert volume(rv, rf) == pytest.approx(6.0, rel=1e-14)  # exact small numbers


def test_uppercase_extension_and_pathlike(tmp_path):
    v, f = box_arrays()
    path = write_binary_stl(tmp_path / "B.STL", v, f)
    rv, rf, *_ = read_mesh(pathlib.Path(path))
    assert volume(rv, rf) == pytest.approx(6.0, rel=1e-14)


def test_ascii_stl_round_trip(tmp_path):
    v, f = sphere_arrays()
    path = write_ascii_stl(tmp_path / "s.stl", v, f)
    rv, rf, *_ = read_mesh(str(path))
    # repr() round-trips float64 exactly: the very same triangles, the same volume.
    assert rv.shape == v.shape and same_triangles(v, f, rv, rf)
    assert volume(rv, rf) == pytest.approx(volume(v, f), rel=1e-13)


def test_ascii_stl_upper_case_and_several_solids(tmp_path):
    v, f = box_arrays()
    one = write_ascii_stl(tmp_path / "a.stl", v, f[:6], name="first part", upper=True)
    two = write_ascii_stl(tmp_path / "b.stl", v, f[6:], name="second")
    both = tmp_path / "both.stl"
    both.write_bytes(one.read_bytes() + two.read_bytes())
    rv, rf, *_ = read_mesh(both)
    assert len(rf) == 12 and volume(rv, rf) == pytest.approx(6.0, rel=1e-14)


def test_trimesh_exports_read_back(tmp_path):
    # trimesh's own writers, an independent implementation of the formats.
    m = trimesh.creation.torus(1.0, 0.3)
    expected = m.volume
    for name, kind in (("t_bin.stl", "stl"), ("t_asc.stl", "stl_ascii"), ("t.obj", "obj")):
        path = tmp_path / name
        m.export(path, file_type=kind)
        rv, rf, *_ = read_mesh(path)
        # binary STL holds float32 (1e-7 relative); the text formats hold ~8+ digits.
        assert volume(rv, rf) == pytest.approx(expected, rel=1e-6), name


def test_negative_zero_is_welded_to_zero(tmp_path):
    v, f = box_arrays()
    v = v - v.min(axis=0)  # corner at the origin: coordinates 0.0
    tri = v[f]
    tri[::2][tri[::2] == 0.0] = -0.0  # every other triangle writes -0.0
    corners = tri.reshape(-1, 3)
    assert np.signbit(corners).any()
    vv = np.arange(len(corners)).reshape(-1, 3)
    path = write_binary_stl(tmp_path / "z.stl", corners, vv)
    rv, rf, *_ = read_mesh(path)
    assert len(rv) == 8  # -0.0 and 0.0 are one vertex, so the box is closed
    assert volume(rv, rf) == pytest.approx(6.0, rel=1e-14)


def test_truncated_binary_stl(tmp_path):
    v, f = box_arrays()
    path = write_binary_stl(tmp_path / "t.stl", v, f, cut=25)
    with pytest.raises(
        MeshFileError, match=r"t\.stl: truncated or corrupt binary stl: header says 12 triangles"
    ) as info:
        read_mesh(path)
    assert "holds 11.5" in str(info.value)


def test_binary_stl_count_larger_than_file(tmp_path):
    v, f = box_arrays()
    path = write_binary_stl(tmp_path / "c.stl", v, f, count=1000)
    with pytest.raises(MeshFileError, match="header says 1000 triangles"):
        read_mesh(path)


def test_binary_stl_with_no_triangles(tmp_path):
    path = write_binary_stl(tmp_path / "e.stl", np.zeros((3, 3)), np.zeros((0, 3), dtype=int))
    with pytest.raises(MeshFileError, match="0 triangles"):
        read_mesh(path)


def test_garbage_bytes(tmp_path):
    path = tmp_path / "g.stl"
    path.write_bytes(np.random.default_rng(1).integers(0, 256, 1000, dtype=np.uint8).tobytes())
    with pytest.raises(MeshFileError, match="g.stl: truncated or corrupt binary stl"):
        read_mesh(path)
    short = tmp_path / "short.stl"
    short.write_bytes(b"\x00\x01garbage")
    with pytest.raises(MeshFileError, match="not an stl file"):
        read_mesh(short)


def test_empty_file(tmp_path):
    for name in ("e.stl", "e.obj"):
        path = tmp_path / name
        path.write_bytes(b"")
        with pytest.raises(MeshFileError, match="empty file"):
            read_mesh(path)


def test_nan_vertex_in_binary_stl(tmp_path):
    v, f = box_arrays()
    v = v.copy()
    v[3, 1] = np.nan
    path = write_binary_stl(tmp_path / "n.stl", v, f)
    with pytest.raises(MeshFileError, match="non-finite coordinate"):
        read_mesh(path)


def test_inf_vertex_in_ascii_stl(tmp_path):
    v, f = box_arrays()
    v = v.copy()
    v[0, 0] = np.inf
    path = write_ascii_stl(tmp_path / "i.stl", v, f)
    with pytest.raises(MeshFileError, match="non-finite coordinate"):
        read_mesh(path)


def test_malformed_ascii_stl_names_the_line(tmp_path):
    v, f = box_arrays()
    good = write_ascii_stl(tmp_path / "good.stl", v, f).read_text().splitlines()
    # good[0] is line 1 'solid'; facet k (from 0) is good[1 + 7k : 8 + 7k]: 'facet
    # normal', 'outer loop', three 'vertex', 'endloop', 'endfacet'. good[i] is line i + 1.
    bad = list(good)
    bad[7 + 3] = "      vertx 0 0 0"  # facet 1, first vertex (line 11)
    path = tmp_path / "bad.stl"
    path.write_text("\n".join(bad) + "\n")
    with pytest.raises(MeshFileError, match=r"bad\.stl:11: malformed ascii stl: expected 'vertex'"):
        read_mesh(path)
    bad = list(good)
    bad[7 + 4] = "      vertex 0 1.2.3 0"  # facet 1, second vertex (line 12)
    path.write_text("\n".join(bad) + "\n")
    with pytest.raises(MeshFileError, match=r"bad\.stl:12: .*'1\.2\.3' is not a number"):
        read_mesh(path)
    bad = list(good)
    del bad[7 + 6]  # facet 1 loses its 'endloop' (line 14): 'endfacet' moves up to 14
    path.write_text("\n".join(bad) + "\n")
    with pytest.raises(
        MeshFileError,
        match=r"bad\.stl:14: malformed ascii stl: expected 'endloop', found 'endfacet'",
    ):
        read_mesh(path)


def test_ascii_stl_without_endsolid(tmp_path):
    v, f = box_arrays()
    lines = write_ascii_stl(tmp_path / "x.stl", v, f).read_text().splitlines()
    path = tmp_path / "cut.stl"
    path.write_text("\n".join(lines[:-1]) + "\n")
    with pytest.raises(MeshFileError, match="without 'endsolid'"):
        read_mesh(path)
    path.write_text("\n".join(lines[:-3]) + "\n" + lines[-1] + "\n")
    with pytest.raises(MeshFileError, match="incomplete facet"):
        read_mesh(path)


def test_ascii_stl_without_facets(tmp_path):
    path = tmp_path / "none.stl"
    path.write_text("solid nothing\nendsolid nothing\n")
    with pytest.raises(MeshFileError, match="without facets"):
        read_mesh(path)


# --------------------------------------------------------------------------------- OBJ

UNIT_CUBE_OBJ = """\
# a unit cube from quads, with every face-index form
mtllib cube.mtl
o cube
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1 1.0
v 1 0 1
v 1 1 1
v 0 1 1
vt 0 0
vt 1 0
vt 1 1
vn 0 0 1
g sides
usemtl steel
s off
f 1 4 3 2
f 5/1 6/2 7/3 8/1
f 1/1/1 2/2/1 6/3/1 5/1/1
f 4//1 8//1 7//1 3//1
f -8 -4 -1 -5
f 2 3 7 6  # a trailing comment
"""


def test_obj_quads_and_every_index_form(tmp_path):
    path = tmp_path / "cube.obj"
    path.write_text(UNIT_CUBE_OBJ)
    rv, rf, *_ = read_mesh(path)
    assert len(rf) == 12  # 6 quads fanned into 2 triangles each
    p = mass_properties(rv, rf)
    # exact small numbers: volume 1, inertia diag 1/6 per unit mass
    assert p.volume == pytest.approx(1.0, rel=1e-14) and not p.flipped
    np.testing.assert_allclose(p.unit_inertia, np.eye(3) / 6, atol=1e-15)


def test_obj_negative_indices_are_relative(tmp_path):
    # Each triangle refers to the three vertices written just before it.
    v, f = box_arrays()
    lines = []
    for t in f:
        for i in t:
            lines.append("v " + " ".join(num(x) for x in v[i]))
        lines.append("f -3 -2 -1")
    path = tmp_path / "rel.obj"
    path.write_text("\n".join(lines) + "\n")
    rv, rf, *_ = read_mesh(path)
    assert len(rv) == 8  # duplicated positions welded
    assert volume(rv, rf) == pytest.approx(6.0, rel=1e-14)


def test_obj_polygon_fan(tmp_path):
    # A hexagonal prism written with two hexagon faces and six quads.
    n, r, h = 6, 1.0, 2.0
    ang = 2 * np.pi * np.arange(n) / n
    ring = np.c_[r * np.cos(ang), r * np.sin(ang)]
    lines = [f"v {num(x)} {num(y)} 0" for x, y in ring]
    lines += [f"v {num(x)} {num(y)} {h}" for x, y in ring]
    lines.append("f " + " ".join(str(i + 1) for i in reversed(range(n))))  # bottom, -z
    lines.append("f " + " ".join(str(n + i + 1) for i in range(n)))  # top, +z
    for i in range(n):
        j = (i + 1) % n
        lines.append(f"f {i + 1} {j + 1} {n + j + 1} {n + i + 1}")
    path = tmp_path / "hex.obj"
    path.write_text("\n".join(lines) + "\n")
    rv, rf, *_ = read_mesh(path)
    assert len(rf) == 2 * (n - 2) + 2 * n
    # Regular hexagon of circumradius r: area 3√3 r²/2; cos/sin rounding: 1e-14.
    assert volume(rv, rf) == pytest.approx(3 * np.sqrt(3) / 2 * r * r * h, rel=1e-14)


def test_obj_index_out_of_range_names_the_line(tmp_path):
    path = tmp_path / "bad.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 3\nf 1 2 9\n")
    with pytest.raises(MeshFileError, match=r"bad\.obj:6: face index 9 is out of range"):
        read_mesh(path)
    path.write_text("v 0 0 0\nv 1 0 0\nf 1 2 -3\nv 0 1 0\n")
    with pytest.raises(MeshFileError, match=r"bad\.obj:3: face index -3 is out of range"):
        read_mesh(path)
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n")
    with pytest.raises(MeshFileError, match=r"bad\.obj:4: face index 0"):
        read_mesh(path)


def test_obj_malformed_lines(tmp_path):
    path = tmp_path / "bad.obj"
    cases = [
        ("v 0 0\nf 1 2 3\n", r":1: vertex line needs x y z"),
        ("v 0 0\n", r"obj file without faces"),  # no face line: refused before the numbers
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", r":4: face needs at least 3 vertices"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", r":4: bad face index 'x'"),
        ("v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n", r":2: 'zero' is not a number"),
        ("v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n", r":2: vertex has a non-finite coordinate"),
        ("# only a comment\nv 0 0 0\n", r"obj file without faces"),
    ]
    for text, message in cases:
        path.write_text(text)
        with pytest.raises(MeshFileError, match=message):
            read_mesh(path)


# ------------------------------------------------------------------- files and welding


def test_unknown_extension_lists_the_allowed_ones(tmp_path):
    path = tmp_path / "part.ply"
    path.write_text("ply\n")
    expected = r"part\.ply: unknown mesh file type \('\.ply'\); use one of \.stl, \.obj"
    with pytest.raises(MeshFileError, match=expected):
        read_mesh(path)
    with pytest.raises(MeshFileError, match="no extension"):
        read_mesh(tmp_path / "noext")
    assert SUFFIXES == (".stl", ".obj")


def test_directory_and_missing_file(tmp_path):
    d = tmp_path / "dir.stl"
    d.mkdir()
    # the reader's errors: an InputError and the OSError open() would raise
    with pytest.raises(IsADirectoryError, match=r"dir\.stl: is a directory"):
        read_mesh(d)
    with pytest.raises(FileNotFoundError, match=r"no such file: .*missing\.obj"):
        read_mesh(tmp_path / "missing.obj")


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0, reason="root reads anything")
def test_unreadable_file(tmp_path):
    path = write_binary_stl(tmp_path / "locked.stl", *box_arrays())
    path.chmod(0)
    try:
        with pytest.raises(PermissionError, match="permission denied"):
            read_mesh(path)
    finally:
        path.chmod(0o644)


@pytest.mark.parametrize(
    ("exc", "message"),
    [
        (PermissionError(13, "Permission denied"), "cannot read the file: permission denied"),
        (OSError(5, "Input/output error"), "cannot read the file: input/output error"),
    ],
)
def test_os_errors_become_read_errors(tmp_path, monkeypatch, exc, message):
    # Works as root too (where chmod 0 does not stop reading): the reader's open fails.
    import rbcli.io.reader as reader

    def failing_open(*args, **kwargs):
        raise exc

    path = write_binary_stl(tmp_path / "p.stl", *box_arrays())
    monkeypatch.setattr(reader.os, "open", failing_open)
    with pytest.raises(reader.ReadError, match=rf"p\.stl: {message}"):
        read_mesh(path)


def test_mesh_file_error_is_a_value_error_and_keeps_the_line(tmp_path):
    path = tmp_path / "bad.obj"
    path.write_text("v 0 0 0\nf 1 2 3\n")
    with pytest.raises(ValueError) as info:
        read_mesh(path)
    err = info.value
    assert isinstance(err, MeshFileError)
    assert err.path == str(path) and err.line == 2
    assert err.reason == err.reason.lower()


def test_weld_merges_exact_duplicates_only():
    rng = np.random.default_rng(3)
    base = rng.normal(size=(50, 3))
    idx = rng.integers(0, 50, 400)
    pts = base[idx].copy()
    pts[0] = np.nextafter(pts[0], np.inf)  # one ulp away: a different point
    for dtype in (np.float64, np.float32):
        p = pts.astype(dtype)
        unique, inverse = weld(p)
        assert unique.dtype == np.float64
        np.testing.assert_array_equal(unique[inverse], p.astype(np.float64))
        expected = len(np.unique(p, axis=0))  # numpy's own (slower) answer
        assert len(unique) == expected


def test_weld_is_exact_even_when_every_hash_collides(monkeypatch):
    import rbcli.io.meshweld as meshweld

    rng = np.random.default_rng(8)
    pts = rng.normal(size=(40, 3))[rng.integers(0, 40, 300)]
    good_u, good_inv = weld(pts)
    monkeypatch.setattr(meshweld, "_MIX", (np.uint64(0),) * 3)  # every key the same
    u, inv = weld(pts)
    assert len(u) == len(good_u) == len(np.unique(pts, axis=0))
    np.testing.assert_array_equal(u[inv], pts)


# ------------------------------------------------ fast readers = line readers, bit for bit


def _fast_and_slow_stl(path):
    import rbcli.io.meshstl as meshstl

    data = pathlib.Path(path).read_bytes()
    with open(path, "rb") as fh:
        fast = meshstl._read_stl_ascii_fast(fh, len(data))
    if fast is not None:  # (each block's distinct corners, which one each corner is)
        points, inverse = fast
        fast = points[inverse]
    return fast, meshstl._read_stl_ascii(str(path), data)


def _fast_and_slow_obj(path):
    import rbcli.io.meshobj as meshobj

    data = pathlib.Path(path).read_bytes()
    return meshobj._read_obj_fast(data), meshobj._read_obj_lines(str(path), data)


def bits(a):
    return np.ascontiguousarray(a, dtype=np.float64).view(np.uint64)


def test_fast_ascii_stl_reader_gives_the_line_readers_bits(tmp_path, monkeypatch):
    import rbcli.io.meshstl as meshstl

    monkeypatch.setattr(meshstl, "_CHUNK", 1000)  # many blocks, cut at facet ends
    v, f = sphere_arrays()
    v = v * np.random.default_rng(1).lognormal(0, 3, v.shape)  # digits of every size
    files = [write_ascii_stl(tmp_path / "a.stl", v, f)]
    files.append(write_ascii_stl(tmp_path / "b.stl", v, f, upper=True))
    crlf = tmp_path / "c.stl"
    crlf.write_bytes(files[0].read_bytes().replace(b"\n", b"\r\n"))
    files.append(crlf)
    m = trimesh.creation.torus(1.0, 0.3)
    m.export(tmp_path / "t.stl", file_type="stl_ascii")
    files.append(tmp_path / "t.stl")
    for path in files:
        fast, slow = _fast_and_slow_stl(path)
        assert fast is not None, path
        assert np.array_equal(bits(fast), bits(slow)), path


@pytest.mark.parametrize("block", [1 << 24, 300])  # one block; many, cut between lines
def test_fast_obj_reader_gives_the_line_readers_bits(tmp_path, monkeypatch, block):
    import rbcli.io.meshobj as meshobj

    monkeypatch.setattr(meshobj, "_CHUNK", block)
    v, f = sphere_arrays()
    v = v * np.random.default_rng(2).lognormal(0, 3, v.shape)
    lines = ["# made here", "o part", "mtllib x.mtl"]
    lines += [f"v {num(x)} {num(y)} {num(z)}" for x, y, z in v]
    lines += ["vt 0.5 0.5", "vn 0 0 1", "s off"]
    forms = ["{}", "{}/1", "{}//1", "{}/1/1"]
    for k, t in enumerate(f):
        items = [forms[(k + j) % 4].format(i + 1) for j, i in enumerate(t)]
        if k % 3 == 0:
            items = [str(i - len(v)) for i in t]  # negative: relative to the end
        lines.append("f " + " ".join(items) + (" # a comment" if k % 5 == 0 else ""))
    text = "\n".join(lines) + "\n"
    quads = tmp_path / "q.obj"
    quads.write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4\nf 1\t2 5\n")
    cont = tmp_path / "cont.obj"
    cont.write_text(text.replace("\nf ", "\nf \\\n ", 7))
    paths = [tmp_path / "p.obj", tmp_path / "crlf.obj", quads, cont]
    paths[0].write_text(text)
    paths[1].write_bytes(text.encode().replace(b"\n", b"\r\n"))
    for path in paths:
        fast, slow = _fast_and_slow_obj(path)
        assert fast is not None, path
        assert np.array_equal(bits(fast[0]), bits(slow[0])), path
        assert np.array_equal(fast[1], slow[1]), path


@pytest.mark.parametrize(
    "text",
    [
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv\nf 1 2 3\n",  # a bare v: an error for the line reader
        "v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n",  # w: the line reader takes x y z
        "  v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",  # indented
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1_0\n",  # int() reads 1_0; np.fromstring does not
    ],
)
def test_what_the_fast_obj_reader_does_not_take_goes_to_the_line_reader(tmp_path, text):
    import rbcli.io.meshobj as meshobj

    assert meshobj._read_obj_fast(text.encode()) is None


def test_obj_line_continuation(tmp_path):
    v, f = box_arrays()
    lines = [f"v {num(x)} \\\n  {num(y)} {num(z)}" for x, y, z in v]
    lines += [f"f {a + 1} {b + 1} \\\n{c + 1}" for a, b, c in f]
    path = tmp_path / "c.obj"
    path.write_text("\n".join(lines) + "\n")
    rv, rf, *_ = read_mesh(path)
    assert volume(rv, rf) == pytest.approx(6.0, rel=1e-14)
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 \\\n 2 \\\n 3\nf 1 2 \\\n x\n")
    with pytest.raises(MeshFileError, match=r"c\.obj:7: bad face index 'x'"):
        read_mesh(path)  # the line where the continued line starts


def test_a_huge_obj_face_index_is_a_located_message(tmp_path):
    path = tmp_path / "big.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 1" + "0" * 23 + "\n")
    with pytest.raises(MeshFileError) as info:
        read_mesh(path)
    assert str(info.value) == (f"{path}:6: face index {10**23} is out of range "
                               "(the file has 4 vertices)")  # not "a value is too large"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 " + "9" * 100 + "\n")
    with pytest.raises(MeshFileError, match=r"big\.obj:4: face index 9{24}… \(100 characters\) is out"):
        read_mesh(path)


# ------------------------------------------------------- what is read, and how much


def test_a_fifo_is_refused_without_waiting(tmp_path):
    fifo = tmp_path / "pipe.stl"
    os.mkfifo(fifo)
    with pytest.raises(ReadError, match=r"pipe\.stl: is a FIFO \(named pipe\), not a regular file"):
        read_mesh(fifo)


def test_a_device_is_refused(tmp_path):
    link = tmp_path / "null.obj"
    link.symlink_to("/dev/null")
    with pytest.raises(ReadError, match=r"null\.obj: is a device, not a regular file"):
        read_mesh(link)


def test_a_large_sparse_file_is_refused_before_it_is_read(tmp_path, monkeypatch):
    from rbcli.io.meshfile import MAX_MESH_BYTES

    path = tmp_path / "huge.stl"
    with open(path, "wb") as fh:
        fh.truncate(2 << 30)  # 2 GiB of holes: no disk used
    with pytest.raises(ReadError, match=r"huge\.stl: is 2147483648 bytes; mesh files are limited to "
                       r"1 GiB \(set RBCLI_MAX_MESH_BYTES to raise it\)"):
        read_mesh(path)
    assert MAX_MESH_BYTES == 1 << 30
    small = write_binary_stl(tmp_path / "box.stl", *box_arrays())
    monkeypatch.setenv("RBCLI_MAX_MESH_BYTES", "500")
    with pytest.raises(ReadError, match=r"mesh files are limited to 500 bytes"):
        read_mesh(small)
    monkeypatch.setenv("RBCLI_MAX_MESH_BYTES", "1k")
    assert len(read_mesh(small).faces) == 12
    assert len(read_mesh(small, max_bytes=684).faces) == 12
    monkeypatch.setenv("RBCLI_MAX_MESH_BYTES", "lots")
    with pytest.raises(MeshFileError, match="RBCLI_MAX_MESH_BYTES must be a number of bytes"):
        read_mesh(small)


def test_a_nul_in_the_file_name_is_a_clear_message():
    with pytest.raises(ReadError, match=r"a\\0b\.stl: the file name contains a NUL character"):
        read_mesh("a\0b.stl")


def test_default_weld_follows_the_files_precision():
    from rbcli.io.meshfile import default_weld

    v = np.array([[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [0.0, 4.0, 0.0]])
    assert default_weld("binary stl", v) == 4 * float(np.spacing(np.float32(4.0)))  # 4 ulps
    assert default_weld("obj", v) == pytest.approx(5e-9)  # 1e-9 of the 5 m diagonal
    far = v + 1e9  # text coordinates far out: at least 4 float64 ulps there
    assert default_weld("ascii stl", far) == 4 * float(np.spacing(1e9 + 4))
    assert default_weld("obj", np.zeros((3, 3))) == 0.0
    path_kinds = {"binary stl", "ascii stl", "obj"}
    assert path_kinds  # the formats read_mesh reports
