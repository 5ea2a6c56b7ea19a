"""ocioforge info: a colour space's or display's gamut, white, curve and matrices, of the library
or of a spec, and how each OCIO version expresses a space."""

import numpy as np
import pytest

from tests.cli.conftest import SHOW, run


def test_info_gives_a_spaces_gamut_grey_and_how_each_version_expresses_it(capsys):
    code, out, _ = run(capsys, "info", "arri_logc4")
    assert code == 0 and "ARRI Wide Gamut 4" in out and "18% grey:  code 0.278396" in out
    assert "OCIO 2.1: analytic (LogCamera)" in out
    _, out, _ = run(capsys, "info", "canonlog3_cinemagamut_d55")
    assert "OCIO 2.1: baked 1D LUT" in out and "OCIO 2.2: analytic (BuiltinTransform)" in out


@pytest.mark.parametrize(
    "name, how",
    [
        ("ARRI LogC4", "(CAT02, as its publisher)"),
        ("DaVinci Intermediate WideGamut", "(CAT02, as the ACES studio config)"),  # said: as its publisher
        ("ACEScg", "(the same white: no adaptation)"),  # said: Bradford, though AP1 and AP0 share ACES white
        ("sRGB Encoded Rec.709 (sRGB)", "(Bradford)"),
    ],
)
def test_info_says_how_and_on_whose_authority_a_gamut_adapts(capsys, name, how):
    code, out, _ = run(capsys, "info", name)
    assert code == 0 and f"to ACES2065-1 {how}:" in out, out


def test_info_takes_a_shows_own_space_with_its_reference_and_version(tmp_path, capsys):
    from generator import reference
    from generator.spec import load

    (tmp_path / "show.toml").write_text(
        'ocio_version = "2.3"\nscene_reference = "ACEScg"\nchromatic_adaptation = "CAT16"\n'
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "Wall"\naliases = ["led_wall"]\nprimaries = [[0.70, 0.29], [0.17, 0.80], [0.13, 0.05]]\n'
        'white = 6000\ntransfer = { family = "gamma", exponent = 2.4 }\n',
        encoding="utf-8",
    )
    spec = load.load(tmp_path / "show.toml")
    code, out, err = run(capsys, "info", "LED_wall", "--spec", str(tmp_path / "show.toml"))
    assert code == 0 and "name:      Wall" in out and "to ACEScg (CAT16):" in out, err
    rows = out.split("to ACEScg (CAT16):\n")[1].splitlines()[:3]
    assert np.allclose(
        [[float(v) for v in row.split()] for row in rows],
        reference.space_matrix(spec, spec.space("Wall")),
        rtol=0,
        atol=5e-11,
    )
    assert "OCIO 2.3: analytic (Power)  (the spec builds this version)" in out and out.count("the spec builds") == 1
    assert "(the spec builds" not in run(capsys, "info", "acescct")[1]
    code, _, err = run(capsys, "info", "arri_logc4", "--spec", str(tmp_path / "show.toml"))
    assert code == 2 and "no colour space 'arri_logc4' in show.toml" in err and err.count("\n") == 1, err


def test_info_describes_a_display_of_the_spec(capsys, show):
    from generator import reference

    code, out, err = run(capsys, "info", "led_wall", "--spec", str(SHOW))
    assert code == 0, err
    wall = show.displays[0]
    for line in (
        "name:      LED Wall  (a display)",
        "primaries: R (0.69150, 0.30720)  G (0.16820, 0.74090)  B (0.13650, 0.05260)",
        "white:     (0.31270, 0.32900)",
        "peak:      1500 cd/m²",
        "encoding:  hdr-video",
        "views:     ACES 2.0 - HDR 1500 nits (LED Wall), Scale, Raw",
    ):
        assert line in out.splitlines(), out
    assert "eotf:      ST 2084: the published formula, codes 0 to 1" in out.splitlines(), out
    to_xyz = out.split("to CIE XYZ-D65 - Display-referred (the same white: no adaptation):\n")[1].splitlines()[:3]
    assert np.allclose(
        [[float(v) for v in row.split()] for row in to_xyz],
        np.linalg.inv(reference.display_matrix(show, wall)),
        rtol=0,
        atol=5e-11,
    )
    scene = out.split("from ACES2065-1 (display-linear, 1.0 = 100 cd/m²):\n")[1].splitlines()[:3]
    assert np.allclose(
        [[float(v) for v in row.split()] for row in scene],
        reference.scene_to_display_matrix(show, wall),
        rtol=0,
        atol=5e-11,
    )


def test_info_describes_a_library_display_without_a_spec(capsys):
    code, out, _ = run(capsys, "info", "rec2100_pq_display")
    assert code == 0 and "name:      Rec.2100-PQ - Display  (a display)" in out and "peak:      1000 cd/m²" in out


@pytest.mark.parametrize(
    "argv, words",
    [
        (["info", "nothing_like_this"], "unknown colour space"),
        (["info", "Nope", "--spec", str(SHOW)], "no colour space 'Nope' in spec.toml, nor a display"),
        (["info", "LED Wall", "--spec", "missing.toml"], "cannot read the spec: it does not exist"),
    ],
)
def test_a_name_or_spec_that_is_not_there_is_one_line(capsys, tmp_path, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, *argv)
    assert code == 2 and err.startswith("error: ") and err.count("\n") == 1 and words in err, err
    assert out == "" and list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "name, encode",
    [
        ("ACEScct", "log_encoding_ACEScct"),
        ("ARRI LogC4", "log_encoding_ARRILogC4"),
        ("S-Log3 S-Gamut3", "log_encoding_SLog3"),
        ("V-Log V-Gamut", "log_encoding_VLog"),
    ],
)
def test_mid_grey_is_the_code_colour_science_encodes(capsys, name, encode):
    import colour

    code, out, _ = run(capsys, "info", name)
    line = next(line for line in out.splitlines() if line.startswith("18% grey:"))
    assert code == 0 and abs(float(line.split("code")[1]) - getattr(colour.models, encode)(0.18)) <= 5e-7, line


@pytest.mark.parametrize("name, gamut", [("ARRI LogC4", "ARRI Wide Gamut 4"), ("S-Log3 S-Gamut3", "S-Gamut3")])
def test_primaries_white_and_matrix_to_aces_are_colour_sciences(capsys, name, gamut):
    """Printed to five decimals (chromaticities) and ten (the matrix, CAT02 as the camera's maker
    adapts): colour-science's definitions of the gamut."""
    import re

    import colour

    published = colour.RGB_COLOURSPACES[gamut]
    code, out, err = run(capsys, "info", name)
    lines = {line.split(":")[0]: line for line in out.splitlines() if ":" in line}
    assert code == 0, err
    primaries = [float(v) for v in re.findall(r"-?\d+\.\d+", lines["primaries"])]
    white = [float(v) for v in re.findall(r"-?\d+\.\d+", lines["white"])]
    assert np.allclose(np.reshape(primaries, (3, 2)), published.primaries, rtol=0, atol=5e-6)
    assert np.allclose(white, published.whitepoint, rtol=0, atol=5e-6)
    rows = out.split("to ACES2065-1 (CAT02, as its publisher):\n")[1].splitlines()[:3]
    expected = colour.matrix_RGB_to_RGB(published, colour.RGB_COLOURSPACES["ACES2065-1"], "CAT02")
    assert np.allclose([[float(v) for v in row.split()] for row in rows], expected, rtol=0, atol=1e-9)


def test_a_data_space_has_no_gamut_and_no_transform_in_any_version(capsys):
    from generator.spec.allowed import newest_ocio_version

    code, out, err = run(capsys, "info", "raw")
    lines = out.splitlines()
    assert code == 0 and "name:      Raw" in lines and "encoding:  data" in lines, err
    assert not [line for line in lines if line.startswith(("gamut:", "primaries:", "curve:", "18% grey:", "to "))]
    versions = range(1, newest_ocio_version()[1] + 1)
    assert [line for line in lines if line.startswith("OCIO ")] == [
        f"OCIO 2.{m}: data (no transform)" for m in versions
    ]
