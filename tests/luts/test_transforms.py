"""The operators a config and a standalone file share (generator/luts/transforms.py), run by OCIO
against the published formulas (CLF's S-2014-006 and the vendors' curves, as colour-science has them)."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.colorimetry import transfer
from generator.colorimetry.curves import CURVES
from generator.luts import transforms

RNG_SEED = 7


def _run(steps, values, optimization=ocio.OPTIMIZATION_LOSSLESS) -> np.ndarray:
    """``values`` (n, 3) through the transforms, as OCIO's CPU runs them."""
    steps = steps if isinstance(steps, list) else [steps]
    pixels = np.ascontiguousarray(values, dtype=np.float32).copy()
    processor = ocio.Config.CreateRaw().getProcessor(ocio.GroupTransform(steps))
    processor.getOptimizedCPUProcessor(optimization).applyRGB(pixels)
    return pixels.astype(np.float64)


def _values(low=-2.0, high=4.0, count=3000) -> np.ndarray:
    rng = np.random.default_rng(RNG_SEED)
    return rng.uniform(low, high, (count, 3)).astype(np.float32).astype(np.float64)


def test_a_matrix_with_an_offset_is_applied_to_columns():
    matrix = np.array([[0.9, 0.2, -0.1], [0.05, 1.1, 0.0], [-0.3, 0.4, 0.8]])
    offset = (0.01, -0.02, 0.5)
    x = _values()
    np.testing.assert_allclose(_run(transforms.matrix_transform(matrix, offset), x), x @ matrix.T + offset, atol=1e-5)
    np.testing.assert_allclose(_run(transforms.scale_transform(2.5), x), 2.5 * x, rtol=1e-6)
    inverse = transforms.matrix_transform(matrix, direction=transforms.INVERSE)
    np.testing.assert_allclose(_run(inverse, x @ matrix.T), x, atol=1e-5)


def test_a_matrix_within_a_residue_of_whole_numbers_is_written_whole():
    """A product of matrices that should be the identity is written as one, with no negative zero."""
    near = np.eye(3) + np.array([[3e-17, -2e-17, 0.0], [0.0, -1e-16, -0.0], [1e-17, 0.0, 2e-16]])
    written = transforms.matrix_transform(near).getMatrix()
    assert written == [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0]
    assert all(np.copysign(1.0, v) == 1.0 for v in written)


def test_normalise_maps_its_range_to_0_1_unclamped_and_range_clamps():
    x = _values()
    np.testing.assert_allclose(_run(transforms.normalise_transform(-0.5, 3.5), x), (x + 0.5) / 4.0, atol=1e-6)
    np.testing.assert_allclose(
        _run(transforms.range_transform(-0.5, 3.5), x), np.clip((x + 0.5) / 4.0, 0.0, 1.0), atol=1e-6
    )
    np.testing.assert_allclose(
        _run(transforms.range_transform(0.0, 2.0, (0.25, 0.75)), x), np.clip(x, 0.0, 2.0) / 4.0 + 0.25, atol=1e-6
    )


@pytest.mark.parametrize(
    "style, clf_style", [(ocio.NEGATIVE_MIRROR, "basicMirrorFwd"), (ocio.NEGATIVE_CLAMP, "basicFwd")]
)
def test_a_power_is_clfs_basic_exponent(style, clf_style):
    import colour

    x = _values()
    expected = colour.models.exponent_function_basic(x, 2.6, clf_style)
    np.testing.assert_allclose(_run(transforms.power(2.6, style), x), expected, rtol=1e-5, atol=1e-7)


@pytest.mark.parametrize("mirror, clf_style", [(True, "monCurveMirrorFwd"), (False, "monCurveFwd")])
def test_a_mon_curve_decodes_as_clfs_moncurve(mirror, clf_style):
    """The sRGB-like curve from code to linear; unmirrored, it continues its linear toe below 0."""
    import colour

    x = _values(-1.0, 1.5)
    decoded = _run(transforms.mon_curve(2.4, 0.055, mirror), x)
    expected = colour.models.exponent_function_monitor_curve(x, 2.4, 0.055, clf_style)
    positive = x >= 0
    np.testing.assert_allclose(decoded[positive], expected[positive], rtol=1e-5, atol=1e-7)
    if mirror:
        np.testing.assert_allclose(decoded[~positive], expected[~positive], rtol=1e-5, atol=1e-7)
    else:
        slope = colour.models.exponent_function_monitor_curve(1e-6, 2.4, 0.055, clf_style) / 1e-6
        np.testing.assert_allclose(decoded[~positive], slope * x[~positive], rtol=1e-5)


@pytest.mark.parametrize(
    "name, decode",
    [
        ("ACEScct", "log_decoding_ACEScct"),
        ("ARRI LogC3 (EI800)", "log_decoding_ARRILogC3"),
        ("S-Log3", "log_decoding_SLog3"),
        ("ARRI LogC4", "log_decoding_ARRILogC4"),
        ("Log3G10", "log_decoding_Log3G10"),
        ("DaVinci Intermediate", "oetf_inverse_DaVinciIntermediate"),
    ],
)
def test_a_log_camera_curve_decodes_as_its_vendor_publishes(name, decode):
    """The library's parameters through OCIO's LogCameraTransform, against colour-science's
    implementation of each vendor's formula, the toe below the break included."""
    import colour

    code = np.repeat(np.linspace(0.0, 1.0, 1001)[:, None], 3, axis=1).astype(np.float32).astype(np.float64)
    [transform] = transforms.analytic_decode(CURVES[name])
    assert isinstance(transform, ocio.LogCameraTransform)
    expected = getattr(colour.models, decode)(code)
    np.testing.assert_allclose(_run(transform, code), expected, rtol=2e-5, atol=1e-7)


def test_a_log_without_a_break_is_a_plain_log_of_its_base():
    curve = transfer.LogCamera(
        base=10.0, log_side_slope=0.25, log_side_offset=0.6, lin_side_slope=1.0, lin_side_offset=0.01
    )
    [transform] = transforms.analytic_decode(curve)
    assert isinstance(transform, ocio.LogAffineTransform) and transform.getBase() == 10.0
    code = np.repeat(np.linspace(0.0, 1.0, 501)[:, None], 3, axis=1)
    np.testing.assert_allclose(_run(transform, code), 10.0 ** ((code - 0.6) / 0.25) - 0.01, rtol=2e-5, atol=1e-7)


def test_only_curves_ocio_holds_exactly_have_an_analytic_decoding():
    assert transforms.analytic_decode(transfer.Linear()) == []
    assert transforms.analytic_decode(CURVES["ST 2084"]) is None
    assert transforms.analytic_decode(transfer.Tabulated("t.csv", (0.0, 1.0), (0.0, 1.0))) is None
    [exponent] = transforms.analytic_decode(transfer.Power(2.2))
    assert isinstance(exponent, ocio.ExponentTransform) and list(exponent.getValue()) == [2.2, 2.2, 2.2, 1.0]


def test_a_log_shaper_is_the_log2_of_light_over_its_span_and_back():
    span, toe = 20.0, 2.0**-14
    x = np.abs(_values(0.0, 100.0))
    shaped = np.log2(x + toe) / span - np.log2(toe) / span
    np.testing.assert_allclose(_run(transforms.log_shaper(span, toe), x), shaped, rtol=1e-5, atol=1e-6)
    np.testing.assert_allclose(
        _run(transforms.log_shaper(span, toe, transforms.INVERSE), shaped), x, rtol=2e-5, atol=1e-7
    )


def test_a_baked_decoding_normalises_its_domain_and_takes_the_shapers_root():
    """Code -0.25 to 1.5 to 0 to 1, the square root (negatives clamped), then the table: here
    one holding u², so the whole is the normalised code, clamped below 0 and above 1."""
    table = transforms.lut1d(np.linspace(0.0, 1.0, 4097) ** 2)
    steps = transforms.baked_decode((-0.25, 1.5), 2.0, table)
    assert [type(s).__name__ for s in steps] == ["MatrixTransform", "ExponentTransform", "Lut1DTransform"]
    code = _values(-1.0, 2.0)
    np.testing.assert_allclose(_run(steps, code), np.clip((code + 0.25) / 1.75, 0.0, 1.0), atol=2e-6)
    assert transforms.baked_decode((0.0, 1.0), 1.0, table) == [table]


def test_a_1d_table_is_one_per_channel_or_shared():
    shared = np.linspace(0.0, 2.0, 5)
    per_channel = np.stack([shared, shared**2, 1.0 - shared], axis=-1)
    x = np.repeat(np.array([0.0, 0.125, 0.5, 1.0])[:, None], 3, axis=1)
    np.testing.assert_allclose(_run(transforms.lut1d(shared), x), np.interp(x, np.linspace(0, 1, 5), shared), atol=1e-6)
    expected = np.stack([np.interp(x[:, c], np.linspace(0, 1, 5), per_channel[:, c]) for c in range(3)], axis=-1)
    np.testing.assert_allclose(_run(transforms.lut1d(per_channel), x), expected, atol=1e-6)


def test_a_3d_table_is_indexed_red_green_blue():
    """On every node (r, g, b) OCIO reads ``cube[r, g, b]``."""
    n = 4
    cube = np.random.default_rng(RNG_SEED).random((n, n, n, 3))
    index = np.indices((n, n, n)).reshape(3, -1).T
    for interpolation in (ocio.INTERP_TETRAHEDRAL, ocio.INTERP_LINEAR):
        out = _run(transforms.lut3d(cube, interpolation), index / (n - 1))
        np.testing.assert_allclose(out, cube[tuple(index.T)], rtol=0, atol=1e-6)
