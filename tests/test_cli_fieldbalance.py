"""``rbcli field-balance`` end to end: the Python API is the command, classic jobs keep their
output, stored coefficients reproduce a job, conventions, measures, units, severity, trial
sizing, the job sheet, and one-line errors.
"""

from __future__ import annotations

import cmath
import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rbcli
from rbcli.errors import InputError, option_name

ROOT = Path(__file__).resolve().parent.parent
FAN = "examples/jobs/fan.yaml"

BK = ["--initial", "170@112,53@78", "--trial", "1.15 g@0", "--run", "235@94,58@68",
      "--trial", "1.15 g@0", "--run", "185@115,77@104"]
ONE = ["--initial", "6.0@30", "--trial", "10 g@0", "--run", "4.0@110"]
GOODMAN = ["--initial", "1@0,1@180,0@0", "--trial", "1@0", "--run", "4@0,4@0,5@0",
           "--trial", "1@0", "--run", "1@180,3@180,3@180"]


def P(m: float, d: float) -> complex:
    return complex(cmath.rect(m, math.radians(d)))


def run_json(cli, *args: str) -> dict:
    r = cli("field-balance", *args, "--json")
    assert r.code == 0, r.err
    return r.json()


def masses(d: dict) -> list[tuple[float, float]]:
    return [(c["mass"], c["angle_deg"]) for c in d["corrections"]]


# ------------------------------------------------------------------ the API is the command


@pytest.mark.parametrize("args, kwargs", [
    (GOODMAN, dict(initial="1@0,1@180,0@0", trial=["1@0", "1@0"], run=["4@0,4@0,5@0", "1@180,3@180,3@180"])),
    (GOODMAN + ["--method", "min-max", "--weights", "1,2,1"],
     dict(initial="1@0,1@180,0@0", trial=["1@0", "1@0"], run=["4@0,4@0,5@0", "1@180,3@180,3@180"],
          method="min-max", weights="1,2,1")),
    ([FAN], dict(job=FAN)),
    ([FAN, "--angle-step", "10"], dict(job=FAN, angle_step="10")),
    (ONE + ["--phase", "lag", "--angle-sense", "with", "--rotation", "cw", "--mass-step", "0.5 g"],
     dict(initial="6.0@30", trial="10 g@0", run="4.0@110", phase="lag", angle_sense="with",
          rotation="cw", mass_step="0.5 g")),
    (["--suggest-trial", "--rotor-mass", "120 kg", "--speed", "1480 rpm", "--trial-radius", "250 mm"],
     dict(suggest_trial=True, rotor_mass="120 kg", speed="1480 rpm", trial_radius="250 mm")),
])
def test_api_equals_command(cli, args, kwargs):
    r = cli("field-balance", *args, "--json")
    assert r.code == 0, r.err
    res = rbcli.field_balance(**kwargs)
    assert res.to_json() == r.json()
    assert [ln.removeprefix("rbcli: warning: ") for ln in r.err.splitlines()] == list(res.warnings)


def test_result_values_are_frozen_and_named_as_json():
    import dataclasses

    r = rbcli.field_balance(job=FAN)
    d = r.to_json()
    assert [x.to_json() for x in r.residuals] == d["residuals"]
    assert r.severity.to_json() == d["severity"] and r.fitted.to_json() == d["fitted"]
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.method = "x"  # type: ignore[misc]


# ------------------------------------------------------------------ classic jobs


def test_classic_jobs_keep_their_output(cli, tmp_path):
    """Saving the coefficients of a one- or two-plane job changes nothing it prints."""
    for args in (BK, ONE):
        plain = cli("field-balance", *args)
        saved = cli("field-balance", *args, "--save-coefficients", str(tmp_path / "c.json"), "--force")
        assert saved.code == 0 and saved.out == plain.out and saved.err == plain.err
        pj = cli("field-balance", *args, "--json").json()
        sj = cli("field-balance", *args, "--json", "--save-coefficients", str(tmp_path / "c.json"), "--force").json()
        assert sj.pop("saved_coefficients") == str(tmp_path / "c.json") and sj == pj
        assert "method" not in pj and "residuals" not in pj


def test_extended_square_job_is_the_classic_solve(cli):
    """A two-plane job with an extended option: the same corrections, bit for bit."""
    classic = run_json(cli, *BK)
    ext = run_json(cli, *BK, "--method", "least-squares")
    assert ext["method"] == "exact" and masses(ext) == masses(classic)
    assert [r["amplitude"] for r in ext["residuals"]] == classic["predicted_residual"]


# ------------------------------------------------------------------ stored coefficients


@pytest.mark.parametrize("first, trim", [
    (ONE, ["--initial", "6.0@30"]),
    (BK, ["--initial", "170@112,53@78"]),
    (GOODMAN, ["--initial", "1@0,1@180,0@0"]),
    (GOODMAN + ["--method", "min-max"], ["--initial", "1@0,1@180,0@0", "--method", "min-max"]),
    ([FAN], [FAN.replace("fan.yaml", "fan.yaml")]),
])
def test_a_trim_run_from_saved_coefficients_reproduces_the_job(cli, tmp_path, first, trim):
    coeffs = tmp_path / "coeffs.json"
    a = run_json(cli, *first, "--save-coefficients", str(coeffs))
    doc = json.loads(coeffs.read_text())
    assert doc["format"] == "rbcli field-balance influence coefficients" and doc["version"] == 2
    if trim == [FAN]:
        # the same job's initial readings, on the command line, in the file's row order
        import yaml

        job = yaml.safe_load((ROOT / FAN).read_text())
        trim = ["--initial", ",".join(job["initial"]["low"] + job["initial"]["run"])]
    b = run_json(cli, "--coefficients", str(coeffs), *trim)
    # exactly the same correction: the same coefficients (re, im read back bit for bit) and
    # the same readings go through the same solve
    assert masses(b) == masses(a)
    assert b["coefficients_from"] == str(coeffs) and b["trials"] == []


def test_saved_coefficients_say_their_units_and_conventions(cli, tmp_path):
    coeffs = tmp_path / "fan.json"
    run_json(cli, FAN, "--save-coefficients", str(coeffs))
    doc = json.loads(coeffs.read_text())
    assert doc["influence"] == {"reading_kind": "velocity", "reading_unit": "m/s", "measure": "rms",
                                "per": "kg of trial mass at the plane's trial radius"}
    assert (doc["conventions"]["phase"], doc["conventions"]["angle_sense"]) == ("lag", "against")
    assert doc["sensors"] == ["NDE-H", "NDE-V", "DE-H", "DE-V"]
    assert [s["name"] for s in doc["speeds"]] == ["low", "run"]
    assert doc["speeds"][1]["speed"] == pytest.approx(1480 * math.pi / 30)
    assert doc["planes"] == [{"name": "A", "trial_radius": 0.25}, {"name": "B", "trial_radius": 0.25}]
    assert len(doc["rows"]) == len(doc["coefficients"]) == 8
    c = doc["coefficients"][0][0]
    assert abs(complex(c["re"], c["im"])) == pytest.approx(c["magnitude"], rel=1e-15)


@pytest.mark.parametrize("args, says", [
    (["--initial", "6@30,1@0"], "holds 1 readings per run"),
    (["--initial", "6 mm/s@30"], "coefficients for bare readings"),
    (["--initial", "6@30", "--trial", "1 g@0", "--run", "4@0"], "--trial: a trim run"),
    (["--initial", "6@30", "--trial-radius", "1"], "--trial-radius: the coefficients file has"),
])
def test_coefficients_that_do_not_fit_are_refused(cli, tmp_path, args, says):
    coeffs = tmp_path / "c.json"
    run_json(cli, *ONE, "--save-coefficients", str(coeffs))
    r = cli("field-balance", "--coefficients", str(coeffs), *args)
    assert r.code == 2 and says in r.err and r.err.count("\n") == 1, r.err


def test_a_file_that_is_not_coefficients_is_refused(cli, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "something else"}')
    r = cli("field-balance", "--coefficients", str(bad), "--initial", "6@30")
    assert r.code == 2 and "not a coefficients file" in r.err
    bad.write_text("{\n  oops")
    r = cli("field-balance", "--coefficients", str(bad), "--initial", "6@30")
    assert r.code == 2 and r.err.startswith(f"rbcli: {bad}:2:3: invalid JSON")


def test_save_coefficients_never_over_an_input(cli, tmp_path):
    r = cli("field-balance", FAN, "--save-coefficients", FAN)
    assert r.code == 2 and "--save-coefficients" in r.err and "input" in r.err
    target = tmp_path / "c.json"
    target.write_text("{}")
    r = cli("field-balance", *ONE, "--save-coefficients", str(target))
    assert r.code == 2 and "exists; use --force" in r.err and target.read_text() == "{}"


# ------------------------------------------------------------------ conventions and readings


def test_phase_lag_with_angles_with_rotation_mirrors_the_phases(cli):
    """Phase lag grows against the rotation: with trial angles counted with it, the phases are
    mirrored. The same job written with mirrored phases and no conventions is the oracle."""
    conv = run_json(cli, *T21_ARGS, "--phase", "lag", "--angle-sense", "with")
    mirrored = [a if "@" not in a or " g@" in a else
                ",".join(f"{p.split('@')[0]}@{-float(p.split('@')[1])!r}" for p in a.split(","))
                for a in T21_ARGS]
    plain = run_json(cli, *mirrored, "--method", "exact")
    assert masses(conv) == masses(plain)
    assert conv["conventions"]["converted"] is True
    # the predicted readings are shown in the instrument's own convention again
    assert conv["residuals"][0]["angle_deg"] == pytest.approx((-plain["residuals"][0]["angle_deg"]) % 360, abs=1e-9)
    # lag with angles against the rotation: one sense, nothing mirrored
    same = run_json(cli, *T21_ARGS, "--phase", "lag", "--angle-sense", "against")
    assert same["conventions"]["converted"] is False and masses(same) == masses(run_json(cli, *T21_ARGS, "--method", "exact"))
    r = cli("field-balance", *T21_ARGS, "--phase", "lag")
    assert r.code == 2 and r.err.startswith("rbcli: --angle-sense: say how")


T21_ARGS = ["--initial", "21.6076@49.52,12.0102@299.16", "--trial", "5 g@0", "--run",
            "31.5134@46.51,12.6512@310.41", "--trial", "5 g@0", "--run", "24.4405@51.98,12.1788@342.84"]


def test_measures_are_converted_or_refused(cli):
    rms = run_json(cli, "--initial", "6 mm/s rms@30", "--trial", "10 g@0", "--run", "4 mm/s rms@110")
    # the same job with the run's reading written as peak (x sqrt 2) and as peak-to-peak
    pk = run_json(cli, "--initial", "6 mm/s rms@30", "--trial", "10 g@0",
                  "--run", f"{4 * math.sqrt(2)!r} mm/s pk@110")
    pp = run_json(cli, "--initial", "6 mm/s rms@30", "--trial", "10 g@0",
                  "--run", f"{8 * math.sqrt(2)!r} mm/s pk-pk@110")
    for d in (pk, pp):
        assert d["readings"]["measure"] == "rms" and d["readings"]["converted"][0]["to"] == "rms"
        # sqrt 2 written to 17 digits and multiplied back: a few ulp
        assert d["corrections"][0]["mass"] == pytest.approx(rms["corrections"][0]["mass"], rel=1e-14)
    r = cli("field-balance", "--initial", "6 mm/s rms@30", "--trial", "10 g@0", "--run", "4 mm/s@110")
    assert r.code == 2 and r.err.startswith("rbcli: --measure: '6 mm/s rms@30' (--initial) says rms but")
    ok = run_json(cli, "--initial", "6 mm/s rms@30", "--trial", "10 g@0", "--run", "4 mm/s@110", "--measure", "rms")
    assert ok["corrections"] == rms["corrections"]


def test_g_is_gravity_in_a_reading_and_gram_in_a_mass(cli):
    d = run_json(cli, "--initial", "0.5 g@30", "--trial", "10 g@0", "--run", "0.3 g@110")
    assert d["readings"]["kind"] == "acceleration" and d["readings"]["g"].startswith("standard gravity")
    assert d["trials"][0]["mass"] == 0.01  # 10 grams
    # 0.5 g = 4.903325 m/s^2 exactly
    assert d["residuals"][0]["initial"] == pytest.approx(0.5 * 9.80665, rel=1e-15)
    text = cli("field-balance", "--initial", "0.5 g@30", "--trial", "10 g@0", "--run", "0.3 g@110").out
    assert "'g' in a reading read as standard gravity" in " ".join(text.split())


def test_units_in_show_mil_and_inches_per_second(cli):
    """Issue 24: --units in,oz shows mil readings in mil, not µm."""
    out = cli("field-balance", "--initial", "2 mil@30", "--trial", "1 oz@0", "--run", "1.5 mil@110",
              "--units", "in,oz").out
    assert "shown in mil" in out and "mil per oz" in out and "µm" not in out and "mass [oz]" in out
    # the coefficient: |1.5 mil e^{i110} - 2 mil e^{i30}| / 1 oz, in mil per oz
    want = abs(P(1.5, 110) - P(2, 30))
    assert f"{want:.6g}" in out
    out = cli("field-balance", "--initial", "0.2 in/s@30", "--trial", "1 oz@0", "--run", "0.1 in/s@110",
              "--units", "in,oz", "--measure", "pk").out
    assert "in/s" in out and "mm/s" not in out


# ------------------------------------------------------------------ fitting, severity, trial


def test_fitted_masses_and_the_readings_they_leave(cli):
    d = run_json(cli, FAN)
    f = d["fitted"]
    a, b = f["planes"]
    assert a["masses"][0]["mass"] == pytest.approx(round(d["corrections"][0]["mass"] * 1e3) * 1e-3)
    assert [m["position"] for m in b["masses"]] == [6, 7] and b["positions"] == 8
    # the prediction: V0 + alpha W_fitted, written out here from the JSON's own numbers
    alpha = np.array([[P(x["magnitude"], x["angle_deg"]) for x in row] for row in d["influence"]])
    init = rbcli.field_balance(job=FAN).initial
    W = [sum(P(m["mass"], m["angle_deg"]) for m in p["masses"]) for p in f["planes"]]
    pred = np.array(init) + alpha @ W
    # alpha from magnitude/angle: ~1e-15 relative; the readings ~1e-3 m/s
    np.testing.assert_allclose([r["amplitude"] for r in f["residuals"]], np.abs(pred), rtol=1e-12)


def test_severity_zones_before_and_after(cli):
    d = run_json(cli, FAN)
    s = d["severity"]
    assert (s["group"], s["foundation"], s["after_is"]) == (2, "rigid", "fitted")
    assert s["boundaries"] == pytest.approx([1.4e-3, 2.8e-3, 4.5e-3])
    rows = s["readings"]
    # the readings as typed, mm/s rms, judged against 1.4 / 2.8 / 4.5
    assert [r["before_zone"] for r in rows] == ["C", "C", "C", "B", "D", "D", "D", "C"]
    assert rows[0]["before"] == pytest.approx(4.41e-3) and all(r["after_zone"] == "A" for r in rows)
    # displacement readings are judged at the speed: v = omega x (an rms of 20 um at 1480 rpm
    # is 3.1 mm/s)
    d2 = run_json(cli, "--initial", "20 um rms@30", "--trial", "10 g@0", "--run", "15 um rms@110",
                  "--severity", "iso20816-3", "--group", "1", "--foundation", "flexible", "--speed", "1480 rpm")
    row = d2["severity"]["readings"][0]
    assert row["before"] == pytest.approx(20e-6 * 1480 * math.pi / 30, rel=1e-14) and row["before_zone"] == "A"


@pytest.mark.parametrize("args, says", [
    (["--severity", "iso20816-3", "--group", "2", "--foundation", "rigid"], "--severity: the ISO 20816-3 zones judge velocities"),
    (["--severity", "iso20816-3", "--group", "3", "--foundation", "rigid"], "--group: must be 1"),
    (["--severity", "iso20816-3"], "--severity: needs the machine --group"),
    (["--group", "2"], "--severity: --group and --foundation go with --severity"),
])
def test_severity_refused_with_the_reason(cli, args, says):
    r = cli("field-balance", *ONE, *args)
    assert r.code == 2 and r.err.startswith(f"rbcli: {says}"), r.err
    r = cli("field-balance", "--initial", "6 mm/s@30", "--trial", "10 g@0", "--run", "4 mm/s@110",
            "--severity", "iso20816-3", "--group", "2", "--foundation", "rigid")
    assert r.code == 2 and r.err.startswith("rbcli: --measure: the ISO 20816-3 zones are in r.m.s.")


def test_trial_suggestion(cli):
    d = run_json(cli, "--suggest-trial", "--rotor-mass", "120 kg", "--speed", "1480 rpm", "--trial-radius", "250 mm")
    (s,) = d["suggested_trial"]
    w = 1480 * math.pi / 30
    # 10 % of half the rotor's weight, m = 0.1 (M g / 2) / (r w^2): a handful of operations
    assert s["mass"] == pytest.approx(0.1 * 120 * 9.80665 / 2 / (0.25 * w * w), rel=1e-14)
    assert s["force"] == pytest.approx(0.1 * 120 * 9.80665 / 2, rel=1e-14)
    # the job's rotor: bearings at 0 and 800 mm, com at 400: half each; with its coefficients
    # the change each reading should show is predicted, |alpha_kj| m_T
    j = run_json(cli, FAN, "--suggest-trial")
    a = j["suggested_trial"][0]
    assert a["bearing_load"] == pytest.approx(60 * 9.80665) and "lever rule" in a["bearing_load_from"]
    assert a["expected_change"][0] == pytest.approx(j["influence"][0][0]["magnitude"] * a["mass"], rel=1e-14)
    r = cli("field-balance", "--suggest-trial", "--rotor-mass", "120 kg", "--trial-radius", "0.25")
    assert r.code == 2 and r.err.startswith("rbcli: --speed: the trial mass needs the balancing speed")


# ------------------------------------------------------------------ sheet and plot


def test_job_sheet_html_and_markdown(cli, tmp_path):
    html = tmp_path / "sheet.html"
    r = cli("field-balance", FAN, "--report", str(html), env={"SOURCE_DATE_EPOCH": "1767225600"})
    assert r.code == 0, r.err
    text = html.read_text()
    for title in ("Readings", "Polar diagram", "Influence coefficients", "Corrections", "Predicted readings",
                  "Severity (ISO 20816-3)"):
        assert f"<h2>{title}</h2>" in text
    assert text.count("<svg") == 1 and "2026-01-01" in text and "ID fan 3" in text
    assert "masses to fit" in text and "zones of the 1× readings" in text and "trial masses" in text
    # the same job gives the same bytes (SOURCE_DATE_EPOCH)
    again = tmp_path / "again.html"
    cli("field-balance", FAN, "--report", str(again), env={"SOURCE_DATE_EPOCH": "1767225600"})
    assert again.read_bytes() == html.read_bytes()
    md = tmp_path / "sheet.md"
    assert cli("field-balance", *BK, "--report", str(md)).code == 0
    assert (tmp_path / "sheet_files" / "polar-polar.svg").is_file() and "## Corrections" in md.read_text()
    r = cli("field-balance", FAN, "--report", str(html))
    assert r.code == 2 and "exists; use --force" in r.err
    r = cli("field-balance", FAN, "--report", str(tmp_path / "x.pdf"))
    assert r.code == 2 and r.err.startswith("rbcli: --report: cannot tell the format")


def test_polar_diagram_of_a_multi_sensor_job(cli, tmp_path):
    path = tmp_path / "fan.svg"
    assert cli("field-balance", FAN, "--plot", str(path)).code == 0
    import xml.etree.ElementTree as ET

    assert ET.parse(path).getroot().tag.endswith("svg")
    from rbcli.render.field.plot import _sense, plot
    from rbcli.render.units import ShopUnits

    res = rbcli.field_balance(job=FAN)
    fig = plot(res, ShopUnits(None), (1e-3, "mm/s"))
    titles = [ax.get_title() for ax in fig.axes]
    assert titles[:2] == ["reading NDE-H at low [mm/s]", "reading NDE-V at low [mm/s]"] and len(titles) == 10
    assert titles[8:] == ["plane A: masses [g]", "plane B: masses [g]"]
    assert all(ax.get_legend() is not None for ax in fig.axes)  # a legend per dial
    assert _sense(res) == 1  # angles against a clockwise rotation run counterclockwise


# ------------------------------------------------------------------ errors


@pytest.mark.parametrize("args, says", [
    (["--initial", "6@30", "--trial", "10 g@0", "--run", "4@110,1@0"], "--run: expected 1 reading"),
    (["--initial", "6@30", "--trial", "1 g@0", "--run", "2@0", "--trial", "1 g@0", "--run", "3@0"],
     "--initial: 2 planes need at least 2 readings"),
    (ONE + ["--method", "fastest"], "--method: must be least-squares, min-max or exact"),
    (GOODMAN + ["--weights", "1,2"], "--weights: give one weight per reading (3)"),
    (GOODMAN + ["--weights", "1,0,1"], "--weights: weights must be positive"),
    (ONE + ["--positions", "2"], "--positions: must be a whole number from 3"),
    (GOODMAN + ["--method", "exact"], "--method: an exact solve needs as many readings as planes"),
    (["--initial", "6@30"], "--trial: required"),
    (["--trial", "1 g@0", "--run", "1@0"], "Missing option '--initial'"),
])
def test_bad_input_is_one_line(cli, args, says):
    r = cli("field-balance", *args)
    assert r.code == 2 and r.out == "" and r.err.count("\n") == 1 and says in r.err, r.err


@pytest.mark.parametrize("kwargs, param", [
    (dict(initial="6@30", trial="10 g@0", run="4@110", method="fastest"), "method"),
    (dict(initial="1@0,1@180,0@0", trial=["1@0", "1@0"], run=["4@0,4@0,5@0", "1@180,3@180,3@180"],
          weights="1,2"), "weights"),
    (dict(initial="6@30", trial="10 g@0", run="4@110", phase="lag"), "angle_sense"),
])
def test_api_errors_are_the_command_lines(cli, kwargs, param):
    with pytest.raises(InputError) as exc:
        rbcli.field_balance(**kwargs)
    assert exc.value.param == param and "--" not in str(exc.value)
    args = []
    for k, v in kwargs.items():
        for x in ([v] if isinstance(v, str) else v):
            args += [f"--{k.replace('_', '-')}", x]
    r = cli("field-balance", *args)
    assert r.code == 2 and r.err == f"rbcli: {exc.value.spelled(option_name)}\n"


amp = st.floats(min_value=1e-6, max_value=1e6, allow_nan=False)
ang = st.floats(min_value=-720, max_value=720, allow_nan=False)


@given(st.lists(st.tuples(amp, ang), min_size=9, max_size=9), st.sampled_from(["least-squares", "min-max"]))
@settings(max_examples=25, deadline=None)
def test_any_readings_give_a_result_or_a_one_line_error(readings, method):
    from conftest import run_inprocess

    txt = [f"{a!r}@{p!r}" for a, p in readings]
    r = run_inprocess("field-balance", "--initial", ",".join(txt[:3]), "--trial", "1 g@0", "--run",
                      ",".join(txt[3:6]), "--trial", "1 g@90", "--run", ",".join(txt[6:9]),
                      "--method", method, "--json")
    assert r.code in (0, 2), r.err
    if r.code == 2:
        assert len([ln for ln in r.err.splitlines() if not ln.startswith("rbcli: warning:")]) == 1, r.err


# ------------------------------------------------------------------ the README says what runs


def test_readme_field_balancing_commands_print_what_it_says(cli, tmp_path):
    """Every command of the README's field-balancing section runs and prints the numbers its
    comment gives (the outputs go to a temporary folder)."""
    import re
    import shlex

    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text[text.index("## Field balancing: `rbcli field-balance`"):]
    section = section[:section.index("\n## ", 10)]
    block = section[section.index("```sh") + 5:section.index("```", section.index("```sh") + 5)]
    commands = [ln for ln in block.splitlines() if ln.startswith("rbcli field-balance")]
    want = [["9.79831"], ["9.07998", "36.5937", "6.05332", "116.594"], ["1.97947", "236.17", "1.07051", "121.844", "2.701"],
            [r"A +\| +— +\| +1 \|", r"B +\| +— +\| +1\.8 \|", r"\| +0\.4 \|"],
            ["29.4325", "21.1288", "18.9552", "246.941", r"A +\| +— +\| +21\.1288 \| +29\n", r"B +\| +6 +\| +225 +\| +10\n"],
            ["29.4325", "18.9552"],
            ["25", r"20\.4031", "20.4255", "265.146", r"0\.396521", r"A +\| +1 +\| +15 +\| +20\n",
             r"A +\| +12 +\| +45 +\| +5\n", r"B +\| +7 +\| +270 +\| +20\n", r"B +\| +8 +\| +315 +\| +5\n"],
            [r"A +\| +— +\| +0\.9 \|", r"B +\| +— +\| +1\.64 \|", r"0\.42 ", r"plane A +\| +0\.9 g .*yes +\| +0\.4\n"]]
    assert len(commands) == len(want)
    for line, says in zip(commands, want):
        args = shlex.split(line)[1:]
        args = [str(tmp_path / a) if a in ("sheet.html", "fan.json") else a for a in args]
        r = cli(*args)
        assert r.code == 0, (line, r.err)
        for s in says:
            assert re.search(s, r.out), (line, s)
    assert (tmp_path / "sheet.html").is_file() and (tmp_path / "fan.json").is_file()


def test_darlow_flags_a_classic_two_plane_job_below_the_condition_warning(cli):
    """alpha = [[1, 1], [1, 1 + 0.25i]] per gram: cond 16.19, under the warning at 50, but plane
    A's column is nearly plane B's: Darlow's factor |a_A - proj_B a_A| / |a_A| = 0.123 (by hand:
    the two columns' angle has sin^2 = 1 - |<a,b>|^2/(|a|^2|b|^2) = 1 - (4 + 0.0625)/(2 x 2.0625))."""
    args = ["--initial", "2.23606797749979@26.56505117707799,1.118033988749895@-26.56505117707799",
            "--trial", "1 g@0", "--run", "3.1622776601683795@18.43494882292201,2.0615528128088303@-14.036243467926479",
            "--trial", "1 g@0", "--run", "3.1622776601683795@18.43494882292201,2.0155644370746373@-7.125016348901798"]
    d = run_json(cli, *args)
    assert d["cond"] == pytest.approx(16.188, abs=1e-3) and not d["ill_conditioned"]
    sf = math.sqrt(1 - (4 + 0.0625) / (2 * 2.0625))
    assert sf == pytest.approx(0.12309, abs=1e-5)
    (w,) = d["warnings"]
    assert w.startswith("plane A is ill-conditioned by Darlow's test: its significance factor 0.123 ")
    assert "method" not in d  # still the classic output, with the warning
    r = cli("field-balance", *args)
    assert "rbcli: warning: plane A is ill-conditioned by Darlow's test" in r.err
    assert "Darlow's plane-significance factor of plane A 0.123" in " ".join(r.out.split())


def test_units_everywhere_in_an_extended_job(cli):
    """--units in,oz: masses in oz, radii in inches, readings and zones in in/s."""
    out = cli("field-balance", FAN, "--units", "in,oz").out
    flat = " ".join(out.split())
    assert "mass [oz]" in flat and "radius [in]" in flat and "initial [in/s rms]" in flat
    assert "before [in/s rms]" in flat and "mm/s" not in out and "[g]" not in out
    # 4.41 mm/s is 0.173622 in/s
    assert f"{4.41 / 25.4:.6g}" in out


def test_no_output_replaces_a_file_the_job_reads(cli, tmp_path):
    """The job's coefficients file and rotor body are inputs too."""
    import shutil

    coeffs = tmp_path / "c.json"
    run_json(cli, *ONE, "--save-coefficients", str(coeffs))
    body = tmp_path / "rotor.yaml"
    body.write_text("{shape: cylinder, radius: 0.1, length: 0.5, mass: 40}\n")
    job = tmp_path / "trim.yaml"
    job.write_text("coefficients: c.json\ninitial: ['6.0@30']\nrotor: {body: rotor.yaml}\n")
    before = coeffs.read_bytes()
    for out in ("c.json", "rotor.yaml"):
        r = cli("field-balance", str(job), "--save-coefficients", str(tmp_path / out), "--force")
        assert r.code == 2 and "is an input file" in r.err, r.err
    assert coeffs.read_bytes() == before and body.read_text().startswith("{shape")
    r = cli("field-balance", str(job), "--plot", str(tmp_path / "rotor.yaml"))
    assert r.code == 2
    shutil.rmtree(tmp_path)


def test_api_takes_lists_of_readings():
    a = rbcli.field_balance(initial=["1@0", "1@180", "0@0"], trial=["1@0", "1@0"],
                            run=[["4@0", "4@0", "5@0"], ["1@180", "3@180", "3@180"]])
    b = rbcli.field_balance(initial="1@0,1@180,0@0", trial=["1@0", "1@0"],
                            run=["4@0,4@0,5@0", "1@180,3@180,3@180"])
    assert a.to_json() == b.to_json()
    with pytest.raises(TypeError):
        rbcli.field_balance(initial=6.0, trial="1@0", run="2@0")


@pytest.mark.parametrize("kwargs", [
    dict(initial="6.0@30", trial="10 g@0", run="4.0@110"),
    dict(initial="170@112,53@78", trial=["1.15 g@0"] * 2, run=["235@94,58@68", "185@115,77@104"],
         trial_radius="100 mm", radius="120 mm"),
    dict(job=FAN),
    dict(job=FAN, suggest_trial=True),
    dict(suggest_trial=True, rotor_mass="120 kg", speed="1480 rpm", trial_radius="250 mm"),
])
def test_every_json_key_is_an_attribute_with_its_value(kwargs):
    """One vocabulary (issue 22): r.<key> is the JSON's value for every key."""
    from rbcli.api.result import jsonable

    r = rbcli.field_balance(**kwargs)
    for key, value in r.to_json().items():
        assert jsonable(getattr(r, key)) == value, key
    if r.corrections:
        assert r.corrections[0].mass_trial_on == r.to_json()["corrections"][0]["mass_trial_on"]
