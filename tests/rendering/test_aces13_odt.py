"""The SDR ODTs' pieces held to the CTL: cinema white and black, dim surround, the white
roll-off, limiting, and the white simulations' scales."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.colorimetry.gamuts import D65, gamuts
from generator.colorimetry.matrices import adaptation_matrix, normalised_primary_matrix
from generator.rendering import aces13_odt as odt
from generator.rendering.aces13 import DCI_WHITE, PRESETS13, forward13, inverse13
from generator.rendering.aces13_rrt import AP1_TO_XYZ, apply3x3, rrt_tonescale
from generator.rendering.aces13_spline import spline_forward

TABLE = tolerances.published_rounding(10)
FLOAT64 = 1e-12

#: Cinema stops of ACES grey: the 48-nit tone scale's minimum and maximum (0.18·2^±6.5).
CINEMA_BLACK_ACES, CINEMA_WHITE_ACES = 0.18 * 2.0**-6.5, 0.18 * 2.0**6.5


def test_cinema_tone_scale_spans_0_02_to_48_nits_with_mid_grey_at_4_8():
    oces = [odt.ODT_48NITS_SPLINE.min_point[0], odt.ODT_48NITS_SPLINE.mid_point[0], odt.ODT_48NITS_SPLINE.max_point[0]]
    nits = spline_forward(np.array(oces) * (1.0 - 1e-15), odt.ODT_48NITS_SPLINE)
    assert np.abs(np.log10(nits) - np.log10([0.02, 4.8, 48.0])).max() <= TABLE
    assert odt.y_to_linear_cv(odt.CINEMA_BLACK, odt.CINEMA_WHITE, odt.CINEMA_BLACK) == 0.0


@pytest.mark.parametrize(
    "view, expected",
    [
        # (4.8 - 0.02) / (48 - 0.02) of a 48 cd/m² white.
        ("ACES 1.0 - SDR Cinema", 48.0 * (4.8 - 0.02) / 47.98),
        # The same code value to the dim-surround gamma 0.9811, of a 100 cd/m² white.
        ("ACES 1.0 - SDR Video", 100.0 * ((4.8 - 0.02) / 47.98) ** 0.9811),
    ],
)
def test_mid_grey_luminance(view, expected):
    """ACES 0.18 shows at 4.782 cd/m² in the cinema and 10.41 cd/m² on video (not 4.8 and 10:
    the code value counts from the 0.02 cd/m² black, and video adds the surround gamma)."""
    y = forward13(np.full(3, 0.18), view)[1] * PRESETS13[view].output_scale
    assert y == pytest.approx(expected, rel=1e-9)
    assert round(y, 2) == {"ACES 1.0 - SDR Cinema": 4.78, "ACES 1.0 - SDR Video": 10.41}[view]


@pytest.mark.parametrize("view", [v for v, p in PRESETS13.items() if p.kind == "sdr"])
def test_cinema_stops_are_black_and_peak_and_the_inverse_clamps_to_them(view):
    """0.18·2^-6.5 and below give black, 0.18·2^6.5 the display's peak (less in a white
    simulation); the inverse of black is 0.18·2^-6.5, of peak and above 0.18·2^6.5."""
    preset = PRESETS13[view]
    greys = np.array([CINEMA_BLACK_ACES / 4.0, CINEMA_BLACK_ACES, CINEMA_WHITE_ACES])[:, None] * np.ones(3)
    luminance = forward13(greys, view)[:, 1]
    assert luminance[:2] == pytest.approx([0.0, 0.0], abs=FLOAT64)
    if preset.odt.white_scale == 1.0:
        assert luminance[2] == pytest.approx(1.0, rel=1e-9)
    peak = forward13(greys[2], view)
    back = inverse13(np.stack([np.zeros(3), peak, 4.0 * peak]), view)
    assert back == pytest.approx(np.array([[CINEMA_BLACK_ACES] * 3] + [[CINEMA_WHITE_ACES] * 3] * 2), rel=1e-9)


@pytest.mark.parametrize(
    "view, display",
    [
        ("ACES 1.0 - SDR Video (D60 sim on D65)", "Rec.709"),
        ("ACES 1.1 - SDR Cinema (D60 sim on D65)", "P3-D65"),
        ("ACES 1.0 - SDR Cinema (D60 sim on DCI)", "DCI-P3"),
        ("ACES 1.1 - SDR Cinema (D65 sim on DCI)", "DCI-P3"),
    ],
)
def test_white_simulations_scale_their_white_into_the_display(view, display):
    """The CTL's SCALE (0.955, 0.964, 0.96, 0.9575, given to three or four digits) brings the
    simulated white's largest display channel to 1 (within 1e-3)."""
    xyz = forward13(np.full(3, CINEMA_WHITE_ACES), view)
    white = gamuts()[display].whitepoint
    rgb = gamuts()[display].xyz_to_rgb @ adaptation_matrix(D65, white, "Bradford") @ xyz
    assert rgb.max() == pytest.approx(1.0, abs=1e-3)


def test_surround_gamma_keeps_chromaticity_and_inverts():
    rng = np.random.default_rng(8)
    rgb = rng.uniform(0.0, 1.0, (2000, 3))
    dim = odt.dark_to_dim(rgb)
    xyz, xyz_dim = apply3x3(AP1_TO_XYZ, rgb), apply3x3(AP1_TO_XYZ, dim)
    xy = xyz[:, :2] / xyz.sum(axis=-1, keepdims=True)
    assert np.allclose(xyz_dim[:, :2] / xyz_dim.sum(axis=-1, keepdims=True), xy, rtol=0.0, atol=FLOAT64)
    assert np.allclose(xyz_dim[:, 1], xyz[:, 1] ** odt.DIM_SURROUND_GAMMA, rtol=FLOAT64)
    assert np.allclose(odt.dim_to_dark(dim), rgb, rtol=0.0, atol=FLOAT64)


@pytest.mark.parametrize("new_white", [0.918, 0.908])
def test_white_roll_off(new_white):
    """roll_white_fwd: identity up to 1 - width, new_white at 1, smooth at 1 - width; its
    inverse undoes it up to new_white and gives 1 above."""
    x = np.linspace(0.0, 1.0, 1001)
    y = odt.roll_white_forward(x, new_white)
    assert np.array_equal(y[x <= 0.5], x[x <= 0.5]) and y[-1] == pytest.approx(new_white, abs=FLOAT64)
    assert np.all(np.diff(y) > 0.0)
    slope = np.diff(odt.roll_white_forward(np.array([0.5 - 1e-7, 0.5, 0.5 + 1e-7]), new_white)) / 1e-7
    assert slope == pytest.approx([1.0, 1.0], abs=1e-6)
    assert np.allclose(odt.roll_white_inverse(y, new_white), x, rtol=0.0, atol=FLOAT64)
    assert odt.roll_white_inverse(np.array([new_white + 0.01, 2.0]), new_white) == pytest.approx([1.0, 1.0])


@pytest.mark.parametrize("gamut", ["Rec.709", "P3-D65"])
def test_limiting_keeps_the_gamut_and_clips_the_rest_into_it(gamut):
    rng = np.random.default_rng(9)
    to_xyz = gamuts()[gamut].rgb_to_xyz
    inside = rng.uniform(0.0, 1.0, (1000, 3))
    assert np.allclose(odt.limit_to_primaries(inside @ to_xyz.T, gamut), inside @ to_xyz.T, rtol=0.0, atol=FLOAT64)
    outside = gamuts()["Rec.2020"].rgb_to_xyz @ np.array([0.0, 1.0, 0.0])
    limited = gamuts()[gamut].xyz_to_rgb @ odt.limit_to_primaries(outside, gamut)
    assert limited.max() <= 1.0 + FLOAT64 and limited.min() == pytest.approx(0.0, abs=FLOAT64)


@pytest.mark.parametrize(
    "view, display, gamut, ctl_odt",
    [
        ("ACES 1.0 - SDR Cinema (D60 sim on DCI)", "P3-DCI - Display", "DCI-P3", {"encoding_white": None}),
        ("ACES 1.1 - SDR Cinema (D65 sim on DCI)", "P3-DCI - Display", "DCI-P3", {"encoding_white": None}),
        ("ACES 1.0 - SDR Cinema", "P3-D60 - Display", "P3-D60", {"adapt_to_d65": False}),
    ],
)
def test_ocios_displays_show_the_ctls_code_values(view, display, gamut, ctl_odt):
    """The CTL writes these ODTs' XYZ into the display's RGB unadapted (P3DCI_D60sim_48nits,
    P3DCI_D65sim_48nits, P3D60_48nits: XYZtoRGB, clamp, 1/2.6 power); the studio config's
    displays adapt XYZ-D65 to their white (Bradford) first, which the presets' XYZ carries
    the inverse of: OpenColorIO's display of it gives the CTL's codes (float32)."""
    preset = PRESETS13[view]
    rng = np.random.default_rng(10)
    aces = 10.0 ** rng.uniform(-1.5, 0.8, (2000, 1)) * rng.uniform(0.7, 1.3, (2000, 3))
    whites = {"DCI-P3": DCI_WHITE, "P3-D60": odt.ACES_WHITE}
    primaries = gamuts()["DCI-P3"].primaries
    to_rgb = np.linalg.inv(normalised_primary_matrix(primaries, whites[gamut]))
    xyz = odt.sdr_odt_forward(rrt_tonescale(aces), replace(preset.odt, **ctl_odt))
    ctl = np.clip(apply3x3(to_rgb, xyz), 0.0, 1.0) ** (1.0 / 2.6)
    config = ocio.Config.CreateFromFile("ocio://studio-config-v2.2.0_aces-v1.3_ocio-v2.4")
    encoding = config.getColorSpace(display).getTransform(ocio.COLORSPACE_DIR_FROM_REFERENCE)
    pixels = np.ascontiguousarray(forward13(aces, view), dtype=np.float32)
    ocio.Config.CreateRaw().getProcessor(encoding).getDefaultCPUProcessor().applyRGB(pixels)
    assert np.abs(pixels - ctl).max() * 1023.0 <= tolerances.ACES13_OCIO_MIDTONE_CODES
