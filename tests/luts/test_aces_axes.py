"""Where a baked ACES view's lattice puts its nodes."""

from __future__ import annotations

import numpy as np
import pytest

from generator.luts import aces_axes
from generator.luts.aces_axes import SourceLogAxis, ViewAxis
from generator.rendering import views

SDR = views.catalogue()["ACES 2.0 - SDR 100 nits (Rec.709)"]


def test_the_basis_is_ap1_clamped_where_the_view_clamps():
    assert aces_axes.basis(SDR).upper == views.tables(SDR).tone.forward_limit == 1024.0
    assert aces_axes.basis(views.catalogue()["ACES 1.0 - SDR Video"]).upper == aces_axes.HALF_MAX


@pytest.mark.parametrize("thin", [aces_axes.SDR_THINNING, aces_axes.HDR_THINNING, aces_axes.HDR_LOW_THINNING])
def test_the_view_axis_is_two_pieces_in_log2_meeting_at_its_bend(thin):
    light, density = thin
    axis = ViewAxis.layout(aces_axes.ACES_TOE, 1024.0, light, density)
    x = np.array([0.0, light, 1024.0, 2048.0])
    np.testing.assert_allclose(axis.coordinate(x), [0.0, axis.bend, 1.0, 1.0], rtol=0, atol=1e-15)
    # per bit of log2(x + toe), the nodes above the bend are ``density`` times as dense
    step = np.diff(axis.coordinate(np.array([1.0, 2.0, 256.0, 512.0])))
    slope = np.log2((np.array([2.0, 512.0]) + axis.toe) / (np.array([1.0, 256.0]) + axis.toe))
    np.testing.assert_allclose((step[2] / slope[1]) / (step[0] / slope[0]), density, rtol=1e-12)


def test_sdr_views_thin_out_lower_than_hdr_views():
    """SDR views thin out above AP1 32 at a fifth, HDR views above 64: at a quarter below 1000
    cd/m², a third from there (docs/aces-views.md)."""
    hdr = views.catalogue()["ACES 2.0 - HDR 1000 nits (P3 D65)"]
    assert aces_axes.thinning(SDR) == aces_axes.SDR_THINNING == (32.0, 0.2)
    assert aces_axes.thinning(hdr) == aces_axes.HDR_THINNING == (64.0, 1.0 / 3.0)
    for name in ("ACES 2.0 - HDR 500 nits (Rec.2020)", "ACES 2.0 - HDR 108 nits (P3 D65)"):
        assert aces_axes.thinning(views.catalogue()[name]) == aces_axes.HDR_LOW_THINNING == (64.0, 0.25)
    assert aces_axes.thinning(views.catalogue()["ACES 2.0 - HDR 2000 nits (P3 D65)"]) == aces_axes.HDR_THINNING
    assert np.isclose(aces_axes.view_axes(SDR)[1].light, 32.0, rtol=0.01)
    assert np.isclose(aces_axes.view_axes(hdr)[1].light, 64.0, rtol=0.01)


def test_the_display_layouts_table_is_exact_on_its_entries():
    """1.0 falls on an entry of the Log operator, the bend on another: the table of two straight
    pieces between them is the axis exactly (up to its written decimals)."""
    log, axis, table = aces_axes.view_axes(SDR)
    entries = np.linspace(0.0, 1.0, table.size)
    assert np.isclose(log.position(entries[log.one]), 1.0, rtol=0, atol=0)
    assert np.isclose(log.position(1.0), 1024.0, rtol=1e-9)
    x = log.position(np.linspace(0.0, 1.0, 100001))
    np.testing.assert_allclose(np.interp(log.coordinate(x), entries, table), axis.coordinate(x), rtol=0, atol=1e-6)


def test_a_source_axis_puts_zero_on_a_node_and_mirrors_below():
    axis = SourceLogAxis.layout(65, -64.0, 1746.0, aces_axes.SDR_THINNING)
    assert 0 < axis.zero <= round(aces_axes.ACES_NEGATIVE_SHARE * 64)
    assert axis.coordinate(0.0) * 64 == axis.zero
    assert axis.coordinate(-64.0) == 0.0 and axis.coordinate(1746.0) == 1.0
    assert np.all(np.diff(axis.coordinate(np.linspace(-70.0, 1800.0, 10001))) >= 0)
    assert SourceLogAxis.layout(65, 0.0, 1024.0, aces_axes.SDR_THINNING).zero == 0


def test_a_linear_source_is_held_from_the_floor_and_ap1_sources_from_zero(default_spec):
    display = default_spec.displays[0]
    low, high = aces_axes.source_range(default_spec, default_spec.space("Linear Rec.709 (sRGB)"), display, SDR)
    assert low == aces_axes.LINEAR_FLOOR and high == aces_axes.linear_high(SDR) == 256.0
    assert aces_axes.source_range(default_spec, default_spec.space("ACEScg"), display, SDR) == (0.0, 256.0)
    assert aces_axes.same_basis(default_spec, default_spec.space("ACEScct"), SDR)
    assert not aces_axes.same_basis(default_spec, default_spec.space("ARRI LogC4"), SDR)


def test_a_linear_sources_table_ends_at_twice_the_grey_that_renders_as_the_clamps():
    """SDR greys render as the clamp's (1024) from 128 on, not at 64; at 1000 cd/m² from 512.
    A table uniform in light then steps by 256 / 65535, not 1024 / 65535."""
    hdr = views.catalogue()["ACES 2.0 - HDR 1000 nits (P3 D65)"]
    for view, reached in ((SDR, 128.0), (hdr, 512.0)):
        b = aces_axes.basis(view)
        greys = np.repeat(np.array([reached / 2, reached, b.upper])[:, None], 3, axis=1)
        light = views.evaluate(view, greys @ np.linalg.inv(b.from_aces).T)[:, 1]
        assert abs(light[1] - light[2]) <= aces_axes.PEAK_REACHED * light[2] < abs(light[0] - light[2])
        assert aces_axes.linear_high(view) == 2 * reached
