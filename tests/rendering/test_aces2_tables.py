"""The ACES 2.0 tables: what the CTL's searches find, checked against what they search for."""

from __future__ import annotations

import numpy as np
import pytest

from generator.rendering.aces2 import tables
from generator.rendering.aces2_params import CUBE_CORNERS
from generator.rendering.aces2_presets import PRESETS
from generator.rendering.aces2_tables import CUSP_M_SCALE, PADDED_SIZE, REACH_TOLERANCE, reach_corners
from generator.rendering.jmh import jmh_to_rgb, rgb_to_jmh
from tests.rendering.aces2_cases import LED_WALL, preset_tables

VIEWS = [
    "ACES 2.0 - SDR 100 nits (Rec.709)",
    "ACES 2.0 - HDR 1000 nits (P3 D65)",
    "ACES 2.0 - HDR 4000 nits (Rec.2020 D60 sim.)",
    "ACES 2.0 - HDR 108 nits (P3 D60 sim.)",
]


def table_of(view):
    return tables(LED_WALL) if view == "LED wall" else preset_tables(view)


@pytest.mark.parametrize("view", [*VIEWS, "LED wall"])
def test_hue_table_holds_every_corner(view):
    t = table_of(view)
    peak = t.params.peak_luminance
    assert t.hues.shape == t.cusp_j.shape == t.cusp_m.shape == t.gamma_top_inv.shape == t.reach_m.shape
    assert t.hues.shape == (PADDED_SIZE,)
    assert np.all(np.diff(t.hues) > 0.0)
    assert t.hues[1] == 0.0 and t.hues[0] == t.hues[-2] - 360.0 and t.hues[-1] == t.hues[1] + 360.0
    limit = rgb_to_jmh(np.asarray(CUBE_CORNERS) * (peak / 100.0), t.limit)
    reach = reach_corners(t.reach, t.limit_j_max, t.tone.forward_limit)[1:-1]
    assert set(limit[:, 2]) | set(reach[:, 2]) <= set(t.hues)
    at_corner = np.searchsorted(t.hues, limit[:, 2])
    np.testing.assert_array_equal(t.cusp_j[at_corner], limit[:, 0])
    np.testing.assert_allclose(t.cusp_m[at_corner], limit[:, 1] * CUSP_M_SCALE, rtol=1e-15)


@pytest.mark.parametrize("view", [*VIEWS, "LED wall"])
def test_cusps_lie_on_the_cube_edges(view):
    """Each cusp is the limiting gamut's colour of its hue with one channel at peak / 100 and
    one at 0 (bisected to 1e-7 along the edge)."""
    t = table_of(view)
    peak = t.params.peak_luminance / 100.0
    jmh = np.stack([t.cusp_j, t.cusp_m / CUSP_M_SCALE, t.hues % 360.0], axis=-1)
    rgb = jmh_to_rgb(jmh, t.limit)
    np.testing.assert_allclose(rgb.max(axis=-1), peak, rtol=1e-6)
    np.testing.assert_allclose(rgb.min(axis=-1), 0.0, atol=1e-6 * peak)


@pytest.mark.parametrize("view", [*VIEWS, "LED wall"])
def test_reach_table_brackets_the_reach_boundary(view):
    """At limit_J_max, AP1 holds M 0.01 below each entry and not the entry itself."""
    t = table_of(view)
    hues = np.arange(360.0)
    m = t.reach_m[1:-1]

    def lowest(values):
        jmh = np.stack(np.broadcast_arrays(t.limit_j_max, values, hues), axis=-1)
        return jmh_to_rgb(jmh, t.reach).min(axis=-1)

    assert np.all(lowest(m) < 0.0)
    assert np.all(lowest(m - REACH_TOLERANCE) >= 0.0)
    assert t.reach_m[0] == t.reach_m[-2] and t.reach_m[-1] == t.reach_m[1]


def test_gamma_is_within_the_search():
    for view in PRESETS:
        gamma = 1.0 / preset_tables(view).gamma_top_inv
        assert np.all((gamma > 0.0) & (gamma < 5.2))
