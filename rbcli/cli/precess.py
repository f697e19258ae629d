"""``rbcli precess``: the exact torque-free motion of a rigid body."""

from __future__ import annotations

from rbcli.api.commands import PRECESS
from rbcli.cli import common as c
from rbcli.cli.app import MANUAL
from rbcli.errors import InputError

HELP = """Torque-free motion from an initial angular velocity: L, T, precession, period, flips.

The body turns freely about its centre of mass (no torque, no gravity), starting
with the angular velocity --omega given in the body frame. Reported: L in the body
frame, |L| and T; whether the body is symmetric; which principal axis w circles
(1 = smallest moment, 3 = largest) and whether that is stable; the period of w in
the body frame; when the body flips (the intermediate axis turns over relative to L:
the tennis-racket or Dzhanibekov effect) the time between flips and the first one; on the
separatrix, that there is no period. A symmetric body also gets the body-frame
precession rate W = w3 (Is/I - 1), the body and space cone semi-angles, the space
precession rate |L|/I and the wobble-to-spin ratio. The motion is the exact
solution (Jacobi elliptic functions; the orientation through the elliptic integral
of the third kind), so --at T costs the same for T = 1 s or 1e9 s. The space frame
is the body frame at t = 0.
"""


@c.command(PRECESS, help=HELP)
def precess(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    args: dict = c.PARAMS,
    json_: bool = c.JsonOpt,
    fmt: str = c.FormatOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.api import precess as api
    from rbcli.render import echo
    from rbcli.render import precess as rp

    e, out, du = c.start(json_, fmt, units)
    csv, plot = args.pop("csv"), args.pop("plot")
    # --- option values, checked before the body is read (bad usage is bad usage)
    opts = api.parse(None, **args)
    if args["samples"] is not None and csv is None:
        raise InputError("--samples: sets the rows of the --csv time series; add --csv FILE and --duration T")
    if csv is not None:
        if opts.duration is None:
            raise InputError("--csv: needs --duration T, the span of the time series (from t = 0)")
        if csv == "-" and out != "table":
            raise InputError(f"--csv -: the time series would go to standard output, so it cannot be combined with --{'json' if json_ else 'format ' + out}; write it to a file")
    elif opts.duration is not None and plot is None:
        raise InputError("--duration: sets the span of --csv or --plot; add one of them")

    # --- the body, and the output paths checked before any computing
    b = c.load_one(body, expr, e)
    opts = api.parse(b, **args)  # bare numbers follow the body's units: read again, for this body
    plot_path, csv_path = c.output_paths(b, plot=plot, csv=csv)
    result = api.run(b, opts)
    for w in result.warnings[len(b.warnings):]:  # (the body's own were shown as it was read)
        e.warn(f"rbcli: {b.source}: warning: {c.said(w)}")
    csv_info = None
    if csv is not None:
        csv_info = {"file": csv, "samples": opts.samples, "duration": opts.duration}
        c.write_csv(e, csv_path, rp.CSV_HEADER, result.series_blocks())  # csv_path None: stdout
    if plot_path is not None:
        c.save_plot(rp.plot(b, result.motion, opts.duration, du), plot_path)

    def data() -> dict:
        out = c.with_file(result.to_json(), b.source)
        if csv_info is not None:
            out["csv"] = csv_info
        if plot_path is not None:
            out["plot"] = str(plot_path)
        return out

    if csv != "-":  # with --csv - the time series is the output
        c.emit(e, out, data, lambda doc: rp.document(
            doc, b, result, du, digits, csv=csv_info, plot=str(plot_path) if plot_path else None),
               given=echo.echo_rows(opts, b.units))
    c.finish(result.return_code)


MANUAL["precess"] = {
    "notes": [
        "Frames: --omega and every vector are in the body frame (the frame of the body file); "
        "the analysis uses the principal frame about the com (moments ascending: axis 1 the "
        "smallest, axis 3 the largest, as rbcli principal prints them). The space frame is the "
        "body frame at t = 0, so L in space is the initial L and the orientation at t = 0 is the "
        "identity. Quaternions are w, x, y, z (scalar first) and turn body coordinates into "
        "space coordinates.",
        "Which motion: w circles axis 3 when G^2 > 2 T I2 (G = |L|, T the kinetic energy), axis "
        "1 when G^2 < 2 T I2; both are stable for a rigid body (a body that dissipates energy "
        "ends up turning about axis 3, the major-axis rule) unless the body flips: a motion that "
        "flips is near the intermediate axis and is not called stable. G^2 = 2 T I2 is the separatrix: no "
        "period, w creeps towards the intermediate axis and the body turns over once. The "
        "intermediate component w2 changes sign every 2K(m)/lambda; that is a flip (the "
        "tennis-racket or Dzhanibekov effect, flip_interval) only when the motion carries the "
        "intermediate axis through a reversal relative to L: when L, seen in the body, passes "
        "nearer to the intermediate axis than to any other principal axis, then nearer to its "
        "opposite. Near the largest or smallest axis w2 changes sign as part of a wobble about "
        "that axis: flip_interval is null and the table says 'no flip: stable about axis k'.",
        "Symmetric body (I1 = I2 = I, I3 = Is, or the prolate I2 = I3): in the body w circles the "
        "symmetry axis at W = w3 (Is/I - 1) (period 2 pi/|W|); in space the axis and w turn "
        "about L at |L|/I. For the Earth (Is/I = 1.00327, one turn a sidereal day) the rigid "
        "value is 304.975 days; the observed Chandler wobble, about 433 days, is not a "
        "rigid-body result (the elastic mantle, the oceans and the fluid core lengthen it).",
        "The CSV has a header line and one row per time, numbers written with full precision "
        "(shortest repr that reads back exactly); the quaternion's sign is kept continuous along "
        "the series (q and -q are the same orientation). An existing CSV or plot file is "
        "replaced, an input file never. Time units on the command line: s, ms, min, h.",
    ],
    "json": [
        ("angular_momentum", "[3] L = J w at t = 0, kg m^2/s, body frame (= the constant L in space)."),
        ("kinetic_energy", "T = w.J.w/2, J."),
        ("symmetric", "true when two (or three) principal moments are equal."),
        ("period", "period of w in the body frame, s; null when not periodic (rest, steady rotation, a spherical body, the separatrix)."),
        ("circles_axis", "1 or 3: the principal axis w circles (or turns steadily about); null at rest, for a spherical body, on the separatrix or steadily about the intermediate (or a transverse) axis."),
        ("precession_rate", "symmetric bodies: W = w3 (Is/I - 1), rad/s, signed about the symmetry axis; null otherwise."),
        ("space_precession_rate", "symmetric bodies: |L|/I, rad/s, the rate the symmetry axis turns about L."),
        ("body_cone_deg, space_cone_deg", "symmetric bodies: the semi-angles of the body cone (w to the axis) and the space cone (w to L), degrees."),
        ("flip_interval", "time between flips, s: when the motion carries the intermediate axis through a reversal relative to L (L passes nearer to the intermediate axis than to the others, then to its opposite; w2 changes sign in the middle of each flip); null near the largest or smallest axis (no flip), for symmetric bodies and when not periodic."),
        ("first_flip, flip_interval_estimate", "the first t > 0 at which w2 changes sign in a flip (on the separatrix: the one flip, if ahead), s; the near-separatrix estimate (2/sigma) ln(4/k'), s; null when the body does not flip."),
        ("omega, angular_momentum_norm, symmetry, principal_moments, principal_axes", "the input w [3] rad/s; |L|; asymmetric/symmetric/spherical; moments ascending [3] and axes [3x3] (rows, body frame)."),
        ("case, description, stable", "rest, spherical, steady, circulates_max, circulates_min or separatrix; one sentence; whether the motion reported is stable: true when w circles (or spins steadily about) the largest or smallest axis or a symmetry axis without flipping; false when the body flips, spins about the intermediate axis or is on the separatrix; null at rest, for a spherical body and about a transverse axis of a symmetric body (neutral)."),
        ("nutation_deg, symmetry_axis, oblate, spin_rate, wobble_to_spin, wobble_period, space_precession_period", "symmetric bodies: angle of L from the axis; the axis [3]; Is > I; psi' = -W; |phi'/psi'|; 2 pi/|W| s (also for steady spin about the axis: the period of a small wobble); 2 pi I/|L| s."),
        ("precession_per_period, mean_precession_rate", "angle the body turns about L per period of w, rad; that over the period, rad/s."),
        ("elliptic_parameter, elliptic_complement, elliptic_rate", "asymmetric motion: m, 1 - m and lambda (1/s) of the Jacobi solution."),
        ("linear_rates, linear_kinds", "[3] for steady rotation about each principal axis with this |L|: the small-oscillation frequency (rad/s) or growth rate (1/s), and which."),
        ("notes", "[strings] what the tables say in words (near the intermediate axis, the separatrix, the Earth's Chandler wobble, ...)."),
        ("at", "with --at: {t (s), omega [3], angular_momentum [3] (body frame at t), quaternion [4] (w, x, y, z), rotation_axis [3] (null for no rotation), rotation_angle_deg, rotation_matrix [3x3], periods (t/period or null)}."),
        ("verify", "with --verify: {t_end, samples, rtol, nfev, omega_error, attitude_error (rad), numeric_energy_drift, numeric_momentum_drift, numeric_L_drift, exact_energy_drift, exact_momentum_drift, exact_L_drift, tol, ok}."),
        ("csv, plot", "with --csv: {file, samples, duration}; with --plot: the file written."),
        ("name, file", "the body's name and where it was read from."),
    ],
    "examples": [
        ("rbcli precess examples/frisbee.yaml --omega 0.871557,0,9.96195",
         "A thin disk spinning at 10 rad/s, 5 degrees off its axis: the wobble is about twice the spin (wobble/spin 2.00191), W = 9.96195 rad/s, space cone 2.49523 degrees."),
        ("rbcli precess examples/earth.yaml --omega '0,0,7.292115855e-5 rad/s'",
         "The rigid Earth: a small wobble has the period 2.63499e7 s = 304.975 days (not the observed 433-day Chandler wobble)."),
        ("rbcli precess examples/book.yaml --omega 0.01,1,0.01",
         "Spin about the intermediate axis: the book flips every 19.5529 s, first at 10.9169 s."),
        ("rbcli precess examples/book.yaml --omega 0.01,1,0.01 --at 1e9 --json | jq .at",
         "w and the orientation 10^9 s later, at the cost of t = 1 s."),
        ("rbcli precess examples/football.yaml --omega 1.73648,0,9.84808 --duration 5 --samples 501 --csv ball.csv --plot ball.svg",
         "A time series and a figure of the wobbling football."),
    ],
}
