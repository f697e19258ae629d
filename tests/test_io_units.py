"""Tests of rbcli.io.units: exact factors, pint as an oracle, and the error messages.

Oracles: exact decimal definitions of the units (NIST SP 811: 1 in = 0.0254 m,
1 lb = 0.45359237 kg, g0 = 9.80665 m/s^2), pi computed here by Machin's formula
(independent of the 60 digits hard-coded in the module), the ``decimal`` module, and
pint (a test-only dependency; it keeps its factors in floats and treats the radian as
dimensionless, so it is compared on magnitudes, and on dimensions only for length,
mass and time).
"""

from __future__ import annotations

import math
from decimal import Decimal, localcontext
from fractions import Fraction

import pytest

from conftest import sample
from hypothesis import example, given, settings
from hypothesis import strategies as st

from rbcli.io.units import (
    KINDS,
    Dim,
    UnitError,
    format_unit_table,
    known_units,
    parse_quantity,
    parse_unit,
    to_si,
    unit_for_kind,
)

# --------------------------------------------------------------------------- helpers


def _machin_pi(digits: int = 70) -> Fraction:
    """pi = 16 atan(1/5) - 4 atan(1/239), in integer arithmetic to `digits` digits."""

    def atan_inv(x: int, one: int) -> int:
        total = term = one // x
        x2, n, sign = x * x, 1, -1
        while term:
            term //= x2
            n += 2
            total += sign * (term // n)
            sign = -sign
        return total

    one = 10 ** (digits + 10)
    return Fraction(16 * atan_inv(5, one) - 4 * atan_inv(239, one), one)


PI = _machin_pi()  # error ~1e-75: far below half an ulp of any double we compare


def _ulps(a: float, b: float) -> float:
    return abs(a - b) / math.ulp(b)


# Names in our table -> pint's name for the same unit (identical unless listed).
# pint's "mil" is an angle (the NATO mil); the engineer's mil is pint's "thou". pint has no
# "lbm": it is the avoirdupois pound.
PINT_NAME = {"rev": "revolution", "r/min": "rpm", "mil": "thou", "lbm": "pound", "lbs": "pound",
             "in.": "inch"}
# Test-side list of how many angle dimensions each unit carries (pint cannot tell us:
# it treats the radian as dimensionless).
ANGLE_EXPONENT = {
    "rad": 1, "mrad": 1, "deg": 1, "°": 1, "arcmin": 1, "arcsec": 1, "rev": 1, "turn": 1,
    "rpm": 1, "r/min": 1,
}  # fmt: skip


@pytest.fixture(scope="module")
def ureg():
    import pint

    return pint.UnitRegistry()


def _pint_si(ureg, name: str):
    """pint's quantity 1 `name`, converted to its base units."""
    return ureg.Quantity(1, PINT_NAME.get(name, name)).to_base_units()


def _pint_lmt(q) -> tuple[float, float, float]:
    d = q.dimensionality
    return (d.get("[length]", 0), d.get("[mass]", 0), d.get("[time]", 0))


# Pint computes a factor in floats: each unit's definition chain (e.g. lbf = lb * g0,
# oz = lb / 16, ft = 12 in) and every product or power costs a rounding of at most
# 1.1e-16 relative; the expressions below take at most ~30 such operations, so pint
# is within ~3e-15 of the exact value. 1e-12 relative leaves a wide margin while any
# wrong definition (0.025 for 0.0254, pi for 2 pi, a missing /60) is off by >1e-3.
PINT_RTOL = 1e-12


# --------------------------------------------------------------------------- exactness


def test_density_in_g_per_cm3_is_exact():
    # 7.85 g/cm^3 = 7.85 * 1e-3 / 1e-6 = 7850 exactly; the float must be 7850.0 exactly
    # (pint's float arithmetic gives 7849.999999999999, see FACTS.md).
    assert parse_quantity("7.85 g/cm^3") == (7850.0, Dim(M=1, L=-3))
    assert parse_unit("g/cm^3") == (1000.0, Dim(M=1, L=-3))


@pytest.mark.parametrize(
    ("text", "decimal_si"),
    [
        # exact decimal definitions (NIST SP 811); the result must be the float
        # nearest to the exact decimal, i.e. float(decimal string), with no tolerance.
        ("1 in", "0.0254"),
        ("2.5 lb", "1.133980925"),  # 2.5 * 0.45359237
        ("1 ft", "0.3048"),
        ("1 yd", "0.9144"),
        ("1 mi", "1609.344"),
        ("1 oz", "0.028349523125"),  # 0.45359237 / 16
        ("1 lbf", "4.4482216152605"),  # 0.45359237 * 9.80665
        ("1 kgf", "9.80665"),
        ("1 g0", "9.80665"),
        ("30 cm", "0.3"),
        ("-3.5 mm", "-0.0035"),
        ("4e-4 kg*m^2", "0.0004"),
        ("3 g*cm^2", "3e-7"),
        ("1 lb*in^2", "0.000292639653429200"),  # 0.45359237 * 0.0254^2
        ("2 h", "7200"),
        ("0.1 kN", "100"),
    ],
)
def test_exact_decimal_factors(text, decimal_si):
    assert parse_quantity(text)[0] == float(decimal_si)


def test_degrees_are_rounded_once():
    value, dim = parse_quantity("12 deg")
    assert dim == Dim(A=1)
    # Correct rounding of the exact 12 pi / 180: equal, no tolerance (our pi is exact
    # to 1e-75, far below the half-ulp that decides the rounding).
    assert value == float(12 * PI / 180)
    # The naive float expression has two or three roundings of its own; the brief asks
    # agreement to 1 ulp, which holds for this value.
    assert _ulps(value, 12 * math.pi / 180) <= 1
    assert parse_quantity("12°")[0] == value


def test_rpm_is_rounded_once():
    value, dim = parse_quantity("1200 rpm")
    assert dim == Dim(A=1, T=-1)
    assert value == float(40 * PI)  # 1200 * 2 pi / 60 = 40 pi, correctly rounded
    # 40 * math.pi: fl(pi) times 40 is one more rounding: within 1 ulp.
    assert _ulps(value, 40 * math.pi) <= 1
    assert parse_quantity("1200 r/min") == (value, dim)
    assert parse_quantity("20 rev/s") == (value, dim)


@settings(max_examples=50, deadline=None)
@given(
    st.decimals(
        min_value=Decimal("-1e12"), max_value=Decimal("1e12"), allow_nan=False, places=6
    )
)
def test_any_decimal_in_g_per_cm3_is_rounded_once(x):
    # Decimal arithmetic with 60 digits is exact here (<= 19 digits times 1000), and
    # float(Decimal) rounds correctly: the unit parser must give exactly that float.
    text = f"{x} g/cm^3"
    with localcontext() as ctx:
        ctx.prec = 60
        expected = float(x * 1000)
    assert parse_quantity(text)[0] == expected


# --------------------------------------------------------------------------- pint oracle


@pytest.mark.parametrize("name", known_units())
def test_every_unit_agrees_with_pint(ureg, name):
    factor, dim = parse_unit(name)
    q = _pint_si(ureg, name)
    assert factor == pytest.approx(q.magnitude, rel=PINT_RTOL)  # see PINT_RTOL
    assert (dim.L, dim.M, dim.T) == _pint_lmt(q)
    assert dim.A == ANGLE_EXPONENT.get(name, 0)


def test_table_has_the_required_units():
    required = (
        "m mm cm dm km um µm nm in inch ft yd mi kg g mg t lb oz s ms min h "
        "rad mrad deg ° arcmin arcsec rev turn rpm r/min Hz kHz N kN lbf kgf J"
    ).split()
    assert set(required) <= set(known_units())


# Single-word names only: an alias with an operator in it ("r/min") cannot take an
# exponent the way the generator below writes one ("r/min^2" is r / min^2).
_NAMES = [n for n in known_units() if "/" not in n]


@st.composite
def unit_products(draw):
    """(our expression, [(name, signed exponent)]) with 1-3 factors."""
    n = draw(st.integers(1, 3))
    parts = []
    text = ""
    for i in range(n):
        name = draw(st.sampled_from(_NAMES))
        e = draw(st.integers(-3, 3))
        style = draw(st.sampled_from(["^", "**", "sup", "paren"]))
        sup = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
        if name == "r/min":
            name_text = "(r/min)" if e != 1 else "r/min"
        else:
            name_text = name
        if e == 1 and draw(st.booleans()):
            factor = name_text
        elif style == "^":
            factor = f"{name_text}^{e}"
        elif style == "**":
            factor = f"{name_text}**{e}"
        elif style == "sup":
            factor = f"{name_text}{str(e).translate(sup)}"
        else:
            factor = f"({name_text})^({e})"
        op = "*" if i == 0 else draw(st.sampled_from(["*", "/", "·", " * ", " / "]))
        sign = -1 if op.strip() == "/" else 1
        text = factor if i == 0 else text + op + factor
        parts.append((name, sign * e))
    return text, parts


@settings(max_examples=50, deadline=None)
@given(unit_products())
def test_products_of_units_agree_with_pint(ureg, case):
    text, parts = case
    factor, dim = parse_unit(text)
    q = ureg.Quantity(1, "")
    for name, e in parts:
        q = q * ureg.Quantity(1, PINT_NAME.get(name, name)) ** e
    q = q.to_base_units()
    # Magnitudes in base units agree whatever pint thinks of radians (rad counts 1).
    assert factor == pytest.approx(q.magnitude, rel=PINT_RTOL)  # see PINT_RTOL
    # Length, mass and time exponents agree with pint; angle from the test-side list.
    assert (dim.L, dim.M, dim.T) == _pint_lmt(q)
    assert dim.A == sum(e * ANGLE_EXPONENT.get(name, 0) for name, e in parts)


@settings(max_examples=50, deadline=None)
@given(
    # Normal floats only: a subnormal x has fewer significant bits, so "one rounding
    # against two" no longer bounds the difference by 2 ulp of the result.
    st.floats(
        min_value=-1e6, max_value=1e6, allow_nan=False, allow_infinity=False, allow_subnormal=False
    ),
    st.sampled_from(_NAMES),
)
@example(8672.45737261267, "in")  # 2 ulp: the bound below is reached
def test_quantities_agree_with_pint(ureg, x, name):
    value, _ = parse_quantity(f"{x!r} {name}")
    expected = ureg.Quantity(x, PINT_NAME.get(name, name)).to_base_units().magnitude
    # pint: a few float roundings (see PINT_RTOL); abs floor for x == 0 and tiny x.
    assert value == pytest.approx(expected, rel=PINT_RTOL, abs=1e-300)
    # the number times the unit's factor: two roundings (the factor's and the product's,
    # each <= 2^-53 relative) against our one (<= half an ulp of the exact product): at the
    # top of a binade 2^-52 relative is 2 ulp, so the two floats are at most 2 ulp apart
    # (x = 8672.45737261267 in: 2 ulp, found by hypothesis)
    assert abs(value - x * parse_unit(name)[0]) <= 2 * math.ulp(value)


# --------------------------------------------------------------------------- grammar


def test_bare_number_is_dimensionless():
    assert parse_quantity("2.5") == (2.5, Dim())
    assert parse_quantity("  -1e3 ") == (-1000.0, Dim())
    assert to_si("2.5", "dimensionless") == 2.5


@pytest.mark.parametrize(
    ("text", "dim"),
    [
        ("kg/m/s", Dim(M=1, L=-1, T=-1)),  # left to right
        ("kg/(m*s)", Dim(M=1, L=-1, T=-1)),
        ("kg*m^2/s", Dim(M=1, L=2, T=-1)),
        ("N·m", Dim(M=1, L=2, T=-2)),
        ("m**-2", Dim(L=-2)),
        ("m^(-2)", Dim(L=-2)),
        ("s⁻¹", Dim(T=-1)),
        ("1/s", Dim(T=-1)),
        ("(m/s)^2", Dim(L=2, T=-2)),
        ("rad/s", Dim(A=1, T=-1)),
        ("Hz", Dim(T=-1)),
        ("deg/s", Dim(A=1, T=-1)),
    ],
)
def test_unit_expressions(text, dim):
    assert parse_unit(text)[1] == dim


@pytest.mark.parametrize(
    "text",
    [
        "",
        "   ",
        "m",
        "3 m m",
        "3 ^2",
        "nan kg",
        "inf",
        "-Infinity m",
        "1e999 m",
        "1e400 km",  # overflows a float after the unit factor
        "3 kgs",
        "3 MM",
        "3 Mm",
        "3 G",
        "3 Nm",
        "3 MS",
        "3 m0",
        "3 m13",
        "3 m^1.5",
        "3 m^99",
        "3 (m",
        "3 m)",
        "3 m/",
        "3 *m",
        "1,5 m",
        "1_000 m",
        "1 000 m",
        "3 1",
        "3 r/min^2",
        "1e999999999 m",  # must be refused without computing 10**999999999
        "1 m^999999999",
        "1 " + "km*" * 100 + "m",  # too long
        "1" * 5000,
    ],
)
def test_garbage_raises_unit_error(text):
    with pytest.raises(UnitError):
        parse_quantity(text)


@pytest.mark.parametrize("text", ["", "3", "m m", "kg/", "^2", "1", "2/s", "(m"])
def test_bad_units_raise_unit_error(text):
    with pytest.raises(UnitError):
        parse_unit(text)


_GRAMMAR = "0123456789.eE+-−  ^*/()·²³⁻mkgsradegHzNJinbltu°µrpm,_"


@settings(max_examples=50, deadline=None)
@given(st.one_of(st.text(), st.text(alphabet=_GRAMMAR, max_size=30)))
def test_any_text_returns_or_raises_unit_error(text):
    for fn in (parse_quantity, parse_unit):
        try:
            value, dim = fn(text)
        except UnitError:
            continue
        assert math.isfinite(value)
        assert isinstance(dim, Dim)


# --------------------------------------------------------------------------- messages


def test_dimension_error_names_both():
    with pytest.raises(UnitError) as info:
        to_si("3 kg", "length")
    assert str(info.value) == "'3 kg' is a mass, but a length is needed here (e.g. m, mm, in)"


# one quantity of each kind (not dimensionless: a bare number gets its own message)
_SAMPLES = {
    "length": "3 mm", "mass": "3 g", "time": "3 ms", "angle": "3 deg", "area": "3 m^2",
    "volume": "3 cm^3", "density": "3 g/cm^3", "areal_density": "3 kg/m^2",
    "linear_density": "3 kg/m", "inertia": "3 kg*m^2", "unbalance": "3 g*mm",
    "speed": "3 m/s", "acceleration": "3 g0", "angular_speed": "3 rpm", "force": "3 lbf",
    "torque": "3 N*m", "angular_momentum": "3 N*m*s", "frequency": "3 Hz",
    "odd": "3 kg*rad/m",
}  # fmt: skip


@settings(max_examples=50, deadline=None)
@given(st.sampled_from(sorted(_SAMPLES)), st.sampled_from(sorted(KINDS)))
def test_wrong_dimension_message_names_both(given_kind, kind):
    text = _SAMPLES[given_kind]
    have = parse_quantity(text)[1]
    want = KINDS[kind]
    if have == want:
        assert to_si(text, kind) == parse_quantity(text)[0]
        return
    with pytest.raises(UnitError) as info:
        to_si(text, kind)
    msg = str(info.value)
    assert msg == msg[0].lower() + msg[1:] or msg.startswith("'")  # lower case
    if have == Dim(T=-1) and kind == "angular_speed":
        assert "not an angular speed" in msg
    else:
        assert have.describe() in msg and want.describe() in msg, msg


@pytest.mark.parametrize("text", ["50 Hz", "0.05 kHz", "50 1/s", "50 s^-1"])
def test_hz_is_not_an_angular_speed(text):
    with pytest.raises(UnitError) as info:
        to_si(text, "angular_speed")
    msg = str(info.value)
    assert "frequency" in msg and "not an angular speed" in msg
    # the hint converts the user's 50 rotations per second three ways:
    # 50 rev/s, 50 * 60 = 3000 rpm, 2 pi * 50 = 314.159 rad/s (6 significant figures)
    assert "'50 rev/s'" in msg and "'3000 rpm'" in msg and "'314.159 rad/s'" in msg


def test_angular_speed_units_are_accepted():
    # 2 pi * 50 rad/s: the same correctly rounded float three ways (exact factors)
    expected = float(100 * PI)
    assert to_si("50 rev/s", "angular_speed") == expected
    assert to_si("3000 rpm", "angular_speed") == expected
    assert to_si("18000 deg/s", "angular_speed") == expected


@pytest.mark.parametrize(
    ("text", "hint"),
    [("3 kgs", "'kg'"), ("3 MM", "'mm'"), ("3 Mm", "'mm'"), ("3 MG", "'mg'"), ("1 kn", "'kN'")],
)
def test_unknown_unit_suggests(text, hint):
    with pytest.raises(UnitError) as info:
        parse_quantity(text)
    msg = str(info.value)
    assert msg.startswith("unknown unit") and "did you mean" in msg and hint in msg


def test_unknown_unit_without_a_close_match_lists_the_units():
    with pytest.raises(UnitError) as info:
        parse_quantity("3 furlongs")
    assert "known units:" in str(info.value) and "mm" in str(info.value)


@pytest.mark.parametrize("kind", sorted(set(KINDS) - {"dimensionless"}))
def test_bare_number_needs_a_unit(kind):
    with pytest.raises(UnitError) as info:
        to_si("2.5", kind)
    assert "'2.5' has no unit" in str(info.value)


def test_unknown_kind_is_a_programming_error():
    with pytest.raises(ValueError, match="unknown kind") as info:
        to_si("3 m", "lenght")
    assert not isinstance(info.value, UnitError)


def test_non_string_is_a_type_error():
    with pytest.raises(TypeError):
        parse_quantity(2.5)  # type: ignore[arg-type]


# --------------------------------------------------------------------------- base units


def test_density_in_mm_and_g():
    # g/mm^3 = 1e-3 kg / 1e-9 m^3 = 1e6 exactly (and 1e6 is a float)
    assert unit_for_kind({"length": "mm", "mass": "g"}, "density") == (1e6, "g/mm^3")


def test_defaults():
    assert unit_for_kind({}, "length") == (1.0, "m")
    assert unit_for_kind({}, "inertia") == (1.0, "kg*m^2")
    assert unit_for_kind({}, "dimensionless") == (1.0, "")
    factor, text = unit_for_kind({}, "angle")
    assert text == "deg"
    assert factor == float(PI / 180)  # correctly rounded pi/180, no tolerance


def test_inertia_in_lb_in2():
    # 0.45359237 * 0.0254^2 exactly, as a decimal, then rounded once
    assert unit_for_kind({"length": "in", "mass": "lb"}, "inertia") == (
        float(Decimal("0.45359237") * Decimal("0.0254") ** 2),
        "lb*in^2",
    )


@pytest.mark.parametrize(
    "base", [{}, {"angle": "rad"}, {"angle": "deg"}, {"angle": "rev"}, {"time": "min"}]
)
def test_bare_angular_speed_is_always_rad_per_s(base):
    assert unit_for_kind(base, "angular_speed") == (1.0, "rad/s")


@pytest.mark.parametrize(
    "base",
    [
        {"length": "kg"},
        {"mass": "m"},
        {"time": "deg"},
        {"angle": "s"},
        {"time": "rpm"},
        {"length": "furlong"},
        {"length": ""},
        {"force": "N"},
        {"length": 3},
    ],
)
def test_bad_base_units_are_refused(base):
    with pytest.raises(UnitError) as info:
        unit_for_kind(base, "length")
    assert "units" in str(info.value)


_BASE_CHOICES = {
    "length": ["m", "mm", "cm", "in", "ft", "km"],
    "mass": ["kg", "g", "lb", "t", "oz"],
    "time": ["s", "ms", "min", "h"],
    "angle": ["deg", "rad", "rev", "arcmin"],
}


@settings(max_examples=50, deadline=None)
@given(
    st.fixed_dictionaries({}, optional={k: st.sampled_from(v) for k, v in _BASE_CHOICES.items()}),
    st.sampled_from(sorted(KINDS)),
)
def test_unit_for_kind_agrees_with_pint(ureg, base, kind):
    factor, text = unit_for_kind(base, kind)
    if kind == "dimensionless":
        assert (factor, text) == (1.0, "")
        return
    # the unit text reads back as the kind's dimension with the same factor
    assert parse_unit(text) == (factor, KINDS[kind])
    # and pint agrees on the factor (see PINT_RTOL); pint spells revolution differently
    q = ureg.Quantity(1, text.replace("rev", "revolution")).to_base_units()
    assert factor == pytest.approx(q.magnitude, rel=PINT_RTOL)


# --------------------------------------------------------------------------- Dim, docs


def test_dim_algebra_and_description():
    assert Dim(M=1) / Dim(L=1) ** 3 == KINDS["density"]
    assert Dim(M=1) * Dim(L=2) == KINDS["inertia"]
    assert KINDS["density"].describe() == "mass/length^3"
    assert KINDS["angular_speed"].describe() == "angle/time"
    assert KINDS["length"].describe() == "length"
    assert Dim(T=-1).describe() == "1/time"
    assert KINDS["force"].describe() == "mass*length/time^2"
    assert Dim(M=1, L=-1, T=-2).describe() == "mass/(length*time^2)"
    assert Dim().describe() == "dimensionless"


def test_unit_table_lists_every_unit():
    import re

    table = format_unit_table()
    listed = set()
    for line in table.splitlines()[2:]:  # after the header and the rule
        unit, aliases = re.split(r"\s{2,}", line)[:2]
        listed.add(unit)
        if "," in aliases or aliases in known_units():  # the alias column may be empty
            listed.update(a.strip() for a in aliases.split(","))
    assert listed == set(known_units())
    assert "pi/180 rad" in table and "45359237/100000000 kg" in table


# --------------------------------------------------------------------------- spellings people use


@pytest.mark.parametrize(
    ("ours", "pints"),
    [
        ("3000 RPM", "3000 rpm"),
        ("3000 Rpm", "3000 rpm"),
        ("2 Kg", "2 kg"),
        ("2 KG", "2 kg"),
        ("50 hz", "50 Hz"),
        ("2 KHZ", "2 kHz"),
        ("3 KN", "3 kN"),
        ("7850 kg/m3", "7850 kg/m**3"),
        ("3 m2", "3 m**2"),
        ("5 mm4", "5 mm**4"),
        ("2 kg*m2", "2 kg*m**2"),
        ("7.85 g/cc", "7.85 g/cc"),
        ("3 lbm", "3 pound"),
        ("3 LBM", "3 pound"),
        ("2 slug", "2 slug"),
        ("4 mil", "4 thou"),
        ("4 thou", "4 thou"),
        ("4 lbm*in2", "4 pound*inch**2"),
        # issue 24: what people type
        ("3 lbs", "3 pound"),
        ("1 pound", "1 pound"),
        ("2.5 pounds", "2.5 pound"),
        ("2 LBS", "2 pound"),
        ("1 inch", "1 inch"),
        ("3 inches", "3 inch"),
        ("3 in.", "3 inch"),
        ("3 in.^2", "3 inch**2"),
        ("4 in.*lbs", "4 inch*pound"),
        ("5 ft", "5 foot"),
        ("1 foot", "1 foot"),
        ("6 feet", "6 foot"),
        ("60 mph", "60 mile/hour"),
        ("10 ft/s", "10 foot/second"),
        ("2 lbs*ft^2", "2 pound*foot**2"),
    ],
)
def test_spellings_people_use_agree_with_pint(ureg, ours, pints):
    value, dim = parse_quantity(ours)
    q = ureg.Quantity(pints).to_base_units()
    assert value == pytest.approx(q.magnitude, rel=PINT_RTOL)
    assert (dim.L, dim.M, dim.T) == _pint_lmt(q)


def test_exact_new_units():
    assert parse_quantity("1 mil") == (float(Fraction("0.0254") / 1000), Dim(L=1))
    assert parse_quantity("7.85 g/cc") == (7850.0, Dim(M=1, L=-3))
    assert parse_quantity("1 slug")[0] == float(Fraction("0.45359237") * Fraction("9.80665") / Fraction("0.3048"))
    assert parse_quantity("1 g0") == (9.80665, Dim(L=1, T=-2))  # a name ending in a digit is itself


@pytest.mark.parametrize("text", ["1 Mm", "1 MM", "1 G", "1 G/CC", "1 Nm", "1 NM", "1 MS", "1 MG", "1 S", "1 T", "1 kn", "1 MRAD"])
def test_case_folding_never_changes_a_prefix_or_symbol(text):
    with pytest.raises(UnitError, match="unknown unit"):
        parse_quantity(text)


def test_linear_speeds_people_type_are_speeds():
    # mph and ft/s are linear speeds (L/T), never angular ones; exact: 1 mph is 1609.344 m
    # an hour, 1 ft/s 0.3048 m/s (NIST SP 811)
    assert to_si("1 mph", "speed") == float(Fraction("1609.344") / 3600)
    assert to_si("1 ft/s", "speed") == 0.3048
    with pytest.raises(UnitError, match="a speed"):
        to_si("60 mph", "angular_speed")


@pytest.mark.parametrize("text", ["1 in.m", "1 mm.", "1 kg.m^2", "1 in..", "1 .in"])
def test_a_point_is_part_of_in_only(text):
    with pytest.raises(UnitError):
        parse_quantity(text)


@pytest.mark.parametrize(("base", "kind", "shown"), [
    ({"angular_speed": "RPM"}, "angular_speed", "rpm"),
    ({"angular_speed": "r/min"}, "angular_speed", "rpm"),
    ({"length": "inches"}, "length", "in"),
    ({"length": "in."}, "area", "in^2"),
    ({"length": "feet", "mass": "LBS"}, "density", "lb/ft^3"),
    ({"length": "Mm"[1:], "mass": "Kg"}, "inertia", "kg*m^2"),
    ({"length": "mm", "mass": "g"}, "density", "g/mm^3"),
    ({"length": "(mm)"}, "length", "(mm)"),  # an expression stays as written
])
def test_bare_units_are_named_in_their_canonical_spelling(base, kind, shown):
    assert unit_for_kind(base, kind)[1] == shown


def test_canonical_unit_spelling():
    from rbcli.io.units import canonical_unit

    for text, shown in [("RPM", "rpm"), (" lbs ", "lb"), ("pounds", "lb"), ("inches", "in"),
                        ("in.", "in"), ("feet", "ft"), ("Kg", "kg"), ("r/min", "rpm"),
                        ("mph", "mph"), ("kg/m^3", "kg/m^3"), ("g/cc", "g/cc")]:
        assert canonical_unit(text) == shown


def test_angular_speed_base_unit():
    assert unit_for_kind({"angular_speed": "rpm"}, "angular_speed") == (float(2 * PI / 60), "rpm")
    assert unit_for_kind({"angular_speed": "rpm", "length": "mm"}, "length") == (0.001, "mm")
    with pytest.raises(UnitError, match="angular_speed"):
        unit_for_kind({"angular_speed": "Hz"}, "angular_speed")


# ----------------------------------------------------------------------------- start-up (issue 16)


@pytest.mark.sampled
def test_plain_decimals_are_numbers_for_both_patterns():
    """plain_decimal (api.options' short path that skips its number pattern) only says yes
    where both patterns match the whole text."""
    import re

    from hypothesis import given, settings
    from hypothesis import strategies as st

    from rbcli.api import options
    from rbcli.io import unitparse as up
    from rbcli.io import units as un

    @settings(max_examples=sample(300, 3000), deadline=None)
    @given(st.text("0123456789.+-eE \u2212\u0663\u00b2x", max_size=8))
    def check(s):
        if un.plain_decimal(s):
            assert re.fullmatch(up._NUMBER_RE.pattern, s) and options.NUMBER.fullmatch(s)
            assert un.parse_quantity(s) == (float(s), un.Dim())

    check()
