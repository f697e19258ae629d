"""Issue 34 item 3 for the table units and digits (issue 32's surfaces): every command's
--units and --digits at empty, odd, huge, inf and NaN values is exit 0, or 2 with one line;
never 70."""

from __future__ import annotations

import pytest

from conftest import sampled_params

COMMANDS = [
    ("inertia", "examples/bracket.yaml"), ("principal", "examples/rotor_mm.yaml"),
    ("balance", "examples/bracket.yaml", "--planes=-1,1", "--radius", "2", "--speed", "1e6"),
    ("precess", "examples/cube.yaml", "--omega", "1e-300,1e300,0"),
    ("top", "examples/top.yaml", "--spin", "150", "--theta", "30"),
    ("rollcheck", "examples/penny.yaml"), ("gyrocompass", "examples/gyroscope.yaml", "--spin", "1e6"),
    ("whirl", "examples/fan_rotor.yaml", "--bearings=-150,150", "--stiffness", "1e300"),
]
UNITS = ["", ",", "si", "SI", "nan", "inf", "1e308 m", "rpm", "mm,mm,mm", "km,t,h", "in,oz", "µm,mg", "ly"]


@pytest.mark.parametrize("units", sampled_params(UNITS, [2, 4, 10]))
def test_no_units_value_is_an_internal_error(cli, units):
    for cmd in COMMANDS:
        code, out, err = cli(*cmd, "--units", units)
        assert code in (0, 1, 2), (cmd, units, err)
        assert code != 2 or (out == "" and len(err.splitlines()) == 1 and err.startswith("rbcli: ")), err


@pytest.mark.parametrize("digits", ["0", "1", "17", "18", "-1", "nan", "1e3"])
def test_no_digits_value_is_an_internal_error(cli, digits):
    code, out, err = cli("inertia", "examples/bracket.yaml", "--digits", digits)
    assert code in (0, 2) and (code == 0) == (digits in ("1", "17")), err
