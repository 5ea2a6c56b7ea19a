"""What every command that writes does with what is already there: nothing replaced without
--force, never anything but a regular file (or a previous build), nothing half-written, one
line and exit status 2 for a path that cannot be used."""

from __future__ import annotations

import shutil
import stat

import pytest

from generator.cli import main
from tests.conftest import special_file

BAKE = ("bake", "--from", "ACEScg", "--to", "sRGB - Display", "--size", "9")


def run(capsys, *argv):
    try:
        main([str(a) for a in argv])
        code = 0
    except SystemExit as exit_:
        code = exit_.code
    out, err = capsys.readouterr()
    return code, out, err


def one_line(code, err, words=""):
    """Bad input: exit status 2 and one error line holding ``words``."""
    return code == 2 and err.startswith("error: ") and err.count("\n") == 1 and words in err


@pytest.fixture
def config(build_config, tmp_path):
    source = build_config((2, 1)).parent
    shutil.copytree(source, tmp_path / "cfg")
    return tmp_path / "cfg" / "config.ocio"


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


@pytest.mark.parametrize("kind", ("fifo", "socket", "device"))
@pytest.mark.parametrize(
    "argv",
    (
        ["plot", "{config}", "-o", "{out}.png", "--force"],
        [*BAKE, "-o", "{out}.clf", "--force"],
        ["init", "{out}.toml", "--force"],
    ),
)
def test_a_device_or_pipe_is_never_replaced(config, tmp_path, capsys, kind, argv):
    out = tmp_path / "out"
    suffix = next(a for a in argv if a.startswith("{out}")).removeprefix("{out}")
    special = special_file(tmp_path / f"out{suffix}", kind)
    code, _, err = run(capsys, *(a.format(config=config, out=out) for a in argv))
    assert one_line(code, err, "is not a regular file"), err
    assert not special.is_file() and stat.S_IFMT(special.lstat().st_mode) != stat.S_IFREG


@pytest.mark.parametrize("argv", (["plot", "{config}", "-o", "{out}"], [*BAKE, "-o", "{out}"], ["init", "{out}"]))
def test_a_link_is_written_through_only_with_force(config, tmp_path, capsys, argv):
    """A dangling link is refused, --force or not (bake replaced it without --force); a link to
    a regular file needs --force, and then the file it points to is written, the link kept."""
    suffix = ".clf" if "bake" in argv else ".png" if "plot" in argv else ".toml"
    link, real = tmp_path / f"link{suffix}", tmp_path / f"real{suffix}"
    link.symlink_to(real.name)
    command = [a.format(config=config, out=link) for a in argv]
    for force in ((), ("--force",)):
        code, _, err = run(capsys, *command, *force)
        assert one_line(code, err, "is a link"), err
    assert link.is_symlink() and not real.exists()
    real.write_bytes(b"old")
    code, _, err = run(capsys, *command)
    assert one_line(code, err, "pass --force"), err
    assert run(capsys, *command, "--force")[0] == 0
    assert link.is_symlink() and real.read_bytes() != b"old"


def test_plot_replaces_an_image_only_with_force(config, tmp_path, capsys):
    image = tmp_path / "diagram.png"
    image.write_bytes(b"keep")
    code, _, err = run(capsys, "plot", config, "-o", image)
    assert one_line(code, err, "exists; pass --force") and image.read_bytes() == b"keep", err
    assert run(capsys, "plot", config, "-o", image, "--force")[0] == 0
    assert image.read_bytes().startswith(b"\x89PNG")


VERIFY = ("verify", "{config}", "--engines", "ocio", "--quick", "--only", "ACEScct -> ACES2065-1", "--summary")


def test_a_report_is_replaced_only_with_force_and_refused_before_the_run(config, tmp_path, capsys):
    report = tmp_path / "report"
    argv = [a.format(config=config) for a in VERIFY]
    assert run(capsys, *argv, "--report", report)[0] == 0
    (report / "summary.json").write_text("keep")
    code, out, err = run(capsys, *argv, "--report", report)
    assert one_line(code, err, "summary.json: exists; pass --force"), err
    assert out == "" and (report / "summary.json").read_text() == "keep"
    assert run(capsys, *argv, "--report", report, "--force")[0] == 0
    assert (report / "summary.json").read_text().startswith("{")


def test_a_report_is_written_whole_or_not_at_all(config, tmp_path, capsys):
    """report.html a folder: refused before the run, and summary.json not written either."""
    report = tmp_path / "report"
    (report / "report.html").mkdir(parents=True)
    code, out, err = run(capsys, *(a.format(config=config) for a in VERIFY), "--report", report, "--force")
    assert one_line(code, err, "report.html: is a folder; allowed: ") and out == "", err
    assert sorted(p.name for p in report.iterdir()) == ["report.html"]


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


LONG = "x" * 300


@pytest.mark.parametrize(
    "argv, words",
    [
        (["build", "-o", "{tmp}/" + LONG], "File name too long"),
        ([*BAKE, "-o", "{tmp}/" + LONG + ".clf"], "File name too long"),
        (["verify", "{tmp}/" + LONG + "/config.ocio"], "File name too long"),
        (["verify", "{config}", "--report", "{tmp}/" + LONG], "File name too long"),
        (["plot", "{tmp}/" + LONG + "/config.ocio", "-o", "{tmp}/a.png"], "File name too long"),
        (["build", "-o", "{tmp}/l1"], "is a link to 'l2', which does not exist (or is a loop of links)"),
        ([*BAKE, "-o", "{tmp}/l1", "--format", "clf", "--force"], "is a link to nothing"),
        ([*BAKE, "-o", "{tmp}/l1/a.clf"], "Too many levels of symbolic links"),
        ([*BAKE, "-o", ".", "--format", "clf"], "names no file of its own"),
        ([*BAKE, "-o", "/", "--format", "spi3d"], "names no file of its own"),
        (["build", "-o", "{tmp}/x/.."], "names no folder of its own"),
    ],
)
def test_a_path_that_cannot_be_used_is_one_line(config, tmp_path, capsys, monkeypatch, argv, words):
    """A name too long, a loop of links, a path naming no file: one line, exit 2, nothing left
    behind (each was a traceback, exit 1; build -o x/.. left x/ and x/....old.XXXX)."""
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    (work / "l1").symlink_to("l2")
    (work / "l2").symlink_to("l1")
    code, _, err = run(capsys, *(a.format(config=config, tmp=work) for a in argv))
    assert one_line(code, err, words), err
    assert sorted(p.name for p in work.iterdir()) == ["l1", "l2"]


@pytest.mark.parametrize("argv", (["build", "-o", "show"], ["info", "acescg"], [*BAKE, "-o", "a.clf"]))
def test_a_deleted_working_directory_is_one_line(tmp_path, capsys, monkeypatch, argv):
    gone = tmp_path / "gone"
    gone.mkdir()
    monkeypatch.chdir(gone)
    gone.rmdir()
    code, _, err = run(capsys, *argv)
    assert one_line(code, err, "the working directory: No such file or directory"), err


@pytest.mark.parametrize(
    "argv, words",
    [
        (["verify", "a\nb.ocio"], "a\\nb.ocio"),
        (["build", "no\npe.toml"], "no\\npe.toml"),
        (["build", "-o", "afile/x\ny"], "afile/x\\ny"),
    ],
)
def test_a_path_holding_a_newline_is_one_line(tmp_path, capsys, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "afile").write_bytes(b"")
    code, _, err = run(capsys, *argv)
    assert one_line(code, err, words), err


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
