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
