"""Read a field-balancing job file (YAML) into a checked :class:`FieldJob`, every problem at
``file:line:col``; its keys are declared in ``rbcli/data/fieldjob.schema.json``. Readings,
masses, limits and drawers stay located texts, read by :mod:`rbcli.api.field` as parameters.
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rbcli.errors import InputError, Location
from rbcli.io import units as un
from rbcli.io import yamlsafe as ys
from rbcli.io import yamlvalues as fl
from rbcli.io.field import CHOICES, plane_names
from rbcli.io.reader import read_regular
from rbcli.io.yamlvalues import FileContext as _Ctx

SCHEMA_PATH = Path(__file__).resolve().parents[2] / "data" / "fieldjob.schema.json"

#: a job file is refused above this size (bytes): a job holds a few hundred readings
MAX_JOB_BYTES = 4 * 1024 * 1024

#: the job file's keys, declared once in its JSON Schema (:func:`schema_text`)
_P = json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))["properties"]
TOP_KEYS = tuple(_P)
UNIT_KEYS, CONVENTION_KEYS, SEVERITY_KEYS, ROTOR_KEYS = (tuple(_P[k]["properties"]) for k in
                                                         ("units", "conventions", "severity", "rotor"))
PLANE_KEYS, TRIAL_KEYS = (tuple(_P[k]["items"]["properties"]) for k in ("planes", "trials"))
SENSOR_KEYS, SPEED_KEYS = (tuple(_P[k]["items"]["anyOf"][1]["properties"]) for k in ("sensors", "speeds"))
HOLE_KEYS = tuple(_P["planes"]["items"]["properties"]["holes"]["properties"])


@dataclass(frozen=True)
class Text:
    """A value as written (a reading, a mass, a limit) and where."""

    text: str
    where: Location


@dataclass(frozen=True)
class JobHoles:
    """A plane's holes: angles (deg, hole 1 first), radius (m or None), numbering, per_hole."""

    angles: tuple[float, ...]
    radius: float | None
    numbering: str
    per_hole: int
    where: Location


@dataclass(frozen=True)
class JobPlane:
    """A plane: lengths m (or None); max_mass (kg, "mass") or (kg m, "unbalance")."""

    name: str
    radius: float | None
    correction_radius: float | None
    positions: int | None
    at: float | None
    where: Location
    holes: JobHoles | None = None
    max_mass: tuple[float, str] | None = None
    max_weights: int | None = None
    drawer: tuple[Text, ...] | None = None


@dataclass(frozen=True)
class JobSpeed:
    """A speed: rad/s or None; the largest reading at it."""

    name: str
    speed: float | None
    where: Location
    limit: Text | None = None


@dataclass(frozen=True)
class JobTrial:
    """A plane's trial run: its mass@angle, readings per speed per sensor."""

    plane: str
    mass: Text
    readings: tuple[tuple[Text, ...], ...]
    where: Location


@dataclass(frozen=True)
class JobRotor:
    """What sizes a trial mass (kg, a path, m, N, m/s²)."""

    mass: float | None
    body: str | None
    bearings: tuple[float, float] | None
    com: float | None
    bearing_load: float | None
    g: float | None
    trial_fraction: float | None
    where: Location


@dataclass(frozen=True)
class FieldJob:
    """A checked job file (SI; readings as located texts, per speed per sensor); ``keys``:
    where each top-level key is; ``units``: the file's bare units (masses g by default)."""

    source: str
    name: str | None
    sensors: tuple[str, ...]
    weights: tuple[float, ...] | None
    limits: tuple[Text | None, ...]
    planes: tuple[JobPlane, ...]
    speeds: tuple[JobSpeed, ...]
    initial: tuple[tuple[Text, ...], ...] | None
    trials: tuple[JobTrial, ...]
    cumulative: bool | None
    method: str | None
    mass_step: float | None
    angle_step: float | None
    measure: str | None
    phase: str | None
    angle_sense: str | None
    rotation: str | None
    severity: tuple[str, int, str] | None
    rotor: JobRotor | None
    coefficients: str | None
    keys: dict[str, Location]
    units: dict[str, str]
    drawer: tuple[Text, ...] | None = None
    max_weights: int | None = None
    robust: str | None = None


def load_job(path: str) -> FieldJob:
    """Read and check the job file ``path``.

    Raises
    ------
    rbcli.InputError
        one located line for any problem (the file, its YAML, a key, a value).
    """
    data = read_regular(path, MAX_JOB_BYTES, "job file")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(f"the job file is not UTF-8 text (byte {exc.start})", Location(path)) from None
    return load_job_text(text, path)


def load_job_text(text: str, source: str = "<job>") -> FieldJob:
    """Check the text of a job file (``source`` names it in messages and resolves a
    relative ``coefficients`` or ``rotor.body`` path)."""
    if not text.strip():
        raise InputError("the job file is empty; a job names its sensors, planes and runs "
                         "(see rbcli-field-balance(1))", Location(source, 1, 1))
    ctx = _Ctx(source, {})
    m = fl.mapping(ctx, ys.load(text, source), "a field-balancing job")
    fl.check_keys(ctx, m, TOP_KEYS, "the job")
    items = m.items
    _header(ctx, items)
    ctx.base_units = _units(ctx, items)
    name = fl.string(ctx, items["name"][1], "name") if "name" in items else None
    if "description" in items:
        fl.string(ctx, items["description"][1], "description")
    conv = _choices(ctx, items, "conventions", CONVENTION_KEYS)
    measure = _choices(ctx, items, "readings", ("measure",)).get("measure")
    sensors, weights, limits = _sensors(ctx, items)
    planes = _planes(ctx, items)
    speeds = _speeds(ctx, items)
    coefficients = None
    if "coefficients" in items:
        coefficients = _relative(source, fl.string(ctx, items["coefficients"][1], "coefficients"))
    initial, trials = _all_runs(ctx, m, planes, speeds, coefficients)
    n = _check_counts(ctx, initial, trials, sensors)
    if sensors and len(sensors) != n:
        raise ctx.error(items["sensors"][1], f"sensors names {len(sensors)} sensors but the runs have "
                                             f"{n} readings per speed")
    return FieldJob(
        source=source, name=name, sensors=sensors or tuple(str(i + 1) for i in range(n)),
        weights=weights, limits=limits or (None,) * n, planes=planes, speeds=speeds, initial=initial, trials=trials,
        measure=measure, phase=conv.get("phase"), angle_sense=conv.get("angle_sense"),
        rotation=conv.get("rotation"), severity=_severity(ctx, items), rotor=_rotor(ctx, items, source),
        coefficients=coefficients, keys={k: ctx.where(mark) for k, (mark, _) in items.items()},
        units=dict(ctx.base_units), drawer=_texts(ctx, items["drawer"][1], "drawer", "mass:count, e.g. "
                                                  "'5 g:4'") if "drawer" in items else None,
        max_weights=_count(ctx, items["max_weights"][1], "max_weights", 1, 4) if "max_weights" in items else None,
        robust=_choice(ctx, items["robust"][1], "robust", "robust") if "robust" in items else None,
        **_settings(ctx, items))


def _header(ctx: _Ctx, items: dict) -> None:
    """``rbcli: 1`` and ``job: field-balance``, when given."""
    v = items.get("rbcli", (None, None))[1]
    if v is not None and not (isinstance(v, ys.ScalarNode) and v.value == 1 and not isinstance(v.value, bool)):
        raise ctx.error(v, f"rbcli: this rbcli reads format 1, not {fl.describe(v)}")
    if "job" in items and fl.string(ctx, v := items["job"][1], "job") != "field-balance":
        raise ctx.error(v, f"job: this is rbcli field-balance's job file; 'job' must be field-balance, not "
                           f"{fl.describe(v)}")


def _units(ctx: _Ctx, items: dict) -> dict[str, str]:
    """What bare numbers are in (a bare trial mass in grams, as on the command line)."""
    units = {"mass": "g"}
    if "units" in items:
        um = fl.mapping(ctx, items["units"][1], "units")
        fl.check_keys(ctx, um, UNIT_KEYS, "units")
        for k, (_, node) in um.items.items():
            units[k] = fl.string(ctx, node, f"units: {k}")
            try:
                un.unit_for_kind({k: units[k]}, k)
            except un.UnitError as exc:
                raise ctx.error(node, f"units: {k}: {exc}") from None
    return units


def _all_runs(ctx: _Ctx, m: ys.MapNode, planes: tuple[JobPlane, ...], speeds: tuple[JobSpeed, ...],
              coefficients: str | None) -> tuple[tuple[tuple[Text, ...], ...] | None, tuple[JobTrial, ...]]:
    """The initial readings and the trial runs (none for a trim run)."""
    items = m.items
    initial = None
    if "initial" in items:
        initial = _runs(ctx, items["initial"][1], speeds, "initial")
    elif "trials" in items or coefficients is None:
        raise ctx.error(m, "the job needs 'initial': the readings without trial masses")
    trials = _trials(ctx, items, planes, speeds)
    if coefficients is not None and trials:
        raise ctx.error(items["coefficients"][0], "a trim run from saved coefficients takes 'initial' alone; "
                                                  "leave out 'trials' (the coefficients hold them)")
    if coefficients is None and not trials:
        raise ctx.error(m, "the job needs 'trials' (one trial run per plane), or 'coefficients' "
                           "(a file of saved influence coefficients) for a trim run")
    return initial, trials


def _settings(ctx: _Ctx, items: dict) -> dict[str, Any]:
    """cumulative, method, mass_step (kg) and angle_step (degrees), None when not given."""
    it = {k: items[k][1] for k in ("cumulative", "method", "mass_step", "angle_step") if k in items}
    angle_step = None
    if "angle_step" in it:
        angle_step = math.degrees(fl.positive(ctx, it["angle_step"], "angle", "angle_step"))
        if not angle_step <= 360.0 * (1 + 1e-12):
            raise ctx.error(it["angle_step"], "angle_step must not exceed 360 degrees")
    return dict(
        cumulative=fl.flag(ctx, it["cumulative"], "cumulative") if "cumulative" in it else None,
        method=_choice(ctx, it["method"], "method", "method") if "method" in it else None,
        mass_step=fl.positive(ctx, it["mass_step"], "mass", "mass_step") if "mass_step" in it else None,
        angle_step=angle_step)


def _relative(source: str, path: str) -> str:
    """A path written in the job file, relative to the job file's folder."""
    if os.path.isabs(path) or source.startswith("<"):
        return path
    return os.path.join(os.path.dirname(source), path) if os.path.dirname(source) else path


def _choice(ctx: _Ctx, node: ys.Node, key: str, what: str) -> str:
    allowed = CHOICES[key]
    word = fl.string(ctx, node, what)
    if word not in allowed:
        raise ctx.error(node, f"{what} must be {' or '.join(allowed)}, not '{word}'{fl.suggest(word, allowed)}")
    return word


def _choices(ctx: _Ctx, items: dict, key: str, keys: tuple[str, ...]) -> dict[str, str]:
    """A mapping of words (``conventions``, ``readings``), each one of its key's choices."""
    if key not in items:
        return {}
    cm = fl.mapping(ctx, items[key][1], key)
    fl.check_keys(ctx, cm, keys, key)
    return {k: _choice(ctx, node, k, f"{key}: {k}") for k, (_, node) in cm.items.items()}


def _name(ctx: _Ctx, node: ys.Node, what: str, seen: set[str]) -> str:
    if isinstance(node, ys.ScalarNode) and isinstance(node.value, (int, float)) and not isinstance(node.value, bool):
        name = node.raw  # a sensor called 1 or 2
    else:
        name = fl.string(ctx, node, what)
    if not name.strip():
        raise ctx.error(node, f"{what} must not be empty")
    if name in seen:
        raise ctx.error(node, f"two {what}s are called '{name}'; names must differ")
    seen.add(name)
    return name


def _sensors(ctx: _Ctx, items: dict) -> tuple[tuple[str, ...], tuple[float, ...] | None, tuple]:
    """The sensors' names, weights (None: none given) and limits (a Text or None each)."""
    if "sensors" not in items:
        return (), None, ()
    node = items["sensors"][1]
    if not isinstance(node, ys.SeqNode) or not node.items:
        raise ctx.error(node, f"sensors must be a list of sensor names, not {fl.describe(node)}")
    names, weights, limits, seen = [], [], [], set()
    for item in node.items:
        it = item.items if isinstance(item, ys.MapNode) else {}
        if isinstance(item, ys.MapNode):
            fl.check_keys(ctx, item, SENSOR_KEYS, "a sensor", required=("name",))
        names.append(_name(ctx, it["name"][1] if it else item, "sensor name", seen))
        weights.append(fl.positive(ctx, it["weight"][1], "dimensionless", "weight") if "weight" in it else None)
        limits.append(_text(ctx, it["limit"][1], f"sensor {names[-1]}: limit") if "limit" in it else None)
    return (tuple(names), None if weights == [None] * len(weights) else tuple(w or 1.0 for w in weights),
            tuple(limits))


def _text(ctx: _Ctx, node: ys.Node, what: str, eg: str = "'2.8 mm/s'") -> Text:
    """A value kept as written (a reading, a limit, a mass) and where it is."""
    if not isinstance(node, ys.ScalarNode) or node.value is None or isinstance(node.value, bool):
        raise ctx.error(node, f"{what} must be a value such as {eg}, not {fl.describe(node)}")
    return Text(node.raw if not isinstance(node.value, str) else node.value, ctx.where(node))


def _count(ctx: _Ctx, node: ys.Node, what: str, low: int, high: int) -> int:
    if not (isinstance(node, ys.ScalarNode) and isinstance(node.value, int) and not isinstance(node.value, bool)
            and low <= node.value <= high):
        raise ctx.error(node, f"{what} must be a whole number from {low} to {high}, not {fl.describe(node)}")
    return int(node.value)


def _planes(ctx: _Ctx, items: dict) -> tuple[JobPlane, ...]:
    if "planes" not in items:
        return ()
    node = items["planes"][1]
    if not isinstance(node, ys.SeqNode) or not node.items:
        raise ctx.error(node, f"planes must be a list of planes, not {fl.describe(node)}")
    out = []
    seen: set[str] = set()
    for item in node.items:
        pm = fl.mapping(ctx, item, "a plane")
        fl.check_keys(ctx, pm, PLANE_KEYS, "a plane", required=("name",))
        it = pm.items
        name = _name(ctx, it["name"][1], "plane name", seen)
        radius = fl.positive(ctx, it["radius"][1], "length", f"plane {name}: radius") if "radius" in it else None
        rc = None
        if "correction_radius" in it:
            rc = fl.positive(ctx, it["correction_radius"][1], "length", f"plane {name}: correction_radius")
            if radius is None:
                raise ctx.error(it["correction_radius"][0], f"plane {name}: correction_radius needs the "
                                                            "trial radius, 'radius'")
        if "positions" in it and "holes" in it:
            raise ctx.error(it["holes"][0], f"plane {name}: give its holes or its positions, not both")
        positions = _count(ctx, it["positions"][1], f"plane {name}: positions", 3,
                           100_000) if "positions" in it else None
        at = fl.number(ctx, it["at"][1], "length", f"plane {name}: at") if "at" in it else None
        out.append(JobPlane(
            name, radius, rc, positions, at, ctx.where(item),
            _holes(ctx, it["holes"][1], f"plane {name}: holes") if "holes" in it else None,
            _mass_or_unbalance(ctx, it["max_mass"][1], f"plane {name}: max_mass") if "max_mass" in it else None,
            _count(ctx, it["max_weights"][1], f"plane {name}: max_weights", 1, 4) if "max_weights" in it else None,
            _texts(ctx, it["drawer"][1], f"plane {name}: drawer", "mass:count, e.g. '5 g:4'")
            if "drawer" in it else None))
    return tuple(out)


def _holes(ctx: _Ctx, node: ys.Node, what: str) -> JobHoles:
    """``{count, zero}`` or ``{angles}``, with radius, numbering and per_hole."""
    hm = fl.mapping(ctx, node, what)
    fl.check_keys(ctx, hm, HOLE_KEYS, what)
    it = hm.items
    if ("count" in it) == ("angles" in it):
        raise ctx.error(hm, f"{what} needs 'count' (equally spaced from 'zero') or 'angles' (a list), one of them")
    numbering = _choice(ctx, it["numbering"][1], "numbering", f"{what}: numbering") if "numbering" in it else "with"
    sign = 1.0 if numbering == "with" else -1.0
    if "count" in it:
        n = _count(ctx, it["count"][1], f"{what}: count", 1, 3600)
        zero = math.degrees(fl.number(ctx, it["zero"][1], "angle", f"{what}: zero")) if "zero" in it else 0.0
        angles = tuple((zero + sign * 360.0 * k / n) % 360.0 for k in range(n))
    else:
        an = it["angles"][1]
        if not isinstance(an, ys.SeqNode) or not 1 <= len(an.items) <= 3600:
            raise ctx.error(an, f"{what}: angles must be a list of 1 to 3600 angles, not {fl.describe(an)}")
        angles = tuple(math.degrees(fl.number(ctx, a, "angle", f"{what}: angles")) % 360.0 for a in an.items)
    return JobHoles(angles, fl.positive(ctx, it["radius"][1], "length", f"{what}: radius") if "radius" in it else None,
                    numbering, _count(ctx, it["per_hole"][1], f"{what}: per_hole", 1, 4) if "per_hole" in it else 1,
                    ctx.where(node))


def mass_or_unbalance(text: str, bare: float) -> tuple[float, str] | str | None:
    """``'50 g'`` -> (kg, "mass"), ``'5000 g*mm'`` -> (kg m, "unbalance"), a bare number
    times ``bare``; None for anything not positive and finite, the unit's error in words."""
    try:
        value, dim = un.parse_quantity(text)
    except un.UnitError as exc:
        return str(exc)
    kind = {un.Dim(): "mass", un.Dim(M=1): "mass", un.Dim(M=1, L=1): "unbalance"}.get(dim)
    value *= bare if dim == un.Dim() else 1.0
    return (value, kind) if kind is not None and 0.0 < value < math.inf else None


def _mass_or_unbalance(ctx: _Ctx, node: ys.Node, what: str) -> tuple[float, str]:
    """A positive mass (kg; bare: the file's mass unit) or mass x radius (kg m)."""
    got = mass_or_unbalance(node.value, ctx.factor("mass", node)[0]) if isinstance(node, ys.ScalarNode) and \
        isinstance(node.value, str) else (fl.positive(ctx, node, "mass", what), "mass")
    if not isinstance(got, tuple):
        raise ctx.error(node, f"{what} must be a positive mass ('50 g') or mass x radius ('5000 g*mm'), not "
                              f"{fl.describe(node)}" + (f": {got}" if got else ""))
    return got


def _speeds(ctx: _Ctx, items: dict) -> tuple[JobSpeed, ...]:
    if "speeds" not in items:
        return (JobSpeed("", None, ctx.where(None)),)
    node = items["speeds"][1]
    if not isinstance(node, ys.SeqNode) or not node.items:
        raise ctx.error(node, f"speeds must be a list of speeds, not {fl.describe(node)}")
    out = []
    seen: set[str] = set()
    for i, item in enumerate(node.items):
        limit = None
        if isinstance(item, ys.MapNode):
            fl.check_keys(ctx, item, SPEED_KEYS, "a speed", required=("name",))
            name = _name(ctx, item.items["name"][1], "speed name", seen)
            w = (fl.positive(ctx, item.items["speed"][1], "angular_speed", f"speed {name}")
                 if "speed" in item.items else None)
            if "limit" in item.items:
                limit = _text(ctx, item.items["limit"][1], f"speed {name}: limit")
        else:  # a bare speed: named by its text
            w = fl.positive(ctx, item, "angular_speed", "speed")
            name = _name(ctx, item, "speed name", seen) if isinstance(item, ys.ScalarNode) else str(i + 1)
        out.append(JobSpeed(name, w, ctx.where(item), limit))
    return tuple(out)


def _texts(ctx: _Ctx, node: ys.Node, what: str, form: str = "readings amplitude@phase, one per sensor") -> tuple[Text, ...]:
    if not isinstance(node, ys.SeqNode) or not node.items:
        raise ctx.error(node, f"{what} must be a list of {form}, not {fl.describe(node)}")
    return tuple(_text(ctx, item, what, "'6.2 mm/s@112'" if "@" in form else "'5 g:4'") for item in node.items)


def _runs(ctx: _Ctx, node: ys.Node, speeds: tuple[JobSpeed, ...], what: str) -> tuple[tuple[Text, ...], ...]:
    """One run's readings: a list (one speed) or a mapping speed name -> list."""
    if isinstance(node, ys.SeqNode):
        if len(speeds) != 1:
            raise ctx.error(node, f"{what}: with {len(speeds)} speeds give the readings per speed, "
                                  f"e.g. {{{speeds[0].name}: [...], {speeds[1].name}: [...]}}")
        return (_texts(ctx, node, what),)
    rm = fl.mapping(ctx, node, what)
    names = [s.name for s in speeds]
    fl.check_keys(ctx, rm, names, f"{what} (the speeds)")
    out = []
    for s in speeds:
        if s.name not in rm.items:
            raise ctx.error(rm, f"{what} has no readings at speed '{s.name}'")
        out.append(_texts(ctx, rm.items[s.name][1], f"{what} at {s.name}"))
    return tuple(out)


def _trials(ctx: _Ctx, items: dict, planes: tuple[JobPlane, ...], speeds: tuple[JobSpeed, ...]) -> tuple[JobTrial, ...]:
    if "trials" not in items:
        return ()
    node = items["trials"][1]
    if not isinstance(node, ys.SeqNode) or not node.items:
        raise ctx.error(node, f"trials must be a list of trial runs, one per plane, not {fl.describe(node)}")
    names = [p.name for p in planes]
    by_plane: dict[str, JobTrial] = {}
    order: list[str] = []
    for i, item in enumerate(node.items):
        tm = fl.mapping(ctx, item, "a trial run")
        fl.check_keys(ctx, tm, TRIAL_KEYS, "a trial run", required=("mass", "readings"))
        it = tm.items
        if "plane" in it:
            plane = _name(ctx, it["plane"][1], "trial plane", set())
            if names and plane not in names:
                raise ctx.error(it["plane"][1], f"no plane is called '{plane}'{fl.suggest(plane, names)} "
                                                f"(planes: {', '.join(names)})")
        elif names:
            raise ctx.error(tm, "a trial run needs 'plane': the plane its trial mass sat in")
        else:
            plane = plane_names(i + 1)[i]
        if plane in by_plane:
            raise ctx.error(it.get("plane", (tm.mark, tm))[1], f"plane {plane} has two trial runs; give one per plane")
        mnode = it["mass"][1]
        if not isinstance(mnode, ys.ScalarNode) or not isinstance(mnode.value, str):
            raise ctx.error(mnode, f"mass must be mass@angle, e.g. '50 g@0', not {fl.describe(mnode)}")
        by_plane[plane] = JobTrial(plane, Text(mnode.value, ctx.where(mnode)),
                                   _runs(ctx, it["readings"][1], speeds, f"trial {plane} readings"),
                                   ctx.where(item))
        order.append(plane)
    if names:
        missing = [p for p in names if p not in by_plane]
        if missing:
            raise ctx.error(node, f"no trial run for plane {', '.join(missing)}; give one per plane")
        return tuple(by_plane[p] for p in names)
    return tuple(by_plane[p] for p in order)


def _check_counts(ctx: _Ctx, initial: Any, trials: tuple[JobTrial, ...], sensors: tuple[str, ...]) -> int:
    """The number of sensors, the same in every run at every speed."""
    runs = ([("initial", initial)] if initial is not None else []) + [(f"trial {t.plane}", t.readings) for t in trials]
    n = len(sensors) if sensors else len(runs[0][1][0]) if runs else 0
    for what, per_speed in runs:
        for texts in per_speed:
            if len(texts) != n:
                raise InputError(f"{what}: {len(texts)} readings where the job has {n} sensors; give one "
                                 "reading per sensor, in the sensors' order", texts[0].where)
    return n


def _severity(ctx: _Ctx, items: dict) -> tuple[str, int, str] | None:
    if "severity" not in items:
        return None
    sm = fl.mapping(ctx, items["severity"][1], "severity")
    fl.check_keys(ctx, sm, SEVERITY_KEYS, "severity", required=("group", "foundation"))
    it = sm.items
    std = _choice(ctx, it["standard"][1], "standard", "severity: standard") if "standard" in it else "iso20816-3"
    g = it["group"][1]
    if not (isinstance(g, ys.ScalarNode) and g.value in (1, 2) and not isinstance(g.value, bool)):
        raise ctx.error(g, f"severity: group must be 1 (large machines, above 300 kW) or 2 (15 to 300 kW), not {fl.describe(g)}")
    return std, int(g.value), _choice(ctx, it["foundation"][1], "foundation", "severity: foundation")


def _rotor(ctx: _Ctx, items: dict, source: str) -> JobRotor | None:
    if "rotor" not in items:
        return None
    rm = fl.mapping(ctx, items["rotor"][1], "rotor")
    fl.check_keys(ctx, rm, ROTOR_KEYS, "rotor")
    it = rm.items
    if ("mass" in it) == ("body" in it):
        raise ctx.error(rm, "rotor needs its 'mass' or a 'body' file (one of them)")
    b = fl.floats(ctx, it["bearings"][1], "length", "rotor: bearings", n=2) if "bearings" in it else None
    if b and b[0] == b[1]:
        raise ctx.error(it["bearings"][1], "rotor: bearings: the two bearings must be at different positions")
    read = {k: (fl.number if k == "com" else fl.positive)(ctx, it[k][1], kind, f"rotor: {k}") if k in it else None
            for k, kind in (("mass", "mass"), ("com", "length"), ("bearing_load", "force"), ("g", "acceleration"),
                            ("trial_fraction", "dimensionless"))}
    return JobRotor(read["mass"], _relative(source, fl.string(ctx, it["body"][1], "rotor: body")) if "body" in it
                    else None, b and (b[0], b[1]), read["com"], read["bearing_load"], read["g"], read["trial_fraction"],
                    ctx.where(rm))


def schema_text() -> str:
    """The JSON Schema of a job file (``rbcli/data/fieldjob.schema.json``, the declaration of
    its keys), as ``--job-schema`` prints it."""
    return SCHEMA_PATH.read_text(encoding="utf-8")
