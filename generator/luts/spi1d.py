"""Sony Pictures Imageworks .spi1d writer (the 1D LUT format OCIO reads natively).

Format: ``Version 1``, ``From lo hi`` (the input domain, sampled uniformly),
``Length N``, ``Components 1``, then ``{`` N values ``}``. Values are written
with 9 significant digits (float32 round-trips exactly), so the same samples
always give the same bytes. Ours, not colour-science's, whose fixed decimals drop a
curve toe's float32 digits.
"""

from __future__ import annotations

import numpy as np


def format_spi1d(values, domain: tuple[float, float] = (0.0, 1.0)) -> str:
    """``values`` as a Sony Imageworks .spi1d over ``domain``."""
    values = np.asarray(values, dtype=np.float64)
    lines = ["Version 1", f"From {domain[0]:.9g} {domain[1]:.9g}", f"Length {values.size}", "Components 1", "{"]
    lines.extend(f"    {v:.9g}" for v in values)
    lines.append("}")
    return "\n".join(lines) + "\n"
