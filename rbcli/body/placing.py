"""Placing primitive parts in batches (100 000-part bodies): the loader keeps each
checked part as a :class:`Pending`; :func:`finish` places a batch at once (``com = at + R c``,
``J = R (m U) Rᵀ`` as stacked products: the same numbers, bit for bit, as one by one) and makes
their :class:`rbcli.body.partmodel.Part` s. An included file's parts stay arrays (a
:class:`Stack`) that each use moves at once.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rbcli.body.partmodel import EMPTY_MAPPING, Outline, Part
from rbcli.core import rotation as rot
from rbcli.errors import Location

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


def place(part_com, part_I, at, R):
    """A part placed one by one (a mesh or given part): ``(at + R com, R J Rᵀ)``."""
    return at + R @ part_com, R @ part_I @ R.T


def dims_of(params: dict) -> tuple:
    """The drawing's description of a primitive part: its parameters (m) as
    :class:`rbcli.body.partmodel.Outline` keeps them (vectors as tuples, lengths as floats)."""
    out = []
    for k, v in params.items():
        if isinstance(v, list):  # size, semi_axes (n,), vertices (3, 3)
            v = tuple(tuple(r) for r in v) if isinstance(v[0], list) else tuple(v)
        elif not isinstance(v, bool):
            v = float(v)  # type: ignore[arg-type]
        out.append((k, v))
    return tuple(out)


def _units(pending: list) -> np.ndarray:
    """The (n, 3, 3) unit inertias of ``pending``: each a diagonal (a 3-tuple) or a (3, 3)
    array."""
    return np.array([np.diag(p.unit_inertia) if isinstance(p.unit_inertia, tuple) else p.unit_inertia
                     for p in pending], dtype=float)


def _placed(pending: list) -> tuple:
    """``pending`` placed: coms (n, 3), inertias (n, 3, 3), axes (n, 3), the outlines' origins
    (n, 3) and rotations (n, 3, 3): read-only arrays owning their data (the parts keep rows)."""
    ats = np.array([p.at for p in pending], dtype=float)  # (n, 3), owns its data
    Rs = rot.from_specs([p.spec for p in pending])
    local_coms = np.array([p.com for p in pending], dtype=float)
    U = _units(pending)
    masses = np.array([p.mass for p in pending], dtype=float)
    coms = ats + (Rs @ local_coms[:, :, None])[:, :, 0]
    Js = Rs @ (masses[:, None, None] * U) @ Rs.transpose(0, 2, 1)
    axes = Rs[:, :, 2].copy()
    if Rs.base is not None:  # the outlines' rows: of an array that owns its data
        Rs = Rs.copy()
    for a in (coms, Js, axes, ats, Rs):  # the parts' rows: read-only, kept as they are
        a.setflags(write=False)
    return coms, Js, axes, ats, Rs


def finish(items: list, start: int = 0) -> list:
    """``items`` with every :class:`Pending` of ``items[start:]`` replaced by its placed
    :class:`Part`, in place (stacked products; the parts' arrays rows of a few shared ones)."""
    pending = [p for p in items[start:] if isinstance(p, Pending)]
    if not pending:
        return items
    dims = [p.dims for p in pending]
    coms, Js, axes, ats, Rs = _placed(pending)
    del pending  # each one goes when its Part replaces it (the peak memory of a large body)
    i = 0
    for k in range(start, len(items)):
        p = items[k]
        if not isinstance(p, Pending):
            continue
        items[k] = Part(
            p.name, p.shape, p.mass, p.subtract, coms[i], Js[i], p.measure, p.measure_kind,
            p.radius, axes[i], EMPTY_MAPPING, p.where, Outline(p.shape, dims[i], ats[i], Rs[i]),
        )
        i += 1
    return items


class Stack:
    """Placed parts kept as arrays (an included file's, a STEP file's): each use moves them
    at once; only the top file makes :class:`Part` s.

    Attributes
    ----------
    names : list of str — ``sub/part`` once moved by an include
    rows : list — per part what placing keeps: its :class:`Pending` or :class:`Part`
    com, inertia, axis : (n, 3), (n, 3, 3), (n, 3) arrays — as :class:`Part` has them
    at, R : (n, 3), (n, 3, 3) read-only arrays — the outlines' placements
    """

    __slots__ = ("names", "rows", "com", "inertia", "axis", "at", "R")

    def __init__(self, names: list, rows: list, com, inertia, axis, at, R) -> None:
        self.names, self.rows = names, rows
        self.com, self.inertia, self.axis, self.at, self.R = com, inertia, axis, at, R

    def __len__(self) -> int:
        return len(self.names)

    @classmethod
    def of(cls, items: list) -> Stack:
        """Pending primitives, finished parts and stacks, in their order, as one stack (the
        primitives placed together)."""
        pending = [p for p in items if isinstance(p, Pending)]
        placed = _placed(pending) if pending else ()
        pieces: list[Stack] = []
        start = j = 0  # pending[start:j]: the run of primitives not yet in pieces
        for item in items:
            if isinstance(item, Pending):
                j += 1
                continue
            if j > start:
                pieces.append(cls._run(pending[start:j], [x[start:j] for x in placed]))
                start = j
            pieces.append(item if isinstance(item, Stack) else cls._of_part(item))
        if j > start:
            pieces.append(cls._run(pending[start:j], [x[start:j] for x in placed]))
        if len(pieces) == 1:
            return pieces[0]
        arrays = [np.concatenate([getattr(s, f) for s in pieces]) for f in cls.__slots__[2:]]
        for a in arrays:  # read-only, own data: the Parts keep their rows
            a.setflags(write=False)
        return cls([n for s in pieces for n in s.names], [r for s in pieces for r in s.rows], *arrays)

    @classmethod
    def _run(cls, pending: list, placed: list) -> Stack:
        return cls([p.name for p in pending], pending, *placed)

    @classmethod
    def _of_part(cls, p: Part) -> Stack:
        o = p.outline
        at, R = (np.zeros(3), np.eye(3)) if o is None else (o.at, o.R)
        return cls([p.name], [p], p.com[None], p.inertia_com[None], p.axis[None], at[None], R[None])

    def moved(self, at: np.ndarray, R: np.ndarray, prefix: str) -> Stack:
        """The parts moved by ``x -> at + R x`` (an include's placement), names prefixed, all
        at once (bit for bit one part's numbers: tests/test_body_fast.py)."""
        com = at + self.com @ R.T
        inertia = np.einsum("ij,njk,lk->nil", R, self.inertia, R)
        axis = self.axis @ R.T
        o_at = at + (R @ self.at[:, :, None])[:, :, 0]
        o_R = R @ self.R
        for a in (com, inertia, axis, o_at, o_R):  # read-only, own data: the Parts keep rows
            a.setflags(write=False)
        return Stack([prefix + n for n in self.names], self.rows, com, inertia, axis, o_at, o_R)

    def parts(self) -> list[Part]:
        """The stacked parts as :class:`Part` s (their arrays rows of the stack's)."""
        out = []
        for name, r, com, J, axis, at, R in zip(self.names, self.rows, self.com, self.inertia,
                                                self.axis, self.at, self.R):
            if isinstance(r, Pending):
                o = Outline(r.shape, r.dims, at, R)
                extra = EMPTY_MAPPING
            else:
                o = r.outline
                o = None if o is None else Outline(o.kind, o.dims, at, R, o.vertices, o.faces)
                extra = r.extra
            out.append(Part(name, r.shape, r.mass, r.subtract, com, J, r.measure, r.measure_kind,
                            r.radius, axis, extra, r.where, o))
        return out


def to_stack(items: list, start: int = 0) -> list:
    """``items`` with ``items[start:]`` replaced by one :class:`Stack` of them (in place):
    :func:`finish` for an included file."""
    if start < len(items):
        items[start:] = [Stack.of(items[start:])]
    return items


def parts_of(items: list) -> list[Part]:
    """Finished parts and stacks (an include's parts, :meth:`Stack.parts`) as one list of
    :class:`Part` s, in order."""
    out = []
    for p in items:
        if isinstance(p, Stack):
            out.extend(p.parts())
        else:
            out.append(p)
    return out
