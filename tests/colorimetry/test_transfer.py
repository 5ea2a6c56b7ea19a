"""The transfer-function families: each against colour-science's implementation of the same
family (the CLF moncurve and camera log functions), the standards' figures, their inverses, and
OpenColorIO's float32 evaluation."""

from __future__ import annotations

import warnings

import colour
import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.colorimetry.transfer import (
    PROBED_LINEAR,
    Function,
    Linear,
    LogCamera,
    PiecewisePower,
    Power,
    Tabulated,
    float32_departure,
    probed_values,
)

#: (gamma, offset) of IEC 61966-2-1 (sRGB), ITU-R BT.709 and an unusual curve.
PIECEWISE = [(2.4, 0.055), (1.0 / 0.45, 0.099), (3.1, 0.2)]
#: A camera log with a linear segment below its break, its slope given or derived, and without one.
LOG_WITH_SLOPE = LogCamera(10.0, 0.247, 0.385, 5.56, 0.052, 0.0109, 5.37)
LOG_WITH_BREAK = LogCamera(2.0, 0.09, 0.6, 3.0, 0.02, 0.005)
LOG_AFFINE = LogCamera(10.0, 0.25, 0.4, 5.0, 0.05)


def test_linear_is_the_identity_as_a_float64_copy():
    values = np.array([-1.0, 0.0, 0.18, 65504.0], dtype=np.float32)
    for out in (Linear().decode(values), Linear().encode(values)):
        assert out.dtype == np.float64 and np.array_equal(out, values) and out is not values


@pytest.mark.parametrize("exponent", [1.8, 2.2, 2.6])
def test_a_power_is_colour_sciences_mirrored_gamma_function(exponent):
    code = np.linspace(-1.0, 2.0, 301)
    curve = Power(exponent)
    np.testing.assert_allclose(curve.decode(code), colour.gamma_function(code, exponent, "Mirror"), rtol=1e-15)
    np.testing.assert_allclose(curve.encode(curve.decode(code)), code, rtol=1e-14, atol=1e-15)
    assert curve.encode(0.0) == 0.0 and curve.encode(1.0) == 1.0


@pytest.mark.parametrize("gamma, offset", PIECEWISE)
@pytest.mark.parametrize("mirror", [False, True])
def test_a_piecewise_power_is_colour_sciences_moncurve(gamma, offset, mirror):
    """The CLF's monCurve (and monCurveMirror), whose linear toe continues below 0 unless mirrored."""
    curve = PiecewisePower(gamma, offset, mirror)
    style = "monCurveMirror" if mirror else "monCurve"
    x = np.linspace(-0.5, 1.5, 401)
    expected_decode = colour.models.exponent_function_monitor_curve(x, gamma, offset, f"{style}Fwd")
    expected_encode = colour.models.exponent_function_monitor_curve(x, gamma, offset, f"{style}Rev")
    np.testing.assert_allclose(curve.decode(x), expected_decode, rtol=1e-14, atol=1e-16)
    np.testing.assert_allclose(curve.encode(x), expected_encode, rtol=1e-14, atol=1e-16)


@pytest.mark.parametrize("gamma, offset", PIECEWISE)
def test_the_toe_meets_the_power_with_its_slope(gamma, offset):
    curve = PiecewisePower(gamma, offset)
    code, h = curve.break_code, 1e-7
    assert float(curve.decode(code)) == pytest.approx(curve.break_linear, rel=1e-14)
    above = (curve.decode(code + h) - curve.decode(code)) / h
    assert above == pytest.approx(curve.slope, rel=1e-5)
    assert float(curve.encode(curve.break_linear)) == pytest.approx(code, rel=1e-14)


def test_the_toes_of_srgb_and_bt709_are_the_published_ones():
    """ITU-R BT.709-6 item 1.2: V = 4.5 L below L = 0.018; IEC 61966-2-1: 12.92 L. The
    standards print the slope and break of the curve whose toe meets the power with its slope,
    rounded (sRGB's printed break, 0.0031308, is not of that curve and is left out)."""
    bt709 = PiecewisePower(1.0 / 0.45, 0.099)
    assert abs(1.0 / bt709.slope - 4.5) <= tolerances.published_rounding(1)
    assert abs(bt709.break_linear - 0.018) <= tolerances.published_rounding(3)
    srgb = PiecewisePower(2.4, 0.055)
    assert abs(1.0 / srgb.slope - 12.92) <= tolerances.published_rounding(2)


@pytest.mark.parametrize("curve", [LOG_WITH_SLOPE, LOG_WITH_BREAK], ids=["given slope", "derived slope"])
def test_a_log_camera_is_colour_sciences_camera_log(curve):
    """The CLF's cameraLinToLog and cameraLogToLin; their default slope makes the derivative continuous."""
    params = dict(
        base=curve.base,
        log_side_slope=curve.log_side_slope,
        lin_side_slope=curve.lin_side_slope,
        log_side_offset=curve.log_side_offset,
        lin_side_offset=curve.lin_side_offset,
        lin_side_break=curve.lin_side_break,
        linear_slope=curve.linear_slope,
    )
    linear = np.linspace(-0.05, 4.0, 401)
    code = np.linspace(-0.1, 1.0, 401)
    expected_encode = colour.models.logarithmic_function_camera(linear, "cameraLinToLog", **params)
    expected_decode = colour.models.logarithmic_function_camera(code, "cameraLogToLin", **params)
    np.testing.assert_allclose(curve.encode(linear), expected_encode, rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(curve.decode(code), expected_decode, rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(curve.decode(curve.encode(linear)), linear, rtol=1e-12, atol=1e-15)


def test_a_log_without_a_break_is_colour_sciences_quasilog():
    curve = LOG_AFFINE
    params = dict(
        base=curve.base,
        log_side_slope=curve.log_side_slope,
        lin_side_slope=curve.lin_side_slope,
        log_side_offset=curve.log_side_offset,
        lin_side_offset=curve.lin_side_offset,
    )
    linear = np.geomspace(1e-4, 100.0, 301)
    expected = colour.models.logarithmic_function_quasilog(linear, "linToLog", **params)
    np.testing.assert_allclose(curve.encode(linear), expected, rtol=1e-13)
    np.testing.assert_allclose(curve.decode(expected), linear, rtol=1e-12)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert np.isnan(curve.encode(-1.0))  # no code below the log's pole, and no warning
    with pytest.raises(ValueError, match="no linear segment"):
        _ = curve.toe_slope


def test_a_table_interpolates_its_rows_and_clamps_at_its_ends():
    curve = Tabulated("t.csv", (0.0, 0.25, 0.5, 1.0), (0.0, 0.02, 0.2, 1.0))
    assert curve.domain == (0.0, 1.0)
    assert np.array_equal(curve.decode(np.array(curve.code)), curve.linear)
    assert np.array_equal(curve.encode(np.array(curve.linear)), curve.code)
    assert float(curve.decode(0.375)) == pytest.approx(0.11, rel=1e-15)
    assert np.array_equal(curve.decode([-1.0, 2.0]), [0.0, 1.0])
    assert np.array_equal(curve.encode([-1.0, 5.0]), [0.0, 1.0])
    code = np.linspace(0.0, 1.0, 101)
    np.testing.assert_allclose(curve.encode(curve.decode(code)), code, rtol=0, atol=1e-15)


def test_a_function_curve_is_quiet_float64_and_finds_its_domain_when_asked():
    asked = []

    def rule(encode):
        asked.append(True)
        return float(encode(0.0)), 1

    curve = Function("log2", np.exp2, np.log2, domain_rule=rule)
    assert not asked
    assert curve.domain == (-np.inf, 1.0) and asked
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = curve.encode(np.array([-1.0, 0.0, 4.0], dtype=np.float32))
    assert out.dtype == np.float64 and np.isnan(out[0]) and out[1] == -np.inf and out[2] == 2.0
    assert Function("same", np.exp2, np.log2) == Function("same", np.negative, np.negative)


@pytest.mark.parametrize(
    "curve", [PiecewisePower(2.4, 0.055), LOG_WITH_SLOPE, LOG_AFFINE], ids=["piecewise", "log", "log affine"]
)
def test_probed_values_are_float32_and_span_what_verify_probes(curve):
    codes, light = probed_values(curve, 65)
    for values in (codes, light):
        assert values.dtype == np.float64 and np.all(np.isfinite(values))
        assert np.array_equal(values, values.astype(np.float32))
    assert {0.0, 1.0} <= set(codes)
    assert 0.0 in light
    magnitudes = np.abs(light[light != 0.0])
    assert magnitudes.min() <= np.float32(PROBED_LINEAR[0]) and magnitudes.max() >= np.float32(PROBED_LINEAR[1])
    assert np.any(light < 0.0) and np.any(light > 0.0)


@pytest.mark.parametrize("offset", [0.0105, 0.0108, 0.011])
def test_a_log_without_a_toe_is_judged_the_same_however_its_samples_fall_near_the_pole(offset):
    """Kodak's Cineon curve (black offset 0.0108): near the log's pole the float32 argument's own
    rounding is unbounded, so it is no departure of the curve's; it had refused 0.0108 alone."""
    curve = LogCamera(10.0, 300.0 / 1023.0, 685.0 / 1023.0, 1.0 - offset, offset)
    figures = [float32_departure(curve, tolerances.RELATIVE_FLOOR, n) for n in (4097, 16385)]
    assert max(figures) <= tolerances.CURVE_FLOAT32_RELATIVE / 5 and abs(figures[0] - figures[1]) < 1e-7


@pytest.mark.parametrize(
    "gamma, offset", [(2.4, 0.055), (1.0 / 0.45, 0.099), (2.4, 1e-9), (10.0, 1e-4), (1.0000001, 0.05)]
)
@pytest.mark.parametrize("mirror", [False, True])
def test_the_float32_piecewise_power_is_ocios(gamma, offset, mirror):
    """PiecewisePower.float32 is OCIO's CPU renderer of ExponentWithLinearTransform, bit for bit:
    its clamps of gamma and offset (OCIO_MONCURVE_EPS) and float32 parameters included, with the
    linear or the mirror negative style."""
    curve = PiecewisePower(gamma, offset, mirror)
    codes, light = (v.astype(np.float32) for v in probed_values(curve, 257))
    style = ocio.NEGATIVE_MIRROR if mirror else ocio.NEGATIVE_LINEAR
    transform = ocio.ExponentWithLinearTransform(
        gamma=[gamma] * 3 + [1.0], offset=[offset] * 3 + [0.0], negativeStyle=style
    )
    config = ocio.Config.CreateRaw()
    ours = curve.float32(codes, light)
    for values, direction, emulated in (
        (codes, ocio.TRANSFORM_DIR_FORWARD, ours[0]),
        (light, ocio.TRANSFORM_DIR_INVERSE, ours[1]),
    ):
        transform.setDirection(direction)
        pixels = np.ascontiguousarray(np.repeat(values[:, None], 3, axis=1))
        config.getProcessor(transform).getOptimizedCPUProcessor(
            ocio.BIT_DEPTH_F32, ocio.BIT_DEPTH_F32, ocio.OPTIMIZATION_LOSSLESS
        ).applyRGB(pixels)
        assert np.array_equal(pixels[:, 0], emulated, equal_nan=True), direction
