"""Writing files so that they are never seen half-written (bake, verify's report, plots, init)."""

from __future__ import annotations

import os
import signal
import stat
from pathlib import Path

import pytest

from generator import files
from generator.files import CannotWrite, Refused, Stopped, staged_folder, write_atomic, write_files
from tests.conftest import special_file


def test_a_written_file_is_readable_as_a_plain_write_would_leave_it(tmp_path):
    old = os.umask(0o022)
    try:
        write_atomic(tmp_path / "sub" / "report.html", b"<html></html>", force=False)
    finally:
        os.umask(old)
    path = tmp_path / "sub" / "report.html"
    assert path.read_bytes() == b"<html></html>"
    assert stat.S_IMODE(path.stat().st_mode) == 0o644
    assert [p.name for p in path.parent.iterdir()] == ["report.html"]  # no temporary left


def test_files_are_written_all_or_none(tmp_path):
    """The second file cannot be written (its folder is a file): the first, though complete,
    is not renamed into place, the existing one is kept, and no temporary is left."""
    (tmp_path / "lut.cube").write_bytes(b"old")
    (tmp_path / "blocked").write_bytes(b"")
    with pytest.raises(CannotWrite, match="lut.spi1d: cannot write: Not a directory"):
        write_files({tmp_path / "lut.cube": b"new", tmp_path / "blocked" / "lut.spi1d": b"shaper"}, force=True)
    assert (tmp_path / "lut.cube").read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["blocked", "lut.cube"]


def test_a_pair_whose_second_rename_fails_keeps_both_old_files(tmp_path, monkeypatch):
    """A .spi3d and its .spi1d: if the .spi1d cannot be renamed into place once the .spi3d has
    been, the .spi3d is taken back, so the old pair stays a pair (the new lattice beside the old
    shaper is off by tens of codes)."""
    import os

    (tmp_path / "lut.spi3d").write_bytes(b"old 3d")
    (tmp_path / "lut.spi1d").write_bytes(b"old 1d")
    real_replace = os.replace

    def failing(source, destination):
        if str(destination).endswith("lut.spi1d") and ".old." not in str(destination) and ".old." not in str(source):
            raise PermissionError(1, "Operation not permitted", str(destination))
        return real_replace(source, destination)

    monkeypatch.setattr(os, "replace", failing)
    with pytest.raises(CannotWrite, match="lut.spi1d"):
        write_files({tmp_path / "lut.spi3d": b"new 3d", tmp_path / "lut.spi1d": b"new 1d"}, force=True)
    monkeypatch.setattr(os, "replace", real_replace)
    assert (tmp_path / "lut.spi3d").read_bytes() == b"old 3d" and (tmp_path / "lut.spi1d").read_bytes() == b"old 1d"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["lut.spi1d", "lut.spi3d"]  # nothing set aside is left


def test_a_folder_that_cannot_be_staged_names_the_folder(tmp_path):
    (tmp_path / "blocked").write_bytes(b"")
    with pytest.raises(CannotWrite, match=r"show: cannot write: Not a directory$"):
        with staged_folder(tmp_path / "blocked" / "show"):
            pass


def test_an_error_filling_the_staged_folder_names_the_folder_and_removes_it(tmp_path):
    """An OSError on a path inside the staging folder is a write failure of the folder; any other
    (reading an input) passes through unchanged. Either way nothing is left behind."""
    with pytest.raises(CannotWrite, match=r"show: cannot write: No space left on device$"):
        with staged_folder(tmp_path / "show") as staging:
            raise OSError(28, os.strerror(28), str(staging / "config.ocio"))
    with pytest.raises(FileNotFoundError), staged_folder(tmp_path / "show"):
        open(tmp_path / "missing.csv")
    assert list(tmp_path.iterdir()) == []


def test_a_full_disk_reported_without_a_file_name_is_a_write_failure(tmp_path):
    """Python reports a full disk on closing a file with no file name: still a write failure of
    the folder (it was a traceback), and nothing is left behind."""
    with pytest.raises(CannotWrite, match=r"show: cannot write: No space left on device$"):
        with staged_folder(tmp_path / "show"):
            raise OSError(28, os.strerror(28))
    assert list(tmp_path.iterdir()) == []


def _refuse_unless_empty(path):
    if path.exists() and any(path.iterdir()):
        raise ValueError(f"{path.name} holds something")


def test_what_appears_at_the_folder_during_a_build_is_checked_again_and_kept(tmp_path):
    """The check runs again right before the rename: footage copied into the folder while it was
    staged (or another build finishing first) is refused, untouched, the staging folder removed."""
    folder = tmp_path / "show"
    with pytest.raises(ValueError, match="show holds something"):
        with staged_folder(folder, _refuse_unless_empty) as staging:
            (staging / "config.ocio").write_bytes(b"new")
            folder.mkdir()
            (folder / "footage.exr").write_bytes(b"precious")
    assert (folder / "footage.exr").read_bytes() == b"precious"
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["footage.exr", "show"]


def test_what_is_moved_aside_is_checked_there_and_moved_back_when_refused(tmp_path):
    """What is deleted is what was checked: a folder that passes the first check but not the one
    made once it was moved aside (written to in between) is put back, whole."""
    folder = tmp_path / "show"
    folder.mkdir()
    (folder / "config.ocio").write_bytes(b"old")
    calls = []

    def second_refuses(path):
        calls.append(path)
        if len(calls) > 1:
            raise ValueError("changed")

    with pytest.raises(ValueError, match="changed"), staged_folder(folder, second_refuses) as staging:
        (staging / "config.ocio").write_bytes(b"new")
    assert calls[0] == folder and calls[1] != folder
    assert (folder / "config.ocio").read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["config.ocio", "show"]


@pytest.mark.parametrize("kind", ("fifo", "socket", "device"))
@pytest.mark.parametrize("force", (False, True))
def test_only_a_regular_file_is_replaced(tmp_path, kind, force):
    path = special_file(tmp_path / f"{kind}.png", kind)
    with pytest.raises(Refused, match="is not a regular file"):
        write_atomic(path, b"x", force)
    assert not path.is_file() and path.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == [path.name]


def test_a_link_is_replaced_only_with_force_and_then_its_file_is_written(tmp_path):
    (tmp_path / "real.png").write_bytes(b"old")
    link = tmp_path / "link.png"
    link.symlink_to("real.png")
    with pytest.raises(Refused, match="is a link; pass --force"):
        write_atomic(link, b"new", force=False)
    assert write_atomic(link, b"new", force=True) == tmp_path / "real.png"
    assert link.is_symlink() and (tmp_path / "real.png").read_bytes() == b"new"


@pytest.mark.parametrize("force", (False, True))
def test_a_link_to_nothing_or_a_loop_is_never_replaced(tmp_path, force):
    (tmp_path / "dangling").symlink_to("nowhere")
    (tmp_path / "l1").symlink_to("l2")
    (tmp_path / "l2").symlink_to("l1")
    for name in ("dangling", "l1"):  # the real reason, --force or not (it had said to pass --force)
        with pytest.raises(Refused, match="a link to nothing"):
            write_atomic(tmp_path / name, b"x", force)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dangling", "l1", "l2"]
    assert all((tmp_path / n).is_symlink() for n in ("dangling", "l1", "l2"))


def test_every_target_is_checked_before_any_is_written(tmp_path):
    """A .spi3d and its .spi1d, the .spi1d a folder: the .spi3d is not replaced either."""
    (tmp_path / "pair.spi3d").write_bytes(b"old")
    (tmp_path / "pair.spi1d").mkdir()
    with pytest.raises(Refused, match="pair.spi1d: is a folder; allowed: "):
        write_files({tmp_path / "pair.spi3d": b"new", tmp_path / "pair.spi1d": b"shaper"}, force=True)
    assert (tmp_path / "pair.spi3d").read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pair.spi1d", "pair.spi3d"]


def test_an_existing_file_is_refused_without_force(tmp_path):
    (tmp_path / "a.png").write_bytes(b"old")
    with pytest.raises(Refused, match="exists; pass --force"):
        write_files({tmp_path / "b.png": b"new", tmp_path / "a.png": b"new"}, force=False)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.png"]


@pytest.mark.parametrize("path", (Path("."), Path("x/.."), Path("/")))
def test_a_path_naming_no_file_is_refused(path):
    """pathlib had raised ValueError ("has an empty name") on such an output's suffix or name."""
    with pytest.raises(Refused, match="names no file of its own"):
        write_atomic(path, b"x", force=True)


@pytest.fixture
def stopped():
    """A stop signal recorded, as the CLI's handler does before raising (the exception may be
    swallowed); cleared after."""
    files.stop(signal.SIGTERM)
    yield
    files.stop(0)


def test_nothing_is_renamed_into_place_once_a_stop_is_recorded(tmp_path, stopped):
    with pytest.raises(Stopped):
        write_atomic(tmp_path / "a.clf", b"x", force=True)
    with pytest.raises(Stopped), staged_folder(tmp_path / "show") as staging:
        (staging / "config.ocio").write_bytes(b"x")
    assert list(tmp_path.iterdir()) == []


@pytest.fixture
def cli_sigint():
    """SIGINT handled as the CLI handles it (the stop recorded, and cleared after)."""
    from generator.cli import _stop

    previous = signal.signal(signal.SIGINT, _stop)
    yield
    signal.signal(signal.SIGINT, previous)
    files.stop(0)


def _signalling(monkeypatch, module, name, after=False):
    """``module.name`` replaced by a function that sends this process SIGINT before calling it
    (``after``: once it returns)."""
    original = getattr(module, name)

    def signalled(*args, **kwargs):
        if not after:
            os.kill(os.getpid(), signal.SIGINT)
        result = original(*args, **kwargs)
        if after:
            os.kill(os.getpid(), signal.SIGINT)
        return result

    monkeypatch.setattr(module, name, signalled)


def test_a_signal_during_the_renames_of_a_pair_waits_until_both_are_done(tmp_path, monkeypatch, cli_sigint):
    """Ctrl-C between the renames of a .spi3d and its .spi1d had left the new lattice paired
    with the old shaper."""
    for name in ("pair.spi3d", "pair.spi1d"):
        (tmp_path / name).write_bytes(b"old")
    _signalling(monkeypatch, files.os, "replace")
    with pytest.raises(Stopped):
        write_files({tmp_path / "pair.spi3d": b"new", tmp_path / "pair.spi1d": b"new"}, force=True)
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == {"pair.spi3d": b"new", "pair.spi1d": b"new"}


def test_a_signal_while_a_previous_build_is_removed_leaves_nothing_of_it(tmp_path, monkeypatch, cli_sigint):
    """Ctrl-C during the removal of the replaced build had left it half-deleted beside the new one."""
    with staged_folder(tmp_path / "show") as staging:
        (staging / "config.ocio").write_bytes(b"old")
    _signalling(monkeypatch, files.shutil, "rmtree")
    with pytest.raises(Stopped), staged_folder(tmp_path / "show") as staging:
        (staging / "config.ocio").write_bytes(b"new")
    assert [p.name for p in tmp_path.iterdir()] == ["show"]
    assert (tmp_path / "show" / "config.ocio").read_bytes() == b"new"


@pytest.mark.parametrize("maker", ["mkdtemp", "mkstemp"])
def test_a_signal_as_a_temporary_is_made_leaves_nothing(tmp_path, monkeypatch, cli_sigint, maker):
    """SIGTERM just as the staging folder had been made (the moment a test waits for) had left it."""
    _signalling(monkeypatch, files.tempfile, maker, after=True)
    with pytest.raises(Stopped):
        if maker == "mkdtemp":
            with staged_folder(tmp_path / "show") as staging:
                (staging / "config.ocio").write_bytes(b"new")
        else:
            write_atomic(tmp_path / "a.clf", b"new", force=False)
    assert list(tmp_path.iterdir()) == []


def test_a_folder_staged_in_a_shared_folder_keeps_its_group_bit(tmp_path):
    """In a setgid folder (a show's shared storage) a new folder inherits the bit, so files made
    in it later keep the group; the staged folder's permissions had been set without it."""
    shared = tmp_path / "shared"
    shared.mkdir()
    os.chmod(shared, 0o2775)
    old = os.umask(0o002)
    try:
        with staged_folder(shared / "show") as staging:
            (staging / "luts").mkdir()
        (shared / "plain").mkdir()
    finally:
        os.umask(old)
    modes = [stat.S_IMODE((shared / name).stat().st_mode) for name in ("show", "show/luts", "plain")]
    assert modes == [0o2775] * 3, [oct(m) for m in modes]


def test_what_is_replaced_keeps_its_permissions_under_a_stricter_umask(tmp_path):
    """A show's LUT and build, rebuilt with --force by someone whose umask is 077: they had become
    readable by that user alone. A replaced file keeps its mode, a replaced folder its own and,
    entry for entry, its entries'; what is new gets a plain write's."""
    lut = tmp_path / "show.cube"
    lut.write_bytes(b"old")
    os.chmod(lut, 0o664)
    build = tmp_path / "build"
    (build / "luts").mkdir(parents=True)
    (build / "config.ocio").write_bytes(b"old")
    for path, mode in ((build, 0o2775), (build / "luts", 0o775), (build / "config.ocio", 0o644)):
        os.chmod(path, mode)
    old = os.umask(0o077)
    try:
        write_files({lut: b"new", tmp_path / "new.cube": b"new"}, force=True)
        with staged_folder(build, files._no_check) as staging:
            (staging / "luts").mkdir()
            (staging / "config.ocio").write_bytes(b"new")
            (staging / "luts" / "new.spi1d").write_bytes(b"new")
    finally:
        os.umask(old)
    modes = {str(p.relative_to(tmp_path)): oct(stat.S_IMODE(p.stat().st_mode)) for p in sorted(tmp_path.rglob("*"))}
    assert modes == {
        "show.cube": "0o664",
        "new.cube": "0o600",
        "build": "0o2775",
        "build/luts": "0o775",
        "build/config.ocio": "0o644",
        "build/luts/new.spi1d": "0o600",
    }
