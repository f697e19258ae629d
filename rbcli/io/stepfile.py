"""A STEP file read with OpenCascade (the ``cad`` extra, imported by :func:`read_step` only):
each solid's volume properties from its B-rep, name, colour and placement, and the file's
length unit. :func:`scan` first refuses, with the line at fault, what would make OpenCascade
crash, hang or drop solids silently (README, "Budgets").
"""

from __future__ import annotations

import importlib
import io
import re
from dataclasses import dataclass
from types import SimpleNamespace

from rbcli.io.reader import limit_from_env, read_regular

__all__ = ["StepError", "Solid", "StepFile", "read_step", "scan"]

MAX_STEP_BYTES = 128 << 20  # RBCLI_MAX_STEP_BYTES
MAX_ENTITIES = 1_000_000  # RBCLI_MAX_STEP_ENTITIES: ~3 s, ~650 MB
MAX_ASSEMBLY_DEPTH = 64
#: a length unit as OpenCascade names it (lower case): as rbcli writes it, in m
UNITS = {"millimetre": ("mm", 1e-3), "metre": ("m", 1.0), "centimetre": ("cm", 1e-2),
         "inch": ("in", 0.0254), "foot": ("ft", 0.3048)}
_COMMENT = re.compile(rb"/\*.*?\*/", re.S)
_STRING = re.compile(rb"'[^']*'")  # ('' in a string: two strings side by side)
#: an entity (strings emptied): number, type (empty: complex), parameters
_ENTITY = re.compile(rb"#(\d+)\s*=\s*([A-Z_0-9]*)([^;]*);")
_REF = re.compile(rb"#(\d+)")


class StepError(ValueError):
    """A STEP file that is not read: the message (no file name) and the ``line`` at fault."""

    def __init__(self, message: str, line: int | None = None) -> None:
        super().__init__(message)
        self.line = line


@dataclass(frozen=True)
class Solid:
    """A solid (m): its instance path (``link:1/pin``); volume, centroid and inertia (the
    tensor at unit density) in its part's frame, placed x -> R x + t; colour ``#rrggbb``."""

    name: str
    volume: float
    centroid: tuple
    inertia: tuple
    R: tuple
    t: tuple
    colour: str | None = None


@dataclass(frozen=True)
class StepFile:
    """The solids, the file's ``unit`` and its ``metres`` (None: unknown), the nodes with no
    solid."""

    solids: tuple[Solid, ...]
    unit: str | None
    metres: float | None
    empty: tuple[str, ...]


def _line(data: bytes, pos: int) -> int:
    return data.count(b"\n", 0, pos) + 1


def _deepest(graph: dict, limit: int) -> tuple[str, bytes] | None:
    """``("cycle", a node on it)``, ``("deep", the top of a path of over limit links)`` or
    None, of ``graph`` (node -> successors), depth first."""
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
    """Check STEP text before OpenCascade reads it; a :class:`StepError` says what and where."""
    text = _STRING.sub(b"''", _COMMENT.sub(b"", data))
    if not text.lstrip().startswith(b"ISO-10303-21;"):
        raise StepError("not a STEP file: it does not start with 'ISO-10303-21;'", 1)
    start, end = text.find(b"\nDATA;"), text.rfind(b"END-ISO-10303-21;")
    if start < 0 or end < start:
        raise StepError("truncated or malformed: no DATA section before 'END-ISO-10303-21;'",
                        _line(data, len(data)))
    entities = _ENTITY.findall(text, start, end)
    if len(entities) > max_entities:
        raise StepError(f"more than {max_entities} entities (set RBCLI_MAX_STEP_ENTITIES to "
                        "raise the limit)", _where(data, entities[max_entities][0]))
    seen: set[bytes] = set()
    if len({n for n, _, _ in entities}) < len(entities):  # which one, only then
        twice = next(n for n, _, _ in entities if n in seen or seen.add(n))
        raise StepError(f"#{twice.decode()} is defined twice", _where(data, twice))
    refs = {n: _REF.findall(p) for n, _, p in entities if b"#" in p}
    assembly: dict[bytes, list[bytes]] = {}
    for n, kind, _ in entities:
        if kind == b"NEXT_ASSEMBLY_USAGE_OCCURRENCE" and len(refs.get(n, ())) >= 2:
            assembly.setdefault(refs[n][0], []).append(refs[n][1])  # relating -> related
    for graph, limit, what in ((refs, len(refs), "references"),
                               (assembly, MAX_ASSEMBLY_DEPTH, "assemblies")):
        found = _deepest(graph, limit)
        if found:
            n = found[1].decode()
            raise StepError(f"{what} are nested more than {limit} deep (at #{n})" if found[0] ==
                            "deep" else f"#{n} contains itself ({what} loop)", _where(data, found[1]))


def _where(data: bytes, number: bytes) -> int:
    """The line where entity ``#number`` is defined."""
    found = re.search(rb"#%s\s*=" % number, data)
    return _line(data, found.start() if found else 0)


def read_step(path: str, max_solids: int) -> StepFile:
    """The solids of the STEP file ``path``, at most ``max_solids`` placed (each use counts);
    a :class:`rbcli.io.reader.ReadError`, :class:`StepError` or ``ImportError``."""
    data = read_regular(path, limit_from_env("RBCLI_MAX_STEP_BYTES", MAX_STEP_BYTES),
                        "STEP file", env="RBCLI_MAX_STEP_BYTES")
    scan(data, limit_from_env("RBCLI_MAX_STEP_ENTITIES", MAX_ENTITIES))
    ocp = SimpleNamespace()  # OpenCascade's names (~0.5 s, on this path only)
    for m in ("BRep", "BRepBuilderAPI", "BRepGProp", "GProp", "IFSelect", "Message", "Quantity",
              "STEPCAFControl", "TCollection", "TDataStd", "TDF", "TDocStd", "TopAbs", "TopExp",
              "TopLoc", "TopoDS", "XCAFDoc", "collections"):
        vars(ocp).update(vars(importlib.import_module(f"OCP.{m}")))
    messenger = ocp.Message.DefaultMessenger_s()
    printers = list(messenger.Printers())  # it prints to stdout: silenced meanwhile
    for p in printers:
        messenger.RemovePrinter(p)
    try:
        return _Reader(ocp, max_solids).read(data)
    finally:
        for p in printers:
            messenger.AddPrinter(p)


class _Reader:
    """One read (``o``: OpenCascade's names): the assembly walked, each part's solids
    integrated once."""

    def __init__(self, o: SimpleNamespace, max_solids: int) -> None:
        self.o, self.max_solids = o, max_solids
        self.solids: list[Solid] = []
        self.empty: list[str] = []
        self.props: dict = {}  # a part's label entry -> its solids' properties

    def read(self, data: bytes) -> StepFile:
        o = self.o
        reader = o.STEPCAFControl_Reader()
        reader.SetNameMode(True)
        reader.SetColorMode(True)
        if reader.ReadStream("step", io.BytesIO(data)) != o.IFSelect_RetDone:
            raise StepError("OpenCascade cannot read it (a syntax error?)")
        names = [o.Sequence_TCollection_AsciiString() for _ in range(3)]
        reader.Reader().FileUnits(*names)
        found = list(dict.fromkeys(UNITS.get(n.ToCString().lower(), (n.ToCString(), None))
                                   for n in names[0]))
        unit, metres = found[0] if len(found) == 1 else (", ".join(u for u, _ in found), None)
        doc = o.TDocStd_Document(o.TCollection_ExtendedString("XmlOcaf"))
        o.XCAFDoc_DocumentTool.SetLengthUnit_s(doc, 1.0)  # lengths in m
        if not reader.Transfer(doc):
            raise StepError("OpenCascade makes no shape of it")
        self.shapes = o.XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
        self.colours = o.XCAFDoc_DocumentTool.ColorTool_s(doc.Main())
        free = o.Sequence_TDF_Label()
        self.shapes.GetFreeShapes(free)
        tops = list(free)
        if len(tops) == 1 and self.shapes.IsAssembly_s(tops[0]):  # its parts, unprefixed
            self._walk(self._components(tops[0]), "")
        else:
            self._walk([(lab, lab, o.TopLoc_Location()) for lab in tops], "")
        if not self.solids:
            raise StepError("the file holds no solid")
        return StepFile(tuple(self.solids), unit, metres, tuple(self.empty))

    def _components(self, label) -> list:
        """(instance, part, placement) of each component of an assembly."""
        comps, out = self.o.Sequence_TDF_Label(), []
        self.shapes.GetComponents_s(label, comps)
        for c in comps:
            ref = self.o.TDF_Label()
            self.shapes.GetReferredShape_s(c, ref)
            out.append((c, ref, self.shapes.GetLocation_s(c)))
        return out

    def _walk(self, items: list, prefix: str, loc=None) -> None:
        """The solids of ``items`` (instance, part, placement), named ``prefix`` + unique
        instance names (:func:`scan` bounds the depth)."""
        names = [self._name(inst) or self._name(ref) or "solid" for inst, ref, _ in items]
        seen: dict[str, int] = {}
        for (inst, ref, place), name in zip(items, names):
            if names.count(name) > 1:
                seen[name] = seen.get(name, 0) + 1
                name = f"{name}:{seen[name]}"
            here = place if loc is None else loc.Multiplied(place)
            if self.shapes.IsAssembly_s(ref):
                self._walk(self._components(ref), f"{prefix}{name}/", here)
                continue
            solids = self._integrals(ref, prefix + name)
            if not solids:
                self.empty.append(prefix + name)
            trsf = here.Transformation()  # rigid: OpenCascade's locations hold no scale
            R = tuple(tuple(trsf.Value(i, j) for j in (1, 2, 3)) for i in (1, 2, 3))
            t = tuple(trsf.Value(i, 4) for i in (1, 2, 3))
            colour = self._colour(inst) or self._colour(ref)
            for i, (vol, com, J, solid) in enumerate(solids):
                if len(self.solids) >= self.max_solids:
                    raise StepError(f"more than {self.max_solids} solids (each use counts); "
                                    "set RBCLI_MAX_PARTS to raise the limit")
                shown = f"{prefix}{name}[{i + 1}]" if len(solids) > 1 else prefix + name
                self.solids.append(Solid(shown, vol, com, J, R, t,
                                         colour or self._face_colour(solid)))

    def _name(self, label) -> str:
        n = self.o.TDataStd_Name()
        if not label.FindAttribute(self.o.TDataStd_Name.GetID_s(), n):
            return ""
        text = n.Get().ToExtString().strip()
        return "" if text.startswith("=>[") else text  # what OpenCascade calls an unnamed one

    def _colour(self, label, shape: bool = False) -> str | None:
        """``#rrggbb`` of a label (or a shape), or None."""
        o, c = self.o, self.o.Quantity_Color()
        for kind in (o.XCAFDoc_ColorType.XCAFDoc_ColorGen, o.XCAFDoc_ColorType.XCAFDoc_ColorSurf):
            if (self.colours.GetColor if shape else o.XCAFDoc_ColorTool.GetColor_s)(label, kind, c):
                return "#" + "".join(f"{round(255 * v):02x}" for v in c.Values(o.Quantity_TOC_sRGB))
        return None

    def _face_colour(self, solid) -> str | None:
        """A solid's colour, else its first face's."""
        return next((c for f in [solid, *self._shapes(solid, self.o.TopAbs_FACE)]
                     if (c := self._colour(f, True))), None)

    def _shapes(self, shape, kind, avoid=None) -> list:
        """The sub-shapes of ``shape`` of ``kind`` (those not inside an ``avoid``)."""
        o, out = self.o, []
        ex = o.TopExp_Explorer(shape, kind, *([avoid] if avoid is not None else []))
        while ex.More():
            out.append(ex.Current())
            ex.Next()
        return out

    def _integrals(self, label, name: str) -> list:
        """(volume, centroid, inertia, solid) of each solid of a part (its shells made solids),
        once a part: the volume integrals over its B-rep; an open shell or solid refused."""
        entry = self.o.TCollection_AsciiString()
        self.o.TDF_Tool.Entry_s(label, entry)
        if entry.ToCString() in self.props:
            return self.props[entry.ToCString()]
        o, shape, out = self.o, self.shapes.GetShape_s(label), []
        shells = self._shapes(shape, o.TopAbs_SHELL, o.TopAbs_SOLID)  # in no solid
        for solid in self._shapes(shape, o.TopAbs_SOLID) + shells:
            p = o.GProp_GProps()
            if solid.ShapeType() == o.TopAbs_SHELL and self._closed(solid):
                solid = o.BRepBuilderAPI_MakeSolid(o.TopoDS.Shell(solid)).Solid()
            o.BRepGProp.VolumeProperties_s(solid, p)
            if not (self._closed(solid) and p.Mass() > 0):
                raise StepError(f"part '{name}': a shell that does not close a volume (a surface "
                                "model, or inside out); export it as a solid")
            c, m = p.CentreOfMass(), p.MatrixOfInertia()
            J = tuple(tuple(m.Value(i, j) for j in (1, 2, 3)) for i in (1, 2, 3))
            out.append((p.Mass(), (c.X(), c.Y(), c.Z()), J, solid))
        self.props[entry.ToCString()] = out
        return out

    def _closed(self, shape) -> bool:
        """Whether each shell of ``shape`` closes (every edge between two of its faces)."""
        return all(self.o.BRep_Tool.IsClosed_s(self.o.TopoDS.Shell(s))
                   for s in self._shapes(shape, self.o.TopAbs_SHELL))
