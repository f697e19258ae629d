"""Tables of ``rbcli field-balance``: masses in g, radii in mm, readings in µm, mm/s or m/s²
(or the ``--units`` ones; with an inch length, mil, in/s and g). A classic one- or two-plane
job keeps its tables (:func:`classic_document`); any other gets :func:`extended_document`."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rbcli.core.field.solve import deg
from rbcli.render.fmt import num, polar
from rbcli.render.text import Doc
from rbcli.render.units import ShopUnits

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.field.result import FieldBalanceResult

#: the most planes a wide table (readings, influence coefficients) shows: the JSON has the rest
MAX_PLANE_COLUMNS = 12

#: how the tables show readings of each kind: (SI per display unit, display unit)
READING_DISPLAY = {"displacement": (1e-6, "µm"), "velocity": (1e-3, "mm/s"), "acceleration": (1.0, "m/s²")}
#: the same in US practice (``--units in,...``): mil, in/s, g
READING_DISPLAY_US = {"displacement": (25.4e-6, "mil"), "velocity": (0.0254, "in/s"),
                      "acceleration": (9.80665, "g")}
#: length units whose users read vibration in mil, in/s and g
_US_LENGTHS = ("in", "inch", "inches", "ft", "foot", "feet", "mil", "mils", "thou", "yd", "yard")


def reading_display(kind: str | None, su: ShopUnits, measure: str | None = None) -> tuple[float, str]:
    """(SI per display unit, unit and ``measure``: "µm pk-pk") of readings of ``kind`` in the
    tables (bare: (1, ""))."""
    if kind is None:
        return 1.0, ""
    f, u = (READING_DISPLAY_US if su.length[1] in _US_LENGTHS else READING_DISPLAY)[kind]
    return f, f"{u} {measure}" if measure else u


def field_document(doc: Doc, res: FieldBalanceResult, su: ShopUnits, digits: int) -> None:
    """The tables of ``rbcli field-balance`` (from the result's finished numbers)."""
    if not res.corrections:
        _suggestion_only(doc, res, su, digits)
    elif res.extended:
        extended_document(doc, res, su, digits)
    else:
        classic_document(doc, res, su, digits)


# --- classic


def classic_document(doc: Doc, res: FieldBalanceResult, su: ShopUnits, digits: int) -> None:
    """The tables of a one- or two-plane job as they always were."""
    d = res.to_json()
    m = su.unit("mass")
    n = d["planes"]
    doc.heading(f"field balancing, {'one plane' if n == 1 else 'two planes, two sensors'} (influence coefficients)")
    doc.note(
        "angles in degrees, counted in the same sense as the trial angles and the phase readings "
        "(they must agree); a correction is a mass to add"
    )
    names = ["A", "B"][:n]
    kind = d["readings"]["kind"]
    scale, ru = reading_display(res.reading_kind, su, res.measure)
    if ru:
        doc.note(f"readings: {kind}, shown in {ru} (JSON: SI, {d['readings']['unit']})")
    rows = []
    for i, row in enumerate(d["influence"]):
        cells = [str(i + 1)]
        for a in row:
            per = a["magnitude"] * su.mass[0] / scale  # reading per display mass unit
            cells += [num(per, digits), num(a["angle_deg"], digits)]
        rows.append(cells)
    cols = ["sensor"]
    for name in names:
        cols += [f"plane {name}: {ru + ' ' if ru else ''}per {m}", "phase [°]"]
    title = ("influence coefficients (reading per unit trial mass)" if not ru
             else f"influence coefficients ({ru} per {m})")
    doc.table(title, cols, rows, right=tuple(range(1, len(cols))))
    crow = []
    for c in d["corrections"]:
        crow.append([c["name"], su.show(c["mass"], "mass", digits), num(c["angle_deg"], digits),
                     su.show(c["mass_trial_on"], "mass", digits), num(c["angle_trial_on_deg"], digits)])
    radii = res.radii
    where = "" if radii is None else (
        f" at radius {su.show(radii[1], 'length', digits)} {su.unit('length')} (trials at "
        f"{su.show(radii[0], 'length', digits)} {su.unit('length')})")
    doc.table(
        f"corrections to add{where}",
        ["plane", f"mass [{m}]", "angle [°]", f"trial left on: add [{m}]", "angle [°]"],
        crow,
        right=(1, 2, 3, 4),
    )
    if n == 2:
        flagged = [(name, f) for name, f in zip(names, res.significance_factors) if f <= res.significance_limit]
        doc.note(
            f"condition number of the influence matrix {num(d['cond'], 4)}"
            + (" (ill-conditioned: the planes are not well separated)" if d["ill_conditioned"] else "")
            + "".join(f"; Darlow's plane-significance factor of plane {name} {num(f, 3)} (at or below "
                      f"{num(res.significance_limit, 3)}: ill-conditioned)" for name, f in flagged)
            + ("; trial A left on during run B (--cumulative)" if d["cumulative"] else "")
        )
    doc.note(
        "predicted residual reading after the corrections (linear model, 0 up to round-off): "
        + ", ".join(num(v / scale, 3, max(map(abs, res.initial)) / scale) for v in d["predicted_residual"])
        + (f" {ru}" if ru else "")
    )


# --- extended


def _row_label(sensor: str, speed: str, res: FieldBalanceResult) -> list[str]:
    """A reading's label cells: a speed column with several speeds, or one named."""
    return [sensor, speed or "—"] if len(res.run_speeds) > 1 or res.run_speeds and res.run_speeds[0][0] else [sensor]


def _head(res: FieldBalanceResult) -> list[str]:
    return ["sensor", "speed"][:len(_row_label("", "", res))]


def _reported(z: complex, res: FieldBalanceResult) -> complex:
    """A reading in the instrument's phase convention (the result's are in the angles' sense)."""
    return z.conjugate() if (res.conventions is not None and res.conventions.converted) else z


def extended_document(doc: Doc, res: FieldBalanceResult, su: ShopUnits, digits: int) -> None:
    """The tables of an extended job: readings, coefficients, corrections as computed and as
    fitted, the predicted readings, significance and severity."""
    scale, ru = reading_display(res.reading_kind, su, res.measure)
    rows = res.row_names()
    n_sp = len(res.run_speeds)
    label = {"exact": "exact solve", "least-squares": "least squares", "min-max": "min-max"}[res.method or "exact"]
    what = (f"{len(res.sensors)} sensor{'s' if len(res.sensors) != 1 else ''}"
            + (f" × {n_sp} speeds" if n_sp > 1 else ""))
    head = f"field balancing: {res.planes} plane{'s' if res.planes != 1 else ''}, {len(rows)} readings ({what}), {label}"
    if res.name:
        head = f"{res.name} — {head}"
    doc.heading(head)
    doc.note(res.angle_convention.replace("angles and phases in degrees", "angles in degrees"))
    doc.note("a correction is a mass to add; each plane's trial removed before the next run"
             if not res.cumulative else "a correction is a mass to add; each trial was left on for the later runs")
    readings_note(doc, res, ru)
    if n_sp > 1 or any(w is not None for _, w in res.run_speeds):
        doc.table("speeds", ["speed", "rpm", "rad/s"],
                  [[n or "—", "—" if w is None else num(w * 30.0 / 3.141592653589793, digits),
                    "—" if w is None else num(w, digits)] for n, w in res.run_speeds], right=(1, 2))
    readings_table(doc, res, scale, ru, rows, digits)
    influence_table(doc, res, scale, ru, rows, su, digits)
    corrections_table(doc, res, su, digits)
    limits_table(doc, res, su, scale, ru, digits)
    robust_note(doc, res)
    if res.fitted is not None:
        fitted_table(doc, res, su, digits)
    residuals_table(doc, res, scale, ru, rows, digits)
    significance_note(doc, res)
    if res.severity is not None:
        severity_table(doc, res, rows, digits, su)
    if res.suggested_trial:
        suggestion_table(doc, res, su, scale, ru, rows, digits)
    if res.coefficients_from is not None:
        doc.note(f"influence coefficients from {res.coefficients_from} (a trim run: no trial runs)")
    for note in res.notes:
        doc.note(note)


def significance_note(doc: Doc, res: FieldBalanceResult) -> None:
    """The condition number and Darlow's plane-significance factors, in one note."""
    sig = ", ".join(f"{n} {num(f, 3)}" for n, f in zip(res.plane_names, res.significance_factors))
    doc.note(f"condition number of the influence matrix {num(res.cond, 4)}"
             + (" (ill-conditioned: the planes are not well separated)" if res.ill_conditioned else "")
             + f"; Darlow's plane-significance factors {sig} (flagged at or below "
             f"{num(res.significance_limit, 3)}: a plane that adds no direction of its own)")


def readings_note(doc: Doc, res: FieldBalanceResult, ru: str) -> None:
    parts = []
    if ru:
        parts.append(f"readings: {res.reading_kind}, shown in {ru} (JSON: SI, {res.reading_unit})")
    else:
        parts.append("readings: bare numbers, one relative scale (the corrections do not depend on it)")
    if res.measure is not None:
        parts.append(f"amplitudes {res.measure}")
    for a, b, k in res.measures_converted:
        parts.append(f"{k} reading{'s' if k != 1 else ''} converted from {a} to {b} (a sinusoid: "
                     "pk-pk = 2 pk, rms = pk/√2)")
    if res.gravity:
        parts.append("'g' in a reading read as standard gravity, 9.80665 m/s² (in a trial mass g is the gram)")
    doc.note("; ".join(parts))


def _wide(doc: Doc, n: int, what: str) -> int:
    """How many planes a wide table shows (a note says what is left out)."""
    if n > MAX_PLANE_COLUMNS:
        doc.note(f"{what}: the first {MAX_PLANE_COLUMNS} of {n} planes (the JSON has them all)")
    return min(n, MAX_PLANE_COLUMNS)


def readings_table(doc: Doc, res: FieldBalanceResult, scale: float, ru: str, rows, digits: int) -> None:
    u = f" [{ru}]" if ru else ""
    cols = [*_head(res), f"initial{u}", "phase [°]"]
    runs = res.runs[:_wide(doc, len(res.runs), "readings")]
    for j, _ in enumerate(runs):
        cols += [f"trial {res.plane_names[j]} on{u}", "phase [°]"]
    table = []
    for k, (s, v) in enumerate(rows):
        z = _reported(res.initial[k], res)
        cells = [*_row_label(s, v, res), num(abs(z) / scale, digits), num(deg(z), digits)]
        for run in runs:
            y = _reported(run[k], res)
            cells += [num(abs(y) / scale, digits), num(deg(y), digits)]
        table.append(cells)
    doc.table("readings", cols, table, right=tuple(range(len(_head(res)), len(cols))))


def influence_table(doc: Doc, res: FieldBalanceResult, scale: float, ru: str, rows, su: ShopUnits,
                     digits: int) -> None:
    m = su.unit("mass")
    cols = _head(res)
    p = _wide(doc, len(res.plane_names), "influence coefficients")
    for name in res.plane_names[:p]:
        cols += [f"plane {name}: {ru + ' ' if ru else ''}per {m}", "phase [°]"]
    table = []
    for k, (s, v) in enumerate(rows):
        cells = [*_row_label(s, v, res)]
        for a in res.alpha[k][:p]:
            cells += [num(abs(a) * su.mass[0] / scale, digits), num(deg(a), digits)]
        table.append(cells)
    doc.table("influence coefficients (at each plane's trial radius; phases in the angles' sense)",
              cols, table, right=tuple(range(len(_head(res)), len(cols))))


def corrections_table(doc: Doc, res: FieldBalanceResult, su: ShopUnits, digits: int) -> None:
    m = su.unit("mass")
    L = su.unit("length")
    radii = res.plane_radii or (res.radii,) * res.planes
    trial_on = bool(res.trial_masses)
    cols = ["plane", f"radius [{L}]", f"mass [{m}]", "angle [°]"]
    if trial_on:
        cols += [f"trial left on: add [{m}]", "angle [°]"]
    table = []
    for c, r in zip(res.corrections, radii):
        cells = [c.name, "—" if r is None else su.show(r[1], "length", digits), su.show(c.mass, "mass", digits),
                 num(c.angle_deg, digits)]
        if trial_on:
            z = c.correction_trial_on
            cells += [su.show(abs(z), "mass", digits), num(deg(z) if z != 0 else 0.0, digits)]
        table.append(cells)
    doc.table("corrections to add (as computed)", cols, table, right=tuple(range(1, len(cols))))


def trials_table(doc: Doc, res: FieldBalanceResult, su: ShopUnits, digits: int) -> None:
    """The trial mass of each run, at its plane's trial radius."""
    if not res.trial_masses:
        return
    radii = res.plane_radii or (res.radii,) * res.planes
    doc.table("trial masses", ["plane", f"mass [{su.unit('mass')}]", "angle [°]", f"radius [{su.unit('length')}]"],
              [[n, su.show(abs(t), "mass", digits), num(deg(t), digits), "—" if r is None else
                su.show(r[0], "length", digits)] for n, t, r in zip(res.plane_names, res.trial_masses, radii)],
              right=(1, 2, 3))


def limits_table(doc: Doc, res: FieldBalanceResult, su: ShopUnits, scale: float, ru: str, digits: int) -> None:
    """Each limit, what the correction gives against it, whether it binds and its cost."""
    lim = res.limits
    if lim is None:
        return
    u = f" [{ru}]" if ru else ""

    def shown(x: float, f: float, unit: str) -> str:
        return f"{num(x / f, digits)} {unit}".strip()

    def row(kind: str, on: str, limit: str, value: str, r: Any) -> list[str]:
        return [kind, on, limit, value, "yes" if r.active else "no",
                "—" if r.objective_without is None else num(r.objective_without / scale, digits)]

    mu, uu = (su.factor("mass"), su.unit("mass")), (su.factor("unbalance"), su.unit("unbalance"))
    table = [row("mass", f"plane {r.plane}", shown(r.max_mass, *mu), shown(r.mass, *mu), r) if r.max_mass is not None
             else row("unbalance", f"plane {r.plane}", shown(r.max_unbalance, *uu), shown(r.unbalance, *uu), r)
             for r in lim.planes]
    table += [row("reading", f"{r.sensor}{' at ' + r.speed if r.speed else ''}", shown(r.limit, scale, ru),
                  shown(r.amplitude, scale, ru), r) for r in lim.readings]
    how = "met" if lim.feasible else (f"cannot all be met: the correction exceeds them least, each reading within "
                                      f"{num(lim.violation, 4)} times its limit")
    doc.table(f"limits ({how})", ["limit", "on", "at most", "the correction", "binds", f"objective without it{u}"],
              table, right=(2, 3, 5))
    doc.note(f"objective with the limits: {num(lim.objective / scale, digits)}{' ' + ru if ru else ''} ("
             + ("the largest weighted predicted reading" if res.method == "min-max" else
                "the root sum of squares of the weighted predicted readings") + ")")


def robust_note(doc: Doc, res: FieldBalanceResult) -> None:
    rb = res.robust
    if rb is not None:
        doc.note("robust fit (Huber): " + (f"discounted {', '.join(rb.discounted)}" if rb.discounted else
                                           "no reading discounted")
                 + f"; a reading beyond {num(rb.threshold, 4)} times the Rayleigh scale of the residuals "
                 "(median/√ln 4) weighs less, in proportion")


def fitted_table(doc: Doc, res: FieldBalanceResult, su: ShopUnits, digits: int) -> None:
    f = res.fitted
    assert f is not None
    m = su.unit("mass")
    if f.drawer is not None:
        return drawer_table(doc, res, su, digits)
    how = []
    if f.mass_step is not None:
        how.append(f"masses to {su.show(f.mass_step, 'mass', digits)} {m}")
    if f.angle_step_deg is not None:
        how.append(f"angles to {num(f.angle_step_deg, digits)}°")
    if any(p.positions for p in f.planes):
        how.append("split onto positions (position 1 on the 0° mark)")
    table = []
    for p in f.planes:
        for fm in (fm for fm in p.masses if fm.mass > 0):  # no weight of nothing at a position
            table.append([p.name, "—" if fm.position is None else str(fm.position), num(fm.angle_deg, digits),
                          su.show(fm.mass, "mass", digits)])
    doc.table(f"masses to fit ({'; '.join(how)})", ["plane", "position", "angle [°]", f"mass [{m}]"], table,
              right=(1, 2, 3))


def drawer_table(doc: Doc, res: FieldBalanceResult, su: ShopUnits, digits: int) -> None:
    """The weights chosen from the drawer, and how each plane's holes were taken."""
    f = res.fitted
    d = f.drawer
    m, L = su.unit("mass"), su.unit("length")
    table = [[p.name, str(fm.position), num(fm.angle_deg, digits), su.show(fm.mass, "mass", digits)]
             for p in f.planes for fm in p.masses]
    judged = "least squares" if res.method != "min-max" else "min-max"
    doc.table(f"weights from the drawer (the best choice by {judged} on the predicted readings)",
              ["plane", "hole", "angle [°]", f"mass [{m}]"], table, right=(1, 2, 3))
    for pl in d.planes:
        h = pl.holes_deg
        doc.note(f"plane {pl.name}: {len(h)} hole{'s' if len(h) != 1 else ''}"
                 + (f" at {su.show(pl.radius, 'length', digits)} {L}" if pl.radius is not None else
                    " at the trial radius") + f", hole 1 at {num(h[0], digits)}°"
                 + (f", numbered {pl.numbering} the angles" if len(h) > 1 else "")
                 + f"; at most {pl.per_hole} weight{'s' if pl.per_hole > 1 else ''} a hole and {pl.max_weights} "
                 f"in the plane" + ("" if pl.max_mass is None else f", {su.show(pl.max_mass, 'mass', digits)} {m} in all"))
    sizes = "; ".join(", ".join(f"{su.show(x['mass'], 'mass', digits)} {m}"
                                + ("" if x["count"] is None else f" × {x['count']}") for x in dr) for dr in d.drawers)
    doc.note(f"drawer: {sizes}; {d.examined} choice{'s' if d.examined != 1 else ''} evaluated (an exact search)"
             + ("" if d.violation <= 1.0 else f"; no choice meets the limits: this one exceeds them least "
                                              f"({num(d.violation, 4)} times a limit)"))


def residuals_table(doc: Doc, res: FieldBalanceResult, scale: float, ru: str, rows, digits: int) -> None:
    u = f" [{ru}]" if ru else ""
    cols = [*_head(res), f"initial{u}", f"predicted{u}", "phase [°]", "change [%]"]
    fitted = res.fitted.residuals if res.fitted is not None else None
    if fitted is not None:
        cols += [f"with the masses fitted{u}", "phase [°]"]
    limits = {(r.sensor, r.speed): r.limit for r in res.limits.readings} if res.limits else {}
    if limits:
        cols.append(f"limit{u}")
    table, big = [], max(r.initial for r in res.residuals)  # round-off: of the largest initial reading
    for k, (s, v) in enumerate(rows):
        r = res.residuals[k]
        change = "—" if r.initial == 0 else num(100.0 * (r.amplitude - r.initial) / r.initial, 3)
        cells = [*_row_label(s, v, res), num(r.initial / scale, digits),
                 *polar(r.amplitude / scale, r.angle_deg, digits, big / scale), change]
        if fitted is not None:
            cells += polar(fitted[k].amplitude / scale, fitted[k].angle_deg, digits, big / scale)
        if limits:
            cells.append("—" if (s, v) not in limits else num(limits[s, v] / scale, digits))
        table.append(cells)
    doc.table("readings predicted after the correction (the linear model)", cols, table,
              right=tuple(range(len(_head(res)), len(cols))))


def severity_table(doc: Doc, res: FieldBalanceResult, rows, digits: int, su: ShopUnits | None = None) -> None:
    sv = res.severity
    assert sv is not None
    f, u = reading_display("velocity", su) if su is not None else READING_DISPLAY["velocity"]
    big = max(r.before for r in sv.readings) / f  # round-off: of the largest reading
    table = [[*_row_label(r.sensor, r.speed, res), num(r.before / f, digits), r.before_zone,
              num(r.after / f, digits, big), r.after_zone] for r in sv.readings]
    after = "with the masses fitted" if sv.after_is == "fitted" else "after the correction"
    doc.table(f"{sv.standard}, group {sv.group}, {sv.foundation} support: zones of the 1× readings",
              [*_head(res), f"before [{u} rms]", "zone", f"{after} [{u} rms]", "zone"], table,
              right=(len(_head(res)), len(_head(res)) + 2))
    ab, bc, cd = (num(x / f, 3) for x in sv.boundaries)
    doc.note(f"zone boundaries A/B {ab}, B/C {bc}, C/D {cd} {u} r.m.s. (ISO 20816-3 Annex A, as ISO "
             "10816-3:2009; a value on a boundary is in the lower zone). A: newly commissioned; B: "
             "unrestricted long-term operation; C: restricted operation; D: damage. The standard judges "
             "the broadband velocity (10 Hz to 1 kHz); these are the 1× readings only, so the machine's "
             "zone is at least the one shown; the 'after' zone is a prediction: measure after fitting")


def suggestion_table(doc: Doc, res: FieldBalanceResult, su: ShopUnits, scale: float, ru: str, rows,
                      digits: int) -> None:
    m = su.unit("mass")
    L = su.unit("length")
    table = []
    for s in res.suggested_trial:
        table.append([s.plane, su.show(s.mass, "mass", digits), su.show(s.radius, "length", digits),
                      num(s.speed * 30.0 / 3.141592653589793, digits), num(s.force, digits),
                      num(s.bearing_load, digits), num(100.0 * s.fraction, 3)])
    doc.table("trial mass to start with",
              ["plane", f"trial mass [{m}]", f"at radius [{L}]", "speed [rpm]", "its force [N]",
               "static bearing load [N]", "fraction [%]"], table, right=(1, 2, 3, 4, 5, 6))
    froms = sorted({s.bearing_load_from for s in res.suggested_trial})
    doc.note("sized so that the trial's centrifugal force m r Ω² is the fraction of the static load on the "
             f"bearing nearest its plane (rbcli's rule, physics notes balance.md §5.1; load: {'; '.join(froms)})")
    for s in res.suggested_trial:
        if s.expected_change is None:
            doc.note(f"plane {s.plane}: the change the trial will make cannot be predicted without influence "
                     "coefficients (a previous job's, --coefficients); after the run rbcli warns if it "
                     "changed no reading by 25 % or 25°")
        else:
            parts = []
            for k, c in enumerate(s.expected_change):
                ratio = "" if s.expected_change_ratio is None else f" ({num(100 * s.expected_change_ratio[k], 3)} %)"
                parts.append(f"{rows[k][0]}{' ' + rows[k][1] if rows[k][1] else ''}: {num(c / scale, 4)}"
                             f"{' ' + ru if ru else ''}{ratio}")
            doc.note(f"plane {s.plane}: expected change of the readings with this trial: " + ", ".join(parts))


def _suggestion_only(doc: Doc, res: FieldBalanceResult, su: ShopUnits, digits: int) -> None:
    doc.heading("field balancing: a trial mass to start with")
    if res.conventions is not None:
        doc.note(res.conventions.text)
    suggestion_table(doc, res, su, 1.0, "", [], digits)
