"""Every answer that applies to a body, in one document: the service behind ``rbcli report``.

:class:`ReportOptions` reads the report's options once, through each command's own
options object (:class:`rbcli.api.balance.BalanceOptions`,
:class:`rbcli.api.precess.PrecessOptions`, :class:`rbcli.api.top.TopOptions`,
:class:`rbcli.api.rollcheck.RollcheckOptions`), so a value means in the report what it
means to the command. :func:`run` computes each section by calling the services and
renders it with :mod:`rbcli.render` (the report is a document: this is the one service that
imports render, see ``tests/test_architecture.py``). :func:`report` is the public function:
it returns the document's text, or writes it through :mod:`rbcli.io.outfile` with the same
all-or-nothing rules as the command line.

Which section is there: parts, mass properties and principal axes always; balance when the
body has a shaft or a balance option is given; free precession with ``omega``; the heavy
top when there is a pivot (the body's or ``pivot``) and ``spin`` and ``theta``; rolling
stability when there is a rim radius (the body's, ``rim_radius`` or a round part). A
section that does not apply, or that this body cannot have (an error located in the body
file, or a value too large to compute with), is one line saying why; a value the user gave
that its command refuses is an :class:`rbcli.InputError`, as on the command line.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from rbcli.api.result import Result
from rbcli.errors import InputError, ParamError

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.balance import BalanceOptions
    from rbcli.api.precess import PrecessOptions
    from rbcli.api.rollcheck import RollcheckOptions
    from rbcli.api.top import TopOptions
    from rbcli.model import Body
    from rbcli.render.fmt import DisplayUnits
    from rbcli.render.report import Report, Section

__all__ = ["FORMATS", "ReportOptions", "ReportResult", "check_output", "report", "run", "write"]

#: the document formats, by file extension
FORMATS = (".html", ".md")

#: the report's options in the order the header lists them (Python name -> option)
_OPTIONS = ("shaft", "through", "planes", "radius", "bearings", "grade", "speed", "omega", "pivot",
            "spin", "theta", "theta_dot", "phi_dot", "rim_radius", "tyre_radius", "g", "symmetry_tol")

#: stand-ins for a missing --spin or --theta, so that the one given is still checked by
#: TopOptions.parse (the heavy-top section is then left out, saying what is missing)
_TOP_STAND_INS = {"spin": 1.0, "theta": 90.0}


# ----------------------------------------------------------------------------- options


def _text(v: Any) -> str:
    """A value as the header's options line shows it (strings as typed, numbers exactly)."""
    if isinstance(v, str):
        return v
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return repr(float(v))
    if hasattr(v, "tolist"):
        v = v.tolist()
    if isinstance(v, (list, tuple)):
        return ",".join(_text(x) for x in v)
    return str(v)


def _section_parse(parse: Callable[[], Any]) -> tuple[Any, InputError | None]:
    """(options, None), or (None, the error) when the error is about the body (located in
    the body file: that section says why it is not there); an error about a value the user
    gave is raised (exit 2)."""
    try:
        return parse(), None
    except InputError as exc:
        if exc.where is None:
            raise
        return None, exc


def _speed(text: Any) -> tuple[Any, Any]:
    """--speed takes its meaning from its unit: (angular speed, speed), one of them None."""
    from rbcli.io import units as un

    s = _text(text)
    try:
        w = un.to_si(s, "angular_speed")
    except un.UnitError:
        try:
            v = un.to_si(s, "speed")
        except un.UnitError:
            raise InputError(
                f"--speed: give a unit: an angular speed (e.g. '3000 rpm', '100 rad/s') for balance "
                f"and rolling, or a speed (e.g. '20 km/h', '5 m/s') for rolling; got '{s}'",
                param="speed") from None
        if not math.isfinite(v):
            raise ParamError("speed", "must be a finite number")
        return None, text
    if not (w > 0.0 and math.isfinite(w)):
        raise ParamError("speed", f"must be a positive angular speed, got '{s}'")
    return text, None


def _date() -> str:
    """The report's date: SOURCE_DATE_EPOCH when set (reproducible builds), else now; UTC."""
    import datetime as dt
    import os

    raw = os.environ.get("SOURCE_DATE_EPOCH")
    if raw is None or raw == "":
        t = dt.datetime.now(dt.timezone.utc)
    else:
        try:
            t = dt.datetime.fromtimestamp(int(raw.strip()), dt.timezone.utc)
        except (ValueError, OverflowError, OSError):
            raise InputError(
                f"SOURCE_DATE_EPOCH: must be a whole number of seconds since 1970-01-01 UTC, got '{raw}'"
            ) from None
    return t.strftime("%Y-%m-%d %H:%M UTC")


@dataclass(frozen=True)
class ReportOptions:
    """The report's options, read once through each command's options object.

    Attributes
    ----------
    given : tuple of (str, str) — the options given, as (option, text), for the header
    balance : BalanceOptions or None — None when the body has no shaft and no balance
        option is given (``balance_skip`` says so), or the body cannot have one
        (``balance_error``)
    precess : PrecessOptions or None — None without ``omega``
    top : TopOptions or None — None without a pivot or without ``spin`` and ``theta``
        (``top_skip`` says which)
    rollcheck : RollcheckOptions or None — None without a rim radius (``rolling_skip``) or
        when the body cannot roll (``rolling_error``)
    units : DisplayUnits — the units of the tables (``units``)
    digits : int — significant figures in the tables (1 to 17)
    date : str — the report's date, UTC: SOURCE_DATE_EPOCH when set, else now
    """

    given: tuple[tuple[str, str], ...]
    balance: BalanceOptions | None
    precess: PrecessOptions | None
    top: TopOptions | None
    rollcheck: RollcheckOptions | None
    units: DisplayUnits
    digits: int
    date: str
    balance_skip: str | None = None
    balance_error: InputError | None = None
    top_skip: str | None = None
    rolling_skip: str | None = None
    rolling_error: InputError | None = None

    @classmethod
    def parse(cls, body: Body, *, shaft=None, through=None, planes=None, radius=None,
              bearings=None, grade=None, speed=None, omega=None, pivot=None, spin=None,
              theta=None, theta_dot=None, phi_dot=None, rim_radius=None, tyre_radius=None,
              g=None, symmetry_tol=None, digits=6, units=None) -> ReportOptions:
        """Read the keyword arguments of :func:`report` (see there) for ``body``.

        Raises
        ------
        rbcli.InputError
            with the message the command line prints (``--planes: ...``).
        """
        from rbcli.api import options as op
        from rbcli.api.balance import BalanceOptions
        from rbcli.api.precess import PrecessOptions
        from rbcli.api.rollcheck import RollcheckOptions, round_parts
        from rbcli.api.top import TopOptions
        from rbcli.render.fmt import DisplayUnits

        kw = dict(shaft=shaft, through=through, planes=planes, radius=radius, bearings=bearings,
                  grade=grade, speed=speed, omega=omega, pivot=pivot, spin=spin, theta=theta,
                  theta_dot=theta_dot, phi_dot=phi_dot, rim_radius=rim_radius,
                  tyre_radius=tyre_radius, g=g, symmetry_tol=symmetry_tol)
        given = tuple((f"--{k.replace('_', '-')}", _text(kw[k])) for k in _OPTIONS if kw[k] is not None)
        if isinstance(digits, bool) or not isinstance(digits, int) or not 1 <= digits <= 17:
            raise ParamError("digits", f"must be a whole number from 1 to 17, got {digits!r}")
        du = DisplayUnits.parse(units)
        date = _date()
        # --speed: its unit says whose it is (the report's own rule)
        rotor_speed = roll_speed = None
        if speed is not None:
            rotor_speed, roll_speed = _speed(speed)
        if grade is not None:
            if rotor_speed is None:
                raise ParamError("grade", "needs an angular --speed, the maximum service speed "
                                 "(e.g. --speed '3000 rpm')")
            if bearings is None:
                raise ParamError("grade", "needs --bearings z1,z2, the planes ISO 21940-11 "
                                 "allocates the tolerance to")
        # the options the report names differently from rollcheck (--shaft for --axle,
        # --rim-radius for --radius), read under the report's names
        axle = op.direction(shaft, "--shaft") if shaft is not None else None
        rim = (op.positive(op.Units.of(body).quantity(rim_radius, "length", "--rim-radius"), "--rim-radius",
                           "the rim radius") if rim_radius is not None else None)

        # balance
        b_opts, b_err = _section_parse(lambda: BalanceOptions.parse(
            body, shaft=shaft, through=through, planes=planes, radius=radius, speed=rotor_speed,
            bearings=bearings, g=g, grade=grade))
        asked = planes is not None or bearings is not None or grade is not None or rotor_speed is not None
        b_skip = None
        if shaft is None and body.shaft is None and not asked:
            b_opts, b_err = None, None
            b_skip = ("balance: no shaft in the body file and no --shaft, --planes, --bearings or "
                      "rotation --speed option")
        # free precession
        p_opts = PrecessOptions.parse(body, omega=omega) if omega is not None else None
        # heavy top: every value given is checked, the section needs a pivot, spin and theta
        t_opts = TopOptions.parse(
            body, pivot=pivot, spin=_TOP_STAND_INS["spin"] if spin is None else spin,
            theta=_TOP_STAND_INS["theta"] if theta is None else theta, theta_dot=theta_dot,
            phi_dot=phi_dot, g=g, symmetry_tol=symmetry_tol)
        t_skip = None
        if pivot is None and body.pivot is None:
            t_skip = "heavy top: no pivot in the body file and no --pivot option"
        elif spin is None or theta is None:
            missing = " and ".join(x for x, v in (("--spin", spin), ("--theta", theta)) if v is None)
            t_skip = (f"heavy top: the body has a pivot, but no {missing} given (the spin about the "
                      "symmetry axis and the start tilt from the vertical)")
        if t_skip is not None:
            t_opts = None
        # rolling stability
        r_opts, r_err = _section_parse(lambda: RollcheckOptions.parse(
            body, axle=axle, through=through, radius=rim, tyre_radius=tyre_radius, g=g,
            speed=roll_speed, spin=rotor_speed, symmetry_tol=symmetry_tol))
        r_skip = None
        if rim is None and body.rim_radius is None and not round_parts(body):
            r_opts, r_err = None, None
            r_skip = ("rolling stability: no rim radius: none in the body file (rim_radius), no "
                      "--rim-radius option and no round part")
        return cls(given=given, balance=b_opts, precess=p_opts, top=t_opts, rollcheck=r_opts,
                   units=du, digits=digits, date=date, balance_skip=b_skip, balance_error=b_err,
                   top_skip=t_skip, rolling_skip=r_skip, rolling_error=r_err)

    def text(self) -> str:
        """The options given, as a shell would take them (the header's "options" line)."""
        import shlex

        return " ".join(f"{k} {shlex.quote(v)}" for k, v in self.given)


# ----------------------------------------------------------------------------- the result


@dataclass(frozen=True)
class ReportResult(Result):
    """The report of a body: its sections, rendered, and the checks that failed.

    Attributes
    ----------
    name : str — the body's name
    document : rbcli.render.report.Report — the whole report (header, sections, input file)
    failed : tuple of str — the checks asked for that failed, in words (``--grade``,
        rolling at ``--speed``); the report is complete all the same
    warnings : tuple of str — the sections' warnings (the report shows them in its sections)

    Methods: ``html()`` and ``markdown(files_dir)`` give the document's text (Markdown with
    its figures, ``{file name: SVG text}``, for the folder ``files_dir``); ``to_json()``
    lists the sections; ``return_code`` is 1 when a check failed.
    """

    name: str
    document: Report
    failed: tuple[str, ...] = ()
    warnings: tuple[str, ...] = field(default=())

    @property
    def sections(self) -> tuple[Section, ...]:
        """The sections in order (a left-out one has ``skipped``: its one-line reason)."""
        return tuple(self.document.sections)

    @property
    def return_code(self) -> int:
        """1 when a check asked for failed (the grade, rolling at the speed), else 0."""
        return 1 if self.failed else 0

    def html(self) -> str:
        """The report as one self-contained HTML5 document."""
        from rbcli.render import report as R

        return R.html(self.document)

    def markdown(self, files_dir: str = "report_files") -> tuple[str, dict[str, str]]:
        """The report as Markdown (figures linked as ``files_dir/NAME.svg``) and its figures."""
        from rbcli.render import report as R

        return R.markdown(self.document, files_dir)

    def to_json(self) -> dict[str, Any]:
        """The sections (key, title, whether included, why not) and the failed checks.
        (``rbcli report`` has no ``--json``; this is for scripts.)"""
        return {
            "name": self.name,
            "sections": [{"key": s.key, "title": s.title, "included": s.skipped is None,
                          "reason": s.skipped} for s in self.document.sections],
            "failed": list(self.failed),
            "warnings": list(self.warnings),
        }


# ----------------------------------------------------------------------------- the sections


class _Ctx:
    """What the section builders share: the body, the options, the failed checks."""

    def __init__(self, body: Body, opts: ReportOptions) -> None:
        from rbcli.core.inertia import body_mass_props

        self.body = body
        self.opts = opts
        self.du = opts.units
        self.digits = opts.digits
        self.failed: list[str] = []
        self.warnings: list[str] = []
        self.mp = body_mass_props(body)


def _section(key: str, title: str) -> Section:
    from rbcli.render.report import Section

    return Section(key, title)


def _skip(key: str, title: str, reason: str) -> Section:
    from rbcli.render.report import Section

    return Section.skip(key, title, reason)


def _note(text: str) -> Any:
    from rbcli.render.text import Note

    return Note(text)


def _options_table(doc: Any, options: Any) -> None:
    """A section's options as understood (the command's "options" table): option, value in
    the body's units, unit; nothing when no option was given."""
    from rbcli.render.text import Heading

    echo = getattr(options, "echo", ())
    if echo:
        at = 1 if doc.items and isinstance(doc.items[0], Heading) else 0
        doc.table("options", ("option", "value", "unit"), echo, right=(1,))
        doc.items.insert(at, doc.items.pop())


def _figure(s: Section, name: str, fig: Any, caption: str) -> None:
    """Add a figure (what a command's --plot draws) as inline SVG: in memory, no file."""
    from rbcli.render.plots import figure_bytes
    from rbcli.render.report import Figure

    s.items.append(Figure(name, caption, figure_bytes(fig, "svg").decode("utf-8")))


def _parts(ctx: _Ctx) -> Section:
    from rbcli.core.inertia import part_contributions
    from rbcli.render.report import parts_table
    from rbcli.render.text import Doc

    s = _section("parts", "Parts")
    doc = Doc()
    parts_table(doc, ctx.body, ctx.mp, part_contributions(ctx.body.parts, ctx.mp.com), ctx.du, ctx.digits)
    s.add_doc(doc)
    return s


def _massprops(ctx: _Ctx) -> Section:
    from rbcli.api.massprops import InertiaOptions, run_inertia
    from rbcli.render import massprops as r
    from rbcli.render.text import Doc

    res = run_inertia(ctx.body, InertiaOptions.parse(ctx.body))
    doc = Doc()
    r.inertia_doc(doc, ctx.body, res, ctx.du, ctx.digits, "tensor", res.reference_label, parts=False)
    s = _section("mass-properties", "Mass properties")
    s.add_doc(doc, drop_heading_prefix=ctx.body.name)
    return s


def _principal(ctx: _Ctx) -> Section:
    from rbcli.api.massprops import PrincipalOptions, run_principal
    from rbcli.render import massprops as r
    from rbcli.render.bodyplot import body_figure
    from rbcli.render.text import Doc

    b = ctx.body
    pr = run_principal(b, PrincipalOptions.parse(b))
    doc = Doc()
    r.principal_doc(doc, b, pr, ctx.du, ctx.digits, "the com", parts=False)
    s = _section("principal-axes", "Principal axes")
    s.add_doc(doc, drop_heading_prefix=b.name)
    from rbcli.render.bodyplot import CAPTION

    fig = body_figure(b, ctx.mp.com, pr, ctx.du,
                      f"principal: {b.name} — the body as built, centre of mass and principal axes")
    _figure(s, "body", fig, CAPTION)
    return s


def _balance(ctx: _Ctx) -> Section:
    key, title = "balance", "Balance"
    o = ctx.opts
    if o.balance_skip is not None:
        return _skip(key, title, o.balance_skip)
    if o.balance_error is not None:
        return _skip(key, title, f"balance: not computed: {o.balance_error}")
    from rbcli.api import balance as api
    from rbcli.render import balance as rb
    from rbcli.render.text import Doc

    b, bo = ctx.body, o.balance
    try:
        res = api.run(b, bo)
    except InputError as exc:
        return _skip(key, title, f"balance: not computed: {exc}")
    doc = Doc()
    su = rb.ShopUnits(None if ctx.du.si else ",".join(u for _, u in (ctx.du.length, ctx.du.mass, ctx.du.time)))
    rb.document(doc, res, su, ctx.digits)
    _options_table(doc, bo)
    s = _section(key, title)
    s.add_doc(doc, drop_heading_prefix=b.name)
    for w in res.warnings:
        s.items.append(_note(f"warning: {w}"))
        ctx.warnings.append(w)
    if res.iso is not None and not res.iso.passed:
        ctx.failed.append(f"balance: the rotor as given fails ISO 21940-11 G{res.iso.grade:g}")
    if not (bo.planes or bo.speed or bo.bearings):
        s.items.append(_note("(corrections, bearing forces and the ISO grade need --planes, --speed with "
                             "a rotation unit, --bearings and --grade)"))
    from rbcli.render import balanceplot

    _figure(s, "balance", balanceplot.plot(res.diagram(), su),
            "The polar (vector) diagram, as `rbcli balance --plot` draws it: the unbalance per plane "
            "and, with --planes, the corrections and the residual, as arrows on the rotor's dial "
            "(angles as the tables count them).")
    return s


def _precess(ctx: _Ctx) -> Section:
    key, title = "free-precession", "Free precession"
    if ctx.opts.precess is None:
        return _skip(key, title, "free precession: no --omega given (the initial angular velocity, body frame)")
    from rbcli.api import precess as api
    from rbcli.render import precess as rp
    from rbcli.render.text import Doc

    b = ctx.body
    try:
        result = api.run(b, ctx.opts.precess)
    except InputError as exc:
        return _skip(key, title, f"free precession: not computed: {exc}")
    doc = Doc()
    rp.document(doc, b, result, ctx.du, ctx.digits)
    _options_table(doc, ctx.opts.precess)
    s = _section(key, title)
    s.add_doc(doc, drop_heading_prefix=b.name)
    _figure(s, "precess", rp.plot(b, result.motion, None, ctx.du),
            "The angular velocity in the body frame against time and the polhode (as rbcli precess --plot).")
    return s


def _top(ctx: _Ctx) -> Section:
    key, title = "heavy-top", "Heavy top"
    o = ctx.opts
    if o.top is None:
        return _skip(key, title, o.top_skip or "heavy top: not computed")
    from rbcli.api import top as at
    from rbcli.render import top as rt
    from rbcli.render.text import Doc

    b = ctx.body
    try:
        res = at.run(b, o.top)
        span = res.default_duration()
    except InputError as exc:
        return _skip(key, title, f"heavy top: not computed: {exc}")
    ctx.warnings.extend(res.warnings)
    doc = Doc()
    rt.document(doc, res, ctx.du, ctx.digits)
    _options_table(doc, o.top)
    s = _section(key, title)
    s.add_doc(doc, drop_heading_prefix=b.name)
    _figure(s, "top", rt.plot(res, res.sample(span), span),
            "The path of the axis (as rbcli top --plot), over three nutation periods.")
    return s


def _rollcheck(ctx: _Ctx) -> Section:
    key, title = "rolling-stability", "Rolling stability"
    o = ctx.opts
    if o.rolling_skip is not None:
        return _skip(key, title, o.rolling_skip)
    from rbcli.api import rollcheck as ar

    if o.rolling_error is not None:
        return _skip(key, title, f"rolling stability: not computed: {o.rolling_error}")
    from rbcli.render import rollcheck as rr
    from rbcli.render.text import Doc

    b = ctx.body
    try:
        res = ar.run(b, o.rollcheck)
    except ar.OffCentreRim as exc:  # a cone or a top on its base rim: not a wheel
        return _skip(key, title, f"rolling stability: left out: {exc.reason}")
    except InputError as exc:
        return _skip(key, title, f"rolling stability: not computed: {exc}")
    doc = Doc()
    rr.document(doc, res, ctx.du, ctx.digits)
    _options_table(doc, o.rollcheck)
    s = _section(key, title)
    s.add_doc(doc, drop_heading_prefix=b.name)
    for w in res.warnings:
        s.items.append(_note("warning: " + w))
        ctx.warnings.append(w)
    if res.return_code:
        ctx.failed.append("rolling: straight rolling at --speed is unstable")
    _figure(s, "rollcheck", rr.plot(res, res.curves()),
            "Lean frequency squared and growth rate against speed (as rbcli rollcheck --plot).")
    return s


#: (progress text, section key, title, builder), in the report's order
STEPS = (
    ("parts", "parts", "Parts", _parts),
    ("mass properties", "mass-properties", "Mass properties", _massprops),
    ("principal axes", "principal-axes", "Principal axes", _principal),
    ("balance", "balance", "Balance", _balance),
    ("free precession", "free-precession", "Free precession", _precess),
    ("heavy top", "heavy-top", "Heavy top", _top),
    ("rolling stability", "rolling-stability", "Rolling stability", _rollcheck),
)


def _guarded(ctx: _Ctx, what: str, key: str, title: str, fn: Callable[[_Ctx], Section]) -> Section:
    """``fn(ctx)``, the section, or one line saying why it is not there when its numbers are
    too large or too small to compute with (an arithmetic error, or inf/NaN in one of its
    tables, which the commands refuse too): that is this body and these options, not a bug."""
    from rbcli.errors import NonFiniteResult
    from rbcli.render.text import check_finite_doc

    n_failed, n_warned = len(ctx.failed), len(ctx.warnings)
    try:
        s = fn(ctx)
        check_finite_doc(s)
    except (OverflowError, ZeroDivisionError, FloatingPointError, NonFiniteResult) as exc:
        del ctx.failed[n_failed:]  # a check of a section that is not there has not failed
        del ctx.warnings[n_warned:]
        if not isinstance(exc, NonFiniteResult):
            exc = f"a value is too large or too small to compute with ({exc})"
        return _skip(key, title, f"{what}: not computed: {exc}")
    return s


def run(body: Body, options: ReportOptions,
        progress: Callable[[str, int, int], None] | None = None) -> ReportResult:
    """The report of ``body`` with parsed ``options`` (:meth:`ReportOptions.parse`).

    ``progress(what, i, n)``, if given, is called before each of the ``n`` sections.
    A section that cannot be computed is one line in the report, never an error.
    """
    import hashlib

    from rbcli import __version__
    from rbcli.render import report as R

    ctx = _Ctx(body, options)
    sections = []
    for i, (what, key, title, fn) in enumerate(STEPS):
        if progress is not None:
            progress(what, i, len(STEPS))
        sections.append(_guarded(ctx, what, key, title, fn))
    du = options.units
    meta = [("body", body.name)]
    if body.description:
        meta.append(("description", body.description))
    meta += [
        ("input file", body.source),
        ("SHA-256 of the input file", hashlib.sha256(body.text.encode("utf-8")).hexdigest()),
        ("options", options.text() or "(none)"),
        ("units in tables", "SI" if du.si else ", ".join(u for _, u in (du.length, du.mass, du.time))),
        ("rbcli version", __version__),
        ("date", options.date),
    ]
    doc = R.Report(title=f"rbcli report: {body.name}", meta=meta, sections=sections,
                   input_name=body.source, input_text=body.text, generator=f"rbcli {__version__}")
    return ReportResult(name=body.name, document=doc, failed=tuple(ctx.failed),
                        warnings=tuple(ctx.warnings))


# ----------------------------------------------------------------------------- writing


def check_output(path: Any, body: Body, *, force: bool = False) -> tuple[str, Any, Any]:
    """(format ".html" or ".md", the path, its figures folder), checked by
    :mod:`rbcli.io.outfile` before anything is computed: never an input file (the body, its
    includes, its meshes), never a link or a device; an existing report, or figures folder
    (treated as an output too), only with ``force``.

    Raises
    ------
    rbcli.InputError
        ``-o: ...`` as the command line prints it.
    """
    from rbcli.io import outfile

    p = outfile.check(path, body, "-o", force=force, exts=FORMATS)
    ext = p.suffix.lower()
    files = outfile.files_dir(p)
    if ext == ".md":
        outfile.check_folder(files, body, "-o", force=force)
    return ext, p, files


def write(result: ReportResult, path: Any, fmt: str, files_dir: Any, *, force: bool = False) -> None:
    """Write the report (and a Markdown report's figures folder) all or nothing, through
    :func:`rbcli.io.outfile.write_document`: an existing report is replaced only with
    ``force``, checked and written in one step. ``fmt``, ``path`` and ``files_dir`` as
    :func:`check_output` gives them."""
    from rbcli.io.outfile import write_document

    if fmt == ".html":
        write_document(path, result.html(), "-o", replace=force)
    else:
        text, figures = result.markdown(files_dir.name)
        write_document(path, text, "-o", replace=force, folder=files_dir, files=figures)


def report(body: Body, path: Any = None, *, force: bool = False, shaft=None, through=None,
           planes=None, radius=None, bearings=None, grade=None, speed=None, omega=None,
           pivot=None, spin=None, theta=None, theta_dot=None, phi_dot=None, rim_radius=None,
           tyre_radius=None, g=None, symmetry_tol=None, digits: int = 6, units: str | None = None,
           format: str | None = None) -> str | ReportResult:  # noqa: A002 - the CLI's word
    """One document with every answer that applies to the body, its tables and figures.

    The same document ``rbcli report BODY -o FILE`` writes: the body (name, input file and
    its SHA-256, rbcli version, date), a parts table with each part's contribution to the
    inertia about the centre of mass, mass properties, principal axes with a figure, and,
    where the body file or the options give what they need, balance, free precession, the
    heavy top and rolling stability (each left-out section says why in one line).

    Parameters
    ----------
    body : rbcli.Body — from :func:`rbcli.load`
    path : str or path-like, optional — write the report there: ``.html`` (one
        self-contained file) or ``.md`` (figures in ``FILE_files/`` beside it), all or
        nothing; an existing file only with ``force``, an input never. Without it the
        document's text is returned.
    force : bool — replace an existing report (and figures folder)
    shaft : direction x,y,z — balance shaft and rolling axle (default: the body's shaft)
    through : "com", "origin" or a point x,y,z (m) — a point of the shaft
    planes : zA,zB (m) — balance correction planes along the shaft
    radius : r or rA,rB (m) — balance correction radius (default: the body's rim_radius)
    bearings : z1,z2 (m) — bearing positions along the shaft
    grade : "G6.3" or a number (mm/s) — ISO 21940-11 grade; needs an angular ``speed`` and
        ``bearings``
    speed : quantity string with a unit — an angular speed ("3000 rpm", rad/s) is the
        balance rotor speed and the rolling spin; a speed ("20 km/h", m/s) is the rolling
        speed; a bare number is refused
    omega : x,y,z (rad/s) — free precession: the initial angular velocity, body frame
    pivot : "com", "origin" or x,y,z (m) — heavy top: the fixed point (default: the body's)
    spin : rad/s — heavy top: spin about the symmetry axis
    theta : degrees (or a quantity string) — heavy top: start tilt from the vertical
    theta_dot, phi_dot : rad/s — heavy top: start rates (default 0)
    rim_radius : m — rolling: rim radius (default: the body's, else the largest round part)
    tyre_radius : m — rolling: tube radius of a rounded rim (default 0)
    g : m/s² — gravity for the top, rolling and static bearing loads (default 9.80665)
    symmetry_tol : relative (0.01) or "1 %" — heavy top and rolling: how far the two moments
        across the axis may differ (answered for the symmetrised body, with a warning)
    digits : int — significant figures in the tables, 1 to 17
    units : str — units of the tables, e.g. "mm,g" (default SI)
    format : "html" or "md" — without ``path`` (default "html"); with ``path`` it must
        agree with the file's extension. Markdown without a path links its figures as
        ``report_files/NAME.svg``: ``run(...).markdown(folder)`` gives the figures too.

    Returns
    -------
    str
        without ``path``: the document's text (the same bytes ``rbcli report`` writes
        for the same options; set SOURCE_DATE_EPOCH for a fixed date).
    ReportResult
        with ``path``, after writing: ``return_code`` is 1 when a check asked for failed
        (``failed`` says which), as the command's exit status.

    Raises
    ------
    rbcli.InputError
        with the message the command line prints, for a value a command refuses or an
        output path that may not be written.

    Examples
    --------
    >>> import rbcli
    >>> body = rbcli.load("examples/top.yaml")
    >>> html = rbcli.report(body, spin=150, theta=30)           # doctest: +SKIP
    >>> rbcli.report(body, "top.md", spin=150, theta=30).return_code  # doctest: +SKIP
    0
    """
    from rbcli.api import options as op

    fmt = None
    if format is not None:
        fmt = "." + op.choice(format, "--format", ("html", "md"))
    checked = None
    if path is not None:
        checked = check_output(path, body, force=force)
        if fmt is not None and fmt != checked[0]:
            raise ParamError("format", f"'{format}' does not match the file '{path}' ({checked[0]})")
    options = ReportOptions.parse(
        body, shaft=shaft, through=through, planes=planes, radius=radius, bearings=bearings,
        grade=grade, speed=speed, omega=omega, pivot=pivot, spin=spin, theta=theta,
        theta_dot=theta_dot, phi_dot=phi_dot, rim_radius=rim_radius, tyre_radius=tyre_radius,
        g=g, symmetry_tol=symmetry_tol, digits=digits, units=units)
    result = run(body, options)
    if checked is not None:
        write(result, checked[1], checked[0], checked[2], force=force)
        return result
    if fmt == ".md":
        return result.markdown()[0]
    return result.html()
