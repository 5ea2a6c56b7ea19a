"""The ACES 1.x Reference Rendering Transform (RRT), forward and inverse, in float64.

Academy of Motion Picture Arts and Sciences, aces-dev v1.3 (2021):
``transforms/ctl/rrt/RRT.ctl`` and ``InvRRT.ctl``, with ``lib/ACESlib.RRT_Common.ctl``
(glow module, red modifier, global desaturation, ``rrt_sweeteners`` and
``inv_rrt_sweeteners``), ``ACESlib.Transform_Common.ctl`` and
``ACESlib.Utilities_Color.ctl`` (saturation, hue, YC, the saturation matrix) and
``ACESlib.Tonescales.ctl`` (the C5 segmented spline). ACES2065-1 in, OCES (AP0) out.

The "sweeteners" act on ACES2065-1 and end in AP1 (the rendering space): the tone
scale follows them per channel. Colours are arrays (..., 3), linear, float64.

The inverse is the CTL's, which is not exact everywhere: the red modifier's inverse
weighs hue at the modified colour (the forward at the unmodified one) and takes
saturation to be (r - min) / r, true where red is the largest channel and at least
1e-2; the glow's inverse takes saturation at the glowed colour, true but for colours
whose largest channel is under 1e-2; the clamps (negative ACES, negative AP1) and the
tone scale's flat ends (below 0.18·2^-15 and above 0.18·2^18) are not undone.
"""

from __future__ import annotations

import numpy as np

from generator.colorimetry.gamuts import gamuts
from generator.colorimetry.matrices import channel_max, channel_min
from generator.rendering.aces13_spline import HALF_MAX, SegmentedSpline, spline_forward, spline_inverse

#: Glow module (ACESlib.RRT_Common.ctl): gain and the YC it is centred on.
GLOW_GAIN = 0.05
GLOW_MID = 0.08

#: Red modifier: scale toward the pivot, hue centre and full width (degrees).
RED_SCALE = 0.82
RED_PIVOT = 0.03
RED_HUE = 0.0
RED_WIDTH = 135.0

#: Global desaturation of the RRT.
RRT_SAT_FACTOR = 0.96

#: ACESlib.Transform_Common.ctl: saturation's numerator floor and denominator floor,
#: and the chroma weight of ``rgb_2_yc`` (ACESlib.Utilities_Color.ctl).
TINY = 1e-10
SATURATION_NOISE_FLOOR = 1e-2
YC_RADIUS_WEIGHT = 1.75

AP0_TO_XYZ = gamuts()["AP0"].rgb_to_xyz
AP1_TO_XYZ = gamuts()["AP1"].rgb_to_xyz
XYZ_TO_AP1 = np.linalg.inv(AP1_TO_XYZ)
AP0_TO_AP1 = XYZ_TO_AP1 @ AP0_TO_XYZ
AP1_TO_AP0 = np.linalg.inv(AP0_TO_XYZ) @ AP1_TO_XYZ

#: Luminance of AP1 RGB (the CTL's AP1_RGB2Y, the Y row of AP1_2_XYZ_MAT).
AP1_RGB_TO_Y = AP1_TO_XYZ[1]


def apply3x3(matrix: np.ndarray, rgb) -> np.ndarray:
    """A 3x3 matrix applied to colours along the last axis (as ``rgb @ matrix.T``, which
    numpy hands to BLAS: 2.5 times faster than an einsum on 65³ colours)."""
    return np.asarray(rgb, dtype=np.float64) @ matrix.T


def sat_adjust_matrix(saturation: float, rgb_to_y) -> np.ndarray:
    """Mix with luminance: (1 - s) Y + s RGB, as a 3x3 matrix on column vectors.

    ``calc_sat_adjust_matrix`` (ACESlib.Utilities_Color.ctl).
    """
    weights = np.asarray(rgb_to_y, dtype=np.float64)
    return (1.0 - saturation) * np.broadcast_to(weights, (3, 3)) + saturation * np.eye(3)


RRT_SAT_MATRIX = sat_adjust_matrix(RRT_SAT_FACTOR, AP1_RGB_TO_Y)

#: The RRT's tone scale (``RRT_PARAMS``, ACESlib.Tonescales.ctl): 0.18·2^-15 -> 1e-4,
#: 0.18 -> 4.8, 0.18·2^18 -> 1e4, flat beyond.
RRT_SPLINE = SegmentedSpline(
    coefs_low=(-4.0000000000, -4.0000000000, -3.1573765773, -0.4852499958, 1.8477324706, 1.8477324706),
    coefs_high=(-0.7185482425, 2.0810307172, 3.6681241237, 4.0000000000, 4.0000000000, 4.0000000000),
    min_point=(0.18 * 2.0**-15, 0.0001),
    mid_point=(0.18, 4.8),
    max_point=(0.18 * 2.0**18, 10000.0),
    slope_low=0.0,
    slope_high=0.0,
)


def rgb_to_saturation(rgb: np.ndarray) -> np.ndarray:
    """(max(M, TINY) - max(m, TINY)) / max(M, 1e-2), M and m the largest and smallest channel."""
    big, small = channel_max(rgb), channel_min(rgb)
    return (np.maximum(big, TINY) - np.maximum(small, TINY)) / np.maximum(big, SATURATION_NOISE_FLOOR)


def rgb_to_yc(rgb: np.ndarray) -> np.ndarray:
    """Luma with a chroma term: (r + g + b + 1.75 sqrt(b(b-g) + g(g-r) + r(r-b))) / 3."""
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    chroma = np.sqrt(np.maximum(b * (b - g) + g * (g - r) + r * (r - b), 0.0))
    return (r + g + b + YC_RADIUS_WEIGHT * chroma) / 3.0


def rgb_to_hue(rgb: np.ndarray) -> np.ndarray:
    """Hue in degrees, [0, 360): atan2(√3 (g - b), 2r - g - b); NaN where r = g = b."""
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    hue = np.degrees(np.arctan2(np.sqrt(3.0) * (g - b), 2.0 * r - g - b))
    hue = np.where(hue < 0.0, hue + 360.0, hue)
    return np.where((r == g) & (g == b), np.nan, hue)


def center_hue(hue: np.ndarray, centre: float) -> np.ndarray:
    """Hue relative to ``centre``, wrapped into [-180, 180]."""
    centred = hue - centre
    return np.where(centred < -180.0, centred + 360.0, np.where(centred > 180.0, centred - 360.0, centred))


def sigmoid_shaper(x: np.ndarray) -> np.ndarray:
    """A smooth step from 0 at x = -2 to 1 at x = +2 (two parabolas)."""
    t = np.maximum(1.0 - np.abs(x / 2.0), 0.0)
    return (1.0 + np.sign(x) * (1.0 - t * t)) / 2.0


def cubic_basis_shaper(x: np.ndarray, width: float) -> np.ndarray:
    """A uniform cubic B-spline bump of full base ``width`` centred on 0, peak 1 (NaN -> 0)."""
    coord = (np.nan_to_num(x, nan=-width) + width / 2.0) * 4.0 / width
    j = np.clip(np.floor(coord), 0, 3).astype(np.intp)
    t = coord - j
    # Rows: the four cubic pieces of the B-spline basis, highest power first, times 6.
    pieces = np.array([[1.0, 0.0, 0.0, 0.0], [-3.0, 3.0, 3.0, 1.0], [3.0, -6.0, 0.0, 4.0], [-1.0, 3.0, -3.0, 1.0]])
    p3, p2, p1, p0 = (np.take(column, j) for column in pieces.T)
    y = ((p3 * t + p2) * t + p1) * t + p0
    inside = (coord > 0.0) & (coord < 4.0)
    return np.where(inside, y / 6.0 * 1.5, 0.0)


def glow_forward(yc: np.ndarray, gain: np.ndarray, mid: float) -> np.ndarray:
    """Added glow: ``gain`` up to YC = 2/3 mid, none from 2 mid, gain (mid / YC - 1/2) between."""
    with np.errstate(divide="ignore", invalid="ignore"):
        between = gain * (mid / yc - 0.5)
    return np.where(yc <= 2.0 / 3.0 * mid, gain, np.where(yc >= 2.0 * mid, 0.0, between))


def glow_inverse(yc: np.ndarray, gain: np.ndarray, mid: float) -> np.ndarray:
    """The glow that takes a glowed colour of YC ``yc`` back (``glow_inv``)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        between = gain * (mid / yc - 0.5) / (gain / 2.0 - 1.0)
    low = yc <= (1.0 + gain) * 2.0 / 3.0 * mid
    return np.where(low, -gain / (1.0 + gain), np.where(yc >= 2.0 * mid, 0.0, between))


def _glow_gain(saturation: np.ndarray) -> np.ndarray:
    """The glow's gain: none up to saturation 0, all of GLOW_GAIN from 0.8."""
    return GLOW_GAIN * sigmoid_shaper((saturation - 0.4) / 0.2)


def glow_module(aces, saturation: np.ndarray | None = None) -> np.ndarray:
    """The glow module: dark saturated colours (YC under 0.16) brightened by up to 5%.

    ``saturation`` is the colour's (computed when not given).
    """
    aces = np.asarray(aces, dtype=np.float64)
    saturation = rgb_to_saturation(aces) if saturation is None else saturation
    return aces * (1.0 + glow_forward(rgb_to_yc(aces), _glow_gain(saturation), GLOW_MID))[..., np.newaxis]


def glow_module_inverse(aces) -> np.ndarray:
    """The inverse glow module (``inv_rrt_sweeteners``), saturation taken at the glowed colour."""
    aces = np.asarray(aces, dtype=np.float64)
    gain = _glow_gain(rgb_to_saturation(aces))
    return aces * (1.0 + glow_inverse(rgb_to_yc(aces), gain, GLOW_MID))[..., np.newaxis]


def _red_weight(aces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The red modifier's hue weight, and the hue centred on red."""
    centred = center_hue(rgb_to_hue(aces), RED_HUE)
    return cubic_basis_shaper(centred, RED_WIDTH), centred


def red_weight(aces) -> np.ndarray:
    """The red modifier's hue weight: 1 at red (hue 0), 0 from 67.5° either side on."""
    return _red_weight(np.asarray(aces, dtype=np.float64))[0]


def red_modifier(aces, saturation: np.ndarray) -> np.ndarray:
    """The red channel of reds (±67.5° of hue) pulled toward 0.03 by up to 18%, weighted by
    hue and by ``saturation`` (RRT.ctl: the colour's before the glow)."""
    aces = np.asarray(aces, dtype=np.float64)
    weight, _ = _red_weight(aces)
    red = aces[..., 0] + weight * saturation * (RED_PIVOT - aces[..., 0]) * (1.0 - RED_SCALE)
    return np.concatenate([red[..., np.newaxis], aces[..., 1:]], axis=-1)


def red_modifier_inverse(aces) -> np.ndarray:
    """The CTL's inverse red modifier: red from the root of a quadratic that weighs hue at
    the modified colour and takes saturation as (r - min) / r."""
    aces = np.asarray(aces, dtype=np.float64)
    weight, centred = _red_weight(aces)
    smallest = np.where(centred < 0.0, aces[..., 1], aces[..., 2])
    k = 1.0 - RED_SCALE
    a = weight * k - 1.0
    b = aces[..., 0] - weight * (RED_PIVOT + smallest) * k
    c = weight * RED_PIVOT * smallest * k
    red = (-b - np.sqrt(np.maximum(b * b - 4.0 * a * c, 0.0))) / (2.0 * a)
    return np.concatenate([red[..., np.newaxis], aces[..., 1:]], axis=-1)


def rrt_sweeteners(aces) -> np.ndarray:
    """ACES2065-1 to the RRT's AP1 rendering space, before its tone scale (``rrt_sweeteners``):
    glow, red modifier, clamp negative ACES, AP0 -> AP1, clamp to [0, HALF_MAX], desaturate
    to 96%."""
    aces = np.asarray(aces, dtype=np.float64)
    saturation = rgb_to_saturation(aces)
    aces = red_modifier(glow_module(aces, saturation), saturation)
    rgb = np.clip(apply3x3(AP0_TO_AP1, np.maximum(aces, 0.0)), 0.0, HALF_MAX)
    return apply3x3(RRT_SAT_MATRIX, rgb)


def rrt_sweeteners_inverse(rgb) -> np.ndarray:
    """AP1 rendering space back to ACES2065-1 (``inv_rrt_sweeteners``)."""
    rgb = apply3x3(np.linalg.inv(RRT_SAT_MATRIX), np.asarray(rgb, dtype=np.float64))
    aces = np.clip(apply3x3(AP1_TO_AP0, np.clip(rgb, 0.0, HALF_MAX)), 0.0, HALF_MAX)
    return glow_module_inverse(red_modifier_inverse(aces))


def rrt_tonescale(aces) -> np.ndarray:
    """ACES2065-1 through the sweeteners and the C5 tone scale: AP1, OCES luminance units."""
    return spline_forward(rrt_sweeteners(aces), RRT_SPLINE)


def rrt_forward(aces) -> np.ndarray:
    """The RRT (RRT.ctl): ACES2065-1 to OCES (AP0).

    >>> round(float(rrt_forward([0.18, 0.18, 0.18])[1]), 6)
    4.8
    """
    return apply3x3(AP1_TO_AP0, rrt_tonescale(aces))


def rrt_tonescale_inverse(rgb) -> np.ndarray:
    """AP1 tone-scale output (OCES luminance units) back to ACES2065-1."""
    return rrt_sweeteners_inverse(spline_inverse(rgb, RRT_SPLINE))


def rrt_inverse(oces) -> np.ndarray:
    """The inverse RRT (InvRRT.ctl): OCES (AP0) to ACES2065-1."""
    return rrt_tonescale_inverse(apply3x3(AP0_TO_AP1, np.asarray(oces, dtype=np.float64)))
