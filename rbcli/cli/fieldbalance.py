"""``rbcli field-balance``: field (trial-weight) balancing from vibration readings."""

from __future__ import annotations

import typer

from rbcli.api.commands import FIELD_BALANCE
from rbcli.cli import common as c
from rbcli.cli.app import MANUAL

HELP = """Field (trial-weight) balancing from vibration readings: the influence-coefficient method.

Readings are amplitude@phase, the phase in degrees from the keyphasor: all bare ('6.0@30', one
relative scale) or all with units of one kind, converted exactly: displacement µm, mm, mil,
velocity mm/s, in/s, acceleration g (standard gravity; in a trial mass g is the gram), m/s²,
optionally with a measure ('6 mm/s rms@30': pk, pk-pk, rms; mixed measures are converted).
Trial masses are mass@angle ('10 g@0'; a bare mass is in grams).

P planes, N >= P readings: --initial V1,...,VN, then --trial and --run once per plane (each
run with that plane's trial on, the others removed or, with --cumulative, left on). N = P is
solved exactly; N > P by least squares (--weights weighs the readings; --robust huber
discounts a bad reading) or --method min-max (the largest predicted reading as small as can
be). --max-mass and --limit bound the masses and the predicted readings (the binding ones and
their cost are said; limits that cannot all be met give the least-violating correction).
Every multi-plane job checks the condition number, Darlow's plane significance and trials
that changed too little.

A job file (JOB.yaml, --job-schema) names the sensors, planes (radii, holes, limits), speeds
(several stack into one solve) and runs. --save-coefficients keeps the coefficients;
--coefficients FILE with --initial alone is a trim run. --suggest-trial sizes a trial mass
from --rotor-mass (or --rotor, --bearing-load), --speed and --trial-radius.

Angles are counted in the sense of the trial angles; give --phase lag|lead with --angle-sense
with|against for rbcli to mirror the phases; --rotation cw|ccw draws the dial as seen.
--trial-radius and --radius move the corrections to another radius. --mass-step, --angle-step
and --positions N round the corrections or split them onto holes; --drawer with --positions
chooses the best weights there are (an exact search). --severity iso20816-3 gives the ISO
20816-3 zones before and after. --plot draws the polar diagrams, --report the job sheet.
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

    fig = plot(res, su, reading_display(res.reading_kind, su, res.measure))
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
        "The model (physics notes balance.md §5): V = V0 + alpha W, readings V = amplitude "
        "e^{i phase}, masses W = m e^{i angle}; alpha_kj = (V_kj - V_k0)/T_j (V_kj - V_k,j-1 with "
        "--cumulative). N = P: alpha W = -V0 (one plane: W = -V0/H; W - T with the trial on). N > P: "
        "least squares, min sum (w_k |r_k|)^2, r = V0 + alpha W (Goodman 1964; a QR), or min-max, "
        "min max w_k |r_k| (as hsbalance's Min_max; a log-barrier method polished by Newton on its "
        "optimality conditions). Sums in a fixed order: the same bytes for any BLAS thread count.",
        "Limits: --max-mass (for all planes or per plane; a mass x radius such as '5000 g*mm' limits "
        "the unbalance) and --limit (the largest predicted reading, for all or SENSOR=amplitude) make "
        "a second-order cone program, in least squares and min-max; the output lists each limit, "
        "whether it binds, the objective without it; limits that cannot all be met give the "
        "correction exceeding them least (every reading within s times its limit), said. --robust "
        "huber reweights least squares by Huber's rule (c/|r_k| beyond c = 2.448 median|r|/sqrt(ln "
        "4)), naming the readings it discounts.",
        "A drawer: --drawer 'mass[:count],...' (bare: grams) and --max-weights K (1-4, default 2) "
        "choose the best weights at each plane's holes (--positions N from 0°, at --radius; a job "
        "file's holes: count and zero or angles, radius, numbering with or against the angles, "
        "per_hole) by the method's objective on the predicted readings, under the limits, by an "
        "exact search (never rounded from the continuous answer). A weight at hole radius r_h counts "
        "r_h/r_trial; --max-mass is then the weights' total.",
        "Checks: cond(alpha) > 50; Darlow's plane-significance factor at or below 0.2 (Darlow, ASME "
        "82-GT-269, 1982: the Gram-Schmidt factor, 0 to 1; hsbalance 0.5.5 projects on the previous "
        "column only); a trial that changed no reading by 25 % or 25°; a reading made larger.",
        "Angles: corrections are in the sense of the trial angles; give --phase lag|lead and "
        "--angle-sense with|against to mirror phases counted the other way. Readings: all bare or "
        "all of one kind (displacement, velocity, acceleration; g is gravity there, the gram in a "
        "trial mass), measures pk, pk-pk, rms converted; amplitudes and trial masses 0 or 1e-100 to "
        "1e100 (SI). Rounding: --mass-step, --angle-step, --positions N (split onto the two "
        "neighbouring positions).",
        "Severity: --severity iso20816-3 --group 1|2 --foundation rigid|flexible: zones before and "
        "after (r.m.s. velocity), boundaries A/B, B/C, C/D mm/s: group 1 rigid 2.3, 4.5, 7.1; flexible "
        "3.5, 7.1, 11.0; group 2 rigid 1.4, 2.8, 4.5; flexible 2.3, 4.5, 7.1 (ISO 20816-3 Annex A).",
        "Job file (--job-schema): units, conventions, readings {measure}, sensors [{name, weight, "
        "limit}], planes [{name, radius, correction_radius, positions or holes, at, max_mass, "
        "max_weights, drawer}], speeds [{name, speed, limit}], initial, trials, cumulative, method, "
        "mass_step, angle_step, severity, rotor, coefficients, drawer, max_weights, robust. Errors "
        "are located at their key; a setting in the file and on the command line is refused; more "
        "than 20 000 influence coefficients (readings x planes) is refused unless "
        "RBCLI_MAX_FIELD_COEFFICIENTS says more.",
        "Stored coefficients: --save-coefficients FILE.json (re, im exact; units, conventions, "
        "sensors, speeds, planes, a row per reading, a sha256 fingerprint); --coefficients FILE "
        "with --initial alone is a trim run. A file changed since written, rows out of order, or "
        "names, units or measure that do not match the job are refused, saying what differs.",
        "--suggest-trial: m_T = f F / (r Omega^2), F the static load on the bearing nearest the plane, "
        "f = 10 % (--trial-fraction). --plot: polar diagrams, a legend per dial, at most 12 readings "
        "and 6 planes. --report FILE.html|FILE.md: the job sheet (wide tables show 12 planes).",
        "One- and two-plane jobs given with --initial, --trial, --run, --cumulative, --radius and "
        "--trial-radius only print what rbcli always printed.",
    ],
    "json": [
        ("planes, corrections", "P; [{name, mass (kg), angle_deg, mass_trial_on, angle_trial_on_deg, radius (m or null)}]."),
        ("influence, trials", "[[{magnitude (per kg), angle_deg}]] row = reading; [{mass, angle_deg}]."),
        ("cond, det_magnitude, ill_conditioned", "of the influence matrix (det: square, null when it overflows)."),
        ("readings", "{kind, unit}; extended: measure, converted [{from, to, count}], g."),
        ("small_response, predicted_residual, cumulative, angle_convention, warnings", "checks; magnitudes per reading."),
        ("method, sensors, speeds", "extended: exact, least-squares or min-max; names; [{name, speed (rad/s)}]."),
        ("residuals, residual_max, residual_rms", "extended: [{sensor, speed, amplitude, angle_deg, initial}]."),
        ("significance, significance_limit", "extended: [{plane, factor, flagged}], 0.2."),
        ("fitted", "extended: {mass_step, angle_step_deg, planes [{name, positions, mass, angle_deg, masses [{mass, angle_deg, position}]}], residuals, drawer {objective, violation, examined, drawers, planes [{name, holes_deg, radius, numbering, per_hole, max_weights, max_mass, drawer}]}}."),
        ("limits", "with limits: {feasible, violation, objective, planes [{plane, max_mass, max_unbalance, mass, unbalance, active, objective_without}], readings [{sensor, speed, limit, amplitude, active, objective_without}]}."),
        ("robust", "with --robust: {method, threshold, weights, discounted}."),
        ("severity", "{standard, group, foundation, boundaries (m/s rms), after_is, readings [{sensor, speed, before, before_zone, after, after_zone}]}."),
        ("suggested_trial", "[{plane, mass, radius, speed, bearing_load, bearing_load_from, fraction, force, expected_change, expected_change_ratio}]."),
        ("conventions, coefficients_from, job, name, notes, weights", "extended: {phase, angle_sense, rotation, converted, text}; sources; conversions."),
        ("saved_coefficients, report", "the files written (command line only)."),
    ],
    "examples": [
        ("rbcli field-balance --initial '6.0 mm/s@30' --trial '10 g@0' --run '4.0 mm/s@110'",
         "One plane: add 9.07998 g at 36.594° (trial removed)."),
        ("rbcli field-balance --initial '1@0,1@180,0@0' --trial '1@0' --run '4@0,4@0,5@0' --trial '1@0' --run '1@180,3@180,3@180'",
         "Goodman 1964, 3 sensors, 2 planes: 17/21 g and 31/21 g; with --method min-max 1 g and 1.8 g."),
        ("rbcli field-balance examples/jobs/fan.yaml --report sheet.html",
         "Two planes, four sensors, two speeds: the job sheet with its polar diagrams and zones."),
        ("rbcli field-balance examples/jobs/fan-drawer.yaml",
         "The same fan with 25 g at most in plane A, a reading limit and a drawer of clip-on weights."),
        ("rbcli field-balance examples/jobs/fan.yaml --save-coefficients fan-coeffs.json",
         "Keep the coefficients for a trim run: --coefficients fan-coeffs.json --initial ..."),
        ("rbcli field-balance --suggest-trial --rotor-mass '120 kg' --speed '1480 rpm' --trial-radius '250 mm'",
         "A trial mass whose force is 10 % of the load on one of two bearings: 9.79831 g."),
    ],
}
