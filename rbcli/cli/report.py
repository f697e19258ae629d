"""``rbcli report``: every answer that applies to a body, in one HTML or Markdown file."""

from __future__ import annotations

import typer

from rbcli.api.commands import REPORT
from rbcli.cli import common as c
from rbcli.cli.app import MANUAL

HELP = """One document with every answer that applies to the body, its tables and figures.

Writes -o FILE.html (one self-contained file: inline CSS and SVG figures, no scripts,
no network references; prints to PDF from a browser) or -o FILE.md (Markdown with its
figures in FILE_files/*.svg beside it). The report has the body (name, input file and
its SHA-256, rbcli version, date), a parts table with each part's contribution, mass
properties (as `inertia`), principal axes (as `principal`) with a picture of the
equivalent ellipsoid and box, and - where the body file or the options give what they
need - balance (the body's shaft, or --shaft, --planes, --bearings, --grade or a rotation
--speed), the rotor on its bearings (--stiffness with --bearings: critical speeds, Campbell
diagram, unbalance response, as `whirl`), free precession (--omega), the heavy top (the body's pivot or --pivot, with
--spin and --theta) and rolling stability (a rim radius or a round part). A section that does not apply, or cannot be computed for this
body, says why in one line. The same input gives the same bytes when SOURCE_DATE_EPOCH
is set. Exit status 1 when a check asked for fails (--grade, rolling at --speed); the
report is written first.
"""


@c.command(REPORT, help=HELP)
def report(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    output: str = typer.Option(None, "-o", "--output", help="The report file: .html (self-contained) or .md (figures in FILE_files/). Required.", show_default=False),
    force: bool = typer.Option(False, "--force", help="Replace an existing report (never an input: the body file, a file it includes or a mesh it reads)."),
    args: dict = c.PARAMS,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    import time

    from rbcli.documents import write_report
    from rbcli.errors import InputError

    t0 = time.monotonic()
    e = c.env()
    if output is None:
        raise InputError("-o/--output: required: the report file, e.g. -o report.html or -o report.md")
    b = c.load_one(body, expr, e)
    progress = _Progress(t0)
    try:
        result = write_report(
            b, output, force=force, digits=digits, units=units, progress=progress.step, **args)
    finally:
        progress.stop()
    if result.failed:
        e.warn(f"rbcli: {output}: written; a check failed: {'; '.join(c.said(f) for f in result.failed)}")
    c.finish(result.return_code)


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


MANUAL["report"] = {
    "notes": [
        "Sections, in order: parts (each part's mass, share, centre and its contribution to Ixx, "
        "Iyy, Izz about the body's centre of mass; the total row is the body), mass properties "
        "(as rbcli inertia: about the body's reference point, else the origin, and about the com), "
        "principal axes (as rbcli principal, about the com) with a figure of the equivalent "
        "uniform ellipsoid and box and the principal axes (a 3-D view and views from +z, -y and "
        "+x at one scale), balance, whirl, free precession, heavy top and rolling stability. The tables "
        "are the same as the commands print (--digits, --units).",
        "Large bodies: the parts table lists at most 100 parts (PARTS_TABLE_ROWS): beyond that, "
        "the 100 with the largest contributions (|Ixx + Iyy + Izz|, then the heaviest), in file "
        "order, one row that sums the others (their mass, share, centre of mass and "
        "contributions) and the total; rbcli inertia --json lists every part. The body figure "
        "draws the 500 heaviest parts (FIGURE_MAX_PARTS) by their outline, the next 2000 "
        "(FIGURE_MAX_DOTS) as dots at their centres, and says under it how many lighter parts "
        "it left out and their share of the mass. The input file is shown up to 500 000 "
        "characters (INPUT_MAX_CHARS), cut at a line end, with a line saying how much is left "
        "out (the SHA-256 in the header covers the whole file). So a 100 000-part body "
        "reports in about 20 s and 0.7 GB (most of both reading the file), in an HTML file of "
        "about 3 MB.",
        "When a section is in the report: balance when the body file has a shaft or one of "
        "--shaft, --planes, --bearings, --grade or a rotation --speed is given (the shaft "
        "defaults as in rbcli balance); whirl (as rbcli whirl, with its default speed range) when "
        "--stiffness is given, with --bearings, an optional --damping and an angular --speed as "
        "the operating speed; free precession with --omega; heavy top when the body "
        "file has a pivot or --pivot is given, and --spin and --theta are given; rolling "
        "stability when the body has a rim_radius, --rim-radius is given or a part is round "
        "(ring, disk, cylinder, ...). Otherwise the report says why in one line, and so it does "
        "when a section cannot be computed for this body (e.g. rolling for a body that is not "
        "of revolution about its axle): the report is still written. An option value that the "
        "section's command refuses (--planes without --radius for a body without rim_radius, "
        "a --tyre-radius not smaller than the rim radius, ...) is bad usage, exit status 2, as in "
        "that command.",
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
