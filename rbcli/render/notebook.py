"""A body or a result in a notebook (``_repr_html_``, which imports this module inside the
method: tests/test_architecture.py lists it): its command's tables as HTML, units in the
headers, and its figure as SVG. No api import at run time: a result is known by its name.
"""

from __future__ import annotations

import html as _markup
from types import SimpleNamespace
from typing import Any

from rbcli.core.inertia import body_mass_props
from rbcli.render import balance, balanceplot, massprops, precess, rollcheck, top, whirl
from rbcli.render.field.plot import plot as field_plot
from rbcli.render.field.tables import field_document, reading_display
from rbcli.render.plots import figure_bytes
from rbcli.render.text import Doc, Heading, Table
from rbcli.render.units import DisplayUnits, ShopUnits

__all__ = ["html"]

DU, SU, D = DisplayUnits(), ShopUnits(None), 6


def _named(r: Any) -> Any:
    """A stand-in for a result's body (its name; SI tables): results that keep no body."""
    return SimpleNamespace(name=r.name, source="", units={}, parts=())


def _body(doc: Doc, b: Any) -> None:
    mp, du = body_mass_props(b), DU.of(b)
    doc.heading(f"{b.name}  ({b.source})")
    doc.kv("body", [("parts", str(len(b.parts)), ""), ("mass", du.show(mp.mass, "mass", D), du.unit("mass")),
                    ("com", ", ".join(du.show(x, "length", D) for x in mp.com), du.unit("length"))])


#: result class -> what puts its tables in a Doc and returns its figure (or None)
_BUILD = {
    "InertiaResult": lambda d, r: massprops.inertia_doc(d, _named(r), r, DU, D, "tensor", r.reference_label, parts=False),
    "PrincipalResult": lambda d, r: massprops.principal_doc(d, _named(r), r, DU, D, r.reference_label, parts=False),
    "BalanceResult": lambda d, r: balance.document(d, r, SU, D) or balanceplot.plot(r.diagram(), SU.of(r.body)),
    "PrecessResult": lambda d, r: precess.document(d, _named(r), r, DU, D) or precess.plot(_named(r), r.motion, None, DU),
    "TopResult": lambda d, r: top.document(d, r, DU, D) or top.plot(r, r.sample(r.default_duration()), r.default_duration()),
    "GyrocompassResult": lambda d, r: top.gyro_document(d, r, DU, D),
    "RollcheckResult": lambda d, r: rollcheck.document(d, r, DU, D) or rollcheck.plot(r, r.curves()),
    "WhirlResult": lambda d, r: whirl.document(d, r, DU, D) or whirl.campbell_figure(r),
    "FieldBalanceResult": lambda d, r: field_document(d, r, SU, D) or field_plot(
        r, SU, reading_display(r.reading_kind, SU, r.measure)),
    "Body": _body,
}


def _html(item: Any) -> str:
    e, right = _markup.escape, lambda i: ' style="text-align:right"' if i in item.right else ""  # noqa: E731
    if not isinstance(item, Table):
        return f"<h4>{e(item.text)}</h4>" if isinstance(item, Heading) else f"<p>{e(item.text)}</p>"
    rows = [[f"<th{right(i)}>{e(c)}</th>" for i, c in enumerate(item.columns)]]
    rows += [[f"<td{right(i)}>{e(x)}</td>" for i, x in enumerate(row)] for row in item.rows]
    return f"<table><caption>{e(item.title)}</caption>" + "".join(f"<tr>{''.join(r)}</tr>" for r in rows) + "</table>"


def html(obj: Any) -> str:
    """``obj``'s tables (and figure) as an HTML fragment; a result of no command: its JSON's
    top-level numbers and words."""
    doc = Doc()
    build = _BUILD.get(type(obj).__name__)
    fig = build(doc, obj) if build else doc.kv(type(obj).__name__, [
        (k, str(v), "") for k, v in obj.to_json().items() if isinstance(v, (int, float, str))])
    svg = figure_bytes(fig, "svg").decode("utf-8") if fig is not None else "<svg"
    return "\n".join([_html(item) for item in doc.items] + [svg[svg.index("<svg"):]] * (fig is not None))
