"""The ACES 1.x SDR Output Device Transforms (ODTs), forward and inverse, in float64.

Academy of Motion Picture Arts and Sciences, aces-dev v1.3 (2021):
``transforms/ctl/odt/`` (``ODT.Academy.Rec709_100nits_dim.ctl``,
``Rec709_D60sim_100nits_dim``, ``Rec2020_P3D65limited_100nits_dim``,
``Rec2020_Rec709limited_100nits_dim``, ``P3D65_48nits``, ``P3D65_Rec709limited_48nits``,
``P3D65_D60sim_48nits``, ``P3DCI_D60sim_48nits``, ``P3DCI_D65sim_48nits`` and their
``InvODT`` files), ``lib/ACESlib.ODT_Common.ctl`` (cinema white and black, dim surround,
ODT desaturation, white roll-off), ``ACESlib.Tonescales.ctl`` (the C9 48-nit spline) and
``ACESlib.OutputTransforms.ctl`` (``limit_to_primaries``).

An ODT here starts from OCES in AP1 (the RRT's tone-scale output, OCES luminance
units) and ends in CIE XYZ relative to the display's white, 1.0 its peak: the
display-encoding part of the CTL (XYZ to display RGB, clamp to [0, 1], inverse EOTF)
is left to the display, as in OpenColorIO's builtins. Colours are arrays (..., 3).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator.colorimetry.gamuts import D65, gamuts
from generator.colorimetry.matrices import adaptation_matrix
from generator.rendering.aces13_rrt import AP1_RGB_TO_Y, AP1_TO_XYZ, RRT_SPLINE, XYZ_TO_AP1, apply3x3, sat_adjust_matrix
from generator.rendering.aces13_spline import SegmentedSpline, spline_forward, spline_inverse

#: Cinema white and black (cd/m²); the black is written pow10(log10(0.02)) in the CTL so
#: that the 48-nit tone scale's minimum gives a code value of exactly 0.
CINEMA_WHITE = 48.0
CINEMA_BLACK = 10.0 ** np.log10(0.02)

#: Gamma on luminance that compensates a dim surround (``DIM_SURROUND_GAMMA``).
DIM_SURROUND_GAMMA = 0.9811

#: Desaturation of the video ODTs, for their brighter 100-nit white (``ODT_SAT_FACTOR``).
ODT_SAT_FACTOR = 0.93
ODT_SAT_MATRIX = sat_adjust_matrix(ODT_SAT_FACTOR, AP1_RGB_TO_Y)

#: Width of the white roll-off of the DCI white simulations (``ROLL_WIDTH``).
ROLL_WIDTH = 0.5

#: The ACES white (D60) and its Bradford adaptation to D65 (``D60_2_D65_CAT``).
ACES_WHITE = gamuts()["AP0"].whitepoint
D60_TO_D65 = adaptation_matrix(ACES_WHITE, D65, "Bradford")

#: The 48-nit cinema tone scale (``ODT_48nits``): its points' inputs are the RRT's outputs
#: at 0.18·2^-6.5, 0.18 and 0.18·2^6.5; 0.02 to 48 cd/m², rising at 0.04 above.
ODT_48NITS_SPLINE = SegmentedSpline(
    coefs_low=(
        -1.6989700043,
        -1.6989700043,
        -1.4779000000,
        -1.2291000000,
        -0.8648000000,
        -0.4480000000,
        0.0051800000,
        0.4511080334,
        0.9113744414,
        0.9113744414,
    ),
    coefs_high=(
        0.5154386965,
        0.8470437783,
        1.1358000000,
        1.3802000000,
        1.5197000000,
        1.5985000000,
        1.6467000000,
        1.6746091357,
        1.6878733390,
        1.6878733390,
    ),
    min_point=(float(spline_forward(0.18 * 2.0**-6.5, RRT_SPLINE)), 0.02),
    mid_point=(float(spline_forward(0.18, RRT_SPLINE)), 4.8),
    max_point=(float(spline_forward(0.18 * 2.0**6.5, RRT_SPLINE)), 48.0),
    slope_low=0.0,
    slope_high=0.04,
)


@dataclass(frozen=True)
class SdrOdt:
    """What distinguishes one SDR ODT from another.

    ``dim_surround``: the video ODTs' surround gamma and desaturation.
    ``white_scale``: the D60/D65 simulations' scale (after clamping to 1, or to
    ``roll_white``); 1 for none. ``roll_white``: the new white of the DCI simulations'
    roll-off, None for none. ``adapt_to_d65``: Bradford from ACES white to D65 (off
    when the display shows the ACES white, D60 simulation). ``limiting``: gamut the
    colours are clipped to (a name of generator.colorimetry.gamuts), None for none.
    ``encoding_white``: the white of a display encoding the CTL writes XYZ into
    unadapted (DCI); OpenColorIO's display adapts from D65 to it, so the builtins'
    XYZ carries the inverse adaptation, as here.
    """

    dim_surround: bool
    white_scale: float = 1.0
    roll_white: float | None = None
    adapt_to_d65: bool = True
    limiting: str | None = None
    encoding_white: tuple[float, float] | None = None


def y_to_linear_cv(y, white: float, black: float) -> np.ndarray:
    """Luminance to linear code value: (Y - black) / (white - black) (``Y_2_linCV``)."""
    return (np.asarray(y, dtype=np.float64) - black) / (white - black)


def linear_cv_to_y(cv, white: float, black: float) -> np.ndarray:
    """Linear code value to luminance (``linCV_2_Y``)."""
    return np.asarray(cv, dtype=np.float64) * (white - black) + black


def surround_xyz(xyz, gamma: float) -> np.ndarray:
    """Luminance to the power ``gamma`` at constant chromaticity, through xyY as the CTL
    does (``dark_to_dim``): negative Y counts as 0, a zero sum X + Y + Z as 1e-10."""
    xyz = np.asarray(xyz, dtype=np.float64)
    total = xyz.sum(axis=-1)
    total = np.where(total == 0.0, 1e-10, total)
    x, y = xyz[..., 0] / total, xyz[..., 1] / total
    luminance = np.maximum(xyz[..., 1], 0.0) ** gamma
    over_y = luminance / np.maximum(y, 1e-10)
    return np.stack([x * over_y, luminance, (1.0 - x - y) * over_y], axis=-1)


def dark_to_dim(rgb) -> np.ndarray:
    """AP1 linear code values, dark to dim surround (``darkSurround_to_dimSurround``)."""
    xyz = surround_xyz(apply3x3(AP1_TO_XYZ, rgb), DIM_SURROUND_GAMMA)
    return apply3x3(XYZ_TO_AP1, xyz)


def dim_to_dark(rgb) -> np.ndarray:
    """AP1 linear code values, dim to dark surround (``dimSurround_to_darkSurround``)."""
    xyz = surround_xyz(apply3x3(AP1_TO_XYZ, rgb), 1.0 / DIM_SURROUND_GAMMA)
    return apply3x3(XYZ_TO_AP1, xyz)


def _roll_constants(new_white: float, width: float) -> tuple[float, float, float, float, float, float]:
    x0 = -1.0
    x1 = x0 + width
    y0, y1 = -new_white, x1
    m1 = x1 - x0
    return x0, x1, y0 - y1 + m1, 2.0 * (y1 - y0) - m1, y0, y1


def roll_white_forward(cv, new_white: float, width: float = ROLL_WIDTH) -> np.ndarray:
    """Roll code values down to ``new_white`` at 1 over the top ``width`` (``roll_white_fwd``):
    a parabola from (1 - width, 1 - width) to (1, new_white), straight beyond 1."""
    cv = np.asarray(cv, dtype=np.float64)
    x0, x1, a, b, c, _ = _roll_constants(new_white, width)
    t = (-cv - x0) / (x1 - x0)
    return np.where(t < 0.0, -(t * b + c), np.where(t > 1.0, cv, -((t * a + b) * t + c)))


def roll_white_inverse(cv, new_white: float, width: float = ROLL_WIDTH) -> np.ndarray:
    """The inverse roll-off (``roll_white_rev``): values above ``new_white`` give 1."""
    cv = np.asarray(cv, dtype=np.float64)
    x0, x1, a, b, c, y1 = _roll_constants(new_white, width)
    c = c + cv
    with np.errstate(invalid="ignore", divide="ignore"):
        t = 2.0 * c / (-np.sqrt(np.maximum(b * b - 4.0 * a * c, 0.0)) - b)
    rolled = -(t * (x1 - x0) + x0)
    return np.where(-cv < -new_white, -x0, np.where(-cv > y1, cv, rolled))


def limit_to_primaries(xyz, gamut: str) -> np.ndarray:
    """Clip XYZ to the RGB cube of ``gamut`` (its own white, no adaptation) and back
    (``limit_to_primaries``, ACESlib.OutputTransforms.ctl)."""
    to_xyz = gamuts()[gamut].rgb_to_xyz
    rgb = np.clip(apply3x3(np.linalg.inv(to_xyz), xyz), 0.0, 1.0)
    return apply3x3(to_xyz, rgb)


def _white_simulation(cv: np.ndarray, odt: SdrOdt) -> np.ndarray:
    if odt.roll_white is not None:
        cv = np.minimum(roll_white_forward(cv, odt.roll_white), odt.roll_white)
        return cv * odt.white_scale
    if odt.white_scale != 1.0:
        return np.minimum(cv, 1.0) * odt.white_scale
    return cv


def sdr_odt_forward(rgb, odt: SdrOdt) -> np.ndarray:
    """OCES in AP1 to display XYZ, 1.0 the display's peak (the ODTs above, display
    encoding left out)."""
    cv = y_to_linear_cv(spline_forward(rgb, ODT_48NITS_SPLINE), CINEMA_WHITE, CINEMA_BLACK)
    cv = _white_simulation(cv, odt)
    if odt.dim_surround:
        cv = apply3x3(ODT_SAT_MATRIX, dark_to_dim(cv))
    xyz = apply3x3(AP1_TO_XYZ, cv)
    if odt.adapt_to_d65:
        xyz = apply3x3(D60_TO_D65, xyz)
    if odt.limiting is not None:
        xyz = limit_to_primaries(xyz, odt.limiting)
    if odt.encoding_white is not None:
        xyz = apply3x3(adaptation_matrix(odt.encoding_white, D65, "Bradford"), xyz)
    return xyz


def sdr_odt_inverse(xyz, odt: SdrOdt) -> np.ndarray:
    """Display XYZ back to OCES in AP1 (the InvODTs). The limiting clip is not undone:
    a colour inside the limiting gamut comes back exactly, one outside as the unlimited
    ODT's inverse of it."""
    xyz = np.asarray(xyz, dtype=np.float64)
    if odt.encoding_white is not None:
        xyz = apply3x3(adaptation_matrix(D65, odt.encoding_white, "Bradford"), xyz)
    if odt.adapt_to_d65:
        xyz = apply3x3(np.linalg.inv(D60_TO_D65), xyz)
    cv = apply3x3(XYZ_TO_AP1, xyz)
    if odt.dim_surround:
        cv = dim_to_dark(apply3x3(np.linalg.inv(ODT_SAT_MATRIX), cv))
    if odt.roll_white is not None:
        cv = roll_white_inverse(cv / odt.white_scale, odt.roll_white)
    elif odt.white_scale != 1.0:
        cv = cv / odt.white_scale
    return spline_inverse(linear_cv_to_y(cv, CINEMA_WHITE, CINEMA_BLACK), ODT_48NITS_SPLINE)
