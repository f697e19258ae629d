"""Write a body file back out with point masses added (``rbcli balance --apply``).

The original document's data is re-emitted (its comments are not: PyYAML keeps none), a
one-part shorthand becomes a ``parts:`` list, relative ``file:`` paths of ``include`` and
``mesh`` parts are rewritten so they still resolve from the new file's folder, and the
file's ``units:`` are kept. The new parts' numbers are strings with explicit units
(``"43.631 g"``, ``["200 mm", "0 mm", "-100 mm"]``), which mean the same whatever the file's
``units:`` say.
"""

from __future__ import annotations

import os
import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from rbcli.errors import InputError
from rbcli.io import outfile
from rbcli.io import yamlsafe as ys
from rbcli.model import Body

#: keys of the one-part shorthand that belong to the body, not the part
_BODY_LEVEL = ("rbcli", "units")
_FILE_SHAPES = ("include", "mesh")


@dataclass(frozen=True)
class NewPoint:
    """A point mass to add: ``name``, ``mass`` (kg), ``at`` (3,) body frame (m)."""

    name: str
    mass: float
    at: Sequence[float]


def _is_file(source: str) -> bool:
    return bool(source) and not source.startswith("<") and source != "-"


def base_dir(body: Body) -> Path:
    """The folder relative paths in the body's text are resolved from."""
    if _is_file(body.source):
        return Path(body.source).parent
    return Path.cwd()


def check_output(out: str, body: Body, *, force: bool, option: str = "--apply") -> Path:
    """The output path, checked: not an input file, folder exists, not existing without force.

    The inputs are every file the body was read from (``Body.inputs``: the body file, its
    includes at any depth, its meshes); see :func:`rbcli.io.outfile.check`.

    Raises
    ------
    InputError
        (exit 2) for an input file (whatever ``force`` says), a missing folder, a
        directory, or an existing file without ``force``.
    """
    return outfile.check(out, body, option, force=force)


def _document(body: Body) -> dict:
    data = ys.to_python(ys.load(body.text, body.source))
    if not isinstance(data, dict):  # the loader accepted it, so this cannot happen
        raise InputError(f"{body.source}: the body is not a mapping")
    return data


def _num(x: float) -> str:
    """A float in at most 15 significant figures (round trip to ~5e-16 relative)."""
    s = f"{x:.15g}"
    return "0" if float(s) == 0.0 else s


def _rebase(path: str, old_dir: Path, new_dir: Path) -> str:
    if os.path.isabs(path):
        return path
    target = os.path.normpath(os.path.join(os.path.abspath(old_dir), path))
    rel = os.path.relpath(target, os.path.abspath(new_dir))
    return Path(rel).as_posix()


def balanced_document(body: Body, points: Sequence[NewPoint], out: Path) -> dict:
    """The body's document with ``points`` appended as ``point`` parts (plain data)."""
    data = _document(body)
    if "parts" not in data:  # one-part shorthand: the mapping is the part
        part = {k: v for k, v in data.items() if k not in _BODY_LEVEL}
        head = {k: data[k] for k in _BODY_LEVEL if k in data}
        doc: dict = {}
        if "rbcli" in head:
            doc["rbcli"] = head["rbcli"]
        doc["name"] = body.name
        if "units" in head:
            doc["units"] = head["units"]
        doc["parts"] = [part]
        data = doc
    parts = list(data["parts"])
    old_dir, new_dir = base_dir(body), out.parent
    names = set()
    for i, part in enumerate(parts):
        if isinstance(part, dict):
            if part.get("shape") in _FILE_SHAPES and isinstance(part.get("file"), str):
                part = dict(part)
                part["file"] = _rebase(part["file"], old_dir, new_dir)
                parts[i] = part
            if isinstance(part.get("name"), str):
                names.add(part["name"])
    names |= {p.name for p in body.parts}
    for pt in points:
        at = [float(x) for x in pt.at]
        big = max(abs(x) for x in at)
        at = [0.0 if abs(x) <= 1e-13 * big else x for x in at]  # round-off of cos/sin
        name = pt.name
        k = 2
        while name in names:
            name = f"{pt.name} ({k})"
            k += 1
        names.add(name)
        parts.append(
            {
                "name": name,
                "shape": "point",
                "mass": f"{_num(pt.mass * 1e3)} g",
                "at": [f"{_num(x * 1e3)} mm" for x in at],
            }
        )
    data["parts"] = parts
    return data


#: plain scalars that the YAML 1.2 core schema reads as something other than a string
_NOT_STR = re.compile(
    r"~|null|Null|NULL|true|True|TRUE|false|False|FALSE"
    r"|[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+"
    r"|[-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?"
    r"|[-+]?(\.inf|\.Inf|\.INF)|\.nan|\.NaN|\.NAN"
)


def dump(data: object) -> str:
    """YAML text of plain data that rbcli's YAML 1.2 loader reads back identically.

    PyYAML quotes strings by the YAML 1.1 rules, so it would leave ``1e3`` (a string that
    YAML 1.2 reads as a number) bare; every string that could be read as something else
    (it starts like a number, null or boolean) is double-quoted here.
    """
    import yaml

    class _Dumper(yaml.SafeDumper):
        pass

    def _str(dumper: yaml.SafeDumper, value: str) -> yaml.Node:
        style = '"' if (not value or _NOT_STR.fullmatch(value)) else None
        return dumper.represent_scalar("tag:yaml.org,2002:str", value, style=style)

    _Dumper.add_representer(str, _str)
    return yaml.dump(
        data, Dumper=_Dumper, sort_keys=False, allow_unicode=True, default_flow_style=None, width=100
    )


def write_balanced(
    body: Body,
    points: Sequence[NewPoint],
    out: str,
    *,
    force: bool = False,
    header: Sequence[str] = (),
) -> Path:
    """Write ``body`` with ``points`` added to ``out`` (YAML); returns the path written.

    The file is written atomically (a temporary file in its folder, then renamed).

    Raises
    ------
    InputError
        see :func:`check_output`; or the file cannot be written.
    """
    path = check_output(out, body, force=force)
    data = balanced_document(body, points, path)
    text = "".join(f"# {line}\n" if line else "#\n" for line in header)
    text += dump(data)
    outfile.write_atomic(path, text, "--apply", replace=force)
    return path
