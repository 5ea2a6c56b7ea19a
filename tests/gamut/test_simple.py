"""clip, scale and desaturate: the invariants each keeps, with their figures."""

from __future__ import annotations

import colour
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from generator.gamut import clip, desaturate, scale
from generator.gamut.simple import desaturation_amount
from generator.tolerances import GAMUT_CHROMATICITY_ABSOLUTE, GAMUT_LUMINANCE_RELATIVE
from tests.gamut import cases


def xy(rgb, display):
    return colour.XYZ_to_xy(rgb @ display.matrix.T)


def test_clip_is_the_per_channel_clamp():
    rgb = np.array([[-0.5, 0.25, 1.5], [2.0, -3.0, 0.0]])
    assert np.array_equal(clip(rgb), [[0.0, 0.25, 1.0], [1.0, 0.0, 0.0]])


@given(arrays(np.float64, (16, 3), elements=st.floats(0.0, 65504.0)))
def test_scale_keeps_the_chromaticity_of_non_negative_colours(rgb):
    d = cases.display("ITU-R BT.709")
    out = scale(rgb, d)
    assert np.allclose(out.max(axis=-1), np.minimum(rgb.max(axis=-1), 1.0), rtol=0, atol=1e-15)
    visible = (rgb @ d.matrix.T).sum(axis=-1) > 1e-100  # xy of black is undefined
    assert np.all(np.abs(xy(out, d) - xy(rgb, d))[visible] <= GAMUT_CHROMATICITY_ABSOLUTE)


@pytest.mark.parametrize("display_name, source", cases.PAIRS)
def test_scale_keeps_xy_of_source_colours_after_the_negative_clamp(display_name, source):
    d = cases.display(display_name)
    rgb = np.maximum(cases.source_colours(source, display_name), 0.0) * 3.0
    assert np.max(np.abs(xy(scale(rgb, d), d) - xy(rgb, d))) <= GAMUT_CHROMATICITY_ABSOLUTE


def needs_no_scale_step(rgb, display):
    """True where the desaturated colour already has max <= 1."""
    neutral = (rgb @ display.luminance_weights)[..., None] / display.luminance_weights.sum()
    mixed = rgb + desaturation_amount(rgb, neutral) * (neutral - rgb)
    return mixed.max(axis=-1) <= 1.0


@pytest.mark.parametrize("display_name, source", cases.PAIRS)
def test_desaturate_keeps_luminance_and_dominant_wavelength(display_name, source):
    d = cases.display(display_name)
    rgb = cases.source_colours(source, display_name)
    out = desaturate(rgb, d)
    kept = needs_no_scale_step(rgb, d)
    assert kept.mean() > 0.7  # most of the unit source cube needs only the first step
    y_in, y_out = rgb @ d.luminance_weights, out @ d.luminance_weights
    assert np.max(np.abs(y_out - y_in)[kept] / y_in[kept]) <= GAMUT_LUMINANCE_RELATIVE
    # Both steps keep the dominant wavelength: compare where the line from the white
    # through the colour meets the spectral locus (1 nm CIE 1931 2 degree samples).
    wl_in, locus_in, _ = colour.dominant_wavelength(xy(rgb, d), d.white_xy)
    wl_out, locus_out, _ = colour.dominant_wavelength(xy(out, d), d.white_xy)
    assert np.array_equal(wl_in, wl_out)
    assert np.max(np.abs(locus_out - locus_in)) <= GAMUT_CHROMATICITY_ABSOLUTE


@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_desaturate_turns_a_negative_sum_colour_to_the_complementary_side(display_name):
    """Y > 0 but X + Y + Z < 0 (negative scene values): xy lies across the white point from the
    mix's direction, so the result's chromaticity is on the same line through white, on the
    other side (README: the complementary dominant wavelength), with Y kept."""
    d = cases.display(display_name)
    rgb = np.random.default_rng(5).uniform(-0.5, 1.5, (200000, 3))
    xyz = rgb @ d.matrix.T
    rgb = rgb[(xyz[:, 1] > 0.0) & (xyz.sum(axis=-1) < 0.0)]
    assert len(rgb) > 1000
    out = desaturate(rgb, d)
    kept = needs_no_scale_step(rgb, d)
    y_in, y_out = rgb @ d.luminance_weights, out @ d.luminance_weights
    assert np.max(np.abs(y_out - y_in)[kept] / y_in[kept]) <= GAMUT_LUMINANCE_RELATIVE
    towards_in, towards_out = xy(rgb, d) - d.white_xy, xy(out, d) - d.white_xy
    cross = towards_in[:, 0] * towards_out[:, 1] - towards_in[:, 1] * towards_out[:, 0]
    scale_ = np.linalg.norm(towards_in, axis=-1) * np.linalg.norm(towards_out, axis=-1)
    assert np.max(np.abs(cross) / scale_) <= 1e-9
    assert np.all(np.sum(towards_in * towards_out, axis=-1) < 0.0)


@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_desaturate_moves_only_to_the_first_non_negative_point(display_name):
    d = cases.display(display_name)
    rgb = cases.source_colours("ACEScg", display_name)
    out = desaturate(rgb, d)
    moved = (rgb.min(axis=-1) < 0.0) & needs_no_scale_step(rgb, d)
    assert moved.sum() > 500
    assert np.max(out[moved].min(axis=-1)) <= GAMUT_LUMINANCE_RELATIVE  # a channel reaches 0


def test_desaturate_makes_non_positive_luminance_black():
    d = cases.display("ITU-R BT.709")
    rgb = np.array([[-1.0, 0.1, 0.1], [0.0, 0.0, 0.0], [2.0, -1.0, 0.5], [-5.0, -5.0, -5.0]])
    assert np.all(rgb @ d.luminance_weights <= 0.0)
    assert np.array_equal(desaturate(rgb, d), np.zeros_like(rgb))


def test_desaturate_scales_bright_colours_along_the_ray():
    d = cases.display("P3-D65")
    rgb = np.array([[4.0, 2.0, 1.0], [3.0, 3.0, 3.0]])
    assert np.allclose(desaturate(rgb, d), [[1.0, 0.5, 0.25], [1.0, 1.0, 1.0]], rtol=0, atol=1e-15)
