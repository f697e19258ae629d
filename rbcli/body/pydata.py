"""Bodies from Python data (:func:`load_data`, :func:`from_parts`), from another body
(:func:`replace_part`, :func:`move_part`, :func:`with_points`) and from a CAD file
(:func:`cad_file`), as :class:`rbcli.body.bodyfile.Built`: the data frozen, made the loader's
tree (:func:`tree`, located by :class:`rbcli.body.loadctx.DataMark`), checked by the one
loader; ``Body.text`` is its YAML, so it is written, changed and reported like a file.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping, Sequence, Sized
from pathlib import Path
from types import MappingProxyType

from rbcli.body.bodyfile import Built, load_node
from rbcli.body.document import document, origin
from rbcli.body.loadctx import DataMark, Label, new_session
from rbcli.body.partspec import freeze, thaw
from rbcli.errors import InputError, Location
from rbcli.io import yamlsafe as ys
from rbcli.io.yamldump import dump
from rbcli.io.yamlvalues import suggest

__all__ = ["tree", "load_data", "from_parts", "cad_file", "replace_part", "move_part", "with_points",
           "SOURCE", "CAD_SUFFIXES"]

#: ``Body.source`` of a body built from Python data
SOURCE = "<data>"
#: the files read as a body of their own (:func:`cad_file`): STEP, then STL and OBJ
CAD_SUFFIXES = (".step", ".stp", ".stl", ".obj")


def tree(data: object, mark: DataMark) -> ys.Node:
    """The loader's tree of frozen ``data``, each node located by its :class:`DataMark`."""
    if isinstance(data, Mapping):
        items = {}
        for k, v in data.items():
            m = mark.child(k)
            items[k] = (m, tree(v, m))
        return ys.MapNode(mark, items)  # type: ignore[arg-type]
    if isinstance(data, tuple):
        return ys.SeqNode(mark, [tree(v, mark.child(i)) for i, v in enumerate(data)])  # type: ignore[arg-type]
    text = isinstance(data, str)
    return ys.ScalarNode(mark, data, data if text else repr(data), text)  # type: ignore[arg-type]


# --- bodies


def _base(base_dir: object, param: str = "base_dir") -> Path:
    if base_dir is None:
        return Path.cwd()
    if not isinstance(base_dir, (str, os.PathLike)):
        raise TypeError(f"{param}: expected a folder (str or path-like), not {type(base_dir).__name__}")
    return Path(base_dir)


def _check_budget(parts: object, where: str) -> None:
    """Refuse a list of parts over the parts budget before it is frozen (a part costs at
    least one of it), as a body file's is refused while it is parsed."""
    if isinstance(parts, Sized) and not isinstance(parts, (str, Mapping)):
        session = new_session()
        if len(parts) > session.max_parts:
            raise InputError(session.over_message(), Location(where))


def _load(data: MappingProxyType, root: str, base_dir: Path, *, name: str = "body",
          units: Mapping[str, str] | None = None, labels: Sequence[str] | None = None,
          source: str = SOURCE) -> Built:
    """The body of frozen ``data`` (a body file's mapping), through the loader; ``labels``
    name each of its parts as a whole (``Body.from_parts``'s ``parts[2] (cylinder 'bore')``)."""
    top = DataMark(None, "", root)
    if labels is None:
        node = tree(data, top)
    else:
        items = {}
        for k, v in data.items():
            m = top.child(k)
            if k == "parts":
                pm = [DataMark(m, Label(label)) for label in labels]
                items[k] = (m, ys.SeqNode(m, [tree(p, pmark) for p, pmark in zip(v, pm)]))  # type: ignore[arg-type]
            else:
                items[k] = (m, tree(v, m))
        node = ys.MapNode(top, items)  # type: ignore[arg-type]
    text = dump(thaw(data))
    return load_node(node, source, base_dir, text=text, name_default=name,
                     units=dict(units) if units else None)


def load_data(mapping: Mapping[str, object], *, units: Mapping[str, str] | None = None,
              name: str = "body", base_dir: object = None) -> Built:
    """The body of ``mapping``, a body file's mapping as Python data (see the module's
    notes); every problem located by its key path (``parts[2].radius``)."""
    if not isinstance(mapping, Mapping):
        raise TypeError(f"mapping: expected a mapping like a body file's (a dict), not "
                        f"{type(mapping).__name__}")
    base = _base(base_dir)
    if "parts" in mapping:
        _check_budget(mapping["parts"], "parts")
    data = freeze(mapping)
    return _load(data, "mapping", base, name=name, units=units)  # type: ignore[arg-type]


def cad_file(path: str, **keys: object) -> Built:
    """A STEP, STL or OBJ file (in mm: no unit in those) as a body of one part of it."""
    mesh = not path.lower().endswith(CAD_SUFFIXES[:2])
    part = {"shape": "mesh" if mesh else "step", "file": path,
            **({"name": Path(path).stem, "units": "mm"} if mesh else {}),
            **{k: v for k, v in keys.items() if v is not None}}
    built = _load(freeze({"parts": (part,)}), path, Path.cwd(), name=Path(path).stem,
                  labels=[path], source=path)
    if mesh:
        built.fields["warnings"] += (f"{path}: note: read in mm (STL and OBJ carry no unit)",)
    return built


def _label(i: int, part: Mapping[str, object]) -> str:
    shape, name = part.get("shape"), part.get("name")
    shown = shape if isinstance(shape, str) else "part"
    if isinstance(name, str):
        return f"parts[{i}] ({shown} {name!r})"
    return f"parts[{i}] ({shown})"


#: Body.from_parts's keyword arguments that are body keys, in the order a file writes them
BODY_ARGS = ("name", "description", "units", "reference", "shaft", "pivot", "rim_radius")


def from_parts(parts: Sequence[Mapping[str, object]], *, base_dir: object = None,
               **body: object) -> Built:
    """The body of ``parts`` (specs or mappings) with the body keys ``body`` (None: not
    given), a part's problems located by the call: ``parts[2] (cylinder 'bore')``."""
    if isinstance(parts, (str, bytes, Mapping)) or not isinstance(parts, Iterable):
        raise TypeError(f"parts: expected a list of parts (rbcli.parts.*), not {type(parts).__name__}")
    _check_budget(parts, "parts")
    parts = list(parts)
    _check_budget(parts, "parts")
    specs = []
    for i, p in enumerate(parts):
        if isinstance(p, Mapping):  # a PartSpec too
            specs.append(freeze(p, f"parts[{i}]"))
        else:
            raise TypeError(f"parts[{i}]: expected a part (rbcli.parts.*) or a mapping of its "
                            f"keys, not {type(p).__name__}")
    name = body.get("name", "body")
    if not isinstance(name, str):
        raise TypeError(f"name: expected a text, not {type(name).__name__}")
    base = _base(base_dir)
    data: dict[str, object] = {}
    for key in BODY_ARGS:
        value = body.get(key)
        if value is not None:
            data[key] = freeze(value, key)
        if key == "units":
            data["parts"] = tuple(specs)
    labels = [_label(i, p) for i, p in enumerate(specs)]
    return _load(MappingProxyType(data), "Body.from_parts", base, name=name, labels=labels)


# --- from a body


def _rebuilt(body, data: dict) -> Built:
    """The body of ``data`` (:func:`rbcli.body.document.document` of ``body``, changed),
    read from ``body``'s folder, its problems located by key path."""
    return load_data(data, base_dir=origin(body))


def _index(body, data: dict, which: object) -> int:
    parts = data["parts"]
    if isinstance(which, bool) or not isinstance(which, (int, str)):
        raise TypeError(f"which: expected a part's name or its index in the body's parts, not "
                        f"{type(which).__name__}")
    if isinstance(which, int):
        if not -len(parts) <= which < len(parts):
            raise InputError(f"which: the body has {len(parts)} parts; no part {which}")
        return which % len(parts)
    names = []
    for i, p in enumerate(parts):
        n = p.get("name") if isinstance(p, dict) else None
        n = n if isinstance(n, str) else f"{p.get('shape')}{i + 1}"
        if n == which:
            return i
        names.append(n)
    raise InputError(f"which: the body has no part named {which!r}{suggest(which, names)} "
                     f"(parts: {', '.join(names)})")


def replace_part(body, which: object, part: object, keys: Mapping[str, object]) -> Built:
    """``body`` with its part ``which`` (a name, or an index in its ``parts:`` list) replaced
    by ``part`` (a spec or mapping, or None: the part as it is) with ``keys`` changed
    (None removes a key)."""
    data = document(body)
    i = _index(body, data, which)
    if part is None:
        new = dict(data["parts"][i])
    elif isinstance(part, Mapping):
        new = thaw(freeze(part, "part"))  # type: ignore[assignment]
    else:
        raise TypeError(f"part: expected a part (rbcli.parts.*) or a mapping of its keys, not "
                        f"{type(part).__name__}")
    for k, v in keys.items():
        k = "from" if k == "from_" else k
        if v is None:
            new.pop(k, None)
        else:
            new[k] = thaw(freeze(v, k))
    data["parts"][i] = new
    return _rebuilt(body, data)


def move_part(body, which: object, at: object = None, axis: object = None,
              rotate: object = None) -> Built:
    """``body`` with part ``which`` placed anew: ``at`` replaces its position, ``axis`` or
    ``rotate`` its orientation (the other one removed)."""
    keys: dict[str, object] = {}
    if axis is not None and rotate is not None:
        raise InputError("give either 'axis' or 'rotate', not both", Location("moved"))
    if at is not None:
        keys["at"] = at
    if axis is not None:
        keys.update(axis=axis, rotate=None)
    if rotate is not None:
        keys.update(rotate=rotate, axis=None)
    return replace_part(body, which, None, keys)


def with_points(body, points: Sequence[tuple[str, float, Sequence[float]]]) -> Built:
    """``body`` with point masses ``(name, mass kg, at (3,) m)`` added as ``point`` parts in
    explicit units (``"43.631 g"``: 15 figures), a name used again numbered `` (2)``
    (``rbcli balance --apply``)."""
    data = document(body)
    parts = data["parts"]
    names = {p["name"] for p in parts if isinstance(p, dict) and isinstance(p.get("name"), str)}
    names |= {p.name for p in body.parts}
    for name, mass, at in points:
        xyz = [float(x) for x in at]
        big = max(abs(x) for x in xyz)
        xyz = [0.0 if abs(x) <= 1e-13 * big else x for x in xyz]  # round-off of cos/sin
        shown, k = name, 2
        while shown in names:
            shown = f"{name} ({k})"
            k += 1
        names.add(shown)
        parts.append({"name": shown, "shape": "point", "mass": f"{_num(mass * 1e3)} g",
                      "at": [f"{_num(x * 1e3)} mm" for x in xyz]})
    return _rebuilt(body, data)


def _num(x: float) -> str:
    """A float in at most 15 significant figures (round trip to ~5e-16 relative)."""
    s = f"{x:.15g}"
    return "0" if float(s) == 0.0 else s
