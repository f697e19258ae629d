"""Tables of ``rbcli balance`` (the JSON is the result's own; ``field-balance``'s tables are
:mod:`rbcli.render.field.tables`).

In :class:`rbcli.render.units.ShopUnits` (g·mm, g·mm², g, mm, µm, the rotor in kg; or the
body's or ``--units``' in, oz...); forces in N, speeds in rpm and rad/s. JSON is SI.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from rbcli.render import echo
from rbcli.render.fmt import num, said
from rbcli.render.text import Doc
from rbcli.render.units import RPM, ShopUnits

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.api.balance import BalanceResult
    from rbcli.core import balance as B


def echo_rows(r: BalanceResult) -> list[tuple[str, str, str]]:
    """The options as understood (:func:`rbcli.render.echo.echo_rows`)."""
    return echo.echo_rows(r.options, r.body.units)


def angle(value: float, defined: bool, digits: int) -> str:
    return num(value, digits, 360.0) if defined else "—"


def mag(su: "ShopUnits", x: float, defined: bool, kind: str, digits: int) -> str:
    """A magnitude, or 0 when it is zero to the tolerance (its angle undefined): tables do
    not show round-off like 1e-12 g·mm; JSON keeps the computed number."""
    return su.show(x if defined else 0.0, kind, digits)


def _snap(x: float, tol: float) -> float:
    return 0.0 if abs(x) <= tol else x


def yes(b: bool) -> str:
    return "yes" if b else "no"


# --- conventions


def _vec(v, digits: int = 6) -> str:
    return "[" + ", ".join(num(0.0 if abs(x) < 1e-15 else float(x), digits) for x in v) + "]"


def frame_sentence(r: BalanceResult) -> str | None:
    """For a shaft frame that is not the body frame: how its axes were chosen."""
    fr = r.unbalance.frame
    if np.array_equal(fr.rotation, np.eye(3)):
        return None
    return (
        f"shaft frame (body components): z = {_vec(fr.rotation[2])} along the shaft; "
        f"x = {_vec(fr.rotation[0])}, the 0° mark ({said(r.mark_source)}); "
        f"y = z × x = {_vec(fr.rotation[1])}"
    )


# --- tables


def document(doc: Doc, r: BalanceResult, su: ShopUnits, digits: int,
             applied: tuple[str, list[dict]] | None = None) -> None:
    """The tables of ``rbcli balance``; ``applied`` = (path, parts) that ``--apply`` wrote."""
    u, su = r.unbalance, su.of(r.body)
    doc.heading(f"{r.body.name}  ({r.body.source})")
    fr = u.frame
    doc.note(
        f"shaft: {_vec(fr.axis)} ({said(r.shaft_source)}) through {_vec(np.asarray(fr.origin) / su.length[0])} "
        f"{su.unit('length')} ({said(r.through_source)}); positions z along the shaft from that point"
    )
    fs = frame_sentence(r)
    if fs:
        doc.note(fs)
    doc.note(said(r.angle_convention))
    _unbalance(doc, r, su, digits)
    if r.installed is not None:
        _corrections(doc, r, su, digits)
    if r.options.bearings is not None or r.options.speed is not None:
        _bearings(doc, r, su, digits)
    if r.iso_check is not None:
        _iso(doc, r, su, digits)
    if applied is not None:
        doc.note(
            f"written {applied[0]}: the body with "
            + ", ".join(f"'{p['name']}'" for p in applied[1])
            + " added as point parts"
        )


def _unbalance(doc: Doc, r: BalanceResult, su: ShopUnits, digits: int) -> None:
    u = r.unbalance
    L = su.unit("length")
    rows = [
        ("rotor mass M", su.show(u.mass, "rotor_mass", digits), su.unit("rotor_mass")),
        ("com along the shaft z_G", su.show(_snap(float(u.com_shaft[2]), u.tol_eccentricity), "length", digits), L),
        ("eccentricity e (com from the shaft)", mag(su, u.eccentricity, u.static_angle_defined, "eccentricity", digits), su.unit("eccentricity")),
        ("static unbalance U = M e", mag(su, u.static_unbalance, u.static_angle_defined, "unbalance", digits), su.unit("unbalance")),
        ("  its angle (heavy side)", angle(u.static_angle_deg, u.static_angle_defined, digits), "°"),
        ("couple unbalance P_G (about the com)", mag(su, u.couple_unbalance, u.couple_angle_defined, "couple", digits), su.unit("couple")),
        ("  its angle", angle(u.couple_angle_deg, u.couple_angle_defined, digits), "°"),
        ("moment unbalance P (about z = 0)", mag(su, u.moment_unbalance, u.angle_of(u.moment, u.tol_moment)[1], "couple", digits), su.unit("couple")),
        ("  its angle", angle(*u.angle_of(u.moment, u.tol_moment), digits), "°"),
        ("tilt of the nearest principal axis", num(u.tilt_deg if u.tilt_azimuth_defined else 0.0, digits) + ("" if u.tilt_well_defined else " (ill-defined)"), "°"),
        ("  direction its +z end leans", angle(u.tilt_azimuth_deg, u.tilt_azimuth_defined, digits), "°"),
        ("statically balanced", yes(u.statically_balanced), ""),
        ("dynamically balanced", yes(u.dynamically_balanced), ""),
    ]
    doc.kv("unbalance about the shaft", rows)
    doc.note(
        "balanced means: e ≤ "
        f"{num(u.tol_eccentricity, 3)} m (rtol {num(u.rtol, 3)} × {num(u.length_scale, 6)} m, the "
        "rotor's size) and |P_G| ≤ "
        f"{num(u.tol_couple, 3)} kg·m² (rtol × trace of the inertia about the com): balanced to the "
        "accuracy of the input; --grade judges against a real tolerance"
    )


def _corrections(doc: Doc, r: BalanceResult, su: ShopUnits, digits: int) -> None:
    final = r.installed
    assert final is not None
    ideal = r.ideal
    assert ideal is not None
    L, m = su.unit("length"), su.unit("mass")
    rounded = r.position_split is None and final.rounded
    how = ""
    if rounded:
        steps = []
        if final.mass_step is not None:
            steps.append(f"masses to {su.show(final.mass_step, 'mass', digits)} {m}")
        if final.angle_step_deg is not None:
            steps.append(f"angles to {num(final.angle_step_deg, digits)}°")
        how = ", rounded: " + " and ".join(steps)
    cols = ["plane", f"z [{L}]", f"radius [{L}]"]
    if rounded:
        cols += [f"ideal mass [{m}]", "ideal angle [°]"]
    cols += [f"mass [{m}]", "angle [°]", "remove at [°]", f"unbalance [{su.unit('unbalance')}]"]
    rows = []
    pairs = zip(ideal.pair, final.pair) if r.position_split is None else zip(ideal.pair, ideal.pair)
    for pi, pc in pairs:
        row = [pc.name, su.show(pc.z, "length", digits), su.show(pc.radius, "length", digits)]
        if rounded:
            row += [mag(su, pi.mass, pi.angle_defined, "mass", digits), angle(pi.angle_deg, pi.angle_defined, digits)]
        row += [
            mag(su, pc.mass, pc.angle_defined or pc.mass > 0 and r.position_split is None and final.rounded, "mass", digits),
            angle(pc.angle_deg, pc.angle_defined, digits),
            angle(pc.remove_angle_deg, pc.angle_defined, digits),
            mag(su, abs(pc.unbalance), pc.angle_defined, "unbalance", digits),
        ]
        rows.append(row)
    doc.table(
        f"two-plane correction: masses to add{how} (radius from {said(r.radius_source)})",
        cols,
        rows,
        right=tuple(range(1, len(cols))),
    )
    st = (final if r.position_split is None else ideal).static
    if st.angle_defined:
        doc.note(
            f"single-plane (static) correction: {su.show(st.mass, 'mass', digits)} {m} at "
            f"{angle(st.angle_deg, st.angle_defined, digits)}° on radius {su.show(st.radius, 'length', digits)} {L}, "
            "in any plane (cancels U only; the couple stays)"
        )
    else:
        doc.note("single-plane (static) correction: none (the rotor is statically balanced)")
    if r.position_split is not None:
        p = r.position_split
        prow = []
        for pc, sp in zip(ideal.pair, p.splits):
            for mass, a, k in ((m, a, k) for m, a, k in zip(sp.masses, sp.angles_deg, sp.positions) if m > 0):
                prow.append([pc.name, str(k), num(a, digits), su.show(mass, "mass", digits)])
        rtxt = f", rounded to {su.show(p.mass_step, 'mass', digits)} {m}" if p.mass_step else ""
        doc.table(
            f"masses to add at {p.n_positions} positions{rtxt}",
            ["plane", "position", "angle [°]", f"mass [{m}]"],
            prow,
            right=(1, 2, 3),
        )
        doc.note(
            f"positions every {num(p.pitch_deg, digits)}°, position 1 on the 0° mark; each plane's "
            "correction split onto the two positions either side of it"
        )
    res = final.residual
    tol = res.tol_static
    which = "the masses at the positions" if r.position_split is not None else (
        "the rounded corrections" if final.rounded else "the corrections")
    s_ang = r.unbalance.angle_of(res.static, tol)
    c_ang = r.unbalance.angle_of(res.couple, res.tol_couple)
    rrows = [
        ("static unbalance", mag(su, abs(res.static), s_ang[1], "unbalance", digits), su.unit("unbalance")),
        ("  its angle", angle(*s_ang, digits), "°"),
        ("couple unbalance (about the new com)", mag(su, abs(res.couple), c_ang[1], "couple", digits), su.unit("couple")),
        ("  its angle", angle(*c_ang, digits), "°"),
    ]
    for name, z, uu in zip(("A", "B"), res.planes, res.plane_unbalances):
        rrows.append(
            (f"residual in plane {name} (z = {su.show(z, 'length', digits)} {L})",
             mag(su, abs(uu), r.unbalance.angle_of(uu, res.tol_plane)[1], "unbalance", digits), su.unit("unbalance"))
        )
    if r.corrected_unbalance is not None:
        c = r.corrected_unbalance
        rrows += [
            ("tilt of the nearest principal axis", num(c.tilt_deg if c.tilt_azimuth_defined else 0.0, digits), "°"),
            ("statically balanced", yes(c.statically_balanced), ""),
            ("dynamically balanced", yes(c.dynamically_balanced), ""),
        ]
    doc.kv(f"after adding {which}", rrows)


def _bearings(doc: Doc, r: BalanceResult, su: ShopUnits, digits: int) -> None:
    f = r.forces
    assert f is not None
    L = su.unit("length")
    if r.options.bearings is not None:
        has_speed = r.options.speed is not None
        cols = ["bearing", f"z [{L}]"]
        if has_speed:
            cols += ["rotating force [N]", "angle [°]", f"equivalent unbalance [{su.unit('unbalance')}]"]
            if r.forces_after is not None:
                cols += ["after correction [N]"]
        cols += ["static load [N]"]
        rows = []
        for i, z in enumerate(r.options.bearings):
            row = [str(i + 1), su.show(z, "length", digits)]
            if has_speed:
                F = f.forces[i]
                a, ok = r.unbalance.angle_of(F, f.tol_force)
                row += [num(abs(F), digits), angle(a, ok, digits), su.show(abs(f.plane_unbalances[i]), "unbalance", digits)]
                if r.forces_after is not None:
                    fa = r.forces_after
                    row += [num(abs(fa.forces[i]) if abs(fa.forces[i]) > fa.tol_force else 0.0, digits)]
            row += [num(f.static_loads[i], digits)]
            rows.append(row)
        title = (
            f"bearings at {num(r.options.speed * RPM, digits)} rpm ({num(r.options.speed, digits)} rad/s)"
            if has_speed
            else "bearings (give --speed for the rotating forces)"
        )
        doc.table(title, cols, rows, right=tuple(range(1, len(cols))))
        notes = []
        if has_speed:
            notes.append(
                "rotating force: the force the rotor exerts on each bearing, Ω² × the equivalent "
                "unbalance in its plane; fixed in the rotor (its angle is in the rotor's frame), it "
                "turns with the rotor"
            )
        notes.append(
            f"static load: M g by the lever rule with the shaft horizontal (g = {num(f.g, digits)} m/s²); "
            "negative means the bearing holds the rotor down"
        )
        doc.note("; ".join(notes))
    if r.options.speed is not None:
        ta, tok = r.torque_direction
        rows = [
            ("speed", f"{num(r.options.speed * RPM, digits)} rpm = {num(r.options.speed, digits)}", "rad/s"),
            ("total rotating force Ω² U", num(abs(f.centrifugal_force), digits), "N"),
            ("|L| about the com (L = J_G ω)", num(r.angular_momentum_magnitude, digits), "kg·m²/s"),
            ("torque ω × L (about the com)", num(r.torque_magnitude, digits), "N·m"),
            ("  its direction (rotor frame)", angle(ta, tok, digits), "°"),
        ]
        doc.kv("dynamics", rows)


def _iso(doc: Doc, r: BalanceResult, su: ShopUnits, digits: int) -> None:
    iso = r.iso_check
    assert iso is not None
    U = su.unit("unbalance")
    L = su.unit("length")
    rows = [
        ("balance quality grade", f"G {num(iso.grade, digits)}", "mm/s"),
        ("maximum service speed", f"{num(iso.speed * RPM, digits)} rpm = {num(iso.speed, digits)}", "rad/s"),
        ("permissible eccentricity e_per = G/Ω", su.show(iso.permissible_eccentricity, "eccentricity", digits), su.unit("eccentricity")),
        ("permissible residual unbalance U_per = e_per M", su.show(iso.permissible_unbalance, "unbalance", digits), U),
    ]
    doc.kv("ISO 21940-11 tolerance", rows)
    al = iso.allocation
    if iso.planes_are == "bearing":
        planes = "the bearing planes (ISO 21940-11)"
        names = ("1", "2")
    else:
        planes = "the correction planes (older practice, ISO 1940/1:1986; --tolerance-planes corrections)"
        names = ("A", "B")
    doc.note(f"tolerance planes: {planes}; the com is {al.kind} ({'between' if al.kind == 'inboard' else 'outside'} them); allocation: {al.rule}")
    after = iso.after
    cols = ["plane", f"z [{L}]", f"allowed [{U}]", f"as given [{U}]", "ratio", "achieved G [mm/s]"]
    if after is not None:
        cols += [f"predicted [{U}]", "ratio"]  # with the corrections fitted: see the note
    rows = []
    tol = iso.tol_plane

    def cells(state: B.IsoState, i: int) -> tuple[str, str, str]:
        zero = not abs(state.residual[i]) > tol  # zero to round-off: shown as 0
        return (
            su.show(0.0 if zero else abs(state.residual[i]), "unbalance", digits),
            num(0.0 if zero else state.ratio[i], 4),
            num(0.0 if zero else state.achieved_grade[i], 4),
        )

    for i in range(2):
        b = cells(iso.before, i)
        row = [names[i], su.show(iso.planes[i], "length", digits), su.show(al.allowed[i], "unbalance", digits),
               b[0], b[1], b[2]]
        if after is not None:
            a = cells(after, i)
            row += [a[0], a[1]]
        rows.append(row)
    doc.table("residual unbalance per plane", cols, rows, right=tuple(range(1, len(cols))))
    st = iso.before
    text = (
        f"{'PASS' if iso.passed else 'FAIL'}: G {num(iso.grade)}, the rotor as given"
        + ("" if iso.passed else " (exit status 1)")
        + "; whole-rotor static figure |U|/M Ω = "
        f"{num(st.static_achieved_grade if st.static_unbalance > r.unbalance.tol_static else 0.0, 4)} mm/s; "
        "PASS when each plane's residual is within its allowed share"
    )
    doc.note(text)
    if after is not None:
        doc.note(
            f"prediction, not the verdict (the predicted columns): with {after_words(iso)} fitted the rotor would "
            f"{'PASS' if after.passed else 'FAIL'} G {num(iso.grade)}; fit them, then run "
            "rbcli balance on the corrected rotor (e.g. the file --apply writes) to check it"
        )


def after_words(iso: B.IsoCheck) -> str:
    """What the ISO prediction assumes is fitted: the corrections, rounded or not."""
    return "the rounded corrections" if iso.after_state == "after rounded corrections" else "the corrections"
