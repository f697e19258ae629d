"""Brent's bracketing root finder in plain Python (no scipy import on the dynamics' path).

:func:`brentq` is a line-by-line port of scipy's C ``brentq`` (scipy/optimize/Zeros/brentq.c,
written by Charles Harris; https://github.com/scipy/scipy/blob/main/scipy/optimize/Zeros/brentq.c),
so that, for the same function, bracket and tolerances, it takes the same steps and returns the
same float as ``scipy.optimize.brentq`` (tests/test_core_roots.py checks this). Importing
``scipy.optimize`` costs ~0.3 s of CPU, more than a whole ``top`` one-liner.

Source: R. P. Brent, *Algorithms for Minimization without Derivatives* (1973), ch. 4.
"""

from __future__ import annotations

import math
from typing import Callable


def brentq(f: Callable[[float], float], xa: float, xb: float, *, xtol: float = 2e-12,
           rtol: float = 8.881784197001252e-16, maxiter: int = 100) -> float:
    """A root of ``f`` in [xa, xb] (f changes sign there), by Brent's method, to a bracket
    half-width below (xtol + rtol |x|) / 2: the end point whose |f| is smaller. ValueError
    when f(xa) and f(xb) have the same sign; RuntimeError after ``maxiter`` iterations."""
    xpre, xcur = float(xa), float(xb)
    xblk = fblk = spre = scur = 0.0
    fpre = float(f(xpre))
    fcur = float(f(xcur))
    if fpre == 0.0:
        return xpre
    if fcur == 0.0:
        return xcur
    if math.copysign(1.0, fpre) == math.copysign(1.0, fcur):
        raise ValueError("f(a) and f(b) must have different signs")
    for _ in range(maxiter):
        if fpre != 0.0 and fcur != 0.0 and math.copysign(1.0, fpre) != math.copysign(1.0, fcur):
            xblk = xpre
            fblk = fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2
        sbis = (xblk - xcur) / 2
        if fcur == 0.0 or abs(sbis) < delta:
            return xcur
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:
                stry = -fcur * (xcur - xpre) / (fcur - fpre)  # interpolate
            else:  # extrapolate
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                den = dblk * dpre * (fblk - fpre)  # 0 when it underflows: C's x/0 is inf or
                stry = -fcur * (fblk * dblk - fpre * dpre) / den if den else math.inf  # NaN: bisect
            if 2 * abs(stry) < min(abs(spre), 3 * abs(sbis) - delta):
                spre = scur  # good short step
                scur = stry
            else:
                spre = scur = sbis
        else:
            spre = scur = sbis
        xpre = xcur
        fpre = fcur
        if abs(scur) > delta:
            xcur += scur
        else:
            xcur += delta if sbis > 0 else -delta
        fcur = float(f(xcur))
    raise RuntimeError(f"brentq: not converged in {maxiter} iterations")
