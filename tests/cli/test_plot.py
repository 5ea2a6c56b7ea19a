"""ocioforge plot: the displays and the spaces --spaces names; --mapping's panel per method."""

from __future__ import annotations

import pytest

from tests.cli.test_verify_cli import run


@pytest.fixture(scope="module")
def config(build_config):
    return build_config((2, 1))


def test_spaces_named_repeated_or_comma_separated_draw_the_same(config, tmp_path):
    plain, repeated, commas = (tmp_path / f"{n}.svg" for n in ("plain", "repeated", "commas"))
    assert run("plot", config, "-o", plain).exit_code == 0
    assert run("plot", config, "-o", repeated, "--spaces", "ACEScg", "--spaces", "lin_rec709").exit_code == 0
    assert run("plot", config, "-o", commas, "--spaces", "acescg, Linear Rec.709 (sRGB)").exit_code == 0
    assert repeated.read_bytes() == commas.read_bytes() != plain.read_bytes()
    assert b"ACEScg (AP1)" in commas.read_bytes() and b"ACEScg" not in plain.read_bytes()


@pytest.mark.parametrize(
    "value, message",
    [
        ("ACEScg,acecg", "unknown colour space 'acecg' (did you mean 'ACEScg'"),
        ("Raw", "'Raw' has no gamut to draw"),
        ("ACEScg,,Raw", "holds an empty name"),
    ],
)
def test_a_bad_space_is_one_error_line_and_exit_2(config, tmp_path, value, message):
    result = run("plot", config, "-o", tmp_path / "g.png", "--spaces", value)
    assert result.exit_code == 2 and result.stderr.count("\n") == 1, result.stderr
    assert result.stderr.startswith("error: ocioforge plot:--spaces: ") and message in result.stderr
    assert not list(tmp_path.iterdir())


def test_mapping_draws_a_panel_per_method_the_same_every_time(config, tmp_path):
    """SVG: the panels' titles are text, and no date or random id changes the bytes."""
    first, second = tmp_path / "a.svg", tmp_path / "b.svg"
    for path in (first, second):
        assert run("plot", config, "-o", path, "--mapping", "--spaces", "ACEScg").exit_code == 0
    drawn = first.read_bytes()
    assert drawn == second.read_bytes()
    for title in (b"clip: ", b"desaturate: toward white", b"scale: negatives clamped", b"rgc: ", b"perceptual: "):
        assert title in drawn
