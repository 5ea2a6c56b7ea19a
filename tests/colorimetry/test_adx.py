"""ADX10 / ADX16 against OpenColorIO's built-in transforms, and the inverse.

OCIO 2.x builds ``ADX10_to_ACES2065-1`` / ``ADX16_to_ACES2065-1`` from the same
published constants, with three implementation differences from the
Academy CTL (which :mod:`generator.colorimetry.adx` follows):

* the density -> log exposure table is baked into a 65536-entry half-float
  domain 1D LUT with float32 output; linear interpolation between half-float
  samples rounds the table's corners (measured: up to 2.1e-5 in log exposure
  next to the knots at density 0.145, 0.3 and 0.6);
* below density -0.19 OCIO extends the first table segment linearly, down
  to log exposure -10, where the CTL holds -6 (exposures below 1e-6: an
  absolute difference below 1e-6);
* above density 3.7585 OCIO clamps log exposure to log10(65504), the largest
  half float; no ADX10 code in [0, 1] reaches it, ADX16 codes above about
  0.482 (neutral) do.

Code values are float32-representable so both sides see the same input.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from generator import tolerances
from generator.colorimetry import adx

ocio = pytest.importorskip("PyOpenColorIO")

HALF_MAX_LOG = math.log10(65504.0)
#: Channel-independent density at which OCIO's clamp starts.
CLAMP_DENSITY = (HALF_MAX_LOG + adx.REFERENCE_POINT) / adx.LINEAR_SLOPE


def _relative(actual, expected) -> np.ndarray:
    return np.abs(actual - expected) / np.maximum(np.abs(expected), tolerances.RELATIVE_FLOOR)


def _ocio(bits: int, rgb, inverse: bool = False) -> np.ndarray:
    transform = ocio.BuiltinTransform(f"ADX{bits}_to_ACES2065-1")
    if inverse:
        transform.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    cpu = ocio.Config.CreateRaw().getProcessor(transform).getDefaultCPUProcessor()
    pixels = np.ascontiguousarray(rgb, dtype=np.float32).reshape(-1, 3).copy()
    cpu.applyRGB(pixels)
    return pixels.astype(np.float64).reshape(np.shape(rgb))


def _float32(values) -> np.ndarray:
    return np.asarray(values, dtype=np.float32).astype(np.float64)


def _cid(code, bits: int) -> np.ndarray:
    return adx.adx_to_cdd(code, bits) @ adx.CDD_TO_CID.T


def _ramp(top: float = 1.0) -> np.ndarray:
    return _float32(np.repeat(np.linspace(0.0, top, 4097)[:, np.newaxis], 3, axis=1))


def _random(bits: int, count: int = 20000, top: float = 1.0) -> np.ndarray:
    return _float32(np.random.default_rng(bits).uniform(0.0, top, (count, 3)))


#: ADX16 codes below this stay clear of OCIO's half-float clamp in every channel
#: (largest CID reached: 3.60).
ADX16_UNCLAMPED_TOP = 0.45


@pytest.mark.parametrize(
    "bits, codes",
    [
        (10, _ramp()),
        (10, _random(10)),
        (16, _ramp(ADX16_UNCLAMPED_TOP)),
        (16, _random(16, top=ADX16_UNCLAMPED_TOP)),
    ],
    ids=["adx10-ramp", "adx10-random", "adx16-ramp", "adx16-random"],
)
def test_matches_ocio_builtin(bits, codes):
    # Measured maxima: ADX10 ramp 7.2e-6, random 1.4e-5 (a 200001-step ramp
    # finds 2.4e-5 beside the knot at density 0.6); ADX16 ramp 4.3e-6, random 7.2e-6.
    assert _cid(codes, bits).max() < CLAMP_DENSITY
    error = _relative(_ocio(bits, codes), adx.adx_to_aces(codes, bits))
    assert error.max() <= tolerances.ANALYTIC_RELATIVE


def _ocio_model(codes, bits: int) -> np.ndarray:
    """The CTL pipeline with OCIO's extensions at both ends of the table."""
    cid = _cid(codes, bits)
    table = adx.CID_TO_LOG_EXPOSURE
    slope = (table[1, 1] - table[0, 1]) / (table[1, 0] - table[0, 0])
    below = np.maximum(table[0, 1] + slope * (cid - table[0, 0]), -10.0)
    log_e = np.where(cid < table[0, 0], below, adx.cid_to_log_exposure(cid))
    return (10.0 ** np.minimum(log_e, HALF_MAX_LOG)) @ adx.EXP_TO_ACES.T


def test_ocio_differences_are_exactly_its_table_extensions():
    """Over the whole ADX16 code range (highlights clamped by OCIO), OCIO equals
    the CTL pipeline once its two table extensions are modelled (measured
    2.1e-5)."""
    codes = np.concatenate([_ramp(), _random(16)])
    # Half floats between 2 and 4 are 2**-9 apart: within one step of the clamp
    # OCIO's LUT interpolates across the corner (measured up to 1.7e-3 there).
    corner = np.abs(_cid(codes, 16) - CLAMP_DENSITY).min(axis=-1) < 2.0**-9
    codes = codes[~corner]
    reached = _cid(codes, 16)
    assert reached.max() > CLAMP_DENSITY and reached.min() < adx.CID_TO_LOG_EXPOSURE[0, 0]
    ocio_aces = _ocio(16, codes)
    assert _relative(ocio_aces, _ocio_model(codes, 16)).max() <= tolerances.ANALYTIC_RELATIVE
    clamped = reached.max(axis=-1) > CLAMP_DENSITY + 0.01
    assert _relative(ocio_aces[clamped], adx.adx_to_aces(codes[clamped], 16)).max() > 0.5


@pytest.mark.parametrize("bits", [10, 16])
def test_inverse_matches_ocio_on_neutral_ramp(bits):
    # Measured: 2.7e-5 (ADX10), 2.7e-6 (ADX16), from OCIO's inverse half-float LUT.
    # Saturated colours are not compared: OCIO inverts the exposure matrix in
    # float32, and where one channel sits near density -0.19 (exposure ~1e-6)
    # beside bright ones the cancellation costs up to 6e-4 in density.
    codes = _ramp(1.0 if bits == 10 else ADX16_UNCLAMPED_TOP)
    aces = _float32(adx.adx_to_aces(codes, bits))
    error = _relative(_ocio(bits, aces, inverse=True), adx.aces_to_adx(aces, bits))
    assert error.max() <= tolerances.ANALYTIC_RELATIVE


@pytest.mark.parametrize("bits", [10, 16])
def test_round_trip(bits):
    # Measured: 3.2e-11 (ADX10), 1.3e-9 (ADX16). ADX16 stays below OCIO's clamp:
    # near code 1 exposures reach 1e12, and beside a channel at the 1e-6 floor
    # the inverse exposure matrix loses the small channel to float64 rounding.
    codes = _random(bits, 50000, top=1.0 if bits == 10 else ADX16_UNCLAMPED_TOP)
    invertible = _cid(codes, bits).min(axis=-1) >= adx.CID_TO_LOG_EXPOSURE[0, 0]
    codes = codes[invertible]
    back = adx.aces_to_adx(adx.adx_to_aces(codes, bits), bits)
    assert _relative(back, codes).max() <= tolerances.ROUND_TRIP_RELATIVE


@pytest.mark.parametrize("bits, grey_code", [(10, 445.0), (16, 7120.0)])
def test_density_0_7_is_18_percent_grey(bits, grey_code):
    code = np.full(3, grey_code / (2**bits - 1))
    expected = 0.18 * adx.EXP_TO_ACES.sum(axis=1)
    np.testing.assert_allclose(adx.adx_to_aces(code, bits), expected, rtol=1e-12)
    np.testing.assert_allclose(adx.aces_to_adx(expected, bits), code, rtol=1e-12)


@pytest.mark.parametrize("bits", [10, 16])
def test_code_zero_is_the_table_floor(bits):
    floor = 1e-6 * adx.EXP_TO_ACES.sum(axis=1)
    np.testing.assert_allclose(adx.adx_to_aces(np.zeros(3), bits), floor, rtol=1e-12)
    # The CTL holds log exposure -6 below density -0.19: the inverse maps any
    # exposure at or below 1e-6, zero and negatives included, to density -0.19.
    for aces in (floor, np.zeros(3), -np.ones(3)):
        np.testing.assert_allclose(adx.aces_to_adx(aces, bits), 0.0, atol=1e-12)


def test_table_is_continuous_with_the_line():
    last_density, last_log = adx.CID_TO_LOG_EXPOSURE[-1]
    assert adx.LINEAR_SLOPE * last_density - adx.REFERENCE_POINT == pytest.approx(last_log, abs=1e-12)
    assert np.all(np.diff(adx.CID_TO_LOG_EXPOSURE, axis=0) > 0)


def test_density_matrix_preserves_neutrals():
    np.testing.assert_allclose(adx.CDD_TO_CID.sum(axis=1), 1.0, atol=1e-12)


def test_shape_and_bits_are_checked():
    assert adx.adx_to_aces(np.zeros((2, 5, 3)), 10).shape == (2, 5, 3)
    with pytest.raises(ValueError, match="allowed: 10, 16"):
        adx.adx_to_aces(np.zeros(3), 12)
    with pytest.raises(ValueError, match=r"shape \(\.\.\., 3\)"):
        adx.aces_to_adx(np.zeros(4), 10)
