"""Names are data in every output (issue 27 item 3): hostile names through every format.

A body and part name, or a file name, may hold a spreadsheet formula (``=1+1``, ``+x``,
``-x``, ``@x``, ``----``), a tab, CR, NUL, ESC (a terminal escape sequence), a bidirectional
override U+202E, the XML-illegal U+FFFE or the line separator U+2028. Each output is read
back by the parser its readers use — the csv module (``newline=''``), json, an XML parser
(xml.etree) for SVG, URDF, SDF and MJCF, html.parser for HTML — and checked for what a
reader would see: no raw control or bidirectional character, no cell a spreadsheet reads as
a formula, numbers that stay numbers, and the JSON string unchanged (its escapes are
lossless).
"""

from __future__ import annotations

import csv
import io
import json
import re
import xml.etree.ElementTree as ET
from html.parser import HTMLParser
from pathlib import Path

import pytest

from conftest import run_inprocess

#: the audit's hostile names (issue 27)
NAMES = ["=1+1", "+x", "-x", "@x", "----", "a\tb", "\tlead", "a\rb", "\rlead", "a\x00b",
         "a\x1b[31mred", "a\u202eb", "a\ufffeb", "a\u2028b", "=HYPERLINK(\"http://x\")", "-0.5"]
#: what no output may hold raw: C0 but newline, DEL, C1, separators, bidi controls, BOM
RAW = re.compile("[\x00-\x09\x0b-\x1f\x7f-\x9f\u2028\u2029\u200e\u200f\u202a-\u202e\u2066-\u2069\ufeff]")
#: a cell a spreadsheet reads as a formula (OWASP)
FORMULA = ("=", "+", "-", "@", "\t", "\r")


def body_yaml(name: str) -> str:
    """A body named ``name`` with one part of that name (JSON is YAML; the escapes keep the
    file itself printable, which body files must be)."""
    return json.dumps({"name": name, "parts": [{"name": name, "shape": "box", "size": [1, 2, 3],
                                                "mass": 1}]})


def read_csv(text: str) -> list[list[str]]:
    return list(csv.reader(io.StringIO(text, newline="")))


@pytest.mark.parametrize("name", NAMES, ids=repr)
def test_csv_parses_and_opens_as_text(name):
    r = run_inprocess("principal", "-e", body_yaml(name), "--format", "csv")
    assert r.code == 0, r.err
    assert not RAW.search(r.out)
    rows = read_csv(r.out)
    assert all(len(row) == 4 for row in rows)  # a lone CR or a tab breaks no row
    doc = run_inprocess("principal", "-e", body_yaml(name), "--json").json()
    by = {row[0]: row for row in rows[1:]}
    assert len(by) == len(rows) - 1
    for key in ("name", "parts[0].name"):
        quantity, value, text, unit = by[key]
        assert value == "" and unit == ""  # a name is never a number cell, "-0.5" neither
        assert not text.startswith(FORMULA), text  # opens in a spreadsheet as text
        if name.startswith(FORMULA) and not name.startswith(("\t", "\r")):
            assert text == "'" + name  # neutralised the OWASP way: an apostrophe in front
    for row in rows[1:]:  # numbers stay numbers, also negative ones
        if row[1]:
            float(row[1])
            assert not row[1].startswith("'")
    assert doc["name"] == name  # the JSON keeps the name as it is


@pytest.mark.parametrize("name", NAMES, ids=repr)
def test_json_escapes_what_a_terminal_would_act_on_and_reads_back_the_same(name):
    for args in (["principal", "-e", body_yaml(name), "--json"],
                 ["inertia", "-e", body_yaml(name), "--json"]):
        r = run_inprocess(*args)
        assert r.code == 0 and not RAW.search(r.out)
        assert json.loads(r.out)["name"] == name and json.loads(r.out)["parts"][0]["name"] == name


@pytest.mark.parametrize("name", NAMES, ids=repr)
def test_text_tables_show_names_escaped(name):
    r = run_inprocess("inertia", "-e", body_yaml(name))
    assert r.code == 0 and not RAW.search(r.out.replace("\n", ""))


@pytest.mark.parametrize("fmt", ["urdf", "sdf", "mjcf"])
@pytest.mark.parametrize("name", NAMES, ids=repr)
def test_robot_xml_is_well_formed(tmp_path, name, fmt):
    f = tmp_path / "body.yaml"
    f.write_text(body_yaml(name), encoding="utf-8")
    r = run_inprocess("inertia", str(f), "--format", fmt)
    assert r.code == 0 and not RAW.search(r.out.replace("\n", ""))
    ET.fromstring(r.out)  # the comment (with the name) and the element: one well-formed document


@pytest.mark.parametrize("name", ["a\ufffeb", "a\uffffb", "a\x1b[31mred", "a\u202eb", "a\x00b", "----"], ids=repr)
def test_svg_figure_is_well_formed_xml(tmp_path, name):
    svg = tmp_path / "body.svg"
    r = run_inprocess("principal", "-e", body_yaml(name), "--plot", str(svg))
    assert r.code == 0, r.err
    text = svg.read_text(encoding="utf-8")
    ET.fromstring(text)  # U+FFFE in a label once made it not well-formed
    assert not RAW.search(text.replace("\n", ""))


class _Collect(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.text: list[str] = []
        self.tags: list[str] = []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)

    def handle_data(self, data):
        self.text.append(data)


@pytest.mark.parametrize("name", NAMES + ["<script>alert(1)</script>"], ids=repr)
def test_html_and_markdown_reports_escape_names(tmp_path, name):
    f = tmp_path / "body.yaml"
    f.write_text(body_yaml(name), encoding="utf-8")
    html_path, md_path = tmp_path / "r.html", tmp_path / "r.md"
    assert run_inprocess("report", str(f), "-o", str(html_path)).code == 0
    html = html_path.read_text(encoding="utf-8")
    assert not RAW.search(html.replace("\n", ""))
    p = _Collect()
    p.feed(html)
    p.close()
    assert "script" not in p.tags  # a name is text, never markup
    shown = "".join(p.text)
    if name == "<script>alert(1)</script>":
        assert name in shown
    assert run_inprocess("report", str(f), "-o", str(md_path)).code == 0
    md = md_path.read_text(encoding="utf-8")
    assert not RAW.search(md.replace("\n", ""))
    for svg in (tmp_path / "r_files").glob("*.svg"):
        ET.fromstring(svg.read_text(encoding="utf-8"))


def test_report_shows_the_input_file_with_its_lines_and_tabs(tmp_path):
    """The input file is shown whole: newlines and tabs kept (CRLF as a line end), any other
    control character escaped."""
    f = tmp_path / "body.yaml"
    f.write_bytes(b"name: \"a\\x1bb\"\r\n# a\tcomment\r\nshape: box\r\nsize: [1, 2, 3]\r\nmass: 1\r\n")
    out = tmp_path / "r.html"
    r = run_inprocess("report", str(f), "-o", str(out))
    assert r.code == 0, r.err
    html = out.read_text(encoding="utf-8")
    pre = html.split("<pre>", 1)[1].split("</pre>", 1)[0]
    assert "\r" not in pre and "# a\tcomment\nshape: box\n" in pre


@pytest.mark.parametrize("stem", ["=1+1", "@x", "+x", "\tx", "\rx", "a\x1bb", "a\u202eb"], ids=repr)
def test_file_names_in_the_csv_file_column(tmp_path, stem):
    """Several bodies: the file column holds file names, escaped and neutralised too."""
    a, b = tmp_path / f"{stem}.yaml", tmp_path / "plain.yaml"
    a.write_text(body_yaml("ok"), encoding="utf-8")
    b.write_text(body_yaml("ok"), encoding="utf-8")
    r = run_inprocess("inertia", a.name, b.name, "--format", "csv", cwd=tmp_path)
    assert r.code == 0, r.err
    assert not RAW.search(r.out)
    rows = read_csv(r.out)
    assert rows[0][0] == "file" and all(len(row) == 5 for row in rows)
    assert all(not row[0].startswith(FORMULA) for row in rows[1:])


def test_time_series_csv_parses():
    r = run_inprocess("top", "-e", "{name: \"=1+1\\r\", parts: [{shape: cylinder, radius: 0.02, length: 0.075, "
                      "mass: 0.4, at: [0, 0, 0.0375]}]}", "--spin", "150", "--theta", "30", "--csv", "-",
                      "--duration", "0.1", "--samples", "5")
    assert r.code == 0, r.err
    rows = read_csv(r.out)
    assert rows[0] == ["t", "theta_deg", "phi_deg", "psi_deg"] and len(rows) == 6
    assert all(float(x) == float(x) for row in rows[1:] for x in row)


def test_api_error_messages_are_escaped_as_the_command_line_prints_them():
    """InputError.message carried raw ESC and newlines (issue 27): now as the CLI shows them."""
    import rbcli

    body = rbcli.load(Path(__file__).resolve().parent.parent / "examples" / "cube.yaml")
    with pytest.raises(rbcli.InputError) as exc:
        rbcli.inertia(body, about="1,2,\x1b[31m\n3\u202e")
    msg = exc.value.message
    assert not RAW.search(msg) and "\\e[31m\\n3\\u202e" in msg and "\n" not in str(exc.value)
    cli = run_inprocess("inertia", "examples/cube.yaml", "--about", "1,2,\x1b[31m\n3\u202e")
    assert cli.code == 2 and msg.split(": ", 1)[1] in cli.err  # the same text, option spelled


def test_output_escapes_are_the_terminals():
    """render.safe.escape writes what rbcli.env.clean shows on a terminal (one look for a name
    everywhere), and more: what XML cannot hold (U+FFFE, U+FFFF)."""
    from hypothesis import given, settings
    from hypothesis import strategies as st

    from rbcli.env import clean
    from rbcli.render.safe import escape

    chars = st.sampled_from(["a", " ", "\t", "\n", "\r", "\x00", "\x1b", "\x7f", "\x85", "\x9f", "\u2028",
                             "\u2029", "\u200e", "\u202e", "\u2066", "\u2069", "\ufeff", "é", "="])

    @settings(max_examples=300, deadline=None)
    @given(st.lists(chars, max_size=40).map("".join))
    def same(text):
        assert escape(text) == clean(text, max_line=None)

    same()
    assert escape("a\ufffeb\uffff") == "a\\ufffeb\\uffff"
