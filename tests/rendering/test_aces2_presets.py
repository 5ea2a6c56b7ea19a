"""The ACES 2.0 presets against OpenColorIO 2.6's builtins and the ACES studio configs, and
their names against their parameters."""

from __future__ import annotations

import re

import colour
import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.rendering.aces2_presets import (
    CINEMA_SCALE,
    D60,
    D65,
    GAMUTS,
    P3,
    PRESETS,
    REC709,
    REC2020,
    STYLE_PREFIX,
)
from tests.rendering.aces2_cases import builtin, preset_tables

#: A view's name: SDR or HDR, nits, the limiting gamut, "sim." where its white is scaled into the
#: encoding gamut, "in <encoding>" where that is not the limiting gamut's (D65) primaries.
VIEW_NAME = re.compile(r"ACES 2\.0 - (SDR|HDR) (\d+) nits \((.+?)( sim\.)?(?: in (.+))?\)")


def test_the_chromaticities_are_colour_sciences():
    """ITU-R BT.709, SMPTE EG 432-1 (P3-D65), ITU-R BT.2020, and the ACES white (D60)."""
    assert np.array_equal(REC709, colour.RGB_COLOURSPACES["ITU-R BT.709"].primaries)
    assert np.array_equal(P3, colour.RGB_COLOURSPACES["P3-D65"].primaries)
    assert np.array_equal(REC2020, colour.RGB_COLOURSPACES["ITU-R BT.2020"].primaries)
    assert np.array_equal(D65, colour.RGB_COLOURSPACES["ITU-R BT.709"].whitepoint)
    assert np.array_equal(D60, colour.RGB_COLOURSPACES["ACES2065-1"].whitepoint)


@pytest.mark.parametrize("view", PRESETS)
def test_the_name_says_the_parameters(view):
    """The nits are the peak times the linear scale (the cinema presets aim at 225 and 625 cd/m²
    and show 0.48 of it), SDR exactly at 100; the gamuts are the named ones."""
    p = PRESETS[view].params
    match = VIEW_NAME.fullmatch(view)
    assert match is not None
    kind, nits, limiting, simulated, encoding = match.groups()
    assert int(nits) == round(p.peak_luminance * p.linear_scale)
    assert (kind == "SDR") == (int(nits) == 100)
    assert (p.linear_scale == CINEMA_SCALE) == (int(nits) in (108, 300))
    assert (p.limiting_primaries, p.limiting_white) == GAMUTS[limiting]
    assert bool(simulated) == p.applies_white_scale
    if encoding is None:
        encoding = next(n for n, (prims, white) in GAMUTS.items() if prims == GAMUTS[limiting][0] and white == D65)
    assert (p.encoding_primaries, p.encoding_white) == GAMUTS[encoding]


STUDIO_CONFIGS = (
    "studio-config-v4.0.0_aces-v2.0_ocio-v2.5",
    "studio-config-v5.0.0_aces-v2.1_ocio-v2.6",
    "cg-config-v4.0.0_aces-v2.0_ocio-v2.5",
    "cg-config-v5.0.0_aces-v2.1_ocio-v2.6",
)


def test_every_builtin_is_a_preset():
    styles = {
        name
        for name, _ in ocio.BuiltinTransformRegistry().getBuiltins()
        if name.startswith(STYLE_PREFIX) and name.endswith("_2.0")
    }
    assert styles == {preset.style for preset in PRESETS.values()}
    assert len(PRESETS) == 31


@pytest.mark.parametrize("config", STUDIO_CONFIGS)
def test_view_names_are_the_studio_configs(config):
    cfg = ocio.Config.CreateFromFile(f"ocio://{config}")
    named = {}
    for view in cfg.getViewTransforms():
        transform = view.getTransform(ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
        if isinstance(transform, ocio.BuiltinTransform) and transform.getStyle().endswith("_2.0"):
            named[view.getName()] = transform.getStyle()
    assert named
    for name, style in named.items():
        assert PRESETS[name].style == style


def decomposition(style: str) -> list:
    return list(ocio.Config.CreateRaw().getProcessor(builtin(style)).createGroupTransform())


@pytest.mark.parametrize("view", PRESETS)
def test_preset_is_the_builtins_decomposition(view):
    """The builtin is AP0->AP1, clamp, AP1->AP0, the fixed function, clamp, scales, limiting RGB
    to XYZ: its parameters are the preset's (OCIO holds the clamp's limit in float32)."""
    preset, t = PRESETS[view], preset_tables(view)
    p = preset.params
    steps = decomposition(preset.style)
    kinds = [type(s).__name__ for s in steps]
    assert kinds[:5] == [
        "MatrixTransform",
        "RangeTransform",
        "MatrixTransform",
        "FixedFunctionTransform",
        "RangeTransform",
    ]
    assert np.float32(t.tone.forward_limit) == np.float32(steps[1].getMaxInValue())
    assert steps[1].getMinInValue() == 0.0
    expected = [p.peak_luminance, *np.ravel(p.limiting_primaries), *p.limiting_white]
    np.testing.assert_allclose(steps[3].getParams(), expected, rtol=0, atol=1e-12)
    assert steps[4].getMaxInValue() == pytest.approx(p.peak_luminance / 100.0, abs=1e-12)
    matrices = [np.reshape(s.getMatrix(), (4, 4))[:3, :3] for s in steps[5:]]
    np.testing.assert_allclose(np.reshape(steps[0].getMatrix(), (4, 4))[:3, :3], t.ap0_to_ap1, atol=1e-9)
    combined = np.linalg.multi_dot([np.eye(3), *reversed(matrices)])
    # OCIO stores 0.48 as float32's 0.47999998927.
    np.testing.assert_allclose(combined, t.limit_to_xyz * t.display_scale, rtol=3e-8, atol=1e-12)
