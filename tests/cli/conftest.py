"""What the command tests share: the command line run in-process through its entry point (whose
error handling is part of what is tested), a copy of a build to edit, and checks every command
that writes a file makes of what is already there."""

from __future__ import annotations

import shutil
import stat
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from generator.cli import main
from tests.conftest import special_file

#: The repository's example show: its own colour spaces and displays.
SHOW = Path(__file__).parents[2] / "examples" / "show" / "spec.toml"

#: A small bake's arguments, -o to follow.
BAKE = ("bake", "--from", "ACEScg", "--to", "sRGB - Display", "--size", "9")

#: A file name longer than any file system takes.
LONG = "x" * 300


def run(capsys, *argv):
    """``ocioforge *argv`` in-process: its exit status, standard output and standard error."""
    try:
        main([str(a) for a in argv])
        code = 0
    except SystemExit as exit_:
        code = exit_.code
    out, err = capsys.readouterr()
    return code, out, err


@click.command(context_settings={"ignore_unknown_options": True, "help_option_names": []})
@click.argument("argv", nargs=-1, type=click.UNPROCESSED)
def _ocioforge(argv):
    """The command line through its entry point."""
    main(list(argv))


def invoke(command, *args):
    """``ocioforge command *args`` through click's runner: its result (exit_code, output, stderr)."""
    return CliRunner().invoke(_ocioforge, [command, *map(str, args)])


def one_line(code, err, words=""):
    """Bad input: exit status 2 and one error line holding ``words``."""
    return code == 2 and err.startswith("error: ") and err.count("\n") == 1 and words in err


@pytest.fixture
def config(build_config, tmp_path):
    """A copy of the default spec's 2.1 build, free to edit: its config.ocio."""
    source = build_config((2, 1)).parent
    shutil.copytree(source, tmp_path / source.name)
    return tmp_path / source.name / "config.ocio"


@pytest.fixture(scope="module")
def show():
    """The example show's spec, loaded."""
    from generator.spec import load

    return load.load(SHOW)


@pytest.fixture
def looped_links(tmp_path, monkeypatch):
    """A working folder holding only l1 and l2, links to each other."""
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    (work / "l1").symlink_to("l2")
    (work / "l2").symlink_to("l1")
    return work


def refuses_a_special_file(capsys, tmp_path, kind, argv, suffix):
    """``argv`` writing ``{out}``, there a ``kind`` of special file named with ``suffix``: refused in
    one line, --force or not, the file left what it was."""
    special = special_file(tmp_path / f"out{suffix}", kind)
    for force in ((), ("--force",)):
        code, _, err = run(capsys, *(a.replace("{out}", str(special)) for a in argv), *force)
        assert one_line(code, err, "is not a regular file"), err
    assert not special.is_file() and stat.S_IFMT(special.lstat().st_mode) != stat.S_IFREG


def writes_through_a_link_only_with_force(capsys, tmp_path, argv, suffix):
    """``argv`` writing ``{out}``, there a link named with ``suffix``: a dangling one refused, --force
    or not; one to a regular file needs --force, and then the file it points to is written, the
    link kept."""
    link, real = tmp_path / f"link{suffix}", tmp_path / f"real{suffix}"
    link.symlink_to(real.name)
    command = [a.replace("{out}", str(link)) for a in argv]
    for force in ((), ("--force",)):
        code, _, err = run(capsys, *command, *force)
        assert one_line(code, err, "is a link"), err
    assert link.is_symlink() and not real.exists()
    real.write_bytes(b"old")
    code, _, err = run(capsys, *command)
    assert one_line(code, err, "pass --force"), err
    assert run(capsys, *command, "--force")[0] == 0
    assert link.is_symlink() and real.read_bytes() != b"old"
