"""Vendor data that colour-science 0.4.7 does not carry.

Two kinds of data, both taken from the vendors' own publications:

* the *Samsung Log* transfer function (colour-science has no Samsung Log), as a
  pair of pure vectorised functions;
* the primaries and white points of the camera gamuts missing from
  ``colour.RGB_COLOURSPACES``, as plain :class:`GamutData` records in
  :data:`VENDOR_GAMUTS`.

Every other camera gamut the project needs is in ``colour.RGB_COLOURSPACES``
under these names: "ARRI Wide Gamut 3", "ARRI Wide Gamut 4", "S-Gamut3",
"S-Gamut3.Cine", "Venice S-Gamut3", "Venice S-Gamut3.Cine", "REDWideGamutRGB",
"Cinema Gamut", "V-Gamut", "Blackmagic Wide Gamut" (Generation 4/5),
"DaVinci Wide Gamut", "DJI D-Gamut", "F-Gamut", "F-Gamut C", "N-Gamut",
"FilmLight E-Gamut" and "FilmLight E-Gamut 2".

Nothing here touches colour-science's registries.
"""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

# --------------------------------------------------------------------------
# Samsung Log
# --------------------------------------------------------------------------

#: Samsung Log constants, Samsung Electronics, *Samsung Log White Paper* (2025),
#: section "Samsung Log transfer function". ``x`` is scene-linear reflectance
#: (0.18 = mid grey), ``y`` the full-range normalised code value.
SAMSUNG_LOG = MappingProxyType(
    {
        "x0": -0.05,  # lowest encodable linear; code 0 below it
        "xt": 0.01,  # linear where the toe meets the upper log segment
        "yt": 0.206561909,  # code where the toe meets the upper log segment
        "alpha1": 0.258984868,
        "beta1": 0.0003645,
        "gamma1": 0.720504856,
        "alpha2": -0.20942,
        "beta2": 0.016904,
        "gamma2": -0.24597,
    }
)


def samsung_log_encode(linear):
    """Samsung Log OETF: scene-linear reflectance to normalised code value.

    ``y = alpha1 * log10(x + beta1) + gamma1`` for ``x >= xt``, the mirrored
    logarithm ``alpha2 * log10(beta2 - x) + gamma2`` for ``x0 <= x < xt`` and
    0 below ``x0``.

    Parameters
    ----------
    linear : array_like
        Scene-linear reflectance, 0.18 for mid grey.

    Returns
    -------
    numpy.ndarray
        Full-range code value, 1.0 at linear 12.0.

    Notes
    -----
    The white paper's constants are rounded: at ``xt`` the toe ends 3.6e-6
    in code above the upper segment's start (so the encoding steps down by
    that much there), and the toe gives 3.8e-6, not 0, at ``x0``. The
    decoding is the exact inverse of each segment.

    References
    ----------
    Samsung Electronics (2025). *Samsung Log White Paper*.
    https://developer.samsung.com/mobile/samsung-log-video.html
    """
    k = SAMSUNG_LOG
    x = np.asarray(linear, dtype=np.float64)
    with np.errstate(invalid="ignore", divide="ignore"):
        upper = k["alpha1"] * np.log10(np.maximum(x, k["xt"]) + k["beta1"]) + k["gamma1"]
        toe = k["alpha2"] * np.log10(k["beta2"] - np.clip(x, k["x0"], k["xt"])) + k["gamma2"]
    return np.where(x >= k["xt"], upper, np.where(x >= k["x0"], toe, 0.0))


def samsung_log_decode(code):
    """Samsung Log inverse OETF: normalised code value to scene-linear reflectance.

    ``x = 10 ** ((y - gamma1) / alpha1) - beta1`` for ``y >= yt``,
    ``beta2 - 10 ** ((y - gamma2) / alpha2)`` for ``0 <= y < yt`` and ``x0``
    below code 0, as the white paper specifies.

    Parameters
    ----------
    code : array_like
        Full-range normalised code value.

    Returns
    -------
    numpy.ndarray
        Scene-linear reflectance, 0.18 for mid grey.

    References
    ----------
    Samsung Electronics (2025). *Samsung Log White Paper*.
    https://developer.samsung.com/mobile/samsung-log-video.html
    """
    k = SAMSUNG_LOG
    y = np.asarray(code, dtype=np.float64)
    upper = 10.0 ** ((np.maximum(y, k["yt"]) - k["gamma1"]) / k["alpha1"]) - k["beta1"]
    toe = k["beta2"] - 10.0 ** ((np.clip(y, 0.0, k["yt"]) - k["gamma2"]) / k["alpha2"])
    return np.where(y >= k["yt"], upper, np.where(y >= 0.0, toe, k["x0"]))


# --------------------------------------------------------------------------
# Camera gamuts missing from colour-science
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class GamutData:
    """An RGB gamut as its vendor publishes it.

    Attributes
    ----------
    name : str
        The gamut's name.
    primaries : tuple
        CIE 1931 xy chromaticities of red, green and blue, a 3x2 nested tuple.
    whitepoint : tuple
        CIE 1931 xy chromaticity of the white point.
    citation : str
        The document the numbers come from.
    """

    name: str
    primaries: tuple[tuple[float, float], tuple[float, float], tuple[float, float]]
    whitepoint: tuple[float, float]
    citation: str


_D65 = (0.3127, 0.3290)

#: ITU-R BT.2020-2 (2015), Table 3, item 1.3: the primaries several phone and
#: mirrorless-camera vendors record their log footage in.
_BT2020 = ((0.708, 0.292), (0.170, 0.797), (0.131, 0.046))

VENDOR_GAMUTS = MappingProxyType(
    {
        g.name: g
        for g in (
            GamutData(
                "Apple Wide Gamut",
                ((0.725, 0.301), (0.221, 0.814), (0.068, -0.076)),
                _D65,
                "Apple Inc. (2025). Apple Log 2 White Paper: Apple Wide Gamut primaries, D65 white.",
            ),
            GamutData(
                "Leica L-Gamut",
                _BT2020,
                _D65,
                "Leica Camera AG (2023). Leica L-Log Reference Manual v1.4, section 4 "
                "'Colorimetric Characteristics': L-Log footage (SL2, SL2-S, Q3) is recorded "
                "in ITU-R BT.2020; no separate L-Gamut primaries are published.",
            ),
            GamutData(
                "Samsung Log Gamut",
                _BT2020,
                _D65,
                "Samsung Electronics (2025). Samsung Log White Paper, Table 2: ITU-R BT.2020 primaries, D65 white.",
            ),
            GamutData(
                "Xiaomi Mi-Log Gamut",
                _BT2020,
                _D65,
                "Xiaomi Inc. (2024). Xiaomi Log Profile White Paper: Mi-Log footage is "
                "recorded in ITU-R BT.2020 primaries, D65 white.",
            ),
        )
    }
)
"""Camera gamuts colour-science lacks, by name."""
