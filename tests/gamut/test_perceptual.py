"""The Oklab chroma compression toward a lightness focus: hue, lines, threshold, limit, monotonicity."""

from __future__ import annotations

import colour
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from generator.gamut import PerceptualParams, perceptual
from generator.gamut.perceptual import (
    FOLD_HUE_MARGIN,
    adapted_matrix,
    boundary_chroma,
    compress_along_lines,
    compress_ratio,
    cusp_table,
    display_to_oklab,
    focus_lightness,
    fold_hues,
    hue_folds,
    line_through,
    oklab_to_display,
)
from generator.tolerances import (
    GAMUT_BOUNDARY_ABSOLUTE,
    GAMUT_FOLD_OKLAB,
    GAMUT_HUE_MIN_CHROMA,
    GAMUT_OKLAB_ABSOLUTE,
    GAMUT_PERCEPTUAL_LIPSCHITZ,
    GAMUT_RGB_RAMP_MONOTONE_ABSOLUTE,
)
from tests.gamut import cases

SOFT = PerceptualParams(threshold=0.8, limit=1.25)
EXACT = PerceptualParams(threshold=1.0)
LIGHTNESSES = np.array([0.2, 0.4, 0.6, 0.8, 0.95])
HUES = np.linspace(0.0, 2.0 * np.pi, 36, endpoint=False)


def lch(rgb, display):
    lab = display_to_oklab(rgb, display)
    return lab[..., 0], np.hypot(lab[..., 1], lab[..., 2]), np.arctan2(lab[..., 2], lab[..., 1])


def line_of(lightness, chroma, hue, display, params=SOFT):
    """The grey and slope of each colour's line, and its focus lightness."""
    focus = focus_lightness(np.cos(hue), np.sin(hue), display)
    return (*line_through(lightness, chroma, focus, params.focus_distance), focus)


def display_boundary(axis, slope, hue, display):
    return boundary_chroma(axis, slope, np.cos(hue), np.sin(hue), adapted_matrix(display))


def ratios(rgb, display, params=SOFT):
    """``C / C_d`` along each colour's line, and whether its grey is within [0, 1]."""
    lightness, chroma, hue = lch(rgb, display)
    axis, slope, _ = line_of(lightness, chroma, hue, display, params)
    boundary = display_boundary(axis, slope, hue, display)
    return chroma / np.maximum(boundary, 1e-300), (axis >= 0.0) & (axis <= 1.0)


def constant_lightness_ramps(display, count=400, top=0.6):
    """Constant-L, constant-hue chroma ramps from 0 to `top`: RGB (L, h, C, 3) and the grid."""
    lightness, hue, chroma = np.meshgrid(LIGHTNESSES, HUES, np.linspace(0, top, count), indexing="ij")
    lab = np.stack([lightness, chroma * np.cos(hue), chroma * np.sin(hue)], axis=-1)
    return oklab_to_display(lab, display), lightness, hue, chroma


def kept_within(rgb, display):
    """What of hue and of the line each colour's image keeps: exactly, except colours outside
    the cube of a display whose Oklab hue folds, of hues near the fold, whose boundary point is
    found with FOLD_SLACK and then clipped (at every hue, an orange on BT.709 had turned 0.18
    degree and moved 10.7 ten-bit codes)."""
    outside = np.any((rgb < 0.0) | (rgb > 1.0), axis=-1)
    near = np.zeros(outside.shape, dtype=bool)
    if hue_folds(display):
        centre, half = fold_hues(display)
        _, _, hue = lch(rgb, display)
        near = np.abs(np.angle(np.exp(1j * (hue - centre)))) <= half + FOLD_HUE_MARGIN
    return np.where(outside & near, GAMUT_FOLD_OKLAB, GAMUT_OKLAB_ABSOLUTE)


def edge_distance(rgb):
    """Distance of each colour from the cube's surface (0 on it)."""
    return np.minimum(rgb.min(axis=-1), 1.0 - rgb.max(axis=-1))


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
def test_the_focus_is_at_the_lightness_of_each_hue_s_most_chromatic_colour(display_name):
    d = cases.display(display_name)
    hue = np.radians(np.arange(360.0))  # whole degrees miss the blue primary's 0.15-degree fold
    focus = focus_lightness(np.cos(hue), np.sin(hue), d)
    level = np.zeros_like(hue)
    at_focus = display_boundary(focus, level, hue, d)
    for step in (-1e-3, 1e-3):
        assert np.all(display_boundary(focus + step, level, hue, d) < at_focus)
    table_hue, table_lightness = cusp_table(d)
    assert np.all(np.diff(table_hue[np.argsort(table_hue)]) > 0) and not table_lightness.flags.writeable


@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_boundary_chroma_brackets_the_cube_surface_along_each_line(display_name):
    d = cases.display(display_name)
    axis, hue = np.meshgrid(LIGHTNESSES, HUES, indexing="ij")
    focus = focus_lightness(np.cos(hue), np.sin(hue), d)
    slope = (axis - focus) / SOFT.focus_distance
    chroma = display_boundary(axis, slope, hue, d)
    for factor, inside in ((1.0, True), (1.0 + 1e-9, False)):
        c = chroma * factor + (0.0 if inside else 1e-12)
        lab = np.stack([axis + slope * c, c * np.cos(hue), c * np.sin(hue)], -1)
        rgb = oklab_to_display(lab, d)
        assert np.all(np.all((rgb >= -1e-12) & (rgb <= 1 + 1e-12), axis=-1) == inside)


def test_compression_curve():
    x = np.linspace(0.0, 3.0, 3001)
    for threshold, limit in ((0.8, 1.25), (0.5, 2.0), (0.9, 1.0), (1.0, 1.25)):
        y = compress_ratio(x, threshold, np.float64(limit))
        assert np.array_equal(y[x <= threshold], x[x <= threshold])
        assert np.all(np.diff(y) >= 0.0) and np.all(y <= 1.0) and np.all(y <= x)
        assert np.all(y[x >= limit] == 1.0)
    for threshold, limit in ((0.8, 1.25), (0.5, 2.0)):
        # Slope 1 at the threshold (C1): one-sided difference quotient.
        h = 1e-7
        slope = (compress_ratio(np.array(threshold + h), threshold, np.float64(limit)) - threshold) / h
        assert abs(slope - 1.0) < 1e-5


@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_inside_threshold_unchanged_and_in_gamut_rest_moves_inwards(display_name):
    d = cases.display(display_name)
    rgb = cases.display_colours()
    ratio, _ = ratios(rgb, d)
    out = perceptual(rgb, d, SOFT)
    inside = ratio <= SOFT.threshold
    assert inside.mean() > 0.6  # measured 0.62 of the cube's volume
    assert np.array_equal(out[inside], rgb[inside])
    _, chroma, _ = lch(rgb[~inside], d)
    _, out_chroma, _ = lch(out[~inside], d)
    assert np.all(out_chroma <= chroma + GAMUT_OKLAB_ABSOLUTE)


@pytest.mark.parametrize("display_name, source", cases.PAIRS)
@pytest.mark.parametrize("params", [SOFT, EXACT], ids=["soft", "exact"])
def test_keeps_hue_and_moves_along_the_line_toward_the_focus(display_name, source, params):
    d = cases.display(display_name)
    rgb = cases.source_colours(source, display_name)
    lightness, chroma, hue = lch(rgb, d)
    axis, _, focus = line_of(lightness, chroma, hue, d, params)
    out_lightness, out_chroma, out_hue = lch(perceptual(rgb, d, params), d)
    on_axis = (axis >= 0.0) & (axis <= 1.0)
    coloured = on_axis & (out_chroma >= GAMUT_HUE_MIN_CHROMA)
    assert coloured.mean() > 0.95
    within = kept_within(rgb, d)
    turn = np.angle(np.exp(1j * (out_hue - hue)))
    assert np.all(np.abs(turn[coloured]) <= within[coloured])
    # The focus (L_f, -D), the colour and its image are collinear, and lightness moves toward L_f.
    distance = params.focus_distance
    cross = (lightness - focus) * (out_chroma + distance) - (out_lightness - focus) * (chroma + distance)
    assert np.all(np.abs(cross[on_axis]) <= within[on_axis])
    toward = np.abs(out_lightness - focus) <= np.abs(lightness - focus) + within
    assert np.all(toward[on_axis])


@pytest.mark.parametrize("display_name, source", cases.PAIRS)
def test_compressed_chroma_is_exactly_monotone_along_each_line(display_name, source):
    d = cases.display(display_name)
    axis, hue, chroma = np.meshgrid(LIGHTNESSES, HUES, np.linspace(0, 0.6, 400), indexing="ij")
    slope = (axis - focus_lightness(np.cos(hue), np.sin(hue), d)) / SOFT.focus_distance
    for params in (SOFT, EXACT, PerceptualParams(source_to_display=cases.source_to_display(source, display_name))):
        out, ratio = compress_along_lines(chroma, axis, slope, np.cos(hue), np.sin(hue), d, params)
        assert np.all(np.diff(out, axis=-1) >= 0.0) and np.all(out <= chroma)
        assert np.array_equal(out[ratio <= params.threshold], chroma[ratio <= params.threshold])


@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
@pytest.mark.parametrize("params", [SOFT, EXACT], ids=["soft", "exact"])
def test_constant_lightness_chroma_ramps_are_monotone_and_end_on_the_boundary(display_name, params):
    d = cases.display(display_name)
    rgb, _lightness, _hue, _chroma = constant_lightness_ramps(d)
    out = perceptual(rgb, d, params)
    _, out_chroma, _ = lch(out, d)
    assert np.min(np.diff(out_chroma, axis=-1)) >= -GAMUT_RGB_RAMP_MONOTONE_ABSOLUTE
    ratio, on_axis = ratios(rgb, d, params)
    beyond = (ratio >= params.limit) & on_axis
    assert beyond.mean() > 0.3 and np.max(edge_distance(out[beyond])) <= GAMUT_BOUNDARY_ABSOLUTE


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
    assert outside.mean() > 0.3 and np.max(edge_distance(out)) <= GAMUT_BOUNDARY_ABSOLUTE


@pytest.mark.parametrize("display_name, source", cases.PAIRS)
def test_threshold_one_leaves_the_cube_and_clips_the_rest_onto_its_boundary(display_name, source):
    d = cases.display(display_name)
    inside = cases.display_colours()
    assert np.array_equal(perceptual(inside, d, EXACT), inside)
    rgb = cases.source_colours(source, display_name)
    rgb = rgb[np.any((rgb < 0.0) | (rgb > 1.0), axis=-1)]
    out = perceptual(rgb, d, EXACT)
    assert np.max(edge_distance(out)) <= GAMUT_BOUNDARY_ABSOLUTE
    _, _, hue = lch(rgb, d)
    _, out_chroma, out_hue = lch(out, d)
    coloured = out_chroma >= GAMUT_HUE_MIN_CHROMA
    turn = np.abs(np.angle(np.exp(1j * (out_hue - hue))))
    assert np.all(turn[coloured] <= kept_within(rgb, d)[coloured])


@pytest.mark.parametrize("display_name", (*cases.DISPLAY_NAMES, "ITU-R BT.2020"))
@pytest.mark.parametrize("threshold", [0.8, 1.0])
def test_continuous_along_the_cube_edges_and_beyond(display_name, threshold):
    """No jump anywhere near the primaries and secondaries, in or out of the cube: a
    perturbation of 1e-7 (relative) moves the image by at most GAMUT_PERCEPTUAL_LIPSCHITZ
    times it. Counting only strictly inside, BT.709's folded blue edge jumped by 0.18."""
    d = cases.display(display_name)
    corners = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1]], dtype=float)
    rgb = (corners[:, None, :] * np.geomspace(1e-3, 16.0, 200)[None, :, None]).reshape(-1, 3)
    rng = np.random.default_rng(7)
    step = 1e-7 * rgb.max(axis=-1, keepdims=True)
    params = PerceptualParams(threshold=threshold)
    for _ in range(4):
        moved = perceptual(rgb + step * rng.standard_normal(rgb.shape), d, params)
        jump = np.abs(moved - perceptual(rgb, d, params)).max(axis=-1)
        assert np.all(jump <= GAMUT_PERCEPTUAL_LIPSCHITZ * 2.0 * step[:, 0])


@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_threshold_one_leaves_the_display_cube_untouched(display_name):
    """Threshold 1 clips onto the boundary along the lines: the cube itself is the identity."""
    rgb = cases.display_colours()
    assert PerceptualParams().threshold == 0.8
    assert np.array_equal(perceptual(rgb, cases.display(display_name), PerceptualParams(threshold=1.0)), rgb)


@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_displacement_vanishes_to_second_order_at_the_threshold(display_name):
    """C1 at the edge of the untouched region: just beyond it a colour moves by O(excess^2)."""
    d = cases.display(display_name)
    axis, hue = np.meshgrid(LIGHTNESSES, HUES, indexing="ij")
    slope = (axis - focus_lightness(np.cos(hue), np.sin(hue), d)) / SOFT.focus_distance
    edge = SOFT.threshold * display_boundary(axis, slope, hue, d)
    moves = []
    for excess in (1e-3, 1e-4):
        chroma = edge * (1.0 + excess)
        out, _ = compress_along_lines(chroma, axis, slope, np.cos(hue), np.sin(hue), d, SOFT)
        moves.append((chroma - out) / (chroma - edge))
    assert np.all(moves[0] > 0.0)
    assert np.all(moves[1] <= 0.11 * moves[0])  # relative move proportional to the excess: order 2


@pytest.mark.parametrize(
    "bad",
    [
        dict(threshold=1.1),
        dict(threshold=-0.1),
        dict(limit=0.9),
        dict(limit=float("inf")),
        dict(focus_distance=0.0),
        dict(focus_distance=float("inf")),
        dict(source_to_display=np.zeros((3, 3))),
    ],
)
def test_invalid_parameters_are_refused(bad):
    with pytest.raises(ValueError):
        PerceptualParams(**bad)


@pytest.mark.parametrize("params", [SOFT, EXACT], ids=["soft", "exact"])
def test_brighter_than_white_is_white_and_below_black_is_black(params):
    d = cases.display("ITU-R BT.709")
    rgb = np.array([[65504.0, 0.0, 0.0], [1.5, 1.5, 1.5], [-1.0, -1.0, -1.0], [-65504.0, 0.0, 0.0]])
    assert np.array_equal(perceptual(rgb, d, params), [[1.0] * 3, [1.0] * 3, [0.0] * 3, [0.0] * 3])


@settings(deadline=None, max_examples=60)
@given(
    arrays(
        np.float64, (8, 3), elements=st.one_of(st.floats(-65504.0, 65504.0), st.sampled_from([np.nan, np.inf, -np.inf]))
    ),
    st.sampled_from([0.0, 0.8, 1.0]),
)
def test_with_a_source_gamut_any_input_maps_into_the_cube(rgb, threshold):
    params = PerceptualParams(threshold=threshold, source_to_display=cases.source_to_display("ACEScg", "P3-D65"))
    out = perceptual(rgb, cases.display("P3-D65"), params)
    assert np.all(np.isfinite(out)) and np.all((out >= 0.0) & (out <= 1.0))


def test_primaries_listed_clockwise_map_as_the_same_display():
    """The same Rec.709 display with its green and blue primaries listed in the other order
    (clockwise in xy, which the spec accepts): its cusp table runs red, magenta, blue, ...,
    and every colour maps as through the usual order (it was up to 720 ten-bit codes off)."""
    from generator.gamut import DisplayGamut

    rec709 = colour.RGB_COLOURSPACES["ITU-R BT.709"]
    swap = [0, 2, 1]
    usual = DisplayGamut(rec709.matrix_RGB_to_XYZ, tuple(rec709.whitepoint))
    clockwise = DisplayGamut(rec709.matrix_RGB_to_XYZ[:, swap], tuple(rec709.whitepoint))
    rgb = np.random.default_rng(3).uniform(-0.3, 1.4, (4096, 3))
    for params in (SOFT, EXACT):
        expected = perceptual(rgb, usual, params)
        np.testing.assert_allclose(
            perceptual(rgb[:, swap], clockwise, params)[:, swap], expected, rtol=0, atol=GAMUT_BOUNDARY_ABSOLUTE
        )


def test_a_gamut_wider_than_the_library_s_is_bracketed():
    """ProPhoto RGB's blue has Oklab chroma 1.41, beyond the library's bracket: threshold 1
    still leaves its whole cube untouched (its blue primary had moved to (0.03, 0.06, 0.72))."""
    from generator.gamut import DisplayGamut

    prophoto = colour.RGB_COLOURSPACES["ProPhoto RGB"]
    display = DisplayGamut(prophoto.matrix_RGB_to_XYZ, tuple(prophoto.whitepoint))
    rgb = np.concatenate([np.eye(3), np.random.default_rng(4).random((4096, 3))])
    np.testing.assert_array_equal(perceptual(rgb, display, EXACT), rgb)
