"""The one look of every rbcli figure, and its bytes in memory (the cli writes them).

matplotlib (~400 ms) is imported only inside these functions, its Figure API without
pyplot. Grey scale with distinct line styles; SVG and PDF without dates (the same input,
the same bytes). Every text is made safe before it is drawn (:func:`label`: control,
bidirectional and XML-illegal characters as visible escapes, so an SVG stays valid XML).
"""

from __future__ import annotations

import io
import textwrap

from rbcli.errors import clean
from rbcli.render.safe import escape

FORMATS = ("png", "svg", "pdf")
#: line styles for successive curves: (colour, linestyle, marker)
STYLES = [
    ("black", "-", None),
    ("0.35", "--", None),
    ("0.55", ":", None),
    ("0.2", "-.", None),
    ("0.45", (0, (5, 1, 1, 1)), None),
]
RC = {
    "font.size": 9,
    "axes.titlesize": 10,
    "axes.labelsize": 9,
    "axes.grid": True,
    "grid.color": "0.85",
    "grid.linewidth": 0.6,
    "lines.linewidth": 1.4,
    "legend.fontsize": 8,
    "legend.frameon": False,
    "svg.hashsalt": "rbcli",
    "svg.fonttype": "path",
    "pdf.fonttype": 42,
    "figure.dpi": 100,
    "savefig.dpi": 150,
    # labels are text, never mathtext or TeX: a body named '$\\frac{$' is shown as written
    "text.parse_math": False,
    "text.usetex": False,
    "axes.formatter.useoffset": False,  # ticks read as numbers, never "1e-5+3.14159e1"
}
#: characters of a suptitle per inch of figure width (~11 pt): longer titles wrap at spaces
TITLE_CHARS_PER_INCH = 11


def figure(title: str, *, nrows: int = 1, ncols: int = 1, size: tuple[float, float] = (7.0, 4.2)):
    """A new Figure (no pyplot) with rbcli's style, a suptitle, and its axes."""
    import logging

    import matplotlib

    logging.getLogger("matplotlib").setLevel(logging.ERROR)  # no log lines on stderr
    matplotlib.rcParams.update(RC)
    from matplotlib.figure import Figure

    fig = Figure(figsize=size, layout="constrained")
    axes = fig.subplots(nrows, ncols, squeeze=False)
    fig.suptitle("\n".join(textwrap.wrap(label(title), int(size[0] * TITLE_CHARS_PER_INCH), break_long_words=False)))
    return fig, axes


def label(text: str) -> str:
    """A figure's text made safe: control, bidirectional and XML-illegal characters (U+FFFE,
    U+FFFF) shown as visible escapes (:func:`rbcli.render.safe.escape`), long words cut
    (:func:`rbcli.errors.clean`)."""
    return clean(escape(text))


def sanitise(fig) -> None:
    """Make every text artist of ``fig`` safe (:func:`label`) before it is drawn: the figure
    modules label with names that came from files; this is the one place that sees them all."""
    from matplotlib.text import Text

    for t in fig.findobj(Text):
        s = t.get_text()
        if s:
            safe = "\n".join(label(line) for line in s.split("\n"))  # the figure's own line breaks kept
            if safe != s:
                t.set_text(safe)


def style(i: int) -> dict:
    """Keyword arguments for the i-th curve of a plot (grey-scale safe)."""
    colour, ls, marker = STYLES[i % len(STYLES)]
    kw = {"color": colour, "linestyle": ls}
    if marker:
        kw["marker"] = marker
    return kw


def figure_bytes(fig, fmt: str) -> bytes:
    """The figure as a ``fmt`` file (png, svg or pdf), in memory, with deterministic metadata
    (no dates; SOURCE_DATE_EPOCH honoured). Writing it is the caller's (rbcli.io.outfile)."""
    fmt = fmt.lower().lstrip(".")
    metadata = {}
    if fmt == "svg":
        metadata = {"Date": None}
    elif fmt == "pdf":
        metadata = {"CreationDate": None, "ModDate": None}
    sanitise(fig)
    buf = io.BytesIO()
    fig.savefig(buf, format=fmt, metadata=metadata or None)
    return buf.getvalue()
