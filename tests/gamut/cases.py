"""Shared test material: real display gamuts and out-of-gamut source colours."""

from __future__ import annotations

import colour
import numpy as np

from generator.gamut import DisplayGamut

#: The destination displays, from colour-science's colourspaces (read only).
DISPLAY_NAMES = ("ITU-R BT.709", "P3-D65")

#: Wider sources whose colours the displays cannot all show.
SOURCE_NAMES = ("ACEScg", "ITU-R BT.2020")

PAIRS = [(display, source) for display in DISPLAY_NAMES for source in SOURCE_NAMES]


def display(name: str) -> DisplayGamut:
    return DisplayGamut.from_colourspace(colour.RGB_COLOURSPACES[name])


def source_to_display(source: str, display_name: str) -> np.ndarray:
    """The matrix a caller applies, CAT02 between different whites (colour-science's default)."""
    return colour.matrix_RGB_to_RGB(colour.RGB_COLOURSPACES[source], colour.RGB_COLOURSPACES[display_name])


def source_colours(source: str, display_name: str, count: int = 4000, seed: int = 0) -> np.ndarray:
    """Uniform source RGB in [0, 1]^3 expressed in linear display RGB, shape (count, 3)."""
    rgb = np.random.default_rng(seed).uniform(0.0, 1.0, (count, 3))
    return colour.RGB_to_RGB(rgb, source, display_name)


def display_colours(count: int = 4000, seed: int = 1) -> np.ndarray:
    """Uniform in-gamut display RGB, plus the cube's corners, shape (count + 8, 3)."""
    corners = np.array([[r, g, b] for r in (0, 1) for g in (0, 1) for b in (0, 1)], dtype=float)
    return np.vstack([np.random.default_rng(seed).uniform(0.0, 1.0, (count, 3)), corners])
