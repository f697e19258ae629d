"""``rbcli rollcheck``: when does a rolling wheel, coin or hoop stay up?"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import typer

from rbcli.cli import common as c
from rbcli.cli.app import MANUAL, app

HELP = """Stability of a wheel, disk or hoop rolling on a rough floor: the critical speed.

The body must be a body of revolution about its axle (--axle, default the body's
shaft, else body z) with its centre of mass on the axle. It rolls without slipping
on its rim, radius a (--radius, default the body's rim_radius, else the largest
round part coaxial with the axle; the output says which). Straight upright rolling
is stable (neutrally: undamped, a small lean oscillates) when the spin s satisfies
s^2 > m g (a - r) I / (Is (Is + m a^2)), I across the axle and Is about it, both
about the centre; r is the tube radius of a rounded rim (--tyre-radius, 0 = knife
edge). At --speed or --spin: the verdict, the margin (speed over critical) and the
lean oscillation frequency or growth rate. With two of --lean, --circle, --speed:
steady circular rolling (turn rate, spin, speed, stable or not). Exit status 1 when
the motion asked about is unstable.
"""

RADIUS_HELP = (
    "Rim radius a, centre to floor when upright (m, or with units). Default: the body's "
    "rim_radius, else the largest round part (ring, disk, cylinder, torus, ...) coaxial "
    "with the axle."
)


@app.command(help=HELP)
def rollcheck(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    axle: str = typer.Option(None, "--axle", help="Axle direction x,y,z (or x, y, z) in the body frame. Default: the body's shaft axis, else z.", show_default=False),
    through: str = typer.Option(None, "--through", help="A point of the axle line: com, origin or x,y,z (m; a unit after the last number applies to all, e.g. '0,0,5 mm'). Default: the body's shaft point, else the origin.", show_default=False),
    radius: str = typer.Option(None, "--radius", help=RADIUS_HELP, show_default=False),
    tyre_radius: str = typer.Option("0", "--tyre-radius", help="Tube radius r of a rounded rim (m, or with units); 0 = knife edge."),
    g: str = typer.Option("9.80665", "--g", help="Gravity (m/s^2, or with units, e.g. '1 g0')."),
    speed: str = typer.Option(None, "--speed", help="Speed of the centre (m/s, or e.g. '20 km/h'); negative = backwards.", show_default=False),
    spin: str = typer.Option(None, "--spin", help="Spin about the axle (rad/s, or e.g. '300 rpm'); speed = a x spin.", show_default=False),
    lean: str = typer.Option(None, "--lean", help="Steady circle: inward lean from the vertical (degrees, or with units), 0 to <90.", show_default=False),
    circle: str = typer.Option(None, "--circle", help="Steady circle: radius of the circle the centre runs on (m, or with units); 0 = spinning in place.", show_default=False),
    plot: str = typer.Option(None, "--plot", help="Save a figure (.png, .svg, .pdf): lean frequency squared and growth rate against speed; with a circle, also the stable region in the (lean, circle radius) plane. An existing figure is replaced (atomically); an input file never.", show_default=False),
    json_: bool = c.JsonOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.errors import InputError
    from rbcli.render.fmt import DisplayUnits

    e = c.env()
    du = DisplayUnits.parse(units)
    # --- option values (checked before the body is read: bad usage is bad usage)
    n_axle = c.direction(axle, "--axle") if axle is not None else None
    p_through = c.point(through, "--through") if through is not None else None
    a_opt = c.positive(c.quantity(radius, "length", "--radius"), "--radius", "the rim radius") if radius is not None else None
    r = c.quantity(tyre_radius, "length", "--tyre-radius")
    if not r >= 0.0 or r != r or r == float("inf"):
        raise InputError(f"--tyre-radius: must be 0 (knife edge) or a positive length, got {tyre_radius}")
    gv = c.positive(c.quantity(g, "acceleration", "--g"), "--g", "gravity")
    v = c.finite(c.quantity(speed, "speed", "--speed"), "--speed") if speed is not None else None
    s = c.finite(c.quantity(spin, "angular_speed", "--spin"), "--spin") if spin is not None else None
    beta = None
    if lean is not None:
        import math

        beta = c.quantity(lean, "angle", "--lean", bare="deg")
        if not (0.0 <= beta < 0.5 * math.pi):
            raise InputError(
                f"--lean: the inward lean from the vertical must be from 0 up to (not including) "
                f"90 degrees, got {lean}"
            )
    R_G = None
    if circle is not None:
        R_G = c.quantity(circle, "length", "--circle")
        if not (R_G >= 0.0 and R_G != float("inf")):
            raise InputError(f"--circle: the circle radius must be 0 (spinning in place) or positive, got {circle}")
    asked_speed = v is not None or s is not None
    if (beta is None) != (R_G is None) and not asked_speed:
        have, need = ("--lean", "--circle") if beta is not None else ("--circle", "--lean")
        raise InputError(
            f"{have}: a steady circle needs two of --lean, --circle and --speed (or --spin); "
            f"add {need} or --speed"
        )
    if R_G is not None and R_G == 0.0 and beta is None and asked_speed:
        raise InputError(
            "--circle 0: spinning in place the centre does not move, so --speed cannot fix the "
            "lean; give --lean instead"
        )

    b = c.load_one(body, expr, e)
    plot_path = None
    if plot is not None:
        plot_path = c.check_plot(plot, b)

    setup = prepare(b, axle=n_axle, through=p_through, radius=a_opt, tyre_radius=r)
    for w in setup.warnings:
        e.warn(f"rbcli: {w}")
    if beta is not None or R_G is not None:
        if r != 0.0:
            raise InputError(
                "--tyre-radius: steady circular rolling (--lean/--circle) is computed for a "
                "knife-edge rim only (tyre radius 0); the straight-rolling threshold takes a "
                "rounded rim"
            )
    from rbcli.core import rolling as rl

    try:
        res = rl.rollcheck(setup.wheel, setup.radius, r, gv, speed=v, spin=s, lean_rad=beta, circle_radius=R_G)
    except ValueError as exc:
        which = _option_for(str(exc), beta, R_G, v, s)
        raise InputError(f"{which}: {exc}") from None

    # which verdicts the user asked for (SPEC §4: exit 1 when one is unstable)
    straight_asked = res.verdict is not None and (res.circle is None or (beta is not None and R_G is not None))
    circle_asked = res.circle is not None
    failed = (straight_asked and not res.verdict.stable) or (circle_asked and not res.circle.stable)

    from rbcli.render import rollcheck as rr

    info = rr.Info(
        body=b,
        radius_source=setup.radius_source,
        radius_kind=setup.radius_kind,
        radius_part=setup.radius_part,
        axle_source=setup.axle_source,
        axle_through=setup.through,
        speed_given=v is not None,
        spin_given=s is not None,
        lean_given=beta is not None,
        circle_given=R_G is not None,
        straight_asked=straight_asked,
        circle_asked=circle_asked,
    )
    if plot_path is not None:
        c.save_plot(rr.plot(res, info), plot_path)
    def tables(doc) -> None:
        rr.document(doc, res, info, du, digits)
        if plot_path is not None:
            doc.note(f"plot written to {plot_path}")

    c.emit(e, json_, lambda: rr.to_json(res, info), tables)
    c.finish(1 if failed else 0)


def _option_for(msg: str, beta, R_G, v, s) -> str:
    """The options a core error is about, for the one-line message."""
    if "disagree" in msg:
        return "--speed, --spin"
    given = [o for o, x in (("--lean", beta), ("--circle", R_G), ("--speed", v), ("--spin", s)) if x is not None]
    return ", ".join(given) or "rollcheck"


@dataclass(frozen=True)
class Setup:
    """The wheel of a body and where its axle and rim radius came from (:func:`prepare`).

    wheel : core.rolling.Wheel — A, C about the com, the axle
    radius : float — m, the rim radius a
    radius_source : str — where a came from, in words
    radius_kind : str — "--radius", "rim_radius" or "largest_round_part"
    radius_part : str | None — the part's name for "largest_round_part"
    axle_source : str — where the axle and its point came from, in words
    through : (3,) ndarray — m, the point of the axle line
    warnings : tuple[str, ...] — for standard error (without the "rbcli: " prefix)
    """

    wheel: Any
    radius: float
    radius_source: str
    radius_kind: str
    radius_part: str | None
    axle_source: str
    through: Any
    warnings: tuple[str, ...] = ()


def prepare(body, *, axle=None, through=None, radius=None, tyre_radius: float = 0.0) -> Setup:
    """The rolling wheel of a body, its rim radius and where each came from; shared with report.

    ``axle`` a direction (default the body's shaft, else body z), ``through`` "com",
    "origin" or [x, y, z] (m; default the body's shaft point, else the origin), ``radius``
    the rim radius (m; default the body's rim_radius, else the largest round part coaxial
    with the axle), ``tyre_radius`` (m), which must be smaller than the rim radius. A body
    that cannot roll, or a tyre as large as the rim, is an InputError (exit 2). Warnings
    (without the "rbcli: " prefix) are in the result's ``warnings``.
    """
    setup = _setup(body, axle, through, radius)
    if tyre_radius >= setup.radius:
        from rbcli.errors import InputError

        raise InputError(
            f"--tyre-radius: the tyre radius {tyre_radius:.6g} m must be smaller than the rim radius "
            f"a = {setup.radius:.6g} m ({setup.radius_source})"
        )
    return setup


def _setup(body, n_axle, p_through, a_opt) -> Setup:
    """Axle line, rim radius and the Wheel (A, C about the com) of a body."""
    import numpy as np

    from rbcli.core.inertia import combine
    from rbcli.core.rolling import wheel_from_body
    from rbcli.errors import InputError

    mp = combine(body.parts)
    if n_axle is not None:
        n = np.asarray(n_axle, dtype=float)
        axle_source = "--axle"
    elif body.shaft is not None:
        n = np.asarray(body.shaft.axis, dtype=float)
        axle_source = "the body's shaft"
    else:
        n = np.array([0.0, 0.0, 1.0])
        axle_source = "body z (default)"
    n = n / np.linalg.norm(n)
    if isinstance(p_through, str):
        P = mp.com.copy() if p_through == "com" else np.zeros(3)
        through_source = f"--through {p_through}"
    elif p_through is not None:
        P = np.asarray(p_through, dtype=float)
        through_source = "--through"
    elif body.shaft is not None:
        P = np.asarray(body.shaft.through, dtype=float)
        through_source = "the body's shaft"
    else:
        P = np.zeros(3)
        through_source = "the origin"
    part = None
    warnings: list[str] = []
    if a_opt is not None:
        a, source, kind = a_opt, "--radius", "--radius"
    elif body.rim_radius is not None:
        a, source, kind = float(body.rim_radius), "the body's rim_radius", "rim_radius"
    else:
        a, source, part = _largest_round_part(body, n, P)
        kind = "largest_round_part"
        rim = next(p for p in body.parts if p.name == part)
        dz = float(np.dot(np.asarray(rim.com, dtype=float) - mp.com, n))
        if abs(dz) > 1e-6 * a:
            warnings.append(
                f"{body.source}: the rim part '{part}' is centred {abs(dz):.6g} m from the "
                "centre of mass along the axle; the model takes the rim circle in the plane of the "
                "centre of mass"
            )
    try:
        wheel = wheel_from_body(mp.mass, mp.com, mp.inertia_com, n, axle_through=P, radius=a)
    except ValueError as exc:
        raise InputError(f"{body.source}: {exc}") from None
    return Setup(wheel, float(a), source, kind, part, f"{axle_source}, through {through_source}", P,
                 tuple(warnings))


def _largest_round_part(body, n, P) -> tuple[float, str, str]:
    """The largest outer radius of the round, non-subtracted parts coaxial with the axle."""
    import numpy as np

    from rbcli.core.shapes import SHAPES
    from rbcli.errors import InputError

    best = None
    for p in body.parts:
        # p.radius is the outer radius of a round shape (None for the others: core.shapes)
        if p.subtract or p.radius is None:
            continue
        if SHAPES[p.shape].round != "any" and abs(abs(float(np.dot(p.axis, n))) - 1.0) > 1e-9:
            continue  # round about another axis: not a rim for this axle
        d = np.asarray(p.com, dtype=float) - P
        off = float(np.linalg.norm(d - np.dot(d, n) * n))
        if off > 1e-6 * p.radius:
            continue  # not centred on the axle line
        if best is None or p.radius > best.radius:
            best = p
    if best is None:
        from rbcli.core.inertia import combine
        from rbcli.core.rolling import wheel_from_body

        mp = combine(body.parts)
        try:  # a body that cannot roll at all says so first (not of revolution, com off the axle)
            wheel_from_body(mp.mass, mp.com, mp.inertia_com, n, axle_through=P)
        except ValueError as exc:
            raise InputError(f"{body.source}: {exc}") from None
        raise InputError(
            f"{body.source}: no rim radius: give --radius, or rim_radius in the body file (no "
            "round part — ring, disk, cylinder, torus, sphere, ... — is centred on the axle and "
            "coaxial with it)"
        )
    return (float(best.radius), f"the largest round part '{best.name}' ({best.shape}, coaxial with the axle)",
            best.name)


MANUAL["rollcheck"] = {
    "notes": [
        "Model (physics notes dynamics.md §3): a rigid body of revolution rolls without "
        "slipping, pivot friction or rolling resistance on a horizontal floor, touching it on "
        "a circle of radius a in its mid-plane (a knife edge) or, with --tyre-radius r, on a "
        "toroidal rim of tube radius r. I (= A) is the moment across the axle and Is (= C) the "
        "moment about it, both about the centre of mass; Is + m a^2 is the axial moment about "
        "the contact point, which is where the condition's mixed product comes from. Energy is "
        "conserved, so 'stable' means neutrally stable (undamped): a small lean oscillates at "
        "the lean frequency nu, nu^2 = [Is (Is + m a^2) s^2 - I m g (a - r)] / [I (I + m a^2)], "
        "and does not decay; 'unstable' means it grows at sqrt(-nu^2). Exactly at the critical "
        "speed the verdict is unstable. Thin disk: v_c = sqrt(g a/3); hoop: v_c = sqrt(g a/4).",
        "The axle is --axle, else the body's shaft axis, else body z; it passes through "
        "--through, else the body's shaft point, else the origin. The body must be of "
        "revolution about it (the two moments across the axle equal to a relative 1e-6, the "
        "axle a principal axis) and its centre of mass must be on it (to 1e-6 of the rim "
        "radius); otherwise rbcli says by how much and exits 2. The rim radius is --radius, "
        "else the body's rim_radius, else the largest outer radius of the round parts (ring, "
        "disk, cylinder, torus, sphere, hemisphere, cone; not holes) centred on and coaxial "
        "with the axle; the output says which.",
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
         "(m/s), whether straight rolling at it is stable, and |speed| / critical_speed."),
        ("circle", "with --lean/--circle: {lean_deg, radius (of the centre's circle, m), "
         "turn_rate (rad/s), spin (rad/s), speed (m/s), stable, contact_radius (m), kappa (N m), "
         "lean_frequency (rad/s or null), lean_frequency_hz, growth_rate (1/s or null)}."),
        ("radius_source, radius_part", "where the radius came from: '--radius', 'rim_radius' "
         "(the body file's) or 'largest_round_part', then radius_part is that part's name."),
        ("tyre_radius, g", "m and m/s^2 as used."),
        ("I_contact, Is_contact", "I + m a^2 and Is + m a^2, about the contact point, kg m^2."),
        ("spin, lean_frequency, lean_frequency_hz, growth_rate, lean_frequency_squared, backwards",
         "with a speed: the spin (rad/s), nu (rad/s) and nu/(2 pi) (Hz) when stable, else null; "
         "the growth rate (1/s) when unstable, else null; nu^2 (rad^2/s^2); whether the speed "
         "was negative."),
        ("axle, axle_through, com", "[3] unit axle, a point of the axle line and the centre "
         "of mass, body frame, m."),
        ("model, name, file", "the model's one-line description; the body's name and source."),
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
         "The spoked wheel's threshold and a plot of the lean frequency against speed."),
    ],
}
