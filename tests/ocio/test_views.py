"""Every view of every display in the built config, through OCIO, against the reference.

Targets (the issue's, in ten-bit codes; for HDR displays in ΔE ITP, DELTA_E_ITP_PER_PQ_CODE
each): in-gamut colours within LUT_CLF_IN_GAMUT_CODES (analytic HDR views within
ANALYTIC_DELTA_E_ITP), and every probe set within LUT_CLF_SCALE_CODES for the views that clip
or scale. A view defined by its lattice (Perceptual, generator.luts.view.LATTICE_DEFINED) is
held to that lattice, evaluated in float64, within LUT_CLF_IN_GAMUT_CODES on every set; how far
the lattice departs from the mapping is bench/lut_accuracy.py's to measure. HLG displays leave
out the dark set: OCIO's HLG builtin departs from BT.2100 below HLG_BUILTIN_BLACK (see
tests/ocio/test_emit.py).
"""

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.luts import probes
from generator.luts.view import LATTICE_DEFINED
from generator.spec import resolved
from generator.spec.load import VIEW_METHODS
from generator.verify import paths


@pytest.fixture(scope="module")
def built(build_config):
    path = build_config((2, 1))
    return ocio.Config.CreateFromFile(str(path)), resolved.read_beside(path)


def view_apply(cfg, spec, display, view):
    processor = cfg.getProcessor(spec.scene_reference, display.name, view, ocio.TRANSFORM_DIR_FORWARD)
    cpu = processor.getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS)

    def apply(rgb):
        pixels = np.ascontiguousarray(rgb, dtype=np.float32)
        cpu.applyRGB(pixels)
        return pixels.astype(np.float64)

    return apply


def cases(spec):
    return [(d, v) for d in spec.displays for v in d.views if v in VIEW_METHODS]


def test_every_view_meets_its_targets(built):
    cfg, spec = built
    failures = []
    for display, view in cases(spec):
        method = VIEW_METHODS[view]
        apply = view_apply(cfg, spec, display, view)
        if method in LATTICE_DEFINED:
            figures = _against_lattice(spec, display, view, apply)
        else:
            figures = probes.measure(spec, None, display, method, apply, gamut_source=spec.space("ACEScg"), count=1024)
        if display.eotf_name == "HLG":
            figures.pop("dark")
        in_gamut, every_set = targets(display, view)
        if figures["in_gamut"].maximum > in_gamut:
            failures.append((display.name, view, "in_gamut", figures["in_gamut"].maximum))
        if every_set is not None:
            failures += [(display.name, view, name, f.maximum) for name, f in figures.items() if f.maximum > every_set]
    assert not failures, failures


def _against_lattice(spec, display, view, apply) -> dict:
    """The probe sets through ``apply`` against the view's lattice evaluated in float64."""
    through = paths.view_function(spec, display, view)
    out = {}
    for name, ref in probes.probes(spec, spec.space("ACEScg"), display, count=1024).items():
        error = probes.errors(display, apply(ref), through(ref))[0]
        out[name] = probes.Figures(float(error.max()), float(np.percentile(error, 99)), "")
    return out


def targets(display, view) -> tuple[float, float | None]:
    """The in-gamut bound of a view and the bound on every set: for views that clip or scale,
    and for a view defined by its lattice (against the lattice: its in-gamut bound)."""
    method = VIEW_METHODS[view]
    analytic = view in ("Colorimetric", "RGC")
    if display.is_hdr:
        in_gamut = tolerances.ANALYTIC_DELTA_E_ITP if analytic else tolerances.LUT_VIEW_HDR_IN_GAMUT_DELTA_E_ITP
        every_set = tolerances.ANALYTIC_DELTA_E_ITP if analytic else tolerances.LUT_VIEW_HDR_SCALE_DELTA_E_ITP
    else:
        in_gamut, every_set = tolerances.LUT_CLF_IN_GAMUT_CODES, tolerances.LUT_CLF_SCALE_CODES
    if method in LATTICE_DEFINED:
        return in_gamut, in_gamut
    return in_gamut, every_set if method in ("clip", "scale") else None


def test_every_gamut_mapped_view_a_spec_can_ask_for(tmp_path):
    """Views beyond the defaults (Scale, Desaturate, Perceptual: baked lattices) on an SDR display
    and on PQ and HLG displays, whose view files end in display light for the config to encode."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    text = load.default_text().split("[[display]]")[0] + (
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Desaturate", "Scale", "Perceptual", "RGC", "Raw"]\n'
        '[[display]]\nname = "Rec.2100-PQ - Display"\nviews = ["Colorimetric", "Desaturate", "Scale", "Perceptual", "RGC", "Raw"]\n'
        '[[display]]\nname = "Rec.2100-HLG - Display"\nviews = ["Colorimetric", "Desaturate", "Scale", "Perceptual", "RGC", "Raw"]\n'
    )
    folder = tmp_path / "all-views"
    build(for_folder(load.parse(text, "all-views.toml", tmp_path), folder), folder)
    test_every_view_meets_its_targets(
        (ocio.Config.CreateFromFile(str(folder / "config.ocio")), resolved.read_beside(folder / "config.ocio"))
    )


def test_an_absolute_led_wall_meets_every_target(tmp_path):
    """An SDR display driven in absolute luminance (code 1 = its 1500 cd/m² peak, a 2.4 power)
    offers every default view within the targets; its Colorimetric view puts scene 1.0
    (display-referred 100 cd/m²) at code (1 / 15) ** (1 / 2.4) and 15 at code 1."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    text = load.default_text().split("[[display]]")[0] + (
        '[[display]]\nname = "LED Wall"\nprimaries = [[0.70, 0.29], [0.17, 0.74], [0.135, 0.05]]\nwhite = "D65"\n'
        'eotf = "gamma 2.4"\npeak_luminance = 1500\nabsolute_luminance = true\n'
    )
    folder = tmp_path / "wall"
    build(for_folder(load.parse(text, "wall.toml", tmp_path), folder), folder)
    cfg, spec = ocio.Config.CreateFromFile(str(folder / "config.ocio")), resolved.read_beside(folder / "config.ocio")
    test_every_view_meets_its_targets((cfg, spec))
    grey = spec.space("ACEScg")  # its white is the display's after adaptation: a grey stays grey
    apply = cfg.getProcessor(grey.name, "LED Wall", "Colorimetric", ocio.TRANSFORM_DIR_FORWARD).getDefaultCPUProcessor()
    codes = np.array([apply.applyRGB([v, v, v]) for v in (1.0, 15.0)])
    assert np.allclose(codes, [[(1 / 15) ** (1 / 2.4)] * 3, [1.0] * 3], rtol=0, atol=tolerances.ANALYTIC_RELATIVE)


def test_scale_keeps_the_hue_of_highlights_far_beyond_the_peak(built):
    """Bright practical lights: ColorChecker colours 2**5 to 2**15 times over, through Scale,
    within the every-set bound of the reference, with no clamp before the mapping (a lattice
    clamped per channel at 32 times the peak turned orange-yellow at 2**6 into yellow, 165
    codes off)."""
    import colour

    from generator import reference

    cfg, spec = built
    checker = colour.CCS_COLOURCHECKERS["ColorChecker24 - After November 2014"]
    xyz = colour.xyY_to_XYZ(np.array(list(checker.data.values())))
    ref = xyz @ np.linalg.inv(reference.scene_to_display_reference(spec)).T
    ref = np.concatenate([ref * 2.0**k for k in range(5, 16)])
    for display in (d for d in spec.displays if "Scale" in d.views):
        expected = reference.mapped_view(spec, display, "scale", ref)
        error = probes.errors(display, view_apply(cfg, spec, display, "Scale")(ref), expected)[0]
        assert error.max() <= targets(display, "Scale")[1], (display.name, error.max())


def test_gamut_mapped_views_read_back_as_colorimetric(built):
    """A display-referred file read into the scene through "Scale - <display>", "Desaturate -
    <display>" or "Perceptual - <display>" comes back as through Colorimetric: the colours the
    display shows (Scale and Desaturate leave every displayable colour alone, so that is their
    one inverse; OCIO's inversion of the Scale lattice sent sRGB white to scene 2.65, of the
    Perceptual one sRGB (0.9, 0.1, 0.1) to ACEScg (0.77, -0.08, -0.04))."""
    from generator.spec.namespace import display_view_space

    cfg, spec = built
    codes = np.random.default_rng(7).random((512, 3))
    codes[:3] = [[1.0, 1.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]

    def back(space):
        cpu = cfg.getProcessor(space, spec.scene_reference).getDefaultCPUProcessor()
        pixels = np.ascontiguousarray(codes, dtype=np.float32)
        cpu.applyRGB(pixels)
        return pixels.astype(np.float64)

    checked = 0
    for display in spec.displays:
        expected = back(display_view_space("Colorimetric", display.name))
        for view in ("Scale", "Desaturate", "Perceptual"):
            if view in display.views:
                actual = back(display_view_space(view, display.name))
                scale = np.maximum(np.abs(expected).max(axis=-1, keepdims=True), 1.0)
                assert (np.abs(actual - expected) <= tolerances.ANALYTIC_RELATIVE * scale).all(), (display.name, view)
                checked += 1
    assert checked


def test_perceptual_takes_bright_saturated_lights_to_white(built):
    """ACEScg primaries and secondaries at 1000 and 10000 times the peak (practical lights, the
    sun) come out of every Perceptual view as the mapping sends them, to white: clamped at 32
    times the peak, a red light's channel beside a far negative green had made its luminance
    negative, and the view showed (0.69, 0, 0.36) where the mapping shows white."""
    from generator import reference

    cfg, spec = built
    hues = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1]], dtype=np.float64)
    acescg = reference.space_matrix(spec, spec.space("ACEScg"))
    ref = np.concatenate([hues * k for k in (1e3, 1e4)]) @ acescg.T
    checked = 0
    for display in (d for d in spec.displays if "Perceptual" in d.views):
        expected = reference.mapped_view(spec, display, "perceptual", ref)
        error = probes.errors(display, view_apply(cfg, spec, display, "Perceptual")(ref), expected)[0]
        assert error.max() <= tolerances.LUT_CLF_SCALE_CODES, (display.name, error.max())
        checked += 1
    assert checked == 6


def test_the_rgc_view_runs_the_specs_parameters_and_verify_judges_it_by_them(tmp_path):
    """The spec's [rgc] table is the config's FixedFunction, and the reference verify compares
    with: the config passes, and the same config with ACES 1.3's parameters fails."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load
    from generator.verify.checks import VIEW
    from generator.verify.judge import FAIL, PASS
    from generator.verify.run import verify

    spec = load.parse(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        "[rgc]\nlimits = [1.5, 1.4, 1.3]\nthresholds = [0.6, 0.7, 0.75]\npower = 1.5\n"
        '[[display]]\nname = "Rec.1886 Rec.709 - Display"\nviews = ["RGC", "Raw"]\n',
        "show.toml",
        tmp_path,
    )
    folder = tmp_path / "show"
    build(for_folder(spec, folder), folder)
    config = folder / "config.ocio"
    text = config.read_text(encoding="utf-8")
    assert text.count("params: [1.5, 1.4, 1.3, 0.6, 0.7, 0.75, 1.5]") == 1  # the view transform
    result = verify(config, ("ocio",), density="quick", kinds=(VIEW,), only="RGC", strict=True)
    assert result.outcomes and all(o.verdict == PASS for o in result.outcomes)
    config.write_text(
        text.replace("[1.5, 1.4, 1.3, 0.6, 0.7, 0.75, 1.5]", "[1.147, 1.264, 1.312, 0.815, 0.803, 0.88, 1.2]"),
        encoding="utf-8",
    )
    result = verify(config, ("ocio",), density="quick", kinds=(VIEW,), only="RGC", strict=True)
    assert any(o.verdict == FAIL for o in result.outcomes)
