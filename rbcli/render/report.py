"""``rbcli report``: one document with every answer and its figures, as HTML or Markdown.

A :class:`Report` is a list of :class:`Section` objects holding the terminal's items
(Heading, Note, Table) and :class:`Figure` items (SVG), or a one-line ``skipped`` reason.
:func:`html` writes one self-contained HTML5 file (inline CSS and SVG with prefixed ids, no
scripts, no network; prints to PDF); :func:`markdown` GitHub-flavoured Markdown with the
figures in ``FILE_files/``. User text is escaped (:func:`rbcli.render.safe.escape`, then
HTML's or Markdown's own); the same Report gives the same bytes."""

from __future__ import annotations

import html as _html
import re
from dataclasses import dataclass, field
from urllib.parse import quote

import numpy as np

from rbcli.render.fmt import num
from rbcli.render.massprops import kept_parts, more_parts, rest_centre, rest_of
from rbcli.render.safe import escape
from rbcli.render.units import DisplayUnits
from rbcli.render.text import Doc, Heading, Note, Table


@dataclass(frozen=True)
class Figure:
    """A figure of the report.

    name : str — file stem (Markdown writes ``FILE_files/<name>.svg``); letters, digits, -, _
    caption : str — one sentence under the figure
    svg : str — the SVG document as matplotlib wrote it (rbcli.render.plots.figure_bytes)
    """

    name: str
    caption: str
    svg: str


@dataclass
class Section:
    """One section: an anchor key, a title, items — or a one-line reason it is not there."""

    key: str
    title: str
    items: list = field(default_factory=list)
    skipped: str | None = None

    @classmethod
    def skip(cls, key: str, title: str, reason: str) -> "Section":
        return cls(key, title, [], " ".join(reason.split()))

    def add_doc(self, doc: Doc, *, drop_heading_prefix: str | None = None) -> None:
        """Append a command's Doc items; leading headings starting with the prefix (the
        body's name, which the report already shows) are left out."""
        items = list(doc.items)
        while items and isinstance(items[0], Heading) and drop_heading_prefix is not None \
                and items[0].text.startswith(drop_heading_prefix):
            items.pop(0)
        self.items.extend(items)


@dataclass
class Report:
    """title : str; meta : [(label, value)]; sections; the input file's name and text."""

    title: str
    meta: list[tuple[str, str]]
    sections: list[Section]
    input_name: str
    input_text: str
    generator: str = "rbcli"


INPUT_KEY = "input-file"

# --- parts table


def parts_table(doc: Doc, body, mp, contributions, du: DisplayUnits, digits: int) -> None:
    """Each part's mass, centre and its contribution to the moments about the body's com.

    ``contributions`` (kg m², one 3×3 per part: :func:`rbcli.core.inertia.part_contributions`)
    shown as their diagonals; the total row is ``mp``. Summarised as
    :data:`rbcli.render.massprops.PARTS_TABLE_ROWS` says, by ``|Ixx + Iyy + Izz|``, then mass.
    """
    m_unit, L, I_unit = du.unit("mass"), du.unit("length"), du.unit("inertia")
    fI, _ = du.factor("inertia")
    parts = body.parts
    J = np.asarray(contributions, dtype=float).reshape(-1, 3, 3)
    diag = np.einsum("kii->ki", J)  # (n, 3) the contributions to Ixx, Iyy, Izz
    masses = np.fromiter((p.signed_mass for p in parts), dtype=float, count=len(parts))
    keep = kept_parts(np.abs(diag.sum(axis=1)), np.abs(masses))
    shown = range(len(parts)) if keep is None else keep.tolist()

    def row(name, shape, m, com, d):
        return (name, shape, du.show(m, "mass", digits), num(100.0 * m / mp.mass, 4),
                *(("",) * 3 if com is None else (du.show(x, "length", digits) for x in com)),
                *(num(x * fI, digits) for x in d))

    rows = [row(parts[i].name, parts[i].shape + (" (hole)" if parts[i].subtract else ""),
                parts[i].signed_mass, parts[i].com, diag[i]) for i in shown]
    if keep is not None:
        rest = rest_of(len(parts), keep)
        rows.append(row(more_parts(int(rest.sum())), "", float(masses[rest].sum()),
                        rest_centre(parts, masses, rest), diag[rest].sum(axis=0)))
    Jb = np.diag(mp.inertia_com)
    rows.append(("total", "", du.show(mp.mass, "mass", digits), num(100.0, 4),
                 *(du.show(x, "length", digits) for x in mp.com), *(num(x * fI, digits) for x in Jb)))
    doc.table(
        f"parts: mass, centre and contribution to the moments about the body's com [{I_unit}]",
        ("part", "shape", f"mass [{m_unit}]", "share [%]", f"x [{L}]", f"y [{L}]", f"z [{L}]",
         "Ixx", "Iyy", "Izz"),
        rows,
        right=(2, 3, 4, 5, 6, 7, 8, 9),
    )
    if keep is not None:
        doc.note(f"The {len(keep)} parts of {len(parts)} with the largest contributions "
                 "(|Ixx + Iyy + Izz|, then the heaviest) are listed, in file order; the row "
                 f"{more_parts(len(parts) - len(keep))} sums the others: their mass, share, centre "
                 "of mass and contributions. rbcli inertia --json lists every part.")
    meshes = [parts[i] for i in shown if "volume" in parts[i].extra]
    for p in meshes:
        tri = f", {p.extra['triangles']} triangles" if "triangles" in p.extra else ""
        doc.note(f"mesh part '{p.name}': volume {du.show(p.extra['volume'], 'volume', digits)} "
                 f"{du.unit('volume')}, area {du.show(p.extra['area'], 'area', digits)} {du.unit('area')}{tri}")
    if keep is not None:
        hidden = sum(1 for p in parts if "volume" in p.extra) - len(meshes)
        if hidden:
            doc.note(f"({hidden} more mesh part{'s' if hidden != 1 else ''} among the parts summed)")
    doc.note(
        "A part's contribution is its own inertia about its centre plus the parallel-axis term "
        "m (d·d − d dᵀ), d from the body's centre of mass to the part's; holes count negative. "
        "The total row is the body: its mass, centre of mass and moments about the centre of mass."
    )


# --- SVG for HTML

_XML_DECL = re.compile(r"<\?xml[^>]*\?>\s*")
_DOCTYPE = re.compile(r"<!DOCTYPE[^>]*>\s*", re.S)
_METADATA = re.compile(r"\s*<metadata>.*?</metadata>", re.S)
_COMMENT = re.compile(r"\s*<!--.*?-->", re.S)
_XMLNS = re.compile(r'\s+xmlns(:\w+)?="[^"]*"')
_ROOT = re.compile(r"<svg\b")


def inline_svg(svg: str, prefix: str, label: str) -> str:
    """An SVG document made fit to sit inside HTML5: no XML declaration, DOCTYPE,
    metadata, comments or namespace declarations (the HTML parser knows SVG), every id
    prefixed with ``prefix`` (figures in one page cannot collide), and an accessible label.

    matplotlib escapes its comments and text (``<``, ``&`` and ``--``), so removing
    comments by a non-greedy match is safe.
    """
    s = _XML_DECL.sub("", svg, count=1)
    s = _DOCTYPE.sub("", s, count=1)
    s = _METADATA.sub("", s, count=1)
    s = _COMMENT.sub("", s)
    s = _XMLNS.sub("", s)
    s = s.replace(' id="', f' id="{prefix}').replace('href="#', f'href="#{prefix}').replace("url(#", f"url(#{prefix}")
    s = _ROOT.sub(f'<svg role="img" aria-label="{_e(label)}"', s, count=1)
    return s.strip()


# --- HTML

CSS = """
:root { color-scheme: light; }
body { font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif;
  color: #111; background: #fff; max-width: 62rem; margin: 1.5rem auto; padding: 0 1.5rem; }
h1 { font-size: 1.55rem; margin: 0 0 .6rem; }
h2 { font-size: 1.2rem; border-bottom: 1px solid #888; padding-bottom: .15rem; margin: 2rem 0 .6rem;
  break-after: avoid; page-break-after: avoid; }
h3 { font-size: 1.02rem; margin: 1.2rem 0 .4rem; break-after: avoid; page-break-after: avoid; }
.wide { overflow-x: auto; }
table { border-collapse: collapse; margin: .4rem 0 .9rem; font-size: .9rem; break-inside: avoid;
  page-break-inside: avoid; }
caption { text-align: left; font-weight: 600; padding: 0 0 .25rem; width: max-content; max-width: min(58rem, 90vw); }
th, td { padding: .18rem .65rem .18rem 0; border-bottom: 1px solid #ddd; text-align: left; vertical-align: top; }
th { border-bottom: 1.5px solid #333; font-weight: 600; }
.r { text-align: right; font-variant-numeric: tabular-nums; }
td.r, td.o { white-space: nowrap; }
table.meta td { border: none; padding: .05rem 1rem .05rem 0; }
table.meta td:first-child { color: #444; white-space: nowrap; }
code, .mono { font-family: ui-monospace, "DejaVu Sans Mono", Menlo, Consolas, monospace; font-size: .88em; }
.hash { word-break: break-all; }
p { margin: .3rem 0 .8rem; }
p.skip { color: #444; font-style: italic; margin: 1rem 0; }
nav ol { margin: .3rem 0 1rem; padding-left: 1.4rem; columns: 2; }
nav li.skip { color: #666; }
a { color: #1a4f8a; }
figure { margin: .8rem 0 1.2rem; break-inside: avoid; page-break-inside: avoid; }
figure svg { display: block; max-width: 100%; height: auto; }
figcaption { font-size: .88rem; color: #333; margin-top: .3rem; }
pre { background: #f5f5f5; border: 1px solid #ddd; padding: .6rem .8rem; font-size: .82rem;
  white-space: pre-wrap; overflow-wrap: anywhere; }
footer { margin-top: 2.5rem; font-size: .8rem; color: #555; border-top: 1px solid #ccc; padding-top: .4rem; }
@page { margin: 14mm 12mm; }
@media print {
  body { max-width: none; margin: 0; padding: 0; font-size: 10.5pt; }
  a { color: inherit; text-decoration: none; }
  .wide { overflow: visible; }
  section { break-before: auto; }
}
""".strip()


def _e(text: str) -> str:
    """Text safe in HTML: control characters escaped visibly, then HTML's escapes."""
    return _html.escape(escape(text), quote=True)


#: the most characters of the input file the report shows (its last section): a file of
#: ~2 500 generated parts (~190 characters a part) is shown whole, the examples are 1-4 KB;
#: a longer file is cut at a line end within it, and a line after it says how much is left
#: out (the header's SHA-256 identifies the whole file). A 100 000-part file (18.7 MB) made
#: an HTML report of 22 MB
INPUT_MAX_CHARS = 500_000


def _file_text(text: str) -> tuple[str, str]:
    """An input file's text to show: its lines and tabs kept (CRLF read as a line end),
    every other control character escaped visibly; and "" or the sentence that says what
    was cut (beyond :data:`INPUT_MAX_CHARS`, at a line end)."""
    text = str(text).replace("\r\n", "\n")
    cut = ""
    if len(text) > INPUT_MAX_CHARS:
        end = text.rfind("\n", 0, INPUT_MAX_CHARS) + 1 or INPUT_MAX_CHARS
        rest = text[end:]
        lines = rest.count("\n") + (not rest.endswith("\n"))
        cut = (f"The file goes on for {lines} more line{'s' if lines != 1 else ''} ({len(rest)} "
               f"characters), not shown here: the report shows the first {end} characters of "
               "an input file; its SHA-256 above identifies the whole file.")
        text = text[:end]
    return escape(text, keep="\n\t"), cut


def _html_table(t: Table) -> list[str]:
    out = ['<div class="wide"><table>']
    if t.title:
        out.append(f"<caption>{_e(t.title)}</caption>")

    def cls(i: int, x: str = "") -> str:  # an option's name (--speed-range) is not broken at its hyphens
        return ' class="r"' if i in t.right else ' class="o"' if i == 0 and x.startswith("--") else ""

    out.append("<thead><tr>" + "".join(f"<th{cls(i)}>{_e(c)}</th>" for i, c in enumerate(t.columns)) + "</tr></thead>")
    out.append("<tbody>")
    for row in t.rows:
        out.append("<tr>" + "".join(f"<td{cls(i, x)}>{_e(x)}</td>" for i, x in enumerate(row)) + "</tr>")
    out.append("</tbody></table></div>")
    return out


def _html_items(items: list, key: str) -> list[str]:
    out: list[str] = []
    n = 0
    for item in items:
        if isinstance(item, Heading):
            out.append(f"<h3>{_e(item.text)}</h3>")
        elif isinstance(item, Note):
            out.append(f'<p class="note">{_e(item.text)}</p>')
        elif isinstance(item, Table):
            out.extend(_html_table(item))
        elif isinstance(item, Figure):
            n += 1
            out.append("<figure>")
            out.append(inline_svg(item.svg, f"{key}-{n}-", item.caption))
            out.append(f"<figcaption>{_e(item.caption)}</figcaption>")
            out.append("</figure>")
        else:  # pragma: no cover - a programming error
            raise TypeError(f"unknown report item {type(item).__name__}")
    return out


def html(report: Report) -> str:
    """The report as one self-contained HTML5 document (str, ends with a newline)."""
    out = [
        "<!DOCTYPE html>",
        '<html lang="en">',
        "<head>",
        '<meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f'<meta name="generator" content="{_e(report.generator)}">',
        f"<title>{_e(report.title)}</title>",
        "<style>",
        CSS,
        "</style>",
        "</head>",
        "<body>",
        "<header>",
        f"<h1>{_e(report.title)}</h1>",
        '<table class="meta"><tbody>',
    ]
    for label, value in report.meta:
        cls = ' class="mono hash"' if label.startswith("SHA-256") else ""
        out.append(f"<tr><td>{_e(label)}</td><td{cls}>{_e(value)}</td></tr>")
    out += ["</tbody></table>", "</header>", "<nav>", "<h2>Contents</h2>", "<ol>"]
    for s in report.sections:
        if s.skipped is None:
            out.append(f'<li><a href="#{s.key}">{_e(s.title)}</a></li>')
        else:
            out.append(f'<li class="skip">{_e(s.title)} (not included)</li>')  # its one line says why
    out.append(f'<li><a href="#{INPUT_KEY}">Input file</a></li>')
    out += ["</ol>", "</nav>", "<main>"]
    for s in report.sections:
        if s.skipped is not None:
            out.append(f'<p class="skip" id="{s.key}">{_e(s.skipped)}</p>')
            continue
        out.append(f'<section id="{s.key}">')
        out.append(f"<h2>{_e(s.title)}</h2>")
        out.extend(_html_items(s.items, s.key))
        out.append("</section>")
    out.append(f'<section id="{INPUT_KEY}">')
    out.append(f"<h2>Input file: {_e(report.input_name)}</h2>")
    shown, cut = _file_text(report.input_text)
    out.append(f"<pre>{_html.escape(shown, quote=True)}</pre>")
    if cut:
        out.append(f'<p class="note">{_e(cut)}</p>')
    out.append("</section>")
    out += ["</main>", f"<footer>Written by {_e(report.generator)}.</footer>", "</body>", "</html>"]
    return "\n".join(out) + "\n"


# --- Markdown

_MD_INLINE = re.compile(r"([\\`*_\[\]<>|&~#!])")
_MD_BLOCKSTART = re.compile(r"^(\s*)([-+=>]|\d+[.)])")


def md_inline(text: str) -> str:
    """Text safe inside a Markdown paragraph or table cell: one line, control characters
    escaped visibly, punctuation that Markdown or HTML would act on backslash-escaped
    (CommonMark escapes any ASCII punctuation), so ``<script>`` stays text."""
    s = escape(" ".join(str(text).split()))
    return _MD_INLINE.sub(r"\\\1", s)


def md_para(text: str) -> str:
    """A paragraph: inline-escaped, and not read as a list, heading or quote."""
    s = md_inline(text)
    return _MD_BLOCKSTART.sub(lambda m: m.group(1) + "\\" + m.group(2), s, count=1)


def _md_table(t: Table) -> list[str]:
    out = []
    if t.title:
        out += [f"**{md_inline(t.title)}**", ""]
    cols = [md_inline(c) or " " for c in t.columns]
    out.append("| " + " | ".join(cols) + " |")
    out.append("|" + "|".join("---:" if i in t.right else "---" for i in range(len(cols))) + "|")
    for row in t.rows:
        out.append("| " + " | ".join(md_inline(x) for x in row) + " |")
    out.append("")
    return out


def _fence(text: str) -> str:
    longest = max((len(m) for m in re.findall(r"`+", text)), default=0)
    return "`" * max(3, longest + 1)


def markdown(report: Report, files_dir: str) -> tuple[str, dict[str, str]]:
    """The report as Markdown, and its figures {file name: SVG text} for ``files_dir``.

    Figures are linked as ``files_dir/<section>-<name>.svg`` (a relative link, URL-quoted).
    """
    files: dict[str, str] = {}
    out = [f"# {md_para(report.title)}", ""]
    out += ["| | |", "|---|---|"]
    for label, value in report.meta:
        v = f"`{value}`" if label.startswith("SHA-256") else md_inline(value)
        out.append(f"| {md_inline(label)} | {v} |")
    out += ["", "## Contents", ""]
    for i, s in enumerate(report.sections, 1):
        if s.skipped is None:
            out.append(f"{i}. [{md_inline(s.title)}](#{s.key})")
        else:  # no heading to link to: the one line below says why
            out.append(f"{i}. {md_inline(s.title)} (not included)")
    out += [f"{len(report.sections) + 1}. [Input file](#{INPUT_KEY})", ""]
    for s in report.sections:
        if s.skipped is not None:
            out += [f"*{md_para(s.skipped)}*", ""]
            continue
        out += [f"## {md_para(s.title)}", ""]
        for item in s.items:
            if isinstance(item, Heading):
                out += [f"### {md_para(item.text)}", ""]
            elif isinstance(item, Note):
                out += [md_para(item.text), ""]
            elif isinstance(item, Table):
                out += _md_table(item)
            elif isinstance(item, Figure):
                fname = f"{s.key}-{item.name}.svg"
                files[fname] = item.svg
                link = quote(f"{files_dir}/{fname}")
                out += [f"![{md_inline(item.caption)}]({link})", "", f"*{md_para(item.caption)}*", ""]
            else:  # pragma: no cover - a programming error
                raise TypeError(f"unknown report item {type(item).__name__}")
    shown, cut = _file_text(report.input_text)
    fence = _fence(shown)
    text = shown if shown.endswith("\n") else shown + "\n"
    out += ["## Input file", "", f"{md_inline(report.input_name)}:", "", f"{fence}yaml", text + fence, ""]
    if cut:
        out += [md_para(cut), ""]
    out += [f"*Written by {md_inline(report.generator)}.*", ""]
    return "\n".join(out), files
