"""The SI unit of every number in each command's JSON: the ``unit`` column of ``--format csv``.

The man page states each JSON key's unit in prose; this is the same statement as data. A
unit is ASCII as pint reads it (``kg*m^2``, ``N*s/m``); ``1`` for a dimensionless number.
Two depend on the data (field-balance): ``{reading}``, the readings' SI unit (or
``reading`` for bare readings), and ``{planes}``, the number of planes.

A key is looked up by its ``path`` (list indices dropped: ``corrections[].mass``):

1. ``path``, then the key's own name, in the command's table;
2. a parameter's name: its SI unit (:func:`rbcli.api.params.si_unit`, passed by the cli);
3. ``path``, then the name, in :data:`COMMON` (``mass`` is kg wherever it sits);
4. the name's ending (:data:`SUFFIXES`: ``_deg`` is degrees).

``tests/test_csv_table.py`` fails on a number found nowhere."""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

ONE = "1"
M, KG, S = "m", "kg", "s"
KGM, KGM2 = "kg*m", "kg*m^2"
RADS, DEG, RAD = "rad/s", "deg", "rad"
N, NM, J = "N", "N*m", "J"
L_UNIT = "kg*m^2/s"  # angular momentum
MS, MS2 = "m/s", "m/s^2"
PER_S, PER_S2 = "1/s", "1/s^2"

#: keys every command shares (a body's parts and the like)
COMMON: dict[str, str] = {
    "parts[].mass": KG,
    "parts[].com": M,
    "parts[].volume": "m^3",
    "parts[].area": "m^2",
    "parts[].triangles": ONE,
    "mass": KG,
}

#: unit by the ending of a key's name, when neither the path nor the name is in a table
SUFFIXES: tuple[tuple[str, str], ...] = (
    ("_deg", DEG),
    ("_hz", "Hz"),
    ("_percent", "%"),
    ("_rel_error", ONE),
    ("_relative", ONE),
    ("_ratio", ONE),
)

#: the slightly asymmetric body's description shared by top, gyrocompass and rollcheck
_ASYMMETRY = {
    "asymmetry.transverse_moments": KGM2,
    "asymmetry.relative": ONE,
    "asymmetry.coupling": KGM2,
    "asymmetry.principal_axis_tilt": RAD,
    "asymmetry.com_offset": M,
    "asymmetry.tolerance": ONE,
}

UNITS: dict[str, dict[str, str]] = {
    "inertia": {
        "com": M, "reference": M, "inertia": KGM2, "inertia_com": KGM2,
        "axis_moment": KGM2,
        "angular_momentum": L_UNIT, "kinetic_energy": J,
    },
    "principal": {
        "reference": M, "moments": KGM2, "axes": ONE, "free_axes": ONE,
        "rotation_axis": ONE, "equivalent_box": M, "equivalent_ellipsoid": M,
    },
    "balance": {
        "eccentricity": M, "static_unbalance": KGM, "couple_unbalance": KGM2,
        "moment_unbalance": KGM2, "principal_gap": KGM2,
        "tolerances.eccentricity": M, "tolerances.couple_unbalance": KGM2, "rtol": ONE,
        "com_shaft": M, "shaft.axis": ONE, "shaft.through": M, "shaft.x_axis": ONE,
        "shaft.y_axis": ONE,
        "plane": M, "unbalance": KGM, "force": N, "equivalent_unbalance": KGM,
        "static_load": N, "narrow_ratio": ONE, "narrow_reference": M,
        "position": ONE, "n_positions": ONE,
        "dynamics.speed": RADS, "centrifugal_force": N,
        "dynamics.angular_momentum": L_UNIT, "torque": NM, "torque_magnitude": NM,
        "torque_origin": NM,
        "iso.grade": "mm/s", "grade_si": MS, "iso.speed": RADS,
        "permissible_eccentricity": M, "permissible_unbalance": KGM, "allowed": KGM,
        "unclamped": KGM, "residual": KGM, "ratio": ONE, "achieved_grade": "mm/s",
        "static_achieved_grade": "mm/s", "iso.planes": M,
        "apply.parts[].at": M,
    },
    "field-balance": {
        "planes": ONE, "mass_trial_on": KG,
        "influence[][].magnitude": "{reading}/kg", "alpha[][].magnitude": "{reading}/kg",
        "cond": ONE, "det_magnitude": "({reading}/kg)^{planes}",
        "predicted_residual": "{reading}", "residual_values": "{reading}",
        "residual_max": "{reading}", "residual_rms": "{reading}",
        "amplitude": "{reading}", "initial": "{reading}",
        "factor": ONE, "significance_limit": ONE,
        "position": ONE,
        "severity.boundaries": "m/s", "severity.group": ONE,
        "severity.readings[].before": "m/s", "severity.readings[].after": "m/s",
        "fraction": ONE, "force": N,
        "expected_change": "{reading}",
        "readings.g": MS2, "count": ONE,
        "fitted.drawer.objective": "{reading}", "violation": ONE, "examined": ONE,
        "fitted.drawer.planes[].radius": M, "per_hole": ONE, "max_weights": ONE, "max_mass": KG,
        "fitted.drawer.planes[].drawer": ONE, "limits.objective": "{reading}", "max_unbalance": KGM,
        "limits.planes[].unbalance": KGM, "limits.readings[].limit": "{reading}",
        "objective_without": "{reading}", "robust.threshold": ONE, "robust.weights": ONE,
    },
    "precess": {
        "angular_momentum": L_UNIT, "angular_momentum_norm": L_UNIT,
        "kinetic_energy": J, "period": S, "circles_axis": ONE,
        "precession_rate": RADS, "space_precession_rate": RADS,
        "flip_interval": S, "first_flip": S, "flip_interval_estimate": S,
        "principal_moments": KGM2, "principal_axes": ONE, "symmetry_axis": ONE,
        "spin_rate": RADS, "wobble_to_spin": ONE, "wobble_period": S,
        "space_precession_period": S, "precession_per_period": RAD,
        "mean_precession_rate": RADS,
        "elliptic_parameter": ONE, "elliptic_complement": ONE, "elliptic_rate": PER_S,
        "linear_rates": PER_S,
        "at.t": S, "quaternion": ONE, "rotation_axis": ONE, "rotation_matrix": ONE,
        "periods": ONE,
        "verify.t_end": S, "rtol": ONE, "nfev": ONE,
        "omega_error": ONE, "attitude_error": RAD,
        "numeric_energy_drift": ONE, "numeric_momentum_drift": ONE, "numeric_L_drift": ONE,
        "exact_energy_drift": ONE, "exact_momentum_drift": ONE, "exact_L_drift": ONE,
        "tol": ONE,
        "csv.duration": S,
    },
    "top": {
        "length": M, "I": KGM2, "Is": KGM2, "I_com": KGM2,
        "steady_precession_rates": RADS, "horizontal_precession_rate": RADS,
        "critical_spin": RADS, "nutation_period": S, "mean_precession_rate": RADS,
        "theta_dot0": RADS, "phi_dot0": RADS, "minimum_spin_for_steady": RADS,
        "steady_nutation_frequencies": RADS, "steady_precession_estimates": RADS,
        "nutation_frequency": RADS, "mean_spin_rate": RADS,
        "precession_per_nutation": RAD, "spin_per_nutation": RAD,
        "goldstein.a": PER_S, "goldstein.b": PER_S, "goldstein.alpha": PER_S2,
        "goldstein.beta": PER_S2,
        "turning_points": ONE, "elliptic_parameter": ONE, "apex_u": ONE,
        "axis": ONE, "com": M,
        **_ASYMMETRY,
        "t_end": S, "rtol": ONE, "nfev": ONE, "max_axis_error": RAD,
        "energy_drift": ONE, "p_phi_drift": ONE, "p_psi_drift": ONE,
        "axis_tolerance": RAD, "energy_tolerance": ONE,
        "csv.rows": ONE, "csv.duration": S,
    },
    "gyrocompass": {
        "A": KGM2, "C": KGM2, "I": KGM2, "Is": KGM2, "C_over_A": ONE, "Is_over_I": ONE,
        "directive": PER_S2,
        "omega0": RADS, "omega0_approx": RADS, "period": S, "period_approx": S,
        "axis": ONE,
        **_ASYMMETRY,
    },
    "rollcheck": {
        "radius": M, "I": KGM2, "Is": KGM2, "I_contact": KGM2, "Is_contact": KGM2,
        "critical_spin": RADS, "critical_speed": MS, "speed": MS, "margin": ONE,
        "circle.radius": M, "turn_rate": RADS, "contact_radius": M,
        "kappa": NM, "lean_frequency": RADS, "growth_rate": PER_S,
        "lean_frequency_squared": "rad^2/s^2",
        "axle": ONE, "axle_through": M, "com": M,
        "band_width": M, "band_edges": M, "knife_edge_critical_spin": RADS,
        "knife_edge_critical_speed": MS,
        **_ASYMMETRY,
    },
    "materials": {"density": "kg/m^3"},
    "whirl": {
        "bearings[].plane": M,
        "speeds": RADS, "frequencies": RADS, "frequency": RADS,
        "damping_ratio": ONE, "log_decrement": ONE,
        "damped_speed": RADS, "node": M, "order": ONE,
        "amplification_factor": ONE, "bearing": ONE, "plane": M,
        "operating_speed": RADS, "modes_speed": RADS,
        "polar_moment": KGM2, "transverse_moment": KGM2, "transverse_moments": KGM2,
        "displacement": M, "displacement_minor": M, "force": N, "rigid_force": N,
        "amplitude": M, "half_power": RADS, "amount": KGM,
        "rotor.asymmetry": ONE, "rotor.com": M, "couple_unbalance": KGM2,
        "eccentricity": M, "static_unbalance": KGM,
        "least_damping_ratio": ONE, "least_damping_speed": RADS, "onset_speeds": RADS,
        "cross_damping": "N*s/m", "forward_share": ONE,
        "bearing_forward_share": ONE, "branch": ONE, "threshold_speed": RADS,
        "stability.thresholds[].mode": ONE, "searched": RADS,
        **dict.fromkeys(("kxx", "kxy", "kyx", "kyy"), "N/m"),
        **dict.fromkeys(("cxx", "cxy", "cyx", "cyy"), "N*s/m"),
    },
}

#: list indices in a JSON path: ``corrections[1].mass`` -> ``corrections[].mass``
_INDEX = re.compile(r"\[\d+\]")


def _name(pattern: str) -> str:
    """The key's own name in a path pattern: ``iso.allowed[]`` -> ``allowed``."""
    return pattern.replace("[]", "").rsplit(".", 1)[-1]


def lookup(command: str, path: str, params: Mapping[str, str] | None = None) -> str | None:
    """The unit template of the number at JSON ``path`` of ``command``'s JSON (see the
    module docstring; ``params``: the SI unit of each of its parameters), or None when no
    table or rule gives one."""
    pattern = _INDEX.sub("[]", path)
    while pattern.endswith("[]"):
        pattern = pattern[:-2]
    table, name = UNITS.get(command, {}), _name(pattern)
    for u in (table.get(pattern), table.get(name), (params or {}).get(name) or None,
              COMMON.get(pattern), COMMON.get(name)):
        if u is not None:
            return u
    for end, u in SUFFIXES:
        if name.endswith(end):
            return u
    return None


def unit(command: str, path: str, data: Any, params: Mapping[str, str] | None = None) -> str:
    """The unit of the number at ``path`` in ``data`` (the command's JSON), or ``""``."""
    u = lookup(command, path, params)
    if u is None:
        return ""
    if "{" in u:
        readings = data.get("readings") if isinstance(data, dict) else None
        reading = readings.get("unit") if isinstance(readings, dict) else None
        planes = data.get("planes") if isinstance(data, dict) else None
        u = u.replace("{reading}", reading if isinstance(reading, str) and reading else "reading")
        u = u.replace("{planes}", str(planes) if isinstance(planes, int) else "P")
    return u
