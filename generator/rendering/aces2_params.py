"""What sets an ACES 2.0 Output Transform, checked, and the record of what is precomputed from it.

The parameters are those of an Academy output preset (aces-output v2.0, 2025, e.g.
``d65/rec709/Output.Academy.Rec709-D65_100nit_in_Rec709-D65_BT1886.ctl``): the peak
luminance the tone scale aims at, the limiting primaries and white (the gamut the
rendering fills, and the white it shows for RGB 1, 1, 1), the encoding primaries and
white (the display's own), whether the limiting white is scaled to fit the encoding
gamut (``scale_white``) and a final linear scale (0.48 for the cinema presets, whose
peak is stated in units of 48 cd/m² = 100).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator.rendering.jmh import JMhParams, jmh_params, rgb_to_jmh
from generator.rendering.tonescale import ToneScale
from generator.tolerances import GAMUT_MIN_XY_AREA

#: The peaks (cd/m²) OpenColorIO's ACES2 fixed functions accept, whole numbers only
#: (FixedFunctionOpData::validate, 2.4 to 2.6).
OCIO_PEAK_RANGE = (1.0, 10000.0)
#: The peaks the Academy designs the transform for (aces-core v2.0 CHANGELOG: "any peak
#: luminance between 100-10000 nits"); a dimmer display takes the 100 cd/m² rendering
#: scaled down, as the 48 cd/m² cinema presets do. Below it the algorithm degrades and then
#: fails: the chroma compression's strength turns negative below 49.8 cd/m² and the tone
#: scale's roof r_hit below 46.4, where the AP1 clamp's upper limit 8 r_hit turns every
#: colour black.
PEAK_RANGE = (100.0, OCIO_PEAK_RANGE[1])
#: The RGB cube's corners around its hue circle, red, yellow, green, cyan, blue, magenta
#: (aces-core v2.0 ``generate_unit_cube_cusp_corners``): the limiting gamut's cusps lie on
#: the edges between them.
CUBE_CORNERS = ((1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0), (0.0, 1.0, 1.0), (0.0, 0.0, 1.0), (1.0, 0.0, 1.0))


def _xy_array(value, shape: tuple[int, ...], name: str) -> np.ndarray:
    try:
        array = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be numbers of shape {shape}, got {value!r}") from None
    if array.shape != shape:
        raise ValueError(f"{name} must have shape {shape} (xy pairs), got {array.shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return array


def triangle_area(a, b, c) -> float:
    """Signed area of the xy triangle a, b, c (positive when counter-clockwise)."""
    return 0.5 * float((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))


def check_gamut(primaries, white, name: str) -> tuple[tuple[tuple[float, float], ...], tuple[float, float]]:
    """``primaries`` (3x2 xy) and ``white`` (xy) as tuples, or ValueError naming ``name``:
    finite, the white's y above 0, the primaries a triangle of xy area at least
    :data:`GAMUT_MIN_XY_AREA` in either orientation, and the white inside it by that margin."""
    p = _xy_array(primaries, (3, 2), f"{name}_primaries")
    w = _xy_array(white, (2,), f"{name}_white")
    if w[1] <= 0.0:
        raise ValueError(f"{name}_white must have y > 0, got {tuple(w)}")
    area = triangle_area(*p)
    if abs(area) < GAMUT_MIN_XY_AREA:
        raise ValueError(
            f"{name}_primaries must span an xy triangle of area at least {GAMUT_MIN_XY_AREA}, got {abs(area):.3g}"
        )
    weights = [triangle_area(w, p[(i + 1) % 3], p[(i + 2) % 3]) / area for i in range(3)]
    if min(weights) * abs(area) < GAMUT_MIN_XY_AREA:
        raise ValueError(
            f"{name}_white must lie inside the triangle of {name}_primaries, at least "
            f"{GAMUT_MIN_XY_AREA} of xy area from each edge, got {tuple(w)}"
        )
    return tuple((float(x), float(y)) for x, y in p), (float(w[0]), float(w[1]))


def corner_hues_in_order(params: JMhParams, peak: float) -> bool:
    """Whether the cube's corners at ``peak`` (cd/m²) go round the JMh hue circle once, in the
    order of :data:`CUBE_CORNERS`: the cusp table's construction assumes it."""
    hues = rgb_to_jmh(np.asarray(CUBE_CORNERS) * (peak / 100.0), params)[:, 2]
    turns = np.diff(np.append(hues, hues[0])) % 360.0
    return bool(np.all(turns > 0.0) and abs(turns.sum() - 360.0) < 1e-9)


def _check_number(value, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ValueError(f"{name} must be a number, got {value!r}")
    if not np.isfinite(value):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return float(value)


#: An xy chromaticity; three of them, red, green, blue.
XY = tuple[float, float]
Triangle = tuple[XY, XY, XY]


@dataclass(frozen=True)
class ACES2Params:
    """An ACES 2.0 Output Transform; checked on construction (ValueError names the field).

    ``peak_luminance``: cd/m², a whole number in :data:`PEAK_RANGE`, 100 to 10 000 (OpenColorIO
    takes whole numbers only). ``limiting_primaries`` (3x2 xy, red, green, blue), ``limiting_white`` (xy):
    a triangle and a white inside it (:func:`check_gamut`) whose six cube corners keep the hue
    order red, yellow, green, cyan, blue, magenta in JMh (:func:`corner_hues_in_order`).
    ``encoding_primaries``, ``encoding_white``: the limiting ones when omitted. ``scale_white``:
    None applies the white scaling exactly when the two whites differ. ``linear_scale``: above 0.
    """

    peak_luminance: float
    limiting_primaries: tuple[tuple[float, float], tuple[float, float], tuple[float, float]]
    limiting_white: tuple[float, float]
    encoding_primaries: tuple[tuple[float, float], tuple[float, float], tuple[float, float]] | None = None
    encoding_white: tuple[float, float] | None = None
    scale_white: bool | None = None
    linear_scale: float = 1.0

    def __post_init__(self) -> None:
        self.validate()

    def validate(self) -> None:
        """Check every field and store the limiting and encoding gamuts as tuples of floats."""
        peak = _check_number(self.peak_luminance, "peak_luminance")
        if not PEAK_RANGE[0] <= peak <= PEAK_RANGE[1] or peak != round(peak):
            raise ValueError(
                f"peak_luminance must be a whole number of cd/m² from {PEAK_RANGE[0]:g} to "
                f"{PEAK_RANGE[1]:g}, got {self.peak_luminance!r}"
            )
        primaries, white = check_gamut(self.limiting_primaries, self.limiting_white, "limiting")
        encoding = check_gamut(
            primaries if self.encoding_primaries is None else self.encoding_primaries,
            white if self.encoding_white is None else self.encoding_white,
            "encoding",
        )
        if not corner_hues_in_order(jmh_params(primaries, white), peak):
            raise ValueError(
                "limiting_primaries must be red, green and blue in that order: their cube's corners "
                "must go round the JMh hue circle as red, yellow, green, cyan, blue, magenta"
            )
        if self.scale_white is not None and not isinstance(self.scale_white, (bool, np.bool_)):
            raise ValueError(f"scale_white must be True, False or None, got {self.scale_white!r}")
        scale = _check_number(self.linear_scale, "linear_scale")
        if scale <= 0.0:
            raise ValueError(f"linear_scale must be above 0, got {self.linear_scale!r}")
        for field, value in (
            ("peak_luminance", peak),
            ("limiting_primaries", primaries),
            ("limiting_white", white),
            ("encoding_primaries", encoding[0]),
            ("encoding_white", encoding[1]),
            ("linear_scale", scale),
        ):
            object.__setattr__(self, field, value)

    @property
    def applies_white_scale(self) -> bool:
        """Whether the limiting white is scaled to fit the encoding gamut (the "D60 sim." step)."""
        if self.scale_white is not None:
            return bool(self.scale_white)
        return self.limiting_white != self.encoding_white


@dataclass(frozen=True, eq=False)
class ACES2Tables:
    """Everything an ACES 2.0 Output Transform precomputes once (aces-core v2.0 ``ODTParams``),
    made by ``generator.rendering.aces2.tables``.

    The hue-indexed tables have the CTL's 362 entries: entries 1 to 360 hold the nominal
    hues, entry 0 repeats the last (hue less 360) and entry 361 the first (hue plus 360).
    """

    params: ACES2Params
    input: JMhParams
    reach: JMhParams
    limit: JMhParams
    tone: ToneScale
    limit_j_max: float
    mid_j: float
    focus_dist: float
    lower_hull_gamma_inv: float
    sat: float
    sat_thr: float
    compr: float
    chroma_compress_scale: float
    #: Reach (AP1) M at limit_j_max, at whole degrees of hue.
    reach_m: np.ndarray
    #: The hues of the cusp table, nearly uniform, holding every corner of both gamuts.
    hues: np.ndarray
    cusp_j: np.ndarray
    #: Cusp M, already enlarged by the cusp smoothing (1 + 0.27 x 0.12).
    cusp_m: np.ndarray
    gamma_top_inv: np.ndarray
    ap0_to_ap1: np.ndarray
    ap1_to_ap0: np.ndarray
    limit_to_xyz: np.ndarray
    xyz_to_limit: np.ndarray
    #: Factor of the white scaling (1 where it does not apply) times the linear scale.
    display_scale: float
