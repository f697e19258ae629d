"""The report's document from its computed sections (:class:`rbcli.api.report.ReportResult`).

:func:`document` fills a :class:`rbcli.render.report.Report` with each section's tables
(the same tables the commands print, through their render modules), its "options" table,
its warnings and its figure (inline SVG); :func:`rbcli.render.report.html` and
:func:`rbcli.render.report.markdown` write it out. Rendering only: every number was
computed by the service.
"""

from __future__ import annotations

import hashlib
import shlex
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from rbcli import __version__
from rbcli.errors import NonFiniteResult, option_name
from rbcli.render import balance as rb
from rbcli.render import balanceplot, echo
from rbcli.render import massprops as rm
from rbcli.render import precess as rp
from rbcli.render import rollcheck as rr
from rbcli.render import top as rt
from rbcli.render import whirl as rw
from rbcli.render import bodyplot
from rbcli.render.fmt import said
from rbcli.render.plots import figure_bytes
from rbcli.render.report import Figure, Report, Section, parts_table
from rbcli.render.text import Doc, Heading, Note, check_finite_doc
from rbcli.render.units import DisplayUnits, ShopUnits

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.report import ReportResult
    from rbcli.api.report import Section as Computed

__all__ = ["document"]


def _options_table(doc: Doc, rows: tuple) -> None:
    """A section's options as understood (the command's "options" table), after its heading."""
    if rows:
        at = 1 if doc.items and isinstance(doc.items[0], Heading) else 0
        doc.table("options", ("option", "value", "unit"), rows, right=(1,))
        doc.items.insert(at, doc.items.pop())


def _figure(s: Section, name: str, fig: Any, caption: str) -> None:
    """Add a figure (what a command's --plot draws) as inline SVG: in memory, no file."""
    s.items.append(Figure(name, caption, figure_bytes(fig, "svg").decode("utf-8")))


def _section(c: Computed, doc: Doc, body: Any) -> Section:
    s = Section(c.key, c.title)
    s.add_doc(doc, drop_heading_prefix=body.name)
    for w in c.warnings:
        s.items.append(Note("warning: " + said(w)))
    return s


def _parts(c: Computed, body: Any, du: DisplayUnits, digits: int) -> Section:
    doc = Doc()
    parts_table(doc, body, c.result, c.figure, du, digits)
    s = Section(c.key, c.title)
    s.add_doc(doc)
    return s


def _massprops(c: Computed, body: Any, du: DisplayUnits, digits: int) -> Section:
    doc = Doc()
    rm.inertia_doc(doc, body, c.result, du, digits, "tensor", c.result.reference_label, parts=False)
    return _section(c, doc, body)


def _principal(c: Computed, body: Any, du: DisplayUnits, digits: int) -> Section:
    doc = Doc()
    rm.principal_doc(doc, body, c.result, du, digits, "the com", parts=False)
    s = _section(c, doc, body)
    fig = bodyplot.body_figure(body, c.result.reference, c.result, du,
                      f"principal: {body.name} — the body as built, centre of mass and principal axes")
    _figure(s, "body", fig, bodyplot.caption(body))
    return s


def _balance(c: Computed, body: Any, du: DisplayUnits, digits: int) -> Section:
    res, bo = c.result, c.options
    su = ShopUnits(",".join(u for _, u in (du.length, du.mass, du.time)) if du.chosen else None, body)
    doc = Doc()
    rb.document(doc, res, su, digits)
    _options_table(doc, rb.echo_rows(res))
    s = _section(c, doc, body)
    if not (bo.planes or bo.speed or bo.bearings):
        s.items.append(Note("(corrections, bearing forces and the ISO grade need --planes, --speed "
                            "with a rotation unit, --bearings and --grade)"))
    _figure(s, "balance", balanceplot.plot(c.figure, su),
            "The polar (vector) diagram, as `rbcli balance --plot` draws it: the unbalance per plane "
            "and, with --planes, the corrections and the residual, as arrows on the rotor's dial "
            "(angles as the tables count them).")
    return s


def _whirl(c: Computed, body: Any, du: DisplayUnits, digits: int) -> Section:
    doc = Doc()
    rw.document(doc, c.result, du, digits, heading=False)
    s = _section(c, doc, body)
    _figure(s, "whirl-campbell", rw.campbell_figure(c.result),
            "Campbell diagram: whirl frequencies against speed, the n× lines and the critical speeds.")
    _figure(s, "whirl-response", rw.response_figure(c.result),
            "Unbalance response at each bearing: amplitude and phase against speed.")
    _figure(s, "whirl-map", rw.map_figure(c.result), "Undamped critical speed map: critical speeds "
            "against bearing stiffness, with the bearings' own stiffness against speed.")
    return s


def _precess(c: Computed, body: Any, du: DisplayUnits, digits: int) -> Section:
    doc = Doc()
    rp.document(doc, body, c.result, du, digits)
    _options_table(doc, echo.echo_rows(c.options, body.units))
    s = _section(c, doc, body)
    _figure(s, "precess", rp.plot(body, c.result.motion, None, du),
            "The angular velocity in the body frame against time and the polhode (as rbcli precess --plot).")
    return s


def _top(c: Computed, body: Any, du: DisplayUnits, digits: int) -> Section:
    doc = Doc()
    rt.document(doc, c.result, du, digits)
    _options_table(doc, echo.echo_rows(c.options, body.units))
    s = Section(c.key, c.title)  # the top's warnings are printed by the command, not in its tables
    s.add_doc(doc, drop_heading_prefix=body.name)
    path, span = c.figure
    _figure(s, "top", rt.plot(c.result, path, span),
            "The path of the axis (as rbcli top --plot), over three nutation periods.")
    return s


def _rollcheck(c: Computed, body: Any, du: DisplayUnits, digits: int) -> Section:
    doc = Doc()
    rr.document(doc, c.result, du, digits)
    _options_table(doc, rr.echo_rows(c.result))
    s = _section(c, doc, body)
    _figure(s, "rollcheck", rr.plot(c.result, c.figure),
            "Lean frequency squared and growth rate against speed (as rbcli rollcheck --plot).")
    return s


#: section key -> (progress text, builder)
_BUILDERS: dict[str, tuple[str, Callable[..., Section]]] = {
    "parts": ("parts", _parts),
    "mass-properties": ("mass properties", _massprops),
    "principal-axes": ("principal axes", _principal),
    "balance": ("balance", _balance),
    "whirl": ("whirl", _whirl),
    "free-precession": ("free precession", _precess),
    "heavy-top": ("heavy top", _top),
    "rolling-stability": ("rolling stability", _rollcheck),
}


def _built(c: Computed, body: Any, du: DisplayUnits, digits: int) -> Section:
    """The section's document, or one line saying why not when a table would show inf or
    NaN (as the commands refuse such a table)."""
    if c.skipped is not None:
        return Section.skip(c.key, c.title, said(c.skipped))
    what, build = _BUILDERS[c.key]
    try:
        s = build(c, body, du, digits)
        check_finite_doc(s)
    except (OverflowError, ZeroDivisionError, FloatingPointError, NonFiniteResult) as exc:
        reason = exc if isinstance(exc, NonFiniteResult) else \
            f"a value is too large or too small to compute with ({exc})"
        return Section.skip(c.key, c.title, f"{what}: not computed: {reason}")
    return s


def options_text(result: ReportResult) -> str:
    """The options given, as a shell would take them (the header's "options" line)."""
    return " ".join(f"{option_name(k)} {shlex.quote(v)}" for k, v in result.options.given)


def document(result: ReportResult, units: DisplayUnits | None = None, digits: int = 6,
             progress: Callable[[str, int, int], None] | None = None) -> Report:
    """The report's document: the header (body, input file and its SHA-256, options, units,
    rbcli version, date) and each section's tables and figure; ``units`` the tables' units
    (default: the body file's), ``digits`` their significant figures. ``progress(what, i, n)`` is called
    before each section is drawn."""
    body = result.body
    du = (units or DisplayUnits()).of(body)
    sections = []
    for i, c in enumerate(result.sections):
        if progress is not None:
            progress(f"drawing {_BUILDERS[c.key][0]}", i, len(result.sections))
        sections.append(_built(c, body, du, digits))
    meta = [("body", body.name)]
    if body.description:
        meta.append(("description", body.description))
    meta += [
        ("input file", body.source),
        ("SHA-256 of the input file", hashlib.sha256(body.text.encode("utf-8")).hexdigest()),
        ("options", options_text(result) or "(none)"),
        ("units in tables", "SI" if du.si else ", ".join(u for _, u in (du.length, du.mass, du.time))),
        ("rbcli version", __version__),
        ("date", result.options.date),
    ]
    return Report(title=f"rbcli report: {body.name}", meta=meta, sections=sections,
                  input_name=body.source, input_text=body.text, generator=f"rbcli {__version__}")
