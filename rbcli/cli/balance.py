"""``rbcli balance``: unbalance of a rotor about its shaft, corrections, bearing loads, ISO grade."""

from __future__ import annotations

import typer

from rbcli.api.commands import BALANCE
from rbcli.cli import common as c
from rbcli.cli.app import MANUAL

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
the corrections added as point parts; --plot FILE draws the polar balancing diagram.

Angles are degrees about the shaft (+z) from +x (the 0° mark) towards +y, in the direction
of rotation for a positive speed (--angle-sense against counts the other way). A bare
number means what it would mean in the body file: positions and lengths in the body's length
unit (metres without units:), masses in its mass unit, speeds in rad/s unless its units name
an angular_speed; in a list a unit after the last number applies to every bare number before
it ('-100,100 mm' is both in mm). Tables show g, mm,
g·mm and N unless --units is given.
"""

@c.command(BALANCE, help=HELP)
def balance(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    args: dict = c.PARAMS,
    apply: str = typer.Option(None, "--apply", help="Write the body with the correction masses added as point parts to this YAML file.", show_default=False),
    force: bool = typer.Option(False, "--force", help="Let --apply replace an existing file (never an input: the body file, a file it includes or a mesh it reads)."),
    plot: str = typer.Option(None, "--plot", help="Write the polar balancing diagram (png, svg or pdf): per correction plane the unbalance as given, the masses to add and the residual, on the rotor's clock face (without --planes: U and P_G).", show_default=False),
    json_: bool = c.JsonOpt,
    fmt: str = c.FormatOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.api import balance as api
    from rbcli.errors import InputError
    from rbcli.render import balance as rb

    e, out, su = c.start(json_, fmt, units, shop=True)
    b = c.load_one(body, expr, e)
    o = api.parse(b, **args)
    if apply is not None and o.planes is None:
        raise InputError("--apply: needs the correction planes, --planes zA,zB")
    if force and apply is None:
        raise InputError("--force: only used with --apply")
    out_path = None
    if apply is not None:
        from rbcli.io.writebody import check_output

        out_path = check_output(apply, b, force=force)
    plot_path = c.check_plot(plot, b, others={"--apply": out_path}) if plot is not None else None
    res = api.run(b, o)
    if plot_path is not None:
        from rbcli.render import balanceplot

        c.save_plot(balanceplot.plot(res.diagram(), su), plot_path)
    applied = _apply(res, out_path, apply, b, args) if out_path is not None else None
    for w in res.warnings:
        e.warn(f"rbcli: warning: {c.said(w)}")
    c.emit(e, out, lambda: _json(res, applied),
           lambda doc: rb.document(doc, res, su, digits, applied=applied),
           given=lambda: rb.echo_rows(res))
    c.finish(res.return_code)


def _json(res, applied) -> dict:
    """``--json``: the result's JSON with ``apply`` (before ``warnings``) and ``file``."""
    d = res.to_json()
    if applied is not None:
        d = {**{k: v for k, v in d.items() if k not in ("warnings", "name")},
             "apply": {"file": applied[0], "parts": applied[1]},
             "warnings": d["warnings"], "name": d["name"]}
    d["file"] = res.body.source
    return d


#: the options the header of ``--apply`` repeats, to check the body written
_CHECK = ("shaft", "through", "mark", "zero_mark_deg", "angle_sense", "planes", "radius",
          "bearings", "speed", "grade")


def _apply(res, out_path, apply: str, b, args: dict) -> tuple[str, list[dict]]:
    """Write ``--apply OUT``: ``res.balanced_body().to_yaml()`` (the body with the correction
    masses as point parts) under a header, never over an input nor, without ``--force``,
    over an existing file. Returns (the path written, the parts added as JSON rows)."""
    import shlex

    from rbcli.errors import option_name
    from rbcli.io import outfile
    from rbcli.io.writebody import check_output

    fr = res.installed
    if res.position_split is not None:
        state = "correction masses at the positions" + (" (rounded)" if fr.rounded else "")
    else:
        state = "rounded correction masses" if fr.rounded else "correction masses"
    check = " ".join(f"{option_name(p)}={shlex.quote(str(args[p]))}" for p in _CHECK
                     if p in res.options.given)
    header = [
        f"Written by rbcli balance --apply from {b.source} ({b.name}):",
        f"the body with the two-plane {state} added as point parts",
        f"(planes z = {fr.planes[0]:.6g} m and {fr.planes[1]:.6g} m along the shaft, "
        f"radii {fr.radii[0]:.6g} m and {fr.radii[1]:.6g} m). Check it:",
        f"  rbcli balance {shlex.quote(apply)} {check}",
    ]
    text = "".join(f"# {line}\n" if line else "#\n" for line in header)
    text += res.balanced_body().to_yaml(base_dir=out_path.parent)
    path = check_output(str(out_path), b, force=True)  # checked again as it is written
    outfile.write_atomic(path, text, "--apply", replace=True)
    rows = [{"name": a.name, "mass": float(a.mass), "at": [float(x) for x in a.at]} for a in res.added]
    return str(out_path), rows


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
        "parts: list, the body's name written when the file left it to the file's stem, and "
        "relative include/mesh paths rewritten for OUT's folder (in Python: "
        "rbcli.balance(...).balanced_body().to_yaml()). It never writes "
        "over an input — the body file, any file it includes (at any depth) or any mesh it reads, "
        "also not through a link to one — nor over an existing OUT without --force (exit 2); it "
        "writes a temporary file beside OUT and renames it, so a failed run leaves no half-written "
        "body.",
        "--plot FILE (png, svg or pdf, by the extension; checked before anything is computed, never "
        "an input) draws the polar balancing diagram: with --planes one clock face per correction "
        "plane with the rotor's unbalance in that plane as given (solid), the masses to add as "
        "unbalances m r (dashed; one arrow per position with --positions, labelled with the mass) "
        "and the residual after adding them (dotted), in g·mm (or the --units); without --planes "
        "the static unbalance U and the couple unbalance P_G. The dial reads the angles the "
        "command prints, 0° (the mark) on the right; the rotor is seen from the +z end of the "
        "shaft turning counterclockwise, so angles counted against the rotation (--angle-sense "
        "against) run clockwise on the dial and every vector sits where it is on the rotor.",
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
        ("rbcli balance examples/two_disk_rotor.yaml --planes 0,400mm --radius 100mm --mass-step '0.5 g' --plot polar.svg",
         "The polar diagram: per plane the unbalance as given, the 8.5 g and 12.5 g to add and the residual."),
        ("rbcli balance examples/car_wheel.yaml --planes=-100,100mm --mass-step '5 g' --apply wheel_balanced.yaml",
         "Writes the wheel with its two 45 g weights; 'rbcli balance wheel_balanced.yaml' shows the residual."),
    ],
}
