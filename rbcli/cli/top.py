"""``rbcli top`` (a heavy symmetric top or gyroscope on a pivot) and ``rbcli gyrocompass``."""

from __future__ import annotations

import typer

from rbcli.cli import common as c
from rbcli.cli.app import MANUAL, app

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

#: the closed form and the integration of --verify must agree this well (axis chord, rad;
#: energy drift relative to T0 + m g l) or the check fails (exit status 1)
VERIFY_AXIS_TOL = 1e-6
VERIFY_ENERGY_TOL = 1e-9
#: most rows --csv (and points --plot) will compute
MAX_SAMPLES = 1_000_000


@app.command(help=HELP)
def top(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    pivot: str = typer.Option(None, "--pivot", help="The fixed point: com, origin or x,y,z (m; a unit after the last number applies to all, e.g. '0,0,-20 mm'). Default: the body's pivot, else the origin.", show_default=False),
    spin: str = typer.Option(None, "--spin", help="Required. Spin S = w3 about the symmetry axis (rad/s, or e.g. '3000 rpm'); negative = the other way.", show_default=False),
    theta: str = typer.Option(None, "--theta", help="Required. Start tilt of the axis from the upward vertical, strictly between 0 and 180 (degrees, or with units, e.g. '0.5 rad').", show_default=False),
    theta_dot: str = typer.Option("0", "--theta-dot", help="Start rate theta' (rad/s, or e.g. '10 deg/s'); positive = tilting further."),
    phi_dot: str = typer.Option("0", "--phi-dot", help="Start precession rate phi' about the vertical (rad/s, or with units)."),
    g: str = typer.Option("9.80665", "--g", help="Gravity (m/s^2, or with units)."),
    verify: bool = typer.Option(False, "--verify", help="Integrate the equations of motion numerically (no Euler angles, DOP853, rtol 1e-12) over 3 nutation periods and compare with the closed form; exit 1 if they differ by more than 1e-6 rad or the energy drifts by more than 1e-9."),
    plot: str = typer.Option(None, "--plot", help="Save a figure (.png, .svg, .pdf): the path of the axis tip, theta against phi and seen from above, theta1 and theta2 marked, over --duration. An existing figure is replaced (atomically); an input file never.", show_default=False),
    csv: str = typer.Option(None, "--csv", help="Write t, theta_deg, phi_deg, psi_deg (s, degrees) at --samples times over --duration to this file ('-' = standard output, instead of the tables). An existing file is replaced (atomically); an input file never.", show_default=False),
    duration: str = typer.Option(None, "--duration", help="Time span of --csv and --plot (s, or with units). Default: 3 nutation periods.", show_default=False),
    samples: int = typer.Option(600, "--samples", help="Rows of --csv, evenly spaced from t = 0 to --duration inclusive (2 to 1000000)."),
    json_: bool = c.JsonOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    import math

    from rbcli.errors import InputError
    from rbcli.render.fmt import DisplayUnits

    e = c.env()
    du = DisplayUnits.parse(units)
    # --- option values, checked before the body is read (bad usage is bad usage)
    if spin is None:
        raise InputError("--spin: required: the spin w3 about the symmetry axis, e.g. --spin 150 (rad/s) or --spin '3000 rpm'")
    if theta is None:
        raise InputError("--theta: required: the start tilt of the axis from the upward vertical, e.g. --theta 30 (degrees)")
    S = c.finite(c.quantity(spin, "angular_speed", "--spin"), "--spin")
    if S == 0.0:
        raise InputError(
            "--spin: must not be 0: a top without spin is a spherical pendulum (it cannot stand); "
            "give the spin w3, e.g. --spin 150 or --spin '3000 rpm'"
        )
    th = c.finite(c.quantity(theta, "angle", "--theta", bare="deg"), "--theta")
    if not (0.0 < th < math.pi):
        raise InputError(
            f"--theta: the start tilt must be strictly between 0 and 180 degrees, got {theta} "
            "(at 0 or 180 the axis is vertical and the precession angle is undefined; start it "
            "slightly tilted, e.g. --theta 0.1)"
        )
    thd = c.finite(c.quantity(theta_dot, "angular_speed", "--theta-dot"), "--theta-dot")
    phd = c.finite(c.quantity(phi_dot, "angular_speed", "--phi-dot"), "--phi-dot")
    gv = c.finite(c.quantity(g, "acceleration", "--g"), "--g")
    if not gv > 0.0:
        raise InputError(f"--g: gravity must be positive (it points down, towards -z), got {g}")
    p_opt = c.point(pivot, "--pivot") if pivot is not None else None
    dur = None
    if duration is not None:
        dur = c.finite(c.quantity(duration, "time", "--duration"), "--duration")
        if not dur > 0.0:
            raise InputError(f"--duration: must be a positive time, got {duration}")
    if not 2 <= samples <= MAX_SAMPLES:
        raise InputError(f"--samples: must be from 2 to {MAX_SAMPLES}, got {samples}")
    if csv == "-" and json_:
        raise InputError("--csv -: the CSV would go to standard output together with --json; write it to a file")

    b = c.load_one(body, expr, e)
    plot_path, csv_path = c.output_paths(b, plot=plot, csv=csv)

    motion, pivot_label = prepare(b, pivot=p_opt, spin=S, theta=th, theta_dot=thd, phi_dot=phd, g=gv)

    check = None
    if verify:
        from rbcli.core import top as core

        try:
            check = core.verify(motion, periods=3)
        except (ValueError, OverflowError, ArithmeticError) as exc:
            raise InputError(f"--verify: {exc}") from None
    span = None
    if plot_path is not None or csv is not None:
        span = dur if dur is not None else default_duration(motion)

    from rbcli.render import top as rt

    info = rt.Info(
        body=b,
        pivot_label=pivot_label,
        released=thd == 0.0 and phd == 0.0,
        verify_axis_tol=VERIFY_AXIS_TOL,
        verify_energy_tol=VERIFY_ENERGY_TOL,
        plot=str(plot_path) if plot_path is not None else None,
        csv=csv,
        duration=span,
        samples=samples if csv is not None else None,
    )
    if plot_path is not None:
        c.save_plot(rt.plot(motion, info, span), plot_path)
    if csv is not None:
        blocks = rt.csv_blocks(motion, span, samples)
        c.write_csv(e, csv_path, rt.CSV_HEADER, blocks)
        if csv_path is None:  # '-': standard output, instead of the tables
            c.finish(_status(check))
            return
    c.emit(e, json_, lambda: rt.to_json(motion, info, check),
           lambda doc: rt.document(doc, motion, info, du, digits, check))
    c.finish(_status(check))


def _status(check) -> int:
    if check is None:
        return 0
    ok = check.max_axis_error <= VERIFY_AXIS_TOL and check.energy_drift <= VERIFY_ENERGY_TOL
    return 0 if ok else 1


def _which(exc: BaseException) -> str:
    """The option a core error from ``analyse`` is about."""
    msg = str(exc)
    for word, opt in (("theta_dot", "--theta-dot"), ("phi_dot", "--phi-dot"), ("theta0", "--theta"),
                      ("tilt", "--theta"), ("gravity", "--g"), ("spin", "--spin")):
        if word in msg:
            return opt
    return "top"


def _check_finite(motion) -> None:
    """Results so extreme that they overflowed are a user error, not NaN in a table."""
    import math

    from rbcli.errors import InputError

    vals = [motion.a, motion.b, motion.alpha, motion.beta, motion.u1, motion.u2, motion.u3,
            motion.theta1, motion.theta2, motion.critical_spin, motion.horizontal_precession_rate]
    if not all(math.isfinite(v) for v in vals):
        raise InputError(_OVERFLOW)


def default_duration(motion) -> float:
    """The span of --csv and --plot when --duration is not given: 3 nutation periods."""
    from rbcli.errors import InputError

    if motion.nutation_period is None:
        raise InputError(
            "--duration: the motion is on the separatrix (the axis creeps to the vertical in "
            "infinite time): it has no nutation period and no periodic closed form to sample"
        )
    return 3.0 * motion.nutation_period


def prepare(body, *, pivot=None, spin: float, theta: float, theta_dot: float = 0.0,
            phi_dot: float = 0.0, g: float = 9.80665):
    """The heavy top's closed-form motion for a body: (TopMotion, pivot label); shared with report.

    ``pivot`` is "com", "origin", [x, y, z] (m) or None (the body's pivot, else the origin);
    ``spin`` w3 (rad/s), ``theta`` the start tilt (rad), ``theta_dot``, ``phi_dot`` (rad/s),
    ``g`` (m/s²). Errors come back as the command reports them (InputError, exit 2): a body
    that is not a top about this pivot, a core ValueError with the option it is about, and
    values that overflow the top's equations.
    """
    from rbcli.core import top as core
    from rbcli.errors import InputError

    params, pivot_label = _params(body, pivot)
    try:
        motion = core.analyse(params, spin, theta, theta_dot, phi_dot, g)
    except (OverflowError, ArithmeticError):
        raise InputError(_OVERFLOW) from None
    except ValueError as exc:
        raise InputError(f"{_which(exc)}: {exc}") from None
    _check_finite(motion)
    return motion, pivot_label


_OVERFLOW = ("--spin, --theta-dot, --phi-dot, --g: the values overflow floating point in the "
             "top's equations; give values of a physical size")


def _params(body, p_opt):
    """The top's TopParams and a label saying where the pivot came from."""
    import numpy as np

    from rbcli.core.inertia import combine
    from rbcli.core.top import PivotAtCom, top_from_body
    from rbcli.errors import InputError

    mp = combine(body.parts)
    if isinstance(p_opt, str):
        P = mp.com.copy() if p_opt == "com" else np.zeros(3)
        label, where = f"--pivot {p_opt}", "--pivot"
    elif p_opt is not None:
        P = np.asarray(p_opt, dtype=float)
        label, where = "--pivot", "--pivot"
    elif body.pivot is not None:
        P = np.asarray(body.pivot, dtype=float)
        label, where = "the body's pivot", body.source
    else:
        P = np.zeros(3)
        label, where = "the origin, as no pivot was given", body.source
    try:
        with np.errstate(over="ignore", invalid="ignore"):
            params = top_from_body(mp.mass, mp.com, mp.inertia_com, P)
    except PivotAtCom as exc:
        raise InputError(f"{where}: {exc}") from None
    except ValueError as exc:
        at = ", ".join(f"{x:.6g}" for x in P)
        raise InputError(f"{body.source}: {exc}; pivot at [{at}] m ({label})") from None
    return params, label


# ----------------------------------------------------------------------------- gyrocompass


@app.command(help=GYRO_HELP)
def gyrocompass(
    body: str = c.BodyArg,
    expr: str = c.ExprOpt,
    ratio: str = typer.Option(None, "--ratio", help="C/A, the axial moment over the moment about the vertical (a flat disk: 2), instead of a body.", show_default=False),
    axis: str = typer.Option(None, "--axis", help="The rotor's spin axis x,y,z (or x, y, z) in the body frame. Default: the body's shaft axis, else z.", show_default=False),
    spin: str = typer.Option(None, "--spin", help="Required. Rotor spin about its axis (rad/s, or e.g. '6000 rpm'); negative = the other way.", show_default=False),
    latitude: str = typer.Option(None, "--latitude", help="Required. Latitude, -90 to 90 (degrees, or with units); negative = south.", show_default=False),
    earth_rate: str = typer.Option("7.2921150e-5", "--earth-rate", help="The Earth's (sidereal) rotation rate (rad/s, or with units)."),
    json_: bool = c.JsonOpt,
    digits: int = c.DigitsOpt,
    units: str = c.UnitsOpt,
) -> None:
    import math

    from rbcli.errors import InputError
    from rbcli.render.fmt import DisplayUnits

    e = c.env()
    du = DisplayUnits.parse(units)
    if spin is None:
        raise InputError("--spin: required: the rotor's spin about its axis, e.g. --spin '6000 rpm'")
    if latitude is None:
        raise InputError("--latitude: required: the latitude in degrees, -90 to 90 (negative = south), e.g. --latitude 52")
    S = c.finite(c.quantity(spin, "angular_speed", "--spin"), "--spin")
    if S == 0.0:
        raise InputError("--spin: must not be 0: a gyrocompass needs a spinning rotor")
    lat = c.finite(c.quantity(latitude, "angle", "--latitude", bare="deg"), "--latitude")
    if abs(lat) > 0.5 * math.pi * (1.0 + 1e-12):
        raise InputError(f"--latitude: must be from -90 to 90 degrees, got {latitude}")
    W = c.finite(c.quantity(earth_rate, "angular_speed", "--earth-rate"), "--earth-rate")
    if not W > 0.0:
        raise InputError(f"--earth-rate: must be positive, got {earth_rate}")
    n_axis = c.direction(axis, "--axis") if axis is not None else None
    r = None
    if ratio is not None:
        r = c.finite(c.quantity(ratio, "dimensionless", "--ratio"), "--ratio")
        if not r > 0.0:
            raise InputError(f"--ratio: C/A must be positive, got {ratio}")
        if body is not None or expr is not None:
            raise InputError("--ratio: give either --ratio or a body (BODY or -e), not both")
        if n_axis is not None:
            raise InputError("--axis: the axis belongs to a body; with --ratio there is no body")
    rotor = None
    if r is None:
        if body is None and expr is None:
            raise InputError("no rotor given: name a BODY file, use -e '{...}', or give --ratio C/A")
        b = c.load_one(body, expr, e)
        rotor = _rotor(b, n_axis)
        r = rotor["C"] / rotor["A"]
    from rbcli.core.top import gyrocompass as gc

    try:
        res = gc(r, S, lat, W)
    except (ValueError, ArithmeticError) as exc:  # the values were checked: what is left overflows
        who = ["--ratio" if rotor is None else rotor["body"].source, "--spin", "--earth-rate"]
        raise InputError(f"{', '.join(who)}: {exc}") from None
    from rbcli.render import top as rt

    c.emit(e, json_, lambda: rt.gyro_json(res, rotor), lambda doc: rt.gyro_document(doc, res, rotor, du, digits))


def _rotor(body, n_axis) -> dict:
    """C and A (about the com) of a body symmetric about its spin axis."""
    import numpy as np

    from rbcli.core.inertia import combine
    from rbcli.core.rolling import wheel_from_body
    from rbcli.errors import InputError

    mp = combine(body.parts)
    if n_axis is not None:
        n, src = np.asarray(n_axis, dtype=float), "--axis"
    elif body.shaft is not None:
        n, src = np.asarray(body.shaft.axis, dtype=float), "the body's shaft"
    else:
        n, src = np.array([0.0, 0.0, 1.0]), "body z (default)"
    n = n / np.linalg.norm(n)
    try:
        w = wheel_from_body(mp.mass, mp.com, mp.inertia_com, n, axle_through=mp.com)
    except ValueError as exc:
        msg = str(exc).replace("body of revolution about the axle", "rotor symmetric about its spin axis")
        msg = msg.replace("axle", "spin axis")
        raise InputError(f"{body.source}: {msg}; spin axis from {src}") from None
    return {"C": float(w.C), "A": float(w.A), "mass": float(mp.mass), "axis": [float(x) for x in n],
            "axis_source": src, "body": body}


# ----------------------------------------------------------------------------- manual

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
        "The pivot is --pivot, else the body's pivot, else the origin. A body that is not "
        "symmetric about the pivot-com line (moments across it differing by more than a "
        "relative 1e-6, or the line not a principal axis) is refused with how asymmetric it "
        "is; a pivot at the com (no gravity torque) is refused with a pointer to free "
        "precession (rbcli precess). Exit status 2 also for --theta outside (0, 180) "
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
        "than 1e-9 (relative to the kinetic energy plus m g l).",
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
        ("path", "waves, loops or cusps (steady precession is waves with steady true)."),
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
        ("verify", "with --verify: {t_end, samples, rtol, max_axis_error (rad), max_theta_error_deg, max_phi_error_deg, max_psi_error_deg, energy_drift, p_phi_drift, p_psi_drift, theta_min_deg, theta_max_deg, mean_precession_rate, nfev, axis_tolerance, energy_tolerance, pass}."),
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
        "z); a body that is not is refused with how asymmetric it is. The latitude is in "
        "degrees unless a unit is given; negative is south.",
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
