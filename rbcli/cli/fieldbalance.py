"""``rbcli field-balance``: field (trial-weight) balancing from vibration readings."""

from __future__ import annotations

import typer

from rbcli.api.commands import FIELD_BALANCE
from rbcli.cli import common as c
from rbcli.cli.app import MANUAL

HELP = """Field (trial-weight) balancing from vibration readings: the influence-coefficient method.

Readings are amplitude@phase, the phase in degrees from the keyphasor: all bare numbers
('6.0@30', one relative scale: the corrections do not depend on it) or all with units of one
kind, converted exactly: displacement µm, mm, mil ('40 um@30'), velocity mm/s, in/s
('6 mm/s@30') or acceleration g (standard gravity; in a trial mass g is the gram), m/s²
('0.5 g@30'). A measure may follow the unit ('6 mm/s rms@30': pk, pk-pk or rms); a mix is
converted to one measure (a sinusoid: pk-pk = 2 pk, rms = pk/√2), a mix of readings with and
without a measure is refused unless --measure says the others'. Mixed kinds, unknown units and
a mix of bare and unit readings are refused. Trial masses are mass@angle ('10 g@0'; a bare mass
is in grams).

P planes, N >= P readings: --initial V1,...,VN (one reading per sensor), then --trial and --run
once per plane, in order (each run with that plane's trial on and the others removed, or left
on with --cumulative). One plane, one sensor: H = (V1 - V0)/T and the correction W = -V0/H
(trial removed; with it left on, add W - T). N = P: alpha W = -V0, exactly. N > P: least
squares (the default; --weights w1,...,wN weighs the readings) or --method min-max (the
largest predicted reading as small as it can be); the predicted reading at every sensor is
printed. The condition number (a warning above 50), Darlow's plane-significance factor (a
warning at or below 0.2: a plane that adds no direction of its own) and a warning for a trial
that changed no reading by 25 % or 25° come with every multi-plane job.

A job file (JOB.yaml, see --job-schema and rbcli-field-balance(1)) names the sensors, planes
(radius, positions), speeds (several speeds stack into one solve) and runs; the command line
is the shorthand for a one-speed job. --save-coefficients FILE keeps the influence
coefficients (JSON, with units, speeds, names and conventions); --coefficients FILE with
--initial alone is a trim run (the next machine of the type: no trial runs).
--suggest-trial sizes a trial mass before the first run: its centrifugal force is 10 % (or
--trial-fraction) of the static load on the nearest bearing, from --rotor-mass (or --rotor
BODY.yaml, or --bearing-load), --speed and --trial-radius.

The correction angles are counted in the same sense as the trial angles; the phases must be
counted in that sense too, or say --phase lag|lead and --angle-sense with|against (the trial
angles counted with or against the rotation) and rbcli mirrors them; --rotation cw|ccw draws
the dial as the rotor is seen. --trial-radius and --radius (m unless a unit is given) move
the corrections to another radius. --mass-step, --angle-step and --positions N round the
corrections or split them onto holes or blades, with the readings those masses leave.
--severity iso20816-3 --group 1|2 --foundation rigid|flexible gives the zone of each reading
before and predicted after (r.m.s. velocity). --plot FILE draws the polar diagram, --report
FILE.html or FILE.md writes the job sheet.
"""


@c.command(FIELD_BALANCE, name="field-balance", help=HELP)
def field_balance(
    ctx: typer.Context,
    args: dict = c.PARAMS,
    plot: str = typer.Option(None, "--plot", help="Write the polar diagram of the balancing sheet (png, svg or pdf): per reading O, O+T and the trial's effect; per plane the trial and the correction mass.", show_default=False),
    report: str = typer.Option(None, "--report", help="Write the job sheet: FILE.html (self-contained) or FILE.md (figures in FILE_files/).", show_default=False),
    force: bool = typer.Option(False, "--force", help="Let --report and --save-coefficients replace an existing file (never an input)."),
    job_schema: bool = typer.Option(False, "--job-schema", help="Print the JSON Schema of the job file and exit."),
    json_: bool = c.JsonOpt,
    fmt: str = c.FormatOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.errors import InputError

    e = c.env()
    if job_schema:
        from rbcli.io.field.jobfile import schema_text

        e.write(schema_text())
        return
    if args["initial"] is None and args["job"] is None and not args["suggest_trial"]:
        from typer._click.exceptions import MissingParameter

        param = next(p for p in ctx.command.params if p.name == "initial")
        raise MissingParameter(ctx=ctx, param=param)
    from rbcli.api.field import service as api
    from rbcli.io import outfile
    from rbcli.render.field import tables as rf
    from rbcli.render.units import ShopUnits

    out = c.output_format(json_, fmt)
    su = ShopUnits(units)
    save_coefficients = args.pop("save_coefficients")
    if force and save_coefficients is None and report is None:
        raise InputError("--force: only used with --report or --save-coefficients")
    job = api.parse(None, **args, full=report is not None)
    # the outputs, checked before anything is computed: never an input the job reads
    inputs = list(job.inputs)
    plot_path = c.check_plot(plot, inputs) if plot is not None else None
    coeff_path = report_path = None
    if save_coefficients is not None:
        coeff_path = outfile.check(save_coefficients, inputs, "--save-coefficients", force=force,
                                   exts=("json",), others={"--plot": plot_path})
    if report is not None:
        report_path = outfile.check(report, inputs, "--report", force=force, exts=("html", "md"),
                                    others={"--plot": plot_path, "--save-coefficients": coeff_path})
        if report_path.suffix.lower() == ".md":
            outfile.check_folder(outfile.files_dir(report_path), inputs, "--report", force=force)
    res = api.run(None, job)
    if not res.corrections and (coeff_path, plot_path, report_path) != (None, None, None):
        raise InputError("--suggest-trial without readings has no coefficients, diagram or sheet to "
                         "write; run the job first")
    fig_svg = _figure(res, su, plot_path, report_path)
    if coeff_path is not None:
        from rbcli.render.jsonout import dumps

        outfile.write_document(coeff_path, dumps(res.coefficients_document()), "--save-coefficients",
                               replace=force)
    if report_path is not None:
        _write_sheet(res, su, digits, report_path, fig_svg, args["job"], force)
    for w in res.warnings:
        e.warn(f"rbcli: warning: {c.said(w)}")

    def data() -> dict:
        d = res.to_json()
        if coeff_path is not None:
            d["saved_coefficients"] = str(coeff_path)
        if report_path is not None:
            d["report"] = str(report_path)
        return d

    c.emit(e, out, data, lambda doc: rf.field_document(doc, res, su, digits))


def _figure(res, su, plot_path, report_path) -> str | None:
    """Draw the polar diagram to ``plot_path``; its SVG text for the sheet when there is one."""
    if plot_path is None and report_path is None:
        return None
    from rbcli.render.field.plot import plot
    from rbcli.render.field.tables import reading_display
    from rbcli.render.plots import figure_bytes

    fig = plot(res, su, reading_display(res.reading_kind, su))
    if plot_path is not None:
        c.save_plot(fig, plot_path)
    return None if report_path is None else figure_bytes(fig, "svg").decode("utf-8")


def _write_sheet(res, su, digits, path, fig_svg, job, force) -> None:
    """Write the job sheet (HTML, or Markdown with its figure beside it)."""
    import shlex
    import sys

    from rbcli import __version__
    from rbcli.io import outfile
    from rbcli.render import report as rr
    from rbcli.render.field.sheet import job_sheet

    if job is not None:
        from rbcli.io.reader import read_regular

        name, text = job, read_regular(job, 4 << 20, "job file").decode("utf-8", "replace")
    else:
        name = "the command line"
        text = "rbcli field-balance " + " ".join(shlex.quote(a) for a in sys.argv[2:]) + "\n"
    meta = [("job", res.name or (job or "from the command line")), ("method", str(res.method)),
            ("date", _date()), ("written by", f"rbcli {__version__}")]
    sheet = job_sheet(res, su, digits, meta=meta, input_name=name, input_text=text, figure_svg=fig_svg)
    if path.suffix.lower() == ".html":
        outfile.write_document(path, rr.html(sheet), "--report", replace=force)
    else:
        files = outfile.files_dir(path)
        md, figures = rr.markdown(sheet, files.name)
        outfile.write_document(path, md, "--report", replace=force, folder=files, files=figures)


def _date() -> str:
    """Today (UTC), or SOURCE_DATE_EPOCH's day for reproducible sheets."""
    import os
    import time

    epoch = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    t = int(epoch) if epoch.isdigit() else time.time()
    return time.strftime("%Y-%m-%d", time.gmtime(t))


MANUAL["field-balance"] = {
    "notes": [
        "Physics notes balance.md §5: readings are complex numbers V = amplitude e^{i phase}; "
        "trials T = mass e^{i angle}. The linear model V = V0 + alpha W, alpha (N readings x P "
        "planes) from one trial run per plane: alpha_kj = (V_kj - V_k0)/T_j (V_kj - V_k,j-1 with "
        "--cumulative). One plane, one sensor: H = (V1 - V0)/T, W = -V0/H (trial removed), W - T "
        "with the trial left on; the predicted residual V0 + H W is 0 in the linear model. N = P: "
        "alpha W = -V0 exactly. N > P: least squares, minimising sum (w_k |r_k|)^2 over the "
        "predicted readings r = V0 + alpha W (Goodman 1964; solved by a QR factorisation), or "
        "min-max, minimising max w_k |r_k| (as hsbalance's Min_max; SLSQP on the epigraph form, "
        "polished by Newton on its optimality conditions).",
        "Warnings: cond(alpha) > 50 (planes not well separated); Darlow's plane-significance "
        "factor at or below 0.2 (the part of a plane's influence column not explained by the "
        "larger columns before it, relative to the column: Darlow, ASME 82-GT-269, 1982, and "
        "Balancing of High-Speed Machinery, 1989, ch. 6, as hsbalance's ill_condition flags it); "
        "a trial run that changed no reading by 25 % in amplitude or 25° in phase; a reading "
        "that the least-squares or min-max correction makes larger.",
        "Angles: the correction angles come out in the sense of the trial angles. The phases "
        "must be counted in that sense, or give --phase lag|lead (phase lag grows against the "
        "rotation) and --angle-sense with|against (how the trial angles are counted from the "
        "mark): phase lag with angles counted with the rotation, or phase lead with angles "
        "counted against it, are mirrored (phase -> -phase) before the solve and back in the "
        "predicted readings. --rotation cw|ccw only draws the dial as the rotor is seen. Every "
        "result prints the conventions (JSON angle_convention, conventions).",
        "Readings and units: all readings are either bare numbers, one relative scale (the "
        "corrections do not depend on it; JSON readings.kind 'relative'), or all carry units of "
        "one kind, converted exactly to SI: displacement (µm, um, mm, mil = 25.4 µm; JSON in m), "
        "velocity (mm/s, in/s, m/s; m/s) or acceleration (g = standard gravity 9.80665 m/s², "
        "m/s²; m/s²). In a reading g is gravity, in a trial mass it is the gram; the output says "
        "so when a reading's g was read. A measure after the unit (pk; pk-pk, p-p; rms) is kept: "
        "readings of different measures are converted to the first reading's (to rms with "
        "--severity), and a mix of readings with and without a measure is refused unless "
        "--measure names the others'. Tables show µm, mm/s and m/s², or mil, in/s and g with "
        "--units in,... . A trial mass needs no unit: a bare mass is in grams ('10@0' = '10 g@0'); "
        "--trial-radius and --radius are metres unless a unit is given.",
        "Rounding: --mass-step and --angle-step round each correction (half up; angles in the "
        "angles' sense), --positions N splits it onto the two neighbouring of N equally spaced "
        "positions (position 1 on the 0° mark; m1 = |C| sin(a2 - phi)/sin(a2 - a1), m2 = |C| "
        "sin(phi - a1)/sin(a2 - a1)) and rounds the two masses; the readings those masses leave "
        "are predicted (JSON fitted).",
        "Severity: --severity iso20816-3 --group 1|2 --foundation rigid|flexible gives the zone of "
        "each reading (r.m.s. velocity; displacement and acceleration converted at --speed, v = "
        "omega x, a = omega v) before and predicted after the correction (the fitted masses when "
        "rounded). Zone boundaries A/B, B/C, C/D in mm/s r.m.s.: group 1 rigid 2.3, 4.5, 7.1; "
        "group 1 flexible 3.5, 7.1, 11.0; group 2 rigid 1.4, 2.8, 4.5; group 2 flexible 2.3, 4.5, "
        "7.1 (ISO 20816-3:2022 Annex A, as ISO 10816-3:2009; a value on a boundary is in the lower "
        "zone). The standard judges the broadband velocity; a 1x reading is part of it, so the "
        "machine's zone is at least the one shown.",
        "Job file (JOB.yaml; --job-schema prints its JSON Schema): rbcli: 1, job: field-balance, "
        "name, units {length, mass, angular_speed} (bare lengths m, masses g, speeds rad/s unless "
        "said), conventions {phase, angle_sense, rotation}, readings {measure}, sensors [names, or "
        "{name, weight}], planes [{name, radius (trial), correction_radius, positions, at}], "
        "speeds [{name, speed}], initial {speed: [one reading per sensor]} (a list with one "
        "speed), trials [{plane, mass: 'm@angle', readings {speed: [...]}}], cumulative, method, "
        "mass_step, angle_step, severity {group, foundation}, rotor {mass or body, bearings "
        "[z1, z2], com, bearing_load, g, trial_fraction}, coefficients (a saved file: a trim run). "
        "Several speeds stack into one solve (a reading = a sensor at a speed). Errors are "
        "located file:line:col. A setting given in the job file and on the command line is "
        "refused.",
        "Stored coefficients: --save-coefficients FILE.json writes {format, version, written_by, "
        "job, description, influence {reading_kind, reading_unit, measure, per}, conventions "
        "{phase, angle_sense, rotation, text}, sensors, speeds [{name, speed (rad/s)}], planes "
        "[{name, trial_radius (m)}], rows [{sensor, speed}], coefficients [[{re, im, magnitude, "
        "angle_deg}]]}: the change of reading k per kg of trial mass in plane j at its trial "
        "radius, re and im exact (they read back bit for bit). --coefficients FILE with --initial "
        "alone solves with them (a trim run): the readings must match in number, kind, measure "
        "and speed; conventions left unsaid are the file's. The same initial readings give the "
        "first job's correction exactly.",
        "Trial mass: --suggest-trial sizes m_T = f F / (r Omega^2), F the static load on the "
        "bearing nearest the trial plane (the job file's rotor bearings and com and the plane's "
        "position, by the lever rule; else half the rotor's weight, or --bearing-load), r the "
        "trial radius, Omega the speed (the highest of a job's), f = 10 % (--trial-fraction, 1 % "
        "to 30 %): rbcli's rule from the physics notes balance.md §5.1, the shop rule of 5-10 % of "
        "the bearing load. With influence coefficients (a previous job's) the change each reading "
        "should show is predicted; a trial run that then changes no reading by 25 % or 25° is "
        "flagged.",
        "--plot FILE (png, svg or pdf) draws the balancing sheet's polar diagram: per reading the "
        "reading O without trial, each run O+T, the change T the trial made (from O's tip to "
        "O+T's) and the predicted reading, and per plane the trial mass, the correction to add "
        "and the masses to fit; 0° on the right, counterclockwise (clockwise when --rotation and "
        "--angle-sense put it so). --report FILE.html|FILE.md writes the job sheet: readings, "
        "polar diagram, coefficients, corrections as fitted, predicted readings, severity and "
        "warnings, with the job file at the end (never over an input; an existing sheet only "
        "with --force).",
        "One- and two-plane jobs with one reading per plane, given with --initial, --trial, "
        "--run, --cumulative, --radius and --trial-radius only, print what rbcli always printed "
        "(with Darlow's warning, and the factor beside the condition number, when it flags a plane); "
        "anything more (a job file, more readings, more planes, a method, weights, rounding, "
        "conventions, measures, g readings, severity, coefficients, a trial suggestion, a report) "
        "gives the extended output.",
    ],
    "json": [
        ("planes", "the number of correction planes."),
        ("corrections", "[{name, mass (kg), angle_deg, mass_trial_on, angle_trial_on_deg, radius (m or null)}]; trial removed, and with that plane's trial left on."),
        ("influence", "[[{magnitude (per kg: the readings' SI unit, m, m/s or m/s^2, or their relative scale), angle_deg}]] row = reading, column = plane."),
        ("cond, det_magnitude, ill_conditioned", "2-norm condition number and |det| (square) of the influence matrix."),
        ("readings", "{kind: relative, displacement, velocity or acceleration; unit: null, m, m/s or m/s^2}; extended: measure, converted [{from, to, count}], g (what a reading's g was read as, or null)."),
        ("small_response, predicted_residual, cumulative, angle_convention, warnings", "checks as in the notes; predicted_residual: magnitudes per reading."),
        ("method", "extended: exact, least-squares or min-max."),
        ("sensors, speeds", "extended: the sensors' names; [{name, speed (rad/s or null)}]. Reading k is sensor k mod S at speed k div S."),
        ("residuals, residual_max, residual_rms", "extended: [{sensor, speed, amplitude (the readings' unit and measure), angle_deg (the instrument's phase convention), initial}] predicted after the correction."),
        ("significance, significance_limit", "extended: [{plane, factor, flagged}], 0.2."),
        ("fitted", "extended, with rounding or positions: {mass_step, angle_step_deg, planes [{name, positions, mass, angle_deg, masses [{mass, angle_deg, position}]}], residuals [...]}."),
        ("severity", "extended, with --severity: {standard, group, foundation, boundaries [3] (m/s rms), after_is, readings [{sensor, speed, before, before_zone, after, after_zone}]} (m/s rms)."),
        ("suggested_trial", "[{plane, mass (kg), radius (m), speed (rad/s), bearing_load (N), bearing_load_from, fraction, force (N), expected_change, expected_change_ratio}]."),
        ("conventions, coefficients_from, job, name, notes, weights", "extended: {phase, angle_sense, rotation, converted, text}; the coefficients file; the job file and its name; conversions made; the weights."),
        ("saved_coefficients, report", "the files written by --save-coefficients and --report (command line only)."),
    ],
    "examples": [
        ("rbcli field-balance --initial '6.0 mm/s@30' --trial '10 g@0' --run '4.0 mm/s@110'",
         "One plane: H = 0.660794 (mm/s)/g at 173.406°, add 9.07998 g at 36.594° (trial removed)."),
        ("rbcli field-balance --initial '6 mm@30' --trial '10 g@0' --run '4000 um@110' --plot sheet.png",
         "Displacement readings in mm and µm, converted: the same 9.08 g at 36.594°, and the polar diagram."),
        ("rbcli field-balance --initial '170@112,53@78' --trial '1.15 g@0' --run '235@94,58@68' --trial '1.15 g@0' --run '185@115,77@104'",
         "The B&K two-plane example: 1.979 g at 236.2° and 1.071 g at 121.8°, cond 2.70."),
        ("rbcli field-balance --initial '1@0,1@180,0@0' --trial '1@0' --run '4@0,4@0,5@0' --trial '1@0' --run '1@180,3@180,3@180'",
         "Goodman's 1964 least-squares example, 3 sensors and 2 planes: 0.809524 g and 1.47619 g at 0° "
         "(17/21 and 31/21); with --method min-max 1 g and 1.8 g, every predicted reading 0.4."),
        ("rbcli field-balance examples/jobs/fan.yaml --report sheet.html",
         "The example job: two planes, four sensors, two speeds, the job sheet with its polar diagram and ISO 20816-3 zones."),
        ("rbcli field-balance examples/jobs/fan.yaml --save-coefficients fan-coeffs.json",
         "Keep the fan's coefficients; then 'rbcli field-balance --coefficients fan-coeffs.json --initial ...' trims the next fan without trial runs."),
        ("rbcli field-balance --suggest-trial --rotor-mass '120 kg' --speed '1480 rpm' --trial-radius '250 mm'",
         "A trial mass whose force is 10 % of the load on one of two bearings (588.4 N): 9.79831 g."),
    ],
}
