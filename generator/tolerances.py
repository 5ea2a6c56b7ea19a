"""Every numerical tolerance of the project, named once.

Relative errors are ``|a - b| / max(|b|, RELATIVE_FLOOR)``. docs/tolerances.md gives
how each measured figure was measured.
"""

#: Floor of the denominator of relative errors, so values near zero are compared absolutely.
RELATIVE_FLOOR = 0.1

#: An analytic OCIO path against the float64 reference evaluation.
ANALYTIC_RELATIVE = 1e-4

#: An analytic HDR display path against the reference, in ΔE ITP (ITU-R BT.2124),
#: where 1 is about one just-noticeable difference: a hundredth of one.
ANALYTIC_DELTA_E_ITP = 0.01

#: Display luminance (cd/m²) below which OCIO's HLG display builtin departs from BT.2100,
#: replacing the inverse OOTF's infinite slope at black with a line (1e-7 at 0.1 cd/m²).
HLG_BUILTIN_BLACK = 0.1

#: A colour space to the reference and back through OCIO.
ROUND_TRIP_RELATIVE = 1e-5

#: Unit roundoff of float32 (2**-24), the precision of the images OCIO processes: a float32
#: round trip resolves no code values closer than this over the curve's slope.
FLOAT32_UNIT_ROUNDOFF = 2.0**-24

#: A baked 1D LUT standing in for a curve OCIO cannot express for the target version.
BAKED_CURVE_RELATIVE = 1e-4

#: Smallest xy area of a spec's gamut triangle, and of the white's triangle with any two
#: primaries: below it the RGB to XYZ matrix's condition number (210 here) brings float32
#: near ANALYTIC_RELATIVE. The library's smallest is 0.024.
GAMUT_MIN_XY_AREA = 1e-3

#: A spec's log_camera or piecewise_gamma curve evaluated as OCIO does (float32, OCIO's clamps)
#: against itself, relative (transfer.float32_departure): a tenth of ANALYTIC_RELATIVE, so a
#: verify can pass; the library's curves depart 1.6e-6 at most.
CURVE_FLOAT32_RELATIVE = ANALYTIC_RELATIVE / 10

#: Chromaticity difference within which two gamuts are the same (published primaries
#: are given to three or four decimals): an HLG display's must be BT.2020's.
GAMUT_SAME_XY_ABSOLUTE = 1e-4


#: The CIE 1931 RGB -> XYZ matrix derived from today's 1 nm CMF tables against the 5-decimal
#: matrix of 1931, which came from unsmoothed data: the measured 8.0e-5, rounded up.
PUBLISHED_MATRIX_ABSOLUTE = 1e-4

#: A camera gamut's matrix to ACES2065-1, derived with its publisher's adaptation, against the
#: published matrix OCIO's builtin carries (6 to 10 decimals): the measured 2.9e-6, rounded up.
PUBLISHED_CAMERA_MATRIX_ABSOLUTE = 1e-5


def published_rounding(decimals: int) -> float:
    """Half a unit in the last place of a figure published with ``decimals`` decimals:
    a derived value must round to the published one."""
    return 0.5 * 10.0**-decimals + 1e-15


#: Chromaticity derived from spectra against tabulated xy.
SPECTRAL_XY_ABSOLUTE = 1e-4

#: A transfer function against values printed in the vendor's paper.
PUBLISHED_CURVE_ABSOLUTE = 1e-4

#: Our float64 evaluation of a published formula against an independent float64
#: implementation of the same formula with the same constants (colour-science).
FORMULA_ABSOLUTE = 1e-9

#: The CIE daylight-locus polynomial at a D illuminant's nominal CCT against the xy of its
#: tabulated SPD: the polynomial sits about 1.0e-4 higher in y, from the tables' rounding.
DAYLIGHT_LOCUS_XY_ABSOLUTE = 2e-4

#: Luminance a gamut mapping keeps (desaturation at constant Y), relative; float64 rounding only.
GAMUT_LUMINANCE_RELATIVE = 1e-12

#: Chromaticity a gamut mapping keeps (xy, or the spectral-locus point of the dominant wavelength).
GAMUT_CHROMATICITY_ABSOLUTE = 1e-12

#: Oklab lightness and hue (radians) the perceptual gamut mapping keeps.
GAMUT_OKLAB_ABSOLUTE = 1e-9

#: Oklab hue (radians) and line a colour outside a hue-folding display's cube keeps, its
#: boundary point sought with ``FOLD_SLACK`` and clipped: the measured 0.0029, with margin.
GAMUT_FOLD_OKLAB = 0.005

#: Largest change of a perceptual image per unit change of the colour, where a line grazes
#: the cube near an edge: the measured 41, with margin.
GAMUT_PERCEPTUAL_LIPSCHITZ = 100.0

#: Oklab chroma below which a mapped colour's hue is not compared (hue is undefined at 0).
GAMUT_HUE_MIN_CHROMA = 1e-3

#: Distance of a channel from 0 or 1 for a colour mapped onto the display gamut boundary.
GAMUT_BOUNDARY_ABSOLUTE = 1e-9

#: The Reference Gamut Compression against OCIO's float32 fixed function, per channel,
#: divided by max(1, largest |component|) (the RGC commutes with positive scaling).
RGC_OCIO_SCALED = 1e-5

#: Fall of Oklab output chroma tolerated along a rising chroma ramp built through linear RGB:
#: near a zero cone response float64 rounding becomes hue errors near 1e-8 rad (drop: 2.5e-9).
GAMUT_RGB_RAMP_MONOTONE_ABSOLUTE = 1e-8

#: One step of a 16-bit integer image file: a value an engine computed and wrote to
#: such a file reads back up to half of this away (the verifier allows exactly that).
UINT16_STEP = 1.0 / 65535.0

#: Half-width, in normalised code values, of the band around a curve's published discontinuity
#: (N-Log's: two 10-bit codes) where a baked LUT interpolates across the jump; verify skips it.
DISCONTINUITY_BAND = 2.0 / 1023.0

#: Float32 rounding a 3x3 matrix product adds to each channel, in units of FLOAT32_UNIT_ROUNDOFF
#: times (|M| |x|) of that channel: gamma_3 = 3u / (1 - 3u) (Higham 2002, 3.5).
FLOAT32_MATRIX_ROUNDINGS = 3.0

#: Float32 rounding of a baked ACES view's Log operator on the luminance, log2(L + toe), in units
#: of FLOAT32_UNIT_ROUNDOFF times the toe in L: the sum (1) and the log2 of a value near the toe,
#: whose result |log2 toe| <= 10 carries 10 u, times ln 2 back in L (7): 8 in all.
ACES_LOG_ROUNDINGS = 8.0

#: Float32 rounding of a baked ACES view's chromaticity (p and q, in [0, 1]) before its 1D table, in
#: units of FLOAT32_UNIT_ROUNDOFF: XYZ_TO_xyY's sum and division (3), the matrix after it (2), the
#: Log operator's sum (1) and its log2, whose result |log2(p + 1/16)| <= 4 carries 4 u, times ln 2
#: back in p (3): 9 in all. OCIO's lossless run measured 7.0 at most over 400,000 AP1 colours.
ACES_CHROMA_ROUNDINGS = 9.0

#: Float32 roundings of a 1D table's fractional index behind a Range (OCIO's CPU renderer):
#: the Range's multiply-add and the scale to entries, each relative to the index.
FLOAT32_TABLE_INDEX_ROUNDINGS = 2.0

#: Float32 roundings an HSV coordinate meets through the desaturate view (generator.luts.hsv),
#: each at most half a unit in the last place of the value.
FLOAT32_HSV_ROUNDINGS = 8

#: Float32 roundings of a lattice coordinate: the shared table's output, the display
#: file's table (its index and its interpolation) and the lattice's index.
FLOAT32_COORDINATE_ROUNDINGS = 4

#: How far OCIO's float32 RGB_TO_HSV leaves a saturation S in [1, 2] from its exact value,
#: absolute: the roundings of max - min and of the division (measured 1.49 * 2**-23). It is
#: the float32 limit of any view through OCIO's HSV: 1.8e-7 / (2 - S) relative.
FLOAT32_HSV_CONE_SATURATION = 1.5 * 2.0**-23

#: A colour a bounded encoding (ADX, a tabulated curve) represents decodes back to itself within
#: this, relative to its largest component (float64 rounding); colours that do not are left out
#: of its checks and of a LUT's probes and fit.
REPRESENTABLE_RELATIVE = 1e-9

#: A baked LUT read back through OCIO against the values the baker stored at its nodes: float32
#: reading of 5- to 6-decimal text (measured 2.3e-7).
LUT_NODE_ABSOLUTE = 1e-5

#: CLF (and config view) of a clip view, 33³, in-gamut colours, ten-bit codes: the project's
#: target (measured 0.008). A Perceptual view is held to it against its own lattice.
LUT_CLF_IN_GAMUT_CODES = 0.05

#: The standalone pack (luts/), every file and its README, in bytes: the pack's limit (30 MB).
LUT_PACK_BYTES = 30_000_000

#: CLF of the clip and scale mappings, 33³, every probe set, ten-bit codes: the project's
#: target (measured 0.011).
LUT_CLF_SCALE_CODES = 1.0

#: As LUT_NODE_ABSOLUTE for a CLF whose decoding, matrix and pre-shaper run in float32 before
#: the lattice, moving node inputs where the mapping is steep (measured 2.3e-5).
LUT_CLF_NODE_ABSOLUTE = 1e-4

#: ΔE ITP (ITU-R BT.2124) of one ten-bit code on a PQ grey: ΔE ITP = 720 ΔI there, so
#: 720 / 1023. It turns targets in ten-bit codes into ΔE ITP for HDR displays.
DELTA_E_ITP_PER_PQ_CODE = 720.0 / 1023.0

#: A baked view of an HDR display on in-gamut colours: LUT_CLF_IN_GAMUT_CODES PQ codes,
#: 0.035 ΔE ITP (measured 0.015 through OCIO's default CPU optimisation).
LUT_VIEW_HDR_IN_GAMUT_DELTA_E_ITP = LUT_CLF_IN_GAMUT_CODES * DELTA_E_ITP_PER_PQ_CODE

#: A baked clip or scale view of an HDR display on every probe set: LUT_CLF_SCALE_CODES PQ
#: codes, 0.70 ΔE ITP (measured 0.003 through OCIO's default CPU optimisation).
LUT_VIEW_HDR_SCALE_DELTA_E_ITP = LUT_CLF_SCALE_CODES * DELTA_E_ITP_PER_PQ_CODE

#: CLF (and config view) of clip or scale on a logarithmic lattice (generator.luts.axes.LogAxis),
#: 33³, every probe set, ten-bit codes: exact but for float32 and the written decimals
#: (measured 0.011).
LUT_CLF_EXACT_CODES = 0.05

#: CLF of clip or scale into HLG, 33³, every probe set, ΔE ITP: HLG's inverse EOTF is not
#: per channel, so the lattice interpolates its luminance factor (measured 0.22).
LUT_CLF_HLG_DELTA_E_ITP = 0.25

#: ociobakelut's (OCIO 2.1) best 33³ Resolve .cube with clip, p99 per probe set in ten-bit
#: codes (ΔE ITP for Rec.2100-PQ), for the pairs of bench/lut_accuracy.py whose .cube meets
#: :data:`LUT_CUBE_P99_RATIO`.
OCIOBAKELUT_P99 = {
    ("ACEScg", "sRGB - Display"): {"in_gamut": 86.7, "dark": 73.4, "out_of_gamut": 146.3, "over_range": 245.8},
    ("ACEScct", "sRGB - Display"): {"in_gamut": 71.4, "dark": 12.4, "out_of_gamut": 146.6, "over_range": 246.2},
    ("ARRI LogC4", "Rec.1886 Rec.709 - Display"): {
        "in_gamut": 100.4,
        "dark": 33.3,
        "out_of_gamut": 193.4,
        "over_range": 318.9,
    },
    ("ACEScg", "Rec.2100-PQ - Display"): {"in_gamut": 7.00, "dark": 52.6, "out_of_gamut": 9.77, "over_range": 5.15},
}

#: How much better than ociobakelut's best bake a Resolve .cube must be, per probe set, in p99
#: (the project's target).
LUT_CUBE_P99_RATIO = 2.0

#: A Resolve .cube of ACEScg to sRGB (clip) against the reference on greys from 1e-4 to 16 times
#: white, ten-bit codes: a linear source's shaper table is coarse near black (measured 0.26).
LUT_CUBE_GREY_CODES = 0.3

#: CLF of clip or scale, 33³, every probe set, ten-bit codes, when the file decodes the source
#: itself: OCIO's float32 Log operator's error, amplified (measured 0.09); the project's target.
LUT_CLF_EVERY_SET_CODES = 1.0

#: ``ocioforge bake --view``'s files read through OCIO as written (lossless flags) against the
#: float64 evaluation of the same file (generator.luts.aces_bake.file_output), display code
#: values: float32 reading (measured 1.5e-6).
LUT_ACES_FILE_ABSOLUTE = 5e-6

#: ``ocioforge bake --view`` at its default 65³ from ACEScct, read through OCIO, against the
#: reference: p99 per kind of colour of generator.luts.aces_probes, in ten-bit codes (SDR, CLF)
#: or ΔE ITP (HDR, Resolve .cube): the measured figures rounded up to two digits.
LUT_ACES_P99 = {
    ("clf", "sRGB - Display"): {
        "in_gamut": 2.1,
        "ap0": 3.3,
        "dark": 0.70,
        "bright": 22.0,
        "greys": 0.45,
        "camera": 24.0,
    },
    ("resolve_cube", "Rec.2100-PQ - Display"): {
        "in_gamut": 0.42,
        "ap0": 0.36,
        "dark": 0.56,
        "bright": 1.4,
        "greys": 0.59,
        "camera": 0.79,
    },
}

#: Least share of white's luminance each display primary must give for a Desaturate view: the
#: view's lattice follows the inverse luminance of a hue's saturated colour, steep near a dim
#: primary (share 0.0050: 0.43 ten-bit codes against a tolerance of 1).
DISPLAY_MIN_LUMINANCE_SHARE = 0.005


# ACES 1.3 output transforms (generator.rendering.aces13*), against OpenColorIO 2.6's builtins on
# the probe sets of tests/rendering/test_aces13_ocio.py and against themselves.

#: The float64 spline inverse, SSTS and output transforms undoing their forward where the CTL
#: inverts exactly: log10 rounding, magnified near the knots (measured 8.0e-11).
ACES13_ROUND_TRIP_RELATIVE = 1e-9

#: Our glow and red modifier against OpenColorIO's fixed functions (ACES_GLOW_10, ACES_RED_MOD_10
#: and its inverse), relative to the largest component: float32 (measured 1.6e-7).
ACES13_OCIO_FIXED_FUNCTION_RELATIVE = 1e-6

#: Reds after the CTL's red modifier and its inverse, relative to the largest component: the
#: inverse weighs hue at the modified colour, the forward at the original (measured 1.69e-2).
ACES13_RED_INVERSE_RELATIVE = 0.02

#: An SDR preset's mid-tones (0.01 to 10, near grey) against OpenColorIO's builtin, ten-bit codes:
#: float32 and the builtins' tone-curve constants (measured 0.014).
ACES13_OCIO_MIDTONE_CODES = 0.02

#: OpenColorIO's B-spline tone curves (log10 in, log10 out) against the CTL's splines where its
#: fit keeps their slopes: float32 and 8-digit control points (measured 4.4e-7).
ACES13_OCIO_CURVE_LOG10 = 1e-6

#: The same where OpenColorIO's fit rescales the slopes (AdjustRGBSlopes), moving the two top
#: segments (measured 2.8e-4).
ACES13_OCIO_SLOPE_ADJUSTED_LOG10 = 3e-4

#: An SDR preset against OpenColorIO 2.6's builtin through the studio config's displays, ten-bit
#: codes, every probe set: black and near-zero channels of a pure power (measured 1.70).
ACES13_OCIO_CODES = 2.0

#: The same for dark colours, whose red modifier OpenColorIO weighs by the saturation after the
#: glow, the CTL before (measured 1.10).
ACES13_OCIO_RED_DARK_CODES = 1.2

#: An HDR preset against OpenColorIO's builtin, ΔE ITP of the display's light (measured 0.091,
#: at 1000 nits, where OCIO rescales its tone curve's slopes).
ACES13_OCIO_DELTA_E_ITP = 0.1

#: The same for the red modifier's dark colours (measured 0.72).
ACES13_OCIO_RED_DARK_DELTA_E_ITP = 0.75

#: inverse13 against OpenColorIO's inverse builtin on display colours of in-range ACES, relative
#: to the largest component (measured 1.25e-3, at 108 nits).
ACES13_OCIO_INVERSE_RELATIVE = 2e-3

#: The ACES 2.0 Output Transform (generator.rendering.aces2) against OpenColorIO 2.6's builtins,
#: ten-bit codes of an SDR preset: OCIO builds its tables in float32 (measured 0.042).
ACES2_OCIO_CODES = 0.05

#: ACES2_OCIO_CODES in ΔE ITP, for an HDR preset (measured 0.010). Both leave out the slivers of
#: hue where OCIO's narrowed hue search extrapolates its tables.
ACES2_OCIO_DELTA_E_ITP = ACES2_OCIO_CODES * DELTA_E_ITP_PER_PQ_CODE

#: The ACES 2.0 view's images back through its inverse and forward, ten-bit codes for SDR (ΔE ITP
#: through DELTA_E_ITP_PER_PQ_CODE for HDR): the CTL's one-pass slope estimate (measured 0.0144).
ACES2_ROUND_TRIP_CODES = 0.02

#: A baked ACES 2.0 view's file through OCIO against its float64 evaluation, relative: float32 and
#: OCIO's fast power in the file's last operator (measured 6.1e-5 with its default flags).
ACES_LATTICE_FILE_RELATIVE = 1e-4

#: A view applying looks, in ΔE ITP (BT.2124) on any display, held as an analytic HDR path is:
#: near black a pure-power EOTF magnifies the looks' float32 rounding without bound in codes.
LOOK_VIEW_DELTA_E_ITP = ANALYTIC_DELTA_E_ITP

#: Float32 rounding a look chain may leave on its output, in float32 epsilons of each channel:
#: a process space's log encoding and back (ACEScct: 12x a code's rounding) around the CDL's power.
LOOK_ROUNDING_ULPS = 16.0
