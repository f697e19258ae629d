"""Job files of ``rbcli field-balance JOB.yaml`` (rbcli.io.field.jobfile): the format, its schema,
located errors, several speeds stacked into one solve, and the command line as a shorthand.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import rbcli
from rbcli.errors import InputError
from rbcli.io.field.jobfile import PLANE_KEYS, TOP_KEYS, load_job, load_job_text, schema_text

ROOT = Path(__file__).resolve().parent.parent
FAN = ROOT / "examples" / "jobs" / "fan.yaml"

ONE = """
sensors: [S1, S2, S3]
planes: [{name: A}, {name: B}]
initial: ["1@0", "1@180", "0@0"]
trials:
  - {plane: A, mass: "1@0", readings: ["4@0", "4@0", "5@0"]}
  - {plane: B, mass: "1@0", readings: ["1@180", "3@180", "3@180"]}
"""


def job_schema() -> dict:
    return json.loads(schema_text())


def test_the_schema_declares_the_keys_the_loader_reads():
    """The loader's keys are the schema's: a key the schema has is read, one it lacks refused."""
    assert TOP_KEYS == tuple(job_schema()["properties"]) and "drawer" in TOP_KEYS and "holes" in PLANE_KEYS
    with pytest.raises(InputError, match="unknown key 'drawers'.*did you mean 'drawer'"):
        load_job_text(ONE + "drawers: ['1 g']\n")


def test_the_example_job_is_valid_by_the_schema_and_the_loader(cli):
    jsonschema = pytest.importorskip("jsonschema")
    import yaml

    doc = yaml.safe_load(FAN.read_text(encoding="utf-8"))
    jsonschema.Draft7Validator(job_schema()).validate(doc)
    job = load_job(str(FAN))
    assert job.sensors == ("NDE-H", "NDE-V", "DE-H", "DE-V")
    assert [s.name for s in job.speeds] == ["low", "run"]
    assert [p.name for p in job.planes] == ["A", "B"] and job.planes[1].positions == 8
    assert job.planes[0].radius == pytest.approx(0.25)  # 250 in the file's mm
    r = cli("field-balance", "--job-schema")
    assert r.code == 0 and json.loads(r.out) == job_schema()


def test_the_command_line_is_a_one_speed_job(tmp_path):
    """The job file above and the same readings on the command line give the same answer."""
    path = tmp_path / "job.yaml"
    path.write_text(ONE)
    a = rbcli.field_balance(job=str(path))
    b = rbcli.field_balance(initial="1@0,1@180,0@0", trial=["1@0", "1@0"],
                            run=["4@0,4@0,5@0", "1@180,3@180,3@180"])
    assert [c.correction for c in a.corrections] == [c.correction for c in b.corrections]
    assert a.sensors == ("S1", "S2", "S3") and b.sensors == ("1", "2", "3")
    # Goodman's example: 17/21 and 31/21 (of a gram: bare trial masses are grams)
    assert [c.mass * 1e3 for c in a.corrections] == pytest.approx([17 / 21, 31 / 21], rel=1e-13)


def test_several_speeds_stack_into_one_solve():
    """The example job: 4 sensors x 2 speeds = 8 readings, stacked speed by speed; the
    answer is numpy's least squares of the stacked system."""
    r = rbcli.field_balance(job=str(FAN))
    job = load_job(str(FAN))
    assert len(r.initial) == 8 and r.method == "least-squares"
    assert r.row_names()[:2] == [("NDE-H", "low"), ("NDE-V", "low")] and r.row_names()[4] == ("NDE-H", "run")
    alpha = np.array(r.alpha)
    V0 = np.array(r.initial)
    ref = np.linalg.lstsq(alpha, -V0, rcond=None)[0]
    # same problem, two backward-stable solvers: ~cond * eps
    np.testing.assert_allclose([c.correction for c in r.corrections], ref, rtol=1e-12)
    # the readings were made from 30 g @ 200 and 20 g @ 70 with 1 % and 1 deg noise: the
    # correction is about the opposite (within the noise)
    a, b = r.corrections
    assert a.mass * 1e3 == pytest.approx(30, rel=0.05) and a.angle_deg == pytest.approx(20, abs=3)
    assert b.mass * 1e3 == pytest.approx(20, rel=0.08) and b.angle_deg == pytest.approx(250, abs=5)
    # one speed alone is a different (4 x 2) problem with its own answer
    assert job.speeds[1].speed == pytest.approx(1480 * np.pi / 30)


BAD = [
    ("sensors: [a]\nplanes: [{name: A}]\ninitial: ['1@0']\ntrials: [{plane: A, mass: '1@0', readings: ['2@0']}]\nfoo: 1\n",
     5, 1, "unknown key 'foo' in the job"),
    ("planes: [{name: A}]\ninitial: ['1@0']\ntrials: [{plane: B, mass: '1@0', readings: ['2@0']}]\n",
     3, 18, "no plane is called 'B'"),
    ("planes: [{name: A}]\ninitial: ['1@0', '2@0']\ntrials: [{plane: A, mass: '1@0', readings: ['2@0']}]\n",
     3, 45, "1 readings where the job has 2 sensors"),
    ("planes: [{name: A}]\ninitial: ['1 kg@0']\ntrials: [{plane: A, mass: '1@0', readings: ['2@0']}]\n",
     2, 11, "not a vibration reading"),
    ("planes: [{name: A}]\ninitial: ['1@0']\ntrials: [{plane: A, mass: '1 mm@0', readings: ['2@0']}]\n",
     3, 27, "a trial mass"),
    ("planes: [{name: A}]\ntrials: [{plane: A, mass: '1@0', readings: ['2@0']}]\n", 1, 1, "needs 'initial'"),
    ("method: fastest\nplanes: [{name: A}]\ninitial: ['1@0']\ntrials: [{plane: A, mass: '1@0', readings: ['2@0']}]\n",
     1, 9, "method must be least-squares or min-max or exact"),
    ("speeds: [{name: a, speed: 1000 rpm}, {name: b, speed: 1200 rpm}]\nplanes: [{name: A}]\n"
     "initial: ['1@0']\ntrials: [{plane: A, mass: '1@0', readings: ['2@0']}]\n", 3, 10, "with 2 speeds"),
    ("planes: [{name: A, positions: 2}]\ninitial: ['1@0']\ntrials: [{plane: A, mass: '1@0', readings: ['2@0']}]\n",
     1, 31, "positions must be a whole number"),
    ("initial: ['6 mm/s rms@0', '2 mm/s@0']\ntrials: [{mass: '1@0', readings: ['2 mm/s rms@0', '3 mm/s rms@0']}]\n",
     1, 27, "says no measure"),
    ("", 1, 1, "the job file is empty"),
    ("a: &x 1\nb: *x\n", 1, 4, "anchor"),
]


@pytest.mark.parametrize("text, line, col, says", BAD)
def test_errors_are_located(cli, tmp_path, text, line, col, says):
    path = tmp_path / "job.yaml"
    path.write_text(text)
    with pytest.raises(InputError) as exc:
        rbcli.field_balance(job=str(path))
    assert says in str(exc.value), str(exc.value)
    assert exc.value.where is not None and exc.value.where.file == str(path)
    assert (exc.value.where.line, exc.value.where.col) == (line, col), str(exc.value)
    r = cli("field-balance", str(path))
    assert r.code == 2 and r.err.startswith(f"rbcli: {path}:{line}:{col}: ") and r.err.count("\n") == 1, r.err


def test_a_setting_given_twice_is_refused(cli):
    r = cli("field-balance", str(FAN), "--method", "min-max")
    assert r.code == 2 and r.err.startswith("rbcli: --method: given twice") and "fan.yaml:" in r.err
    r = cli("field-balance", str(FAN), "--initial", "1@0")
    assert r.code == 2 and r.err.startswith("rbcli: --initial: the job file holds the readings")
    # a setting the job leaves open is taken from the command line
    r = cli("field-balance", str(FAN), "--angle-step", "5", "--json")
    assert r.code == 0 and r.json()["fitted"]["angle_step_deg"] == 5.0


def test_relative_paths_in_a_job_file_are_the_job_files(tmp_path):
    (tmp_path / "sub").mkdir()
    job = tmp_path / "sub" / "job.yaml"
    job.write_text(ONE + "rotor: {body: rotor.yaml}\n")
    j = load_job_text(job.read_text(), str(job))
    assert j.rotor is not None and j.rotor.body == str(tmp_path / "sub" / "rotor.yaml")


from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

_KEYS = ["rbcli", "job", "name", "units", "conventions", "readings", "sensors", "planes", "speeds",
         "initial", "trials", "cumulative", "method", "mass_step", "angle_step", "severity", "rotor",
         "coefficients", "plane", "mass", "radius", "positions", "speed", "low", "run", "A"]
_VALUES = st.recursive(
    st.one_of(st.sampled_from(["1@0", "6 mm/s rms@30", "10 g@0", "x@y", "1e999@0", "-1@0", "lag", "rms",
                               "least-squares", "A", "", "1480 rpm", "nan", "0"]),
              st.integers(-5, 10), st.floats(allow_nan=True), st.booleans(), st.none()),
    lambda inner: st.one_of(st.lists(inner, max_size=4),
                            st.dictionaries(st.sampled_from(_KEYS), inner, max_size=4)),
    max_leaves=12)


@given(st.dictionaries(st.sampled_from(_KEYS), _VALUES, max_size=8))
@settings(max_examples=150, deadline=None)
def test_any_job_document_loads_or_is_one_located_error(doc):
    """Whatever the structure: a result, or an InputError at a place in the file (or naming
    a value); never another exception."""
    import os
    import tempfile

    import yaml

    text = yaml.safe_dump(doc)
    try:
        load_job_text(text, "job.yaml")
    except InputError as exc:
        assert exc.where is not None and exc.where.file == "job.yaml" and "\n" not in str(exc)
        return
    fd, path = tempfile.mkstemp(suffix=".yaml")
    try:
        with os.fdopen(fd, "w") as fh:
            fh.write(text)
        try:
            rbcli.field_balance(job=path)
        except InputError as exc:
            assert "\n" not in str(exc)
    finally:
        os.unlink(path)
