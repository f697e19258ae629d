"""A body's document (``Body.text``: the file as read, or the YAML of its data), to write it
(:func:`to_yaml`: ``Body.to_yaml``, ``rbcli balance --apply``) or change it (:func:`document`:
``Body.replace``): as data (no comments or layout), a shorthand as a ``parts:`` list, with the
body's ``name`` and ``units``, relative ``file:`` paths rewritten for the folder it will be
read from, every number as read (a float's ``repr``): it reads back bit for bit.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

from rbcli.errors import InputError, Location
from rbcli.io import outfile
from rbcli.io import yamlsafe as ys
from rbcli.io.yamldump import dump

if TYPE_CHECKING:
    from rbcli.body.model import Body

__all__ = ["to_yaml", "document", "check_output", "origin", "remember_origin"]

_FILE_SHAPES = ("include", "mesh", "step")


def check_output(out: str, body: Body, *, force: bool, option: str = "--apply") -> Path:
    """The output path, checked (:func:`rbcli.io.outfile.check`): none of ``Body.inputs``,
    its folder there, an existing file only with ``force``; else an InputError."""
    return outfile.check(out, body, option, force=force)


def remember_origin(body: Body, folder: str) -> None:
    """Keep on ``body`` the folder its document's relative paths start from (not a field: a
    ``dataclasses.replace`` of it has none)."""
    object.__setattr__(body, "_origin", folder)


def origin(body: Body) -> str | None:
    """The folder :func:`remember_origin` kept on ``body`` (a body a reader of rbcli made:
    its document is ``body.text``); else None."""
    return getattr(body, "_origin", None)


def _rebase(path: str, old_dir: str, new_dir: Path) -> str:
    if os.path.isabs(path):
        return path
    target = os.path.normpath(os.path.join(old_dir, path))
    rel = os.path.relpath(target, os.path.abspath(new_dir))
    return Path(rel).as_posix()


def document(body) -> dict:
    """``body``'s document as plain data (dicts and lists; a shorthand a ``parts:`` list;
    ``name`` and ``units`` written); an InputError for a body no reader made."""
    if origin(body) is None:
        raise InputError("this body has no document to write or change: it was not made by "
                         "rbcli.load, load_text, load_data, Body.from_parts, Body.replace or "
                         "Body.moved (a Body(...) or a dataclasses.replace of one is not)")
    data = ys.to_python(ys.load(body.text, body.source))
    if not isinstance(data, dict):  # the loader accepted it, so this cannot happen
        raise InputError("the body's document is not a mapping", Location(body.source))
    if "parts" not in data:  # one-part shorthand: the mapping is the part (a text units too)
        mine = ("rbcli", "units") if isinstance(data.get("units"), dict) else ("rbcli",)
        part = {k: v for k, v in data.items() if k not in mine}
        head = {k: data[k] for k in mine if k in data}
        data = {**({"rbcli": head["rbcli"]} if "rbcli" in head else {}), "name": body.name,
                **({"units": head["units"]} if "units" in head else {}), "parts": [part]}
    if "name" not in data:
        data = {**({"rbcli": data["rbcli"]} if "rbcli" in data else {}), "name": body.name,
                **{k: v for k, v in data.items() if k != "rbcli"}}
    if "units" not in data and body.units:  # load_text(..., units=...): the caller's units
        at = list(data).index("parts")
        items = list(data.items())
        data = dict([*items[:at], ("units", dict(body.units)), *items[at:]])
    return data


def to_yaml(body: Body, base_dir: str | os.PathLike[str] | None = None) -> str:
    """``body``'s document as YAML text, its relative paths resolving from ``base_dir``
    (default: the current folder); an InputError for a body no reader made."""
    if base_dir is not None and not isinstance(base_dir, (str, os.PathLike)):
        raise TypeError(f"base_dir: expected a folder (str or path-like), not {type(base_dir).__name__}")
    data = document(body)
    old_dir = origin(body)
    new_dir = Path(base_dir) if base_dir is not None else Path.cwd()
    for part in data["parts"]:
        if isinstance(part, dict) and part.get("shape") in _FILE_SHAPES \
                and isinstance(part.get("file"), str):
            part["file"] = _rebase(part["file"], old_dir, new_dir)  # type: ignore[arg-type]
    return dump(data)
