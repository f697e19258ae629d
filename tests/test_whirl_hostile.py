"""``whirl`` under hostile numbers and hostile bearing tables (issue 34 items 3 and 7).

- Every whirl parameter that takes numbers, at 0, tiny, huge, inf and NaN (as numbers, as
  strings with a unit, in every place of a list), through the API and the command line:
  a result, a TypeError or an rbcli.InputError; exit 0, 1 or 2 with one line; never exit 70
  (a bug) and never a traceback. The values are generated from the command's parameter
  table, so a parameter added to it is driven too.
- A generated corpus of bad ``bearings:`` sections and bad coefficient tables (CSV): each is
  refused in one line located in its file (``file:line``), and nothing is misread
  silently — a table whose rows are out of order is refused, never sorted.
"""

from __future__ import annotations

import itertools
import math

import pytest

import rbcli
from rbcli.api.commands import WHIRL
from rbcli.errors import InputError

from conftest import sampled_params

CYL = "{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}"
BASE = dict(bearings="-0.2,0.2", stiffness=1e6, damping=300.0, points=11)
NUMBERS = [0.0, 5e-324, 1e-300, 1e160, 1e300, math.inf, -math.inf, math.nan, -1.0]
UNIT = {"length": "m", "stiffness": "N/m", "damping": "N*s/m", "angular_speed": "rpm"}


def _values(p) -> list:
    """Hostile values of a numeric parameter: each number alone and in every place of the
    list the parameter takes, as a float and as a string with a unit."""
    n = max(p.counts) if p.kind == "values" else 1
    good = {"speed_range": [0.0, 300.0], "map_stiffness": [1e5, 1e7], "bearings": [-0.2, 0.2]}.get(p.name, [1e5] * n)
    out = []
    for x in NUMBERS:
        for i in range(min(n, 2)):
            row = list(good[:n]) if p.name in ("speed_range", "map_stiffness", "bearings") else [good[0]] * min(n, 2)
            row[i] = x
            out.append(row[0] if len(row) == 1 else row)
            out.append(",".join(repr(v) for v in row) + f" {UNIT.get(p.quantity, '')}".rstrip())
    return out


NUMERIC = [p for p in WHIRL if p.kind in ("quantity", "values") and p.api]
CASES = [(p.name, v) for p in NUMERIC for v in _values(p)]


def _kept(case) -> bool:
    """The default run: the biggest, the NaN and the smallest of each parameter, as floats."""
    name, v = case
    x = v if isinstance(v, float) else v[-1] if isinstance(v, list) else None
    return isinstance(x, float) and (x in (1e300, 5e-324) or x != x)


@pytest.mark.parametrize("case", sampled_params(CASES, _kept, ids=lambda c: f"{c[0]}={c[1]!r}"[:60]))
def test_hostile_numbers_give_a_result_or_an_input_error(case):
    name, value = case
    body = rbcli.load_text(CYL)
    kw = {**BASE, name: value}
    try:
        res = rbcli.whirl(body, **kw)
    except InputError as exc:
        assert "\n" not in str(exc) and "--" not in str(exc).split("'")[0]
        return
    except TypeError:
        return
    assert res.to_json()  # every number finite (jsonable refuses inf and NaN)


@pytest.mark.parametrize("args", sampled_params([
    ["--speed", "1e160"], ["--speed", "1e300 rpm"], ["--speed-range", "1,1e300 rpm"],
    ["--speed-range", "0,inf"], ["--speed", "nan"], ["--stiffness", "1e300"],
    ["--stiffness", "1e-300"], ["--damping", "1e300"], ["--cross-stiffness", "1e300"],
    ["--stiffness-xy", "inf"], ["--damping-yx", "1e-320"], ["--map-stiffness", "1e-300,1e300"],
    ["--bearings", "0,1e300"], ["--unbalance", "1e300@0,1@0", "--unbalance-planes", "-0.2,0.2"],
    ["--points", "99999999999999999999"], ["--orders", "1,2,3,4,5,6,7,8,9,10"],
], keep=range(16), ids=lambda a: " ".join(a)[:40]))
def test_the_command_line_never_exits_70(cli, args):
    r = cli("whirl", "-e", CYL, "--bearings=-0.2,0.2", "--stiffness", "1e6", "--damping", "300",
            "--points", "11", *args)
    assert r.code in (0, 1, 2), r.err
    if r.code == 2:
        assert len(r.err.splitlines()) == 1 and r.err.startswith("rbcli: "), r.err


# --------------------------------------------------------------------- bearings: sections


BODY = "name: r\nparts:\n  - {shape: cylinder, radius: 0.1, length: 0.6, mass: 50}\n"
ROW = "[100, 1e6, 0, 0, 1e6, 200, 0, 0, 200]"

SECTIONS = [
    ("bearings: 3", "a list of bearings"),
    ("bearings: []", "a list of bearings"),
    ("bearings: [3, 4]", "must be a mapping"),
    ("bearings: [{k: 1e6}, {at: 0.2, k: 1e6}]", "needs its position"),
    ("bearings: [{at: 0, k: 1e6, kxx: 2e6}, {at: 0.2, k: 1e6}]", "not both"),
    ("bearings: [{at: -0.2, k: -1e6}, {at: 0.2, k: 1e6}]", "must be positive"),
    ("bearings: [{at: -0.2, k: 1e6, c: -1}, {at: 0.2, k: 1e6}]", "must not be negative"),
    ("bearings: [{at: -0.2, k: 1e6, stiffnes: 3}, {at: 0.2, k: 1e6}]", "unknown key 'stiffnes'"),
    ("bearings: [{at: -0.2, k: '1e6 kg'}, {at: 0.2, k: 1e6}]", "bearings[0].k"),
    ("bearings: [{at: -0.2, k: .inf}, {at: 0.2, k: 1e6}]", "finite"),
    ("bearings: [{at: -0.2, k: 1e61}, {at: 0.2, k: 1e6}]", "at most 1e60"),
    ("bearings: [{at: -0.2, k: true}, {at: 0.2, k: 1e6}]", "must be a number"),
    ("bearings: [{at: -0.2, k: [1, 2]}, {at: 0.2, k: 1e6}]", "must be a number"),
    ("bearings: [{at: [0, 0, 1], k: 1e6}, {at: 0.2, k: 1e6}]", "bearings[0].at"),
    ("bearings: [{at: -0.2, name: [1], k: 1e6}, {at: 0.2, k: 1e6}]", "name must be text"),
    ("bearings: [{at: -0.2, k: 1e6, units: {speed: kg}}, {at: 0.2, k: 1e6}]", "units.speed"),
    ("bearings: [{at: -0.2, k: 1e6, units: {force: N}}, {at: 0.2, k: 1e6}]", "unknown key 'force'"),
    ("bearings: [{at: -0.2, table: 3}, {at: 0.2, k: 1e6}]", "CSV file name or a list of rows"),
    (f"bearings: [{{at: -0.2, table: [{ROW}]}}, {{at: 0.2, k: 1e6}}]", "two rows or more"),
    ("bearings: [{at: -0.2, table: [[1, 2, 3]]}, {at: 0.2, k: 1e6}]", "a list of 9 numbers"),
    (f"bearings: [{{at: -0.2, table: [{ROW}, {ROW}]}}, {{at: 0.2, k: 1e6}}]", "ascending speed"),
    ("bearings: [{at: -0.2, table: [[200, 1e6, 0, 0, 1e6, 200, 0, 0, 200], " + ROW + "]}, {at: 0.2, k: 1e6}]",
     "not reordered"),
    ("bearings: [{at: -0.2, table: [[-5, 1e6, 0, 0, 1e6, 0, 0, 0, 0], " + ROW + "]}, {at: 0.2, k: 1e6}]",
     "must not be negative"),
    ("bearings: [{at: -0.2, table: [[50, 0, 0, 0, 1e6, 0, 0, 0, 0], " + ROW + "]}, {at: 0.2, k: 1e6}]",
     "kxx must be positive"),
    ("bearings: [{at: -0.2, k: 1e6, table: nope.csv}, {at: 0.2, k: 1e6}]", "not both"),
    ("bearings: [{at: -0.2, table: nope.csv}, {at: 0.2, k: 1e6}]", "no such file"),
    ("bearings: [{at: -0.2, table: .}, {at: 0.2, k: 1e6}]", "directory"),
    ("bearings: [{at: -0.2, table: /dev/zero}, {at: 0.2, k: 1e6}]", "not a regular file"),
    ("bearings: [{at: 0.2, k: 1e6}, {at: 0.2, k: 1e6}]", "bearings[1]: the bearings are all at one place"),
    ("bearings: [{at: 0, k: 1e6}, {at: 0.2, k: 1e6}, {at: 0.2, k: 1e6}]", "bearings 2 and 3 are both at"),
    ("bearings: [{at: 0.2, k: 1e6}]", "bearings[0]: a rotor on bearings needs two or more"),
    ("bearings: [{at: -0.2, c: 100}, {at: 0.2, c: 100}]", "needs the bearing stiffness"),
]

HEADER = "speed [rpm], kxx, kxy, kyx, kyy, cxx, cxy, cyx, cyy"
CSVS = [
    ("", "empty table"),
    ("# only a comment\n", "empty table"),
    ("1000, 1e6, 0, 0, 1e6, 0, 0, 0, 0\n", "unknown column '1000'"),
    ("speed, kxx, kxy, kxx\n1, 1e6, 0, 1e6\n", "named twice"),
    ("kxx, kyy\n1e6, 1e6\n", "the header names"),
    ("speed\n1\n2\n", "the header names"),
    ("speed, kxx, ky\n", "unknown column 'ky'"),
    ("speed [kg], kxx, kyy\n1, 1e6, 1e6\n2, 1e6, 1e6\n", "column speed"),
    ("speed, kxx [N], kyy\n1, 1e6, 1e6\n2, 1e6, 1e6\n", "column kxx"),
    (HEADER + "\n1000, 1e6, 0, 0, 1e6, 0, 0, 0\n", "8 cells where the header names 9"),
    (HEADER + "\n1000, 1e6, x, 0, 1e6, 0, 0, 0, 0\n", "is not a number"),
    (HEADER + "\n1000, 1e6, nan, 0, 1e6, 0, 0, 0, 0\n2000, 1e6, 0, 0, 1e6, 0, 0, 0, 0\n", "is not a number"),
    (HEADER + "\n1000, 1e6, .nan, 0, 1e6, 0, 0, 0, 0\n2000, 1e6, 0, 0, 1e6, 0, 0, 0, 0\n", "finite"),
    (HEADER + "\n1000, 1e6, -.inf, 0, 1e6, 0, 0, 0, 0\n2000, 1e6, 0, 0, 1e6, 0, 0, 0, 0\n", "finite"),
    (HEADER + "\n1000, 1e6, 1e400, 0, 1e6, 0, 0, 0, 0\n2000, 1e6, 0, 0, 1e6, 0, 0, 0, 0\n", "finite"),
    (HEADER + "\n1000, 1e6, 0, 0, 1e6, 0, 0, 0, 0\n", "two rows or more"),
    (HEADER + "\n2000, 1e6, 0, 0, 1e6, 0, 0, 0, 0\n1000, 1e6, 0, 0, 1e6, 0, 0, 0, 0\n", "not reordered"),
    (HEADER + "\n1000, 1e6, 0, 0, 1e6, 0, 0, 0, 0\n1000, 2e6, 0, 0, 2e6, 0, 0, 0, 0\n", "each speed once"),
    (HEADER + "\n1000, -1e6, 0, 0, 1e6, 0, 0, 0, 0\n2000, 1e6, 0, 0, 1e6, 0, 0, 0, 0\n", "must be positive"),
    ("speed, kyy\n1, 1e6\n2, 1e6\n", "kxx must be positive"),
    (b"\xff\xfe" + HEADER.encode("utf-16-le"), "not UTF-8"),
    (HEADER + "\n" + "".join(f"{i}, 1e6, 0, 0, 1e6, 0, 0, 0, 0\n" for i in range(1, 10_003)), "more than 10000 rows"),
]


def _write(tmp_path, section: str, csv: str | bytes | None = None):
    p = tmp_path / "rotor.yaml"
    p.write_text(BODY + section + "\n", encoding="utf-8")
    if csv is not None:
        (tmp_path / "t.csv").write_bytes(csv if isinstance(csv, bytes) else csv.encode("utf-8"))
    return p


@pytest.mark.parametrize("section, says", SECTIONS, ids=[s[1][:30] for s in SECTIONS])
def test_a_bad_bearings_section_is_one_located_line(cli, tmp_path, section, says):
    p = _write(tmp_path, section)
    r = cli("whirl", str(p), "--points", "11", cwd=tmp_path)
    assert r.code == 2, (r.code, r.err)
    lines = r.err.splitlines()
    assert len(lines) == 1 and says in lines[0], r.err
    if "no such file" not in says:
        assert lines[0].startswith(f"rbcli: {p}:"), r.err  # located in the body file


@pytest.mark.parametrize("csv, says", CSVS, ids=[s[1][:30] for s in CSVS])
def test_a_bad_coefficient_table_is_one_located_line(cli, tmp_path, csv, says):
    p = _write(tmp_path, "bearings: [{at: -0.2, table: t.csv}, {at: 0.2, k: 1e6}]", csv)
    r = cli("whirl", str(p), "--points", "11", cwd=tmp_path)
    assert r.code == 2, (r.code, r.err)
    lines = r.err.splitlines()
    assert len(lines) == 1 and says in lines[0] and "t.csv" in lines[0], r.err
    assert lines[0].count("t.csv") == 1, r.err  # located once ('t.csv:3: t.csv: ...' before)


def test_every_row_order_but_the_ascending_one_is_refused(tmp_path):
    """Nothing misread silently: a table's rows in any other order are refused, never
    sorted (a coefficient file is what it says, row by row)."""
    rows = [f"{s}, {k}, 0, 0, {k}, 100, 0, 0, 100" for s, k in ((500, 1e6), (1000, 2e6), (2000, 3e6))]
    body = None
    for perm in itertools.permutations(rows):
        p = _write(tmp_path, "bearings: [{at: -0.2, table: t.csv}, {at: 0.2, table: t.csv}]",
                   HEADER + "\n" + "\n".join(perm) + "\n")
        body = rbcli.load(p)
        if list(perm) == rows:
            res = rbcli.whirl(body, points=11)
            for b in res.bearings:  # as written (a bare number times the unit's factor: ~1 ulp)
                assert list(b.table.speeds) == pytest.approx([s * math.pi / 30 for s in (500, 1000, 2000)], rel=1e-15)
                assert list(b.table.kxx) == [1e6, 2e6, 3e6]
        else:
            with pytest.raises(InputError, match="ascending speed"):
                rbcli.whirl(body, points=11)


def test_a_table_is_never_extrapolated(tmp_path):
    p = _write(tmp_path, "bearings: [{at: -0.2, table: t.csv}, {at: 0.2, k: 1e6}]",
               HEADER + "\n500, 1e6, 0, 0, 1e6, 100, 0, 0, 100\n3000, 2e6, 0, 0, 2e6, 100, 0, 0, 100\n")
    body = rbcli.load(p)
    res = rbcli.whirl(body, points=11)  # the default range: within the table
    assert res.speed_range[0] == pytest.approx(500 * math.pi / 30) and res.speed_range[1] <= 3000 * math.pi / 30
    for kw in (dict(speed="4000 rpm"), dict(speed_range="0,2000 rpm"), dict(speed_range="600,3001 rpm")):
        with pytest.raises(InputError, match="not extrapolated"):
            rbcli.whirl(body, points=11, **kw)
