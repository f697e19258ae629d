"""Output files (review F2): no output ever replaces an input, one --force policy, atomic writes.

The inputs are every file a body was read from: the body file, its includes at any depth and
its meshes (``Body.inputs``). The review's reproductions (an included file, a nested include
and a mesh as the target of --csv, --plot, --apply and -o) must be refused with exit status 2,
one ``rbcli:`` line naming the option, and the file's bytes unchanged. Documents and bodies
(``report -o``, ``balance --apply``) replace an existing file only with --force; figures and
data (``--plot``, ``--csv``) replace an existing file; every output is written through a
temporary file in the same folder, so none is left behind.

No numbers are checked here (the commands' own test files do that): only which files are
written, refused or left alone, byte for byte.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from rbcli.errors import InputError
from rbcli.io import outfile
from rbcli.body.model import load_body, load_expr

ROOT = Path(__file__).resolve().parent.parent

#: a disk symmetric about z, above the origin (a top on a pivot at the origin, a wheel)
DISK = "parts:\n  - {name: disk, shape: disk, radius: 0.1, mass: 1, at: [0, 0, 0.1]}\n"


def cube_stl(path: Path, a: float = 0.05) -> Path:
    """A closed cube mesh a x a x a about the origin (trimesh, binary STL)."""
    import trimesh

    path.write_bytes(trimesh.creation.box(extents=[a, a, a]).export(file_type="stl"))
    return path


@pytest.fixture
def tree(tmp_path, monkeypatch):
    """main.yaml includes sub.yaml and reads cube.stl; top2.yaml includes d/mid.yaml, which
    includes d/leaf.yaml; pic.yaml includes shape.svg and notes.md (body files whose names
    have a figure's or a report's extension). The working folder is tmp_path."""
    (tmp_path / "sub.yaml").write_text(DISK)
    cube_stl(tmp_path / "cube.stl")
    (tmp_path / "main.yaml").write_text(
        "name: main\nparts:\n"
        "  - {name: s, shape: include, file: sub.yaml}\n"
        "  - {name: c, shape: mesh, file: cube.stl, density: 1000, at: [0, 0, 0.1]}\n"
    )
    (tmp_path / "d").mkdir()
    (tmp_path / "d" / "leaf.yaml").write_text(
        "parts:\n  - {name: disk, shape: disk, radius: 0.1, mass: 1}\n"
        "  - {name: lump, shape: point, mass: 0.01, at: [0.05, 0, 0.02]}\n"
    )
    (tmp_path / "d" / "mid.yaml").write_text("parts:\n  - {name: leaf, shape: include, file: leaf.yaml}\n")
    (tmp_path / "top2.yaml").write_text("name: top2\nparts:\n  - {name: mid, shape: include, file: d/mid.yaml}\n")
    (tmp_path / "shape.svg").write_text(DISK)
    (tmp_path / "notes.md").write_text(DISK)
    (tmp_path / "pic.yaml").write_text(
        "name: pic\nparts:\n  - {name: a, shape: include, file: shape.svg}\n"
        "  - {name: b, shape: include, file: notes.md, at: [0, 0, 0.1]}\n"
    )
    monkeypatch.chdir(tmp_path)
    return tmp_path


def refused(cli, tree: Path, target: Path, *args: str, says: str = "is an input file") -> str:
    """Run ``rbcli ARGS`` in the folder ``tree`` (the ``cli`` fixture); expect exit 2, one
    rbcli: line containing ``says``, and ``target`` unchanged."""
    before = target.read_bytes()
    r = cli(*args, cwd=tree)
    assert r.code == 2, (r.code, r.err)
    assert r.out == ""
    assert r.err.startswith("rbcli: ") and r.err.count("\n") == 1, r.err
    assert says in r.err, r.err
    assert target.read_bytes() == before
    return r.err


def leftovers(folder: Path) -> list[str]:
    """Temporary files an atomic write would leave behind."""
    return sorted(p.name for p in folder.rglob("*") if p.name.startswith(".rbcli-"))


# --------------------------------------------------------------------------- Body.inputs


def real(*paths: Path) -> tuple[str, ...]:
    return tuple(os.path.realpath(p) for p in paths)


def test_the_loader_records_every_file_it_read(tree):
    assert load_body("main.yaml").inputs == real(tree / "main.yaml", tree / "sub.yaml", tree / "cube.stl")
    # nested includes, at any depth, in the order they were read
    assert load_body("top2.yaml").inputs == real(tree / "top2.yaml", tree / "d/mid.yaml", tree / "d/leaf.yaml")
    # -e (and standard input) read no file of their own, but what they include counts
    assert load_expr("{shape: include, file: d/mid.yaml}").inputs == real(tree / "d/mid.yaml", tree / "d/leaf.yaml")
    assert load_expr("{shape: point, mass: 1}").inputs == ()
    # a file included twice is listed once; a symlinked body is listed by its real path
    (tree / "twice.yaml").write_text(
        "parts:\n  - {name: a, shape: include, file: sub.yaml}\n"
        "  - {name: b, shape: include, file: ./sub.yaml, at: [1, 0, 0]}\n"
    )
    (tree / "link.yaml").symlink_to(tree / "twice.yaml")
    assert load_body("link.yaml").inputs == real(tree / "twice.yaml", tree / "sub.yaml")


# --------------------------------------------------------------------------- the review's reproductions


def test_precess_csv_onto_an_included_file_is_refused(cli, tree):
    refused(cli, tree, tree / "sub.yaml", "precess", "main.yaml", "--omega", "0,0,1", "--csv", "sub.yaml",
            "--duration", "1", says="--csv: 'sub.yaml' is an input file")
    # the same through -e: the expression reads sub.yaml
    refused(cli, tree, tree / "sub.yaml", "precess", "-e", "{shape: include, file: sub.yaml}", "--omega", "0,0,1",
            "--csv", "sub.yaml", "--duration", "1", says="--csv:")


def test_top_csv_onto_an_included_file_or_a_mesh_is_refused(cli, tree):
    args = ("top", "main.yaml", "--spin", "150", "--theta", "30")
    refused(cli, tree, tree / "sub.yaml", *args, "--csv", "sub.yaml", says="--csv: 'sub.yaml' is an input file")
    refused(cli, tree, tree / "cube.stl", *args, "--csv", "cube.stl", says="--csv: 'cube.stl' is an input file")
    refused(cli, tree, tree / "main.yaml", *args, "--csv", "./main.yaml", says="--csv:")


def test_plot_onto_an_included_file_is_refused(cli, tree):
    svg = tree / "shape.svg"  # an included body file with a figure's extension
    refused(cli, tree, svg, "top", "pic.yaml", "--spin", "150", "--theta", "30", "--plot", "shape.svg", says="--plot:")
    refused(cli, tree, svg, "precess", "pic.yaml", "--omega", "0,0,1", "--plot", "shape.svg", says="--plot:")
    refused(cli, tree, svg, "rollcheck", "pic.yaml", "--plot", str(svg), says="--plot:")
    # a plot onto a mesh: refused as an input, before its extension is looked at
    refused(cli, tree, tree / "cube.stl", "top", "main.yaml", "--spin", "150", "--theta", "30",
            "--plot", "cube.stl", says="--plot: 'cube.stl' is an input file")


def test_apply_onto_a_nested_include_is_refused_even_with_force(cli, tree):
    for target in ("d/leaf.yaml", "d/mid.yaml", "top2.yaml"):
        refused(cli, tree, tree / target, "balance", "top2.yaml", "--planes=-0.1,0.1", "--radius", "0.1",
                "--apply", target, "--force", says=f"--apply: '{target}' is an input file")


def test_report_onto_an_include_is_refused_even_with_force(cli, tree):
    refused(cli, tree, tree / "notes.md", "report", "pic.yaml", "-o", "notes.md", "--force",
            says="-o: 'notes.md' is an input file")
    # a Markdown report's figures folder must not hold an input either
    (tree / "r_files").mkdir()
    (tree / "r_files" / "inner.yaml").write_text(DISK)
    (tree / "r.yaml").write_text("parts:\n  - {name: i, shape: include, file: r_files/inner.yaml}\n")
    refused(cli, tree, tree / "r_files" / "inner.yaml", "report", "r.yaml", "-o", "r.md", "--force",
            says="holds an input file")
    assert not (tree / "r.md").exists()


def test_hard_links_and_symlinks_to_an_input_are_refused(cli, tree):
    os.link(tree / "sub.yaml", tree / "alias.csv")  # the same file under another name
    (tree / "sym.csv").symlink_to(tree / "cube.stl")
    args = ("top", "main.yaml", "--spin", "150", "--theta", "30")
    refused(cli, tree, tree / "sub.yaml", *args, "--csv", "alias.csv")
    refused(cli, tree, tree / "cube.stl", *args, "--csv", "sym.csv")


def test_the_review_reproduction_through_the_real_entry_point(cli_proc, tree):
    before = (tree / "sub.yaml").read_bytes()
    p = cli_proc("precess", "main.yaml", "--omega", "0,0,1", "--csv", "sub.yaml", "--duration", "1", cwd=tree)
    assert p.code == 2 and p.out == ""
    assert p.err == "rbcli: --csv: 'sub.yaml' is an input file; rbcli never overwrites its inputs\n"
    assert (tree / "sub.yaml").read_bytes() == before


# --------------------------------------------------------------------------- --force policy


def test_apply_and_report_replace_an_existing_file_only_with_force(cli, tree):
    for args, target in (
        (("balance", "top2.yaml", "--planes=-0.1,0.1", "--radius", "0.1", "--apply"), tree / "out.yaml"),
        (("report", "main.yaml", "-o"), tree / "out.html"),
    ):
        target.write_text("keep me\n")
        refused(cli, tree, target, *args, target.name, says="exists; use --force")
        r = cli(*args, target.name, "--force", cwd=tree)
        assert r.code == 0, r.err
        assert target.read_text() != "keep me\n"
    assert "balance A" in (tree / "out.yaml").read_text()  # a body with the corrections
    assert load_body("out.yaml").inputs[0] == os.path.realpath(tree / "out.yaml")
    assert (tree / "out.html").read_text().lstrip().lower().startswith("<!doctype html")
    assert leftovers(tree) == []


def test_plot_and_csv_replace_an_existing_file_that_is_not_an_input(cli, tree):
    fig, csv = tree / "fig.svg", tree / "series.csv"
    fig.write_text("old figure\n")
    csv.write_text("old data\n")
    r = cli("top", "main.yaml", "--spin", "150", "--theta", "30", "--plot", "fig.svg",
            "--csv", "series.csv", "--samples", "3", cwd=tree)
    assert r.code == 0, r.err
    assert fig.read_text().startswith("<?xml")
    assert csv.read_text().splitlines()[0] == "t,theta_deg,phi_deg,psi_deg"
    r = cli("precess", "main.yaml", "--omega", "0,0,1", "--duration", "1", "--samples", "2",
            "--csv", "series.csv", "--plot", "fig.svg", cwd=tree)
    assert r.code == 0, r.err
    assert csv.read_text().splitlines()[0] == "t,wx,wy,wz,Lx,Ly,Lz,qw,qx,qy,qz"
    assert len(csv.read_text().splitlines()) == 3  # header and 2 rows
    assert leftovers(tree) == []


def test_csv_and_plot_must_be_different_files(cli, tree):
    refused(cli, tree, tree / "sub.yaml", "top", "main.yaml", "--spin", "150", "--theta", "30",
            "--plot", "x.svg", "--csv", "x.svg", says="--csv: 'x.svg' is also the --plot file")
    assert not (tree / "x.svg").exists()


@pytest.mark.parametrize("args", [
    ("top", "main.yaml", "--spin", "150", "--theta", "30", "--csv", "no/x.csv"),
    ("top", "main.yaml", "--spin", "150", "--theta", "30", "--plot", "no/x.png"),
    ("precess", "main.yaml", "--omega", "0,0,1", "--duration", "1", "--csv", "no/x.csv"),
    ("rollcheck", "main.yaml", "--plot", "no/x.pdf"),
    ("balance", "top2.yaml", "--planes=-0.1,0.1", "--radius", "0.1", "--apply", "no/x.yaml"),
    ("report", "main.yaml", "-o", "no/x.html"),
], ids=lambda a: a[0] + " " + a[-2])
def test_a_missing_folder_is_exit_2(cli, tree, args):
    r = cli(*args, cwd=tree)
    assert r.code == 2 and r.out == "" and r.err.count("\n") == 1
    assert f"{args[-2]}: the folder 'no' does not exist" in r.err
    assert not (tree / "no").exists()


def test_a_folder_is_not_a_file_name(cli, tree):
    refused(cli, tree, tree / "sub.yaml", "top", "main.yaml", "--spin", "150", "--theta", "30", "--csv", "d",
            says="--csv: 'd' is a folder")
    refused(cli, tree, tree / "sub.yaml", "top", "main.yaml", "--spin", "150", "--theta", "30", "--csv", "new/",
            says="is a folder")


# --------------------------------------------------------------------------- outfile itself


def test_check_lists_the_allowed_extensions_and_names_the_option(tree):
    with pytest.raises(InputError, match=r"^--plot: cannot tell the format of 'a.gif' .* use one of \.png, \.svg$"):
        outfile.check("a.gif", None, "--plot", exts=("png", ".SVG"), replace_ok=True)
    assert outfile.check("A.PNG", None, "--plot", exts=("png",), replace_ok=True) == Path("A.PNG")
    (tree / "file").write_text("x")
    with pytest.raises(InputError, match="'file' is not a folder"):
        outfile.check("file/x.csv", None, "--csv")
    # the inputs may be given as paths instead of a Body
    with pytest.raises(InputError, match="input file"):
        outfile.check("./file", [str(tree / "file")], "--csv", replace_ok=True)


def test_write_atomic_replaces_keeps_the_mode_and_leaves_no_temporary_file(tree):
    f = tree / "d" / "out.txt"
    outfile.write_atomic(f, "one\n")
    assert f.read_text() == "one\n"
    f.chmod(0o640)
    outfile.write_atomic(f, b"two\n")
    assert f.read_bytes() == b"two\n" and (f.stat().st_mode & 0o777) == 0o640
    assert sorted(p.name for p in (tree / "d").iterdir()) == ["leaf.yaml", "mid.yaml", "out.txt"]


def test_a_failed_write_keeps_the_old_file_and_removes_the_temporary_one(tree):
    f = tree / "data.csv"
    f.write_text("old\n")
    with pytest.raises(RuntimeError):
        with outfile.atomic_open(f, "--csv") as fh:
            fh.write("half a fi")
            raise RuntimeError("interrupted")
    assert f.read_text() == "old\n"
    assert leftovers(tree) == []
    # an OSError while writing is a one-line user error naming the option
    with pytest.raises(InputError, match=r"^--csv: cannot write 'data.csv': "):
        with outfile.atomic_open("data.csv", "--csv") as fh:
            raise OSError(28, "No space left on device")
    assert f.read_text() == "old\n" and leftovers(tree) == []


def test_a_symlink_is_never_written_through(tree):
    # issue 15: a link is refused (not followed, not replaced); its target is unchanged
    (tree / "real.csv").write_text("old\n")
    (tree / "link.csv").symlink_to("real.csv")
    with pytest.raises(InputError, match="symbolic link"):
        outfile.write_atomic(tree / "link.csv", "new\n")
    assert (tree / "link.csv").is_symlink() and (tree / "real.csv").read_text() == "old\n"
    assert leftovers(tree) == []
