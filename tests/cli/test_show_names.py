"""A show's own names through the CLI: list --spec, and info and matrix of a display."""

import json
from pathlib import Path

import numpy as np
import pytest

from tests.cli.test_cli import run

SHOW = Path(__file__).parents[2] / "examples" / "show" / "spec.toml"


@pytest.fixture(scope="module")
def show():
    from generator.spec import load

    return load.load(SHOW)


def test_list_spec_gives_the_shows_own_spaces_displays_and_views(capsys, show):
    code, out, err = run(capsys, "list", "--spec", str(SHOW))
    lines = out.splitlines()
    assert code == 0 and lines[0].split("\t")[0] == "colour space", err
    assert [line.split("\t")[0] for line in lines[1:]] == [s.name for s in show.colour_spaces]
    assert "Linear LED Wall\tStage\tLinear LED Wall\tlinear\tlin_ledwall" in lines
    _, out, _ = run(capsys, "list", "--spec", str(SHOW), "--displays")
    assert "LED Wall\tLED Wall\tST 2084\t1500\tled_wall\tACES 2.0 - HDR 1500 nits (LED Wall), Scale, Raw" in out
    assert len(out.splitlines()) == 3  # the header and the show's two displays, not the library's
    _, out, _ = run(capsys, "list", "--views", "--spec", str(SHOW))
    assert out.splitlines() == ["display\tview"] + [f"{d.name}\t{v}" for d in show.displays for v in d.views]


def test_list_spec_reads_a_build_folder(capsys, tmp_path):
    """A build's folder holds the spec it was built from (ocioforge-spec.json)."""
    from generator.spec import load, resolved

    (tmp_path / "show").mkdir()
    (tmp_path / "show" / resolved.FILENAME).write_text(resolved.dumps(load.load(SHOW)), encoding="utf-8")
    assert (
        run(capsys, "list", "--spec", str(tmp_path / "show"), "--displays")[1]
        == (run(capsys, "list", "--spec", str(SHOW), "--displays")[1])
    )


@pytest.mark.parametrize(
    "argv, words",
    [
        (["list", "--spec", "missing.toml"], "missing.toml:-: cannot read the spec: it does not exist"),
        (["list", "--spec", ".", "--views"], "no resolved spec here"),
        (["list", "--spec", str(SHOW), "--curves"], "allowed with --spec: --spaces, --displays, --views"),
        (["info", "Nope", "--spec", str(SHOW)], "no colour space 'Nope' in spec.toml, nor a display"),
        (["info", "LED Wall", "--spec", "missing.toml"], "cannot read the spec: it does not exist"),
        (["matrix", "LED Wal", "acescg", "--spec", str(SHOW)], "(did you mean 'LED Wall'"),
        (["matrix", "LED Wall", "acescg"], "unknown colour space 'LED Wall'"),
    ],
)
def test_a_name_or_spec_that_is_not_there_is_one_line(capsys, tmp_path, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, *argv)
    assert code == 2 and err.startswith("error: ") and err.count("\n") == 1 and words in err, err
    assert out == ""


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
    assert "eotf:      ST 2084" in out
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
