"""``--format table|json|csv`` on every command that prints tables.

CSV is read back with the csv module (a real parse) and checked against ``--json`` of
the same command: one table, one header, a quantity's value (full precision by default)
is the JSON number exactly. tests/test_csv_table.py checks every value of every command.
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
    "whirl": ("whirl", "-e", "{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}", "--bearings=-0.2,0.2",
              "--stiffness", "1e6", "--points", "5"),
}


def table(text: str) -> list[dict]:
    """The CSV's rows keyed by its one header."""
    return list(csv.DictReader(io.StringIO(text, newline="")))


def value_of(text: str, quantity: str) -> float:
    for row in table(text):
        if row["quantity"] == quantity:
            return float(row["value"])
    raise AssertionError(f"no '{quantity}' in the CSV")


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_csv_is_one_table_and_json_is_the_json_option(cli, name):
    args = COMMANDS[name]
    r = cli(*args, "--format", "csv")
    assert r.code in (0, 1), r.err
    rows = list(csv.reader(io.StringIO(r.out, newline="")))
    assert rows[0] == ["quantity", "value", "text", "unit"]
    assert all(len(row) == 4 for row in rows)  # the header's width on every row, no blank lines
    assert len({row[0] for row in rows}) == len(rows)  # unique names
    j1, j2 = cli(*args, "--format", "json"), cli(*args, "--json")
    assert j1.out == j2.out and j1.code == j2.code
    assert cli(*args).out == cli(*args, "--format", "table").out


@pytest.mark.parametrize("args, quantity, key", [
    (COMMANDS["inertia"], "mass", "mass"),
    (COMMANDS["balance"], "mass", "mass"),
    (COMMANDS["rollcheck"], "critical_speed", "critical_speed"),
    (COMMANDS["top"], "nutation_period", "nutation_period"),
])
def test_csv_numbers_are_the_json_numbers(cli, args, quantity, key):
    # --units changes the tables only: the CSV is SI, like the JSON
    text = cli(*args, "--format", "csv", "--units", "mm,g").out
    assert value_of(text, quantity) == cli(*args, "--json").json()[key]


def test_several_bodies_give_one_csv_with_a_file_column(cli):
    r = cli("inertia", "examples/cube.yaml", "examples/square_lamina.yaml", "--format", "csv")
    rows = table(r.out)
    assert {row["file"] for row in rows} == {"examples/cube.yaml", "examples/square_lamina.yaml"}
    assert r.out.count("file,quantity,value,text,unit") == 1


def test_json_and_another_format_together_is_refused(cli):
    r = cli(*COMMANDS["rollcheck"], "--json", "--format", "csv")
    assert r.code == 2 and "--json" in r.err and "csv" in r.err


def test_an_unknown_format_names_the_allowed_ones(cli):
    r = cli(*COMMANDS["precess"], "--format", "yaml")
    assert r.code == 2 and "table, json or csv" in r.err
