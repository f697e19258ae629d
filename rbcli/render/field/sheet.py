"""The job sheet of ``rbcli field-balance --report``: the tables of
:mod:`rbcli.render.field.tables` and the polar diagrams in a :class:`rbcli.render.report.Report`
(the command line writes it)."""

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
    """The job sheet of an extended result ``res`` (``rbcli.field_balance(..., full=True)``):
    ``meta`` the (label, value) rows under the title, the job file (or the command line)
    shown at the end, the polar diagrams as SVG text (:mod:`rbcli.render.field.plot`) or None."""
    scale, ru = fb.reading_display(res.reading_kind, su, res.measure)
    rows = res.row_names()

    def section(key: str, title: str, *fill) -> Section:
        s, d = Section(key, title), Doc()
        for f in fill:
            f(d)
        s.add_doc(d)
        return s

    sections = [section("readings", "Readings", lambda d: d.note(res.angle_convention),
                        lambda d: fb.readings_note(d, res, ru),
                        lambda d: fb.readings_table(d, res, scale, ru, rows, digits),
                        lambda d: fb.trials_table(d, res, su, digits))]
    if figure_svg is not None:
        sections.append(Section("polar", "Polar diagram", [Figure(
            "polar", "per reading the reading without trial (O), with each trial (O+T, in the run's colour), "
            "the trial's effect and the predicted reading; per plane the trial mass, the correction and the "
            "masses to fit (a drawer's holes numbered on the rim)", figure_svg)]))
    sections += [
        section("coefficients", "Influence coefficients", lambda d: fb.influence_table(d, res, scale, ru, rows, su, digits),
                lambda d: fb.significance_note(d, res),
                lambda d: res.coefficients_from and d.note(f"from {res.coefficients_from} (a trim run)")),
        section("corrections", "Corrections", lambda d: d.note(f"method: {res.method}; a correction is a mass to add"),
                lambda d: fb.corrections_table(d, res, su, digits),
                lambda d: fb.limits_table(d, res, su, scale, ru, digits), lambda d: fb.robust_note(d, res),
                lambda d: res.fitted and fb.fitted_table(d, res, su, digits)),
        section("residuals", "Predicted readings", lambda d: fb.residuals_table(d, res, scale, ru, rows, digits)),
        section("severity", "Severity (ISO 20816-3)", lambda d: fb.severity_table(d, res, rows, digits, su))
        if res.severity is not None else Section.skip(
            "severity", "Severity (ISO 20816-3)", "Severity: not judged (give --severity iso20816-3 --group 1|2 "
            "--foundation rigid|flexible with velocity readings).")]
    if res.suggested_trial:
        sections.append(section("trial", "Trial mass", lambda d: fb.suggestion_table(d, res, su, scale, ru, rows, digits)))
    if res.warnings:
        sections.append(Section("warnings", "Warnings", [Note(w) for w in res.warnings]))
    return Report(f"Field balancing job sheet{': ' + res.name if res.name else ''}", meta, sections, input_name,
                  input_text, generator="rbcli field-balance")
