"""A rigid rotor on linear bearings (constant, cross-coupled or tabled against speed):
whirl modes, Campbell diagram, critical speeds, stability, unbalance response and
separation margins (``rbcli whirl``).

Physics sheet ``physics/whirl.md`` of the project's notes; the equations are written out
in :mod:`rbcli.core.whirl.model`. Modules:

- :mod:`~rbcli.core.whirl.model` — :class:`Bearing`, :class:`BearingTable`, :class:`Rotor`
  (M, C, G, K at each speed; the directional reduction for isotropic bearings) and the
  mode shapes (whirl direction and forward share, cylindrical / conical / mixed, node);
- :mod:`~rbcli.core.whirl.modes` — the modes over speeds (one stacked eigen-solve), each
  followed by its shape, and the roots of a followed mode's frequency or growth;
- :mod:`~rbcli.core.whirl.critical` — undamped critical speeds (an eigenproblem in the
  speed, or a root solve), damped crossings, the branches that never cross;
- :mod:`~rbcli.core.whirl.stability` — thresholds of instability (onset, recovery);
- :mod:`~rbcli.core.whirl.response` — unbalance response, peaks, amplification factors
  and the API 617 / 684 separation margins;
- :mod:`~rbcli.core.whirl.cmap` — the undamped critical speed map.
"""

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
