"""Gamut-mapped views of the reference evaluation: clip is the Colorimetric view,
in-gamut colours pass the hard mappings unchanged, HDR maps into [0, peak]."""

from __future__ import annotations

import numpy as np
import pytest

from generator import reference

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


def test_a_perceptual_bake_lands_its_source_gamut_on_the_displays(default_spec):
    """From a known source the compression spans the source's gamut: a ray of ACEScg from grey
    to its green primary rises in chroma all the way and reaches the display's boundary only at
    its end, the source's edge (a fixed limit of 1.25 times the display's chroma had put its last
    27% onto the boundary); a source inside the display (Linear Rec.709 into Display P3) is left
    alone."""
    from generator.gamut.perceptual import display_to_oklab

    display = next(d for d in default_spec.displays if d.name == "sRGB - Display")
    source = default_spec.space("ACEScg")
    params = reference.method_params(default_spec, "perceptual", None, source, display)
    assert params.source_to_display is not None
    t = np.linspace(0.0, 1.0, 201)[:, None]
    ray = 0.18 * ((1.0 - t) * np.ones(3) + t * np.array([0.0, 1.0, 0.0]))  # ACEScg grey to green
    linear = reference.apply_matrix(reference.source_gamut_matrix(default_spec, source, display), ray)
    mapped = reference.gamut_map(display, "perceptual", linear, params)
    lab = display_to_oklab(mapped, reference.display_gamut(display))
    chroma = np.hypot(lab[:, 1], lab[:, 2])
    assert np.all(np.diff(chroma) > 0.0)
    edge = np.minimum(mapped.min(axis=-1), 1.0 - mapped.max(axis=-1))
    assert edge[-1] <= 1e-12 and np.all(edge[:190] > 1e-9)  # the source's edge alone on the display's
    inner = next(d for d in default_spec.displays if d.name == "Display P3 - Display")
    rec709 = default_spec.space("Linear Rec.709 (sRGB)")
    cube = np.random.default_rng(2).random((2000, 3))
    linear = reference.apply_matrix(reference.source_gamut_matrix(default_spec, rec709, inner), cube)
    kept = reference.gamut_map(
        inner, "perceptual", linear, reference.method_params(default_spec, "perceptual", None, rec709, inner)
    )
    np.testing.assert_allclose(kept, linear, rtol=0, atol=1e-12)
