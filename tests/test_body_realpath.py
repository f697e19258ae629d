"""rbcli.body.bodyfile._realpath: os.path.realpath of a file, its folder's real path cached
(issue 16, a batch of files in one folder) -- the same string in every case."""

from __future__ import annotations

import os

import pytest

from rbcli.body import bodyfile as body


@pytest.fixture
def tree(tmp_path, monkeypatch):
    """real/a/f.yaml, real/a/g.yaml; link_dir -> real/a; real/a/link_file -> g.yaml;
    up -> real (a link to a folder used with '..'); the cwd is tmp_path."""
    a = tmp_path / "real" / "a"
    a.mkdir(parents=True)
    (a / "f.yaml").write_text("x")
    (a / "g.yaml").write_text("x")
    (tmp_path / "link_dir").symlink_to(a)
    (a / "link_file").symlink_to("g.yaml")
    (tmp_path / "up").symlink_to(tmp_path / "real")
    (tmp_path / "b").mkdir()
    monkeypatch.chdir(tmp_path)
    body._REAL_DIRS.clear()
    return tmp_path


CASES = [
    "real/a/f.yaml", "./real/a/f.yaml", "real//a/./f.yaml", "b/../real/a/f.yaml",
    "link_dir/f.yaml", "link_dir/link_file", "real/a/link_file", "up/a/f.yaml",
    "link_dir/../a/f.yaml", "up/../real/a/f.yaml", "link_dir/../../b/../real/a/f.yaml",
    "real/a/missing.yaml", "real/a/f.yaml/", "real/a/.", "real/a/..", "f.yaml",
]


@pytest.mark.parametrize("rel", CASES)
def test_same_as_realpath(tree, rel):
    for path in (rel, str(tree / rel)):
        for _ in range(2):  # the first call fills the cache, the second uses it
            assert body._realpath(path) == os.path.realpath(path)


def test_relative_paths_follow_the_cwd(tree, monkeypatch):
    assert body._realpath("f.yaml") == os.path.realpath("f.yaml")
    monkeypatch.chdir(tree / "real" / "a")
    assert body._realpath("f.yaml") == os.path.realpath("f.yaml") == str(tree / "real" / "a" / "f.yaml")
    assert body._realpath("./f.yaml") == os.path.realpath("./f.yaml")


def test_a_folder_relinked_is_seen(tree):
    assert body._realpath("link_dir/f.yaml") == str(tree / "real" / "a" / "f.yaml")
    (tree / "b" / "f.yaml").write_text("x")
    (tree / "link_dir").unlink()
    (tree / "link_dir").symlink_to(tree / "b")
    assert body._realpath("link_dir/f.yaml") == os.path.realpath("link_dir/f.yaml") == str(tree / "b" / "f.yaml")


def test_a_file_made_a_link_is_seen(tree):
    assert body._realpath("real/a/f.yaml") == os.path.realpath("real/a/f.yaml")
    (tree / "real" / "a" / "f.yaml").unlink()
    (tree / "real" / "a" / "f.yaml").symlink_to(tree / "b")
    assert body._realpath("real/a/f.yaml") == os.path.realpath("real/a/f.yaml") == str(tree / "b")


def test_load_body_inputs(tree):
    (tree / "real" / "a" / "f.yaml").write_text("shape: point\nmass: 1\n")
    for path in ("link_dir/f.yaml", "up/a/f.yaml", str(tree / "link_dir" / "f.yaml")):
        assert body.load_body(path).inputs == (os.path.realpath(path),)
