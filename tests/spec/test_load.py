"""The spec: strict parsing, custom spaces of every family, clear errors, the resolved JSON."""

import json
import tomllib
from pathlib import Path

import numpy as np
import pytest

from generator import reference, tolerances
from generator.colorimetry import transfer
from generator.spec import load, resolved
from generator.spec.schema import SpecError


def parse(text: str, base: Path = Path(".")):
    return load.parse(text, "show.toml", base)


def test_default_spec_loads_every_library_space_and_display(default_spec):
    from generator.colorimetry import library

    assert len(default_spec.colour_spaces) == len(library.SPACES)
    assert [d.name for d in default_spec.displays] == [d.name for d in library.DISPLAYS]
    assert default_spec.ocio_version == (2, 1)
    assert default_spec.reference.name == "ACES2065-1"


def test_sdr_displays_offer_desaturate_by_default_and_hdr_displays_on_request(default_spec):
    """The issue's default: clip and desaturate on every SDR display (with scale, rgc and raw);
    HDR displays leave Desaturate's 1 MB file out unless their spec names it."""
    for display in default_spec.displays:
        assert ("Desaturate" in display.views) == (not display.is_hdr)
        assert {"Colorimetric", "Scale", "RGC", "Raw"} <= set(display.views)
    base = '[[display]]\nname = "Custom"\ngamut = "Rec.709"\n'
    assert parse(base + 'eotf = "sRGB"').displays[0].views == load.DEFAULT_VIEWS
    assert parse(base + 'eotf = "ST 2084"\npeak_luminance = 1000').displays[0].views == load.DEFAULT_HDR_VIEWS
    assert (
        "Desaturate"
        in parse('[[display]]\nname = "Rec.2100-PQ - Display"\nviews = ["Colorimetric", "Desaturate"]')
        .displays[0]
        .views
    )


@pytest.mark.parametrize(
    "transfer, encoding",
    [
        ('"linear"', "scene-linear"),
        ('{ family = "gamma", exponent = 2.2 }', "sdr-video"),
        (
            '{ family = "log_camera", base = 10, log_side_slope = 0.25, log_side_offset = 0.4, lin_side_slope = 5.0, '
            "lin_side_offset = 0.05, lin_side_break = 0.01 }",
            "log",
        ),
    ],
)
def test_a_custom_spaces_encoding_follows_its_transfer_unless_given(transfer, encoding):
    text = f'[[custom_space]]\nname = "C"\ngamut = "Rec.709"\ntransfer = {transfer}\n'
    space = parse(text).space("C")
    assert space.encoding == encoding
    assert parse(text + 'encoding = "data"\n').space("C").encoding == "data"


@pytest.mark.parametrize(
    "text, field, words",
    [
        ("colour_space = ['ACEScg']", "colour_space", "allowed: name"),
        ("colour_spaces = ['ACEScgg']", "colour_spaces[0]", "did you mean 'ACEScg'"),
        ("ocio_version = '1.3'", "ocio_version", "allowed: 2.1 to"),
        ("ocio_version = 'two'", "ocio_version", "allowed"),
        ("ocio_version = '２.１'", "ocio_version", "expected a version like"),
        (
            "[[custom_space]]\nname = 'x'\ngamut = 'Rec.709'\ntransfer = { family = 'log_camera', base = 10, "
            "log_side_slope = 1e-6, log_side_offset = 0.4, lin_side_slope = 5.0, lin_side_offset = 0.05 }",
            "custom_space[0].transfer",
            "OCIO evaluates a log_camera curve in float32, which departs inf",
        ),
        (
            "[[custom_space]]\nname = 'x'\ngamut = 'Rec.709'\ntransfer = { family = 'log_camera', base = 10, "
            "log_side_slope = 0.25, log_side_offset = 0.4, lin_side_slope = 5.0, lin_side_offset = 0.05, "
            "lin_side_break = 100 }",
            "custom_space[0].transfer",
            "which departs 0.00051 relative",
        ),
        (
            "[[custom_space]]\nname = 'x'\ngamut = 'Rec.709'\ntransfer = { family = 'log_camera', base = 2, "
            "log_side_slope = 0.06, log_side_offset = 0.55, lin_side_slope = 1.0, lin_side_offset = 0.0 }",
            "custom_space[0].transfer.lin_side_offset",
            "leaves black without a code",
        ),
        (
            "[[custom_space]]\nname = 'x'\ngamut = 'Rec.709'\ntransfer = { family = 'log_camera', base = 2, "
            "log_side_slope = 0.06, log_side_offset = 0.55, lin_side_slope = 1.0, lin_side_offset = 1e-6 }",
            "custom_space[0].transfer.lin_side_offset",
            "so near the log's pole that float32's rounding of linear 0",
        ),
        ("ocio_version = '2.01'", "ocio_version", "expected a version like"),
        ("ocio_version = ' 2.1'", "ocio_version", "expected a version like"),
        ("chromatic_adaptation = 'Sharp'", "chromatic_adaptation", "allowed: Bradford"),
        ("scene_reference = 'Nope'", "scene_reference", "not among"),
        ("[roles]\nscene_linear = 'Nope'", "roles.scene_linear", "not among"),
        (
            "colour_spaces = ['ACES2065-1', 'ACEScg', 'sRGB Encoded Rec.709 (sRGB)', 'Raw']",
            "roles.compositing_log",
            "the default target 'ACEScct' is not among the colour spaces; allowed: list it in colour_spaces, or set",
        ),
        ("[[display]]\nname = 'sRGB'", "display[0].name", "did you mean 'sRGB - Display'"),
        ("[[display]]\nname = 'sRGB - Display'\nviews = ['Filmic']", "display[0].views[0]", "allowed: Colorimetric"),
        (
            "[[custom_space]]\nname = 'x'\nprimaries = [[0.7, 0.3], [0.2, 0.7]]\nwhite = 'D65'",
            "custom_space[0].primaries",
            "three chromaticities",
        ),
        (
            "[[custom_space]]\nname = 'x'\ngamut = 'Rec.709'\ntransfer = 'S-Log9'",
            "custom_space[0].transfer",
            "did you mean 'S-Log3'",
        ),
        (
            "[[custom_space]]\nname = 'x'\ngamut = 'Rec.709'\ntransfer = {family = 'cubic'}",
            "custom_space[0].transfer.family",
            "allowed: linear, gamma",
        ),
        (
            "[[custom_space]]\nname = 'x'\ngamut = 'Rec.709'\ntransfer = {family = 'gamma', exponent = 2.2, offset = 1}",
            "custom_space[0].transfer.offset",
            "allowed: exponent",
        ),
        (
            "[[custom_space]]\nname = 'x'\nprimaries = [[0.64, 0.33], [0.3, 0.6], [0.15, 0.06]]\nwhite = 'D66'",
            "custom_space[0].white",
            "did you mean",
        ),
        (
            "[[custom_space]]\nname = 'ACEScg'\ngamut = 'Rec.709'",
            "custom_space[0].name",
            "'ACEScg' already names the library colour space 'ACEScg' of colour_spaces",
        ),
        ("display = 5", "display", "expected an array of tables ([[display]])"),
        ("[custom_space]\nname = 'x'", "custom_space", "expected an array of tables ([[custom_space]])"),
        ("[[display]]\nname = ''\ngamut = 'Rec.709'\neotf = 'sRGB'", "display[0].name", "required"),
        (
            "[[display]]\nname = 'sRGB - Display'\nviews = ['Raw', 'Colorimetric', 'Raw']",
            "display[0].views[2]",
            "listed twice",
        ),
        (
            "[[display]]\nname = 'sRGB - Display'\n[[display]]\nname = 'srgb - display'",
            "display[1].name",
            "'sRGB - Display' is listed twice (display[0]); allowed: each display once",
        ),
        ("[[file_rule]]\nname = 'Default'", "file_rule[0].colour_space", "required"),
        (
            "[[display]]\nname = 'Wall'\ngamut = 'Rec.709'\neotf = 'gamma 2.4'\npeak_luminance = 1500",
            "display[0].peak_luminance",
            "1500 cd/m² is outside what a Gamma 2.4 display takes; allowed: 100 to 10000",
        ),
        (
            "[[display]]\nname = 'Wall'\ngamut = 'Rec.709'\neotf = 'gamma 2.4'\npeak_luminance = 20000\n"
            "absolute_luminance = true",
            "display[0].peak_luminance",
            "1 to 10000",
        ),
        (
            "[[display]]\nname = 'Wall'\ngamut = 'Rec.2020'\neotf = 'ST 2084'\nabsolute_luminance = true",
            "display[0].absolute_luminance",
            "allowed: absolute_luminance with an SDR eotf",
        ),
        (
            "[[display]]\nname = 'Wall'\ngamut = 'Rec.709'\neotf = 'gamma 2.4'\nabsolute_luminance = 'yes'",
            "display[0].absolute_luminance",
            "true or false",
        ),
        (
            "[[display]]\nname = 'sRGB - Display'\npeak_luminance = 200",
            "display[0].peak_luminance",
            "is a library display, whose peak_luminance is fixed",
        ),
        ("[[display]]\nname = 'sRGB - Display'\nwhite = 'D50'", "display[0].white", "allowed: name, views here"),
        ("[[display]]\nname = 'sRGB - Display'\naliases = ['monitor']", "display[0].aliases", "allowed: name, views"),
        ("[[display]]\nname = 'sRGB - Display'\nviews = []", "display[0].views", "empty; allowed: one or more"),
        ("[[display]]\nname = 'Projector'\ngamut = 'P3-D65'", "display[0].eotf", "required for a custom display"),
        ("display = []", "display", "no displays"),
        (
            "[[display]]\nname = 'sRGB - Display'\ngamut = 'P3-D65'\neotf = 'gamma 2.2'",
            "display[0].name",
            "names the library display 'sRGB - Display', whose gamut and eotf are fixed; allowed: another name",
        ),
        (
            "[[display]]\nname = 'Wall'\naliases = ['srgb_display']\ngamut = 'P3-D65'\neotf = 'gamma 2.2'",
            "display[0].aliases",
            "names the library display 'sRGB - Display'",
        ),
        ("[[custom_space]]\nname = 'Log, A'\ngamut = 'Rec.709'", "custom_space[0].name", "holds a comma"),
        ("[[display]]\nname = 'Wall, Left'\ngamut = 'Rec.709'\neotf = 'sRGB'", "display[0].name", "holds a comma"),
        (
            "[[custom_space]]\nname = 'x'\naliases = ['a,b']\ngamut = 'Rec.709'",
            "custom_space[0].aliases[0]",
            "holds a comma",
        ),
        ("chromatic_adaptation = ['Bradford']", "chromatic_adaptation", "allowed: Bradford"),
        ("scene_reference = 'Raw'", "scene_reference", "allowed: a scene-linear colour space"),
        ("scene_reference = 'ACEScct'", "scene_reference", "'ACEScct' is log"),
        (
            "scene_reference = 'Cam'\n[[custom_space]]\nname = 'Cam'\ngamut = 'Rec.709'\nencoding = 'scene-linear'\n"
            "transfer = { family = 'gamma', exponent = 2.2 }",
            "scene_reference",
            "labelled scene-linear but has a transfer",
        ),
        ("[[custom_space]]\nname = '  '\ngamut = 'Rec.709'", "custom_space[0].name", "visible character"),
        ("[[custom_space]]\nname = 'x'\naliases = ['']\ngamut = 'Rec.709'", "custom_space[0].aliases[0]", "blank"),
        (
            "[[file_rule]]\nname = 'A'\ncolour_space = 'ACEScg'\nextension = 'exr'\n[[file_rule]]\nname = 'A'\n"
            "colour_space = 'ACEScg'\n[[file_rule]]\nname = 'Default'\ncolour_space = 'ACEScg'",
            "file_rule[1].name",
            "names an earlier rule too",
        ),
        (
            "[[file_rule]]\nname = 'Default'\ncolour_space = 'ACEScg'\nextension = 'exr'",
            "file_rule[0].extension",
            "the Default rule matches every file",
        ),
        (
            "[[file_rule]]\nname = 'A'\ncolour_space = 'ACEScg'\npattern = '[abc'\n[[file_rule]]\nname = 'Default'\n"
            "colour_space = 'ACEScg'",
            "file_rule[0].pattern",
            "OpenColorIO cannot read it",
        ),
        (
            "[[display]]\nname = 'HLG P3'\ngamut = 'P3-D65'\neotf = 'HLG'",
            "display[0].gamut",
            "BT.2020 primaries and D65",
        ),
        (
            "[[display]]\nname = 'HLG'\nprimaries = [[0.708, 0.292], [0.170, 0.797], [0.131, 0.046]]\nwhite = 6504\n"
            "eotf = 'HLG'",
            "display[0].white",
            "BT.2020 primaries and D65",
        ),
        (
            "[[file_rule]]\nname = 'ColorSpaceNamePathSearch'\ncolour_space = 'ACEScg'\n[[file_rule]]\nname = 'Default'\n"
            "colour_space = 'ACEScg'",
            "file_rule[0].name",
            "OCIO reserves 'ColorSpaceNamePathSearch'",
        ),
        (
            "[[file_rule]]\nname = 'A'\ncolour_space = 'ACEScg'\nregex = '.*(plate'\n[[file_rule]]\nname = 'Default'\n"
            "colour_space = 'ACEScg'",
            "file_rule[0].regex",
            "OpenColorIO cannot read it",
        ),
        (
            "[[file_rule]]\nname = 'A'\ncolour_space = 'ACEScg'\nregex = ''\n[[file_rule]]\nname = 'Default'\n"
            "colour_space = 'ACEScg'",
            "file_rule[0].regex",
            "regex is empty",
        ),
        (
            "[[file_rule]]\nname = 'A'\ncolour_space = 'ACEScg'\nregex = '.*exr'\nextension = 'exr'\n[[file_rule]]\n"
            "name = 'Default'\ncolour_space = 'ACEScg'",
            "file_rule[0].extension",
            "by its regex or by pattern and extension",
        ),
        (
            "[[file_rule]]\nname = 'Default'\ncolour_space = 'ACEScg'\nregex = '.*'",
            "file_rule[0].regex",
            "the Default rule matches every file",
        ),
        (
            'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
            'inactive = ["ACEScct", "acescct_ap1"]',
            "inactive[1]",
            "'acescct_ap1' names 'ACEScct', as inactive[0] does",
        ),
        ('inactive = ["Scale - Nope"]', "inactive[0]", "the display reference or a '<view> - <display>' space"),
        (
            'display_view_spaces = false\ninactive = ["Scale - sRGB - Display"]',
            "inactive[0]",
            "not among the colour spaces",
        ),
        (
            'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\ninactive = ["lin_ap1"]',
            "inactive[0]",
            "'lin_ap1' is the scene_linear role's colour space, which hosts take without asking",
        ),
        (
            'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\ninactive = ["Raw"]',
            "inactive[0]",
            "'Raw' is the data role's colour space",
        ),
        (
            'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\ninactive = ["ACEScct"]\n'
            '[[file_rule]]\nname = "Plates"\nextension = "dpx"\ncolour_space = "compositing_log"\n[[file_rule]]\n'
            'name = "Default"\ncolour_space = "default"',
            "inactive[0]",
            "the colour space of file rule 'Plates'",
        ),
        (
            'inactive = ["srgb_display"]',
            "inactive[0]",
            "'srgb_display' is a display's colour space (its views show through it)",
        ),
        (
            "[[display]]\nname = 'HLG'\nprimaries = [[0.68, 0.32], [0.265, 0.69], [0.15, 0.06]]\nwhite = 'D65'\neotf = 'HLG'",
            "display[0].primaries",
            'allowed: gamut = "Rec.2020"',
        ),
        ("name = = 1", "-", "not valid TOML"),
        (
            "[[display]]\nname = 'Wide'\nprimaries = [[0.73, 0.28], [0.14, 0.86], [0.10, -0.03]]\nwhite = 'D65'\n"
            "eotf = 'sRGB'",
            "display[0].primaries",
            "the blue primary (x 0.1, y -0.03) gives -0.",
        ),
        (
            "[[display]]\nname = 'Wide'\nprimaries = [[0.73, 0.28], [0.14, 0.86], [0.10, 0.001]]\nwhite = 'D65'\n"
            "eotf = 'sRGB'",
            "display[0].primaries",
            "needs at least 0.005; allowed: such primaries, or views without Desaturate",
        ),
        (
            "[[display]]\nname = 'Wall'\ngamut = 'Rec.709'\neotf = { family = 'gamma', exponent = 0.3 }",
            "display[0].eotf",
            "the Perceptual view needs an exponent of at least 1, got 0.3",
        ),
        ("[rgc]\nlimits = [1.0, 1.4, 1.3]", "rgc.limits[0]", "allowed: 1.001 to 65504"),  # OCIO refuses the config
        ("[rgc]\nthresholds = [0.5, 0.9996, 0.5]", "rgc.thresholds[1]", "allowed: 0 to 0.9995"),
        ("[rgc]\npower = 0.9", "rgc.power", "allowed: 1 to 65504"),
        ("[rgc]\npower = 'a'", "rgc.power", "expected a finite number"),
        ("[rgc]\nlimits = [1.5, 1.4]", "rgc.limits", "expected three numbers [cyan, magenta, yellow]"),
        ("[rgc]\nlimit = 1.5", "rgc.limit", "allowed: limits, thresholds, power"),
        ("rgc = 3", "rgc", "expected a table"),
        (
            "[[display]]\nname = 'sRGB - Display'\nviews = ['ACES 2.0 - HDR 1000 nits (P3 D65)']",
            "display[0].views[0]",
            "cannot show 'ACES 2.0 - HDR 1000 nits (P3 D65)': it is an HDR view",
        ),
        (
            "[[display]]\nname = 'sRGB - Display'\nviews = ['ACES 2.0 - SDR 100 nits (P3 D65)']",
            "display[0].views[0]",
            "limiting red and green primaries lie outside the display's gamut",
        ),
        (
            "[[display]]\nname = 'sRGB - Display'\nviews = ['ACES 2.0 - SDR 100 nits (Rec.7090)']",
            "display[0].views[0]",
            "unknown ACES view 'ACES 2.0 - SDR 100 nits (Rec.7090)'",
        ),
        ("[[display]]\nname = 'sRGB - Display'\nviews = ['ACES 9']", "display[0].views[0]", "unknown view 'ACES 9'"),
        (
            "[[display]]\nname = 'sRGB - Display'\nviews = ['ACES 2.0', 'ACES 2.0 - SDR 100 nits (Rec.709)']",
            "display[0].views[1]",
            "listed twice",
        ),
        (
            "[[display]]\nname = 'Dim'\ngamut = 'Rec.709'\neotf = 'Gamma 2.4'\nabsolute_luminance = true\n"
            "peak_luminance = 48\nviews = ['ACES 2.0']",
            "display[0].views[0]",
            "own ACES 2.0 view cannot be made: peak_luminance must be a whole number",
        ),
        (
            "[[display]]\nname = 'Swapped'\nprimaries = [[0.15, 0.06], [0.3, 0.6], [0.64, 0.33]]\nwhite = 'D65'\n"
            "eotf = 'ST 2084'\nviews = ['ACES 2.0']",
            "display[0].views[0]",
            "limiting_primaries must be red, green and blue",
        ),
    ],
)
def test_bad_specs_name_the_field_and_what_is_allowed(text, field, words):
    with pytest.raises(SpecError) as error:
        parse(text)
    assert error.value.field == field
    assert words in error.value.message
    assert "\n" not in str(error.value)


def test_custom_spaces_of_every_family(tmp_path):
    (tmp_path / "curve.csv").write_text("code,linear\n0,0\n0.5,0.2\n1,1\n")
    text = """
colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw",
                 "CIE XYZ-D65 - Scene-referred"]
[[custom_space]]
name = "Gamma"
gamut = "Rec.2020"
transfer = { family = "gamma", exponent = 2.6 }
[[custom_space]]
name = "Piecewise"
primaries = [[0.64, 0.33], [0.3, 0.6], [0.15, 0.06]]
white = 6504
transfer = { family = "piecewise_gamma", gamma = 2.4, offset = 0.055 }
[[custom_space]]
name = "Log"
primaries = [[0.73, 0.28], [0.14, 0.86], [0.10, -0.03]]
white = [0.3127, 0.329]
encoding = "log"
transfer = { family = "log_camera", base = 10, log_side_slope = 0.25, log_side_offset = 0.4, lin_side_slope = 5.0, lin_side_offset = 0.05, lin_side_break = 0.01 }
[[custom_space]]
name = "Table"
gamut = "P3-D65"
transfer = { family = "tabulated", file = "curve.csv" }
"""
    spec = parse(text, tmp_path)
    assert isinstance(spec.space("Gamma").curve, transfer.Power)
    assert isinstance(spec.space("Piecewise").curve, transfer.PiecewisePower)
    assert isinstance(spec.space("Log").curve, transfer.LogCamera)
    assert spec.space("Table").curve.decode(np.array(0.5)) == pytest.approx(0.2)
    # A CCT of 6504 K gives the daylight locus near D65.
    assert np.allclose(spec.space("Piecewise").gamut.whitepoint, (0.3127, 0.329), atol=2e-4)


def test_white_and_primaries_from_spectra(tmp_path):
    import colour

    wl = np.arange(380, 781, 1)
    d65 = colour.SDS_ILLUMINANTS["D65"]
    (tmp_path / "d65.csv").write_text("".join(f"{w},{d65[w]}\n" for w in wl))
    rows = [(w, float(w == 610), float(w == 540), float(w == 465)) for w in wl]
    (tmp_path / "leds.csv").write_text("".join(f"{w},{r},{g},{b}\n" for w, r, g, b in rows))
    spec = parse(
        'colour_spaces = ["ACES2065-1", "Raw", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)"]\n'
        '[[custom_space]]\nname = "LED wall"\nprimaries_spectra = "leds.csv"\nwhite = "d65.csv"\n'
        '[[display]]\nname = "LED Wall Display"\nprimaries_spectra = "leds.csv"\nwhite = "d65.csv"\n'
        'eotf = "Gamma 2.4"\n',
        tmp_path,
    )
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"]
    red = colour.XYZ_to_xy(cmfs[610])
    # A custom space's primaries and a custom display's (the wall as the camera sees it and as it shows).
    for gamut in (spec.space("LED wall").gamut, spec.displays[0].gamut):
        assert np.allclose(gamut.whitepoint, (0.3127, 0.3290), atol=2e-4)
        assert np.allclose(gamut.primaries[0], red, atol=1e-6)


def test_missing_file_is_a_spec_error(tmp_path):
    with pytest.raises(SpecError, match="does not exist"):
        parse(
            "[[custom_space]]\nname = 'x'\ngamut = 'Rec.709'\ntransfer = {family = 'tabulated', file = 'no.csv'}",
            tmp_path,
        )


def test_an_absolute_sdr_display_puts_code_1_at_its_peak():
    """An LED wall at 1500 cd/m² with a 2.4 power: display-referred 1.0 (100 cd/m²) is code
    (100 / 1500) ** (1 / 2.4), its peak code 1; the resolved spec keeps it."""
    text = (
        "[[display]]\nname = 'Wall'\ngamut = 'Rec.709'\neotf = 'gamma 2.4'\npeak_luminance = 1500\n"
        "absolute_luminance = true"
    )
    wall = parse(text).displays[0]
    assert (wall.absolute, wall.is_hdr, wall.clip_high, wall.code_one) == (True, False, 15.0, 15.0)
    light = np.array([[1.0, 1.0, 1.0], [15.0, 15.0, 15.0], [0.0, 0.0, 0.0]])
    codes = reference.display_encode(wall, light)
    assert np.allclose(codes[:, 0], [(100.0 / 1500.0) ** (1 / 2.4), 1.0, 0.0], rtol=0, atol=tolerances.FORMULA_ABSOLUTE)
    assert np.allclose(reference.display_decode(wall, codes), light, rtol=0, atol=tolerances.FORMULA_ABSOLUTE)
    relative = parse(text.replace("peak_luminance = 1500\nabsolute_luminance = true", "")).displays[0]
    assert (relative.absolute, relative.code_one) == (False, 1.0)
    assert resolved.loads(resolved.dumps(parse(text))).displays[0] == wall


def test_resolved_spec_round_trips_and_evaluates_identically(default_spec):
    again = resolved.loads(resolved.dumps(default_spec))
    assert resolved.dumps(again) == resolved.dumps(default_spec)
    codes = np.linspace(0, 1, 11)[:, None] * [1, 1, 1]
    for space in (s for s in default_spec.colour_spaces if not s.is_data):
        assert np.array_equal(
            reference.to_reference(default_spec, space, codes),
            reference.to_reference(again, again.space(space.name), codes),
        ), space.name


def test_embedded_default_is_the_documented_file():
    assert load.parse(load.default_text(), "<default>", Path(".")) == load.load()


def test_a_key_left_out_takes_the_embedded_default_specs_value(monkeypatch):
    """display_view_spaces left out is what the default spec (and so ocioforge init) says, not
    false; the value is read from the embedded default, so the two cannot drift apart."""
    text = 'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
    assert load.embedded_default("display_view_spaces") is True
    assert parse(text).display_view_spaces is True
    assert parse(text + "display_view_spaces = false\n").display_view_spaces is False
    flipped = load.default_text().replace("display_view_spaces = true", "display_view_spaces = false")
    monkeypatch.setattr(load, "default_text", lambda: flipped)
    assert parse(text).display_view_spaces is False


def test_file_rules_left_out_are_the_embedded_defaults_and_cover_both_jpeg_suffixes():
    """A spec without file rules gets the default spec's (there was a second, different copy),
    and a built config sends .jpeg as .jpg to the texture space."""
    import PyOpenColorIO as ocio

    from generator.ocio.emit import emit

    text = 'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
    assert parse(text).file_rules == load.load().file_rules
    config = emit(load.load()).config

    def resolved(path):
        return config.getColorSpace(config.getColorSpaceFromFilepath(path)[0]).getName()

    texture = config.getColorSpace(ocio.ROLE_TEXTURE_PAINT).getName()
    for path in ("plate.jpg", "plate.jpeg", "plate.JPEG"):
        assert resolved(path) == texture, path
    assert resolved("plate.exr") == config.getColorSpace(ocio.ROLE_SCENE_LINEAR).getName()


def test_inactive_spaces_are_written_by_their_own_names_generated_ones_too():
    """OCIO hides no colour space that its alias names in inactive_colorspaces (it logs and shows it),
    and a build's display reference and '<view> - <display>' spaces are colour spaces a TD may
    hide too."""
    spec = parse(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        'inactive = ["acescct_ap1", "scale - srgb - display", "cie_xyz_d65_display", '
        '"Colorimetric - Gamma 2.6 DCI-P3 - Display"]'
    )
    assert spec.inactive == (
        "ACEScct",
        "Scale - sRGB - Display",
        "CIE XYZ-D65 - Display-referred",
        "Colorimetric - Gamma 2.6 DCI-P3 - Display",
    )
    assert resolved.loads(resolved.dumps(spec)) == spec


def test_a_file_rule_matches_by_a_regex_or_by_a_glob():
    text = (
        '[[file_rule]]\nname = "Plates"\nregex = \'.*/plates/.*\\.dpx$\'\ncolour_space = "ACEScct"\n'
        '[[file_rule]]\nname = "EXR"\nextension = "exr"\ncolour_space = "ACEScg"\n'
        '[[file_rule]]\nname = "Default"\ncolour_space = "default"\n'
    )
    spec = parse(text)
    assert [(r.pattern, r.extension, r.regex) for r in spec.file_rules] == [
        ("", "", r".*/plates/.*\.dpx$"),
        ("*", "exr", ""),
        ("*", "*", ""),
    ]
    stored = json.loads(resolved.dumps(spec))["file_rules"]
    assert [sorted(r) for r in stored] == [
        ["colour_space", "name", "regex"],
        *[["colour_space", "extension", "name", "pattern"]] * 2,
    ]
    assert resolved.loads(resolved.dumps(spec)) == spec


def test_an_extension_with_its_dot_is_refused():
    """OCIO puts a dot before a rule's extension: '.exr' matched only names ending in '..exr', so
    every EXR fell through to the Default rule and was read as sRGB, without a word."""
    text = (
        '[[file_rule]]\nname = "EXR"\nextension = ".exr"\ncolour_space = "ACEScg"\n'
        '[[file_rule]]\nname = "Default"\ncolour_space = "default"\n'
    )
    with pytest.raises(SpecError) as error:
        parse(text)
    assert error.value.field == "file_rule[0].extension" and "allowed: the extension without its dot, 'exr'" in str(
        error.value
    )


@pytest.mark.parametrize(
    "role, near",
    [("scene_lienar", "scene_linear"), ("colour_picking", "color_picking"), ("Texture_Pain", "texture_paint")],
)
def test_a_misspelt_role_is_refused_and_a_custom_one_kept(role, near):
    """A misspelt role had been written as a custom role beside the one meant, which kept its default:
    the TD's scene_linear never took. A custom role spelt unlike any known one is kept."""
    with pytest.raises(SpecError) as error:
        parse(f'[roles]\n{role} = "ACEScct"\n')
    assert error.value.field == f"roles.{role}" and f"did you mean {near!r}" in str(error.value)
    assert ("plate_linear", "ACEScg") in parse('[roles]\nplate_linear = "ACEScg"\n').roles


def test_a_role_naming_a_display_says_what_is_allowed():
    with pytest.raises(SpecError) as error:
        parse('[roles]\ncolor_picking = "sRGB - Display"\n')
    assert "allowed: a colour space of colour_spaces or custom_space" in str(error.value)


def test_a_spec_loaded_for_one_space_is_checked_whole():
    """bake loads a spec keeping only the spaces it uses: a spec build accepts must load (an inactive
    space left out is no error), and one build refuses must not (an unknown space left out is)."""
    text = 'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw", "ADX10"]\n'
    whole = parse(text + 'inactive = ["ADX10"]\n')
    kept = load.parse(text + 'inactive = ["ADX10"]\n', "show.toml", Path("."), keep=("ACEScg",))
    assert whole.inactive == ("ADX10",) and kept.inactive == ()
    assert "ADX10" not in {s.name for s in kept.colour_spaces}
    with pytest.raises(SpecError) as error:
        load.parse(text.replace('"ADX10"', '"ADX11"'), "show.toml", Path("."), keep=("ACEScg",))
    assert error.value.field == "colour_spaces[5]"


def test_the_resolved_spec_records_the_spec_files_name_alone(tmp_path, monkeypatch):
    """The same spec builds the same bytes however its path is typed, and no path is written."""
    (tmp_path / "show.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", '
        '"sRGB Encoded Rec.709 (sRGB)", "Raw"]\n[[custom_space]]\nname = "Wall"\n'
        'primaries = [[0.68, 0.31], [0.2, 0.72], [0.14, 0.05]]\nwhite = "D65"\n'
    )
    monkeypatch.chdir(tmp_path)
    typed = resolved.dumps(load.load("show.toml"))
    assert resolved.dumps(load.load(tmp_path / "show.toml")) == typed
    assert str(tmp_path) not in typed and '"custom, show.toml"' in typed


def test_a_spec_saved_with_a_byte_order_mark_loads(tmp_path):
    (tmp_path / "show.toml").write_bytes(b"\xef\xbb\xbfname = 'bom'\n")
    assert load.load(tmp_path / "show.toml").name == "bom"


def test_a_library_display_may_be_named_by_an_alias():
    assert (
        parse('[[display]]\nname = "srgb_display"\nviews = ["Colorimetric", "Raw"]').displays[0].name
        == "sRGB - Display"
    )


def test_the_reference_role_follows_the_scene_reference_unless_set():
    """OCIO 2.1's ociocheck warns of a config without the reference role."""
    assert ("reference", "ACES2065-1") in parse("").roles
    assert ("reference", "ACEScg") in parse("scene_reference = 'ACEScg'").roles
    assert ("reference", "ACEScg") in parse("[roles]\nreference = 'ACEScg'").roles
    assert ("reference", "ACEScg") in parse("[roles]\nReference = 'ACEScg'").roles  # OCIO keeps roles in lower case


#: A spec without a data space (its data role on a space that converts).
NO_RAW = (
    'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)"]\n[roles]\ndata = "ACEScg"\n'
)


@pytest.mark.parametrize(
    "text, field",
    [
        # a display's default views hold Raw, and no colour space is data: the build raised OCIO's
        # "a non-empty color space name is needed" as a traceback
        (f"{NO_RAW}[[display]]\nname = 'sRGB - Display'", "display[0].views"),
        (f"{NO_RAW}[[display]]\nname = 'sRGB - Display'\nviews = ['Colorimetric', 'Raw']", "display[0].views"),
        # hosts read a file of the data role unconverted: a space that converts cannot be it
        ("[roles]\ndata = 'ACEScg'", "roles.data"),
        # nor can a custom space labelled data, which still converts by its gamut and transfer
        (
            "[[custom_space]]\nname = 'Mattes'\ngamut = 'Rec.709'\nencoding = 'data'\n[roles]\ndata = 'Mattes'",
            "roles.data",
        ),
    ],
)
def test_raw_and_the_data_role_need_a_data_colour_space(text, field):
    with pytest.raises(SpecError) as error:
        parse(text)
    assert error.value.field == field and "allowed:" in str(error.value) and "'Raw'" in str(error.value)
    with_raw = 'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
    assert ("data", "Raw") in parse(f"{with_raw}[[display]]\nname = 'sRGB - Display'").roles


def test_the_rgc_table_sets_the_compressions_parameters_each_defaulting_to_aces_13():
    from generator.gamut import RGCParams

    assert parse("").rgc == RGCParams()
    spec = parse("[rgc]\nlimits = [1.5, 1.4, 1.3]\nthresholds = [0.6, 0.7, 0.75]\npower = 1.5")
    assert spec.rgc.as_ocio_params() == [1.5, 1.4, 1.3, 0.6, 0.7, 0.75, 1.5]
    assert parse("[rgc]\npower = 2").rgc == RGCParams(power=2.0)


@pytest.mark.parametrize("make", ["device", "pipe"])
def test_a_spec_that_is_a_device_or_a_pipe_is_refused_unread(tmp_path, make):
    """/dev/zero was read until memory ran out, and a named pipe waited for a writer forever."""
    import os

    if make == "device":
        path = Path("/dev/zero")
    else:
        path = tmp_path / "show.toml"
        os.mkfifo(path)
    with pytest.raises(SpecError, match="is not a regular file"):
        load.load(path)


SPACES = 'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
CUSTOM = "[[custom_space]]\nname = {name}\ngamut = 'Rec.709'\n"
RULES = "[[file_rule]]\nname = {name}\ncolour_space = 'ACEScg'\n{extra}\n[[file_rule]]\nname = 'Default'\ncolour_space = 'ACEScg'\n"


#: Where the spec gives a name of the config: the TOML giving the TOML string ``n`` there, and the field.
NAME_PLACES = [
    (lambda n: CUSTOM.format(name=n), "custom_space[0].name"),
    (lambda n: CUSTOM.format(name="'x'") + f"aliases = [{n}]", "custom_space[0].aliases[0]"),
    (lambda n: f"[[display]]\nname = {n}\ngamut = 'Rec.709'\neotf = 'sRGB'", "display[0].name"),
    (lambda n: f"[roles]\n{n} = 'ACEScg'", "roles.{quoted}"),
]
#: Names OCIO cannot carry as given: control characters (its strings end at NUL, so two spaces would
#: merge; DEL and C1 are no text either), spaces at either end (it trims them), and $ and % (context
#: variables, an exception in colour-space and role names).
BAD_NAMES = [
    ('"a\\u0000b"', "control character '\\x00'"),
    ('"a\\u0001b"', "control character '\\x01'"),
    ('"a\\u007fb"', "control character '\\x7f'"),
    ('"a\\u0085b"', "control character '\\x85'"),
    ("' A'", "space at either end, which OCIO trims"),
    ("'A '", "space at either end"),
    ("'A$B'", "holds '$', which OCIO reads as a context variable"),
    ("'a%b'", "holds '%'"),
]


@pytest.mark.parametrize("name, words", BAD_NAMES)
@pytest.mark.parametrize("place, field", NAME_PLACES)
def test_a_name_ocio_cannot_carry_is_refused_wherever_the_spec_gives_it(place, field, name, words):
    quoted = json.dumps(tomllib.loads(f"k = {name}")["k"], ensure_ascii=False)
    with pytest.raises(SpecError) as error:
        parse(place(name))
    assert (error.value.field, "\n" in str(error.value)) == (field.format(quoted=quoted), False)
    assert words in error.value.message


@pytest.mark.parametrize(
    "text, field, words",
    [
        (RULES.format(name='"A\\u0000"', extra="extension = 'exr'"), "file_rule[0].name", "control character"),
        (SPACES + 'inactive = ["ACEScct\\u0000"]', "inactive[0]", "control character"),
        ('name = "show\\u007f"', "name", "control character"),
        ('description = "a\\u0000b"', "description", "tabs and line breaks but no other control characters"),
        (RULES.format(name="'A '", extra="extension = 'exr'"), "file_rule[0].name", "space at either end"),
        (SPACES + 'inactive = [" ACEScct"]', "inactive[0]", "not among the colour spaces"),
        # Empty names and globs, which OCIO refuses with an exception.
        ("[roles]\n'' = 'ACEScg'", 'roles.""', "blank; required: a name with a visible character"),
        (RULES.format(name="''", extra="extension = 'exr'"), "file_rule[0].name", "blank"),
        (RULES.format(name="' '", extra="extension = 'exr'"), "file_rule[0].name", "blank"),
        (RULES.format(name="'A'", extra="pattern = ''"), "file_rule[0].pattern", "empty, which OCIO refuses"),
        (RULES.format(name="'A'", extra="extension = ''"), "file_rule[0].extension", "empty, which OCIO refuses"),
        # A TOML number as the version loses its digits (2.10 reads as 2.1); the string "2.10" is 2.10.
        ("ocio_version = 2.10", "ocio_version", 'expected a quoted version like "2.1", got 2.1'),
        ("ocio_version = 2", "ocio_version", "expected a quoted version"),
        ("ocio_version = '2.10'", "ocio_version", "2.10 is not supported; allowed: 2.1 to"),
        # A name given twice names the field that gives it second, and the first.
        (
            CUSTOM.format(name="'A'") + CUSTOM.format(name="'a'"),
            "custom_space[1].name",
            "'a' already names custom_space[0] 'A'",
        ),
        (
            CUSTOM.format(name="'A'") + "aliases = ['a']",
            "custom_space[0].aliases[0]",
            "'a' already names custom_space[0] 'A'",
        ),
        (
            SPACES + CUSTOM.format(name="'acescg'"),
            "custom_space[0].name",
            "'acescg' already names the library colour space 'ACEScg' of colour_spaces[1]",
        ),
        (
            'colour_spaces = ["ACES2065-1", "ACEScg", "lin_ap1", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]',
            "colour_spaces[2]",
            "'ACEScg' already names the library colour space 'ACEScg' of colour_spaces[1]",
        ),
        # Messages that say what is expected.
        ("custom_space = [1]", "custom_space[0]", "expected a table of name, aliases"),
        ("[roles]\nscene_linear = 5", "roles.scene_linear", "expected a string naming a colour space, got 5"),
    ],
)
def test_names_shapes_and_versions_ocio_cannot_take_name_the_field(text, field, words):
    with pytest.raises(SpecError) as error:
        parse(text)
    assert (error.value.field, "\n" in str(error.value)) == (field, False)
    assert words in error.value.message


@pytest.mark.parametrize(
    "display",
    [
        "gamut = 'CIE XYZ-E'\neotf = 'gamma 2.6'",  # a DCDM X'Y'Z' display: X and Z carry no luminance
        "gamut = 'Rec.709'\neotf = { family = 'gamma', exponent = 0.3 }",
    ],
)
def test_a_display_only_desaturate_or_perceptual_cannot_hold_takes_the_other_views(display):
    spec = parse(f"[[display]]\nname = 'Cinema'\n{display}\nviews = ['Colorimetric', 'Scale', 'RGC', 'Raw']")
    assert spec.displays[0].views == ("Colorimetric", "Scale", "RGC", "Raw")


def test_a_description_may_hold_tabs_and_line_breaks():
    assert parse('description = """\nline one\n\tline two\n"""').description == "line one\n\tline two\n"


@pytest.mark.parametrize("named", ["name = 'Linear'", "name = 'My Lin'\naliases = ['linear']"])
def test_a_space_called_linear_keeps_its_name_and_takes_the_linear_roles_place(named):
    """OpenImageIO 2.4 looks for "Linear": the default linear role (scene_linear's target) is
    left out where a colour space has that name, which built before the role existed."""
    spec = parse(f"[[custom_space]]\n{named}\ngamut = 'AP1'\n")
    assert "linear" not in dict(spec.roles) and spec.space("linear")
    assert dict(parse("").roles)["linear"] == dict(parse("").roles)["scene_linear"]
    assert dict(parse("[roles]\nscene_linear = 'ACES2065-1'").roles)["linear"] == "ACES2065-1"
