"""Placing a body file's primitive parts in batches (issue 15: 100 000-part bodies).

The loader (:mod:`rbcli.io.body`) checks each part as it reads it and keeps what it
found as a :class:`Pending`; :func:`finish` then places a batch of them at once: their
rotations per kind (:func:`rbcli.core.rotation.from_specs`), ``com = at + R c`` and
``J = R (m U) Rᵀ`` as stacked matrix products — the same numbers, bit for bit, as one
product per part (numpy makes the same BLAS call for each matrix of a stack) — and
makes their :class:`rbcli.model.Part` s, whose arrays are rows of a few shared arrays.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rbcli.core import rotation as rot
from rbcli.errors import Location
from rbcli.model import Outline, Part

#: primitives placed per batch: large enough for numpy to pay, small enough that the
#: batch's arrays and pending parts add little to the peak memory of a large body
BATCH = 4096


@dataclass(slots=True)
class Pending:
    """A checked primitive part not yet placed: :func:`finish` places all of them at once
    (``at + R com``, ``R (mass U) Rᵀ``, stacked: the same numbers as one by one)."""

    name: str
    shape: str
    mass: float
    subtract: bool
    measure: float | None
    measure_kind: str
    radius: float | None
    where: Location
    at: list
    spec: tuple | None
    com: object  # the local com: a 3-tuple or (3,) array
    unit_inertia: object  # the 3 diagonal entries, or a (3, 3) array
    dims: tuple


def dims_of(params: dict) -> tuple:
    """The drawing's description of a primitive part: its parameters (m) as
    :class:`rbcli.model.Outline` keeps them (vectors as tuples, lengths as floats)."""
    dims = []
    for k, v in params.items():
        if isinstance(v, list):  # size, semi_axes (n,), vertices (3, 3)
            v = tuple(tuple(r) for r in v) if isinstance(v[0], list) else tuple(v)
        elif not isinstance(v, bool):
            v = float(v)  # type: ignore[arg-type]
        dims.append((k, v))
    return tuple(dims)


def _units(pending: list) -> np.ndarray:
    """The (n, 3, 3) unit inertias of ``pending`` (:func:`_mixed_units`'s numbers)."""
    units = [p.unit_inertia for p in pending]
    if all(u.__class__ is tuple for u in units):  # all diagonal (the common case): one copy
        U = np.zeros((len(units), 9))
        U[:, ::4] = units  # the diagonal of each row's 3x3
        return U.reshape(-1, 3, 3)
    return _mixed_units(pending)


def _mixed_units(pending: list) -> np.ndarray:
    """The (n, 3, 3) unit inertias of ``pending``: diagonal 3-tuples and (3, 3) arrays."""
    n = len(pending)
    U = np.zeros((n, 3, 3))
    diag = [i for i, p in enumerate(pending) if p.unit_inertia.__class__ is tuple]
    if diag:
        d = np.array([pending[i].unit_inertia for i in diag], dtype=float).reshape(-1, 3)
        for j in range(3):
            U[diag, j, j] = d[:, j]
    full = [i for i, p in enumerate(pending) if p.unit_inertia.__class__ is not tuple]
    U[full] = [pending[i].unit_inertia for i in full]
    return U


def finish(items: list, start: int = 0) -> list[Part]:
    """``items`` with every :class:`Pending` of ``items[start:]`` replaced by its placed
    :class:`Part` (in place).

    The primitives are placed together: their rotations per kind
    (:func:`rbcli.core.rotation.from_specs`), ``com = at + R c`` and ``J = R (m U) Rᵀ`` as stacked matrix
    products, which give the same numbers as one product per part. The parts' arrays are
    rows of a few shared arrays (the outlines' read-only ones).
    """
    pending = [p for p in items[start:] if p.__class__ is Pending]
    if not pending:
        return items
    n = len(pending)
    dims = [p.dims for p in pending]
    ats = np.array([p.at for p in pending], dtype=float)  # (n, 3), not a view (see _frozen)
    Rs = rot.from_specs([p.spec for p in pending])
    local_coms = np.array([p.com for p in pending], dtype=float).reshape(n, 3)
    U = _units(pending)
    masses = np.array([p.mass for p in pending], dtype=float)
    del pending  # each one goes when its Part replaces it (the peak memory of a large body)
    coms = ats + (Rs @ local_coms[:, :, None])[:, :, 0]
    Js = Rs @ (masses[:, None, None] * U) @ Rs.transpose(0, 2, 1)
    axes = Rs[:, :, 2].copy()
    if Rs.base is not None:  # the outlines' rows: of an array that owns its data
        Rs = Rs.copy()
    ats.setflags(write=False)
    Rs.setflags(write=False)
    outline = Outline.of_frozen  # read-only rows of read-only arrays, as Outline keeps them
    i = 0
    for k in range(start, len(items)):
        p = items[k]
        if p.__class__ is not Pending:
            continue
        # Part's fields in order (positional: one part after another in a large body)
        items[k] = Part(
            p.name, p.shape, p.mass, p.subtract, coms[i], Js[i], p.measure, p.measure_kind,
            p.radius, axes[i], {}, p.where, outline(p.shape, dims[i], ats[i], Rs[i]),
        )
        i += 1
    return items
