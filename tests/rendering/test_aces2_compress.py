"""The ACES 2.0 chroma and gamut compressions: their inverses, the geometry of the compression
lines, and the continuity of what they interpolate."""

from __future__ import annotations

import numpy as np
import pytest

from generator.rendering.aces2_compress import (
    COMPRESSION_THRESHOLD,
    FOCUS_GAIN_BLEND,
    NORM_COEFFICIENTS,
    SMOOTH_CUSPS,
    chroma_compress,
    chroma_compress_norm,
    compression_slope,
    focus_gain,
    focus_j,
    gamut_compress,
    hue_dependent,
    reach_m_at,
    remap_m,
    smooth_min,
    solve_j_intersect,
    toe_forward,
    toe_inverse,
)
from generator.rendering.jmh import j_to_y, y_to_j
from generator.rendering.tonescale import tonescale_forward
from tests.rendering.aces2_cases import preset_tables

VIEWS = [
    "ACES 2.0 - SDR 100 nits (Rec.709)",
    "ACES 2.0 - HDR 1000 nits (P3 D65)",
    "ACES 2.0 - HDR 4000 nits (Rec.2020 D60 sim.)",
    "ACES 2.0 - HDR 108 nits (P3 D60 sim.)",
]
SDR = VIEWS[0]


def jmh_samples(t, count: int = 4000, seed: int = 11):
    """J in (0, limit_J_max], M up to 1.3 times the reach table's, hues all round."""
    rng = np.random.default_rng(seed)
    h = rng.uniform(0.0, 360.0, count)
    j = rng.uniform(0.5, 1.0, count) * t.limit_j_max
    m = rng.uniform(0.01, 1.3, count) * reach_m_at(h, t)
    return j, m, h


def test_the_toe_rounds_zero_to_its_limit_and_inverts():
    """The toe meets the identity at its limit and keeps values beyond it; 0 stays 0."""
    rng = np.random.default_rng(3)
    limit, k1, k2 = rng.uniform(0.5, 2.0, 50), rng.uniform(0.0, 1.0, 50), rng.uniform(0.0, 0.5, 50)
    x = rng.uniform(0.0, 1.0, (400, 1)) * limit * 1.5
    toed = toe_forward(x, limit, k1, k2)
    assert np.all(np.diff(toe_forward(np.linspace(0.0, 2.0, 401)[:, None], limit, k1, k2), axis=0) > 0.0)
    np.testing.assert_allclose(toe_forward(limit, limit, k1, k2), limit, rtol=1e-14)
    np.testing.assert_allclose(toe_forward(0.0, limit, k1, k2), 0.0, atol=1e-16)
    assert np.array_equal(toed[x > limit], x[x > limit])
    np.testing.assert_allclose(toe_inverse(toed, limit, k1, k2), x, rtol=1e-12, atol=1e-14)


def test_the_normaliser_is_its_fourier_series():
    """The CTL's multiple-angle identities are the series in cos kh and sin kh."""
    h = np.radians(np.linspace(0.0, 360.0, 721))
    w = NORM_COEFFICIENTS
    series = sum(w[k - 1] * np.cos(k * h) + w[k + 2] * np.sin(k * h) for k in (1, 2, 3)) + w[6]
    np.testing.assert_allclose(chroma_compress_norm(np.cos(h), np.sin(h), 1.7), 1.7 * series, rtol=1e-13)


@pytest.mark.parametrize("view", VIEWS)
def test_chroma_compression_inverts_and_keeps_greys(view):
    t = preset_tables(view)
    j, m, h = jmh_samples(t)
    j_ts = y_to_j(tonescale_forward(j_to_y(j, t.input) / 100.0, t.tone), t.input)
    hr = np.radians(h)
    norm = chroma_compress_norm(np.cos(hr), np.sin(hr), t.chroma_compress_scale)
    compressed = chroma_compress(j, j_ts, m, h, norm, t)
    assert np.all(np.isfinite(compressed)) and np.all(compressed > 0.0)
    np.testing.assert_allclose(chroma_compress(j, j_ts, compressed, h, norm, t, invert=True), m, rtol=1e-9)
    grey = np.zeros_like(m)
    assert np.array_equal(chroma_compress(j, j_ts, grey, h, norm, t), grey)


def test_the_reach_table_is_read_at_whole_degrees_and_between_them():
    t = preset_tables(SDR)
    degrees = np.arange(360.0)
    assert np.array_equal(reach_m_at(degrees, t), t.reach_m[1:-1])
    halfway = reach_m_at(degrees + 0.5, t)
    np.testing.assert_allclose(halfway, (t.reach_m[1:-1] + t.reach_m[2:]) / 2.0, rtol=1e-15)


def test_the_smooth_minimum_rounds_the_corner_only():
    """Below min(a, b), by s / 6 where a = b, equal to it from |a - b| = s on (s = 0.12 x reference)."""
    reference = 50.0
    s = SMOOTH_CUSPS * reference
    a = np.full(2001, 30.0)
    b = np.linspace(20.0, 40.0, 2001)
    smooth = smooth_min(a, b, reference)
    assert np.all(smooth <= np.minimum(a, b))
    far = np.abs(a - b) >= s
    assert np.array_equal(smooth[far], np.minimum(a, b)[far])
    assert smooth_min(30.0, 30.0, reference) == pytest.approx(30.0 - s / 6.0, rel=1e-15)
    assert np.max(np.abs(np.diff(smooth))) < 2.0 * (b[1] - b[0])  # no jump at |a - b| = s


def test_m_is_remapped_from_the_threshold_so_that_the_reach_lands_on_the_boundary():
    gamut_m, reach_m = 60.0, 100.0
    threshold = COMPRESSION_THRESHOLD * gamut_m
    m = np.linspace(0.0, 400.0, 4001)
    moved = remap_m(m, gamut_m, reach_m)
    below = m <= threshold
    assert np.array_equal(moved[below], m[below])
    assert np.all(np.diff(moved) > 0.0) and np.all(moved < gamut_m + (gamut_m - threshold))
    assert remap_m(reach_m, gamut_m, reach_m) == pytest.approx(gamut_m, rel=1e-14)
    inside = moved < gamut_m
    np.testing.assert_allclose(remap_m(moved[inside], gamut_m, reach_m, invert=True), m[inside], rtol=1e-12)
    assert np.array_equal(remap_m(m, 120.0, reach_m), m)  # a boundary beyond the reach leaves M alone


@pytest.mark.parametrize("view", VIEWS)
def test_the_compression_line_passes_through_the_colour(view):
    """The line from its J-axis intersection, of the slope computed there, meets (J, M)."""
    t = preset_tables(view)
    j, m, h = jmh_samples(t)
    cusp_j = hue_dependent(h, t)[0]
    focus = focus_j(cusp_j, t.mid_j, t.limit_j_max)
    gain = focus_gain(j, cusp_j + (t.limit_j_max - cusp_j) * FOCUS_GAIN_BLEND, t.limit_j_max, t.focus_dist)
    j_is = solve_j_intersect(j, m, focus, t.limit_j_max, gain)
    slope = compression_slope(j_is, focus, t.limit_j_max, gain)
    assert np.all((j_is >= 0.0) & (j_is <= t.limit_j_max))
    np.testing.assert_allclose(j_is + slope * m, j, rtol=1e-10)


def test_the_focus_lies_between_the_cusp_and_mid_grey():
    j_max, mid = 100.0, 34.0
    cusp = np.linspace(1.0, 99.0, 99)
    focus = focus_j(cusp, mid, j_max)
    assert np.all((focus - cusp) * (focus - mid) <= 1e-12)
    assert np.array_equal(focus[cusp <= 0.3 * j_max], np.full(np.sum(cusp <= 0.3 * j_max), mid))


def test_the_focus_gain_rises_from_its_threshold_on():
    j = np.linspace(0.0, 99.9, 1000)
    gain = focus_gain(j, 70.0, 100.0, 1.35)
    assert np.array_equal(gain[j <= 70.0], np.full(np.sum(j <= 70.0), 135.0))
    assert np.all(np.diff(gain[j > 70.0]) > 0.0)
    assert focus_gain(70.0 + 1e-9, 70.0, 100.0, 1.35) == pytest.approx(135.0, rel=1e-12)


@pytest.mark.parametrize("view", VIEWS)
def test_gamut_compression_inverts_and_passes_greys_and_black(view):
    """Exactly where the slope gain takes no estimate (J at or below its threshold)."""
    t = preset_tables(view)
    j, m, h = jmh_samples(t)
    cusp_j = hue_dependent(h, t)[0]
    low = j <= cusp_j + (t.limit_j_max - cusp_j) * FOCUS_GAIN_BLEND
    jmh = np.stack([j, m, h], axis=-1)[low]
    compressed = gamut_compress(jmh, t)
    assert np.array_equal(compressed[:, 2], jmh[:, 2])
    np.testing.assert_allclose(gamut_compress(compressed, t, invert=True), jmh, rtol=1e-9)
    edge = np.array([[-1.0, 20.0, 10.0], [0.0, 20.0, 10.0], [50.0, 0.0, 10.0], [t.limit_j_max * 1.01, 20.0, 10.0]])
    out = gamut_compress(edge, t)
    assert np.array_equal(out[:, 1], np.zeros(4)) and np.array_equal(out[:, 0], [0.0, 0.0, 50.0, edge[3, 0]])


@pytest.mark.parametrize("view", VIEWS)
def test_hue_dependent_values_are_continuous(view):
    """Interpolating by each interval's share, the cusp and the upper hull's gamma meet at every
    entry from both sides (the CTL's unnormalised gamma weight would jump there)."""
    t = preset_tables(view)
    entries = t.hues[2:-1]
    below = np.stack(hue_dependent(np.nextafter(entries, -np.inf), t), axis=-1)
    at = np.stack(hue_dependent(entries, t), axis=-1)
    np.testing.assert_allclose(below, at, rtol=1e-12)
    np.testing.assert_allclose(at, np.stack([t.cusp_j, t.cusp_m, t.gamma_top_inv], axis=-1)[2:-1], rtol=1e-12)
