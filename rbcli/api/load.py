"""Reading a body for the Python API: :func:`load` (a path), :func:`load_text` (YAML text),
:func:`load_data` (a mapping). Arguments are checked at the door (a ``TypeError`` or a
:class:`rbcli.ParamError` naming the parameter); the body by the one body reader.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path

from rbcli.api import check
from rbcli.api import options as op
from rbcli.body import materials, model
from rbcli.body.bodyfile import default_units
from rbcli.body.model import Body
from rbcli.body.pydata import CAD_SUFFIXES
from rbcli.errors import ParamError, literal

__all__ = ["load", "load_text", "load_data"]


def _path(value: object, param: str) -> str:
    """A file or folder path given as ``str`` or path-like (of text), as ``str``."""
    if isinstance(value, str):
        return value
    if isinstance(value, os.PathLike):
        p = os.fspath(value)
        if isinstance(p, str):
            return p
    raise TypeError(f"{param}: expected a path (str or path-like), not {type(value).__name__}")


def _base_dir(value: object) -> Path:
    return Path.cwd() if value is None else Path(_path(value, "base_dir"))


def _name(value: object) -> str:
    if not isinstance(value, str):
        raise TypeError(f"name: expected a text (str), not {type(value).__name__}")
    return value


def _units(units: object) -> dict[str, str] | None:
    """The caller's default units, checked: a mapping of kinds to unit names."""
    if units is None:
        return None
    if not isinstance(units, Mapping):
        raise TypeError(f"units: expected a mapping of kinds to unit names, such as "
                        f"{{'length': 'mm'}}, not {type(units).__name__}")
    out: dict[str, str] = {}
    for kind, unit in units.items():
        if not isinstance(kind, str):
            raise TypeError(f"units: its keys are kinds (length, mass, ...), not {type(kind).__name__}")
        if not isinstance(unit, str):
            raise TypeError(f"units: the unit of {kind!r} is a text such as 'mm', not "
                            f"{type(unit).__name__}")
        out[str(kind)] = str(unit)
    try:
        default_units(out)
    except ValueError as exc:
        raise ParamError("units", str(exc)) from None
    return out


def load(path: str | os.PathLike[str], *, material: str | None = None,
         density: float | str | None = None, part: str | None = None) -> Body:
    """Read and validate a body file, or a STEP, STL or OBJ file as a body of its own.

    Parameters
    ----------
    path : str or path-like
        A YAML body file (``"-"``: standard input), or a ``.step``/``.stp`` file (each solid a
        part, exact: ``pip install 'rbcli[cad]'``) or a ``.stl``/``.obj`` file (in mm).
    material, density : str; float or str, optional
        For a STEP, STL or OBJ file, one: every solid's material (``rbcli materials``) or
        density (kg/m³, or ``"2.7 g/cm^3"``).
    part : str, optional
        For a STEP file: the solids this name or pattern (``"link*"``) matches.

    Returns
    -------
    Body
        Validated, SI; its ``warnings`` are what the command line prints.

    Raises
    ------
    TypeError
        An argument of the wrong type.
    rbcli.InputError
        Anything wrong with the file, located, with the command line's message.

    Examples
    --------
    >>> import rbcli
    >>> body = rbcli.load("examples/square_lamina.yaml")
    >>> body.name, len(body.parts)
    ('Square lamina about a corner', 1)
    >>> block = rbcli.load("examples/cad_block.obj", material="aluminium 6061")
    >>> round(rbcli.inertia(block).mass, 6)   # 2700 kg/m³ × 80 × 40 × 20 mm³, kg
    0.1728
    """
    p = _path(path, "path")
    if not p:
        raise ParamError("path", "an empty path names no file")
    keys = {"material": check.text(material, "material"), "part": check.text(part, "part"),
            "density": check.quantity(density, "density")}
    if not p.lower().endswith(CAD_SUFFIXES):
        given = [k for k, v in keys.items() if v is not None]
        if given:
            raise ParamError(given[0], "applies to a STEP, STL or OBJ file, not a body file")
        return model.load_body(p)
    if (material is None) == (density is None):
        raise ParamError("material" if material is None else "density",
                         f"{literal(p)}: give {{material}} or {{density}}, one of them")
    if part is not None and not p.lower().endswith(CAD_SUFFIXES[:2]):
        raise ParamError("part", "applies to a STEP file")
    if material is not None:
        try:
            materials.density(material)
        except ValueError as exc:
            raise ParamError("material", str(exc)) from None
    if density is not None:
        keys["density"] = op.positive(op.quantity(density, "density", "density"), "density",
                                      "the density", "kg/m^3")
    return model.load_cad(p, **keys)


def load_text(text: str | bytes, *, units: Mapping[str, str] | None = None, name: str = "body",
              base_dir: str | os.PathLike[str] | None = None) -> Body:
    """Read and validate a body written as YAML text (a file's contents, or a one-part
    mapping such as ``"{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}"``).

    Parameters
    ----------
    text : str or bytes
        The YAML.
    units : mapping, optional
        What bare numbers mean when the text has no ``units:``, e.g. ``{"length": "mm"}``.
    name : str
        The body's name when the text gives none.
    base_dir : path-like, optional
        Where relative ``include``, mesh and STEP paths start (default: the current folder).

    Returns
    -------
    Body

    Raises
    ------
    TypeError
        An argument of the wrong type, named.
    rbcli.InputError
        A bad unit; anything wrong with the body, as :func:`load`, located in ``<text>``.

    Examples
    --------
    >>> import rbcli
    >>> box = rbcli.load_text("{shape: box, mass: 2, size: [100, 200, 300]}", units={"length": "mm"})
    >>> round(float(rbcli.inertia(box).inertia_com[2][2]), 10)   # m (a² + b²)/12, kg m²
    0.0083333333
    """
    if not isinstance(text, (str, bytes, bytearray)):
        raise TypeError(f"text: expected YAML text (str or bytes), not {type(text).__name__}")
    if isinstance(text, bytearray):
        text = bytes(text)
    return model.load_text(text, "<text>", _base_dir(base_dir), name_default=_name(name),
                           units=_units(units))


def load_data(mapping: Mapping[str, object], *, units: Mapping[str, str] | None = None,
              name: str = "body", base_dir: str | os.PathLike[str] | None = None) -> Body:
    """Read and validate a body given as Python data (a body file's mapping, as
    ``json.load`` would give it; numpy values too), checked as a file is, each problem
    located by its key path (``parts[2].radius: ...``).

    Parameters
    ----------
    mapping : mapping
        ``{"name": ..., "parts": [{"shape": "disk", ...}, ...]}``, or one part's mapping.
    units, name, base_dir : optional
        As :func:`load_text`.

    Returns
    -------
    Body
        Validated (``source`` ``"<data>"``, ``text`` the mapping as YAML).

    Raises
    ------
    TypeError
        A value of a type no body file holds, named by its key path.
    rbcli.InputError
        Anything a body file could get wrong, located by key path; a cycle in the data.

    Examples
    --------
    >>> import rbcli
    >>> data = {"name": "wheel", "units": {"length": "mm"},
    ...         "parts": [{"name": "rim", "shape": "ring", "radius": 300, "mass": 2}]}
    >>> round(float(rbcli.inertia(rbcli.load_data(data)).inertia_com[2][2]), 12)   # m R²
    0.18
    >>> data["parts"][0]["radius"] = -300
    >>> rbcli.load_data(data)
    Traceback (most recent call last):
    ...
    rbcli.errors.InputError: parts[0].radius: part 'rim': radius must be greater than 0 (got -300 mm)
    """
    if not isinstance(mapping, Mapping):
        raise TypeError(f"mapping: expected a mapping like a body file's (a dict), not "
                        f"{type(mapping).__name__}")
    return model.load_data(mapping, units=_units(units), name=_name(name), base_dir=_base_dir(base_dir))
