"""``rbcli.InputError`` is a ``ValueError`` (issue 22 item 4, issue 27 item 1), so every
``except ValueError`` in rbcli would also catch an InputError raised in its ``try`` and swallow
or re-word it (a located message re-located, a named parameter lost). Each such handler is
either guarded (an earlier handler of the same ``try`` catches ``InputError`` — or
``RbcliError``, ``ParamError`` — and re-raises it) or listed in :data:`REVIEWED` with the
reason its ``try`` cannot raise one. A new ``except ValueError`` fails this test until it is
one or the other: the audit stays true.

Read from the source with ast. The behaviour the guards keep is tested where it shows: the
golden cases (``tests/test_golden.py``, byte for byte) and the hostile inputs
(``tests/test_hostile_*.py``), and below for the sites whose ``try`` does raise one.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import rbcli
from conftest import EXAMPLES

PKG = Path(__file__).resolve().parent.parent / "rbcli"

#: handlers that catch what an InputError is (or a subclass of it), re-raising it
GUARDS = {"InputError", "RbcliError", "ParamError", "ReadError"}

#: (file, function) -> (how many unguarded handlers of ValueError it has, why their ``try``
#: raises no InputError: it converts numbers, asks the OS, or calls code that raises plain
#: ValueErrors only). One more handler in the function changes the count: review it.
REVIEWED: dict[tuple[str, str], tuple[int, str]] = {
    ("body/model.py", "checked"): (1, "core.inertia.combine: a plain ValueError (the parts' total mass)"),
    ("api/commands.py", "_rows"): (1, "int() of the value"),
    ("api/load.py", "_units"): (1, "body.bodyfile.default_units: plain ValueErrors (it turns UnitError into one)"),
    ("api/load.py", "load"): (1, "body.materials.density: plain ValueErrors"),
    ("body/partkeys.py", "mass_source"): (1, "body.materials.density: plain ValueErrors"),
    ("body/steppart.py", "_density"): (1, "body.materials.density: plain ValueErrors"),
    ("api/report.py", "_date"): (1, "int(), datetime of SOURCE_DATE_EPOCH"),
    ("api/whirl.py", "_points"): (1, "int(points)"),
    ("api/whirl.py", "_orders"): (1, "int() of each order"),
    ("cli/report.py", "__init__"): (1, "sys.stderr.isatty()"),
    ("core/balance/common.py", "finite"): (1, "float()"),
    ("core/field/solve.py", "_complex_array"): (1, "numpy.asarray"),
    ("core/field/solve.py", "_positive"): (1, "numpy.asarray"),
    ("core/checks.py", "finite"): (1, "float()"),
    ("core/inertia.py", "inertia_report"): (1, "unit_vector: plain ValueErrors"),
    ("core/rotation.py", "_vector"): (1, "numpy.asarray"),
    ("core/rotation.py", "axis_angle"): (1, "float()"),
    ("core/rotation.py", "euler"): (1, "numpy.asarray"),
    ("core/rotation.py", "from_matrix"): (1, "numpy.asarray"),
    ("core/top.py", "start"): (1, "core.checks.finite: plain ValueErrors"),
    ("env.py", "silence"): (1, "os.open, os.dup2"),
    ("env.py", "finish_stdout"): (1, "sys.stdout.flush()"),
    ("env.py", "from_process"): (1, "isatty()"),
    ("env.py", "prepare_streams"): (1, "stream.reconfigure"),
    ("interrupts.py", "_defer"): (1, "signal.setitimer"),
    ("interrupts.py", "install"): (2, "signal.getsignal, signal.signal"),
    ("interrupts.py", "restore"): (1, "signal.signal"),
    ("body/bodyfile.py", "_mass_props"): (1, "core.inertia.combine: plain ValueErrors"),
    ("body/bodyfile.py", "_load"): (1, "default_units: plain ValueErrors (it turns UnitError into one)"),
    ("body/partkeys.py", "rotation"): (2, "core.rotation's euler_intrinsic, from_matrix: plain ValueErrors"),
    ("body/partlist.py", "_geometry"): (1, "plan.build: core.shapes, ShapeError and plain ValueErrors"),
    ("io/meshfile.py", "read_mesh"): (1, "max_mesh_bytes: plain ValueErrors"),
    ("io/meshbase.py", "numbers"): (1, "numpy.fromstring"),
    ("io/meshbase.py", "floats"): (2, "numpy.array of the coordinates, float()"),
    ("io/outfile.py", "_probe"): (1, "os.lstat"),
    ("io/outfile.py", "_kind"): (1, "os.lstat"),
    ("io/reader.py", "limit_from_env"): (1, "int() of the variable"),
    ("io/unitparse.py", "check_exponent"): (1, "int()"),
    ("io/yamlsafe.py", "_int"): (1, "int()"),
}


def _names(node: ast.expr | None) -> set[str]:
    """The exception class names a handler's type names."""
    if node is None:
        return {"BaseException"}
    items = node.elts if isinstance(node, ast.Tuple) else [node]
    out = set()
    for it in items:
        if isinstance(it, ast.Name):
            out.add(it.id)
        elif isinstance(it, ast.Attribute):
            out.add(it.attr)
    return out


def _sites() -> list[tuple[str, str, str, int, bool]]:
    """(file, function, the try's first line, line, guarded) of every handler that catches
    ValueError."""
    out = []
    for path in sorted(PKG.rglob("*.py")):
        rel = path.relative_to(PKG).as_posix()
        source = path.read_text(encoding="utf-8")
        lines = source.splitlines()
        tree = ast.parse(source)
        funcs = [n for n in ast.walk(tree) if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))]

        def owner(lineno: int) -> str:
            best = None
            for f in funcs:
                if f.lineno <= lineno <= (f.end_lineno or f.lineno) and (best is None or f.lineno > best.lineno):
                    best = f
            return best.name if best is not None else "<module>"

        for node in ast.walk(tree):
            if not isinstance(node, ast.Try):
                continue
            first = lines[node.body[0].lineno - 1].strip()
            guarded = False
            for h in node.handlers:
                names = _names(h.type)
                if names & GUARDS:
                    guarded = True
                if "ValueError" in names:
                    out.append((rel, owner(h.lineno), first, h.lineno, guarded))
    return out


SITES = _sites()


def test_input_error_is_a_value_error():
    assert issubclass(rbcli.InputError, ValueError)
    assert issubclass(rbcli.ParamError, ValueError) and issubclass(rbcli.NonFiniteResult, ValueError)
    try:
        rbcli.top(rbcli.load(EXAMPLES / "top.yaml"), spin=0, theta=30)
    except ValueError as exc:  # what a scipy or numpy user writes
        assert isinstance(exc, rbcli.ParamError) and exc.param == "spin"
    else:  # pragma: no cover
        pytest.fail("no error")


def test_the_audit_finds_the_handlers():
    # the scan can fail: it sees the ~50 handlers there are, guarded ones among them
    assert len(SITES) >= 40
    assert sum(1 for *_, g in SITES if g) >= 5  # the guards of api/top, api/rollcheck, io


def _unguarded() -> dict[tuple[str, str], list[int]]:
    out: dict[tuple[str, str], list[int]] = {}
    for rel, func, _first, line, guarded in SITES:
        if not guarded:
            out.setdefault((rel, func), []).append(line)
    return out


UNGUARDED = _unguarded()


@pytest.mark.parametrize("key", sorted(UNGUARDED), ids=lambda k: f"{k[0]}:{k[1]}")
def test_every_except_value_error_is_guarded_or_reviewed(key):
    lines = UNGUARDED[key]
    rel, func = key
    where = ", ".join(f"rbcli/{rel}:{n}" for n in lines)
    assert key in REVIEWED and REVIEWED[key][0] == len(lines), (
        f"{where} ({func}) catch ValueError, which an InputError is: re-raise InputError first "
        "(`except InputError: raise`) or, if the try cannot raise one, review it in REVIEWED "
        "(with the number of such handlers in the function and the reason)")


def test_the_reviewed_sites_exist():
    assert set(REVIEWED) <= set(UNGUARDED), sorted(set(REVIEWED) - set(UNGUARDED))


@pytest.mark.parametrize("text, line, col", [
    # body/partkeys.py rotation: a located error from inside the rotate mapping
    ("parts:\n  - {shape: box, mass: 1, size: [1, 1, 1], rotate: {axis: [0, 0, 0], angle: 30}}\n", 2, 59),
    # io/yamlsafe.py load: the parser's located error
    ("a: &x 1\nparts: [*x]\n", 1, 4),
])
def test_located_errors_keep_their_place(tmp_path, text, line, col):
    path = tmp_path / "b.yaml"
    path.write_text(text)
    with pytest.raises(rbcli.InputError) as info:
        rbcli.load(path)
    exc = info.value
    assert (exc.where.line, exc.where.col) == (line, col)
    assert str(exc).count(str(path)) == 1, str(exc)  # not located twice
