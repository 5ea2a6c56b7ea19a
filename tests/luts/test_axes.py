"""Lattice axes: 0 and the display's peak are nodes, and the axis inverts exactly."""

from __future__ import annotations

import numpy as np
import pytest

from generator.luts import lattice
from generator.luts.axes import Axis


@pytest.mark.parametrize("method", ("clip", "scale", "desaturate"))
@pytest.mark.parametrize("size", (9, 17, 33, 65))
def test_display_code_zero_and_one_are_nodes(default_spec, size, method):
    for display in default_spec.displays:
        axis = lattice.display_axis(display, size, method)
        nodes = axis.nodes()
        assert nodes[axis.zero] == 0.0 and nodes[axis.one] == pytest.approx(1.0, abs=1e-12)
        pre = lattice.PreShaper.for_display(display)
        domain, table = lattice.display_table(axis, pre)
        grid = np.linspace(*domain, table.size)
        for value, index in ((0.0, axis.zero), (1.0, axis.one)):
            entry = np.flatnonzero(np.isclose(grid, pre.forward(value), rtol=0, atol=1e-12))
            assert entry.size == 1
            assert table[entry[0]] == pytest.approx(index / (size - 1), abs=1e-6)


def test_axis_inverts(default_spec):
    display = default_spec.displays[0]
    axis = Axis.layout(display, 33, -16.0, 32.0)
    x = np.concatenate([-np.logspace(-5, np.log10(16), 40), np.logspace(-5, np.log10(32), 40)])
    np.testing.assert_allclose(axis.position(axis.index(x)), x, rtol=1e-9, atol=1e-14)
    assert np.all(np.diff(axis.index(np.sort(x))) > 0)
