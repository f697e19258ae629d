"""The bare-number rule: which unit a number typed without one is in, for one body.

A bare number for an option (``--radius 180``) means what it would in the body's file:
lengths and masses in its ``units`` (SI without them), angles in degrees, angular speeds in
rad/s unless ``units`` names another; any other kind is SI. The API reads by it
(:class:`rbcli.api.options.Units`), tables echo in it (:class:`rbcli.render.units.BodyUnits`)."""

from __future__ import annotations

from collections.abc import Mapping

from rbcli.io import units as un

__all__ = ["bare_unit", "factor", "label"]

#: how messages and tables name the SI unit of a kind
SI_LABELS = {"length": "m", "mass": "kg", "angular_speed": "rad/s", "speed": "m/s",
             "acceleration": "m/s^2", "time": "s"}


def bare_unit(units: Mapping[str, str] | None, kind: str) -> str | None:
    """The unit a bare number of ``kind`` is in for a body whose ``units`` block is
    ``units`` (None: SI, or the kind has no bare unit of its own)."""
    if kind == "angle":
        return "deg"
    if kind == "angular_speed":
        return (units or {}).get("angular_speed")
    if kind in ("length", "mass") and units and kind in units:
        f, text = un.unit_for_kind({kind: units[kind]}, kind)
        return text if f != 1.0 else None
    return None  # speeds, accelerations, times, ...: SI (a body file has no bare g or speed)


def label(units: Mapping[str, str] | None, kind: str) -> str:
    """How help, echo lines and messages name the bare unit of ``kind`` (``"mm"``, ``"m"``,
    ``"SI"``)."""
    return bare_unit(units, kind) or SI_LABELS.get(kind, "SI")


def factor(units: Mapping[str, str] | None, kind: str) -> float:
    """SI per bare unit of ``kind`` (1.0 for SI; an angle's is pi/180)."""
    unit = bare_unit(units, kind)
    if unit is None:
        return 1.0
    return un.parse_unit(unit)[0]
