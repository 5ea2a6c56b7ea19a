"""The RRT: its published mid grey, its shapers, its glow and red modifier against
OpenColorIO's fixed functions, and its (CTL) inverse."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.rendering import aces13_rrt as rrt
from generator.rendering.aces13_rrt import rrt_forward, rrt_inverse, rrt_sweeteners, rrt_sweeteners_inverse

TABLE = tolerances.published_rounding(10)


def ocio_fixed(style, colours: np.ndarray, inverse: bool = False) -> np.ndarray:
    direction = ocio.TRANSFORM_DIR_INVERSE if inverse else ocio.TRANSFORM_DIR_FORWARD
    cpu = ocio.Config.CreateRaw().getProcessor(ocio.FixedFunctionTransform(style, direction=direction))
    pixels = np.ascontiguousarray(colours, dtype=np.float32).copy()
    cpu.getDefaultCPUProcessor().applyRGB(pixels)
    return pixels.astype(np.float64)


def relative(a, b) -> float:
    return float((np.abs(a - b).max(axis=-1) / np.abs(b).max(axis=-1)).max())


def test_mid_grey_is_oces_4_8():
    """ACES 0.18 grey renders to OCES 4.8 (RRT_PARAMS' midPoint), every channel."""
    oces = rrt_forward(np.full(3, 0.18))
    assert np.abs(np.log10(oces) - np.log10(4.8)).max() <= TABLE


def test_greys_stay_grey_and_pass_the_sweeteners_unchanged():
    grey = np.geomspace(1e-4, 1e4, 50)[:, None] * np.ones(3)
    rgb = rrt_sweeteners(grey)
    assert np.allclose(rgb, grey, rtol=1e-14, atol=0.0)


def test_shapers_meet_their_published_shapes():
    """cubic_basis_shaper: the cubic B-spline basis times 3/2 (peak 1, 1/4 at a quarter
    width, 0 at half width); sigmoid_shaper: 0 at -2, 1/2 at 0, 1 at 2."""
    w = rrt.RED_WIDTH
    bump = rrt.cubic_basis_shaper(np.array([-w / 2, -w / 4, 0.0, w / 4, w / 2, np.nan]), w)
    assert bump == pytest.approx([0.0, 0.25, 1.0, 0.25, 0.0, 0.0], abs=1e-15)
    assert rrt.sigmoid_shaper(np.array([-3.0, -2.0, 0.0, 2.0, 3.0])) == pytest.approx([0, 0, 0.5, 1, 1])


def test_glow_matches_ocio():
    rng = np.random.default_rng(3)
    aces = 10.0 ** rng.uniform(-4.0, 0.5, (20000, 3))
    error = relative(rrt.glow_module(aces), ocio_fixed(ocio.FIXED_FUNCTION_ACES_GLOW_10, aces))
    assert error <= tolerances.ACES13_OCIO_FIXED_FUNCTION_RELATIVE


def test_red_modifier_matches_ocio_which_weighs_by_the_glowed_saturation():
    """OpenColorIO's RedMod10 takes saturation from the colour it is given, the glowed one;
    RRT.ctl takes it before the glow. The two agree where the largest channel is 1e-2 or
    more (saturation is then scale invariant); below, OpenColorIO is the CTL's formula with
    the glowed saturation."""
    rng = np.random.default_rng(4)
    aces = 10.0 ** rng.uniform(-4.0, 0.5, (20000, 3))
    aces[:, 0] *= 4.0
    glow = rrt.glow_module(aces)
    theirs = ocio_fixed(ocio.FIXED_FUNCTION_ACES_RED_MOD_10, glow)
    ctl = rrt.red_modifier(glow, rrt.rgb_to_saturation(aces))
    bright = aces.max(axis=-1) >= 1e-2
    assert relative(ctl[bright], theirs[bright]) <= tolerances.ACES13_OCIO_FIXED_FUNCTION_RELATIVE
    assert relative(ctl[~bright], theirs[~bright]) > 100 * tolerances.ACES13_OCIO_FIXED_FUNCTION_RELATIVE
    glowed_saturation = rrt.red_modifier(glow, rrt.rgb_to_saturation(glow))
    assert relative(glowed_saturation, theirs) <= tolerances.ACES13_OCIO_FIXED_FUNCTION_RELATIVE


def in_ap1(count: int, low: float, high: float, seed: int) -> np.ndarray:
    """ACES whose AP1 channels lie between ``low`` and ``high``, none negative in AP0."""
    rng = np.random.default_rng(seed)
    aces = rrt.apply3x3(rrt.AP1_TO_AP0, 10.0 ** rng.uniform(np.log10(low), np.log10(high), (count, 3)))
    return aces[aces.min(axis=-1) >= 0.0]


def test_inverse_is_exact_away_from_reds_and_the_dark():
    """inv_rrt_sweeteners undoes the glow exactly where the largest channel is 1e-2 or more,
    and the red modifier is absent outside ±67.5° of red."""
    aces = in_ap1(20000, 0.01, 100.0, 5)
    weight = rrt.red_weight(rrt.glow_module(aces))
    keep = weight == 0.0
    assert keep.sum() > 5000
    assert relative(rrt_inverse(rrt_forward(aces[keep])), aces[keep]) <= tolerances.ACES13_ROUND_TRIP_RELATIVE


def test_red_modifier_inverse_is_the_ctls_approximation():
    """The CTL solves for red with the hue weight of the modified colour: reds come back
    within ACES13_RED_INVERSE_RELATIVE, as OpenColorIO's inverse (the same algorithm) does."""
    aces = in_ap1(20000, 0.01, 100.0, 6)
    back = rrt_sweeteners_inverse(rrt_sweeteners(aces))
    assert relative(back, aces) <= tolerances.ACES13_RED_INVERSE_RELATIVE
    modified = rrt.red_modifier(rrt.glow_module(aces), rrt.rgb_to_saturation(aces))
    theirs = ocio_fixed(ocio.FIXED_FUNCTION_ACES_RED_MOD_10, modified, inverse=True)
    assert relative(rrt.red_modifier_inverse(modified), theirs) <= tolerances.ACES13_OCIO_FIXED_FUNCTION_RELATIVE
