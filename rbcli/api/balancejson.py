"""The JSON form of the balancing results of :mod:`rbcli.core.balance` (SPEC §3).

One function per core result, each the dict that ``rbcli balance --json`` prints for it:
SI units, angles in degrees in the reported sense, an angle of a zero quantity reported 0
with ``*_angle_defined`` false. :func:`balance_json` puts them together in the order of the
command's document. Plain Python data; the finiteness check is
:func:`rbcli.api.result.jsonable`'s.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from rbcli.core.balance import angle_of

if TYPE_CHECKING:  # pragma: no cover
    from rbcli.core import balance as B

__all__ = ["frame_json", "unbalance_json", "plane_correction_json", "residual_json",
           "corrections_json", "positions_json", "bearing_forces_json", "allocation_json",
           "iso_state_json", "iso_json", "balance_json"]


def _f(x: float) -> float | None:
    """Plain finite float, or None."""
    x = float(x)
    return x if math.isfinite(x) else None


def _phasor(key: str, z: complex, tol: float, sense: str, angle: str | None = None) -> dict:
    """``{key: |z|, <angle>angle_deg, <angle>angle_defined}``; ``angle`` is ``key + "_"``
    unless given."""
    a, ok = angle_of(z, tol, sense)
    angle = f"{key}_" if angle is None else angle
    return {key: float(abs(z)), f"{angle}angle_deg": a, f"{angle}angle_defined": ok}


def _floats(v) -> list[float]:
    return [float(x) for x in v]


def frame_json(f: B.ShaftFrame) -> dict:
    return {"axis": _floats(f.rotation[2]), "through": _floats(f.origin),
            "x_axis": _floats(f.rotation[0]), "y_axis": _floats(f.rotation[1])}


def unbalance_json(u: B.Unbalance) -> dict:
    s = u.angle_sense
    return {
        "mass": float(u.mass),
        "eccentricity": float(u.eccentricity),
        **_phasor("static_unbalance", u.static, u.tol_static, s),
        **_phasor("couple_unbalance", u.couple, u.tol_couple, s),
        **_phasor("moment_unbalance", u.moment, u.tol_moment, s),
        "tilt_deg": float(u.tilt_deg),
        "tilt_azimuth_deg": float(u.tilt_azimuth_deg),
        "tilt_azimuth_defined": bool(u.tilt_azimuth_defined),
        "tilt_well_defined": bool(u.tilt_well_defined),
        "principal_gap": float(u.principal_gap),
        "statically_balanced": bool(u.statically_balanced),
        "dynamically_balanced": bool(u.dynamically_balanced),
        "tolerances": {
            "eccentricity": float(u.tol_eccentricity),
            "couple_unbalance": float(u.tol_couple),
            "rtol": float(u.rtol),
            "rule": (
                "statically balanced: eccentricity <= rtol * max(sqrt(trace(J_G)/M), "
                "|com - through|); dynamically balanced: also couple <= rtol * trace(J_G)"
            ),
        },
        "com_shaft": _floats(u.com_shaft),
        "shaft": frame_json(u.frame),
        "angle_sense": u.angle_sense,
        "warnings": list(u.warnings),
    }


def plane_correction_json(pc: B.PlaneCorrection) -> dict:
    return {
        "plane": None if pc.z is None else float(pc.z),
        "name": pc.name,
        "mass": float(pc.mass),
        "radius": float(pc.radius),
        "angle_deg": float(pc.angle_deg),
        "angle_defined": bool(pc.angle_defined),
        "remove_angle_deg": float(pc.remove_angle_deg),
        "unbalance": float(abs(pc.unbalance)),
    }


def residual_json(r: B.Residual) -> dict:
    s = r.angle_sense
    return {
        "mass": float(r.mass),
        "eccentricity": float(r.eccentricity),
        **_phasor("static_unbalance", r.static, r.tol_static, s),
        **_phasor("couple_unbalance", r.couple, r.tol_couple, s),
        "planes": [{"plane": float(z), **_phasor("unbalance", u, r.tol_plane, s, angle="")}
                   for z, u in zip(r.planes, r.plane_unbalances)],
    }


def corrections_json(c: B.Corrections) -> dict:
    return {
        "corrections": [plane_correction_json(c.a), plane_correction_json(c.b)],
        "static_correction": plane_correction_json(c.static),
        "narrow_planes": bool(c.narrow_planes),
        "narrow_ratio": None if c.narrow_ratio is None else _f(c.narrow_ratio),
        "narrow_reference": float(c.narrow_reference),
        "narrow_reference_kind": c.narrow_reference_kind,
        "residual": residual_json(c.residual),
        "rounded": bool(c.rounded),
        "mass_step": None if c.mass_step is None else float(c.mass_step),
        "angle_step_deg": None if c.angle_step_deg is None else float(c.angle_step_deg),
        "ideal": (
            None if c.ideal is None else [plane_correction_json(c.ideal.a), plane_correction_json(c.ideal.b)]
        ),
        "angle_sense": c.source.angle_sense,
        "warnings": list(c.warnings),
    }


def positions_json(p: B.PositionCorrections) -> dict:
    rows = [{"plane": float(pc.z) if pc.z is not None else None, "name": pc.name, "position": int(k),
             "angle_deg": float(a), "mass": float(m), "radius": float(pc.radius)}
            for pc, sp in zip(p.ideal.pair, p.splits)
            for m, a, k in zip(sp.masses, sp.angles_deg, sp.positions)]
    return {
        "n_positions": int(p.n_positions),
        "pitch_deg": float(p.pitch_deg),
        "offset_deg": float(p.offset_deg),
        "masses": rows,
        "mass_step": None if p.mass_step is None else float(p.mass_step),
        "rounded": p.mass_step is not None,
        "residual": residual_json(p.corrections.residual),
    }


def bearing_forces_json(bf: B.BearingForces) -> dict:
    rows = [{"plane": float(z), "name": str(i + 1), **_phasor("force", F, bf.tol_force, bf.angle_sense, angle=""),
             "equivalent_unbalance": float(abs(u)), "static_load": float(W)}
            for i, (z, F, u, W) in enumerate(zip(bf.bearings or (), bf.forces, bf.plane_unbalances,
                                                 bf.static_loads))]
    return {
        "speed": float(bf.speed),
        "bearing_forces": rows,
        "g": float(bf.g),
        "static_load_assumption": "shaft horizontal, gravity at right angles to it",
        "centrifugal_force": float(abs(bf.centrifugal_force)),
        "angular_momentum": [float(v) + 0.0 for v in bf.angular_momentum],
        "torque": [float(v) + 0.0 for v in bf.torque],
        "torque_magnitude": float(np.linalg.norm(bf.torque)),
        "torque_origin": [float(v) + 0.0 for v in bf.torque_origin],
        "frame": "shaft (rotor-fixed)",
    }


def allocation_json(a: B.Allocation) -> dict:
    return {
        "allowed": _floats(a.allowed),
        "unclamped": _floats(a.unclamped),
        "kind": a.kind,
        "rule": a.rule,
        "rbcli_rule": bool(a.rbcli_rule),
    }


def iso_state_json(st: B.IsoState, tol: float = 0.0, sense: str = "with") -> dict:
    return {
        "residual": [float(abs(u)) for u in st.residual],
        "residual_angle_deg": [angle_of(u, tol, sense)[0] for u in st.residual],
        "residual_angle_defined": [angle_of(u, tol, sense)[1] for u in st.residual],
        "ratio": [_f(r) for r in st.ratio],
        "achieved_grade": [_f(g) for g in st.achieved_grade],
        "static_unbalance": float(st.static_unbalance),
        "static_achieved_grade": float(st.static_achieved_grade),
        "pass": bool(st.passed),
    }


def iso_json(iso: B.IsoCheck) -> dict:
    st = iso.before  # residual, ratio, pass: the rotor as given (SPEC §3)
    after = None
    if iso.after is not None:
        after = iso_state_json(iso.after, iso.tol_plane, iso.angle_sense)
        after["state"] = iso.after_state
        after["prediction"] = True
    return {
        "grade": float(iso.grade),
        "grade_si": float(iso.grade) * 1e-3,
        "speed": float(iso.speed),
        "mass": float(iso.mass),
        "permissible_eccentricity": float(iso.permissible_eccentricity),
        "permissible_unbalance": float(iso.permissible_unbalance),
        "allowed": _floats(iso.allocation.allowed),
        "residual": [float(abs(u)) for u in st.residual],
        "ratio": [_f(r) for r in st.ratio],
        "achieved_grade": [_f(g) for g in st.achieved_grade],
        "static_achieved_grade": float(st.static_achieved_grade),
        "pass": bool(iso.passed),
        "judged": "as given",
        "planes": _floats(iso.planes),
        "planes_are": iso.planes_are,
        "allocation": allocation_json(iso.allocation),
        "before": iso_state_json(iso.before, iso.tol_plane, iso.angle_sense),
        "after": after,
        "warnings": list(iso.warnings),
    }


def balance_json(
    unb: B.Unbalance,
    corrections: B.Corrections | None = None,
    forces: B.BearingForces | None = None,
    iso: B.IsoCheck | None = None,
) -> dict:
    """The SPEC §3 part of ``rbcli balance --json`` (SI, no NaN): :func:`unbalance_json`'s
    keys, and ``corrections``, ``static_correction``, ``correction_details``,
    ``bearing_forces``, ``dynamics`` and ``iso`` when asked for (the man page lists them)."""
    d = unbalance_json(unb)
    if corrections is not None:
        cj = corrections_json(corrections)
        d["corrections"] = cj.pop("corrections")
        d["static_correction"] = cj.pop("static_correction")
        d["correction_details"] = cj
    if forces is not None:
        fj = bearing_forces_json(forces)
        rows = fj.pop("bearing_forces")
        if forces.bearings is not None:
            d["bearing_forces"] = rows
        d["dynamics"] = fj
    if iso is not None:
        d["iso"] = iso_json(iso)
    return d
