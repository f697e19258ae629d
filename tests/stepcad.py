"""STEP files for the tests, built with OpenCascade (import after ``pytest.importorskip("OCP")``)
and STEP text generated for the hostile corpus (no OpenCascade needed).

Solids are made in rbcli's local frames (centred, symmetry axis z; a cone and a hemisphere
with their base at the origin), so that each is the rbcli shape of the same parameters.
"""

from __future__ import annotations

import math
from pathlib import Path

from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut
from OCP.BRepPrimAPI import (BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCone, BRepPrimAPI_MakeCylinder,
                             BRepPrimAPI_MakeSphere, BRepPrimAPI_MakeTorus)
from OCP.gp import gp_Ax1, gp_Ax2, gp_Dir, gp_Pnt, gp_Trsf, gp_Vec
from OCP.Interface import Interface_Static
from OCP.Message import Message
from OCP.Quantity import Quantity_Color, Quantity_TOC_sRGB
from OCP.STEPCAFControl import STEPCAFControl_Writer
from OCP.STEPControl import STEPControl_AsIs
from OCP.TCollection import TCollection_ExtendedString
from OCP.TDataStd import TDataStd_Name
from OCP.TDocStd import TDocStd_Document
from OCP.TopLoc import TopLoc_Location
from OCP.XCAFDoc import XCAFDoc_ColorType, XCAFDoc_DocumentTool


def _cut(a, *holes):
    for h in holes:
        a = BRepAlgoAPI_Cut(a, h).Shape()
    return a


def _cyl(R, L, x=0.0, y=0.0):
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, -L / 2), gp_Dir(0, 0, 1)), R, L).Shape()


def box(a, b, c):
    return BRepPrimAPI_MakeBox(gp_Pnt(-a / 2, -b / 2, -c / 2), a, b, c).Shape()


def cylinder(R, L, r=0.0):
    return _cut(_cyl(R, L), *([_cyl(r, L)] if r else []))


def sphere(R, r=0.0):
    return _cut(BRepPrimAPI_MakeSphere(R).Shape(), *([BRepPrimAPI_MakeSphere(r).Shape()] if r else []))


def hemisphere(R):
    return BRepPrimAPI_MakeSphere(R, 0.0, math.pi / 2).Shape()


def cone(R, h):
    return BRepPrimAPI_MakeCone(R, 0.0, h).Shape()


def torus(R, r):
    return BRepPrimAPI_MakeTorus(R, r).Shape()


def plate(a, b, t, holes):
    """A box a × b × t with through holes ``(radius, x, y)``."""
    return _cut(box(a, b, t), *(_cyl(r, 2 * t, x, y) for r, x, y in holes))


def placed(x=0.0, y=0.0, z=0.0, angle=0.0, axis=(0, 0, 1)) -> TopLoc_Location:
    """x -> R x + t: a rotation by ``angle`` degrees about ``axis``, then (x, y, z)."""
    t, r = gp_Trsf(), gp_Trsf()
    r.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(*axis)), math.radians(angle))
    t.SetTranslation(gp_Vec(x, y, z))
    t.Multiply(r)
    return TopLoc_Location(t)


def write(path: str | Path, tree: list, unit: str = "MM") -> Path:
    """Write an assembly to a STEP file: ``tree`` is a list of ``(name, node, placement,
    colour)``, a node a shape or a list (a sub-assembly); the same shape or list object used
    twice is one part used twice. One entry and no list: a file of one part."""
    doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
    shapes = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    colours = XCAFDoc_DocumentTool.ColorTool_s(doc.Main())
    labels: dict[int, object] = {}

    def name(label, text):
        TDataStd_Name.Set_s(label, TCollection_ExtendedString(text))

    def label_of(entry):
        text, node, _loc, colour = entry
        if id(node) not in labels:
            if isinstance(node, list):
                lab = shapes.NewShape()
                for child in node:
                    name(shapes.AddComponent(lab, label_of(child), child[2]), child[0])
            else:
                lab = shapes.AddShape(node, False)
            name(lab, text.split(":")[0])
            if colour:
                colours.SetColor(lab, Quantity_Color(*colour, Quantity_TOC_sRGB),
                                 XCAFDoc_ColorType.XCAFDoc_ColorGen)
            labels[id(node)] = lab
        return labels[id(node)]

    if len(tree) == 1 and not isinstance(tree[0][1], list) and tree[0][2] is None:
        label_of(tree[0])
    else:
        label_of(("root", tree, None, None))
    shapes.UpdateAssemblies()
    messenger = Message.DefaultMessenger_s()
    printers = list(messenger.Printers())
    for p in printers:  # the writer prints statistics
        messenger.RemovePrinter(p)
    try:
        w = STEPCAFControl_Writer()  # first: it registers the static that the next line sets
        Interface_Static.SetCVal_s("write.step.unit", unit)
        w.Transfer(doc, STEPControl_AsIs)
        w.Write(str(path))
    finally:
        Interface_Static.SetCVal_s("write.step.unit", "MM")
        for p in printers:
            messenger.AddPrinter(p)
    return Path(path)


def arm(path: str | Path) -> Path:
    """The example arm (examples/step_arm.step, mm): a base, two uses of the link
    sub-assembly (an upper plate with two holes, a pin) and a tool, with colours."""
    link = [("upper", plate(100, 20, 10, [(4, -40, 0), (4, 40, 0)]), placed(40, 0, 5), (0.75, 0.75, 0.8)),
            ("pin", cylinder(5, 30), placed(0, 0, 15), None)]
    return write(path, [
        ("base", cylinder(40, 20, 10), placed(0, 0, 10), (0.2, 0.2, 0.25)),
        ("link:1", link, placed(0, 0, 20, 30), None),
        ("link:2", link, placed(80 * math.cos(math.radians(30)), 80 * math.sin(math.radians(30)),
                                30, 75), None),
        ("tool", sphere(10), placed(100, 120, 45), (0.9, 0.4, 0.1)),
    ])


# ----------------------------------------------------------------------------- STEP text


def nested(one: str, depth: int, cycle: bool = False) -> str:
    """A file of one solid (``one``, written by :func:`write`: its product definition #5,
    representation #10, axis placement #11, contexts #2 #8 #9 and geometric context found
    below) placed ``depth`` assemblies deep; ``cycle``: the outermost also inside the
    innermost."""
    head, tail = one.split("ENDSEC;\nEND-ISO-10303-21;")
    ctx = head.split("#10 = ADVANCED_BREP_SHAPE_REPRESENTATION(")[1].split(")")[1].strip(",;")
    lines, child_pd, child_rep, base = [], 5, 10, 10_000_000
    for i in range(depth + cycle):
        a = base + 20 * i
        last = cycle and i == depth
        if not last:
            lines += [f"#{a+1} = SHAPE_DEFINITION_REPRESENTATION(#{a+2},#{a+8});",
                      f"#{a+2} = PRODUCT_DEFINITION_SHAPE('','',#{a+3});",
                      f"#{a+3} = PRODUCT_DEFINITION('design','',#{a+4},#9);",
                      f"#{a+4} = PRODUCT_DEFINITION_FORMATION('','',#{a+5});",
                      f"#{a+5} = PRODUCT('level{i}','level{i}','',(#8));",
                      f"#{a+8} = SHAPE_REPRESENTATION('',(#11),{ctx});"]
        parent_pd, parent_rep = (base + 3, base + 8) if last else (a + 3, a + 8)
        lines += [f"#{a+9} = CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(#{a+10},#{a+12});",
                  f"#{a+10} = ( REPRESENTATION_RELATIONSHIP('','',#{child_rep},#{parent_rep}) "
                  f"REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#{a+11}) "
                  "SHAPE_REPRESENTATION_RELATIONSHIP() );",
                  f"#{a+11} = ITEM_DEFINED_TRANSFORMATION('','',#11,#11);",
                  f"#{a+12} = PRODUCT_DEFINITION_SHAPE('Placement','',#{a+13});",
                  f"#{a+13} = NEXT_ASSEMBLY_USAGE_OCCURRENCE('{i}','inst{i}','',#{parent_pd},"
                  f"#{child_pd},$);"]
        child_pd, child_rep = a + 3, a + 8
    return head + "\n".join(lines) + "\nENDSEC;\nEND-ISO-10303-21;" + tail
