"""The desaturate view as a lattice in OCIO's HSV (generator.luts.hsv)."""

from __future__ import annotations

import numpy as np
import pytest

from generator import reference, tolerances
from generator.gamut.simple import desaturate
from generator.luts import hsv, hsv_axes
from generator.luts.view import bake_view_lut
from generator.ocio.emit import lut_steps
from generator.ocio.view_luts import view_figures, view_transform
from generator.verify.allowance import hsv_rounding_shift
from tests.luts import hsv_cases

SDR = ("sRGB - Display", "Gamma 2.2 Rec.709 - Display", "Gamma 2.6 DCI-P3 - Display")


def _display(spec, name):
    return next(d for d in spec.displays if d.name == name)


@pytest.mark.parametrize("name", SDR)
def test_the_lattice_is_exact(default_spec, name):
    """Trilinear interpolation of the lattice, with its 1D tables' exact functions and the
    file's final clamp of the value, is the desaturate method to float64 rounding, for
    colours of every kind, up to 1e-3 from the cone, as far as the lattice reaches
    (saturation within 1 / SATURATION_REACH of 2: 1.2e-7 from the cone, as near as OCIO's
    float32 saturation short of 2 gets). Near the cone the colour is ``V u`` (``u = 1 / (2 - S)``),
    and float64's rounding of ``2 - S`` grows with ``u``: each colour is held to that."""
    display = _display(default_spec, name)
    gamut = reference.display_gamut(display)
    lattice = hsv.hsv_lattice(display)
    colours = hsv_cases.colours()
    values = hsv_axes.ocio_rgb_to_hsv(colours)
    reached = 2.0 - values[:, 1] >= 1.0 / hsv_axes.SATURATION_REACH
    assert (~reached).sum() < 0.01 * len(colours)
    colours, values = colours[reached], values[reached]
    result = hsv_axes.ocio_hsv_to_rgb(hsv.apply(lattice, values))
    scale = np.maximum(1.0, np.abs(colours).max(axis=-1, keepdims=True))
    u = 1.0 / np.minimum(2.0 - values[:, 1:2], 1.0)
    assert np.abs(result - desaturate(colours, gamut)).max() < 1e-9 * scale.max()
    assert np.all(np.abs(result - desaturate(colours, gamut)) <= 1e-10 * scale * u)


@pytest.mark.parametrize("name", SDR)
def test_view_through_ocio_meets_the_exact_target_on_every_probe_set(default_spec, name):
    view = bake_view_lut(default_spec, _display(default_spec, name), "desaturate")
    figures = view_figures(view)
    assert view.hsv and view.light and figures["in_gamut"].unit == "10-bit codes"
    assert figures["in_gamut"].maximum <= tolerances.LUT_CLF_IN_GAMUT_CODES
    assert max(f.maximum for f in figures.values()) <= tolerances.LUT_CLF_EXACT_CODES


def _view_apply(spec, display, tmp_path, matrix=None):
    import PyOpenColorIO as ocio

    from generator.luts import probes

    view = bake_view_lut(spec, display, "desaturate")
    (tmp_path / view.filename).write_bytes(view.data)
    (tmp_path / hsv.SHARED_FILE).write_bytes(hsv.shared_clf())
    transform = view_transform(
        view.matrix if matrix is None else matrix, str(tmp_path / view.filename), hsv_folder=str(tmp_path)
    )
    ocio.ClearAllCaches()
    return probes.ocio_apply(transform)


def test_a_zero_channel_stays_exactly_zero(default_spec, tmp_path):
    """Colours on the cube's faces (a zero channel, given as display-linear RGB) land on the
    lattice's S = 1 node plane in float32: the channel comes back 0, not a rounding above
    it, which a 2.2 power would show as half a code."""
    display = _display(default_spec, "Gamma 2.2 Rec.709 - Display")
    rng = np.random.default_rng(3)
    linear = rng.random((500, 3))
    linear[np.arange(500), rng.integers(0, 3, 500)] = 0.0
    out = _view_apply(default_spec, display, tmp_path, np.eye(3))(linear)
    assert np.array_equal(out == 0.0, linear == 0.0)
    assert np.abs(out - linear).max() < 1e-5


@pytest.mark.parametrize("name", SDR)
def test_colours_a_rounding_from_black_stay_black(default_spec, tmp_path, name):
    """Render noise around black, channels of either sign down to 1e-12 of the peak: OCIO
    interpolates a V between the smallest negative half float and 0 from the shared table's
    entries at both, so -0's entry continues the negative side (at 0, such a grey of -1e-8
    read coordinate 0.33 and came out white). The view is the method itself to the exact
    views' tolerance in code values, never brighter, darker at most by the float32
    resolution of OCIO HSV through the view (near its cone, where V is the small difference
    of two equal magnitudes, a pure power shows it as a tenth of a code)."""
    display = _display(default_spec, name)
    rng = np.random.default_rng(11)
    linear = rng.choice([-1.0, 1.0], (4000, 3)) * rng.random((4000, 3)) * 10.0 ** rng.uniform(-12, -6, (4000, 1))
    linear = np.concatenate([linear, [[-1e-8] * 3, [0.0, 0.0, -2e-8], [-0.0] * 3, [3e-8, -3e-8, 0.0]]])
    linear = linear.astype(np.float32).astype(np.float64)
    out = _view_apply(default_spec, display, tmp_path, np.eye(3))(linear)
    expected = desaturate(linear, reference.display_gamut(display))
    peak, tolerance = display.clip_high, tolerances.LUT_CLF_EXACT_CODES / 1023.0
    low = np.maximum(expected - hsv_rounding_shift(display, linear * peak) / peak, 0.0)
    codes, high, least = (reference.display_encode(display, light) for light in (out, expected, low))
    assert np.all(codes <= high + tolerance) and np.all(codes >= least - tolerance)


def test_bright_colours_of_little_luminance_are_mapped_beyond_a_thousand_times_the_peak(default_spec, tmp_path):
    """Far outside the gamut a colour's desaturated value can be a thousandth of its V: at V
    from 1e3 to 6e4 times the peak the lattice still holds the method (it had clamped V at
    1024, leaving such a colour at 2000 times the peak 216 codes dim), within the float32
    resolution of its HSV through the view, which grows with V there (a code or two)."""
    display = _display(default_spec, "Gamma 2.2 Rec.709 - Display")
    direction = np.array([[-1.2152757, -1.91399594, 22.55316027], [-0.9, 0.05, -0.02], [0.3, -0.2, 0.5]])
    linear = np.concatenate([direction * k for k in (50.0, 90.0, 400.0, 2500.0)]).astype(np.float32).astype(np.float64)
    assert hsv_axes.ocio_rgb_to_hsv(linear)[:, 2].max() > 2000.0
    out = _view_apply(default_spec, display, tmp_path, np.eye(3))(linear)
    expected = desaturate(linear, reference.display_gamut(display))
    shift = hsv_rounding_shift(display, linear * display.clip_high) / display.clip_high
    codes, low, high = (
        reference.display_encode(display, np.clip(light, 0.0, 1.0))
        for light in (out, expected - shift, expected + shift)
    )
    tolerance = tolerances.LUT_CLF_SCALE_CODES / 1023.0
    assert np.all(codes >= low - tolerance) and np.all(codes <= high + tolerance)


def _cone_colours(rng, t, count):
    """Display-linear colours ``t`` from OCIO HSV's cone (largest channel M, smallest
    -M (1 - t), so ``2 - S = t``), of every hue and size, either sign, in float32."""
    size = 10.0 ** rng.uniform(-2.0, 1.0, count)
    colours = np.stack([size, -size * (1.0 - t), rng.uniform(-1.0, 1.0, count) * size], axis=-1)
    colours = np.take_along_axis(colours, np.argsort(rng.random((count, 3)), axis=-1), axis=-1)
    colours[count // 2 :] *= -1.0
    return colours.astype(np.float32).astype(np.float64)


@pytest.mark.parametrize("name", SDR)
def test_colours_a_hair_from_the_cone_keep_their_size(default_spec, tmp_path, name):
    """1e-5 and 1e-6 from OCIO HSV's cone (``t = 2 - S``) a colour's size is ``V / t``, and
    OCIO's float32 S leaves ``t`` uncertain by FLOAT32_HSV_CONE_SATURATION (2% and 18% of the
    size); the view lands between the method at ``t`` moved that far, and by its lattice
    coordinate's resolution, either way (within the exact views' tolerance in code values).
    With ``u = 1 / t`` clamped at 2**14 (t 6e-5) such colours came out up to 600 codes dark."""
    display = _display(default_spec, name)
    gamut, peak = reference.display_gamut(display), display.clip_high
    rng = np.random.default_rng(23)
    linear = np.concatenate([_cone_colours(rng, t, 300) for t in (1e-5, 1e-6)])
    values = hsv_axes.ocio_rgb_to_hsv(linear)
    assert np.all(np.abs(2.0 - values[:, 1] - np.repeat([1e-5, 1e-6], 300)) < 2e-7)
    out = _view_apply(default_spec, display, tmp_path, np.eye(3))(linear) * peak
    shift = tolerances.FLOAT32_HSV_CONE_SATURATION + hsv_axes.saturation_coordinate_resolution(values)
    bounds = []
    for sign in (1.0, -1.0):
        moved = values.copy()
        moved[:, 1] += sign * shift
        bounds.append(desaturate(hsv_axes.ocio_hsv_to_rgb(moved, max_saturation=2.0), gamut) * peak)
    codes, low, high = (
        reference.display_encode(display, light) for light in (out, np.minimum(*bounds), np.maximum(*bounds))
    )
    tolerance = tolerances.LUT_CLF_EXACT_CODES / 1023.0
    assert np.all(codes >= low - tolerance) and np.all(codes <= high + tolerance)
    assert codes.max() > 0.5  # not all black


def test_near_the_cone_the_view_keeps_ocio_hsv_precision(default_spec, tmp_path):
    """An ACEScct green ramp near black crosses OCIO HSV's cone: V is the small difference
    of two equal magnitudes, and a small negative V's coordinate sits near 1 in float32. The
    view returns what the exact method gives for OCIO's own HSV of the colour (its matrix
    and RGB_TO_HSV in float32) within the float32 resolution of those HSV values through
    the view, which verify allows, and within 1e-4 of the ramp's brightest output (the old
    layout, one cell from V = -1/16 to -0, was 6e-3 off)."""
    import PyOpenColorIO as ocio

    display = _display(default_spec, "sRGB - Display")
    cct = np.array([[0.0, g, 0.0] for g in np.linspace(0.14, 0.24, 401)])
    ref = reference.to_reference(default_spec, default_spec.space("ACEScct"), cct)
    matrix = reference.normalised_display_matrix(default_spec, display)
    steps = lut_steps(matrix, "unused.clf", "")[:2]
    processor = ocio.Config.CreateRaw().getProcessor(ocio.GroupTransform(steps)).getDefaultCPUProcessor()
    values = np.ascontiguousarray(ref, dtype=np.float32)
    processor.applyRGB(values)
    values = values.astype(np.float64)
    assert (values[:, 2] < 0).any() and (values[:, 1] > 1.999).any()  # the ramp crosses the cone
    expected = desaturate(hsv_axes.ocio_hsv_to_rgb(values, max_saturation=2.0), reference.display_gamut(display))
    out = _view_apply(default_spec, display, tmp_path)(ref)
    linear = hsv_axes.ocio_hsv_to_rgb(values, max_saturation=2.0) * display.clip_high
    assert np.all(np.abs(out - expected) <= hsv_rounding_shift(display, linear) / display.clip_high)
    assert np.abs(out - expected).max() <= 1e-4 * expected.max()
