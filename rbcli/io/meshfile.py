"""Readers for triangle-mesh files: STL (binary and ASCII) and Wavefront OBJ.

:func:`read_mesh` returns an *indexed* mesh (exactly equal vertices merged) and the weld
tolerance that suits the file's precision (:func:`default_weld`), which
:mod:`rbcli.core.mesh` uses only to close the gaps of a surface that is not closed.
Text formats are read in blocks with numpy; the per-line Python readers remain to locate
what the fast path refuses and to read the unusual layouts (the same bits either way, as
the tests check). Formats: :mod:`rbcli.io.meshstl`, :mod:`rbcli.io.meshobj`; welding:
:mod:`rbcli.io.meshweld`. Errors are :class:`MeshFileError` (a ``ValueError``), lower
case, starting with the file name (and the line, for text).
"""

from __future__ import annotations

import os
import re
from typing import NamedTuple

import numpy as np

from rbcli.io.meshbase import MeshFileError, read_all
from rbcli.io.meshobj import read_obj
from rbcli.io.meshstl import read_stl
from rbcli.io.meshweld import weld
from rbcli.io.reader import open_regular

__all__ = [
    "MeshFileError", "MeshFile", "read_mesh", "weld", "default_weld", "max_mesh_bytes",
    "SUFFIXES", "MAX_MESH_BYTES", "TEXT_WELD_RTOL", "FLOAT32_WELD_ULPS",
]  # fmt: skip

#: File-name endings :func:`read_mesh` understands (case-insensitive).
SUFFIXES = (".stl", ".obj")

#: Default size limit of a mesh file in bytes (1 GiB: an ASCII STL of ~4 M triangles,
#: a binary STL of ~21 M); the environment variable ``RBCLI_MAX_MESH_BYTES`` changes it.
MAX_MESH_BYTES = 1 << 30

#: Text formats (ASCII STL, OBJ): the default weld tolerance is this times the diagonal
#: of the bounding box (and at least 4 float64 ulps of the largest coordinate).
TEXT_WELD_RTOL = 1e-9

#: Binary STL stores float32: the default weld tolerance is this many float32 ulps of
#: the largest coordinate magnitude (the spacing of the file's own numbers there).
FLOAT32_WELD_ULPS = 4


class MeshFile(NamedTuple):
    """What :func:`read_mesh` returns.

    Attributes
    ----------
    vertices : (V, 3) ndarray of float64 — distinct positions, in the file's length unit
    faces : (F, 3) ndarray of int64 — vertex indices of each triangle, in file order
    format : str — ``"binary stl"``, ``"ascii stl"`` or ``"obj"``
    weld : float — the default weld tolerance for this file (file unit), see
        :func:`default_weld`
    """

    vertices: np.ndarray
    faces: np.ndarray
    format: str
    weld: float


def max_mesh_bytes() -> int:
    """The mesh-file size limit in bytes: ``RBCLI_MAX_MESH_BYTES`` (bytes, optionally with
    ``k``, ``M``, ``G``: powers of 1024) or :data:`MAX_MESH_BYTES`."""
    text = os.environ.get("RBCLI_MAX_MESH_BYTES", "").strip()
    if not text:
        return MAX_MESH_BYTES
    m = re.fullmatch(r"([0-9]{1,15})\s*([kKmMgGtT]?)(?:i?[bB])?", text)
    if not m:
        shown = text if len(text) <= 30 else text[:30] + "…"
        raise ValueError(
            f"RBCLI_MAX_MESH_BYTES must be a number of bytes such as 2000000000 or 2G, not {shown!r}"
        )
    power = " KMGT".index(m.group(2).upper() or " ")
    return int(m.group(1)) << (10 * power)


def default_weld(fmt: str, vertices: np.ndarray) -> float:
    """The weld tolerance that suits a file's own precision (in the file's unit).

    Parameters
    ----------
    fmt : str — ``"binary stl"`` (float32 coordinates) or a text format
    vertices : (V, 3) ndarray — the file's distinct vertices

    Returns
    -------
    float
        Binary STL: :data:`FLOAT32_WELD_ULPS` float32 ulps at the largest coordinate
        magnitude M, ``4 * 2**(floor(log2 M) - 23)`` (about 5e-7 M): two float32 numbers
        that round the same CAD value differently differ by one or two. Text formats:
        :data:`TEXT_WELD_RTOL` times the bounding-box diagonal, at least 4 float64 ulps
        of M. 0 for an empty or all-zero mesh.
    """
    if len(vertices) == 0:
        return 0.0
    big = float(np.abs(vertices).max())
    if big == 0.0:
        return 0.0
    if fmt == "binary stl":
        return float(FLOAT32_WELD_ULPS * np.spacing(np.float32(big)))
    diag = float(np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0)))
    return max(TEXT_WELD_RTOL * diag, 4.0 * float(np.spacing(big)))


def read_mesh(path: str | os.PathLike[str], *, max_bytes: int | None = None) -> MeshFile:
    """Read a triangle mesh from an STL (binary or ASCII) or OBJ file.

    Parameters
    ----------
    path : str or path-like
        The file. Its format comes from the extension, ``.stl`` or ``.obj``
        (case-insensitive).
    max_bytes : int, optional
        Refuse a larger file before reading it; default :func:`max_mesh_bytes`.

    Returns
    -------
    MeshFile
        Vertices with equal coordinates merged (``-0.0`` equals ``0.0``), triangles in
        file order (its orientation kept; OBJ polygons fanned), format, weld tolerance.

    Raises
    ------
    ReadError
        A file missing, not regular, over the size limit, unreadable (rbcli.io.reader).
    MeshFileError
        Unknown extension; a truncated or malformed file (with the line); non-finite
        coordinates; a face index out of range (OBJ); no triangles.

    Notes
    -----
    Binary STL: an 80-byte header, a little-endian uint32 triangle count and 50-byte
    records (normal, three float32 vertices, uint16 attribute). A file is taken as
    binary when its size is exactly ``84 + 50 n`` for the count ``n`` in its header,
    even if the header starts with ``solid`` (many exporters do that), unless the
    bytes after the header are plain text containing ``facet``. Normals are ignored:
    the orientation comes from the vertex order. OBJ reads ``v`` and ``f`` lines
    (``f`` items ``i``, ``i/t``, ``i//n``, ``i/t/n``; negative indices count back from
    the latest vertex), ``#`` comments and ``\\`` line continuations.
    """
    p = os.fspath(path)
    name = p if isinstance(p, str) else os.fsdecode(p)
    suffix = os.path.splitext(name)[1].lower()
    if suffix not in SUFFIXES:
        allowed = ", ".join(SUFFIXES)
        shown = f"'{suffix}'" if suffix else "no extension"
        raise MeshFileError(name, f"unknown mesh file type ({shown}); use one of {allowed}")
    if max_bytes is None:
        try:
            max_bytes = max_mesh_bytes()
        except ValueError as exc:
            raise MeshFileError(name, str(exc)) from None
    fd, size = open_regular(name, max_bytes, "mesh file", env="RBCLI_MAX_MESH_BYTES")
    with open(fd, "rb", closefd=True) as fh:
        if not size:
            raise MeshFileError(name, "empty file (no triangles)")
        try:
            if suffix == ".obj":
                vertices, faces = read_obj(name, read_all(name, fh, size))
                fmt = "obj"
            else:
                vertices, faces, fmt = read_stl(name, fh, size)
        except OSError as exc:
            raise MeshFileError(name, f"cannot read the file: {(exc.strerror or str(exc)).lower()}") from None
    return MeshFile(vertices, faces, fmt, default_weld(fmt, vertices))
