"""Transfer records as OCIO transforms: the transforms decode as the reference does."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.colorimetry import transfer
from generator.ocio.curves import decode_transforms, group
from generator.verify.metrics import relative_error


def decode_through_ocio(transforms: list, codes: np.ndarray) -> np.ndarray:
    """``codes`` (one per channel) through the transforms in an empty config."""
    cfg = ocio.Config.CreateRaw()
    processor = cfg.getProcessor(group(transforms)).getDefaultCPUProcessor()
    rgb = np.ascontiguousarray(np.repeat(codes[:, None], 3, axis=1), dtype=np.float32)
    processor.applyRGB(rgb)
    return rgb[:, 0].astype(np.float64)


LOG_AFFINE = transfer.LogCamera(base=10.0, log_side_slope=0.25, log_side_offset=0.4,
                                lin_side_slope=5.0, lin_side_offset=0.05)
LOG_CAMERA = transfer.LogCamera(base=10.0, log_side_slope=0.247, log_side_offset=0.385, lin_side_slope=5.56,
                                lin_side_offset=0.052, lin_side_break=0.0109, linear_slope=5.37)


@pytest.mark.parametrize("curve", [LOG_AFFINE, LOG_CAMERA], ids=["no break", "break"])
def test_log_camera_decodes_as_the_reference(curve):
    """With or without a linear segment, in the record's own base (not OCIO's default 2)."""
    codes = np.linspace(0.1, 1.0, 91).astype(np.float32).astype(np.float64)
    out = decode_through_ocio(decode_transforms("custom", curve, (2, 1), {}), codes)
    assert relative_error(out, curve.decode(codes)).max() < tolerances.ANALYTIC_RELATIVE
