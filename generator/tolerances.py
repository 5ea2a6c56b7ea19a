"""Every numerical tolerance of the project, named once.

Relative errors are ``|a - b| / max(|b|, RELATIVE_FLOOR)``.
"""

#: Floor of the denominator of relative errors, so values near zero are compared absolutely.
RELATIVE_FLOOR = 0.1

#: An analytic OCIO path against the float64 reference evaluation.
ANALYTIC_RELATIVE = 1e-4

#: An analytic HDR display path against the reference, in ΔE ITP (ITU-R BT.2124),
#: where 1 is about one just-noticeable difference: a hundredth of one.
ANALYTIC_DELTA_E_ITP = 0.01

#: Display luminance (cd/m²) below which OCIO's HLG display builtin departs from
#: BT.2100: it replaces the inverse OOTF's infinite slope at black with a straight
#: line (measured: equal to 1e-7 at 0.1 cd/m², ΔE ITP 1.8 at 0.001 cd/m²).
HLG_BUILTIN_BLACK = 0.1

#: A colour space to the reference and back through OCIO.
ROUND_TRIP_RELATIVE = 1e-5

#: Relative precision of a float32 value (unit roundoff, 2**-24): the images OCIO
#: processes carry no more, so a round trip through float32 linear values cannot
#: resolve code values closer than this divided by the curve's slope.
FLOAT32_UNIT_ROUNDOFF = 2.0**-24

#: A baked 1D LUT standing in for a curve OCIO cannot express for the target version.
BAKED_CURVE_RELATIVE = 1e-4

#: Smallest xy area of a spec's gamut triangle, and of the triangle its white point makes with
#: any two of its primaries: a smaller one makes the RGB to XYZ matrix near singular (measured:
#: a sliver of this area gives a condition number of 210, a white this close to an edge 110,
#: ten times more at a tenth of the area), and float32 evaluation with it departs from the
#: reference by that factor times FLOAT32_UNIT_ROUNDOFF, near ANALYTIC_RELATIVE. The library's
#: smallest is 0.024.
GAMUT_MIN_XY_AREA = 1e-3

#: How far a spec's log_camera or piecewise_gamma curve evaluated as OCIO does (float32, and for
#: piecewise_gamma OCIO's clamps of gamma and offset) may depart from it, relative, on the codes
#: and linear values verify probes (transfer.float32_departure): a tenth of ANALYTIC_RELATIVE, so
#: a verify of the built config can pass. Measured: the library's LogCamera curves depart 1.6e-6
#: at most, its piecewise powers 8.2e-7; a base of 1e6 or a log-side slope of 1e-6 overflow, a
#: log-side offset of 100 departs 980, a lin_side_break of 1000 above black 3.8e-3 (OCIO itself
#: 2.4e-3: the toe's code carries the break's code, 1.3, whose float32 rounding the toe's
#: slope magnifies); a piecewise_gamma offset of 1e-9 departs 1.6e4 (OCIO evaluates offsets
#: below 1e-6 as 1e-6, a toe 1e4 times less steep), and gamma 10 with an offset up to 1e-4
#: overflows (the inverse toe's slope, ((gamma - 1) / offset)^(gamma - 1) ((1 + offset) /
#: gamma)^gamma, passes float32's 3.4e38).
CURVE_FLOAT32_RELATIVE = ANALYTIC_RELATIVE / 10

#: Chromaticity difference within which two gamuts are the same (published primaries
#: are given to three or four decimals): an HLG display's must be BT.2020's.
GAMUT_SAME_XY_ABSOLUTE = 1e-4


#: The CIE 1931 RGB -> XYZ matrix derived from today's 1 nm CMF tables against the
#: 5-decimal matrix of 1931: the 1931 figures came from the Wright-Guild data, the
#: tables were smoothed later (measured 8.0e-5).
PUBLISHED_MATRIX_ABSOLUTE = 1e-4

#: A camera gamut's matrix to ACES2065-1 derived with its publisher's adaptation against the
#: published matrix OCIO's builtin carries (printed to 6 to 10 decimals; measured 2.9e-6,
#: Venice S-Gamut3.Cine, whose primaries are themselves derived from the matrix).
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

#: The CIE daylight-locus polynomial at a D illuminant's nominal CCT against the
#: chromaticity of its tabulated SPD (the polynomial sits about 1.0e-4 higher in y
#: for D50 to D75, from the rounding in CIE's D-series tables).
DAYLIGHT_LOCUS_XY_ABSOLUTE = 2e-4

#: Luminance a gamut mapping keeps (desaturation at constant Y), relative; float64 rounding only.
GAMUT_LUMINANCE_RELATIVE = 1e-12

#: Chromaticity a gamut mapping keeps (xy, or the spectral-locus point of the dominant wavelength).
GAMUT_CHROMATICITY_ABSOLUTE = 1e-12

#: Oklab lightness and hue (radians) the perceptual gamut mapping keeps.
GAMUT_OKLAB_ABSOLUTE = 1e-9

#: Oklab hue (radians) and departure from the focus line of a colour outside the cube of
#: a display whose Oklab hue folds (BT.709, BT.2020): its boundary point is sought with
#: ``FOLD_SLACK`` and clipped (measured: 0.0029 rad on the test colours).
GAMUT_FOLD_OKLAB = 0.005

#: Largest change of a perceptual image per unit change of the colour, where a line
#: meets the cube near an edge at a grazing angle (measured 41 along the edges).
GAMUT_PERCEPTUAL_LIPSCHITZ = 100.0

#: Oklab chroma below which a mapped colour's hue is not compared (hue is undefined at 0).
GAMUT_HUE_MIN_CHROMA = 1e-3

#: Distance of a channel from 0 or 1 for a colour mapped onto the display gamut boundary.
GAMUT_BOUNDARY_ABSOLUTE = 1e-9

#: The Reference Gamut Compression against OCIO's float32 fixed function, per channel,
#: divided by max(1, largest |component|) (the RGC commutes with positive scaling).
RGC_OCIO_SCALED = 1e-5

#: Decrease of Oklab output chroma tolerated along a ramp of increasing chroma at constant
#: L and hue built through linear RGB: where a cone response nears 0, its cube root turns
#: float64 rounding of the RGB into hue errors near 1e-8 rad (measured drop: 2.5e-9).
GAMUT_RGB_RAMP_MONOTONE_ABSOLUTE = 1e-8

#: One step of a 16-bit integer image file: a value an engine computed and wrote to
#: such a file reads back up to half of this away (the verifier allows exactly that).
UINT16_STEP = 1.0 / 65535.0

#: Half-width, in normalised code values, of the band around a published discontinuity
#: of a curve (N-Log's: two 10-bit codes) where a baked LUT interpolates across the jump
#: and the decoding is not monotonic; the verifier leaves it out.
DISCONTINUITY_BAND = 2.0 / 1023.0

#: Float32 rounding a 3x3 matrix product adds to each channel, in units of
#: FLOAT32_UNIT_ROUNDOFF times (|M| |x|) of that channel: gamma_3 = 3u / (1 - 3u)
#: (Higham 2002, 3.5). The verifier carries it, with the source curve's own
#: rounding (its condition number times u), through the destination curve: a
#: curve steep near zero (a pure power) turns it into a visible code difference.
FLOAT32_MATRIX_ROUNDINGS = 3.0

#: Float32 roundings of a 1D table's fractional index behind a Range (OCIO's CPU
#: renderer): the Range's multiply-add and the scale to entries, each relative to the
#: index, so a table of a thousand entries moves a coordinate by its slope times hundreds
#: of units in the last place (a Perceptual file's shaper near Display P3 HDR's black:
#: 5u, which the lattice's slope there makes 0.5 ΔE ITP of PQ's steep start).
FLOAT32_TABLE_INDEX_ROUNDINGS = 2.0

#: Float32 roundings an HSV coordinate meets through the desaturate view (generator.luts.hsv:
#: OCIO's RGB_TO_HSV, the shared file's matrix and table, the display file's matrix, tables
#: and lattice, and HSV_TO_RGB), each at most half a unit in the last place of the value.
FLOAT32_HSV_ROUNDINGS = 8

#: Float32 roundings of a lattice coordinate: the shared table's output, the display
#: file's table (its index and its interpolation) and the lattice's index.
FLOAT32_COORDINATE_ROUNDINGS = 4

#: How far OCIO's float32 RGB_TO_HSV leaves a saturation S in [1, 2] from the exact S of
#: its float32 input, absolute: the rounding of max - min (2**-24 of it, up to 2**-23 of S
#: near 2) and of the division (half of S's last place, 2**-24); measured 1.49 * 2**-23 on
#: colours from 1e-7 to 1e-3 of OCIO HSV's cone. There the colour's size is V / (2 - S), so
#: this is the float32 limit of any view through OCIO's HSV: 1.8e-7 / (2 - S) relative
#: (2% 1e-5 from the cone, 18% 1e-6 from it).
FLOAT32_HSV_CONE_SATURATION = 1.5 * 2.0**-23

#: A colour a bounded encoding (ADX, a tabulated curve) represents decodes back to itself
#: within float64 rounding, relative to its largest component; colours that do not
#: (non-positive printing-density exposure has no unique density, a table clamps beyond its
#: ends) are left out of its checks and of a LUT's probes and fit.
REPRESENTABLE_RELATIVE = 1e-9

#: A baked LUT read back through OCIO against the values the baker stored at the
#: lattice nodes (float32 reading of 5- to 6-decimal text; measured 2.3e-7).
LUT_NODE_ABSOLUTE = 1e-5

#: CLF (and config view) of a clip view, 33³, against the reference, ten-bit codes,
#: in-gamut colours (the issue's target; measured 0.008, float32 processing). A view
#: defined by its lattice (Perceptual) is held to it on every set against that lattice
#: (measured 0.007 lossless; hosts' default flags reach 0.06 from ACEScct, which verify names).
LUT_CLF_IN_GAMUT_CODES = 0.05

#: The standalone pack (luts/), every file and its README, in bytes: the issue's limit (30 MB).
LUT_PACK_BYTES = 30_000_000

#: CLF of the clip and scale mappings, 33³, every probe set, ten-bit codes (the issue's
#: target; measured 0.011 into sRGB and P3 since the lattice is uniform in log2(x + toe),
#: where both mappings are linear inside every tetrahedron).
LUT_CLF_SCALE_CODES = 1.0

#: As LUT_NODE_ABSOLUTE for a CLF whose source decoding, matrix and pre-shaper run in
#: float32 before the lattice, moving node inputs by about 1e-7 relative where the
#: mapping is steep (measured 2.3e-5, desaturate, ACEScct to sRGB).
LUT_CLF_NODE_ABSOLUTE = 1e-4

#: ΔE ITP (ITU-R BT.2124) of one ten-bit code on a PQ grey: a grey's I is the PQ code of
#: its luminance and ΔE ITP = 720 ΔI, so 720 / 1023 (checked on greys in tests). It turns
#: the issue's targets in ten-bit codes into ΔE ITP for HDR displays.
DELTA_E_ITP_PER_PQ_CODE = 720.0 / 1023.0

#: A baked view of an HDR display on in-gamut colours: LUT_CLF_IN_GAMUT_CODES PQ codes,
#: 0.035 ΔE ITP (measured 0.015 through OCIO's default CPU optimisation, 0.003 lossless: the
#: file ends in display light, which the config encodes).
LUT_VIEW_HDR_IN_GAMUT_DELTA_E_ITP = LUT_CLF_IN_GAMUT_CODES * DELTA_E_ITP_PER_PQ_CODE

#: A baked clip or scale view of an HDR display on every probe set: LUT_CLF_SCALE_CODES PQ
#: codes, 0.70 ΔE ITP (measured 0.003 through OCIO's default CPU optimisation, 0.0004
#: lossless, Rec.2100-PQ and Rec.2100-HLG).
LUT_VIEW_HDR_SCALE_DELTA_E_ITP = LUT_CLF_SCALE_CODES * DELTA_E_ITP_PER_PQ_CODE

#: CLF (and config view) of clip or scale on a logarithmic lattice (generator.luts.axes.LogAxis),
#: 33³, every probe set, ten-bit codes: exact but for float32 processing and the written
#: decimals (measured 0.011; the issue asks for 0.05 in-gamut and 1 on every set).
LUT_CLF_EXACT_CODES = 0.05

#: CLF of clip or scale into HLG, 33³, every probe set, ΔE ITP: HLG's inverse EOTF is not
#: per channel, so the lattice interpolates its luminance factor (measured 0.22).
LUT_CLF_HLG_DELTA_E_ITP = 0.25

#: ociobakelut's (OCIO 2.1) best 33³ Resolve .cube with clip (the shaper with the lowest p99
#: over all probe sets pooled, config with the source's linear space as scene reference),
#: p99 per probe set in ten-bit codes (ΔE ITP for Rec.2100-PQ), tetrahedral, for the pairs of
#: bench/lut_accuracy.py whose .cube meets :data:`LUT_CUBE_P99_RATIO` (shapers: ACEScct, none,
#: none, ACEScc). Linear Rec.2020 to Gamma 2.6 P3-D65 is left out: its best bake (shaper
#: Mi-Log) has an in-gamut p99 of 34.5, which ours only matches.
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
#: (the issue's target).
LUT_CUBE_P99_RATIO = 2.0

#: A Resolve .cube of ACEScg to sRGB (clip) against the reference on greys from 1e-4 to 16
#: times white, ten-bit codes: tetrahedral interpolation takes greys from the diagonal's
#: nodes, kept at their sampled values, and the shaper is linear in code values between
#: nodes, but a linear source's shaper table is uniform in linear light, 1e-3 of white
#: apart (measured 0.26, at 0.0036 of white; 0.12 from ARRI LogC4 into Rec.1886, but 13.7
#: from ACEScg into Rec.1886, whose 2.4 power is steep in the table's first step).
LUT_CUBE_GREY_CODES = 0.3

#: CLF of clip or scale, 33³, every probe set, ten-bit codes, when the file decodes the source
#: itself: OCIO's float32 Log operator is within about 3e-6 of the curve, which the matrix and
#: a steep encoding can amplify (measured 0.09, ACEScct to sRGB, brightest over-range colours;
#: the issue's target).
LUT_CLF_EVERY_SET_CODES = 1.0

#: ``ocioforge bake --view``'s files read through OCIO as written (lossless flags) against the
#: float64 evaluation of the same file (generator.luts.aces_bake.file_output), in display code
#: values: float32 reading of the decoding, Log operator and tables (measured 1.5e-6 at 17³,
#: ACEScct and ACEScg to sRGB and to Rec.2100-PQ, every format).
LUT_ACES_FILE_ABSOLUTE = 5e-6

#: ``ocioforge bake --view`` at its default 65³ from ACEScct, read through OCIO, against the
#: reference: p99 of each kind of colour of generator.luts.aces_probes (2048 of each), ten-bit
#: codes for the SDR view (ACES 2.0 Rec.709 on sRGB) as a CLF, ΔE ITP for the HDR view (ACES
#: 2.0 1000 cd/m² P3 D65 on Rec.2100-PQ) as a Resolve .cube: the figures measured, rounded up
#: to two digits (docs/aces-views.md gives them beside the plain recipe's and ociobakelut's).
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

#: Least share of white's luminance each of a display's primaries must give for a Desaturate
#: view (the other views take any primaries). The desaturate view's lattice follows ``1 / h_Y``, the
#: inverse luminance of a hue's saturated colour, which grows steep near a primary of
#: little luminance (measured through verify, a display with red (0.73, 0.28), green (0.14,
#: 0.86) and a blue of share 0.0050: 0.43 ten-bit codes against its tolerance of 1; share
#: 0.0012: 4.3; Rec.709's blue gives 0.072, DCI-P3's 0.069).
DISPLAY_MIN_LUMINANCE_SHARE = 0.005


# ACES 1.3 output transforms (generator.rendering.aces13*), against OpenColorIO 2.6's builtins on
# the probe sets of tests/rendering/test_aces13_ocio.py and against themselves.

#: The float64 spline inverse, SSTS and output transforms undoing their forward where the CTL
#: inverts exactly (log10 and its exponential rounding, magnified by the quadratic's root
#: near its knots; measured 8.0e-11).
ACES13_ROUND_TRIP_RELATIVE = 1e-9

#: Our glow and red modifier against OpenColorIO's fixed functions (ACES_GLOW_10, ACES_RED_MOD_10
#: and its inverse), relative to the largest component where both weigh by the same
#: saturation: float32 (measured 1.6e-7).
ACES13_OCIO_FIXED_FUNCTION_RELATIVE = 1e-6

#: The CTL's inverse red modifier weighs hue at the modified colour, the forward at the
#: original: reds come back this far, relative to the largest component (measured 1.69e-2 in
#: ACES, 1.1e-2 in display XYZ).
ACES13_RED_INVERSE_RELATIVE = 0.02

#: An SDR preset's mid-tones (0.01 to 10, near grey: no display channel near its zero) against
#: OpenColorIO's builtin, ten-bit codes: float32 and the builtins' tone-curve constants
#: (measured 0.014, SDR Video; 0.006 SDR Cinema).
ACES13_OCIO_MIDTONE_CODES = 0.02

#: OpenColorIO's B-spline tone curves (log10 in, log10 out) against the CTL's splines where its
#: fit keeps their slopes: float32 and the builtins' 8-digit control points (measured 4.4e-7).
ACES13_OCIO_CURVE_LOG10 = 1e-6

#: The same where OpenColorIO's fit rescales the slopes (AdjustRGBSlopes: float32 rounding
#: makes the top segment's end slope, 0, come out negative; the RRT's C5 and the 1000- and
#: 108-nit SSTS): its two top segments move (measured 2.8e-4, the RRT's: 6.4e-4 relative).
ACES13_OCIO_SLOPE_ADJUSTED_LOG10 = 3e-4

#: An SDR preset against OpenColorIO 2.6's builtin through the studio config's displays,
#: ten-bit codes, every probe set (measured 1.70, SDR Cinema (Rec.709 lim) on P3-D65). Black:
#: OCIO subtracts 0.02 where the CTL's black is pow10(log10(0.02)), leaving 1.5e-9 (0.22 codes
#: through BT.1886, 0.37 through gamma 2.6). Elsewhere its XYZ is within 2e-5 (relative) of
#: ours, which a display channel near the zero of a pure power turns into up to 1.7 codes on
#: these probes (more the nearer a colour comes: 3.7 on 400,000 random colours, SDR Cinema).
ACES13_OCIO_CODES = 2.0

#: The same for colours whose red modifier OpenColorIO weighs by the saturation after the glow
#: (RRT.ctl: before): they differ where the largest channel is under 1e-2, up to 1.3% of red
#: (measured 1.10 codes on the probes, SDR Video; 6.5 on 400,000 dark reds, SDR Cinema).
ACES13_OCIO_RED_DARK_CODES = 1.2

#: An HDR preset against OpenColorIO's builtin, ΔE ITP of the display's light (measured 0.091,
#: 1000 nits, where OCIO rescales its tone curve's slopes; 0.002 at 2000 and 4000 nits).
ACES13_OCIO_DELTA_E_ITP = 0.1

#: The same for the red modifier's dark colours (measured 0.72, 1000 and 2000 nits).
ACES13_OCIO_RED_DARK_DELTA_E_ITP = 0.75

#: inverse13 against OpenColorIO's inverse builtin on display colours of in-range ACES, relative
#: to the largest component (measured 1.25e-3, 108 nits, and 7.5e-4 at 1000 nits, where OCIO's
#: tone curve is rescaled; 1.2e-4 SDR, through its RRT curve's top segments).
ACES13_OCIO_INVERSE_RELATIVE = 2e-3

#: The ACES 2.0 Output Transform (generator.rendering.aces2) against OpenColorIO 2.6's builtins
#: and fixed function, ten-bit codes of IEC 61966-2-1's curve on an SDR preset (measured 0.042,
#: bright camera-gamut yellows). OCIO builds its tables in float32: its upper-hull gamma search
#: lands up to 2e-4 from float64's, the test point next to limit_J_max deciding it.
ACES2_OCIO_CODES = 0.05

#: ACES2_OCIO_CODES in ΔE ITP, for an HDR preset (measured 0.010). Both leave out the hues where
#: OCIO's narrowed hue search misses the interval and extrapolates its tables (slivers below a
#: few entries of the Rec.2020 presets' tables, under 1% of the hue circle: up to 0.3 ΔE ITP).
ACES2_OCIO_DELTA_E_ITP = ACES2_OCIO_CODES * DELTA_E_ITP_PER_PQ_CODE

#: The ACES 2.0 view's images back through its inverse and forward, ten-bit codes of IEC
#: 61966-2-1's curve for SDR (ΔE ITP through DELTA_E_ITP_PER_PQ_CODE for HDR): the CTL's inverse
#: estimates the compression line's slope gain in one pass above the analytic threshold
#: (measured 0.0144 codes, 0.0044 ΔE ITP; below it 1e-10).
ACES2_ROUND_TRIP_CODES = 0.02

#: A baked ACES 2.0 view's file through OCIO against its float64 evaluation, relative (the
#: file's output, limiting RGB over the peak, is about 1 at most): float32 and OCIO's fast
#: power in the file's last operator (measured 6.1e-5 with its default flags, 2.1e-6 lossless).
ACES_LATTICE_FILE_RELATIVE = 1e-4

#: A view applying looks, in ΔE ITP (BT.2124) on any display: the looks' float32 rounding, which
#: no per-sample allowance models, reaches near-black channels that a pure-power EOTF (Rec.1886)
#: magnifies without bound in codes; held as an analytic HDR path is.
LOOK_VIEW_DELTA_E_ITP = ANALYTIC_DELTA_E_ITP

#: The float32 rounding a look chain may leave on its output, in float32 epsilons of each channel:
#: a process space's log encoding and back (ACEScct: 12x a code's rounding) around the CDL's power.
LOOK_ROUNDING_ULPS = 16.0
