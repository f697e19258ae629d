"""Named materials (issue 33 item 4) and what a STEP part says without OpenCascade (item 6).

The table's densities are checked against what matter has and against each other (an alloy
near its base metal); a material by name gives exactly the density it names; the names
people type (case, hyphens, US spelling, designations) find it, and a misspelt one is
refused with the nearest. Hostile material names and ``materials:`` sections (issue 34
item 7) get one located line. None of this needs OpenCascade.
"""

from __future__ import annotations

import sys

import pytest

import rbcli
from rbcli.body import materials as mt
from rbcli.body.plausible import AEROGEL, OSMIUM


def test_every_row_has_a_density_matter_has_a_source_and_names_of_its_own():
    rows = mt.table()
    assert len(rows) >= 60
    keys = [mt.key(n) for m in rows for n in (m.name, *m.aliases)]
    assert len(keys) == len(set(keys)), "a name or alias names one material"
    for m in rows:
        assert AEROGEL < m.density <= OSMIUM and m.source.strip(), m
    # alloys near their base metal: a wrong digit or unit would stand out (1 g/cm³ apart)
    for alloy, base in (("aluminium 6061", "aluminium"), ("stainless steel 316", "steel"),
                        ("titanium Ti-6Al-4V", "titanium"), ("brass", "copper")):
        assert abs(mt.density(alloy) - mt.density(base)) < 1000, alloy


@pytest.mark.parametrize("typed, density", [
    ("steel", 7850), ("Aluminum-6061", 2700), ("6061-T6", 2700), ("  PEEK ", 1300),
    ("stainless_steel_316", 8000), ("Ti-6Al-4V", 4430), ("oak", 710), ("1.4301", 7900)])
def test_names_as_people_type_them(typed, density):
    assert mt.density(typed) == density


def test_a_misspelt_name_gets_the_nearest_and_a_long_one_no_search():
    with pytest.raises(ValueError, match="unknown material 'stainles steel 361'; did you mean 'stainless steel 316'"):
        mt.density("stainles steel 361")
    with pytest.raises(ValueError, match="unknown material 'x{60}…' [(]"):
        mt.density("x" * 10**6)  # no did-you-mean search over a megabyte, 60 shown


def test_material_gives_the_density_it_names_on_every_solid():
    for make, kw in ((rbcli.parts.box, {"size": [0.1, 0.2, 0.3]}), (rbcli.parts.torus, {
            "major_radius": 0.3, "minor_radius": 0.05}), (rbcli.parts.cylinder, {"radius": 0.1, "length": 1})):
        named = rbcli.Body.from_parts([make(**kw, material="brass")])
        typed = rbcli.Body.from_parts([make(**kw, density="8500 kg/m^3")])
        assert rbcli.inertia(named).mass == rbcli.inertia(typed).mass


def test_a_body_files_own_materials_come_first_and_are_checked(cli, tmp_path):
    f = tmp_path / "b.yaml"
    f.write_text("units: {length: mm}\nmaterials: {Steel: 8 g/cm^3, impeller alloy: 7930 kg/m^3}\n"
                 "parts:\n  - {shape: box, size: [10, 10, 10], material: steel}\n"
                 "  - {shape: box, size: [10, 10, 10], material: Impeller-Alloy, at: [100, 0, 0]}\n")
    assert rbcli.inertia(rbcli.load(str(f))).mass == pytest.approx((8000 + 7930) * 1e-6, rel=1e-15)
    f.write_text("materials: {foam: 0.01}\nparts: [{shape: box, size: [1, 1, 1], material: foam}]\n")
    r = cli("inertia", str(f))
    assert r.code == 0 and "below that of any solid" in r.err  # the density warning stays


def test_rbcli_materials_lists_and_filters(cli):
    data = cli("materials", "--json").json()
    assert [m["name"] for m in data] == [m.name for m in mt.table()]
    assert {m["name"] for m in cli("materials", "alu", "--json").json()} >= {"aluminium", "aluminium 7075"}
    table = cli("materials", "PEEK")
    assert table.code == 0 and "1300" in table.out and "Victrex" in table.out
    assert cli("materials", "unobtainium").code == 2


# ----------------------------------------------------------------------------- hostile names

HOSTILE = ["", " ", "stell", "{speed}", "x" * 5000, "\x1b[31mred", "鋼", "steel\nsteel", "*", "[",
           "steel; drop table", "%s%s", "../../etc/passwd"]


@pytest.mark.parametrize("name", HOSTILE, ids=range(len(HOSTILE)))
def test_hostile_material_names_get_one_line(cli, name):
    r = cli("inertia", "-e", "{shape: box, size: [1, 1, 1], material: MAT}".replace("MAT", repr(name)))
    assert r.code == 2 and r.err.count("\n") == 1 and r.err.startswith("rbcli: <expr>:1:"), r.err
    assert "--speed" not in r.err  # a name is data, not a parameter to spell
    r = cli("inertia", "examples/housing.stl", "--material", name)
    assert r.code == 2 and r.err.count("\n") == 1 and "--material: " in r.err, r.err


@pytest.mark.parametrize("section", [
    "materials: [steel]", "materials: {a: -1}", "materials: {a: 1e400}", "materials: {a: steel}",
    "materials: {a: [1, 2]}", "materials: {a: '5 m'}", "materials: {a: {density: 1}}",
    "materials: 5"])
def test_hostile_materials_sections_get_one_located_line(cli, tmp_path, section):
    f = tmp_path / "b.yaml"
    f.write_text(f"{section}\nparts: [{{shape: box, size: [1, 1, 1], mass: 1}}]\n")
    r = cli("inertia", str(f))
    assert r.code == 2 and r.err.count("\n") == 1 and r.err.startswith(f"rbcli: {f}:1:"), r.err


@pytest.mark.parametrize("value", ["5", "true", "[steel]", "{a: 1}", "null"])
def test_a_material_that_is_not_a_name(cli, value):
    r = cli("inertia", "-e", "{shape: box, size: [1, 1, 1], material: %s}" % value)
    assert r.code == 2 and r.err.count("\n") == 1 and "material" in r.err, r.err


def test_material_where_a_density_per_volume_does_not_apply(cli):
    r = cli("inertia", "-e", "{shape: ring, radius: 1, material: steel}")
    assert r.code == 2 and "'material' does not apply; use 'linear_density'" in r.err
    r = cli("inertia", "-e", "{shape: box, size: [1, 1, 1], material: steel, density: 7000}")
    assert r.code == 2 and "gives both 'density' and 'material'" in r.err


# ----------------------------------------------------------------------------- without OpenCascade


def test_a_step_part_without_opencascade_names_the_extra(cli, monkeypatch):
    monkeypatch.setitem(sys.modules, "OCP", None)  # import OCP... raises ImportError
    monkeypatch.setitem(sys.modules, "OCP.Message", None)
    r = cli("inertia", "examples/cad/step_arm.yaml")
    assert r.code == 2 and r.err.count("\n") == 1 and "pip install 'rbcli[cad]'" in r.err, r.err
    assert r.err.startswith("rbcli: examples/cad/step_arm.yaml:")
    r = cli("inertia", "examples/cad/step_arm.step", "--material", "steel")
    assert r.code == 2 and "pip install 'rbcli[cad]'" in r.err, r.err


def test_no_yaml_body_and_no_start_up_loads_opencascade(cli_proc):
    for args in (["--help"], ["inertia", "examples/cube.yaml", "--json"], ["materials"],
                 ["inertia", "examples/housing.stl", "--density", "2700", "--json"]):
        r = cli_proc(*args, imports=True)
        assert r.code == 0, r.err
        assert not [m for m in r.imported if m.split(".")[0] == "OCP"], args
