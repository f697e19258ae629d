"""The body file's JSON Schema: the installed copy is current, it is valid draft-07, it
accepts every example (and bodies the loader accepts) and refuses what the loader refuses.

Validation uses the ``jsonschema`` package, a test-only dependency (the ``test`` extra);
without it those tests are skipped with the reason.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rbcli.io import yamlsafe
from rbcli.body.model import load_text
from rbcli.body.schema import SCHEMA_PATH, body_schema, schema_text

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.yaml"))


def data(text: str):
    """YAML text as plain data, read by rbcli's own YAML 1.2 loader."""
    return yamlsafe.to_python(yamlsafe.load(text, "t.yaml"))


@pytest.fixture(scope="module")
def validator():
    jsonschema = pytest.importorskip("jsonschema", reason="jsonschema (the test extra) is not installed")
    schema = body_schema()
    jsonschema.Draft7Validator.check_schema(schema)  # a valid draft-07 schema
    return jsonschema.Draft7Validator(schema)


def test_installed_schema_file_is_current():
    assert SCHEMA_PATH.exists(), f"{SCHEMA_PATH} is missing: write rbcli.body.schema.schema_text() to it"
    assert SCHEMA_PATH.read_text(encoding="utf-8") == schema_text(), (
        f"{SCHEMA_PATH} is stale: python -c 'from rbcli.body.schema import *; "
        "SCHEMA_PATH.write_text(schema_text())'")
    assert json.loads(schema_text())["$schema"] == "http://json-schema.org/draft-07/schema#"


def test_schema_command_prints_the_path_of_an_existing_file_and_the_schema(cli):
    r = cli("schema", "--path")
    assert r.code == 0, r.err
    path = Path(r.out.strip())
    assert path.is_file() and path.read_text(encoding="utf-8") == schema_text()
    r = cli("schema")
    assert r.code == 0 and r.json() == body_schema()


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_the_schema_accepts_every_example(validator, path):
    errors = [e.message for e in validator.iter_errors(data(path.read_text(encoding="utf-8")))]
    assert not errors, errors


GOOD = [
    "{shape: box, size: [1, 2, 3], mass: 1}",
    "{shape: box, size: ['10 mm', 2, 3], mass: '2 kg', units: {length: mm}, rbcli: 1, name: b}",
    "parts: [{shape: plate, size: [1, 2], areal_density: 1, rotate: {euler: [1, 2, 3], seq: ZYX}}]",
    "parts: [{shape: rod, from: [0, 0, 0], to: [1, 0, 0], mass: 1}]",
    "parts: [{shape: given, mass: 1, inertia: {Ixx: 1, Iyy: 1, Izz: 1, Ixy: 0.1, convention: positive}}]",
    "parts: [{shape: given, mass: 1, com: [0, 0, 1], inertia: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}]",
    "parts: [{shape: given, mass: 1, inertia: {Lxx: 1, Lyy: 1, Lzz: 1, Lxz: 0.1, convention: positive}}]",
    "parts: [{shape: given, mass: 1, inertia: {Ixx: 1, Lyy: 1, Izz: 1, Iyx: 0, Izy: 0}}]",
    "parts: [{shape: sphere, radius: 1, shell: true, areal_density: 2, rotate: {quaternion: [1, 0, 0, 0]}}]",
    "parts: [{shape: cylinder, radius: 1, length: 2, density: 1}, "
    "{name: h, shape: cylinder, radius: 0.1, length: 2, subtract: true, cut_from: cylinder1}]",
    "reference: com\nshaft: {axis: [0, 0, 1]}\npivot: [0, 0, 0]\nrim_radius: 0.3\nparts: [{shape: point, mass: 1}]",
]
BAD = [
    "{shape: box, size: [1, 2, 3], mass: 1, colour: red}",  # unknown key
    "parts: [{shape: boks, size: [1, 2, 3], mass: 1}]",  # unknown shape
    "parts: [{shape: box, size: [1, 2], mass: 1}]",  # a box has three sides
    "parts: [{shape: plate, size: [1, 2, 3], mass: 1}]",  # a plate two
    "parts: [{shape: box, size: [1, 2, 3], mass: 1, units: {length: mm}}]",  # units belong to the body
    "{shape: box, size: [1, 2, 3], mass: 1, rbcli: 2}",  # format version 1 only
    "parts: []",  # at least one part
    "parts: [{shape: box, size: [1, 2, 3], mass: 1, rotate: {euler: [1, 2, 3], seq: ZyX}}]",  # mixed case
    "parts: [{shape: given, mass: 1, inertia: {Ixx: 1, Iyy: 1, Izz: 1, convention: cad}}]",
    "parts: [{shape: given, mass: 1, inertia: {Ixx: 1, Lxx: 1, Iyy: 1, Izz: 1}}]",  # Ixx twice
    "parts: [{shape: given, mass: 1, inertia: {Ixx: 1, Iyy: 1, Izx: 0, Lxz: 0, Izz: 1}}]",  # Izx twice
    "parts: [{shape: given, mass: 1, inertia: {Lxx: 1, Lyy: 1}}]",  # no Izz
]


@pytest.mark.parametrize("text", GOOD)
def test_the_schema_accepts_what_the_loader_accepts(validator, text):
    load_text(text, "t.yaml", Path.cwd())  # the loader accepts it ...
    errors = [e.message for e in validator.iter_errors(data(text))]
    assert not errors, errors  # ... and so does the schema


@pytest.mark.parametrize("text", BAD)
def test_the_schema_refuses_what_the_loader_refuses(validator, text):
    from rbcli.errors import InputError

    with pytest.raises(InputError):
        load_text(text, "t.yaml", Path.cwd())
    assert list(validator.iter_errors(data(text)))


def test_a_one_part_mesh_body_may_write_its_files_units_as_a_text(validator):
    mesh = {"shape": "mesh", "file": "tet.obj", "mass": 1}
    for units in ("mm", {"length": "mm"}):  # the file's length unit, or the body's units
        assert not list(validator.iter_errors({**mesh, "units": units})), units
    assert list(validator.iter_errors({"shape": "box", "size": [1, 2, 3], "mass": 1, "units": "mm"}))
