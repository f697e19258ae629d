"""``rbcli whirl``: the rotor on its bearings — critical speeds, Campbell diagram, unbalance
response and separation margins."""

from __future__ import annotations

import typer

from rbcli.api.commands import WHIRL
from rbcli.cli import common as c
from rbcli.cli.app import MANUAL, app

HELP = """The rotor on its bearings: critical speeds, Campbell diagram, unbalance response.

The body is a rigid rotor (its mass, centre of mass, and its moments about the centre of
mass: Ip about the shaft, It across it) on two or more linear spring-damper bearings at
--bearings z1,z2[,...] along the shaft (--shaft through --through, as for balance), each
with --stiffness (N/m; one value for every bearing or one per bearing; --stiffness-y for
the y direction, --cross-stiffness for kxy = -kyx) and optional --damping (N s/m). Four
degrees of freedom: the two translations and two tilts of the shaft axis at the centre of
mass, coupled by the gyroscopic moment Ip Omega. Gravity is left out of the linear modes.

Over --speed-range a,b (e.g. '0,6000 rpm'; default 0 to 1.25 times the highest critical
speed or operating speed) in --points speeds: the whirl frequencies (fixed frame) with
forward/backward labels, each mode's kind (cylindrical, conical or mixed, with the node
along the shaft), damping ratio and logarithmic decrement, and the stability (a growing
mode is said in capitals). The critical speeds of --orders (default 1; '1,2' adds 2x)
come from an exact eigenproblem in the speed (undamped) and a root solve (damped), and a
branch that never meets its line is explained (Ip > It: the forward conical whirl of a
disk-like rotor never reaches 1x).

The unbalance response (bearing displacement and force, amplitude and phase, against
speed) is to the body's own static and couple unbalance (what balance computes) or to
--unbalance U1@angle1,... in --unbalance-planes z1,...; its peaks give the amplification
factor AF by the half-power method. With --speed (the operating speed, or min,max of the
operating range) each peak is judged by the API 617 / API 684 separation-margin rule
(required margin from AF); exit status 1 when one fails or a mode grows at that speed.
--plot FILE draws the Campbell diagram and --plot-response FILE the response.

A bare number means what it would mean in the body file: positions in the body's length
unit (metres without units:), speeds in rad/s unless its units name an angular_speed;
stiffness is N/m and damping N s/m unless a unit is given ('200 N/mm'). Whirl frequencies
are in the fixed frame; forward whirl turns the same way as the spin.
"""

@c.command(WHIRL, help=HELP)
def whirl(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    args: dict = c.PARAMS,
    plot: str = typer.Option(None, "--plot", help="Write the Campbell diagram (png, svg or pdf): whirl frequencies against speed, forward solid, backward dashed, the n× lines and the critical speeds.", show_default=False),
    plot_response: str = typer.Option(None, "--plot-response", help="Write the unbalance response (png, svg or pdf): each bearing's displacement amplitude and phase against speed, peaks and half-power points marked.", show_default=False),
    json_: bool = c.JsonOpt,
    fmt: str = c.FormatOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.api import whirl as api
    from rbcli.io import outfile
    from rbcli.render import whirl as rw

    e, out, du = c.start(json_, fmt, units)
    b = c.load_one(body, expr, e)
    o = api.parse(b, **args)
    plot_path = c.check_plot(plot, b) if plot is not None else None
    resp_path = None
    if plot_response is not None:
        resp_path = outfile.check(plot_response, b, "--plot-response", exts=c.PLOT_FORMATS,
                                  replace_ok=True, others={"--plot": plot_path})
    res = api.run(b, o)
    if plot_path is not None:
        c.save_plot(rw.campbell_figure(res), plot_path)
    if resp_path is not None:
        c.save_plot(rw.response_figure(res), resp_path, "--plot-response")

    def tables(doc) -> None:
        rw.document(doc, res, du, digits)
        for opt, path in (("--plot", plot_path), ("--plot-response", resp_path)):
            if path is not None:
                doc.note(f"{opt}: figure written to {path}")

    c.emit(e, out, lambda: {**res.to_json(), "file": b.source}, tables)
    for w in res.warnings:  # after the output: a result that cannot be printed says only that
        e.warn(f"rbcli: {b.source}: warning: {c.said(w)}")
    c.finish(res.return_code)


MANUAL["whirl"] = {
    "notes": [
        "Model (physics notes whirl.md): a rigid rotor, mass m, centre of mass at z_G on the "
        "shaft, Ip about the shaft and It across it (about the centre of mass, the mean of the "
        "two moments across), on linear bearings at z_i: F = -K_i d - C_i d' with d the "
        "displacement of the shaft axis there. Coordinates q = (x, y, theta_x, theta_y) of the "
        "axis at the centre of mass; M q'' + (C + Omega G) q' + K q = f with M = diag(m, m, It, "
        "It), K = sum T_i^T K_i T_i (T_i = [[1, 0, 0, a_i], [0, 1, -a_i, 0]], a_i = z_i - z_G) and "
        "the gyroscopic G from Ip Omega (Friswell, Penny, Garvey and Lees, Dynamics of Rotating "
        "Machines, 2010, ch. 3). Gravity sets a static sag and is left out of the linear modes.",
        "The rotor must be symmetric about its shaft within --symmetry-tol (default 1 %): its "
        "two moments across the shaft may differ, and its couple unbalance may be, up to that "
        "fraction of It; within it the answer is for the symmetrised rotor with a warning, "
        "beyond it the rotor is refused (exit 2) with the numbers: an asymmetric rotor's whirl "
        "equations have periodic coefficients. A principal axis tilted from the shaft is said "
        "so; its products of inertia drive the rotor once per revolution (the couple "
        "unbalance) and their effect on the frequencies is neglected.",
        "Modes: the quadratic eigenproblem at each speed through its first-order form. With "
        "isotropic bearings (kxx = kyy, kxy = -kyx, cxx = cyy at every bearing) the complex "
        "coordinates r = x + i y, phi = theta_y - i theta_x give each mode a whirl direction: "
        "forward (the orbit turns with the spin) or backward. With anisotropic bearings the "
        "orbits are ellipses: forward or backward by the larger of the two circular parts "
        "(weighted by m and It), linear when they are equal (a straight-line orbit, e.g. at "
        "rest). Frequencies are in the fixed frame. Modes are numbered by frequency at each "
        "speed. Kind: conical when the outermost bearings move out of phase (a node between "
        "them), cylindrical when in phase with the smaller motion at least half the larger, "
        "mixed in between; the node is where the motion along the shaft is least. Damping "
        "ratio -Re(lambda)/|lambda|, log decrement -2 pi Re(lambda)/Im(lambda); a mode with "
        "Re(lambda) > 1e-9 |lambda| grows: UNSTABLE (the onset speed is found by a root "
        "solve). Undamped without cross-coupling every mode is neutrally stable.",
        "Critical speeds: undamped, exactly, as the eigenvalues of K Q = Omega^2 (n^2 M - i n G) "
        "Q (n the order); symmetric bearings give Omega^2 = sum k/m (cylindrical) and "
        "Omega^2 = sum k a^2 / (It -/+ Ip) (conical, forward/backward). When n It <= Ip the "
        "forward conical branch never meets the n× line (said in words). The damped critical "
        "speed is where the damped whirl frequency meets the line (Brent's method on the mode "
        "followed by its shape); 'excited' says whether the unbalance drives the mode (never a "
        "backward one on isotropic bearings). Rigid-support limit: the critical speeds grow as "
        "the square root of the stiffness; on rigid supports a rigid rotor has none and the "
        "bearing forces are balance's; at the operating speed the table compares the two.",
        "Unbalance response: forcing Omega^2 U e^{i Omega t} on the centre of mass and Omega^2 "
        "P_G e^{i Omega t} about it, U and P_G the body's static and couple unbalance (as "
        "balance gives them) or those of --unbalance in --unbalance-planes. Per bearing: the "
        "orbit's semi-major axis (m; tables in µm) and its phase, the rotor-frame angle of the "
        "high spot when the displacement is largest; the force the rotor exerts on the bearing "
        "(N). Peaks (local maxima over the range, refined by golden-section search) get the "
        "amplification factor AF = Nc/(N2 - N1), N1 and N2 the half-power points (amplitude "
        "peak/sqrt 2, by Brent's method); no damping: the excited critical speeds are infinite "
        "peaks (AF infinite).",
        "Separation margins (with --speed): the rule of API 617 (8th ed.) 6.8.2.4-6.8.2.5 / "
        "API 684 (2nd ed.) SP6.8.2.1, SP6.8.2.10, taken from public implementations (ROSS, "
        "petrobras/ross, ross/api_report.py): AF < 2.5 needs no margin; a critical speed below "
        "the minimum operating speed needs SM = min(16, 17 (1 - 1/(AF - 1.5))) % of it, one above "
        "the maximum operating speed SM = min(26, 10 + 17 (1 - 1/(AF - 1.5))) % of it; an "
        "undamped peak, or one whose half-power points are not separated from the next peak, "
        "is judged as AF infinite (16 % and 26 %). A critical speed inside the operating range "
        "fails unless AF < 2.5. Check the clause against a licensed copy before claiming "
        "conformity. Exit status 1 when a check fails or a mode grows at the operating speed.",
        "Figures: --plot draws the Campbell diagram (speed in rpm, whirl frequency in cpm with "
        "Hz on the right, so the 1× line is the diagonal; forward solid, backward dashed, "
        "straight-line orbits dash-dotted; growing points crossed; critical speeds filled when "
        "the unbalance drives them); --plot-response draws amplitude and phase per bearing "
        "with the peaks and half-power points. The format follows the extension (png, svg, "
        "pdf); no input is ever overwritten.",
    ],
    "json": [
        ("name, conventions", "the body's name; the conventions of every number, in words."),
        ("shaft, shaft_source, through, through_source", "the shaft used and where it came from (shaft, body_shaft, default)."),
        ("rotor", "{mass, com (z_G along the shaft, m), polar_moment, transverse_moment, transverse_moments [2], asymmetry, tilt_deg, eccentricity, static_unbalance (kg m), static_unbalance_angle_deg, couple_unbalance (kg m^2), couple_unbalance_angle_deg}."),
        ("bearings", "[{plane (m), stiffness [kxx, kyy] N/m, cross_stiffness [kxy, kyx] N/m, damping [cxx, cyy] N s/m}]."),
        ("speed_range, speed_range_source, orders, speed, symmetry_tol", "the range (rad/s) and whether it was given or the default; the orders; the operating speed [min, max] rad/s or null."),
        ("modes, modes_speed", "[{frequency (rad/s), whirl, kind, node (m or null), damping_ratio, log_decrement (null if not oscillating), stable}] at modes_speed (the maximum operating speed, else 0)."),
        ("campbell", "{speeds [N] rad/s, frequencies [4][N] rad/s, whirl [4][N], kind [4][N], damping_ratio [4][N], log_decrement [4][N]}: modes numbered by frequency at each speed."),
        ("critical_speeds", "[{speed (rad/s, undamped), order, mode (cylindrical, conical, mixed), whirl, node, damped_speed, damping_ratio, log_decrement, in_range, excited}]."),
        ("no_crossings", "[{order, whirl, mode, reason (gyroscopic, coincident, complex), polar_moment, transverse_moment, explanation}]."),
        ("stability", "{stable_in_range, onset_speeds [rad/s], least_damping_ratio, least_damping_speed, stable_at_speed (null without --speed)}."),
        ("response", "{source (body or planes), unbalance [{plane, amount (kg m), angle_deg}], speeds [N], bearings [{plane, displacement [N] (m), displacement_minor [N], displacement_phase_deg [N], force [N] (N), force_phase_deg [N]}], peaks [{bearing, plane, speed, amplitude, amplification_factor, half_power [N1, N2], mode, whirl, undamped}], at_speed [{plane, displacement, displacement_phase_deg, force, force_phase_deg, rigid_force}]}."),
        ("margins", "null without --speed; else {rule, operating_speed [min, max], checks [{bearing, plane, speed, mode, amplification_factor, basis (half-power, undamped, undefined), position (below, above, within), margin_percent, required_margin_percent, passed}], passed (null when nothing was judged)}."),
        ("warnings", "one-line warnings (also on standard error)."),
    ],
    "examples": [
        ("rbcli whirl -e '{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}' --bearings=-0.2,0.2 --stiffness 1e6",
         "The sheet's solid cylinder: critical speeds 200 rad/s (cylindrical, forward and backward), 206.559 (conical, backward) and 241.209 rad/s (conical, forward)."),
        ("rbcli whirl -e '{shape: cylinder, radius: 0.3, length: 0.05, mass: 100}' --bearings=-0.1,0.1 --stiffness 2e6",
         "A disk (Ip > It): 76.8615 rad/s (conical, backward) and 200 rad/s (cylindrical) only; the forward conical whirl never reaches 1x, said in words."),
        ("rbcli whirl examples/fan_rotor.yaml --bearings 0,500mm --stiffness '5 N/um' --damping '1 N*s/mm' --speed '1480 rpm' --speed-range '0,3000 rpm' --orders 1,2 --plot campbell.png --plot-response response.png",
         "The README's fan on rolling bearings in a light pedestal: forward conical critical speed 1958.84 rpm, driven by the rotor's own unbalance, its response peak (AF 24.3) 32.4 % above 1480 rpm where the API rule asks 26 %: PASS; and the two figures."),
    ],
}
