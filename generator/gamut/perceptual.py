"""Hue-preserving soft chroma compression in Oklab.

Method (this project's design, documented here):

1. Display RGB -> XYZ -> *display-adapted* Oklab. Oklab (B. Ottosson, "A
   perceptual color space for image processing", 2020) is defined for D65;
   its neutral axis ``a = b = 0`` is not exactly any display's white (the
   colour-science D65, x = 0.3127, y = 0.3290, lands at a chroma of 1.2e-4).
   XYZ is therefore first adapted with CAT02 (CIE 159:2004) from the display
   white to the XYZ that Oklab maps to ``(1, 0, 0)``, so the display's greys
   ``k (1, 1, 1)`` are exactly ``(k^(1/3), 0, 0)`` and its white has
   ``L = 1``. For D65 displays this is a correction of order 1e-4.
2. Lightness ``L`` and hue ``h`` are kept; only the chroma ``C`` changes
   (no lightness focus). Lightness outside the display's range [0, 1] is
   first clamped to it: there the only displayable colour of that lightness
   is black or white, so such colours go to black or white.
3. Along the hue at constant ``L`` the display boundary chroma ``C_d`` is
   found by bisection (:data:`BISECTION_STEPS` fixed steps, bracket
   [0, :data:`CHROMA_BRACKET`]) on "display RGB within [0, 1]", assuming
   the constant-``L`` hue slice is star-shaped from the grey. The source
   boundary ``C_s`` is found the same way on the source gamut when
   ``source_to_display`` is given, and the limit is ``max(C_s / C_d, 1)``;
   otherwise the limit is a fixed ratio, as the RGC's distance limits.
4. With ``x = C / C_d``, threshold ``t`` and limit ``l``, the compressed
   ratio is ``x`` for ``x <= t``, ``t + (1 - t)(1 - (1 - u)^k)`` with
   ``u = (x - t) / (l - t)`` and ``k = (l - t) / (1 - t)`` for
   ``t < x < l``, and 1 beyond. It is continuous with slope 1 at ``t``
   (so C1), increasing up to ``l``, where it reaches 1 with slope 0 (for
   ``l > 1``): the source boundary lands on the display boundary and
   everything beyond is clamped to it.
5. Back to RGB, then a clip removes rounding excursions (of order 1e-12).
   Colours not compressed (``x <= t`` and ``L`` in range) are returned
   unchanged, bit for bit.

Non-finite input follows :mod:`generator.gamut.display`: NaN -> 0, -Inf -> 0,
+Inf -> the largest value (so the colour is brighter than white: white). The
output is never NaN for any input.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator.gamut.display import DisplayGamut, matrix_tuple, sanitize

#: Bisection steps for a boundary chroma; the bracket shrinks to 2^-40 of its width.
BISECTION_STEPS = 40

#: Upper end of the chroma bracket; every gamut met has C < 0.5 (AP1 green: 0.49).
CHROMA_BRACKET = 1.0

#: RGB excursion still counted as inside a gamut during the bisection.
_INSIDE_SLACK = 1e-12

#: XYZ that Oklab maps to exactly (1, 0, 0): its implicit white.


def _colour():
    """colour-science, imported when a perceptual mapping first runs (it is slow to import)."""
    import colour

    return colour


def _oklab_white_xyz() -> np.ndarray:
    """XYZ of Oklab's white (L = 1, a = b = 0)."""
    return _colour().Oklab_to_XYZ(np.array([1.0, 0.0, 0.0]))


@dataclass(frozen=True)
class PerceptualParams:
    """Parameters of the Oklab chroma compression.

    Parameters
    ----------
    threshold : float
        Fraction of the display boundary chroma left untouched, in [0, 1).
    limit : float
        Chroma, as a multiple (>= 1) of the display boundary chroma, that lands
        on the boundary; used when ``source_to_display`` is None.
    source_to_display : array_like (3, 3), optional
        The matrix the caller applied (display RGB = matrix @ source RGB). The
        source gamut is its image of the unit cube; its boundary chroma at
        each lightness and hue sets the limit there.
    """

    threshold: float = 0.8
    limit: float = 1.25
    source_to_display: tuple[tuple[float, float, float], ...] | None = None

    def __post_init__(self) -> None:
        if not 0.0 <= self.threshold < 1.0:
            raise ValueError(f"threshold must lie in [0, 1), got {self.threshold}")
        if not 1.0 <= self.limit < np.inf:
            raise ValueError(f"limit must be finite and at least 1, got {self.limit}")
        if self.source_to_display is not None:
            object.__setattr__(self, "source_to_display", matrix_tuple(self.source_to_display))


def adapted_matrix(display: DisplayGamut) -> np.ndarray:
    """Display RGB to Oklab-white-adapted XYZ, shape (3, 3) (CAT02 von Kries)."""
    cat = _colour().adaptation.matrix_chromatic_adaptation_VonKries(
        display.white_xyz, _oklab_white_xyz(), transform="CAT02")
    return cat @ display.matrix


def display_to_oklab(rgb: np.ndarray, display: DisplayGamut) -> np.ndarray:
    """Finite linear display RGB (..., 3) to display-adapted Oklab (..., 3)."""
    return _colour().XYZ_to_Oklab(rgb @ adapted_matrix(display).T)


def oklab_to_display(lab: np.ndarray, display: DisplayGamut) -> np.ndarray:
    """Display-adapted Oklab (..., 3) to linear display RGB (..., 3)."""
    return _colour().Oklab_to_XYZ(lab) @ np.linalg.inv(adapted_matrix(display)).T


def boundary_chroma(lightness, hue_cos, hue_sin, xyz_to_rgb: np.ndarray) -> np.ndarray:
    """Largest chroma at which the colour stays inside the RGB cube, by bisection.

    Parameters
    ----------
    lightness, hue_cos, hue_sin : numpy.ndarray, shape (...)
        Oklab ``L`` in [0, 1] and the unit hue direction ``(cos h, sin h)``.
    xyz_to_rgb : numpy.ndarray, shape (3, 3)
        Adapted XYZ to the RGB whose unit cube is the gamut.

    Returns
    -------
    numpy.ndarray, shape (...)
        The inside end of the final bracket, within ``CHROMA_BRACKET * 2^-40``
        below the boundary; 0 if even the grey is outside.
    """
    inside_low = np.zeros(np.shape(lightness))
    outside_high = np.full(np.shape(lightness), CHROMA_BRACKET)
    for _ in range(BISECTION_STEPS):
        middle = 0.5 * (inside_low + outside_high)
        lab = np.stack([lightness, middle * hue_cos, middle * hue_sin], axis=-1)
        rgb = _colour().Oklab_to_XYZ(lab) @ xyz_to_rgb.T
        inside = np.all((rgb >= -_INSIDE_SLACK) & (rgb <= 1.0 + _INSIDE_SLACK), axis=-1)
        inside_low = np.where(inside, middle, inside_low)
        outside_high = np.where(inside, outside_high, middle)
    return inside_low


def compress_ratio(ratio: np.ndarray, threshold: float, limit: np.ndarray) -> np.ndarray:
    """The compression curve on ``x = C / C_d`` (step 4 of the module docstring).

    Parameters
    ----------
    ratio : numpy.ndarray
        Non-negative ratios, finite or +Inf.
    threshold : float
        In [0, 1).
    limit : numpy.ndarray
        Broadcastable to ``ratio``, each >= 1.

    Returns
    -------
    numpy.ndarray
        Non-decreasing in ``ratio``, equal to it up to ``threshold``, at most 1.
    """
    span = limit - threshold
    u = np.clip((ratio - threshold) / span, 0.0, 1.0)
    compressed = threshold + (1.0 - threshold) * (1.0 - (1.0 - u) ** (span / (1.0 - threshold)))
    return np.where(ratio <= threshold, ratio, compressed)


def _limits(lightness, hue_cos, hue_sin, display_chroma, display, params) -> np.ndarray:
    if params.source_to_display is None:
        return np.full(np.shape(lightness), params.limit)
    to_source = np.linalg.inv(adapted_matrix(display) @ np.array(params.source_to_display))
    source_chroma = boundary_chroma(lightness, hue_cos, hue_sin, to_source)
    ratio = source_chroma / np.where(display_chroma > 0.0, display_chroma, 1.0)
    return np.where(display_chroma > 0.0, np.maximum(ratio, 1.0), 1.0)


def compress_chroma(lightness, chroma, hue_cos, hue_sin, display: DisplayGamut,
                    params: PerceptualParams) -> tuple[np.ndarray, np.ndarray]:
    """The chroma compression at fixed Oklab lightness and hue (steps 3 and 4).

    Parameters
    ----------
    lightness : numpy.ndarray, shape (...)
        Display-adapted Oklab ``L``, within [0, 1].
    chroma : numpy.ndarray, shape (...)
        Oklab chroma, finite and non-negative.
    hue_cos, hue_sin : numpy.ndarray, shape (...)
        The unit hue direction.
    display : DisplayGamut
    params : PerceptualParams

    Returns
    -------
    (numpy.ndarray, numpy.ndarray), shapes (...)
        The compressed chroma, non-decreasing in ``chroma`` at fixed lightness
        and hue and never above it; and the ratio ``C / C_d`` (+Inf where the
        boundary chroma is 0 and the chroma is not).
    """
    display_chroma = boundary_chroma(lightness, hue_cos, hue_sin, np.linalg.inv(adapted_matrix(display)))
    limit = _limits(lightness, hue_cos, hue_sin, display_chroma, display, params)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(chroma > 0.0, chroma / display_chroma, 0.0)
    compressed = np.where(display_chroma > 0.0, compress_ratio(ratio, params.threshold, limit), 0.0)
    compressed = np.minimum(compressed * display_chroma, chroma)
    return np.where(ratio <= params.threshold, chroma, compressed), ratio


def perceptual(rgb, display: DisplayGamut, params: PerceptualParams | None = None) -> np.ndarray:
    """Hue- and lightness-preserving soft chroma compression in Oklab.

    Parameters
    ----------
    rgb : array_like, shape (..., 3)
        Linear display RGB, any values (non-finite per the module policy).
    display : DisplayGamut
    params : PerceptualParams, optional
        Defaults: threshold 0.8, limit 1.25, no source gamut.

    Returns
    -------
    numpy.ndarray, shape (..., 3), float64, within [0, 1], never NaN.
    """
    params = params or PerceptualParams()
    c = sanitize(rgb)
    lab = display_to_oklab(c, display)
    lightness = np.clip(lab[..., 0], 0.0, 1.0)
    chroma = np.hypot(lab[..., 1], lab[..., 2])
    coloured = chroma > 0.0
    hue_cos = np.where(coloured, lab[..., 1] / np.where(coloured, chroma, 1.0), 1.0)
    hue_sin = np.where(coloured, lab[..., 2] / np.where(coloured, chroma, 1.0), 0.0)

    new_chroma, ratio = compress_chroma(lightness, chroma, hue_cos, hue_sin, display, params)
    mapped_lab = np.stack([lightness, new_chroma * hue_cos, new_chroma * hue_sin], axis=-1)
    mapped = oklab_to_display(mapped_lab, display)
    in_range = np.abs(lab[..., 0] - lightness) <= _INSIDE_SLACK
    untouched = (ratio <= params.threshold) & in_range
    # At the ends of the lightness range the only displayable colours are exact black and white.
    ends = np.where(lab[..., 0] >= 1.0, 1.0, 0.0)[..., None]
    mapped = np.where(in_range[..., None], mapped, ends)
    return np.clip(np.where(untouched[..., None], c, mapped), 0.0, 1.0)
