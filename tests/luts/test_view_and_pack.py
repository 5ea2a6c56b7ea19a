"""The config's view LUTs (the standalone pack: test_pack.py)."""

from __future__ import annotations

import numpy as np
import pytest

from generator import tolerances
from generator.luts import probes
from generator.luts.view import bake_view_lut, view_filename
from generator.metrics import delta_e_itp
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


def test_view_files_of_displays_named_alike_are_apart(default_spec, tmp_path):
    """Displays whose names slug alike each name their own view files (they shared one, and
    one display's view read the other's lattice); a display named apart keeps its slug."""
    from generator.spec import load

    walls = (("Wall A", "P3-D65"), ("Wall-A", "Rec.709"))
    text = "".join(
        f'[[display]]\nname = "{name}"\ngamut = "{gamut}"\neotf = "Gamma 2.4"\nviews = ["Colorimetric", "Scale"]\n'
        for name, gamut in walls
    )
    (tmp_path / "walls.toml").write_text(text)
    spec = load.load(tmp_path / "walls.toml")
    names = {
        view_filename(spec, d, method)
        for d in spec.displays
        if d.name.startswith("Wall")
        for method in ("scale", "desaturate")
    }
    assert len(names) == 4 and all(n.startswith("view_wall_a_") for n in names)
    srgb = next(d for d in default_spec.displays if d.name == "sRGB - Display")
    assert view_filename(default_spec, srgb, "scale") == "view_srgb_display_scale_17.clf"


def test_one_pq_code_on_a_grey_is_the_delta_e_itp_the_hdr_targets_use(default_spec):
    display = next(d for d in default_spec.displays if d.eotf_name == "ST 2084")
    grey = np.linspace(0.01, 0.99, 50)[:, None] * np.ones(3)
    for codes in (tolerances.LUT_CLF_IN_GAMUT_CODES, tolerances.LUT_CLF_SCALE_CODES):
        error = delta_e_itp(display, grey + codes / 1023.0, grey)
        assert np.allclose(error, codes * tolerances.DELTA_E_ITP_PER_PQ_CODE, rtol=1e-9)


@pytest.mark.parametrize("eotf", ["ST 2084", "HLG"])
@pytest.mark.parametrize("method", ["scale", "desaturate"])
def test_hdr_view_lut_ends_in_display_light_and_meets_the_targets(default_spec, eotf, method):
    """A display CLF cannot encode: the file ends in normalised display light (the config
    encodes it), and its lattice holds the curve of its input, so in-gamut colours, which
    these mappings leave alone, come back as they went in (scale: every colour, up to the
    lattice's toe)."""
    display = next(d for d in default_spec.displays if d.eotf_name == eotf)
    view = bake_view_lut(default_spec, display, method)
    undo = b'style="logToLin"' if method == "scale" else b"<LUT3D"
    measured = view_figures(view)
    assert view.light and measured["in_gamut"].unit == "ΔE ITP" and undo in view.data
    assert measured["in_gamut"].maximum <= tolerances.LUT_VIEW_HDR_IN_GAMUT_DELTA_E_ITP
    # OCIO's HLG builtin departs from BT.2100 near black (tolerances.HLG_BUILTIN_BLACK).
    figures = {name: f for name, f in measured.items() if not (eotf == "HLG" and name == "dark")}
    assert max(f.maximum for f in figures.values()) <= tolerances.LUT_VIEW_HDR_SCALE_DELTA_E_ITP


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
