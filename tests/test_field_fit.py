"""Fitting field corrections (rbcli.core.field.fit) and sizing trial masses
(rbcli.core.field.trial), and the measures and kinds of a reading and the ISO 20816-3 zones
(rbcli.core.field.severity).

Oracles: the physics notes' worked examples (T22 split, §5.1 trial mass), vector sums
written out here, a sampled sinusoid (its peak, peak-to-peak, r.m.s. and finite-difference
derivative) for the measures and kinds, and the zone table as cited in the module.
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

from rbcli.core.balance.common import BalanceValueError
from rbcli.core.field.fit import fit_plane
from rbcli.core.field.trial import static_bearing_loads, suggest_trial
from rbcli.core.field.severity import (
    ISO_20816_3, MEASURES, convert_measure, to_velocity, zone, zone_boundaries,
)


def P(m: float, d: float) -> complex:
    return complex(cmath.rect(m, math.radians(d)))


def test_split_onto_positions_t22():
    # sheet §2.5, T22: 18 g @ 100° onto blades every 45° -> 14.6009 g @ 90° + 4.4204 g @ 135°
    f = fit_plane(P(18e-3, 100), positions=8)
    (a, b) = f.masses
    assert (a.position, b.position) == (3, 4) and (a.angle_deg, b.angle_deg) == (90.0, 135.0)
    assert a.mass * 1e3 == pytest.approx(14.6009, abs=5e-5)  # printed to 4 decimals
    assert b.mass * 1e3 == pytest.approx(4.4204, abs=5e-5)
    # the two masses make the correction exactly (unrounded): round-off only
    assert f.net == pytest.approx(P(18e-3, 100), rel=1e-14)


def test_rounding_and_the_net_correction():
    f = fit_plane(P(29.4325e-3, 21.1288), mass_step=1e-3, angle_step_deg=5.0)
    (m,) = f.masses
    assert m.mass == pytest.approx(29e-3, rel=1e-15) and m.angle_deg == 20.0
    assert f.net == pytest.approx(P(29e-3, 20.0), rel=1e-15) and f.rounded
    # half up, as balance rounds: 2.5 g -> 3 g, 2.49 g -> 2 g
    assert fit_plane(P(2.5e-3, 0), mass_step=1e-3).masses[0].mass == pytest.approx(3e-3)
    assert fit_plane(P(2.49e-3, 0), mass_step=1e-3).masses[0].mass == pytest.approx(2e-3)
    # split and rounded: each of the two masses rounded, the net is their vector sum
    g = fit_plane(P(18e-3, 100), positions=8, mass_step=0.5e-3)
    assert [x.mass for x in g.masses] == pytest.approx([14.5e-3, 4.5e-3])
    assert g.net == pytest.approx(P(14.5e-3, 90) + P(4.5e-3, 135), rel=1e-15)
    # nothing asked: the correction itself
    z = P(1e-3, 33)
    assert fit_plane(z).net == z and not fit_plane(z).rounded


@pytest.mark.parametrize("kwargs, param", [
    (dict(mass_step=0.0), "mass_step"), (dict(angle_step_deg=400.0), "angle_step"),
    (dict(positions=2), "positions"), (dict(positions=8, angle_step_deg=5.0), "angle_step"),
])
def test_fit_errors(kwargs, param):
    with pytest.raises(BalanceValueError) as e:
        fit_plane(P(1e-3, 10), **kwargs)
    assert e.value.param == param


def test_trial_mass_sheet_example():
    # sheet §5.1: "100 kg, r = 200 mm, 1500 rpm gives 19.9 g" for a force of 10 % of the
    # rotor's weight: m = 0.1 M g / (r w^2)
    w = 1500 * math.pi / 30
    s = suggest_trial(100 * 9.80665, 0.2, w, 0.10)
    assert s.mass * 1e3 == pytest.approx(19.9, abs=0.05)
    assert s.force == pytest.approx(0.1 * 100 * 9.80665, rel=1e-14)  # m r w^2 = f F
    with pytest.raises(BalanceValueError) as e:
        suggest_trial(100.0, 0.2, w, 0.5)
    assert e.value.param == "trial_fraction"


def test_static_bearing_loads_lever_rule():
    F1, F2 = static_bearing_loads(120.0, 9.80665, 0.3, (0.0, 0.8))
    assert F1 + F2 == pytest.approx(120 * 9.80665, rel=1e-15)  # vertical balance
    assert F2 * 0.8 == pytest.approx(120 * 9.80665 * 0.3, rel=1e-15)  # moments about bearing 1
    # overhung: the far bearing holds the rotor down
    assert static_bearing_loads(10.0, 9.81, 1.2, (0.0, 1.0))[0] < 0


# ------------------------------------------------------------------ measures and kinds


def _sampled(amplitude: float, omega: float, n: int = 200_000):
    t = np.linspace(0.0, 2 * math.pi / omega, n, endpoint=False)
    x = amplitude * np.sin(omega * t + 0.3)
    return t, x


def test_measures_of_a_sampled_sinusoid():
    _, x = _sampled(2.0, 50.0)
    pk, pkpk, rms = np.max(np.abs(x)), np.max(x) - np.min(x), math.sqrt(np.mean(x * x))
    # 2e5 samples over a period: peak to 1e-9 (the grid misses the crest by < pi/2e5 rad),
    # r.m.s. exact to round-off (a whole period)
    assert convert_measure(2.0, "pk", "pk-pk") == pytest.approx(pkpk, rel=1e-9)
    assert convert_measure(2.0, "pk", "rms") == pytest.approx(rms, rel=1e-12)
    assert convert_measure(rms, "rms", "pk") == pytest.approx(pk, rel=1e-9)
    assert set(MEASURES) == {"pk", "pk-pk", "rms"}


def test_kinds_at_a_speed_by_finite_differences():
    omega = 154.98
    t, x = _sampled(40e-6, omega)
    v = np.gradient(x, t)
    a = np.gradient(v, t)
    # central differences on 2e5 points a period: relative error ~ (omega dt)^2 / 6 ~ 1e-10,
    # and at the ends one-sided (first order) - take the interior
    assert to_velocity(40e-6, "displacement", omega) == pytest.approx(np.max(np.abs(v[10:-10])), rel=1e-6)
    assert to_velocity(np.max(np.abs(a[10:-10])), "acceleration", omega) == pytest.approx(
        np.max(np.abs(v[10:-10])), rel=1e-6)
    assert to_velocity(3e-3, "velocity", omega) == 3e-3


def test_iso_20816_3_zones():
    # the table as cited (mm/s r.m.s.): group 1 rigid 2.3/4.5/7.1, flexible 3.5/7.1/11.0;
    # group 2 rigid 1.4/2.8/4.5, flexible 2.3/4.5/7.1
    want = {(1, "rigid"): (2.3, 4.5, 7.1), (1, "flexible"): (3.5, 7.1, 11.0),
            (2, "rigid"): (1.4, 2.8, 4.5), (2, "flexible"): (2.3, 4.5, 7.1)}
    assert {k: tuple(round(x * 1e3, 6) for x in v) for k, v in ISO_20816_3.items()} == want
    for (g, f), (ab, bc, cd) in want.items():
        assert zone_boundaries(g, f) == pytest.approx((ab * 1e-3, bc * 1e-3, cd * 1e-3))
        # a value on a boundary is in the lower zone
        assert [zone(x * 1e-3, g, f) for x in (0.0, ab, ab * 1.0001, bc, bc * 1.0001, cd, cd * 1.0001)] == \
            ["A", "A", "B", "B", "C", "C", "D"]
    with pytest.raises(ValueError):
        zone(1e-3, 3, "rigid")
