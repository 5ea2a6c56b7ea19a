"""ocioforge plot: the chromaticity diagram of a built config's displays and the spaces --spaces
names, --mapping's panel per method; the image written whole, only over a regular file."""

from __future__ import annotations

import pytest

from tests.cli.conftest import (
    LONG,
    invoke,
    one_line,
    refuses_a_special_file,
    run,
    writes_through_a_link_only_with_force,
)


@pytest.fixture(scope="module")
def built(build_config):
    """The default spec's 2.1 build, shared: not to be edited."""
    return build_config((2, 1))


def test_plot_draws_the_chromaticity_diagram(built, tmp_path):
    result = invoke("plot", built, "-o", tmp_path / "diagram.png")
    assert result.exit_code == 0, result.output
    assert (tmp_path / "diagram.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("suffix", ("svg", "pdf"))
def test_plot_gives_the_same_bytes_every_time(built, tmp_path, suffix):
    """No date and no random element ids: the same config plots to the same file (SVG and PDF
    held their creation date, SVG random clip-path ids)."""
    for name in ("a", "b"):
        assert invoke("plot", built, "-o", tmp_path / f"{name}.{suffix}").exit_code == 0
    assert (tmp_path / f"a.{suffix}").read_bytes() == (tmp_path / f"b.{suffix}").read_bytes()


def test_plot_refuses_an_unknown_format_and_writes_nothing(built, tmp_path):
    result = invoke("plot", built, "-o", tmp_path / "diagram.bmp")
    assert result.exit_code == 2 and result.stderr.startswith("error: ")
    assert not list(tmp_path.glob("diagram*"))


def test_spaces_named_repeated_or_comma_separated_draw_the_same(built, tmp_path):
    plain, repeated, commas = (tmp_path / f"{n}.svg" for n in ("plain", "repeated", "commas"))
    assert invoke("plot", built, "-o", plain).exit_code == 0
    assert invoke("plot", built, "-o", repeated, "--spaces", "ACEScg", "--spaces", "lin_rec709").exit_code == 0
    assert invoke("plot", built, "-o", commas, "--spaces", "acescg, Linear Rec.709 (sRGB)").exit_code == 0
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
def test_a_bad_space_is_one_error_line_and_exit_2(built, tmp_path, value, message):
    result = invoke("plot", built, "-o", tmp_path / "g.png", "--spaces", value)
    assert result.exit_code == 2 and result.stderr.count("\n") == 1, result.stderr
    assert result.stderr.startswith("error: ocioforge plot:--spaces: ") and message in result.stderr
    assert not list(tmp_path.iterdir())


def test_mapping_draws_a_panel_per_method_the_same_every_time(built, tmp_path):
    """SVG: the panels' titles are text, and no date or random id changes the bytes."""
    first, second = tmp_path / "a.svg", tmp_path / "b.svg"
    for path in (first, second):
        assert invoke("plot", built, "-o", path, "--mapping", "--spaces", "ACEScg").exit_code == 0
    drawn = first.read_bytes()
    assert drawn == second.read_bytes()
    for title in (b"clip: ", b"desaturate: toward white", b"scale: negatives clamped", b"rgc: ", b"perceptual: "):
        assert title in drawn


def test_plot_maps_onto_the_display_asked_for(build_config, tmp_path, capsys):
    config = build_config((2, 1))
    first, chosen = tmp_path / "first.png", tmp_path / "pq.png"
    assert run(capsys, "plot", str(config), "-o", str(first), "--mapping")[0] == 0
    assert (
        run(capsys, "plot", str(config), "-o", str(chosen), "--mapping", "--display", "rec.2100-pq - display")[0] == 0
    )
    assert first.read_bytes() != chosen.read_bytes()
    code, _, err = run(capsys, "plot", str(config), "-o", str(tmp_path / "x.png"), "--mapping", "--display", "Nope")
    assert code == 2 and err.count("\n") == 1 and "unknown display 'Nope'; allowed: sRGB - Display" in err, err


def test_plot_display_without_mapping_is_refused(capsys, tmp_path, build_config):
    """--display chooses the display --mapping draws: alone, any name (a typo too) was ignored."""
    code, _, err = run(capsys, "plot", str(build_config((2, 1))), "-o", str(tmp_path / "g.png"), "--display", "nope")
    assert code == 2 and "allowed: with one of them" in err, err
    assert not any(tmp_path.iterdir())


def test_highlights_draw_a_panel_per_view_of_the_display_asked_for(built, tmp_path, capsys):
    """SVG: the panels' labels are text; Raw has no panel."""
    image = tmp_path / "pq.svg"
    assert run(capsys, "plot", built, "-o", image, "--highlights", "--display", "rec2100_pq_display")[0] == 0
    drawn = image.read_bytes()
    for label in (b"ACES 2.0 - HDR 1000 nits (P3 D65)", b"ACES 1.1 - HDR Video (1000 nits &amp; Rec.2020 lim)"):
        assert label in drawn
    assert b"highlights through each view of Rec.2100-PQ - Display (ST 2084 signal drawn as is)" in drawn


@pytest.mark.parametrize(
    "extra, words",
    [
        (["--highlights", "--mapping"], "--highlights: draws another figure than --mapping"),
        (["--highlights", "--spaces", "ACEScg"], "--spaces: draws gamuts, which --highlights does not"),
    ],
)
def test_highlights_with_another_figure_is_refused(capsys, tmp_path, built, extra, words):
    code, _, err = run(capsys, "plot", built, "-o", tmp_path / "g.png", *extra)
    assert code == 2 and err.count("\n") == 1 and words in err, err
    assert not any(tmp_path.iterdir())


def test_plot_replaces_an_image_only_with_force(config, tmp_path, capsys):
    image = tmp_path / "diagram.png"
    image.write_bytes(b"keep")
    code, _, err = run(capsys, "plot", config, "-o", image)
    assert one_line(code, err, "exists; pass --force") and image.read_bytes() == b"keep", err
    assert run(capsys, "plot", config, "-o", image, "--force")[0] == 0
    assert image.read_bytes().startswith(b"\x89PNG")


def test_plot_reads_the_config_as_verify_does(config, tmp_path, capsys):
    """An empty or foreign config beside a stored spec, or the stored spec itself, is not a
    config: refused as verify refuses it, no image written (it had been drawn, exit 0)."""
    spec = config.parent / "ocioforge-spec.json"
    code, _, err = run(capsys, "plot", spec, "-o", tmp_path / "a.png")
    assert one_line(code, err, "OpenColorIO cannot load it"), err
    config.write_bytes(b"")
    code, _, err = run(capsys, "plot", config, "-o", tmp_path / "a.png")
    assert one_line(code, err, "OpenColorIO cannot load it"), err
    assert not (tmp_path / "a.png").exists()


def test_an_unwritable_image_is_one_line_and_exit_2(built, tmp_path, capsys):
    """The path and the OS's reason, exit status 2."""
    blocked = tmp_path / "blocked"
    blocked.write_bytes(b"")
    code, _, err = run(capsys, "plot", built, "-o", f"{blocked}/diagram.png")
    assert code == 2 and err.count("\n") == 1, err
    assert err.startswith(f"error: {blocked}/") and err.endswith(": cannot write: Not a directory\n")


@pytest.mark.parametrize(
    "name, words",
    [
        ("nd/sub/gamuts.png", "its folder"),
        ("gamuts", "is a folder"),  # said: unknown image format ''
    ],
)
def test_a_file_output_in_no_folder_or_naming_one_is_refused_and_makes_nothing(
    capsys, tmp_path, monkeypatch, built, name, words
):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "gamuts").mkdir()
    code, _, err = run(capsys, "plot", built, "-o", name)
    assert code == 2 and err.count("\n") == 1 and words in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["gamuts"] and not any((tmp_path / "gamuts").iterdir())


@pytest.mark.parametrize("kind", ("fifo", "socket", "device"))
def test_a_device_or_pipe_is_never_replaced(built, tmp_path, capsys, kind):
    refuses_a_special_file(capsys, tmp_path, kind, ["plot", str(built), "-o", "{out}"], ".png")


def test_a_link_is_written_through_only_with_force(built, tmp_path, capsys):
    """A dangling link is refused, --force or not; a link to a regular file needs --force, and
    then the file it points to is written, the link kept."""
    writes_through_a_link_only_with_force(capsys, tmp_path, ["plot", str(built), "-o", "{out}"], ".png")


def test_a_config_path_too_long_is_one_line(looped_links, capsys):
    code, _, err = run(capsys, "plot", f"{looped_links}/{LONG}/config.ocio", "-o", f"{looped_links}/a.png")
    assert one_line(code, err, "File name too long"), err
    assert sorted(p.name for p in looped_links.iterdir()) == ["l1", "l2"]


def test_highlights_of_a_display_with_only_raw_is_one_line(tmp_path, capsys):
    """Nothing to draw: it had raised from matplotlib (no rows), exit 1."""
    spec = tmp_path / "raw.toml"
    spec.write_text(
        'name = "raw-only"\nocio_version = "2.1"\n'
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Raw"]\n',
        encoding="utf-8",
    )
    assert run(capsys, "build", spec, "-o", tmp_path / "cfg")[0] == 0
    code, _, err = run(capsys, "plot", tmp_path / "cfg", "-o", tmp_path / "h.png", "--highlights")
    assert one_line(code, err, "'sRGB - Display' offers no view but Raw"), err
    assert not (tmp_path / "h.png").exists()
