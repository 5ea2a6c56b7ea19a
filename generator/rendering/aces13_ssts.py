"""The single-stage tone scale (SSTS) of the ACES 1.1+ HDR Output Transforms, in float64.

Academy of Motion Picture Arts and Sciences, aces-dev v1.3 (2021):
``transforms/ctl/lib/ACESlib.SSTS.ctl`` (``init_TsParams``, ``ssts``, ``inv_ssts``) and
``ACESlib.OutputTransforms.ctl`` (``outputTransform`` / ``invOutputTransform``), as the
``transforms/ctl/outputTransform/`` files call them (``RRTODT.Academy.Rec2020_1000nits_15nits_ST2084``
and its 2000, 4000 nit, P3-D65 and 108-nit cinema siblings).

The tone scale is one C5 segmented spline from the minimum luminance to the peak,
built from three points: the minimum (slope 0), 0.18 -> 4.8 cd/m² (slope 1.55) and the
maximum (slope 0), whose scene exposures interpolate in stops between those of the
RRT (0.18·2^-15 at 1e-4 cd/m², 0.18·2^18 at 1e4) and of the 48-nit cinema tone scale
(0.18·2^-6.5 at 0.02, 0.18·2^6.5 at 48). The whole curve is then shifted in exposure
so that 0.18 gives the mid luminance asked for (15 cd/m² for HDR video).
The HDR output transforms add no surround, desaturation or white simulation.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator.rendering.aces13_odt import D60_TO_D65, limit_to_primaries, linear_cv_to_y, y_to_linear_cv
from generator.rendering.aces13_rrt import AP1_TO_XYZ, XYZ_TO_AP1, apply3x3
from generator.rendering.aces13_spline import SegmentedSpline, spline_forward, spline_inverse

#: Stops of 0.18 at the RRT's ends and the 48-nit SDR tone scale's, and their luminances.
MIN_STOP_RRT, MAX_STOP_RRT = -15.0, 18.0
MIN_STOP_SDR, MAX_STOP_SDR = -6.5, 6.5
MIN_LUM_RRT, MAX_LUM_RRT = 0.0001, 10000.0
MIN_LUM_SDR, MAX_LUM_SDR = 0.02, 48.0

#: The middle point (exposure, cd/m², log-log slope) before the exposure shift.
MID_POINT = (0.18, 4.8, 1.55)

#: The middle coefficient of each half, as a share of the way from the end's log
#: luminance to the middle's, interpolated in stops between the RRT's and the SDR's.
BEND_LOW = ((MIN_STOP_RRT, 0.18), (MIN_STOP_SDR, 0.35))
BEND_HIGH = ((MAX_STOP_SDR, 0.89), (MAX_STOP_RRT, 0.90))


def _interpolate(table, x) -> float:
    """The CTL's ``interpolate1D`` on a two-row table: linear, held at the ends."""
    (x0, y0), (x1, y1) = table
    return float(np.interp(x, [x0, x1], [y0, y1]))


def aces_min(min_luminance: float) -> float:
    """Scene exposure of the minimum point (``lookup_ACESmin``)."""
    table = ((np.log10(MIN_LUM_RRT), MIN_STOP_RRT), (np.log10(MIN_LUM_SDR), MIN_STOP_SDR))
    return 0.18 * 2.0 ** _interpolate(table, np.log10(min_luminance))


def aces_max(max_luminance: float) -> float:
    """Scene exposure of the maximum point (``lookup_ACESmax``)."""
    table = ((np.log10(MAX_LUM_SDR), MAX_STOP_SDR), (np.log10(MAX_LUM_RRT), MAX_STOP_RRT))
    return 0.18 * 2.0 ** _interpolate(table, np.log10(max_luminance))


def _straddle(point: tuple[float, float, float], half_knot: float) -> tuple[float, float]:
    """The two coefficients straddling a point: its tangent line at ± half a knot."""
    x, y, slope = point
    lx, ly = np.log10(x), np.log10(y)
    return slope * (lx - half_knot) + ly - slope * lx, slope * (lx + half_knot) + ly - slope * lx


def _coefficients(low_point, high_point, bend: float) -> tuple[float, ...]:
    """Six coefficients of one half (``init_coefsLow`` / ``init_coefsHigh``)."""
    half_knot = (np.log10(high_point[0]) - np.log10(low_point[0])) / 3.0 / 2.0
    c0, c1 = _straddle(low_point, half_knot)
    c3, c4 = _straddle(high_point, half_knot)
    ly_low, ly_high = np.log10(low_point[1]), np.log10(high_point[1])
    c2 = ly_low + bend * (ly_high - ly_low)
    return tuple(float(c) for c in (c0, c1, c2, c3, c4, c4))


def ssts_spline(min_luminance: float, max_luminance: float, exposure_shift: float = 0.0) -> SegmentedSpline:
    """The SSTS between two luminances, inputs shifted by ``exposure_shift`` stops
    (``init_TsParams``): the coefficients come from the unshifted points."""
    low = (aces_min(min_luminance), min_luminance, 0.0)
    high = (aces_max(max_luminance), max_luminance, 0.0)
    bend_low = _interpolate(BEND_LOW, np.log2(low[0] / 0.18))
    bend_high = _interpolate(BEND_HIGH, np.log2(high[0] / 0.18))
    shift = 2.0**-exposure_shift
    return SegmentedSpline(
        coefs_low=_coefficients(low, MID_POINT, bend_low),
        coefs_high=_coefficients(MID_POINT, high, bend_high),
        min_point=(low[0] * shift, min_luminance),
        mid_point=(MID_POINT[0] * shift, MID_POINT[1]),
        max_point=(high[0] * shift, max_luminance),
        slope_low=low[2],
        slope_high=high[2],
    )


def hdr_spline(min_luminance: float, mid_luminance: float, max_luminance: float) -> SegmentedSpline:
    """The SSTS whose 0.18 gives ``mid_luminance`` (``outputTransform``: the exposure shift
    is log2 of the unshifted curve's input for that luminance over 0.18).

    >>> round(float(spline_forward(0.18, hdr_spline(0.0001, 15.0, 1000.0))), 6)
    15.0
    """
    unshifted = ssts_spline(min_luminance, max_luminance)
    shift = float(np.log2(spline_inverse(mid_luminance, unshifted)) - np.log2(0.18))
    return ssts_spline(min_luminance, max_luminance, shift)


@dataclass(frozen=True)
class HdrOdt:
    """An HDR Output Transform's parameters: black, mid-grey and peak luminance (cd/m²)
    and the limiting gamut (a name of generator.colorimetry.gamuts)."""

    y_min: float
    y_mid: float
    y_max: float
    limiting: str

    @property
    def spline(self) -> SegmentedSpline:
        """The SSTS tone curve of the ODT's black, mid-grey and peak luminance."""
        return hdr_spline(self.y_min, self.y_mid, self.y_max)


def hdr_odt_forward(rgb, odt: HdrOdt, spline: SegmentedSpline | None = None) -> np.ndarray:
    """The RRT's sweetened AP1 to display XYZ (D65), 1.0 = 100 cd/m² (``outputTransform``
    with STRETCH_BLACK: the minimum luminance shows as 0, the peak as itself; display
    encoding left out)."""
    spline = odt.spline if spline is None else spline
    cv = y_to_linear_cv(spline_forward(rgb, spline), odt.y_max, odt.y_min)
    xyz = limit_to_primaries(apply3x3(AP1_TO_XYZ, cv), odt.limiting)
    return apply3x3(D60_TO_D65, xyz) * (odt.y_max / 100.0)


def hdr_odt_inverse(xyz, odt: HdrOdt, spline: SegmentedSpline | None = None) -> np.ndarray:
    """Display XYZ (1.0 = 100 cd/m²) back to the RRT's sweetened AP1 (``invOutputTransform``);
    the limiting clip is not undone, and luminances beyond the tone scale's ends give its ends."""
    spline = odt.spline if spline is None else spline
    xyz = apply3x3(np.linalg.inv(D60_TO_D65), np.asarray(xyz, dtype=np.float64) / (odt.y_max / 100.0))
    cv = apply3x3(XYZ_TO_AP1, xyz)
    return spline_inverse(linear_cv_to_y(cv, odt.y_max, odt.y_min), spline)
