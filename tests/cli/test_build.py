"""ocioforge build: a config folder from a spec; a previous build replaced only with --force,
nothing else ever; bad input one line, exit status 2, nothing written."""

import pytest

from tests.cli.conftest import LONG, one_line, run


def test_build_writes_a_named_config_and_refuses_to_overwrite(tmp_path, capsys):
    out = tmp_path / "my-show"
    code, stdout, _ = run(capsys, "build", "-o", str(out), "--ocio-version", "2.3")
    assert code == 0 and "OCIO 2.3" in stdout
    import PyOpenColorIO as ocio

    cfg = ocio.Config.CreateFromFile(str(out / "config.ocio"))
    assert cfg.getName() == "my-show" and cfg.getMinorVersion() == 3
    before = sorted(p.name for p in out.iterdir())
    code, _, err = run(capsys, "build", "-o", str(out))
    assert code == 2 and err.count("\n") == 1 and "--force" in err
    assert sorted(p.name for p in out.iterdir()) == before
    assert run(capsys, "build", "-o", str(out), "--force")[0] == 0


def test_build_counts_the_inactive_colour_spaces_it_writes(tmp_path, capsys):
    (tmp_path / "show.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "ARRI LogC4", '
        '"sRGB Encoded Rec.709 (sRGB)", "Raw"]\ninactive = ["ARRI LogC4"]\n'
    )
    code, stdout, err = run(capsys, "build", str(tmp_path / "show.toml"), "-o", str(tmp_path / "show"))
    import PyOpenColorIO as ocio

    cfg = ocio.Config.CreateFromFile(str(tmp_path / "show" / "config.ocio"))
    written = cfg.getColorSpaceNames(ocio.SEARCH_REFERENCE_SPACE_ALL, ocio.COLORSPACE_ALL)
    assert code == 0 and f" {len(written)} colour spaces," in stdout, err
    assert len(written) == len(cfg.getColorSpaceNames()) + 1


def test_counts_are_singular_for_one():
    from generator.cli.build import counted

    assert (counted(1, "display"), counted(2, "display"), counted(0, "view")) == ("1 display", "2 displays", "0 views")


@pytest.mark.parametrize("foreign", ("footage/shot.exr", "config.ocio"))
def test_force_replaces_only_a_previous_build(tmp_path, capsys, foreign):
    """A folder holding anything a build does not write (footage), or not holding the resolved
    spec a build writes (a hand-made config alone), is never replaced, --force or not."""
    out = tmp_path / "show"
    (out / foreign).parent.mkdir(parents=True, exist_ok=True)
    (out / foreign).write_bytes(b"keep")
    code, _, err = run(capsys, "build", "-o", str(out), "--force")
    assert code == 2 and err.count("\n") == 1 and "previous build" in err
    assert (out / foreign).read_bytes() == b"keep"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["show"]


def test_force_keeps_what_is_not_a_build_inside_its_lut_folder(tmp_path, capsys):
    """A previous build whose luts/ also holds a file no build writes is not replaced."""
    out = tmp_path / "show"
    assert run(capsys, "build", "-o", str(out))[0] == 0
    (out / "luts" / "shot.exr").write_bytes(b"keep")
    code, _, err = run(capsys, "build", "-o", str(out), "--force")
    assert code == 2 and err.count("\n") == 1 and "luts/shot.exr, which no build writes" in err
    assert (out / "luts" / "shot.exr").read_bytes() == b"keep"


@pytest.mark.parametrize("name", ("grade.clf", "show_curve.spi1d"))
def test_force_keeps_a_lut_of_its_own_in_the_lut_folder(tmp_path, capsys, name):
    """A file of a build's suffixes that its config does not read is not the build's: --force
    had deleted a TD's own CLF or .spi1d put in luts/, judging by suffix alone."""
    out = tmp_path / "show"
    assert run(capsys, "build", "-o", str(out))[0] == 0
    (out / "luts" / name).write_bytes(b"keep")
    code, _, err = run(capsys, "build", "-o", str(out), "--force")
    assert code == 2 and err.count("\n") == 1 and f"luts/{name}, which its config.ocio does not read" in err, err
    assert (out / "luts" / name).read_bytes() == b"keep"


@pytest.mark.parametrize("src", ("/mnt/show/grades/grade.clf", "grade.clf"))
def test_force_keeps_a_lut_only_a_look_of_its_own_reads(tmp_path, capsys, src):
    """A TD's look reading their grade (from luts/, or another file of the same name) does not
    make it the build's: files_read had gone by file name over every transform, looks too."""
    import PyOpenColorIO as ocio

    out = tmp_path / "show"
    assert run(capsys, "build", "-o", str(out))[0] == 0
    cfg = ocio.Config.CreateFromFile(str(out / "config.ocio"))
    cfg.addLook(ocio.Look(name="Grade", processSpace="ACEScct", transform=ocio.FileTransform(src=src)))
    (out / "config.ocio").write_text(cfg.serialize(), encoding="utf-8")
    (out / "luts" / "grade.clf").write_bytes(b"keep")
    code, _, err = run(capsys, "build", "-o", str(out), "--force")
    assert code == 2 and err.count("\n") == 1 and "luts/grade.clf, which its config.ocio does not read" in err, err
    assert (out / "luts" / "grade.clf").read_bytes() == b"keep"


@pytest.mark.parametrize("force", (True, False))
def test_a_previous_build_without_its_config_is_refused_in_one_line(tmp_path, capsys, force):
    """A build whose config.ocio is gone had ended the next build in a traceback, --force or not."""
    out = tmp_path / "show"
    assert run(capsys, "build", "-o", str(out))[0] == 0
    (out / "config.ocio").unlink()
    code, _, err = run(capsys, "build", "-o", str(out), *(["--force"] if force else []))
    assert code == 2 and err.count("\n") == 1 and "has no config.ocio" in err, err
    assert (out / "luts").is_dir()


def test_force_refuses_a_build_whose_config_does_not_load(tmp_path, capsys):
    """Which of luts/ a build wrote is told by the config that reads them: without one that
    loads, nothing is replaced."""
    out = tmp_path / "show"
    assert run(capsys, "build", "-o", str(out))[0] == 0
    (out / "config.ocio").write_text("not a config")
    code, _, err = run(capsys, "build", "-o", str(out), "--force")
    assert code == 2 and err.count("\n") == 1 and "config.ocio OpenColorIO cannot load" in err, err
    assert (out / "config.ocio").read_text() == "not a config"


def test_force_through_a_link_replaces_the_build_it_points_to(tmp_path, capsys):
    """A show's ``current`` link to a versioned build stays a link; the build is replaced."""
    build = tmp_path / "v001"
    assert run(capsys, "build", "-o", str(build))[0] == 0
    (tmp_path / "current").symlink_to("v001")
    with (build / "config.ocio").open("a") as config:
        config.write("# stale\n")
    assert run(capsys, "build", "-o", str(tmp_path / "current"), "--force")[0] == 0
    assert (tmp_path / "current").is_symlink() and not (build / "config.ocio").read_text().endswith("# stale\n")
    import PyOpenColorIO as ocio

    assert ocio.Config.CreateFromFile(str(build / "config.ocio")).getName() == "v001"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["current", "v001"]


def test_a_link_to_nothing_is_named(tmp_path, capsys):
    (tmp_path / "current").symlink_to("v002")
    code, _, err = run(capsys, "build", "-o", str(tmp_path / "current"))
    assert code == 2 and err.count("\n") == 1 and "is a link to 'v002', which does not exist" in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["current"] and not (tmp_path / "current").exists()


def test_footage_put_in_the_folder_during_a_build_is_kept(tmp_path, capsys, monkeypatch):
    """The check that the folder is new or a previous build runs again right before the rename
    (it ran only at the start, and the rename deleted what had appeared since)."""
    from generator.ocio import write

    out = tmp_path / "show"
    fill = write.write_files

    def footage_meanwhile(spec, staging):
        out.mkdir()
        (out / "footage.exr").write_bytes(b"precious")
        return fill(spec, staging)

    monkeypatch.setattr(write, "write_files", footage_meanwhile)
    code, _, err = run(capsys, "build", "-o", out)
    assert one_line(code, err, "holds 'footage.exr', which no build writes"), err
    assert (out / "footage.exr").read_bytes() == b"precious"
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["footage.exr", "show"]


def test_a_build_finished_meanwhile_is_not_replaced_without_force(tmp_path, capsys, monkeypatch):
    """Two builds into one new folder: the slower is refused, not silently replacing the other."""
    from generator.ocio import write

    out = tmp_path / "show"
    fill = write.write_files

    def other_build_meanwhile(spec, staging):
        out.mkdir()
        (out / write.resolved.FILENAME).write_text("{}")
        (out / write.CONFIG_FILENAME).write_text("ocio_profile_version: 2.1\n")
        return fill(spec, staging)

    monkeypatch.setattr(write, "write_files", other_build_meanwhile)
    code, _, err = run(capsys, "build", "-o", out)
    assert one_line(code, err, "holds a previous build; pass --force"), err
    assert sorted(p.name for p in out.iterdir()) == sorted([write.CONFIG_FILENAME, write.resolved.FILENAME])


def test_a_folder_of_footage_is_said_not_to_be_a_build_without_force_too(tmp_path, capsys):
    """Not "pass --force to replace a previous build", which --force would then refuse."""
    (tmp_path / "show").mkdir()
    (tmp_path / "show" / "shot.exr").write_bytes(b"keep")
    code, _, err = run(capsys, "build", "-o", tmp_path / "show")
    assert one_line(code, err, "holds 'shot.exr', which no build writes") and "pass --force" not in err, err


def test_a_spec_not_in_utf8_is_one_line(tmp_path, capsys):
    spec = tmp_path / "show.toml"
    spec.write_bytes('name = "show"\n'.encode("utf-16"))
    code, _, err = run(capsys, "build", str(spec), "-o", str(tmp_path / "out"))
    assert code == 2 and err.count("\n") == 1 and "not UTF-8 text" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["show.toml"]


def test_a_build_failing_while_written_leaves_no_folders_it_made(tmp_path, capsys):
    """A table no 1D LUT holds is found while the folder is staged: the folders made for the
    output go too, and the error names the space."""
    codes = sorted([(i / 39) ** 1.7 for i in range(40)] + [0.33331, 0.33333])  # uneven rows, a step between two
    (tmp_path / "rough.csv").write_text(
        "".join(f"{x:.6f},{x * 0.3 + (0.2 if x > 0.33332 else 0.0):.6f}\n" for x in codes)
    )
    (tmp_path / "rough.toml").write_text(
        'colour_spaces = ["*"]\n[[custom_space]]\nname = "Rough"\ngamut = "Rec.709"\n'
        'transfer = { family = "tabulated", file = "rough.csv" }\n'
    )
    code, _, err = run(capsys, "build", str(tmp_path / "rough.toml"), "-o", str(tmp_path / "a" / "b" / "show"))
    assert code == 2 and err.count("\n") == 1 and "custom_space[name = 'Rough'].transfer" in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["rough.csv", "rough.toml"]


@pytest.mark.parametrize(
    ("name", "words"),
    [
        ("../escape", "cannot name a folder"),
        ("", "cannot name a folder"),
        ("..", "cannot name a folder"),
        ("show\nbuild", "control character"),
        ("a/b", "cannot name a folder"),
        ("CON", "keeps it for a device"),
        ("aux.show", "keeps it for a device"),
        ("Com1", "keeps it for a device"),
        ("show.", "drops a final dot"),
        ("show..", "drops a final dot"),
    ],
)
def test_a_spec_name_that_cannot_name_the_default_folder_is_refused(tmp_path, capsys, monkeypatch, name, words):
    """Without -o a build goes to configs/<name>: a name no folder takes is one line, exit 2."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "show.toml").write_text(f"name = {name!r}\n".replace("'", '"').replace('\n"', '\\n"'))
    code, _, err = run(capsys, "build", "show.toml")
    assert code == 2 and err.count("\n") == 1 and words in err, err
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["show.toml"]
    (tmp_path / "show.toml").write_text('name = "Show: A"\n')
    assert run(capsys, "build", "show.toml", "-o", str(tmp_path / "out"))[0] == 0  # -o names the folder


def test_bad_spec_gives_one_line_exit_2_and_writes_nothing(tmp_path, capsys):
    spec = tmp_path / "bad.toml"
    spec.write_text('colour_spaces = ["ACEScg", "Linear Rec.709 (sRGB)", "S-Log3 S-Gamut9"]\n')
    code, _, err = run(capsys, "build", str(spec), "-o", str(tmp_path / "out"))
    assert code == 2
    assert err.startswith("error: ") and err.count("\n") == 1
    assert "bad.toml:colour_spaces[2]" in err and "S-Log3 S-Gamut3" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml"]


@pytest.mark.parametrize(
    "argv, words",
    [
        (("build", "--ocio-version", "1.9"), "allowed: 2.1 to"),
        (("build", "nowhere.toml"), "cannot read"),
    ],
)
def test_bad_arguments_exit_2_with_one_line(tmp_path, capsys, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, *argv)
    assert code == 2 and err.startswith("error: ") and err.count("\n") == 1 and words in err
    assert list(tmp_path.iterdir()) == []


def test_an_unwritable_output_is_one_line_and_exit_2(tmp_path, capsys):
    """A folder under a regular file cannot be written, for any user: the path and the OS's
    reason on one line, exit status 2 (1 is verify's "checks failed"), nothing left behind."""
    blocked = tmp_path / "blocked"
    blocked.write_bytes(b"")
    code, _, err = run(capsys, "build", "-o", f"{blocked}/show")
    assert code == 2 and err.count("\n") == 1, err
    assert err == f"error: {blocked / 'show'}: cannot write: Not a directory\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["blocked"]


@pytest.mark.parametrize(
    "argv, words",
    [
        (["build", "-o", "{tmp}/" + LONG], "File name too long"),
        (["build", "-o", "{tmp}/l1"], "is a link to 'l2', which does not exist (or is a loop of links)"),
        (["build", "-o", "{tmp}/x/.."], "names no folder of its own"),
    ],
)
def test_a_path_that_cannot_be_used_is_one_line(looped_links, capsys, argv, words):
    """A name too long, a loop of links, a path naming no folder: one line, exit 2, nothing left
    behind (each was a traceback, exit 1; build -o x/.. left x/ and x/....old.XXXX)."""
    code, _, err = run(capsys, *(a.format(tmp=looped_links) for a in argv))
    assert one_line(code, err, words), err
    assert sorted(p.name for p in looped_links.iterdir()) == ["l1", "l2"]


def test_a_folder_name_that_is_not_utf8_is_one_line(tmp_path, capsys):
    """The folder's name names the config, which OCIO writes in UTF-8: a name of other bytes had
    failed inside OCIO with a traceback."""
    import os

    out = os.fsdecode(os.fsencode(tmp_path) + b"/bad\xffname")
    code, _, err = run(capsys, "build", "-o", out)
    assert code == 2 and err.count("\n") == 1 and "bad\\xffname:-o: the folder's name" in err
    assert list(tmp_path.iterdir()) == []
