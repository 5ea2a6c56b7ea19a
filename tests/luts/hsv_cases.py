"""Colours and OCIO fixed functions the HSV view's tests share."""

from __future__ import annotations

import numpy as np


def colours(count: int = 20000) -> np.ndarray:
    """Display-linear colours of every kind: inside the cube, with negative channels, over
    range, all negative, and within 1e-3 of OCIO HSV's cone (largest = -smallest)."""
    rng = np.random.default_rng(7)
    inside = rng.random((count, 3))
    wide = rng.uniform(-2.0, 3.0, (count, 3))
    bright = rng.random((count, 3)) * 10.0 ** rng.uniform(0, 3, (count, 1))
    negative = -rng.random((count // 10, 3))
    cone = rng.random((count, 3))
    cone[:, 0] = -cone[:, 1] * (1.0 + rng.uniform(-1e-3, 1e-3, count))
    return np.concatenate([inside, wide, bright, negative, cone])


def ocio_fixed(style, direction):
    import PyOpenColorIO as ocio

    transform = ocio.FixedFunctionTransform(style, direction=direction)
    processor = ocio.Config.CreateRaw().getProcessor(transform).getDefaultCPUProcessor()

    def apply(values):
        pixels = np.ascontiguousarray(values, dtype=np.float32)
        processor.applyRGB(pixels)
        return pixels.astype(np.float64)

    return apply
