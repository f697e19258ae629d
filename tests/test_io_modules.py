"""The io layer's modules (issue 23): each one job, none over 800 lines, no import cycle
among them (an import inside a function counts: it is still a cycle of dependence)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

IO = Path(__file__).resolve().parent.parent / "rbcli" / "io"
MODULES = sorted(IO.glob("*.py"))
MAX_LINES = 800  # RULES.md: "modules <= 800 lines with one job each"


@pytest.mark.parametrize("path", MODULES, ids=lambda p: p.name)
def test_no_io_module_is_over_800_lines(path):
    n = len(path.read_text(encoding="utf-8").splitlines())
    assert n <= MAX_LINES, f"{path.name} has {n} lines"


def _io_imports(path: Path, io: Path = IO) -> set[str]:
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        names = []
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names = [node.module] + [f"{node.module}.{a.name}" for a in node.names]
        for n in names:
            if n.startswith("rbcli.io."):
                mod = n.split(".")[2]
                if (io / f"{mod}.py").exists() and mod != path.stem:
                    out.add(mod)
    return out


def _cycle(io: Path) -> list[str] | None:
    graph = {p.stem: _io_imports(p, io) for p in sorted(io.glob("*.py"))}
    done: set[str] = set()

    def visit(m: str, path: tuple[str, ...]) -> list[str] | None:
        if m in path:
            return [*path[path.index(m):], m]
        if m in done:
            return None
        for n in sorted(graph.get(m, ())):
            found = visit(n, (*path, m))
            if found:
                return found
        done.add(m)
        return None

    for m in graph:
        found = visit(m, ())
        if found:
            return found
    return None


def test_io_modules_import_each_other_without_a_cycle():
    cycle = _cycle(IO)
    assert cycle is None, "import cycle: " + " -> ".join(cycle or [])


def test_the_cycle_check_finds_a_cycle(tmp_path):
    """The check above cannot pass vacuously: a function-level import closing a loop is found."""
    (tmp_path / "a.py").write_text("def f():\n    from rbcli.io.b import g\n")
    (tmp_path / "b.py").write_text("from rbcli.io import a\n")
    (tmp_path / "c.py").write_text("import rbcli.io.a\n")
    assert _cycle(tmp_path) == ["a", "b", "a"]
