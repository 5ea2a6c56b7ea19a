"""Lattice axes: 0 and the display's peak are nodes, and the axes invert exactly."""

from __future__ import annotations

import numpy as np
import pytest

from generator.luts import axes, lattice
from generator.luts.axes import Axis, LogAxis


@pytest.mark.parametrize("size", (9, 17, 33, 65))
def test_display_code_zero_and_one_are_nodes(default_spec, size):
    for display in default_spec.displays:
        axis = lattice.display_axis(display, size, "desaturate")
        nodes = axis.nodes()
        assert nodes[axis.zero] == 0.0 and nodes[axis.one] == pytest.approx(1.0, abs=1e-12)
        pre = lattice.PreShaper.for_display(display)
        domain, table = lattice.display_table(axis, pre)
        grid = np.linspace(*domain, table.size)
        for value, index in ((0.0, axis.zero), (1.0, axis.one)):
            entry = np.flatnonzero(np.isclose(grid, pre.forward(value), rtol=0, atol=1e-12))
            assert entry.size == 1
            assert table[entry[0]] == pytest.approx(index / (size - 1), abs=1e-6)


@pytest.mark.parametrize("method", axes.LOG_METHODS)
@pytest.mark.parametrize("size", (9, 17, 33, 65))
def test_log_axis_puts_zero_one_and_the_range_on_nodes(default_spec, size, method):
    for display in default_spec.displays:
        axis = lattice.display_axis(display, size, method)
        assert isinstance(axis, LogAxis)
        nodes = axis.nodes()
        assert nodes[0] == 0.0 and nodes[axis.one] == 1.0
        assert axis.high == pytest.approx(lattice.log_axis_high(display), rel=1e-9)
        wanted = axes.HLG_TOE_BITS if display.eotf_name == "HLG" else axes.LOG_TOE_BITS
        assert np.log2(1.0 / axis.toe + 1.0) >= wanted - 1e-9
        np.testing.assert_allclose(axis.coordinate(nodes), np.arange(size) / (size - 1), rtol=0, atol=1e-12)
        assert axis.coordinate(-1.0) == 0.0 and axis.coordinate(1e9) == 1.0


def test_axis_inverts(default_spec):
    display = default_spec.displays[0]
    axis = Axis.layout(display, 33, -16.0, 32.0)
    x = np.concatenate([-np.logspace(-5, np.log10(16), 40), np.logspace(-5, np.log10(32), 40)])
    np.testing.assert_allclose(axis.position(axis.index(x)), x, rtol=1e-9, atol=1e-14)
    assert np.all(np.diff(axis.index(np.sort(x))) > 0)


def test_a_dim_displays_log_axis_still_reaches_half_float_light(tmp_path):
    """An absolute display of 1 cd/m² (a hundredth of display-referred 1.0): its clip and scale
    lattice reaches 65504 display-referred units, not 65504 times its own peak (655)."""
    from generator.spec import load

    spec = load.parse(
        "[[display]]\nname = 'Dim'\ngamut = 'Rec.709'\neotf = 'gamma 2.2'\npeak_luminance = 1\n"
        "absolute_luminance = true",
        "show.toml",
        tmp_path,
    )
    axis = lattice.display_axis(spec.displays[0], 17, "scale")
    assert axis.high * spec.displays[0].clip_high == pytest.approx(lattice.LOG_DISPLAY_HIGH, rel=1e-9)
