"""``shape: mesh`` parts through the body loader and the command line.

The meshes are built here (boxes, a lumpy icosphere, tetrahedra) and written by this
file's own writers (binary STL with numpy records, ASCII STL and OBJ as text), never by
rbcli. Expected values come from closed forms worked here (box, cylinder, the example's
chamfered block by "square minus corner triangles"), from the same body written with the
primitive ``box``, from scipy rotations, or from trimesh on the same arrays — not from
rbcli's own output.

Most cases run in-process (the loader, or the ``cli`` fixture: ``rbcli.cli.main`` with its
exit status and standard error); a few run as a real process (``cli_proc``) to see the exit
status and a one-line message without a traceback.
"""

from __future__ import annotations

import json
import math
import os
import re
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from rbcli.core.inertia import combine
from rbcli.body.model import load_body

ROOT = Path(__file__).resolve().parent.parent
EX = ROOT / "examples"
MM = 1e-3

# ---------------------------------------------------------------------------- meshes


def box_mesh(a: float, b: float, c: float) -> tuple[np.ndarray, np.ndarray, list[list[int]]]:
    """A box a x b x c centred at the origin: vertices, outward triangles, outward quads."""
    V = np.array([[x, y, z] for x in (-a / 2, a / 2) for y in (-b / 2, b / 2) for z in (-c / 2, c / 2)])
    quads = []
    for k in range(3):  # the face at coordinate k = -/+
        i, j = [m for m in range(3) if m != k]
        for side in (0, 1):
            corner = []
            for bi, bj in ((0, 0), (1, 0), (1, 1), (0, 1)):  # around the face
                bits = [0, 0, 0]
                bits[k], bits[i], bits[j] = side, bi, bj
                corner.append(4 * bits[0] + 2 * bits[1] + bits[2])
            n = np.cross(V[corner[1]] - V[corner[0]], V[corner[2]] - V[corner[0]])
            if n @ V[corner].mean(axis=0) < 0:  # convex, centred: outward = away from 0
                corner.reverse()
            quads.append(corner)
    F = np.array([t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))])
    return V, F, quads


def lumpy_mesh() -> tuple[np.ndarray, np.ndarray]:
    """An asymmetric closed mesh (320 triangles): a stretched, dented icosphere, off-centre."""
    import trimesh

    m = trimesh.creation.icosphere(subdivisions=2, radius=1.0)
    rng = np.random.default_rng(7)
    v = m.vertices * (1 + 0.15 * rng.standard_normal(len(m.vertices)))[:, None]  # radial dents
    v = v * [0.30, 0.18, 0.11] + [0.02, -0.01, 0.03]
    return np.asarray(v, dtype=float), np.asarray(m.faces, dtype=np.int64)


def outward_tetra(V: np.ndarray, idx: tuple[int, int, int, int]) -> list[tuple[int, int, int]]:
    """The four faces of the tetrahedron V[idx], each counter-clockwise seen from outside."""
    centre = V[list(idx)].mean(axis=0)
    faces = []
    for k in range(4):
        f = [i for j, i in enumerate(idx) if j != k]
        n = np.cross(V[f[1]] - V[f[0]], V[f[2]] - V[f[0]])
        faces.append(tuple(f) if n @ (V[f[0]] - centre) > 0 else (f[0], f[2], f[1]))
    return faces


def write_stl_binary(path: Path, V: np.ndarray, F: np.ndarray) -> Path:
    rec = np.zeros(len(F), dtype=[("n", "<f4", (3,)), ("v", "<f4", (3, 3)), ("attr", "<u2")])
    rec["v"] = V[F]
    path.write_bytes(b"test mesh".ljust(80, b"\0") + np.uint32(len(F)).tobytes() + rec.tobytes())
    return path


def write_stl_ascii(path: Path, V: np.ndarray, F: np.ndarray) -> Path:
    lines = ["solid test"]
    for t in F:
        lines += ["  facet normal 0 0 0", "    outer loop"]
        lines += ["      vertex " + " ".join(repr(float(x)) for x in V[i]) for i in t]
        lines += ["    endloop", "  endfacet"]
    lines.append("endsolid test")
    path.write_text("\n".join(lines) + "\n")
    return path


def write_obj(path: Path, V: np.ndarray, faces) -> Path:
    lines = ["# test mesh"] + ["v " + " ".join(repr(float(x)) for x in row) for row in V]
    lines += ["f " + " ".join(str(int(i) + 1) for i in f) for f in faces]
    path.write_text("\n".join(lines) + "\n")
    return path


def body_file(tmp: Path, parts: str, name: str = "body.yaml", header: str = "") -> Path:
    p = tmp / name
    p.write_text(f"{header}name: test\nparts:\n{parts}")
    return p


def mesh_part(file: str, extra: str = "density: 1000", name: str = "housing") -> str:
    lines = [f"  - name: {name}", "    shape: mesh", f"    file: {file}"]
    lines += [f"    {x.strip()}" for x in extra.split("\n") if x.strip()]
    return "\n".join(lines) + "\n"


def mp_of(path: Path):
    body = load_body(str(path))
    return body, combine(body.parts)


def rel_err(a, b) -> float:
    a, b = np.asarray(a, float), np.asarray(b, float)
    return float(np.abs(a - b).max() / np.abs(b).max())


def js(cli, *args: str) -> dict:
    """``rbcli ARGS --json`` through the ``cli`` fixture: its JSON, after exit status 0 (an
    error, internal (70) or of input (2), fails here with its message)."""
    r = cli(*args, "--json")
    assert r.code == 0, r.err
    return r.json()


def table(cli, *args: str) -> str:
    """``rbcli ARGS`` through the ``cli`` fixture: its table, after exit status 0."""
    r = cli(*args)
    assert r.code == 0, r.err
    return r.out


# Box sides exact in float32 (binary STL stores float32): only float64 round-off is left.
A, B, C = 0.5, 0.25, 0.125
RHO = 7850.0


def box_closed_form(m: float, a: float, b: float, c: float) -> np.ndarray:
    return m / 12 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])


# ---------------------------------------------------------------------------- mesh = box


@pytest.mark.parametrize("fmt", ["stl-binary", "stl-ascii", "obj-quads", "obj-triangles"])
def test_a_mesh_box_is_the_primitive_box(tmp_path, fmt):
    V, F, quads = box_mesh(A, B, C)
    file = {
        "stl-binary": lambda: write_stl_binary(tmp_path / "box.stl", V, F),
        "stl-ascii": lambda: write_stl_ascii(tmp_path / "box.stl", V, F),
        "obj-quads": lambda: write_obj(tmp_path / "box.obj", V, quads),  # fanned by the reader
        "obj-triangles": lambda: write_obj(tmp_path / "box.OBJ", V, F),
    }[fmt]()
    place = "at: [1, -2, 0.5]\nrotate: {axis: [1, 2, 3], angle: 35}"
    mesh = body_file(tmp_path, mesh_part(file.name, f"density: {RHO}\n{place}"), "mesh.yaml")
    prim = body_file(tmp_path, f"  - shape: box\n    size: [{A}, {B}, {C}]\n    density: {RHO}\n"
                     + "".join(f"    {x}\n" for x in place.split("\n")), "prim.yaml")
    bm, m1 = mp_of(mesh)
    _, m2 = mp_of(prim)
    # the same solid: ~100 float64 operations on O(1) numbers on each side -> 1e-13
    assert m1.mass == pytest.approx(RHO * A * B * C, rel=1e-13)
    np.testing.assert_allclose(m1.com, m2.com, rtol=1e-13, atol=1e-14)
    assert rel_err(m1.inertia_com, m2.inertia_com) < 1e-13
    assert bm.parts[0].extra == {
        "volume": pytest.approx(A * B * C, rel=1e-14),
        "area": pytest.approx(2 * (A * B + B * C + C * A), rel=1e-14),
        "triangles": 12,  # six quads fanned into two triangles each
    }
    assert bm.warnings == ()


def test_inertia_and_principal_report_volume_and_area_of_the_mesh_part(tmp_path, cli):
    V, F, _ = box_mesh(A, B, C)
    write_stl_binary(tmp_path / "box.stl", V, F)
    parts = mesh_part("box.stl", f"density: {RHO}") + "  - name: lug\n    shape: point\n    mass: 1\n    at: [1, 0, 0]\n"
    f = str(body_file(tmp_path, parts))
    vol, area = A * B * C, 2 * (A * B + B * C + C * A)
    for cmd in ("inertia", "principal"):
        j = js(cli, cmd, f)
        mesh_row, point_row = j["parts"]
        assert mesh_row["name"] == "housing" and mesh_row["shape"] == "mesh"
        # sums of 12 products of exact binary fractions: round-off only
        assert mesh_row["volume"] == pytest.approx(vol, rel=1e-14)
        assert mesh_row["area"] == pytest.approx(area, rel=1e-14)
        assert mesh_row["triangles"] == 12
        assert mesh_row["mass"] == pytest.approx(RHO * vol, rel=1e-14)
        assert not {"volume", "area", "triangles"} & set(point_row)
    # the SPEC keys still lead, unrenamed
    assert list(js(cli, "principal", f))[:5] == ["reference", "moments", "axes", "symmetry", "stable"]
    assert list(js(cli, "inertia", f))[:5] == ["mass", "com", "reference", "inertia", "inertia_com"]
    # tables: volume and area columns, in SI and in the display units asked for
    for cmd in ("inertia", "principal"):
        out = table(cli, cmd, f)
        assert "volume [m³]" in out and "area [m²]" in out and "triangles" in out
        assert "0.015625" in out and "0.4375" in out  # V = 1/64 m^3, A = 7/16 m^2, exact
        mm = table(cli, cmd, f, "--units", "mm,g")
        assert "volume [mm³]" in mm and "1.5625e+07" in mm and "437500" in mm


def test_a_body_without_meshes_shows_no_mesh_columns(cli):
    out = table(cli, "inertia", str(EX / "bracket.yaml")) + table(cli, "principal", str(EX / "bracket.yaml"))
    assert "parts" in out and "volume [" not in out and "mesh parts" not in out
    assert "volume" not in json.dumps(js(cli, "principal", str(EX / "bracket.yaml"))["parts"])


# ---------------------------------------------------------------------------- scale, units


def test_scale_and_units_give_the_same_body(tmp_path):
    V, F, _ = box_mesh(A, B, C)
    write_obj(tmp_path / "m.obj", V, F)
    write_obj(tmp_path / "mm.obj", V * 1000, F)
    write_obj(tmp_path / "in.obj", V / 0.0254, F)
    write_obj(tmp_path / "half.obj", V / 2, F)
    cases = {
        "m": mesh_part("m.obj", f"density: {RHO}"),
        "mm": mesh_part("mm.obj", f"units: mm\ndensity: {RHO}"),
        "mm-scale": mesh_part("mm.obj", f"scale: 0.001\ndensity: {RHO}"),
        "in": mesh_part("in.obj", f"units: in\ndensity: {RHO}"),
        "half-x2": mesh_part("half.obj", f"scale: 2\ndensity: {RHO}"),
        "um-x1000": mesh_part("mm.obj", f"units: um\nscale: 1000\ndensity: {RHO}"),
    }
    ref = None
    for key, parts in cases.items():
        _, mp = mp_of(body_file(tmp_path, parts, f"{key}.yaml"))
        if ref is None:
            ref = mp
            assert mp.mass == pytest.approx(RHO * A * B * C, rel=1e-14)
            continue
        # mm -> m is one multiplication per coordinate: round-off of a few ulp
        assert mp.mass == pytest.approx(ref.mass, rel=1e-13), key
        assert rel_err(mp.inertia_com, ref.inertia_com) < 1e-13, key
    # the body file's length unit is the mesh's when the part says none
    _, mp = mp_of(body_file(tmp_path, mesh_part("mm.obj", f'density: "{RHO} kg/m^3"'), "u.yaml",
                            header="units: {length: mm}\n"))
    assert mp.mass == pytest.approx(ref.mass, rel=1e-13)


def test_a_one_part_mesh_body_reads_a_text_units_as_its_files_and_a_mapping_as_the_bodys(tmp_path, cli):
    import rbcli

    # a tetrahedron with legs 10 (file units): volume 1000/6, com at 2.5 on each axis
    write_obj(tmp_path / "tet.obj", np.array([[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10]]),
              [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)])
    one = "{shape: mesh, file: tet.obj, mass: 1, units: mm}"
    r = cli("inertia", "-e", one, "--json", cwd=tmp_path)
    assert r.code == 0, r.err
    # mm -> m: one product per coordinate, a few ulp
    assert r.json()["com"] == pytest.approx([2.5e-3] * 3, rel=1e-14)
    inside = cli("inertia", "-e", "{parts: [" + one + "]}", "--json", cwd=tmp_path).json()
    assert inside["inertia_com"] == r.json()["inertia_com"]  # the same part, the same numbers
    body = rbcli.load_text(one, base_dir=tmp_path)
    again = rbcli.load_text(body.to_yaml(base_dir=tmp_path), base_dir=tmp_path)  # as written
    for other in (again, body.replace(0, mass=2)):
        assert not body.units and other.parts[0].com.tolist() == body.parts[0].com.tolist()
    # the body's units as a mapping: the file's coordinates and the bare numbers in mm
    r = cli("inertia", "-e", "{shape: mesh, file: tet.obj, mass: 1, units: {length: mm}}", "--json",
            cwd=tmp_path)
    assert r.json()["com"] == pytest.approx([2.5e-3] * 3, rel=1e-14)
    for text, words in (("{shape: mesh, file: tet.obj, mass: 1, units: kg}", "length unit"),
                        ("{shape: disk, radius: 1, mass: 1, units: mm}", "'units: {length: mm}'")):
        r = cli("inertia", "-e", text, cwd=tmp_path)
        assert r.code == 2 and words in r.err and r.err.count("\n") == 1, r.err


def test_bad_scale_and_units_are_located_errors(tmp_path, cli):
    V, F, _ = box_mesh(A, B, C)
    write_obj(tmp_path / "m.obj", V, F)
    for extra, words in (("units: kg", "length unit"), ("units: furlongz", "units"),
                         ("scale: -2", "positive"), ("scale: 0", "positive"),
                         ("allow_open: 1", "true or false"), ("colour: red", "unknown key 'colour'")):
        f = body_file(tmp_path, mesh_part("m.obj", f"density: 1\n{extra}"))
        r = cli("inertia", str(f))
        assert r.code == 2 and r.out == "" and words in r.err, (extra, r.err)
        assert re.match(rf"rbcli: {re.escape(str(f))}:\d+:\d+: ", r.err) and r.err.count("\n") == 1


# ---------------------------------------------------------------------------- far away


def test_10_km_away_and_rotated_keeps_the_inertia_about_the_com(tmp_path):
    import trimesh

    V, F = lumpy_mesh()
    rho = 2700.0
    write_obj(tmp_path / "here.obj", V, F)
    _, here = mp_of(body_file(tmp_path, mesh_part("here.obj", f"density: {rho}"), "here.yaml"))
    # the oracle near the origin: trimesh on the same arrays agrees to round-off there
    tm = trimesh.Trimesh(V, F, process=False)
    tm.density = rho
    assert here.mass == pytest.approx(tm.mass, rel=1e-12)
    assert rel_err(here.inertia_com, tm.moment_inertia) < 1e-11  # ~300 triangles' sums
    np.testing.assert_allclose(here.com, tm.center_mass, atol=1e-14)

    axis, angle = np.array([1.0, -2.0, 0.5]), 37.0
    R = Rotation.from_rotvec(np.radians(angle) * axis / np.linalg.norm(axis)).as_matrix()
    t = np.array([10_000.0, -3_000.0, 250.0])  # 10.4 km from the origin
    want = R @ here.inertia_com @ R.T
    # (a) placed far away by the YAML
    placed = mesh_part("here.obj", f"density: {rho}\nat: [{t[0]}, {t[1]}, {t[2]}]\n"
                       f"rotate: {{axis: [1, -2, 0.5], angle: {angle}}}")
    _, a = mp_of(body_file(tmp_path, placed, "placed.yaml"))
    # (b) the same mesh with its coordinates 10 km away in the file (float64 text, ASCII STL)
    write_stl_ascii(tmp_path / "far.stl", V @ R.T + t, F)
    _, b = mp_of(body_file(tmp_path, mesh_part("far.stl", f"density: {rho}"), "far.yaml"))
    for mp in (a, b):
        assert mp.mass == pytest.approx(here.mass, rel=1e-12)
        # 1e-9 is the requirement; coordinates 1e4 m written to 1 ulp (2e-12 m) of a 0.3 m
        # part leave ~1e-11 relative, the integration about the bounding-box centre no more
        assert rel_err(mp.inertia_com, want) < 1e-9
        np.testing.assert_allclose(mp.com, t + R @ here.com, rtol=0, atol=1e-9)
    # that the test can fail: integrating about the origin (trimesh) loses the digits
    far = trimesh.Trimesh(V @ R.T + t, F, process=False)
    far.density = rho
    assert rel_err(far.moment_inertia, want) > 1e-6


# ---------------------------------------------------------------------------- bad meshes


def _bad_meshes(tmp: Path) -> dict[str, tuple[Path, str]]:
    """file -> (path, words the message must hold)."""
    V, F, _ = box_mesh(A, B, C)
    out = {}
    out["open"] = (write_stl_ascii(tmp / "open.stl", V, F[1:]), "not closed: 3 boundary edges")
    mixed = F.copy()
    mixed[0] = mixed[0][::-1]
    out["mixed"] = (write_stl_ascii(tmp / "mixed.stl", V, mixed), "inconsistent orientation")
    # two tetrahedra sharing one edge (0-1): that edge has four triangles
    tv = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0, -1, 0], [0, 0, -1.0]])
    nm = outward_tetra(tv, (0, 1, 2, 3)) + outward_tetra(tv, (0, 1, 4, 5))
    out["nonmanifold"] = (write_obj(tmp / "nm.obj", tv, nm), "not manifold: 1 edge is shared by more than two")
    flat = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float)
    out["flat"] = (write_obj(tmp / "flat.obj", flat, [(0, 1, 2), (0, 2, 1)]), "encloses no volume")
    out["degenerate"] = (write_obj(tmp / "deg.obj", flat, [(0, 0, 1), (1, 2, 2)]), "degenerate")
    nan = write_stl_ascii(tmp / "nan.stl", V, F)
    nan.write_text(nan.read_text().replace(repr(A / 2), "nan", 1))
    out["nan"] = (nan, "non-finite")
    good = write_stl_binary(tmp / "trunc.stl", V, F)
    (tmp / "trunc.stl").write_bytes(good.read_bytes()[:-25])
    out["truncated"] = (tmp / "trunc.stl", "truncated or corrupt binary stl: header says 12 triangles")
    rng = np.random.default_rng(1)
    (tmp / "garbage.stl").write_bytes(rng.integers(0, 256, 1000, dtype=np.uint8).tobytes())
    out["garbage"] = (tmp / "garbage.stl", "binary stl")
    (tmp / "text.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n")
    out["obj-text"] = (tmp / "text.obj", "'zero' is not a number")
    (tmp / "empty.stl").write_bytes(b"")
    out["empty"] = (tmp / "empty.stl", "empty file")
    out["missing"] = (tmp / "nonesuch.stl", "no such file")
    (tmp / "part.step").write_text("ISO-10303-21;")
    out["step"] = (tmp / "part.step", "unknown mesh file type ('.step'); use one of .stl, .obj")
    (tmp / "dir.stl").mkdir()
    out["directory"] = (tmp / "dir.stl", "is a directory")
    return out


def test_every_bad_mesh_is_one_located_line_naming_the_file(tmp_path, cli):
    for key, (path, words) in _bad_meshes(tmp_path).items():
        f = body_file(tmp_path, mesh_part(path.name), f"{key}.yaml")
        r = cli("inertia", str(f))
        assert r.code == 2 and r.out == "", (key, r.err)
        # one line: where in the body file (the file: value, line 5 col 11), the part, the mesh file
        assert r.err.count("\n") == 1 and "Traceback" not in r.err, (key, r.err)
        assert r.err.startswith(f"rbcli: {f}:5:11: part 'housing' (mesh): {tmp_path / path.name}"), (key, r.err)
        assert words in r.err, (key, r.err)
    open_msg = cli("inertia", str(tmp_path / "open.yaml")).err
    assert "allow_open: true" in open_msg  # says how to accept it


def test_allow_open_accepts_an_open_mesh_with_a_warning(tmp_path, cli):
    V, F, _ = box_mesh(A, B, C)
    write_stl_ascii(tmp_path / "open.stl", V, F[1:])
    f = body_file(tmp_path, mesh_part("open.stl", "density: 1000\nallow_open: true"))
    r = cli("inertia", str(f), "--json")
    assert r.code == 0 and json.loads(r.out)["mass"] > 0
    assert re.fullmatch(rf"rbcli: {re.escape(str(f))}:5:11: warning: part 'housing' \(mesh\): "
                        rf"{re.escape(str(tmp_path / 'open.stl'))}: mesh is open \(3 boundary edges\)[^\n]*\n", r.err)


def test_an_inward_mesh_is_turned_outward_with_a_warning(tmp_path, cli):
    V, F, _ = box_mesh(A, B, C)
    write_stl_binary(tmp_path / "inv.stl", V, F[:, ::-1])
    write_stl_binary(tmp_path / "box.stl", V, F)
    inv = body_file(tmp_path, mesh_part("inv.stl", f"density: {RHO}"), "inv.yaml")
    good = body_file(tmp_path, mesh_part("box.stl", f"density: {RHO}"), "good.yaml")
    r = cli("inertia", str(inv), "--json")
    assert r.code == 0
    assert r.err.count("\n") == 1 and r.err.startswith(f"rbcli: {inv}:5:11: warning: part 'housing' (mesh): {tmp_path / 'inv.stl'}: ")
    assert "inward" in r.err and "outward" in r.err
    got, want = json.loads(r.out), js(cli, "inertia", str(good))
    assert got["mass"] == pytest.approx(RHO * A * B * C, rel=1e-14)  # positive, not -m
    assert rel_err(got["inertia_com"], want["inertia_com"]) < 1e-14  # the same sums, negated
    assert got["parts"][0]["volume"] > 0


def test_bad_meshes_through_a_real_process(tmp_path, cli_proc):
    bad = _bad_meshes(tmp_path)
    for key in ("truncated", "open"):
        path, words = bad[key]
        body_file(tmp_path, mesh_part(path.name), f"{key}.yaml")
        r = cli_proc("inertia", f"{key}.yaml", cwd=tmp_path)
        assert r.code == 2 and r.out == "", (key, r.err)
        # the path as the body file names it (relative to the current folder)
        assert re.fullmatch(rf"rbcli: {key}\.yaml:5:11: part 'housing' \(mesh\): {re.escape(path.name)}: [^\n]*{words}[^\n]*\n",
                            r.err), r.err
    V, F, _ = box_mesh(A, B, C)
    write_stl_binary(tmp_path / "inv.stl", V, F[:, ::-1])
    body_file(tmp_path, mesh_part("inv.stl"), "inv.yaml")
    r = cli_proc("principal", "inv.yaml", "--json", cwd=tmp_path)
    assert r.code == 0 and r.json()["parts"][0]["volume"] > 0
    assert re.fullmatch(r"rbcli: inv\.yaml:5:11: warning: part 'housing' \(mesh\): inv\.stl: [^\n]*inward[^\n]*\n", r.err)


def test_the_yaml_is_checked_before_the_mesh_is_read(tmp_path, cli):
    # a missing mass is reported even though the file does not exist: no time spent reading
    f = body_file(tmp_path, "  - name: housing\n    shape: mesh\n    file: nonesuch.stl\n")
    r = cli("inertia", str(f))
    assert r.code == 2 and "needs its mass or density" in r.err and "no such file" not in r.err
    f = body_file(tmp_path, mesh_part("nonesuch.stl", "density: 3\nrotate: {axis: [0, 0, 0], angle: 3}"))
    assert "rotate axis must be a non-zero vector" in cli("inertia", str(f)).err


# ---------------------------------------------------------------------------- holes


def test_a_hole_cut_from_a_mesh_takes_the_mesh_density(tmp_path, cli):
    V, F, _ = box_mesh(A, B, C)
    write_stl_binary(tmp_path / "box.stl", V, F)
    r, d = 0.03, np.array([0.1, 0.05, 0.0])
    hole = (f"  - name: bore\n    shape: cylinder\n    radius: {r}\n    length: {C}\n"
            f"    at: [{d[0]}, {d[1]}, {d[2]}]\n    subtract: true\n    cut_from: housing\n")
    rho = 2000.0
    f = str(body_file(tmp_path, mesh_part("box.stl", f"density: {rho}") + hole))
    j = js(cli, "inertia", f)
    m_box, m_cyl = rho * A * B * C, rho * math.pi * r * r * C
    J_box = box_closed_form(m_box, A, B, C)
    J_cyl = np.diag([m_cyl * (3 * r * r + C * C) / 12] * 2 + [m_cyl * r * r / 2])
    J_cyl += m_cyl * (d @ d * np.eye(3) - np.outer(d, d))  # parallel axes to the origin
    # closed forms on both sides, a few dozen operations: round-off only
    assert j["mass"] == pytest.approx(m_box - m_cyl, rel=1e-13)
    assert j["parts"][1]["mass"] == pytest.approx(-m_cyl, rel=1e-13)
    np.testing.assert_allclose(j["com"], -m_cyl * d / (m_box - m_cyl), rtol=1e-12, atol=1e-15)
    assert rel_err(j["inertia"], J_box - J_cyl) < 1e-13
    # a mesh given by its mass: the hole takes the mean density mass / volume
    f2 = str(body_file(tmp_path, mesh_part("box.stl", "mass: 3") + hole, "bymass.yaml"))
    j2 = js(cli, "inertia", f2)
    assert j2["parts"][1]["mass"] == pytest.approx(-3 * (math.pi * r * r * C) / (A * B * C), rel=1e-13)


def test_a_mesh_can_be_the_hole(tmp_path):
    # a block with a box-shaped pocket given as a mesh cut from it (cut_from: block)
    V, F, _ = box_mesh(0.125, 0.125, 0.0625)
    write_stl_binary(tmp_path / "pocket.stl", V, F)
    parts = (f"  - name: block\n    shape: box\n    size: [{A}, {B}, {C}]\n    density: {RHO}\n"
             + mesh_part("pocket.stl", "subtract: true\ncut_from: block\nat: [0.1, 0, 0]", name="pocket"))
    _, mp = mp_of(body_file(tmp_path, parts))
    m_p = RHO * 0.125 * 0.125 * 0.0625
    assert mp.mass == pytest.approx(RHO * A * B * C - m_p, rel=1e-13)
    assert mp.com[0] == pytest.approx(-m_p * 0.1 / mp.mass, rel=1e-12)


# ---------------------------------------------------------------------------- other commands


def _pair(tmp: Path) -> tuple[str, str]:
    """The same off-axis, tilted rotor as a mesh and as a primitive box."""
    V, F, _ = box_mesh(A, B, C)
    write_stl_binary(tmp / "box.stl", V, F)
    place = "at: [0.01, 0.002, 0.05]\nrotate: {axis: [1, 0.3, 0], angle: 5}"
    mesh = body_file(tmp, mesh_part("box.stl", f"density: {RHO}\n{place}"), "mesh.yaml")
    prim = body_file(tmp, f"  - shape: box\n    size: [{A}, {B}, {C}]\n    density: {RHO}\n"
                     + "".join(f"    {x}\n" for x in place.split("\n")), "prim.yaml")
    return str(mesh), str(prim)


def test_balance_and_precess_see_the_mesh_as_the_box(tmp_path, cli):
    mesh, prim = _pair(tmp_path)
    # balance: the unbalance of the same solid; ~1e3 operations -> 1e-12
    a, b = js(cli, "balance", mesh), js(cli, "balance", prim)
    for key in ("mass", "eccentricity", "static_unbalance", "couple_unbalance", "tilt_deg"):
        assert a[key] == pytest.approx(b[key], rel=1e-10), key
    assert a["statically_balanced"] is b["statically_balanced"] is False
    assert a["couple_unbalance"] > 0
    # precess: torque-free motion; the elliptic period is well conditioned away from the separatrix
    a, b = js(cli, "precess", mesh, "--omega", "0.3,0.2,3"), js(cli, "precess", prim, "--omega", "0.3,0.2,3")
    for key in ("kinetic_energy", "period"):
        assert a[key] == pytest.approx(b[key], rel=1e-10), key
    np.testing.assert_allclose(a["angular_momentum"], b["angular_momentum"], rtol=1e-10)


def test_balance_apply_writes_a_body_whose_mesh_still_loads(tmp_path, cli):
    mesh, _ = _pair(tmp_path)
    out = tmp_path / "elsewhere" / "balanced.yaml"
    out.parent.mkdir()
    r = cli("balance", mesh, "--planes", "-0.05,0.05", "--radius", "0.1", "--apply", str(out))
    assert r.code in (0, 1), r.err
    body = load_body(str(out))  # the mesh path was rewritten for the new folder
    assert [p.shape for p in body.parts][0] == "mesh"
    a = js(cli, "balance", str(out))
    # two exact correction masses: the ideal verdict after them
    assert a["statically_balanced"] and a["dynamically_balanced"]


def test_include_stdin_and_expr_find_the_mesh(tmp_path, cli):
    V, F, _ = box_mesh(A, B, C)
    sub = tmp_path / "sub"
    sub.mkdir()
    write_stl_binary(sub / "box.stl", V, F)
    body_file(sub, mesh_part("box.stl", f"density: {RHO}"), "part.yaml")
    top = body_file(tmp_path, "  - name: sub\n    shape: include\n    file: sub/part.yaml\n    at: [1, 0, 0]\n")
    j = js(cli, "inertia", str(top))
    m = RHO * A * B * C
    assert j["mass"] == pytest.approx(m, rel=1e-14) and j["parts"][0]["name"] == "sub/housing"
    assert j["parts"][0]["volume"] == pytest.approx(A * B * C, rel=1e-14)
    # -e and standard input: paths relative to the current folder
    r = cli("inertia", "-e", "{shape: mesh, file: box.stl, mass: 2}", "--json", cwd=sub)
    assert r.code == 0 and r.json()["mass"] == 2, r.err
    r = cli("inertia", "-", "--json", input=f"shape: mesh\nfile: box.stl\ndensity: {RHO}\n", cwd=sub)
    assert r.code == 0 and r.json()["mass"] == pytest.approx(m, rel=1e-14)
    r = cli("inertia", "-e", "{shape: mesh, file: nope.stl, mass: 2}", cwd=sub)
    assert r.code == 2 and "<expr>:1:21: part 'mesh1' (mesh): nope.stl: no such file" in r.err


# ---------------------------------------------------------------------------- catalogue, start-up


def test_the_shapes_catalogue_describes_the_mesh(cli):
    out = table(cli, "shapes", "mesh")
    for words in ("STL", "OBJ", "file", "scale", "units", "allow_open", "density",
                  "boundary edges", "manifold", "orientation", "inward", "truncated", "NaN"):
        assert words in out, words
    (entry,) = [e for e in js(cli, "shapes") if e["shape"] == "mesh"]
    assert "allow_open" in entry["parameters"]


def test_bodies_without_meshes_do_not_import_the_mesh_modules(cli_proc):
    mesh_modules = {"rbcli.core.mesh", "rbcli.io.meshfile", "trimesh"}
    r = cli_proc("inertia", "examples/bracket.yaml", "--json", imports=True)
    assert r.code == 0 and not mesh_modules & r.imported, (r.err, sorted(mesh_modules & r.imported))
    # the check can fail: a mesh body does import them (and never trimesh)
    r = cli_proc("inertia", "examples/housing.yaml", "--json", imports=True)
    assert r.code == 0 and mesh_modules & r.imported == {"rbcli.core.mesh", "rbcli.io.meshfile"}, r.err


# ---------------------------------------------------------------------------- the example


def test_the_housing_example_prints_its_number(cli):
    """examples/housing.yaml, worked by hand.

    housing.stl: a 100 x 100 mm square with its corners chamfered 20 mm at 45°, 60 mm long
    (z from 0 to 60 mm), aluminium 2700 kg/m^3. Its polar second moment of area is the
    square's a^4/6 minus four right isosceles corner triangles (legs b = 20 mm, area 200,
    own polar moment b^4/18, centroid at (130/3, 130/3) mm). The bore: r = 20 mm through it
    at the housing's density, on the z axis. The boss: steel 7850, r = 15 mm, 20 mm long
    along x, its centre 60 mm from the z axis.
    """
    a, b, L = 100.0, 20.0, 60.0  # mm
    area = a * a - 4 * b * b / 2  # 9200 mm^2
    J = a**4 / 6 - 4 * (b**4 / 18 + (b * b / 2) * 2 * (a / 2 - b / 3) ** 2)  # mm^4
    rho_al, rho_st = 2700.0, 7850.0
    m_h = rho_al * area * L * MM**3
    r, rb, lb, xb = 20 * MM, 15 * MM, 20 * MM, 60 * MM
    m_bore = rho_al * math.pi * r * r * L * MM
    m_boss = rho_st * math.pi * rb * rb * lb
    mass = m_h - m_bore + m_boss
    Izz = rho_al * L * MM * J * MM**4 - m_bore * r * r / 2 + m_boss * ((3 * rb * rb + lb * lb) / 12 + xb * xb)
    assert f"{Izz:.6g}" == "0.00257626" and f"{mass:.6g}" == "1.3978"  # the header's numbers

    ex = str(EX / "housing.yaml")
    j = js(cli, "inertia", ex, "--axis", "z")
    # coordinates are integers in mm (exact in float32); float64 round-off only
    assert j["axis_moment"] == pytest.approx(Izz, rel=1e-12)
    assert j["mass"] == pytest.approx(mass, rel=1e-12)
    assert j["com"] == pytest.approx([m_boss * xb / mass, 0, 30 * MM], rel=1e-12, abs=1e-15)
    housing = j["parts"][0]
    assert housing["volume"] == pytest.approx(area * L * MM**3, rel=1e-13)
    side = 4 * (a - 2 * b) + 4 * b * math.sqrt(2)  # the octagon's perimeter, mm
    assert housing["area"] == pytest.approx((2 * area + side * L) * MM**2, rel=1e-13)
    assert housing["triangles"] == 32
    out = table(cli, "inertia", ex, "--axis", "z")
    assert "0.00257626" in out and "1.3978" in out
    header = (EX / "housing.yaml").read_text()
    assert "0.00257626" in header and "1.3978" in header
    pj = js(cli, "principal", ex)
    assert pj["parts"][0]["volume"] == housing["volume"]
    assert "mesh parts" in table(cli, "principal", ex)


def test_what_the_mesh_check_tolerates_is_said_on_stderr(tmp_path, cli):
    V, F, _ = box_mesh(A, B, C)
    F2 = np.vstack([F, [[0, 0, 1]]])  # a triangle that repeats a vertex: no area, no edges
    write_obj(tmp_path / "extra.obj", V, F2)
    f = body_file(tmp_path, mesh_part("extra.obj", f"density: {RHO}"))
    r = cli("inertia", str(f), "--json")
    assert r.code == 0 and json.loads(r.out)["mass"] == pytest.approx(RHO * A * B * C, rel=1e-14)
    assert r.err == (f"rbcli: {f}:5:11: warning: part 'housing' (mesh): {tmp_path / 'extra.obj'}: "
                     "dropped 1 degenerate triangle (a repeated vertex)\n")


# ------------------------------------------------------------- welding, file checks


def noisy_soup(V, F, delta):
    """Triangle corners of their own, every other copy moved by ``delta`` along x."""
    c = np.asarray(V, dtype=float)[np.asarray(F)].reshape(-1, 3).copy()
    c[::2, 0] += delta
    return c, np.arange(len(c)).reshape(-1, 3)


def test_a_noisy_cad_mesh_is_welded_with_one_located_warning(tmp_path, cli):
    V, F, _ = box_mesh(A, B, C)
    ulp = float(np.spacing(np.float32(A / 2)))  # one float32 step at the box's size
    write_stl_binary(tmp_path / "n.stl", *noisy_soup(V, F, ulp))
    f = body_file(tmp_path, mesh_part("n.stl", f"density: {RHO}"))
    r = cli("inertia", f, "--json")
    assert r.code == 0 and r.json()["mass"] == pytest.approx(RHO * A * B * C, rel=1e-6)
    (line,) = r.err.splitlines()
    assert line.startswith(f"rbcli: {f}:5:11: warning: part 'housing' (mesh): {tmp_path / 'n.stl'}: welded ")
    assert f"largest gap closed {ulp:.3g} m" in line
    f2 = body_file(tmp_path, mesh_part("n.stl", f"density: {RHO}\nweld: exact"), name="exact.yaml")
    r = cli("inertia", f2)
    assert r.code == 2 and "not closed" in r.err and "allow_open: true accepts" in r.err


def test_weld_sets_the_tolerance_per_part(tmp_path, cli):
    V, F, _ = box_mesh(A, B, C)
    write_obj(tmp_path / "gap.obj", *noisy_soup(V, F, 1e-4 * A))  # 0.05 mm gaps
    f = body_file(tmp_path, mesh_part("gap.obj", f"density: {RHO}"))
    r = cli("inertia", f)
    assert r.code == 2 and "not closed" in r.err and "(after welding vertices closer than" in r.err
    f = body_file(tmp_path, mesh_part("gap.obj", f"density: {RHO}\nweld: 0.1 mm"), name="w.yaml")
    r = cli("inertia", f, "--json")
    assert r.code == 0 and r.json()["mass"] == pytest.approx(RHO * A * B * C, rel=1e-3)
    assert "weld tolerance 0.0001 m (largest gap closed 5e-05 m)" in r.err
    for bad, message in (("weld: -1 mm", "must be zero or positive"), ("weld: exactly", "weld"),
                         ("weld: 1 kg", "weld")):
        f = body_file(tmp_path, mesh_part("gap.obj", f"density: {RHO}\n{bad}"), name="b.yaml")
        r = cli("inertia", f)
        assert r.code == 2 and r.err.startswith(f"rbcli: {f}:") and message in r.err, bad
        assert len(r.err.splitlines()) == 1


def test_mesh_files_that_are_not_regular_files_or_names_with_nul(tmp_path, cli, cli_proc):
    os.mkfifo(tmp_path / "pipe.stl")
    f = body_file(tmp_path, mesh_part("pipe.stl"))
    r = cli_proc("inertia", f)  # a real process: it must not hang on the FIFO
    assert r.code == 2 and "is a FIFO (named pipe), not a regular file" in r.err
    f = body_file(tmp_path, mesh_part('"a\\0b.stl"'), name="nul.yaml")
    r = cli("inertia", f)
    assert r.code == 2 and r.err == f"rbcli: {f}:5:11: file: a file name cannot contain a NUL character\n"


def test_a_huge_obj_face_index_through_the_command_line(tmp_path, cli):
    (tmp_path / "big.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 " + "1" + "0" * 23 + "\n")
    f = body_file(tmp_path, mesh_part("big.obj"))
    r = cli("inertia", f)
    assert r.code == 2 and f"big.obj:4: face index {10**23} is out of range" in r.err


def test_a_mesh_over_the_size_limit_is_refused(tmp_path, cli):
    V, F, _ = box_mesh(A, B, C)
    write_stl_binary(tmp_path / "box.stl", V, F)
    f = body_file(tmp_path, mesh_part("box.stl"))
    r = cli("inertia", f, env={"RBCLI_MAX_MESH_BYTES": "100"})
    assert r.code == 2 and "mesh files are limited to 100 bytes (set RBCLI_MAX_MESH_BYTES" in r.err
    assert cli("inertia", f, env={"RBCLI_MAX_MESH_BYTES": "1M"}).code == 0
