"""The ACES 2.0 Output Transform as a whole: round trips, greys, shapes, the white scale."""

from __future__ import annotations

import numpy as np
import pytest

from generator import tolerances
from generator.rendering.aces2 import ACES2Params, forward, inverse, output_rgb, output_rgb_inverse, tables
from generator.rendering.aces2_presets import D60, D65, PRESETS, REC709, REC2020
from tests.rendering.aces2_cases import LED_WALL, display_error, is_sdr, preset_tables, probe_sets

ROUND_TRIP_VIEWS = [
    "ACES 2.0 - SDR 100 nits (Rec.709)",
    "ACES 2.0 - SDR 100 nits (P3 D65)",
    "ACES 2.0 - SDR 100 nits (P3 D60 sim.)",
    "ACES 2.0 - SDR 100 nits (P3 D60 in XYZ)",
    "ACES 2.0 - HDR 108 nits (P3 D65)",
    "ACES 2.0 - HDR 1000 nits (P3 D65)",
    "ACES 2.0 - HDR 4000 nits (Rec.2020)",
    "ACES 2.0 - HDR 1000 nits (Rec.2020 D60 sim.)",
]


@pytest.mark.parametrize("view", ROUND_TRIP_VIEWS)
def test_display_round_trip(view):
    """What the view shows, back through its inverse and forward again: exact (1e-10) below the
    gamut compression's analytic threshold, within the CTL's one-pass estimate above it. Colours
    the view clips to the display cube are left out: the clip is not inverted."""
    preset, t = PRESETS[view], preset_tables(view)
    aces = np.concatenate(list(probe_sets().values()))
    clamped = np.clip(aces @ t.ap0_to_ap1.T, 0.0, t.tone.forward_limit) @ t.ap1_to_ap0.T
    core = output_rgb(clamped, t)
    shown = forward(aces[np.all((core > 0.0) & (core < preset.params.peak_luminance / 100.0), axis=-1)], t)
    error = display_error(forward(inverse(shown, t), t), shown, preset.params)
    limit = tolerances.ACES2_ROUND_TRIP_CODES
    assert error.max() <= (limit if is_sdr(preset.params) else limit * tolerances.DELTA_E_ITP_PER_PQ_CODE)


def test_core_round_trip_for_a_custom_display():
    t = tables(LED_WALL)
    rgb = np.random.default_rng(3).uniform(0.0, 1.0, (20000, 3)) * 2.0
    back = output_rgb_inverse(output_rgb(rgb, t), t)
    assert np.percentile(np.abs(back - rgb).max(axis=-1) / np.abs(rgb).max(axis=-1), 99) < 1e-9


@pytest.mark.parametrize("view", ["ACES 2.0 - SDR 100 nits (Rec.709)", "ACES 2.0 - HDR 1000 nits (P3 D60 sim.)"])
def test_greys_stay_neutral_and_reach_the_peak(view):
    """A grey shows as the limiting white (scaled into the encoding gamut where it applies), at
    the peak from the tone scale's roof r_hit on."""
    preset, t = PRESETS[view], preset_tables(view)
    grey = np.geomspace(1e-3, 1e4, 200)[:, None] * np.ones(3)
    limiting = forward(grey, t) @ t.xyz_to_limit.T / t.display_scale
    np.testing.assert_allclose(limiting, limiting[:, :1] * np.ones(3), rtol=1e-9, atol=1e-12)
    roof = t.tone.forward_limit / 8.0
    at_roof = forward(np.full(3, roof), t) @ t.xyz_to_limit.T / t.display_scale
    np.testing.assert_allclose(at_roof, preset.params.peak_luminance / 100.0, rtol=1e-9)
    assert np.all(np.diff(limiting[:, 1]) >= 0.0)


def test_vectorised_over_leading_axes():
    t = preset_tables("ACES 2.0 - SDR 100 nits (Rec.709)")
    aces = np.random.default_rng(5).uniform(-0.1, 4.0, (2, 3, 4, 3))
    flat = forward(aces.reshape(-1, 3), t)
    np.testing.assert_array_equal(forward(aces, t), flat.reshape(aces.shape))
    np.testing.assert_array_equal(inverse(flat, t).reshape(aces.shape), inverse(flat.reshape(aces.shape), t))
    assert forward(np.full(3, 0.18), t).shape == (3,)
    with pytest.raises(ValueError, match="3 components"):
        forward(np.zeros((4, 2)), t)


def test_the_white_scale_is_ocios():
    """Applied only where the limiting white differs from the encoding's: 1 / the largest channel
    of D60 in Rec.709 (OpenColorIO's builtin: 0.9550158655187944)."""
    assert tables(ACES2Params(100, REC709, D65)).display_scale == 1.0
    assert tables(ACES2Params(100, REC709, D60, REC709, D65)).display_scale == pytest.approx(
        0.9550158655187944, rel=1e-12
    )


def test_wide_and_custom_gamuts_are_taken():
    for primaries in (REC2020, LED_WALL.limiting_primaries, ((0.7347, 0.2653), (0.0, 1.0), (0.0001, -0.077))):
        params = ACES2Params(1000, primaries, D65)
        assert np.all(np.isfinite(forward(probe_sets()["camera"], tables(params))))
