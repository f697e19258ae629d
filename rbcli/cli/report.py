"""``rbcli report``: every answer that applies to a body, in one HTML or Markdown file."""

from __future__ import annotations

import typer

from rbcli.cli import common as c
from rbcli.cli.app import MANUAL, app

HELP = """One document with every answer that applies to the body, its tables and figures.

Writes -o FILE.html (one self-contained file: inline CSS and SVG figures, no scripts,
no network references; prints to PDF from a browser) or -o FILE.md (Markdown with its
figures in FILE_files/*.svg beside it). The report has the body (name, input file and
its SHA-256, rbcli version, date), a parts table with each part's contribution, mass
properties (as `inertia`), principal axes (as `principal`) with a picture of the
equivalent ellipsoid and box, and - where the body file or the options give what they
need - balance (the body's shaft, or --shaft, --planes, --bearings, --grade or a rotation
--speed), free precession (--omega), the heavy top (the body's pivot or --pivot, with
--spin and --theta) and rolling stability (a rim radius or a round part). A section that does not apply, or cannot be computed for this
body, says why in one line. The same input gives the same bytes when SOURCE_DATE_EPOCH
is set. Exit status 1 when a check asked for fails (--grade, rolling at --speed); the
report is written first.
"""

FORMATS = (".html", ".md")


@app.command(help=HELP)
def report(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    output: str = typer.Option(None, "-o", "--output", help="The report file: .html (self-contained) or .md (figures in FILE_files/). Required.", show_default=False),
    force: bool = typer.Option(False, "--force", help="Replace an existing report (never an input: the body file, a file it includes or a mesh it reads)."),
    shaft: str = typer.Option(None, "--shaft", help="Balance and rolling: shaft (axle) direction x,y,z (or x, y, z). Default: the body's shaft; without either there is no balance section.", show_default=False),
    through: str = typer.Option(None, "--through", help="Balance and rolling: a point of the shaft: com, origin or x,y,z (m; a unit after the last number applies to all, e.g. '0,0,50 mm'). Default: the body's shaft point, else the origin.", show_default=False),
    planes: str = typer.Option(None, "--planes", help="Balance: correction planes zA,zB along the shaft (m; a unit after the last number applies to both, e.g. '-100,100 mm').", show_default=False),
    radius: str = typer.Option(None, "--radius", help="Balance: correction radius r, or rA,rB (m, or with units as for --planes). Default: the body's rim_radius.", show_default=False),
    bearings: str = typer.Option(None, "--bearings", help="Balance: bearing positions z1,z2 along the shaft (m; a unit after the last number applies to both, e.g. '-50,150 mm').", show_default=False),
    grade: str = typer.Option(None, "--grade", help="Balance: ISO 21940-11 grade, e.g. G6.3; needs an angular --speed and --bearings.", show_default=False),
    speed: str = typer.Option(None, "--speed", help="With a unit: an angular speed ('3000 rpm', rad/s) is the balance rotor speed and the rolling spin; a speed ('20 km/h', m/s) is the rolling speed.", show_default=False),
    omega: str = typer.Option(None, "--omega", help="Free precession: initial angular velocity x,y,z, body frame (rad/s; a unit after the last number applies to all, e.g. '0,0,300 rpm').", show_default=False),
    pivot: str = typer.Option(None, "--pivot", help="Heavy top: the fixed point: com, origin or x,y,z (m; a unit after the last number applies to all, e.g. '0,0,-20 mm'). Default: the body's pivot; without either there is no top section.", show_default=False),
    spin: str = typer.Option(None, "--spin", help="Heavy top: spin about the symmetry axis (rad/s, or e.g. '3000 rpm').", show_default=False),
    theta: str = typer.Option(None, "--theta", help="Heavy top: start tilt of the axis from the upward vertical (degrees, or with units).", show_default=False),
    theta_dot: str = typer.Option(None, "--theta-dot", help="Heavy top: start rate theta' (rad/s, or with units). Default: 0.", show_default=False),
    phi_dot: str = typer.Option(None, "--phi-dot", help="Heavy top: start precession rate phi' (rad/s, or with units). Default: 0.", show_default=False),
    rim_radius: str = typer.Option(None, "--rim-radius", help="Rolling: rim radius (m, or with units). Default: the body's rim_radius, else the largest round part coaxial with the axle.", show_default=False),
    tyre_radius: str = typer.Option(None, "--tyre-radius", help="Rolling: tube radius of a rounded rim (m, or with units). Default: 0, a knife edge.", show_default=False),
    g: str = typer.Option(None, "--g", help="Gravity for the top, rolling and static bearing loads (m/s^2, or with units). Default: 9.80665 m/s^2.", show_default=False),
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    import time

    from rbcli.errors import InputError
    from rbcli.render.fmt import DisplayUnits

    t0 = time.monotonic()
    e = c.env()
    du = DisplayUnits.parse(units)
    if output is None:
        raise InputError("-o/--output: required: the report file, e.g. -o report.html or -o report.md")
    opts = _Options.parse(
        shaft=shaft, through=through, planes=planes, radius=radius, bearings=bearings, grade=grade,
        speed=speed, omega=omega, pivot=pivot, spin=spin, theta=theta, theta_dot=theta_dot,
        phi_dot=phi_dot, rim_radius=rim_radius, tyre_radius=tyre_radius, g=g,
    )
    date = _date()
    b = c.load_one(body, expr, e)
    fmt, out, files_dir = _check_output(output, force, b)

    progress = _Progress(t0)
    try:
        rep, failed = build(b, opts, du, digits, date, progress)
        progress.step("writing")
        from rbcli.render import report as R

        if fmt == ".html":
            _write(out, R.html(rep), force)
        else:
            text, figs = R.markdown(rep, files_dir.name)
            _write(out, text, force, files_dir, figs)
    finally:
        progress.stop()
    if failed:
        e.warn(f"rbcli: {out}: written; a check failed: {'; '.join(failed)}")
    c.finish(1 if failed else 0)


# ----------------------------------------------------------------------------- options


class _Options:
    """The section options, parsed to SI (bad usage is found before the body is read)."""

    @classmethod
    def parse(cls, **kw) -> "_Options":
        import math

        from rbcli.errors import InputError
        from rbcli.io import units as un

        o = cls()
        o.given = [(f"--{k.replace('_', '-')}", v) for k, v in kw.items()
                   if v is not None]
        o.shaft = c.direction(kw["shaft"], "--shaft") if kw["shaft"] is not None else None
        o.through = c.point(kw["through"], "--through") if kw["through"] is not None else None
        o.planes = (c.distinct(c.numbers(kw["planes"], "length", "--planes", counts=(2,)), "--planes", "correction planes")
                    if kw["planes"] is not None else None)
        o.radius = None
        if kw["radius"] is not None:
            o.radius = [c.positive(x, "--radius", "the correction radius")
                        for x in c.numbers(kw["radius"], "length", "--radius", counts=(1, 2))]
            if o.planes is None:
                raise InputError("--radius: needs the correction planes, --planes zA,zB")
        o.bearings = (c.distinct(c.numbers(kw["bearings"], "length", "--bearings", counts=(2,)), "--bearings", "bearings")
                      if kw["bearings"] is not None else None)
        o.grade = c.grade(kw["grade"]) if kw["grade"] is not None else None
        o.rotor_speed = o.roll_speed = o.roll_spin = None
        if kw["speed"] is not None:
            text = kw["speed"]
            try:
                w = un.to_si(text, "angular_speed")
            except un.UnitError:
                try:
                    o.roll_speed = un.to_si(text, "speed")
                except un.UnitError:
                    raise InputError(
                        f"--speed: give a unit: an angular speed (e.g. '3000 rpm', '100 rad/s') for balance "
                        f"and rolling, or a speed (e.g. '20 km/h', '5 m/s') for rolling; got '{text}'"
                    ) from None
            else:
                if not (w > 0.0 and math.isfinite(w)):
                    raise InputError(f"--speed: must be a positive angular speed, got '{text}'")
                o.rotor_speed = o.roll_spin = w
            if o.roll_speed is not None and not math.isfinite(o.roll_speed):
                raise InputError("--speed: must be a finite number")
        if o.grade is not None:
            if o.rotor_speed is None:
                raise InputError("--grade: needs an angular --speed, the maximum service speed (e.g. --speed '3000 rpm')")
            if o.bearings is None:
                raise InputError("--grade: needs --bearings z1,z2, the planes ISO 21940-11 allocates the tolerance to")
        o.omega = c.vector(kw["omega"], "angular_speed", "--omega") if kw["omega"] is not None else None
        if o.omega is not None and not all(math.isfinite(x) for x in o.omega):
            raise InputError("--omega: must be finite numbers")
        o.pivot = c.point(kw["pivot"], "--pivot") if kw["pivot"] is not None else None
        o.spin = c.finite(c.quantity(kw["spin"], "angular_speed", "--spin"), "--spin") if kw["spin"] is not None else None
        if o.spin == 0.0:
            raise InputError("--spin: must not be 0: a top without spin cannot stand; give e.g. --spin '3000 rpm'")
        o.theta = None
        if kw["theta"] is not None:
            o.theta = c.finite(c.quantity(kw["theta"], "angle", "--theta", bare="deg"), "--theta")
            if not (0.0 < o.theta < math.pi):
                raise InputError(f"--theta: the start tilt must be strictly between 0 and 180 degrees, got {kw['theta']}")
        o.theta_dot = o.phi_dot = 0.0
        if kw["theta_dot"] is not None:
            o.theta_dot = c.finite(c.quantity(kw["theta_dot"], "angular_speed", "--theta-dot"), "--theta-dot")
        if kw["phi_dot"] is not None:
            o.phi_dot = c.finite(c.quantity(kw["phi_dot"], "angular_speed", "--phi-dot"), "--phi-dot")
        o.rim_radius = None
        if kw["rim_radius"] is not None:
            o.rim_radius = c.quantity(kw["rim_radius"], "length", "--rim-radius")
            if not (o.rim_radius > 0.0 and math.isfinite(o.rim_radius)):
                raise InputError(f"--rim-radius: must be a positive length, got {kw['rim_radius']}")
        o.tyre_radius = c.quantity(kw["tyre_radius"], "length", "--tyre-radius") if kw["tyre_radius"] is not None else 0.0
        if not (o.tyre_radius >= 0.0 and math.isfinite(o.tyre_radius)):
            raise InputError(f"--tyre-radius: must be 0 (knife edge) or a positive length, got {kw['tyre_radius']}")
        o.g_given = kw["g"] is not None  # balance names --g among the options of an error only then
        o.g = c.quantity(kw["g"], "acceleration", "--g") if o.g_given else 9.80665
        if not (o.g > 0.0 and math.isfinite(o.g)):
            raise InputError(f"--g: gravity must be a positive number, got {kw['g']}")
        return o

    def text(self) -> str:
        import shlex

        return " ".join(f"{k} {shlex.quote(v)}" for k, v in self.given)


def _date() -> str:
    """The report's date: SOURCE_DATE_EPOCH when set (reproducible builds), else now; UTC."""
    import datetime as dt
    import os

    from rbcli.errors import InputError

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


def _check_output(output: str, force: bool, body):
    """(format, path, figures folder) for -o, checked by rbcli.io.outfile: never an input
    file (the body, its includes, its meshes), never a link or a device; an existing report
    or figures folder (a real folder of files, treated as an output too) only with --force."""
    from rbcli.io import outfile

    p = outfile.check(output, body, "-o", force=force, exts=FORMATS)
    ext = p.suffix.lower()
    files = outfile.files_dir(p)
    if ext == ".md":
        outfile.check_folder(files, body, "-o", force=force)
    return ext, p, files


def _write(path, text: str, force: bool, folder=None, figures=None) -> None:
    """Write the report (and a Markdown report's figures folder) all or nothing, through
    rbcli.io.outfile: an existing report is replaced only with --force, checked and
    written in one step."""
    from rbcli.io.outfile import write_document

    write_document(path, text, "-o", replace=force, folder=folder, files=figures)


class _Progress:
    """A transient progress line on standard error, only on a terminal and only once
    the report has taken more than a second (a timer shows it even while one long
    section is being computed)."""

    def __init__(self, t0: float, console=None, tty: bool | None = None) -> None:
        import sys
        import threading
        import time

        self.t0 = t0
        self.console = console  # a rich Console (tests); default: standard error
        self.bar = None
        self.task = None
        self.state = ("starting", 0, 0)
        self.stopped = False
        self.lock = threading.Lock()
        self.timer = None
        if tty is None:
            try:
                tty = sys.stderr.isatty()
            except (AttributeError, ValueError):
                tty = False
        self.tty = tty
        if tty:
            delay = max(0.0, 1.0 - (time.monotonic() - t0))
            self.timer = threading.Timer(delay, self._show)
            self.timer.daemon = True
            self.timer.start()

    def _show(self) -> None:
        with self.lock:
            if self.bar is not None or self.stopped:
                return
            from rich.console import Console
            from rich.progress import BarColumn, Progress, SpinnerColumn, TextColumn

            what, done, total = self.state
            self.bar = Progress(SpinnerColumn(), TextColumn("rbcli report: {task.description}"), BarColumn(),
                                console=self.console or Console(stderr=True), transient=True)
            self.bar.start()
            self.task = self.bar.add_task(what, total=total or None, completed=done)

    def step(self, what: str, done: int = 0, total: int = 0) -> None:
        import time

        if not self.tty:
            return
        with self.lock:
            self.state = (what, done, total)
            bar = self.bar
        if bar is None:
            if time.monotonic() - self.t0 >= 1.0:
                self._show()
            return
        bar.update(self.task, description=what, completed=done, total=total or None)

    def stop(self) -> None:
        with self.lock:
            self.stopped = True
            if self.timer is not None:
                self.timer.cancel()
            if self.bar is not None:
                self.bar.stop()
                self.bar = None


# ----------------------------------------------------------------------------- the report


def build(b, opts: _Options, du, digits: int, date: str, progress=None):
    """The Report of a body, and the checks that failed ([] if none)."""
    import hashlib

    from rbcli import __version__
    from rbcli.render import report as R

    steps = [  # (progress text, section key, title, builder)
        ("parts", "parts", "Parts", _parts),
        ("mass properties", "mass-properties", "Mass properties", _massprops),
        ("principal axes", "principal-axes", "Principal axes", _principal),
        ("balance", "balance", "Balance", _balance),
        ("free precession", "free-precession", "Free precession", _precess),
        ("heavy top", "heavy-top", "Heavy top", _top),
        ("rolling stability", "rolling-stability", "Rolling stability", _rollcheck),
    ]
    failed: list[str] = []
    sections = []
    ctx = _Ctx(b, opts, du, digits, failed)
    for i, (what, key, title, fn) in enumerate(steps):
        if progress is not None:
            progress.step(what, i, len(steps))
        sections.append(_guarded(ctx, what, key, title, fn))
    meta = [("body", b.name)]
    if b.description:
        meta.append(("description", b.description))
    meta += [
        ("input file", b.source),
        ("SHA-256 of the input file", hashlib.sha256(b.text.encode("utf-8")).hexdigest()),
        ("options", opts.text() or "(none)"),
        ("units in tables", "SI" if du.si else ", ".join(u for _, u in (du.length, du.mass, du.time))),
        ("rbcli version", __version__),
        ("date", date),
    ]
    rep = R.Report(title=f"rbcli report: {b.name}", meta=meta, sections=sections, input_name=b.source,
                   input_text=b.text, generator=f"rbcli {__version__}")
    return rep, failed


def _guarded(ctx, what: str, key: str, title: str, fn):
    """``fn(ctx)``, the section, or one line saying why it is not there when its numbers are
    too large or too small to compute with (an arithmetic error, or inf/NaN in one of its
    tables, which the commands refuse too): that is this body and these options, not a bug."""
    from rbcli.errors import NonFiniteResult

    n_failed = len(ctx.failed)
    try:
        s = fn(ctx)
        c.check_finite_doc(s)
    except (OverflowError, ZeroDivisionError, FloatingPointError, NonFiniteResult) as exc:
        del ctx.failed[n_failed:]  # a check of a section that is not there has not failed
        if not isinstance(exc, NonFiniteResult):
            exc = f"a value is too large or too small to compute with ({exc})"
        return _skip(key, title, f"{what}: not computed: {exc}")
    return s


class _Ctx:
    def __init__(self, body, opts, du, digits, failed):
        from rbcli.core.inertia import combine

        self.body = body
        self.opts = opts
        self.du = du
        self.digits = digits
        self.failed = failed
        self.mp = combine(body.parts)

    def figure_svg(self, fig, name: str) -> str:
        """The SVG text of a figure made by render (in memory, no temporary file)."""
        from rbcli.render.plots import figure_bytes

        return figure_bytes(fig, "svg").decode("utf-8")


def _section(key: str, title: str):
    from rbcli.render.report import Section

    return Section(key, title)


def _skip(key: str, title: str, reason: str):
    from rbcli.render.report import Section

    return Section.skip(key, title, reason)


def _parts(ctx: _Ctx):
    from rbcli.render.report import parts_table
    from rbcli.render.text import Doc

    s = _section("parts", "Parts")
    doc = Doc()
    parts_table(doc, ctx.body, ctx.mp, ctx.du, ctx.digits)
    s.add_doc(doc)
    return s


def _massprops(ctx: _Ctx):
    from rbcli.cli.massprops import reference
    from rbcli.core.inertia import inertia_report
    from rbcli.render import massprops as r
    from rbcli.render.text import Doc

    mp, ref, label = reference(ctx.body)
    res = inertia_report(mp, ref)
    doc = Doc()
    r.inertia_doc(doc, ctx.body, res, ctx.du, ctx.digits, "tensor", label, parts=False)
    s = _section("mass-properties", "Mass properties")
    s.add_doc(doc, drop_heading_prefix=ctx.body.name)
    return s


def _principal(ctx: _Ctx):
    from rbcli.core.principal import principal_report
    from rbcli.render import massprops as r
    from rbcli.render.bodyplot import body_figure
    from rbcli.render.report import Figure
    from rbcli.render.text import Doc

    mp = ctx.mp
    pr = principal_report(mp.mass, mp.inertia_com, mp.com)
    doc = Doc()
    r.principal_doc(doc, ctx.body, pr, ctx.du, ctx.digits, "the com", parts=False)
    s = _section("principal-axes", "Principal axes")
    s.add_doc(doc, drop_heading_prefix=ctx.body.name)
    fig = body_figure(ctx.body, mp.com, pr, ctx.du, f"principal: {ctx.body.name} — equivalent ellipsoid, box and principal axes")
    s.items.append(Figure(
        "body", "The equivalent uniform ellipsoid (filled) and box (dashed) — same mass and principal "
        "moments about the centre of mass — and the principal axes 1, 2, 3 (ascending moments), in the "
        "body frame: a 3-D view and three views along the body axes at one scale.",
        ctx.figure_svg(fig, "body")))
    return s


def _balance(ctx: _Ctx):
    from rbcli.errors import InputError

    key, title = "balance", "Balance"
    b, o = ctx.body, ctx.opts
    asked = o.planes is not None or o.bearings is not None or o.grade is not None or o.rotor_speed is not None
    if o.shaft is None and b.shaft is None and not asked:
        return _skip(key, title, "balance: no shaft in the body file and no --shaft, --planes, --bearings or "
                     "rotation --speed option")
    from rbcli.api.balance import balance
    from rbcli.render import balance as rb
    from rbcli.render.text import Doc

    try:
        res = balance(b, shaft=o.shaft, through=o.through, planes=o.planes, radius=o.radius,
                      speed=o.rotor_speed, bearings=o.bearings, g=o.g if o.g_given else None,
                      grade=o.grade)
    except InputError as exc:
        return _skip(key, title, f"balance: not computed: {exc}")
    doc = Doc()
    su = rb.ShopUnits(_units_text(ctx.du))
    rb.document(doc, res, su, ctx.digits)
    s = _section(key, title)
    s.add_doc(doc, drop_heading_prefix=b.name)
    for w in res.warnings:
        s.items.append(_note(f"warning: {w}"))
    if res.iso is not None and not res.iso.passed:
        ctx.failed.append(f"balance: the rotor as given fails ISO 21940-11 G{res.iso.grade:g}")
    if not (o.planes or o.rotor_speed or o.bearings):
        s.items.append(_note("(corrections, bearing forces and the ISO grade need --planes, --speed with "
                             "a rotation unit, --bearings and --grade)"))
    return s


def _units_text(du) -> str | None:
    return None if du.si else ",".join(u for _, u in (du.length, du.mass, du.time))


def _note(text: str):
    from rbcli.render.text import Note

    return Note(text)


def _plot(ctx: _Ctx, s, name: str, fig, caption: str) -> None:
    """Add a command's figure (what its --plot draws), as inline SVG."""
    from rbcli.render.report import Figure

    s.items.append(Figure(name, caption, ctx.figure_svg(fig, name)))


def _precess(ctx: _Ctx):
    from rbcli.errors import InputError

    key, title = "free-precession", "Free precession"
    if ctx.opts.omega is None:
        return _skip(key, title, "free precession: no --omega given (the initial angular velocity, body frame)")
    from rbcli.api import precess as api
    from rbcli.render import precess as rp
    from rbcli.render.text import Doc

    b = ctx.body
    try:
        result = api.run(b, api.PrecessOptions.parse(b, omega=ctx.opts.omega))
    except InputError as exc:
        return _skip(key, title, f"free precession: not computed: {exc}")
    doc = Doc()
    rp.document(doc, b, result, ctx.du, ctx.digits)
    s = _section(key, title)
    s.add_doc(doc, drop_heading_prefix=b.name)
    _plot(ctx, s, "precess", rp.plot(b, result.motion, None, ctx.du),
          "The angular velocity in the body frame against time and the polhode (as rbcli precess --plot).")
    return s


def _top(ctx: _Ctx):
    from rbcli.errors import InputError

    key, title = "heavy-top", "Heavy top"
    b, o = ctx.body, ctx.opts
    if o.pivot is None and b.pivot is None:
        return _skip(key, title, "heavy top: no pivot in the body file and no --pivot option")
    if o.spin is None or o.theta is None:
        missing = " and ".join(x for x, v in (("--spin", o.spin), ("--theta", o.theta)) if v is None)
        return _skip(key, title, f"heavy top: the body has a pivot, but no {missing} given "
                     "(the spin about the symmetry axis and the start tilt from the vertical)")
    from rbcli.api import top as at
    from rbcli.render import top as rt
    from rbcli.render.text import Doc

    try:
        res = at.top(b, pivot=o.pivot, spin=o.spin, theta=f"{o.theta!r} rad", theta_dot=o.theta_dot,
                     phi_dot=o.phi_dot, g=o.g)
        span = res.default_duration()
    except InputError as exc:
        return _skip(key, title, f"heavy top: not computed: {exc}")
    doc = Doc()
    rt.document(doc, res, ctx.du, ctx.digits)
    s = _section(key, title)
    s.add_doc(doc, drop_heading_prefix=b.name)
    _plot(ctx, s, "top", rt.plot(res, res.sample(span), span),
          "The path of the axis (as rbcli top --plot), over three nutation periods.")
    return s


def _rollcheck(ctx: _Ctx):
    from rbcli.errors import InputError

    key, title = "rolling-stability", "Rolling stability"
    b, o = ctx.body, ctx.opts
    from rbcli.api import rollcheck as ar

    if o.rim_radius is None and b.rim_radius is None and not ar.round_parts(b):
        return _skip(key, title, "rolling stability: no rim radius: none in the body file (rim_radius), no "
                     "--rim-radius option and no round part")
    from rbcli.render import rollcheck as rr
    from rbcli.render.text import Doc

    try:
        res = ar.rollcheck(b, axle=o.shaft, through=o.through, radius=o.rim_radius, tyre_radius=o.tyre_radius,
                           g=o.g, speed=o.roll_speed, spin=o.roll_spin)
    except ar.OffCentreRim as exc:  # a cone or a top on its base rim: not a wheel
        return _skip(key, title, f"rolling stability: left out: {exc.reason}")
    except InputError as exc:
        return _skip(key, title, f"rolling stability: not computed: {exc}")
    doc = Doc()
    rr.document(doc, res, ctx.du, ctx.digits)
    s = _section(key, title)
    s.add_doc(doc, drop_heading_prefix=b.name)
    for w in res.warnings:
        s.items.append(_note("warning: " + w))
    if res.return_code:
        ctx.failed.append("rolling: straight rolling at --speed is unstable")
    _plot(ctx, s, "rollcheck", rr.plot(res, res.curves()),
          "Lean frequency squared and growth rate against speed (as rbcli rollcheck --plot).")
    return s


MANUAL["report"] = {
    "notes": [
        "Sections, in order: parts (each part's mass, share, centre and its contribution to Ixx, "
        "Iyy, Izz about the body's centre of mass; the total row is the body), mass properties "
        "(as rbcli inertia: about the body's reference point, else the origin, and about the com), "
        "principal axes (as rbcli principal, about the com) with a figure of the equivalent "
        "uniform ellipsoid and box and the principal axes (a 3-D view and views from +z, -y and "
        "+x at one scale), balance, free precession, heavy top and rolling stability. The tables "
        "are the same as the commands print (--digits, --units).",
        "When a section is in the report: balance when the body file has a shaft or one of "
        "--shaft, --planes, --bearings, --grade or a rotation --speed is given (the shaft "
        "defaults as in rbcli balance); free precession with --omega; heavy top when the body "
        "file has a pivot or --pivot is given, and --spin and --theta are given; rolling "
        "stability when the body has a rim_radius, --rim-radius is given or a part is round "
        "(ring, disk, cylinder, ...). Otherwise the report says why in one line, and so it does "
        "when a section cannot be computed for this body (e.g. rolling for a body that is not "
        "of revolution about its axle): the report is still written.",
        "--speed takes its meaning from its unit: an angular speed ('3000 rpm', '100 rad/s') is "
        "the rotor speed of the balance section and the spin of the rolling section; a speed "
        "('20 km/h', '5 m/s') is the rolling speed. A bare number is refused. --radius is the "
        "balance correction radius and --rim-radius the rolling rim radius; --spin and --theta "
        "are the heavy top's. The figures are those of the commands' --plot.",
        "FILE.html is one self-contained file: CSS inline, figures inline SVG, no scripts, no "
        "fonts or images fetched; it prints to PDF from a browser (tables and figures are not "
        "split across pages). FILE.md is GitHub-flavoured Markdown with its figures in "
        "FILE_files/ beside it (relative links). All text from the body file (names, the "
        "description, the input file itself) is escaped: it shows as text and never acts as "
        "HTML or Markdown.",
        "The header gives the body's name, the input file, the SHA-256 of its text (UTF-8; "
        "included files and meshes are not covered), the options that shaped the report, the "
        "rbcli version and the date: from SOURCE_DATE_EPOCH (seconds since 1970, UTC) when set, "
        "so that the same input gives the same bytes; otherwise the current time.",
        "An existing report (or FILE_files/ folder for Markdown) is replaced only with --force; "
        "an input never: the body file, any file it includes (at any depth) or any mesh it reads, "
        "also not through a link to one, nor a FILE_files/ folder holding one. The report is written to a temporary file and renamed, so a "
        "failed run leaves no half-written report. When a report takes more than a second and "
        "standard error is a terminal, a progress line shows which section is being computed.",
        "Exit status 1 after writing the report when a check it was asked for failed: the "
        "balance grade (--grade) or straight rolling at --speed.",
    ],
    "examples": [
        ("rbcli report examples/bracket.yaml -o bracket.html",
         "The bracket's parts, mass properties and principal axes with the figure; balance, "
         "precession, top and rolling each say in one line why they are not there."),
        ("rbcli report examples/two_disk_rotor.yaml -o rotor.html --planes 0,400mm --radius 100mm "
         "--speed '3000 rpm' --bearings 0,400mm --grade G6.3",
         "Adds the balance section: add 8.5 g at 208.072° and 12.2577 g at 258.232°, bearing "
         "forces 83.8916 N and 120.978 N, G6.3 FAIL as given (the report is written, exit status 1) "
         "and PASS predicted with the corrections fitted."),
        ("rbcli report examples/top.yaml -o top.md --spin 150 --theta 30 --g 9.81",
         "Markdown, with its figures in top_files/ beside it; the heavy top nutates between "
         "30° and 34.5082° (its rolling section is left out: the disk's rim is 10 mm off the centre of mass)."),
        ("SOURCE_DATE_EPOCH=0 rbcli report examples/penny.yaml -o penny.html --speed '0.1 m/s'",
         "The penny's rolling section: critical speed 0.176454 m/s, so at 0.1 m/s it falls over: "
         "the report is written and the exit status is 1. Run again (with --force): the same bytes."),
    ],
}
