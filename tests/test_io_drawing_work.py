"""Drawing work only when a figure is drawn (issue 23): loading a body makes no drawing
geometry — a mesh part keeps its file's mesh (read-only), not a decimated copy, which the
figure's outline module (rbcli.render.outline) decimates when it draws. (A given part keeps
its equivalent ellipsoid: not only drawn, also measured by the plausibility warnings.)"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rbcli

ROOT = Path(__file__).resolve().parent.parent


def _imported(err: str) -> set[str]:
    """The modules a process imported, from ``PYTHONPROFILEIMPORTTIME``'s lines."""
    return {line.rsplit("|", 1)[-1].strip() for line in err.splitlines() if line.startswith("import time:")}


@pytest.mark.parametrize("example, kind", [("housing.yaml", "rbcli.io.meshfile"),
                                           ("earth.yaml", "rbcli.body.bodyfile")])
def test_inertia_json_imports_no_drawing_geometry(cli_proc, example, kind):
    r = cli_proc("inertia", f"examples/{example}", "--json", env={"PYTHONPROFILEIMPORTTIME": "1"})
    assert r.code == 0, r.err[-2000:]
    mods = _imported(r.err)
    assert kind in mods  # the check can fail: the import lines are read
    assert not [m for m in mods if m.endswith(".outline") or m.startswith("matplotlib")]


def test_a_mesh_part_keeps_its_files_mesh_and_only_a_figure_decimates_it(tmp_path):
    trimesh = pytest.importorskip("trimesh")
    from rbcli.render import outline as ol

    sphere = trimesh.creation.icosphere(subdivisions=5, radius=0.1)  # 20 480 triangles
    sphere.export(tmp_path / "ball.stl")
    (tmp_path / "ball.yaml").write_text("name: ball\nparts:\n  - {shape: mesh, file: ball.stl, density: 1000}\n")
    p = rbcli.load(tmp_path / "ball.yaml").parts[0]
    o = p.outline
    assert len(o.faces) == p.extra["triangles"] == 20480 and len(o.vertices) == 10242
    assert not o.vertices.flags.writeable and not o.faces.flags.writeable
    s = ol.sketch(o)  # what the flat views draw: at most MESH_MAX_TRIANGLES, marked rough
    assert s.rough and 100 < len(s.faces) <= ol.MESH_MAX_TRIANGLES
    assert len(ol.sketch(o, max_triangles=400).faces) <= 400  # the 3-D view's coarser copy


def test_a_given_part_is_drawn_as_its_equivalent_ellipsoid(tmp_path):
    from rbcli.render import outline as ol

    # a uniform solid sphere of radius 0.1 m: 2/5 m R² about every axis, here 2 kg
    p = rbcli.load_text("{shape: given, mass: 2, com: [0.1, 0, 0], inertia: {Ixx: 0.008, Iyy: 0.008, Izz: 0.008}}").parts[0]
    assert p.outline.kind == "given"
    # 1e-15 m: the square root of 2.5 (I2 + I3 - I1) / m, a few roundings of 0.1
    assert np.allclose(dict(p.outline.dims)["semi_axes"], 0.1, rtol=0, atol=1e-15)
    s = ol.sketch(p.outline)
    # the sphere's surface points are 0.1 m from its centre; 1e-12 m: rounding of the
    # eigen-decomposition and the square root (~1e-16 relative), far below any wrong size
    assert np.allclose(np.linalg.norm(s.vertices - [0.1, 0, 0], axis=1), 0.1, rtol=0, atol=1e-12)
    assert np.allclose(s.points, [[0.1, 0, 0]])
