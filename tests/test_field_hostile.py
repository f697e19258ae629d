"""``field-balance`` under hostile numbers and hostile files (issue 34 items 2, 3 and 7).

- Every field-balance parameter that takes numbers, and every number inside a reading, a
  trial mass, a limit or a drawer, at 0, tiny, huge, inf and NaN (generated from the
  command's parameter table, so a parameter added to it is driven too), through the API and
  the command line: a result, a TypeError or an rbcli.InputError; exit 0, 1 or 2 with one
  line; never exit 70 (a bug).
- A generated corpus of bad limits, holes and drawers in job files: each refused in one line
  located in the job file (``file:line``), never misread.
- Coefficient files permuted, repeated, retyped or edited: refused, saying what differs,
  never read in another order.
"""

from __future__ import annotations

import json
import math

import pytest

import rbcli
from rbcli.api.commands import FIELD_BALANCE
from rbcli.errors import InputError

from conftest import sampled_params

GOODMAN = dict(initial="1@0,1@180,0@0", trial=["1 g@0", "1 g@0"], run=["4@0,4@0,5@0", "1@180,3@180,3@180"])
NUMBERS = [0.0, 5e-324, 1e-300, 1e160, 1e300, math.inf, -math.inf, math.nan, -1.0]
TEXT = {"trial_radius": "{} m", "radius": "{} m", "mass_step": "{} g", "angle_step": "{} deg",
        "speed": "{} rpm", "rotor_mass": "{} kg", "bearing_load": "{} N", "trial_fraction": "{}",
        "max_mass": "{} g", "limit": "{}", "drawer": "{} g:2", "weights": "{},1,1", "positions": "{}",
        "max_weights": "{}", "group": "{}"}
#: what else a parameter needs to be used at all
NEEDS = {"trial_radius": dict(radius="0.2"), "radius": dict(trial_radius="0.2"),
         "drawer": dict(positions=6), "max_weights": dict(drawer="1 g:4", positions=6),
         "rotor_mass": dict(suggest_trial=True, speed="1000 rpm", trial_radius="0.1"),
         "bearing_load": dict(suggest_trial=True, speed="1000 rpm", trial_radius="0.1"),
         "trial_fraction": dict(suggest_trial=True, speed="1000 rpm", trial_radius="0.1", rotor_mass=10),
         "group": dict(severity="iso20816-3", foundation="rigid")}
NUMERIC = [p.name for p in FIELD_BALANCE if p.name in TEXT]


def _cases() -> list:
    out = []
    for name in NUMERIC:
        for x in NUMBERS:
            out.append((name, TEXT[name].format(repr(x))))
            if name in ("trial_radius", "radius", "mass_step", "speed", "rotor_mass", "bearing_load",
                        "trial_fraction", "weights"):
                out.append((name, x if name != "weights" else [x, 1.0, 1.0]))
    for where in ("initial", "run", "trial"):  # the numbers inside readings and trial masses
        for x in NUMBERS:
            for text in (f"{x!r}@0", f"1@{x!r}", f"{x!r} mm/s@0"):
                out.append((where, text))
    return out


CASES = _cases()


def _kwargs(name, value) -> dict:
    kw = {**GOODMAN, **NEEDS.get(name, {})}
    if name == "initial":
        kw["initial"] = f"{value},1@180,0@0"
    elif name == "run":
        kw["run"] = [f"{value},4@0,5@0", GOODMAN["run"][1]]
    elif name == "trial":
        kw["trial"] = [value, "1 g@0"]
    else:
        kw[name] = value
    return kw


def _kept(case) -> bool:
    """The default run: each parameter's huge, NaN and tiniest value, as text."""
    name, v = case
    return isinstance(v, str) and any(s in v for s in ("1e+300", "nan", "5e-324"))


@pytest.mark.parametrize("case", sampled_params(CASES, _kept, ids=lambda c: f"{c[0]}={c[1]!r}"[:50]))
def test_hostile_numbers_give_a_result_or_an_input_error(case):
    name, value = case
    try:
        res = rbcli.field_balance(**_kwargs(name, value))
    except InputError as exc:
        assert "\n" not in str(exc) and "--" not in str(exc).split("'")[0]
        return
    except TypeError:
        return
    assert json.dumps(res.to_json(), allow_nan=False)  # every number finite


@pytest.mark.parametrize("args", sampled_params([
    ["--trial-radius", "1e300", "--radius", "1e-300"], ["--mass-step", "5e-324 g"],
    ["--max-mass", "1e-300 g"], ["--max-mass", "nan"], ["--limit", "1e-300"], ["--limit", "1=inf"],
    ["--drawer", "1e300 g:1", "--positions", "6"], ["--drawer", "1e-300 g", "--positions", "6"],
    ["--weights", "1e300,1e-300,1"], ["--max-weights", "99999999999999999999", "--drawer", "1 g", "--positions", "6"],
    ["--method", "min-max", "--limit", "1e-300"], ["--robust", "huber", "--weights", "1e300,1,1"],
], keep=range(12), ids=lambda a: " ".join(a)[:40]))
def test_the_command_line_never_exits_70(cli, args):
    r = cli("field-balance", "--initial", "1@0,1@180,0@0,2@90", "--trial", "1 g@0", "--run",
            "4@0,4@0,5@0,1@0", "--trial", "1 g@0", "--run", "1@180,3@180,3@180,2@0", *args)
    assert r.code in (0, 2), r.err
    if r.code == 2:
        assert len(r.err.splitlines()) == 1 and r.err.startswith("rbcli: "), r.err


# --------------------------------------------------------------------- job files: limits, holes, drawers


JOB = """sensors: [S1, {name: S2, limit: 2}, S3, S4]
planes:
  - {name: A, radius: 0.2, %s}
  - {name: B, radius: 0.2, positions: 6}
initial: ["1@0", "1@180", "0@0", "2@90"]
trials:
  - {plane: A, mass: "1 g@0", readings: ["4@0", "4@0", "5@0", "1@0"]}
  - {plane: B, mass: "1 g@0", readings: ["1@180", "3@180", "3@180", "2@0"]}
drawer: %s
"""
GOOD_A, GOOD_DRAWER = "holes: {count: 8}", '["1 g:4", "2 g:4"]'

BAD_JOBS = [
    ("holes: 8", GOOD_DRAWER, "must be a mapping"),
    ("holes: {}", GOOD_DRAWER, "needs 'count'"),
    ("holes: {count: 8, angles: [0, 90]}", GOOD_DRAWER, "one of them"),
    ("holes: {count: 0}", GOOD_DRAWER, "count must be a whole number from 1"),
    ("holes: {count: 1e400}", GOOD_DRAWER, "count must be a whole number"),
    ("holes: {count: 8, zero: .nan}", GOOD_DRAWER, "finite"),
    ("holes: {count: 8, zero: '10 kg'}", GOOD_DRAWER, "zero"),
    ("holes: {angles: []}", GOOD_DRAWER, "a list of 1 to 3600 angles"),
    ("holes: {angles: [0, .inf]}", GOOD_DRAWER, "finite"),
    ("holes: {angles: [0, [1]]}", GOOD_DRAWER, "must be a number"),
    ("holes: {count: 8, radius: -1}", GOOD_DRAWER, "radius must be positive"),
    ("holes: {count: 8, numbering: clockwise}", GOOD_DRAWER, "numbering must be with or against"),
    ("holes: {count: 8, per_hole: 9}", GOOD_DRAWER, "per_hole must be a whole number from 1 to 4"),
    ("holes: {count: 8, depth: 3}", GOOD_DRAWER, "unknown key 'depth'"),
    ("positions: 8, holes: {count: 8}", GOOD_DRAWER, "not both"),
    ("max_mass: -5", GOOD_DRAWER, "max_mass must be positive"),
    ("max_mass: '5 mm'", GOOD_DRAWER, "a positive mass"),
    ("max_mass: '1e999 g'", GOOD_DRAWER, "max_mass"),
    ("max_mass: [1]", GOOD_DRAWER, "max_mass"),
    ("max_weights: 5", GOOD_DRAWER, "max_weights must be a whole number from 1 to 4"),
    ("max_weights: true", GOOD_DRAWER, "max_weights must be a whole number"),
    ("drawer: 3", GOOD_DRAWER, "drawer must be a list"),
    (GOOD_A, "3", "drawer must be a list"),
    (GOOD_A, "[]", "drawer must be a list"),
    (GOOD_A, '["1 g:0"]', "the count after ':' must be a whole number from 1"),
    (GOOD_A, '["1 g:x"]', "the count after ':'"),
    (GOOD_A, '["-1 g"]', "positive"),
    (GOOD_A, '["1 mm"]', "drawer"),
    (GOOD_A, '["1 g", "1 g:2"]', "a mass twice"),
    (GOOD_A, '[[1]]', "drawer must be a value"),
    (GOOD_A, '["nan g"]', "drawer"),
    ("holes: {count: 8}, max_mass: '5 g*mm'", '["1 g"]', ""),  # read: a mass x radius limit
]


@pytest.mark.parametrize("plane, drawer, says", BAD_JOBS, ids=lambda v: str(v)[:30])
def test_bad_holes_limits_and_drawers_are_located(tmp_path, plane, drawer, says):
    path = tmp_path / "job.yaml"
    path.write_text(JOB % (plane, drawer))
    try:
        rbcli.field_balance(job=str(path))
    except InputError as exc:
        assert says and says in str(exc), str(exc)
        where = str(exc).split(": ")[0]
        assert where.startswith(str(path)) and where.count(":") >= 1, str(exc)  # file:line
        return
    assert not says, f"accepted: {plane} / {drawer}"


@pytest.mark.parametrize("extra, says", [
    ("sensors: [S1, {name: S2, limit: -2}, S3, S4]", "a limit must be a positive amplitude"),
    ("sensors: [S1, {name: S2, limit: 2 mm/s}, S3, S4]", "is velocity; the readings are bare"),
    ("sensors: [S1, {name: S2, limit: [2]}, S3, S4]", "limit must be a value"),
    ("sensors: [S1, {name: S2, limit: 2 rms}, S3, S4]", "is a bare number rms; the readings are bare numbers with no"),
    ("speeds: [{name: run, limit: 1e400}]", "limit"),
    ("speeds: [{name: run, limit: .nan}]", "limit"),
    ("robust: hubber", "robust must be huber"),
    ("max_weights: 0", "max_weights must be a whole number from 1 to 4"),
], ids=lambda v: str(v)[:30])
def test_bad_limits_are_located(tmp_path, extra, says):
    text = JOB % (GOOD_A, GOOD_DRAWER)
    key = extra.split(":")[0]
    lines = [ln for ln in text.splitlines() if not ln.startswith(key + ":")]
    if key == "speeds":
        lines = [ln.replace('["1@0"', '{run: ["1@0"').replace('"2@90"]', '"2@90"]}')
                 .replace('["4@0", "4@0", "5@0", "1@0"]', '{run: ["4@0", "4@0", "5@0", "1@0"]}')
                 .replace('["1@180", "3@180", "3@180", "2@0"]', '{run: ["1@180", "3@180", "3@180", "2@0"]}')
                 for ln in lines]
    path = tmp_path / "job.yaml"
    path.write_text("\n".join(lines + [extra]) + "\n")
    with pytest.raises(InputError) as e:
        rbcli.field_balance(job=str(path))
    assert says in str(e.value) and str(e.value).startswith(f"{path}:"), str(e.value)


# --------------------------------------------------------------------- coefficient files


@pytest.fixture
def saved(tmp_path):
    """A 4-sensor, 2-speed job's coefficients file and the trim run's readings."""
    path = tmp_path / "fan.json"
    path.write_text(json.dumps(rbcli.field_balance(job="examples/jobs/fan.yaml").coefficients_document()))
    return path


TRIM = ("4.41 mm/s@78,3.48 mm/s@163,2.86 mm/s@136,2.45 mm/s@225,7.47 mm/s@68,5.65 mm/s@149,"
        "4.75 mm/s@121,3.95 mm/s@212")


def _edit(doc: dict, how: str) -> dict:
    from rbcli.io.field.coefficients import fingerprint

    if how == "permute":  # rows and their coefficients moved together, fingerprint renewed
        order = [4, 5, 6, 7, 0, 1, 2, 3]
        doc["rows"] = [doc["rows"][k] for k in order]
        doc["coefficients"] = [doc["coefficients"][k] for k in order]
    elif how == "duplicate":
        doc["rows"][1] = doc["rows"][0]
    elif how == "conventions-list":
        doc["conventions"] = ["lag"]
    elif how == "conventions-text":
        doc["conventions"] = "lag"
    elif how == "huge-int":
        doc["coefficients"][0][0]["re"] = 10 ** 400
    elif how == "sensors-renamed":  # consistently: the sensors and the rows
        doc["sensors"][0] = "X"
        doc["rows"] = [dict(r, sensor="X" if r["sensor"] == "NDE-H" else r["sensor"]) for r in doc["rows"]]
    elif how == "planes-renamed":
        doc["planes"][0]["name"] = "Z"
    elif how == "speed-changed":
        doc["speeds"][0]["speed"] = 1.0
    if how != "edited":
        doc["fingerprint"] = fingerprint(doc)
    else:
        doc["coefficients"][0][0]["re"] *= 2
    return doc


TRIM_JOB = ("sensors: [NDE-H, NDE-V, DE-H, DE-V]\nplanes: [{name: A}, {name: B}]\n"
            "speeds: [{name: low, speed: 1180 rpm}, {name: run, speed: 1480 rpm}]\n"
            "conventions: {phase: lag, angle_sense: against, rotation: cw}\n"
            "readings: {measure: rms}\ncoefficients: %s\ninitial:\n"
            "  low: [4.41 mm/s@78, 3.48 mm/s@163, 2.86 mm/s@136, 2.45 mm/s@225]\n"
            "  run: [7.47 mm/s@68, 5.65 mm/s@149, 4.75 mm/s@121, 3.95 mm/s@212]\n")


@pytest.mark.parametrize("how, says", [
    ("edited", "does not match its fingerprint"),
    ("permute", "row 1 is sensor 'NDE-H' at speed 'run' where sensor 'NDE-H' at speed 'low' belongs"),
    ("duplicate", "row 2 is sensor 'NDE-H'"),
    ("conventions-list", "conventions must be objects"),
    ("conventions-text", "conventions must be objects"),
    ("huge-int", "re must be a finite number"),
    ("sensors-renamed", "is for sensors X, NDE-V"),
    ("planes-renamed", "is for planes Z, B"),
    ("speed-changed", "influence coefficients change with speed"),
])
def test_coefficient_files_that_do_not_fit_are_refused_never_reordered(saved, tmp_path, how, says):
    path = tmp_path / "edited.json"
    path.write_text(json.dumps(_edit(json.loads(saved.read_text()), how)))
    job = tmp_path / "trim.yaml"
    job.write_text(TRIM_JOB % path)
    with pytest.raises(InputError) as e:
        if how in ("planes-renamed", "speed-changed", "sensors-renamed"):
            rbcli.field_balance(job=str(job))
        else:
            rbcli.field_balance(coefficients=str(path), initial=TRIM)
    assert says in str(e.value), str(e.value)


def test_the_unedited_file_trims_the_job_exactly(saved, tmp_path):
    job = tmp_path / "trim.yaml"
    job.write_text(TRIM_JOB % saved)
    a = rbcli.field_balance(job="examples/jobs/fan.yaml")
    for b in (rbcli.field_balance(job=str(job)), rbcli.field_balance(coefficients=str(saved), initial=TRIM)):
        assert [c.correction for c in b.corrections] == [c.correction for c in a.corrections]


# --------------------------------------------------------------------- job-file messages, big jobs


@pytest.mark.parametrize("text, says", [
    ("sensors: [S1, S2, S3]\nplanes: [{name: A}, {name: B}]\ninitial: ['1@0', '1@180', '0@0']\ntrials:\n"
     "  - {plane: A, mass: '1@0', readings: ['2@0', '2@180', '1@0']}\n"
     "  - {plane: B, mass: '1@0', readings: ['2@0', '2@180', '1@0']}\n", ":4:1: a trial run: the influence matrix is singular"),
    ("initial: ['1@0', '1@180', '0@0']\ntrials:\n  - {mass: '1@0', readings: ['4@0', '4@0', '5@0']}\n"
     "  - {mass: '1@0', readings: ['1@180', '3@180', '3@180']}\nmethod: exact\n", ":5:1: method: an exact solve needs"),
    ("initial: ['1@0', '1@180', '0@0']\ntrials:\n  - {mass: '1@0', readings: ['4@0', '4@0', '5@0']}\n"
     "severity: {group: 1, foundation: rigid}\n", ":4:1: severity: the ISO 20816-3 zones judge velocities"),
    ("initial: ['1e-320@0', '1@180']\ntrials:\n  - {mass: '1@0', readings: ['4@0', '4@0']}\n",
     "initial: '1e-320@0': the amplitude must be 0 or from 1e-100"),
    ("initial: ['1@0']\ntrials:\n  - {mass: '1@0', readings: ['4@0']}\nrotor: {body: job.yaml}\n",
     "rotor: body is the job file itself"),
    ("initial: ['1@0']\ntrials:\n  - {mass: '1@0', readings: ['4@0']}\nrotor: {body: nope.yaml}\n",
     ":4:8: rotor: body: no such file"),
    ("initial: ['1@0']\ntrials:\n  - {mass: '1@0', readings: ['4@0']}\nrotor: {body: /dev/zero}\n",
     ":4:8: rotor: body: /dev/zero: is a device"),
    ("initial: ['1@0']\ntrials:\n  - {mass: '1@0', readings: ['4@0']}\nrotor: {body: .}\n", ":4:8: rotor: body:"),
], ids=lambda v: str(v)[-30:])
def test_job_file_problems_are_located_in_the_job_file(tmp_path, cli, text, says):
    path = tmp_path / "job.yaml"
    path.write_text(text)
    r = cli("field-balance", str(path))
    assert r.code == 2 and r.err.startswith(f"rbcli: {path}") and says in r.err, r.err
    assert "--" not in r.err  # never an option that was not given


def test_a_job_beyond_the_budget_is_refused_naming_its_variable(cli):
    r = cli("field-balance", "--initial", "1@0,1@180,0@0", "--trial", "1@0", "--run", "4@0,4@0,5@0", "--trial",
            "1@0", "--run", "1@180,3@180,3@180", env={"RBCLI_MAX_FIELD_COEFFICIENTS": "5"})
    assert r.code == 2 and "3 readings per run x 2 planes = 6 influence coefficients, above the limit of 5" in r.err
    assert "RBCLI_MAX_FIELD_COEFFICIENTS" in r.err and len(r.err.splitlines()) == 1


@pytest.mark.slow
@pytest.mark.parametrize("p", [80, 120])
def test_large_square_jobs_are_computed_not_refused(tmp_path, p):
    """80 x 80 and 120 x 120 were refused as "the result overflows": only |det| overflowed
    (now null in the JSON)."""
    import numpy as np

    rng = np.random.default_rng(p)
    A = rng.normal(size=(p, p)) + 1j * rng.normal(size=(p, p))
    v0 = A @ (rng.normal(size=p) + 1j * rng.normal(size=p))
    fmt = lambda z: f"'{abs(z):.9g}@{np.degrees(np.angle(z)) % 360:.9g}'"  # noqa: E731
    lines = ["initial: [" + ", ".join(fmt(z) for z in v0) + "]", "trials:"]
    lines += [f"  - {{mass: '1 g@0', readings: [{', '.join(fmt(z) for z in v0 + A[:, j])}]}}" for j in range(p)]
    (tmp_path / "big.yaml").write_text("\n".join(lines) + "\n")
    res = rbcli.field_balance(job=str(tmp_path / "big.yaml"))
    assert json.dumps(res.to_json(), allow_nan=False) and res.to_json()["det_magnitude"] is None
