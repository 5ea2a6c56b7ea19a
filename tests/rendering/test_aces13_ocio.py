"""The ACES 1.3 output transforms against OpenColorIO 2.6's builtins: every ACES 1.x
output builtin, forward and inverse, judged where a display shows the colour (ten-bit
codes of each display the ACES 1.3 studio config offers the view on, ΔE ITP for HDR)."""

from __future__ import annotations

from functools import cache

import colour
import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.colorimetry.gamuts import gamuts
from generator.colorimetry.matrices import apply_matrix, rgb_to_rgb
from generator.rendering import aces13_rrt as rrt
from generator.rendering.aces13 import PRESETS13, forward13, inverse13
from generator.rendering.aces13_odt import ODT_48NITS_SPLINE
from generator.rendering.aces13_spline import spline_forward
from tests.rendering.aces2_cases import builtin, ocio_apply

STUDIO = "ocio://studio-config-v2.2.0_aces-v1.3_ocio-v2.4"
CAMERAS = ("ARRI Wide Gamut 3", "S-Gamut3")
EXPOSURES = (0.01, 0.05, 0.18, 0.5, 1.0, 2.0, 8.0)


def cube_edges(samples: int = 33) -> np.ndarray:
    """The twelve edges of the unit RGB cube: a gamut's most saturated colours."""
    t = np.linspace(0.0, 1.0, samples)
    edges = []
    for axis in range(3):
        others = [i for i in range(3) if i != axis]
        for a in (0.0, 1.0):
            for b in (0.0, 1.0):
                edge = np.empty((samples, 3))
                edge[:, axis], edge[:, others[0]], edge[:, others[1]] = t, a, b
                edges.append(edge)
    return np.concatenate(edges)


@cache
def probe_sets() -> dict[str, np.ndarray]:
    """ACES2065-1 probes: greys to half float's largest, random AP0, camera gamuts' edges
    at several exposures, bright and dark random colours."""
    rng = np.random.default_rng(13)
    aces = gamuts()["AP0"]
    cameras = [
        apply_matrix(rgb_to_rgb(gamuts()[name], aces, gamuts()[name].adaptation), cube_edges()) * k
        for name in CAMERAS
        for k in EXPOSURES
    ]
    return {
        "greys": np.repeat(np.geomspace(1e-4, 65504.0, 600)[:, None], 3, axis=1),
        "random": rng.uniform(0.0, 1.0, (20000, 3)),
        "cameras": np.concatenate(cameras),
        "bright": rng.uniform(1.0, 64.0, (5000, 3)),
        "dark": 10.0 ** rng.uniform(-4.0, -1.0, (5000, 3)),
    }


@cache
def displays_of(view: str) -> tuple[str, ...]:
    """The studio config's displays that offer ``view``."""
    config = ocio.Config.CreateFromFile(STUDIO)
    return tuple(
        d for d in config.getDisplays() for v in config.getViews(d) if config.getDisplayViewTransformName(d, v) == view
    )


@cache
def display_encoding(display: str):
    config = ocio.Config.CreateFromFile(STUDIO)
    return config.getColorSpace(display).getTransform(ocio.COLORSPACE_DIR_FROM_REFERENCE)


def hdr_ictcp(display: str, xyz: np.ndarray) -> np.ndarray:
    """ICtCp of the light an HDR display shows for XYZ (1.0 = 100 cd/m²): its RGB,
    negatives clipped as the CTL's final clamp does, as BT.2020 in cd/m²."""
    primaries = gamuts()["P3-D65" if "P3" in display else "Rec.2020"]
    rgb = np.maximum(apply_matrix(primaries.xyz_to_rgb, xyz), 0.0)
    to_2020 = gamuts()["Rec.2020"].xyz_to_rgb @ primaries.rgb_to_xyz
    return colour.RGB_to_ICtCp(apply_matrix(to_2020, rgb) * 100.0)


def departure(view: str, xyz: np.ndarray, expected: np.ndarray) -> np.ndarray:
    """Per colour, the largest departure over the view's displays: ten-bit codes of the
    display's encoding (clipped to its range) for SDR, ΔE ITP (ITU-R BT.2124) for HDR."""
    worst = np.zeros(xyz.shape[:-1])
    for display in displays_of(view):
        if PRESETS13[view].kind == "sdr":
            codes = [np.clip(ocio_apply(display_encoding(display), c), 0.0, 1.0) for c in (xyz, expected)]
            error = np.abs(codes[0] - codes[1]).max(axis=-1) * 1023.0
        else:
            error = colour.delta_E(hdr_ictcp(display, xyz), hdr_ictcp(display, expected), method="ITP")
        worst = np.maximum(worst, error)
    return worst


def red_modifier_departs(aces: np.ndarray) -> np.ndarray:
    """Colours OpenColorIO's red modifier weighs by another saturation than the CTL's: it
    takes saturation after the glow (RRT.ctl, before), which differs where the largest
    channel is under the saturation's noise floor (1e-2)."""
    saturation = rrt.rgb_to_saturation(aces)
    glowed = rrt.glow_module(aces, saturation)
    weight = rrt.red_weight(glowed)
    return (weight > 0.0) & (np.abs(rrt.rgb_to_saturation(glowed) - saturation) > 1e-9)


def forward_departures(view: str, set_name: str) -> tuple[np.ndarray, np.ndarray]:
    """Departure of forward13 from the builtin on one probe set, and the red-modifier mask."""
    aces = probe_sets()[set_name]
    ours = forward13(aces, view)
    theirs = ocio_apply(builtin(PRESETS13[view].style), aces)
    return departure(view, ours, theirs), red_modifier_departs(aces)


def bounds(kind: str) -> tuple[float, float]:
    if kind == "sdr":
        return tolerances.ACES13_OCIO_CODES, tolerances.ACES13_OCIO_RED_DARK_CODES
    return tolerances.ACES13_OCIO_DELTA_E_ITP, tolerances.ACES13_OCIO_RED_DARK_DELTA_E_ITP


@pytest.mark.parametrize("set_name", ["greys", "random", "cameras", "bright", "dark"])
@pytest.mark.parametrize("view", list(PRESETS13))
def test_forward_matches_the_ocio_builtin(view, set_name):
    error, red_dark = forward_departures(view, set_name)
    bound, red_bound = bounds(PRESETS13[view].kind)
    assert error[~red_dark].max(initial=0.0) <= bound
    assert error[red_dark].max(initial=0.0) <= red_bound


def test_every_aces1_output_builtin_is_a_preset():
    names = {name for name, _ in ocio.BuiltinTransformRegistry().getBuiltins()}
    aces1 = {n for n in names if n.startswith("ACES-OUTPUT - ") and n.endswith(("_1.0", "_1.1"))}
    assert aces1 == {p.style for p in PRESETS13.values()}


def test_mid_tones_match_to_float32():
    """Greys and pale colours, 0.01 to 10, no display channel near its zero: what is left is
    float32 and the builtins' tone-curve constants (and, at 1000 and 108 nits, OpenColorIO's
    slope adjustment of their curves)."""
    rng = np.random.default_rng(5)
    level = 10.0 ** rng.uniform(-2.0, 1.0, (4000, 1))
    aces = level * rng.uniform(0.8, 1.2, (4000, 3))
    for view, preset in PRESETS13.items():
        error = departure(view, forward13(aces, view), ocio_apply(builtin(preset.style), aces))
        bound = tolerances.ACES13_OCIO_MIDTONE_CODES if preset.kind == "sdr" else tolerances.ACES13_OCIO_DELTA_E_ITP
        assert error.max() <= bound, view


def test_inverse_matches_the_ocio_builtins_inverse():
    """Display colours the presets make from in-range ACES, back through both inverses:
    the CTL's inverse, which OpenColorIO's follows, relative to the largest component."""
    rng = np.random.default_rng(7)
    aces = apply_matrix(rrt.AP1_TO_AP0, 10.0 ** rng.uniform(-2.0, 0.9, (5000, 3)))
    for view, preset in PRESETS13.items():
        xyz = forward13(aces, view)
        ours = inverse13(xyz, view)
        theirs = ocio_apply(builtin(preset.style, inverse=True), xyz)
        error = np.abs(ours - theirs).max(axis=-1) / np.abs(ours).max(axis=-1)
        assert error.max() <= tolerances.ACES13_OCIO_INVERSE_RELATIVE, view


def ocio_adjusts_slopes(curve: ocio.GradingRGBCurveTransform) -> bool:
    """Whether OpenColorIO's B-spline fit rescales this curve's slopes: its AdjustRGBSlopes
    does so where a segment's end slope, 2 (y1 - y0) / (x1 - x0) - s0 in float32, comes out
    negative, as float32 rounding makes it in a segment ending at slope 0."""
    master = curve.getValue().master
    points = np.array([(p.x, p.y) for p in master.getControlPoints()], dtype=np.float32)
    slopes = np.array(master.getSlopes(), dtype=np.float32)
    dx, dy = np.diff(points[:, 0]), np.diff(points[:, 1])
    return bool(np.any((np.float32(2.0) * dy - dx * slopes[:-1]) / dx < 0.0))


@pytest.mark.parametrize("view", list(PRESETS13))
def test_tone_curves_match_where_ocio_keeps_their_slopes(view):
    """OpenColorIO holds the tone scales as B-spline curves in log10: they are ours to
    float32 but where its fit rescales their slopes (the RRT's C5, the 1000- and 108-nit
    SSTS), which moves the two top segments by up to ACES13_OCIO_SLOPE_ADJUSTED_LOG10."""
    preset = PRESETS13[view]
    group = ocio.Config.CreateRaw().getProcessor(builtin(preset.style)).createGroupTransform()
    curves = [t for t in group if isinstance(t, ocio.GradingRGBCurveTransform)]
    splines = [rrt.RRT_SPLINE, ODT_48NITS_SPLINE] if preset.kind == "sdr" else [preset.odt.spline]
    for curve, spline in zip(curves, splines, strict=True):
        (lmin, _), _, (lmax, _) = spline.log_points()
        logx = np.linspace(lmin - 0.5, lmax + 0.5, 20001).astype(np.float32)
        pixels = np.repeat(logx[:, None], 3, axis=1)
        ocio.Config.CreateRaw().getProcessor(curve).getDefaultCPUProcessor().applyRGB(pixels)
        error = np.abs(pixels[:, 0] - np.log10(spline_forward(10.0 ** logx.astype(np.float64), spline))).max()
        adjusted = ocio_adjusts_slopes(curve)
        assert adjusted == (spline is rrt.RRT_SPLINE or preset.peak_luminance in (1000.0, 108.0))
        bound = tolerances.ACES13_OCIO_SLOPE_ADJUSTED_LOG10 if adjusted else tolerances.ACES13_OCIO_CURVE_LOG10
        assert error <= bound
