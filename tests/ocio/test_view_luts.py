"""A view's baked LUT as the config runs it, measured through OCIO (generator/ocio/view_luts.py)."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.luts import probes
from generator.luts.view import bake_view_lut
from generator.ocio.view_luts import view_figures, view_transform


def test_view_lut_reads_back_and_is_measured(default_spec, tmp_path):
    display = default_spec.displays[0]
    view = bake_view_lut(default_spec, display, "clip")
    measured = view_figures(view)
    assert max(f.maximum for f in measured.values()) <= tolerances.LUT_CLF_IN_GAMUT_CODES
    assert measured["in_gamut"].unit == "10-bit codes"
    path = tmp_path / view.filename
    path.write_bytes(view.data)
    apply = probes.ocio_apply(view_transform(view.matrix, str(path)))
    figures = probes.measure(default_spec, None, display, "clip", apply, count=512)
    assert max(f.maximum for f in figures.values()) <= tolerances.LUT_CLF_IN_GAMUT_CODES
    assert bake_view_lut(default_spec, display, "clip").data == view.data


def test_a_display_with_a_tabulated_eotf_has_its_views_measured_through_its_baked_curve(tmp_path):
    """No CLF operator encodes a tabulated EOTF: the view file ends in display light and the
    config encodes it with the display's baked curve, which the measurement must find (it
    looked the file up before it was written)."""
    from generator.spec import load

    code = np.linspace(0.0, 1.0, 65)
    rows = "".join(f"{c:.17g},{c**2.4:.17g}\n" for c in code)
    (tmp_path / "eotf.csv").write_text("code,linear\n" + rows)
    (tmp_path / "show.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[display]]\nname = "Tab EOTF"\ngamut = "Rec.709"\neotf = { family = "tabulated", file = "eotf.csv" }\n'
        'views = ["Colorimetric", "Scale", "Desaturate", "Raw"]\n'
    )
    spec = load.load(tmp_path / "show.toml")
    for method in ("scale", "desaturate"):
        view = bake_view_lut(spec, spec.displays[0], method)
        figures = view_figures(view)
        assert view.light and figures["in_gamut"].unit == "10-bit codes"
        assert figures["in_gamut"].maximum <= tolerances.LUT_CLF_IN_GAMUT_CODES, method
        assert max(f.maximum for f in figures.values()) <= tolerances.LUT_CLF_SCALE_CODES, method


@pytest.mark.parametrize("display_name", ["Rec.2100-PQ - Display", "ST2084-P3-D65 - Display"])
def test_a_pq_views_transform_encodes_light_with_the_published_curve(default_spec, tmp_path, display_name):
    """A file ending in display light is followed by the display's encoding: ACES greys of 0.01,
    0.18, 1 and 10 (100 cd/m² for 1) come out at SMPTE ST 2084's codes of 1, 18, 100 and 1000
    cd/m² (as colour-science has them), which scale leaves alone below the 1000 cd/m² peak."""
    import colour

    display = next(d for d in default_spec.displays if d.name == display_name)
    view = bake_view_lut(default_spec, display, "scale")
    (tmp_path / view.filename).write_bytes(view.data)
    transform = view_transform(view.matrix, str(tmp_path / view.filename), default_spec, display)
    greys = np.repeat(np.array([0.01, 0.18, 1.0, 10.0])[:, None], 3, axis=1)
    codes = probes.ocio_apply(transform)(greys)
    expected = colour.models.eotf_inverse_ST2084(greys * 100.0)
    np.testing.assert_allclose(codes, expected, rtol=0, atol=1e-5)
    without = probes.ocio_apply(view_transform(view.matrix, str(tmp_path / view.filename)))(greys)
    np.testing.assert_allclose(without, greys / display.clip_high, rtol=1e-5)
    assert isinstance(transform, ocio.GroupTransform)
