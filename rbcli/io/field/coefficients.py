"""Read a file of influence coefficients written by ``--save-coefficients``: JSON (version 2;
version 1, without a fingerprint, is read too) with a ``sha256:`` fingerprint of
:data:`FINGERPRINTED`, rows every sensor at every speed, speed by speed, and ``re``, ``im``
exact (they read back bit for bit). A file changed since written, or whose rows are out of
order, repeated or missing, is refused — never read in another order.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from typing import Any

from rbcli.errors import InputError, Location
from rbcli.io.field import CHOICES
from rbcli.io.reader import read_regular

FORMAT = "rbcli field-balance influence coefficients"
VERSION = 2
#: the keys the fingerprint covers (everything the file says of its job and coefficients)
FINGERPRINTED = ("influence", "conventions", "sensors", "speeds", "planes", "rows", "coefficients")


def fingerprint(doc: dict) -> str:
    """``sha256:`` of the fingerprinted keys of a coefficients document, as canonical JSON."""
    text = json.dumps({k: doc.get(k) for k in FINGERPRINTED}, sort_keys=True, separators=(",", ":"))
    return "sha256:" + hashlib.sha256(text.encode("utf-8")).hexdigest()
MAX_COEFF_BYTES = 8 * 1024 * 1024


@dataclass(frozen=True)
class SavedCoefficients:
    """What a coefficients file holds (SI; ``coefficients[k][j]``: reading k, plane j, per kg)."""

    source: str
    reading_kind: str | None
    measure: str | None
    phase: str | None
    angle_sense: str | None
    rotation: str | None
    sensors: tuple[str, ...]
    speeds: tuple[tuple[str, float | None], ...]
    planes: tuple[tuple[str, float | None], ...]
    rows: tuple[tuple[str, str], ...]
    coefficients: tuple[tuple[complex, ...], ...]


def _err(source: str, message: str) -> InputError:
    return InputError(message, Location(source))


def _get(d: Any, key: str, source: str, what: str) -> Any:
    if not isinstance(d, dict) or key not in d:
        raise _err(source, f"not a coefficients file: {what} has no '{key}'")
    return d[key]


def _opt_str(v: Any, allowed: tuple[str, ...], source: str, what: str) -> str | None:
    if v is None:
        return None
    if v not in allowed:
        raise _err(source, f"{what} must be {' or '.join(allowed)} or null, not {v!r}")
    return str(v)


def _number(v: Any, source: str, what: str, *, positive: bool = False) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not abs(v) < 1e308:
        raise _err(source, f"{what} must be a finite number, not {v!r}")
    if positive and not v > 0:
        raise _err(source, f"{what} must be positive, not {v!r}")
    return float(v)


def load_coefficients(path: str) -> SavedCoefficients:
    """Read and check a coefficients file.

    Raises
    ------
    rbcli.InputError
        a file that cannot be read, is not JSON, or is not a coefficients file of this
        format (one line naming the file and what is wrong).
    """
    data = read_regular(path, MAX_COEFF_BYTES, "coefficients file")
    try:
        doc = json.loads(data.decode("utf-8"))
    except UnicodeDecodeError:
        raise _err(path, "the coefficients file is not UTF-8 text") from None
    except json.JSONDecodeError as exc:
        raise InputError(f"invalid JSON: {exc.msg}", Location(path, exc.lineno, exc.colno)) from None
    except RecursionError:
        raise _err(path, "invalid JSON: nested too deeply") from None
    return parse_coefficients(doc, path)


def parse_coefficients(doc: Any, source: str = "<coefficients>") -> SavedCoefficients:
    """Check a coefficients document (parsed JSON)."""
    if not isinstance(doc, dict) or doc.get("format") != FORMAT:
        raise _err(source, f"not a coefficients file: its 'format' is not '{FORMAT}'")
    if doc.get("version") not in (1, VERSION):
        raise _err(source, f"coefficients file version {doc.get('version')!r}; this rbcli reads versions 1 and {VERSION}")
    if doc["version"] == VERSION and doc.get("fingerprint") != fingerprint(doc):
        raise _err(source, "the file does not match its fingerprint: its rows, names, units or coefficients "
                           "were changed after rbcli wrote it; save the coefficients again (--save-coefficients)")
    inf = _get(doc, "influence", source, "the file")
    kind = _opt_str(_get(inf, "reading_kind", source, "influence"), ("displacement", "velocity", "acceleration"),
                    source, "influence.reading_kind")
    measure = _opt_str(inf.get("measure"), CHOICES["measure"], source, "influence.measure")
    conv = _get(doc, "conventions", source, "the file")
    if not isinstance(inf, dict) or not isinstance(conv, dict):
        raise _err(source, "influence and conventions must be objects {key: value}")
    words = {k: _opt_str(conv.get(k), CHOICES[k], source, f"conventions.{k}")
             for k in ("phase", "angle_sense", "rotation")}
    sensors = _get(doc, "sensors", source, "the file")
    if not isinstance(sensors, list) or not sensors or not all(isinstance(s, str) for s in sensors):
        raise _err(source, "sensors must be a list of names")
    speeds = _named(doc, ("speeds", "speed"), ("a speed", "a speed"), source)
    planes = _named(doc, ("planes", "trial_radius"), ("a plane", "a trial radius"), source)
    rows = _rows(_get(doc, "rows", source, "the file"), sensors, speeds, source)
    return SavedCoefficients(
        source=source, reading_kind=kind, measure=measure, sensors=tuple(sensors), speeds=speeds,
        planes=planes, rows=rows, coefficients=_coefficients(
            _get(doc, "coefficients", source, "the file"), len(rows), len(planes), source), **words)


def _named(doc: dict, keys: tuple[str, str], words: tuple[str, str],
           source: str) -> tuple[tuple[str, float | None], ...]:
    """``speeds`` [{name, speed}] or ``planes`` [{name, trial_radius}] (``keys``): (name,
    positive number or None); ``words`` say an item and its number in messages."""
    key, value = keys
    item, number = words
    items = _get(doc, key, source, "the file")
    if not isinstance(items, list) or not items:
        raise _err(source, f"{key} must be a list of {{name, {value}}}")
    out = []
    for it in items:
        name, x = _get(it, "name", source, item), _get(it, value, source, item)
        if not isinstance(name, str):
            raise _err(source, f"{item}'s name must be a text")
        out.append((name, None if x is None else _number(x, source, number, positive=True)))
    return tuple(out)


def _rows(rows: Any, sensors: list[str], speeds: tuple, source: str) -> tuple[tuple[str, str], ...]:
    """(sensor, speed) of each reading: every sensor at every speed, speed by speed."""
    want = [(s, v) for v, _ in speeds for s in sensors]
    if len(set(sensors)) != len(sensors) or len({v for v, _ in speeds}) != len(speeds):
        raise _err(source, "the sensors' names and the speeds' names must each differ")
    if not isinstance(rows, list) or len(rows) != len(want):
        raise _err(source, f"rows must list {len(want)} readings (every sensor at every speed)")
    for k, (r, (s, v)) in enumerate(zip(rows, want)):
        got = (_get(r, "sensor", source, "a row"), _get(r, "speed", source, "a row"))
        if got != (s, v):
            raise _err(source, f"row {k + 1} is sensor {got[0]!r} at speed {got[1]!r} where sensor {s!r} at "
                               f"speed {v!r} belongs (every sensor at every speed, speed by speed): rows out of "
                               "order, repeated or missing are never read in another order")
    return tuple(want)


def _coefficients(rows: Any, n: int, p: int, source: str) -> tuple[tuple[complex, ...], ...]:
    """The ``n`` x ``p`` coefficients, from their exact ``re`` and ``im``."""
    if not isinstance(rows, list) or len(rows) != n:
        raise _err(source, f"coefficients must have {n} rows, one per reading")
    out = []
    for row in rows:
        if not isinstance(row, list) or len(row) != p:
            raise _err(source, f"each row of coefficients must have {p} entries, one per plane")
        out.append(tuple(complex(_number(_get(c, "re", source, "a coefficient"), source, "re"),
                                 _number(_get(c, "im", source, "a coefficient"), source, "im")) for c in row))
    return tuple(out)
