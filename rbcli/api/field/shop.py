"""The shop's limits and drawer (:func:`read`): ``max_mass``, ``limit``, ``drawer``,
``max_weights``, ``positions`` from the parameters, or a job file's plane ``max_mass``,
``holes``, ``max_weights``, ``drawer``, sensor or speed ``limit`` — never both.
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
from rbcli.errors import ParamError, literal
from rbcli.io.field.jobfile import JobHoles, mass_or_unbalance

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.field.job import Job

__all__ = ["Drawer", "read", "counts"]

#: weights a plane takes from a drawer unless told
DEFAULT_WEIGHTS = 2


@dataclass(frozen=True)
class Drawer:
    """Per plane its search :class:`~rbcli.core.field.drawer.Plane` and holes (degrees,
    radius m or None, numbering); the drawers ((kg, count or None: any number) each)."""

    planes: tuple[Plane, ...]
    holes: tuple[JobHoles, ...]
    drawers: tuple[tuple[tuple[float, int | None], ...], ...]


def _texts(v: Any) -> list[Any]:
    """A parameter's comma-separated items, or a job file's located texts."""
    if v is None:
        return []
    return [x.strip() for x in v.split(",")] if isinstance(v, str) else [y for t in v for y in _texts(t)] \
        if not hasattr(v, "text") else [v]


def read(job: Job) -> Job:
    """``job`` with its mass limits, reading limits and drawer read (SI)."""
    o, src, p = job.options, job.source, job.planes
    pl = [src.planes[j] if src is not None and j < len(src.planes) else None for j in range(p)]
    items = _texts(o.max_mass)
    if len(items) not in (0, 1, p):
        raise ParamError("max_mass", f"give one largest mass for every plane or one per plane ({p}), not {len(items)}")
    mm = tuple(_max_mass(items[0 if len(items) == 1 else j]) if items else x and x.max_mass for j, x in enumerate(pl))
    for m, rr, name in zip(mm, job.plane_radii, job.plane_names):
        if m is not None and m[1] == "unbalance" and rr is None:
            raise ParamError("max_mass", f"plane {literal(name)}: a mass x radius limit needs the plane's radius")
    job = replace(job, max_mass=mm, limits=_limits(job, o.limit))
    drawers = [_texts(o.drawer) or (src and src.drawer) or []] + [x.drawer for x in pl if x and x.drawer]
    if not any(drawers):
        return job
    if o.mass_step is not None or o.angle_step is not None:
        raise ParamError("drawer", "a drawer and rounding ({mass_step}, {angle_step}) do not go together: the "
                                   "drawer's weights are what is fitted")
    bare = src.units.get("mass", "g") if src is not None else "g"
    sizes = tuple(tuple(read_at(t, lambda s: _size(s, bare)) for t in d) for d in drawers)
    if any(len({m for m, _ in d}) != len(d) for d in sizes):
        raise ParamError("drawer", "a drawer lists a mass twice; give each size once, with its count")
    return replace(job, drawer=Drawer(*_planes(job, pl, mm), sizes))


def _planes(job: Job, pl: list, mm: tuple) -> tuple[tuple[Plane, ...], tuple[JobHoles, ...]]:
    """Each plane's search :class:`Plane` and holes."""
    o, planes, holes, own = job.options, [], [], 0
    for j, x in enumerate(pl):
        name, rr = literal(job.plane_names[j]), job.plane_radii[j]
        h = x.holes if x is not None else None
        if h is None and not job.positions[j]:
            raise ParamError("drawer", f"plane {name} has no holes: give {{positions}} (N equally spaced) or, in "
                                       "a job file, the plane's holes")
        h = h or JobHoles(tuple(360.0 * i / job.positions[j] for i in range(job.positions[j])), None, "with", 1, None)
        r = h.radius if h.radius is not None else rr and rr[1]
        if r is not None and rr is None:
            raise ParamError("drawer", f"plane {name}: the hole radius needs the radius the trial sat at (the plane's "
                                       "radius)")
        most = (x and x.max_weights) or o.max_weights or DEFAULT_WEIGHTS
        if not 1 <= most <= MOST_WEIGHTS:
            raise ParamError("max_weights", f"must be from 1 to {MOST_WEIGHTS}, not {most}")
        lim = mm[j]
        own += bool(x and x.drawer)
        planes.append(Plane(tuple(math.radians(a) for a in h.angles), 1.0 if r is None else r / rr[0], most,
                            h.per_hole, math.inf if lim is None else lim[0] / (1.0 if lim[1] == "mass" else r),
                            own if x and x.drawer else 0))
        holes.append(replace(h, radius=r))
    return tuple(planes), tuple(holes)


def _size(text: str, bare: str) -> tuple[float, int | None]:
    """``'5 g:4'`` -> (kg, 4); ``'5 g'`` -> (kg, None: any number)."""
    mass, _, count = text.partition(":")
    m = op.quantity(mass, "mass", "drawer", bare=bare)
    if not 1e-9 <= m <= 1e3:
        raise ParamError("drawer", f"'{literal(text)}': a weight's mass must be positive, from 1 µg to 1 t")
    if count and not (count.strip().isdigit() and 1 <= int(count) <= 100_000):
        raise ParamError("drawer", f"'{literal(text)}': the count after ':' must be a whole number from 1 to 100000")
    return m, int(count) if count else None


def _max_mass(text: Any) -> tuple[float, str]:
    """A positive mass (kg; a bare number is kg) or a mass x radius (kg m)."""
    if not isinstance(text, str):
        with op.naming("max_mass"):
            return op.quantity(text, "mass", "max_mass"), "mass"
    got = mass_or_unbalance(text, 1.0)
    if isinstance(got, str) or got is None:
        raise ParamError("max_mass", f"must be a positive mass (e.g. '50 g') or mass x radius (e.g. '5000 g*mm'), "
                                     f"not '{literal(text)}'" + (f": {literal(got)}" if got else ""))
    return got


def _limits(job: Job, given: Any) -> tuple[float, ...] | None:
    """The largest reading allowed, per reading (inf: none), in the readings' unit and measure."""
    ns, n, src = len(job.sensors), len(job.initial), job.source
    out = [math.inf] * n
    for item in _texts(given):
        sensor, sep, amp = item.rpartition("=")
        rows = [k for k in range(n) if not sep or job.sensors[k % ns] == sensor.strip()]
        if sep and not rows:
            raise ParamError("limit", f"no sensor is called '{literal(sensor.strip())}' (sensors: "
                                      f"{literal(', '.join(job.sensors))})")
        for k in rows:
            out[k] = min(out[k], _amplitude(job, amp))
    for k in range(n) if src is not None and given is None else ():
        for t in (src.limits[k % ns], src.speeds[k // ns].limit):
            out[k] = out[k] if t is None else min(out[k], read_at(t, lambda s: _amplitude(job, s)))
    return tuple(out) if any(math.isfinite(x) for x in out) else None


def _amplitude(job: Job, text: str) -> float:
    """A limit in the readings' unit and measure (theirs when it says none)."""
    amp, measure = split_measure(text.strip())
    value, kind, _ = amplitude(amp, "limit", text)
    if kind != job.reading_kind or measure is not None and job.measure is None:
        raise ParamError("limit", f"'{literal(text)}' is {kind or 'a bare number'}{' ' + measure if measure else ''}; "
                                  f"the readings are {job.reading_kind or 'bare numbers'} "
                                  f"{job.measure or 'with no measure'}: give the limit as they are")
    if not 1e-100 <= value <= 1e100:
        raise ParamError("limit", f"'{literal(text)}': a limit must be a positive amplitude, from 1e-100 to 1e100 (SI)")
    return value * (1.0 if measure is None else convert_measure(1.0, measure, job.measure))


def counts(d: tuple[tuple[float, int | None], ...]) -> tuple[np.ndarray, np.ndarray]:
    """A drawer as the search takes it: masses (kg) and counts (any number: 10⁶)."""
    return np.array([m for m, _ in d]), np.array([10**6 if c is None else c for _, c in d])
