"""A file that cannot be read raises an error a Python user catches either way (issue 32
item 6): rbcli.InputError (exit 2 on the command line) and the OSError subclass Python's
own open() would raise, with errno and filename."""

from __future__ import annotations

import errno
import os
import pickle

import pytest

import rbcli
from rbcli.io import reader


def test_a_missing_body_is_an_input_error_and_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError) as exc:
        rbcli.load(tmp_path / "nope.yaml")
    assert isinstance(exc.value, rbcli.InputError) and isinstance(exc.value, ValueError)
    assert exc.value.errno == errno.ENOENT and exc.value.filename == str(tmp_path / "nope.yaml")
    assert str(exc.value) == f"no such file: {tmp_path / 'nope.yaml'}"  # the message as it was


def test_a_folder_is_an_is_a_directory_error(tmp_path):
    with pytest.raises(IsADirectoryError) as exc:
        rbcli.load(tmp_path)
    assert isinstance(exc.value, rbcli.InputError) and exc.value.errno == errno.EISDIR


def test_an_unreadable_file_is_a_permission_error(tmp_path, monkeypatch):
    # root reads any file: the refusal os.open gives a user without the right is played
    body = tmp_path / "b.yaml"
    body.write_text("{shape: point, mass: 1}\n")

    def denied(*args, **kwargs):
        raise PermissionError(errno.EACCES, "Permission denied")

    monkeypatch.setattr(os, "open", denied)
    with pytest.raises(PermissionError) as exc:
        reader.read_regular(body, 1 << 20, "body file")
    assert isinstance(exc.value, rbcli.InputError) and "permission denied" in str(exc.value)


def test_the_command_line_still_says_one_line(cli):
    code, out, err = cli("inertia", "examples/nope.yaml")
    assert (code, out, err) == (2, "", "rbcli: no such file: examples/nope.yaml\n")


def test_the_error_keeps_its_kind_when_pickled(tmp_path):
    try:
        rbcli.load(tmp_path / "nope.yaml")
    except rbcli.InputError as exc:
        back = pickle.loads(pickle.dumps(exc))
        assert isinstance(back, FileNotFoundError) and str(back) == str(exc)


@pytest.mark.parametrize("part, file", [
    ("{shape: include, file: missing.yaml}", "missing.yaml"),
    ("{shape: mesh, file: missing.stl, density: 1000}", "missing.stl"),
    ("{shape: mesh, file: missing.obj, mass: 1}", "missing.obj"),
])
def test_a_missing_include_or_mesh_is_file_not_found_at_its_line(tmp_path, part, file):
    body = tmp_path / "b.yaml"
    body.write_text(f"name: b\nparts:\n  - {part}\n")
    with pytest.raises(FileNotFoundError) as exc:
        rbcli.load(body)
    e = exc.value
    assert isinstance(e, rbcli.InputError) and e.errno == errno.ENOENT and e.filename == str(tmp_path / file)
    assert str(e).startswith(f"{body}:3:") and str(tmp_path / file) in str(e)  # located where it is named
    assert isinstance(pickle.loads(pickle.dumps(e)), FileNotFoundError)


def test_a_folder_named_as_a_mesh_is_an_is_a_directory_error(tmp_path):
    (tmp_path / "d.stl").mkdir()
    body = tmp_path / "b.yaml"
    body.write_text("name: b\nparts:\n  - {shape: mesh, file: d.stl, density: 1000}\n")
    with pytest.raises(IsADirectoryError) as exc:
        rbcli.load(body)
    assert str(exc.value).startswith(f"{body}:3:")


def test_a_missing_step_file_is_file_not_found(tmp_path):
    pytest.importorskip("OCP")
    body = tmp_path / "b.yaml"
    body.write_text("name: b\nparts:\n  - {shape: step, file: gone.step, density: 1000}\n")
    with pytest.raises(FileNotFoundError) as exc:
        rbcli.load(body)
    assert str(exc.value).startswith(f"{body}:3:") and "gone.step" in str(exc.value)
