"""A rigid rotor on linear bearings (constant, cross-coupled or tabled against speed):
whirl modes, Campbell diagram, critical speeds, stability, unbalance response and
separation margins (``rbcli whirl``; physics sheet ``whirl.md``).

Modules: ``model`` (bearings, the rotor's matrices, mode shapes), ``modes`` (the modes over
speeds, followed by shape), ``critical`` (undamped and damped critical speeds, the map),
``stability`` (thresholds of instability), ``response`` (unbalance response, peaks,
amplification factors, API 617 / 684 separation margins)."""

from rbcli.core.whirl.critical import CriticalSpeed, Missing, critical_speeds, damped_crossing
from rbcli.core.whirl.model import Bearing, BearingTable, ModeShape, Rotor
from rbcli.core.whirl.modes import Campbell, Mode, branch_roots, campbell, follow, modes_at, track
from rbcli.core.whirl.response import (
    Forcing, Margin, Peak, Response, margin, peaks, required_margin, response,
)

__all__ = [
    "Bearing", "BearingTable", "Rotor", "ModeShape", "Mode", "modes_at", "Campbell", "campbell",
    "track", "follow", "branch_roots", "CriticalSpeed", "Missing", "critical_speeds",
    "damped_crossing", "Forcing", "Response", "response", "Peak", "peaks", "Margin", "margin",
    "required_margin",
]
