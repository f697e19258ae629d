"""What the shop has and allows: the most mass a plane takes, the largest reading allowed,
the holes of each plane and the weights in the drawer (:func:`read`), from the parameters
(``max_mass``, ``limit``, ``drawer``, ``max_weights``, ``positions``) or the job file (a
plane's ``max_mass``, ``holes``, ``max_weights``, ``drawer``; a sensor's or speed's
``limit``; the job's ``drawer`` and ``max_weights``), never both.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from rbcli.api import options as op
from rbcli.api.field.readings import amplitude, read_at, split_measure
from rbcli.core.field.drawer import MOST_WEIGHTS, Plane
from rbcli.core.field.severity import convert_measure
from rbcli.errors import InputError, ParamError, literal
from rbcli.io import units as un

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.field.job import Job

__all__ = ["Drawer", "read"]

#: weights a plane takes from a drawer unless told
DEFAULT_WEIGHTS = 2


@dataclass(frozen=True)
class Drawer:
    """The discrete problem: per plane its :class:`rbcli.core.field.drawer.Plane`, hole
    angles (deg), hole radius (m or None) and numbering; the drawers ((masses kg, counts) —
    a count of None is any number, kept as 10⁶)."""

    planes: tuple[Plane, ...]
    angles: tuple[tuple[float, ...], ...]
    radii: tuple[float | None, ...]
    numbering: tuple[str, ...]
    drawers: tuple[tuple[tuple[float, int | None], ...], ...]


def _texts(v: Any) -> list[Any]:
    """A parameter's comma-separated items, or a job file's located texts."""
    if v is None:
        return []
    if isinstance(v, str):
        return [x.strip() for x in v.split(",")]
    return [x for t in v for x in ([t] if not isinstance(t, str) else _texts(t))]


def read(job: Job) -> Job:
    """``job`` with its mass limits, reading limits and drawer read (SI).

    Raises
    ------
    rbcli.InputError
        a value that cannot be read, a sensor that is not the job's, a drawer without
        holes, rounding beside a drawer.
    """
    o, src = job.options, job.source
    p = job.planes
    planes = src.planes if src is not None else ()
    pl = [planes[j] if j < len(planes) else None for j in range(p)]
    items = _texts(o.max_mass)
    if len(items) not in (0, 1, p):
        raise ParamError("max_mass", f"give one largest mass for every plane or one per plane ({p}), "
                                     f"not {len(items)}")
    with op.naming("max_mass"):
        mm = tuple(_mass_or_unbalance(items[0 if len(items) == 1 else j], "max_mass") if items else
                   (x.max_mass if x is not None else None) for j, x in enumerate(pl))
    limits = _limits(job, o.limit)
    job = replace(job, max_mass=mm, limits=limits)
    drawers = [_texts(o.drawer) or (src.drawer if src is not None else None) or []]
    drawers += [x.drawer for x in pl if x is not None and x.drawer is not None]
    if not any(drawers):
        return job
    if o.mass_step is not None or o.angle_step is not None:
        raise ParamError("drawer", "a drawer and rounding ({mass_step}, {angle_step}) do not go together: "
                                   "the drawer's weights are what is fitted")
    bare = src.units.get("mass", "g") if src is not None else "g"
    sizes = [tuple(read_at(t, lambda s: _size(s, bare)) for t in d) for d in drawers]
    for d in sizes:
        if len({m for m, _ in d}) != len(d):
            raise ParamError("drawer", "a drawer lists a mass twice; give each size once, with its count")
    return replace(job, drawer=_drawer(job, pl, sizes))


def _drawer(job: Job, pl: list, sizes: list) -> Drawer:
    """Each plane's holes, radius factor, most weights and drawer."""
    o, out, angles, radii, numbering = job.options, [], [], [], []
    k = 0
    for j, x in enumerate(pl):
        name = job.plane_names[j]
        holes = x.holes if x is not None else None
        if holes is None:
            n = job.positions[j]
            if not n:
                raise ParamError("drawer", f"plane {literal(name)} has no holes: give {{positions}} (N equally "
                                           "spaced) or, in a job file, the plane's holes")
        ang = holes.angles if holes is not None else tuple(360.0 * i / n for i in range(n))
        rr = job.plane_radii[j]
        r = holes.radius if holes is not None and holes.radius is not None else None if rr is None else rr[1]
        if r is not None and rr is None:
            raise ParamError("drawer", f"plane {literal(name)}: the hole radius needs the radius the trial sat at "
                                       "(the plane's radius)")
        most = (x.max_weights if x is not None and x.max_weights else None) or o.max_weights or DEFAULT_WEIGHTS
        if not 1 <= most <= MOST_WEIGHTS:
            raise ParamError("max_weights", f"must be from 1 to {MOST_WEIGHTS}, not {most}")
        lim = job.max_mass[j]
        top = math.inf if lim is None else lim[0] if lim[1] == "mass" else _per_radius(lim[0], r, name)
        own = x is not None and x.drawer is not None
        k += own
        out.append(Plane(tuple(math.radians(a) for a in ang), 1.0 if r is None else r / rr[0], most,
                         holes.per_hole if holes is not None else 1, top, k if own else 0))
        angles.append(ang)
        radii.append(r)
        numbering.append(holes.numbering if holes is not None else "with")
    return Drawer(tuple(out), tuple(angles), tuple(radii), tuple(numbering), tuple(sizes))


def _per_radius(unbalance: float, r: float | None, name: str) -> float:
    if r is None:
        raise ParamError("max_mass", f"plane {literal(name)}: a mass x radius limit needs the radius the weights "
                                     "go at")
    return unbalance / r


def _size(text: str, bare: str) -> tuple[float, int | None]:
    """``'5 g:4'`` -> (kg, 4); ``'5 g'`` -> (kg, None: any number)."""
    mass, _, count = text.partition(":")
    m = op.quantity(mass, "mass", "drawer", bare=bare)
    if not 1e-9 <= m <= 1e3:
        raise ParamError("drawer", f"'{literal(text)}': a weight's mass must be positive, from 1 µg to 1 t")
    if count and not (count.strip().isdigit() and 1 <= int(count) <= 100_000):
        raise ParamError("drawer", f"'{literal(text)}': the count after ':' must be a whole number from 1 to "
                                   "100000")
    return m, int(count) if count else None


def _mass_or_unbalance(text: Any, param: str) -> tuple[float, str]:
    """A positive mass (kg; a bare number is kg) or a mass x radius (kg m)."""
    if not isinstance(text, str):
        return op.quantity(text, "mass", param), "mass"
    try:
        value, dim = un.parse_quantity(text)
    except un.UnitError as exc:
        raise ParamError(param, f"'{literal(text)}': {literal(exc)}") from None
    kind = "mass" if dim in (un.Dim(), un.Dim(M=1)) else "unbalance" if dim == un.Dim(M=1, L=1) else None
    if kind is None or not 0.0 < value < math.inf:
        raise ParamError(param, f"must be a positive mass (e.g. '50 g') or mass x radius (e.g. '5000 g*mm'), "
                                f"not '{literal(text)}'")
    return value, kind


def _limits(job: Job, given: Any) -> tuple[float, ...] | None:
    """The largest reading allowed, per reading (inf: none), in the readings' unit and measure."""
    ns, n = len(job.sensors), len(job.initial)
    out = [math.inf] * n
    src = job.source
    for item in _texts(given):
        sensor, sep, amp = getattr(item, "text", item).rpartition("=")
        rows = [k for k in range(n) if not sep or job.sensors[k % ns] == sensor.strip()]
        if sep and not rows:
            raise ParamError("limit", f"no sensor is called '{literal(sensor.strip())}' (sensors: "
                                      f"{literal(', '.join(job.sensors))})")
        for k in rows:
            out[k] = min(out[k], _amplitude(job, amp, "limit"))
    if src is not None and given is None:
        for k in range(n):
            for t in (src.limits[k % ns] if k % ns < len(src.limits) else None,
                      src.speeds[k // ns].limit if k // ns < len(src.speeds) else None):
                if t is not None:
                    out[k] = min(out[k], read_at(t, lambda s: _amplitude(job, s, "limit")))
    return tuple(out) if any(math.isfinite(x) for x in out) else None


def _amplitude(job: Job, text: str, param: str) -> float:
    """A limit in the readings' unit and measure (the readings' measure when it says none)."""
    amp, measure = split_measure(text.strip())
    value, kind, _ = amplitude(amp, param, text)
    if kind != job.reading_kind:
        raise ParamError(param, f"'{literal(text)}' is {kind or 'a bare number'}; the readings are "
                                f"{job.reading_kind or 'bare numbers'}: give the limit as they are")
    if measure is not None and job.measure is None:
        raise ParamError(param, f"'{literal(text)}' says {measure}; the readings say no measure")
    if not 1e-100 <= value <= 1e100:
        raise ParamError(param, f"'{literal(text)}': a limit must be a positive amplitude, from 1e-100 to 1e100 (SI)")
    return value * (1.0 if measure is None else convert_measure(1.0, measure, job.measure))


def counts(d: tuple[tuple[float, int | None], ...]) -> tuple[np.ndarray, np.ndarray]:
    """A drawer as the search takes it: masses (kg) and counts (any number: 10⁶)."""
    return np.array([m for m, _ in d]), np.array([10**6 if c is None else c for _, c in d])

