"""The per-display LUT a config's gamut-mapped view references (generator/luts/view.py); measured
through OCIO as the config runs it in tests/ocio/test_view_luts.py."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.luts import hsv, hsv_axes
from generator.luts.view import HSV_METHOD, bake_view_lut, ends_in_light, view_filename, view_size
from generator.ocio.view_luts import view_figures


def _display(spec, name):
    return next(d for d in spec.displays if d.name == name)


def _operators(tmp_path, view) -> list:
    """The operators OCIO reads in the view's file."""
    (tmp_path / view.filename).write_bytes(view.data)
    return list(
        ocio.Config.CreateRaw().getProcessor(ocio.FileTransform(str(tmp_path / view.filename))).createGroupTransform()
    )


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


def test_the_matrix_before_the_file_is_the_aces_studio_configs(default_spec):
    """Scene-reference ACES2065-1 to sRGB's linear light: the matrix of OCIO's own ACES studio
    config (ACES2065-1 to Linear Rec.709), to its float32."""
    view = bake_view_lut(default_spec, _display(default_spec, "sRGB - Display"), "clip")
    config = ocio.Config.CreateFromFile("ocio://studio-config-latest")
    columns = np.eye(3, dtype=np.float32)
    config.getProcessor("ACES2065-1", "Linear Rec.709 (sRGB)").getDefaultCPUProcessor().applyRGB(columns)
    np.testing.assert_allclose(np.array(view.matrix), columns.T, rtol=0, atol=1e-6)


def test_views_of_hdr_displays_end_in_light_and_sdr_ones_in_code_values(default_spec):
    light = {d.name: ends_in_light(d) for d in default_spec.displays}
    assert light["Rec.2100-PQ - Display"] and light["Rec.2100-HLG - Display"] and light["Display P3 HDR - Display"]
    assert not light["sRGB - Display"] and not light["Gamma 2.6 P3-D65 - Display"]


@pytest.mark.parametrize("method, size", [("clip", 17), ("scale", 17), ("rgc", 33), ("perceptual", 33)])
def test_a_views_lattice_has_its_methods_size(default_spec, tmp_path, method, size):
    """Clip and scale, exact on a log axis, at 17³; the others at 33³, as OCIO reads the file."""
    display = _display(default_spec, "sRGB - Display")
    view = bake_view_lut(default_spec, display, method)
    assert view_size(display, method) == size and view.filename == f"view_srgb_display_{method}_{size}.clf"
    lattices = [op for op in _operators(tmp_path, view) if isinstance(op, ocio.Lut3DTransform)]
    assert [op.getGridSize() for op in lattices] == [size]
    assert not view.light and not view.hsv and view.beside == ()


def test_a_size_asked_for_is_the_files_and_its_name(default_spec, tmp_path):
    view = bake_view_lut(default_spec, _display(default_spec, "sRGB - Display"), "clip", size=9)
    assert view.filename == "view_srgb_display_clip_9.clf"
    assert [op.getGridSize() for op in _operators(tmp_path, view) if isinstance(op, ocio.Lut3DTransform)] == [9]


def test_the_desaturate_view_is_an_hsv_lattice_with_its_shared_file_beside(default_spec, tmp_path):
    display = _display(default_spec, "sRGB - Display")
    view = bake_view_lut(default_spec, display, HSV_METHOD)
    assert view.hsv and view.light and view.filename == f"view_srgb_display_desaturate_hsv{hsv_axes.HSV_SIZE}.clf"
    assert dict(view.beside) == {hsv.SHARED_FILE: hsv.shared_clf()}
    baked = bake_view_lut(default_spec, display, HSV_METHOD, size=17)
    assert not baked.hsv and baked.filename == "view_srgb_display_desaturate_17.clf"
    assert [op.getGridSize() for op in _operators(tmp_path, baked) if isinstance(op, ocio.Lut3DTransform)] == [17]
