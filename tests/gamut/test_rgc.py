"""The Reference Gamut Compression against OpenColorIO's fixed function, and its invariants."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from generator.gamut import RGCParams, rgc, rgc_compress
from generator.tolerances import RGC_OCIO_SCALED
from tests.gamut import cases

#: A second parameter set, far from the defaults, every value settable.
CUSTOM = RGCParams(1.25, 1.4, 1.6, 0.7, 0.75, 0.8, 2.3)


def ocio_rgc(rgb32: np.ndarray, params: RGCParams) -> np.ndarray:
    transform = ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_ACES_GAMUT_COMP_13, params.as_ocio_params())
    cpu = ocio.Config.CreateRaw().getProcessor(transform).getDefaultCPUProcessor()
    out = np.ascontiguousarray(rgb32, dtype=np.float32).copy()
    cpu.applyRGB(out)
    return out.astype(np.float64)


def scaled_error(rgb32: np.ndarray, params: RGCParams) -> float:
    """Largest per-channel difference over max(1, largest |component|), where OCIO is finite.

    OCIO computes in float32, where the distance (a - c) / |a| overflows to +Inf when the
    achromatic value a is tiny next to another channel, and its shaper then gives NaN
    (see test_ocio_overflows_where_float64_does_not); those colours are left out.
    """
    ours = rgc_compress(rgb32.astype(np.float64), params)
    theirs = ocio_rgc(rgb32, params)
    assert np.all(np.isfinite(ours))
    scale = np.maximum(1.0, np.abs(rgb32.astype(np.float64)).max(axis=-1, keepdims=True))
    finite = np.all(np.isfinite(theirs), axis=-1)
    return float(np.max(np.abs(ours - theirs)[finite] / scale[finite], initial=0.0))


def test_published_defaults():
    assert RGCParams().as_ocio_params() == [1.147, 1.264, 1.312, 0.815, 0.803, 0.880, 1.2]


@pytest.mark.parametrize("params", [RGCParams(), CUSTOM], ids=["aces13", "custom"])
@pytest.mark.parametrize("display_name, source", cases.PAIRS)
def test_agrees_with_ocio_on_source_colours(params, display_name, source):
    rgb32 = cases.source_colours(source, display_name).astype(np.float32)
    assert scaled_error(rgb32, params) <= RGC_OCIO_SCALED


@pytest.mark.parametrize("params", [RGCParams(), CUSTOM], ids=["aces13", "custom"])
@given(arrays(np.float32, (32, 3), elements=st.floats(-65504, 65504, width=32)))
def test_agrees_with_ocio_on_any_finite_rgb(params, rgb32):
    assert scaled_error(rgb32, params) <= RGC_OCIO_SCALED


def test_ocio_applies_no_ap0_matrices():
    # A neutral-preserving look would map greys to greys under any matrix; a pure red
    # (distance 1 in g and b) shows the compression acting on the given RGB itself.
    red = np.array([[1.0, 0.0, 0.0]], dtype=np.float32)
    assert np.allclose(ocio_rgc(red, RGCParams()), rgc_compress(red.astype(float)), rtol=0, atol=1e-6)
    assert np.all(rgc_compress([1.0, 0.0, 0.0])[1:] > 0.0)


def test_ocio_overflows_where_float64_does_not():
    rgb = np.array([[-1.0, 1e-43, 1e-43]], dtype=np.float32)
    assert np.all(np.isnan(ocio_rgc(rgb, RGCParams())[:, 0]))
    ours = rgc_compress(rgb.astype(np.float64))
    # The red distance (1 + 1e-43) / 1e-43 is about 1e43: compressed to nearly thr + s.
    params = RGCParams()
    limit = params.thresholds[0] + params.scales()[0]
    achromatic = float(rgb[0, 1])  # the binary32 subnormal nearest 1e-43
    assert np.isclose(ours[0, 0], achromatic * (1.0 - limit), rtol=1e-6, atol=0.0)


def test_colours_within_all_thresholds_are_bit_identical():
    rgb = cases.display_colours()
    ach = rgb.max(axis=-1, keepdims=True)
    inside = np.all((ach - rgb) < np.array(RGCParams().thresholds) * ach, axis=-1)
    assert inside.sum() > 1000
    assert np.array_equal(rgc(rgb[inside]), rgb[inside])
    # The rest of the cube moves inwards but stays inside it, before any clip.
    compressed = rgc_compress(rgb[~inside])
    assert np.all((compressed >= 0.0) & (compressed <= 1.0))


@pytest.mark.parametrize("params", [RGCParams(), CUSTOM], ids=["aces13", "custom"])
def test_the_distance_limit_lands_on_the_gamut_boundary(params):
    # A channel at distance `lim` from the achromatic value 1 is compressed to distance 1: 0.
    rgb = np.eye(3)[[1, 2, 0]] + np.eye(3)[[2, 0, 1]] + np.diag(1.0 - np.array(params.limits))
    assert np.allclose(np.diag(rgc_compress(rgb, params)), 0.0, rtol=0, atol=1e-12)


def test_zero_achromatic_value_is_black_as_in_ocio():
    rgb = np.array([[0.0, -1.0, -2.0]])
    assert np.array_equal(rgc_compress(rgb), np.zeros((1, 3)))
    assert np.array_equal(ocio_rgc(rgb.astype(np.float32), RGCParams()), np.zeros((1, 3)))


@pytest.mark.parametrize(
    "bad",
    [
        dict(limit_cyan=1.0),
        dict(threshold_yellow=1.0),
        dict(threshold_cyan=-0.1),
        dict(power=0.5),
        dict(limit_magenta=float("nan")),
    ],
)
def test_invalid_parameters_are_refused(bad):
    with pytest.raises(ValueError):
        RGCParams(**bad)


@pytest.mark.parametrize("params", [RGCParams(), CUSTOM], ids=["aces13", "custom"])
def test_a_distance_exactly_at_its_threshold_stays_there_as_in_ocio(params):
    """The shaper is continuous at the threshold: a distance equal to it is unchanged (it was
    sent to the asymptote, threshold plus scale: (0.185, 1, 1) became (0, 1, 1))."""
    thresholds = np.array(params.thresholds)
    rgb = np.ones((3, 3))
    rgb[np.arange(3), np.arange(3)] = 1.0 - thresholds  # distance (1 - c) / 1 = threshold
    rgb32 = rgb.astype(np.float32)
    np.testing.assert_array_equal(rgc_compress(rgb32.astype(np.float64), params), rgb32.astype(np.float64))
    assert scaled_error(rgb32, params) <= RGC_OCIO_SCALED
