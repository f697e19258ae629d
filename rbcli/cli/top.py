"""``rbcli top`` (a heavy symmetric top or gyroscope on a pivot) and ``rbcli gyrocompass``."""

from __future__ import annotations

from rbcli.api.commands import GYROCOMPASS, TOP
from rbcli.cli import common as c
from rbcli.cli.app import MANUAL
from rbcli.errors import InputError

HELP = """A heavy symmetric top or gyroscope on a fixed pivot: precession, nutation, sleeping.

The body stands on --pivot (default: the body's pivot, else the origin); its symmetry
axis runs from the pivot through the centre of mass, and the body must be symmetric
about it (the two moments across it equal to a relative 1e-6). It spins at --spin S =
w3, the component of the angular velocity along that axis (not the Euler rate psi'),
and starts at --theta from the upward vertical (a bare number is degrees), released
from rest unless --theta-dot or --phi-dot is given. Exact closed form (Goldstein §5.7):
the two steady precession rates at theta (or that none exists, and the least spin for
one), the horizontal rate m g l/(Is S), the sleeping-top critical spin, the nutation
limits theta1 and theta2, the nutation period, the mean precession and spin rates and
the kind of path the axis draws (waves, loops, cusps), with the fast-top estimates
beside the exact values. --verify integrates the equations of motion numerically and
compares; --plot draws the path of the axis; --csv writes theta, phi, psi against time.
For a gyrocompass see rbcli gyrocompass.
"""

GYRO_HELP = """A gyrocompass: the period of its swing about north and where it settles.

A rotor spinning at --spin about its axis, the axis held horizontal and free to turn
about the vertical, at --latitude (degrees; negative south) on the rotating Earth:
gravity-free gyroscopic torque swings the axis about the meridian with
w0^2 = (C/A) S W cos(latitude) - W^2 cos^2(latitude), W the Earth's rate, and period
T = 2 pi/w0 (undamped). C/A is the axial moment over the moment about the vertical:
--ratio, or from a body (BODY or -e) symmetric about its spin axis (--axis, default the
body's shaft axis, else body z), both moments about its centre of mass.
"""


def _warn(e, result) -> None:
    for w in result.warnings:
        e.warn(f"rbcli: {c.said(w)}")


@c.command(TOP, help=HELP)
def top(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    args: dict = c.PARAMS,
    json_: bool = c.JsonOpt,
    fmt: str = c.FormatOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.api import top as api
    from rbcli.api.params import read
    from rbcli.render import echo
    from rbcli.render import top as rt
    from rbcli.render.csvout import times

    e, out, du = c.start(json_, fmt, units)
    csv, plot = args.pop("csv"), args.pop("plot")
    read(None, TOP, {k: args[k] for k in ("duration", "samples")})  # bad values: before the body
    if args["samples"] is not None and csv is None:
        raise InputError("--samples: sets the rows of the --csv time series; add --csv FILE")
    if csv == "-" and out != "table":
        raise InputError(f"--csv -: the CSV would go to standard output together with --{'json' if json_ else 'format ' + out}; write it to a file")

    b = c.load_one(body, expr, e)
    opts = api.parse(b, **args)
    plot_path, csv_path = c.output_paths(b, plot=plot, csv=csv)
    r = api.run(b, opts)
    _warn(e, r)
    span = None
    if plot_path is not None or csv is not None:
        span = opts.duration if opts.duration is not None else r.default_duration()
    if plot_path is not None:
        c.save_plot(rt.plot(r, r.sample(span), span), plot_path)
    if csv is not None:
        c.write_csv(e, csv_path, rt.CSV_HEADER, (rt.csv_block(r.at(t)) for t in times(span, opts.samples)))
        if csv_path is None:  # '-': standard output, instead of the tables
            c.finish(r.return_code)
            return

    def data() -> dict:
        out = c.with_file(r.to_json(), b.source)
        if plot_path is not None:
            out["plot"] = str(plot_path)
        if csv is not None:
            out["csv"] = {"file": csv, "rows": opts.samples, "duration": span}
        return out

    c.emit(e, out, data, lambda doc: rt.document(
        doc, r, du, digits, plot=str(plot_path) if plot_path is not None else None, csv=csv,
        rows=opts.samples if csv is not None else None, duration=span),
           given=echo.echo_rows(opts, b.units))
    c.finish(r.return_code)


# --- gyrocompass


@c.command(GYROCOMPASS, help=GYRO_HELP)
def gyrocompass(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    args: dict = c.PARAMS,
    json_: bool = c.JsonOpt,
    fmt: str = c.FormatOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    from rbcli.api import gyrocompass as api
    from rbcli.render import echo
    from rbcli.render import top as rt

    e, out, du = c.start(json_, fmt, units)
    b = c.load_one(body, expr, e) if body is not None or expr is not None else None
    opts = api.parse(b, **args)
    r = api.run(b, opts)
    _warn(e, r)
    c.emit(e, out, lambda: c.with_file(r.to_json(), b.source) if b is not None else r.to_json(),
           lambda doc: rt.gyro_document(doc, r, du, digits),
           given=echo.echo_rows(opts, b.units if b is not None else None))


# --- manual

MANUAL["top"] = {
    "notes": [
        "Model (physics notes dynamics.md §2, Goldstein 3rd ed. §5.7): a rigid body symmetric "
        "about the line from the pivot through its centre of mass, on a fixed frictionless "
        "pivot, in uniform gravity g along -z. theta is the tilt of the axis from the upward "
        "vertical, phi the azimuth of the axis about the vertical (precession), psi the spin "
        "angle. m is the mass, l the distance from the pivot to the com, I the moment about the "
        "pivot across the axis (I_cm + m l^2) and Is the moment about the axis. The spin S is "
        "w3 = psi' + phi' cos theta, the component of the angular velocity along the axis; it "
        "is constant. Energy and the two angular momenta p_phi and p_psi are conserved, so "
        "u = cos theta moves between two roots u1 and u2 of the cubic f(u); theta1 = arccos u2 "
        "is the least tilt, theta2 = arccos u1 the greatest. Everything is evaluated in closed "
        "form (Jacobi elliptic functions, complete and incomplete elliptic integrals of the "
        "first and third kinds); nothing is integrated except with --verify.",
        "Steady precession at theta: phi' solves I cos(theta) phi'^2 - Is S phi' + m g l = 0; "
        "two rates (slow and fast) when Is^2 S^2 >= 4 I m g l cos(theta), none below that "
        "spin (printed), one (m g l/(Is S)) with the axis horizontal. A top started at a "
        "steady rate (--phi-dot) keeps theta fixed (the path is reported as steady "
        "precession). Sleeping top: upright spinning is stable when S > S_c = sqrt(4 I m g "
        "l)/Is. The path of the axis tip: waves (phi' keeps its sign), loops (phi' reverses "
        "inside the band) or cusps (phi' = 0 at the least tilt: a top released from rest). "
        "The fast-top estimates (a^2 >> beta with a = Is S/I, beta = 2 m g l/I) are shown "
        "beside the exact values with their relative errors: nutation frequency Is S/I, "
        "nutation amplitude (2 I m g l/(Is S)^2) sin(theta0) (released from rest), mean "
        "precession m g l/(Is S), steady rates m g l/(Is S) and Is S/(I cos theta).",
        "The pivot is --pivot, else the body's pivot, else the origin. Nearly symmetric bodies "
        "(issue 14; a CAD body is symmetric only to its modelling, typically 0.01 %): the two "
        "moments across the pivot-com line may differ, and the products of inertia coupling "
        "that line to the plane across it may be, up to --symmetry-tol (default 1 %) of their "
        "mean. Within it the answer is for the symmetrised body (I the mean moment across), "
        "with one warning on standard error giving the asymmetry in %, a table line saying how "
        "far the answer may be off (a relative amount of the order of the asymmetry; the path "
        "of the axis by a few times the tilt of the nearest principal axis) and the JSON key "
        "asymmetry; --verify then also integrates the real body (full inertia tensor about "
        "the pivot, quaternion and body rates, DOP853) from the same start and prints its "
        "largest difference from the closed form (information, not part of the verdict). "
        "Departures below 1e-6 are rounding and say nothing. Beyond the tolerance the body is "
        "refused with both moments, how far apart, and the option to change; a pivot at the "
        "com (no gravity torque) is refused with a pointer to free precession (rbcli precess). Exit status 2 also for --theta outside (0, 180) "
        "degrees, a zero spin, g <= 0, and missing --spin or --theta.",
        "--csv FILE writes a header line t,theta_deg,phi_deg,psi_deg and --samples rows from "
        "t = 0 to --duration (default 3 nutation periods) inclusive, in seconds and degrees, "
        "each number as Python's shortest round-trip repr; the first row is the start (0, "
        "theta0, 0, 0). phi and psi are continuous (not wrapped to 360). An existing file is "
        "replaced, as --plot replaces a figure, but never a file given as input; --csv - "
        "writes the CSV to standard output instead of the tables. --plot draws the same span "
        "(400 points per nutation period, at least 2000 and at most 200000). --verify integrates over 3 "
        "nutation periods and prints the largest differences of the axis, theta, phi and psi "
        "from the closed form and the drift of energy and of the two conserved momenta; exit "
        "status 1 when the axis differs by more than 1e-6 rad or the energy drifts by more "
        "than 1e-9 (relative to the kinetic energy plus m g l). The integration is bounded: when it "
        "would need more than 20000 steps (a slow nutation under a fast spin, e.g. a top at "
        "exactly its critical spin started near upright) --verify stops in a few seconds with "
        "one line saying so (exit status 2); the closed form needs no integration.",
    ],
    "json": [
        ("mass, length, I, Is", "m (kg), pivot-to-com distance l (m), the moment about the pivot across the axis and the moment about the axis (kg m^2)."),
        ("spin", "S = w3, rad/s."),
        ("steady_precession_rates", "[slow, fast] steady precession rates at theta0, rad/s; [] when the spin is below minimum_spin_for_steady; [rate] with the axis horizontal."),
        ("horizontal_precession_rate", "m g l/(Is S), rad/s."),
        ("critical_spin", "sleeping-top threshold sqrt(4 I m g l)/Is, rad/s."),
        ("theta1_deg, theta2_deg", "least and greatest tilt from the upward vertical, degrees."),
        ("nutation_period", "s (null on the separatrix)."),
        ("mean_precession_rate", "<phi'>, rad/s (null on the separatrix)."),
        ("path", "waves, loops, cusps, or steady (steady precession: theta stays at theta0, as steady true says)."),
        ("g, theta0_deg, theta_dot0, phi_dot0", "the start: gravity (m/s^2), tilt (degrees), rates (rad/s)."),
        ("steady, sleeps", "whether theta stays fixed (steady precession); whether |S| > critical_spin."),
        ("minimum_spin_for_steady", "the least |S| for steady precession at theta0, rad/s (0 at or below the horizontal)."),
        ("steady_nutation_frequencies", "small-nutation frequency about each steady rate, rad/s."),
        ("steady_precession_estimates", "fast-top estimates of the steady rates: [m g l/(Is S), Is S/(I cos theta0)] (rad/s; the second absent when horizontal)."),
        ("nutation_amplitude_deg, nutation_frequency", "theta2 - theta1 (degrees) and 2 pi/T_n (rad/s)."),
        ("mean_spin_rate, precession_per_nutation, spin_per_nutation", "<psi'> (rad/s), and delta phi, delta psi per nutation period (rad)."),
        ("goldstein, turning_points, elliptic_parameter, apex_u", "a, b (1/s), alpha, beta (1/s^2); u1, u2, u3; m of the elliptic functions; u where phi' = 0 (b/a)."),
        ("fast_top", "{nutation_frequency, nutation_amplitude_deg, mean_precession_rate, and each *_rel_error = (estimate - exact)/exact}."),
        ("I_com", "the moment across the axis about the com, I - m l^2, kg m^2."),
        ("axis, pivot, com", "[3] the unit symmetry axis (pivot to com), the pivot and the com in the body frame (m)."),
        ("pivot_source, name, file", "where the pivot came from; the body's name and source."),
        ("asymmetry", "only for a nearly symmetric body: {transverse_moments [I1, I2] about the pivot (kg m^2), relative (I2 - I1)/mean, coupling (kg m^2), coupling_relative, principal_axis_tilt (rad), com_offset (m, 0: the axis runs through the com), com_offset_relative, tolerance}."),
        ("verify", "with --verify: {t_end, samples, rtol, max_axis_error (rad), max_theta_error_deg, max_phi_error_deg, max_psi_error_deg, energy_drift, p_phi_drift, p_psi_drift, theta_min_deg, theta_max_deg, mean_precession_rate, nfev, axis_tolerance, energy_tolerance, pass}; for a nearly symmetric body also real_body {t_end, samples, max_axis_error, max_theta_error_deg, max_phi_error_deg, energy_drift, nfev}: the real body against the symmetrised closed form."),
        ("plot, csv", "with --plot / --csv: the file written; csv also {rows, duration}."),
    ],
    "examples": [
        ("rbcli top examples/top.yaml --spin 150 --theta 30 --g 9.81",
         "The course text's top released from rest at 30 degrees: theta2 = 34.5082 degrees, "
         "T_n = 0.142133 s, mean precession 3.46842 rad/s, cusps; steady rates 3.47973 and "
         "54.2553 rad/s; horizontal rate 3.27 rad/s; critical spin 76.7203 rad/s (it sleeps)."),
        ("rbcli top examples/gyroscope.yaml --spin '3000 rpm' --theta 90",
         "A lab gyroscope let go with its axle horizontal: it precesses at 0.897393 rad/s and "
         "dips 0.922558 degrees; here the fast-top estimates are good to 2e-4."),
        ("rbcli top examples/top.yaml --spin 150 --theta 30 --g 9.81 --phi-dot 10 --plot path.svg",
         "Loops: started with a precession rate above the mean; the path of the axis drawn."),
        ("rbcli top examples/top.yaml --spin 150 --theta 30 --verify --json | jq .verify.max_axis_error",
         "The closed form against a numerical integration (about 1e-15 rad)."),
        ("rbcli top examples/top.yaml --spin 150 --theta 30 --csv - --samples 5",
         "theta, phi and psi at five times over three nutation periods, as CSV."),
        ("rbcli top examples/cad_flywheel.yaml --spin '1500 rpm' --theta 60 --verify",
         "A CAD flywheel symmetric to 0.01 % (a set screw): answered for the symmetrised body "
         "with a warning; the real body's axis stays within 1e-4 rad of the closed form."),
    ],
}

MANUAL["gyrocompass"] = {
    "notes": [
        "Model (physics notes dynamics.md §2, 'Gyrocompass'): the rotor's axis is held "
        "horizontal and is free to turn about the vertical; alpha is its azimuth from north. "
        "On the Earth, rotating at W about its axis, A alpha'' = -C S W cos(lat) sin(alpha) + "
        "A W^2 cos^2(lat) sin(alpha) cos(alpha). For S > 0 the axis swings about north (the "
        "spin vector points north, along the Earth's rotation); for S < 0 about south. Small "
        "swings: w0 = sqrt(|C S W cos(lat)|/A - W^2 cos^2(lat)), period T = 2 pi/w0, "
        "undamped (a real gyrocompass adds damping to settle). The usual estimate "
        "sqrt(C S W cos(lat)/A) is shown beside it. At a pole, or with a spin too slow to "
        "beat the W^2 term, there is no directive torque and no period (null in JSON).",
        "C is the moment about the spin axis and A the moment about the vertical (across the "
        "spin axis), both about the rotor's centre of mass: --ratio C/A directly, or from a "
        "body symmetric about its spin axis (--axis, default the body's shaft axis, else body "
        "z). A nearly symmetric rotor (the two moments across the axis, or the products "
        "coupling it to the plane across, within --symmetry-tol of their mean, default 1 %) "
        "is answered with A their mean, one warning, a table line (C/A may be off by up to "
        "half the difference of the moments across) and the JSON key asymmetry; beyond it, "
        "refused with the numbers. The latitude is in degrees unless a unit is given; "
        "negative is south.",
    ],
    "json": [
        ("C_over_A, Is_over_I", "the ratio C/A (the same number under both names)."),
        ("spin", "rad/s."),
        ("latitude_deg", "degrees."),
        ("earth_rate", "W, rad/s."),
        ("directive", "C S W cos(lat)/A, 1/s^2."),
        ("omega0, omega0_approx", "the swing's angular frequency, exact and the usual estimate, rad/s (null with no directive torque)."),
        ("period, period_approx", "2 pi/omega0 and 2 pi/omega0_approx, s (null with no directive torque)."),
        ("settles_to", "north (S > 0) or south (S < 0): where the rotor's +axis settles; null with no directive torque."),
        ("C, A, mass, axis, axis_source, name, file", "with a body: the moments about the com (kg m^2), its mass, the unit spin axis and where it came from, its name and source."),
        ("Is, I", "with a body: C and A again under the names top and rollcheck use (Is about the spin axis, I across it)."),
        ("asymmetry", "only for a nearly symmetric rotor: as top's, about the centre of mass."),
    ],
    "examples": [
        ("rbcli gyrocompass --ratio 2 --spin '6000 rpm' --latitude 30",
         "A flat disk rotor at 6000 rpm at latitude 30 degrees: w0 = 0.281707 rad/s, period 22.3040 s about north."),
        ("rbcli gyrocompass --ratio 2 --spin '20000 rpm' --latitude 45",
         "Faster and further north: period 13.5197 s."),
        ("rbcli gyrocompass -e '{shape: disk, radius: 0.1, mass: 1}' --spin '6000 rpm' --latitude 30",
         "The same from a body: a thin disk about its axis (C/A = 2)."),
    ],
}
