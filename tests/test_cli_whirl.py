"""``rbcli whirl`` on the command line: exit statuses, one-line errors, figures, formats,
and the report section render builds from a result."""

from __future__ import annotations

import pytest

import rbcli

from conftest import EXAMPLES

CYL = ["-e", "{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}"]
FAN = [str(EXAMPLES / "fan_rotor.yaml"), "--bearings", "0,500mm", "--stiffness", "5 N/um",
       "--damping", "1 N*s/mm", "--speed-range", "0,3000 rpm"]


@pytest.mark.parametrize("args, says", [
    (["--bearings", "0", "--stiffness", "1e6"], "--bearings: a rotor on bearings needs two or more"),
    (["--bearings", "0.1,0.1", "--stiffness", "1e6"], "--bearings: the bearings are all at one place"),
    (["--bearings=-0.2,0.2", "--stiffness=-1e6"], "--stiffness: must be positive"),
    (["--bearings=-0.2,0.2", "--stiffness", "1e6", "--damping=-3"], "--damping: must not be negative"),
    (["--bearings=-0.2,0.2", "--stiffness", "1e6", "--speed-range", "100,100"], "--speed-range: '100,100' is an empty range"),
    (["--bearings=-0.2,0.2", "--stiffness", "1e6", "--speed-range", "3000,0 rpm"], "is not a range"),
    (["--bearings=-0.2,0.2", "--stiffness", "1e6", "--speed-range", "0"], "--speed-range: expected 2"),
    (["--bearings=-0.2,0.2"], "--stiffness: needs the bearing stiffness"),
    (["--stiffness", "1e6"], "--bearings: needs the bearing positions"),
    (["--bearings=-0.2,0.2", "--stiffness", "1e6", "--unbalance", "5 g*mm@0"], "--unbalance: needs the planes"),
    (["--bearings=-0.2,0.2", "--stiffness", "1e6 N"], "--stiffness:"),
    (["--bearings=-0.2,0.2", "--stiffness", "1e6", "--plot", "a.png", "--plot-response", "a.png"],
     "--plot-response: 'a.png' is also the --plot file"),
    (["--bearings=-0.2,0.2", "--stiffness", "1e6", "--plot", "a.txt"], "--plot:"),
    # bearings 1e-7 m apart, 5 m from the com: K singular to round-off (a singular solve, once
    # the generic 'the result overflows' line naming nothing); 1e-10 m apart likewise
    (["--bearings", "5,5.0000001", "--stiffness", "1e6"], "the bearings span 1e-07 m, too little"),
    (["--bearings", "0.29,0.2900000001", "--stiffness", "1e6"], "give --bearings further apart"),
])
def test_bad_input_is_one_located_line_exit_2(cli, args, says):
    r = cli("whirl", *CYL, *args)
    assert r.code == 2, r.err
    assert r.out == ""
    lines = r.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("rbcli: ") and says in lines[0], r.err


def test_an_asymmetric_rotor_is_refused_in_one_line(cli):
    r = cli("whirl", str(EXAMPLES / "two_blade_fan.yaml"), "--bearings=-0.05,0.05", "--stiffness", "1e6")
    assert r.code == 2
    assert len(r.err.splitlines()) == 1 and "not symmetric about its shaft" in r.err and "--symmetry-tol" in r.err


def test_separation_margin_pass_and_fail_set_the_exit_status(cli):
    ok = cli("whirl", *FAN, "--speed", "1480 rpm")
    assert ok.code == 0 and "separation margins: PASS" in ok.out
    bad = cli("whirl", *FAN, "--speed", "1800 rpm")  # 1960 rpm is 8.9 % above: 26 % required
    assert bad.code == 1 and "FAIL" in bad.out
    j = cli("whirl", *FAN, "--speed", "1800 rpm", "--json")
    assert j.code == 1 and j.json()["margins"]["passed"] is False


def test_a_growing_mode_is_said_loudly_and_fails_at_the_operating_speed(cli):
    args = [*CYL, "--bearings=-0.2,0.2", "--stiffness", "1e6", "--cross-stiffness", "1e5",
            "--damping", "100", "--speed", "150"]
    r = cli("whirl", *args)
    assert r.code == 1
    assert "UNSTABLE" in r.out and "GROWS" in r.out
    assert "warning: UNSTABLE AT THE OPERATING SPEED --speed" in r.err


def test_figures_are_written_and_deterministic(cli, tmp_path):
    files = {}
    for run in (1, 2):
        c, p = tmp_path / f"c{run}.svg", tmp_path / f"r{run}.png"
        r = cli("whirl", *FAN, "--speed", "1480 rpm", "--plot", str(c), "--plot-response", str(p))
        assert r.code == 0, r.err
        assert f"--plot: figure written to {c}" in r.out
        files[run] = (c.read_bytes(), p.read_bytes())
    assert files[1][1].startswith(b"\x89PNG")
    assert files[1] == files[2]


def test_response_figure_of_peaks_without_an_amplification_factor(cli, tmp_path):
    # bearings of 1e160 N/m: every peak's AF is undefined (JSON null); the figure drew
    # "AF {None:.3g}" and exited 70 (found by the slow hostile report sweep)
    args = ["examples/two_disk_rotor.yaml", "--bearings=-50,450 mm", "--stiffness", "1e160", "--damping", "500"]
    peaks = cli("whirl", *args, "--json").json()["response"]["peaks"]
    assert peaks and all(p["amplification_factor"] is None for p in peaks)
    r = cli("whirl", *args, "--plot-response", str(tmp_path / "r.svg"))
    assert r.code == 0, r.err
    assert "AF " not in (tmp_path / "r.svg").read_text(encoding="utf-8")


@pytest.mark.parametrize("planes", ["-1e160,1e160", "-1e150,1e150"])
def test_an_unbalance_moment_that_overflows_is_refused(cli, tmp_path, planes):
    # 1e160 kg m at z = -1e160 m: its moment is inf, every response speed was left out as
    # "an undamped critical speed on the grid" (with damping), and the response figure of no
    # speeds exited 70 (IndexError); at --speed the damped rotor was said to sit on a critical
    r = cli("whirl", *CYL, "--bearings=-0.2,0.2", "--stiffness", "1e6", "--damping", "300",
            "--points", "21", "--unbalance", "1e160@0,0@0", f"--unbalance-planes={planes}",
            "--speed", "300", "--plot-response", str(tmp_path / "r.svg"))
    assert r.code == 2 and len(r.err.splitlines()) == 1, r.err
    assert r.err.startswith("rbcli: --unbalance, --unbalance-planes: the unbalance force")
    assert not (tmp_path / "r.svg").exists()


def test_undamped_response_spikes_are_left_out_with_a_warning(cli):
    # 0..250 rad/s in 201 points puts 200 rad/s (the cylindrical critical speed) on the grid
    r = cli("whirl", *CYL, "--bearings=-0.2,0.2", "--stiffness", "1e6", "--unbalance", "1 g*mm@0",
            "--unbalance-planes", "0", "--speed-range", "0,250", "--json")
    assert r.code == 0
    d = r.json()
    assert 200.0 not in d["response"]["speeds"] and len(d["response"]["speeds"]) == 200
    assert "unbounded at 200 rad/s" in r.err
    # no damping: the driven critical speeds are the (infinite) peaks
    assert {(p["speed"], p["undamped"]) for p in d["response"]["peaks"]} == {(200.0, True)}


def test_csv_and_help(cli):
    r = cli("whirl", *FAN, "--speed", "1480 rpm", "--format", "csv")
    assert r.code == 0 and "\ncritical_speeds[0].speed," in r.out  # one CSV table (tests/test_csv_table.py)
    h = cli("whirl", "--help")
    assert h.code == 0
    for words in ("--speed-range", "--unbalance-planes", "forward whirl turns the same way as the spin",
                  "fixed frame", "API 617"):
        assert words in " ".join(h.out.split()), words


def test_report_section_from_a_result():
    from rbcli.api import report
    from rbcli.render import reportdoc
    from rbcli.render.units import DisplayUnits
    from rbcli.render.report import Figure, Section
    from rbcli.render.text import Table

    body = rbcli.load(EXAMPLES / "fan_rotor.yaml")
    res = rbcli.whirl(body, bearings="0,500mm", stiffness="5 N/um", damping="1 N*s/mm", speed="1480 rpm")
    s = reportdoc._whirl(report.Section("whirl", "Whirl", res, warnings=res.warnings), body, DisplayUnits(), 6)
    assert isinstance(s, Section) and s.key == "whirl" and s.skipped is None
    titles = [i.title for i in s.items if isinstance(i, Table)]
    assert any(t.startswith("critical speeds") for t in titles)
    assert any(t.startswith("separation margins") for t in titles)
    figs = [i for i in s.items if isinstance(i, Figure)]
    assert [f.name for f in figs] == ["whirl-campbell", "whirl-response", "whirl-map"]
    assert all(f.svg.lstrip().startswith("<?xml") for f in figs)


def test_figures_say_what_the_table_says(tmp_path, cli):
    """Driven critical speeds drawn on top of undriven ones; coincident critical speeds one
    mark and one label; legends below the axes (never over the data); --plot-map writes the
    map (log-log, plain tick labels)."""
    from rbcli.render import whirl as rw

    # the sheet's cylinder with an unbalance: forward and backward cylindrical at 200 rad/s
    body = rbcli.load_text("{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}")
    res = rbcli.whirl(body, bearings="-0.2,0.2", stiffness=1e6, damping=100,
                      unbalance="5 g*mm@0,5 g*mm@0", unbalance_planes="-0.3,0.3")
    fig = rw.campbell_figure(res)
    ax = fig.axes[0]
    marks = [ln for ln in ax.lines if ln.get_marker() in ("o", "s")]
    driven = [ln for ln in marks if ln.get_markerfacecolor() in ("black", (0, 0, 0, 1))]
    assert driven and all(d.get_zorder() > m.get_zorder() for d in driven for m in marks if m not in driven)
    labels = [t.get_text() for t in ax.texts if t.get_text()[:1].isdigit()]
    assert len(labels) == len(set(labels)) and any("(×2)" in t for t in labels)  # 200 twice: one label
    assert ax.get_legend() is None and fig.legends  # the legend is the figure's, outside the axes
    assert rw.response_figure(res).axes[0].get_legend() is None
    r = cli("whirl", str(EXAMPLES / "journal_rotor.yaml"), "--points", "21", "--plot-map", str(tmp_path / "m.svg"))
    assert r.code == 0 and (tmp_path / "m.svg").stat().st_size > 1000
    m = rw.map_figure(rbcli.whirl(rbcli.load(EXAMPLES / "journal_rotor.yaml"), points=21)).axes[0]
    assert m.get_xscale() == m.get_yscale() == "log"
    m.figure.canvas.draw()  # tick labels are plain numbers (the house's text escapes mathtext's $)
    ticks = [t.get_text() for t in m.get_xticklabels() + m.get_yticklabels() if t.get_text()]
    assert ticks and not any("$" in t for t in ticks)
