"""The Oklab chroma compression: hue, lightness, threshold, limit, monotonicity."""

from __future__ import annotations

import colour
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from generator.gamut import PerceptualParams, perceptual
from generator.gamut.perceptual import (
    adapted_matrix, boundary_chroma, compress_chroma, compress_ratio, display_to_oklab,
    oklab_to_display)
from generator.tolerances import (
    GAMUT_BOUNDARY_ABSOLUTE, GAMUT_HUE_MIN_CHROMA, GAMUT_MONOTONE_ABSOLUTE, GAMUT_OKLAB_ABSOLUTE,
    GAMUT_RGB_RAMP_MONOTONE_ABSOLUTE)
from tests.gamut import cases

LIGHTNESSES = np.array([0.2, 0.4, 0.6, 0.8, 0.95])
HUES = np.linspace(0.0, 2.0 * np.pi, 36, endpoint=False)


def lch(rgb, display):
    lab = display_to_oklab(rgb, display)
    return lab[..., 0], np.hypot(lab[..., 1], lab[..., 2]), np.arctan2(lab[..., 2], lab[..., 1])


def display_boundary(lightness, hue, display):
    return boundary_chroma(lightness, np.cos(hue), np.sin(hue), np.linalg.inv(adapted_matrix(display)))


def ramps(display, count=400, top=0.6):
    """Constant-L, constant-hue chroma ramps from 0 to `top`: RGB (L, h, C, 3) and the grid."""
    lightness, hue, chroma = np.meshgrid(LIGHTNESSES, HUES, np.linspace(0, top, count), indexing="ij")
    lab = np.stack([lightness, chroma * np.cos(hue), chroma * np.sin(hue)], axis=-1)
    return oklab_to_display(lab, display), lightness, hue, chroma


@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_display_white_and_greys_are_oklab_neutral(display_name):
    d = cases.display(display_name)
    greys = np.linspace(0.0, 1.0, 11)[:, None] * np.ones(3)
    lightness, chroma, _ = lch(greys, d)
    assert np.max(np.abs(lightness - np.cbrt(greys[:, 0]))) <= GAMUT_OKLAB_ABSOLUTE
    assert np.max(chroma) <= GAMUT_OKLAB_ABSOLUTE
    # The adaptation is the identity on Oklab up to the 1e-4 offset of D65 from Oklab's white.
    xyz = np.random.default_rng(3).uniform(0, 1, (50, 3)) @ d.matrix.T
    plain = colour.XYZ_to_Oklab(xyz)
    assert np.max(np.abs(display_to_oklab(xyz @ np.linalg.inv(d.matrix).T, d) - plain)) < 2e-4


@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_boundary_chroma_brackets_the_cube_surface(display_name):
    d = cases.display(display_name)
    lightness, hue = np.meshgrid(LIGHTNESSES, HUES, indexing="ij")
    chroma = display_boundary(lightness, hue, d)
    for factor, inside in ((1.0, True), (1.0 + 1e-9, False)):
        c = chroma * factor + (0.0 if inside else 1e-12)
        rgb = oklab_to_display(np.stack([lightness, c * np.cos(hue), c * np.sin(hue)], -1), d)
        in_cube = np.all((rgb >= -1e-12) & (rgb <= 1 + 1e-12), axis=-1)
        assert np.all(in_cube == inside)


def test_compression_curve():
    x = np.linspace(0.0, 3.0, 3001)
    for threshold, limit in ((0.8, 1.25), (0.5, 2.0), (0.9, 1.0)):
        y = compress_ratio(x, threshold, np.float64(limit))
        assert np.array_equal(y[x <= threshold], x[x <= threshold])
        assert np.all(np.diff(y) >= 0.0) and np.all(y <= 1.0) and np.all(y <= x)
        assert np.all(y[x >= limit] == 1.0)
        # Slope 1 at the threshold (C1): one-sided difference quotient.
        h = 1e-7
        slope = (compress_ratio(np.array(threshold + h), threshold, np.float64(limit)) - threshold) / h
        assert abs(slope - 1.0) < 1e-5


@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_inside_threshold_unchanged_and_in_gamut_rest_moves_inwards(display_name):
    d = cases.display(display_name)
    rgb = cases.display_colours()
    lightness, chroma, hue = lch(rgb, d)
    ratio = chroma / np.maximum(display_boundary(np.clip(lightness, 0, 1), hue, d), 1e-300)
    out = perceptual(rgb, d)
    inside = ratio <= PerceptualParams().threshold
    assert inside.mean() > 0.5
    assert np.array_equal(out[inside], rgb[inside])
    _, out_chroma, _ = lch(out[~inside], d)
    assert np.all(out_chroma <= chroma[~inside] + GAMUT_MONOTONE_ABSOLUTE)


@pytest.mark.parametrize("display_name, source", cases.PAIRS)
def test_keeps_oklab_lightness_and_hue(display_name, source):
    d = cases.display(display_name)
    rgb = cases.source_colours(source, display_name)
    lightness, _, hue = lch(rgb, d)
    out_lightness, out_chroma, out_hue = lch(perceptual(rgb, d), d)
    assert np.max(np.abs(out_lightness - lightness)) <= GAMUT_OKLAB_ABSOLUTE
    coloured = out_chroma >= GAMUT_HUE_MIN_CHROMA
    assert coloured.mean() > 0.95
    turn = np.angle(np.exp(1j * (out_hue - hue)))[coloured]
    assert np.max(np.abs(turn)) <= GAMUT_OKLAB_ABSOLUTE


@pytest.mark.parametrize("display_name, source", cases.PAIRS)
def test_compressed_chroma_is_exactly_monotone_at_fixed_lightness_and_hue(display_name, source):
    d = cases.display(display_name)
    lightness, hue, chroma = np.meshgrid(LIGHTNESSES, HUES, np.linspace(0, 0.6, 400), indexing="ij")
    for params in (PerceptualParams(), PerceptualParams(source_to_display=cases.source_to_display(
            source, display_name))):
        out, ratio = compress_chroma(lightness, chroma, np.cos(hue), np.sin(hue), d, params)
        assert np.all(np.diff(out, axis=-1) >= 0.0) and np.all(out <= chroma)
        assert np.array_equal(out[ratio <= params.threshold], chroma[ratio <= params.threshold])


@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_chroma_ramps_are_monotone_and_end_on_the_boundary(display_name):
    d = cases.display(display_name)
    rgb, lightness, hue, chroma = ramps(d)
    out = perceptual(rgb, d)
    out_lightness, out_chroma, _ = lch(out, d)
    assert np.max(np.abs(out_lightness - lch(rgb, d)[0])) <= GAMUT_OKLAB_ABSOLUTE
    assert np.min(np.diff(out_chroma, axis=-1)) >= -GAMUT_RGB_RAMP_MONOTONE_ABSOLUTE
    # Beyond limit x boundary the colour sits on the display boundary: a channel at 0 or 1.
    limit = PerceptualParams().limit * display_boundary(lightness[..., 0], hue[..., 0], d)
    beyond = chroma >= limit[..., None]
    edge = np.minimum(out.min(axis=-1), 1.0 - out.max(axis=-1))
    assert beyond.mean() > 0.3 and np.max(edge[beyond]) <= GAMUT_BOUNDARY_ABSOLUTE


@pytest.mark.parametrize("display_name, source", cases.PAIRS)
def test_source_gamut_surface_lands_on_the_display_boundary(display_name, source):
    d = cases.display(display_name)
    matrix = cases.source_to_display(source, display_name)
    params = PerceptualParams(source_to_display=matrix)
    surface = np.random.default_rng(4).uniform(0, 1, (3000, 3))
    surface[np.arange(3000), np.arange(3000) % 3] = np.arange(3000) % 2  # one channel at 0 or 1
    rgb = surface @ matrix.T
    outside = np.any((rgb < 0.0) | (rgb > 1.0), axis=-1)
    out = perceptual(rgb[outside], d, params)
    edge = np.minimum(out.min(axis=-1), 1.0 - out.max(axis=-1))
    assert outside.mean() > 0.3 and np.max(edge) <= GAMUT_BOUNDARY_ABSOLUTE


@pytest.mark.parametrize("bad", [dict(threshold=1.0), dict(threshold=-0.1), dict(limit=0.9),
                                 dict(limit=float("inf")), dict(source_to_display=np.zeros((3, 3)))])
def test_invalid_parameters_are_refused(bad):
    with pytest.raises(ValueError):
        PerceptualParams(**bad)


def test_brighter_than_white_is_white_and_below_black_is_black():
    d = cases.display("ITU-R BT.709")
    rgb = np.array([[65504.0, 0.0, 0.0], [1.5, 1.5, 1.5], [-1.0, -1.0, -1.0], [-65504.0, 0.0, 0.0]])
    assert np.array_equal(perceptual(rgb, d), [[1.0] * 3, [1.0] * 3, [0.0] * 3, [0.0] * 3])


@settings(deadline=None, max_examples=60)
@given(arrays(np.float64, (8, 3), elements=st.one_of(
    st.floats(-65504.0, 65504.0), st.sampled_from([np.nan, np.inf, -np.inf]))))
def test_with_a_source_gamut_any_input_maps_into_the_cube(rgb):
    params = PerceptualParams(source_to_display=cases.source_to_display("ACEScg", "P3-D65"))
    out = perceptual(rgb, cases.display("P3-D65"), params)
    assert np.all(np.isfinite(out)) and np.all((out >= 0.0) & (out <= 1.0))
