"""The report in Python (``rbcli.report``, ``rbcli.report_text``, ``rbcli.write_report``)
against ``rbcli report`` (the command line).

The oracle is the command line itself: for several examples and option sets the document
``rbcli.report_text(body, ...)`` returns is, byte for byte, the file ``rbcli report`` writes
(HTML and Markdown, SOURCE_DATE_EPOCH fixed); written by ``rbcli.write_report`` the file, its
figures and the exit status are the CLI's; errors are InputError with the CLI's line (options
spelled as parameters). What the report holds is checked in ``test_cli_report.py``.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import rbcli
from conftest import sampled_params
from rbcli.errors import option_name
from rbcli.api.report import ReportResult, parse, run

ROOT = Path(__file__).resolve().parent.parent
EPOCH = "1700000000"

#: (example, CLI options, the same as API keywords)
CASES = {
    "two_disk_rotor": (["--planes", "0,400mm", "--radius", "100mm", "--speed", "3000 rpm",
                        "--bearings", "0,400mm", "--grade", "G6.3"],
                       {"planes": "0,400mm", "radius": "100mm", "speed": "3000 rpm",
                        "bearings": "0,400mm", "grade": "G6.3"}),
    "top": (["--spin", "150", "--theta", "30"], {"spin": "150", "theta": "30"}),
    "bracket": ([], {}),
    "frisbee": (["--omega", "0,1,30"], {"omega": "0,1,30"}),
}


@pytest.fixture(autouse=True)
def _fixed_date(monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", EPOCH)
    monkeypatch.chdir(ROOT)  # bodies named by relative path, as the CLI runs see them


def _body(name: str):
    return rbcli.load(f"examples/{name}.yaml")


def _cli_file(cli, tmp_path, name, args, ext):
    out = tmp_path / f"report{ext}"
    r = cli("report", f"examples/{name}.yaml", *args, "-o", out, env={"SOURCE_DATE_EPOCH": EPOCH})
    assert r.code in (0, 1), r.err
    return r, out


# by default one case in each format (two_disk_rotor, the most sections, as HTML; bracket as
# Markdown, and top's Markdown with its figures below); every case in both formats under -m slow
@pytest.mark.parametrize("name", sampled_params(sorted(CASES), lambda n: n == "two_disk_rotor",
                                                ids=sorted(CASES)))
def test_html_text_is_the_file_the_cli_writes(cli, tmp_path, name):
    args, kw = CASES[name]
    _, out = _cli_file(cli, tmp_path, name, args, ".html")
    text = rbcli.report_text(_body(name), **kw)
    assert isinstance(text, str)
    assert text == out.read_text(encoding="utf-8")


@pytest.mark.parametrize("name", sampled_params(sorted(CASES), lambda n: n == "bracket",
                                                ids=sorted(CASES)))
def test_markdown_text_is_the_file_the_cli_writes(cli, tmp_path, name):
    args, kw = CASES[name]
    _, out = _cli_file(cli, tmp_path, name, args, ".md")  # figures in report_files/, as the API links them
    assert rbcli.report_text(_body(name), format="md", **kw) == out.read_text(encoding="utf-8")


@pytest.mark.parametrize("name", sampled_params(["two_disk_rotor", "top"], [1], ids=["two_disk_rotor", "top"]))
def test_written_through_the_api_as_by_the_cli(cli, tmp_path, name):
    args, kw = CASES[name]
    (tmp_path / "cli").mkdir()
    r, out = _cli_file(cli, tmp_path / "cli", name, args, ".md")
    mine = tmp_path / "api" / "report.md"
    mine.parent.mkdir()
    res = rbcli.write_report(_body(name), mine, **kw)
    assert isinstance(res, ReportResult)
    assert res.return_code == r.code
    assert mine.read_bytes() == out.read_bytes()
    cli_files = {p.name: p.read_bytes() for p in (tmp_path / "cli" / "report_files").iterdir()}
    api_files = {p.name: p.read_bytes() for p in (tmp_path / "api" / "report_files").iterdir()}
    assert api_files == cli_files and api_files
    # the same rules as the CLI: an existing report only with force
    with pytest.raises(rbcli.InputError) as exc:
        rbcli.write_report(_body(name), mine, **kw)
    assert str(exc.value).startswith("path: ") and "exists; use force" in str(exc.value)  # its parameters
    cli_text = exc.value.spelled(lambda p: option_name(p, "report"))  # as `rbcli report` says it
    assert cli_text.startswith("-o: ") and cli_text.endswith("exists; use --force to replace it")
    assert rbcli.write_report(_body(name), mine, force=True, **kw).return_code == r.code
    for bad in ("false", "no", 0, 1, None):  # a flag takes a bool: no string turns it on
        with pytest.raises(TypeError, match="force"):
            rbcli.write_report(_body(name), mine, force=bad, **kw)
    # rbcli.report computes the same sections and checks without writing
    assert rbcli.report(_body(name), **kw).return_code == r.code


def test_the_result_says_which_sections_and_checks():
    body = _body("two_disk_rotor")
    _, kw = CASES["two_disk_rotor"]
    res = run(body, parse(body, **kw))
    j = res.to_json()
    assert [s["key"] for s in j["sections"]] == [
        "parts", "mass-properties", "principal-axes", "balance", "whirl", "free-precession",
        "heavy-top", "rolling-stability"]
    included = {s["key"]: s["included"] for s in j["sections"]}
    assert included["balance"] and not included["free-precession"] and not included["heavy-top"]
    assert res.failed == ("balance: the rotor as given fails ISO 21940-11 G6.3",) and res.return_code == 1
    assert [s.key for s in res.sections] == [s["key"] for s in j["sections"]]
    # SI numbers are taken as the commands take them
    res2 = run(body, parse(body, planes=[0.0, 0.4], radius=0.1, speed="3000 rpm",
                                         bearings=[0, 0.4], grade=6.3))
    assert res2.return_code == 1


def test_html_contents_link_only_included_sections():
    text = rbcli.report_text(_body("cube"))
    assert '<li class="skip">Balance (not included)</li>' in text
    assert 'href="#balance"' not in text and 'href="#parts"' in text


@pytest.mark.parametrize("args, kw", [
    (["--speed", "3000"], {"speed": "3000"}),
    (["--grade", "G6.3", "--bearings", "0,1"], {"grade": "G6.3", "bearings": "0,1"}),
    (["--theta", "190"], {"theta": 190}),
    (["--spin", "0", "--theta", "30"], {"spin": 0, "theta": 30}),
    (["--planes", "1,2,3"], {"planes": "1,2,3"}),
    (["--radius", "0.1"], {"radius": 0.1}),
    (["--omega", "1,2"], {"omega": "1,2"}),
    (["--rim-radius", "-1"], {"rim_radius": -1}),
    (["--units", "furlong,kg"], {"units": "furlong,kg"}),
    (["--units", "mm,in"], {"units": "mm,in"}),  # two length units
    (["--units", ""], {"units": ""}),
])
def test_bad_options_raise_the_clis_message(cli, tmp_path, args, kw):
    r = cli("report", "examples/cube.yaml", *args, "-o", tmp_path / "r.html")
    assert r.code == 2 and r.err.startswith("rbcli: ")
    with pytest.raises(rbcli.InputError) as exc:
        rbcli.report_text(_body("cube"), **kw)
    assert r.err.strip() == f"rbcli: {exc.value.spelled(option_name)}"
    assert not (tmp_path / "r.html").exists()


def test_output_errors_are_the_clis(cli, tmp_path):
    body = _body("cube")
    for path, needle in ((tmp_path / "r.pdf", "use one of .html, .md"),
                         (Path("examples/cube.yaml"), "never overwrites"),
                         (tmp_path / "nowhere" / "r.html", "does not exist")):
        r = cli("report", "examples/cube.yaml", "-o", path)
        assert r.code == 2 and needle in r.err
        with pytest.raises(rbcli.InputError) as exc:
            rbcli.write_report(body, path)
        assert r.err.strip() == f"rbcli: {exc.value.spelled(option_name)}"
        assert "--" not in str(exc.value).replace("--force", "")  # the API names output, not -o
    with pytest.raises(rbcli.InputError, match="^format must be 'html' or 'md'"):
        rbcli.report_text(body, format="pdf")
    with pytest.raises(rbcli.InputError, match="^format: "):
        rbcli.write_report(body, tmp_path / "r.html", format="md")
    with pytest.raises(rbcli.InputError, match="^speed: give a unit"):  # rad/s or m/s?
        rbcli.report(body, speed=3000)
    with pytest.raises(rbcli.InputError, match="^digits: "):
        rbcli.report_text(body, digits=0)
