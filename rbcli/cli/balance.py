"""``rbcli balance``: unbalance of a rotor about its shaft, corrections, bearing loads, ISO grade."""

from __future__ import annotations

import re

import typer

from rbcli.cli import common as c
from rbcli.cli.app import MANUAL, app

HELP = """Rotor balance about a shaft: unbalance, two-plane corrections, bearing forces, ISO 21940-11.

About the shaft (--shaft through --through; default the body's shaft, else body z through
the origin): the mass, the eccentricity of the com, the static unbalance U = M e and its
angle, the couple unbalance about the com, the tilt of the nearest principal axis from the
shaft and its direction, and whether the rotor is statically and dynamically balanced.

With --planes zA,zB (positions along the shaft) and --radius: the two correction masses to
add and their angles (remove the same mass at +180°) and the single-plane static
correction; --mass-step and --angle-step round them, --positions N splits each onto the
two neighbouring of N equally spaced holes or blades, and the residual after that is
recomputed. With --speed and --bearings z1,z2: the rotating force on each bearing, the
static gravity loads (shaft horizontal; negative on an overhung rotor) and the torque
w x L. With --grade G6.3 (and --speed, the maximum service speed, and --bearings): the ISO
21940-11 permissible residual unbalance, its allocation to the bearing planes, the exact
residual per plane, the achieved grade and PASS or FAIL for the rotor as given (exit status
1 on FAIL, with or without --planes); with --planes also the residuals and verdict predicted
for the rotor with the (rounded) corrections fitted. --apply OUT.yaml writes the body with
the corrections added as point parts.

Angles are degrees about the shaft (+z) from +x (the 0° mark) towards +y, in the direction
of rotation for a positive speed (--angle-sense against counts the other way). Positions
and lengths are in metres unless a unit is given; in a list a unit after the last number
applies to every bare number before it ('-100,100 mm' is both in mm). Tables show g, mm,
g·mm and N unless --units is given.
"""

@app.command(help=HELP)
def balance(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    shaft: str = typer.Option(None, "--shaft", help="Shaft direction x,y,z (or x, y, z) in the body frame. Default: the body's shaft, else z.", show_default=False),
    through: str = typer.Option(None, "--through", help="A point of the shaft (z = 0 there): com, origin or x,y,z (m; a unit after the last number applies to all). Default: the body's shaft point, else the origin.", show_default=False),
    mark: str = typer.Option(None, "--mark", help="Direction x,y,z (body frame) of the 0° reference mark; only its part at right angles to the shaft counts. Default: body x projected (body y for a shaft near body x).", show_default=False),
    zero_mark_deg: str = typer.Option(None, "--zero-mark-deg", help="Turn the 0° mark this far about the shaft, in the direction of rotation (degrees, or with units, e.g. '0.5 rad'). Default: 0.", show_default=False),
    angle_sense: str = typer.Option("with", "--angle-sense", help="Count angles with the rotation (with) or against it (against)."),
    planes: str = typer.Option(None, "--planes", help="Correction planes zA,zB along the shaft (m; a unit after the last number applies to both, e.g. '-100,100 mm').", show_default=False),
    radius: str = typer.Option(None, "--radius", help="Correction radius r, or rA,rB per plane (m, or with units as for --planes). Default: the body's rim_radius.", show_default=False),
    mass_step: str = typer.Option(None, "--mass-step", help="Round correction masses to multiples of this (e.g. '1 g'; a bare number is kg).", show_default=False),
    angle_step: str = typer.Option(None, "--angle-step", help="Round correction angles to multiples of this (degrees, or with units).", show_default=False),
    positions: int = typer.Option(None, "--positions", help="N equally spaced fixed positions (holes, blades), position 1 on the 0° mark: split each correction onto the two neighbouring ones.", show_default=False),
    speed: str = typer.Option(None, "--speed", help="Rotor speed (rad/s, or e.g. '1500 rpm'); with --grade the maximum service speed.", show_default=False),
    bearings: str = typer.Option(None, "--bearings", help="Bearing positions z1,z2 along the shaft (m; a unit after the last number applies to both, e.g. '-50,150 mm').", show_default=False),
    g: str = typer.Option(None, "--g", help="Gravity for the static bearing loads (m/s^2, or with units). Default: 9.80665 m/s^2.", show_default=False),
    grade: str = typer.Option(None, "--grade", help="ISO 21940-11 balance quality grade, e.g. G6.3 (G0.4 to G4000); needs --speed and --bearings.", show_default=False),
    tolerance_planes: str = typer.Option(None, "--tolerance-planes", help="Planes the permissible unbalance is allocated to: bearings (ISO 21940-11, the default) or corrections (older practice).", show_default=False),
    apply: str = typer.Option(None, "--apply", help="Write the body with the correction masses added as point parts to this YAML file.", show_default=False),
    force: bool = typer.Option(False, "--force", help="Let --apply replace an existing file (never an input: the body file, a file it includes or a mesh it reads)."),
    json_: bool = c.JsonOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    import math

    from rbcli.errors import InputError
    from rbcli.render.balance import ShopUnits

    e = c.env()
    su = ShopUnits(units)
    # --- option values, checked before the body is read (bad usage is bad usage)
    if angle_sense not in ("with", "against"):
        raise InputError(f"--angle-sense must be 'with' or 'against', not '{angle_sense}'")
    if tolerance_planes not in (None, "bearings", "corrections"):
        raise InputError(f"--tolerance-planes must be 'bearings' or 'corrections', not '{tolerance_planes}'")
    t_planes = tolerance_planes or "bearings"
    zero_deg = 0.0
    if zero_mark_deg is not None:
        zero_deg = c.degrees(zero_mark_deg, "--zero-mark-deg")
        if not math.isfinite(zero_deg):
            raise InputError("--zero-mark-deg: must be a finite angle")
    n_shaft = c.direction(shaft, "--shaft") if shaft is not None else None
    p_through = c.point(through, "--through") if through is not None else None
    v_mark = c.vector(mark, "dimensionless", "--mark") if mark is not None else None
    z_planes = c.distinct(c.numbers(planes, "length", "--planes", counts=(2,)), "--planes", "correction planes") if planes is not None else None
    r_opt = None
    if radius is not None:
        r_opt = [c.positive(x, "--radius", "the correction radius") for x in c.numbers(radius, "length", "--radius", counts=(1, 2))]
    m_step = c.positive(c.quantity(mass_step, "mass", "--mass-step"), "--mass-step", "the mass step") if mass_step is not None else None
    a_step = None
    if angle_step is not None:
        a_step = c.degrees(angle_step, "--angle-step")
        if not (0.0 < a_step <= 360.0):
            raise InputError(f"--angle-step: must be more than 0 and at most 360 degrees, got {angle_step}")
    if positions is not None and positions < 3:
        raise InputError(f"--positions: needs at least 3 equally spaced positions, got {positions}")
    W = c.positive(c.quantity(speed, "angular_speed", "--speed"), "--speed", "the speed (to turn the other way, reverse --shaft)") if speed is not None else None
    z_bear = c.distinct(c.numbers(bearings, "length", "--bearings", counts=(2,)), "--bearings", "bearings") if bearings is not None else None
    gv = c.positive(c.quantity(g, "acceleration", "--g"), "--g", "gravity") if g is not None else None
    G = c.grade(grade) if grade is not None else None
    # --- which options need which
    if z_planes is None:
        for opt, val in (("--radius", radius), ("--mass-step", mass_step), ("--angle-step", angle_step),
                         ("--positions", positions), ("--apply", apply)):
            if val is not None:
                raise InputError(f"{opt}: needs the correction planes, --planes zA,zB")
    if positions is not None and a_step is not None:
        raise InputError("--angle-step: the angles are fixed by --positions; give one or the other")
    if G is not None:
        if W is None:
            raise InputError("--grade: needs --speed, the maximum service speed (e.g. --speed '3000 rpm')")
        if t_planes == "bearings" and z_bear is None:
            raise InputError(
                "--grade: needs --bearings z1,z2, the planes ISO 21940-11 allocates the tolerance to "
                "(or --tolerance-planes corrections with --planes)"
            )
        if t_planes == "corrections" and z_planes is None:
            raise InputError("--tolerance-planes corrections: needs --planes zA,zB")
    elif tolerance_planes is not None:
        raise InputError("--tolerance-planes: only used with --grade")
    if force and apply is None:
        raise InputError("--force: only used with --apply")

    b = c.load_one(body, expr, e)
    out_path = None
    if apply is not None:
        from rbcli.io.writebody import check_output

        out_path = check_output(apply, b, force=force)

    from rbcli.render import balance as rb

    res = compute(b, shaft=n_shaft, through=p_through, mark=v_mark, zero_mark_deg=zero_deg,
                  angle_sense=angle_sense, planes=z_planes, radius=r_opt, mass_step=m_step,
                  angle_step=a_step, positions=positions, speed=W, bearings=z_bear, g=gv, grade=G,
                  tolerance_planes=t_planes)
    if m_step is not None and res.corrections is not None:
        biggest = max(pc.mass for pc in res.corrections.pair)
        if m_step > biggest:
            res.warnings.append(
                f"--mass-step {mass_step} is larger than the largest correction "
                f"({su.show(biggest, 'mass', 4)} {su.unit('mass')}): the masses round to 0 or one step "
                "(a bare number is kg: did you mean grams, e.g. '1 g'?)"
            )
    if out_path is not None:
        import shlex

        given = [("--shaft", shaft), ("--through", through), ("--mark", mark),
                 ("--zero-mark-deg", zero_mark_deg),
                 ("--angle-sense", "against" if angle_sense == "against" else None),
                 ("--planes", planes), ("--radius", radius), ("--bearings", bearings),
                 ("--speed", speed), ("--grade", grade)]
        check = " ".join(f"{o}={shlex.quote(v)}" for o, v in given if v is not None)
        _apply(res, out_path, apply, b, check)
    for w in res.warnings:
        e.warn(f"rbcli: warning: {w}")
    c.emit(e, json_, lambda: rb.to_json(res), lambda doc: rb.document(doc, res, su, digits))
    c.finish(1 if (res.iso is not None and not res.iso.passed) else 0)


def compute(body, *, shaft=None, through=None, mark=None, zero_mark_deg: float = 0.0,
            angle_sense: str = "with", planes=None, radius=None, mass_step=None, angle_step=None,
            positions=None, speed=None, bearings=None, g=None, grade=None,
            tolerance_planes: str = "bearings"):
    """Everything ``rbcli balance`` reports for a body, as a render Result (shared with report).

    Options are parsed values in SI (None = not given): ``shaft`` a direction, ``through``
    "com", "origin" or [x, y, z], ``mark`` a direction, ``planes``/``bearings`` (z1, z2),
    ``radius`` [r] or [rA, rB], ``mass_step`` kg, ``angle_step`` and ``zero_mark_deg``
    degrees, ``positions`` N, ``speed`` rad/s, ``g`` m/s² (default 9.80665), ``grade`` G in
    mm/s. Errors come back as the command reports them: a ValueError of the physics as an
    InputError naming the options given, a result that overflows (or is inf or NaN anywhere
    in its JSON) as NonFiniteResult; both exit 2.
    """
    import numpy as np

    from rbcli.errors import InputError, NonFiniteResult
    from rbcli.render import balance as rb
    from rbcli.render.jsonout import jsonable

    given = [o for o, v in (("--planes", planes), ("--radius", radius), ("--bearings", bearings),
                            ("--speed", speed), ("--mass-step", mass_step), ("--through", through),
                            ("--g", g)) if v is not None]
    try:
        with np.errstate(all="ignore"):
            res = _compute(body, n_shaft=shaft, p_through=through, v_mark=mark,
                           zero_mark_deg=zero_mark_deg, sense=angle_sense, z_planes=planes,
                           r_opt=radius, m_step=mass_step, a_step=angle_step, n_pos=positions,
                           W=speed, z_bear=bearings, gv=9.80665 if g is None else g, G=grade,
                           tolerance_planes=tolerance_planes)
            jsonable(rb.to_json(res))  # refuses inf and NaN
    except (ValueError, OverflowError, ZeroDivisionError, NonFiniteResult) as exc:
        if isinstance(exc, ValueError):
            raise InputError(f"{', '.join(given) or 'balance'}: {exc}") from None
        raise NonFiniteResult(
            f"{', '.join(given) or 'balance'}: the result overflows (a number beyond 1e308): "
            "an option value is too large or too small for this body"
        ) from None
    return res


def _compute(b, *, n_shaft, p_through, v_mark, zero_mark_deg, sense, z_planes, r_opt, m_step, a_step,
              n_pos, W, z_bear, gv, G, tolerance_planes):
    """The work of :func:`compute`, without its error mapping."""
    import numpy as np

    from rbcli.core import balance as B
    from rbcli.core.inertia import combine
    from rbcli.errors import InputError
    from rbcli.render.balance import Result, mark_source

    mp = combine(b.parts)
    if n_shaft is not None:
        axis, shaft_source = np.asarray(n_shaft, dtype=float), "--shaft"
    elif b.shaft is not None:
        axis, shaft_source = np.asarray(b.shaft.axis, dtype=float), "the body's shaft"
    else:
        axis, shaft_source = np.array([0.0, 0.0, 1.0]), "body z, the default"
    if isinstance(p_through, str):
        P = np.array(mp.com) if p_through == "com" else np.zeros(3)
        through_source = f"--through {p_through}"
    elif p_through is not None:
        P, through_source = np.asarray(p_through, dtype=float), "--through"
    elif b.shaft is not None:
        P, through_source = np.asarray(b.shaft.through, dtype=float), "the body's shaft"
    else:
        P, through_source = np.zeros(3), "the origin, the default"
    try:
        unb = B.unbalance(mp.mass, mp.com, mp.inertia_com, axis, P, reference=v_mark,
                          zero_mark_deg=zero_mark_deg, angle_sense=sense)
    except ValueError as exc:
        raise InputError(f"{'--mark' if 'reference' in str(exc) else '--shaft'}: {exc}") from None
    res = Result(body=b, unb=unb, shaft_source=shaft_source, through_source=through_source,
                 mark_source=mark_source(axis, v_mark is not None, zero_mark_deg))
    res.warnings += list(unb.warnings)
    res.speed = W
    res.bearings = z_bear
    if z_planes is not None:
        if r_opt is not None:
            radii = r_opt[0] if len(r_opt) == 1 else (r_opt[0], r_opt[1])
            res.radius_source = "--radius"
        elif b.rim_radius is not None:
            radii = float(b.rim_radius)
            res.radius_source = "the body's rim_radius"
        else:
            raise InputError("--planes: needs --radius (the radius the correction masses sit at), "
                             "or rim_radius in the body file")
        try:
            corr = B.corrections(unb, z_planes, radii, bearings=z_bear)
        except ValueError as exc:
            raise InputError(f"--planes/--radius: {exc}") from None
        res.corrections = corr
        final = corr
        if n_pos is not None:
            pos = B.split_corrections(corr, n_pos, mass_step=m_step)
            res.positions = pos
            final = pos.corrections
            pts = [(m, x) for _, _, m, x in pos.points()]
        else:
            if m_step is not None or a_step is not None:
                final = B.round_corrections(corr, m_step, a_step)
            pts = list(B.correction_points(final))
        res.final = final
        res.warnings += list(final.warnings)
        res.corrected = B.add_point_masses(unb, pts)
    if W is not None or z_bear is not None:
        res.forces = B.bearing_forces(unb, W if W is not None else 0.0, z_bear, g=gv)
        if W is not None and z_bear is not None and res.corrected is not None:
            res.forces_after = B.bearing_forces(res.corrected, W, z_bear, g=gv)
    if G is not None:
        tp = z_bear if tolerance_planes == "bearings" else z_planes
        try:
            res.iso = B.iso_check(unb, G, W, tp,
                                  planes_are="bearing" if tolerance_planes == "bearings" else "correction",
                                  corrections=res.final)
        except ValueError as exc:
            raise InputError(f"--grade: {exc}") from None
        res.warnings += list(res.iso.warnings)
    return res


def _apply(res, out_path, apply: str, b, check: str) -> None:
    from rbcli.io.writebody import NewPoint, write_balanced

    pts = []
    if res.positions is not None:
        for name, k, m, x in res.positions.points():
            pts.append(NewPoint(f"balance {name} (position {k})", m, x))
    else:
        from rbcli.core.balance import correction_points

        names = [pc.name for pc in res.final.pair if pc.mass > 0.0]
        for name, (m, x) in zip(names, correction_points(res.final)):
            pts.append(NewPoint(f"balance {name}", m, x))
    import shlex

    fr = res.final
    if res.positions is not None:
        state = "correction masses at the positions" + (" (rounded)" if fr.rounded else "")
    else:
        state = "rounded correction masses" if fr.rounded else "correction masses"
    header = [
        f"Written by rbcli balance --apply from {b.source} ({b.name}):",
        f"the body with the two-plane {state} added as point parts",
        f"(planes z = {fr.planes[0]:.6g} m and {fr.planes[1]:.6g} m along the shaft, "
        f"radii {fr.radii[0]:.6g} m and {fr.radii[1]:.6g} m). Check it:",
        f"  rbcli balance {shlex.quote(apply)} {check}",
    ]
    write_balanced(b, pts, str(out_path), force=True, header=header)
    res.apply_path = str(out_path)
    res.apply_parts = [
        {"name": p.name, "mass": float(p.mass), "at": [float(x) for x in p.at]} for p in pts
    ]


MANUAL["balance"] = {
    "notes": [
        "Frame and signs (physics notes balance.md §2): z runs along the shaft from the point "
        "--through (z = 0), in the direction of the shaft axis. For a shaft along body z the "
        "shaft frame is the body frame; for any other shaft, x (the 0° mark) is body x projected "
        "at right angles to the shaft (body y when the shaft is within 25.8° of body x), or the "
        "--mark direction, turned by --zero-mark-deg; y = z × x; the output prints the three "
        "axes. Angles are degrees in [0, 360) about +z from +x towards +y, the direction of "
        "rotation for a positive speed; --angle-sense against reports 360 − angle. An angle "
        "whose quantity is zero (to the tolerance) is printed as — (0 with *_angle_defined "
        "false in JSON).",
        "Unbalance: U = M (x_G + i y_G) (static, kg m), P_G = D_xz + i D_yz about the com with "
        "D = +∫xz dm = −J_xz (couple, kg m²), P = P_G + z_G U about z = 0. Balanced statically "
        "when e ≤ 1e-9 × the rotor's size, dynamically when also |P_G| ≤ 1e-9 × trace J_G: "
        "ideal verdicts, to the accuracy of the input (an ISO grade is a real tolerance). The "
        "tilt is the angle between the shaft and the nearest principal axis of the inertia about "
        "the com, and its direction is where that axis's +z end leans; for a (nearly) isotropic "
        "rotor it is ill-defined and rbcli warns.",
        "Corrections: C_A = (P − z_B U)/(z_B − z_A), C_B = (z_A U − P)/(z_B − z_A); mass |C|/r "
        "to add at arg C, or remove it at +180°. The single-plane (static) correction −U cancels "
        "the static unbalance only. --mass-step and --angle-step round (half up; angles in the "
        "reported sense); --positions N splits each correction onto the two neighbouring of N "
        "equally spaced positions (position 1 on the 0° mark), m1 = |C| sin(a2 − φ)/sin(a2 − a1), "
        "m2 = |C| sin(φ − a1)/sin(a2 − a1), then rounds with --mass-step. The residual after "
        "adding exactly what rbcli says to add is recomputed, with the tilt and the verdicts of "
        "the corrected rotor. Warnings: planes closer than 0.2 of the bearing span (or of the "
        "rotor's axial length), corrections heavier than 10 % of the rotor.",
        "Bearings: F_1 = Ω² (z_2 U − P)/(z_2 − z_1), F_2 = Ω² (P − z_1 U)/(z_2 − z_1), the force "
        "the rotor exerts on each bearing, fixed in the rotor frame (it turns with the rotor); "
        "F/Ω² is the equivalent unbalance in that plane. Static loads: M g by the lever rule, "
        "shaft horizontal; negative on the far bearing of an overhung rotor (a hold-down). "
        "Torque: ω × L with L = J_G ω about the com.",
        "ISO 21940-11: e_per = G/Ω at the maximum service speed (--speed), U_per = e_per M. "
        "Allocation to the tolerance planes (the bearings by default; --tolerance-planes "
        "corrections uses the correction planes, older practice): the lever rule on the com, "
        "each share clamped to 0.3..0.7 U_per when the com lies between the planes; when it lies "
        "outside (an overhung rotor) rbcli's own rule, flagged in the output: each plane gets "
        "the load U_per at the com would put on it, the far share floored at 0.3 U_per (the "
        "standard's clause for outboard rotors was not available to check). The exact residual "
        "in each plane is compared with its share. The verdict, PASS or FAIL, and the exit status "
        "are those of the rotor as given, with or without --planes; with --planes the residuals "
        "and verdict of the rotor with the (rounded) corrections fitted are shown too, as a "
        "prediction (JSON iso.after): fit them and run rbcli balance on the corrected rotor to "
        "check it. "
        "Achieved grade per plane G |U_i|/U_per,i. Exit status 1 on FAIL, after the full result.",
        "--apply OUT.yaml writes the body's document again (comments are lost) with the "
        "correction masses (rounded, or at the positions, when asked) as point parts 'balance "
        "A' and 'balance B' (with numbers in explicit units), a one-part shorthand turned into a "
        "parts: list and relative include/mesh paths rewritten for OUT's folder. It never writes "
        "over an input — the body file, any file it includes (at any depth) or any mesh it reads, "
        "also not through a link to one — nor over an existing OUT without --force (exit 2); it "
        "writes a temporary file beside OUT and renames it, so a failed run leaves no half-written "
        "body.",
    ],
    "json": [
        ("mass", "rotor mass, kg."),
        ("eccentricity", "distance of the com from the shaft, m."),
        ("static_unbalance, static_unbalance_angle_deg", "|U| = M e, kg m, and its angle (heavy side)."),
        ("couple_unbalance, couple_unbalance_angle_deg", "|P_G| about the com, kg m², and its angle."),
        ("moment_unbalance, moment_unbalance_angle_deg", "|P| about z = 0, kg m², and its angle."),
        ("tilt_deg, tilt_azimuth_deg", "angle of the nearest principal axis from the shaft, and where its +z end leans."),
        ("statically_balanced, dynamically_balanced", "the ideal verdicts; tolerances {eccentricity, couple_unbalance, rtol, rule} says how."),
        ("*_angle_defined, tilt_well_defined", "false when the quantity is zero to tolerance (angle reported 0) or the rotor is isotropic."),
        ("corrections", "with --planes: [{plane (z, m), name (A, B), mass (kg), radius (m), angle_deg, remove_angle_deg, unbalance (kg m)}], rounded when asked (ideal with --positions)."),
        ("static_correction", "the single-plane correction {mass, radius, angle_deg, ...}."),
        ("correction_details", "{residual {static_unbalance, couple_unbalance, planes [...]} after adding what rbcli says to add, rounded, mass_step, angle_step_deg, ideal, narrow_planes, narrow_ratio, ...}."),
        ("positions", "with --positions: {n_positions, pitch_deg, masses [{plane, name, position, angle_deg, mass, radius}], mass_step, rounded}."),
        ("corrected", "the rotor with the corrections added: {mass, eccentricity, static_unbalance, couple_unbalance, tilt_deg, statically_balanced, dynamically_balanced}."),
        ("bearing_forces", "with --speed and --bearings: [{plane (z, m), name, force (N), angle_deg (rotor frame), equivalent_unbalance (kg m), static_load (N)}]."),
        ("bearing_forces_after", "the same forces after the corrections."),
        ("bearings, static_load_assumption", "with --bearings: [{plane, name, static_load (N)}] (shaft horizontal)."),
        ("dynamics", "with --speed: {speed (rad/s), centrifugal_force (N), angular_momentum [3] (kg m²/s, about the com, shaft frame), torque [3] (N m), torque_magnitude, torque_origin [3]}."),
        ("iso", "with --grade: {grade (G, mm/s), grade_si (m/s), speed, permissible_eccentricity (m), permissible_unbalance (kg m), allowed [2] (kg m), residual [2] (kg m), ratio [2], achieved_grade [2] (mm/s) and pass, all of the rotor as given; judged ('as given'), planes, planes_are, allocation {rule, kind, rbcli_rule, ...}, before (the same state in full), after (with --planes: the prediction for the corrected rotor {residual, ratio, achieved_grade, pass, state, prediction: true}, else null)}."),
        ("angle_convention, shaft, shaft_source, through_source, mark_source", "the convention in words; the shaft frame {axis, through, x_axis, y_axis}; where each came from."),
        ("apply", "with --apply: {file, parts [{name, mass, at}]}."),
        ("warnings, name, file", "the warnings also printed on standard error; the body's name and source."),
    ],
    "examples": [
        ("rbcli balance examples/car_wheel.yaml --planes=-100,100mm --speed '1500 rpm' --bearings=-50,150mm",
         "The course text's car wheel, tilted 0.5°: statically balanced, couple 1.74524e+06 g·mm²; "
         "43.631 g at 180° (z = −100 mm) and at 0° (z = +100 mm); 215.31 N on each bearing."),
        ("rbcli balance examples/car_wheel.yaml --planes=-100,100mm --speed '1500 rpm' --bearings=-50,150mm --grade G40 --mass-step '5 g'",
         "Clip-on weights in 5 g steps: 45 g each. The wheel as given fails G40 (8726.2 g·mm per "
         "bearing plane, exit status 1); with the weights fitted it would pass (residual 273.797 g·mm)."),
        ("rbcli balance examples/two_disk_rotor.yaml --planes 0,400mm --radius 100mm --speed '3000 rpm' --bearings 0,400mm --grade G6.3",
         "8.5 g at 208.072° and 12.2577 g at 258.232°; bearing forces 83.8916 N and 120.978 N; "
         "FAIL G6.3 as given (exit status 1), PASS predicted with the corrections fitted."),
        ("rbcli balance examples/fan_impeller.yaml --planes 320,380mm --radius 190mm --bearings 0,200mm --speed '1480 rpm' --grade G6.3 --positions 6 --mass-step '0.5 g'",
         "An overhung fan: a negative static load on the far bearing, weights on the blades, "
         "rbcli's outboard allocation rule flagged."),
        ("rbcli balance examples/car_wheel.yaml --planes=-100,100mm --mass-step '5 g' --apply wheel_balanced.yaml",
         "Writes the wheel with its two 45 g weights; 'rbcli balance wheel_balanced.yaml' shows the residual."),
    ],
}


# ----------------------------------------------------------------------------- field balancing

FIELD_HELP = """Field (trial-weight) balancing from vibration readings: the influence-coefficient method.

Readings are amplitude@phase (any one vibration unit: µm, mils, mm/s; the phase in degrees
from the keyphasor), trial masses mass@angle ('10 g@0'). One plane: --initial V0, one
--trial T and one --run V1 (with the trial on) give H = (V1 - V0)/T and the correction
W = -V0/H (trial removed; with it left on, add W - T). Two planes: two sensors per run
(--initial V1,V2), --trial twice (planes A and B) and --run twice (trial A on, then trial B
on and A removed, or left on with --cumulative) give the 2x2 influence matrix and W =
-alpha^-1 V0, with its condition number (a warning above 50) and a warning for a trial that
changed no reading by 25 % or 25°. The correction angles are counted in the same sense as
the trial angles and the phases (they must agree). --trial-radius and --radius move the
corrections to another radius (m = m_trial r_trial / r).
"""

_READING = re.compile(r"\s*(?P<num>[^@]+?)\s*@\s*(?P<ang>.+?)\s*")


def _phasor_text(text: str, option: str, *, mass: bool):
    """'6.0@30' (a reading) or '10 g@0' (a mass, kg) -> complex; the angle in degrees."""
    import cmath
    import math

    from rbcli.errors import InputError

    m = _READING.fullmatch(text)
    if not m:
        what = "mass@angle, e.g. '10 g@0'" if mass else "amplitude@phase, e.g. '6.0@30'"
        raise InputError(f"{option}: '{text}' is not {what}")
    if mass:
        amp = c.quantity(m["num"], "mass", option)
    else:
        num = c.NUMBER.match(m["num"])
        if not num:
            raise InputError(f"{option}: '{text}': the amplitude must be a number (a unit after it is a label)")
        amp = float(m["num"][: num.end()])
    ang = math.degrees(c.quantity(m["ang"], "angle", option, bare="deg"))
    if not (math.isfinite(amp) and math.isfinite(ang)) or amp < 0:
        raise InputError(f"{option}: '{text}': amplitude must be a finite number >= 0 and the angle finite")
    return complex(cmath.rect(amp, math.radians(ang)))


def _readings(text: str, option: str, n: int) -> list[complex]:
    from rbcli.errors import InputError

    parts = [p for p in text.split(",")]
    if len(parts) != n:
        raise InputError(
            f"{option}: expected {n} reading{'s' if n > 1 else ''} (one per sensor, as many as "
            f"trial planes), got {len(parts)} in '{text}'"
        )
    return [_phasor_text(p, option, mass=False) for p in parts]


@app.command("field-balance", help=FIELD_HELP)
def field_balance(
    initial: str = typer.Option(..., "--initial", help="Readings without trial: amplitude@phase, one per sensor (1 or 2), e.g. '6.0@30' or '170@112,53@78'.", show_default=False),
    trial: list[str] = typer.Option(..., "--trial", help="Trial mass@angle per plane, e.g. '10 g@0' (give it twice for two planes; a bare mass is kg).", show_default=False),
    run_: list[str] = typer.Option(..., "--run", help="Readings with each trial on, in the order of --trial (same form as --initial).", show_default=False),
    cumulative: bool = typer.Option(False, "--cumulative", help="Two planes: trial A was left on during the run with trial B."),
    trial_radius: str = typer.Option(None, "--trial-radius", help="Radius the trials sat at (m, or with units); with --radius.", show_default=False),
    radius: str = typer.Option(None, "--radius", help="Radius the corrections go at (m, or with units); needs --trial-radius.", show_default=False),
    json_: bool = c.JsonOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.errors import InputError
    from rbcli.render.balance import ShopUnits

    e = c.env()
    su = ShopUnits(units)
    n = len(trial)
    if n not in (1, 2):
        raise InputError(f"--trial: give one trial (one plane) or two (two planes), not {n}")
    if len(run_) != n:
        raise InputError(f"--run: give one run per trial ({n}), not {len(run_)}")
    if cumulative and n != 2:
        raise InputError("--cumulative: only for two planes")
    if (trial_radius is None) != (radius is None):
        raise InputError("--radius and --trial-radius go together (the corrections move from the trial radius to --radius)")
    scale = 1.0
    radii = None
    if radius is not None:
        rt = c.positive(c.quantity(trial_radius, "length", "--trial-radius"), "--trial-radius", "the trial radius")
        rc = c.positive(c.quantity(radius, "length", "--radius"), "--radius", "the correction radius")
        scale, radii = rt / rc, (rt, rc)
    v0 = _readings(initial, "--initial", n)
    runs = [_readings(r, "--run", n) for r in run_]
    trials = [_phasor_text(t, "--trial", mass=True) for t in trial]
    for t in trials:
        if t == 0:
            raise InputError("--trial: the trial mass must not be zero")
    from rbcli.core import balance as B

    import numpy as np

    from rbcli.errors import NonFiniteResult
    from rbcli.render import balance as rb
    from rbcli.render.jsonout import jsonable

    try:
        with np.errstate(all="ignore"):
            if n == 1:
                res = B.field_single_plane(v0[0], runs[0][0], trials[0])
            else:
                res = B.field_two_plane(v0, runs[0], runs[1], trials[0], trials[1], cumulative=cumulative)
            data = jsonable(rb.field_json(res, trials, scale, radii))  # refuses inf and NaN
    except (ValueError, OverflowError, ZeroDivisionError, np.linalg.LinAlgError, NonFiniteResult) as exc:
        if isinstance(exc, ValueError):  # LinAlgError too
            raise InputError(f"--run: {exc}") from None
        raise NonFiniteResult(
            "--initial, --trial, --run: the result overflows (a number beyond 1e308); "
            "the readings or trial masses are too large or too small"
        ) from None
    for w in res.warnings:
        e.warn(f"rbcli: warning: {w}")
    c.emit(e, json_, lambda: data, lambda doc: rb.field_document(doc, res, trials, scale, radii, su, digits))


MANUAL["field-balance"] = {
    "notes": [
        "Physics notes balance.md §5: readings are complex numbers V = amplitude e^{i phase}; "
        "trials T = mass e^{i angle}. One plane: H = (V1 - V0)/T, W = -V0/H (trial removed), "
        "W - T with the trial left on; the predicted residual V0 + H W is 0 in the linear model. "
        "Two planes, two sensors: alpha_iA = (V_iA - V_i0)/T_A, alpha_iB = (V_iB - V_i0)/T_B "
        "(V_iB - V_iA with --cumulative), W = -alpha^-1 V0. Warnings: cond(alpha) > 50 (planes "
        "not well separated), a trial run that changed no reading by 25 % in amplitude or 25° "
        "in phase (use a larger trial).",
        "The trial angles and the phases must be counted in the same sense; the correction "
        "angles come out in that sense. Correction masses are in the trial's mass unit scaled "
        "by --trial-radius / --radius when given.",
    ],
    "json": [
        ("planes", "1 or 2."),
        ("corrections", "[{name, mass (kg), angle_deg, mass_trial_on, angle_trial_on_deg, radius (m or null)}]; trial removed, and with that plane's trial left on."),
        ("influence", "[[{magnitude (reading unit per kg), angle_deg}]] row = sensor, column = plane."),
        ("cond, det_magnitude", "2-norm condition number and |det| of the influence matrix (two planes)."),
        ("small_response, predicted_residual, cumulative, warnings", "checks as in the notes."),
    ],
    "examples": [
        ("rbcli field-balance --initial '6.0@30' --trial '10 g@0' --run '4.0@110'",
         "One plane: H = 0.66079 (mm/s)/g at 173.406°, add 9.08 g at 36.594° (trial removed)."),
        ("rbcli field-balance --initial '170@112,53@78' --trial '1.15 g@0' --run '235@94,58@68' --trial '1.15 g@0' --run '185@115,77@104'",
         "The B&K two-plane example: 1.979 g at 236.2° and 1.071 g at 121.8°, cond 2.70."),
    ],
}
