"""OCIO's HSV in numpy and the desaturate view's lattice coordinates (generator.luts.hsv_axes)."""

from __future__ import annotations

import numpy as np
import pytest

from generator.luts import hsv_axes
from tests.luts import hsv_cases


def test_ports_of_ocio_hsv_agree_with_ocio():
    import PyOpenColorIO as ocio

    colours = hsv_cases.colours(2000)
    colours = colours[np.abs(colours.max(axis=-1) + colours.min(axis=-1)) > 0.05 * np.abs(colours).max(axis=-1)]
    ours = hsv_axes.ocio_rgb_to_hsv(colours.astype(np.float32).astype(np.float64))
    theirs = hsv_cases.ocio_fixed(ocio.FIXED_FUNCTION_RGB_TO_HSV, ocio.TRANSFORM_DIR_FORWARD)(colours)
    hue_difference = np.abs(ours[:, 0] - theirs[:, 0])
    assert np.minimum(hue_difference, 1.0 - hue_difference).max() < 1e-6
    assert np.allclose(ours[:, 1:], theirs[:, 1:], rtol=1e-5, atol=1e-6)
    back = hsv_cases.ocio_fixed(ocio.FIXED_FUNCTION_RGB_TO_HSV, ocio.TRANSFORM_DIR_INVERSE)(theirs)
    assert np.allclose(
        hsv_axes.ocio_hsv_to_rgb(theirs.astype(np.float32).astype(np.float64)),
        back,
        rtol=1e-5,
        atol=1e-5 * np.abs(colours).max(axis=-1, keepdims=True),
    )


def test_shared_table_puts_grey_zero_and_the_gamut_boundary_on_nodes():
    table = hsv_axes.shared_table()
    half = np.arange(65536, dtype=np.uint16).view(np.float16).astype(np.float64)
    at = {float(v): i for i, v in enumerate(half) if np.isfinite(v) and not np.signbit(v)}
    n = hsv_axes.HSV_SIZE
    assert table[at[1.0], 1] == 0.5  # t = 2 - S = 1: saturation 1, the cube's surface
    minus_zero = np.flatnonzero((half == 0.0) & np.signbit(half))[0]
    assert table[at[0.0], 2] == 0.0 and table[minus_zero, 2] == 1.0  # +0 first, -0 last, as VALUE_NODES
    assert table[minus_zero + 1, 2] < 1.0  # the smallest negative half float: a float between reads both
    assert table[at[1.0], 2] == hsv_axes.VALUE_NODES.index(1.0) / (n - 1)
    assert np.array_equal(table[[at[0.25], at[0.5]], 0], np.array([0.25, 0.5]) / hsv_axes.SHARED_SCALE)
    # Saturation's u = 1 / t above S = 1, reaching SATURATION_REACH at t = 2**-23, a subnormal half.
    assert table[at[2.0**-23], 1] == 1.0 and table[at[0.5], 1] == pytest.approx(
        np.interp(2.0, hsv_axes.saturation_nodes(), np.linspace(0, 1, n)), abs=1e-15
    )
    # Every t OCIO gives below 2**-14 (a multiple of 2**-23: 2 - S in float32) is an entry.
    t = np.arange(1, 2**9 + 1) * 2.0**-23
    assert np.all(np.isin(t, half))
    entries = table[[at[v] for v in t], 1]
    assert np.allclose(
        entries, np.interp(1.0 / t, hsv_axes.saturation_nodes(), np.linspace(0, 1, n)), rtol=0, atol=1e-15
    )
    assert np.all(np.diff(entries) < 0.0)  # u's coordinate resolves each of them


def test_the_far_saturation_cells_resolve_u_within_ocio_hsv_float32():
    """From u = 256 to the reach (t from 2**-8 to 2**-23, the cells widening fastest), the
    float32 resolution of u's lattice coordinate, back in S, stays within OCIO's own float32
    resolution of S through the view (FLOAT32_HSV_ROUNDINGS): nodes 256, 8192 and 2**23 keep
    it to about half (one cell from 256 to 2**23 would be 500 times it)."""
    from generator import tolerances

    u = np.geomspace(256.0, hsv_axes.SATURATION_REACH, 20001)
    values = np.stack([np.zeros_like(u), 2.0 - 1.0 / u, np.full_like(u, 0.5)], axis=-1)
    own = tolerances.FLOAT32_HSV_ROUNDINGS * tolerances.FLOAT32_UNIT_ROUNDOFF * values[:, 1]
    assert np.all(hsv_axes.saturation_coordinate_resolution(values) <= own)
