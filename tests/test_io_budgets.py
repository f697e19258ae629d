"""Budgets and strict formats (issue 27): the part cap checked while the YAML tree is built,
a mesh without faces or with an absurd face refused before its numbers are read, an
included file read and parsed once however often it is used, OBJ/STL numbers by their
formats' grammar (no Python-only spellings such as ``1_000``), a trailing slash naming a
folder, and an output name the system refuses (ENAMETOOLONG) an output error."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from rbcli.errors import InputError
from rbcli.io import meshobj
from rbcli.body.model import load_body, load_text
from rbcli.io.meshfile import MeshFileError, read_mesh

ROOT = Path(__file__).resolve().parent.parent
CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f]")


def one_line(r, code: int = 2, says: str = "") -> str:
    """Exit ``code`` and exactly one ``rbcli:`` line on standard error, no traceback."""
    assert r.code == code, (r.code, r.err[-2000:])
    lines = r.err.rstrip("\n").split("\n")
    assert len(lines) == 1 and lines[0].startswith("rbcli: "), r.err[:2000]
    assert "internal error" not in r.err and "Traceback" not in r.err
    assert says in r.err, r.err
    return r.err


def _points(n: int, tail: str = "") -> str:
    return "parts:\n" + "".join(f"  - {{shape: point, mass: 1, at: [{i}, 0, 0]}}\n" for i in range(n)) + tail


# ----------------------------------------------------------------------------- the part cap


def test_the_part_cap_stops_the_yaml_tree_before_the_rest_of_the_file(monkeypatch):
    # a YAML error after part 3000: with a cap of 1000 the file is refused at part 1001,
    # while the tree is built (the rest of the file, with its error, is never parsed)
    monkeypatch.setenv("RBCLI_MAX_PARTS", "1000")
    text = _points(3000, tail="  - {shape: point, mass: 1\n")
    with pytest.raises(InputError, match="more than 1000 parts") as exc:
        load_text(text, "big.yaml", ROOT)
    assert exc.value.where.line == 1002  # 'parts:' is line 1: part 1001 is line 1002
    monkeypatch.setenv("RBCLI_MAX_PARTS", "5000")  # the check can fail: under the cap, the YAML error
    with pytest.raises(InputError, match="invalid YAML"):
        load_text(text, "big.yaml", ROOT)


def test_an_included_file_gets_what_is_left_of_the_cap(tmp_path, monkeypatch):
    # the top file's 500 parts are spent before its include is read: sub.yaml may hold 500
    # of the 1000, and its 501st part is refused while its tree is built (its YAML error at
    # the end is never reached); with a cap of 1200 sub.yaml is parsed to its error
    (tmp_path / "sub.yaml").write_text(_points(600, tail="  - {shape: point, mass: 1\n"))
    top = tmp_path / "top.yaml"
    top.write_text(_points(500) + "  - {name: s, shape: include, file: sub.yaml}\n")
    monkeypatch.setenv("RBCLI_MAX_PARTS", "1000")
    with pytest.raises(InputError, match="more than 1000 parts") as exc:
        load_body(str(top))
    assert exc.value.where.file.endswith("sub.yaml") and exc.value.where.line == 502
    monkeypatch.setenv("RBCLI_MAX_PARTS", "1200")
    with pytest.raises(InputError, match="invalid YAML"):
        load_body(str(top))


def test_a_file_over_the_part_cap_is_one_line_in_a_real_process(cli_proc, tmp_path):
    big = tmp_path / "big.yaml"
    big.write_text(_points(40_000))
    r = cli_proc("inertia", str(big), "--json", env={"RBCLI_MAX_PARTS": "20000"})
    one_line(r, says="more than 20000 parts")
    assert f"{big}:20002:" in r.err  # located at part 20 001


# ----------------------------------------------------------------------------- meshes


def test_a_vertex_only_obj_is_refused_before_its_numbers_are_read(tmp_path, monkeypatch):
    path = tmp_path / "cloud.obj"
    path.write_bytes(b"".join(b"v %d 0.5 1e-3\n" % i for i in range(100_000)))

    def never(*args, **kwargs):
        raise AssertionError("the vertices were read")

    monkeypatch.setattr(meshobj, "_read_obj_fast", never)
    monkeypatch.setattr(meshobj, "_read_obj_lines", never)
    with pytest.raises(MeshFileError, match="without faces"):
        read_mesh(path)


@pytest.mark.parametrize("text", ["v 0 0 0\nv 1 0 0\nv 0 1 0\n# f 1 2 3\n",
                                  "v 0 0 0\nv 1 0 0\n  vf 1 2 3\n"])
def test_a_face_in_a_comment_or_another_word_is_no_face(tmp_path, text):
    path = tmp_path / "x.obj"
    path.write_text(text)
    with pytest.raises(MeshFileError, match="without faces"):
        read_mesh(path)


def test_a_face_of_absurdly_many_corners_is_refused_at_its_line(tmp_path):
    path = tmp_path / "fan.obj"
    corners = meshobj.MAX_FACE_CORNERS + 1
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n# a face\nf " + " ".join(["1"] * corners) + "\n")
    with pytest.raises(MeshFileError, match=f"{corners} corners") as exc:
        read_mesh(path)
    assert exc.value.line == 6
    ok = tmp_path / "ok.obj"  # the check can fail: a polygon of many distinct corners is read
    n = 2000
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    ok.write_text("".join(f"v {float(np.cos(a))!r} {float(np.sin(a))!r} 0\n" for a in t)
                  + "f " + " ".join(str(i + 1) for i in range(n)) + "\n")
    assert len(read_mesh(ok).faces) == n - 2


@pytest.mark.parametrize("number", ["1_000", "1_0.5", "0_1e3", "1e1_0"])
@pytest.mark.parametrize("fmt", ["obj", "stl"])
def test_python_only_number_spellings_are_not_numbers(tmp_path, number, fmt):
    path = tmp_path / f"x.{fmt}"
    if fmt == "obj":
        path.write_text(f"v {number} 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n")
    else:
        path.write_text("solid x\nfacet normal 0 0 1\nouter loop\n"
                        f"vertex {number} 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid x\n")
    with pytest.raises(MeshFileError, match=f"'{number}' is not a number") as exc:
        read_mesh(path)
    assert exc.value.line == (1 if fmt == "obj" else 4)


@pytest.mark.parametrize("index", ["1_0", "٣"])
def test_python_only_index_spellings_are_not_indices(tmp_path, index):
    path = tmp_path / "x.obj"
    path.write_text("".join("v 0 0 0\n" for _ in range(12)) + f"f 1 2 {index}\n", encoding="utf-8")
    with pytest.raises(MeshFileError, match="bad face index"):
        read_mesh(path)


def test_obj_numbers_of_every_form_the_grammar_allows_are_read(tmp_path):
    # the OBJ grammar's numbers (C's strtod without hex): signs, points at either end,
    # exponents of both cases; checked against Python's float of the same text
    texts = ["-1", "+2.", ".5", "-.25e1", "3E-2", "+4.5e+1", "007", "1e0"]
    path = tmp_path / "x.obj"
    path.write_text(f"v {texts[0]} {texts[1]} {texts[2]}\nv {texts[3]} {texts[4]} {texts[5]}\n"
                    f"v {texts[6]} {texts[7]} 1 0.5\nf 1 2 3\n")
    m = read_mesh(path)
    got = sorted(m.vertices.ravel().tolist())
    assert got == sorted(float(t) for t in [*texts, "1"])


# ----------------------------------------------------------------------------- includes, paths


def test_ten_thousand_includes_of_one_file_read_and_parse_it_once(tmp_path, monkeypatch):
    from rbcli.body import includes
    from rbcli.io import yamlsafe as ys

    (tmp_path / "small.yaml").write_text("{shape: box, mass: 1, size: [1, 1, 1]}\n")
    top = tmp_path / "top.yaml"
    top.write_text("parts:\n" + "".join(
        f"  - {{name: i{i}, shape: include, file: small.yaml, at: [{i}, 0, 0]}}\n" for i in range(10_000)))
    parses, reads = [], []
    real_load, real_read = ys.load, includes.read_body_file
    monkeypatch.setattr(ys, "load", lambda data, name, **kw: parses.append(name) or real_load(data, name, **kw))
    monkeypatch.setattr(includes, "read_body_file", lambda p, where=None: reads.append(p) or real_read(p, where))
    b = load_body(str(top))
    assert len(b.parts) == 10_000 and b.parts[-1].com[0] == 9999.0
    assert len(parses) == 2 and len(reads) == 2  # the top file and small.yaml, once each


@pytest.mark.parametrize("key", ["include", "mesh"])
def test_a_trailing_slash_names_a_folder(tmp_path, key):
    (tmp_path / "c.yaml").write_text("{shape: box, mass: 1, size: [1, 1, 1]}\n")
    (tmp_path / "c.stl").write_bytes((ROOT / "examples" / "housing.stl").read_bytes())
    top = tmp_path / "top.yaml"
    if key == "include":
        top.write_text("parts:\n  - {name: s, shape: include, file: c.yaml/}\n")
    else:
        top.write_text("parts:\n  - {name: s, shape: mesh, file: c.stl/, units: mm, density: 1000}\n")
    with pytest.raises(InputError, match="names a folder") as exc:
        load_body(str(top))
    assert exc.value.where.line == 2
    with pytest.raises(InputError, match="names a folder"):
        load_body(str(tmp_path / "c.yaml") + "/")


LONG = "a" * 300


@pytest.mark.parametrize("args", [
    ("principal", "examples/cube.yaml", "--plot", f"{LONG}.png"),
    ("report", "examples/top.yaml", "-o", f"{LONG}.html"),
    ("precess", "examples/book.yaml", "--omega", "0.01,1,0.01", "--duration", "1", "--csv", f"{LONG}.csv"),
])
def test_an_output_name_too_long_is_an_output_error(cli_proc, tmp_path, args):
    r = cli_proc(*[str(ROOT / a) if a.startswith("examples/") else a for a in args], cwd=tmp_path)
    one_line(r, says="file name too long")
    assert list(tmp_path.iterdir()) == []  # nothing written
