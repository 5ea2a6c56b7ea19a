"""Source-layout axes: nodes on the display's code values, 0 and the peak on nodes, negatives spaced where needed."""

from __future__ import annotations

import numpy as np
import pytest

from generator.luts import source_axes
from generator.luts.axes import grey_code
from generator.luts.source_axes import SourceAxis


@pytest.mark.parametrize("source", ("ACEScg", "ACEScct", "ARRI LogC4", "sRGB Encoded Rec.709 (sRGB)"))
def test_source_axis_is_linear_in_code_values_between_nodes(default_spec, source):
    for display in default_spec.displays:
        axis = source_axes.source_axis(default_spec, default_spec.space(source), display, 33)
        nodes = axis.values
        assert np.all(np.diff(nodes) > 0) and nodes[axis.zero] == 0.0
        assert nodes[axis.one] == pytest.approx(min(1.0, nodes[-1]), rel=1e-12)
        np.testing.assert_allclose(axis.coordinate(nodes), np.arange(nodes.size) / (nodes.size - 1), atol=1e-12)
        inside = nodes[axis.zero : axis.one + 1]
        middle = grey_code(display, 0.5 * (inside[:-1] + inside[1:]))
        code = grey_code(display, inside)
        expected = (np.arange(axis.zero, axis.one) + (middle - code[:-1]) / (code[1:] - code[:-1])) / (nodes.size - 1)
        np.testing.assert_allclose(axis.coordinate(0.5 * (inside[:-1] + inside[1:])), expected, atol=1e-12)


def test_source_axis_refuses_too_few_nodes(default_spec):
    with pytest.raises(ValueError):
        SourceAxis.layout(default_spec.displays[0], 3, -1.0, 16.0)


def test_source_axis_spaces_negatives_when_the_display_reaches_outside_the_source(default_spec):
    """Rec.709 inside P3: P3's in-gamut colours have Rec.709 values down to -0.22."""
    source = default_spec.space("Linear Rec.709 (sRGB)")
    wide, narrow = (
        next(d for d in default_spec.displays if d.name == name)
        for name in ("Gamma 2.6 P3-D65 - Display", "sRGB - Display")
    )
    reach = source_axes.display_reach(default_spec, source, wide)
    assert 0.2 < reach < 0.25 and source_axes.display_reach(default_spec, source, narrow) < 1e-12
    axis = source_axes.source_axis(default_spec, source, wide, 33)
    negative = axis.values[: axis.zero]
    assert negative.size == 1 + round(32 * source_axes.SOURCE_NEGATIVE_SHARE)
    assert negative[1] == pytest.approx(-reach, rel=1e-2) and np.all(np.diff(negative[1:]) > 0)
    assert source_axes.source_axis(default_spec, source, narrow, 33).zero == 1
