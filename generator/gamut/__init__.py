"""Gamut mapping of linear display RGB into the display's unit cube.

Every method has the signature ``fn(rgb, display, params=None) -> rgb``:
``rgb`` is linear RGB of the destination display, shape (..., 3), after the
caller's source-to-display matrix; ``display`` a :class:`DisplayGamut`; the
result is float64 of the same shape with every channel within [0, 1]. The
non-finite input policy is the same for all (see
:mod:`generator.gamut.display`): NaN -> 0, -Inf -> 0, +Inf -> the largest
value, hence 1 after mapping.

``METHODS`` maps the method names to the functions; it is read-only.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from types import MappingProxyType

import numpy as np

from generator.gamut.display import LARGEST, DisplayGamut, sanitize
from generator.gamut.perceptual import PerceptualParams, perceptual
from generator.gamut.rgc import RGCParams, rgc, rgc_compress
from generator.gamut.simple import clip, desaturate, scale

#: ``fn(rgb, display, params=None) -> rgb``; clip and scale also take ``display`` None.
Method = Callable[..., np.ndarray]

METHODS: Mapping[str, Method] = MappingProxyType(
    {
        "clip": clip,
        "desaturate": desaturate,
        "scale": scale,
        "rgc": rgc,
        "perceptual": perceptual,
    }
)

__all__ = [
    "LARGEST",
    "METHODS",
    "DisplayGamut",
    "PerceptualParams",
    "RGCParams",
    "clip",
    "desaturate",
    "perceptual",
    "rgc",
    "rgc_compress",
    "sanitize",
    "scale",
]
