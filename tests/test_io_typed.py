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


# ----------------------------------------------------------------------------- given parts

#: a tensor with products, about the com, kg m^2 (tensor convention: off-diagonals −∫xy dm)
J = np.array([[0.30, -0.05, 0.02], [-0.05, 0.20, -0.01], [0.02, -0.01, 0.40]])


def _given(inertia: str, extra: str = "") -> rbcli.Body:
    return rbcli.load_text(f"{{shape: given, mass: 3, inertia: {inertia}{extra}}}")


def test_solidworks_names_read_as_the_tensor_names():
    # SolidWorks prints Lxx, Lxy, Lxz, Lyy, Lyz, Lzz (and Lyx, Lzx, Lzy): the same entries as
    # Ixx ... Izx; both orders of a product's letters name one entry
    ref = _given("{Ixx: 0.3, Iyy: 0.2, Izz: 0.4, Ixy: -0.05, Iyz: -0.01, Izx: 0.02, convention: tensor}")
    for text in ("{Lxx: 0.3, Lyy: 0.2, Lzz: 0.4, Lxy: -0.05, Lyz: -0.01, Lxz: 0.02, convention: tensor}",
                 "{Ixx: 0.3, Iyy: 0.2, Izz: 0.4, Iyx: -0.05, Izy: -0.01, Ixz: 0.02, convention: tensor}",
                 "{Lxx: 0.3, Lyy: 0.2, Lzz: 0.4, Lyx: -0.05, Lzy: -0.01, Lzx: 0.02, convention: tensor}"):
        got = _given(text)
        assert np.array_equal(got.parts[0].inertia_com, ref.parts[0].inertia_com), text
    assert np.array_equal(ref.parts[0].inertia_com, J)  # exactly the typed tensor


def test_a_full_cad_matrix_with_mirrored_entries_that_agree_is_read():
    # SolidWorks's report lists all nine entries (issue 32): Lxy and Lyx are one product; they
    # agree to the printed digits (here exactly, or within 1e-9 of the largest entry)
    ref = _given("{Lxx: 0.3, Lyy: 0.2, Lzz: 0.4, Lxy: -0.05, Lyz: -0.01, Lxz: 0.02, convention: tensor}")
    for lyx in ("-0.05", "-0.05000000008"):
        full = _given("{Lxx: 0.3, Lxy: -0.05, Lxz: 0.02, Lyx: %s, Lyy: 0.2, Lyz: -0.01, Lzx: 0.02, "
                      "Lzy: -0.01, Lzz: 0.4, convention: tensor}" % lyx)
        assert np.allclose(full.parts[0].inertia_com, ref.parts[0].inertia_com, rtol=0, atol=1e-10)
    with pytest.raises(InputError, match="'Lxy' and 'Lyx' differ"):  # beyond the printed digits
        _given("{Lxx: 0.3, Lxy: -0.05, Lyx: -0.051, Lyy: 0.2, Lzz: 0.4, convention: tensor}")


@pytest.mark.parametrize("text, twice", [
    ("{Ixx: 1, Iyy: 1, Izz: 1, Izx: 0.1, Lxz: 0.1, convention: tensor}", ("Izx", "Lxz")),
    ("{Lxx: 1, Ixx: 1, Iyy: 1, Izz: 1}", ("Lxx", "Ixx")),
    ("{Ixx: 1, Iyy: 1, Izz: 1, Lxy: 0, Ixy: 0}", ("Lxy", "Ixy")),
])
def test_an_entry_given_under_two_names_is_an_error(text, twice):
    with pytest.raises(InputError, match=f"'{twice[0]}' and '{twice[1]}'") as exc:
        _given(text)
    assert exc.value.where.line == 1


def test_the_convention_is_needed_only_when_a_product_is_not_zero():
    b = _given("{Ixx: 0.3, Iyy: 0.2, Izz: 0.4, Ixy: 0, Iyz: 0.0, Izx: 0}")
    assert np.array_equal(b.parts[0].inertia_com, np.diag([0.3, 0.2, 0.4]))
    with pytest.raises(InputError, match="convention"):  # the check can fail: a product
        _given("{Ixx: 0.3, Iyy: 0.2, Izz: 0.4, Ixy: 0, Iyz: 0.01, Izx: 0}")


def test_a_matrix_symmetric_to_the_digits_printed_is_read_with_a_note():
    # Lxy and Lyx printed apart by 2e-10 of the largest entry (0.4): within 1e-9, accepted;
    # its symmetric part is used, and a note says so
    m = "[[0.3, -0.05, 0.02], [-0.05000000008, 0.2, -0.01], [0.02, -0.01, 0.4]]"
    b = _given(m, ", convention: tensor")
    got = b.parts[0].inertia_com
    assert got[0, 1] == got[1, 0] == 0.5 * (-0.05 + -0.05000000008)
    assert len(b.warnings) == 1 and "note" in b.warnings[0] and "symmetric" in b.warnings[0]
    exact = _given("[[0.3, -0.05, 0.02], [-0.05, 0.2, -0.01], [0.02, -0.01, 0.4]]", ", convention: tensor")
    assert exact.warnings == ()  # no note when it is symmetric as typed
    with pytest.raises(InputError, match="not symmetric"):  # 2e-8 of 0.4: beyond the digits
        _given("[[0.3, -0.05, 0.02], [-0.050000008, 0.2, -0.01], [0.02, -0.01, 0.4]]", ", convention: tensor")


# ----------------------------------------------------------------------------- densities

def _warnings(text: str) -> tuple[str, ...]:
    return rbcli.load_text(text).warnings


def test_a_bare_si_density_in_a_mm_body_is_warned_with_what_was_meant():
    w = _warnings("{units: {length: mm}, shape: box, size: [100, 100, 100], density: 7850}")
    assert len(w) == 1
    assert "7.85e+12 kg/m³" in w[0] and "osmium" in w[0] and "22 590 kg/m³" in w[0]
    assert 'did you mean "7850 kg/m^3"?' in w[0]
    assert w[0].startswith("<expr>:1:") or w[0].startswith("<text>") or ":1:" in w[0]


def test_a_density_lighter_than_any_solid_is_warned():
    w = _warnings("{shape: box, size: [1, 1, 1], density: 0.01}")
    assert len(w) == 1 and "0.01 kg/m³" in w[0] and "aerogel" in w[0]
    assert 'did you mean "0.01 g/cm^3"?' in w[0]  # 10 kg/m³: what a foam has


@pytest.mark.parametrize("text", [
    "{shape: box, size: [1, 1, 1], density: 7850}",
    "{units: {length: mm}, shape: box, size: [100, 100, 100], density: '7850 kg/m^3'}",
    "{units: {length: mm, mass: g}, shape: box, size: [100, 100, 100], density: 0.00785}",  # g/mm^3
    "{shape: box, size: [1, 1, 1], density: 22590}",  # osmium itself
    "{shape: box, size: [1, 1, 1], density: 0.16}",  # the lightest aerogel itself
    "{shape: sphere, radius: 1, shell: true, areal_density: 0.0001}",  # a thin film: no lower bound
    "{units: {length: mm}, shape: plate, size: [100, 100], areal_density: '7.85 kg/m^2'}",
    "{units: {length: mm}, shape: rod, length: 1000, linear_density: '0.6 kg/m'}",
])
def test_densities_that_matter_has_are_not_warned(text):
    assert _warnings(text) == ()


def test_an_areal_density_thicker_than_the_part_is_wide_is_warned():
    # 7.85 kg/mm² is 7.85e6 kg/m²: even osmium would be a sheet 347 m thick on a 0.1 m plate
    w = _warnings("{units: {length: mm}, shape: plate, size: [100, 100], areal_density: 7.85}")
    assert len(w) == 1 and "7.85e+06 kg/m²" in w[0] and "osmium" in w[0]
    assert 'did you mean "7.85 kg/m^2"?' in w[0]


def test_a_linear_density_thicker_than_the_part_is_long_is_warned():
    # 0.6 kg/mm is 600 kg/m: an osmium bar of 0.0266 m² (0.163 m a side) on a 0.1 m rod
    w = _warnings("{units: {length: mm}, shape: rod, length: 100, linear_density: 0.6}")
    assert len(w) == 1 and "600 kg/m" in w[0] and 'did you mean "0.6 kg/m"?' in w[0]


def test_the_density_warning_is_given_once_per_body(tmp_path):
    (tmp_path / "sub.yaml").write_text(
        "units: {length: mm}\nparts:\n  - {shape: box, size: [10, 10, 10], density: 2700}\n")
    top = tmp_path / "top.yaml"
    top.write_text("units: {length: mm}\nparts:\n"
                   "  - {name: a, shape: box, size: [100, 100, 100], density: 7850}\n"
                   "  - {name: b, shape: cylinder, radius: 10, length: 50, density: 7850}\n"
                   "  - {name: s, shape: include, file: sub.yaml}\n")
    w = rbcli.load(top).warnings
    assert len(w) == 1 and "part 'a'" in w[0] and "3 parts" in w[0]
    assert f"{top}:3:" in w[0]  # located at the first one's density


def test_a_density_warning_in_a_real_process_is_one_line(cli_proc):
    r = cli_proc("inertia", "-e", "{units: {length: mm}, shape: box, size: [100, 100, 100], density: 7850}")
    assert r.code == 0
    lines = r.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("rbcli: <expr>:1:") and "warning" in lines[0]
