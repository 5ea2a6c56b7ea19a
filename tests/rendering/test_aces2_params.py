"""What sets an ACES 2.0 Output Transform: its checks, defaults and the range of peaks."""

from __future__ import annotations

import numpy as np
import pytest

from generator.rendering.aces2_params import (
    CUBE_CORNERS,
    PEAK_RANGE,
    ACES2Params,
    check_gamut,
    corner_hues_in_order,
)
from generator.rendering.aces2_presets import D60, D65, GAMUTS, P3, PRESETS, REC709, REC2020
from generator.rendering.jmh import jmh_params
from generator.rendering.tonescale import tone_scale


def test_defaults_and_white_scaling():
    """The encoding gamut defaults to the limiting one; the white is scaled where the two whites
    differ unless scale_white says otherwise (the scale itself: test_aces2.py)."""
    plain = ACES2Params(100, REC709, D65)
    assert plain.encoding_primaries == plain.limiting_primaries and plain.encoding_white == D65
    assert not plain.applies_white_scale
    assert ACES2Params(100, REC709, D60, REC709, D65).applies_white_scale
    assert not ACES2Params(100, REC709, D60, REC709, D65, scale_white=False).applies_white_scale
    assert ACES2Params(100, REC709, D65, scale_white=True).applies_white_scale
    assert hash(plain) == hash(ACES2Params(100.0, REC709, D65))


BAD = [
    (dict(peak_luminance=float("nan")), "peak_luminance"),
    (dict(peak_luminance=99), "peak_luminance"),
    (dict(peak_luminance=10001), "peak_luminance"),
    (dict(peak_luminance=1000.5), "peak_luminance"),
    (dict(peak_luminance="1000"), "peak_luminance"),
    (dict(peak_luminance=True), "peak_luminance"),
    (dict(limiting_primaries=((0.64, 0.33), (0.3, 0.6))), "limiting_primaries"),
    (dict(limiting_primaries=((0.64, 0.33), (0.3, float("inf")), (0.15, 0.06))), "limiting_primaries"),
    (dict(limiting_primaries=((0.64, 0.33), (0.40, 0.4657), (0.16, 0.60))), "limiting_primaries"),
    (dict(limiting_primaries=((0.15, 0.06), (0.3, 0.6), (0.64, 0.33))), "limiting_primaries"),
    (dict(limiting_white=(0.3127, 0.0)), "limiting_white"),
    (dict(limiting_white=(0.7, 0.29)), "limiting_white"),
    (dict(limiting_white=(0.3127,)), "limiting_white"),
    (dict(encoding_primaries=((0.64, 0.33), (0.64, 0.33), (0.15, 0.06))), "encoding_primaries"),
    (dict(encoding_white=(0.9, 0.05)), "encoding_white"),
    (dict(scale_white="yes"), "scale_white"),
    (dict(linear_scale=0.0), "linear_scale"),
    (dict(linear_scale=float("inf")), "linear_scale"),
]


@pytest.mark.parametrize("change, field", BAD, ids=[f"{field}-{i}" for i, (_, field) in enumerate(BAD)])
def test_bad_parameters_name_the_field(change, field):
    values = dict(peak_luminance=1000, limiting_primaries=P3, limiting_white=D65)
    values.update(change)
    with pytest.raises(ValueError, match=field):
        ACES2Params(**values)


def test_a_gamut_is_taken_in_either_orientation_as_tuples_of_floats():
    """check_gamut alone: the hue order of red, green and blue is ACES2Params' own check."""
    forward = check_gamut(np.asarray(REC709), list(D65), "limiting")
    assert forward == (REC709, D65) and all(type(v) is float for xy in forward[0] for v in xy)
    assert check_gamut(REC709[::-1], D65, "limiting") == (REC709[::-1], D65)


def test_the_cube_corners_go_round_the_hue_circle_in_every_gamut_of_the_presets():
    """Red, yellow, green, cyan, blue, magenta, in increasing JMh hue, once round; not when
    red and blue trade places."""
    assert len(CUBE_CORNERS) == 6
    for primaries, white in {
        *GAMUTS.values(),
        *((p.params.limiting_primaries, p.params.limiting_white) for p in PRESETS.values()),
    }:
        if primaries[0] == (1.0, 0.0):
            continue  # XYZ is an encoding gamut only
        for peak in (100.0, 1000.0, 10000.0):
            assert corner_hues_in_order(jmh_params(primaries, white), peak), (primaries, white)
    assert not corner_hues_in_order(jmh_params(REC709[::-1], D65), 100.0)


def test_peaks_are_whole_numbers_from_100_to_10000_stored_as_floats():
    for peak in (PEAK_RANGE[0], 1000, np.int64(4000), np.float32(225.0), PEAK_RANGE[1]):
        params = ACES2Params(peak, P3, D65)
        assert params.peak_luminance == float(peak) and type(params.peak_luminance) is float


def test_lists_are_stored_as_tuples_and_hash_alike():
    listed = ACES2Params(1000, [list(xy) for xy in REC2020], list(D60), scale_white=True, linear_scale=0.5)
    assert listed == ACES2Params(1000, REC2020, D60, REC2020, D60, True, 0.5)
    assert hash(listed) == hash(ACES2Params(1000, REC2020, D60, scale_white=True, linear_scale=0.5))


def test_the_peak_range_starts_above_where_the_tone_scale_fails():
    """The roof r_hit = 128 + 384 log10(peak / 100) reaches 0 at 100 x 10^(-1/3) = 46.4 cd/m²,
    where the AP1 clamp's upper limit, 8 r_hit, leaves nothing but black."""
    failing = 100.0 * 10.0 ** (-1.0 / 3.0)
    assert tone_scale(failing).forward_limit == pytest.approx(0.0, abs=1e-12)
    assert tone_scale(failing * 0.99).forward_limit < 0.0 < tone_scale(failing * 1.01).forward_limit
    assert PEAK_RANGE[0] > failing
