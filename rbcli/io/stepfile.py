"""A STEP file (ISO 10303-21, AP203/AP214/AP242) read with OpenCascade: each solid's exact
volume properties from its B-rep, its name, colour and placement in the assembly, and the
file's length unit. Plain data; the body (:mod:`rbcli.body.steppart`) makes parts of it.

OpenCascade (the ``cad`` extra, ``cadquery-ocp-novtk``) is imported inside :func:`read_step`
only. Before it sees the file, :func:`scan` checks what would make it crash, hang or misread
silently, each refused with the line at fault: not a STEP file, truncated, more entities than
the budget, entity references that loop or nest too deep, an assembly that contains itself
or nests more than :data:`MAX_ASSEMBLY_DEPTH` levels (README, "Budgets").
"""

from __future__ import annotations

import io
import itertools
import re
from dataclasses import dataclass

from rbcli.io.reader import limit_from_env, read_regular

__all__ = ["StepError", "Solid", "StepFile", "read_step", "scan", "SUFFIXES"]

SUFFIXES = (".step", ".stp")
MAX_STEP_BYTES = 128 << 20  # RBCLI_MAX_STEP_BYTES
MAX_ENTITIES = 1_000_000  # RBCLI_MAX_STEP_ENTITIES: ~3 s and ~650 MB in OpenCascade
MAX_ASSEMBLY_DEPTH = 64
#: entity references nested deeper than this (a B-rep needs ~12) are refused: OpenCascade
#: follows them recursively
MAX_REF_DEPTH = 1000
#: the file's length unit as OpenCascade names it -> as rbcli writes it
UNIT_NAMES = {"millimetre": "mm", "millimeter": "mm", "metre": "m", "meter": "m",
              "centimetre": "cm", "centimeter": "cm", "micrometre": "um", "micrometer": "um",
              "kilometre": "km", "kilometer": "km", "inch": "in", "foot": "ft", "mil": "mil",
              "yard": "yd", "mile": "mi"}
_METRES = {"mm": 1e-3, "m": 1.0, "cm": 1e-2, "um": 1e-6, "km": 1e3, "in": 0.0254,
           "ft": 0.3048, "mil": 2.54e-5, "yd": 0.9144, "mi": 1609.344}
_COMMENT = re.compile(rb"/\*.*?\*/", re.S)
_STRING = re.compile(rb"'[^']*'")  # ('' inside a string: two strings side by side)
#: an entity instance (strings emptied): its number, its type (empty: complex), parameters
_ENTITY = re.compile(rb"#(\d+)\s*=\s*([A-Z_0-9]*)([^;]*);")
_REF = re.compile(rb"#(\d+)")


class StepError(ValueError):
    """A STEP file that is not read: ``message`` (lower case, no file name) and the 1-based
    ``line`` at fault, or None."""

    def __init__(self, message: str, line: int | None = None) -> None:
        super().__init__(message)
        self.line = line


@dataclass(frozen=True)
class Solid:
    """One solid placed in the file's assembly, in the file's length unit.

    Attributes
    ----------
    name : str — unique: the instance names from the top (``link:1/pin``)
    volume : float — its volume, unit³
    centroid : (3,) tuple — its centre of volume in its own part's frame, unit
    inertia : (3, 3) tuple — its second moments of volume about the centroid, own axes,
        tensor convention (off-diagonals −∫xy dV), unit⁵: the inertia at unit density
    R, t : (3, 3), (3,) tuples — where the assembly puts the part: x -> R x + t (R a rotation
        or a reflection)
    colour : str | None — ``#rrggbb`` (sRGB) of the solid, its part or its first face
    healed : float | None — where OpenCascade had to heal the solid (ShapeFix), the relative
        change of its volume: a bound on what healing changed
    """

    name: str
    volume: float
    centroid: tuple
    inertia: tuple
    R: tuple
    t: tuple
    colour: str | None = None
    healed: float | None = None


@dataclass(frozen=True)
class StepFile:
    """What :func:`read_step` found: ``solids``; ``unit`` the file's length unit (``mm``)
    and ``metres`` its size (None: the file names none rbcli knows); ``empty`` the names of
    assembly nodes and parts that hold no solid."""

    solids: tuple[Solid, ...]
    unit: str | None
    metres: float | None
    empty: tuple[str, ...]


def _line(data: bytes, pos: int) -> int:
    return data.count(b"\n", 0, pos) + 1


def _deepest(graph: dict, limit: int) -> tuple[str, bytes] | None:
    """The first cycle (``("cycle", a node on it)``) or path of more than ``limit`` links
    (``("deep", its top)``) in ``graph`` (node -> successors), by an iterative depth-first
    walk; None when neither."""
    depth: dict = {}  # finished nodes: the longest path from each, in nodes
    for root in graph:
        if root in depth:
            continue
        stack, on_path = [[root, iter(graph[root]), 0]], {root}
        while stack:
            top = stack[-1]
            for nxt in top[1]:
                if nxt in on_path:
                    return "cycle", top[0]
                d = depth.get(nxt)
                if d is None and nxt in graph:
                    on_path.add(nxt)
                    stack.append([nxt, iter(graph[nxt]), 0])
                    break
                top[2] = max(top[2], d or 1)  # a node with no successors: 1
            else:
                node, _, below = stack.pop()
                on_path.discard(node)
                depth[node] = below + 1
                if below > limit:  # ``below`` links under it
                    return "deep", node
                if stack:
                    stack[-1][2] = max(stack[-1][2], below + 1)
    return None


def scan(data: bytes, max_entities: int) -> None:
    """Check STEP text before OpenCascade reads it (see the module's docstring).

    Raises
    ------
    StepError
        What is wrong and its line.
    """
    text = _STRING.sub(b"''", _COMMENT.sub(b"", data))
    if not text.lstrip().startswith(b"ISO-10303-21;"):
        raise StepError("not a STEP file: it does not start with 'ISO-10303-21;'", 1)
    start, end = text.find(b"\nDATA;"), text.rfind(b"END-ISO-10303-21;")
    if start < 0 or end < start:
        raise StepError("the file is truncated or malformed: no DATA section ending in "
                        "'ENDSEC; END-ISO-10303-21;'", _line(data, len(data)))
    entities = _ENTITY.findall(text, start, end)
    if len(entities) > max_entities:
        raise StepError(f"more than {max_entities} entities (set RBCLI_MAX_STEP_ENTITIES to "
                        "raise the limit)", _where(data, entities[max_entities][0]))
    seen: set[bytes] = set()
    if len({n for n, _, _ in entities}) < len(entities):  # which one, only then
        twice = next(n for n, _, _ in entities if n in seen or seen.add(n))
        raise StepError(f"entity #{twice.decode()} is defined twice", _where(data, twice, 2))
    refs = {n: _REF.findall(p) for n, _, p in entities if b"#" in p}
    assembly: dict[bytes, list[bytes]] = {}
    for n, kind, _ in entities:
        if kind == b"NEXT_ASSEMBLY_USAGE_OCCURRENCE" and len(refs.get(n, ())) >= 2:
            assembly.setdefault(refs[n][0], []).append(refs[n][1])  # relating -> related
    for graph, limit, what in ((refs, MAX_REF_DEPTH, "entity references"),
                               (assembly, MAX_ASSEMBLY_DEPTH, "assemblies")):
        found = _deepest(graph, limit)
        if found:
            kind, n = found[0], found[1].decode()
            message = (f"entity #{n} refers to itself through other entities" if graph is refs
                       else f"the assembly of product definition #{n} contains itself")
            if kind == "deep":
                message = f"{what} are nested more than {limit} deep (at #{n})"
            raise StepError(message, _where(data, found[1]))


def _where(data: bytes, number: bytes, nth: int = 1) -> int:
    """The line where entity ``#number`` is defined (the ``nth`` time)."""
    found = list(itertools.islice(re.finditer(rb"#%s\s*=" % number, data), nth))
    return _line(data, found[-1].start() if found else 0)


def read_step(path: str, max_solids: int) -> StepFile:
    """The solids of the STEP file ``path`` (see :class:`Solid`), at most ``max_solids``
    placed (every use of a part counts).

    Raises
    ------
    rbcli.io.reader.ReadError
        Not a regular file, or larger than ``RBCLI_MAX_STEP_BYTES`` (default 128 MiB).
    StepError
        :func:`scan`'s refusals; a file OpenCascade cannot read or that holds no solid; a
        solid that is not valid and that OpenCascade cannot heal; more than ``max_solids``.
    ImportError
        OpenCascade is not installed.
    """
    data = read_regular(path, limit_from_env("RBCLI_MAX_STEP_BYTES", MAX_STEP_BYTES),
                        "STEP file", env="RBCLI_MAX_STEP_BYTES")
    scan(data, limit_from_env("RBCLI_MAX_STEP_ENTITIES", MAX_ENTITIES))
    from OCP.Message import Message  # the cad extra; ~0.5 s, on this path only

    messenger = Message.DefaultMessenger_s()
    printers = list(messenger.Printers())  # OpenCascade prints to stdout: silenced meanwhile
    for p in printers:
        messenger.RemovePrinter(p)
    try:
        return _Reader(max_solids).read(data)
    finally:
        for p in printers:
            messenger.AddPrinter(p)


class _Reader:
    """One read: the XDE document, the walk over its assembly tree, the solids' properties
    (once per distinct part, whatever its uses)."""

    def __init__(self, max_solids: int) -> None:
        self.max_solids = max_solids
        self.solids: list[Solid] = []
        self.empty: list[str] = []
        self.props: dict = {}  # a part's label entry -> its solids' properties

    def read(self, data: bytes) -> StepFile:
        from OCP.collections import Sequence_TCollection_AsciiString as Names
        from OCP.collections import Sequence_TDF_Label as Labels
        from OCP.IFSelect import IFSelect_RetDone
        from OCP.STEPCAFControl import STEPCAFControl_Reader
        from OCP.TCollection import TCollection_ExtendedString
        from OCP.TDocStd import TDocStd_Document
        from OCP.TopLoc import TopLoc_Location
        from OCP.XCAFDoc import XCAFDoc_DocumentTool

        reader = STEPCAFControl_Reader()
        reader.SetNameMode(True)
        reader.SetColorMode(True)
        if reader.ReadStream("step", io.BytesIO(data)) != IFSelect_RetDone:
            raise StepError("OpenCascade cannot read the file (a syntax error?)")
        names = Names(), Names(), Names()
        reader.Reader().FileUnits(*names)
        units = list(dict.fromkeys(UNIT_NAMES.get(n.ToCString().lower(), n.ToCString())
                                   for n in names[0]))
        unit = units[0] if len(units) == 1 else (", ".join(units) or None)
        doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
        metres = _METRES.get(unit) if unit else None
        XCAFDoc_DocumentTool.SetLengthUnit_s(doc, metres or 1e-3)  # numbers as the file has them
        if not reader.Transfer(doc):
            raise StepError("OpenCascade cannot make shapes of the file's entities")
        self.shapes = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
        self.colours = XCAFDoc_DocumentTool.ColorTool_s(doc.Main())
        free = Labels()
        self.shapes.GetFreeShapes(free)
        tops = list(free)
        if len(tops) == 1 and self.shapes.IsAssembly_s(tops[0]):  # one assembly: its parts
            tops = self._components(tops[0])
        else:
            tops = [(lab, lab, TopLoc_Location()) for lab in tops]
        self._walk(tops, "")
        if not self.solids:
            raise StepError("the file holds no solid" + (f" ({', '.join(self.empty[:3])}: no "
                            "volume)" if self.empty else ""))
        return StepFile(tuple(self.solids), unit, metres, tuple(self.empty))

    def _components(self, label) -> list:
        """(instance label, part label, placement) of each component of an assembly."""
        from OCP.collections import Sequence_TDF_Label as Labels
        from OCP.TDF import TDF_Label

        comps = Labels()
        self.shapes.GetComponents_s(label, comps)
        out = []
        for c in comps:
            ref = TDF_Label()
            self.shapes.GetReferredShape_s(c, ref)
            out.append((c, ref, self.shapes.GetLocation_s(c)))
        return out

    def _walk(self, items: list, prefix: str, depth: int = 0, loc=None) -> None:
        """The solids of ``items`` (instance, part, placement), named ``prefix`` + unique
        instance names, depth first (the depth is bounded by :func:`scan`)."""
        names = [_name(inst) or _name(ref) or "solid" for inst, ref, _ in items]
        seen: dict[str, int] = {}
        for (inst, ref, place), name in zip(items, names):
            if names.count(name) > 1:
                seen[name] = seen.get(name, 0) + 1
                name = f"{name}:{seen[name]}"
            here = place if loc is None else loc.Multiplied(place)
            if self.shapes.IsAssembly_s(ref):
                self._walk(self._components(ref), f"{prefix}{name}/", depth + 1, here)
            else:
                self._part(inst, ref, prefix + name, here)

    def _part(self, inst, ref, name: str, loc) -> None:
        solids = self._properties(ref, name)
        if not solids:
            self.empty.append(name)
        R, t = _placement(loc)
        colour = _colour(inst) or _colour(ref)
        for i, (vol, com, J, healed, col) in enumerate(solids):
            if len(self.solids) >= self.max_solids:
                raise StepError(f"the assembly places more than {self.max_solids} solids (every "
                                "use of a part counts); set RBCLI_MAX_PARTS to raise the limit")
            shown = f"{name}[{i + 1}]" if len(solids) > 1 else name
            self.solids.append(Solid(shown, vol, com, J, R, t, colour or col, healed))

    def _properties(self, label, name: str) -> list:
        """(volume, centroid, inertia, healed, colour) of each solid of a part (its closed
        shells made solids), computed once per part."""
        from OCP.TDF import TDF_Tool
        from OCP.TCollection import TCollection_AsciiString

        entry = TCollection_AsciiString()
        TDF_Tool.Entry_s(label, entry)
        key = entry.ToCString()
        if key not in self.props:
            self.props[key] = [(*_solid(s, name), _face_colour(self.colours, s))
                               for s in _solids(self.shapes.GetShape_s(label), name)]
        return self.props[key]


def _name(label) -> str:
    from OCP.TDataStd import TDataStd_Name

    n = TDataStd_Name()
    if not label.FindAttribute(TDataStd_Name.GetID_s(), n):
        return ""
    text = n.Get().ToExtString().strip()
    return "" if text.startswith("=>[") else text  # OpenCascade's name of an unnamed instance


def _colour(label, tool=None) -> str | None:
    """``#rrggbb`` of a label (or, with its colour ``tool``, of a shape), or None."""
    from OCP.Quantity import Quantity_Color, Quantity_TOC_sRGB
    from OCP.XCAFDoc import XCAFDoc_ColorTool, XCAFDoc_ColorType

    c = Quantity_Color()
    for kind in (XCAFDoc_ColorType.XCAFDoc_ColorGen, XCAFDoc_ColorType.XCAFDoc_ColorSurf):
        if (tool.GetColor(label, kind, c) if tool else XCAFDoc_ColorTool.GetColor_s(label, kind, c)):
            return "#" + "".join(f"{round(255 * v):02x}" for v in c.Values(Quantity_TOC_sRGB))
    return None


def _face_colour(tool, solid) -> str | None:
    """The colour of the solid, else of its first face that has one."""
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer

    found = _colour(solid, tool)
    ex = TopExp_Explorer(solid, TopAbs_FACE)
    while found is None and ex.More():
        found = _colour(ex.Current(), tool)
        ex.Next()
    return found


def _placement(loc) -> tuple:
    trsf = loc.Transformation()
    if abs(abs(trsf.ScaleFactor()) - 1.0) > 1e-12:
        raise StepError(f"an instance is scaled by {trsf.ScaleFactor():g}; rbcli reads rigid "
                        "placements only")
    R = tuple(tuple(trsf.Value(i, j) for j in (1, 2, 3)) for i in (1, 2, 3))
    return R, tuple(trsf.Value(i, 4) for i in (1, 2, 3))


def _solids(shape, name: str) -> list:
    """The solids of a part's shape; its closed shells made solids; an open shell refused."""
    from OCP.BRep import BRep_Tool
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeSolid
    from OCP.TopAbs import TopAbs_SHELL, TopAbs_SOLID
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS

    out = []
    ex = TopExp_Explorer(shape, TopAbs_SOLID)
    while ex.More():
        out.append(ex.Current())
        ex.Next()
    ex = TopExp_Explorer(shape, TopAbs_SHELL, TopAbs_SOLID)  # shells outside any solid
    while ex.More():
        shell = TopoDS.Shell(ex.Current())
        if not BRep_Tool.IsClosed_s(shell):
            raise StepError(f"part '{name}': a shell that does not close a volume (a surface "
                            "model); export the part as a solid")
        out.append(BRepBuilderAPI_MakeSolid(shell).Solid())
        ex.Next()
    return out


def _solid(solid, name: str) -> tuple:
    """(volume, centroid, inertia, healed) of one solid: OpenCascade's exact volume
    integrals over its B-rep; an invalid solid healed by ShapeFix if it can be."""
    from OCP.BRepCheck import BRepCheck_Analyzer
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps
    from OCP.ShapeFix import ShapeFix_Shape

    def props(s):
        p = GProp_GProps()
        BRepGProp.VolumeProperties_s(s, p)
        return p

    p, healed = props(solid), None
    if not BRepCheck_Analyzer(solid).IsValid() or not p.Mass() > 0:
        fix = ShapeFix_Shape(solid)
        fix.Perform()
        fixed = fix.Shape()
        q = props(fixed)
        if not (BRepCheck_Analyzer(fixed).IsValid() and q.Mass() > 0):
            raise StepError(f"solid '{name}' is not a valid solid (open, self-intersecting or "
                            "inside out) and OpenCascade cannot heal it")
        healed = abs(q.Mass() - abs(p.Mass())) / q.Mass()
        p = q
    c, m = p.CentreOfMass(), p.MatrixOfInertia()
    J = tuple(tuple(m.Value(i, j) for j in (1, 2, 3)) for i in (1, 2, 3))
    return p.Mass(), (c.X(), c.Y(), c.Z()), J, healed
