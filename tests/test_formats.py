"""``--format table|json|csv`` on every command that prints tables.

CSV is read back with the csv module (a real parse) and checked against ``--json`` of
the same command: a quantity's value in the CSV, printed at ``--digits 17``, is the JSON
number (17 significant figures round-trip a double exactly, so equality is exact).
"""

from __future__ import annotations

import csv
import io

import pytest

ROTOR = ("balance", "examples/two_disk_rotor.yaml", "--planes", "0,400mm", "--radius", "100mm",
         "--speed", "3000 rpm", "--bearings", "0,400mm")
FIELD = ("field-balance", "--initial", "6.0@30", "--trial", "10 g@0", "--run", "4.0@110")
COMMANDS = {
    "inertia": ("inertia", "examples/bracket.yaml"),
    "principal": ("principal", "examples/two_blade_fan.yaml"),
    "balance": ROTOR,
    "field-balance": FIELD,
    "precess": ("precess", "examples/book.yaml", "--omega", "0.01,1,0.01"),
    "rollcheck": ("rollcheck", "examples/bicycle_wheel.yaml", "--speed", "5 km/h"),
    "top": ("top", "examples/top.yaml", "--spin", "150", "--theta", "30"),
    "gyrocompass": ("gyrocompass", "--ratio", "2", "--spin", "6000 rpm", "--latitude", "30"),
}


def blocks(text: str) -> list[list[dict]]:
    """The CSV's blocks, each a list of rows keyed by its header."""
    out = []
    for chunk in text.split("\n\n"):
        if chunk.strip():
            out.append(list(csv.DictReader(io.StringIO(chunk))))
    return out


def value_of(text: str, table_part: str, quantity: str) -> float:
    for block in blocks(text):
        for row in block:
            if table_part in row["table"] and row.get("quantity", "").startswith(quantity):
                return float(row["value"])
    raise AssertionError(f"no '{quantity}' in a table like '{table_part}'")


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_csv_is_one_header_per_block_and_json_is_the_json_option(cli, name):
    args = COMMANDS[name]
    r = cli(*args, "--format", "csv")
    assert r.code in (0, 1), r.err
    bs = blocks(r.out)
    assert bs and all(b and "table" in b[0] for b in bs)
    assert all(len(set(map(len, b))) == 1 for b in bs)  # a header's width on every row
    j1, j2 = cli(*args, "--format", "json"), cli(*args, "--json")
    assert j1.out == j2.out and j1.code == j2.code
    assert cli(*args).out == cli(*args, "--format", "table").out


@pytest.mark.parametrize("args, table, quantity, key", [
    (COMMANDS["inertia"], "mass properties", "mass", "mass"),
    (COMMANDS["balance"], "unbalance", "rotor mass M", "mass"),
    (COMMANDS["rollcheck"], "threshold", "critical speed", "critical_speed"),
    (COMMANDS["top"], "", "nutation period", "nutation_period"),
])
def test_csv_numbers_are_the_json_numbers(cli, args, table, quantity, key):
    text = cli(*args, "--format", "csv", "--digits", "17", "--units", "m,kg").out
    assert value_of(text, table, quantity) == cli(*args, "--json").json()[key]


def test_several_bodies_give_one_csv_with_a_file_column(cli):
    r = cli("inertia", "examples/cube.yaml", "examples/square_lamina.yaml", "--format", "csv")
    files = {row["file"] for b in blocks(r.out) for row in b}
    assert files == {"examples/cube.yaml", "examples/square_lamina.yaml"}


def test_json_and_another_format_together_is_refused(cli):
    r = cli(*COMMANDS["rollcheck"], "--json", "--format", "csv")
    assert r.code == 2 and "--json" in r.err and "csv" in r.err


def test_an_unknown_format_names_the_allowed_ones(cli):
    r = cli(*COMMANDS["precess"], "--format", "yaml")
    assert r.code == 2 and "table, json or csv" in r.err
