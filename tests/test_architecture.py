"""The layers import one way (STYLE.md): core and model see only numpy/scipy/stdlib,
render never reads YAML, and nothing but the cli package imports the cli.

Read from the source with ast, so an import hidden inside a function counts too.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parent.parent / "rbcli"

#: third-party or rbcli modules each layer must never import
FORBIDDEN = {
    "core": {"yaml", "typer", "rich", "matplotlib", "pydantic", "rbcli.io", "rbcli.render", "rbcli.cli"},
    "model": {"yaml", "typer", "rich", "matplotlib", "pydantic", "scipy", "rbcli.io", "rbcli.render", "rbcli.cli", "rbcli.core"},
    "io": {"typer", "rich", "matplotlib", "rbcli.render", "rbcli.cli"},
    "render": {"yaml", "typer", "rbcli.cli", "rbcli.io.yamlsafe", "rbcli.io.body"},
    "errors": {"numpy", "scipy", "yaml", "typer", "rich", "matplotlib", "rbcli"},
    "env": {"numpy", "scipy", "yaml", "typer", "rich", "matplotlib", "rbcli.core", "rbcli.io", "rbcli.render", "rbcli.cli"},
}


def _layer(path: Path) -> str | None:
    rel = path.relative_to(PKG)
    if rel.parts[0] in ("core", "io", "render", "cli"):
        return rel.parts[0]
    if rel.name in ("model.py", "errors.py", "env.py"):
        return rel.stem
    return None


def _imports(path: Path) -> list[tuple[str, int]]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out += [(a.name, node.lineno) for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.append((node.module, node.lineno))
            out += [(f"{node.module}.{a.name}", node.lineno) for a in node.names]
    return out


MODULES = sorted(p for p in PKG.rglob("*.py") if _layer(p))


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PKG)))
def test_layer_imports_go_one_way(path):
    layer = _layer(path)
    bad = []
    for name, line in _imports(path):
        for banned in FORBIDDEN.get(layer, ()):  # cli may import anything
            if name == banned or name.startswith(banned + "."):
                if layer == "errors" and name.startswith("rbcli.errors"):
                    continue
                bad.append(f"line {line}: {name}")
    assert not bad, f"{path.relative_to(PKG)} ({layer}) imports what its layer must not: {bad}"


@pytest.mark.parametrize("path", [p for p in MODULES if _layer(p) != "cli"], ids=lambda p: str(p.relative_to(PKG)))
def test_nothing_outside_cli_imports_cli(path):
    assert not [n for n, _ in _imports(path) if n == "rbcli.cli" or n.startswith("rbcli.cli.")]
