"""The same numbers whatever the processor offers (generator/backends.py)."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from generator import backends
from generator.colorimetry import gamuts

pytestmark = pytest.mark.skipif(not backends.fixes_numbers(), reason="numbers are fixed on x86-64 alone")

#: Every library gamut pair's matrix and a power, exp and log curve, as exact hex floats.
_NUMBERS = """
import itertools, generator, numpy as np
from generator.colorimetry import gamuts, matrices
g = gamuts.gamuts()
for a, b in itertools.product(g.values(), repeat=2):
    print(*(v.hex() for v in matrices.rgb_to_rgb(a, b).ravel()))
x = np.linspace(0.0, 1.0, 4097)[1:]
for values in (np.power(x, 2.4), np.exp(x), np.log(x), np.power(x.astype(np.float32), np.float32(1 / 2.4))):
    print(*(float(v).hex() for v in values))
"""


def _numbers(**environ) -> str:
    env = {k: v for k, v in os.environ.items() if not k.startswith(("NPY_", "OPENBLAS_CORETYPE"))}
    done = subprocess.run(
        [sys.executable, "-c", _NUMBERS], env={**env, **environ}, capture_output=True, text=True, check=True
    )
    return done.stdout


def test_numbers_are_the_same_bits_whatever_kernels_the_environment_asks_for():
    """numpy's AVX-512 functions and OpenBLAS's FMA kernels round differently from its baseline's
    and Nehalem's in the last bit: importing generator fixes both, whatever the environment says."""
    fast = _numbers(OPENBLAS_CORETYPE="Haswell", NPY_ENABLE_CPU_FEATURES="X86_V3 X86_V4 AVX512_ICL")
    plain = _numbers(OPENBLAS_CORETYPE="Prescott", NPY_DISABLE_CPU_FEATURES="X86_V3 X86_V4 AVX512_ICL AVX512_SPR")
    assert fast.count("\n") == len(gamuts.gamuts()) ** 2 + 4
    assert fast == plain


def test_numpy_loaded_first_is_named():
    """A process that loaded numpy before generator keeps that numpy's choices, and is told how to fix them."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("NPY_", "OPENBLAS_CORETYPE"))}
    done = subprocess.run(
        [sys.executable, "-c", "import numpy, generator"], env=env, capture_output=True, text=True, check=True
    )
    assert "numpy was loaded before generator" in done.stderr
    assert "OPENBLAS_CORETYPE='Nehalem'" in done.stderr
    pinned = {**env, **backends.PINNED}
    done = subprocess.run(
        [sys.executable, "-W", "error", "-c", "import numpy, generator"], env=pinned, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr


def test_a_baseline_feature_named_in_the_environment_does_not_stop_numpy():
    """numpy refuses to load when told to turn off a baseline feature; generator sets the list
    whole, every target above the baseline, so a shell's X86_V2 there adds nothing and breaks nothing."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("NPY_", "OPENBLAS_CORETYPE"))}
    done = subprocess.run(
        [sys.executable, "-c", "import generator, numpy"],
        capture_output=True,
        text=True,
        env={**env, "NPY_DISABLE_CPU_FEATURES": "X86_V2 AVX512_ICL"},
    )
    assert done.returncode == 0, done.stderr
