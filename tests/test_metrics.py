"""The error metrics: relative errors with their floor, ΔE ITP (ITU-R BT.2124) of any display's
codes, and the helpers verify judges with."""

from __future__ import annotations

import colour
import numpy as np
import pytest

from generator import reference, tolerances
from generator.metrics import colour_relative_error, delta_e_itp, dequantised, percentile_99, relative_error


def test_a_relative_error_is_absolute_below_the_floor():
    """|a - b| / max(|b|, 0.1): 10% of 2 is 0.1 relative; 0.01 off at 0.01 or at -0.05 is 0.1 too."""
    assert tolerances.RELATIVE_FLOOR == 0.1
    np.testing.assert_allclose(relative_error([2.2, 0.02, -0.06], [2.0, 0.01, -0.05]), [0.1, 0.1, 0.1], rtol=1e-14)
    assert relative_error(3.0, 3.0) == 0.0


def test_a_colours_error_is_relative_to_its_largest_component():
    """A channel 1e-3 off in a colour whose largest component is 10 is 1e-4 off, however small
    the channel; a colour below the floor is judged absolutely."""
    expected = np.array([[10.0, 0.001, -4.0], [0.01, 0.02, 0.0]])
    actual = expected + np.array([[0.0, 1e-3, 0.0], [0.0, 0.0, 0.005]])
    np.testing.assert_allclose(colour_relative_error(actual, expected), [1e-4, 0.05], rtol=1e-12)
    assert colour_relative_error(np.ones((2, 4, 3)), np.ones((2, 4, 3))).shape == (2, 4)


def pq(light_cd_m2) -> np.ndarray:
    """SMPTE ST 2084's inverse EOTF of luminance in cd/m² (colour-science)."""
    return np.asarray(colour.models.eotf_inverse_ST2084(light_cd_m2), dtype=np.float64)


@pytest.mark.parametrize("name", ["sRGB - Display", "Rec.2100-HLG - Display", "Gamma 2.6 P3-D65 - Display"])
def test_a_grey_pairs_delta_e_itp_is_720_times_its_pq_difference(default_spec, name):
    """BT.2124: ΔE ITP = 720 √(ΔI² + (ΔCt / 2)² + ΔCp²). A D65 grey has equal LMS (BT.2100's
    rows sum to 4096), so Ct = Cp = 0 and I is the PQ code of its luminance, whichever display
    shows it: decoded with BT.2100's HLG EOTF at 1000 cd/m² or the display's own curve."""
    display = next(d for d in default_spec.displays if d.name == name)
    codes = np.linspace(0.05, 0.95, 19)[:, None] * np.ones(3)
    step = 0.01
    if display.eotf_name == "HLG":
        light = colour.models.eotf_BT2100_HLG(np.stack([codes, codes + step]), L_B=0.0, L_W=1000.0)
    else:
        light = display.eotf.decode(np.stack([codes, codes + step])) * 100.0
    expected = 720.0 * np.abs(pq(light[1, :, 1]) - pq(light[0, :, 1]))
    np.testing.assert_allclose(delta_e_itp(display, codes, codes + step), expected, rtol=1e-6)


@pytest.mark.parametrize(
    "narrow, wide",
    [("ST2084-P3-D65 - Display", "Rec.2100-PQ - Display"), ("sRGB - Display", "Display P3 - Display")],
)
def test_delta_e_itp_judges_light_whichever_display_shows_it(default_spec, narrow, wide):
    """The same two colours of light (of the narrower gamut), encoded for two D65 displays of
    different gamuts, differ by the same ΔE ITP; a colour differs from itself by 0, and the
    difference is the same both ways."""
    small, large = (next(d for d in default_spec.displays if d.name == n) for n in (narrow, wide))
    rgb = np.random.default_rng(9).uniform(0.005, 0.9, (2, 300, 3)) * small.clip_high
    xyz = rgb @ np.linalg.inv(reference.display_matrix(default_spec, small)).T
    in_large = xyz @ reference.display_matrix(default_spec, large).T
    assert np.all(in_large > 0.0)
    codes = [reference.display_encode(d, light) for d, light in ((small, rgb), (large, in_large))]
    errors = [delta_e_itp(d, c[0], c[1]) for d, c in zip((small, large), codes)]
    assert errors[0].min() > 0.1
    np.testing.assert_allclose(errors[0], errors[1], rtol=1e-9)
    assert np.array_equal(delta_e_itp(large, codes[1][0], codes[1][0]), np.zeros(300))
    np.testing.assert_allclose(delta_e_itp(large, codes[1][1], codes[1][0]), errors[1], rtol=1e-12)


def test_dequantised_takes_off_half_a_step_and_no_more():
    got = dequantised([0.5 + 0.4 / 65535, 0.5 - 2.0 / 65535], [0.5, 0.5], 1.0 / 65535)
    assert got[0] == 0.5 and got[1] == pytest.approx(0.5 - 1.5 / 65535, abs=1e-15)
    assert percentile_99([np.nan, 1.0, 2.0]) == pytest.approx(1.99)


def test_dequantised_leaves_exact_values_and_takes_each_channels_own_step():
    actual = np.array([[0.5 + 3e-5, 0.5 - 3e-5, 0.25]])
    expected = np.array([[0.5, 0.5, 0.25]])
    assert np.array_equal(dequantised(actual, expected, 0.0), actual)
    steps = np.array([1e-4, 2e-5, 1e-3])
    np.testing.assert_allclose(dequantised(actual, expected, steps), [[0.5, 0.5 - 2e-5, 0.25]], rtol=0, atol=1e-15)


def test_percentile_99_is_numpys_without_nan():
    errors = np.random.default_rng(4).random(1000)
    errors[::7] = np.nan
    assert percentile_99(errors) == pytest.approx(float(np.nanpercentile(errors, 99)), rel=1e-15)
    assert np.isnan(percentile_99([np.nan, np.nan])) and np.isnan(percentile_99([]))
