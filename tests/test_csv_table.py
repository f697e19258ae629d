"""``--format csv`` is one table (issue 24 item 6): every command's CSV, read back with the csv
module, is its ``--json``, value by value.

The layout (rbcli/render/tablecsv.py, rbcli(1)): a header ``quantity,value,text,unit``
(``file`` first with several bodies), one row per JSON leaf, the JSON path as the quantity,
numbers only in ``value`` (full precision unless ``--digits``), strings and booleans only in
``text``, every number with its SI unit. The reference here is the JSON the same command
prints, walked by this test's own flattener (not the renderer's).
"""

from __future__ import annotations

import csv
import io
import json
import re
from pathlib import Path

import pytest
import yaml

from conftest import run_inprocess

ROOT = Path(__file__).resolve().parent.parent
CASES_DIR = ROOT / "tests" / "cases"

#: a nearly symmetric body (a disk with a 0.2 g point on its rim): the asymmetry keys of top,
#: gyrocompass and rollcheck
ASYM = ("{parts: [{shape: cylinder, radius: 0.1, length: 0.02, mass: 1, at: [0, 0, 0.05]}, "
        "{shape: point, mass: 0.0002, at: [0.05, 0, 0.05]}]}")

#: command lines that reach the keys the golden cases do not (--verify, --at, asymmetric
#: bodies, field-balance's extended outputs, whirl's response and margins)
EXTRA = [
    ["inertia", "examples/square_lamina.yaml", "--about", "1,1,0", "--omega", "0,0,300 rpm", "--axis", "z"],
    ["inertia", "examples/housing.yaml"],
    ["principal", "examples/housing.yaml", "examples/cube.yaml"],
    ["balance", "examples/fan_impeller.yaml", "--planes", "320,380mm", "--radius", "190mm", "--bearings",
     "0,200mm", "--speed", "1480 rpm", "--grade", "G6.3", "--positions", "6", "--mass-step", "0.5 g"],
    ["field-balance", "examples/jobs/fan.yaml"],
    ["field-balance", "--initial", "1@0,1@180,0@0", "--trial", "1@0", "--run", "4@0,4@0,5@0", "--trial",
     "1@0", "--run", "1@180,3@180,3@180", "--method", "min-max"],
    ["field-balance", "--suggest-trial", "--rotor-mass", "120 kg", "--speed", "1480 rpm", "--trial-radius",
     "250 mm"],
    ["field-balance", "--initial", "0.25 in/s@30", "--trial", "10@0", "--run", "4.0 mm/s@110", "--severity",
     "iso20816-3", "--group", "1", "--foundation", "rigid", "--speed", "1480 rpm", "--measure", "rms"],
    ["precess", "examples/book.yaml", "--omega", "0.01,1,0.01", "--at", "12.5", "--verify"],
    ["precess", "examples/frisbee.yaml", "--omega", "0.8715574275,0,9.961946981", "--at", "1"],
    ["top", "examples/top.yaml", "--spin", "150", "--theta", "30", "--verify"],
    ["top", "-e", ASYM, "--spin", "150", "--theta", "30", "--verify"],
    ["gyrocompass", "examples/gyroscope.yaml", "--spin", "6000 rpm", "--latitude", "30"],
    ["gyrocompass", "-e", ASYM, "--spin", "6000 rpm", "--latitude", "30"],
    ["rollcheck", "examples/hoop.yaml", "--lean", "20", "--circle", "2"],
    ["rollcheck", "-e", ASYM, "--speed", "3"],
    ["whirl", "examples/fan_rotor.yaml", "--bearings", "0,500", "--stiffness", "5e6,4e6", "--stiffness-y",
     "8e6", "--damping", "800", "--speed", "1200,1600 rpm", "--unbalance", "50 g*mm@0,30 g*mm@120",
     "--unbalance-planes", "710,800", "--units", "mm,kg", "--points", "7"],
    ["whirl", "-e", "{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}", "--bearings=-0.2,0.2",
     "--stiffness", "1e6", "--cross-stiffness", "1e5", "--damping", "100", "--speed", "150", "--points", "7"],
]


def _golden_json_cases() -> list[tuple[list[str], Path]]:
    """(args without --json, the golden JSON file) of every golden --json case that exits 0 or 1."""
    out = []
    for case in sorted(CASES_DIR.glob("*/*.yaml")):
        spec = yaml.safe_load(case.read_text(encoding="utf-8"))
        args = spec["args"]
        if "--json" in args and spec["exit"] in (0, 1):
            out.append(([a for a in args if a != "--json"], case.with_suffix(".out")))
    return out


GOLDEN_JSON = _golden_json_cases()
FORMULA = ("=", "+", "-", "@", "\t", "\r")


def leaves(data, path=""):
    """(path, value) of every leaf of JSON data; an empty list or mapping is a None leaf."""
    if isinstance(data, dict):
        if not data:
            yield path, None
        for k, v in data.items():
            yield from leaves(v, f"{path}.{k}" if path else k)
    elif isinstance(data, list):
        if not data:
            yield path, None
        for i, v in enumerate(data):
            yield from leaves(v, f"{path}[{i}]")
    else:
        yield path, data


def undefined_paths(data, path="") -> set[str]:
    """Paths of the ``<name>_deg`` numbers whose ``<name>_defined`` sibling is false."""
    out: set[str] = set()
    if isinstance(data, dict):
        for k, v in data.items():
            p = f"{path}.{k}" if path else k
            flag = data.get(k[:-4] + "_defined") if k.endswith("_deg") else None
            if flag is False:
                out.add(p)
            elif isinstance(flag, list):
                out |= {f"{p}[{i}]" for i, f in enumerate(flag) if f is False}
            out |= undefined_paths(v, p)
    elif isinstance(data, list):
        for i, v in enumerate(data):
            out |= undefined_paths(v, f"{path}[{i}]")
    return out


def read_csv(text: str) -> tuple[list[str], list[list[str]]]:
    rows = list(csv.reader(io.StringIO(text, newline="")))
    return rows[0], rows[1:]


def unneutralised(text: str) -> str:
    """A text cell as the JSON has it: the apostrophe before a formula character dropped."""
    return text[1:] if text.startswith("'") and text[1:].startswith(FORMULA) else text


def check_against_json(rows: list[list[str]], doc: dict, digits: int | None = None) -> None:
    """The CSV rows of one body are its JSON, value by value, in order."""
    undefined = undefined_paths(doc)
    expected = list(leaves(doc))
    assert [r[0] for r in rows] == [p for p, _ in expected]
    assert len({r[0] for r in rows}) == len(rows)  # unique names
    for (quantity, value, text, unit), (path, v) in zip(rows, expected):
        if isinstance(v, bool):
            assert (value, text, unit) == ("", "true" if v else "false", ""), path
        elif isinstance(v, (int, float)):
            assert text == "" and unit != "", (path, unit)  # every number has its unit
            if path in undefined:
                assert value == "", path
            elif digits is None:
                assert float(value) == v, path  # full precision: the very same double
                if isinstance(v, int):
                    assert value == str(v)
            else:  # N significant figures: the JSON's number rounded to N figures
                assert float(value) == float(f"{v:.{digits}g}"), path
        elif isinstance(v, str):
            assert value == "" and unit == "", path
            assert unneutralised(text) == v, path
        else:
            assert (value, text, unit) == ("", "", ""), path


def _csv_and_json(args: list[str]) -> tuple[str, list[dict]]:
    r = run_inprocess(*args, "--format", "csv")
    assert r.code in (0, 1), r.err
    j = run_inprocess(*args, "--json")
    assert j.code == r.code
    docs = j.json()
    return r.out, docs if isinstance(docs, list) else [docs]


def _check(text: str, docs: list[dict], digits: int | None = None) -> None:
    header, rows = read_csv(text)
    if len(docs) == 1:
        assert header == ["quantity", "value", "text", "unit"]
        check_against_json(rows, docs[0], digits)
        return
    assert header == ["file", "quantity", "value", "text", "unit"]
    for doc in docs:
        mine = [r[1:] for r in rows if r[0] == doc["file"]]
        check_against_json(mine, doc, digits)
    assert sum(1 for _ in rows) == sum(len(list(leaves(d))) for d in docs)


@pytest.mark.parametrize("args,golden", GOLDEN_JSON, ids=lambda x: str(x)[:60] if isinstance(x, Path) else " ".join(x)[:70])
def test_csv_is_the_golden_json(args, golden):
    """Every command on every example (the golden --json cases): the CSV is that JSON."""
    r = run_inprocess(*args, "--format", "csv")
    text = golden.read_text(encoding="utf-8")
    docs = [json.loads(line) for line in text.splitlines()] if text.startswith('{"') else [json.loads(text)]
    _check(r.out, docs)


@pytest.mark.parametrize("args", EXTRA, ids=lambda a: " ".join(a)[:70])
def test_csv_is_the_json(args):
    out, docs = _csv_and_json(args)
    _check(out, docs)


def test_csv_with_files_written(tmp_path):
    """The JSON keys of the files a command writes (--apply, --csv, --plot) are rows too."""
    body = tmp_path / "rotor.yaml"
    body.write_text((ROOT / "examples" / "two_disk_rotor.yaml").read_text(encoding="utf-8"), encoding="utf-8")
    for args in (
        ["balance", str(body), "--planes", "0,400mm", "--radius", "100mm", "--apply", str(tmp_path / "out.yaml"),
         "--force"],
        ["precess", "examples/book.yaml", "--omega", "0.01,1,0.01", "--csv", str(tmp_path / "p.csv"),
         "--duration", "1", "--plot", str(tmp_path / "p.png")],
        ["top", "examples/top.yaml", "--spin", "150", "--theta", "30", "--csv", str(tmp_path / "t.csv"),
         "--duration", "0.5"],
    ):
        out, docs = _csv_and_json(args)
        _check(out, docs)
        assert any(key in docs[0] for key in ("apply", "csv"))


@pytest.mark.parametrize("args", [EXTRA[0], EXTRA[3], ["principal", "examples/two_blade_fan.yaml"],
                                  ["precess", "examples/book.yaml", "--omega", "0.01,1,0.01"]],
                         ids=lambda a: " ".join(a)[:60])
@pytest.mark.parametrize("digits", [3, 17])
def test_digits_round_every_number(args, digits):
    """--digits N: N significant figures in every number cell (angles too: issue 24 found
    principal's angles at 4 figures whatever --digits said)."""
    out, docs = _csv_and_json([*args, "--digits", str(digits)])
    _check(out, docs, digits)


def test_golden_csv_cases_are_one_table():
    """Every golden CSV case (tests/cases/*/*-csv) reads as one table with the one header."""
    seen = 0
    for case in sorted(CASES_DIR.glob("*/*.yaml")):
        spec = yaml.safe_load(case.read_text(encoding="utf-8"))
        if "--format" not in spec["args"] or spec["args"][spec["args"].index("--format") + 1] != "csv":
            continue
        seen += 1
        with open(case.with_suffix(".out"), newline="", encoding="utf-8") as fh:
            rows = list(csv.reader(fh))
        assert rows[0][-4:] == ["quantity", "value", "text", "unit"], case
        assert all(len(r) == len(rows[0]) for r in rows), case
        args = [a for a in spec["args"]]
        i = args.index("--format")
        out, docs = _csv_and_json(args[:i] + args[i + 2:])
        _check(case.with_suffix(".out").read_text(encoding="utf-8"), docs)
    assert seen >= 9  # one per command that has --format csv


def test_several_bodies_one_header_past_a_bad_file(tmp_path):
    """inertia on several files: one header, a file column, a bad file in the middle left out."""
    bad = tmp_path / "bad.yaml"
    bad.write_text("parts: [{shape: box}]\n", encoding="utf-8")
    r = run_inprocess("inertia", "examples/cube.yaml", str(bad), "examples/square_lamina.yaml",
                      "--format", "csv")
    assert r.code == 2 and "bad.yaml" in r.err
    header, rows = read_csv(r.out)
    assert header == ["file", "quantity", "value", "text", "unit"]
    assert {row[0] for row in rows} == {"examples/cube.yaml", "examples/square_lamina.yaml"}
    assert sum(1 for row in rows if row[1] == "mass") == 2


def test_units_named_for_every_number():
    """The unit table knows every numeric key of every command's golden JSON (else the CSV's
    unit column would be empty): checked by check_against_json above for each case; here the
    documented names of a few, against the man pages' JSON sections."""
    from rbcli.api.commands import TABLES
    from rbcli.api.params import si_unit
    from rbcli.render import csvunits

    def lookup(command, path):  # as the command line looks it up: with its parameters' units
        return csvunits.lookup(command, path, {p.name: si_unit(p) for p in TABLES[command]})

    assert lookup("inertia", "inertia[1][2]") == "kg*m^2"
    assert lookup("balance", "corrections[0].unbalance") == "kg*m"
    assert lookup("balance", "iso.achieved_grade[1]") == "mm/s"  # ISO 21940-11's G, mm/s
    assert lookup("rollcheck", "speed") == "m/s" and lookup("whirl", "speed[0]") == "rad/s"
    assert lookup("whirl", "cross_stiffness[1]") == "N/m"  # from the parameter's table
    assert csvunits.lookup("whirl", "cross_stiffness[1]") is None  # (not in csvunits)
    assert lookup("top", "theta1_deg") == "deg"
    assert lookup("precess", "at.rotation_matrix[2][1]") == "1"


def test_pandas_reads_it_in_one_call():
    """The optional peer: pandas.read_csv takes it in one call, the value column as floats."""
    pd = pytest.importorskip("pandas")
    args = ["balance", "examples/two_disk_rotor.yaml", "--planes", "0,400mm", "--radius", "100mm",
            "--speed", "3000 rpm", "--bearings", "0,400mm", "--grade", "G6.3"]
    out, docs = _csv_and_json(args)
    df = pd.read_csv(io.StringIO(out), keep_default_na=False, na_values=[""])
    assert list(df.columns) == ["quantity", "value", "text", "unit"]
    assert df["value"].dtype == float and df["quantity"].is_unique
    values = df.set_index("quantity")["value"]
    assert values["corrections[1].mass"] == docs[0]["corrections"][1]["mass"]  # the same double
    assert values["iso.before.residual[1]"] == docs[0]["iso"]["before"]["residual"][1]


def test_the_readme_csv_example_is_what_the_command_prints():
    import shlex

    text = (ROOT / "README.md").read_text(encoding="utf-8")
    part = text.split("`--format csv` (every command that prints tables", 1)[1]
    command = " ".join(re.search(r"`(rbcli balance\s.*?--format csv)`", part, re.S).group(1).split())
    rows = re.search(r"```\n(.*?)```", part, re.S).group(1).split()
    out = run_inprocess(*shlex.split(command)[1:]).out.splitlines()
    assert rows[0] == out[0] and set(rows) <= set(out)
