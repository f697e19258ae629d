"""Tests of rbcli.body.bodyfile: the body-file loader.

What is checked, and against what:

- every primitive shape read from YAML gives the mass, com and inertia of
  ``rbcli.core.shapes.geometry`` (tested on its own against textbooks) scaled by the
  mass and placed by ``at`` and a rotation built here by scipy's ``Rotation``;
- placement: ``at``, ``axis`` and the four ``rotate`` forms against scipy ``Rotation``
  (an independent oracle), bare angles in degrees or in the file's angle unit;
- mass keys: mass, density, areal_density, linear_density (and the wrong one refused
  with the right one named), subtract and cut_from against closed forms worked here;
- ``given`` with a matrix and with the map in both product conventions;
- ``include``: relative paths, placement, "sub/part" names, cycles, missing files;
- ``units`` and quantity strings: a mm/g body equals the m/kg body;
- the one-part shorthand;
- errors: a table of (YAML, line, column, message fragment), each an InputError at the
  place a person would look, with a message that says what is wrong.

Tolerances: sums of a few products of O(1) numbers carry a few ulp of round-off, so
"exact" comparisons use rtol 1e-12 (about 5000 ulp: generous for ~10 operations, far
below any modelling error a wrong formula would make, which is O(1) relative).
"""

from __future__ import annotations

import json
import math
import textwrap
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from rbcli.core import shapes as shp
from rbcli.core.inertia import combine
from rbcli.errors import InputError
from rbcli.body.model import load_body, load_expr, load_text

RTOL = 1e-12  # a few ulp of ~10 float operations, with a wide margin (see module doc)


def load(text: str, base: Path | None = None, name: str = "t.yaml"):
    return load_text(textwrap.dedent(text), name, base or Path.cwd())


def massprops(text: str, base: Path | None = None):
    return combine(load(text, base).parts)


def flow(value) -> str:
    """A Python value as YAML flow text (JSON is valid YAML 1.2)."""
    return json.dumps(value)


def error_of(text: str, base: Path | None = None, name: str = "t.yaml") -> InputError:
    with pytest.raises(InputError) as info:
        load(text, base, name)
    return info.value


def close(a, b, rtol=RTOL, scale=None):
    """Compare arrays relative to the larger of their magnitudes (or ``scale``)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    s = scale if scale is not None else max(float(np.max(np.abs(a))), float(np.max(np.abs(b))), 1e-300)
    return float(np.max(np.abs(a - b))) <= rtol * s


# --------------------------------------------------------------------------- every shape

SHAPE_CASES = {
    "point": {},
    "rod": {"length": 0.7},
    "ring": {"radius": 0.3},
    "disk": {"radius": 0.3, "inner_radius": 0.1},
    "plate": {"size": [0.4, 0.2]},
    "plate-thick": {"size": [0.4, 0.2], "thickness": 0.05},
    "triangle": {"vertices": [[0, 0, 0], [0.3, 0.05, 0], [0.1, 0.2, 0.02]]},
    "box": {"size": [0.3, 0.2, 0.1]},
    "cylinder": {"radius": 0.1, "length": 0.5, "inner_radius": 0.04},
    "cylinder-shell": {"radius": 0.1, "length": 0.5, "shell": True},
    "sphere": {"radius": 0.2, "inner_radius": 0.15},
    "sphere-shell": {"radius": 0.2, "shell": True},
    "hemisphere": {"radius": 0.25},
    "cone": {"radius": 0.1, "height": 0.4},
    "ellipsoid": {"semi_axes": [0.1, 0.2, 0.3]},
    "torus": {"major_radius": 0.3, "minor_radius": 0.05},
}

AT = [0.3, -1.2, 2.5]
QUAT_WXYZ = [0.8, 0.2, -0.4, 0.4]  # normalised by the loader (|q| = 1.0 here anyway)


def _shape_of(case: str) -> str:
    return case.split("-")[0]


@pytest.mark.parametrize("case", list(SHAPE_CASES))
def test_every_shape_with_mass_is_the_core_geometry_scaled_and_placed(case):
    shape, params = _shape_of(case), SHAPE_CASES[case]
    m = 2.5
    body = load(
        f"parts:\n  - {{name: p, shape: {shape}, mass: {m}, at: {flow(AT)}, "
        f"rotate: {{quaternion: {flow(QUAT_WXYZ)}}}"
        + "".join(f", {k}: {flow(v)}" for k, v in params.items())
        + "}\n"
    )
    (part,) = body.parts
    geo = shp.geometry(shape, **params)
    w, x, y, z = QUAT_WXYZ
    R = Rotation.from_quat([x, y, z, w]).as_matrix()  # scipy: scalar-last
    assert part.mass == pytest.approx(m, rel=RTOL)
    assert close(part.com, np.array(AT) + R @ geo.com)
    assert close(part.inertia_com, m * R @ geo.unit_inertia @ R.T)
    assert part.name == "p" and part.shape == shape and not part.subtract
    assert close(part.axis, R[:, 2])


DENSITY_KEY = {"volume": "density", "area": "areal_density", "length": "linear_density"}


@pytest.mark.parametrize("case", [c for c in SHAPE_CASES if c != "point"])
def test_every_shape_with_its_density_has_mass_density_times_measure(case):
    shape, params = _shape_of(case), SHAPE_CASES[case]
    geo = shp.geometry(shape, **params)
    key = DENSITY_KEY[geo.measure_kind]
    rho = 1234.5
    body = load(
        f"parts:\n  - {{shape: {shape}, {key}: {rho}"
        + "".join(f", {k}: {flow(v)}" for k, v in params.items())
        + "}\n"
    )
    (part,) = body.parts
    assert part.mass == pytest.approx(rho * geo.measure, rel=RTOL)
    assert close(part.inertia_com, part.mass * geo.unit_inertia)
    assert part.measure == pytest.approx(geo.measure, rel=RTOL)


def test_measures_are_the_textbook_ones():
    # independent of core.shapes: V = pi r^2 L, A = pi (R^2 - r^2), L = 2 pi R, ...
    def mass_of(line):
        return load(f"parts:\n  - {line}\n").parts[0].mass

    # one multiplication and one pi each: rtol 1e-12 is round-off with a wide margin
    assert mass_of("{shape: cylinder, radius: 0.1, length: 2, density: 1000}") == pytest.approx(
        1000 * math.pi * 0.01 * 2, rel=RTOL)
    assert mass_of("{shape: disk, radius: 0.3, inner_radius: 0.1, areal_density: 2}") == pytest.approx(
        2 * math.pi * (0.09 - 0.01), rel=RTOL)
    assert mass_of("{shape: ring, radius: 0.5, linear_density: 3}") == pytest.approx(3 * 2 * math.pi * 0.5, rel=RTOL)
    assert mass_of("{shape: sphere, radius: 0.5, shell: true, areal_density: 3}") == pytest.approx(
        3 * 4 * math.pi * 0.25, rel=RTOL)
    assert mass_of("{shape: plate, size: [2, 3], thickness: 0.01, density: 100}") == pytest.approx(6.0, rel=RTOL)
    assert mass_of("{shape: rod, from: [0, 0, 0], to: [3, 4, 0], linear_density: 2}") == pytest.approx(10.0, rel=RTOL)


# --------------------------------------------------------------------------- placement

def _probe_body(rotate_yaml: str) -> tuple[np.ndarray, np.ndarray]:
    """A part whose com and inertia reveal its rotation: a 'given' part with an off-centre
    com and three different moments."""
    mp = massprops(
        f"""\
        parts:
          - shape: given
            mass: 2
            com: [0.1, 0.2, 0.3]
            inertia: [[1, 0, 0], [0, 2, 0], [0, 0, 2.5]]
            at: [1, 2, 3]
            {rotate_yaml}
        """
    )
    return mp.com, mp.inertia_com


def _expected(R: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    com = np.array([1, 2, 3]) + R @ np.array([0.1, 0.2, 0.3])
    return com, R @ np.diag([1.0, 2.0, 2.5]) @ R.T


def _check_rotation(rotate_yaml: str, R: np.ndarray) -> None:
    com, J = _probe_body(rotate_yaml)
    ecom, eJ = _expected(R)
    # rotation matrices built two ways (scipy vs rbcli.core.rotation) agree to ~1e-16;
    # 1e-12 relative leaves room for the trigonometry of large angles
    assert close(com, ecom, scale=4.0)
    assert close(J, eJ, scale=2.5)


angles = st.floats(-360, 360, allow_nan=False)
unit_vectors = st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda v: np.linalg.norm(v) > 0.1)


@settings(max_examples=30, deadline=None)
@given(axis=unit_vectors, angle=angles)
def test_rotate_axis_angle_matches_scipy(axis, angle):
    n = np.array(axis) / np.linalg.norm(axis)
    R = Rotation.from_rotvec(n * math.radians(angle)).as_matrix()
    _check_rotation(f"rotate: {{axis: {flow(list(axis))}, angle: {angle!r}}}", R)


@settings(max_examples=30, deadline=None)
@given(
    a=st.tuples(angles, angles, angles),
    seq=st.sampled_from(["ZYX", "XYZ", "ZXZ", "zyx", "xyz", "zxz", "YXY"]),
)
def test_rotate_euler_matches_scipy_intrinsic_and_extrinsic(a, seq):
    R = Rotation.from_euler(seq, a, degrees=True).as_matrix()
    _check_rotation(f"rotate: {{euler: {flow(list(a))}, seq: {seq}}}", R)


@settings(max_examples=30, deadline=None)
@given(q=st.tuples(*[st.floats(-1, 1)] * 4).filter(lambda q: np.linalg.norm(q) > 0.1))
def test_rotate_quaternion_wxyz_matches_scipy_scalar_last(q):
    w, x, y, z = q
    R = Rotation.from_quat([x, y, z, w]).as_matrix()  # scipy normalises too
    _check_rotation(f"rotate: {{quaternion: {flow(list(q))}}}", R)


@settings(max_examples=20, deadline=None)
@given(rv=st.tuples(*[st.floats(-3, 3)] * 3))
def test_rotate_matrix_matches_scipy(rv):
    R = Rotation.from_rotvec(rv).as_matrix()
    _check_rotation(f"rotate: {{matrix: {flow(R.tolist())}}}", R)


def test_angles_in_the_files_angle_unit_and_with_units():
    R = Rotation.from_rotvec([0, 0, 0.5]).as_matrix()
    _check_rotation("rotate: {axis: [0, 0, 1], angle: '0.5 rad'}", R)
    mp = massprops(
        """\
        units: {angle: rad}
        parts:
          - {shape: given, mass: 2, com: [0.1, 0.2, 0.3], inertia: [[1, 0, 0], [0, 2, 0], [0, 0, 2.5]],
             at: [1, 2, 3], rotate: {axis: [0, 0, 1], angle: 0.5}}
        """
    )
    assert close(mp.com, _expected(R)[0], scale=4.0)  # bare 0.5 is in the file's unit, rad
    assert close(mp.inertia_com, _expected(R)[1], scale=2.5)
    # bare angles default to degrees: 30 (bare) == '30 deg' == pi/6 rad
    R30 = Rotation.from_rotvec([0, 0, math.pi / 6]).as_matrix()
    _check_rotation("rotate: {axis: [0, 0, 1], angle: 30}", R30)
    _check_rotation("rotate: {axis: [0, 0, 1], angle: '30 deg'}", R30)


@settings(max_examples=30, deadline=None)
@given(d=unit_vectors)
def test_axis_turns_local_z_onto_the_direction(d):
    n = np.array(d) / np.linalg.norm(d)
    body = load(f"parts:\n  - {{shape: rod, length: 2, mass: 3, axis: {flow(list(d))}, at: [1, 0, 0]}}\n")
    (p,) = body.parts
    assert close(p.axis, n, scale=1.0)
    # a thin rod has no moment about its own axis and m L^2/12 = 1 about any axis across it
    assert abs(n @ p.inertia_com @ n) <= 1e-12  # round-off of a rotated 3x3 product
    perp = np.cross(n, [0.3, 0.5, 0.7])
    perp /= np.linalg.norm(perp)
    assert perp @ p.inertia_com @ perp == pytest.approx(1.0, rel=1e-12)


def test_at_places_the_local_origin_not_the_com():
    # the hemisphere's local origin is the centre of its flat face; its com is 3R/8 above
    p = load("parts:\n  - {shape: hemisphere, radius: 0.8, mass: 1, at: [1, 2, 3], axis: [1, 0, 0]}\n").parts[0]
    assert close(p.com, [1 + 3 * 0.8 / 8, 2, 3], scale=3.0)


def test_rod_from_to_places_the_rod_between_its_ends():
    p = load("parts:\n  - {shape: rod, from: [1, 1, 0], to: [1, 1, 2], mass: 3}\n").parts[0]
    assert close(p.com, [1, 1, 1], scale=1.0)
    # m L^2 / 12 = 3 * 4 / 12 = 1 across the rod, 0 along it
    assert close(p.inertia_com, np.diag([1.0, 1.0, 0.0]), scale=1.0)


# --------------------------------------------------------------------------- mass keys

@pytest.mark.parametrize(
    "line, right",
    [
        ("{shape: box, size: [1, 1, 1], areal_density: 1}", "'density'"),
        ("{shape: box, size: [1, 1, 1], linear_density: 1}", "'density'"),
        ("{shape: plate, size: [1, 1], density: 1}", "'areal_density'"),
        ("{shape: plate, size: [1, 1], thickness: 0.1, areal_density: 1}", "'density'"),
        ("{shape: disk, radius: 1, density: 1}", "'areal_density'"),
        ("{shape: sphere, radius: 1, shell: true, density: 1}", "'areal_density'"),
        ("{shape: cylinder, radius: 1, length: 1, shell: true, linear_density: 1}", "'areal_density'"),
        ("{shape: rod, length: 1, density: 1}", "'linear_density'"),
        ("{shape: ring, radius: 1, areal_density: 1}", "'linear_density'"),
        ("{shape: point, density: 1}", "give its mass"),
    ],
)
def test_wrong_density_kind_names_the_right_one(line, right):
    err = error_of(f"parts:\n  - {line}\n")
    assert right in err.message and "does not apply" in err.message
    assert err.where.line == 2


def test_a_part_needs_a_mass_and_only_one():
    assert "needs its mass or density" in error_of("parts:\n  - {shape: box, size: [1, 1, 1]}\n").message
    err = error_of("parts:\n  - {shape: box, size: [1, 1, 1], mass: 1, density: 2}\n")
    assert "both 'mass' and 'density'" in err.message


def test_subtract_and_cut_from_against_a_hand_computed_plate_with_a_hole():
    # steel plate a x b x c with a round hole of radius r through it at (x0, y0) from its centre
    a, b, c, r, x0, y0, rho = 0.4, 0.3, 0.02, 0.05, 0.1, -0.05, 7850.0
    mp = massprops(
        f"""\
        parts:
          - {{name: plate, shape: box, size: [{a}, {b}, {c}], density: {rho}}}
          - {{name: hole, shape: cylinder, radius: {r}, length: {c}, subtract: true, cut_from: plate,
             at: [{x0}, {y0}, 0]}}
        """
    )
    mb, mh = rho * a * b * c, rho * math.pi * r * r * c
    m = mb - mh
    assert mp.mass == pytest.approx(m, rel=RTOL)
    assert close(mp.com, [-mh * x0 / m, -mh * y0 / m, 0], scale=0.1)
    # about the plate's centre O: J_O = box - (hole about its com + mh (d.d E - d d^T))
    Jb = mb / 12 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])
    Jh = mh * np.diag([(3 * r * r + c * c) / 12, (3 * r * r + c * c) / 12, r * r / 2])
    d = np.array([x0, y0, 0.0])
    JO = Jb - (Jh + mh * (d @ d * np.eye(3) - np.outer(d, d)))
    g = mp.com
    J_expected = JO - m * (g @ g * np.eye(3) - np.outer(g, g))  # move from O to the com
    # parallel-axis shifts of ~1e-3 relative on O(1) entries: 1e-10 covers the cancellation
    assert close(mp.inertia_com, J_expected, rtol=1e-10)


def test_cut_from_needs_subtract_and_an_earlier_part_with_the_same_kind_of_density():
    assert "needs 'subtract: true'" in error_of(
        "parts:\n  - {name: a, shape: box, size: [1, 1, 1], density: 1}\n"
        "  - {name: b, shape: box, size: [0.1, 0.1, 0.1], cut_from: a}\n").message
    err = error_of(
        "parts:\n  - {name: a, shape: box, size: [1, 1, 1], density: 1}\n"
        "  - {name: b, shape: box, size: [0.1, 0.1, 0.1], cut_from: aa, subtract: true}\n")
    assert "no earlier part is named 'aa'" in err.message and "did you mean 'a'" in err.message
    err = error_of(
        "parts:\n  - {name: a, shape: plate, size: [1, 1], areal_density: 1}\n"
        "  - {name: b, shape: box, size: [0.1, 0.1, 0.1], cut_from: a, subtract: true}\n")
    assert "an areal_density" in err.message and "needs a density" in err.message


def test_cut_from_a_part_given_by_mass_takes_its_mean_density():
    # 1 m^3 of 8 kg: 8 kg/m^3; a 0.5 m cube cut from it removes 8 * 0.125 = 1 kg
    mp = massprops(
        "parts:\n  - {name: a, shape: box, size: [1, 1, 1], mass: 8}\n"
        "  - {name: b, shape: box, size: [0.5, 0.5, 0.5], cut_from: a, subtract: true, at: [0.25, 0, 0]}\n"
    )
    assert mp.mass == pytest.approx(7.0, rel=RTOL)
    assert close(mp.com, [-0.25 / 7, 0, 0], scale=1.0)


# --------------------------------------------------------------------------- given

GIVEN_J = np.array([[2.0, -0.3, 0.1], [-0.3, 3.0, -0.2], [0.1, -0.2, 4.0]])  # tensor convention


def test_given_with_a_matrix_and_with_both_map_conventions_agree():
    as_matrix = massprops(
        f"parts:\n  - {{shape: given, mass: 5, com: [1, 0, 0], inertia: {flow(GIVEN_J.tolist())}, "
        "convention: tensor}\n")
    # the same matrix with positive products: off-diagonals negated
    P = np.where(np.eye(3, dtype=bool), GIVEN_J, -GIVEN_J)
    as_positive = massprops(
        f"parts:\n  - {{shape: given, mass: 5, com: [1, 0, 0], inertia: {flow(P.tolist())}, "
        "convention: positive}\n")
    tensor_map = massprops(
        "parts:\n  - {shape: given, mass: 5, com: [1, 0, 0], inertia: "
        "{Ixx: 2, Iyy: 3, Izz: 4, Ixy: -0.3, Iyz: -0.2, Izx: 0.1, convention: tensor}}\n")
    # positive products are the negated tensor entries: Ixy = +0.3 means J_xy = -0.3
    positive_map = massprops(
        "parts:\n  - {shape: given, mass: 5, com: [1, 0, 0], inertia: "
        "{Ixx: 2, Iyy: 3, Izz: 4, Ixy: 0.3, Iyz: 0.2, Izx: -0.1, convention: positive}}\n")
    for mp in (as_matrix, as_positive, tensor_map, positive_map):
        assert mp.mass == 5.0
        assert close(mp.com, [1, 0, 0])
        assert close(mp.inertia_com, GIVEN_J)  # no arithmetic: equal to round-off


def test_given_map_without_products_needs_no_convention_and_products_need_one():
    mp = massprops("parts:\n  - {shape: given, mass: 1, inertia: {Ixx: 1, Iyy: 2, Izz: 2.5}}\n")
    assert close(mp.inertia_com, np.diag([1, 2, 2.5]))
    err = error_of("parts:\n  - {shape: given, mass: 1, inertia: {Ixx: 1, Iyy: 1, Izz: 1, Ixy: 0.1}}\n")
    assert "convention: tensor" in err.message and "convention: positive" in err.message


def test_given_matrix_with_products_needs_a_convention():
    err = error_of("parts:\n  - {shape: given, mass: 1, inertia: [[1, 0.1, 0], [0.1, 1, 0], [0, 0, 1]]}\n")
    assert "convention: tensor" in err.message and "convention: positive" in err.message
    err = error_of("parts:\n  - {shape: given, mass: 1, inertia: [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "
                   "convention: both}\n")
    assert "'tensor' or 'positive'" in err.message


def test_impossible_inertia_is_quoted_in_the_files_units():
    err = error_of("units: {length: mm, mass: g}\nparts:\n  - {shape: given, mass: 100, "
                   "inertia: [[1000, 0, 0], [0, 1000, 0], [0, 0, 2500]]}\n")
    assert "(1000, 1000, 2500 g·mm²)" in err.message, err.message
    err = error_of("parts:\n  - {shape: given, mass: 1, inertia: [[1, 0, 0], [0, 1, 0], [0, 0, 2.5]]}\n")
    assert "(1, 1, 2.5 kg·m²)" in err.message, err.message


def test_diameter_wherever_radius():
    a = massprops("parts:\n  - {shape: cylinder, mass: 2, radius: 0.05, inner_radius: 0.02, length: 0.1}\n")
    b = massprops("parts:\n  - {shape: cylinder, mass: 2, diameter: 0.1, inner_diameter: 0.04, length: 0.1}\n")
    c = massprops("units: {length: mm}\nparts:\n  - {shape: cylinder, mass: 2, diameter: 100, inner_diameter: '4 cm', length: 100}\n")
    assert close(a.inertia_com, b.inertia_com) and close(a.inertia_com, c.inertia_com)
    err = error_of("parts:\n  - {shape: disk, mass: 1, radius: 0.1, diameter: 0.2}\n")
    assert "'radius'" in err.message and "'diameter'" in err.message and "not both" in err.message
    err = error_of("parts:\n  - {shape: disk, mass: 1}\n")
    assert "'radius' or 'diameter'" in err.message
    err = error_of("parts:\n  - {shape: box, mass: 1, size: [1, 1, 1], diameter: 2}\n")
    assert "diameter" in err.message


def test_given_inertia_is_placed_with_the_part():
    R = Rotation.from_euler("ZYX", [30, 20, 10], degrees=True).as_matrix()
    mp = massprops(
        f"parts:\n  - {{shape: given, mass: 5, com: [0.1, 0, 0], inertia: {flow(GIVEN_J.tolist())}, "
        "convention: tensor, at: [0, 0, 1], rotate: {euler: [30, 20, 10], seq: ZYX}}\n")
    assert close(mp.com, np.array([0, 0, 1]) + R @ [0.1, 0, 0])
    assert close(mp.inertia_com, R @ GIVEN_J @ R.T)


# --------------------------------------------------------------------------- include

def _write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    return path


def test_include_is_relative_to_the_including_file_placed_and_prefixed(tmp_path, monkeypatch):
    _write(tmp_path / "asm" / "parts" / "wheel.yaml", """\
        units: {length: mm, mass: g}
        parts:
          - {name: tyre, shape: box, size: [100, 200, 300], mass: 500, at: [100, 0, 0]}
          - {name: hub, shape: point, mass: 250}
        """)
    main = _write(tmp_path / "asm" / "car.yaml", """\
        parts:
          - {name: body, shape: point, mass: 1, at: [0, 0, 5]}
          - {name: front, shape: include, file: parts/wheel.yaml, at: [1, 2, 3], rotate: {axis: [0, 0, 1], angle: 90}}
        """)
    monkeypatch.chdir(tmp_path)  # the include must not depend on the working directory
    body = load_body(str(main.relative_to(tmp_path)))
    names = [p.name for p in body.parts]
    assert names == ["body", "front/tyre", "front/hub"]
    R = Rotation.from_euler("z", 90, degrees=True).as_matrix()
    tyre = body.parts[1]
    assert tyre.mass == pytest.approx(0.5, rel=RTOL)
    assert close(tyre.com, np.array([1, 2, 3]) + R @ [0.1, 0, 0], scale=3.0)
    J0 = 0.5 / 12 * np.diag([0.2**2 + 0.3**2, 0.1**2 + 0.3**2, 0.1**2 + 0.2**2])
    assert close(tyre.inertia_com, R @ J0 @ R.T)
    assert close(body.parts[2].com, [1, 2, 3], scale=3.0)


def test_include_cycle_is_refused_with_the_chain(tmp_path):
    a = _write(tmp_path / "a.yaml", "parts:\n  - {name: b, shape: include, file: b.yaml}\n")
    _write(tmp_path / "b.yaml", "parts:\n  - {shape: point, mass: 1}\n  - {name: a, shape: include, file: a.yaml}\n")
    with pytest.raises(InputError) as info:
        load_body(str(a))
    err = info.value
    assert "include cycle: a.yaml -> b.yaml -> a.yaml" in err.message
    # located in b.yaml, at the file: value that closes the cycle (line 3, col 37)
    assert err.where.file.endswith("b.yaml") and (err.where.line, err.where.col) == (3, 37)


def test_self_include_is_a_cycle(tmp_path):
    a = _write(tmp_path / "a.yaml", "parts:\n  - {shape: point, mass: 1}\n  - {name: me, shape: include, file: a.yaml}\n")
    with pytest.raises(InputError, match="include cycle: a.yaml -> a.yaml"):
        load_body(str(a))


def test_a_missing_include_file_is_located_at_its_file_line(tmp_path):
    main = _write(tmp_path / "main.yaml", """\
        parts:
          - name: sub
            shape: include
            file: nothere.yaml
        """)
    with pytest.raises(InputError) as info:
        load_body(str(main))
    err = info.value
    assert (err.where.line, err.where.col) == (4, 11)
    assert "no such file" in err.message and "nothere.yaml" in err.message


def test_an_error_inside_an_included_file_points_into_that_file(tmp_path):
    _write(tmp_path / "sub.yaml", "parts:\n  - {shape: box, size: [1, 1, 1], mass: -1}\n")
    main = _write(tmp_path / "main.yaml", "parts:\n  - {name: s, shape: include, file: sub.yaml}\n")
    with pytest.raises(InputError) as info:
        load_body(str(main))
    assert info.value.where.file.endswith("sub.yaml")
    assert (info.value.where.line, info.value.where.col) == (2, 41)  # at the -1


# --------------------------------------------------------------------------- units

SI_BODY = """\
parts:
  - {name: a, shape: box, size: [0.3, 0.2, 0.1], density: 7850, at: [0.1, 0.2, 0.3]}
  - {name: b, shape: cylinder, radius: 0.02, length: 0.1, subtract: true, cut_from: a, at: [0.15, 0.2, 0.3]}
  - {name: c, shape: rod, length: 0.5, linear_density: 2, axis: [1, 1, 0]}
  - {name: d, shape: point, mass: 0.25, at: [-0.1, 0, 0]}
"""
MM_G_BODY = """\
units: {length: mm, mass: g}
parts:
  - {name: a, shape: box, size: [300, 200, 100], density: 0.00785, at: [100, 200, 300]}
  - {name: b, shape: cylinder, radius: 20, length: 100, subtract: true, cut_from: a, at: [150, 200, 300]}
  - {name: c, shape: rod, length: 500, linear_density: 2, axis: [1, 1, 0]}
  - {name: d, shape: point, mass: 250, at: [-100, 0, 0]}
"""
STRINGS_BODY = """\
parts:
  - {name: a, shape: box, size: ["30 cm", "200 mm", "0.1 m"], density: "7.85 g/cm^3", at: ["10 cm", "0.2 m", "300 mm"]}
  - {name: b, shape: cylinder, radius: "2 cm", length: "10 cm", subtract: true, cut_from: a, at: ["15 cm", "20 cm", "30 cm"]}
  - {name: c, shape: rod, length: "50 cm", linear_density: "2 g/mm", axis: [1, 1, 0]}
  - {name: d, shape: point, mass: "250 g", at: ["-100 mm", 0, 0]}
"""


@pytest.mark.parametrize("other", [MM_G_BODY, STRINGS_BODY], ids=["units-block", "quantity-strings"])
def test_the_same_body_in_mm_g_and_in_strings_equals_the_si_body(other):
    a, b = massprops(SI_BODY), massprops(other)
    # each conversion is one exact factor rounded once (a few ulp); sums of ~10 terms
    assert a.mass == pytest.approx(b.mass, rel=RTOL)
    assert close(a.com, b.com)
    assert close(a.inertia_com, b.inertia_com)


def test_inch_pound_units_are_exact():
    # 1 in = 0.0254 m and 1 lb = 0.45359237 kg by definition (NIST SP 811)
    p = load("units: {length: in, mass: lb}\nparts:\n  - {shape: rod, length: 10, mass: 2}\n").parts[0]
    assert p.mass == pytest.approx(2 * 0.45359237, rel=1e-15)
    assert p.inertia_com[0, 0] == pytest.approx(2 * 0.45359237 * (10 * 0.0254) ** 2 / 12, rel=1e-14)


# --------------------------------------------------------------------------- shorthand, stdin, expr

def test_one_part_shorthand_equals_the_parts_list():
    a = load("shape: box\nsize: [1, 2, 3]\nmass: 2\nat: [1, 0, 0]\nname: blk\n")
    b = load("parts:\n  - {shape: box, size: [1, 2, 3], mass: 2, at: [1, 0, 0], name: blk}\n")
    assert a.name == "blk" and a.parts[0].name == "blk"
    ma, mb = combine(a.parts), combine(b.parts)
    assert ma.mass == mb.mass and close(ma.com, mb.com) and close(ma.inertia_com, mb.inertia_com)
    c = load("units: {length: mm}\nrbcli: 1\nshape: box\nsize: [1000, 2000, 3000]\nmass: 2\nat: [1000, 0, 0]\n")
    assert close(combine(c.parts).inertia_com, mb.inertia_com)


def test_expr_and_stdin():
    import io

    b = load_expr("{shape: box, mass: 2, size: [0.1, 0.2, 0.3]}")
    assert b.source == "<expr>" and b.parts[0].mass == 2.0
    s = load_body("-", stdin=io.BytesIO(b"shape: point\nmass: 3\n"))
    assert s.source == "<stdin>" and s.parts[0].mass == 3.0
    with pytest.raises(InputError) as info:
        load_body("-", stdin=io.BytesIO(b"shape: point\nmass: x\n"))
    assert str(info.value).startswith("<stdin>:2:7: ")


def test_body_defaults_are_read():
    b = load("""\
        name: rotor
        reference: [0, 0, 1]
        pivot: [0, 0, -1]
        shaft: {axis: [0, 0, 2], through: [1, 0, 0]}
        rim_radius: '30 cm'
        parts:
          - {shape: point, mass: 1}
        """)
    assert b.name == "rotor" and close(b.reference, [0, 0, 1]) and close(b.pivot, [0, 0, -1])
    assert close(b.shaft.axis, [0, 0, 1]) and close(b.shaft.through, [1, 0, 0])
    assert b.rim_radius == pytest.approx(0.3, rel=1e-15)
    assert load("reference: com\nparts:\n  - {shape: point, mass: 1}\n").reference_is_com


def test_default_part_names_and_the_file_name_as_body_name(tmp_path):
    f = _write(tmp_path / "widget.yaml", "parts:\n  - {shape: box, size: [1, 1, 1], mass: 1}\n  - {shape: point, mass: 1}\n")
    b = load_body(str(f))
    assert b.name == "widget" and [p.name for p in b.parts] == ["box1", "point2"]


# --------------------------------------------------------------------------- errors (table)

# (yaml text, line, where, fragment of the message). Lines are 1-based; ``where`` is the
# column, or the text the error must point at (its first occurrence on that line gives
# the column); chosen by hand as the value or key a person must change.
ERROR_CASES = [
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    densty: 7850\n",
        4, "densty", "unknown key 'densty' in part 'box1' (box); did you mean 'density'?", id="unknown-key"),
    pytest.param(
        "parts:\n  - shape: cylindre\n    radius: 1\n", 2, "cylindre",
        "unknown shape 'cylindre'; did you mean 'cylinder'?", id="unknown-shape"),
    pytest.param("parts:\n  - shape: box\n    mass: 1\n", 2, "shape", "needs 'size'", id="missing-size"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, -1, 1]\n    mass: 1\n", 3, "[",
        "size[1] must be greater than 0", id="negative-size"),
    pytest.param(
        "parts:\n  - shape: sphere\n    radius: -2\n    mass: 1\n", 3, "-2",
        "radius must be greater than 0", id="negative-radius"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: true\n", 4, "true",
        "mass must be a number or a quantity like '30 cm', not 'true' (a boolean)", id="bool-as-number"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: null\n", 4, "null",
        "not nothing (null)", id="null"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: .inf\n", 4, ".inf", "must be finite", id="inf"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: 1e999\n", 4, "1e999", "must be finite",
        id="overflow"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: .nan\n", 4, ".nan", "must be finite", id="nan"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: 1e61\n", 4, "1e61",
        "too large (1e61); numbers are limited to 1e60", id="huge"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1e40, 1e40, 1e40]\n    density: 1e50\n", 4, "1e50",
        "its mass (density × volume) is 1e+170 kg, too large", id="huge-derived-mass"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: '3 m'\n", 4, "'3 m'",
        "'3 m' is a length, but a mass is needed here", id="wrong-dimension"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: 1\n    rotate: {axis: [0, 0, 1], angle: '3 Hz'}\n",
        5, "'3 Hz'", "'3 Hz' is a frequency", id="hz-for-angle"),
    pytest.param(
        "parts:\n  - shape: box\n    size: ['1 deg', 1, 1]\n    mass: 1\n", 3, "'1 deg'",
        "'1 deg' is an angle, but a length is needed", id="angle-for-length"),
    pytest.param(
        "parts:\n  - shape: given\n    mass: 1\n    convention: tensor\n    inertia: [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]\n", 5, "[[",
        "not symmetric", id="given-not-symmetric"),
    pytest.param(
        "parts:\n  - shape: given\n    mass: 1\n    inertia: [[1, 0, 0], [0, 1, 0], [0, 0, -1]]\n", 4, "[[",
        "negative principal moment", id="given-negative"),
    pytest.param(
        "parts:\n  - shape: given\n    mass: 1\n    inertia: [[1, 0, 0], [0, 1, 0], [0, 0, 2.5]]\n", 4, "[[",
        "triangle inequality", id="given-triangle"),
    pytest.param(
        "parts:\n  - shape: given\n    mass: 1\n    inertia: {Ixx: 1, Iyy: 1, Izz: 1, convention: cad}\n", 4, "cad",
        "convention must be 'tensor' or 'positive', not 'cad'", id="given-convention"),
    pytest.param(
        "parts:\n  - {shape: box, size: [1, 1, 1], mass: 1}\n  - {shape: box, size: [1, 1, 1], mass: 2, subtract: true}\n",
        2, "-", "the total mass is -1 kg", id="negative-mass"),
    pytest.param(
        "parts:\n  - {shape: box, size: [1, 1, 1], mass: 1}\n  - {shape: box, size: [1, 1, 1], mass: 1, subtract: true}\n",
        2, "-", "the total mass is 0 kg", id="zero-mass"),
    pytest.param(
        "parts:\n  - {name: a, shape: box, size: [1, 1, 1], density: 1}\n"
        "  - {name: h, shape: cylinder, radius: 0.2, length: 3, subtract: true, cut_from: a}\n",
        2, "-", "not physically possible: it has a negative principal moment", id="hole-larger-than-part"),
    pytest.param(
        "parts:\n  - {name: a, shape: point, mass: 1}\n  - {name: a, shape: point, mass: 1}\n", 3, "a,",
        "two parts are named 'a'", id="duplicate-names"),
    pytest.param("rbcli: 2\nparts:\n  - {shape: point, mass: 1}\n", 1, "2",
                 "reads body format version 1, not 2", id="version"),
    pytest.param("parts: []\n", 1, "[]", "parts is empty", id="empty-parts"),
    pytest.param("- 1\n- 2\n", 1, "-", "a body file is a mapping", id="not-a-mapping"),
    pytest.param("just text\n", 1, "just", "a body file is a mapping", id="scalar"),
    pytest.param("name: x\n", 1, "name", "needs 'parts:'", id="no-parts"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: 1\n    axis: [0, 0, 1]\n"
        "    rotate: {axis: [1, 0, 0], angle: 3}\n",
        6, "rotate", "give either 'axis' or 'rotate', not both", id="axis-and-rotate"),
    pytest.param(
        "parts:\n  - shape: rod\n    from: [1, 2, 3]\n    to: [1, 2, 3]\n    mass: 1\n", 4, "[",
        "'from' and 'to' are the same point", id="rod-from-equals-to"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: 1\n    axis: [0, 0, 0]\n", 5, "[",
        "axis must be a non-zero vector", id="zero-axis"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: 1\n"
        "    rotate: {matrix: [[1, 0, 0], [0, 1, 0], [0, 0, -1]]}\n",
        5, "[[", "reflection", id="reflection-matrix"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: 1\n    rotate: {quaternion: [0, 0, 0, 0]}\n",
        5, "[", "non-zero", id="zero-quaternion"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: 1\n    rotate: {euler: [1, 2, 3], seq: ZYQ}\n",
        5, "ZYQ", "euler sequence 'ZYQ' is not valid", id="euler-seq"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: 1\n    rotate: {axis: [0, 0, 1]}\n",
        5, "{", "rotate takes one of", id="rotate-incomplete"),
    pytest.param(
        "units: {length: kg}\nparts:\n  - {shape: point, mass: 1}\n", 1, "kg",
        "length is 'kg', which is a mass, not a length", id="units-wrong-dimension"),
    pytest.param(
        "units: {lenght: mm}\nparts:\n  - {shape: point, mass: 1}\n", 1, "lenght",
        "did you mean 'length'?", id="units-typo"),
    pytest.param(
        "parts:\n  - shape: sphere\n    radius: 1\n    mass: 1\n    subtract: no\n", 5, "no",
        "subtract must be true or false, not 'no'", id="yaml-1.1-bool"),
    pytest.param(
        "parts:\n  - shape: cylinder\n    radius: 1\n    length: 1\n    inner_radius: 1\n    mass: 1\n", 5, "1",
        "inner_radius (1 m) must be less than radius (1 m)", id="inner-radius"),
    pytest.param(
        "parts:\n  - shape: triangle\n    vertices: [[0, 0, 0], [1, 0, 0], [2, 0, 0]]\n    mass: 1\n", 3, "[[",
        "collinear", id="collinear-triangle"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1]\n    mass: 1\n", 3, "[",
        "size must have 3 components, not 2", id="size-count"),
    pytest.param(
        "parts:\n  - shape: box\n    size: [1, 1, 1]\n    mass: 1\n    at: [0, 0]\n", 5, "[",
        "at must have 3 components, not 2", id="at-count"),
    pytest.param("parts:\n  - 5\n", 2, "5", "part 1 must be a mapping", id="part-not-mapping"),
    pytest.param("parts:\n  - {mass: 1}\n", 2, "{", "part 1 needs 'shape'", id="no-shape"),
    pytest.param(
        "parts:\n  - {shape: point, mass: 1}\nshafts: {axis: [0, 0, 1]}\n", 3, "shafts",
        "unknown key 'shafts' in the body; did you mean 'shaft'?", id="body-key-typo"),
    pytest.param(
        "parts:\n  - {shape: point, mass: 1, at: &p [0, 0, 0]}\n", 2, "&p", "anchors and aliases", id="anchor"),
    pytest.param(
        "parts:\n  - {shape: point, mass: !!python/object:os.system 1}\n", 2, "!!", "tags", id="unsafe-tag"),
    pytest.param(
        "parts:\n  - {shape: point, mass: 1, mass: 2}\n", 2, "mass: 2", "duplicate key 'mass'", id="duplicate-key"),
    pytest.param("parts:\n  - {shape: point, mass: 1\n", 3, 1, "invalid YAML", id="malformed"),
]


@pytest.mark.parametrize("text, line, where, fragment", ERROR_CASES)
def test_bad_body_files_give_a_located_input_error(text, line, where, fragment):
    col = where if isinstance(where, int) else text.split("\n")[line - 1].index(where) + 1
    err = error_of(text, name="bad.yaml")
    assert err.exit_status == 2
    assert (err.where.file, err.where.line, err.where.col) == ("bad.yaml", line, col), str(err)
    assert fragment in err.message, err.message
    # one line, starting lower case (the CLI prints "rbcli: file:line:col: message")
    assert "\n" not in str(err) and err.message[:1] == err.message[:1].lower()
    assert str(err).startswith(f"bad.yaml:{line}:{col}: ")


def test_a_body_s_inputs_are_the_real_paths_of_its_file(tmp_path, monkeypatch):
    # read through a link to its folder, or a link to a folder above it: the file itself
    a = tmp_path / "real" / "a"
    a.mkdir(parents=True)
    (a / "f.yaml").write_text("shape: point\nmass: 1\n")
    (tmp_path / "link_dir").symlink_to(a)
    (tmp_path / "up").symlink_to(tmp_path / "real")
    monkeypatch.chdir(tmp_path)
    for path in ("link_dir/f.yaml", "up/a/f.yaml", str(tmp_path / "link_dir" / "f.yaml")):
        assert load_body(path).inputs == (str(a.resolve() / "f.yaml"),)
