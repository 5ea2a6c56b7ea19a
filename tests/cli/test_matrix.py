"""ocioforge matrix: the 3x3 between two colour spaces' (or displays') linear RGB, as a config
converts, in four formats."""

import json

import numpy as np
import pytest

from tests.cli.conftest import SHOW, run


def test_matrix_formats_agree(capsys):
    from generator.colorimetry.gamuts import gamuts
    from generator.colorimetry.matrices import rgb_to_rgb

    expected = rgb_to_rgb(gamuts()["AP1"], gamuts()["Rec.709"], "Bradford")
    code, out, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--format", "json")
    assert code == 0 and np.allclose(json.loads(out)["matrix"], expected, rtol=0, atol=1e-15)
    _, plain, _ = run(capsys, "matrix", "ACEScg", "Linear Rec.709 (sRGB)")
    assert np.allclose(np.array(plain.split(), dtype=float).reshape(3, 3), expected, atol=1e-10)
    _, nuke, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--format", "nuke")
    assert nuke.startswith("ColorMatrix {") and "name lin_ap1_to_lin_rec709_srgb" in nuke
    _, snippet, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--format", "ocio")
    assert snippet.startswith("!<MatrixTransform>") and "1.705050992657" in snippet
    _, cat02, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--cat", "CAT02", "--format", "json")
    assert not np.allclose(json.loads(cat02)["matrix"], expected, atol=1e-6)


def test_matrix_reads_cat_in_any_case_and_gives_one_gamut_the_identity(capsys):
    _, lower, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--cat", "cat02", "--format", "json")
    _, upper, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--cat", "CAT02", "--format", "json")
    assert lower == upper
    code, out, _ = run(capsys, "matrix", "srgb", "lin_srgb", "--format", "json")
    assert code == 0 and json.loads(out)["matrix"] == np.eye(3).tolist()


def test_matrix_takes_a_shows_own_spaces_as_its_config_converts(tmp_path, capsys):
    from generator import reference
    from generator.spec import load

    (tmp_path / "show.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "ARRI LogC4", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "Caméra B"\nprimaries = [[0.70, 0.29], [0.17, 0.80], [0.13, 0.05]]\nwhite = "D65"\n',
        encoding="utf-8",
    )
    spec = load.load(tmp_path / "show.toml")
    code, out, err = run(
        capsys, "matrix", "Caméra B", "ACEScg", "--spec", str(tmp_path / "show.toml"), "--format", "json"
    )
    expected = np.linalg.solve(
        reference.space_matrix(spec, spec.space("ACEScg")), reference.space_matrix(spec, spec.space("Caméra B"))
    )
    assert code == 0 and np.allclose(json.loads(out)["matrix"], expected, rtol=0, atol=1e-15), err
    library = run(capsys, "matrix", "ARRI LogC4", "ACEScg", "--format", "json")[1]
    assert (
        run(capsys, "matrix", "ARRI LogC4", "ACEScg", "--format", "json", "--spec", str(tmp_path / "show.toml"))[1]
        == library
    )
    code, _, err = run(capsys, "matrix", "Nope", "ACEScg", "--spec", str(tmp_path / "show.toml"))
    assert code == 2 and "no colour space 'Nope' in show.toml" in err and err.count("\n") == 1, err


def test_matrix_takes_a_display_as_its_config_converts(capsys, show):
    from generator import reference

    wall = show.displays[0]
    code, out, err = run(capsys, "matrix", "LED Wall", "ACEScg", "--spec", str(SHOW), "--format", "json")
    expected = np.linalg.solve(
        reference.space_matrix(show, show.space("ACEScg")), np.linalg.inv(reference.scene_to_display_matrix(show, wall))
    )
    assert code == 0 and np.allclose(json.loads(out)["matrix"], expected, rtol=0, atol=1e-15), err
    # its RGB to XYZ and back, through the display reference (CIE XYZ-D65) by name or alias
    _, out, _ = run(capsys, "matrix", "led_wall", "cie_xyz_d65_display", "--spec", str(SHOW), "--format", "json")
    assert np.allclose(json.loads(out)["matrix"], np.linalg.inv(reference.display_matrix(show, wall)), atol=1e-15)
    _, out, _ = run(capsys, "matrix", "CIE XYZ-D65 - Display-referred", "LED Wall", "--spec", str(SHOW))
    assert np.allclose(np.array(out.split(), dtype=float).reshape(3, 3), reference.display_matrix(show, wall))
    # the wall's scene-linear working space has its gamut: the identity
    _, out, _ = run(capsys, "matrix", "Linear LED Wall", "LED Wall", "--spec", str(SHOW), "--format", "json")
    assert json.loads(out)["matrix"] == np.eye(3).tolist()


def test_matrix_takes_a_library_display_as_the_default_spec_converts(capsys):
    from generator.colorimetry.gamuts import gamuts
    from generator.colorimetry.matrices import rgb_to_rgb

    code, out, err = run(capsys, "matrix", "rec2100_pq_display", "acescg", "--format", "json")
    expected = rgb_to_rgb(gamuts()["Rec.2020"], gamuts()["AP1"], "Bradford")
    assert code == 0 and np.allclose(json.loads(out)["matrix"], expected, rtol=0, atol=1e-12), err


def test_matrix_refuses_a_display_the_spec_does_not_define(capsys):
    code, _, err = run(capsys, "matrix", "rec2100_pq_display", "acescg", "--spec", str(SHOW))
    assert code == 2 and "no colour space 'rec2100_pq_display' in spec.toml, nor a display" in err


@pytest.mark.parametrize(
    "argv, words",
    [
        (("matrix", "acescg", "lin_rec709", "--cat", "Sharp"), "allowed: Bradford"),
        (("matrix", "acescg", "raw"), "no RGB primaries"),
        (("matrix", "acescg"), "Missing argument"),
        (("matrix", "LED Wal", "acescg", "--spec", str(SHOW)), "(did you mean 'LED Wall'"),
        (("matrix", "LED Wall", "acescg"), "unknown colour space 'LED Wall'"),
    ],
)
def test_bad_arguments_exit_2_with_one_line(tmp_path, capsys, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, *argv)
    assert code == 2 and err.startswith("error: ") and err.count("\n") == 1 and words in err, err
    assert out == "" and list(tmp_path.iterdir()) == []


#: Each --cat and colour-science's name for the same chromatic adaptation transform.
CATS = {
    "Bradford": "Bradford",
    "CAT02": "CAT02",
    "CAT16": "CAT16",
    "von Kries": "Von Kries",
    "XYZ scaling": "XYZ Scaling",
    "none": None,
}


@pytest.mark.parametrize("cat", sorted(CATS))
def test_a_chosen_adaptation_gives_colour_sciences_matrix(capsys, cat):
    """ACEScg (ACES white) to linear Rec.709 (D65) with each --cat, against colour-science's
    conversion between its own definitions of the two spaces."""
    import colour

    spaces = colour.RGB_COLOURSPACES
    code, out, err = run(capsys, "matrix", "ACEScg", "Linear Rec.709 (sRGB)", "--cat", cat, "--format", "json")
    expected = colour.matrix_RGB_to_RGB(spaces["ACEScg"], spaces["ITU-R BT.709"], CATS[cat])
    assert code == 0 and np.allclose(json.loads(out)["matrix"], expected, rtol=0, atol=1e-12), err


@pytest.mark.parametrize(
    "space, gamut",
    [
        ("ARRI LogC4", "ARRI Wide Gamut 4"),
        ("S-Log3 S-Gamut3", "S-Gamut3"),
        ("DaVinci Intermediate WideGamut", "DaVinci Wide Gamut"),
    ],
)
def test_a_camera_gamut_reaches_aces_through_cat02_without_cat(capsys, space, gamut):
    """Without --cat, ARRI's, Sony's and Blackmagic's gamuts reach ACES2065-1 through CAT02, the
    adaptation behind their published matrices (the ACES studio config's for Blackmagic), not
    the default Bradford, 4e-3 away."""
    import colour

    spaces = colour.RGB_COLOURSPACES
    code, out, err = run(capsys, "matrix", space, "ACES2065-1", "--format", "json")
    matrix = json.loads(out)["matrix"]
    assert code == 0, err
    assert np.allclose(
        matrix, colour.matrix_RGB_to_RGB(spaces[gamut], spaces["ACES2065-1"], "CAT02"), rtol=0, atol=1e-9
    )
    assert not np.allclose(matrix, colour.matrix_RGB_to_RGB(spaces[gamut], spaces["ACES2065-1"], "Bradford"), atol=1e-3)


def test_the_ocio_snippet_loads_in_opencolorio_as_the_same_matrix(capsys):
    """The snippet pasted as a colour space's transform: OpenColorIO reads the matrix printed as
    json, and applies it to column vectors (red goes to the first column)."""
    import PyOpenColorIO as ocio

    expected = np.array(json.loads(run(capsys, "matrix", "ACEScg", "lin_rec709", "--format", "json")[1])["matrix"])
    code, snippet, err = run(capsys, "matrix", "ACEScg", "lin_rec709", "--format", "ocio")
    assert code == 0 and snippet.count("\n") == 1, err
    config = ocio.Config.CreateFromStream(
        "ocio_profile_version: 2.1\nroles:\n  default: reference\ncolorspaces:\n"
        "  - !<ColorSpace>\n    name: reference\n"
        f"  - !<ColorSpace>\n    name: matrix\n    to_scene_reference: {snippet}"
    )
    loaded = np.reshape(
        config.getColorSpace("matrix").getTransform(ocio.COLORSPACE_DIR_TO_REFERENCE).getMatrix(), (4, 4)
    )
    assert np.allclose(loaded[:3, :3], expected, rtol=0, atol=1e-14)
    assert np.array_equal(loaded[3], [0, 0, 0, 1]) and np.array_equal(loaded[:3, 3], [0, 0, 0])
    red = config.getProcessor("matrix", "reference").getDefaultCPUProcessor().applyRGB([1.0, 0.0, 0.0])
    assert np.allclose(red, expected[:, 0], rtol=1e-6, atol=0)


def test_the_nuke_node_holds_the_matrix_to_ten_digits_named_by_aliases(capsys):
    import re

    expected = json.loads(run(capsys, "matrix", "ARRI LogC4", "ACEScg", "--format", "json")[1])["matrix"]
    code, node, err = run(capsys, "matrix", "ARRI LogC4", "ACEScg", "--format", "nuke")
    rows = re.findall(r"^ +\{([^{}]+)\}$", node, re.MULTILINE)
    assert code == 0 and node.startswith("ColorMatrix {\n matrix {\n") and len(rows) == 3, err
    assert np.allclose([[float(v) for v in row.split()] for row in rows], expected, rtol=1e-9, atol=1e-12)
    assert node.endswith("\n name arri_logc4_to_lin_ap1\n}\n")


def test_a_nuke_node_name_is_ascii_and_starts_with_no_digit(tmp_path, capsys):
    """Nuke names nodes with ASCII letters, digits and underscores, not starting with a digit: an
    alias with an accent is passed over, and a name starting with a digit gets an underscore."""
    (tmp_path / "show.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "709 Caméra"\naliases = ["caméra"]\n'
        'primaries = [[0.64, 0.33], [0.30, 0.60], [0.15, 0.06]]\nwhite = "D65"\n',
        encoding="utf-8",
    )
    code, node, err = run(
        capsys, "matrix", "709 Caméra", "ACEScg", "--spec", str(tmp_path / "show.toml"), "--format", "nuke"
    )
    name = next(line.split()[1] for line in node.splitlines() if line.strip().startswith("name "))
    assert code == 0 and name == "_709_camera_to_" + name.split("_to_")[1], (node, err)
    assert name.isascii() and name.isidentifier()
