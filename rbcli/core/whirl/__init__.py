"""A rigid rotor on linear spring-damper bearings: whirl modes, Campbell diagram,
critical speeds, unbalance response and separation margins (``rbcli whirl``).

Physics sheet ``physics/whirl.md`` of the project's notes; the equations are written out
in :mod:`rbcli.core.whirl.model`. Modules:

- :mod:`~rbcli.core.whirl.model` — :class:`Bearing`, :class:`Rotor` (M, C, G, K; the
  directional reduction for isotropic bearings) and the mode shapes (whirl direction,
  cylindrical / conical / mixed, node);
- :mod:`~rbcli.core.whirl.modes` — the modes at a speed, the Campbell diagram, the onset
  of instability;
- :mod:`~rbcli.core.whirl.critical` — undamped critical speeds by an eigenproblem in the
  speed, damped crossings by a root solve, the branches that never cross;
- :mod:`~rbcli.core.whirl.response` — unbalance response, peaks, amplification factors
  (half-power) and the API 617 / 684 separation margins.
"""

from rbcli.core.whirl.critical import CriticalSpeed, Missing, critical_speeds, damped_crossing
from rbcli.core.whirl.model import Bearing, ModeShape, Rotor
from rbcli.core.whirl.modes import Campbell, Mode, campbell, modes_at, onset_speeds
from rbcli.core.whirl.response import (
    Forcing, Margin, Peak, Response, margin, peaks, required_margin, response,
)

__all__ = [
    "Bearing", "Rotor", "ModeShape", "Mode", "modes_at", "Campbell", "campbell", "onset_speeds",
    "CriticalSpeed", "Missing", "critical_speeds", "damped_crossing", "Forcing", "Response",
    "response", "Peak", "peaks", "Margin", "margin", "required_margin",
]
