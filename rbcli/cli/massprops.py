"""``rbcli inertia`` and ``rbcli principal``."""

from __future__ import annotations

import typer

from rbcli.api.commands import INERTIA, PRINCIPAL
from rbcli.cli import common as c
from rbcli.cli.app import MANUAL
from rbcli.errors import InputError, option_name

INERTIA_HELP = """Mass, centre of mass and the inertia tensor about a point.

The tensor is about --about (default: the body's `reference`, else the origin) and
about the com. With --axis n, the moment of inertia I = n.J.n about the axis n
through that point; with --omega w, the angular momentum L = J.w, the angle
between L and w, and the kinetic energy T = w.J.w/2. Several bodies at once: with
--json, one JSON object per line (JSON Lines), each with a "file" key.
"""

PRINCIPAL_HELP = """Principal moments and axes, symmetry, and which free rotations are stable.

Moments ascending; row i of "axes" is the unit axis of moment i (body frame), a
right-handed set whose signs make the rotation from body to principal axes the
smallest one (a body tilted 0.5 degrees reads 0.5 degrees). Where moments coincide
the free axes are said and chosen along the body axes where possible. Also the
direction angles, the rotation from body to principal axes and the equivalent
uniform box and ellipsoid.
"""


#: the robot-description formats of ``inertia --format`` (rbcli.render.robot)
ROBOT_FORMATS = ("urdf", "sdf", "mjcf")

INERTIA_FORMAT_HELP = (
    "Output: table (for people), json (= --json), csv (the JSON as one table for spreadsheets), or the "
    "body's <inertial> element for a robot model: urdf, sdf or mjcf (about the com, SI, full "
    "precision; the frame is stated in a comment).")


@c.command(INERTIA, help=INERTIA_HELP)
def inertia(
    bodies: list[str] = c.BodiesArg,
    expr: str = c.ExprOpt,
    args: dict = c.PARAMS,
    products: str = typer.Option("tensor", "--products", help="Show off-diagonals as the tensor (tensor) or as positive products (positive), in the tables; --format urdf, sdf and mjcf fix the tensor's sign (positive is refused there)."),
    json_: bool = c.JsonOpt,
    fmt: str = typer.Option(None, "--format", metavar="table|json|csv|urdf|sdf|mjcf", help=INERTIA_FORMAT_HELP, show_default=False),
    principal_: bool = typer.Option(False, "--principal", help="With --format urdf|sdf|mjcf: the principal moments and the principal axes' orientation instead of the full tensor in body axes."),
    each: bool = typer.Option(False, "--each", help="With --format urdf|sdf|mjcf: one <link> per part up to its first '/' (a STEP file's top-level solid or sub-assembly)."),
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.api import inertia as api
    from rbcli.api.options import choice
    from rbcli.render import echo, robot
    from rbcli.render import massprops as r
    from rbcli.render.units import DisplayUnits

    choice(products, "--products", ("tensor", "positive"))
    out = c.output_format(json_, fmt, ROBOT_FORMATS)
    if out in ROBOT_FORMATS:
        if products.strip().lower() == "positive":
            raise InputError(f"--products positive does not apply to --format {out}: the element "
                             "holds the tensor's entries (ixy = -sum m x y), as the format requires")
        given = [option_name(k) for k, v in c.without_body(args).items() if v is not None]
        given += ["--units"] * (units is not None)
        if given:
            raise InputError(f"{given[0]} does not apply to --format {out}: the <inertial> element is "
                             "always about the centre of mass, in SI units")
    elif principal_ or each:
        raise InputError(f"{'--principal' if principal_ else '--each'} applies to --format urdf, "
                         f"sdf or mjcf, not to {out}")
    e = c.env()
    du = DisplayUnits.parse(units)
    api.parse(None, **args)  # bad values: one line, before any body

    def one(body, many: bool, first: bool) -> None:
        opts = api.parse(body, **args)
        res = api.run(body, opts)
        _warn(e, body, res)
        if out in ROBOT_FORMATS:
            res.to_json()  # the one finiteness check of the numbers
            e.write(robot.links(out, body.name, body.source, api.links(body, principal_)) if each
                    else robot.render(out, body.name, body.source, res.inertial(principal_)))
            return
        c.emit(e, out, lambda: c.with_file(res.to_json(), body.source),
               lambda doc: r.inertia_doc(doc, body, res, du, digits, products, res.reference_label),
               lines=many, file=body.source if many else None,
               given=lambda: echo.echo_rows(opts, body.units), plain=True, header=first)

    _each(bodies, expr, e, one)


def _warn(e, body, res) -> None:
    for w in res.warnings:
        e.warn(f"rbcli: {body.source}: warning: {c.said(w)}")


def _each(bodies, expr, e, one) -> None:
    """Run ``one(body, many, first)`` per body; go on past bad files, exit 2 at the end if any
    failed.

    ``many``: more than one body named (JSON Lines, one CSV table); ``first``: the first
    body printed (the CSV's header comes with it).
    """
    srcs = c.sources(bodies, expr)
    many = len(srcs) > 1
    failed = False
    done = 0
    for src, body in c.each_body(srcs, expr, e):
        if e.pipe_closed:  # the reader has gone (| head -1): nobody reads the rest
            break
        try:
            if isinstance(body, InputError):
                raise body
            one(body, many, done == 0)
            done += 1
        except InputError as exc:
            if len(srcs) == 1:
                raise
            e.warn(f"rbcli: {c.said(exc)}" if exc is body else f"rbcli: {src}: {c.said(exc)}")
            failed = True
    if failed:
        c.finish(2)


@c.command(PRINCIPAL, help=PRINCIPAL_HELP)
def principal(
    bodies: list[str] = c.BodiesArg,
    expr: str = c.ExprOpt,
    args: dict = c.PARAMS,
    plot: str = typer.Option(None, "--plot", help="Draw the body as built (its parts, holes dashed), the com and the principal axes about the com, in a 3-D view and three views along the body axes, to this file (.png, .svg or .pdf). One body only.", show_default=False),
    json_: bool = c.JsonOpt,
    fmt: str = c.FormatOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.api import principal as api
    from rbcli.render import echo
    from rbcli.render import massprops as r
    from rbcli.render.bodyplot import body_figure

    e, out, du = c.start(json_, fmt, units)
    api.parse(None, **args)  # a bad --about: one line, before any body
    if plot is not None:
        c.sources(bodies, expr, single=True)  # one figure, one body

    def one(body, many: bool, first: bool) -> None:
        plot_path = c.check_plot(plot, body) if plot is not None else None
        opts = api.parse(body, **args)
        res = api.run(body, opts)
        _warn(e, body, res)
        if plot_path is not None:
            at_com = res if opts.about == "com" else api.principal(body, about="com")
            c.save_plot(body_figure(body, at_com.reference, at_com, du, f"principal: {body.name} — "
                                    "the body as built, centre of mass and principal axes"), plot_path)
        c.emit(e, out, lambda: c.with_file(res.to_json(), body.source),
               lambda doc: r.principal_doc(doc, body, res, du, digits, res.reference_label),
               lines=many, file=body.source if many else None,
               given=lambda: echo.echo_rows(opts, body.units), plain=True, header=first)

    _each(bodies, expr, e, one)


MANUAL["inertia"] = {
    "notes": [
        "The inertia tensor is the tensor: its off-diagonal entries are the negated products "
        "(Ixy = -sum m x y). --products positive shows the positive engineering products "
        "instead, and says so. Tables use six significant figures (--digits) and the body "
        "file's units (SI without units:) unless --units is given; JSON is always SI with full "
        "precision.",
        "--format table (default), json (the same as --json) or csv (the JSON as one table, "
        "quantity,value,text,unit, one row per value; several bodies add a file column; layout "
        "in rbcli(1)).",
        "The parts table lists at most 100 parts (PARTS_TABLE_ROWS): a body of more shows the "
        "100 heaviest, in file order, and one row that sums the others (their mass and centre "
        "of mass; a mesh's volume, area and triangles), and says so under it. --json and "
        "--format csv list every part.",
        "--format urdf, sdf or mjcf prints the body's <inertial> element for a robot or "
        "simulation model, after a comment that states its frame: the link frame is the body "
        "frame; the position is the centre of mass (m); the inertia is about the centre of "
        "mass, in kg m^2, at full precision (each number reads back to the same double). By "
        "default it is the tensor in body axes (URDF and SDF ixy, ixz, iyz are the tensor's "
        "entries, -sum m x y; MJCF fullinertia=\"ixx iyy izz ixy ixz iyz\") with no rotation. "
        "With --principal it is the principal moments (ascending, as rbcli principal) and the "
        "orientation of the principal axes: URDF <origin rpy> and SDF <pose> as fixed-axis "
        "roll, pitch, yaw in rad (R = Rz(yaw) Ry(pitch) Rx(roll)), MJCF quat=\"w x y z\" with "
        "diaginertia. Every comment states the off-diagonals' sign. --about, --axis, --omega, "
        "--units and --products positive do not apply to these formats (exit 2: they fix "
        "the tensor's sign). Several bodies: one element per body, one after another.",
        "--each (urdf, sdf, mjcf): one <link> (MJCF <body>) per part up to its first '/' (a "
        "STEP file's top-level solid or sub-assembly), each in the body frame.",
    ],
    "json": [
        ("mass", "total mass, kg."),
        ("com", "[3] centre of mass, m, body frame."),
        ("reference", "[3] the point the inertia is about, m."),
        ("inertia", "[3x3] inertia tensor about reference, kg m^2 (off-diagonals -sum m x y)."),
        ("inertia_com", "[3x3] inertia tensor about the com, kg m^2."),
        ("axis, axis_moment", "with --axis: the unit axis [3] and n.J.n about it through reference, kg m^2."),
        ("omega, angular_momentum, kinetic_energy, angle_L_omega_deg",
         "with --omega: w [3] rad/s, L = J.w [3] kg m^2/s, T = w.J.w/2 J, and the angle between L and w in degrees."),
        ("name, file", "the body's name and where it was read from."),
        ("parts", "[{name, shape, mass, com}] each part's contribution (mass negative for a "
                  "subtracted part; mesh parts add volume m^3, area m^2 and triangles; STEP "
                  "solids their unit and colour)."),
    ],
    "examples": [
        ("rbcli inertia examples/square_lamina.yaml --axis 1,1,0",
         "The square lamina of mass 1 kg and side 1 m about its corner: I about the diagonal is 0.0833333 kg m^2 (m a^2/12)."),
        ("rbcli inertia -e '{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}' --json",
         "A box written inline; JSON for scripts."),
        ("rbcli inertia examples/*.yaml --json | jq .mass",
         "Several bodies at once: one JSON object per line."),
        ("rbcli inertia examples/bracket.yaml --format urdf",
         "The <inertial> element of a URDF link whose frame is the body frame."),
        ("rbcli inertia examples/two_blade_fan.yaml --format mjcf --principal",
         "MuJoCo: pos, quat (w x y z) of the principal axes and diaginertia (0.00666667, 0.0266667, 0.0333333)."),
    ],
}

MANUAL["principal"] = {
    "notes": [
        "Free rotation about the axes of the largest and the smallest principal moment is "
        "stable, about the intermediate one unstable (the tennis-racket flip); for a symmetric "
        "body, stable about its symmetry axis and neutral about the others. The equivalent "
        "uniform box and ellipsoid have the same mass and principal moments.",
        "The mesh parts table lists at most 100 mesh parts (PARTS_TABLE_ROWS): beyond that the "
        "100 largest by volume and one row that sums the others. --plot draws the 500 heaviest "
        "parts by their outline and the next 2000 as dots at their centres; the legend's title "
        "says how many lighter parts are left out.",
        "Tilts: each principal axis's angle from its nearest body axis (a rod turned 0.5 degrees "
        "reads 0.5 degrees). The moments are listed in ascending order, so the rotation taking the "
        "body axes to principal axes 1, 2, 3 may be about 90 degrees for a body tilted a little; "
        "it is printed too, labelled so.",
        "Signs of the axes: of the sign choices that keep the axes right-handed, the one "
        "whose rotation from the body axes is smallest (largest trace of the axes matrix), so "
        "a flywheel tilted 0.5 degrees has its axis 3 along +z tilted 0.5 degrees, and the "
        "rotation reads 0.5 degrees when the ascending order keeps each axis on its own body axis. "
        "Where moments coincide, the free axes are also ordered "
        "this way. Exact ties keep the first two axes with their largest component positive.",
    ],
    "json": [
        ("reference", "[3] the point the moments are about, m."),
        ("moments", "[3] principal moments, ascending, kg m^2."),
        ("axes", "[3x3] row i is the unit axis of moment i in the body frame; a right-handed set "
                 "(a rotation matrix) with the signs that make it the rotation nearest the body frame."),
        ("symmetry", "asymmetric, symmetric or spherical."),
        ("stable", "[3] whether free rotation about each axis is stable (false for a neutral axis)."),
        ("stability", "[3] stable, unstable or neutral: neutral about an axis of the equal pair of a "
                      "symmetric body (the spin axis wanders round the symmetry axis)."),
        ("tilt_deg, tilt_axis", "[3] each principal axis's angle from its nearest body axis, degrees, "
                                "and that axis (x, y or z): the tilt of a body near its body axes."),
        ("free_axes", "axes (1-based) that are free to choose where moments coincide."),
        ("direction_angles_deg", "[3x3] angle of principal axis i from body axis j."),
        ("rotation_axis, rotation_angle_deg", "the rotation taking the body axes onto the principal "
                                              "axes 1, 2, 3 in ascending order (about 90 degrees or more "
                                              "when that order permutes the body axes)."),
        ("equivalent_box, equivalent_ellipsoid", "[3] box sides and ellipsoid semi-axes along the principal axes, m."),
        ("mass, name, file", "the body's mass (kg), name and source."),
        ("parts", "[{name, shape, mass, com}] each part's contribution, as in inertia (mesh parts "
                  "add volume m^3, area m^2 and triangles)."),
    ],
    "examples": [
        ("rbcli principal examples/square_lamina.yaml --about origin",
         "Principal axes of the lamina about its corner: along the diagonal (m a^2/12) and across it (7 m a^2/12)."),
        ("rbcli principal examples/two_disk_rotor.yaml --plot rotor.png",
         "The rotor as built: the shaft, disks and point masses in three views and in 3-D, with the "
         "centre of mass and the principal axes about it (README shows it)."),
        ("rbcli principal examples/two_blade_fan.yaml",
         "The two-blade fan: principal axes at 45 degrees (tan 2 theta = 2 Ixy/(Ixx - Iyy))."),
    ],
}
