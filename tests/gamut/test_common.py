"""Invariants every method of the registry keeps: range, in-gamut identity, non-finite policy."""

from __future__ import annotations

import inspect

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from generator.gamut import LARGEST, METHODS
from tests.gamut import cases

HARD = ("clip", "desaturate", "scale")
HALF_MAX = 65504.0  # the largest finite binary16 value, the largest an OpenEXR half image holds

finite_rgb = arrays(np.float64, st.tuples(st.integers(1, 8), st.just(3)), elements=st.floats(-HALF_MAX, HALF_MAX))
special = st.sampled_from([np.nan, np.inf, -np.inf])
any_rgb = arrays(
    np.float64, st.tuples(st.integers(1, 8), st.just(3)), elements=st.one_of(st.floats(-HALF_MAX, HALF_MAX), special)
)


def test_registry_names_and_uniform_signature():
    assert set(METHODS) == {"clip", "desaturate", "scale", "rgc", "perceptual"}
    for fn in METHODS.values():
        assert list(inspect.signature(fn).parameters) == ["rgb", "display", "params"]
    with pytest.raises(TypeError):
        METHODS["other"] = METHODS["clip"]  # read-only


@pytest.mark.parametrize("name", sorted(METHODS))
def test_shapes_are_kept(name):
    d = cases.display("ITU-R BT.709")
    rgb = np.random.default_rng(2).uniform(-0.5, 1.5, (2, 4, 3))
    assert METHODS[name](rgb, d).shape == (2, 4, 3)
    assert METHODS[name](rgb[0, 0], d).shape == (3,)
    with pytest.raises(ValueError):
        METHODS[name](np.zeros((4, 2)), d)


@pytest.mark.parametrize("name", sorted(METHODS))
@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
@settings(deadline=None, max_examples=60)
@given(rgb=finite_rgb)
def test_finite_input_maps_into_the_unit_cube(name, display_name, rgb):
    out = METHODS[name](rgb, cases.display(display_name))
    assert np.all((out >= 0.0) & (out <= 1.0))


@pytest.mark.parametrize("name", sorted(METHODS))
@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_source_colours_map_into_the_unit_cube(name, display_name):
    for source in cases.SOURCE_NAMES:
        rgb = cases.source_colours(source, display_name) * np.array([[1.0], [40.0]]).repeat(2000, 0)
        out = METHODS[name](rgb, cases.display(display_name))
        assert np.all((out >= 0.0) & (out <= 1.0))


@pytest.mark.parametrize("name", HARD)
@pytest.mark.parametrize("display_name", cases.DISPLAY_NAMES)
def test_hard_methods_leave_in_gamut_colours_bit_identical(name, display_name):
    rgb = cases.display_colours()
    assert np.array_equal(METHODS[name](rgb, cases.display(display_name)), rgb)


@pytest.mark.parametrize("name", sorted(METHODS))
@settings(deadline=None, max_examples=60)
@given(rgb=any_rgb)
def test_non_finite_input_follows_the_policy(name, rgb):
    d = cases.display("P3-D65")
    out = METHODS[name](rgb, d)
    # NaN -> 0, -Inf -> 0, +Inf -> the largest value: the same output as the replaced input.
    replaced = np.where(np.isnan(rgb) | (rgb == -np.inf), 0.0, np.where(rgb == np.inf, LARGEST, rgb))
    assert np.array_equal(out, METHODS[name](replaced, d))
    assert np.all(np.isfinite(out)) and np.all((out >= 0.0) & (out <= 1.0))
    assert np.all(out[rgb == np.inf] == 1.0)  # a +Inf channel maps to 1


@pytest.mark.parametrize("name", sorted(METHODS))
def test_all_nan_is_black(name):
    assert np.array_equal(METHODS[name](np.full(3, np.nan), cases.display("ITU-R BT.709")), np.zeros(3))
