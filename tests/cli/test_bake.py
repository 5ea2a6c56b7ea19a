"""ocioforge bake: writes the file; bad input exits 2 with one line and leaves nothing."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

import generator.cli as cli
from generator.cli.bake import command
from generator.luts import formats
from tests.cli.conftest import BAKE, LONG, one_line, refuses_a_special_file, run, writes_through_a_link_only_with_force


def test_bakes_a_resolve_cube(tmp_path):
    out = tmp_path / "acescg_srgb.cube"
    result = CliRunner().invoke(command, ["--from", "ACEScg", "--to", "srgb_display", "--size", "17", "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert out.read_text().count("\n") > 17**3
    assert [p.name for p in tmp_path.iterdir()] == [out.name]


def test_a_bake_into_hlg_warns_of_nothing(tmp_path):
    """HLG's inverse OOTF divides by a colour's luminance: black is code 0, and numpy's warnings
    of the division (ten lines on stderr) are not the user's business."""
    import warnings

    from generator import reference
    from generator.spec import load

    hlg = next(d for d in load.load().displays if d.name == "Rec.2100-HLG - Display")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert reference.display_encode(hlg, [[0.0, 0.0, 0.0], [0.0, 0.0, 1e-6]])[0].tolist() == [0.0, 0.0, 0.0]
    out = tmp_path / "hlg.clf"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = CliRunner().invoke(
            command, ["--from", "ACEScg", "--to", "Rec.2100-HLG - Display", "--size", "9", "-o", str(out)]
        )
    assert result.exit_code == 0, result.output
    assert "Warning" not in result.output


def test_spi3d_writes_its_shaper_beside(tmp_path):
    out = tmp_path / "a.spi3d"
    result = CliRunner().invoke(command, ["--from", "ACEScct", "--to", "sRGB - Display", "--size", "9", "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.spi1d", "a.spi3d"]
    assert "apply the .spi1d, then the .spi3d" in result.output  # the .spi3d alone is hundreds of codes off


def test_bakes_from_a_spec_whose_inactive_spaces_it_does_not_load(tmp_path):
    spec = tmp_path / "show.toml"
    spec.write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw", '
        '"ADX10"]\ninactive = ["ADX10"]\n'
    )
    out = tmp_path / "a.cube"
    result = CliRunner().invoke(
        command, ["--spec", str(spec), "--from", "ACEScg", "--to", "sRGB - Display", "--size", "9", "-o", str(out)]
    )
    assert result.exit_code == 0, result.output
    assert out.exists()


BAD = {
    "display as source": ["--from", "sRGB - Display", "--to", "sRGB - Display"],
    "data source": ["--from", "Raw", "--to", "sRGB - Display"],
    "scene space as display": ["--from", "ACEScg", "--to", "ACEScct"],
    "unknown format": ["--from", "ACEScg", "--to", "sRGB - Display", "--format", "3dl"],
    "unknown method": ["--from", "ACEScg", "--to", "sRGB - Display", "--gamut-map", "squash"],
    "empty method": ["--from", "ACEScg", "--to", "sRGB - Display", "--gamut-map", ""],
    "size too large": ["--from", "ACEScg", "--to", "sRGB - Display", "--size", "130"],
    "size too small": ["--from", "ACEScg", "--to", "sRGB - Display", "--size", "2"],
    "shaper in iridas": [
        "--from",
        "ACEScg",
        "--to",
        "sRGB - Display",
        "--format",
        "iridas_cube",
        "--shaper",
        "ACEScct",
    ],
    "data shaper": ["--from", "ACEScg", "--to", "sRGB - Display", "--shaper", "Raw"],
    "iridas from linear": ["--from", "ACEScg", "--to", "sRGB - Display", "--format", "iridas_cube"],
    "no shaper from linear": ["--from", "Linear Rec.2020", "--to", "Rec.2100-PQ - Display", "--shaper", "none"],
    "linear shaper": ["--from", "ACEScct", "--to", "sRGB - Display", "--shaper", "ACEScg"],
    "display shaper": ["--from", "ACEScct", "--to", "sRGB - Display", "--shaper", "Rec.1886 Rec.709 - Display"],
    "suffix of another format": ["--from", "ACEScg", "--to", "sRGB - Display", "--format", "spi3d"],
    "unknown view": ["--from", "ACEScct", "--to", "sRGB - Display", "--view", "ACES 2.0 - SDR 100 nits (Rec.7O9)"],
    "HDR view on an SDR display": [
        "--from",
        "ACEScct",
        "--to",
        "sRGB - Display",
        "--view",
        "ACES 2.0 - HDR 1000 nits (P3 D65)",
    ],
    "view with a gamut mapping": [
        "--from",
        "ACEScct",
        "--to",
        "sRGB - Display",
        "--view",
        "ACES 2.0 - SDR 100 nits (Rec.709)",
        "--gamut-map",
        "clip",
    ],
    "view limited beyond the display": [
        "--from",
        "ACEScct",
        "--to",
        "sRGB - Display",
        "--view",
        "ACES 2.0 - SDR 100 nits (P3 D65)",
    ],
    "view in iridas from linear": [
        "--from",
        "ACEScg",
        "--to",
        "sRGB - Display",
        "--format",
        "iridas_cube",
        "--view",
        "ACES 2.0 - SDR 100 nits (Rec.709)",
    ],
    "view size too large": [
        "--from",
        "ACEScct",
        "--to",
        "sRGB - Display",
        "--view",
        "ACES 2.0 - SDR 100 nits (Rec.709)",
        "--size",
        "130",
    ],
}


#: A name whose suffix no host reads as the format asked for (the case below writes to "out.cube").
BAD_NAMES = {
    "suffix no format has": (["--format", "clf"], "out.3dl", "ends in .3dl, not clf's"),
    "no suffix": (["--format", "resolve_cube"], "out", "has no suffix"),
}


@pytest.fixture
def bake_exits(monkeypatch, capsys):
    """Run ``ocioforge bake`` with arguments expected to end it: its exit status and standard error."""
    monkeypatch.setitem(cli.COMMANDS, "bake", "Bake a LUT.")

    def _run(args):
        with pytest.raises(SystemExit) as exited:
            cli.main(["bake", *args])
        return exited.value.code, capsys.readouterr().err

    return _run


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_input_exits_2_with_one_line(tmp_path, bake_exits, case):
    code, err = bake_exits([*BAD[case], "-o", str(tmp_path / "out.cube")])
    assert code == 2
    assert err.startswith("error: ") and err.count("\n") == 1, err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("blocker, reason", [(None, "does not exist"), ("file", "Not a directory")])
def test_an_output_folder_that_is_not_one_is_named(tmp_path, bake_exits, blocker, reason):
    folder = tmp_path / "luts"
    if blocker:
        folder.write_text("keep")
    code, err = bake_exits(["--from", "ACEScg", "--to", "sRGB - Display", "-o", str(folder / "out.cube")])
    assert code == 2 and err.count("\n") == 1 and reason in err, err
    assert [p.name for p in tmp_path.iterdir()] == (["luts"] if blocker else [])


@pytest.mark.parametrize(
    "args, words",
    [
        (["--from", "ARRI LogC4x", "--to", "sRGB - Display"], "did you mean 'ARRI LogC4'"),
        (["--from", "ACEScg", "--to", "sRGB - Display", "--shaper", "ACEScctt"], "did you mean 'ACEScct'"),
        (["--from", "ACEScg", "--to", "Nope"], "allowed: sRGB - Display, "),
    ],
)
def test_a_mistyped_name_is_answered_with_the_names_the_spec_has(tmp_path, bake_exits, args, words):
    """The bake loads only the spaces it names, yet suggests among all the spec's."""
    code, err = bake_exits([*args, "-o", str(tmp_path / "out.cube")])
    assert code == 2 and err.count("\n") == 1 and words in err, err


def test_a_library_space_the_spec_leaves_out_and_a_space_without_a_curve_say_so(tmp_path, bake_exits):
    spec = tmp_path / "small.toml"
    spec.write_text('colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n')
    code, err = bake_exits(
        ["--spec", str(spec), "--from", "ARRI LogC4", "--to", "sRGB - Display", "-o", str(tmp_path / "a.cube")]
    )
    assert code == 2 and "'ARRI LogC4' is in the library but not in this spec" in err, err
    code, err = bake_exits(["--from", "ADX10", "--to", "sRGB - Display", "-o", str(tmp_path / "a.cube")])
    assert code == 2 and "allowed: a space with a curve and primaries" in err, err


def test_a_spi3d_rebaked_without_a_shaper_takes_the_old_shaper_with_it(tmp_path, bake_exits):
    """An earlier bake's .spi1d beside a .spi3d that no longer needs one would be paired with
    it by whoever reads the two: refused without --force, deleted with it."""
    out = tmp_path / "s.spi3d"
    args = ["--from", "sRGB Encoded Rec.709 (sRGB)", "--to", "Display P3 - Display", "--size", "9", "-o", str(out)]
    assert CliRunner().invoke(command, args).exit_code == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.spi1d", "s.spi3d"]
    (tmp_path / "s.spi3d").unlink()
    code, err = bake_exits([*args, "--shaper", "none"])
    assert code == 2 and "s.spi1d" in err and "--force" in err
    assert CliRunner().invoke(command, [*args, "--shaper", "none", "--force"]).exit_code == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.spi3d"]


def test_existing_output_needs_force(tmp_path, bake_exits):
    out = tmp_path / "out.clf"
    out.write_text("keep")
    code, err = bake_exits(["--from", "ACEScg", "--to", "sRGB - Display", "--size", "9", "-o", str(out)])
    assert code == 2 and "--force" in err and out.read_text() == "keep"
    result = CliRunner().invoke(
        command, ["--from", "ACEScg", "--to", "sRGB - Display", "--size", "9", "-o", str(out), "--force"]
    )
    assert result.exit_code == 0 and out.read_text().startswith("<?xml")


def test_a_failed_bake_leaves_no_file(tmp_path, monkeypatch):
    from generator.luts import formats

    def broken(*args, **kwargs):
        raise RuntimeError("disk full")

    monkeypatch.setattr(formats, "clf", broken)
    result = CliRunner().invoke(command, ["--from", "ACEScg", "--to", "sRGB - Display", "-o", str(tmp_path / "x.clf")])
    assert result.exit_code != 0 and list(tmp_path.iterdir()) == []


def test_an_unwritable_output_is_one_line_and_exit_2(tmp_path, bake_exits):
    """A folder where the LUT file should go cannot be replaced, for any user: the path and the
    OS's reason on one line, exit status 2, the folder and its contents untouched."""
    out = tmp_path / "out.cube"
    (out / "keep").mkdir(parents=True)
    code, err = bake_exits(["--from", "ACEScg", "--to", "sRGB - Display", "--size", "9", "-o", str(out), "--force"])
    assert code == 2 and err.startswith(f"error: {out}: is a folder; allowed: ") and err.count("\n") == 1, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.cube"] and (out / "keep").is_dir()


def test_a_spi3d_named_like_its_shaper_is_refused(tmp_path, bake_exits):
    """The shaper goes beside the .spi3d with the suffix .spi1d: an output named .spi1d would be
    overwritten by it, and the lattice lost."""
    code, err = bake_exits(
        ["--from", "ACEScct", "--to", "sRGB - Display", "--format", "spi3d", "-o", str(tmp_path / "a.spi1d")]
    )
    assert code == 2 and "allowed: a name ending in .spi3d" in err and list(tmp_path.iterdir()) == []


def test_a_format_in_any_case(tmp_path):
    out = tmp_path / "a.clf"
    result = CliRunner().invoke(
        command, ["--from", "ACEScg", "--to", "sRGB - Display", "--size", "9", "--format", "CLF", "-o", str(out)]
    )
    assert result.exit_code == 0, result.output
    assert out.read_text().startswith("<?xml")


@pytest.mark.parametrize(
    "source, shaper", [("ACEScct", "NONE"), ("ACEScg", "Auto"), ("ACEScg", "arri_logc4"), ("ACEScg", "V-Log V-Gamut")]
)
def test_shaper_words_in_any_case_and_any_library_space(tmp_path, source, shaper):
    out = tmp_path / "a.cube"
    result = CliRunner().invoke(
        command, ["--from", source, "--to", "sRGB - Display", "--size", "9", "--shaper", shaper, "-o", str(out)]
    )
    assert result.exit_code == 0, result.output
    assert out.exists()


@pytest.mark.parametrize("fmt", ["resolve_cube", "iridas_cube"])
def test_a_cube_of_spaces_named_in_any_script_writes_an_ascii_header(tmp_path, fmt):
    """A .cube's header is ASCII (its formats' text): accented names had crashed the writer."""
    spec = tmp_path / "show.toml"
    spec.write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "Caméra A カメラ"\ngamut = "P3-D65"\ntransfer = "ACEScct"\n'
        '[[display]]\nname = "Écran LED"\ngamut = "Rec.709"\neotf = "gamma 2.4"\n',
        encoding="utf-8",
    )
    out = tmp_path / "a.cube"
    result = CliRunner().invoke(
        command,
        [
            "--spec",
            str(spec),
            "--from",
            "Caméra A カメラ",
            "--to",
            "Écran LED",
            "--format",
            fmt,
            "--size",
            "9",
            "-o",
            str(out),
        ],
    )
    assert result.exit_code == 0, result.output
    head = out.read_bytes().split(b"LUT_3D_SIZE")[0].decode("ascii")
    assert "Camera A \\u30ab\\u30e1\\u30e9 to Ecran LED" in head


@pytest.mark.parametrize("fmt", ["resolve_cube", "iridas_cube"])
def test_a_cube_header_holds_quotes_and_long_names_within_the_line_limit(tmp_path, fmt):
    """Adobe's Cube specification quotes TITLE with no escape and caps lines at 250 bytes: a
    name with double quotes had closed the title early, and a long one passed the cap."""
    name = 'Cam "Q" Log ' + "wide " * 40
    spec = tmp_path / "show.toml"
    spec.write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        f'[[custom_space]]\nname = {name.strip()!r}\ngamut = "P3-D65"\ntransfer = "ACEScct"\n',
        encoding="utf-8",
    )
    out = tmp_path / "a.cube"
    result = CliRunner().invoke(
        command,
        [
            "--spec",
            str(spec),
            "--from",
            name.strip(),
            "--to",
            "sRGB - Display",
            "--format",
            fmt,
            "--size",
            "9",
            "-o",
            str(out),
        ],
    )
    assert result.exit_code == 0, result.output
    head = out.read_bytes().split(b"LUT_3D_SIZE")[0].decode("ascii").splitlines(keepends=True)
    assert max(len(line) for line in head) <= formats.LINE_MAX
    titles = [line for line in head if line.startswith("TITLE")]
    assert len(titles) == (fmt == "iridas_cube")
    for line in titles:
        assert line.startswith("TITLE \"Cam 'Q' Log wide") and line.rstrip("\n").endswith('..."')
        assert line.count('"') == 2


def test_a_build_bakes_from_the_spec_it_stored(tmp_path, build_config):
    """A TD with only the deployed config bakes from it (its config.ocio or ocioforge-spec.json):
    the same bytes as from the spec that built it."""
    config = build_config((2, 1))
    outputs = []
    for spec in (None, config, config.parent / "ocioforge-spec.json", config.parent):
        outputs.append(tmp_path / f"{len(outputs)}.cube")
        args = ["--from", "ARRI LogC4", "--to", "sRGB - Display", "--size", "9", "-o", str(outputs[-1])]
        result = CliRunner().invoke(command, [*args, *(["--spec", str(spec)] if spec else [])])
        assert result.exit_code == 0, result.output
    assert len({path.read_bytes() for path in outputs}) == 1


@pytest.mark.parametrize("case", sorted(BAD_NAMES))
def test_a_name_without_the_formats_suffix_is_refused(tmp_path, bake_exits, case):
    """README: hosts tell formats by suffix; a .clf named .3dl, or a cube with no suffix, reads as nothing."""
    args, name, words = BAD_NAMES[case]
    code, err = bake_exits(["--from", "ACEScg", "--to", "sRGB - Display", *args, "-o", str(tmp_path / name)])
    assert code == 2 and err.count("\n") == 1 and words in err, err
    assert list(tmp_path.iterdir()) == []


def test_a_missing_folder_is_refused_before_the_bake(tmp_path, bake_exits, monkeypatch):
    """A 65³ perceptual bake took seconds before saying its folder did not exist."""
    from generator.luts import bake

    monkeypatch.setattr(bake, "bake", lambda req: pytest.fail("baked before the folder was checked"))
    code, err = bake_exits(["--from", "ACEScg", "--to", "sRGB - Display", "-o", str(tmp_path / "nodir" / "out.cube")])
    assert code == 2 and "does not exist" in err, err


def test_a_spi3d_baked_through_a_link_keeps_its_shaper_beside_the_file_written(tmp_path, bake_exits):
    """The .spi3d is written to the file the link points to: its .spi1d goes beside that file,
    not beside the link, where the target's earlier shaper had stayed paired with the new lattice
    (168 ten-bit codes off in gamut)."""
    real = tmp_path / "v001" / "show.spi3d"
    real.parent.mkdir()
    assert CliRunner().invoke(command, ["--from", "ACEScct", "--to", "sRGB - Display", "-o", str(real)]).exit_code == 0
    first = real.with_suffix(".spi1d").read_bytes()
    link = tmp_path / "current.spi3d"
    link.symlink_to(real)
    CliRunner().invoke(command, ["--from", "ACEScct", "--to", "Rec.1886 Rec.709 - Display", "-o", str(link), "--force"])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["current.spi3d", "v001"]
    assert "Rec.1886" in real.with_suffix(".spi1d").read_text() and real.with_suffix(".spi1d").read_bytes() != first
    assert "Rec.1886" in real.read_text()


def test_a_bake_whose_weights_reach_zero_warns_of_nothing(tmp_path):
    """An HLG desaturate fit has a set whose 99th percentile error is about 0: squaring each
    colour's error over it overflowed, and numpy printed a RuntimeWarning on a good bake."""
    import warnings

    out = tmp_path / "hlg.cube"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = CliRunner().invoke(
            command,
            [
                "--from",
                "slog3_sgamut3cine",
                "--to",
                "Rec.2100-HLG - Display",
                "--gamut-map",
                "desaturate",
                "-o",
                str(out),
            ],
        )
    assert result.exit_code == 0, result.output


def test_bake_view_writes_the_displays_aces_view_in_any_case(tmp_path, capsys):
    """``--view ACES 2.0`` is the display's first ACES 2.0 studio view, as in a spec; names are
    matched in any case, and the report says which view was baked."""
    out = tmp_path / "a.cube"
    code, printed, err = run(
        capsys, "bake", "--from", "acescct", "--to", "srgb_display", "--view", "aces 2.0", "--size", "9", "-o", str(out)
    )
    assert code == 0 and "view ACES 2.0 - SDR 100 nits (Rec.709), 9^3" in printed and out.exists(), err
    again = tmp_path / "b.cube"
    code, _, err = run(
        capsys,
        "bake",
        "--from",
        "ACEScct",
        "--to",
        "sRGB - Display",
        "--view",
        "ACES 2.0 - SDR 100 nits (rec.709)",
        "--size",
        "9",
        "-o",
        str(again),
    )
    assert code == 0 and again.read_bytes() == out.read_bytes(), err


@pytest.mark.parametrize(
    "args, words",
    [
        (
            ("--view", "ACES 2.0 - HDR 1000 nits (P3 D65)"),
            "cannot show 'ACES 2.0 - HDR 1000 nits (P3 D65)': it is an HDR view",
        ),
        (("--view", "ACES 3.0"), "unknown ACES view 'ACES 3.0'"),
        (("--view", "ACES 2.0", "--gamut-map", "scale"), "--view and --gamut-map exclude each other"),
    ],
)
def test_bake_view_refuses_in_one_line_and_writes_nothing(tmp_path, capsys, args, words):
    code, out, err = run(
        capsys, "bake", "--from", "ACEScct", "--to", "sRGB - Display", *args, "-o", str(tmp_path / "a.clf")
    )
    assert code == 2 and err.startswith("error: ") and err.count("\n") == 1 and words in err and out == "", err
    assert list(tmp_path.iterdir()) == []


def test_a_spi3d_is_not_replaced_when_its_shaper_cannot_be(tmp_path, capsys):
    (tmp_path / "pair.spi3d").write_bytes(b"keep")
    (tmp_path / "pair.spi1d").mkdir()
    code, _, err = run(
        capsys,
        "bake",
        "--from",
        "ACEScct",
        "--to",
        "sRGB - Display",
        "--size",
        "9",
        "-o",
        tmp_path / "pair.spi3d",
        "--force",
    )
    assert one_line(code, err, "pair.spi1d: is a folder; allowed: "), err
    assert (tmp_path / "pair.spi3d").read_bytes() == b"keep"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pair.spi1d", "pair.spi3d"]


@pytest.mark.parametrize("kind", ("fifo", "socket", "device"))
def test_a_device_or_pipe_is_never_replaced(tmp_path, capsys, kind):
    refuses_a_special_file(capsys, tmp_path, kind, [*BAKE, "-o", "{out}"], ".clf")


def test_a_link_is_written_through_only_with_force(tmp_path, capsys):
    """A dangling link is refused, --force or not (bake replaced it without --force); a link to
    a regular file needs --force, and then the file it points to is written, the link kept."""
    writes_through_a_link_only_with_force(capsys, tmp_path, [*BAKE, "-o", "{out}"], ".clf")


@pytest.mark.parametrize(
    "argv, words",
    [
        ([*BAKE, "-o", "{tmp}/" + LONG + ".clf"], "File name too long"),
        ([*BAKE, "-o", "{tmp}/l1", "--format", "clf", "--force"], "is a link to nothing"),
        ([*BAKE, "-o", "{tmp}/l1/a.clf"], "Too many levels of symbolic links"),
        ([*BAKE, "-o", ".", "--format", "clf"], "names no file of its own"),
        ([*BAKE, "-o", "/", "--format", "spi3d"], "names no file of its own"),
    ],
)
def test_a_path_that_cannot_be_used_is_one_line(looped_links, capsys, argv, words):
    """A name too long, a loop of links, a path naming no file: one line, exit 2, nothing left
    behind (each was a traceback, exit 1)."""
    code, _, err = run(capsys, *(a.format(tmp=looped_links) for a in argv))
    assert one_line(code, err, words), err
    assert sorted(p.name for p in looped_links.iterdir()) == ["l1", "l2"]
