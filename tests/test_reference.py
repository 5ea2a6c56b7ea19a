"""The reference evaluation: conversions to and from the scene reference against OpenColorIO's
builtins and their own inverses, the displays' encodings against BT.2100 and BT.2408, and the
gamut-mapped views (clip is the Colorimetric view, in-gamut colours pass the hard mappings
unchanged, HDR maps into [0, peak])."""

from __future__ import annotations

import dataclasses

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import reference
from generator.colorimetry.matrices import rgb_to_rgb
from generator.spec import load

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


def builtin_matrix(style: str) -> np.ndarray:
    """The 3x3 matrix of an OpenColorIO builtin that is one, read back from the unit vectors."""
    processor = ocio.Config.CreateRaw().getProcessor(ocio.BuiltinTransform(style)).getDefaultCPUProcessor()
    pixels = np.ascontiguousarray(np.eye(3), dtype=np.float32)
    processor.applyRGB(pixels)
    return pixels.astype(np.float64).T


def test_every_space_goes_to_the_reference_and_back(default_spec):
    """Codes a film scan or a camera writes (0.1 to 0.4 keeps ADX16 within the densities of film)."""
    codes = np.random.default_rng(4).uniform(0.1, 0.4, (500, 3))
    for space in default_spec.colour_spaces:
        ref = reference.to_reference(default_spec, space, codes)
        back = reference.from_reference(default_spec, space, ref)
        np.testing.assert_allclose(back, codes, rtol=0, atol=1e-12, err_msg=space.name)


def test_a_data_space_passes_values_through_as_a_copy(default_spec):
    raw = default_spec.space("Raw")
    values = np.array([[-1.0, 0.5, 7.0]])
    for convert in (reference.to_reference, reference.from_reference):
        out = convert(default_spec, raw, values)
        assert np.array_equal(out, values) and out is not values
    with pytest.raises(ValueError, match="data space"):
        reference.space_matrix(default_spec, raw)


def test_matrices_are_ocios_bradford_builtins(default_spec):
    """ACEScg to ACES2065-1 and ACES2065-1 to CIE XYZ-D65 (Bradford), as OCIO's builtins hold them
    (float32)."""
    acescg = reference.space_matrix(default_spec, default_spec.space("ACEScg"))
    np.testing.assert_allclose(acescg, builtin_matrix("ACEScg_to_ACES2065-1"), rtol=0, atol=2e-7)
    to_xyz = reference.scene_to_display_reference(default_spec)
    np.testing.assert_allclose(to_xyz, builtin_matrix("UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD"), rtol=0, atol=2e-7)
    np.testing.assert_allclose(reference.to_aces_matrix(default_spec), np.eye(3), rtol=0, atol=1e-15)
    from_acescg = dataclasses.replace(default_spec, scene_reference="ACEScg")
    np.testing.assert_allclose(
        reference.to_aces_matrix(from_acescg), builtin_matrix("ACEScg_to_ACES2065-1"), rtol=0, atol=2e-7
    )


def test_scene_white_is_each_displays_white(default_spec):
    """Each display adapts to its own white (DCI-P3's too): the reference white shows as R = G = B,
    code 1 on every SDR display, 100 cd/m² on the HDR ones (51% PQ, ITU-R BT.2408)."""
    for display in default_spec.displays:
        code = reference.colorimetric_view(default_spec, display, np.ones(3))
        light = reference.display_decode(display, code)
        np.testing.assert_allclose(light, 1.0, rtol=1e-6, err_msg=display.name)
        if not display.is_hdr:
            np.testing.assert_allclose(code, 1.0, rtol=0, atol=1e-12, err_msg=display.name)
        elif display.eotf_name == "ST 2084":
            assert round(float(code[0]) * 100.0) == 51


def test_every_display_decodes_what_it_encodes(default_spec):
    """Light within the display's range, but for HLG's saturated colours near the peak, whose
    signal would pass 1 (HLG's OOTF lifts them above their luminance's grey)."""
    light = np.random.default_rng(5).uniform(0.0, 1.0, (300, 3))
    for display in default_spec.displays:
        shown = light * display.clip_high
        code = reference.display_encode(display, shown)
        signal = np.all(code < 1.0, axis=-1) if display.eotf_name == "HLG" else np.full(len(code), True)
        assert signal.mean() > 0.5, display.name
        back = reference.display_decode(display, code[signal])
        np.testing.assert_allclose(back, shown[signal], rtol=1e-9, atol=1e-12, err_msg=display.name)


def test_the_hlg_display_follows_bt2100_and_bt2408(default_spec):
    """ITU-R BT.2100's HLG EOTF at the display's 1000 cd/m² peak: signal 1 is the peak (to the
    precision of the standard's constants, 3e-8), BT.2408's HDR reference white, 203 cd/m², is 75%;
    a signal ends at 1."""
    hlg = next(d for d in default_spec.displays if d.eotf_name == "HLG")
    assert hlg.peak == 1000.0
    np.testing.assert_allclose(reference.display_decode(hlg, np.ones(3)), 10.0, rtol=1e-7)
    assert round(float(reference.display_encode(hlg, np.full(3, 2.03))[0]) * 100.0) == 75
    assert np.array_equal(reference.display_encode(hlg, np.full(3, 20.0)), np.ones(3))
    assert np.array_equal(reference.display_encode(hlg, np.zeros(3)), np.zeros(3))


def test_a_baked_views_ends_compose_to_the_display_reference(default_spec):
    """A view's LUT takes normalised display light (1 = peak) and hands over to CIE XYZ-D65: the
    two matrices compose to the scene reference's own conversion to XYZ-D65."""
    to_xyz = reference.scene_to_display_reference(default_spec)
    for display in default_spec.displays:
        composed = reference.normalised_display_to_xyz(default_spec, display) @ reference.normalised_display_matrix(
            default_spec, display
        )
        np.testing.assert_allclose(composed, to_xyz, rtol=0, atol=1e-14, err_msg=display.name)


def test_a_camera_space_is_adapted_as_its_publisher_whatever_the_spec():
    """A spec adapting with CAT16 still converts ARRI LogC4 as ARRI publishes (CAT02)."""
    spec = dataclasses.replace(load.load(), chromatic_adaptation="CAT16")
    space = spec.space("ARRI LogC4")
    assert np.array_equal(reference.space_matrix(spec, space), rgb_to_rgb(space.gamut, spec.reference.gamut, "CAT02"))
    srgb = spec.space("Linear Rec.709 (sRGB)")
    assert np.array_equal(reference.space_matrix(spec, srgb), rgb_to_rgb(srgb.gamut, spec.reference.gamut, "CAT16"))
