"""The one look of every rbcli figure, and saving it safely (never over an input, atomically).

matplotlib is imported only inside these functions (it costs ~400 ms), through its
Figure API without pyplot, so nothing is ever drawn on screen. Figures are readable
in print and in grey scale: black and dark greys with distinct line styles and
markers rather than colour alone. SVG and PDF are written without dates (and honour
SOURCE_DATE_EPOCH), so the same input gives the same bytes.
"""

from __future__ import annotations

from pathlib import Path

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
}


def check_path(path: str, inputs=(), *, others=None) -> Path:
    """The plot path, checked before anything is computed (see :func:`rbcli.io.outfile.check`).

    ``inputs`` is the Body (every file it was read from: the body file, includes at any
    depth, meshes) or a tuple of input paths. An existing figure is replaced (as plotting
    tools do), an input file never.

    Raises
    ------
    InputError
        For an unknown extension (listing the allowed ones), a path that is an input, a
        folder, or a folder that does not exist.
    """
    from rbcli.io import outfile

    return outfile.check(path, inputs, "--plot", exts=FORMATS, replace_ok=True, others=others)


def figure(title: str, *, nrows: int = 1, ncols: int = 1, size: tuple[float, float] = (7.0, 4.2)):
    """A new Figure (no pyplot) with rbcli's style, a suptitle, and its axes."""
    import matplotlib

    matplotlib.rcParams.update(RC)
    from matplotlib.figure import Figure

    fig = Figure(figsize=size, layout="constrained")
    axes = fig.subplots(nrows, ncols, squeeze=False)
    fig.suptitle(title)
    return fig, axes


def style(i: int) -> dict:
    """Keyword arguments for the i-th curve of a plot (grey-scale safe)."""
    colour, ls, marker = STYLES[i % len(STYLES)]
    kw = {"color": colour, "linestyle": ls}
    if marker:
        kw["marker"] = marker
    return kw


def save(fig, path: Path) -> None:
    """Save with deterministic metadata, atomically; the format follows the extension."""
    import io

    from rbcli.io.outfile import write_atomic

    ext = path.suffix.lower().lstrip(".")
    metadata = {}
    if ext == "svg":
        metadata = {"Date": None}
    elif ext == "pdf":
        metadata = {"CreationDate": None, "ModDate": None}
    buf = io.BytesIO()
    fig.savefig(buf, format=ext, metadata=metadata or None)
    write_atomic(path, buf.getvalue(), "--plot")
