"""Thresholds of instability: the speeds where a mode's growth rate Re lambda crosses zero.

Each mode followed by its shape (:func:`rbcli.core.whirl.modes.track`: a growing mode whose
frequency crosses a decaying one's is no change of stability); where its Re lambda changes
sign between two speeds (read by :func:`rbcli.core.whirl.modes.growth`), the
threshold is the root of Re lambda = 0 (Brent), independent of the grid: an *onset* where
the mode starts growing as the speed rises, else a *recovery*.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rbcli.core.whirl.modes import Campbell, Mode, branch_roots, growth

__all__ = ["Threshold", "Stability", "stability"]


@dataclass(frozen=True, eq=False)
class Threshold:
    """A mode's growth rate crossing zero: speed (rad/s), branch (the mode followed by
    its shape, numbered by frequency at the first speed), change ("onset" or
    "recovery") and the mode there."""

    speed: float
    branch: int
    change: str
    mode: Mode


@dataclass(frozen=True, eq=False)
class Stability:
    """thresholds (by speed); from_start: the branches growing at the first speed;
    speeds: (first, last) speed searched."""

    thresholds: tuple[Threshold, ...]
    from_start: tuple[int, ...]
    speeds: tuple[float, float]

    def growing(self, lo: float, hi: float) -> bool:
        """A mode grows somewhere in [lo, hi] (rad/s, within :attr:`speeds`)."""
        for k in range(4):
            state, x0 = k in self.from_start, self.speeds[0]
            for t in (t for t in self.thresholds if t.branch == k):
                if state and x0 <= hi and t.speed >= lo:
                    return True
                state, x0 = t.change == "onset", t.speed
            if state and x0 <= hi:
                return True
        return False

    @property
    def threshold(self) -> float | None:
        """rad/s, the threshold speed of instability: the first speed at which a mode
        grows (the first speed searched when one grows there already); None if none."""
        if self.from_start:
            return self.speeds[0]
        return next((t.speed for t in self.thresholds if t.change == "onset"), None)


def stability(cb: Campbell, ranks: np.ndarray) -> Stability:
    """The thresholds of the modes of ``cb`` followed by ``ranks`` (see the module)."""
    banded = growth(cb.eigenvalues)
    out = []
    for x, k, md, after in branch_roots(cb, ranks, banded, lambda lam, x: lam.real):
        out.append(Threshold(x, k, "onset" if after > 0.0 else "recovery", md))
    start = tuple(k for k in range(4) if banded[0, ranks[0, k]] > 0.0)
    return Stability(tuple(out), start, (float(cb.speeds[0]), float(cb.speeds[-1])))
