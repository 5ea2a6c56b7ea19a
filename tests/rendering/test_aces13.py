"""The ACES 1.3 presets as the studio config names them, their round trips, and what the
inverse returns where the forward clips."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.colorimetry.gamuts import gamuts
from generator.rendering import aces13_rrt as rrt
from generator.rendering.aces13 import PRESETS13, Preset13, forward13, inverse13
from generator.rendering.aces13_odt import D60_TO_D65, sdr_odt_inverse
from generator.rendering.aces13_spline import spline_inverse
from generator.rendering.aces13_ssts import aces_max, aces_min, hdr_odt_inverse

STUDIO = "ocio://studio-config-v2.2.0_aces-v1.3_ocio-v2.4"


def test_presets_are_the_studio_configs_aces1_views():
    config = ocio.Config.CreateFromFile(STUDIO)
    views = {}
    for view in config.getViewTransforms():
        transform = view.getTransform(ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
        if isinstance(transform, ocio.BuiltinTransform) and transform.getStyle().startswith("ACES-OUTPUT"):
            views[view.getName()] = transform.getStyle()
    assert views == {name: preset.style for name, preset in PRESETS13.items()}
    assert all(isinstance(p, Preset13) and p.view == name for name, p in PRESETS13.items())
    kinds = {name: (p.kind, p.peak_luminance) for name, p in PRESETS13.items()}
    assert kinds["ACES 1.0 - SDR Video"] == ("sdr", 100.0) and kinds["ACES 1.0 - SDR Cinema"] == ("sdr", 48.0)
    assert kinds["ACES 1.1 - HDR Video (4000 nits & P3 lim)"] == ("hdr", 4000.0)
    with pytest.raises(KeyError, match="known: ACES 1.0 - SDR Video"):
        forward13(np.zeros(3), "ACES 1.0 - SDR Video (P3 lim)")


def test_any_leading_shape_and_non_finite_colours():
    rng = np.random.default_rng(11)
    aces = rng.uniform(0.0, 2.0, (4, 5, 3))
    for view in PRESETS13:
        xyz = forward13(aces, view)
        assert xyz.shape == (4, 5, 3) and xyz.dtype == np.float64
        assert np.array_equal(xyz[2, 3], forward13(aces[2, 3], view))
        assert inverse13(xyz, view).shape == (4, 5, 3)
    bad = np.array([[np.nan, 0.1, 0.2], [np.inf, 1.0, 1.0], [-np.inf, 0.0, 0.0]])
    for view in PRESETS13:
        assert np.array_equal(forward13(bad, view), forward13(np.zeros((3, 3)), view))
        assert np.array_equal(inverse13(bad, view), inverse13(np.zeros((3, 3)), view))


def limiting_rgb_to_xyz(view: str) -> np.ndarray:
    """Limiting-gamut RGB (1 = the display's peak) to the preset's XYZ: the SDR ODTs limit
    D65 XYZ, the HDR ones the ACES-white XYZ before adapting it to D65."""
    preset = PRESETS13[view]
    to_xyz = gamuts()[preset.odt.limiting or "Rec.709"].rgb_to_xyz * preset.peak_luminance / preset.output_scale
    return D60_TO_D65 @ to_xyz if preset.kind == "hdr" else to_xyz


def display_probes(view: str, count: int = 6000) -> np.ndarray:
    """Display XYZ inside the preset's limiting gamut (Rec.709 where none) and inside the range
    every tone scale and white simulation inverts: its RGB from 0.02 to 0.6 of peak."""
    rgb = np.random.default_rng(12).uniform(0.02, 0.6, (count, 3))
    return rgb @ limiting_rgb_to_xyz(view).T


def clamped_by_inverse(xyz: np.ndarray, view: str) -> np.ndarray:
    """Colours the inverse RRT clamps (inv_rrt_sweeteners: negative AP1 once the
    desaturation is undone, or negative ACES), which the forward does not give back."""
    preset = PRESETS13[view]
    if preset.kind == "hdr":
        rgb = hdr_odt_inverse(xyz, preset.odt)
    else:
        rgb = spline_inverse(sdr_odt_inverse(xyz, preset.odt), rrt.RRT_SPLINE)
    ap1 = rgb @ np.linalg.inv(rrt.RRT_SAT_MATRIX).T
    return (ap1.min(axis=-1) < 0.0) | ((ap1 @ rrt.AP1_TO_AP0.T).min(axis=-1) < 0.0)


@pytest.mark.parametrize("view", list(PRESETS13))
def test_display_colours_come_back_where_the_ctl_inverts(view):
    """Display colours to ACES and back: exact (float64) but where the CTL's inverse is
    approximate (the red modifier, within ±67.5° of red; the glow of colours whose largest
    channel is under 1e-2) or clamps; the approximations come back within
    ACES13_RED_INVERSE_RELATIVE."""
    xyz = display_probes(view)
    aces = inverse13(xyz, view)
    again = forward13(aces, view)
    error = np.abs(again - xyz).max(axis=-1) / np.abs(xyz).max(axis=-1)
    weight = rrt.red_weight(aces)
    kept = ~clamped_by_inverse(xyz, view)
    exact = kept & (weight == 0.0) & (aces.max(axis=-1) >= 1e-2)
    assert exact.mean() > 0.3
    assert error[exact].max() <= tolerances.ACES13_ROUND_TRIP_RELATIVE
    assert error[kept].max() <= tolerances.ACES13_RED_INVERSE_RELATIVE


@pytest.mark.parametrize("view", list(PRESETS13))
def test_aces_comes_back_where_nothing_clips(view):
    """ACES inside AP1, 0.01 to 8 (within every tone scale's ends), away from reds, and
    inside the limiting gamut: forward then inverse gives it back."""
    rng = np.random.default_rng(14)
    aces = rrt.apply3x3(rrt.AP1_TO_AP0, 10.0 ** rng.uniform(-2.0, 0.9, (20000, 3)))
    weight = rrt.red_weight(aces)
    aces = aces[(weight == 0.0) & (aces.min(axis=-1) >= 0.0)]
    xyz = forward13(aces, view)
    if PRESETS13[view].odt.limiting is not None:
        rgb = xyz @ np.linalg.inv(limiting_rgb_to_xyz(view)).T
        keep = (rgb.min(axis=-1) > 1e-6) & (rgb.max(axis=-1) < 1.0 - 1e-6)
        aces, xyz = aces[keep], xyz[keep]
    assert len(aces) > 2000
    error = np.abs(inverse13(xyz, view) - aces).max(axis=-1) / aces.max(axis=-1)
    assert error.max() <= tolerances.ACES13_ROUND_TRIP_RELATIVE


@pytest.mark.parametrize("view", [v for v, p in PRESETS13.items() if p.kind == "hdr"])
def test_hdr_inverse_clamps_to_the_tone_scales_ends(view):
    """Black gives the SSTS's shifted minimum exposure, the peak and beyond its maximum
    (the HDR output transforms' inverse does not extend the tone scale)."""
    preset = PRESETS13[view]
    shift = preset.odt.spline.mid_point[0] / 0.18
    white = gamuts()["AP1"].rgb_to_xyz @ np.ones(3)
    peak = (gamuts()["P3-D65"].rgb_to_xyz @ np.ones(3)) * preset.peak_luminance / 100.0
    ends = inverse13(np.stack([np.zeros(3), peak * 2.0, white * 1e3]), view)
    assert ends[0] == pytest.approx([aces_min(0.0001) * shift] * 3, rel=1e-9)
    assert ends[1:] == pytest.approx(np.full((2, 3), aces_max(preset.peak_luminance) * shift), rel=1e-9)
