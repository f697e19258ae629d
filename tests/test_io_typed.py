"""What people type (issue 24): units in the spellings people use, shown in one canonical
spelling; given parts copied from CAD reports; a density no matter has, warned with the
reading the user probably meant."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rbcli
from rbcli.errors import InputError

ROOT = Path(__file__).resolve().parent.parent


# ----------------------------------------------------------------------------- units


def test_a_bodys_units_are_kept_in_their_canonical_spelling():
    b = rbcli.load_text("{units: {angular_speed: RPM, length: inches, mass: lbs}, shape: disk, "
                        "radius: 4, mass: 2}")
    assert dict(b.units) == {"angular_speed": "rpm", "length": "in", "mass": "lb"}
    # the numbers follow the units typed: a 4 in disk of 2 lb (exact factors, NIST SP 811)
    assert b.parts[0].mass == 2 * 0.45359237 and b.parts[0].radius == 4 * 0.0254


def test_the_bare_unit_is_echoed_in_its_canonical_spelling(cli):
    r = cli("precess", "-e", "{units: {angular_speed: RPM}, shape: disk, radius: 0.1, mass: 1}",
            "--omega", "0,1,100")
    assert r.code == 0, r.err
    echo = next(line for line in r.out.splitlines() if line.startswith("--omega"))
    assert echo.rstrip().endswith("| rpm") and "RPM" not in r.out
