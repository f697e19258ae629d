"""The layers import one way (STYLE.md): cli -> api -> body -> {io, core}; render -> core,
body; io reads and writes files and imports neither core nor body; core imports nothing above
it (the body's types only for annotations); render never reads YAML; nothing but the cli
package imports the cli.

Read from the source with ast, so an import hidden inside a function counts too.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parent.parent / "rbcli"

#: third-party or rbcli modules each layer must never import
FORBIDDEN = {
    "core": {"yaml", "typer", "rich", "matplotlib", "pydantic", "rbcli.io", "rbcli.body", "rbcli.render",
             "rbcli.cli", "rbcli.api"},
    # io reads and writes files: no physics, no body
    "io": {"typer", "rich", "matplotlib", "rbcli.core", "rbcli.body", "rbcli.render", "rbcli.cli", "rbcli.api"},
    # the body: built from YAML trees (io's), computed with core; never the services above it
    "body": {"yaml", "typer", "rich", "matplotlib", "pydantic", "rbcli.render", "rbcli.cli", "rbcli.api"},
    # the services (the Python API): compute and return results; never print or draw
    "api": {"typer", "rich", "matplotlib", "rbcli.cli", "rbcli.render"},
    # render renders: it never reads YAML or a body file, nor writes a file (the cli writes
    # through io.outfile)
    "render": {"yaml", "typer", "rbcli.cli", "rbcli.api", "rbcli.io.yamlsafe", "rbcli.io.outfile",
               "rbcli.io.meshfile", "rbcli.body.bodyfile", "rbcli.body.pydata", "rbcli.body.document"},
    # the library's documents: compute (api), lay out (render), write (io); never the cli
    "documents": {"typer", "rbcli.cli"},
    "errors": {"numpy", "scipy", "yaml", "typer", "rich", "matplotlib", "rbcli"},
    "env": {"numpy", "scipy", "yaml", "typer", "rich", "matplotlib", "rbcli.core", "rbcli.io", "rbcli.body",
            "rbcli.render", "rbcli.cli"},
}


#: forbidden imports a layer may make under ``if TYPE_CHECKING:`` only (names for annotations):
#: core's functions take the body's parts; render reads the services' results (never calls one)
TYPES_ONLY: dict[str, set[str]] = {"core": {"rbcli.body.partmodel"}, "render": {"rbcli.api"}}


#: the only imports of render from below it, each inside ``_repr_html_``: a body or a result
#: shows itself in a notebook as its command's tables and figure, which render alone draws
#: (issue 32 item 7); rbcli.render.notebook imports no api module at run time: no cycle
NOTEBOOK = {"api/result.py", "body/model.py"}


def _in_repr_html(path: Path, line: int) -> bool:
    return any(isinstance(n, ast.FunctionDef) and n.name == "_repr_html_" and n.lineno <= line <= (n.end_lineno or 0)
               for n in ast.walk(ast.parse(path.read_text(encoding="utf-8"))))


def _layer(path: Path) -> str | None:
    rel = path.relative_to(PKG)
    if rel.parts[0] in ("core", "io", "body", "render", "cli", "api"):
        return rel.parts[0]
    if rel.name == "parts.py":  # rbcli.parts: the body's public constructors
        return "body"
    if rel.name in ("errors.py", "env.py", "documents.py"):
        return rel.stem
    return None


def _type_checking_nodes(tree: ast.AST) -> set[int]:
    """The ids of the nodes under ``if TYPE_CHECKING:``."""
    skip: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            skip |= {id(n) for child in node.body for n in ast.walk(child)}
    return skip


def _imports(path: Path, *, typing: bool = True) -> list[tuple[str, int]]:
    """Every import of ``path`` (those under TYPE_CHECKING only when ``typing``)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    skip = set() if typing else _type_checking_nodes(tree)
    out = []
    for node in ast.walk(tree):
        if id(node) in skip:
            continue
        if isinstance(node, ast.Import):
            out += [(a.name, node.lineno) for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.append((node.module, node.lineno))
            out += [(f"{node.module}.{a.name}", node.lineno) for a in node.names]
    return out


def _within(name: str, prefixes) -> bool:
    return any(name == p or name.startswith(p + ".") for p in prefixes)


MODULES = sorted(p for p in PKG.rglob("*.py") if _layer(p))


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PKG)))
def test_layer_imports_go_one_way(path):
    layer = _layer(path)
    at_run_time = set(_imports(path, typing=False))
    bad = []
    for name, line in _imports(path):
        if (name, line) not in at_run_time and _within(name, TYPES_ONLY.get(layer, ())):
            continue
        # errors may use env's clean (messages made safe): both are stdlib-only leaves
        if layer == "errors" and name.startswith(("rbcli.errors", "rbcli.env")):
            continue
        if str(path.relative_to(PKG)) in NOTEBOOK and name in ("rbcli.render", "rbcli.render.notebook") \
                and _in_repr_html(path, line):
            continue
        if _within(name, FORBIDDEN.get(layer, ())):  # cli may import anything
            bad.append(f"line {line}: {name}")
    assert not bad, f"{path.relative_to(PKG)} ({layer}) imports what its layer must not: {bad}"


@pytest.mark.parametrize("path", [p for p in MODULES if _layer(p) != "cli"], ids=lambda p: str(p.relative_to(PKG)))
def test_nothing_outside_cli_imports_cli(path):
    assert not [n for n, _ in _imports(path) if n == "rbcli.cli" or n.startswith("rbcli.cli.")]


#: cli modules every command may use; the others each declare commands
CLI_SHARED = {"__init__", "app", "common", "manpages"}


@pytest.mark.parametrize("path", [p for p in MODULES if _layer(p) == "cli" and p.stem not in CLI_SHARED],
                         ids=lambda p: str(p.relative_to(PKG)))
def test_no_command_imports_another_commands_cli_module(path):
    """A command reaches another command's computation through the services (rbcli.api),
    never through its cli module (as the report did through cli/balance, cli/top, ...)."""
    others = {f"rbcli.cli.{p.stem}" for p in MODULES
              if _layer(p) == "cli" and p.stem not in CLI_SHARED and p != path}
    bad = [f"line {line}: {n}" for n, line in _imports(path)
           if any(n == o or n.startswith(o + ".") for o in others)]
    assert not bad, f"{path.relative_to(PKG)} imports another command's cli module: {bad}"


# ----------------------------------------------------------------------------- private names


def _module_name(path: Path, root: Path = PKG.parent) -> str:
    parts = list(path.relative_to(root).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def _private_uses(path: Path, root: Path = PKG.parent) -> list[tuple[int, str]]:
    """Private names (a leading '_', not a dunder) this module takes from another rbcli
    module, as (line, 'rbcli.x._y'): ``from rbcli.x import _y`` and ``m._y`` where ``m``
    names an rbcli module (``import rbcli.x as m``, ``from rbcli.cli import balance as m``)."""
    me = _module_name(path, root)
    tree = ast.parse(path.read_text(encoding="utf-8"))
    bound: dict[str, str] = {}  # local name -> the rbcli module or object it is
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.level == 0 and (node.module or "").split(".")[0] == "rbcli":
            for a in node.names:
                if _private(a.name) and node.module != me:
                    found.append((node.lineno, f"{node.module}.{a.name}"))
                bound[a.asname or a.name] = f"{node.module}.{a.name}"
        elif isinstance(node, ast.Import):
            for a in node.names:
                if a.name.split(".")[0] == "rbcli":
                    bound[a.asname or "rbcli"] = a.name if a.asname else "rbcli"
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and _private(node.attr):
            base, chain = node.value, []
            while isinstance(base, ast.Attribute):
                chain.append(base.attr)
                base = base.value
            if isinstance(base, ast.Name) and base.id in bound:
                owner = ".".join([bound[base.id], *reversed(chain)])
                if owner != me:
                    found.append((node.lineno, f"{owner}.{node.attr}"))
    return sorted(found)


#: known uses in files this rule's change could not edit; each must still be there (so the
#: list shrinks when one is fixed): rename the name to a public one, then delete the entry
KNOWN_PRIVATE_USES: dict[str, list[str]] = {}


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PKG)))
def test_no_module_uses_another_modules_private_names(path):
    """A name with a leading '_' is private to its module: another module that needs it
    needs a public function (as the report service uses each command's options object and
    run(), not their private helpers)."""
    rel = str(path.relative_to(PKG))
    used = {name for _, name in _private_uses(path)}
    known = set(KNOWN_PRIVATE_USES.get(rel, []))
    assert known <= used, f"{rel}: no longer uses {sorted(known - used)}; delete it from KNOWN_PRIVATE_USES"
    bad = [f"line {line}: {name}" for line, name in _private_uses(path) if name not in known]
    assert not bad, f"{rel} uses private names of other rbcli modules: {bad}"


def test_the_private_name_check_sees_both_forms(tmp_path):
    """The check above cannot pass vacuously: it finds each kind of use in a sample module,
    and not a public name, a dunder or the module's own private names."""
    mod = tmp_path / "rbcli" / "cli" / "sample.py"
    mod.parent.mkdir(parents=True)
    mod.write_text(
        "from rbcli import __version__\n"
        "from rbcli.cli import balance as cb\n"
        "import rbcli.core.top as ct\n"
        "import rbcli.render.text\n"
        "from rbcli.cli.massprops import _reference\n"
        "from rbcli.cli.sample import _mine\n"
        "def f(x):\n"
        "    cb._compute(); ct._finite(1); rbcli.render.text._wrap(); cb.compute(); x._private()\n",
        encoding="utf-8")
    assert [name for _, name in _private_uses(mod, tmp_path)] == [
        "rbcli.cli.massprops._reference", "rbcli.cli.balance._compute", "rbcli.core.top._finite",
        "rbcli.render.text._wrap"]


# ----------------------------------------------------------------------------- issue 23's rules


ALL_MODULES = sorted(PKG.rglob("*.py"))


@pytest.mark.parametrize("path", ALL_MODULES, ids=lambda p: str(p.relative_to(PKG)))
def test_each_module_is_at_most_800_lines(path):
    n = len(path.read_text(encoding="utf-8").splitlines())
    assert n <= 800, f"{path.relative_to(PKG)} has {n} lines: split it by job"


#: calls that change the whole process: only the command line may make them (for itself)
_PROCESS_CALLS = ("gc.disable", "gc.enable", "gc.freeze", "gc.set_threshold", "os.putenv",
                  "warnings.filterwarnings", "warnings.simplefilter", "warnings.catch_warnings",
                  "warnings.resetwarnings", "locale.setlocale", "np.seterr", "numpy.seterr",
                  "sys.setrecursionlimit")


def _process_changes(path: Path) -> list[str]:
    """The calls and assignments in ``path`` that change the whole process."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    bad = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            name = ast.unparse(node.func)
            if name in _PROCESS_CALLS or (name.startswith("os.environ.") and name.split(".")[-1]
                                          in ("pop", "setdefault", "update", "clear")):
                bad.append(f"line {node.lineno}: {name}()")
        if isinstance(node, (ast.Assign, ast.AugAssign)):
            for t in node.targets if isinstance(node, ast.Assign) else [node.target]:
                if "os.environ" in ast.unparse(t):
                    bad.append(f"line {node.lineno}: {ast.unparse(t)} = ...")
    return bad


@pytest.mark.parametrize("path", [p for p in ALL_MODULES if _layer(p) not in ("cli", "env")
                                  and p.name not in ("interrupts.py", "__main__.py")],
                         ids=lambda p: str(p.relative_to(PKG)))
def test_a_library_call_leaves_the_process_alone(path):
    """No library code switches the garbage collector, the environment, the warning filters,
    numpy's error state or the locale (issue 22: a notebook's process is the user's). The
    command line may, in rbcli/cli, rbcli/env.py and the entry modules."""
    bad = _process_changes(path)
    assert not bad, f"{path.relative_to(PKG)} changes the process: {bad}"


def test_the_process_check_sees_what_it_forbids(tmp_path):
    f = tmp_path / "m.py"
    f.write_text("import gc, os, warnings\ngc.disable()\nos.environ['X'] = '1'\n"
                 "os.environ.setdefault('Y', '2')\nwith warnings.catch_warnings():\n    pass\n",
                 encoding="utf-8")
    assert sorted(b.split(": ")[1] for b in _process_changes(f)) == [
        "gc.disable()", "os.environ.setdefault()", "os.environ['X'] = ...", "warnings.catch_warnings()"]


# ----------------------------------------------------------------------------- issue 31's rules


def _all_imports(path: Path, names: set[str]) -> set[str]:
    """The modules of ``names`` that ``path`` imports when it runs, at module level or inside
    a function (not under TYPE_CHECKING): ``from rbcli.x import y`` is ``rbcli.x.y`` when that
    is a module, else ``rbcli.x``."""
    out = set()
    for name, _line in _imports(path, typing=False):
        while name and name not in names:
            name = name.rpartition(".")[0]
        if name:
            out.add(name)
    return out


def _in_cycles(root: Path, prefixes: tuple[str, ...]) -> list[str]:
    """The modules under ``prefixes`` of the package at ``root`` that import themselves
    through others, counting imports inside functions."""
    paths = {_module_name(p, root.parent): p for p in sorted(root.rglob("*.py"))}
    graph = {m: {d for d in _all_imports(p, set(paths)) if d != m and not d.startswith(m + ".")
                 and not m.startswith(d + ".")} for m, p in paths.items()}

    def reach(start: str) -> set[str]:
        seen, todo = set(), [start]
        while todo:
            for d in graph[todo.pop()]:
                if d not in seen:
                    seen.add(d)
                    todo.append(d)
        return seen

    return [m for m in sorted(paths) if _within(m, prefixes) and m in reach(m)]


def test_no_import_cycle_counting_imports_in_functions():
    """An import inside a function hides a cycle from an import-time check (issue 31: the
    model called back into io, which built the model): none, counting them."""
    bad = _in_cycles(PKG, ("rbcli",))
    assert not bad, f"these modules import themselves through others: {bad}"


def test_the_cycle_check_sees_a_cycle_hidden_in_a_function(tmp_path):
    root = tmp_path / "rbcli"
    for rel, text in {"__init__.py": "", "io/__init__.py": "", "body/__init__.py": "",
                      "io/a.py": "def f():\n    from rbcli.body import b\n",
                      "body/b.py": "from rbcli.io.a import f\n",
                      "body/c.py": "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    import rbcli.body.d\n",
                      "body/d.py": "import rbcli.body.c\n"}.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text, encoding="utf-8")
    assert _in_cycles(root, ("rbcli",)) == ["rbcli.body.b", "rbcli.io.a"]  # c <-> d: types only


#: imports of rbcli modules inside functions in io and the body, each with its reason: the mesh
#: reader and mass properties (~10 ms of imports) only for a body that has a mesh
LAZY = {"body/meshpart.py": {"rbcli.core.mesh", "rbcli.io.meshfile"},
        "body/model.py": {"rbcli.render.notebook"}}  # Body._repr_html_ (see NOTEBOOK)


@pytest.mark.parametrize("path", [p for p in MODULES if _layer(p) in ("io", "body")]
                         + [PKG / "api" / "load.py"], ids=lambda p: str(p.relative_to(PKG)))
def test_io_and_the_body_import_rbcli_modules_at_module_level(path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    allowed = LAZY.get(path.relative_to(PKG).as_posix(), set())
    bad = []
    for f in ast.walk(tree):
        if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef)):
            for node in ast.walk(f):
                if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("rbcli"):
                    found = [node.module] if node.module in allowed else [f"{node.module}.{a.name}" for a in node.names]
                elif isinstance(node, ast.Import):
                    found = [a.name for a in node.names if a.name.startswith("rbcli")]
                else:
                    continue
                bad += [f"line {node.lineno}: {n}" for n in found if n not in allowed]
    assert not bad, f"{path.relative_to(PKG)} imports rbcli modules inside functions: {bad}"



def _lazy_imports(path: Path) -> list[str]:
    """The rbcli modules ``path`` imports inside its functions (not under TYPE_CHECKING)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    skip = _type_checking_nodes(tree)
    out = []
    for f in ast.walk(tree):
        if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef)):
            for node in ast.walk(f):
                if id(node) in skip:
                    continue
                if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("rbcli"):
                    out += [f"{node.module}.{a.name}" for a in node.names]
                elif isinstance(node, ast.Import):
                    out += [a.name for a in node.names if a.name.startswith("rbcli")]
    return out


def test_imports_of_rbcli_modules_inside_functions_are_few():
    """Outside the command line (which imports the one command being run), an rbcli module is
    imported at module level: a lazy import is for a heavy third-party module behind it (numpy
    off the command line's start-up path, a mesh reader only for a mesh), at most 25 in all."""
    found = {str(p.relative_to(PKG)): _lazy_imports(p) for p in ALL_MODULES if _layer(p) != "cli"}
    n = sum(len(v) for v in found.values())
    assert n <= 25, f"{n} imports of rbcli modules inside functions: {({k: v for k, v in found.items() if v})}"


def test_no_function_above_complexity_30():
    """radon's cyclomatic complexity (issue 31); skipped where radon is not installed."""
    cc = pytest.importorskip("radon.complexity")
    bad = []
    for path in ALL_MODULES:
        for block in cc.cc_visit(path.read_text(encoding="utf-8")):
            if block.complexity > 30:
                bad.append(f"{path.relative_to(PKG)}:{block.name} ({block.complexity})")
    assert not bad, f"split these functions: {bad}"


#: the size of rbcli/'s source (issue 31: a change must stay cheap as the features grow)
MAX_LINES, MAX_CHARS = 38_000, 1_700_000


def test_the_source_stays_within_its_size():
    texts = [p.read_text(encoding="utf-8") for p in ALL_MODULES]
    lines, chars = sum(t.count("\n") for t in texts), sum(len(t) for t in texts)
    assert lines <= MAX_LINES, f"rbcli/ has {lines} lines of Python (at most {MAX_LINES}): delete what repeats"
    assert chars <= MAX_CHARS, f"rbcli/ has {chars} characters of Python (at most {MAX_CHARS})"


def _defined_twice(path: Path) -> list[str]:
    """Top-level names a module defines more than once (a def, a class or an assignment):
    the later silently replaces the earlier (a merge once left two ``_positive``)."""
    seen: dict[str, int] = {}
    twice = []
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names = [node.name]
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names = [t.id for t in targets if isinstance(t, ast.Name)]
        else:
            continue
        for name in names:
            if name in seen and name != "__all__":
                twice.append(f"{name} (lines {seen[name]} and {node.lineno})")
            seen.setdefault(name, node.lineno)
    return twice


@pytest.mark.parametrize("path", ALL_MODULES, ids=lambda p: str(p.relative_to(PKG)))
def test_no_module_defines_a_name_twice(path):
    twice = _defined_twice(path)
    assert not twice, f"{path.relative_to(PKG)} defines these names twice: {twice}"


def test_the_name_check_sees_a_second_definition(tmp_path):
    f = tmp_path / "m.py"
    f.write_text("def _positive(x):\n    pass\nA = 1\ndef _positive(y):\n    pass\n", encoding="utf-8")
    assert _defined_twice(f) == ["_positive (lines 1 and 4)"]
