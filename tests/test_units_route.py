"""A bare number in a body's unit: io.units.bare_to_si moves the decimal point for a unit of
10^k and multiplies Fractions otherwise; both must give the bits of the number written with
its unit (issue 32 item 4: one route), which this checks against the Fraction route itself
and against to_si reading the text."""

from __future__ import annotations

import math
from fractions import Fraction

from hypothesis import given
from hypothesis import strategies as st

from rbcli.io.unitparse import parse_unit_exact
from rbcli.io.units import bare_to_si, to_si
from rbcli.io.unittable import UnitError, to_float

TEN = {"mm": "length", "cm": "length", "km": "length", "g": "mass", "t": "mass", "mm^2": "area",
       "kg*mm^2": "inertia", "g/cm^3": "density", "g*mm": "unbalance"}
OTHER = {"in": "length", "lb": "mass", "deg": "angle", "lb*in^2": "inertia"}


def _fraction_route(x: float, unit: str) -> float:
    q, p, _ = parse_unit_exact(unit)
    try:
        return to_float(Fraction(repr(x)) * q, p)
    except UnitError:
        return math.copysign(math.inf, x)


@given(x=st.floats(allow_nan=False, allow_infinity=False), unit=st.sampled_from(sorted(TEN) + sorted(OTHER)))
def test_the_decimal_shift_is_the_fraction_route_bit_for_bit(x, unit):
    got, want = bare_to_si(x, unit), _fraction_route(x, unit)
    assert got == want and math.copysign(1, got) == math.copysign(1, want), (x, unit, got, want)


@given(x=st.floats(min_value=-1e30, max_value=1e30, allow_nan=False), unit=st.sampled_from(sorted(TEN)))
def test_a_bare_number_is_the_number_written_with_its_unit(x, unit):
    kind = {**TEN, **OTHER}[unit]
    assert bare_to_si(x, unit) == to_si(f"{x!r} {unit}", kind)


def test_edges():
    assert bare_to_si(1.0, "mm") == 0.001 and bare_to_si(0.1, "km") == 100.0
    assert bare_to_si(1e308, "km") == math.inf and bare_to_si(5e-324, "mm") == 0.0
    assert str(bare_to_si(-0.0, "mm")) == "0.0"  # as "-0.0 mm" reads
