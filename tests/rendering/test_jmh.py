"""The simplified Hellwig 2022 JMh model of ACES 2.0: its definitions, its inverse, and
OpenColorIO 2.6's ``ACES2_RGB_TO_JMh`` fixed function."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.metrics import colour_relative_error
from generator.rendering.aces2 import ACES_WHITE, AP0_PRIMARIES, AP1_PRIMARIES
from generator.rendering.jmh import (
    MODEL_GAMMA,
    compress_cone,
    decompress_cone,
    j_to_y,
    jmh_params,
    jmh_to_rgb,
    luminance_adaptation,
    rgb_to_jmh,
    y_to_j,
)
from tests.rendering.aces2_cases import LED_WALL, float32, ocio_apply, probe_sets

SPACES = {
    "AP0": (AP0_PRIMARIES, ACES_WHITE),
    "AP1": (AP1_PRIMARIES, ACES_WHITE),
    "LED wall": (LED_WALL.limiting_primaries, LED_WALL.limiting_white),
}


def test_viewing_conditions():
    """CIECAM02's F_L (CIE 159:2004, eq. 7.2) for L_A = 100: 0.1 (5 L_A)^(1/3) but for terms in
    k^4 = 501^-4 (1.6e-9); and c z for the dim surround and Y_b = 20: 0.59 (1.48 + sqrt(0.2))."""
    assert luminance_adaptation() == pytest.approx(0.1 * 500.0 ** (1.0 / 3.0), abs=2e-9)
    assert pytest.approx(0.59 * (1.48 + np.sqrt(0.2)), rel=1e-15) == MODEL_GAMMA


@pytest.mark.parametrize("space", SPACES)
def test_white_and_greys(space):
    """Each space's white at 100 cd/m² is J = 100, M = 0; its greys have M = 0 and the J of
    their luminance, whichever the space."""
    p = jmh_params(*SPACES[space])
    greys = np.geomspace(1e-4, 100.0, 50)[:, None] * np.ones(3)
    jmh = rgb_to_jmh(greys, p)
    assert rgb_to_jmh(np.ones(3), p)[0] == pytest.approx(100.0, rel=1e-13)
    assert np.max(jmh[:, 1]) < 1e-9
    np.testing.assert_allclose(jmh[:, 0], y_to_j(greys[:, 0] * 100.0, p), rtol=1e-12)


def test_cone_compression_inverts():
    v = np.concatenate([-np.geomspace(1e-6, 1e4, 100), np.geomspace(1e-6, 1e4, 100)])
    np.testing.assert_allclose(decompress_cone(compress_cone(v)), v, rtol=1e-12)
    assert decompress_cone(0.995) == decompress_cone(0.99)


@pytest.mark.parametrize("space", SPACES)
def test_luminance_and_lightness_invert(space):
    p = jmh_params(*SPACES[space])
    y = np.geomspace(1e-4, 1e4, 200)
    np.testing.assert_allclose(j_to_y(y_to_j(y, p), p), y, rtol=1e-12)
    assert y_to_j(-1.0, p) == -y_to_j(1.0, p)


@pytest.mark.parametrize("space", SPACES)
def test_rgb_jmh_round_trip(space):
    p = jmh_params(*SPACES[space])
    rgb = np.random.default_rng(1).uniform(0.0, 1.0, (2, 500, 3))
    np.testing.assert_allclose(jmh_to_rgb(rgb_to_jmh(rgb, p), p), rgb, rtol=1e-11, atol=1e-13)


def cartesian(jmh):
    """(J, M cos h, M sin h): a hue error weighs as much as the chroma it moves."""
    hr = np.radians(jmh[..., 2])
    return np.stack([jmh[..., 0], jmh[..., 1] * np.cos(hr), jmh[..., 1] * np.sin(hr)], axis=-1)


def ocio_jmh(space: str, inverse: bool = False) -> ocio.FixedFunctionTransform:
    primaries, white = SPACES[space]
    transform = ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_ACES_RGB_TO_JMH_20, [*np.ravel(primaries), *white])
    transform.setDirection(ocio.TRANSFORM_DIR_INVERSE if inverse else ocio.TRANSFORM_DIR_FORWARD)
    return transform


@pytest.mark.parametrize("space", SPACES)
@pytest.mark.parametrize("probe", ["grey", "random", "camera", "bright", "dark"])
def test_agrees_with_ocio(space, probe):
    """OCIO's float32 JMh (measured 2e-6 of the larger of J and M, forward and inverse)."""
    p = jmh_params(*SPACES[space])
    rgb = probe_sets()[probe]
    ours, theirs = rgb_to_jmh(rgb, p), ocio_apply(ocio_jmh(space), rgb)
    assert colour_relative_error(cartesian(ours), cartesian(theirs)).max() <= tolerances.ANALYTIC_RELATIVE
    jmh = float32(ours)
    back, theirs_back = jmh_to_rgb(jmh, p), ocio_apply(ocio_jmh(space, inverse=True), jmh)
    assert colour_relative_error(back, theirs_back).max() <= tolerances.ANALYTIC_RELATIVE
