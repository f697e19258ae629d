"""The job sheet of ``rbcli field-balance --report sheet.html|sheet.md``: one document for the
customer with the readings, the polar diagram, the influence coefficients, the
corrections as computed and as fitted, the predicted readings and the severity verdicts.

Built from the blocks of :mod:`rbcli.render.report` (:class:`~rbcli.render.report.Report`,
sections, figures, :func:`~rbcli.render.report.html` and
:func:`~rbcli.render.report.markdown`) and the tables of :mod:`rbcli.render.field.tables`;
it never writes a file (the command line does, through :mod:`rbcli.io.outfile`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rbcli.render.field import tables as fb
from rbcli.render.units import ShopUnits
from rbcli.render.report import Figure, Report, Section
from rbcli.render.text import Doc, Note

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.field.result import FieldBalanceResult


def job_sheet(res: FieldBalanceResult, su: ShopUnits, digits: int, *, meta: list[tuple[str, str]],
              input_name: str, input_text: str, figure_svg: str | None) -> Report:
    """The job sheet of an extended result ``res``.

    Parameters
    ----------
    res : the result (extended: ``rbcli.field_balance(..., full=True)``)
    su : display units; digits : significant figures
    meta : (label, value) rows under the title (job, date, rbcli version...)
    input_name, input_text : the job file (or the command line) shown at the end
    figure_svg : the polar diagram as SVG text (rbcli.render.plots.figure_bytes of
        rbcli.render.balanceplot.plot), or None
    """
    scale, ru = fb.reading_display(res.reading_kind, su)
    rows = res.row_names()
    title = f"Field balancing job sheet{': ' + res.name if res.name else ''}"
    sections = []

    s = Section("readings", "Readings")
    d = Doc()
    d.note(res.conventions.text if res.conventions is not None else
           "angles in degrees, counted in the same sense as the trial angles and the phase readings "
           "(they must agree)")
    fb.readings_note(d, res, ru)
    fb.readings_table(d, res, scale, ru, rows, digits)
    fb.trials_table(d, res, su, digits)
    s.add_doc(d)
    sections.append(s)

    if figure_svg is not None:
        s = Section("polar", "Polar diagram")
        s.items.append(Figure("polar", "per reading the reading without trial (O), with each trial (O+T, "
                              "in the run's colour), the trial's effect and the predicted reading; per "
                              "plane the trial mass, the correction and the masses to fit (a drawer's "
                              "holes numbered on the rim)", figure_svg))
        sections.append(s)

    s = Section("coefficients", "Influence coefficients")
    d = Doc()
    fb.influence_table(d, res, scale, ru, rows, su, digits)
    fb.significance_note(d, res)
    if res.coefficients_from is not None:
        d.note(f"from {res.coefficients_from} (a trim run)")
    s.add_doc(d)
    sections.append(s)

    s = Section("corrections", "Corrections")
    d = Doc()
    d.note(f"method: {res.method}; a correction is a mass to add")
    fb.corrections_table(d, res, su, digits)
    fb.limits_table(d, res, su, scale, ru, digits)
    fb.robust_note(d, res)
    if res.fitted is not None:
        fb.fitted_table(d, res, su, digits)
    s.add_doc(d)
    sections.append(s)

    s = Section("residuals", "Predicted readings")
    d = Doc()
    fb.residuals_table(d, res, scale, ru, rows, digits)
    s.add_doc(d)
    sections.append(s)

    if res.severity is not None:
        s = Section("severity", "Severity (ISO 20816-3)")
        d = Doc()
        fb.severity_table(d, res, rows, digits, su)
        s.add_doc(d)
        sections.append(s)
    else:
        sections.append(Section.skip("severity", "Severity (ISO 20816-3)",
                                     "Severity: not judged (give --severity iso20816-3 --group 1|2 "
                                     "--foundation rigid|flexible with velocity readings)."))
    if res.suggested_trial:
        s = Section("trial", "Trial mass")
        d = Doc()
        fb.suggestion_table(d, res, su, scale, ru, rows, digits)
        s.add_doc(d)
        sections.append(s)
    if res.warnings:
        s = Section("warnings", "Warnings")
        for w in res.warnings:
            s.items.append(Note(w))
        sections.append(s)
    return Report(title, meta, sections, input_name, input_text, generator="rbcli field-balance")


