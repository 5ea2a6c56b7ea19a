"""Gamut-mapped views of the reference evaluation: clip is the Colorimetric view,
in-gamut colours pass the hard mappings unchanged, HDR maps into [0, peak]."""

from __future__ import annotations

import numpy as np
import pytest

from generator.colorimetry import reference

METHODS = ("clip", "desaturate", "scale", "rgc", "perceptual")


@pytest.fixture(scope="module")
def colours():
    return np.random.default_rng(7).normal(0.3, 2.0, (2000, 3))


def test_clip_is_the_colorimetric_view(default_spec, colours):
    for display in default_spec.displays:
        expected = reference.colorimetric_view(default_spec, display, colours)
        actual = reference.mapped_view(default_spec, display, "clip", colours)
        np.testing.assert_allclose(actual, expected, rtol=0, atol=1e-12)


@pytest.mark.parametrize("method", ("clip", "desaturate", "scale"))
def test_in_gamut_colours_are_unchanged(default_spec, method):
    for display in default_spec.displays:
        linear = np.random.default_rng(3).random((500, 3)) * display.clip_high
        ref = reference.apply_matrix(np.linalg.inv(reference.scene_to_display_matrix(default_spec, display)), linear)
        expected = reference.display_encode(display, linear)
        np.testing.assert_allclose(reference.mapped_view(default_spec, display, method, ref), expected, atol=1e-9)


@pytest.mark.parametrize("method", METHODS)
def test_every_method_stays_within_the_display_range(default_spec, colours, method):
    for display in default_spec.displays:
        with np.errstate(all="ignore"):
            code = reference.mapped_view(default_spec, display, method, colours[:300] * display.clip_high)
        top = reference.display_encode(display, np.full(3, display.clip_high))[0]
        assert np.all(np.isfinite(code)) and np.min(code) >= -1e-12
        if display.eotf_name != "HLG":  # HLG's inverse OOTF lifts saturated colours above the grey's code
            assert np.max(code) <= top + 1e-9
