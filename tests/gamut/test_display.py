"""The destination display of a gamut mapping: its record against colour-science's colourspaces
and the published luminance coefficients, and the non-finite input policy."""

from __future__ import annotations

import colour
import numpy as np
import pytest

from generator.gamut.display import LARGEST, DisplayGamut, matrix_tuple, sanitize


def test_sanitize_policy():
    out = sanitize([[np.nan, np.inf, -np.inf], [1e300, -1e300, 0.5]])
    assert np.array_equal(out, [[0.0, LARGEST, 0.0], [LARGEST, -LARGEST, 0.5]])


def test_sanitize_returns_a_new_float64_array_and_wants_rgb():
    given = np.array([[0.25, np.nan, 2.0]], dtype=np.float32)
    out = sanitize(given)
    assert out.dtype == np.float64 and np.isnan(given[0, 1]) and out[0, 1] == 0.0
    finite = np.array([0.1, 0.2, 0.3])
    assert sanitize(finite) is not finite and np.array_equal(sanitize(finite), finite)
    assert float(np.finfo(np.float32).max) == LARGEST
    for bad in (0.5, [0.1, 0.2], np.zeros((2, 4))):
        with pytest.raises(ValueError, match="shape"):
            sanitize(bad)


@pytest.mark.parametrize("name", ["ITU-R BT.709", "P3-D65", "ITU-R BT.2020", "DCI-P3", "ACEScg"])
def test_a_display_from_colour_science_holds_its_primaries_and_white(name):
    space = colour.RGB_COLOURSPACES[name]
    display = DisplayGamut.from_colourspace(space)
    np.testing.assert_allclose(display.primaries_xy, space.primaries, rtol=0, atol=1e-12)
    np.testing.assert_allclose(display.white_xyz, colour.xy_to_XYZ(space.whitepoint), rtol=1e-12)
    assert display.white_xyz[1] == pytest.approx(1.0, rel=1e-12)
    assert display.white_xy == tuple(space.whitepoint)


@pytest.mark.parametrize(
    "name, weights",
    [
        ("ITU-R BT.709", (0.2126, 0.7152, 0.0722)),  # ITU-R BT.709-6, item 3.2
        ("ITU-R BT.2020", (0.2627, 0.6780, 0.0593)),  # ITU-R BT.2020-2, table 4
    ],
)
def test_the_luminance_weights_are_the_published_ones(name, weights):
    display = DisplayGamut.from_colourspace(colour.RGB_COLOURSPACES[name])
    assert np.all(np.abs(display.luminance_weights - weights) <= 0.5e-4)


def test_the_record_is_immutable_hashable_and_checked():
    space = colour.RGB_COLOURSPACES["ITU-R BT.709"]
    display = DisplayGamut(space.matrix_RGB_to_XYZ, space.whitepoint)
    assert display == DisplayGamut(space.matrix_RGB_to_XYZ.tolist(), tuple(space.whitepoint))
    assert hash(display) == hash(DisplayGamut.from_colourspace(space))
    display.matrix[0, 0] = 0.0  # a copy
    assert display.rgb_to_xyz[0][0] == space.matrix_RGB_to_XYZ[0, 0]
    with pytest.raises(AttributeError):
        display.white_xy = (0.3, 0.3)
    with pytest.raises(ValueError, match="disagrees"):
        DisplayGamut(space.matrix_RGB_to_XYZ, colour.RGB_COLOURSPACES["ACEScg"].whitepoint)
    with pytest.raises(ValueError, match="white chromaticity"):
        DisplayGamut(space.matrix_RGB_to_XYZ, (0.3127, np.nan))


@pytest.mark.parametrize(
    "matrix, words",
    [
        (np.eye(2), "3x3"),
        (np.full((3, 3), np.inf), "finite"),
        (np.ones((3, 3)), "singular"),
    ],
)
def test_a_matrix_must_be_finite_and_invertible(matrix, words):
    with pytest.raises(ValueError, match=words):
        matrix_tuple(matrix)
