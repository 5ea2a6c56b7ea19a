"""Hard gamut mappings: per-channel clip, desaturation to white, ray scaling.

All act on linear RGB of the destination display, arrays of shape (..., 3),
in float64, and return every channel within [0, 1]. Non-finite input follows
the policy of :mod:`generator.gamut.display`: NaN -> 0, -Inf -> 0, +Inf ->
the largest value (1 after mapping).

The two geometric methods are the two steps of the classical treatment of
undisplayable colours that this project's colour course teaches: first
*desaturate*, moving the colour on the line to the white point at constant
luminance until it lies inside the display's primary triangle, which keeps
its dominant wavelength (as defined in CIE 015:2018); then *scale*
along the ray through the origin into the RGB cube, which keeps its
chromaticity.
"""

from __future__ import annotations

import numpy as np

from generator.colorimetry.matrices import channel_max
from generator.gamut.display import DisplayGamut, sanitize


def clip(rgb, display: DisplayGamut | None = None, params=None) -> np.ndarray:
    """Clamp each channel to [0, 1].

    Parameters
    ----------
    rgb : array_like, shape (..., 3)
        Linear display RGB, any values (non-finite per the module policy).
    display, params : ignored
        Accepted for the uniform method signature.

    Returns
    -------
    numpy.ndarray, shape (..., 3), float64, within [0, 1].
    """
    return np.clip(sanitize(rgb), 0.0, 1.0)


def scale(rgb, display: DisplayGamut | None = None, params=None) -> np.ndarray:
    """Clamp negatives to 0, then divide by ``max(1, max(r, g, b))``.

    The second step is a move along the ray through the origin, so the
    chromaticity of the non-negative colour is kept.

    Parameters
    ----------
    rgb : array_like, shape (..., 3)
        Linear display RGB, any values (non-finite per the module policy).
    display, params : ignored
        Accepted for the uniform method signature.

    Returns
    -------
    numpy.ndarray, shape (..., 3), float64, within [0, 1].
    """
    c = np.maximum(sanitize(rgb), 0.0)
    return c / np.maximum(1.0, channel_max(c))[..., None]


def desaturation_amount(rgb: np.ndarray, neutral: np.ndarray) -> np.ndarray:
    """Smallest ``t`` in [0, 1] making ``rgb + t * (neutral - rgb)`` non-negative.

    Parameters
    ----------
    rgb : numpy.ndarray, shape (..., 3)
        Finite linear RGB.
    neutral : numpy.ndarray, shape (..., 1)
        The grey level to mix with, strictly positive.

    Returns
    -------
    numpy.ndarray, shape (..., 1)
        For a negative channel ``c`` the mix is non-negative from
        ``t = -c / (neutral - c)`` on, a value in (0, 1); channels already
        non-negative stay so for every ``t``. The result is the largest such
        bound, or 0 when nothing is negative.
    """
    negative = rgb < 0.0
    denominator = np.where(negative, neutral - rgb, 1.0)
    bound = np.where(negative, -rgb / denominator, 0.0)
    return bound.max(axis=-1, keepdims=True)


def desaturate(rgb, display: DisplayGamut, params=None) -> np.ndarray:
    """Mix with the neutral of equal luminance, then scale into the cube.

    With ``Y = rgb . w`` (``w`` the display's luminance weights, summing to
    ``Y_white``), a colour with ``Y <= 0`` becomes black. Otherwise the
    neutral ``n = Y / Y_white * (1, 1, 1)`` has luminance ``Y`` and the
    display white's chromaticity, and ``c' = c + t (n - c)`` with the
    smallest ``t`` in [0, 1] making every channel non-negative keeps ``Y``
    and lies on the line from the colour's chromaticity to the white point,
    so its dominant wavelength is kept (where its X + Y + Z is positive: a
    colour with ``Y > 0`` but negative X + Y + Z has its xy across the white
    point, and comes out with the complementary one). Then, if ``max(c') > 1``,
    ``c'' = c' / max(c')`` keeps the chromaticity.

    Parameters
    ----------
    rgb : array_like, shape (..., 3)
        Linear display RGB, any values (non-finite per the module policy).
    display : DisplayGamut
        Supplies the luminance weights.
    params : ignored
        Accepted for the uniform method signature.

    Returns
    -------
    numpy.ndarray, shape (..., 3), float64, within [0, 1]. A final clamp
    removes rounding residues of order 1e-16 at the zero channel.
    """
    c = sanitize(rgb)
    weights = display.luminance_weights
    luminance = c @ weights
    positive = (luminance > 0.0)[..., None]
    neutral = np.where(positive, luminance[..., None] / weights.sum(), 1.0)
    t = desaturation_amount(c, neutral)
    mixed = np.where(positive, c + t * (neutral - c), 0.0)
    peak = np.maximum(1.0, mixed.max(axis=-1, keepdims=True))
    return np.clip(mixed / peak, 0.0, 1.0)
