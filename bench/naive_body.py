"""The body-file peer: load with PyYAML's CSafeLoader, mass properties with numpy, no checks.

Usage: python bench/naive_body.py BODY.yaml [BODY.yaml ...]

What a user could write in an afternoon instead of rbcli: ``yaml.load(..., CSafeLoader)``,
a table of textbook formulas for the shapes that ``bench/large_bodies.py`` generates, the
placements it uses (at, axis, rotate axis/angle, euler, quaternion, matrix), unit strings
through a small dictionary, holes with ``cut_from``, and the parallel-axis sum. It validates
nothing (no locations, no unknown keys, no limits). It prints, per file, one JSON line with
the mass, the centre of mass and the inertia tensor about it, so that its figures can be
compared with ``rbcli inertia --json`` (bench/large_bodies.py checks them within 1e-9).
"""

from __future__ import annotations

import json
import math
import sys

import numpy as np
import yaml

_U = {"mm": 1e-3, "cm": 1e-2, "m": 1.0, "kg": 1.0, "g": 1e-3, "lb": 0.45359237,
      "kg/m^3": 1.0, "g/cm^3": 1000.0, "kg/m^2": 1.0, "kg/m": 1.0, "deg": math.pi / 180}


def q(v, base: float) -> float:
    """A number in the file's unit (``base`` to SI) or a "number unit" string."""
    if isinstance(v, str):
        num, unit = v.split(None, 1)
        return float(num) * _U[unit.strip()]
    return float(v) * base


def rot_axis_angle(a, ang):
    a = np.asarray(a, float) / np.linalg.norm(a)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(ang) * K + (1 - math.cos(ang)) * K @ K


def axis_to_z(a):
    a = np.asarray(a, float) / np.linalg.norm(a)
    z = np.array([0.0, 0.0, 1.0])
    c = float(a @ z)
    v = np.cross(z, a)
    s = np.linalg.norm(v)
    if s < 1e-12:
        return np.eye(3) if c > 0 else np.diag([1.0, -1.0, -1.0])
    return rot_axis_angle(v, math.atan2(s, c))


def rotation(p, deg):
    if "axis" in p:
        return axis_to_z(p["axis"])
    r = p.get("rotate")
    if r is None:
        return np.eye(3)
    if "angle" in r:
        return rot_axis_angle(r["axis"], q(r["angle"], deg))
    if "quaternion" in r:
        w, x, y, z = np.asarray(r["quaternion"], float) / np.linalg.norm(r["quaternion"])
        return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    if "matrix" in r:
        return np.asarray(r["matrix"], float)
    R = np.eye(3)
    intrinsic = r["seq"].isupper()
    for ax, ang in zip(r["seq"].upper(), r["euler"]):
        e = np.eye(3)["XYZ".index(ax)]
        step = rot_axis_angle(e, q(ang, deg))
        R = R @ step if intrinsic else step @ R
    return R


def shape(p, L, M):
    """(mass or None, measure, centre of mass in the part's frame, inertia per unit mass)."""
    s = p["shape"]
    if s == "point":
        return 0.0, np.zeros(3), np.zeros((3, 3))
    if s == "box":
        a, b, c = (q(x, L) for x in p["size"])
        return a * b * c, np.zeros(3), np.diag([b * b + c * c, a * a + c * c, a * a + b * b]) / 12
    if s == "plate":
        a, b = (q(x, L) for x in p["size"])
        t = q(p["thickness"], L)
        return a * b * t, np.zeros(3), np.diag([b * b + t * t, a * a + t * t, a * a + b * b]) / 12
    if s == "cylinder":
        R, h = q(p["radius"], L), q(p["length"], L)
        r = q(p.get("inner_radius", 0), L)
        sq = R * R + r * r
        return math.pi * (R * R - r * r) * h, np.zeros(3), np.diag([sq / 4 + h * h / 12] * 2 + [sq / 2])
    if s == "sphere":
        R, r = q(p["radius"], L), q(p.get("inner_radius", 0), L)
        k = 0.4 * (R ** 5 - r ** 5) / (R ** 3 - r ** 3)
        return 4 / 3 * math.pi * (R ** 3 - r ** 3), np.zeros(3), np.eye(3) * k
    if s == "cone":
        R, h = q(p["radius"], L), q(p["height"], L)
        return (math.pi * R * R * h / 3, np.array([0, 0, h / 4]),
                np.diag([3 / 20 * R * R + 3 / 80 * h * h] * 2 + [0.3 * R * R]))
    if s == "hemisphere":
        R = q(p["radius"], L)
        return 2 / 3 * math.pi * R ** 3, np.array([0, 0, 3 * R / 8]), np.diag([83 / 320 * R * R] * 2 + [0.4 * R * R])
    if s == "ellipsoid":
        a, b, c = (q(x, L) for x in p["semi_axes"])
        return 4 / 3 * math.pi * a * b * c, np.zeros(3), np.diag([b * b + c * c, a * a + c * c, a * a + b * b]) / 5
    if s == "disk":
        R, r = q(p["radius"], L), q(p.get("inner_radius", 0), L)
        sq = R * R + r * r
        return math.pi * (R * R - r * r), np.zeros(3), np.diag([sq / 4, sq / 4, sq / 2])
    if s == "rod":
        h = q(p["length"], L)
        return h, np.zeros(3), np.diag([h * h / 12, h * h / 12, 0.0])
    if s == "ring":
        R = q(p["radius"], L)
        return 0.0, np.zeros(3), np.diag([R * R / 2, R * R / 2, R * R])
    if s == "triangle":
        v = np.array([[q(x, L) for x in row] for row in p["vertices"]])
        area = 0.5 * np.linalg.norm(np.cross(v[1] - v[0], v[2] - v[0]))
        c = v.mean(axis=0)
        d = v - c
        S = (d.T @ d + np.outer(3 * c - 3 * c, c)) / 12 + (np.outer(d.sum(0), d.sum(0))) / 12
        return area, c, np.trace(S) * np.eye(3) - S
    raise ValueError(f"shape {s}")


def mass_properties(body) -> dict:
    units = body.get("units", {})
    L = _U[units.get("length", "m")]
    Mu = _U[units.get("mass", "kg")]
    deg = _U["deg"]
    density = {}
    ms, coms, Is = [], [], []
    for p in body["parts"]:
        measure, c, I1 = shape(p, L, Mu)
        if "mass" in p:
            m = q(p["mass"], Mu)
        else:
            src = p["cut_from"] if "cut_from" in p else None
            rho = density[src] if src else q(next(p[k] for k in ("density", "areal_density", "linear_density") if k in p), 1.0)
            density[p.get("name")] = rho
            m = rho * measure
        if p.get("subtract"):
            m = -m
        R = rotation(p, deg)
        at = np.array([q(x, L) for x in p.get("at", (0, 0, 0))])
        ms.append(m)
        coms.append(at + R @ c)
        Is.append(m * (R @ I1 @ R.T))
    ms = np.array(ms)
    coms = np.array(coms)
    M = ms.sum()
    com = (ms[:, None] * coms).sum(0) / M
    d = coms - com
    I = np.sum(Is, axis=0) + np.einsum("i,ij,ik->jk", ms, d, d) * -1 + np.eye(3) * np.einsum("i,ij,ij->", ms, d, d)
    return {"mass": M, "com": com.tolist(), "inertia_com": I.tolist(), "parts": len(ms)}


def main(paths: list[str]) -> int:
    for path in paths:
        with open(path, "rb") as fh:
            body = yaml.load(fh, Loader=yaml.CSafeLoader)
        print(json.dumps({"file": path, **mass_properties(body)}))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
