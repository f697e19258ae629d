"""``rbcli rollcheck``: when does a rolling wheel, coin or hoop stay up?"""

from __future__ import annotations

import typer

from rbcli.api.commands import ROLLCHECK
from rbcli.cli import common as c
from rbcli.cli.app import MANUAL

HELP = """Stability of a wheel, disk or hoop rolling on a rough floor: the critical speed.

The body must be a body of revolution about its axle (--axle, default the body's
shaft, else body z) with its centre of mass on the axle (within --symmetry-tol,
default 1 %: a nearly symmetric wheel is answered for its symmetrised form with a
warning) and its rim circle in the
plane of the centre of mass (within 1 % of the radius; a cone on its base rim is refused). It rolls without slipping
on its rim, radius a (--radius, default the body's rim_radius, else the largest
round part coaxial with the axle; the output says which). The rim's shape sets the
contact: a disk or ring is a knife edge, a torus has its tube radius r, a sphere
(r = a) has no lean instability and stays up at any speed, a cylinder on its side is
a flat band (its weight holds it up for leans below atan(c/a), c the band's half
width; its critical speed is that of rolling balanced on an edge). Straight upright
rolling is stable (neutrally: undamped, a small lean oscillates) when the spin s
satisfies s^2 > m g (a - r) I / (Is (Is + m a^2)), I across the axle and Is about it,
both about the centre; --tyre-radius r (0 <= r <= a) overrides the shape's r.
At --speed or --spin: the verdict, the margin (speed over critical) and the
lean oscillation frequency or growth rate. With two of --lean, --circle, --speed:
steady circular rolling (turn rate, spin, speed, stable or not). Exit status 1 when
the motion asked about is unstable.
"""

@c.command(ROLLCHECK, help=HELP)
def rollcheck(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    args: dict = c.PARAMS,
    plot: str = typer.Option(None, "--plot", help="Save a figure (.png, .svg, .pdf): lean frequency squared and growth rate against speed; with a circle, also the stable region in the (lean, circle radius) plane. An existing figure is replaced (atomically); an input file never.", show_default=False),
    json_: bool = c.JsonOpt,
    fmt: str = c.FormatOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.api import rollcheck as api
    from rbcli.render import rollcheck as rr

    e, out, du = c.start(json_, fmt, units)
    b = c.load_one(body, expr, e)
    o = api.parse(b, **args)
    plot_path = c.check_plot(plot, b) if plot is not None else None
    res = api.run(b, o)
    if plot_path is not None:
        c.save_plot(rr.plot(res, res.curves()), plot_path)

    def tables(doc) -> None:
        rr.document(doc, res, du, digits)
        if plot_path is not None:
            doc.note(f"plot written to {plot_path}")

    c.emit(e, out, lambda: {**res.to_json(), "file": res.source}, tables,
           given=lambda: rr.echo_rows(res))
    for w in res.warnings:  # after the output: a result that cannot be printed says only that
        e.warn(f"rbcli: {res.source}: warning: {c.said(w)}")
    c.finish(res.return_code)


MANUAL["rollcheck"] = {
    "notes": [
        "Model (physics notes dynamics.md §3): a rigid body of revolution rolls without "
        "slipping, pivot friction or rolling resistance on a horizontal floor, touching it on "
        "a circle of radius a in its mid-plane (a knife edge) or on a toroidal rim of tube "
        "radius r (0 < r < a), a sphere (r = a) or a flat band. I (= A) is the moment across the axle and Is (= C) the "
        "moment about it, both about the centre of mass; Is + m a^2 is the axial moment about "
        "the contact point, which is where the condition's mixed product comes from. Energy is "
        "conserved, so 'stable' means neutrally stable (undamped): a small lean oscillates at "
        "the lean frequency nu, nu^2 = [Is (Is + m a^2) s^2 - I m g (a - r)] / [I (I + m a^2)], "
        "and does not decay; 'unstable' means it grows at sqrt(-nu^2). Exactly at the critical "
        "speed the verdict is unstable. Thin disk: v_c = sqrt(g a/3); hoop: v_c = sqrt(g a/4).",
        "The rim as it is (issue 24): the parts whose outer radius is the rim radius say what "
        "touches the floor. A disk, ring, a cone's base or a hemisphere's flat face: a knife "
        "edge, r = 0. A torus (a tyre): its tube radius r, which shortens gravity's lever to "
        "a - r. A sphere: r = a, no lever at any lean: no lean instability, critical speed 0, "
        "stable at every speed (JSON margin null). A cylinder on its side (a thick coin, a can), "
        "or rim circles in two planes (two wheels on an axle): a flat band from c1 on one side "
        "of the centre of mass's plane to c2 on the other. Upright it stands on the band, and "
        "its weight holds it up against leans below atan(min(c1, c2)/a) at any speed (a "
        "disturbance within that rocks it back, or rolls it along a curve on one edge: it "
        "leans no further). Tipped past that it balances on one edge circle, c from the centre "
        "of mass's plane, leaning atan(c/a) with the centre of mass above the contact; rolling "
        "so is stable above s_e, s_e^2 = m g l Delta / (Is (Is + m a^2)(Is + m l^2)), "
        "l^2 = a^2 + c^2, Delta = (Is + m a^2)(I + m c^2) - m^2 a^2 c^2 (derived from the "
        "rolling equations, checked against their integration; c = 0 is the knife edge). The "
        "critical speed of a band is the larger of its two edges'; the knife-edge value at the "
        "centre of mass's plane (the sheet's idealisation) is printed beside it. --tyre-radius "
        "overrides the shape (a torus of tube r; r = a a sphere). Steady circles are computed "
        "for a knife edge only.",
        "The axle is --axle, else the body's shaft axis, else body z; it passes through "
        "--through, else the body's shaft point, else the origin. The body must be of "
        "revolution about it and its centre of mass must be on it, within --symmetry-tol (see "
        "below); otherwise rbcli says by how much, names --symmetry-tol and exits 2. The rim radius is --radius, "
        "else the body's rim_radius, else the largest outer radius of the round parts (ring, "
        "disk, cylinder, torus, sphere, hemisphere, cone; not holes) centred on and coaxial "
        "with the axle; the output says which.",
        "Rims off the centre of mass: rollcheck measures where the rim lies along the "
        "axle from the parts whose outer radius is the rim radius (disk, ring, sphere, torus: "
        "their own plane; cylinder: a band, its length, about its centre; hemisphere: its flat "
        "face, 3R/8 from its centre of mass; cone: its base, h/4 from its centre of mass; several "
        "such parts: a band from the outermost to the other). A rim circle (a band) off the plane of the "
        "centre of mass makes upright rolling no equilibrium: the centre of mass is to the side "
        "of the contact point. Up to 1 % of the rim radius (a lean of 0.57° would bring the centre "
        "of mass over the rim) the model takes the rim in that plane and warns with the real "
        "offset; beyond 1 % both straight rolling and steady circles are refused with the offset "
        "and that reason (exit 2): a cone or hemisphere on its base rim, a top. With a --radius or "
        "rim_radius that no round part has, there is nothing to measure and the rim is taken in "
        "the plane of the centre of mass.",
        "Nearly symmetric wheels (issue 14; a CAD wheel is of revolution only to its "
        "modelling: a valve, a balancing mark, a tilt on the axle): the two moments across the "
        "axle (about the centre of mass) may differ, and the products of inertia coupling the "
        "axle to the plane across it may be, up to --symmetry-tol (default 1 %, a fraction 0.01 "
        "or '1 %', at most 10 %) of their mean; the centre of mass may be off the axle by that "
        "fraction of the rim radius. Within it the answer is for the symmetrised wheel (I the "
        "mean moment across, the centre of mass taken on the axle), with one warning on "
        "standard error giving the asymmetry in %, a table line saying how far the critical "
        "spin and speed may be off, and the JSON key asymmetry. The bound: s_c is proportional "
        "to sqrt(I), so with the moments across I1 <= I2 differing by delta of their mean the "
        "real threshold lies between the values for I1 and I2, within delta/(4 - delta) "
        "(about delta/4) of the symmetrised one; products of inertia add about their relative "
        "size, a centre of mass e off the axle about e/(2 (a - r)); the line quotes the largest. "
        "Beyond the tolerance the wheel is refused with both moments (digits enough to differ), "
        "the % and the option. Symmetric to rounding (1e-6): nothing is said.",
        "Straight rolling: --speed (m/s, or e.g. '20 km/h'; negative = backwards, the verdict "
        "uses |speed|) or --spin (rad/s, or '300 rpm'); both may be given if they agree "
        "(speed = a x spin). The margin is |speed| / critical speed.",
        "Steady circular rolling (knife edge only): the wheel leans inwards by --lean degrees "
        "from the vertical with its centre on a circle of radius --circle; give two of --lean, "
        "--circle and --speed. --circle 0 is spinning in place (Euler's disk; give --lean). "
        "--speed with --circle solves for the lean, --speed with --lean for the circle radius. "
        "The output has the turn rate Omega, the spin about the axle, the speed of the centre, "
        "the radius of the contact point's circle R_P = R_G + a sin(lean), the lean stiffness "
        "kappa (stable iff kappa > 0) and the lean frequency sqrt(kappa/(I + m a^2)) or the "
        "growth rate.",
        "Exit status 1 when the motion asked about is unstable: straight rolling at --speed "
        "or --spin; the circle when --lean/--circle is given (with --speed, --lean and "
        "--circle all given, either verdict). The full result is printed first.",
        "--plot FILE draws the squared lean frequency nu^2 against speed with the critical "
        "speed marked, and the lean frequency / growth rate; with a circle, the stable region "
        "in the (lean, circle radius) plane with the asked motion marked.",
    ],
    "json": [
        ("radius", "rim radius a, m."),
        ("mass", "kg."),
        ("I", "moment across the axle about the centre of mass (A), kg m^2."),
        ("Is", "moment about the axle (C), kg m^2."),
        ("critical_spin", "spin above which straight rolling is stable, rad/s."),
        ("critical_speed", "critical_spin x radius, m/s."),
        ("speed, stable, margin", "when --speed or --spin is given: the speed of the centre "
         "(m/s), whether straight rolling at it is stable (a band: balanced on either edge; a "
         "sphere: always), and |speed| / critical_speed (null for a sphere)."),
        ("circle", "with --lean/--circle: {lean_deg, radius (of the centre's circle, m), "
         "turn_rate (rad/s), spin (rad/s), speed (m/s), stable, contact_radius (m), kappa (N m), "
         "lean_frequency (rad/s or null), lean_frequency_hz, growth_rate (1/s or null)}."),
        ("radius_source, radius_part", "where the radius came from: '--radius', 'rim_radius' "
         "(the body file's) or 'largest_round_part', then radius_part is that part's name."),
        ("tyre_radius, g", "m and m/s^2 as used."),
        ("rim, tyre_radius_source", "what touches the floor: edge, torus, sphere or band; where "
         "r came from: '--tyre-radius', 'shape' (a torus's tube, a sphere's radius) or "
         "'knife_edge' (0)."),
        ("band_width, band_edges, static_lean_limit_deg, knife_edge_critical_spin, knife_edge_critical_speed",
         "a flat band only: its width (m), its edges' distances c1, c2 from the centre of mass's "
         "plane (m), the lean below which its weight holds it up (degrees), and the knife edge "
         "at the centre of mass's plane for comparison (rad/s, m/s)."),
        ("I_contact, Is_contact", "I + m a^2 and Is + m a^2, about the contact point, kg m^2."),
        ("spin, lean_frequency, lean_frequency_hz, growth_rate, lean_frequency_squared, backwards",
         "with a speed: the spin (rad/s), nu (rad/s) and nu/(2 pi) (Hz) when stable, else null; "
         "the growth rate (1/s) when unstable, else null; nu^2 (rad^2/s^2); whether the speed "
         "was negative."),
        ("axle, axle_through, com", "[3] unit axle, a point of the axle line and the centre "
         "of mass, body frame, m."),
        ("asymmetry", "only for a nearly symmetric wheel: {transverse_moments [I1, I2] about "
         "the centre of mass (kg m^2), relative (I2 - I1)/mean, coupling (kg m^2), "
         "coupling_relative, principal_axis_tilt (rad), com_offset (m, from the axle line), "
         "com_offset_relative (of the rim radius), tolerance}; as top's."),
        ("model, warnings, name, file", "the model's one-line description; the warnings also "
         "printed on standard error (a list, [] when none); the body's name and source."),
    ],
    "examples": [
        ("rbcli rollcheck examples/penny.yaml",
         "A US cent (thin disk, a = 9.525 mm): critical speed 0.176454 m/s (17.6 cm/s)."),
        ("rbcli rollcheck examples/bicycle_wheel.yaml --speed '5 km/h'",
         "A bicycle wheel as a hoop of radius 0.35 m: critical speed 0.926327 m/s; at 5 km/h "
         "stable with margin 1.49935."),
        ("rbcli rollcheck examples/penny.yaml --speed 0.1 --json | jq .stable",
         "false, and exit status 1: a penny rolling at 10 cm/s falls over."),
        ("rbcli rollcheck examples/hoop.yaml --lean 20 --circle 1",
         "Steady circular rolling of a hoop leaning 20 degrees on a 1 m circle."),
        ("rbcli rollcheck examples/spoked_wheel.yaml --plot margin.svg",
         "The spoked wheel (its tyre a torus of tube radius 12.5 mm): critical speed 1.01418 m/s, "
         "and a plot of the lean frequency against speed."),
        ("rbcli rollcheck -e '{units: {length: mm}, shape: sphere, radius: 50, mass: 0.4}'",
         "A ball: critical speed 0, it stays up at any speed."),
        ("rbcli rollcheck -e '{units: {length: mm}, shape: cylinder, radius: 50, length: 100, mass: 0.4}'",
         "A can on its side: its band holds it up for leans below 45 degrees; balanced on an edge it "
         "needs 0.713105 m/s (the knife-edge idealisation says 0.617551)."),
        ("rbcli rollcheck examples/car_wheel.yaml",
         "A disk tilted 0.5° on its axle: products of inertia 0.87 % of the moment across, within "
         "the default --symmetry-tol of 1 %; answered for the symmetrised wheel (critical speed "
         "0.8086 m/s) with a warning and the JSON key asymmetry."),
        ("rbcli rollcheck examples/car_wheel.yaml --symmetry-tol 0.5%",
         "Refused, exit status 2: the axle is not a principal axis (0.87 % of the moment across, "
         "the nearest principal axis 0.5° away), beyond 0.5 %."),
        ("rbcli rollcheck examples/toy_top.yaml",
         "Refused, exit status 2: the cone's base rim is 8.48 mm (28.3 % of its radius) from the "
         "centre of mass along the axle, so upright rolling is not an equilibrium."),
    ],
}
