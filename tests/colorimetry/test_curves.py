"""The named curves: round trips, printed values, colour-science and OCIO builtins."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.colorimetry.curves import CURVES, HALF_MAX
from generator.colorimetry.transfer import Function, LogCamera, PiecewisePower, float32_departure

LOG_CAMERA = {
    "ACEScct",
    "ARRI LogC3 (EI800)",
    "ARRI LogC4",
    "S-Log3",
    "Log3G10",
    "V-Log",
    "BMDFilm Gen5",
    "DaVinci Intermediate",
    "D-Log",
    "F-Log",
    "F-Log2",
    "L-Log",
    "T-Log",
    "T-LogE",
    "JPLog2",
}
FUNCTION = {
    "ACEScc",
    "Canon Log 2",
    "Canon Log 3",
    "Apple Log",
    "N-Log",
    "Samsung Log",
    "Mi-Log",
    "ST 2084",
    "HLG",
}
OTHER = {
    "linear",
    "sRGB",
    "sRGB extended",
    "Rec.709",
    "Gamma 1.8",
    "Gamma 2.2",
    "Adobe RGB (1998)",
    "Gamma 2.4",
    "Gamma 2.6",
}


def relative(actual, expected) -> np.ndarray:
    expected = np.asarray(expected, dtype=np.float64)
    actual = np.asarray(actual, dtype=np.float64)
    return np.abs(actual - expected) / np.maximum(np.abs(expected), tolerances.RELATIVE_FLOOR)


def code_ramp(curve, n=2001) -> np.ndarray:
    """Code values over a Function's LUT domain, or from below black to 1 for the analytic families."""
    lo, hi = curve.domain if isinstance(curve, Function) else (-0.05, 1.0)
    return np.linspace(lo, hi, n)


def test_names_and_families():
    assert set(CURVES) == LOG_CAMERA | FUNCTION | OTHER
    assert {n for n, c in CURVES.items() if isinstance(c, LogCamera)} == LOG_CAMERA
    assert {n for n, c in CURVES.items() if isinstance(c, Function)} == FUNCTION
    assert all(CURVES[n].name == n for n in FUNCTION)
    with pytest.raises(TypeError):
        CURVES["sRGB"] = CURVES["linear"]


@pytest.mark.parametrize("name", sorted(CURVES))
def test_round_trip(name):
    curve = CURVES[name]
    codes = code_ramp(curve)
    linear = curve.decode(codes)
    assert np.all(np.isfinite(linear))
    assert np.all(np.diff(linear) > 0), "decoding must be strictly increasing over the domain"
    assert relative(curve.encode(linear), codes).max() <= tolerances.ROUND_TRIP_RELATIVE
    assert relative(curve.decode(curve.encode(linear)), linear).max() <= tolerances.ROUND_TRIP_RELATIVE


def test_function_domains():
    acescc, clog2 = CURVES["ACEScc"], CURVES["Canon Log 2"]
    assert acescc.decode(acescc.domain[0]) == pytest.approx(0.0, abs=1e-12)
    assert acescc.decode(acescc.domain[1]) == pytest.approx(HALF_MAX, rel=1e-9)
    assert clog2.domain[0] < 0.0 and clog2.decode(clog2.domain[0]) == pytest.approx(-0.05, rel=1e-9)
    for name in FUNCTION - {"ACEScc", "Canon Log 2"}:
        assert CURVES[name].domain == (0.0, 1.0), name


# --- Values printed in the vendors' papers and the standards -----------------------------

PRINTED = [
    # (curve, linear, code, source)
    ("ACEScct", 0.18, 0.4135884, "S-2016-001, ACEScct of 0.18"),
    ("ACEScct", 0.0, 0.0729055341958355, "S-2016-001, constant B"),
    ("ACEScc", 0.18, 0.4135884, "S-2014-003, ACEScc of 0.18"),
    ("ARRI LogC3 (EI800)", 0.18, 0.391007, "ARRI, ALEXA Log C Curve in VFX, EI 800 18 % grey"),
    ("ARRI LogC4", 0.18, 0.278396, "ARRI LogC4 specification, 18 % grey"),
    ("ARRI LogC4", CURVES["ARRI LogC4"].lin_side_break, 0.0, "ARRI LogC4 specification, t encodes to 0"),
    ("V-Log", 0.18, 0.423311, "Panasonic VARICAM V-Log/V-Gamut, 18 % grey"),
    ("Log3G10", 0.18, 1.0 / 3.0, "RED Log3G10 white paper, 18 % grey at 1/3"),
    ("Log3G10", -0.01, 0.0, "RED Log3G10 white paper, -0.01 encodes to 0"),
    ("DaVinci Intermediate", 0.00262409, 0.02740668, "DaVinci Intermediate, LIN_CUT to LOG_CUT"),
    ("F-Log", 0.00089, 0.100537775223865, "F-Log Data Sheet, cut1 to cut2"),
    ("F-Log2", 0.000889, 0.100686685370811, "F-Log2 Data Sheet, cut1 to cut2"),
    ("N-Log", 1.0, 619.0 / 1023.0, "Nikon N-Log specification, x = 150 ln(y) + 619 at y = 1"),
    ("ST 2084", 100.0, 1.0, "SMPTE ST 2084, 10000 cd/m2 at full signal"),
    ("HLG", 1.0 / 12.0, 0.5, "ITU-R BT.2100 Table 5, E = 1/12 at E' = 0.5"),
    ("HLG", 1.0, 1.0, "ITU-R BT.2100 Table 5, E = 1 at E' = 1"),
]

PRINTED_10_BIT = [
    # (curve, linear, 10-bit code, source)
    ("S-Log3", 0.0, 95, "Sony S-Log3 technical summary, 0 % black"),
    ("S-Log3", 0.18, 420, "Sony S-Log3 technical summary, 18 % grey"),
    ("S-Log3", 0.90, 598, "Sony S-Log3 technical summary, 90 % white"),
    ("F-Log", 0.0, 95, "F-Log Data Sheet, 0 % black"),
    ("F-Log", 0.18, 470, "F-Log Data Sheet, 18 % grey"),
    ("V-Log", 0.0, 128, "Panasonic V-Log, 0 % black"),
    ("V-Log", 0.18, 433, "Panasonic V-Log, 18 % grey"),
    ("V-Log", 0.90, 602, "Panasonic V-Log, 90 % white"),
]


@pytest.mark.parametrize("name, linear, code, source", PRINTED, ids=[f"{p[0]}-{p[1]:.4g}" for p in PRINTED])
def test_printed_values(name, linear, code, source):
    assert float(CURVES[name].encode(linear)) == pytest.approx(code, abs=tolerances.PUBLISHED_CURVE_ABSOLUTE), source


@pytest.mark.parametrize("name, linear, code, source", PRINTED_10_BIT, ids=[f"{p[0]}-{p[1]}" for p in PRINTED_10_BIT])
def test_printed_10_bit_codes(name, linear, code, source):
    assert round(float(CURVES[name].encode(linear)) * 1023.0) == code, source


def test_pq_reference_white():
    """ITU-R BT.2408: HDR reference white, 203 cd/m², is 58 % of the PQ signal."""
    assert round(float(CURVES["ST 2084"].encode(2.03)) * 100.0) == 58


def test_pq_is_clamped_to_its_signal_range():
    """ST 2084 ends at code 1 (10000 cd/m²) and starts at 0: codes and light beyond are
    clamped (the formula decoded code 11.5 to negative light and encoded negative light to
    codes above 10)."""
    pq = CURVES["ST 2084"]
    codes = np.array([-1.0, -0.457, 0.0, 1.0, 1.5, 2.5, 10.04, 11.5])
    assert np.array_equal(pq.decode(codes), pq.decode(np.clip(codes, 0.0, 1.0)))
    light = np.array([-1.0, -0.1, 0.0, 100.0, 150.0, 1e5])
    assert np.array_equal(pq.encode(light), pq.encode(np.clip(light, 0.0, 100.0)))
    assert 0.0 <= pq.encode(-1.0) < 1e-6 and pq.encode(1e5) == pytest.approx(1.0, rel=1e-12)


# --- Against PyOpenColorIO's builtins -----------------------------------------------------

_CONFIG = ocio.Config.CreateRaw()


def apply_builtin(style: str, rgb) -> np.ndarray:
    processor = _CONFIG.getProcessor(ocio.BuiltinTransform(style)).getDefaultCPUProcessor()
    pixels = np.ascontiguousarray(rgb, dtype=np.float32)
    processor.applyRGB(pixels)
    return pixels.astype(np.float64)


#: Curve -> (builtin taking code to linear, factor from our linear to the builtin's).
#: The camera builtins end with a matrix to ACES2065-1 that keeps neutrals neutral,
#: so a grey ramp reads the curve. OCIO's HLG builtin returns 3 E: it scales BT.2100's
#: scene light so that mid grey 0.18 sits at HLG 0.42 (sqrt(3 x 0.06)).
DECODE_BUILTINS = {
    "ACEScct": ("CURVE - ACEScct-LOG_to_LINEAR", 1.0),
    "ACEScc": ("ACEScc_to_ACES2065-1", 1.0),
    "ARRI LogC3 (EI800)": ("ARRI_ALEXA-LOGC-EI800-AWG_to_ACES2065-1", 1.0),
    "ARRI LogC4": ("ARRI_LOGC4_to_ACES2065-1", 1.0),
    "S-Log3": ("SONY_SLOG3-SGAMUT3_to_ACES2065-1", 1.0),
    "Log3G10": ("RED_LOG3G10-RWG_to_ACES2065-1", 1.0),
    "V-Log": ("PANASONIC_VLOG-VGAMUT_to_ACES2065-1", 1.0),
    "Canon Log 2": ("CURVE - CANON_CLOG2_to_LINEAR", 1.0),
    "Canon Log 3": ("CURVE - CANON_CLOG3_to_LINEAR", 1.0),
    "Apple Log": ("CURVE - APPLE_LOG_to_LINEAR", 1.0),
    "ST 2084": ("CURVE - ST-2084_to_LINEAR", 1.0),
    "HLG": ("CURVE - HLG-OETF-INVERSE", 3.0),
}


@pytest.mark.parametrize("name", sorted(DECODE_BUILTINS))
def test_decode_against_ocio_builtin(name):
    style, factor = DECODE_BUILTINS[name]
    curve = CURVES[name]
    codes = code_ramp(curve, 4097)
    if name == "Canon Log 2":
        codes = codes[codes >= 0.0]  # see test_canon_log2_ocio_builtin_clamps_below_code_0
    actual = apply_builtin(style, np.repeat(codes[:, None], 3, axis=1))
    expected = factor * curve.decode(codes)
    assert relative(actual, expected[:, None]).max() <= tolerances.ANALYTIC_RELATIVE


def test_canon_log2_ocio_builtin_clamps_below_code_0():
    """OCIO bakes Canon Log 2 into a LUT over codes 0..1 and clamps below; the curve goes on."""
    curve = CURVES["Canon Log 2"]
    low = curve.domain[0]
    actual = apply_builtin("CURVE - CANON_CLOG2_to_LINEAR", np.full((1, 3), low))
    assert actual[0, 0] == pytest.approx(float(curve.decode(0.0)), rel=1e-5)
    assert float(curve.decode(low)) < float(curve.decode(0.0)) - 0.03


#: Display curves, linear to code, through builtins from CIE XYZ: a neutral of
#: luminance Y arrives as R = G = B = Y in the display's primaries.
ENCODE_BUILTINS = {
    "sRGB": "DISPLAY - CIE-XYZ-D65_to_sRGB",
    "Gamma 2.2": "DISPLAY - CIE-XYZ-D65_to_G2.2-REC.709",
    "Gamma 2.4": "DISPLAY - CIE-XYZ-D65_to_REC.1886-REC.709",
    "Gamma 2.6": "DISPLAY - CIE-XYZ-D65_to_G2.6-P3-D65",
}


@pytest.mark.parametrize("name", sorted(ENCODE_BUILTINS))
def test_encode_against_ocio_display_builtin(name):
    x, y = 0.3127, 0.3290
    white = np.array([x / y, 1.0, (1.0 - x - y) / y])
    linear = np.linspace(0.0, 1.0, 1025)
    actual = apply_builtin(ENCODE_BUILTINS[name], linear[:, None] * white[None, :])
    assert relative(actual, CURVES[name].encode(linear)[:, None]).max() <= tolerances.ANALYTIC_RELATIVE


def test_adobe_rgb_decodes_as_the_studio_config(default_spec):
    """Adobe RGB (1998) Color Image Encoding, 2005, 4.3.1.2: the exponent 2 51/256, as the ACES
    studio config's Gamma 2.2 Encoded AdobeRGB (2.2 was 5.5e-4 relative off at mid grey)."""
    import PyOpenColorIO as ocio

    from generator import reference

    assert CURVES["Adobe RGB (1998)"].exponent == 2.0 + 51.0 / 256.0
    codes = np.random.default_rng(2).random((256, 3))
    pixels = np.ascontiguousarray(codes, dtype=np.float32)
    studio = ocio.Config.CreateFromFile("ocio://studio-config-latest")
    studio.getProcessor("Gamma 2.2 Encoded AdobeRGB", "ACES2065-1").getDefaultCPUProcessor().applyRGB(pixels)
    ours = reference.to_reference(default_spec, default_spec.space("Gamma 2.2 Encoded AdobeRGB"), codes)
    assert np.abs(ours - pixels).max() <= tolerances.ANALYTIC_RELATIVE


def test_the_library_log_curves_and_piecewise_powers_survive_float32():
    """OCIO evaluates LogCamera and ExponentWithLinear in float32: every library curve's formula stays
    within the bound a spec's log_camera or piecewise_gamma is held to, with room (within 1.6e-6), on
    the values verify probes."""
    for name, curve in CURVES.items():
        if isinstance(curve, (LogCamera, PiecewisePower)):
            assert float32_departure(curve, tolerances.RELATIVE_FLOOR) <= tolerances.CURVE_FLOAT32_RELATIVE / 5, name
