"""ASC CDL v1.2 against published values: OpenColorIO's CDLOp tests (tests/cpu/ops/cdl/CDLOp_tests.cpp,
CDL_DATA_1, "calculated via an independent ASC CDL implementation"), and OCIO's CDLTransform."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio

from generator.colorimetry.cdl import Correction, asc_cdl

DATA_1 = Correction((1.35, 1.1, 0.071), (0.05, -0.23, 0.11), (0.93, 0.81, 1.27), 1.23)
INPUTS = [[0.3278, 0.01, 1.0], [0.25, 0.5, 0.75], [1.25, 1.5, 1.75], [-0.2, 0.5, 1.4], [0.0, 0.8, 0.99]]
#: apply_clamp_fwd (CDL_V1_2_FWD, OCIO's CDL_ASC) and apply_noclamp_fwd (CDL_NO_CLAMP_FWD).
ASC = [
    [0.609399, 0.000000, 0.113130],
    [0.422056, 0.401466, 0.035820],
    [1.000000, 1.000000, 0.000000],
    [0.000000, 0.421096, 0.101225],
    [0.000000, 0.746748, 0.018691],
]
NO_CLAMP = [
    [0.645424, -0.260548, 0.149154],
    [0.422056, 0.401466, 0.035820],
    [1.753162, 1.331130, -0.108181],
    [-0.327485, 0.431854, 0.111983],
    [-0.045094, 0.746748, 0.018691],
]


def test_published_values():
    # The published values have six decimals, computed in float32 inputs.
    x = np.asarray(INPUTS, dtype=np.float32).astype(np.float64)
    np.testing.assert_allclose(asc_cdl(x, DATA_1, "asc"), ASC, rtol=0, atol=2e-6)
    np.testing.assert_allclose(asc_cdl(x, DATA_1, "no_clamp"), NO_CLAMP, rtol=0, atol=2e-6)


def test_ocio_cdl_transform_on_random_colours():
    rng = np.random.default_rng(23)
    x = rng.uniform(-0.2, 1.3, (2000, 3)).astype(np.float32)
    cfg = ocio.Config.CreateRaw()
    for style, ours in ((ocio.CDL_ASC, "asc"), (ocio.CDL_NO_CLAMP, "no_clamp")):
        t = ocio.CDLTransform(slope=list(DATA_1.slope), offset=list(DATA_1.offset), power=list(DATA_1.power), sat=1.23)
        t.setStyle(style)
        out = x.copy()
        cfg.getProcessor(t).getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS).applyRGB(out)
        np.testing.assert_allclose(out, asc_cdl(x.astype(np.float64), DATA_1, ours), rtol=0, atol=2e-6)
