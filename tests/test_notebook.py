"""A body and every result show themselves in a notebook (issue 32 item 7): a short one-line
``repr``, and ``_repr_html_`` with the command's tables (units in them) and, where the
command draws one, its figure as inline SVG."""

from __future__ import annotations

import re

import pytest

import rbcli

FAN = "examples/fan_rotor.yaml"


def _results():
    fan = rbcli.load(FAN)
    return {
        "inertia": (rbcli.inertia(fan), False),
        "principal": (rbcli.principal(fan), False),
        "balance": (rbcli.balance(fan, planes="-100,100", radius="100", speed="1500 rpm"), True),
        "precess": (rbcli.precess(fan, omega="0.3,1,0.2"), True),
        "whirl": (rbcli.whirl(fan, bearings="-150,150", stiffness=5e6, speed="1480 rpm"), True),
        "top": (rbcli.top(rbcli.load("examples/top.yaml"), spin=150, theta=30), True),
        "rollcheck": (rbcli.rollcheck(rbcli.load("examples/penny.yaml")), True),
        "gyrocompass": (rbcli.gyrocompass(rbcli.load("examples/gyroscope.yaml"), spin="6000 rpm", latitude=30), False),
        "field_balance": (rbcli.field_balance(job="examples/jobs/fan.yaml"), True),
    }


@pytest.mark.sampled
def test_every_result_has_a_short_repr_and_its_tables_and_figure_as_html():
    for name, (res, figure) in _results().items():
        text = repr(res)
        assert "\n" not in text and len(text) < 400 and text.startswith(f"<{type(res).__name__} "), name
        page = res._repr_html_()
        assert page.count("<table>") >= 1 and "</table>" in page, name
        assert re.search(r"\[(kg|m|mm|g|rad/s|°|N|g·mm|kg·m²|kg·mm²)[\]·/ ]|<td>(kg|m|mm|g|kg·m²|kg·mm²|rad/s)</td>", page), name
        assert ("<svg" in page) == figure, name
        assert "<script" not in page  # text of the body is escaped


def test_the_body_shows_its_name_mass_and_units():
    body = rbcli.load(FAN)
    assert repr(body) == "<Body 'Centrifugal fan rotor (overhung impeller, rolling bearings)' from examples/fan_rotor.yaml: 13 parts>"
    page = body._repr_html_()
    assert "<td>kg</td>" in page and "<td>mm</td>" in page  # the file's units (mm, kg)
    evil = rbcli.load_text("{name: '<script>x</script>', shape: point, mass: 1}")
    assert "<script>" not in evil._repr_html_()
