"""``principal`` reports tilts as tilts and stability words that agree with its text (issue 24,
item 2 and the neutral axes of item 3).

The oracle is the construction: a cylinder (100 mm across, 1000 mm long) turned 0.5° about
body x has its axis 0.5° from z, one transverse axis 0.5° from y and the other along x;
the ascending order of the moments puts axis 1 along z, so the rotation to the ordered frame
is about 90° — printed too, but labelled as that rotation.
"""

from __future__ import annotations

import pytest

ROD = ("{units: {length: mm}, shape: cylinder, diameter: 100, length: 1000, mass: 1, "
       "rotate: {axis: [1, 0, 0], angle: 0.5}}")


def test_a_rod_turned_half_a_degree_reads_half_a_degree(cli):
    d = cli("principal", "-e", ROD, "--json").json()
    # 1e-12°: atan2 of the turned components, round-off of sin/cos of 0.5° only
    assert d["tilt_deg"] == pytest.approx([0.5, 0.5, 0.0], abs=1e-12)
    assert d["tilt_axis"] == ["z", "y", "x"]
    assert d["rotation_angle_deg"] == pytest.approx(90.0011, abs=1e-4)  # kept, unchanged
    text = cli("principal", "-e", ROD).out
    assert "principal axes tilted up to 0.5° from the body axes: axis 1 by 0.5° from z, " \
           "axis 2 by 0.5° from y, axis 3 by 0° from x" in " ".join(text.split())
    assert "rotation taking the body axes to principal axes 1, 2, 3 (in ascending order of the " \
           "moments): 90.0011°" in " ".join(text.split())
    # the tilt comes before the rotation: it is the headline
    assert text.index("tilted up to") < text.index("rotation taking")


def test_neutral_axes_are_not_called_stable(cli):
    d = cli("principal", "-e", ROD, "--json").json()
    assert d["stability"] == ["stable", "neutral", "neutral"]
    assert d["stable"] == [True, False, False]
    text = cli("principal", "-e", ROD).out
    rows = [line.split("|") for line in text.splitlines() if line[:1] in "123" and "|" in line]
    assert [r[-1].strip() for r in rows] == ["stable", "neutral", "neutral"]
    assert "(neutral)" in " ".join(text.split())


def test_an_asymmetric_body_keeps_its_words(cli):
    d = cli("principal", "-e", "{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}", "--json").json()
    assert d["stability"] == ["stable", "unstable", "stable"] and d["stable"] == [True, False, True]
    assert d["tilt_deg"] == [0.0, 0.0, 0.0] and d["tilt_axis"] == ["z", "y", "x"]


def test_the_api_gives_the_same(cli):
    import rbcli

    r = rbcli.principal(rbcli.load_text(ROD))
    assert r.to_json()["tilt_deg"] == cli("principal", "-e", ROD, "--json").json()["tilt_deg"]
    assert r.tilt_axis == ("z", "y", "x") and r.stability == ("stable", "neutral", "neutral")
