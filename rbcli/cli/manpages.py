"""Write the man pages in man/ from the real command tree.

click-man does not work with typer 0.29 (click is vendored as ``typer._click``), so
this walks the command tree itself (``rbcli.cli.app.command_tree()``). Run ``python -m rbcli.cli.manpages
man/`` after changing an option; ``tests/test_manpages.py`` fails when a page is stale.
"""

from __future__ import annotations

import sys
from pathlib import Path

EXIT_STATUS = [
    ("0", "done."),
    ("1", "a check you asked for failed (an ISO balance grade, rolling that is unstable at the "
          "given speed, --check); the full result is still printed."),
    ("2", "bad usage or bad input: the message on standard error says file:line:column, what is "
          "wrong and what is allowed."),
    ("70", "an internal error (a bug in rbcli), said in one line; --debug shows the traceback."),
    ("130", "interrupted (Ctrl-C, SIGINT), at any moment: one line on standard error, no output "
            "file left half-written."),
    ("143", "terminated (SIGTERM), as 130."),
    ("129", "hung up (SIGHUP), as 130."),
]

ENVIRONMENT = [
    ("NO_COLOR", "plain text tables without colour (also when standard output is not a terminal)."),
    ("COLUMNS", "table width when standard output is not a terminal (default 100)."),
    ("SOURCE_DATE_EPOCH", "the date written into reports, for reproducible output."),
    ("OPENBLAS_NUM_THREADS", "BLAS threads; rbcli sets 1 unless it is set (its products are small; "
     "the numbers are the same either way)."),
]


def esc(text: str) -> str:
    """Escape text for roff: backslashes, leading dots/quotes, hyphens in options."""
    out = text.replace("\\", "\\e")
    lines = []
    for line in out.split("\n"):
        if line.startswith((".", "'")):
            line = "\\&" + line
        lines.append(line)
    return "\n".join(lines)


def _opt(text: str) -> str:
    return text.replace("-", "\\-")


def _param_line(p) -> tuple[str, str]:
    if p.param_type_name == "argument":
        head = f"\\fI{esc(p.metavar or p.name.upper())}\\fR"
    else:
        names = ", ".join(f"\\fB{_opt(o)}\\fR" for o in p.opts)
        if not getattr(p, "is_flag", False):
            names += f" \\fI{esc(p.metavar or p.name.upper().rstrip('_'))}\\fR"
        head = names
    text = esc(p.help or "")
    default = p.default
    if (
        p.param_type_name == "option"
        and not getattr(p, "is_flag", False)
        and default not in (None, "", (), [])
        and getattr(p, "show_default", True) is not False
    ):
        text += f" Default: {esc(str(default))}."
    return head, text


def _paragraphs(text: str) -> list[str]:
    return [" ".join(block.split()) for block in text.strip().split("\n\n") if block.strip()]


def _section(title: str) -> str:
    return f".SH {title}\n"


def page(name: str, cmd, version: str, manual: dict, parent: str = "rbcli") -> str:
    full = f"{parent}-{name}" if name else parent
    title = full.upper()
    help_text = (cmd.help or "").strip()
    paras = _paragraphs(help_text)
    summary = paras[0].rstrip(".") if paras else ""
    if summary.startswith(f"{full} — "):
        summary = summary[len(full) + 3 :]
    out = [
        f'.TH {title} 1 "" "rbcli {version}" "rbcli manual"\n',
        _section("NAME"),
        f"{esc(full)} \\- {esc(summary)}\n",
        _section("SYNOPSIS"),
    ]
    if name:
        args = " ".join(
            f"[\\fI{esc(p.metavar or p.name.upper())}\\fR]" for p in cmd.params if p.param_type_name == "argument"
        )
        out.append(f"\\fBrbcli {esc(name)}\\fR [\\fIOPTIONS\\fR] {args}\n")
    else:
        out.append("\\fBrbcli\\fR [\\fB\\-\\-version\\fR] [\\fB\\-\\-debug\\fR] \\fICOMMAND\\fR [\\fIOPTIONS\\fR] [\\fIBODY\\fR...]\n")
    out.append(_section("DESCRIPTION"))
    for para in paras[1:] if len(paras) > 1 else paras:
        out.append(f".PP\n{esc(para)}\n")
    for para in manual.get("notes", []):
        out.append(f".PP\n{esc(para)}\n")
    if not name:
        out.append(_section("COMMANDS"))
        for sub_name, sub in sorted(cmd.commands.items()):
            sub_summary = _paragraphs(sub.help or "")[0] if sub.help else ""
            out.append(f".TP\n\\fB{esc(sub_name)}\\fR\n{esc(sub_summary)} See \\fBrbcli\\-{esc(sub_name)}\\fR(1).\n")
    params = [p for p in cmd.params if p.name not in ("help",)]
    if params:
        out.append(_section("OPTIONS"))
        for p in params:
            head, text = _param_line(p)
            out.append(f".TP\n{head}\n{text}\n")
        out.append(".TP\n\\fB\\-h\\fR, \\fB\\-\\-help\\fR\nShow the help and exit.\n")
    if manual.get("json"):
        out.append(_section("JSON OUTPUT"))
        for key, meaning in manual["json"]:
            out.append(f".TP\n\\fB{esc(key)}\\fR\n{esc(meaning)}\n")
    out.append(_section("EXIT STATUS"))
    for code, meaning in EXIT_STATUS:
        out.append(f".TP\n\\fB{code}\\fR\n{esc(meaning)}\n")
    if not name:
        out.append(_section("ENVIRONMENT"))
        for var, meaning in ENVIRONMENT:
            out.append(f".TP\n\\fB{var}\\fR\n{esc(meaning)}\n")
    if manual.get("examples"):
        out.append(_section("EXAMPLES"))
        for command, result in manual["examples"]:
            out.append(f".PP\n{esc(result)}\n.PP\n.RS 4\n.nf\n{esc(command)}\n.fi\n.RE\n")
    out.append(_section("SEE ALSO"))
    others = [f"\\fBrbcli\\-{esc(n)}\\fR(1)" for n in sorted(_commands()) if n != name]
    if name:
        others.insert(0, "\\fBrbcli\\fR(1)")
    out.append(", ".join(others) + "\n")
    return "".join(out)


def _commands():
    from rbcli.cli.app import command_tree

    return command_tree().commands


def pages() -> dict[str, str]:
    """File name → roff text of every page."""
    from rbcli import __version__
    from rbcli.cli.app import MANUAL, command_tree

    root = command_tree()  # imports every command module (they fill in MANUAL)
    out = {"rbcli.1": page("", root, __version__, MANUAL.get("", {}))}
    for name, cmd in sorted(root.commands.items()):
        out[f"rbcli-{name}.1"] = page(name, cmd, __version__, MANUAL.get(name, {}))
    return out


def main(argv: list[str] | None = None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    target = Path(args[0] if args else "man")
    target.mkdir(parents=True, exist_ok=True)
    wanted = pages()
    for fname, text in wanted.items():
        (target / fname).write_text(text, encoding="utf-8")
    for old in target.glob("rbcli*.1"):
        if old.name not in wanted:
            old.unlink()
    print(f"wrote {len(wanted)} pages to {target}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
