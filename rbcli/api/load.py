"""Reading a body for the Python API: :func:`load` (a path) and :func:`load_text` (YAML text)."""

from __future__ import annotations

import os
from pathlib import Path

from rbcli.model import Body


def load(path: str | os.PathLike[str]) -> Body:
    """Read and validate a body file.

    Parameters
    ----------
    path : str or path-like
        The YAML body file; relative ``include`` and mesh paths are resolved from its
        folder. ``"-"`` reads standard input.

    Returns
    -------
    Body
        The validated body in SI units (a frozen :class:`rbcli.model.Body`); its
        ``warnings`` are the located warnings the command line prints.

    Raises
    ------
    rbcli.InputError
        Anything wrong with the file, with ``where`` (file, line, column) and the same
        one-line message the command line prints.

    Examples
    --------
    >>> import rbcli
    >>> body = rbcli.load("examples/square_lamina.yaml")
    >>> body.name, len(body.parts)
    ('Square lamina about a corner', 1)
    """
    from rbcli.io.body import load_body

    return load_body(os.fspath(path))


def load_text(text: str | bytes, *, units: dict[str, str] | None = None, name: str = "body",
              base_dir: str | os.PathLike[str] | None = None) -> Body:
    """Read and validate a body written as YAML text (a file's contents, or a one-part
    mapping such as ``"{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}"``).

    Parameters
    ----------
    text : str or bytes
        The YAML.
    units : dict, optional
        What bare numbers mean when the text has no ``units:`` of its own, e.g.
        ``{"length": "mm", "mass": "g"}`` (kinds: length, mass, time, angle). Default SI.
    name : str
        The body's name when the text gives none.
    base_dir : path-like, optional
        Where relative ``include`` and mesh paths start (default: the current folder).

    Returns
    -------
    Body

    Raises
    ------
    rbcli.InputError
        As :func:`load`, located in ``<text>``.

    Examples
    --------
    >>> import rbcli
    >>> box = rbcli.load_text("{shape: box, mass: 2, size: [100, 200, 300]}", units={"length": "mm"})
    >>> round(float(rbcli.inertia(box).inertia_com[2][2]), 10)   # m (a² + b²)/12, kg m²
    0.0083333333
    """
    from rbcli.io.body import load_text as _load_text

    base = Path(base_dir) if base_dir is not None else Path.cwd()
    return _load_text(text, "<text>", base, name_default=name, units=units)
