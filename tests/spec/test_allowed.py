"""What a spec may ask for that depends on no spec, against what OpenColorIO, the gamut mappings
and the bake offer."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.gamut import METHODS
from generator.luts.bake import FORMATS
from generator.spec.allowed import (
    COLORIMETRIC_ALIASES,
    HLG_DISPLAY_PEAK,
    LUT_FORMATS,
    OCIO_MIN_VERSION,
    VIEW_METHODS,
    VIEWS,
    newest_ocio_version,
)


def test_the_newest_version_is_the_newest_ocio_writes():
    """PyOpenColorIO's version number (0xMMmmpp00), and the newest minor a config of it takes."""
    newest = newest_ocio_version()
    hexadecimal = ocio.GetVersionHex()
    assert newest == (hexadecimal >> 24, (hexadecimal >> 16) & 0xFF)
    config = ocio.Config.CreateRaw()
    for version in (OCIO_MIN_VERSION, newest):
        config.setVersion(*version)
        assert (config.getMajorVersion(), config.getMinorVersion()) == version
    with pytest.raises(ocio.Exception, match="not supported"):
        config.setVersion(newest[0], newest[1] + 1)
    assert newest >= OCIO_MIN_VERSION


def test_every_gamut_mapping_is_a_view_and_raw_is_one_too():
    assert set(VIEW_METHODS.values()) == set(METHODS)
    assert (*VIEW_METHODS, "Raw") == VIEWS and len(set(VIEWS)) == len(VIEWS)


def test_the_studio_configs_untone_mapped_view_is_colorimetric():
    """Its view transform is OCIO's Bradford matrix to CIE XYZ-D65 alone, no tone scale: what our
    Colorimetric view shows."""
    config = ocio.Config.CreateFromFile("ocio://studio-config-latest")
    for name in COLORIMETRIC_ALIASES:
        assert name in config.getViews("sRGB - Display")
        transform = config.getViewTransform(name).getTransform(ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
        assert isinstance(transform, ocio.BuiltinTransform)
        assert transform.getStyle() == "UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD"


def test_the_hlg_peak_is_ocios_hlg_display_builtins():
    """OCIO's one HLG display builtin: signal 1 is the peak, 75% is BT.2408's HDR reference
    white (203 cd/m²), on a grey."""
    styles = [name for name, _ in ocio.BuiltinTransformRegistry().getBuiltins() if name.startswith("DISPLAY -")]
    hlg = [style for style in styles if "HLG" in style]
    assert hlg == [f"DISPLAY - CIE-XYZ-D65_to_REC.2100-HLG-{HLG_DISPLAY_PEAK:.0f}nit"]
    transform = ocio.BuiltinTransform(hlg[0])
    transform.setDirection(ocio.TRANSFORM_DIR_INVERSE)
    pixels = np.ascontiguousarray([[1.0, 1.0, 1.0], [0.75, 0.75, 0.75]], dtype=np.float32)
    ocio.Config.CreateRaw().getProcessor(transform).getDefaultCPUProcessor().applyRGB(pixels)
    luminance = pixels[:, 1] * 100.0  # 1.0 = 100 cd/m²
    assert luminance[0] == pytest.approx(HLG_DISPLAY_PEAK, rel=1e-6)
    assert round(float(luminance[1])) == 203


def test_the_lut_formats_are_the_bakes():
    assert tuple(FORMATS) == LUT_FORMATS
