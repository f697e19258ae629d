"""Hostile inputs (issue 15): no input, stream, signal or file name makes rbcli crash, hang
or damage a file.

The promise (README, "Output, exit status and speed"): bad input gets exit 2 and one
located ``rbcli:`` line; nothing is overwritten, nothing is left behind; an internal error
(exit 70) is a bug. Cases are generated per class of failure the campaign found:

- data loss: links, devices, FIFOs and races at an output; a link planted in ``X_files/``;
- unbounded work: include diamonds, nested unit powers, devices and FIFOs as inputs,
  endless standard input, a huge sparse file, the parts budget;
- internal errors: matplotlib math in names, NUL in file names, dangling ``X_files/``;
- terminal injection: newlines, CR, NEL, LS/PS, ESC sequences, megabyte values;
- leftovers: failures and interrupts while writing.

Streams and signals (closed or full stdout/stderr/stdin, ASCII terminals, SIGTERM, SIGINT)
are in ``tests/test_hostile_streams.py``: they need a real process.
"""

from __future__ import annotations

import os
import re
import stat
from pathlib import Path

import pytest

from conftest import sampled_params

from rbcli.errors import InputError, option_name
from rbcli.body import includes as includes_mod
from rbcli.body.model import load_body
from rbcli.io import yamlsafe as ys
from rbcli.io import outfile

#: what a terminal must never receive from rbcli's messages or tables
CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u2028\u2029]")
BOX = "{name: b, shape: box, mass: 2, size: [0.1, 0.2, 0.3]}"
DISK = "parts:\n  - {name: disk, shape: disk, radius: 0.1, mass: 1, at: [0, 0, 0.1]}\n"


def one_line(r, code: int = 2, *, located: bool = False, says: str = "") -> str:
    """Exit ``code``, exactly one ``rbcli:`` line on stderr, no control character echoed."""
    assert r.code == code, (r.code, r.err[-2000:])
    lines = r.err.rstrip("\n").split("\n")
    assert len(lines) == 1 and lines[0].startswith("rbcli: "), r.err[:2000]
    assert not CONTROL.search(r.err), repr(r.err[:400])
    assert len(r.err) < 2500, len(r.err)
    if located:
        assert re.match(r"rbcli: [^:]+:\d+(:\d+)?: ", r.err), r.err
    assert says in r.err, r.err
    return r.err


def leftovers(folder: Path) -> list[str]:
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*") if p.name.startswith(".rbcli-"))


def snapshot(folder: Path) -> dict[str, bytes | str]:
    """Every entry under ``folder``: file bytes, or what a link/device/FIFO is."""
    out: dict[str, bytes | str] = {}
    for p in sorted(folder.rglob("*")):
        st = p.lstat()
        key = str(p.relative_to(folder))
        if stat.S_ISLNK(st.st_mode):
            out[key] = "link->" + os.readlink(p)
        elif stat.S_ISREG(st.st_mode):
            out[key] = p.read_bytes()
        else:
            out[key] = f"mode {stat.S_IFMT(st.st_mode):o}"
    return out


@pytest.fixture
def tree(tmp_path):
    """body.yaml (includes sub.yaml) in tmp_path."""
    (tmp_path / "sub.yaml").write_text(DISK)
    (tmp_path / "body.yaml").write_text(
        "name: body\nparts:\n  - {name: s, shape: include, file: sub.yaml}\n"
        "  - {name: lump, shape: point, mass: 0.1, at: [0.05, 0, 0.1]}\n"
    )
    return tmp_path


# --------------------------------------------------------------------------- data loss

#: (command line writing FILE, option named) — every kind of output
WRITERS = [
    (("precess", "body.yaml", "--omega", "0,0,1", "--duration", "1", "--csv", "FILE"), "--csv", ".csv"),
    (("precess", "body.yaml", "--omega", "0,0,1", "--plot", "FILE"), "--plot", ".png"),
    (("report", "body.yaml", "-o", "FILE", "--force"), "-o", ".html"),
    (("report", "body.yaml", "-o", "FILE", "--force"), "-o", ".md"),
    (("balance", "body.yaml", "--planes", "0,0.2", "--radius", "0.1", "--apply", "FILE", "--force"), "--apply", ".yaml"),
]


def _make(kind: str, path: Path, tree: Path) -> None:
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "link-to-input":
        path.symlink_to(tree / "sub.yaml")
    elif kind == "link-to-other":
        (tree / "other.dat").write_text("keep me\n")
        path.symlink_to(tree / "other.dat")
    elif kind == "dangling-link":
        path.symlink_to(tree / "nowhere" / "x")
    elif kind == "device":
        os.mknod(path, 0o644 | stat.S_IFCHR, os.makedev(1, 3))  # a copy of /dev/null
    elif kind == "folder":
        path.mkdir()


KINDS = ["fifo", "link-to-input", "link-to-other", "dangling-link", "device", "folder"]


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("args, option, ext", WRITERS, ids=[f"{w[1]}{w[2]}" for w in WRITERS])
def test_an_output_that_is_not_a_regular_file_is_refused(cli, tree, kind, args, option, ext):
    if kind == "device" and os.geteuid() != 0:
        pytest.skip("mknod needs root")
    target = tree / f"out{ext}"
    _make(kind, target, tree)
    before = snapshot(tree)
    r = cli(*[str(target) if a == "FILE" else a for a in args], cwd=tree)
    one_line(r, says=option)
    assert snapshot(tree) == before  # the link, device or FIFO is still there, nothing written


def test_dev_null_is_never_replaced(cli, tree):
    r = cli("precess", "body.yaml", "--omega", "0,0,1", "--duration", "1", "--csv", "/dev/null", cwd=tree)
    one_line(r, says="is a device")
    assert stat.S_ISCHR(os.lstat("/dev/null").st_mode)


@pytest.mark.parametrize("planted", ["link-to-body", "link-to-include", "hard-link-to-body"])
def test_a_link_planted_in_the_figures_folder_never_reaches_an_input(cli, tree, planted):
    files = tree / "r_files"
    files.mkdir()
    name = files / "principal-axes-body.svg"
    if planted == "link-to-body":
        name.symlink_to("../body.yaml")
    elif planted == "link-to-include":
        name.symlink_to(tree / "sub.yaml")
    else:
        os.link(tree / "body.yaml", name)
    before = {p: (tree / p).read_bytes() for p in ("body.yaml", "sub.yaml")}
    r = cli("report", "body.yaml", "-o", "r.md", "--force", cwd=tree)
    one_line(r, says="-o: ")
    assert {p: (tree / p).read_bytes() for p in before} == before
    assert leftovers(tree) == []


def test_figures_folder_is_replaced_whole_with_force(cli, tree):
    files = tree / "r_files"
    files.mkdir()
    (files / "old.svg").write_text("<svg/>")
    r = cli("report", "body.yaml", "-o", "r.md", "--force", cwd=tree)
    assert r.code == 0, r.err
    assert not (files / "old.svg").exists() and list(files.iterdir())
    assert leftovers(tree) == []


@pytest.mark.parametrize("case", ["dangling-link", "link-to-folder", "file", "holds-a-folder"])
def test_a_figures_folder_that_is_not_a_folder_of_files_is_refused(cli, tree, case):
    files = tree / "r_files"
    if case == "dangling-link":
        files.symlink_to(tree / "gone")
    elif case == "link-to-folder":
        (tree / "elsewhere").mkdir()
        files.symlink_to(tree / "elsewhere")
    elif case == "file":
        files.write_text("x")
    else:
        (files / "keep").mkdir(parents=True)
    before = snapshot(tree)
    r = cli("report", "body.yaml", "-o", "r.md", "--force", cwd=tree)
    one_line(r, says="r_files")
    assert snapshot(tree) == before


def test_no_clobber_is_one_step(tree, monkeypatch):
    # the name appears between the check and the rename (another process): never replaced
    target = tree / "new.html"
    real_commit = outfile._commit

    def racing(tmp, path, option, replace):
        target.write_text("the other run's report\n")
        return real_commit(tmp, path, option, replace)

    monkeypatch.setattr(outfile, "_commit", racing)
    with pytest.raises(InputError, match="exists; use force") as info:
        outfile.write_atomic(target, "mine\n", "-o", replace=False)
    assert "exists; use --force" in info.value.spelled(option_name)  # the command line's words
    assert target.read_text() == "the other run's report\n"
    assert leftovers(tree) == []


def test_rename_noreplace_fallback_is_no_clobber_too(tree, monkeypatch):
    monkeypatch.setattr(outfile, "_renameat2_noreplace", lambda a, b: False)  # link(2) path
    (tree / "a").write_text("a")
    (tree / "b").write_text("b")
    with pytest.raises(FileExistsError):
        outfile.rename_noreplace(str(tree / "a"), str(tree / "b"))
    outfile.rename_noreplace(str(tree / "a"), str(tree / "c"))
    assert (tree / "c").read_text() == "a" and not (tree / "a").exists()


@pytest.mark.slow
def test_twenty_parallel_reports_without_force_exactly_one_wins(cli_proc, tree):
    procs = [cli_proc.start("report", "body.yaml", "-o", "new.html", cwd=tree) for _ in range(20)]
    runs = [cli_proc.finish(p, timeout=300) for p in procs]
    codes = [r.code for r in runs]
    assert sorted(codes) == [0] + [2] * 19, (codes, [r.err for r in runs])
    assert all("exists; use --force" in r.err for r in runs if r.code == 2)
    assert leftovers(tree) == []


# --------------------------------------------------------------------------- unbounded work


def _diamond(folder: Path, n: int) -> Path:
    """n files, each including the next twice; the last is one box."""
    for i in range(n - 1):
        (folder / f"f{i}.yaml").write_text(
            f"parts:\n  - {{name: a, shape: include, file: f{i + 1}.yaml}}\n"
            f"  - {{name: b, shape: include, file: f{i + 1}.yaml, at: [1, 0, 0]}}\n"
        )
    (folder / f"f{n - 1}.yaml").write_text(BOX + "\n")
    return folder / "f0.yaml"


def test_an_include_diamond_is_parsed_once_per_file(tmp_path, monkeypatch):
    top = _diamond(tmp_path, 16)
    parses: list[str] = []
    real_load = ys.load

    def counting(data, filename, **kw):
        parses.append(filename)
        return real_load(data, filename, **kw)

    monkeypatch.setattr(ys, "load", counting)
    reads: list[str] = []
    real_read = includes_mod.read_body_file
    monkeypatch.setattr(includes_mod, "read_body_file", lambda p, where=None: reads.append(str(p)) or real_read(p, where))
    b = load_body(str(top))
    assert len(parses) == 16 and len(set(parses)) == 16  # linear work: each file once
    assert len(reads) == 16
    assert len(b.parts) == 2 ** 15
    assert b.parts[-1].name == "b/" * 15 + "b"
    assert abs(sum(p.mass for p in b.parts) - 2 * 2 ** 15) < 1e-6
    # a memoised file is placed per use: the two halves are 1 m apart at every level
    assert b.parts[0].com[0] == 0.0 and b.parts[-1].com[0] == 15.0


def test_the_parts_budget_is_located_and_settable(cli, tmp_path):
    top = _diamond(tmp_path, 12)
    r = cli("inertia", str(top), "--json", env={"RBCLI_MAX_PARTS": "1000"})
    one_line(r, located=True, says="RBCLI_MAX_PARTS")
    assert "more than 1000 parts" in r.err
    assert cli("inertia", str(top), "--json", env={"RBCLI_MAX_PARTS": "100000"}).code == 0
    one_line(cli("inertia", str(top), env={"RBCLI_MAX_PARTS": "many"}), says="RBCLI_MAX_PARTS")


def test_a_memoised_include_still_obeys_the_depth_limit(tmp_path):
    # deep.yaml nests 10 levels; used once near the top, then again 10 levels down
    for i in range(10):
        (tmp_path / f"d{i}.yaml").write_text(f"parts:\n  - {{name: x, shape: include, file: d{i + 1}.yaml}}\n")
    (tmp_path / "d10.yaml").write_text(BOX + "\n")
    for i in range(8):
        (tmp_path / f"e{i}.yaml").write_text(f"parts:\n  - {{name: y, shape: include, file: e{i + 1}.yaml}}\n")
    (tmp_path / "e8.yaml").write_text("parts:\n  - {name: z, shape: include, file: d0.yaml}\n")
    (tmp_path / "top.yaml").write_text(
        "parts:\n  - {name: first, shape: include, file: d0.yaml}\n"
        "  - {name: deep, shape: include, file: e0.yaml}\n"
    )
    with pytest.raises(InputError, match="nested more than 16 deep"):
        load_body(str(tmp_path / "top.yaml"))


NESTED = "(((((((mm^12)^12)^12)^12)^12)^12)^12)"
UNIT_CASES = [
    ("inertia", "examples/cube.yaml", "--about", f"1,1,1 {NESTED}"),
    ("inertia", "examples/cube.yaml", "--omega", f"0,0,1 rad/s*{NESTED}"),
    ("inertia", "examples/cube.yaml", "--units", f"{NESTED},g"),
    ("inertia", "-e", f"{{shape: box, mass: 2, size: ['1 {NESTED}', 1, 1]}}"),
    ("inertia", "-e", f"{{units: {{length: '{NESTED}'}}, shape: box, mass: 2, size: [1, 1, 1]}}"),
    ("inertia", "-e", "{shape: box, mass: '2 kg*(m/m)^12^12', size: [1, 1, 1]}"),
    ("inertia", "-e", "{shape: box, mass: '2 kg*' + 'm*' * 40, size: [1, 1, 1]}"),
]


@pytest.mark.parametrize("args", UNIT_CASES, ids=range(len(UNIT_CASES)))
def test_nested_unit_powers_are_refused_at_once(cli, args):
    r = cli(*args)
    one_line(r)


def test_unit_powers_are_bounded_before_anything_is_expanded():
    from rbcli.io import unitparse, units

    calls = []
    real = unitparse._UnitParser.expand
    unitparse._UnitParser.expand = lambda self, p: calls.append(dict(p)) or real(self, p)
    try:
        with pytest.raises(units.UnitError, match="power of 'mm' reaches 144"):
            units.parse_quantity(f"1 {NESTED}")
        assert calls == []  # refused while reading, before any factor was built
        assert units.parse_unit("(mm^2)^3")[1] == units.Dim(L=6)
        assert units.parse_unit("kg*m^2/s^2")[0] == 1.0
    finally:
        unitparse._UnitParser.expand = real


INPUT_DEVICES = ["/dev/zero", "/dev/urandom", "/dev/null"]


@pytest.mark.parametrize("dev", INPUT_DEVICES)
def test_a_device_as_body_is_refused_before_reading(cli, dev):
    one_line(cli("inertia", dev), says="is a device")


def test_a_fifo_as_body_or_include_is_refused_without_hanging(cli, tmp_path):
    os.mkfifo(tmp_path / "pipe.yaml")  # no writer: opening it for reading would block
    one_line(cli("inertia", str(tmp_path / "pipe.yaml")), says="FIFO")
    (tmp_path / "inc.yaml").write_text("parts:\n  - {name: p, shape: include, file: pipe.yaml}\n")
    one_line(cli("inertia", str(tmp_path / "inc.yaml")), located=True, says="FIFO")


def test_a_folder_and_a_huge_sparse_file_are_refused_before_reading(cli, tmp_path):
    one_line(cli("inertia", str(tmp_path)), says="is a directory")
    big = tmp_path / "big.yaml"
    with open(big, "wb") as fh:
        fh.truncate(2 * 1024 ** 3)  # 2 GiB, sparse: reading it would take 2 GiB of memory
    one_line(cli("inertia", str(big)), says="limited to 32 MiB")
    one_line(cli("inertia", str(big), env={"RBCLI_MAX_BODY_BYTES": "1024"}), says="RBCLI_MAX_BODY_BYTES")


def test_standard_input_is_read_incrementally_with_the_same_cap():
    from rbcli.io.reader import ReadError, read_stream

    class Endless:
        served = 0

        def read(self, n=-1):
            assert n > 0  # never "read everything"
            self.served += n
            return b"\0" * n

    s = Endless()
    with pytest.raises(ReadError, match="is more than 8 MiB"):
        read_stream(s, 8 * 1024 * 1024, "body file")
    assert s.served <= 8 * 1024 * 1024 + 65536


def test_stdin_over_the_cap_is_refused(cli):
    one_line(cli("inertia", "-", input=b"#" * (32 * 1024 * 1024 + 10)), says="standard input")


# --------------------------------------------------------------------------- internal errors

MATH_NAMES = ["$\\frac{$", "a^{" * 300, "$x$ $", "\\begin{x}", "$" * 50]


@pytest.mark.parametrize("name", sampled_params(MATH_NAMES, [0, 4], ids=[str(i) for i in range(len(MATH_NAMES))]))
def test_matplotlib_math_in_a_name_is_shown_as_text(cli, tmp_path, name):
    import json

    body = tmp_path / "b.yaml"
    body.write_text(f"name: {json.dumps(name)}\nparts:\n  - {BOX}\n")
    r = cli("precess", str(body), "--omega", "0,0,1", "--plot", str(tmp_path / "p.svg"))
    assert r.code == 0 and r.err == "", r.err
    assert (tmp_path / "p.svg").stat().st_size > 0


NUL_CASES = [
    "{shape: include, file: \"a\\0b.yaml\"}",
    "{shape: mesh, file: \"a\\0b.stl\", density: 1}",
]


@pytest.mark.parametrize("expr", NUL_CASES, ids=["include", "mesh"])
def test_a_nul_in_a_file_name_is_bad_input(cli, expr):
    one_line(cli("inertia", "-e", expr))


def test_a_nul_in_an_output_name_is_bad_input(cli, tree):
    one_line(cli("precess", "body.yaml", "--omega", "0,0,1", "--csv", "a\0b.csv", cwd=tree))


# --------------------------------------------------------------------------- terminal injection

#: YAML double-quoted escapes that would forge or break a line on a terminal
FORGERIES = {
    "newline": "\\nrbcli: all good",
    "cr": "\\rrbcli: all good",
    "nel": "\\Nrbcli: all good",
    "ls": "\\Lrbcli: all good",
    "ps": "\\Prbcli: all good",
    "esc": "\\e[31mred\\e[0m\\e]0;title\\a",
    "nul": "\\0x",
    "bidi": "\\u202eevil",
}


@pytest.mark.parametrize("kind", FORGERIES)
def test_a_value_echoed_in_an_error_is_one_safe_line(cli, kind):
    r = cli("inertia", "-e", f'{{shape: box, mass: "2 furlong{FORGERIES[kind]}", size: [1, 1, 1]}}')
    err = one_line(r, located=True)
    assert "all good" not in err or "\\" in err


@pytest.mark.parametrize("kind", FORGERIES)
def test_a_name_in_a_table_title_and_warning_is_safe(cli, tmp_path, kind):
    body = tmp_path / "b.yaml"
    body.write_text(f'name: "body{FORGERIES[kind]}"\nparts:\n  - {{name: "p{FORGERIES[kind]}", '
                    'shape: box, mass: 2, size: [0.1, 0.2, 0.3]}\n')
    r = cli("inertia", str(body))
    assert r.code == 0, r.err
    assert not CONTROL.search(r.out.replace("\n", "")), repr(r.out[:300])
    r = cli("inertia", str(body), "--about", "1,2")
    one_line(r)


def test_a_block_scalar_value_stays_on_one_line(cli):
    r = cli("inertia", "-e", "shape: box\nmass: |\n  2 furlong\n  rbcli: all good\nsize: [1, 1, 1]\n")
    one_line(r, located=True)


@pytest.mark.parametrize("where", ["mass", "name"])
def test_a_megabyte_value_is_cut(cli, tmp_path, where):
    big = "9" * 5_000_000
    body = tmp_path / "b.yaml"
    if where == "mass":
        body.write_text(f"shape: box\nmass: '{big} furlong'\nsize: [1, 1, 1]\n")
    else:
        body.write_text(f"parts:\n  - {{name: x{big}, shape: box, mass: 1, size: [1, 1, 1]}}\n"
                        f"  - {{name: x{big}, shape: box, mass: 1, size: [1, 1, 1]}}\n")
    err = one_line(cli("inertia", str(body)))
    assert "…" in err or len(err) < 400


def test_clean_escapes_and_cuts():
    from rbcli.env import clean

    assert clean("a\nb\rc\x1b[31m\x85\u2028\u2029\x00\t") == "a\\nb\\rc\\e[31m\\x85\\u2028\\u2029\\x00\\t"
    assert clean("line\nnext", keep_newlines=True) == "line\nnext"
    cut = clean("x" * 1000)
    assert cut == "x" * 200 + "…"
    assert clean("ok · ² µ °") == "ok · ² µ °"  # printable text is left alone


# --------------------------------------------------------------------------- leftovers


@pytest.mark.parametrize("failure", [KeyboardInterrupt, OSError(28, "No space left on device")],
                         ids=["interrupt", "disk-full"])
def test_a_report_interrupted_while_writing_figures_leaves_nothing(cli, tree, monkeypatch, failure):
    calls = []
    real_create = outfile._create

    def failing(path):
        calls.append(path)
        if len(calls) == 1 and os.sep + ".rbcli-" in path:  # the first figure in the folder
            raise failure
        return real_create(path)

    monkeypatch.setattr(outfile, "_create", failing)
    before = snapshot(tree)
    r = cli("report", "body.yaml", "-o", "r.md", cwd=tree)
    assert r.code == (130 if failure is KeyboardInterrupt else 2), r.err
    assert snapshot(tree) == before  # no r.md, no r_files/, no .rbcli-*.tmp
    if r.code == 2:
        one_line(r, says="-o: cannot write")
    # and the next run is not refused because of a half-made r_files/
    monkeypatch.setattr(outfile, "_create", real_create)
    assert cli("report", "body.yaml", "-o", "r.md", cwd=tree).code == 0


def test_a_failed_document_rename_takes_the_new_folder_back(tree, monkeypatch):
    files = tree / "r_files"
    files.mkdir()
    (files / "old.svg").write_text("old")
    (tree / "r.md").write_text("old report")

    def broken(tmp, path, option, replace):
        raise OSError(5, "Input/output error")

    monkeypatch.setattr(outfile, "_commit", broken)
    with pytest.raises(InputError, match="cannot write"):
        outfile.write_document(tree / "r.md", "new", "-o", replace=True, files={"a.svg": "<svg/>"})
    assert (files / "old.svg").read_text() == "old" and sorted(os.listdir(files)) == ["old.svg"]
    assert (tree / "r.md").read_text() == "old report"
    assert leftovers(tree) == []


def test_matplotlib_warnings_do_not_reach_stderr(cli, tmp_path):
    body = tmp_path / "b.yaml"
    body.write_text('name: "ctrl \\e \\x01 \\x7f"\nparts:\n  - ' + BOX + "\n")
    r = cli("precess", str(body), "--omega", "0,0,1", "--plot", str(tmp_path / "p.png"))
    assert r.code == 0 and r.err == "", r.err
