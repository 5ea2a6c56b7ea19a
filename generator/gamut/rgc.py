"""The ACES Reference Gamut Compression (RGC), applied in display RGB.

The algorithm is that of the Academy's ACES 1.3 look transform
``LMT.Academy.ReferenceGamutCompress`` (Academy of Motion Picture Arts and
Sciences, aces-dev v1.3, 2021, designed by the ACES Gamut Mapping Virtual
Working Group), which OpenColorIO (2.1 and later) implements as
``FixedFunctionTransform(FIXED_FUNCTION_ACES_GAMUT_COMP_13, params)`` with
params ``[lim_c, lim_m, lim_y, thr_c, thr_m, thr_y, power]``:

* the achromatic value is ``a = max(r, g, b)``;
* each channel's distance from it is ``d = (a - c) / |a|`` (0 when ``a = 0``);
  ``d = 1`` is the gamut boundary (channel at 0), ``d > 1`` is outside;
* distances below the threshold ``thr`` are kept; above, they are compressed
  by ``thr + s n / (1 + n^p)^(1/p)``, ``n = (d - thr) / s``, with the scale
  ``s`` chosen so that the distance limit ``lim`` lands on ``d = 1``;
* the channel is rebuilt as ``a - d' |a|``.

The Academy's look wraps this between the AP0-to-AP1 matrix and its inverse;
OpenColorIO's fixed function does *not* contain those matrices and acts on
whatever RGB it is given. Here it acts on destination display RGB, exactly as
that fixed function fed with display RGB, and :func:`rgc` then clips to
[0, 1] (beyond ``lim`` the compressed distance exceeds 1, and colours above 1
remain). Non-finite input follows the policy of
:mod:`generator.gamut.display`: NaN -> 0, -Inf -> 0, +Inf -> the largest
value (1 after mapping).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator.gamut.display import DisplayGamut, sanitize

#: The ranges OpenColorIO's FIXED_FUNCTION_ACES_GAMUT_COMP_13 accepts for each limit, each
#: threshold and the power (its FixedFunctionOpData validation, 2.1 to 2.6; measured): a
#: config with a parameter beyond them does not load.
OCIO_RANGES = {"limits": (1.001, 65504.0), "thresholds": (0.0, 0.9995), "power": (1.0, 65504.0)}


@dataclass(frozen=True)
class RGCParams:
    """Parameters of the Reference Gamut Compression; defaults are ACES 1.3's.

    The published defaults (``LMT.Academy.ReferenceGamutCompress.ctl``):
    limits cyan 1.147, magenta 1.264, yellow 1.312, chosen to enclose the
    encoding gamuts of common digital cinema cameras; thresholds 0.815, 0.803,
    0.880, chosen to protect the ColorChecker 24; power 1.2. Cyan, magenta and
    yellow are the red, green and blue distances.

    Valid ranges: limits > 1, thresholds in [0, 1), power >= 1.
    """

    limit_cyan: float = 1.147
    limit_magenta: float = 1.264
    limit_yellow: float = 1.312
    threshold_cyan: float = 0.815
    threshold_magenta: float = 0.803
    threshold_yellow: float = 0.880
    power: float = 1.2

    def __post_init__(self) -> None:
        if not all(np.isfinite(self.as_ocio_params())):
            raise ValueError("RGC parameters must be finite")
        if min(self.limits) <= 1.0:
            raise ValueError(f"RGC limits must exceed 1, got {self.limits}")
        if min(self.thresholds) < 0.0 or max(self.thresholds) >= 1.0:
            raise ValueError(f"RGC thresholds must lie in [0, 1), got {self.thresholds}")
        if self.power < 1.0:
            raise ValueError(f"RGC power must be at least 1, got {self.power}")

    @property
    def limits(self) -> tuple[float, float, float]:
        """The cyan, magenta and yellow limits."""
        return (self.limit_cyan, self.limit_magenta, self.limit_yellow)

    @property
    def thresholds(self) -> tuple[float, float, float]:
        """The cyan, magenta and yellow thresholds."""
        return (self.threshold_cyan, self.threshold_magenta, self.threshold_yellow)

    def as_ocio_params(self) -> list[float]:
        """The seven values in OpenColorIO's FixedFunctionTransform order."""
        return [*self.limits, *self.thresholds, self.power]

    def scales(self) -> np.ndarray:
        """Per-channel scale ``s`` putting the compressed limit at distance 1, shape (3,).

        From ``thr + s x / (1 + x^p)^(1/p) = 1`` at ``x = (lim - thr) / s``:
        ``s = (lim - thr) / (((1 - thr) / (lim - thr))^(-p) - 1)^(1/p)``.
        """
        lim, thr, p = np.array(self.limits), np.array(self.thresholds), self.power
        return (lim - thr) / (((1.0 - thr) / (lim - thr)) ** -p - 1.0) ** (1.0 / p)


def compress_distance(distance: np.ndarray, params: RGCParams) -> np.ndarray:
    """The RGC's shaper on distances from the achromatic axis.

    Parameters
    ----------
    distance : numpy.ndarray, shape (..., 3)
        Non-negative distances (cyan, magenta, yellow), finite or +Inf.
    params : RGCParams

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        Distances below threshold unchanged; above, ``thr + s / (1 + n^-p)^(1/p)``
        (the published ``thr + s n / (1 + n^p)^(1/p)`` rewritten so that
        huge ``n`` cannot overflow), increasing towards ``thr + s``.
    """
    thr = np.array(params.thresholds)
    s = params.scales()
    p = params.power
    n = np.maximum(distance - thr, 0.0) / s
    with np.errstate(divide="ignore"):
        inverse_power = n**-p  # +Inf at the threshold itself (n = 0): the distance stays there
    compressed = thr + s / (1.0 + inverse_power) ** (1.0 / p)
    return np.where(distance < thr, distance, compressed)


def rgc_compress(rgb, params: RGCParams | None = None) -> np.ndarray:
    """The Reference Gamut Compression alone, without the final clip.

    Parameters
    ----------
    rgb : array_like, shape (..., 3)
        Linear RGB, any values (non-finite per the module policy).
    params : RGCParams, optional
        Defaults to the ACES 1.3 values.

    Returns
    -------
    numpy.ndarray, shape (..., 3), float64
        Equal to OpenColorIO's ``FIXED_FUNCTION_ACES_GAMUT_COMP_13`` on the
        same RGB, up to its float32 arithmetic. Colours whose distances are
        all below their thresholds are returned unchanged, bit for bit.
    """
    params = params or RGCParams()
    c = sanitize(rgb)
    achromatic = c.max(axis=-1, keepdims=True)
    magnitude = np.abs(achromatic)
    nonzero = magnitude > 0.0
    with np.errstate(over="ignore"):  # a huge ratio overflows to +Inf, which compresses to thr + s
        distance = np.where(nonzero, (achromatic - c) / np.where(nonzero, magnitude, 1.0), 0.0)
    rebuilt = achromatic - compress_distance(distance, params) * magnitude
    keep = distance < np.array(params.thresholds)
    # As in the Academy's CTL and OpenColorIO, a zero achromatic value gives black.
    return np.where(nonzero, np.where(keep, c, rebuilt), 0.0)


def rgc(rgb, display: DisplayGamut | None = None, params: RGCParams | None = None) -> np.ndarray:
    """Reference Gamut Compression in display RGB, then a clip to [0, 1].

    Parameters
    ----------
    rgb : array_like, shape (..., 3)
        Linear display RGB, any values (non-finite per the module policy).
    display : ignored
        The RGC works on RGB ratios and needs no colorimetry; accepted for the
        uniform method signature.
    params : RGCParams, optional
        Defaults to the ACES 1.3 values.

    Returns
    -------
    numpy.ndarray, shape (..., 3), float64, within [0, 1].
    """
    return np.clip(rgc_compress(rgb, params), 0.0, 1.0)
