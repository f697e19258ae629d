"""Every answer that applies to a body, computed for one document: the service behind
``rbcli report``.

:func:`parse` reads each section's parameters by its command's own ``parse`` (a value means
what it means to the command); :func:`run` computes each section, or the one-line reason it
is left out (which sections apply when: ``rbcli report --help``)."""

from __future__ import annotations

import dataclasses
import datetime as dt
import math
import os
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, NamedTuple

from rbcli.api import balance, check, precess, rollcheck, top, whirl
from rbcli.api import inertia as api_inertia
from rbcli.api import options as op
from rbcli.api import principal as api_principal
from rbcli.api.commands import REPORT
from rbcli.api.params import Options, function
from rbcli.api.result import Result, frozen, jsonable
from rbcli.api.whirlbearings import entries
from rbcli.core.inertia import body_mass_props, part_contributions
from rbcli.env import clean
from rbcli.errors import InputError, NonFiniteResult, Note, ParamError, literal
from rbcli.io import units as un

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body

__all__ = ["ReportOptions", "ReportResult", "Section", "parse", "report", "run"]

#: stand-ins for a missing spin or theta, so that the one given is still checked by
#: top.parse (the heavy-top section is then left out, saying what is missing)
_TOP_STAND_INS = {"spin": 1.0, "theta": 90.0}


# --- options


def _text(v: Any) -> str:
    """A value as the header's options line shows it (strings as typed, numbers exactly)."""
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
    """The report's speed takes its meaning from its unit: (angular speed, speed), one of them None."""
    s = _text(text)
    try:
        w = un.to_si(s, "angular_speed")
    except un.UnitError:
        try:
            v = un.to_si(s, "speed")
        except un.UnitError:
            raise ParamError(
                "speed", "give a unit: an angular speed (e.g. '3000 rpm', '100 rad/s') for balance "
                f"and rolling, or a speed (e.g. '20 km/h', '5 m/s') for rolling; got '{literal(s)}'"
            ) from None
        if not math.isfinite(v):
            raise ParamError("speed", "must be a finite number")
        return None, text
    if not (w > 0.0 and math.isfinite(w)):
        raise ParamError("speed", f"must be a positive angular speed, got '{literal(s)}'")
    return text, None


def _date() -> str:
    """The report's date: SOURCE_DATE_EPOCH when set (reproducible builds), else now; UTC."""
    raw = os.environ.get("SOURCE_DATE_EPOCH")
    if raw is None or raw == "":
        t = dt.datetime.now(dt.timezone.utc)
    else:
        try:
            t = dt.datetime.fromtimestamp(int(raw.strip()), dt.timezone.utc)
        except (ValueError, OverflowError, OSError):
            raise InputError(
                "SOURCE_DATE_EPOCH: must be a whole number of seconds since 1970-01-01 UTC, got "
                f"'{literal(raw)}'") from None
    return t.strftime("%Y-%m-%d %H:%M UTC")


@dataclass(frozen=True)
class ReportOptions:
    """The report's parameters (:func:`parse`): ``given`` ((parameter, text) pairs, for the
    header); each section's options (``balance``, ``whirl``, ...; None when left out, its
    ``..._skip`` says why, ``whirl_error`` the body's); ``date`` (UTC, :func:`_date`).
    """

    given: tuple[tuple[str, str], ...]
    balance: Options | None
    whirl: Options | None
    precess: Options | None
    top: Options | None
    rollcheck: Options | None
    date: str
    balance_skip: str | None = None
    whirl_skip: str | None = None
    whirl_error: InputError | None = None
    top_skip: str | None = None
    rolling_skip: str | None = None


def _whirl_options(body: Body, kw: dict[str, Any], speed: Any) -> tuple[Any, Any, Any]:
    """(whirl's options, the body's error, why it is left out): with a bearing stiffness,
    given or the body's bearings."""
    if kw.get("stiffness") is not None or entries(body) is not None:
        opts, err = _section_parse(lambda: whirl.parse(
            body, bearings=kw.get("bearings"), stiffness=kw.get("stiffness"),
            damping=kw.get("damping"), speed=speed, shaft=kw.get("shaft"),
            through=kw.get("through"), symmetry_tol=kw.get("symmetry_tol")))
        return opts, err, None
    if kw.get("damping") is not None:
        raise ParamError("damping", "needs {stiffness}, the bearings' stiffness (the whirl "
                         "section)")
    return None, None, Note("whirl: no {stiffness} given (the bearings' stiffness, with "
                            "{bearings})")


def _top_options(body: Body, kw: dict[str, Any]) -> tuple[Any, Any]:
    """(top's options, why it is left out): every value given is checked, the section needs
    a pivot, spin and theta."""
    spin, theta = kw.get("spin"), kw.get("theta")
    opts = top.parse(body, pivot=kw.get("pivot"),
                     spin=_TOP_STAND_INS["spin"] if spin is None else spin,
                     theta=_TOP_STAND_INS["theta"] if theta is None else theta,
                     theta_dot=kw.get("theta_dot"), phi_dot=kw.get("phi_dot"), g=kw.get("g"),
                     symmetry_tol=kw.get("symmetry_tol"))
    if kw.get("pivot") is None and body.pivot is None:
        return None, Note("heavy top: no pivot in the body file and no {pivot} option")
    if spin is None or theta is None:
        missing = " and ".join(x for x, v in (("{spin}", spin), ("{theta}", theta)) if v is None)
        return None, Note(f"heavy top: the body has a pivot, but no {missing} given (the spin "
                          "about the symmetry axis and the start tilt from the vertical)")
    return opts, None


def parse(body: Body, **kwargs: Any) -> ReportOptions:
    """The keyword arguments of :func:`report` read for ``body``, each section's by its
    command's ``parse``; an InputError names the parameter at fault."""
    kw = {k: v for k, v in kwargs.items() if v is not None}
    # the header lists the options in the table's order, the tolerance last
    order = sorted((p.name for p in REPORT), key=lambda n: n == "symmetry_tol")
    given = tuple((k, _text(kw[k])) for k in order if k in kw)
    date = _date()
    # speed: its unit says whose it is (the report's own rule)
    rotor_speed, roll_speed = _speed(kw["speed"]) if "speed" in kw else (None, None)
    if "grade" in kw and rotor_speed is None:
        raise ParamError("grade", "needs an angular {speed}, the maximum service speed (e.g. "
                         "{speed} '3000 rpm')")
    if "grade" in kw and "bearings" not in kw:
        raise ParamError("grade", "needs {bearings} z1,z2, the planes ISO 21940-11 allocates the "
                         "tolerance to")
    # read under the report's names what rollcheck names differently
    axle = op.direction(kw["shaft"], "shaft") if "shaft" in kw else None
    rim = (op.Units.of(body).positive(kw["rim_radius"], "length", "rim_radius", "the rim radius")
           if "rim_radius" in kw else None)
    b_opts = balance.parse(body, shaft=kw.get("shaft"), through=kw.get("through"),
                           planes=kw.get("planes"), radius=kw.get("radius"), speed=rotor_speed,
                           bearings=kw.get("bearings"), g=kw.get("g"), grade=kw.get("grade"))
    b_skip = None
    asked = {"shaft", "planes", "bearings", "grade"} & set(kw) or rotor_speed is not None
    if body.shaft is None and not asked:
        b_opts, b_skip = None, Note("balance: no shaft in the body file and no {shaft}, {planes}, "
                                    "{bearings} or rotation {speed} option")
    w_opts, w_err, w_skip = _whirl_options(body, kw, rotor_speed)
    p_opts = precess.parse(body, omega=kw["omega"]) if "omega" in kw else None
    t_opts, t_skip = _top_options(body, kw)
    r_opts = rollcheck.parse(body, shaft=axle, through=kw.get("through"), rim_radius=rim,
                             tyre_radius=kw.get("tyre_radius"), g=kw.get("g"),
                             rolling_speed=roll_speed, spin=rotor_speed,
                             symmetry_tol=kw.get("symmetry_tol"))
    r_skip = None
    if rim is None and body.rim_radius is None and not rollcheck.round_parts(body):
        r_opts, r_skip = None, Note("rolling stability: no rim radius: none in the body file "
                                    "(rim_radius), no {rim_radius} option and no round part")
    return ReportOptions(given=given, balance=b_opts, whirl=w_opts, precess=p_opts, top=t_opts,
                         rollcheck=r_opts, date=date, balance_skip=b_skip, whirl_skip=w_skip,
                         whirl_error=w_err, top_skip=t_skip, rolling_skip=r_skip)


# --- the result


@dataclass(frozen=True)
class Section:
    """One section of the report: ``key`` (the anchor), ``title``, ``result`` (the command's
    result; for "parts" the body's mass properties) or ``skipped`` (why not, one line),
    ``options`` (the command's, for its "options" table), ``figure`` (what its figure draws,
    computed) and ``warnings``."""

    key: str
    title: str
    result: Any = None
    skipped: str | None = None
    options: Any = None
    figure: Any = None
    warnings: tuple[str, ...] = ()

    def to_json(self) -> dict[str, Any]:
        """key, title, whether the section is in the report, and why not."""
        return {"key": self.key, "title": self.title, "included": self.skipped is None,
                "reason": self.skipped}


@dataclass(frozen=True)
class ReportResult(Result):
    """The report of a body: ``name``, ``body``, ``options`` (:class:`ReportOptions`),
    ``sections``, ``failed`` (the checks asked for that failed, in words: ``return_code`` 1)
    and ``warnings``. ``to_json()`` lists the sections."""

    name: str
    body: Body
    options: ReportOptions
    sections: tuple[Section, ...]
    failed: tuple[str, ...] = ()
    warnings: tuple[str, ...] = field(default=())

    def __post_init__(self) -> None:
        """Every field made immutable but the body (immutable already: walking its parts
        again cost 9 s for 100 000 parts)."""
        for f in dataclasses.fields(self):
            if f.name == "body":
                continue
            v = getattr(self, f.name)
            fv = frozen(v)
            if fv is not v:
                object.__setattr__(self, f.name, fv)

    @property
    def return_code(self) -> int:
        """1 when a check asked for failed (the grade, rolling at the speed), else 0."""
        return 1 if self.failed else 0

    def section(self, key: str) -> Section:
        """The section with this key (``"balance"``, ``"heavy-top"``, ...).

        Raises
        ------
        TypeError
            ``key`` that is not a string.
        KeyError
            a key no section has (the message lists the keys).
        """
        key = check.text(key, "key")
        for s in self.sections:
            if s.key == key:
                return s
        raise KeyError(f"no section {clean(repr(key), max_line=120)} (the sections: "
                       f"{', '.join(s.key for s in self.sections)})")

    def to_json(self) -> dict[str, Any]:
        """The sections (key, title, whether included, why not) and the failed checks."""
        return jsonable({
            "name": self.name,
            "sections": [s.to_json() for s in self.sections],
            "failed": list(self.failed),
            "warnings": list(self.warnings),
        })


# --- the sections


class _Ctx:
    """What the section builders share: the body, the options, the failed checks."""

    def __init__(self, body: Body, opts: ReportOptions) -> None:
        self.body = body
        self.opts = opts
        self.failed: list[str] = []
        self.mp = body_mass_props(body)


class _Step(NamedTuple):
    """One section of the report: its progress text (and the prefix of its one-line
    reasons), key, title and builder ``build(ctx, step)``."""

    what: str
    key: str
    title: str
    build: Callable[[_Ctx, _Step], Section]

    def section(self, result: Any, **kw: Any) -> Section:
        return Section(self.key, self.title, result, **kw)

    def skip(self, reason: Any) -> Section:
        return Section(self.key, self.title, skipped=reason)

    def not_computed(self, why: Any) -> Section:
        """``what: not computed: <why>`` (an InputError's parameters kept as parameters)."""
        if isinstance(why, InputError):
            why = f"{literal(why.where)}: {why.template}" if why.where else why.template
        return self.skip(Note(f"{self.what}: not computed: {why}"))


def _parts(ctx: _Ctx, s: _Step) -> Section:
    return s.section(ctx.mp, figure=part_contributions(ctx.body.parts, ctx.mp.com))


def _massprops(ctx: _Ctx, s: _Step) -> Section:
    o = api_inertia.parse(ctx.body)
    return s.section(api_inertia.run(ctx.body, o), options=o)


def _principal(ctx: _Ctx, s: _Step) -> Section:
    o = api_principal.parse(ctx.body)
    return s.section(api_principal.run(ctx.body, o), options=o)


def _balance(ctx: _Ctx, s: _Step) -> Section:
    o = ctx.opts
    if o.balance_skip is not None:
        return s.skip(o.balance_skip)
    try:
        res = balance.run(ctx.body, o.balance)
    except InputError as exc:
        return s.not_computed(exc)
    if res.iso_check is not None and not res.iso_check.passed:
        ctx.failed.append(f"balance: the rotor as given fails ISO 21940-11 G{res.iso_check.grade:g}")
    return s.section(res, options=o.balance, figure=res.diagram(), warnings=res.warnings)


def _whirl(ctx: _Ctx, s: _Step) -> Section:
    o = ctx.opts
    if o.whirl_skip is not None:
        return s.skip(o.whirl_skip)
    if o.whirl_error is not None:
        return s.not_computed(o.whirl_error)
    try:
        res = whirl.run(ctx.body, o.whirl)
    except InputError as exc:
        return s.not_computed(exc)
    if res.return_code:
        ctx.failed.append("whirl: a separation margin fails, or a mode grows, at {speed}")
    return s.section(res, options=o.whirl, warnings=res.warnings)


def _precess(ctx: _Ctx, s: _Step) -> Section:
    if ctx.opts.precess is None:
        return s.skip(Note("free precession: no {omega} given (the initial angular velocity, "
                           "body frame)"))
    try:
        res = precess.run(ctx.body, ctx.opts.precess)
    except InputError as exc:
        return s.not_computed(exc)
    return s.section(res, options=ctx.opts.precess)


def _top(ctx: _Ctx, s: _Step) -> Section:
    o = ctx.opts
    if o.top is None:
        return s.skip(o.top_skip or "heavy top: not computed")
    try:
        res = top.run(ctx.body, o.top)
        span = res.default_duration()
        path = res.sample(span)
    except InputError as exc:
        return s.not_computed(exc)
    return s.section(res, options=o.top, figure=(path, span), warnings=res.warnings)


def _rollcheck(ctx: _Ctx, s: _Step) -> Section:
    o = ctx.opts
    if o.rolling_skip is not None:
        return s.skip(o.rolling_skip)
    try:
        res = rollcheck.run(ctx.body, o.rollcheck)
    except rollcheck.OffCentreRim as exc:  # a cone or a top on its base rim: not a wheel
        return s.skip(Note(f"rolling stability: left out: {literal(exc.reason)}"))
    except InputError as exc:
        return s.not_computed(exc)
    if res.return_code:
        ctx.failed.append("rolling: straight rolling at {speed} is unstable")
    return s.section(res, options=o.rollcheck, figure=res.curves(), warnings=res.warnings)


#: the sections, in the report's order
STEPS = (
    _Step("parts", "parts", "Parts", _parts),
    _Step("mass properties", "mass-properties", "Mass properties", _massprops),
    _Step("principal axes", "principal-axes", "Principal axes", _principal),
    _Step("balance", "balance", "Balance", _balance),
    _Step("whirl", "whirl", "Whirl: critical speeds and unbalance response", _whirl),
    _Step("free precession", "free-precession", "Free precession", _precess),
    _Step("heavy top", "heavy-top", "Heavy top", _top),
    _Step("rolling stability", "rolling-stability", "Rolling stability", _rollcheck),
)


def _without_part_rows(result: Any) -> Any:
    """``result`` without its rows of the body's parts, for the finiteness check: those were
    checked as the body was read, and again cost 3 s a section for 100 000 parts."""
    if dataclasses.is_dataclass(result) and getattr(result, "parts", None) and \
            "parts" in {f.name for f in dataclasses.fields(result)}:
        return dataclasses.replace(result, parts=())
    return result


def _guarded(ctx: _Ctx, step: _Step) -> Section:
    """The section ``step`` builds, or one line saying why not when its numbers are too large
    or too small to compute with (an arithmetic error, inf/NaN in its JSON): not a bug."""
    n_failed = len(ctx.failed)
    try:
        s = step.build(ctx, step)
        if s.result is not None and hasattr(s.result, "to_json"):
            jsonable(_without_part_rows(s.result).to_json())  # the commands' one finiteness check
    except (OverflowError, ZeroDivisionError, FloatingPointError, NonFiniteResult) as exc:
        del ctx.failed[n_failed:]  # a check of a section that is not there has not failed
        if isinstance(exc, NonFiniteResult):  # its parameters stay parameters (spelled when shown)
            return step.not_computed(exc.template or literal(exc))
        return step.not_computed(f"a value is too large or too small to compute with "
                                 f"({literal(exc)})")
    return s


def run(body: Body, options: ReportOptions,
        progress: Callable[[str, int, int], None] | None = None) -> ReportResult:
    """The report of ``body`` with parsed ``options``; ``progress(what, i, n)``, if given, is
    called before each of the ``n`` sections."""
    ctx = _Ctx(body, options)
    sections = []
    for i, step in enumerate(STEPS):
        if progress is not None:
            progress(step.what, i, len(STEPS))
        sections.append(_guarded(ctx, step))
    warnings = tuple(w for s in sections for w in s.warnings)
    return ReportResult(name=body.name, body=body, options=options, sections=tuple(sections),
                        failed=tuple(Note(f) for f in ctx.failed), warnings=warnings)


@function(REPORT)
def report(body: Body, **kwargs: Any) -> ReportResult:
    """Every answer that applies to the body, computed for one report: the sections
    ``rbcli report`` writes (:func:`rbcli.report_text`, :func:`rbcli.write_report`).

    Parameters
    ----------
    body : rbcli.Body
    {parameters}

    Returns
    -------
    ReportResult
        ``sections`` (each with its result or why it is left out), ``failed``, ``return_code``.

    Raises
    ------
    TypeError, rbcli.InputError
        A wrong type (:mod:`rbcli.api.check`) or value a command refuses, naming the parameter.

    Examples
    --------
    >>> import rbcli
    >>> r = rbcli.report(rbcli.load("examples/top.yaml"), spin=150, theta=30)
    >>> [s.key for s in r.sections if s.skipped is None]
    ['parts', 'mass-properties', 'principal-axes', 'heavy-top']"""
    return run(body, parse(body, **kwargs))
