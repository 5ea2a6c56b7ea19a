"""What every name of a built config should do, from the spec alone: spaces decode and encode
back, displays clip their light to the peak, codes clamp where the config's curve does (a baked
LUT, a clamping builtin, PQ's signal range), a display-view space read back as its display."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.colorimetry.curves import HALF_MAX
from generator.verify import paths
from generator.verify.checks import FROM_REFERENCE, TO_REFERENCE
from generator.verify.run import verify
from tests.conftest import NEWEST
from tests.verify.conftest import newly_failing, rewrite, scale_view_matrix


@pytest.mark.parametrize("view", ["Scale", "Desaturate"])
def test_a_view_read_back_wrongly_is_named(config_copy, view):
    """A "<view> - <display>" space read into the scene (a display-referred image brought into
    a comp) is checked against the display's decoding: its view transform's inverse matrix
    off by a tenth in one entry fails that space alone."""
    change = scale_view_matrix(f"{view} (sRGB - Display)", ocio.VIEWTRANSFORM_DIR_TO_REFERENCE, 0, 1.1)
    failing = newly_failing(config_copy, lambda path: rewrite(path, change), (TO_REFERENCE,))
    assert failing == {f"{view} - sRGB - Display"}


@pytest.mark.parametrize("name", ["CanonLog2", "CanonLog3", "Apple Log"])
def test_curves_a_clamping_builtin_expresses_are_judged_on_its_codes(build_config, name):
    """From OCIO 2.2 (2.4 for Apple Log) the config decodes Canon Log 2 and 3 with OCIO's
    builtins, which tabulate codes 0 to 1 and clamp outside (Apple Log's below 0): verify
    judges those spaces on those codes, as it does a baked curve on its LUT's domain
    (it failed every Canon space of the default spec at 2.2 and later before)."""

    result = verify(build_config(NEWEST), ("ocio",), density="quick", kinds=(TO_REFERENCE, FROM_REFERENCE), only=name)
    assert result.outcomes and result.passed, [(o.check.title, o.engine, o.worst) for o in result.failures]


@pytest.mark.parametrize("version", [(2, 1), "newest"])
def test_a_pq_scene_space_passes_beyond_the_signal_range(tmp_path, version):
    """A scene space encoded with ST 2084 is judged on negative and over-range colours too:
    config and reference both clamp to the signal range (it failed by 1.45 relative)."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    (tmp_path / "pq.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "P3 PQ"\ngamut = "P3-D65"\ntransfer = "ST 2084"\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
    )
    folder = tmp_path / "pq"
    build(for_folder(load.load(tmp_path / "pq.toml"), folder, NEWEST if version == "newest" else version), folder)
    result = verify(
        folder / "config.ocio",
        ("ocio",),
        density="quick",
        kinds=(TO_REFERENCE, FROM_REFERENCE),
        only="P3 PQ",
    )
    assert result.outcomes and result.passed, [(o.check.title, o.engine, o.worst) for o in result.failures]


@pytest.mark.parametrize(
    "name",
    [
        "ACEScct",
        "sRGB Encoded Rec.709 (sRGB)",
        "Gamma 2.2 Encoded Rec.709",
        "CanonLog2 CinemaGamut D55",
        "N-Log N-Gamut",
        "ADX10",
    ],
)
def test_a_scene_space_encodes_back_the_codes_it_decodes(spec, name):
    """Over its code range (a baked curve's domain), a space's decoding to the scene reference
    and its encoding are inverse, so a check can judge either direction against the other."""
    end = paths.LazyEndpoints(spec)[name]
    lo, hi = end.code_range
    codes = np.random.default_rng(11).uniform(lo, hi, (300, 3))
    with np.errstate(all="ignore"):
        back = end.encode(end.decode(codes))
    np.testing.assert_allclose(back, codes, rtol=0, atol=1e-6)


def test_adx16s_codes_stop_where_its_exposure_reaches_half_float_max(spec):
    """OCIO's ADX16 builtin clamps its exposure at half-float max: the range ends at the code
    that decodes there, so codes past it are not compared."""
    end = paths.LazyEndpoints(spec)["ADX16"]
    lo, hi = end.code_range
    top = end.linear(np.full((1, 3), hi))
    assert lo == 0.0 and hi < 1.0
    np.testing.assert_allclose(top, HALF_MAX, rtol=1e-5)
    assert np.all(end.linear(np.full((1, 3), hi + 1e-4)) > HALF_MAX)


def test_a_display_decodes_its_codes_to_light_clipped_at_its_peak(spec):
    """A 1000 cd/m² PQ display: every code above its peak's decodes to the peak (OCIO's range
    clamp), and codes below it come back unchanged."""
    display = next(d for d in spec.displays if d.name == "Rec.2100-PQ - Display")
    end = paths.LazyEndpoints(spec)[display.name]
    peak_code = float(display.eotf.encode(display.clip_high))
    assert 0.7 < peak_code < 0.8
    codes = np.repeat(np.linspace(0.0, 1.0, 201)[:, None], 3, axis=1)
    light = end.linear(codes)
    assert light.max() == pytest.approx(display.clip_high, rel=1e-12)
    above = codes[:, 0] > peak_code
    np.testing.assert_allclose(light[above], display.clip_high, rtol=1e-12)
    np.testing.assert_allclose(end.encode(end.decode(codes[~above])), codes[~above], atol=1e-6)
    np.testing.assert_allclose(end.encode(end.decode(codes[above])), peak_code, atol=1e-6)


def test_a_view_space_reads_back_as_its_display_unless_its_inverse_has_no_evaluation(spec):
    """ "Scale - sRGB - Display" is inverted as Colorimetric: read into the scene it decodes as
    its display does; RGC's analytic inverse has no evaluation here, so its space is checked
    forward only."""
    display = next(d for d in spec.displays if d.name == "sRGB - Display")
    codes = np.random.default_rng(12).random((50, 3))
    shown = paths.LazyEndpoints(spec)[display.name]
    scale = paths.display_view_endpoint(spec, display, "Scale")
    np.testing.assert_array_equal(scale.decode(codes), shown.decode(codes))
    rgc = paths.display_view_endpoint(spec, display, "RGC")
    assert rgc.decode is None and rgc.linear is None and rgc.encode is not None


def test_the_endpoints_are_the_configs_colour_spaces_each_built_when_looked_up(build_config, spec):
    """Names only, in config order, until one is looked up; a name the config lacks is none."""
    cfg = ocio.Config.CreateFromFile(str(build_config((2, 1))))
    lazy = paths.LazyEndpoints(spec)
    names = set(cfg.getColorSpaceNames(ocio.SEARCH_REFERENCE_SPACE_ALL, ocio.COLORSPACE_ALL))
    assert set(lazy.makers) == names and len(lazy) == 0
    assert lazy["ACEScg"].name == "ACEScg" and list(lazy) == ["ACEScg"]
    assert "ACEScg" in lazy and "No Such Space" not in lazy and lazy.get("No Such Space") is None
    with pytest.raises(KeyError):
        lazy["No Such Space"]


def test_a_view_is_named_for_its_gamut_mapping_method():
    assert paths.view_method("Colorimetric") == "clip"
    assert paths.view_method("Raw") is None
    assert {paths.view_method(v) for v in ("Scale", "Desaturate", "Perceptual", "RGC")} == {
        "scale",
        "desaturate",
        "perceptual",
        "rgc",
    }
