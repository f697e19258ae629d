"""Documents from Python: the report's text, or the report written to a file, computed by
:mod:`rbcli.api`, laid out by :mod:`rbcli.render.reportdoc` and written by
:mod:`rbcli.io.outfile` (never over an input, all or nothing). The command line uses these
same functions: the same bytes."""

from __future__ import annotations

from collections.abc import Callable
from os import PathLike
from typing import TYPE_CHECKING, Any

from rbcli.api import check
from rbcli.api.commands import REPORT
from rbcli.api.options import choice
from rbcli.api.params import checkers
from rbcli.api.report import ReportResult, parse, run
from rbcli.errors import ParamError, literal
from rbcli.io import outfile
from rbcli.render import report as R
from rbcli.render.reportdoc import document
from rbcli.render.units import DisplayUnits

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.body.model import Body

__all__ = ["FORMATS", "report_text", "write_report", "check_report_path"]

#: the report's document formats, by file extension
FORMATS = (".html", ".md")


def _format(format: str | None) -> str | None:  # noqa: A002 - the command line's word
    return None if format is None else "." + choice(format, "format", ("html", "md"))


def _layout(digits: int, units: str | None) -> tuple[int, Any]:
    if not 1 <= digits <= 17:
        raise ParamError("digits", f"must be a whole number from 1 to 17, got {digits!r}")
    return digits, DisplayUnits.parse(units)


def _door(body: Any, format: Any, digits: Any, units: Any,  # noqa: A002
          options: dict[str, Any]) -> tuple[Any, str | None, int, str | None, dict[str, Any]]:
    """The arguments of :func:`report_text` and :func:`write_report` checked at the door
    (:mod:`rbcli.api.check`, the report's parameters by its table): TypeErrors naming the
    parameter before anything is read."""
    body = check.body(body)
    format = check.text(format, "format")  # noqa: A001
    digits = check.count(digits, "digits")
    if digits is None:
        raise TypeError("digits: expected an int, got NoneType")
    units = check.text(units, "units")
    return body, format, digits, units, check.arguments(checkers(REPORT), **options)


def report_text(body: Body, *, format: str = "html", digits: int = 6,  # noqa: A002
                units: str | None = None, **options: Any) -> str:
    """The report of ``body`` as one document's text: the bytes ``rbcli report`` writes for
    the same options (set ``SOURCE_DATE_EPOCH`` for a fixed date).

    ``format`` "html" is one self-contained file, "md" Markdown whose figures are linked as
    ``report_files/NAME.svg``; ``digits`` the tables' significant figures (1 to 17); ``units``
    theirs (``"mm,g"``, default SI); ``**options`` the parameters of :func:`rbcli.report`.
    A TypeError or an :class:`rbcli.InputError` names the parameter at fault.

    Examples
    --------
    >>> import rbcli
    >>> html = rbcli.report_text(rbcli.load("examples/top.yaml"), spin=150, theta=30)
    >>> html.startswith("<!DOCTYPE html>")
    True"""
    body, format, digits, units, options = _door(body, format, digits, units, options)  # noqa: A001
    if format is None:
        raise TypeError("format: expected a str, got NoneType")
    fmt = _format(format)
    digits, du = _layout(digits, units)
    with check.arithmetic(options):
        doc = document(run(body, parse(body, **options)), du, digits)
    return R.html(doc) if fmt == ".html" else R.markdown(doc, "report_files")[0]


def check_report_path(path: str | PathLike, body: Body, *, force: bool = False) -> tuple[str, Any, Any]:
    """(format ``".html"`` or ``".md"``, the path, its figures folder), checked by
    :mod:`rbcli.io.outfile` before anything is computed: never an input file (the body, its
    includes, its meshes), never a link or a device; an existing report, or figures folder
    (an output too), only with ``force``.

    Raises
    ------
    rbcli.InputError
        naming ``path`` (the command line's ``-o``).
    """
    p = outfile.check(path, body, "path", force=force, exts=FORMATS)
    ext = p.suffix.lower()
    files = outfile.files_dir(p)
    if ext == ".md":
        outfile.check_folder(files, body, "path", force=force)
    return ext, p, files


def write_report(body: Body, path: str | PathLike, *, force: bool = False,
                 format: str | None = None, digits: int = 6,  # noqa: A002
                 units: str | None = None,
                 progress: Callable[[str, int, int], None] | None = None,
                 **options: Any) -> ReportResult:
    """Write the report of ``body`` to ``path`` (``.html``, or ``.md`` with its figures in
    ``FILE_files/``) and return what it found (:class:`rbcli.api.report.ReportResult`,
    ``return_code`` 1 when a check asked for failed; the report is written all the same).

    All or nothing; an existing report only with ``force``; an input file never. ``format``
    must agree with the extension; ``digits``, ``units``, ``**options`` as :func:`report_text`;
    ``progress(what, i, n)`` is called before each step. A TypeError or an
    :class:`rbcli.InputError` names the parameter at fault (``force`` must be a bool).

    Examples
    --------
    >>> import rbcli, tempfile, pathlib
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "top.html"
    >>> r = rbcli.write_report(rbcli.load("examples/top.yaml"), out, spin=150, theta=30)
    >>> r.return_code, out.exists()
    (0, True)"""
    body, format, digits, units, options = _door(body, format, digits, units, options)  # noqa: A001
    path = check.path(path, "path")
    if path is None:
        raise TypeError("path: expected a str or an os.PathLike (a pathlib.Path), got NoneType")
    force = check.flag(force, "force")
    progress = check.function(progress, "progress")
    fmt = _format(format)
    digits, du = _layout(digits, units)
    ext, p, files = check_report_path(path, body, force=force)
    if fmt is not None and fmt != ext:
        raise ParamError("format", f"'{literal(format)}' does not match the file '{literal(path)}' ({ext})")
    with check.arithmetic(options):
        result = run(body, parse(body, **options), progress)
        doc = document(result, du, digits, progress)
    if progress is not None:
        progress("writing", 1, 1)
    if ext == ".html":
        outfile.write_document(p, R.html(doc), "path", replace=force)
    else:
        text, figures = R.markdown(doc, files.name)
        outfile.write_document(p, text, "path", replace=force, folder=files, files=figures)
    return result
