"""``rbcli whirl``: the rotor on its bearings — critical speeds, Campbell diagram, unbalance
response and separation margins."""

from __future__ import annotations

import typer

from rbcli.api.commands import WHIRL
from rbcli.cli import common as c
from rbcli.cli.app import MANUAL, app

HELP = """The rotor on its bearings: critical speeds, Campbell diagram, unbalance response.

The body is a rigid rotor (its mass, centre of mass, and its moments about the centre of
mass: Ip about the shaft, It across it) on two or more linear bearings along the shaft
(--shaft through --through, as for balance), each a 2x2 stiffness and damping: kxx, kxy,
kyx, kyy and cxx, cxy, cyx, cyy, constant or tabled against speed (an oil film, a seal).
The body file's bearings: section gives them (positions, coefficients or tables, names:
see the man page), so that 'rbcli whirl rotor.yaml' needs no options; --bearings
z1,z2[,...], --stiffness, --stiffness-y, the cross-coupled terms and --damping override it.
Four degrees of freedom: the translations and tilts of the shaft axis at the centre of
mass, coupled by the gyroscopic moment Ip Omega. Gravity is left out of the linear modes.

Over a range of speeds (default 0 to 1.25 times the highest critical or operating speed,
within the bearing tables) in --points speeds, all solved at once: the whirl frequencies
(fixed frame), each mode followed by its shape, with its whirl (forward, backward, and
the forward share of its orbits), kind (cylindrical, conical or mixed, with its node),
damping ratio and log decrement. Stability: the speeds where a mode's growth rate crosses
zero, solved as roots, each an onset or a recovery, and the threshold speed of
instability. The critical speeds of --orders (default 1; '1,2' adds 2x): undamped (the
rotor without damping or follower stiffness: an eigenproblem in the speed, or a root solve
on tables) and damped (where the whirl frequency meets the line, a root solve); a branch
that never meets its line is explained. The undamped critical speed map (critical speeds
against bearing stiffness) is tabled.

The unbalance response (bearing displacement and force, amplitude and phase, against
speed) is to the body's own static and couple unbalance (what balance computes) or to
--unbalance U1@angle1,... in --unbalance-planes z1,...; its peaks give the amplification
factor AF by the half-power method (1/2 zeta where the half-power bands overlap). With
--speed (the operating speed, or min,max of the operating range) each peak is judged by
the API 617 / API 684 separation-margin rule; exit status 1 when one fails or a mode grows
at that speed. --plot, --plot-response and --plot-map draw the Campbell diagram, the
response and the map.

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
    plot_map: str = typer.Option(None, "--plot-map", help="Write the undamped critical speed map (png, svg or pdf): critical speeds against bearing stiffness, log-log, with each bearing's own stiffness against speed drawn over it.", show_default=False),
    json_: bool = c.JsonOpt,
    fmt: str = c.FormatOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.api import whirl as api
    from rbcli.render import whirl as rw

    e, out, du = c.start(json_, fmt, units)
    b = c.load_one(body, expr, e)
    o = api.parse(b, **args)
    plot_path = c.check_plot(plot, b) if plot is not None else None
    paths = {"--plot": plot_path}
    for opt, name in (("--plot-response", plot_response), ("--plot-map", plot_map)):
        if name is not None:
            from rbcli.io import outfile  # (only to write figures: it loads secrets, ~3 ms)

            paths[opt] = outfile.check(name, b, opt, exts=c.PLOT_FORMATS, replace_ok=True,
                                       others={k: v for k, v in paths.items() if v is not None})
    res = api.run(b, o)
    for opt, draw in (("--plot", rw.campbell_figure), ("--plot-response", rw.response_figure),
                      ("--plot-map", rw.map_figure)):
        if paths.get(opt) is not None:
            c.save_plot(draw(res), paths[opt], opt)

    def tables(doc) -> None:
        rw.document(doc, res, du, digits)
        for opt, path in paths.items():
            if path is not None:
                doc.note(f"{opt}: figure written to {path}")

    c.emit(e, out, lambda: {**res.to_json(), "file": b.source}, tables, plain=True)
    for w in res.warnings:  # after the output: a result that cannot be printed says only that
        e.warn(f"rbcli: {b.source}: warning: {c.said(w)}")
    c.finish(res.return_code)


MANUAL["whirl"] = {
    "notes": [
        "Model (physics notes whirl.md): a rigid rotor, mass m, centre of mass at z_G on the "
        "shaft, Ip about the shaft and It across it (about the centre of mass, the mean of the "
        "two moments across), on linear bearings at z_i: F = -K_i d - C_i d' with d the "
        "displacement of the shaft axis there, K_i = [[kxx, kxy], [kyx, kyy]] and C_i likewise. "
        "Coordinates q = (x, y, theta_x, theta_y) of the axis at the centre of mass; M q'' + (C + "
        "Omega G) q' + K q = f with M = diag(m, m, It, It), K = sum T_i^T K_i T_i (T_i = [[1, 0, 0, "
        "a_i], [0, 1, -a_i, 0]], a_i = z_i - z_G) and the gyroscopic G from Ip Omega (Friswell, "
        "Penny, Garvey and Lees, Dynamics of Rotating Machines, 2010, ch. 3). Gravity sets a "
        "static sag (and an oil film's coefficients) and is left out of the linear modes.",
        "Bearings in the body file: a bearings: section, a list of {name, at (the position along "
        "the shaft, in the body's length unit), k (kxx = kyy) or kxx, kyy, kxy, kyx (N/m), c or "
        "cxx, cyy, cxy, cyx (N s/m), or table, and units: {speed, stiffness, damping} (what bare "
        "numbers mean)}. A table gives the coefficients against speed, one row a speed, "
        "ascending, as bearing programs print them: in the body file as rows [speed, kxx, kxy, "
        "kyx, kyy, cxx, cxy, cyx, cyy], or a CSV file named from the body file (relative to it) "
        "whose header row names its columns, speed and any of the eight, each optionally with "
        "its unit in brackets ('kxx [N/mm]'). Between rows the coefficients are interpolated "
        "linearly in the speed; a speed beyond a table is refused, never extrapolated (the "
        "default speed range stays within the tables). The options override the section: "
        "--bearings its positions (another number of bearings: the section is not used), "
        "--stiffness kxx and kyy (kxx alone with --stiffness-y), --cross-stiffness kxy = -kyx, "
        "--stiffness-xy and --stiffness-yx kxy and kyx, --damping, --damping-y, --damping-xy and "
        "--damping-yx likewise, at every speed.",
        "The rotor must be symmetric about its shaft within --symmetry-tol (default 1 %): its "
        "two moments across the shaft may differ, and its couple unbalance may be, up to that "
        "fraction of It; within it the answer is for the symmetrised rotor with a warning, "
        "beyond it the rotor is refused (exit 2) with the numbers: an asymmetric rotor's whirl "
        "equations have periodic coefficients. Numbers too far apart to compute with (natural "
        "frequencies at rest spread over 1e8, damping rates or speeds above 1e4 times the "
        "highest of them) are refused with the values.",
        "Modes: the quadratic eigenproblem at every speed at once (a stack of first-order "
        "forms). With isotropic bearings (kxx = kyy, kxy = -kyx, cxx = cyy, cxy = -cyx) the "
        "complex coordinates r = x + i y, phi = theta_y - i theta_x give each mode a whirl "
        "direction: forward (the orbit turns with the spin) or backward. Otherwise the orbits "
        "are ellipses: the forward share (the forward part of the orbit by kinetic weight, 1 "
        "forward circular, 0 backward, 0.5 a line) is given overall and per bearing, and the "
        "word follows the larger part (linear when equal). Frequencies are in the fixed frame. "
        "Each mode is followed from speed to speed by its shape (the assignment of largest "
        "modal assurance criterion, the step halved where it is not clear), not by its "
        "frequency rank. Kind: conical when the outermost bearings move out of phase (a node "
        "between them), cylindrical when in phase with the smaller motion at least half the "
        "larger, mixed in between; the node is where the motion along the shaft is least. "
        "Damping ratio -Re(lambda)/|lambda|, log decrement -2 pi Re(lambda)/Im(lambda).",
        "Stability: a mode grows (UNSTABLE) when Re(lambda) > 1e-10 |lambda|. Where a followed "
        "mode's Re(lambda) changes sign between two speeds, the threshold is the root of "
        "Re(lambda) = 0 (Brent's method, independent of --points): an onset when the mode "
        "starts growing as the speed rises, a recovery when it stops. The threshold speed of "
        "instability is the first onset, or the range's start when a mode grows there "
        "already. Exit status 1 when a mode grows at the operating speed or anywhere in the "
        "operating range. Undamped, without cross-coupling, every mode is neutrally stable.",
        "Critical speeds: undamped, of the rotor without its dampers and without the follower "
        "part of its cross-coupled stiffness (kxy and kyx both their mean): exactly, as the "
        "eigenvalues of K Q = Omega^2 (n^2 M - i n G) Q (n the order), on constant bearings "
        "(symmetric bearings give Omega^2 = sum k/m, cylindrical, and sum k a^2 / (It -/+ Ip), "
        "conical); on tables, each followed mode's crossing of the n× line by a root solve over "
        "the speeds the tables cover. When n It <= Ip the forward conical branch never meets the "
        "n× line (said in words); a branch that does not cross within the tables is said so. "
        "The damped critical speed is where the whirl frequency of the rotor as it is (damping "
        "and cross-coupling included) meets the line (Brent's method on the mode followed by "
        "its shape); 'driven' says whether the unbalance excites the mode (its left null "
        "vector; never a backward mode on isotropic bearings). Rigid-support limit: the "
        "critical speeds grow as the square root of the stiffness; on rigid supports a rigid "
        "rotor has none and the bearing forces are balance's.",
        "Undamped critical speed map (API 684's first look): the order-1 critical speeds with "
        "every bearing an isotropic spring k and no damping, for k over --map-stiffness "
        "(default: whole decades from a tenth of the softest bearing to ten times the stiffest), "
        "8 points a decade; for a rigid rotor each is c sqrt(k), a line of slope 1/2 on log-log "
        "axes. --plot-map draws it with each bearing's kxx and kyy against speed over it: where "
        "a bearing's curve meets a branch is that critical speed on that bearing.",
        "Unbalance response: forcing Omega^2 U e^{i Omega t} on the centre of mass and Omega^2 "
        "P_G e^{i Omega t} about it, U and P_G the body's static and couple unbalance (as "
        "balance gives them) or those of --unbalance in --unbalance-planes, solved at every "
        "speed at once. Per bearing: the orbit's semi-major axis (m; tables in µm) and its "
        "phase, the rotor-frame angle of the high spot when the displacement is largest; the "
        "force the rotor exerts on the bearing (N). Peaks (local maxima, refined by a root of "
        "the amplitude's exact slope) get the amplification factor AF = Nc/(N2 - N1), N1 and N2 "
        "the half-power points (amplitude peak/sqrt 2, by Brent's method) when the response "
        "falls that far on both sides before rising into another peak; where the half-power "
        "bands overlap, AF = 1/(2 zeta) of the nearest driven critical speed's mode at its "
        "damped crossing (API 684), the basis said; no damping: the excited critical speeds are "
        "infinite peaks (AF infinite).",
        "Separation margins (with --speed): the rule of API 617 (8th ed.) 6.8.2.4-6.8.2.5 / "
        "API 684 (2nd ed.) SP6.8.2.1, SP6.8.2.10, taken from public implementations (ROSS, "
        "petrobras/ross, ross/api_report.py): AF < 2.5 (critically damped) needs no margin; a "
        "critical speed below the minimum operating speed needs SM = min(16, 17 (1 - 1/(AF - "
        "1.5))) % of it, one above the maximum operating speed SM = min(26, 10 + 17 (1 - 1/(AF - "
        "1.5))) % of it; an undamped peak, or one with no AF at all, is judged as AF infinite "
        "(16 % and 26 %). A critical speed inside the operating range fails unless AF < 2.5. "
        "Check the clause against a licensed copy before claiming conformity.",
        "Figures: --plot draws the Campbell diagram (speed in rpm, whirl frequency in cpm with "
        "Hz on the right, so the 1× line is the diagonal; each mode followed by its shape, "
        "forward solid, backward dashed, straight-line orbits dash-dotted; growing points "
        "crossed; critical speeds filled and on top when the unbalance drives them, coincident "
        "ones one mark and one label); --plot-response draws amplitude and phase per bearing "
        "with the peaks and half-power points; --plot-map the critical speed map. Legends sit "
        "below the axes. The format follows the extension (png, svg, pdf); no input is ever "
        "overwritten.",
    ],
    "json": [
        ("name, conventions", "the body's name; the conventions of every number, in words."),
        ("shaft, shaft_source, through, through_source", "the shaft used and where it came from (shaft, body_shaft, default)."),
        ("rotor", "{mass, com (z_G along the shaft, m), polar_moment, transverse_moment, transverse_moments [2], asymmetry, tilt_deg, eccentricity, static_unbalance (kg m), static_unbalance_angle_deg, couple_unbalance (kg m^2), couple_unbalance_angle_deg}."),
        ("bearings", "[{plane (m), stiffness [kxx, kyy] N/m, cross_stiffness [kxy, kyx] N/m, damping [cxx, cyy] N s/m, name, cross_damping [cxy, cyx] N s/m, table (null, or {speeds [S] rad/s, kxx ... cyy [S], source})}]; tabled coefficients at modes_speed."),
        ("speed_range, speed_range_source, orders, speed, symmetry_tol", "the range (rad/s) and whether it was given or the default; the orders; the operating speed [min, max] rad/s or null."),
        ("modes, modes_speed", "[{frequency (rad/s), whirl, kind, node (m or null), damping_ratio, log_decrement (null if not oscillating), stable, forward_share, bearing_forward_share [n]}] at modes_speed (the maximum operating speed, else the start of the tables, 0 without)."),
        ("campbell", "{speeds [N] rad/s, frequencies [4][N] rad/s, whirl [4][N], kind [4][N], damping_ratio [4][N], log_decrement [4][N], branch [4][N]}: modes numbered by frequency at each speed; branch: the mode followed by its shape (1-4) each belongs to."),
        ("critical_speeds", "[{speed (rad/s, undamped), order, mode (cylindrical, conical, mixed), whirl, node, damped_speed, damping_ratio, log_decrement, in_range, excited, forward_share}]."),
        ("no_crossings", "[{order, whirl, mode, reason (gyroscopic, coincident, range), polar_moment, transverse_moment, searched ([lo, hi] rad/s for range, else null), explanation}]."),
        ("stability", "{stable_in_range, onset_speeds [rad/s], least_damping_ratio, least_damping_speed, stable_at_speed (null without --speed), threshold_speed (rad/s or null), unstable_from_start, thresholds [{speed, change (onset, recovery), mode (1-4, followed by shape), whirl, kind, frequency}]}."),
        ("response", "{source (body or planes), unbalance [{plane, amount (kg m), angle_deg}], speeds [N], bearings [{plane, displacement [N] (m), displacement_minor [N], displacement_phase_deg [N], force [N] (N), force_phase_deg [N]}], peaks [{bearing, plane, speed, amplitude, amplification_factor, half_power [N1, N2], mode, whirl, undamped, basis (half-power, damping ratio, undamped, undefined)}], at_speed [{plane, displacement, displacement_phase_deg, force, force_phase_deg, rigid_force}]}."),
        ("margins", "null without --speed; else {rule, operating_speed [min, max], checks [{bearing, plane, speed, mode, amplification_factor, basis (half-power, damping ratio, undamped, undefined), position (below, above, within), margin_percent, required_margin_percent, passed}], passed (null when nothing was judged)}."),
        ("critical_speed_map", "{stiffness [K] N/m, speeds [B][K] rad/s, whirl [B], mode [B], bearings [{plane, speeds, kxx, kyy}]}: the undamped critical speed map and each bearing's direct stiffness against speed over the range."),
        ("warnings", "one-line warnings (also on standard error)."),
    ],
    "examples": [
        ("rbcli whirl -e '{shape: cylinder, radius: 0.1, length: 0.6, mass: 50}' --bearings=-0.2,0.2 --stiffness 1e6",
         "The sheet's solid cylinder: critical speeds 200 rad/s (cylindrical, forward and backward), 206.559 (conical, backward) and 241.209 rad/s (conical, forward)."),
        ("rbcli whirl -e '{shape: cylinder, radius: 0.3, length: 0.05, mass: 100}' --bearings=-0.1,0.1 --stiffness 2e6",
         "A disk (Ip > It): 76.8615 rad/s (conical, backward) and 200 rad/s (cylindrical) only; the forward conical whirl never reaches 1x, said in words."),
        ("rbcli whirl examples/fan_rotor.yaml --bearings 0,500mm --stiffness '5 N/um' --damping '1 N*s/mm' --speed '1480 rpm' --speed-range '0,3000 rpm' --orders 1,2 --plot campbell.png --plot-response response.png",
         "The README's fan on rolling bearings in a light pedestal: forward conical critical speed 1958.84 rpm, driven by the rotor's own unbalance, its response peak (AF 24.3) 32.4 % above 1480 rpm where the API rule asks 26 %: PASS; and the two figures."),
        ("rbcli whirl examples/journal_rotor.yaml --speed '8500 rpm' --plot-map map.png",
         "A rotor on two plain journal bearings whose coefficients the body file tables against speed (examples/journal_bearing.csv, from Someya's Journal-Bearing Databook): the forward cylindrical whirl starts growing at 7999.63 rpm (oil whip, at 0.66 of the speed), so 8500 rpm is UNSTABLE: exit status 1; and the critical speed map."),
    ],
}
