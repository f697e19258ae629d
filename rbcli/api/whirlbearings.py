"""The bearings of a whirl analysis: the body file's ``bearings:`` section
(:mod:`rbcli.io.bearingtable`) with the options given over it.

The override rule is the man page's ("The options override the section"); the options apply
in the order of :data:`OPTIONS` (``stiffness_xy`` overrides the kxy a follower stiffness sets),
what none sets comes from the section, else 0.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.api.params import Options, as_text
from rbcli.core import whirl as W
from rbcli.errors import InputError, ParamError, literal
from rbcli.io.bearingtable import BearingEntry, section

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body

__all__ = ["entries", "bearings", "per_bearing", "OPTIONS"]

#: each option and the coefficients (indices in kxx, kxy, kyx, kyy, cxx, cxy, cyx, cyy) it
#: sets, with their signs; stiffness and damping set y too unless their _y is given
OPTIONS = {"stiffness": ((0, 1.0), (3, 1.0)), "stiffness_y": ((3, 1.0),),
           "cross_stiffness": ((1, 1.0), (2, -1.0)), "stiffness_xy": ((1, 1.0),),
           "stiffness_yx": ((2, 1.0),), "damping": ((4, 1.0), (7, 1.0)), "damping_y": ((7, 1.0),),
           "damping_xy": ((5, 1.0),), "damping_yx": ((6, 1.0),)}


def entries(body: Body) -> tuple[BearingEntry, ...] | None:
    """The body file's ``bearings:`` section (None without one); tables are found beside
    the body file (the working directory for standard input and ``-e``)."""
    src = str(body.source)
    base = "." if src.startswith("<") or src == "-" else str(Path(src).parent)
    return section(body.text, src, dict(body.units or {}), base)


def per_bearing(vals: tuple[float, ...], given: Any, param: str, n: int) -> tuple[float, ...]:
    """One value for every bearing, or one per bearing (``n``): positive for a direct
    stiffness, >= 0 for a direct damping, any sign for a cross-coupled term."""
    if len(vals) not in (1, n):
        raise ParamError(param, f"expected {'1 or ' + str(n) if n > 1 else '1'} comma-separated "
                         f"value{'s' if n > 1 else ''}, got '{literal(as_text(given))}'")
    unit = "N s/m" if param.startswith("damping") else "N/m"
    for i, v in enumerate(vals):
        where = f" (bearing {i + 1})" if len(vals) > 1 else ""
        if param in ("stiffness", "stiffness_y") and not v > 0.0:
            raise ParamError(param, f"must be positive, got {v:.6g} {unit}{where}: a bearing "
                             "with no (or negative) stiffness does not hold the rotor")
        if param in ("damping", "damping_y") and v < 0.0:
            raise ParamError(param, f"must not be negative, got {v:.6g} {unit}{where}: a "
                             "negative damper feeds energy in")
    return vals * n if len(vals) == 1 else vals


def _check_positions(zs: tuple[float, ...], found: tuple[BearingEntry, ...] | None) -> None:
    """Two or more bearings at distinct places (named as the option, or located in the body
    file when the section gave them)."""
    def fail(i: int, msg: str) -> InputError:
        return ParamError("bearings", msg) if found is None else InputError(f"bearings[{i}]: {msg}", found[i].where)
    if len(zs) < 2:
        raise fail(0, f"a rotor on bearings needs two or more, got one (at z = {zs[0]:.6g} m): one "
                   "bearing cannot hold the rotor's tilt")
    for i in range(len(zs)):
        for j in range(i + 1, len(zs)):
            if zs[i] == zs[j]:
                if len(set(zs)) == 1:
                    raise fail(j, f"the bearings are all at one place (z = {zs[i]:.6g} m): nothing "
                               "holds the rotor's tilt; give positions along the shaft")
                raise fail(j, f"bearings {i + 1} and {j + 1} are both at z = {zs[i]:.6g} m; give each "
                           "its own place (or one bearing with the summed stiffness)")


def _sets(o: Options, name: str) -> tuple:
    if name == "stiffness" and o.stiffness_y is not None or name == "damping" and o.damping_y is not None:
        return OPTIONS[name][:1]
    return OPTIONS[name]


def bearings(body: Body, o: Options) -> tuple[tuple, tuple[str, ...], tuple[str, ...]]:
    """(core bearings, names, table sources) of ``o`` over the body's section.

    Raises
    ------
    rbcli.InputError
        a missing position or stiffness, values for the wrong number of bearings, naming
        the parameter or located in the body file.
    """
    found = entries(body)
    zs = o.bearings if o.bearings is not None else None if found is None else tuple(e.at for e in found)
    if zs is None:
        raise ParamError("bearings", "needs the bearing positions along the shaft, {bearings} "
                         "z1,z2[,...] (or a bearings: section in the body file)")
    if found is not None and len(found) != len(zs):
        found = None
    _check_positions(zs, None if o.bearings is not None else found)
    n = len(zs)
    tables = []
    for i, z in enumerate(zs):
        e = found[i] if found is not None else None
        if e is not None and e.speeds:
            tables.append((np.array(e.speeds), np.array(e.rows, dtype=float)))
        else:
            row = np.array([[e.values.get(k, np.nan) if e is not None else np.nan for k in
                             ("kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy")]])
            tables.append((None, row))
    for name in OPTIONS:
        value = getattr(o, name)
        if value is None:
            continue
        each = per_bearing(value, value, name, n)
        for (_, t), v in zip(tables, each):
            for col, sign in _sets(o, name):
                t[:, col] = sign * v
    out = []
    for i, (z, (speeds, t)) in enumerate(zip(zs, tables)):
        if np.isnan(t[:, [0, 3]]).any():
            where = found[i].where if found is not None else None
            msg = "needs the bearing stiffness, {stiffness} k (N/m, one for all bearings or one " \
                  "per bearing)" + (f", or k (kxx and kyy) or a table for bearing {i + 1} in the " \
                                    "body file's bearings: section" if found is not None else "")
            raise ParamError("stiffness", msg, where)
        t = np.nan_to_num(t, nan=0.0)
        out.append(W.BearingTable(z, speeds, t) if speeds is not None else
                   W.Bearing(z, *(float(t[0, c]) for c in (0, 3, 1, 2, 4, 7, 5, 6))))
    names = tuple(e.name for e in found) if found is not None else tuple(f"bearing {i + 1}" for i in range(n))
    sources = tuple(e.table for e in found) if found is not None else ("",) * n
    return tuple(out), names, sources
