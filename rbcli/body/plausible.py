"""Densities that matter has (issue 24): one no matter has is warned, once a body, with its
value in SI and the reading probably meant (``density: 7850`` in a mm body is 7850 kg/mm³).
The bounds are what matter has, not what is usual, so every warning is true:

- no matter is denser than osmium, 22 590 kg/m³ (22.587 ± 0.009 g/cm³ from its lattice
  constants, the densest element: J. W. Arblaster, Platinum Metals Rev. 33 (1989) 14; the
  Guinness record, 22.59 g/cm³);
- no solid is lighter than the lightest aerogel made, 0.16 kg/m³ (a graphene aerogel of
  0.16 mg/cm³: H. Sun, Z. Xu, C. Gao, Adv. Mater. 25 (2013) 2554); this bound is for
  solid parts (those with a volume) only, a film's areal density has no lower bound;
- an areal density is a sheet of some thickness: a sheet of osmium that heavy thicker than
  the part is wide (the square root of its area) is no sheet; a linear density is a bar of
  some section: an osmium bar that heavy wider than the part is long is no rod.
"""

from __future__ import annotations

import math

from rbcli.io import units as un

__all__ = ["OSMIUM", "AEROGEL", "finding", "note_density", "density_warning"]

#: kg/m³, the densest matter (osmium; see the module docstring)
OSMIUM = 22_590.0
#: kg/m³, the lightest solid made (a graphene aerogel; see the module docstring)
AEROGEL = 0.16
_SI = {"density": "kg/m^3", "areal_density": "kg/m^2", "linear_density": "kg/m"}
_SHOWN = {"density": "kg/m³", "areal_density": "kg/m²", "linear_density": "kg/m"}


def finding(kind: str, value: float, measure: float | None, solid: bool) -> str | None:
    """Why a part's ``kind`` of density ``value`` (SI) is one no matter has, or None.

    Parameters
    ----------
    kind : ``"density"``, ``"areal_density"`` or ``"linear_density"``
    value : float — kg/m³, kg/m² or kg/m
    measure : float | None — the part's area (m²) or length (m), for the last two kinds
    solid : bool — a part with a volume (the aerogel bound applies)
    """
    if kind == "density":
        if AEROGEL <= value <= OSMIUM or (value < AEROGEL and not solid):
            return None
        g = f"{value:.3g} {_SHOWN[kind]}"
        if value > OSMIUM:
            return f"its density is {g}, above that of any matter (osmium, the densest, 22 590 kg/m³)"
        return f"its density is {g}, below that of any solid (the lightest aerogel, 0.16 kg/m³)"
    if not measure or measure <= 0.0:
        return None
    if kind == "areal_density":
        thick, wide = value / OSMIUM, math.sqrt(measure)
        if thick > wide:
            g = f"{value:.3g} {_SHOWN[kind]}"
            return (f"its areal density is {g}: a sheet of osmium (the densest matter, 22 590 "
                    f"kg/m³) {thick:.3g} m thick, on a part of {measure:.3g} m² — no thin sheet")
        return None
    side = math.sqrt(value / OSMIUM)
    if side > measure:
        g = f"{value:.3g} {_SHOWN[kind]}"
        return (f"its linear density is {g}: a bar of osmium (the densest matter, 22 590 "
                f"kg/m³) {side:.3g} m a side, on a part {measure:.3g} m long — no thin rod")
    return None


def _meant(kind: str, raw: str, factor: float, measure: float | None, solid: bool) -> str:
    """The reading of a bare ``raw`` probably meant: in the SI unit (the body's is not), else
    in g/cm³ (a density), the first that matter has; '' for neither."""
    candidates = ([_SI[kind]] if factor != 1.0 else []) + (["g/cm^3"] if kind == "density" else [])
    for unit in candidates:
        try:
            value = un.to_si(f"{raw} {unit}", kind)
        except un.UnitError:
            continue
        if finding(kind, value, measure, solid) is None:
            return f': did you mean "{raw} {unit}"?'
    return ""


def note_density(ctx, node, kind: str, value: float, measure: float | None, solid: bool,
                 what: str) -> None:
    """Record on the load's session a ``kind`` of density typed at ``node`` (the key's
    value) that no matter has; :func:`density_warning` says the first of a body."""
    problem = finding(kind, value, measure, solid)
    if problem is None:
        return
    raw = getattr(node, "raw", "")
    value = getattr(node, "value", None)
    bare = isinstance(value, (int, float)) and not isinstance(value, bool)
    tail = ""
    if bare:
        factor, unit = ctx.factor(kind, node)
        here = f"; a bare {kind.replace('_', ' ')} in this body is in {unit}" if factor != 1.0 else ""
        tail = here + _meant(kind, raw, factor, measure, solid)
    ctx.session.densities.append(f"{ctx.where(node)}: warning: {what}: {problem}{tail}")


def density_warning(session) -> tuple[str, ...]:
    """The body's one density warning (its first such part, and how many there are)."""
    found = session.densities
    if not found:
        return ()
    more = f" ({len(found)} parts have densities no matter has; this is the first)" if len(found) > 1 else ""
    return (found[0] + more,)
