"""``rbcli report`` through the command line.

What is checked: a report builds for every bundled example; the HTML parses and carries,
in its table cells, each section's key numbers exactly as ``--json`` of the command that
owns the section gives them, formatted as the report formats them (``num(x, 6)`` in the
table's unit); the sections that do not apply say why in one line; user text is escaped
(HTML and Markdown); no network references; same bytes for the same input; --force; the
input is never overwritten; exit codes; Markdown snapshots (SOURCE_DATE_EPOCH fixed); and
the HTML rendered by a real browser (Debian's chromium, skipped where it is not installed).

Regenerate the Markdown snapshots after an intended change of the report with

    RBCLI_UPDATE_SNAPSHOTS=1 .venv/bin/python -m pytest tests/test_cli_report.py -k snapshot

and review the diff of tests/snapshots/ before committing it.
"""

from __future__ import annotations

import hashlib
import os
import re
import shutil
import subprocess
import time
import xml.etree.ElementTree as ET
from html.parser import HTMLParser
from pathlib import Path

import pytest

import rbcli
from conftest import sampled_params
from rbcli.render.fmt import num
from rbcli.render.units import DisplayUnits

ROOT = Path(__file__).resolve().parent.parent
EX = ROOT / "examples"
SNAP = Path(__file__).resolve().parent / "snapshots"
EXAMPLES = sorted(EX.glob("*.yaml"))
EPOCH = "1700000000"  # 2023-11-14 22:13:20 UTC
SECTIONS = ("parts", "mass-properties", "principal-axes", "balance", "whirl", "free-precession",
            "heavy-top", "rolling-stability", "input-file")
CHROMIUM = shutil.which("chromium") or ("/usr/bin/chromium" if Path("/usr/bin/chromium").exists() else None)


@pytest.fixture(autouse=True)
def _fixed_date(monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", EPOCH)
    monkeypatch.chdir(ROOT)  # bodies named by relative path, as the snapshots show them


def js(cli, *args: str, code: int = 0) -> dict:
    r = cli(*args, "--json")
    assert r.code == code, r.err
    return r.json()


class Page(HTMLParser):
    """The parts of an HTML page the tests look at (and a strict nesting check)."""

    VOID = {"meta", "br", "img", "hr", "link", "input", "col", "area", "base", "wbr", "source"}

    def __init__(self, text: str) -> None:
        super().__init__(convert_charrefs=True)
        self.stack: list[str] = []
        self.cells: list[str] = []  # text of every td/th
        self.cell: list[str] | None = None
        self.ids: list[str] = []
        self.attrs: list[tuple[str, str, str]] = []  # (tag, name, value)
        self.tags: list[str] = []
        self.skips: dict[str, str] = {}  # section key -> its one-line reason
        self.skip_key: str | None = None
        self.sections: list[str] = []
        self.pre: list[str] = []
        self.in_pre = False
        self.text: list[str] = []
        self.tables: list[tuple[str, list[list[str]]]] = []  # (caption, rows of cells incl. header)
        self.caption: list[str] | None = None
        self.feed(text)
        self.close()
        assert self.stack == [], f"unclosed elements: {self.stack}"

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        a = dict(attrs)
        for k, v in attrs:
            self.attrs.append((tag, k, v or ""))
            if k == "id":
                self.ids.append(v)
        if tag in ("td", "th"):
            self.cell = []
        if tag == "table":
            self.tables.append(("", []))
        if tag == "caption":
            self.caption = []
        if tag == "tr":
            self.tables[-1][1].append([])
        if tag == "section":
            self.sections.append(a.get("id", ""))
        if tag == "p" and a.get("class") == "skip":
            self.skip_key = a["id"]
            self.skips[self.skip_key] = ""
        if tag == "pre":
            self.in_pre = True
        if tag not in self.VOID:
            self.stack.append(tag)

    def handle_startendtag(self, tag, attrs):  # <path .../> inside SVG
        self.tags.append(tag)
        for k, v in attrs:
            self.attrs.append((tag, k, v or ""))
            if k == "id":
                self.ids.append(v)

    def handle_endtag(self, tag):
        if tag in self.VOID:
            return
        assert self.stack and self.stack[-1] == tag, f"</{tag}> closes <{self.stack[-1] if self.stack else None}>"
        self.stack.pop()
        if tag in ("td", "th") and self.cell is not None:
            self.cells.append("".join(self.cell))
            self.tables[-1][1][-1].append(self.cells[-1])
            self.cell = None
        if tag == "caption" and self.caption is not None:
            self.tables[-1] = ("".join(self.caption), self.tables[-1][1])
            self.caption = None
        if tag == "p":
            self.skip_key = None
        if tag == "pre":
            self.in_pre = False

    def handle_data(self, data):
        self.text.append(data)
        if self.cell is not None:
            self.cell.append(data)
        if self.caption is not None:
            self.caption.append(data)
        if self.skip_key is not None:
            self.skips[self.skip_key] += data
        if self.in_pre:
            self.pre.append(data)


def report(cli, tmp_path, *args: str, name: str = "r.html", code: int = 0) -> tuple[Path, str]:
    out = tmp_path / name
    rc, stdout, err = cli("report", *args, "-o", str(out))
    assert rc == code, err
    assert stdout == ""  # the report goes to the file; nothing on standard output
    return out, err


def cells_have(page: Page, *values: str) -> None:
    missing = [v for v in values if v not in page.cells]
    assert not missing, f"not in any table cell: {missing}"


def sections_of(page: Page) -> set[str]:
    return set(page.sections) | set(page.skips)


# ----------------------------------------------------------------------------- every example


#: reported by default (the rest under -m slow): a mesh, a many-part wheel that rolls, a body
#: in mm, a top with its pivot
SAMPLE = ("housing", "bicycle_wheel", "rotor_mm", "top")


@pytest.mark.parametrize("example", sampled_params(EXAMPLES, lambda p: p.stem in SAMPLE,
                                                   ids=lambda p: p.stem))
def test_every_example_builds_a_report_with_the_commands_numbers(cli, tmp_path, example):
    src = str(example.relative_to(ROOT))
    out, err = report(cli, tmp_path, src, "--units", "si")  # SI tables, to compare with --json
    text = out.read_text(encoding="utf-8")
    page = Page(text)
    # every section is there, as a section or as one line saying why not
    assert sections_of(page) == set(SECTIONS)
    assert not set(page.sections) & set(page.skips)
    for key, why in page.skips.items():
        assert "\n" not in why.strip() and why.strip(), (key, why)
    # mass properties: the same numbers as rbcli inertia --json (tables show 6 significant
    # figures of the SI value, so the formatted JSON value must be the cell's text; a com
    # coordinate within 1e-12 of the body's size is round-off, printed 0: README "Round-off")
    ij = js(cli, "inertia", src)
    size = DisplayUnits().of(rbcli.load(example)).scale[1]
    cells_have(page, num(ij["mass"]), *(num(x, scale=size) for x in ij["com"]))
    cells_have(page, *(num(x) for x in [ij["inertia_com"][i][i] for i in range(3)]))
    cells_have(page, *(num(x) for x in [ij["inertia"][i][i] for i in range(3)]))
    # principal axes: moments as rbcli principal --json gives them
    pj = js(cli, "principal", src)
    cells_have(page, *(num(x) for x in pj["moments"]))
    # parts: one row per part (in the file's order, signed mass as inertia --json gives it),
    # then the total row with the body's mass
    (parts,) = [rows for caption, rows in page.tables if caption.startswith("parts:")]
    assert [r[0] for r in parts[1:]] == [p["name"] for p in ij["parts"]] + ["total"]
    assert [r[2] for r in parts[1:-1]] == [num(p["mass"]) for p in ij["parts"]]
    assert parts[-1][2] == num(ij["mass"])
    # the picture of the body is there, and every id in the page is unique
    assert page.tags.count("svg") >= 1
    assert len(page.ids) == len(set(page.ids))
    # the input file is echoed and its SHA-256 (of the bytes on disk) given
    assert "".join(page.pre) == example.read_text(encoding="utf-8")
    assert hashlib.sha256(example.read_bytes()).hexdigest() in page.cells
    assert "2023-11-14 22:13 UTC" in page.cells
    # rolling stability is computed or explained; when computed it agrees with rollcheck
    if "rolling-stability" in page.sections:
        rj = js(cli, "rollcheck", src)
        cells_have(page, num(rj["critical_speed"]), num(rj["critical_spin"]))
    else:
        assert page.skips["rolling-stability"].startswith("rolling stability: ")


# ----------------------------------------------------------------------------- sections with options


def test_balance_section_has_the_numbers_of_rbcli_balance(cli, tmp_path):
    args = ["examples/two_disk_rotor.yaml", "--planes", "0,400mm", "--radius", "100mm",
            "--speed", "3000 rpm", "--bearings", "0,400mm", "--grade", "G6.3"]
    # the rotor as given fails G6.3 (by 17-24x): both exit 1 after writing the full result
    out, err = report(cli, tmp_path, *args, code=1)
    assert "a check failed: balance:" in err
    page = Page(out.read_text(encoding="utf-8"))
    assert "balance" in page.sections
    bj = js(cli, "balance", *args, code=1)
    assert bj["iso"]["pass"] is False and bj["iso"]["after"]["pass"] is True
    # balance tables are in shop units (g, mm, g·mm, N): SI value times the unit factor,
    # then 6 significant figures, as rbcli balance prints them
    cells_have(page, num(bj["static_unbalance"] * 1e6))  # kg m -> g mm
    cells_have(page, num(bj["couple_unbalance"] * 1e9))  # kg m^2 -> g mm^2
    for cor in bj["corrections"]:
        cells_have(page, num(cor["mass"] * 1e3), num(cor["angle_deg"]))
    for f in bj["bearing_forces"]:
        cells_have(page, num(f["force"]), num(f["angle_deg"]))
    # the numbers the example file's header states (physics notes Example A)
    cells_have(page, "8.5", "208.072", "12.2577", "258.232", "83.8916", "120.978")
    # an option's name is one unbreakable cell (the browser broke --mass-step at its hyphen)
    assert '<td class="o">--planes</td>' in out.read_text(encoding="utf-8")
    assert "td.r, td.o { white-space: nowrap; }" in out.read_text(encoding="utf-8")


def test_precess_section_has_the_numbers_of_rbcli_precess(cli, tmp_path):
    args = ["examples/rectangular_block.yaml", "--omega", "0,10,0.1"]
    out, err = report(cli, tmp_path, *args)
    assert err == ""  # no progress line: standard error is not a terminal here
    page = Page(out.read_text(encoding="utf-8"))
    assert "free-precession" in page.sections
    pj = js(cli, "precess", *args)
    cells_have(page, num(pj["kinetic_energy"]), num(pj["period"]), num(pj["flip_interval"]))
    assert page.tags.count("svg") >= 2  # the body and the precession figure


def test_top_section_has_the_numbers_of_rbcli_top(cli, tmp_path):
    args = ["examples/top.yaml", "--spin", "150", "--theta", "30", "--g", "9.81"]
    out, _ = report(cli, tmp_path, *args)
    page = Page(out.read_text(encoding="utf-8"))
    assert "heavy-top" in page.sections
    tj = js(cli, "top", *args)
    cells_have(page, num(tj["theta2_deg"]), num(tj["nutation_period"]), num(tj["mean_precession_rate"]),
               *(num(x) for x in tj["steady_precession_rates"]))
    # the course numbers the example's header states (dynamics.md cases T1, T2)
    cells_have(page, "34.5082", "0.142133", "3.46842", "3.47973", "54.2553")


def test_rolling_at_a_speed_that_falls_is_written_then_exit_1(cli, tmp_path):
    out, err = report(cli, tmp_path, "examples/penny.yaml", "--speed", "0.1 m/s", code=1)
    page = Page(out.read_text(encoding="utf-8"))
    rj = js(cli, "rollcheck", "examples/penny.yaml", "--speed", "0.1", code=1)
    assert rj["stable"] is False
    cells_have(page, num(rj["critical_speed"]), num(rj["margin"]))
    assert "a check failed" in err and "rolling" in err


def test_angular_speed_goes_to_balance_and_to_the_rolling_spin(cli, tmp_path):
    args = ["examples/hoop.yaml", "--shaft", "z", "--speed", "300 rpm"]
    out, _ = report(cli, tmp_path, *args)
    page = Page(out.read_text(encoding="utf-8"))
    assert {"balance", "rolling-stability"} <= set(page.sections)
    rj = js(cli, "rollcheck", "examples/hoop.yaml", "--spin", "300 rpm")
    cells_have(page, num(rj["speed"]), num(rj["margin"]))


def test_sections_that_do_not_apply_say_why_in_one_line(cli, tmp_path):
    out, _ = report(cli, tmp_path, "examples/cube.yaml")
    page = Page(out.read_text(encoding="utf-8"))
    assert page.sections == ["parts", "mass-properties", "principal-axes", "input-file"]
    assert page.skips["balance"].startswith("balance: no shaft in the body file")
    assert page.skips["free-precession"].startswith("free precession: no --omega")
    assert page.skips["heavy-top"] == "heavy top: no pivot in the body file and no --pivot option"
    assert page.skips["rolling-stability"].startswith("rolling stability: no rim radius")


def test_a_section_that_cannot_be_computed_says_why(cli, tmp_path):
    # a box is not of revolution about z: rollcheck refuses it, the report says so in one line
    out, _ = report(cli, tmp_path, "examples/rectangular_block.yaml", "--rim-radius", "0.2")
    page = Page(out.read_text(encoding="utf-8"))
    why = page.skips["rolling-stability"]
    assert why.startswith("rolling stability: not computed: ") and "revolution" in why
    rc, _, err = cli("rollcheck", "examples/rectangular_block.yaml", "--radius", "0.2")
    assert rc == 2 and err.strip().removeprefix("rbcli: ") in why
    # the top without --spin/--theta: the pivot is there, the report says what is missing
    out, _ = report(cli, tmp_path, "examples/top.yaml", name="t.html")
    assert "no --spin and --theta" in Page(out.read_text(encoding="utf-8")).skips["heavy-top"]


@pytest.mark.parametrize("args, key, needle", [
    # balance.compute's own error mapping (report used to get an OverflowError, exit 70)
    (["examples/car_wheel.yaml", "--planes=-100,100mm", "--speed", "1e300 rpm", "--bearings", "0,1"],
     "balance", "balance: not computed: --planes, --bearings, --speed: the result overflows"),
    # an arithmetic error in the physics (a critical spin that underflows to 0)
    (["examples/penny.yaml", "--rim-radius", "1e300", "--speed", "1 m/s"],
     "rolling-stability", "rolling stability: not computed: a value is too large or too small"),
    # a result that overflows to inf is refused, as rbcli rollcheck --json refuses it
    (["examples/penny.yaml", "--speed", "1e300 m/s"],
     "rolling-stability", "rolling stability: not computed: the result 'lean_frequency' is not a finite"),
])
def test_a_section_whose_numbers_overflow_says_why(cli, tmp_path, args, key, needle):
    out, err = report(cli, tmp_path, *args)  # written, exit 0: a section not there checks nothing
    page = Page(out.read_text(encoding="utf-8"))
    assert key not in page.sections and page.skips[key].startswith(needle), page.skips.get(key)
    assert "inf" not in page.cells and err == ""


# ----------------------------------------------------------------------------- escaping, references


HOSTILE = ('{name: "</title><script>alert(1)</script>", description: "a & b <i>x</i> *y* [z](u) | --> -->", '
           'parts: [{name: "<script>alert(2)</script>", shape: box, mass: 1, size: [1, 2, 3]}, '
           '{name: "| `pipe` ![i](x.svg)", shape: sphere, mass: 1, radius: 0.5, at: [2, 0, 0]}]}')


def test_user_text_stays_text_in_html(cli, tmp_path):
    out, _ = report(cli, tmp_path, "-e", HOSTILE)
    text = out.read_text(encoding="utf-8")
    assert "<script" not in text.lower()
    assert "<i>" not in text
    page = Page(text)
    assert "<script>alert(2)</script>" in page.cells
    assert "a & b <i>x</i> *y* [z](u) | --> -->" in page.cells
    assert not [t for t in page.tags if t in ("script", "i", "iframe", "object", "embed")]
    # the SVG title (the body name) is drawn as paths; nothing of it leaks as markup
    assert "alert(1)" not in "".join(v for _, _, v in page.attrs)


def test_user_text_stays_text_in_markdown(cli, tmp_path):
    out, _ = report(cli, tmp_path, "-e", HOSTILE, name="r.md")
    text = out.read_text(encoding="utf-8")
    body = text.split("## Input file")[0]  # the echoed input is in a code block
    assert "<script>" not in body and "\\<script\\>" in body
    assert "![i](x.svg)" not in body  # no image of the user's
    # a table row has exactly the table's columns: the user's | is escaped
    rows = [ln for ln in body.splitlines() if ln.startswith("| ") and "pipe" in ln]
    assert rows and all(len(re.findall(r"(?<!\\)\|", r)) == 11 for r in rows)
    fence = re.search(r"^(`{3,})yaml$", text, re.M).group(1)
    assert text.count(fence + "yaml") == 1


def test_no_network_references_and_no_scripts(cli, tmp_path):
    out, _ = report(cli, tmp_path, "examples/top.yaml", "--spin", "150", "--theta", "30")
    text = out.read_text(encoding="utf-8")
    assert "http:" not in text and "https:" not in text  # not even XML namespaces or DTDs
    page = Page(text)
    for tag, name, value in page.attrs:
        if name in ("href", "xlink:href", "src"):
            assert value.startswith("#"), (tag, name, value)  # in-page links only
    assert re.findall(r"url\((?!#)", text) == []
    assert "script" not in page.tags and "link" not in page.tags and "img" not in page.tags


# ----------------------------------------------------------------------------- Markdown


def test_markdown_figures_sit_beside_it_and_links_resolve(cli, tmp_path):
    out, _ = report(cli, tmp_path, "examples/top.yaml", "--spin", "150", "--theta", "30", name="top.md")
    text = out.read_text(encoding="utf-8")
    links = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", text)
    assert len(links) >= 2  # body, top (rolling is left out: the disk's rim is 10 mm off the com)
    for link in links:
        assert link.startswith("top_files/") and link.endswith(".svg")
        f = tmp_path / link
        assert f.is_file()
        ET.fromstring(f.read_bytes())  # a well-formed SVG document
    assert sorted(p.name for p in (tmp_path / "top_files").iterdir()) == sorted(Path(x).name for x in links)


SNAPSHOTS = {
    "two_blade_fan.md": ["examples/two_blade_fan.yaml"],
    "top.md": ["examples/top.yaml", "--spin", "150", "--theta", "30", "--g", "9.81"],
}


@pytest.mark.parametrize("name", sorted(SNAPSHOTS))
def test_markdown_snapshot(cli, tmp_path, name):
    out, _ = report(cli, tmp_path, *SNAPSHOTS[name], name=name)
    text = out.read_text(encoding="utf-8")
    snap = SNAP / name
    if os.environ.get("RBCLI_UPDATE_SNAPSHOTS"):
        SNAP.mkdir(exist_ok=True)
        snap.write_text(text, encoding="utf-8")
    assert snap.exists(), f"no snapshot {snap}; make it with RBCLI_UPDATE_SNAPSHOTS=1"
    assert text == snap.read_text(encoding="utf-8")


# ----------------------------------------------------------------------------- files and exit codes


def test_same_input_same_bytes_and_force(cli, tmp_path):
    a, _ = report(cli, tmp_path, "examples/spoked_wheel.yaml", "--speed", "5 km/h", name="a.html")
    first = a.read_bytes()
    rc, _, err = cli("report", "examples/spoked_wheel.yaml", "--speed", "5 km/h", "-o", str(a))
    assert rc == 2 and "exists; use --force" in err and err.count("\n") == 1
    assert a.read_bytes() == first
    rc, _, err = cli("report", "examples/spoked_wheel.yaml", "--speed", "5 km/h", "-o", str(a), "--force")
    assert rc == 0, err
    assert a.read_bytes() == first  # same input, same bytes
    assert [p.name for p in tmp_path.iterdir()] == ["a.html"]  # no temporary files left


def test_markdown_folder_is_not_replaced_without_force(cli, tmp_path):
    (tmp_path / "r_files").mkdir()
    rc, _, err = cli("report", "examples/cube.yaml", "-o", str(tmp_path / "r.md"))
    assert rc == 2 and "r_files" in err and "--force" in err
    assert not (tmp_path / "r.md").exists()
    rc, _, err = cli("report", "examples/cube.yaml", "-o", str(tmp_path / "r.md"), "--force")
    assert rc == 0, err


def test_date_comes_from_source_date_epoch(cli, tmp_path, monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "0")
    out, _ = report(cli, tmp_path, "examples/cube.yaml")
    assert "1970-01-01 00:00 UTC" in Page(out.read_text(encoding="utf-8")).cells
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "yesterday")
    rc, _, err = cli("report", "examples/cube.yaml", "-o", str(tmp_path / "x.html"))
    assert rc == 2 and "SOURCE_DATE_EPOCH" in err


def test_input_is_never_overwritten(cli, tmp_path):
    body = tmp_path / "body.md"
    body.write_text((EX / "cube.yaml").read_text(encoding="utf-8"), encoding="utf-8")
    before = body.read_bytes()
    for extra in ([], ["--force"]):
        rc, _, err = cli("report", str(body), "-o", str(body), *extra)
        assert rc == 2 and "input file" in err and "never overwrites" in err
    assert body.read_bytes() == before


@pytest.mark.parametrize(
    "args, needle",
    [
        (["examples/cube.yaml", "-o", "{tmp}/r.pdf"], "use one of .html, .md"),
        (["examples/cube.yaml"], "-o/--output: required"),
        (["examples/cube.yaml", "-o", "{tmp}/r.html", "--speed", "3000"], "--speed: give a unit"),
        (["examples/cube.yaml", "-o", "{tmp}/r.html", "--grade", "G6.3", "--bearings", "0,1"], "--grade: needs an angular --speed"),
        (["examples/cube.yaml", "-o", "{tmp}/r.html", "--theta", "190"], "--theta"),
        (["examples/cube.yaml", "-o", "{tmp}/nowhere/r.html"], "does not exist"),
        (["examples/missing.yaml", "-o", "{tmp}/r.html"], "missing.yaml"),
    ],
)
def test_bad_usage_is_exit_2_with_one_line(cli, tmp_path, args, needle):
    r = cli("report", *[a.format(tmp=tmp_path) for a in args])
    assert r.code == 2, r.err
    assert r.err.startswith("rbcli: ") and r.err.count("\n") == 1 and needle in r.err
    assert "Traceback" not in r.err
    assert not (tmp_path / "r.html").exists()


def test_progress_shows_on_a_terminal_after_a_second():
    import io

    from rich.console import Console

    from rbcli.cli.report import _Progress

    buf = io.StringIO()
    quick = _Progress(t0=time.monotonic(), console=Console(file=buf, force_terminal=True), tty=True)
    quick.step("parts", 0, 7)  # within the first second: nothing yet
    assert quick.bar is None
    quick.stop()  # done before a second: never shown
    assert quick.bar is None and buf.getvalue() == ""
    slow = _Progress(t0=time.monotonic() - 2.0, console=Console(file=buf, force_terminal=True), tty=True)
    slow.step("balance", 3, 7)
    assert slow.bar is not None
    slow.bar.refresh()
    slow.stop()
    assert "rbcli report: balance" in buf.getvalue()
    # one long section: the timer shows the line without waiting for the next step
    buf2 = io.StringIO()
    long = _Progress(t0=time.monotonic() - 0.9, console=Console(file=buf2, force_terminal=True), tty=True)
    long.step("free precession", 4, 7)
    deadline = time.monotonic() + 10.0  # the timer is due after ~0.1 s; a loaded machine may lag
    while long.bar is None and time.monotonic() < deadline:
        time.sleep(0.02)
    assert long.bar is not None
    long.bar.refresh()
    long.stop()
    assert "rbcli report: free precession" in buf2.getvalue()
    # not a terminal: never
    off = _Progress(t0=time.monotonic() - 5.0, console=Console(file=io.StringIO()), tty=False)
    off.step("parts", 0, 7)
    assert off.bar is None and off.timer is None


# ----------------------------------------------------------------------------- a real browser


@pytest.mark.slow
@pytest.mark.skipif(CHROMIUM is None, reason="no browser: install Debian's chromium (apt-get install chromium) to render the report headless")
def test_html_renders_in_a_real_browser(cli, tmp_path):
    args = ["examples/gyroscope.yaml", "--spin", "3000 rpm", "--theta", "80", "--omega", "0,1,30", "--shaft", "z"]
    out, _ = report(cli, tmp_path, *args)
    page = Page(out.read_text(encoding="utf-8"))
    assert {"balance", "free-precession", "heavy-top", "rolling-stability"} <= set(page.sections)
    shot = tmp_path / "shot.png"
    pdf = tmp_path / "print.pdf"
    common = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
              "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars",
              f"--user-data-dir={tmp_path / 'profile'}"]
    url = out.resolve().as_uri()
    subprocess.run([*common, f"--screenshot={shot}", "--window-size=1200,5000", url],
                   capture_output=True, timeout=120, check=False)
    subprocess.run([*common, f"--print-to-pdf={pdf}", "--no-pdf-header-footer", url],
                   capture_output=True, timeout=120, check=False)
    assert shot.exists(), "chromium wrote no screenshot"
    from PIL import Image

    import numpy as np

    im = Image.open(shot).convert("RGB")
    assert im.size == (1200, 5000)
    px = np.asarray(im, dtype=int).reshape(-1, 3)
    dark = int(np.count_nonzero(px.sum(axis=1) < 200))
    # text and table rules on a white page: some dark ink, most of it white paper
    assert 0.002 < dark / len(px) < 0.3
    # the first figure (the body) is in the first 5000 px: its ellipsoid's light-grey fill
    # (matplotlib "0.88" = #e0e0e0) is drawn, so inline SVG rendered
    assert int(np.count_nonzero(np.all(px == 224, axis=1))) > 2000
    # and it prints: a PDF of several pages
    data = pdf.read_bytes()
    assert data.startswith(b"%PDF")
    assert len(re.findall(rb"/Type\s*/Page[^s]", data)) >= 3


# ----------------------------------------------------------------------------- whirl


def test_whirl_section_with_a_stiffness_has_the_commands_critical_speeds(cli, tmp_path):
    args = ["--bearings", "0,500mm", "--stiffness", "5 N/um", "--damping", "1 N*s/mm",
            "--speed", "1480 rpm"]
    out, err = report(cli, tmp_path, "examples/fan_rotor.yaml", *args)
    page = Page(out.read_text(encoding="utf-8"))
    assert "whirl" in page.sections and err == ""
    w = cli("whirl", "examples/fan_rotor.yaml", *args, "--json").json()
    # the critical speeds of rbcli whirl, at the tables' six significant figures
    from rbcli.render.fmt import num
    from rbcli.render.units import RPM

    crit = [c for c in w["critical_speeds"] if c["in_range"]]
    assert crit
    for c in crit:
        assert num(c["speed"] * RPM, 6) in "".join(page.text) or num(c["speed"], 6) in "".join(page.text)
    # without a stiffness the section says what it needs, in one line
    out, _ = report(cli, tmp_path, "examples/fan_rotor.yaml", name="plain.html")
    why = Page(out.read_text(encoding="utf-8")).skips["whirl"]
    assert "--stiffness" in why and "--bearings" in why
    # damping alone is a mistake, said before anything is written
    r = cli("report", "examples/fan_rotor.yaml", "--damping", "5", "-o", tmp_path / "d.html")
    assert r.code == 2 and "--damping: needs --stiffness" in r.err and not (tmp_path / "d.html").exists()
