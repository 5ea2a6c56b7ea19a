"""numpy's and OpenBLAS's settings, fixed before they load: the same spec builds the same
bytes on every x86-64 machine.

When it loads, numpy picks SIMD versions of its functions for the processor it finds, and
OpenBLAS (numpy's and scipy's matrix library) picks its kernels the same way. Their results
differ in the last bit: on a processor with AVX-512, numpy's float64 ``power`` differs from
its baseline's for 5.4% of values in [0, 1], ``exp`` for 4.4%, ``log`` for 0.3%, float32
``power`` for 20%; OpenBLAS's Haswell kernels (fused multiply-add) and its Nehalem ones give
3×3 products that differ in the sixteenth digit. A value written with a file's decimals then
rounds the other way on another machine (measured: three of the pack's .cube files, 17 lines
in all, and 23 of its files and the default config's matrices). Imported first by the package,
this module fixes both at what every x86-64 processor numpy runs on can run: numpy's
baseline (its dispatch targets above it turned off) and OpenBLAS's Nehalem kernels, which cost
a 65³ bake 5% (bench/lut_bake.py). Both read the environment once, as they load: a process
that loaded numpy before importing ``generator`` keeps what it had, and is warned.

Elsewhere than x86-64 nothing is fixed: outputs are the same from run to run on one machine.
"""

from __future__ import annotations

import os
import platform
import sys
import warnings

#: numpy 2.4's dispatch targets above its x86-64 baseline (X86_V2), as
#: NPY_DISABLE_CPU_FEATURES names them.
NUMPY_ABOVE_BASELINE = ("X86_V3", "X86_V4", "AVX512_ICL", "AVX512_SPR")

#: OpenBLAS's kernels for SSE4.2, numpy's x86-64 baseline.
OPENBLAS_CORE = "Nehalem"

#: What is set, name to value; numpy refuses NPY_ENABLE_CPU_FEATURES beside the first.
PINNED = {"NPY_DISABLE_CPU_FEATURES": " ".join(NUMPY_ABOVE_BASELINE), "OPENBLAS_CORETYPE": OPENBLAS_CORE}


def fixes_numbers() -> bool:
    """Whether this machine is one whose numbers :data:`PINNED` fixes (x86-64)."""
    return platform.machine().lower() in ("x86_64", "amd64")


def _pin(environ) -> None:
    """Every dispatch target above the baseline off, whatever was there: numpy fails to load
    when asked to turn off a baseline feature (X86_V2), and other names add nothing."""
    environ.pop("NPY_ENABLE_CPU_FEATURES", None)
    environ.update(PINNED)


def _pinned_already(environ) -> bool:
    """Whether ``environ`` already holds :data:`PINNED` (a numpy loaded with it has its baseline)."""
    disabled = environ.get("NPY_DISABLE_CPU_FEATURES", "").replace(",", " ").split()
    return (
        "NPY_ENABLE_CPU_FEATURES" not in environ
        and set(NUMPY_ABOVE_BASELINE) <= set(disabled)
        and environ.get("OPENBLAS_CORETYPE") == OPENBLAS_CORE
    )


# A command multiplies 3×3 matrices, never large ones, so OpenBLAS's thread pool (numpy starts
# it on import) is not started: numpy's import took 100 ms rather than 160 on a 2-core machine
# (the gain varies with the machine and OpenBLAS). A setting in the environment is kept.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

if fixes_numbers():
    if "numpy" in sys.modules and not _pinned_already(os.environ):
        warnings.warn(
            "numpy was loaded before generator, with the SIMD functions and OpenBLAS kernels of this "
            "processor: files written may differ in their last digit from other machines'; import "
            "generator first, or set " + " ".join(f"{k}={v!r}" for k, v in PINNED.items()),
            RuntimeWarning,
            stacklevel=2,
        )
    else:
        _pin(os.environ)
