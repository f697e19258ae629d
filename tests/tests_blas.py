"""Pin OpenBLAS's kernel for the test suite and ``tests/cases/regen.py``.

The golden cases are exact to the last printed digit. OpenBLAS chooses its kernels by the
CPU it finds (``OPENBLAS_VERBOSE=2`` prints the choice), and the last bit of a 3x3 product
differs between them: the cases written on an Intel AVX-512 machine (kernel SkylakeX) fail
in one or two trailing digits on an AMD EPYC one (kernel Haswell). The suite therefore
runs with ``OPENBLAS_CORETYPE=Haswell`` (AVX2 and FMA, present on every x86-64 machine of
the last decade) unless the caller chose a kernel. It must be set before numpy is first
imported, and child processes inherit it.
"""

from __future__ import annotations

import os
import sys


def pin_blas_kernel() -> None:
    if "OPENBLAS_CORETYPE" in os.environ:  # the caller's choice, or pinned already
        return
    if "numpy" in sys.modules:  # too late: the kernel is already chosen
        raise RuntimeError("tests_blas.pin_blas_kernel() must run before numpy is imported")
    try:
        with open("/proc/cpuinfo", encoding="ascii", errors="replace") as f:
            flags = next((line for line in f if line.startswith("flags")), "").split()
    except OSError:
        return
    if "avx2" in flags and "fma" in flags:
        os.environ["OPENBLAS_CORETYPE"] = "Haswell"
