"""A 100-solid STEP assembly: rbcli against a bare OpenCascade script (issue 33 item 7).

Usage: python bench/step_assembly.py [--solids N] [--runs N] [--rounds R] [--json FILE]

The goal: the mass properties of a 100-solid assembly (boxes, cylinders, spheres, tori and
cones, each its own part with a name and a colour, placed and turned in one assembly),
``rbcli inertia FILE --density 7850 --json``, within 1.2 times a bare OpenCascade script that
computes the same properties (``STEPControl_Reader``, each solid's
``BRepGProp.VolumeProperties``, their sum ``GProp_GProps.Add``, printed), whole processes
alternating, N runs after warm-up, the ratio of median CPU times. Also the work alone, in one
process after OpenCascade is imported (``rbcli.load`` then ``rbcli.inertia`` against the
script's function), R rounds: what rbcli adds to the read (its checks of the STEP text
before OpenCascade sees it, names, colours, the body).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from common import ROOT, alternate, compile_rbcli, load_avg, med, py, rbcli_cmd  # noqa: E402

GOAL = 1.2
BARE = '''
import sys
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_SOLID
from OCP.TopExp import TopExp_Explorer


def bare(path, density):
    reader = STEPControl_Reader()
    reader.ReadFile(path)
    reader.TransferRoots()
    total, solids = GProp_GProps(), []
    ex = TopExp_Explorer(reader.OneShape(), TopAbs_SOLID)
    while ex.More():
        p = GProp_GProps()
        BRepGProp.VolumeProperties_s(ex.Current(), p)
        c, m = p.CentreOfMass(), p.MatrixOfInertia()
        solids.append((p.Mass(), (c.X(), c.Y(), c.Z()), [[m.Value(i, j) for j in (1, 2, 3)] for i in (1, 2, 3)]))
        total.Add(p, density)
        ex.Next()
    return total.Mass(), solids


if __name__ == "__main__":
    print(bare(sys.argv[1], 7850.0)[0])
'''


def write_assembly(path: Path, n: int) -> None:
    """n distinct solids, named and coloured, each placed and turned, in one assembly (mm)."""
    from OCP.BRepPrimAPI import (BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCone, BRepPrimAPI_MakeCylinder,
                                 BRepPrimAPI_MakeSphere, BRepPrimAPI_MakeTorus)
    from OCP.gp import gp_Ax1, gp_Dir, gp_Pnt, gp_Trsf, gp_Vec
    from OCP.Quantity import Quantity_Color, Quantity_TOC_sRGB
    from OCP.STEPCAFControl import STEPCAFControl_Writer
    from OCP.STEPControl import STEPControl_AsIs
    from OCP.TCollection import TCollection_ExtendedString
    from OCP.TDataStd import TDataStd_Name
    from OCP.TDocStd import TDocStd_Document
    from OCP.TopLoc import TopLoc_Location
    from OCP.XCAFDoc import XCAFDoc_ColorType, XCAFDoc_DocumentTool

    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    tool = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    colours = XCAFDoc_DocumentTool.ColorTool_s(doc.Main())
    top = tool.NewShape()
    TDataStd_Name.Set_s(top, TCollection_ExtendedString("machine"))
    makers = (lambda s: BRepPrimAPI_MakeBox(10 * s, 20, 30).Shape(),
              lambda s: BRepPrimAPI_MakeCylinder(5 * s, 40).Shape(),
              lambda s: BRepPrimAPI_MakeSphere(8 * s).Shape(),
              lambda s: BRepPrimAPI_MakeTorus(20 * s, 4).Shape(),
              lambda s: BRepPrimAPI_MakeCone(10 * s, 2, 30).Shape())
    for i in range(n):
        label = tool.AddShape(makers[i % 5](1 + i / n), False)
        TDataStd_Name.Set_s(label, TCollection_ExtendedString(f"p{i}"))
        colours.SetColor(label, Quantity_Color(i / n, 0.5, 0.2, Quantity_TOC_sRGB),
                         XCAFDoc_ColorType.XCAFDoc_ColorGen)
        turn, move = gp_Trsf(), gp_Trsf()
        turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 1, 1)), 0.1 * i)
        move.SetTranslation(gp_Vec(100 * (i % 10), 100 * (i // 10), 0))
        move.Multiply(turn)
        TDataStd_Name.Set_s(tool.AddComponent(top, label, TopLoc_Location(move)),
                            TCollection_ExtendedString(f"p{i}:1"))
    tool.UpdateAssemblies()
    writer = STEPCAFControl_Writer()
    writer.Transfer(doc, STEPControl_AsIs)
    writer.Write(str(path))


def in_process(path: Path, runs: int) -> dict:
    """CPU and wall seconds of each, alternating in this process (OpenCascade imported)."""
    import rbcli

    space: dict = {}
    exec(BARE, space)
    bare = space["bare"]
    want = bare(str(path), 7850.0)[0]
    got = rbcli.inertia(rbcli.load(str(path), density=7850)).mass
    assert math.isclose(got, want * 1e-9, rel_tol=1e-12), (got, want)  # the model is in mm
    out: dict = {"bare": {"wall": [], "cpu": []}, "rbcli": {"wall": [], "cpu": []}}
    for i in range(runs + 2):
        for name, fn in (("bare", lambda: bare(str(path), 7850.0)),
                         ("rbcli", lambda: rbcli.inertia(rbcli.load(str(path), density=7850)))):
            w, c = time.perf_counter(), time.process_time()
            fn()
            if i >= 2:
                out[name]["wall"].append(time.perf_counter() - w)
                out[name]["cpu"].append(time.process_time() - c)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--solids", type=int, default=100)
    ap.add_argument("--runs", type=int, default=9)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--json", type=Path)
    a = ap.parse_args()
    compile_rbcli()
    data = ROOT / "bench" / "data"
    data.mkdir(parents=True, exist_ok=True)
    path = data / f"assembly{a.solids}.step"
    write_assembly(path, a.solids)
    script = data / "bare_step.py"
    script.write_text(BARE)
    out = {"load_start": load_avg(), "solids": a.solids, "bytes": path.stat().st_size, "rounds": []}
    for _ in range(a.rounds):
        t = in_process(path, a.runs)
        out["rounds"].append({k: {"cpu": med(v["cpu"]), "wall": med(v["wall"])} for k, v in t.items()})
    ratios = [r["rbcli"]["cpu"] / r["bare"]["cpu"] for r in out["rounds"]]
    out["work_ratio"], out["work_ratios"] = med(ratios), ratios
    t = alternate({"rbcli": [*rbcli_cmd(), "inertia", str(path), "--density", "7850", "--json"],
                   "bare": [py(), str(script), str(path)]}, a.runs)
    out["process"] = {k: {"cpu": med(v["cpu"]), "wall": med(v["wall"])} for k, v in t.items()}
    out["load_end"] = load_avg()
    p = out["process"]
    out["ratio"] = p["rbcli"]["cpu"] / p["bare"]["cpu"]
    print(f"{a.solids}-solid assembly ({out['bytes'] / 1e6:.2f} MB), whole processes, CPU: rbcli "
          f"inertia {p['rbcli']['cpu']:.2f} s, python bare script {p['bare']['cpu']:.2f} s: ratio "
          f"{out['ratio']:.2f} (wall {p['rbcli']['wall']:.2f} s / {p['bare']['wall']:.2f} s; goal "
          f"<= {GOAL}: {'met' if out['ratio'] <= GOAL else 'NOT met'})")
    r0 = out["rounds"][len(out["rounds"]) // 2]
    print(f"the work alone, in one process, CPU: rbcli {r0['rbcli']['cpu'] * 1e3:.0f} ms, bare "
          f"{r0['bare']['cpu'] * 1e3:.0f} ms: ratio {out['work_ratio']:.2f} (rounds "
          f"{min(ratios):.2f}-{max(ratios):.2f})")
    if a.json:
        a.json.write_text(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
